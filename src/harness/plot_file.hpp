// A PNG that another program draws (gnuplot) and that lands at its path
// whole or not at all (issue 38).
//
// gnuplot exits 0 when its writes fail: on a full disk it left a PNG without
// its end (no IEND chunk) that was renamed into place, and `--png /dev/full`
// "succeeded".  So gnuplot draws into a regular temporary file, commit()
// reads the PNG's chunks to its IEND and only then moves it into place: by
// rename beside a regular target (AtomicFile), or by copying its bytes to a
// target that is a device or a FIFO, where the write's failure is reported.
#pragma once

#include <memory>
#include <string>

#include "harness/atomic_file.hpp"

namespace rocking::harness {

// Empty when the file at path is a whole PNG: the signature, then chunks
// each inside the file, the last one IEND, ending at the file's end;
// otherwise what is wrong ("no IEND chunk: the file is cut at byte 30720").
std::string png_fault(const std::string& path);

class PlotFile {
public:
    // Throws std::runtime_error naming the target when nothing can be drawn for it.
    explicit PlotFile(const std::string& target);
    PlotFile(const PlotFile&) = delete;
    PlotFile& operator=(const PlotFile&) = delete;
    ~PlotFile();

    // Where the drawing program writes the PNG: a file we created, in the target's
    // folder (or, for a device, the temporary folder), whose name is plain characters
    // (".rocking.tmpXXXXXX").  A script should name it as draw_name() and run in
    // draw_folder(), so that no byte of the target's path or its folder's passes
    // through the script's quoting: gnuplot, given a name with a newline as '?',
    // drew into another file, which was left behind.
    const std::string& draw_path() const { return draw_; }
    std::string draw_folder() const;
    std::string draw_name() const;
    // Checks the PNG is whole and moves it into place; throws std::runtime_error
    // naming the target otherwise, leaving nothing at a regular target.
    void commit();

private:
    std::string target_;
    std::unique_ptr<AtomicFile> beside_;  // a regular target: gnuplot draws into its temporary file
    std::string draw_;
    bool own_draw_ = false;  // a device target: draw_ is ours to remove
};

}  // namespace rocking::harness
