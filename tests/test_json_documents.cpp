// The library's --json documents (src/json, issue 42), each builder alone
// against a literal document: its members, their order and their kinds
// (json_text prints an integer without a point, a double to 17 digits).  The
// command line prints these values and the Python module converts them, so
// a member renamed, moved or turned from an integer into a double fails here
// before it reaches either front end.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "cli/json_text.hpp"
#include "json/collapse_json.hpp"
#include "json/pieces.hpp"
#include "json/qfactor_json.hpp"
#include "qfactor/closed_forms.hpp"
#include "qfactor/superposition.hpp"

using rocking::cli::json_text;
namespace json = rocking::json;

namespace {

const std::string kModelText = "\"linearised eq. 3, one corner, no impact, collapse theta(t_fin) = alpha\"";

}  // namespace

// rocking q --case 2 --x 0.5 --json's document: q by superposition (S2),
// checked against eq. 15's closed form, a second method.
TEST(JsonDocuments, QOfCase2) {
    const rocking::PulseTrain train = rocking::repeated_case(2, 2);
    const rocking::QFactor q = rocking::q_factor(train, 0.5);
    const json::Json doc = json::q_json(train, 0.5, q, "eq. 15", rocking::collapse_excursion(train, 0.5));
    EXPECT_NEAR(doc["q"].get<double>(), rocking::q2(0.5), 1e-14 * rocking::q2(0.5));
    EXPECT_TRUE(doc["pulses"].is_number_integer());
    EXPECT_EQ(json_text(doc),
              "{\"input\": \"case 2, N = 2\", \"pulses\": 2, \"x\": 0.5, \"q\": 4.3882187233118106, "
              "\"condition\": 2.0888296517954248, \"equation\": \"eq. 15\", \"model\": " + kModelText +
                  ", \"rocking_starts\": true, \"impact_free\": true, \"motion_reverses\": false, "
                  "\"passes_alpha_before_t_fin\": false}");
}

// Rows that stop early (theta left the double range): the end at t_fin k/steps
// for the first row missing, its reason, and the rows kept.  Case 2 ends at
// t_fin = 2 to, so with 3 steps the rows stand at 0, 2/3 and 4/3.
TEST(JsonDocuments, ResponseSaysWhereItsRowsEnd) {
    const rocking::PulseTrain train = rocking::repeated_case(2, 2);
    ASSERT_EQ(train.t_fin(), 2.0);
    rocking::Excursion e{};
    e.onset = true, e.min_phi = 0.5, e.min_dphi = -0.1, e.max_phi = 1.2;  // lifts, no impact, reverses, passes alpha
    std::vector<rocking::ResponseState> rows(2);
    rows[1].phi = 0.5, rows[1].dphi = -0.25;
    const std::string head = "{\"input\": \"case 2, N = 2\", \"x\": 3, \"q\": 7.5, \"at_collapse_q\": false, \"model\": " +
                             kModelText +
                             ", \"rocking_starts\": true, \"impact_free\": true, \"motion_reverses\": true, "
                             "\"passes_alpha_before_t_fin\": true, ";
    EXPECT_EQ(json_text(json::response_json(train, 3, 7.5, false, e, rows, 3)),
              head + "\"rows_complete\": false, \"rows_end_at\": 1.3333333333333333, \"rows_end_reason\": \"theta/alpha "
                     "leaves the double range (beyond 1.8e308) on the linearised equation\", \"samples\": [[0, 0, 0], "
                     "[0.66666666666666663, 0.5, -0.25]]}");
    // All steps + 1 rows: complete, and null where no end is.
    EXPECT_EQ(json_text(json::response_json(train, 3, 7.5, false, e, rows, 1)),
              head + "\"rows_complete\": true, \"rows_end_at\": null, \"rows_end_reason\": null, \"samples\": [[0, 0, 0], "
                     "[2, 0.5, -0.25]]}");
}

// Nothing found: p and p_safe null, the simulations an integer; the block
// given by alpha and p has no size (nulls); the imperfections alone, fc in MPa.
TEST(JsonDocuments, CollapseWithNothingFound) {
    rocking::records::CollapseResult c;
    c.found = false, c.simulations = 12;
    rocking::records::CollapseOptions o;
    o.imperfection.lean = 0.002, o.imperfection.fc = 2e6, o.imperfection.density = 1800;
    rocking::dynamics::GivenBlock given;
    given.alpha = 0.25, given.block = rocking::dynamics::Block::from_p(2.5, 0.25);
    const json::Json doc = json::collapse_json("rec.txt", 0.25, c, o, &given);
    EXPECT_TRUE(doc["simulations"].is_number_integer());
    EXPECT_EQ(json_text(doc), "{\"file\": \"rec.txt\", \"alpha\": 0.25, \"found\": false, \"p\": null, \"p_safe\": null, "
                              "\"below_range\": false, \"simulations\": 12, \"search\": " + json_text(json::Json(o.describe())) +
                                  ", \"block_p\": 2.5, \"given\": \"alpha and p\", \"thickness\": null, \"height\": null, "
                                  "\"R\": null, \"imperfection\": {\"lean\": 0.002, \"out_of_plumb\": 0, \"fc\": 2, "
                                  "\"density\": 1800}}");
    // Without a block or imperfections, the document ends at the search.
    const json::Json plain = json::collapse_json("rec.txt", 0.25, c, rocking::records::CollapseOptions{}, nullptr);
    EXPECT_EQ(plain.back(), json::Json(rocking::records::CollapseOptions{}.describe()));
    EXPECT_EQ(plain.size(), 8u);
}

TEST(JsonDocuments, NearestSideOfAMark) {
    rocking::studies::SpectrumFirst f{};
    EXPECT_EQ(json_text(json::nearest_json(f, 3.0)), "{\"found\": false}");
    f.found = true, f.p = 2.5;
    EXPECT_EQ(json_text(json::nearest_json(f, 1.25)), "{\"found\": true, \"p\": 2.5, \"height\": 1.25}");
}
