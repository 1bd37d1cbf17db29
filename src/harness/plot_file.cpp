#include "harness/plot_file.hpp"

#include <cerrno>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <cstdio>
#include <stdexcept>

#include <sys/stat.h>
#include <unistd.h>

namespace rocking::harness {

namespace {

std::uint32_t big_endian(const unsigned char* b) {
    return (std::uint32_t(b[0]) << 24) | (std::uint32_t(b[1]) << 16) | (std::uint32_t(b[2]) << 8) | b[3];
}

std::string read_all(const std::string& path, bool& ok) {
    std::string bytes;
    std::FILE* f = std::fopen(path.c_str(), "rb");
    ok = f != nullptr;
    if (!f) return bytes;
    char buffer[65536];
    for (std::size_t n; (n = std::fread(buffer, 1, sizeof buffer, f)) > 0;) bytes.append(buffer, n);
    ok = !std::ferror(f);
    std::fclose(f);
    return bytes;
}

}  // namespace

std::string png_fault(const std::string& path) {
    bool ok = false;
    const std::string bytes = read_all(path, ok);
    if (!ok) return "cannot read it back";
    static const unsigned char signature[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1A, '\n'};
    if (bytes.size() < 8 || std::memcmp(bytes.data(), signature, 8) != 0)
        return bytes.empty() ? "empty: nothing was drawn" : "not a PNG (no PNG signature)";
    const auto* b = reinterpret_cast<const unsigned char*>(bytes.data());
    std::size_t at = 8;
    while (at + 12 <= bytes.size()) {
        const std::uint64_t length = big_endian(b + at);
        const std::string type(bytes, at + 4, 4);
        const std::uint64_t end = at + 12 + length;  // length, type, data, CRC
        if (end > bytes.size()) break;
        if (type == "IEND")
            return end == bytes.size() ? "" : "bytes after its IEND chunk";
        at = end;
    }
    return "no IEND chunk: the file is cut at byte " + std::to_string(bytes.size());
}

PlotFile::PlotFile(const std::string& target) : target_(target) {
    struct stat s {};
    const bool device = ::stat(target.c_str(), &s) == 0 && !S_ISREG(s.st_mode) && !S_ISDIR(s.st_mode);
    if (!device) {
        beside_ = std::make_unique<AtomicFile>(target, AtomicFile::Temporary::plain);
        draw_ = beside_->temporary_path();
        return;
    }
    if (::access(target.c_str(), W_OK) != 0)
        throw std::runtime_error(target + ": cannot write: " + std::strerror(errno));
    std::string pattern = (std::filesystem::temp_directory_path() / "rocking-plot.XXXXXX").string();
    const int fd = ::mkstemp(pattern.data());
    if (fd < 0)
        throw std::runtime_error(target + ": cannot create a temporary file in " +
                                 std::filesystem::temp_directory_path().string() + ": " + std::strerror(errno));
    ::close(fd);
    draw_ = pattern;
    own_draw_ = true;
}

std::string PlotFile::draw_folder() const {
    const auto slash = draw_.find_last_of('/');
    return slash == std::string::npos ? "." : slash == 0 ? "/" : draw_.substr(0, slash);
}

std::string PlotFile::draw_name() const {
    const auto slash = draw_.find_last_of('/');
    return slash == std::string::npos ? draw_ : draw_.substr(slash + 1);
}

PlotFile::~PlotFile() {
    if (own_draw_) ::unlink(draw_.c_str());
}

void PlotFile::commit() {
    if (const std::string fault = png_fault(draw_); !fault.empty()) {
        beside_.reset();  // removes the temporary file: nothing lands at the target
        throw std::runtime_error(target_ + ": the plot was not written whole (" + fault +
                                 "; a full disk or a failed write)");
    }
    if (beside_) {
        beside_->commit();
        return;
    }
    bool ok = false;
    const std::string bytes = read_all(draw_, ok);
    if (!ok) throw std::runtime_error(target_ + ": cannot read back the plot drawn in " + draw_);
    AtomicFile device(target_);
    device.write(bytes);
    device.commit();
}

}  // namespace rocking::harness
