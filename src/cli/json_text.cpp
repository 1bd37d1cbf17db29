#include "cli/json_text.hpp"

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <stdexcept>

#include "harness/table.hpp"

namespace rocking::cli {

namespace {

// How many bytes the UTF-8 sequence at s[i] spans when it is well formed;
// 0 when it is not, with `bad` set to its maximal subpart (Unicode 15, 3.9):
// the bytes one U+FFFD stands for, as Python's decode(errors="replace") counts.
std::size_t utf8_length(const std::string& s, std::size_t i, std::size_t& bad) {
    const unsigned char c = static_cast<unsigned char>(s[i]);
    if (c < 0x80) return 1;
    std::size_t need = 0;
    unsigned char low = 0x80, high = 0xBF;  // the second byte's range; overlongs and surrogates narrow it
    if (c >= 0xC2 && c <= 0xDF) need = 2;
    else if (c >= 0xE0 && c <= 0xEF) need = 3, low = c == 0xE0 ? 0xA0 : 0x80, high = c == 0xED ? 0x9F : 0xBF;
    else if (c >= 0xF0 && c <= 0xF4) need = 4, low = c == 0xF0 ? 0x90 : 0x80, high = c == 0xF4 ? 0x8F : 0xBF;
    else {
        bad = 1;
        return 0;
    }
    std::size_t k = 1;
    for (; k < need && i + k < s.size(); ++k) {
        const unsigned char d = static_cast<unsigned char>(s[i + k]);
        if (d < (k == 1 ? low : 0x80) || d > (k == 1 ? high : 0xBF)) break;
    }
    if (k == need) return need;
    bad = k;
    return 0;
}

// The code point of a well-formed sequence of 1 or 2 bytes (enough to find the controls).
unsigned short_code_point(const std::string& s, std::size_t i, std::size_t length) {
    const unsigned c = static_cast<unsigned char>(s[i]);
    return length == 1 ? c : ((c & 0x1F) << 6) | (static_cast<unsigned char>(s[i + 1]) & 0x3F);
}

void escape_control(unsigned code, std::string& out) {
    static const char* named[] = {"\\b", "\\t", "\\n", nullptr, "\\f", "\\r"};
    if (code >= 0x08 && code <= 0x0D && named[code - 0x08]) {
        out += named[code - 0x08];
        return;
    }
    char text[8];
    std::snprintf(text, sizeof text, "\\u%04x", code);
    out += text;
}

// File names, ESM header values and PEER titles are bytes, not text: JSON
// must be valid UTF-8 without raw control characters.  Each ill-formed
// sequence becomes U+FFFD, one per maximal subpart (as Python decodes with
// errors="replace"), rather than \u00XX: that escape names a character, so a
// byte 0xFF would come back as a real "ÿ" that was never in the name.  The
// C0 and C1 controls and DEL are \u-escaped (or \n, \t, ...), so that a name
// cannot break a line-oriented reader or a terminal either.  (nlohmann's
// dump would throw on the ill-formed bytes, or drop them, and pass C1 raw.)
void append_string(const std::string& s, std::string& out) {
    out += '"';
    for (std::size_t i = 0; i < s.size();) {
        std::size_t bad = 0;
        const std::size_t length = utf8_length(s, i, bad);
        if (length == 0) {
            out += "\xEF\xBF\xBD";  // U+FFFD
            i += bad;
            continue;
        }
        const unsigned code = length <= 2 ? short_code_point(s, i, length) : 0x100;
        if (code == '"' || code == '\\') out += '\\', out += static_cast<char>(code);
        else if (code < 0x20 || (code >= 0x7F && code <= 0x9F)) escape_control(code, out);
        else out.append(s, i, length);
        i += length;
    }
    out += '"';
}

void append(const Json& v, std::string& out) {
    switch (v.type()) {
    case Json::value_t::object: {
        out += '{';
        bool first = true;
        for (auto member = v.begin(); member != v.end(); ++member) {
            if (!first) out += ", ";
            first = false;
            append_string(member.key(), out);
            out += ": ";
            append(member.value(), out);
        }
        out += '}';
        return;
    }
    case Json::value_t::array: {
        out += '[';
        for (std::size_t i = 0; i < v.size(); ++i) {
            if (i) out += ", ";
            append(v[i], out);
        }
        out += ']';
        return;
    }
    case Json::value_t::string: append_string(v.get_ref<const std::string&>(), out); return;
    case Json::value_t::boolean: out += v.get<bool>() ? "true" : "false"; return;
    case Json::value_t::number_integer: out += std::to_string(v.get<std::int64_t>()); return;
    case Json::value_t::number_unsigned: out += std::to_string(v.get<std::uint64_t>()); return;
    // A bare nan or inf makes the whole document unreadable (json_text.hpp).
    case Json::value_t::number_float: {
        const double d = v.get<double>();
        out += std::isfinite(d) ? harness::format_number(d) : "null";
        return;
    }
    case Json::value_t::null: out += "null"; return;
    case Json::value_t::binary:
    case Json::value_t::discarded: break;
    }
    throw std::logic_error("json_text: a value JSON has no text for");
}

}  // namespace

std::string json_text(const Json& value) {
    std::string out;
    append(value, out);
    return out;
}

}  // namespace rocking::cli
