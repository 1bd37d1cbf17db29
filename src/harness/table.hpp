// A scene's output: a CSV table with a self-describing header.
//
// On disk: '# key: value' lines (scene, model, solver, tolerance, inputs,
// provenance of each column), then one header row, then the rows.  Numbers
// are written with 17 significant digits so that a round trip is exact; a
// label with a comma or a quote is quoted as in RFC 4180.
#pragma once

#include <string>
#include <utility>
#include <vector>

namespace rocking::harness {

class Table {
public:
    explicit Table(std::vector<std::string> columns) : columns_(std::move(columns)) {}

    void note(const std::string& key, const std::string& value) { notes_.emplace_back(key, value); }
    // Each cell is a number or a label; the row must have one cell per column.
    Table& row();
    Table& add(double value);
    Table& add(const std::string& label);
    Table& add(const char* label) { return add(std::string(label)); }
    Table& add(int value) { return add(std::to_string(value)); }
    Table& add(bool value) { return add(std::string(value ? "yes" : "no")); }

    const std::vector<std::string>& columns() const { return columns_; }
    const std::vector<std::vector<std::string>>& rows() const { return rows_; }
    const std::vector<std::pair<std::string, std::string>>& notes() const { return notes_; }

    // Throws std::runtime_error when a row is incomplete or the file cannot be written.
    void write(const std::string& path) const;

private:
    std::vector<std::string> columns_;
    std::vector<std::vector<std::string>> rows_;
    std::vector<std::pair<std::string, std::string>> notes_;
};

// printf's "%.17g" (it reads back to the same double), "nan", "inf" or "-inf".
std::string format_number(double value);

// A CSV read back: header, rows of cells, and the line number of each row.
struct CsvFile {
    std::string path;
    std::vector<std::string> columns;
    std::vector<std::vector<std::string>> rows;
    std::vector<int> line_of_row;
};
// Throws std::runtime_error naming the file and line on a malformed file.
CsvFile read_csv(const std::string& path);

}  // namespace rocking::harness
