#include "harness/compare.hpp"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <stdexcept>

namespace rocking::harness {

namespace {

bool parse_double(const std::string& text, double& value) {
    if (text.empty()) return false;
    char* end = nullptr;
    errno = 0;
    value = std::strtod(text.c_str(), &end);
    return end == text.c_str() + text.size();
}

}  // namespace

ToleranceSpec ToleranceSpec::read(const std::string& path) {
    std::ifstream in(path);
    if (!in) throw std::runtime_error(path + ": cannot open tolerance file");
    ToleranceSpec spec;
    spec.path_ = path;
    std::string line;
    int number = 0;
    while (std::getline(in, line)) {
        ++number;
        const auto first = line.find_first_not_of(" \t");
        if (first == std::string::npos || line[first] == '#') continue;
        std::istringstream ss(line);
        std::string file, column, a;
        ss >> file >> column >> a;
        auto fail = [&](const std::string& why) {
            throw std::runtime_error(path + ":" + std::to_string(number) + ": " + why);
        };
        if (a.empty())
            fail("expected '<file> <column> <abs> <rel> <reason>', '<file> <column> exact <reason>' or "
                 "'<file> <column> reference <reason>'");
        Tolerance t;
        if (a == "exact" || a == "reference") {
            t.exact = true;
            t.reference = a == "reference";
        } else {
            std::string r;
            ss >> r;
            if (!parse_double(a, t.abs) || !parse_double(r, t.rel) || t.abs < 0 || t.rel < 0 ||
                !std::isfinite(t.abs) || !std::isfinite(t.rel))
                fail("abs and rel must be finite numbers >= 0 (got '" + a + "' '" + r + "')");
        }
        std::getline(ss, t.reason);
        const auto start = t.reason.find_first_not_of(" \t");
        t.reason = start == std::string::npos ? "" : t.reason.substr(start);
        if (t.reason.empty()) fail("every tolerance needs its reason");
        if (!spec.rules_.count(file)) spec.order_.push_back(file);
        if (spec.rules_[file].count(column)) fail("second rule for " + file + " column " + column);
        spec.rules_[file][column] = t;
    }
    if (spec.order_.empty()) throw std::runtime_error(path + ": names no file");
    return spec;
}

std::vector<std::string> ToleranceSpec::files() const { return order_; }

bool ToleranceSpec::has_reference_columns() const {
    for (const auto& [file, columns] : rules_)
        for (const auto& [column, t] : columns)
            if (t.reference) return true;
    return false;
}

const Tolerance& ToleranceSpec::of(const std::string& file, const std::string& column) const {
    const auto f = rules_.find(file);
    if (f == rules_.end()) throw std::runtime_error(path_ + ": no rule for file " + file);
    auto c = f->second.find(column);
    if (c == f->second.end()) c = f->second.find("*");
    if (c == f->second.end())
        throw std::runtime_error(path_ + ": no rule for " + file + " column " + column + " and no '*'");
    return c->second;
}

Comparison compare(const CsvFile& expected, const CsvFile& actual, const ToleranceSpec& spec,
                   const std::string& file, bool reference_run) {
    Comparison out;
    out.file = file;
    if (expected.columns != actual.columns) {
        std::string e, a;
        for (const auto& c : expected.columns) e += (e.empty() ? "" : ",") + c;
        for (const auto& c : actual.columns) a += (a.empty() ? "" : ",") + c;
        out.problem = "columns differ: expected [" + e + "], got [" + a + "]";
        return out;
    }
    if (expected.rows.size() != actual.rows.size()) {
        out.problem = "row count differs: expected " + std::to_string(expected.rows.size()) + ", got " +
                      std::to_string(actual.rows.size());
        return out;
    }
    std::vector<const Tolerance*> tolerance;
    for (const auto& column : expected.columns) tolerance.push_back(&spec.of(file, column));

    for (std::size_t r = 0; r < expected.rows.size(); ++r) {
        for (std::size_t c = 0; c < expected.columns.size(); ++c) {
            const Tolerance& t = *tolerance[c];
            const std::string& e = t.reference && !reference_run ? std::string(kNotChecked) : expected.rows[r][c];
            const std::string& a = actual.rows[r][c];
            Deviation d{expected.columns[c], expected.line_of_row[r], e, a, 0.0, 0.0, 0.0};
            double ev = 0, av = 0;
            const bool numeric = !t.exact && parse_double(e, ev) && parse_double(a, av);
            bool pass;
            if (numeric) {
                if (std::isnan(ev) || std::isnan(av)) {
                    pass = false;  // a NaN is never an expected output
                    d.deviation = INFINITY;
                } else if (std::isinf(ev) || std::isinf(av)) {
                    pass = ev == av;
                    d.deviation = pass ? 0.0 : INFINITY;
                } else {
                    d.deviation = std::fabs(av - ev);
                    d.allowed = t.abs + t.rel * std::fabs(ev);
                    pass = d.deviation <= d.allowed;
                }
            } else {
                pass = e == a;
                d.deviation = pass ? 0.0 : 1.0;
            }
            d.ratio = d.deviation == 0.0 ? 0.0 : (d.allowed > 0.0 ? d.deviation / d.allowed : INFINITY);
            ++out.cells;
            if (out.cells == 1 || d.ratio > out.worst.ratio) out.worst = d;
            if (!pass) {
                ++out.failed;
                if (out.failures.size() < 5) out.failures.push_back(d);
            }
        }
    }
    return out;
}

}  // namespace rocking::harness
