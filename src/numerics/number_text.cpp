#include "numerics/number_text.hpp"

#include <algorithm>
#include <cfloat>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <system_error>

namespace rocking::numerics {

namespace {

bool blank(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\n' || c == '\v' || c == '\f'; }
bool digit(char c) { return c >= '0' && c <= '9'; }

std::string_view without_blanks(std::string_view text) {
    std::size_t a = 0, b = text.size();
    while (a < b && blank(text[a])) ++a;
    while (b > a && blank(text[b - 1])) --b;
    return text.substr(a, b - a);
}

bool same_letters(std::string_view text, std::string_view lower) {
    if (text.size() != lower.size()) return false;
    for (std::size_t k = 0; k < text.size(); ++k)
        if ((text[k] | 0x20) != lower[k]) return false;
    return true;
}

// The power of ten of a number's leading digit (1e400 -> 400, 0.001e-400 ->
// -403), from text std::from_chars has found well formed: a number out of a
// double's range lies above it when this is positive, below it otherwise.
long long decimal_power(std::string_view number) {
    std::size_t k = 0;
    long long power = -1;
    bool seen = false, after_point = false;
    for (; k < number.size() && (digit(number[k]) || number[k] == '.'); ++k) {
        if (number[k] == '.') after_point = true;
        else if (!seen && number[k] != '0') seen = true, power += after_point ? 0 : 1;
        else if (!seen && after_point) --power;
        else if (seen && !after_point) ++power;
    }
    long long exponent = 0;
    if (k < number.size()) {  // e or E, then an optional sign and digits
        ++k;
        const bool negative = k < number.size() && number[k] == '-';
        if (k < number.size() && (number[k] == '-' || number[k] == '+')) ++k;
        for (; k < number.size(); ++k)
            if (exponent < 1000000000) exponent = 10 * exponent + (number[k] - '0');
        if (negative) exponent = -exponent;
    }
    return power + exponent;
}

std::string to_17(double v) {
    char text[40];
    std::snprintf(text, sizeof text, "%.17g", v);
    return text;
}

// A comma between two digits, as a decimal comma writes "0,0123".
bool digit_comma_digit(std::string_view t) {
    for (std::size_t k = 1; k + 1 < t.size(); ++k)
        if (t[k] == ',' && digit(t[k - 1]) && digit(t[k + 1])) return true;
    return false;
}

}  // namespace

NumberRead read_number(std::string_view text) {
    const std::string_view t = without_blanks(text);
    const bool negative = !t.empty() && t[0] == '-';
    // std::from_chars takes no '+', and takes "nan" and "inf": the sign and
    // the first character after it are checked here.
    const std::string_view unsigned_part = t.substr(!t.empty() && (t[0] == '+' || t[0] == '-') ? 1 : 0);
    if (unsigned_part.empty()) return {0, NumberProblem::not_a_number};
    if (!digit(unsigned_part[0]) && unsigned_part[0] != '.') {
        for (std::string_view word : {"nan", "inf", "infinity"})
            if (same_letters(unsigned_part, word)) return {NAN, NumberProblem::not_finite};
        return {0, NumberProblem::not_a_number};
    }
    const std::string_view number = negative ? t : unsigned_part;
    double v = 0;
    const auto [end, error] = std::from_chars(number.data(), number.data() + number.size(), v);
    if (end != number.data() + number.size()) return {0, NumberProblem::not_a_number};  // "1e", "1,5", "0x10"
    if (error == std::errc::result_out_of_range) {
        if (decimal_power(unsigned_part) > 0) return {negative ? -HUGE_VAL : HUGE_VAL, NumberProblem::too_large};
        return {negative ? -0.0 : 0.0, NumberProblem::subnormal};  // below the smallest subnormal: rounds to 0
    }
    if (error != std::errc()) return {0, NumberProblem::not_a_number};
    if (v != 0 && std::fabs(v) < DBL_MIN) return {v, NumberProblem::subnormal};
    return {v, NumberProblem::none};
}

std::string largest_double_text() { return to_17(DBL_MAX); }
std::string smallest_normal_text() { return to_17(DBL_MIN); }

namespace {

// The text as a message can show it: printable ASCII kept, any other byte as
// \xNN, at most 40 of them.  A record of zero bytes printed "z.bin:1: '" and
// stopped at the first NUL; random bytes put carriage returns in the message.
std::string shown(std::string_view text) {
    std::string out;
    const std::size_t n = std::min<std::size_t>(text.size(), 40);
    for (std::size_t k = 0; k < n; ++k) {
        const unsigned char c = static_cast<unsigned char>(text[k]);
        if (c >= 0x20 && c < 0x7f) out += static_cast<char>(c);
        else {
            char hex[8];
            std::snprintf(hex, sizeof hex, "\\x%02X", c);
            out += hex;
        }
    }
    if (text.size() > n) out += "... (" + std::to_string(text.size()) + " bytes)";
    return out;
}

}  // namespace

std::string number_problem(std::string_view text, NumberProblem problem) {
    const std::string quoted = "'" + shown(text) + "'";
    switch (problem) {
        case NumberProblem::none: return quoted + " is a number";
        case NumberProblem::not_finite: return quoted + " is not a finite number";
        case NumberProblem::too_large: return quoted + " is too large for a double (magnitude beyond " + largest_double_text() + ")";
        case NumberProblem::subnormal:
            return quoted + " is below the smallest normal double, " + smallest_normal_text();
        case NumberProblem::not_a_number: break;
    }
    const std::string_view t = without_blanks(text);
    if (t.empty()) return quoted + " is empty, not a number";
    if (digit_comma_digit(t)) return quoted + " is not a number (decimal commas are not read)";
    const std::string_view unsigned_part = t.substr(t[0] == '+' || t[0] == '-' ? 1 : 0);
    if (unsigned_part.size() > 1 && unsigned_part[0] == '0' && (unsigned_part[1] | 0x20) == 'x')
        return quoted + " is not a number (hexadecimal is not read)";
    return quoted + " is not a number";
}

double parameter_number(std::string_view text) {
    const NumberRead r = read_number(text);
    if (r.problem != NumberProblem::none) throw std::invalid_argument(number_problem(text, r.problem));
    return r.value;
}

bool sample_number(std::string_view text, double& value) {
    const NumberRead r = read_number(text);
    value = r.value;
    return r.problem == NumberProblem::none || r.problem == NumberProblem::subnormal;
}

long long whole_number(std::string_view text, long long lo, long long hi) {
    const NumberRead r = read_number(text);
    const bool whole = r.problem == NumberProblem::none && r.value == std::floor(r.value);
    if (whole && r.value >= static_cast<double>(lo) && r.value <= static_cast<double>(hi))
        return static_cast<long long>(r.value);
    const std::string got = r.problem == NumberProblem::none ? std::string(without_blanks(text)) : "'" + std::string(text) + "'";
    throw std::invalid_argument("must be a whole number from " + std::to_string(lo) + " to " + std::to_string(hi) +
                                " (got " + got + ")");
}

}  // namespace rocking::numerics
