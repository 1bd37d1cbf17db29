// The command line's --json documents (issue 42): each is built as a value,
// nlohmann::ordered_json (its keys keep the order they are set in, the order
// the documents have always had), and printed by json_text alone, so that no
// subcommand assembles JSON from fragments of text.
#pragma once

#include <string>

#include <nlohmann/json.hpp>

namespace rocking::cli {

using Json = nlohmann::ordered_json;

// One line, no final newline: objects as {"k": v, "k2": v2}, arrays as
// [a, b], the separators the documents had before they were values.
// Strings as bytes: ill-formed UTF-8 becomes U+FFFD, controls are escaped
// (json_text.cpp says why).  Integers as integers; a double to 17
// significant digits (harness::format_number), and null when it is not
// finite: JSON has no NaN or infinity, and each document says why beside a
// null (tests/json_test.sh) or its command refuses the input before.
std::string json_text(const Json& value);

}  // namespace rocking::cli
