#include "batch/manifest.hpp"

#include <cerrno>
#include <cstring>
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

}  // namespace

std::vector<std::string> split_csv_line(std::string_view line) {
    std::vector<std::string> cells;
    std::size_t i = 0;
    for (;;) {
        while (i < line.size() && (line[i] == ' ' || line[i] == '\t')) ++i;
        std::string cell;
        if (i < line.size() && line[i] == '"') {
            ++i;
            for (;;) {
                if (i >= line.size()) throw std::invalid_argument("an unterminated quote");
                if (line[i] == '"') {
                    if (i + 1 < line.size() && line[i + 1] == '"') cell += '"', i += 2;
                    else break;
                } else cell += line[i++];
            }
            ++i;  // the closing quote
            while (i < line.size() && (line[i] == ' ' || line[i] == '\t')) ++i;
            if (i < line.size() && line[i] != ',') throw std::invalid_argument("text after a closing quote");
        } else {
            const std::size_t end = std::min(line.find(',', i), line.size());
            cell = std::string(trimmed(line.substr(i, end - i)));
            i = end;
        }
        cells.push_back(std::move(cell));
        if (i >= line.size()) return cells;
        ++i;  // the comma
    }
}

std::string csv_cell(const std::string& cell) {
    const bool quote = cell.find_first_of(",\"") != std::string::npos ||
                       (!cell.empty() && (cell.front() == ' ' || cell.back() == ' ' || cell.front() == '\t' ||
                                          cell.back() == '\t'));
    if (!quote) return cell;
    std::string out = "\"";
    for (char c : cell) out += c == '"' ? std::string("\"\"") : std::string(1, c);
    return out + "\"";
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
    return parse(std::move(text), path);
}

Manifest Manifest::parse(std::string text, const std::string& path) {
    Manifest m;
    m.path_ = path;
    const auto slash = path.find_last_of('/');
    m.folder_ = slash == std::string::npos ? "." : slash == 0 ? "/" : path.substr(0, slash);
    m.text_ = std::move(text);
    m.digest_ = sha256_hex(m.text_);
    bool have_header = false;
    int line = 0;
    for (std::size_t at = 0; at < m.text_.size();) {
        std::size_t end = m.text_.find('\n', at);
        if (end == std::string::npos) end = m.text_.size();
        ++line;
        std::size_t length = end - at;
        if (length > 0 && m.text_[at + length - 1] == '\r') --length;
        const std::string_view row(m.text_.data() + at, length);
        if (!blank(row) && trimmed(row).front() != '#') {
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
        }
        at = end + 1;
    }
    if (!have_header) throw ManifestError(path + ": the manifest has no header row (the first line that is not blank or a '#' comment)");
    return m;
}

std::string_view Manifest::text(std::size_t job) const {
    return std::string_view(text_.data() + rows_[job].offset, rows_[job].length);
}

}  // namespace rocking::batch
