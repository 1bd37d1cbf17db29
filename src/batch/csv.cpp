// RFC 4180 by libcsv (libcsv-dev): the manifest's rows and cells, and the
// rows of a results file read back.  libcsv ends a row at CR or LF outside
// quotes and trims spaces and tabs around unquoted cells, as the manifest's
// rules want; what it does not know (a row known by the line it starts on,
// a bare CR refused, the line a quote was opened on) is kept here, from its
// callbacks.
#include <csv.h>

#include <stdexcept>

#include "batch/manifest.hpp"

namespace rocking::batch {

namespace {

class Parser {
public:
    explicit Parser(unsigned char options) {
        if (csv_init(&p_, options) != 0) throw std::bad_alloc();
    }
    ~Parser() { csv_free(&p_); }
    Parser(const Parser&) = delete;
    Parser& operator=(const Parser&) = delete;
    csv_parser* get() { return &p_; }

private:
    csv_parser p_{};
};

// What the callbacks saw of a row being delimited: the cells it closed and
// the line each closed on, and the row's end with the character that ended it.
struct Delimiting {
    int line = 0;             // lines fed so far after the row's first
    int last_cell_line = 0;   // where the last cell closed: an unclosed one opens there
    bool ended = false;
    int terminator = -1;      // '\n' (ours), '\r' (a bare CR in the text), -1 (the end)
};

void cell_closed(void*, std::size_t, void* data) {
    auto* d = static_cast<Delimiting*>(data);
    d->last_cell_line = d->line;
}

void row_ended(int c, void* data) {
    auto* d = static_cast<Delimiting*>(data);
    if (!d->ended) d->ended = true, d->terminator = c;
}

}  // namespace

CsvRecordEnd csv_record_end(std::string_view text, std::size_t at) {
    // Strict, or libcsv would read on after text that follows a closing quote
    // as if the quote were still open; where it stops, the row ends with its
    // line, and split_csv_line refuses the cells.
    Parser parser(CSV_STRICT | CSV_STRICT_FINI);
    Delimiting d;
    CsvRecordEnd r;
    for (;;) {
        const std::size_t eol = std::min(text.find('\n', at), text.size());
        std::size_t length = eol - at;
        // A CRLF's CR: outside quotes it ends the row as the LF does; inside, the cell's, which only split_csv_line keeps.
        if (length > 0 && text[at + length - 1] == '\r') --length;
        if (csv_parse(parser.get(), text.data() + at, length, cell_closed, row_ended, &d) < length && !d.ended) {
            r.end = eol;
            return r;
        }
        if (d.ended) {  // a CR alone, outside quotes, inside the line
            r.end = eol;
            r.bare_cr = true;
            return r;
        }
        if (eol >= text.size()) {
            if (csv_fini(parser.get(), cell_closed, row_ended, &d) != 0 || !d.ended) {
                r.closed = false;
                r.quote_line = d.last_cell_line;
            }
            r.end = text.size();
            return r;
        }
        static const char newline = '\n';
        csv_parse(parser.get(), &newline, 1, cell_closed, row_ended, &d);
        if (d.ended) {
            r.end = eol;
            return r;
        }
        ++r.newlines, ++d.line;  // inside a quoted cell: the break is the cell's
        at = eol + 1;
    }
}

std::vector<std::string> split_csv_line(std::string_view line) {
    Parser parser(CSV_STRICT | CSV_STRICT_FINI);
    std::vector<std::string> cells;
    auto cell = [](void* s, std::size_t n, void* data) {
        static_cast<std::vector<std::string>*>(data)->emplace_back(static_cast<const char*>(s), n);
    };
    const std::size_t read = csv_parse(parser.get(), line.data(), line.size(), cell, nullptr, &cells);
    if (read < line.size()) {
        // Strict libcsv stops at a quote where RFC 4180 has none; its public
        // `quoted` says whether the cell it stopped in was a quoted one.
        throw std::invalid_argument(parser.get()->quoted
                                        ? "text after a closing quote"
                                        : "a quote inside an unquoted cell (quote the cell, the quote written twice)");
    }
    if (csv_fini(parser.get(), cell, nullptr, &cells) != 0) throw std::invalid_argument("an unterminated quote");
    if (cells.empty()) cells.emplace_back();  // an empty line is one empty cell
    return cells;
}

}  // namespace rocking::batch
