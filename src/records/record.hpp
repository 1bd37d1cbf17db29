// Strong-motion records: one type for every source format.  Samples are held
// in m/s^2 internally; every reader refuses a malformed file with an error
// that names the file, the line and the problem.
#pragma once

#include <map>
#include <stdexcept>
#include <string>
#include <vector>

namespace rocking::records {

struct Record {
    std::string path;
    std::string format;                         // "ESM ASCII", "PEER AT2"
    std::string name;                           // station, stream, event
    double dt = 0.0;                            // s
    std::vector<double> accel;                  // m/s^2, paper's sign as recorded
    std::map<std::string, std::string> header;  // the source's header fields

    double duration() const { return dt * (accel.size() - 1); }
    double pga() const;                         // max |a|, m/s^2
    // The samples in units of g (the dynamics engine's input unit).
    std::vector<double> in_g(double g = 9.81) const;
};

// A malformed file: what() reads "<path>:<line>: <problem>" (line 0: the whole file).
struct RecordError : std::runtime_error {
    RecordError(const std::string& path, int line, const std::string& problem)
        : std::runtime_error(path + ":" + std::to_string(line) + ": " + problem) {}
};

// ESM/ITACA ASCII ("DYNA 1.2"): 'KEY: value' header lines, then one sample per
// line in cm/s^2.  Checks SAMPLING_INTERVAL_S > 0, UNITS = cm/s^2, NDATA equal
// to the samples read and PGA_CM/S^2 equal to max |a| (to its printed digits).
Record read_esm(const std::string& path);
// PEER NGA .AT2: four header lines (the fourth 'NPTS= n, DT= dt SEC'), then
// samples in g, several per line.  Checks NPTS against the samples read.
Record read_peer(const std::string& path);
// By content: ESM when the first line is 'KEY: value', PEER otherwise.
Record read_any(const std::string& path);
// Plain text: two columns 'time acceleration' (evenly spaced times; dt = 0) or
// one column with the given dt > 0, in `unit` (g, m/s2, cm/s2).  Comma,
// space or tab separated; lines starting with '#' are comments.
Record read_plain(const std::string& path, const std::string& unit, double dt);

}  // namespace rocking::records
