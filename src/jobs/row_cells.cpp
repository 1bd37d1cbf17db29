#include "jobs/row_cells.hpp"

#include <cmath>
#include <cstdlib>
#include <stdexcept>

#include "harness/table.hpp"
#include "numerics/number_text.hpp"

namespace rocking::jobs {

std::string one_line(std::string text) {
    for (char& c : text)
        if (c == '\n' || c == '\r') c = ' ';
    return text;
}

double number_of(const std::string& cell, const std::string& where) {
    // format_number's words for the doubles that are not numbers.
    if (cell == "nan") return NAN;
    if (cell == "inf" || cell == "-inf") return cell == "inf" ? HUGE_VAL : -HUGE_VAL;
    double v;
    if (!numerics::sample_number(cell, v))
        throw std::runtime_error(where + ": " + numerics::number_problem(cell, numerics::read_number(cell).problem));
    return v;
}

long whole_of(const std::string& cell, const std::string& where) {
    char* end = nullptr;
    const long v = std::strtol(cell.c_str(), &end, 10);
    if (cell.empty() || *end != '\0') throw std::runtime_error("not a whole number in " + where + ": '" + cell + "'");
    return v;
}

studies::Confirmation confirmation_of(const std::string& name) {
    using studies::Confirmation;
    for (Confirmation c : {Confirmation::not_checked, Confirmation::confirmed, Confirmation::disagrees,
                           Confirmation::ill_conditioned})
        if (studies::confirmation_name(c) == name) return c;
    throw std::runtime_error("an unknown check '" + name + "'");
}

std::vector<std::string> split(const std::string& text, char by) {
    std::vector<std::string> parts;
    std::size_t at = 0;
    for (std::size_t next; (next = text.find(by, at)) != std::string::npos; at = next + 1)
        parts.push_back(text.substr(at, next - at));
    parts.push_back(text.substr(at));
    return parts;
}

}  // namespace rocking::jobs
