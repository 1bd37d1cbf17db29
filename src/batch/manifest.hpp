// A batch's manifest as text: a CSV file, one job a line, under a header
// row naming the columns.  This layer knows lines and cells, not what they
// mean (src/jobs/ does): the jobs are the data lines in order, each with its
// line number for messages, and the file's SHA-256 identifies it on resume.
//
// Lines starting with '#' and blank lines are skipped (comments); the first
// other line is the header.  Rows follow RFC 4180: a cell holding a comma, a
// quote or a line break is quoted, "" inside for a quote, and a quoted line
// break belongs to the cell, so that a row may span lines (it is known by the
// line it starts on).  Spaces around a cell are dropped; a UTF-8 byte-order
// mark at the head is skipped; CRLF ends a row as LF does, and a CR alone
// outside quotes (a file of classic Mac OS line ends) refuses the whole
// manifest, its line named.  A quote never
// closed is refused with the whole manifest: every row after it would be
// read into one cell.  The whole file is held (about 100 bytes a job, plus 16
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
    // The folder relative record paths are resolved against, and how the
    // messages say it (absolute, and why that folder).
    struct Folder {
        std::string path, said;
    };
    // The manifest's own folder, as its path names it (a link's, not its
    // target's); the current folder for a manifest that is not a regular
    // file (/dev/stdin, a pipe), whose folder holds no records.
    static Folder folder_of(const std::string& path);
    // Reads the file (up to kMaxBytes); throws ManifestError naming it.
    static Manifest read(const std::string& path);
    // The same from text already read (tests); `path` names it, and gives
    // the folder unless one is given.
    static Manifest parse(std::string text, const std::string& path);
    static Manifest parse(std::string text, const std::string& path, const Folder& folder);
    static constexpr std::size_t kMaxBytes = std::size_t{4} << 30;

    const std::string& path() const { return path_; }
    // The folder relative paths in the manifest are resolved against: the
    // manifest's own ("." for a bare file name).
    const std::string& folder() const { return folder_; }
    // That folder for the messages: "/abs/dir, the manifest's folder".
    const std::string& folder_said() const { return folder_said_; }
    const std::vector<std::string>& header() const { return header_; }
    std::size_t size() const { return rows_.size(); }
    int line(std::size_t job) const { return rows_[job].line; }  // where its row starts
    std::string_view text(std::size_t job) const;
    // The file's SHA-256, 64 hex digits.
    const std::string& digest() const { return digest_; }

private:
    struct Row {
        std::size_t offset;
        std::size_t length;
        int line;
    };
    std::string path_, folder_, folder_said_, text_, digest_;
    std::vector<std::string> header_;
    std::vector<Row> rows_;
};

// Where the CSV row starting at `at` ends: the line break outside quotes, or
// the text's end; `newlines` counts the line breaks inside its quoted cells.
// Not closed: a quoted cell runs to the end, opened `quote_line` lines below
// the row's first.  bare_cr: the row ended at a carriage return outside
// quotes with no line feed after it, on line `newlines` below its first
// (the rest of that line is not read).  By libcsv (batch/csv.cpp).
struct CsvRecordEnd {
    std::size_t end = 0;
    int newlines = 0;
    bool closed = true;
    int quote_line = 0;
    bool bare_cr = false;
};
CsvRecordEnd csv_record_end(std::string_view text, std::size_t at);

// The cells of one CSV row (its quoted cells may hold line breaks), spaces
// around each dropped; throws std::invalid_argument on an unterminated quote,
// text after a closing one or a quote inside an unquoted cell (libcsv's
// strict mode).
std::vector<std::string> split_csv_line(std::string_view line);
// A cell as CSV writes it: quoted when it holds a comma, a quote, a line
// break or spaces at either end (which reading would drop).
std::string csv_cell(const std::string& cell);
// The same appended to `out` after a comma: a row of many cells built
// without a string a cell (a batch row is written for every job).
void append_csv_cell(std::string& out, std::string_view cell);

}  // namespace rocking::batch
