#include "harness/atomic_file.hpp"

#include <atomic>
#include <cerrno>
#include <chrono>
#include <csignal>
#include <cstdlib>
#include <cstring>
#include <iostream>
#include <mutex>
#include <random>
#include <stdexcept>

#include <fcntl.h>
#include <pthread.h>
#include <sys/stat.h>
#include <unistd.h>

namespace rocking::harness {

namespace {

// The temporary files being written, for the signal handler: fixed slots of
// lock-free pointers, because a handler may neither lock nor allocate.
constexpr int kSlots = 64;
std::atomic<const char*> g_temporary[kSlots];

extern "C" void remove_temporaries(int sig) {
    for (auto& slot : g_temporary)
        if (const char* path = slot.load()) unlink(path);
    // SA_RESETHAND has restored the default action: the process now ends as the signal meant.
    raise(sig);
}

// Installed once, and only where the action is the default one: a signal
// the caller ignores (nohup) or handles stays theirs.
void install_handlers() {
    static std::once_flag once;
    std::call_once(once, [] {
        for (int sig : {SIGTERM, SIGINT, SIGHUP}) {
            struct sigaction current {};
            if (sigaction(sig, nullptr, &current) != 0 || (current.sa_flags & SA_SIGINFO) ||
                current.sa_handler != SIG_DFL)
                continue;
            struct sigaction mine {};
            mine.sa_handler = remove_temporaries;
            sigemptyset(&mine.sa_mask);
            mine.sa_flags = SA_RESETHAND;
            sigaction(sig, &mine, nullptr);
        }
    });
}

// -1 when every slot is taken: the file is still atomic, only not removed on a signal.
int enlist(const char* path) {
    for (int k = 0; k < kSlots; ++k) {
        const char* empty = nullptr;
        if (g_temporary[k].compare_exchange_strong(empty, path)) return k;
    }
    return -1;
}

void delist(int slot) {
    if (slot >= 0) g_temporary[slot].store(nullptr);
}

std::string random_suffix() {
    static const char letters[] = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789";
    thread_local std::mt19937_64 draw(std::random_device{}() ^
                                      static_cast<std::uint64_t>(std::chrono::steady_clock::now().time_since_epoch().count()) ^
                                      (static_cast<std::uint64_t>(getpid()) << 32));
    std::string s(6, 'x');
    for (char& c : s) c = letters[draw() % (sizeof letters - 1)];
    return s;
}

// "DIR/.NAME.tmp" for "DIR/NAME"; the name is cut so that the temporary one
// stays within the 255 bytes a file name may have.
std::string temporary_prefix(const std::string& path, AtomicFile::Temporary naming) {
    const auto slash = path.find_last_of('/');
    const std::string dir = slash == std::string::npos ? "" : path.substr(0, slash + 1);
    const std::string name = slash == std::string::npos ? path : path.substr(slash + 1);
    return dir + "." + (naming == AtomicFile::Temporary::plain ? std::string("rocking") : name.substr(0, 200)) + ".tmp";
}

std::string folder_of(const std::string& path) {
    const auto slash = path.find_last_of('/');
    return slash == std::string::npos ? "." : slash == 0 ? "/" : path.substr(0, slash);
}

}  // namespace

AtomicFile::AtomicFile(const std::string& path, Temporary naming) : path_(path), shown_(path) {
    struct stat existing {};
    const bool exists = ::stat(path.c_str(), &existing) == 0;
    if (exists && S_ISDIR(existing.st_mode)) fail("is a folder, not a file", 0);
    if (exists && !S_ISREG(existing.st_mode)) {
        in_place_ = true;
        temp_ = path_;
        file_ = std::fopen(path.c_str(), "w");
        if (!file_) fail("cannot open it for writing", errno);
        return;
    }
    if (exists) {
        // A read-only file was refused before: renaming over it would defeat that.
        if (::access(path.c_str(), W_OK) != 0) fail("cannot write", errno);
        if (char* real = ::realpath(path.c_str(), nullptr)) path_ = real, std::free(real);
    }
    const std::string prefix = temporary_prefix(path_, naming);
    install_handlers();
    // A signal between creating the file and listing it would leave it: held until listed.
    sigset_t held, before;
    sigemptyset(&held);
    for (int sig : {SIGTERM, SIGINT, SIGHUP}) sigaddset(&held, sig);
    pthread_sigmask(SIG_BLOCK, &held, &before);
    int fd = -1;
    for (int attempt = 0; attempt < 100 && fd < 0; ++attempt) {
        temp_ = prefix + random_suffix();
        fd = ::open(temp_.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
        if (fd < 0 && errno != EEXIST) break;
    }
    const int create_error = errno;
    if (fd >= 0) slot_ = enlist(temp_.c_str());
    pthread_sigmask(SIG_SETMASK, &before, nullptr);
    if (fd < 0) {
        temp_.clear();  // not ours: nothing to remove
        fail("cannot create a file in " + folder_of(path_), create_error);
    }
    if (exists) ::fchmod(fd, existing.st_mode & 07777);  // the file it replaces keeps its permissions
    file_ = ::fdopen(fd, "w");
    if (!file_) {
        const int error = errno;
        ::close(fd);
        fail("cannot write", error);
    }
}

AtomicFile::~AtomicFile() {
    if (!committed_) discard();
}

void AtomicFile::write(const std::string& text) {
    if (std::fwrite(text.data(), 1, text.size(), file_) != text.size()) fail("cannot write", errno);
}

void AtomicFile::commit() {
    std::FILE* f = file_;
    file_ = nullptr;  // from here fail() must not close it again
    if (std::fflush(f) != 0) {
        const int error = errno;
        std::fclose(f);
        fail("cannot write", error);
    }
    // Without it a crash of the machine could leave the new name on a file
    // whose data never reached the disk.
    if (!in_place_ && ::fsync(fileno(f)) != 0) {
        const int error = errno;
        std::fclose(f);
        fail("cannot write", error);
    }
    if (std::fclose(f) != 0) fail("cannot write", errno);
    if (!in_place_ && std::rename(temp_.c_str(), path_.c_str()) != 0)
        fail("cannot move " + temp_ + " into its place", errno);
    delist(slot_);
    slot_ = -1;
    committed_ = true;
}

void AtomicFile::fail(const std::string& what, int error) {
    discard();
    throw std::runtime_error(shown_ + ": " + what + (error ? std::string(": ") + std::strerror(error) : ""));
}

void AtomicFile::discard() {
    if (file_) std::fclose(file_);
    file_ = nullptr;
    if (!in_place_ && !temp_.empty()) ::unlink(temp_.c_str());
    delist(slot_);
    slot_ = -1;
}

int finish_standard_output(const char* program, int status) {
    // stdout first: std::cout's flush flushes it too and would take its errno.
    const int error = std::fflush(stdout) != 0 ? errno : 0;
    std::cout.flush();
    if (std::cout && !error && !std::ferror(stdout)) return status;
    std::fprintf(stderr, "%s: error writing standard output%s%s\n", program, error ? ": " : "",
                 error ? std::strerror(error) : "");
    return status == 0 ? 1 : status;
}

}  // namespace rocking::harness
