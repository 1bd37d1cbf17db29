#include "harness/table.hpp"

#include "harness/atomic_file.hpp"

#include <charconv>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <sstream>
#include <stdexcept>

namespace rocking::harness {

std::string format_number(double value) {
    if (std::isnan(value)) return "nan";
    if (std::isinf(value)) return value > 0 ? "inf" : "-inf";
    // printf's %.17g, by the standard's definition of to_chars with a precision,
    // at a fifth of its cost: a batch row holds a dozen numbers, and printf took
    // a tenth of a simulation's time (tests: Harness.FormatNumberIsPrintfs17g).
    char buffer[40];
    const auto end = std::to_chars(buffer, buffer + sizeof buffer, value, std::chars_format::general, 17).ptr;
    return std::string(buffer, end);
}

Table& Table::row() {
    if (!rows_.empty() && rows_.back().size() != columns_.size())
        throw std::runtime_error("table: row " + std::to_string(rows_.size()) + " has " +
                                 std::to_string(rows_.back().size()) + " cells, expected " +
                                 std::to_string(columns_.size()));
    rows_.emplace_back();
    return *this;
}

Table& Table::add(double value) { return add(format_number(value)); }

Table& Table::add(const std::string& label) {
    if (rows_.empty()) throw std::runtime_error("table: add() before row()");
    if (label.find_first_of("\r\n") != std::string::npos)
        throw std::runtime_error("table: cell '" + label + "' contains a newline");
    rows_.back().push_back(label);
    return *this;
}

namespace {
// RFC 4180 quoting for a cell with a comma or a quote.
std::string csv_cell(const std::string& cell) {
    if (cell.find_first_of(",\"") == std::string::npos) return cell;
    std::string out = "\"";
    for (char c : cell) out += c == '"' ? std::string("\"\"") : std::string(1, c);
    return out + "\"";
}
}  // namespace

namespace {
// A note is one '# key: value' line: a record's name with a newline in it
// (simulate --output's input note) made its second half read as the header.
std::string one_line(const std::string& text) {
    std::string out;
    for (char c : text) out += c == '\n' ? std::string("\\n") : c == '\r' ? std::string("\\r") : std::string(1, c);
    return out;
}
}  // namespace

// Atomically (AtomicFile): two runs writing the same path mixed their lines,
// and a full disk or a SIGTERM left half a table at the path.
void Table::write(const std::string& path) const {
    if (!rows_.empty() && rows_.back().size() != columns_.size())
        throw std::runtime_error("table for " + path + ": last row is incomplete");
    AtomicFile out(path);
    for (const auto& [key, value] : notes_) out.write("# " + one_line(key) + ": " + one_line(value) + "\n");
    std::string line;
    for (std::size_t c = 0; c < columns_.size(); ++c) line += (c ? "," : "") + columns_[c];
    out.write(line + "\n");
    for (const auto& r : rows_) {
        line.clear();
        for (std::size_t c = 0; c < r.size(); ++c) line += (c ? "," : "") + csv_cell(r[c]);
        out.write(line + "\n");
    }
    out.commit();
}

namespace {
// Splits an RFC 4180 line; returns false on an unterminated quote.
bool split(const std::string& line, std::vector<std::string>& cells) {
    cells.assign(1, "");
    bool quoted = false;
    for (std::size_t i = 0; i < line.size(); ++i) {
        const char c = line[i];
        if (quoted) {
            if (c == '"' && i + 1 < line.size() && line[i + 1] == '"') cells.back() += '"', ++i;
            else if (c == '"') quoted = false;
            else cells.back() += c;
        } else if (c == '"') quoted = true;
        else if (c == ',') cells.emplace_back();
        else cells.back() += c;
    }
    return !quoted;
}
}  // namespace

CsvFile read_csv(const std::string& path) {
    std::ifstream in(path);
    if (!in) throw std::runtime_error(path + ": cannot open");
    CsvFile file{path, {}, {}, {}};
    std::string line;
    int number = 0;
    while (std::getline(in, line)) {
        ++number;
        if (!line.empty() && line.back() == '\r') line.pop_back();
        if (line.empty() || line[0] == '#') continue;
        std::vector<std::string> cells;
        if (!split(line, cells))
            throw std::runtime_error(path + ":" + std::to_string(number) + ": unterminated quote");
        if (file.columns.empty()) {
            file.columns = cells;
            continue;
        }
        if (cells.size() != file.columns.size())
            throw std::runtime_error(path + ":" + std::to_string(number) + ": " +
                                     std::to_string(cells.size()) + " cells, the header has " +
                                     std::to_string(file.columns.size()));
        file.rows.push_back(std::move(cells));
        file.line_of_row.push_back(number);
    }
    if (file.columns.empty()) throw std::runtime_error(path + ": empty file (no header row)");
    return file;
}

}  // namespace rocking::harness
