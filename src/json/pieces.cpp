#include "json/pieces.hpp"

#include <cmath>

namespace rocking::json {

void add_block(Json& o, const dynamics::GivenBlock& b) {
    const bool sized = b.sized();
    o["given"] = dynamics::given_name(b);
    o["thickness"] = sized ? Json(b.thickness) : Json(nullptr);
    o["height"] = sized ? Json(b.height) : Json(nullptr);
    o["R"] = sized ? Json(b.block.R) : Json(nullptr);
}

Json imperfection_inputs_json(const dynamics::Imperfection& imp) {
    // fc in MPa, the unit the option and the keyword take it in.
    return {{"lean", imp.lean}, {"out_of_plumb", imp.out_of_plumb}, {"fc", imp.fc / 1e6}, {"density", imp.density}};
}

Json imperfection_json(const dynamics::Imperfection& imp, const dynamics::Block& base, double restitution) {
    const dynamics::ImperfectGeometry g = dynamics::imperfect_geometry(base, imp);
    auto corner = [&](const dynamics::CornerGeometry& k) {
        return Json{{"alpha", k.alpha}, {"p", k.p}, {"R", k.R},
                    {"restitution_onto", std::isnan(restitution) ? k.restitution_onto : restitution}};
    };
    Json o = imperfection_inputs_json(imp);
    o["sigma0_kpa"] = g.sigma0 / 1e3;
    o["setback_m"] = g.setback;
    o["corner_plus"] = corner(g.plus);
    o["corner_minus"] = corner(g.minus);
    return o;
}

Json nearest_json(const studies::SpectrumFirst& f, double height) {
    return f.found ? Json{{"found", true}, {"p", f.p}, {"height", height}} : Json{{"found", false}};
}

}  // namespace rocking::json
