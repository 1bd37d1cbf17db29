// Strong-motion records: one type for every source format.  Samples are held
// in m/s^2 internally; every reader refuses a malformed file with an error
// that names the file, the line and the problem.
#pragma once

#include <cstddef>
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
// "path:line: problem", or "path: problem" where no line is at fault (line 0:
// the file cannot be opened or read as a whole).
struct RecordError : std::runtime_error {
    RecordError(const std::string& path, int line, const std::string& problem)
        : std::runtime_error(path + (line > 0 ? ":" + std::to_string(line) : std::string()) + ": " + problem) {}
};

// Caps on what a reader takes in, so that /dev/zero, an endless line or a
// FIFO nobody writes to ends with an error naming the file and the cap
// instead of growing or waiting without bound.  Real records sit far inside
// them: the largest file in ../shared/records is 329 KB, its longest line
// 442 bytes, an ESM header about 4 KB.
struct ReadLimits {
    std::size_t max_bytes = std::size_t{256} << 20;  // a whole file: 256 MiB (about 10^7 samples)
    std::size_t max_line = std::size_t{1} << 20;     // one line: 1 MiB
    double timeout_s = 10;                           // a pipe or FIFO silent this long, s
};
// ESM's 'KEY: value' lines before the first sample: 1 MiB.
constexpr std::size_t kMaxHeaderBytes = std::size_t{1} << 20;

// The whole file, read once: a pipe, a FIFO or /dev/stdin cannot be opened a
// second time to read what sniffing its format consumed.  Refuses a folder,
// a file or line over the caps, and a pipe silent for timeout_s (waiting
// for its first byte or after one).
std::string read_text(const std::string& path, const ReadLimits& limits = {});

// The readers of a file's text (from read_text); `path` names it in errors.
//
// ESM/ITACA ASCII ("DYNA 1.2"): 'KEY: value' header lines, then one sample per
// line in cm/s^2.  Checks SAMPLING_INTERVAL_S > 0, UNITS = cm/s^2, NDATA equal
// to the samples read and PGA_CM/S^2 equal to max |a| (to its printed digits).
Record parse_esm(const std::string& text, const std::string& path);
// PEER NGA .AT2: four header lines (the fourth 'NPTS= n, DT= dt SEC'), then
// samples in g, several per line.  Checks NPTS against the samples read.
Record parse_peer(const std::string& text, const std::string& path);
// By content: ESM when the first line is 'KEY: value', PEER otherwise.
Record parse_any(const std::string& text, const std::string& path);
// Plain text: two columns 'time acceleration' (evenly spaced times; dt = 0) or
// one column with the given dt > 0, in `unit` (g, m/s2, cm/s2).  Comma,
// space or tab separated; lines starting with '#' are comments.  Decimal
// commas are not read: a file whose values have no decimal point and a comma
// between two digits ("0,0123") is refused, as that comma could be either.
Record parse_plain(const std::string& text, const std::string& path, const std::string& unit, double dt);

// Whether the text is ESM ASCII (a first line 'KEY: value', not a '#'
// comment) or PEER AT2 ('UNITS OF G' on line 3): a file that states its own
// unit and step, which a plain-text unit must not override.
bool states_its_units(const std::string& text);

// The same, reading the file with read_text's default caps.
Record read_esm(const std::string& path);
Record read_peer(const std::string& path);
Record read_any(const std::string& path);
Record read_plain(const std::string& path, const std::string& unit, double dt);
// read_plain for a plain-text file, read_any for one that states its units:
// a study's --unit and --dt apply to its plain-text records only, so that
// ESM, AT2 and text records can be mixed in one command.
Record read_with_unit(const std::string& path, const std::string& unit, double dt);

}  // namespace rocking::records
