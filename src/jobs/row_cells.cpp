#include "jobs/row_cells.hpp"

#include <cstdlib>
#include <stdexcept>

namespace rocking::jobs {

std::string one_line(std::string text) {
    for (char& c : text)
        if (c == '\n' || c == '\r') c = ' ';
    return text;
}

double number_of(const std::string& cell, const std::string& where) {
    char* end = nullptr;
    const double v = std::strtod(cell.c_str(), &end);
    if (cell.empty() || *end != '\0') throw std::runtime_error("not a number in " + where + ": '" + cell + "'");
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
