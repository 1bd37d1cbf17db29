#include "records/record.hpp"

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <chrono>
#include <climits>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <sstream>

#include <fcntl.h>
#include <poll.h>
#include <sys/stat.h>
#include <unistd.h>

#include "numerics/number_text.hpp"

namespace rocking::records {

double Record::pga() const {
    double m = 0;
    for (double a : accel) m = std::max(m, std::fabs(a));
    return m;
}

std::vector<double> Record::in_g(double g) const {
    std::vector<double> out(accel.size());
    for (std::size_t k = 0; k < accel.size(); ++k) out[k] = accel[k] / g;
    return out;
}

namespace {

std::string trim(const std::string& s) {
    const auto a = s.find_first_not_of(" \t\r"), b = s.find_last_not_of(" \t\r");
    return a == std::string::npos ? "" : s.substr(a, b - a + 1);
}

// A whole token as a sample, or false: numerics' rule for samples (a
// subnormal reads as itself, as numpy and record synth write it).
bool parse_number(const std::string& token, double& value) { return numerics::sample_number(token, value); }

// A header's value (a step, a count, a peak): a parameter of the record, held
// to the options' rule (no subnormal).
bool header_number(const std::string& token, double& value) {
    const numerics::NumberRead r = numerics::read_number(token);
    value = r.value;
    return r.problem == numerics::NumberProblem::none;
}

// A comma between two digits, as a decimal comma writes "0,0123".
bool digit_comma_digit(const std::string& t) {
    for (std::size_t k = 1; k + 1 < t.size(); ++k)
        if (t[k] == ',' && std::isdigit(static_cast<unsigned char>(t[k - 1])) &&
            std::isdigit(static_cast<unsigned char>(t[k + 1])))
            return true;
    return false;
}

// What is wrong with a token parse_number() refused, in the number reader's words.
std::string refused(const std::string& token) {
    return numerics::number_problem(token, numerics::read_number(token).problem);
}

// PEER AT2's third header line names its unit: "... UNITS OF G".
// "UNITS OF G" as a word: "UNITS OF GAL" (cm/s^2) is another unit, which
// the samples, read as g, would turn 981 times too strong.
bool peer_units_line(std::string line) {
    std::transform(line.begin(), line.end(), line.begin(), ::toupper);
    const auto at = line.find("UNITS OF G");
    if (at == std::string::npos) return false;
    const std::size_t after = at + 10;
    return after == line.size() || !std::isalnum(static_cast<unsigned char>(line[after]));
}

// "256 MiB" for the caps' messages ("100 bytes" for a cap a test chose).
std::string size_text(std::size_t bytes) {
    if (bytes >= (1u << 20) && bytes % (1u << 20) == 0) return std::to_string(bytes >> 20) + " MiB";
    return std::to_string(bytes) + " bytes";
}

std::string seconds_text(double s) {
    std::ostringstream os;
    os << s << " s";
    return os.str();
}

// The line being read when `text` has been read so far (1 for the first).
int line_at_end(const std::string& text) {
    return 1 + static_cast<int>(std::count(text.begin(), text.end(), '\n'));
}

// Closes the descriptor whatever the reader throws.
struct Descriptor {
    int fd;
    ~Descriptor() {
        if (fd >= 0) ::close(fd);
    }
};

// Non-blocking, so that opening a FIFO without a writer returns at once (a
// blocking open would wait for one for ever); poll() then does the waiting.
int open_for_reading(const std::string& path) {
    const int fd = ::open(path.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC);
    if (fd < 0) throw RecordError(path, 0, std::string("cannot open the file (") + std::strerror(errno) + ")");
    return fd;
}

// Waits for bytes (or the writer's end) on a pipe, FIFO or terminal.  A FIFO
// whose writer has not come yet reads as its end: poll() is what tells the
// two apart, as it does not return before a writer has come.
void wait_for_data(int fd, const std::string& path, const std::string& text, double timeout_s) {
    using clock = std::chrono::steady_clock;
    const auto deadline = clock::now() + std::chrono::duration<double>(timeout_s);
    pollfd p{fd, POLLIN, 0};
    for (;;) {
        const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(deadline - clock::now()).count();
        const int ready = ::poll(&p, 1, static_cast<int>(std::clamp<long long>(left, 0, INT_MAX)));
        if (ready > 0) return;
        if (ready < 0 && errno == EINTR) continue;
        if (ready < 0) throw RecordError(path, 0, std::string("cannot wait for data (") + std::strerror(errno) + ")");
        if (text.empty())
            throw RecordError(path, 0, "no data within " + seconds_text(timeout_s) +
                                           " (the read timeout): a pipe or FIFO that nobody writes to?");
        throw RecordError(path, line_at_end(text), "no more data for " + seconds_text(timeout_s) + " after " +
                                                       std::to_string(text.size()) +
                                                       " bytes (the read timeout): the writer stalled");
    }
}

// Refuses the chunk about to be appended to `text` when it makes the file or
// one of its lines longer than the caps; `line` is the length of the last,
// unfinished line so far, carried from chunk to chunk.
void check_caps(const std::string& path, const std::string& text, const char* chunk, std::size_t n,
                std::size_t& line, const ReadLimits& limits) {
    if (text.size() + n > limits.max_bytes)
        throw RecordError(path, 0, "larger than " + size_text(limits.max_bytes) +
                                       " (the cap on a record file's size)");
    const char* at = chunk;
    const char* const end = chunk + n;
    while (at < end) {
        const char* newline = static_cast<const char*>(std::memchr(at, '\n', end - at));
        line += (newline ? newline : end) - at;
        if (line > limits.max_line) {
            const int number = line_at_end(text) + static_cast<int>(std::count(chunk, at, '\n'));
            throw RecordError(path, number, "a line longer than " + size_text(limits.max_line) +
                                                " (the cap on a line's length): not a text record?");
        }
        if (!newline) break;
        line = 0;
        at = newline + 1;
    }
}

// The lines of a text, one at a time, as std::getline gives them from a file.
class Lines {
  public:
    explicit Lines(const std::string& text) : text_(text) {}
    bool next(std::string& line) {
        if (at_ >= text_.size()) return false;
        std::size_t end = text_.find('\n', at_);
        if (end == std::string::npos) end = text_.size();
        line.assign(text_, at_, end - at_);
        at_ = end + 1;
        return true;
    }

