// Where the closed forms hold at a q (Excursion), as q and response print it.
#pragma once

#include <string>

#include "qfactor/superposition.hpp"

namespace rocking::cli {

void print_validity(const Excursion& e, const char* prefix);

}  // namespace rocking::cli
