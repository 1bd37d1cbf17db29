// Where the closed forms hold at a q (Excursion), as q and response print it.
#pragma once

#include <string>

#include "cli/json_text.hpp"
#include "qfactor/superposition.hpp"

namespace rocking::cli {

extern const char* kModel;
void print_validity(const Excursion& e, const char* prefix);
// The same four answers as members of a --json document.
void add_validity(Json& o, const Excursion& e);

}  // namespace rocking::cli
