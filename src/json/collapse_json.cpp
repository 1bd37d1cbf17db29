#include "json/collapse_json.hpp"

#include <cmath>

#include "json/pieces.hpp"

namespace rocking::json {

Json collapse_json(const std::string& file, double alpha, const records::CollapseResult& c,
                   const records::CollapseOptions& o, const dynamics::GivenBlock* given) {
    Json j;
    j["file"] = file;
    j["alpha"] = alpha;
    j["found"] = c.found;
    j["p"] = c.found ? Json(c.p) : Json(nullptr);
    j["p_safe"] = c.found && !c.below_range() ? Json(c.p_safe) : Json(nullptr);
    j["below_range"] = c.below_range();
    j["simulations"] = c.simulations;
    j["search"] = o.describe();
    if (given) {
        j["block_p"] = given->block.p;
        add_block(j, *given);
    }
    if (o.imperfection.any())
        j["imperfection"] = c.found ? imperfection_json(o.imperfection, dynamics::Block::from_p(c.p, alpha),
                                                        o.housner_restitution ? NAN : o.restitution)
                                    : imperfection_inputs_json(o.imperfection);
    return j;
}

}  // namespace rocking::json
