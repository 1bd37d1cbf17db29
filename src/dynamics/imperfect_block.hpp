// Imperfect blocks (issue 41, docs/imperfect.md): a block whose two corners
// differ, and corners set back by the masonry's finite strength.
//
// The block: a rectangle of half-width b and half-height h (uniform mass),
// or the parallelogram of a wall built out of plumb, on rigid ground.  Three
// imperfections, which combine:
//   lean ψ:          the block stands on a bed inclined by ψ toward theta > 0
//                    (both corners touching): alpha on each side alpha -+ ψ,
//                    the same R, p and Housner restitution on both;
//   out of plumb φ:  a wall built leaning by φ toward theta > 0 on a
//                    horizontal bed: its centre of gravity shifted by
//                    h tan φ from the base's centre; alpha, R, p and the
//                    restitution differ on the two sides;
//   setback u:       the pivot set back from each edge by half the width of
//                    the compressed zone, the rectangular stress block of NTC
//                    2018 eq. 7.8.2 (0.85 f_c over x = N / (0.85 f_c t)):
//                    u = x / 2 = b sigma0 / (0.85 f_c), sigma0 = W / (2 b t)
//                    = 2 rho g h the mean stress of the block's own weight.
// Each corner sigma is then the vector r_sigma from its pivot to the centre
// of gravity, and (docs/imperfect.md, by angular momentum about each pivot):
//   alpha_sigma = the angle of r_sigma from the vertical, R_sigma = |r_sigma|,
//   p_sigma^2 = g R_sigma / (k^2 + R_sigma^2),  k^2 = (b^2 + e^2 + h^2) / 3,
//   e onto sigma = (k^2 + r_+ . r_-) / (k^2 + R_sigma^2),
// where k is the radius of gyration about the centre of gravity and e = h
// tan φ.  The perfect rectangle gives back eqs. 2 and 4 (p^2 = 3 g / 4R) and
// Housner's 1 - 1.5 sin^2 alpha.
#pragma once

#include <functional>
#include <optional>
#include <string>
#include <vector>

#include <cmath>

#include "dynamics/ground_input.hpp"
#include "dynamics/model.hpp"
#include "dynamics/simulate.hpp"

namespace rocking::dynamics {

// The masonry's density when none is given, kg/m^3 (18 kN/m^3, a solid
// brick or stone masonry's weight in NTC 2018's Circolare, Table C8.5.I).
constexpr double kDefaultMasonryDensity = 1800.0;

struct Imperfection {
    double lean = 0;          // rad, toward theta > 0
    double out_of_plumb = 0;  // rad, toward theta > 0
    double fc = 0;            // masonry compressive strength, Pa (0: rigid corners, no setback)
    double density = kDefaultMasonryDensity;  // kg/m^3, for the setback's axial stress
    bool any() const { return lean != 0 || out_of_plumb != 0 || fc != 0; }
};

// The imperfections as a front end takes them: angles (rad) within (-pi/4,
// pi/4), fc in MPa in (0, 1000] or absent, density (kg/m^3) in (0, 1e5] and
// only with fc.  std::invalid_argument naming the caller's argument
// (name("lean") -> "--lean" or "lean") where one is wrong.
struct ImperfectionSpec {
    std::optional<double> lean, out_of_plumb, fc_mpa, density;
};
Imperfection imperfection_of(const ImperfectionSpec& spec, const std::function<std::string(const std::string&)>& name);

struct CornerGeometry {
    double alpha, R, p;       // rad, m, rad/s
    double restitution_onto;  // of an impact that lands on this corner
};

struct ImperfectGeometry {
    double b = 0, h = 0;             // the block's half-width and half-height, m
    double sigma0 = 0, setback = 0;  // Pa, m (0 without fc)
    double k2 = 0;                   // radius of gyration squared about the centre of gravity, m^2
    CornerGeometry plus{}, minus{};
};

// The corners of a block of half-width b and half-height h with the
// imperfections; std::invalid_argument (naming the cause) when the block
// cannot stand (its centre of gravity beyond a pivot), a corner's alpha
// leaves (0, pi/4), or the weight crushes the base (sigma0 >= 0.85 fc).
ImperfectGeometry imperfect_geometry(double b, double h, const Imperfection& imperfection);

// With pivots set back (fc > 0), the pulsation at and below which a block of
// slenderness alpha crushes its base under its own weight: 2 rho g R cos
// alpha >= 0.85 fc with R = 3 g / (4 p^2) (eq. 4), so p^2 <= 3 rho g^2 cos
// alpha / (1.7 fc); 0 without fc.
double crushing_p(double alpha, const Imperfection& imperfection);

// The lowest p from which the block of slenderness alpha with these
// imperfections stands (imperfect_geometry accepts it: it does not crush,
// and a lean does not take a set-back corner's alpha to 0), to 1e-12
// relative above the limit: where a search over p starts.  0 for a block
// that stands at every p, INFINITY for one that stands at none up to 1000 rad/s.
double lowest_standing_p(double alpha, const Imperfection& imperfection);

// The p from which every block of these slendernesses stands (the largest
// of their lowest_standing_p): where a range over p shared by them starts
// when the caller gives no start of its own.
double lowest_standing_p(const std::vector<double>& alphas, const Imperfection& imperfection);

// The same for a symmetric block `base` given by its alpha and R, or its p,
// which gives R = 3 g / (4 p^2) (eq. 4) and the half-dimensions R sin alpha,
// R cos alpha.
ImperfectGeometry imperfect_geometry(const Block& base, const Imperfection& imperfection);

// The model of `base` (a symmetric block: its alpha and R, or its p, which
// gives R = 3 g / (4 p^2) and the half-dimensions R sin alpha, R cos alpha)
// with the imperfections.  restitution: a factor for both corners, or NaN
// for each corner's own from the geometry above.  Symmetric imperfections
// (a setback alone) give a symmetric model (minus unset).
Model imperfect_model(Equation equation, const Block& base, const Imperfection& imperfection, double restitution);

// One line: the imperfections and the corners they give; restitution as
// imperfect_model's (NaN: each corner's own, else the factor given).
std::string describe_imperfection(const Imperfection& imperfection, const ImperfectGeometry& g,
                                  double restitution = NAN);

// The largest share of the way to the top during the input, each side by
// its own alpha: max(theta/alpha_+, -theta/alpha_-), or max |theta| over
// the block's alpha where the model is symmetric (a setback alone: the
// record kernel keeps no sides).
double peak_over_own_alpha(const SimulationResult& r, const Model& model);

// Whether the input lifts the block at rest at all: it passes a corner's
// uplift threshold (Model::uplift_threshold_on) before its end.
bool input_lifts(const GroundInput& input, const Model& model);

}  // namespace rocking::dynamics
