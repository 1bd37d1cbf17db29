// The imperfection scene (issue 41, items 4-5 for imperfect blocks): the
// paper's closed forms and eq. 27's conservativeness retested on blocks that
// lean, stand out of plumb or pivot on set-back corners
// (dynamics/imperfect_block.hpp).  Its two halves share the imperfections'
// names and the blocks' geometry.
#pragma once

#include <string>
#include <vector>

#include "dynamics/imperfect_block.hpp"
#include "scene.hpp"

namespace rocking::scenes::imperfection_scene {

struct NamedImperfection {
    std::string name;  // the rows' label: "lean 0.01", "fc 2 MPa", "perfect"
    dynamics::Imperfection imperfection;
};

// The closed forms' imperfections: two leans, two out-of-plumb angles and
// three strengths (setbacks) at the default density.
std::vector<NamedImperfection> closed_form_imperfections();
// The records' imperfections: the perfect block first (the fragility scene's
// study, again), then two leans, one out-of-plumb angle and the three strengths.
std::vector<NamedImperfection> record_imperfections();

// The half-width and half-height of the perfect block (alpha, p):
// R = 3 g / (4 p^2) (eq. 4), b = R sin alpha, h = R cos alpha.
struct HalfDimensions {
    double b, h;
};
HalfDimensions half_dimensions(double alpha, double p);

// The imperfection as its columns print it (rad, rad, MPa, kg/m3).
void add_imperfection_cells(harness::Table& t, const NamedImperfection& n);
extern const std::vector<std::string> kImperfectionColumns;

void run_closed_forms(SceneContext& ctx);
void run_records(SceneContext& ctx);

}  // namespace rocking::scenes::imperfection_scene
