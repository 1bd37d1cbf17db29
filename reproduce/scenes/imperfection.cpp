#include "imperfection.hpp"

#include <cmath>
#include <cstdio>

#include "dynamics/model.hpp"

namespace rocking::scenes {

namespace imperfection_scene {

namespace {

dynamics::Imperfection strength(double fc_mpa) {
    dynamics::Imperfection i;
    i.fc = fc_mpa * 1e6;
    return i;  // at the default density, dynamics::kDefaultMasonryDensity
}

dynamics::Imperfection lean(double rad) {
    dynamics::Imperfection i;
    i.lean = rad;
    return i;
}

dynamics::Imperfection out_of_plumb(double rad) {
    dynamics::Imperfection i;
    i.out_of_plumb = rad;
    return i;
}

}  // namespace

const std::vector<std::string> kImperfectionColumns = {"imperfection", "lean", "out_of_plumb", "fc_MPa", "density"};

std::vector<NamedImperfection> closed_form_imperfections() {
    return {{"lean 0.01", lean(0.01)},         {"lean 0.02", lean(0.02)},        {"out of plumb 0.01", out_of_plumb(0.01)},
            {"out of plumb 0.02", out_of_plumb(0.02)}, {"fc 1 MPa", strength(1)}, {"fc 2 MPa", strength(2)},
            {"fc 5 MPa", strength(5)}};
}

std::vector<NamedImperfection> record_imperfections() {
    return {{"perfect", {}},           {"lean 0.01", lean(0.01)}, {"lean 0.02", lean(0.02)},
            {"out of plumb 0.01", out_of_plumb(0.01)}, {"fc 1 MPa", strength(1)}, {"fc 2 MPa", strength(2)},
            {"fc 5 MPa", strength(5)}};
}

HalfDimensions half_dimensions(double alpha, double p) {
    const double R = 3.0 * dynamics::kGravity / (4.0 * p * p);
    return {R * std::sin(alpha), R * std::cos(alpha)};
}

void add_imperfection_cells(harness::Table& t, const NamedImperfection& n) {
    const dynamics::Imperfection& i = n.imperfection;
    t.add(n.name).add(i.lean).add(i.out_of_plumb).add(i.fc / 1e6);
    if (i.fc > 0) t.add(i.density);
    else t.add("-");  // the density enters only the setback
}

}  // namespace imperfection_scene

void run_imperfection(SceneContext& ctx) {
    imperfection_scene::run_closed_forms(ctx);
    imperfection_scene::run_records(ctx);
}

}  // namespace rocking::scenes
