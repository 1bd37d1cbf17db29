// The command line's one JSON serializer (src/cli/json_text.hpp, issue 42):
// every document's bytes come from it, so each rule is checked here against
// literal text: "%.17g" and C's own digits for the numbers, Unicode 15 §3.9's
// maximal subparts (Python's decode(errors="replace") agrees) for the bytes.
#include <gtest/gtest.h>

#include <cfloat>
#include <cmath>
#include <cstdint>
#include <limits>
#include <string>

#include "cli/json_text.hpp"

using rocking::cli::Json;
using rocking::cli::json_text;

namespace {

std::string text_of(const std::string& s) { return json_text(Json(s)); }

}  // namespace

TEST(JsonText, DoublesToSeventeenDigitsIntegersAsIntegers) {
    EXPECT_EQ(json_text(Json(0.1)), "0.10000000000000001");
    EXPECT_EQ(json_text(Json(1.0 / 3.0)), "0.33333333333333331");
    EXPECT_EQ(json_text(Json(2.0)), "2");
    EXPECT_EQ(json_text(Json(-0.0)), "-0");
    EXPECT_EQ(json_text(Json(1e17)), "1e+17");  // a double, printed by %.17g
    EXPECT_EQ(json_text(Json(DBL_MAX)), "1.7976931348623157e+308");
    EXPECT_EQ(json_text(Json(4.9406564584124654e-324)), "4.9406564584124654e-324");
    EXPECT_EQ(json_text(Json(2)), "2");
    EXPECT_EQ(json_text(Json(std::uint64_t{100000000000000000})), "100000000000000000");
    EXPECT_EQ(json_text(Json(std::numeric_limits<std::uint64_t>::max())), "18446744073709551615");
    EXPECT_EQ(json_text(Json(std::numeric_limits<std::int64_t>::min())), "-9223372036854775808");
    EXPECT_EQ(json_text(Json(4294967295u)), "4294967295");
}

TEST(JsonText, NotFiniteIsNullNeverANumber) {
    EXPECT_EQ(json_text(Json(std::nan(""))), "null");
    EXPECT_EQ(json_text(Json(HUGE_VAL)), "null");
    EXPECT_EQ(json_text(Json(-HUGE_VAL)), "null");
    EXPECT_EQ(json_text(Json::array({1.5, std::nan(""), -HUGE_VAL})), "[1.5, null, null]");
}

TEST(JsonText, LiteralsAndEmptyContainers) {
    EXPECT_EQ(json_text(Json(nullptr)), "null");
    EXPECT_EQ(json_text(Json(true)), "true");
    EXPECT_EQ(json_text(Json(false)), "false");
    EXPECT_EQ(json_text(Json::object()), "{}");
    EXPECT_EQ(json_text(Json::array()), "[]");
    EXPECT_EQ(text_of(""), "\"\"");
}

TEST(JsonText, QuotesBackslashesAndNamedControls) {
    EXPECT_EQ(text_of("a\"b\\c/d"), "\"a\\\"b\\\\c/d\"");
    EXPECT_EQ(text_of("\b\t\n\f\r"), "\"\\b\\t\\n\\f\\r\"");
    // The controls without a short escape: \u and four lower-case hex digits.
    EXPECT_EQ(text_of(std::string("\x00\x01\x0b\x1b\x1f", 5)), "\"\\u0000\\u0001\\u000b\\u001b\\u001f\"");
    EXPECT_EQ(text_of("a\x7f" "b"), "\"a\\u007fb\"");  // DEL
}

TEST(JsonText, C1ControlsEscapedOtherCharactersKept) {
    EXPECT_EQ(text_of("\xc2\x85"), "\"\\u0085\"");  // NEL
    EXPECT_EQ(text_of("\xc2\x9b"), "\"\\u009b\"");  // CSI
    EXPECT_EQ(text_of("\xc2\x9f"), "\"\\u009f\"");
    EXPECT_EQ(text_of("\xc2\xa0\xc3\xa9 \xe2\x82\xac \xf0\x9f\x99\x82"), "\"\xc2\xa0\xc3\xa9 \xe2\x82\xac \xf0\x9f\x99\x82\"");
    EXPECT_EQ(text_of("\xf4\x8f\xbf\xbf"), "\"\xf4\x8f\xbf\xbf\"");  // U+10FFFF, the last code point
}

TEST(JsonText, IllFormedBytesOneReplacementPerMaximalSubpart) {
    const std::string r = "\xef\xbf\xbd";  // U+FFFD
    EXPECT_EQ(text_of("a\xff" "b"), "\"a" + r + "b\"");
    EXPECT_EQ(text_of("\xc3("), "\"" + r + "(\"");                  // a lead byte without its continuation
    EXPECT_EQ(text_of("x\xe2\x82"), "\"x" + r + "\"");              // truncated at the end: one
    EXPECT_EQ(text_of("\xed\xa0\x80"), "\"" + r + r + r + "\"");    // a surrogate: three
    EXPECT_EQ(text_of("\xe0\x80\xaf"), "\"" + r + r + r + "\"");    // overlong: three
    EXPECT_EQ(text_of("\xf4\x90\x80\x80"), "\"" + r + r + r + r + "\"");  // above U+10FFFF: four
    EXPECT_EQ(text_of("\xc0\xaf"), "\"" + r + r + "\"");
}

TEST(JsonText, ObjectsKeepTheOrderTheirKeysAreSetIn) {
    Json o;
    o["z"] = 1;
    o["a"] = "x";
    o["m"] = nullptr;
    o["a"] = 2.5;  // set again: keeps its place
    EXPECT_EQ(json_text(o), "{\"z\": 1, \"a\": 2.5, \"m\": null}");
    Json k;
    k["t\"ab\tle"] = true;
    EXPECT_EQ(json_text(k), "{\"t\\\"ab\\tle\": true}");
}

TEST(JsonText, NestingOnOneLine) {
    Json row;
    row["q"] = 0.5;
    row["bounds"] = Json::array({1, 2.25});
    row["check"] = Json::object();
    Json doc;
    doc["rows"] = Json::array({row, row});
    doc["empty"] = Json::array();
    doc["deep"] = Json::array({Json::array({Json::array({false})})});
    EXPECT_EQ(json_text(doc),
              "{\"rows\": [{\"q\": 0.5, \"bounds\": [1, 2.25], \"check\": {}}, "
              "{\"q\": 0.5, \"bounds\": [1, 2.25], \"check\": {}}], \"empty\": [], \"deep\": [[[false]]]}");
    EXPECT_EQ(json_text(doc).find('\n'), std::string::npos);
}