  private:
    const std::string& text_;
    std::size_t at_ = 0;
};

// Number of decimals printed in a header value (for the PGA comparison).
int decimals(const std::string& text) {
    const auto dot = text.find('.');
    return dot == std::string::npos ? 0 : static_cast<int>(text.size() - dot - 1);
}

}  // namespace

std::string read_text(const std::string& path, const ReadLimits& limits) {
    const Descriptor in{open_for_reading(path)};
    struct stat st {};
    if (::fstat(in.fd, &st) != 0) throw RecordError(path, 0, std::string("cannot read the file (") + std::strerror(errno) + ")");
    // A folder opens and reads nothing, which read as "empty file".
    if (S_ISDIR(st.st_mode)) throw RecordError(path, 0, "is a folder, not a record file");
    const bool regular = S_ISREG(st.st_mode);
    if (regular && static_cast<unsigned long long>(st.st_size) > limits.max_bytes)
        throw RecordError(path, 0, "larger than " + size_text(limits.max_bytes) + " (the cap on a record file's size)");
    std::string text;
    text.reserve(regular ? static_cast<std::size_t>(st.st_size) + 1 : std::size_t{1} << 16);
    std::vector<char> chunk(std::size_t{1} << 16);
    std::size_t line = 0;
    for (;;) {
        if (!regular) wait_for_data(in.fd, path, text, limits.timeout_s);
        const ssize_t n = ::read(in.fd, chunk.data(), chunk.size());
        if (n == 0) break;
        if (n < 0 && (errno == EINTR || errno == EAGAIN || errno == EWOULDBLOCK)) continue;
        if (n < 0) throw RecordError(path, line_at_end(text), std::string("cannot read the file (") + std::strerror(errno) + ")");
        check_caps(path, text, chunk.data(), static_cast<std::size_t>(n), line, limits);
        text.append(chunk.data(), static_cast<std::size_t>(n));
    }
    return text;
}

Record parse_esm(const std::string& text, const std::string& path) {
    Lines in(text);
    Record r;
    r.path = path;
    r.format = "ESM ASCII";
    std::string line;
    int number = 0;
    std::map<std::string, int> line_of;
    bool in_header = true;
    std::size_t header_bytes = 0;
    while (in.next(line)) {
        ++number;
        const std::string t = trim(line);
        if (in_header) {
            const auto colon = t.find(':');
            double v;
            if (colon != std::string::npos && !parse_number(t, v)) {
                // Each key is kept: a file of endless 'KEY: value' lines would fill memory with them.
                header_bytes += line.size() + 1;
                if (header_bytes > kMaxHeaderBytes)
                    throw RecordError(path, number, "a header longer than " + size_text(kMaxHeaderBytes) +
                                                        " (the cap on an ESM header's size)");
                const std::string key = trim(t.substr(0, colon));
                r.header[key] = trim(t.substr(colon + 1));
                line_of[key] = number;
                continue;
            }
            in_header = false;
        }
        if (t.empty()) continue;
        double v;
        if (!parse_number(t, v)) throw RecordError(path, number, "sample " + refused(t));
        r.accel.push_back(v);
    }
    if (r.header.empty() && r.accel.empty()) throw RecordError(path, 0, "empty file");
    for (const char* key : {"SAMPLING_INTERVAL_S", "NDATA", "UNITS", "PGA_CM/S^2"})
        if (!r.header.count(key)) throw RecordError(path, 0, std::string("missing header key ") + key);
    double dt, ndata, pga;
    if (!header_number(r.header["SAMPLING_INTERVAL_S"], dt) || !(dt > 0))
        throw RecordError(path, line_of["SAMPLING_INTERVAL_S"], "SAMPLING_INTERVAL_S must be a number > 0");
    if (!header_number(r.header["NDATA"], ndata) || ndata != std::floor(ndata) || ndata < 2)
        throw RecordError(path, line_of["NDATA"], "NDATA must be a whole number >= 2");
    if (r.header["UNITS"] != "cm/s^2")
        throw RecordError(path, line_of["UNITS"], "UNITS is '" + r.header["UNITS"] + "', expected cm/s^2");
    if (!header_number(r.header["PGA_CM/S^2"], pga))
        throw RecordError(path, line_of["PGA_CM/S^2"], "PGA_CM/S^2 is not a number");
    if (r.accel.size() != static_cast<std::size_t>(ndata))
        throw RecordError(path, line_of["NDATA"], "NDATA says " + r.header["NDATA"] + " samples, the file has " +
                                                      std::to_string(r.accel.size()));
    const double peak = r.pga();  // still in cm/s^2 here
    // The header's PGA is signed (the sign of the peak) and comes from ESM's
    // own data; the samples are single-precision values printed to fixed
    // decimals (seen: relative differences up to 4e-8).  1e-6 relative plus
    // half a unit of the printed digit separates that from a wrong header.
    const double allowed = 0.5 * std::pow(10.0, -decimals(r.header["PGA_CM/S^2"])) + 1e-6 * std::fabs(pga);
    if (std::fabs(peak - std::fabs(pga)) > allowed) {
        std::ostringstream os;
        os.precision(10);
        os << "PGA_CM/S^2 says " << r.header["PGA_CM/S^2"] << ", max |a| of the samples is " << peak;
        throw RecordError(path, line_of["PGA_CM/S^2"], os.str());
    }
    r.dt = dt;
    for (double& a : r.accel) a *= 0.01;  // cm/s^2 -> m/s^2
    r.name = r.header["NETWORK"] + "." + r.header["STATION_CODE"] + " " + r.header["STREAM"] + " " +
             r.header["EVENT_DATE_YYYYMMDD"] + "_" + r.header["EVENT_TIME_HHMMSS"];
    return r;
}

Record parse_peer(const std::string& text, const std::string& path) {
    Lines in(text);
    Record r;
    r.path = path;
    r.format = "PEER AT2";
    std::string line;
    int number = 0;
    long npts = -1;
    while (in.next(line)) {
        ++number;
        if (number <= 3) {
            r.header["LINE" + std::to_string(number)] = trim(line);
            if (number == 3 && !peer_units_line(line))
                throw RecordError(path, 3, "expected 'UNITS OF G' on the third header line");
            continue;
        }
        if (number == 4) {
            std::string upper = line;
            std::transform(upper.begin(), upper.end(), upper.begin(), ::toupper);
            const auto n = upper.find("NPTS="), d = upper.find("DT=");
            if (n == std::string::npos || d == std::string::npos)
                throw RecordError(path, 4, "expected 'NPTS= n, DT= dt SEC'");
            std::string npts_text = trim(upper.substr(n + 5, upper.find(',', n) - n - 5));
            std::string dt_text = trim(upper.substr(d + 3));
            dt_text = trim(dt_text.substr(0, dt_text.find_first_of(" ,S")));
            double v;
            if (!header_number(npts_text, v) || v != std::floor(v) || v < 2)
                throw RecordError(path, 4, "NPTS '" + npts_text + "' is not a whole number >= 2");
            npts = static_cast<long>(v);
            if (!header_number(dt_text, r.dt) || !(r.dt > 0)) throw RecordError(path, 4, "DT '" + dt_text + "' must be > 0");
            r.header["NPTS"] = npts_text;
            r.header["DT"] = dt_text;
            continue;
        }
        std::istringstream ss(line);
        std::string token;
        while (ss >> token) {
            double v;
            if (!parse_number(token, v)) throw RecordError(path, number, "sample " + refused(token));
            r.accel.push_back(v * 9.81);  // g -> m/s^2 (NGA files use g = 9.81 m/s^2)
            if (!std::isfinite(r.accel.back()))
                throw RecordError(path, number, "sample '" + token + "' g is out of range for a double in m/s^2");
        }
    }
    if (number == 0) throw RecordError(path, 0, "empty file");
    if (npts < 0) throw RecordError(path, number, "the header ends before the NPTS line");
    if (static_cast<long>(r.accel.size()) != npts)
        throw RecordError(path, 4, "NPTS says " + std::to_string(npts) + " samples, the file has " +
                                       std::to_string(r.accel.size()));
    r.name = r.header["LINE2"];
    return r;
}

namespace {

// Samples in `unit` times this are m/s^2; an unknown unit or a bad step is
// refused before the file is read.
double scale_of(const std::string& path, const std::string& unit, double dt) {
    double scale;
    if (unit == "g") scale = 9.81;
    else if (unit == "m/s2" || unit == "m/s^2") scale = 1.0;
    else if (unit == "cm/s2" || unit == "cm/s^2") scale = 0.01;
    else throw RecordError(path, 0, "unknown unit '" + unit + "' (g, m/s2, cm/s2)");
    if (!(dt >= 0) || !std::isfinite(dt)) throw RecordError(path, 0, "time step must be > 0");
    return scale;
}

// The first data line with a comma between digits, when no value in the
// file has a decimal point: "0,0123" is then a decimal comma or two columns
// (0 and 123), readings that differ by orders of magnitude, so it is not
// guessed.  One decimal point anywhere settles that commas separate.
struct AmbiguousComma {
    int line = 0;  // 0: none
    std::string text;
};
AmbiguousComma ambiguous_comma(const std::string& text) {
    Lines in(text);
    std::string line;
    AmbiguousComma first;
    for (int number = 1; in.next(line); ++number) {
        const std::string t = trim(line);
        if (t.empty() || t[0] == '#') continue;
        if (t.find('.') != std::string::npos) return {};
        if (first.line == 0 && digit_comma_digit(t)) first = {number, t.size() > 40 ? t.substr(0, 40) + "..." : t};
    }
    return first;
}

}  // namespace

Record parse_plain(const std::string& text, const std::string& path, const std::string& unit, double dt) {
    const double scale = scale_of(path, unit, dt);
    if (const AmbiguousComma comma = ambiguous_comma(text); comma.line > 0)
        throw RecordError(path, comma.line,
                          "'" + comma.text + "' has a comma between digits and no value in the file has a decimal "
                          "point: decimal commas are not read, and this one cannot be told from a column separator; "
                          "write decimal points (one column: tr , . < FILE) or separate the columns with a space");
    Lines in(text);
    Record r;
    r.path = path;
    r.format = dt > 0 ? "one column" : "two columns";
    r.name = path;
    std::string line;
    int number = 0;
    std::vector<double> times;
    while (in.next(line)) {
        ++number;
        std::string t = trim(line);
        if (t.empty() || t[0] == '#') continue;
        std::replace(t.begin(), t.end(), ',', ' ');
        std::istringstream ss(t);
        std::vector<std::string> tokens;
        std::string token;
        while (ss >> token) tokens.push_back(token);
        const std::size_t want = dt > 0 ? 1 : 2;
        if (tokens.size() != want)
            throw RecordError(path, number,
                              std::to_string(tokens.size()) + " values, expected " + std::to_string(want) +
                                  (dt > 0 ? " (one column, acceleration, as the step dt is given)"
                                          : " (two columns, time and acceleration, as no step dt is given: give it "
                                            "for one column)"));
        std::vector<double> values;  // each token parsed once: [time,] acceleration
        for (const auto& tok : tokens) {
            double v;
            if (!parse_number(tok, v)) throw RecordError(path, number, refused(tok));
            values.push_back(v);
        }
        if (dt == 0) {
            const double time = values.front();
            if (!times.empty() && !(time > times.back()))
                throw RecordError(path, number, "time does not increase");
            if (times.size() >= 2) {
                const double step = times[1] - times[0];
                if (std::fabs((time - times.back()) - step) > 1e-6 * step)
                    throw RecordError(path, number, "uneven time step (the engine needs evenly spaced samples)");
            }
            times.push_back(time);
        }
        r.accel.push_back(values.back() * scale);
        if (!std::isfinite(r.accel.back()))
            throw RecordError(path, number, "'" + tokens.back() + "' " + unit + " is out of range for a double in m/s^2");
    }
    if (r.accel.empty()) throw RecordError(path, 0, "empty file");
    if (r.accel.size() < 2) throw RecordError(path, number, "a record needs at least 2 samples");
    r.dt = dt > 0 ? dt : times[1] - times[0];
    return r;
}

namespace {

enum class Stated { none, esm, peer };

// ESM's first line is 'KEY: value' (a '#' comment with a colon is plain
// text's); PEER's third says 'UNITS OF G'.
Stated stated_format(const std::string& text) {
    Lines in(text);
    std::string first, second, third;
    if (!in.next(first)) return Stated::none;
    if (first.rfind('#', 0) != 0 && first.find(':') != std::string::npos) return Stated::esm;
    in.next(second);
    in.next(third);
    return peer_units_line(third) ? Stated::peer : Stated::none;
}

}  // namespace

Record parse_any(const std::string& text, const std::string& path) {
    Lines in(text);
    std::string first;
    if (!in.next(first)) return parse_peer(text, path);  // empty: parse_peer says so
    switch (stated_format(text)) {
        case Stated::esm: return parse_esm(text, path);
        case Stated::peer: return parse_peer(text, path);
        case Stated::none: break;
    }
    throw RecordError(path, 1,
                      "neither ESM ASCII (its header lines are 'KEY: value') nor PEER AT2 ('UNITS OF G' on "
                      "line 3); plain one- or two-column text is read with its unit (rocking: --unit)");
}

bool states_its_units(const std::string& text) { return stated_format(text) != Stated::none; }

Record read_esm(const std::string& path) { return parse_esm(read_text(path), path); }
Record read_peer(const std::string& path) { return parse_peer(read_text(path), path); }
Record read_any(const std::string& path) { return parse_any(read_text(path), path); }
Record read_plain(const std::string& path, const std::string& unit, double dt) {
    scale_of(path, unit, dt);
    return parse_plain(read_text(path), path, unit, dt);
}
Record read_with_unit(const std::string& path, const std::string& unit, double dt) {
    scale_of(path, unit, dt);
    const std::string text = read_text(path);
    return states_its_units(text) ? parse_any(text, path) : parse_plain(text, path, unit, dt);
}

}  // namespace rocking::records
