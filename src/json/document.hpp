// The --json documents, built once in the library (issue 42): the command
// line prints each with cli::json_text, the Python module converts the same
// value to dicts and lists (python/src/json_value.cpp).  A document is an
// nlohmann::ordered_json, whose members keep the order they are set in: the
// order the command line's documents have always had.  Numbers keep their
// kind (an integer stays one), and a value that is not finite stays a double:
// json_text prints it as null, Python keeps it a float.
#pragma once

#include <nlohmann/json.hpp>

namespace rocking::json {

using Json = nlohmann::ordered_json;

}  // namespace rocking::json
