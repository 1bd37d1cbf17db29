#include "records/record.hpp"

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>

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

// A whole token as a finite double, or false.
bool parse_number(const std::string& token, double& value) {
    if (token.empty()) return false;
    char* end = nullptr;
    errno = 0;
    value = std::strtod(token.c_str(), &end);
    return end == token.c_str() + token.size() && errno != ERANGE && std::isfinite(value);
}

// What is wrong with a token parse_number() refused: a number a double
// cannot hold (1e400, or "inf" spelled out) is out of range, anything else
// is not a number.
std::string refused(const std::string& token) {
    char* end = nullptr;
    const double v = std::strtod(token.c_str(), &end);
    const bool whole = !token.empty() && end == token.c_str() + token.size();
    return "'" + token + (whole && !std::isnan(v) ? "' is out of range for a double" : "' is not a number");
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

std::ifstream open(const std::string& path) {
    // A folder opens as a stream that reads nothing, which read as "empty file".
    std::error_code ec;
    if (std::filesystem::is_directory(path, ec)) throw RecordError(path, 0, "is a folder, not a record file");
    std::ifstream in(path);
    if (!in) throw RecordError(path, 0, "cannot open the file");
    return in;
}

// Number of decimals printed in a header value (for the PGA comparison).
int decimals(const std::string& text) {
    const auto dot = text.find('.');
    return dot == std::string::npos ? 0 : static_cast<int>(text.size() - dot - 1);
}

}  // namespace

Record read_esm(const std::string& path) {
    std::ifstream in = open(path);
    Record r;
    r.path = path;
    r.format = "ESM ASCII";
    std::string line;
    int number = 0;
    std::map<std::string, int> line_of;
    bool in_header = true;
    while (std::getline(in, line)) {
        ++number;
        const std::string t = trim(line);
        if (in_header) {
            const auto colon = t.find(':');
            double v;
            if (colon != std::string::npos && !parse_number(t, v)) {
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
    if (!parse_number(r.header["SAMPLING_INTERVAL_S"], dt) || !(dt > 0))
        throw RecordError(path, line_of["SAMPLING_INTERVAL_S"], "SAMPLING_INTERVAL_S must be a number > 0");
    if (!parse_number(r.header["NDATA"], ndata) || ndata != std::floor(ndata) || ndata < 2)
        throw RecordError(path, line_of["NDATA"], "NDATA must be a whole number >= 2");
    if (r.header["UNITS"] != "cm/s^2")
        throw RecordError(path, line_of["UNITS"], "UNITS is '" + r.header["UNITS"] + "', expected cm/s^2");
    if (!parse_number(r.header["PGA_CM/S^2"], pga))
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

Record read_peer(const std::string& path) {
    std::ifstream in = open(path);
    Record r;
    r.path = path;
    r.format = "PEER AT2";
    std::string line;
    int number = 0;
    long npts = -1;
    while (std::getline(in, line)) {
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
            if (!parse_number(npts_text, v) || v != std::floor(v) || v < 2)
                throw RecordError(path, 4, "NPTS '" + npts_text + "' is not a whole number >= 2");
            npts = static_cast<long>(v);
            if (!parse_number(dt_text, r.dt) || !(r.dt > 0)) throw RecordError(path, 4, "DT '" + dt_text + "' must be > 0");
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

Record read_plain(const std::string& path, const std::string& unit, double dt) {
    double scale;
    if (unit == "g") scale = 9.81;
    else if (unit == "m/s2" || unit == "m/s^2") scale = 1.0;
    else if (unit == "cm/s2" || unit == "cm/s^2") scale = 0.01;
    else throw RecordError(path, 0, "unknown unit '" + unit + "' (g, m/s2, cm/s2)");
    if (!(dt >= 0) || !std::isfinite(dt)) throw RecordError(path, 0, "time step must be > 0");
    std::ifstream in = open(path);
    Record r;
    r.path = path;
    r.format = dt > 0 ? "one column" : "two columns";
    r.name = path;
    std::string line;
    int number = 0;
    std::vector<double> times;
    while (std::getline(in, line)) {
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
            throw RecordError(path, number, std::to_string(tokens.size()) + " values, expected " + std::to_string(want));
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

Record read_any(const std::string& path) {
    std::ifstream in = open(path);
    std::string first, second, third;
    if (!std::getline(in, first)) return read_peer(path);  // empty: read_peer says so
    if (first.find(':') != std::string::npos) return read_esm(path);
    std::getline(in, second);
    std::getline(in, third);
    if (!peer_units_line(third))
        throw RecordError(path, 1,
                          "neither ESM ASCII (its header lines are 'KEY: value') nor PEER AT2 ('UNITS OF G' on "
                          "line 3); plain one- or two-column text is read with its unit (rocking: --unit)");
    return read_peer(path);
}

}  // namespace rocking::records
