// A file that appears at its path complete, or not at all.
//
// Two runs writing the same --output mixed one's header with the other's
// body, and a full disk or a SIGTERM left a truncated CSV.  So the text goes
// to a temporary file beside the target, .NAME.tmpXXXXXX (in the same folder:
// rename() is atomic only within one file system), which commit() flushes,
// syncs, closes and renames over the target.  Readers see the old file or the
// new one, whole; of two writers, the last rename wins.  On any failure the
// temporary file is removed and the error names the target and the problem;
// SIGTERM, SIGINT and SIGHUP remove it too before the process ends (a SIGKILL
// leaves it, under its dot-name).
//
// A target that exists and is not a regular file (/dev/null, /dev/stdout, a
// FIFO) is written in place: nothing there can be replaced atomically, and a
// rename would replace the device itself.  A symbolic link to a file is
// followed, so the link stays and its target is replaced.
#pragma once

#include <cstdio>
#include <string>

namespace rocking::harness {

class AtomicFile {
public:
    // How the temporary file beside the target is named: ".NAME.tmpXXXXXX" (NAME the
    // target's, so that a leftover says whose it was), or ".rocking.tmpXXXXXX", plain
    // characters whatever the target's name, for a path another program must read
    // from a script (gnuplot read a newline in NAME as '?' and drew into another file).
    enum class Temporary { named_after_target, plain };
    // Throws std::runtime_error ("PATH: cannot create a file in DIR: reason").
    explicit AtomicFile(const std::string& path, Temporary naming = Temporary::named_after_target);
    AtomicFile(const AtomicFile&) = delete;
    AtomicFile& operator=(const AtomicFile&) = delete;
    // Removes the temporary file unless commit() succeeded.
    ~AtomicFile();

    // Throws std::runtime_error on a failed write, after which nothing lands at the path.
    void write(const std::string& text);
    // Flushes, syncs, closes and renames into place; throws std::runtime_error on failure.
    void commit();
    // Where another program may write the content itself (gnuplot) before commit().
    const std::string& temporary_path() const { return temp_; }

private:
    [[noreturn]] void fail(const std::string& what, int error);
    void discard();

    std::string path_;  // the target, symbolic links resolved
    std::string shown_;  // the target as the caller named it, for messages
    std::string temp_;   // == path_ when written in place
    std::FILE* file_ = nullptr;
    bool in_place_ = false;
    bool committed_ = false;
    int slot_ = -1;  // in the signal handler's list of temporary files
};

// At the end of main: flushes standard output and, when a write to it
// failed (a full disk behind > FILE), says so on stderr as "PROGRAM: error
// writing standard output: reason" and turns a 0 status into 1.  A closed
// pipe ends the process by SIGPIPE before this, quietly, as other Unix tools
// end; with SIGPIPE ignored the write fails with EPIPE and is reported here.
int finish_standard_output(const char* program, int status);

}  // namespace rocking::harness
