#include "batch/results_file.hpp"

#include <fcntl.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <algorithm>
#include <cstring>
#include <fstream>
#include <sstream>
#include <vector>

#include "batch/manifest.hpp"
#include "batch/row_digest.hpp"
#include "batch/sha256.hpp"

namespace rocking::batch {

namespace {

const char kDigestLine[] = "# manifest sha256: ";
const char kInputLine[] = "# record sha256: ";
const char kStateLine[] = "rocking batch state:";

bool exists(const std::string& path) {
    struct stat s {};
    return ::stat(path.c_str(), &s) == 0;
}

std::string why(int error) { return std::strerror(error); }

std::string first_line(const std::string& text) { return text.substr(0, text.find('\n')); }

std::string end_line(std::size_t jobs, std::size_t failed) {
    return "# end: " + std::to_string(jobs) + " jobs, " + std::to_string(failed) + " failed\n";
}

// The file's text, or throws naming it.
std::string slurp(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    if (!in) throw ResultsError(path + ": cannot read: " + why(errno));
    std::ostringstream text;
    text << in.rdbuf();
    return text.str();
}

std::string input_line(const InputDigest& input) {
    std::string name = input.name;  // one line, whatever the file's name
    for (std::size_t at = 0; (at = name.find_first_of("\r\n", at)) != std::string::npos; at += 2)
        name.replace(at, 1, name[at] == '\n' ? "\\n" : "\\r");
    return kInputLine + (input.digest.empty() ? std::string(kUnverifiable) : input.digest) + " " + name;
}

// Whether another process holds the partial file's lock: a run still writing it.
bool locked_by_another(const std::string& path) {
    const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
    if (fd < 0) return false;
    const bool locked = ::flock(fd, LOCK_EX | LOCK_NB) != 0 && errno == EWOULDBLOCK;
    ::close(fd);  // and the lock taken, if it was
    return locked;
}

// A resume's first word on a partial file another run holds.
std::string held_by_another(const std::string& partial) {
    return partial + " is being written by another run, which holds its lock: wait for that run to end (a --resume "
                     "then completes whatever it leaves), or give another --output";
}

}  // namespace

std::vector<EngineFile> engine_files(const std::string& output) {
    return {{"", output},
            {"partial file", output + ".partial"},
            {"state file", output + ".partial.state"},
            {"state file's temporary", output + ".partial.state.tmp"}};
}

ResultsFile::ResultsFile(const ResultsOptions& options, const std::string& header, const std::string& digest,
                         std::size_t jobs, const std::vector<InputDigest>& inputs)
    : options_(options), jobs_(jobs), inputs_(inputs), last_flush_(std::chrono::steady_clock::now()) {
    std::string preamble = kDigestLine + digest + "\n";
    for (const InputDigest& input : inputs_) preamble += input_line(input) + "\n";
    preamble += header;
    preamble_lines_ = static_cast<std::size_t>(std::count(preamble.begin(), preamble.end(), '\n'));
    try {
        open(preamble, digest);
    } catch (...) {
        discard_unless_rows_kept();  // a header that could not be written (a full disk) leaves nothing
        if (fd_ >= 0) ::close(fd_);  // and its lock: the destructor does not run
        fd_ = -1;
        throw;
    }
}

void ResultsFile::open(const std::string& preamble, const std::string& digest) {
    if (options_.path.empty()) {
        if (options_.resume) throw ResultsError("--resume needs --output: rows written to standard output cannot be resumed");
        write_all(preamble);
        return;
    }
    struct stat target {};
    if (::stat(options_.path.c_str(), &target) == 0 && !S_ISREG(target.st_mode))
        throw ResultsError(options_.path + ": not a regular file (the results are written beside it as " + partial_path() +
                           ", then renamed)");
    if (!options_.resume) {
        if (exists(partial_path()) && locked_by_another(partial_path())) throw ResultsError(held_by_another(partial_path()));
        if (exists(partial_path()) && exists(state_path()))
            throw ResultsError(partial_path() + " exists: an interrupted batch's results. Add --resume to complete it, or "
                               "remove " + partial_path() + " and " + state_path() + " to start over");
        // Only the files there are named: a message naming one that is not sends the user looking for it.
        if (exists(partial_path()))
            throw ResultsError(partial_path() + " exists, with no state file: a run that ended before it kept a row "
                               "left it. Add --resume to start over in it, or remove " + partial_path());
        start_fresh(preamble);
        return;
    }
    if (exists(partial_path()) && resume_partial(digest)) return;
    if (!exists(partial_path()) && exists(options_.path)) {
        check_complete(digest);
        return;
    }
    start_fresh(preamble);  // nothing was committed yet
}

ResultsFile::~ResultsFile() {
    if (fd_ >= 0) ::close(fd_);  // the lock goes with it
}

std::size_t ResultsFile::done() const {
    std::lock_guard<std::mutex> lock(mutex_);
    return done_;
}

std::size_t ResultsFile::failed() const {
    std::lock_guard<std::mutex> lock(mutex_);
    return failed_;
}

std::size_t ResultsFile::kept() const {
    std::lock_guard<std::mutex> lock(mutex_);
    return written_done_;
}

void ResultsFile::start_fresh(const std::string& preamble) {
    if (fd_ < 0) {
        fd_ = ::open(partial_path().c_str(), O_RDWR | O_CREAT | O_CLOEXEC, 0666);
        if (fd_ < 0) throw ResultsError(partial_path() + ": cannot create: " + why(errno));
        if (::flock(fd_, LOCK_EX | LOCK_NB) != 0) {
            ::close(fd_);
            fd_ = -1;
            throw ResultsError(held_by_another(partial_path()));
        }
    }
    began_ = true;
    if (::ftruncate(fd_, 0) != 0 || ::lseek(fd_, 0, SEEK_SET) != 0)
        throw ResultsError(partial_path() + ": cannot write: " + why(errno));
    bytes_ = 0;
    digest_ = 0;
    done_ = failed_ = written_done_ = written_failed_ = 0;
    held_ = preamble;
    header_bytes_ = preamble.size();
    held_digest_ = header_digest(preamble);
    flush_locked();
}

// Takes up OUT.partial where its state says it is good.  False when it has
// no state yet (killed before its header was committed): start over.
bool ResultsFile::resume_partial(const std::string& digest) {
    fd_ = ::open(partial_path().c_str(), O_RDWR | O_CLOEXEC);
    if (fd_ < 0) throw ResultsError(partial_path() + ": cannot open: " + why(errno));
    if (::flock(fd_, LOCK_EX | LOCK_NB) != 0) {
        ::close(fd_);  // another run's files: this one holds no lock on them, and touches none
        fd_ = -1;
        throw ResultsError(held_by_another(partial_path()));
    }
    if (!exists(state_path())) return false;
    const std::string state = slurp(state_path());
    unsigned long long jobs = 0, failed = 0, bytes = 0, header = 0;
    char hex[65] = {};
    std::uint64_t sum = 0;
    std::string sha256;  // a state of a rocking before the sum of row terms
    if (std::sscanf(state.c_str(), "rocking batch state: jobs %llu failed %llu bytes %llu header %llu xxh3 %16s", &jobs,
                    &failed, &bytes, &header, hex) == 5 &&
        std::strlen(hex) == 16 && std::strspn(hex, "0123456789abcdef") == 16)
        sum = std::strtoull(hex, nullptr, 16);
    else if (std::sscanf(state.c_str(), "rocking batch state: jobs %llu failed %llu bytes %llu sha256 %64s", &jobs,
                         &failed, &bytes, hex) == 4 &&
             std::strlen(hex) == 64)
        sha256 = hex;
    else
        throw ResultsError(state_path() + ": not a state file of rocking batch; remove it and " + partial_path() +
                           " to start over");
    const std::string kept = verify_kept(jobs, bytes, header, sum, sha256);
    const std::string head = first_line(kept);
    if (head != kDigestLine + digest)
        throw ResultsError("the " + options_.jobs_from + " has changed since " + partial_path() + " was begun (its sha256 was " +
                           head.substr(std::min(head.size(), sizeof kDigestLine - 1)) + ", it is now " + digest +
                           "): the rows written are another " + options_.jobs_from + "'s jobs. Run the " + options_.jobs_from +
                           " it was begun with, or "
                           "remove " + partial_path() + " and " + state_path() + " to start over");
    check_inputs(kept, partial_path() + " was begun", "remove " + partial_path() + " and " + state_path() + " to start over");
    if (jobs > jobs_ || failed > jobs)
        throw ResultsError(state_path() + ": counts " + std::to_string(jobs) + " jobs, more than the " + options_.jobs_from + "'s " +
                           std::to_string(jobs_));
    if (::ftruncate(fd_, static_cast<off_t>(bytes)) != 0 || ::lseek(fd_, 0, SEEK_END) != static_cast<off_t>(bytes))
        throw ResultsError(partial_path() + ": cannot cut off the rows its state does not count: " + why(errno));
    bytes_ = bytes;
    done_ = written_done_ = jobs;
    failed_ = written_failed_ = failed;
    return true;
}

std::string ResultsFile::verify_kept(unsigned long long jobs, unsigned long long bytes, unsigned long long header,
                                     std::uint64_t digest, const std::string& sha256) {
    const bool old = !sha256.empty();
    // The header ends at the length the state gives, or (an old state) after this run's preamble's lines.
    std::string head;
    bool in_header = old ? preamble_lines_ > 0 : header > 0;
    std::size_t lines = 0;
    RowsDigest rows;
    Sha256 hash;
    std::vector<char> block(std::size_t{1} << 20);
    bool whole = header <= bytes;
    for (unsigned long long at = 0; whole && at < bytes;) {
        const ssize_t got = ::pread(fd_, block.data(), std::min<unsigned long long>(block.size(), bytes - at), static_cast<off_t>(at));
        if (got < 0 && errno == EINTR) continue;
        if (got <= 0) {
            whole = false;
            break;
        }
        const std::size_t n = static_cast<std::size_t>(got);
        if (old) hash.update(block.data(), n);
        std::size_t k = 0;
        for (; in_header && k < n; ++k) {
            head += block[k];
            in_header = old ? !(block[k] == '\n' && ++lines == preamble_lines_) : head.size() < header;
        }
        rows.feed(block.data() + k, n - k);
        at += n;
    }
    const std::uint64_t sum = header_digest(head) + rows.sum();
    if (!whole || in_header || (old ? hash.hex() != sha256 : sum != digest) || rows.rows() != jobs || rows.row_open())
        throw ResultsError(partial_path() + ": its first " + std::to_string(bytes) + " bytes do not match the checksum in " +
                           state_path() + " (the file was changed or damaged); remove both to start over");
    header_bytes_ = head.size();
    digest_ = sum;
    return head;
}

// --resume where OUT.partial is gone: the results at the path, when they are
// this manifest's and complete, are the answer.
void ResultsFile::check_complete(const std::string& digest) {
    const std::string text = slurp(options_.path);
    if (first_line(text) != kDigestLine + digest)
        throw ResultsError(options_.path + " holds no results of this " + options_.jobs_from + " (its first line is not '" + kDigestLine +
                           digest + "'): --resume has nothing to complete; run without --resume to replace it");
    const std::size_t last = text.rfind('\n', text.size() >= 2 ? text.size() - 2 : 0);
    const std::string end = text.substr(last == std::string::npos ? 0 : last + 1);
    unsigned long long jobs = 0, failed = 0;
    if (text.empty() || text.back() != '\n' ||
        std::sscanf(end.c_str(), "# end: %llu jobs, %llu failed", &jobs, &failed) != 2 || jobs != jobs_)
        throw ResultsError(options_.path + ": no '# end: " + std::to_string(jobs_) +
                           " jobs' line closes it: not a complete results file, and no " + partial_path() +
                           " to resume; run without --resume to replace it");
    check_inputs(text, options_.path + " was written", "run without --resume to replace it");
    ::unlink(state_path().c_str());  // a kill between the last rename and this removal left it
    done_ = written_done_ = jobs;
    failed_ = written_failed_ = failed;
    complete_ = true;
}

void ResultsFile::check_inputs(const std::string& text, const std::string& since, const std::string& remedy) const {
    // A digest as the messages say it: the hex digits, or why there are none.
    auto said = [](const std::string& digest) {
        return digest.size() == 64 ? digest : digest == "unreadable" ? "none (the file could not be read)" : digest;
    };
    std::istringstream in(text);
    std::string line;
    std::getline(in, line);  // the manifest's digest, checked before
    for (const InputDigest& input : inputs_) {
        if (!std::getline(in, line) || line.rfind(kInputLine, 0) != 0)
            throw ResultsError("no sha256 of " + input.name + " was kept when " + since + " (by a rocking before " +
                               "records' digests were kept): a resume cannot prove that the rows written were computed " +
                               "from the records as they are now; " + remedy);
        std::string was = line.substr(sizeof kInputLine - 1);
        was = was.substr(0, was.find(' '));
        if (input.digest.empty() || was == kUnverifiable)
            throw ResultsError(input.name + ", a record the " + options_.jobs_from + " names, " +
                               (input.digest.empty() ? "is" : "was") + " not a regular file when " +
                               (input.digest.empty() ? "resumed" : since) +
                               " (a pipe or a device): what the rows written were computed from cannot be read again " +
                               "to prove it unchanged, so they cannot be resumed; " + remedy);
        if (line != input_line(input))
            throw ResultsError(input.name + ", a record the " + options_.jobs_from + " names, has changed since " + since +
                               " (its sha256 was " + said(was) + ", it is now " + said(input.digest) +
                               "): the rows written were computed from the other file. Put that file back, or " + remedy);
    }
    if (std::getline(in, line) && line.rfind(kInputLine, 0) == 0)
        throw ResultsError("more records' digests were kept when " + since + " than the " + options_.jobs_from +
                           " names now; " + remedy);
}

void ResultsFile::discard_unless_rows_kept() {
    std::lock_guard<std::mutex> lock(mutex_);
    // Files this run holds no lock on are another run's, or a refused resume's: not ours to remove.
    if (options_.path.empty() || fd_ < 0) return;
    ::unlink(state_temporary().c_str());
    // A partial file begun again by a resume that found no state holds no row either.
    if (written_done_ > 0 || !began_) return;
    ::unlink(state_path().c_str());
    ::unlink(partial_path().c_str());
    ::close(fd_);  // the lock last: no other run finds the files half gone
    fd_ = -1;
}

void ResultsFile::append(const std::string& row, bool failed) {
    std::lock_guard<std::mutex> lock(mutex_);
    const std::size_t at = held_.size();
    held_ += row;
    held_ += '\n';
    held_digest_ += row_digest(std::string_view(held_).substr(at), done_);
    ++done_;
    failed_ += failed;
    const double since = std::chrono::duration<double>(std::chrono::steady_clock::now() - last_flush_).count();
    if (held_.size() >= options_.flush_bytes || since >= options_.flush_seconds) flush_locked();
}

void ResultsFile::append(const RowChunk& chunk) {
    std::lock_guard<std::mutex> lock(mutex_);
    const double since = std::chrono::duration<double>(std::chrono::steady_clock::now() - last_flush_).count();
    if (since < options_.flush_seconds && held_.size() + chunk.text.size() < options_.flush_bytes) {
        held_ += chunk.text;  // no flush due inside the chunk: it goes whole
        held_digest_ += chunk.digest;
        done_ += chunk.count();
        failed_ += chunk.failed;
        return;
    }
    // A flush is due inside the chunk: row by row, as append(row) would, so that
    // the held bytes stay within flush_bytes and a flush after each row
    // (flush_seconds 0) is one after each row.
    std::size_t at = 0;
    for (const std::uint32_t entry : chunk.lengths) {
        held_.append(chunk.text, at, RowChunk::length(entry));
        held_digest_ += row_digest(std::string_view(chunk.text).substr(at, RowChunk::length(entry)), done_);
        at += RowChunk::length(entry);
        ++done_;
        failed_ += RowChunk::failed_row(entry);
        const double now = std::chrono::duration<double>(std::chrono::steady_clock::now() - last_flush_).count();
        if (held_.size() >= options_.flush_bytes || now >= options_.flush_seconds) flush_locked();
    }
}

void ResultsFile::flush() {
    std::lock_guard<std::mutex> lock(mutex_);
    if (!finished_ && !complete_) flush_locked();
}

void ResultsFile::write_all(const std::string& text) {
    if (options_.path.empty()) {
        if (std::fwrite(text.data(), 1, text.size(), stdout) != text.size() || std::fflush(stdout) != 0)
            throw ResultsError("standard output: cannot write the results: " + why(errno));
        return;
    }
    for (std::size_t at = 0; at < text.size();) {
        const ssize_t n = ::write(fd_, text.data() + at, text.size() - at);
        if (n < 0 && errno == EINTR) continue;
        if (n < 0) throw ResultsError(partial_path() + ": cannot write: " + why(errno));
        at += static_cast<std::size_t>(n);
    }
}

void ResultsFile::flush_locked() {
    last_flush_ = std::chrono::steady_clock::now();
    if (placing_) {
        // Own chunks are on the disk once this sync returns, the others once their writers said so.
        if (own_unsynced_ && ::fdatasync(fd_) != 0) throw ResultsError(partial_path() + ": cannot sync: " + why(errno));
        own_unsynced_ = false;
        std::size_t jobs = written_done_, failed = written_failed_;
        unsigned long long bytes = bytes_;
        std::uint64_t digest = digest_;
        for (; !placed_.empty() && (placed_.front().own || placed_.front().synced); placed_.pop_front(), ++placed_before_) {
            const ChunkSummary& c = placed_.front().chunk;
            jobs += c.count, failed += c.failed, bytes += c.bytes, digest += c.digest;
        }
        if (jobs == written_done_) return;
        bytes_ = bytes, digest_ = digest;
        write_state(jobs, failed);
        written_done_ = jobs, written_failed_ = failed;
        return;
    }
    if (held_.empty()) return;
    write_all(held_);
    if (options_.path.empty()) {
        held_.clear();
        written_done_ = done_, written_failed_ = failed_;
        return;
    }
    bytes_ += held_.size();
    digest_ += held_digest_;
    held_digest_ = 0;
    held_.clear();
    // The rows reach the disk before the state that counts them.
    if (::fdatasync(fd_) != 0) throw ResultsError(partial_path() + ": cannot sync: " + why(errno));
    // Counted as kept only once the state on the disk counts them: a state that could not be
    // written leaves the rows uncounted, and the files removable (discard_unless_rows_kept).
    write_state(done_, failed_);
    written_done_ = done_;
    written_failed_ = failed_;
}

void ResultsFile::write_state(std::size_t jobs, std::size_t failed) {
    const std::string temporary = state_temporary();
    char text[200];
    std::snprintf(text, sizeof text, "%s jobs %zu failed %zu bytes %llu header %llu xxh3 %s\n", kStateLine, jobs, failed,
                  bytes_, header_bytes_, digest_hex(digest_).c_str());
    const int fd = ::open(temporary.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0666);
    if (fd < 0) throw ResultsError(temporary + ": cannot create: " + why(errno));
    const std::size_t size = std::strlen(text);
    // A short write sets no errno: the next one says why (a full disk, a file size limit).
    std::size_t written = 0;
    for (ssize_t n = 0; written < size && (n = ::write(fd, text + written, size - written)) != 0;) {
        if (n < 0 && errno == EINTR) continue;
        if (n < 0) break;
        written += static_cast<std::size_t>(n);
    }
    const bool ok = written == size && ::fsync(fd) == 0;
    const int error = errno;
    ::close(fd);
    if (!ok || std::rename(temporary.c_str(), state_path().c_str()) != 0) {
        const int failure = ok ? errno : error;
        ::unlink(temporary.c_str());  // half a state, of no use to a resume (a full disk left it)
        throw ResultsError(state_path() + ": cannot write: " + why(failure));
    }
}

ResultsFile::Placement ResultsFile::place(const ChunkSummary& chunk) {
    std::lock_guard<std::mutex> lock(mutex_);
    if (!placing_) {
        flush_locked();  // the header, before the first chunk's offset is taken from it
        placing_ = true;
        placed_end_ = bytes_;
    }
    const Placement at{placed_before_ + placed_.size(), placed_end_};
    placed_end_ += chunk.bytes;
    done_ += chunk.count, failed_ += chunk.failed;
    placed_.push_back({chunk, false, false});
    return at;
}

void ResultsFile::write_own(const Placement& at, const std::string& text) {
    write_at_locked(at.offset, text);  // pwrite: no lock needed, and none held while it copies
    std::lock_guard<std::mutex> lock(mutex_);
    // Not own until written: a flush before (a signal's) must not count it.
    if (at.number >= placed_before_ && at.number - placed_before_ < placed_.size()) placed_[at.number - placed_before_].own = true;
    own_unsynced_ = true;
}

void ResultsFile::place_own(const RowChunk& chunk) { write_own(place(chunk.summary()), chunk.text); }

void ResultsFile::synced(std::size_t number) {
    std::lock_guard<std::mutex> lock(mutex_);
    if (number >= placed_before_ && number - placed_before_ < placed_.size()) placed_[number - placed_before_].synced = true;
}

std::uint64_t ResultsFile::write_probe(const std::string& text) {
    std::lock_guard<std::mutex> lock(mutex_);
    flush_locked();
    write_at_locked(bytes_, text);
    if (::fdatasync(fd_) != 0) throw ResultsError(partial_path() + ": cannot sync: " + why(errno));
    return bytes_;
}

void ResultsFile::clear_probe() {
    std::lock_guard<std::mutex> lock(mutex_);
    if (::ftruncate(fd_, static_cast<off_t>(bytes_)) != 0)
        throw ResultsError(partial_path() + ": cannot cut off its probe: " + why(errno));
}

void ResultsFile::write_at_locked(std::uint64_t offset, const std::string& text) {
    for (std::size_t at = 0; at < text.size();) {
        const ssize_t n = ::pwrite(fd_, text.data() + at, text.size() - at, static_cast<off_t>(offset + at));
        if (n < 0 && errno == EINTR) continue;
        if (n <= 0) throw ResultsError(partial_path() + ": cannot write: " + why(n < 0 ? errno : ENOSPC));
        at += static_cast<std::size_t>(n);
    }
}

void ResultsFile::finish() {
    std::lock_guard<std::mutex> lock(mutex_);
    if (complete_ || finished_) return;
    if (placing_) {
        flush_locked();
        if (written_done_ != done_)
            throw ResultsError(partial_path() + ": " + std::to_string(done_ - written_done_) +
                               " rows placed were never synced by the ranks that wrote them");
        write_at_locked(placed_end_, end_line(done_, failed_));
    } else {
        held_ += end_line(done_, failed_);
        write_all(held_);
        held_.clear();
    }
    finished_ = true;
    if (options_.path.empty()) return;
    if (::fsync(fd_) != 0) throw ResultsError(partial_path() + ": cannot sync: " + why(errno));
    if (std::rename(partial_path().c_str(), options_.path.c_str()) != 0)
        throw ResultsError(options_.path + ": cannot move " + partial_path() + " into its place: " + why(errno));
    ::unlink(state_path().c_str());
}

void ResultsFile::read_rows(const std::string& path, std::size_t header_lines,
                            const std::function<void(std::size_t, const std::string&)>& row) {
    std::ifstream in(path, std::ios::binary);
    if (!in) throw ResultsError(path + ": cannot read: " + why(errno));
    std::string line;
    for (std::size_t k = 0; k <= header_lines; ++k)
        if (!std::getline(in, line)) throw ResultsError(path + ": ends inside its header");
    std::size_t rows = 0;
    while (std::getline(in, line)) {
        if (line.rfind("# end: ", 0) == 0) return;
        // A quoted cell's line break belongs to the row (RFC 4180).
        for (std::string more; !csv_record_end(line, 0).closed && std::getline(in, more);) line += "\n" + more;
        row(rows++, line);
    }
    throw ResultsError(path + ": has no end line: not a finished results file");
}

}  // namespace rocking::batch
