// A batch's manifest as text: a CSV file, one job a line, under a header
// row naming the columns.  This layer knows lines and cells, not what they
// mean (src/jobs/ does): the jobs are the data lines in order, each with its
// line number for messages, and the file's SHA-256 identifies it on resume.
//
// Lines starting with '#' and blank lines are skipped (comments); the first
// other line is the header.  Cells follow RFC 4180 (a cell with a comma or a
// quote is quoted, "" inside for a quote), one row a line; spaces around a
// cell are dropped.  The whole file is held (about 100 bytes a job, plus 16
// for its index): a manifest of 10^6 jobs takes about 120 MB.
#pragma once

#include <cstddef>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

namespace rocking::batch {

// A manifest that cannot be used at all: unreadable, no header, a header
// cell empty or twice, an unterminated quote in the header.
struct ManifestError : std::runtime_error {
    using std::runtime_error::runtime_error;
};

class Manifest {
public:
    // Reads the file (up to kMaxBytes); throws ManifestError naming it.
    static Manifest read(const std::string& path);
    // The same from text already read (tests); `path` names it.
    static Manifest parse(std::string text, const std::string& path);
    static constexpr std::size_t kMaxBytes = std::size_t{4} << 30;

    const std::string& path() const { return path_; }
    // The folder relative paths in the manifest are resolved against: the
    // manifest's own ("." for a bare file name).
    const std::string& folder() const { return folder_; }
    const std::vector<std::string>& header() const { return header_; }
    std::size_t size() const { return rows_.size(); }
    int line(std::size_t job) const { return rows_[job].line; }
    std::string_view text(std::size_t job) const;
    // The file's SHA-256, 64 hex digits.
    const std::string& digest() const { return digest_; }

private:
    struct Row {
        std::size_t offset;
        std::size_t length;
        int line;
    };
    std::string path_, folder_, text_, digest_;
    std::vector<std::string> header_;
    std::vector<Row> rows_;
};

// The cells of one CSV line, spaces around each dropped; throws
// std::invalid_argument on an unterminated quote or text after a closing one.
std::vector<std::string> split_csv_line(std::string_view line);
// A cell as CSV writes it: quoted when it holds a comma, a quote or spaces at
// either end (which reading would drop).
std::string csv_cell(const std::string& cell);

}  // namespace rocking::batch
