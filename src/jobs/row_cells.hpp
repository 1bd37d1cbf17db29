// The cells of the rows that the studies on the batch engine (rocking
// fragility, rocking spectrum) write and read back: each row is read only by
// the command that wrote it, so anything but its own writing is a damaged
// file, refused with std::runtime_error naming `where` (the row).
#pragma once

#include <string>
#include <vector>

#include "studies/intervals.hpp"

namespace rocking::jobs {

// One line a row: a message's newlines would split it.
std::string one_line(std::string text);

// A number written with harness::format_number ("nan", "inf" and "-inf"
// included) back to the same double, by the samples' rule of
// numerics/number_text.hpp (a subnormal is itself).
double number_of(const std::string& cell, const std::string& where);
long whole_of(const std::string& cell, const std::string& where);

// studies::confirmation_name's inverse.
studies::Confirmation confirmation_of(const std::string& name);

// The parts of `text` between each `by`: one part for an empty text.
std::vector<std::string> split(const std::string& text, char by);

}  // namespace rocking::jobs
