#include "batch/manifest.hpp"

#include <sys/stat.h>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "batch/sha256.hpp"

namespace rocking::batch {

namespace {

bool blank(std::string_view s) { return s.find_first_not_of(" \t") == std::string_view::npos; }

std::string_view trimmed(std::string_view s) {
    const auto from = s.find_first_not_of(" \t");
    if (from == std::string_view::npos) return {};
    return s.substr(from, s.find_last_not_of(" \t") - from + 1);
}

std::string absolute(const std::string& folder) {
    std::error_code error;
    std::string p = std::filesystem::absolute(folder, error).lexically_normal().string();
    if (error) return folder;
    if (p.size() > 1 && p.back() == '/') p.pop_back();  // "/tmp/x/." is "/tmp/x/" once normal
    return p;
}

}  // namespace

void append_csv_cell(std::string& out, std::string_view cell) {
    out += ',';
    // One pass over the cell (find_first_of over a set called memchr a character).
    bool quote = !cell.empty() && (cell.front() == ' ' || cell.back() == ' ' || cell.front() == '\t' || cell.back() == '\t');
    for (std::size_t k = 0; k < cell.size() && !quote; ++k)
        quote = cell[k] == ',' || cell[k] == '"' || cell[k] == '\n' || cell[k] == '\r';
    if (!quote) {
        out += cell;
        return;
    }
    out += '"';
    for (char c : cell) {
        if (c == '"') out += '"';
        out += c;
    }
    out += '"';
}

std::string csv_cell(const std::string& cell) {
    std::string out;
    append_csv_cell(out, cell);
    return out.substr(1);
}

Manifest::Folder Manifest::folder_of(const std::string& path) {
    struct stat s {};
    // A descriptor's folder (/dev for /dev/stdin, /dev/fd for <(...)) holds no records of the study,
    // even when the descriptor is a regular file (rocking batch /dev/stdin < study.csv).
    const bool descriptor = path.rfind("/dev/", 0) == 0 || path.rfind("/proc/", 0) == 0;
    if (descriptor || (::stat(path.c_str(), &s) == 0 && !S_ISREG(s.st_mode)))
        return {".", absolute(".") + ", the current folder, as the manifest is read from " +
                         (descriptor ? path : "a pipe or a device") + ", not from a file in a folder"};
    const auto slash = path.find_last_of('/');
    const std::string folder = slash == std::string::npos ? "." : slash == 0 ? "/" : path.substr(0, slash);
    struct stat link {};
    const bool symlink = ::lstat(path.c_str(), &link) == 0 && S_ISLNK(link.st_mode);
    return {folder, absolute(folder) + (symlink ? ", the folder of the link " + path + ", not of the file it points to"
                                                : ", the manifest's folder")};
}

Manifest Manifest::read(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    if (!in) throw ManifestError(path + ": cannot open the manifest: " + std::strerror(errno));
    std::string text;
    char buffer[1 << 16];
    while (in.read(buffer, sizeof buffer) || in.gcount() > 0) {
        text.append(buffer, static_cast<std::size_t>(in.gcount()));
        if (text.size() > kMaxBytes) throw ManifestError(path + ": the manifest is larger than 4 GiB");
    }
    if (in.bad()) throw ManifestError(path + ": cannot read the manifest");
    return parse(std::move(text), path, folder_of(path));
}

Manifest Manifest::parse(std::string text, const std::string& path) {
    const auto slash = path.find_last_of('/');
    const std::string folder = slash == std::string::npos ? "." : slash == 0 ? "/" : path.substr(0, slash);
    return parse(std::move(text), path, {folder, absolute(folder) + ", the manifest's folder"});
}

Manifest Manifest::parse(std::string text, const std::string& path, const Folder& folder) {
    Manifest m;
    m.path_ = path;
    m.folder_ = folder.path;
    m.folder_said_ = folder.said;
    m.text_ = std::move(text);
    m.digest_ = sha256_hex(m.text_);
    bool have_header = false;
    int line = 1;
    // A byte-order mark is no part of the first column's name (the digest still covers it).
    std::size_t at = m.text_.compare(0, 3, "\xEF\xBB\xBF") == 0 ? 3 : 0;
    while (at < m.text_.size()) {
        const std::size_t eol = std::min(m.text_.find('\n', at), m.text_.size());
        const std::string_view physical(m.text_.data() + at, eol - at);
        if (blank(physical) || trimmed(physical).front() == '#') {  // a comment or a blank line, never inside a row
            at = eol + 1;
            ++line;
            continue;
        }
        const CsvRecordEnd end = csv_record_end(m.text_, at);
        if (!end.closed)
            throw ManifestError(path + ":" + std::to_string(line) + ": the " + (have_header ? "row" : "header row") +
                                " has an unterminated quote: the quoted cell opened on line " +
                                std::to_string(line + end.quote_line) +
                                " is never closed (a quote inside a quoted cell is written twice)");
        std::size_t length = end.end - at;
        if (length > 0 && m.text_[at + length - 1] == '\r') --length;
        const std::string_view row(m.text_.data() + at, length);
        if (end.bare_cr)
            throw ManifestError(path + ":" + std::to_string(line + end.newlines) +
                                ": a carriage return (CR) with no line feed after it, outside quotes: lines ending "
                                "with CR alone (as classic Mac OS wrote them) are not read as line ends (RFC 4180 "
                                "ends a row with CRLF or LF); convert them, e.g. tr '\\r' '\\n' <in.csv >out.csv");
        if (!have_header) {
            try {
                m.header_ = split_csv_line(row);
            } catch (const std::invalid_argument& e) {
                throw ManifestError(path + ":" + std::to_string(line) + ": the header row has " + e.what());
            }
            for (std::size_t c = 0; c < m.header_.size(); ++c) {
                if (m.header_[c].empty())
                    throw ManifestError(path + ":" + std::to_string(line) + ": the header's column " +
                                        std::to_string(c + 1) + " has no name");
                for (std::size_t d = 0; d < c; ++d)
                    if (m.header_[d] == m.header_[c])
                        throw ManifestError(path + ":" + std::to_string(line) + ": the header names column '" +
                                            m.header_[c] + "' twice");
            }
            have_header = true;
        } else
            m.rows_.push_back({at, length, line});
        line += 1 + end.newlines;
        at = end.end + 1;
    }
    if (!have_header) throw ManifestError(path + ": the manifest has no header row (the first line that is not blank or a '#' comment)");
    return m;
}

std::string_view Manifest::text(std::size_t job) const {
    return std::string_view(text_.data() + rows_[job].offset, rows_[job].length);
}

}  // namespace rocking::batch
