// The rocking block and its equations of motion (Housner), in the paper's
// sign: a ground acceleration a > 0 drives theta > 0.  On corner sigma = sgn theta:
//   full (eqs. 1, 2, 4, corrected sign):  theta'' = p^2 [(a/g) cos(sigma alpha - theta) - sin(sigma alpha - theta)]
//   linearised (eq. 3, corrected sign):   theta'' = p^2 [a/g - sigma alpha + theta]
// (the printed eqs. 1 and 3 have the gravity term's sign wrong: see the errata scene).
#pragma once

#include <algorithm>
#include <string>

namespace rocking::dynamics {

inline constexpr double kGravity = 9.81;  // m/s^2 for geometry; Table 1 uses 981 cm/s^2 as well

enum class Equation { linearised, full };

// A rectangular block of half-width b and half-height h:
//   alpha = atan(b/h), R = sqrt(b^2 + h^2), I0 = (4/3) m R^2 (eq. 2), p = sqrt(3 g / (4 R)) (eq. 4).
// Eq. 2 prints I0 = (1/3)(W/g) 4 H^2 (1 + tan^2 alpha) = (4/3)(W/g) H^2 / cos^2 alpha,
// which is (4/3) m R^2 only when H is the half-height h.
struct Block {
    double alpha;  // slenderness, rad
    double p;      // pulsation, rad/s
    double R;      // distance of the centre of gravity from the corner, m (0 if given by p)

    static Block from_half_dimensions(double b, double h);
    static Block from_half_height(double h, double alpha);  // the H of eq. 2
    static Block from_full_height(double H, double alpha);  // H = 2 h
    static Block from_p(double p, double alpha);            // geometry not needed
};

// Housner's restitution factor on angular velocity, from conservation of
// angular momentum about the impacting corner: e = 1 - 1.5 sin^2 alpha.
double housner_restitution(double alpha);

// The corner theta < 0 of an imperfect block (issue 41, docs/imperfect.md),
// where it differs from the corner theta > 0: its own slenderness and
// pulsation, and the restitution of an impact that lands on it.
struct Corner {
    double alpha = 0;        // rad; 0: the block is symmetric (this corner is block's mirror image)
    double p = 0;            // rad/s
    double restitution = 0;  // angular velocity kept through an impact onto this corner
};

struct Model {
    Equation equation = Equation::linearised;
    Block block{0.1, 2.0, 0.0};  // the corner theta > 0 (and theta < 0 when minus is unset)
    double restitution = 1.0;  // angular velocity kept through an impact onto theta > 0 (1: no dissipation)
    // An imperfect block's corner theta < 0.  Unset (alpha 0), every rule
    // runs exactly as for the symmetric block, bit for bit.
    Corner minus{};

    bool symmetric() const { return minus.alpha == 0.0; }
    // On corner sigma (sgn theta): its slenderness and pulsation; the
    // restitution of an impact landing on it.
    double alpha_on(int sigma) const { return sigma < 0 && minus.alpha != 0.0 ? minus.alpha : block.alpha; }
    double p_on(int sigma) const { return sigma < 0 && minus.alpha != 0.0 ? minus.p : block.p; }
    double restitution_onto(int sigma) const {
        return sigma < 0 && minus.alpha != 0.0 ? minus.restitution : restitution;
    }
    // The bounds the solvers take their scales from: the shorter time scale
    // (1/p) and the smaller rotation (alpha) of the two corners.
    double p_max() const { return symmetric() ? block.p : std::max(block.p, minus.p); }
    double p_min() const { return symmetric() ? block.p : std::min(block.p, minus.p); }
    double alpha_min() const { return symmetric() ? block.alpha : std::min(block.alpha, minus.alpha); }

    // |a|/g above which a block at rest uplifts: alpha (the paper's alpha ~ tan alpha) or tan alpha.
    // An imperfect block: the smaller of its two corners' (uplift_threshold_on).
    double uplift_threshold() const;
    // a/g beyond which a block at rest uplifts onto corner sigma: sigma a/g > this.
    double uplift_threshold_on(int sigma) const;
    // theta'' on corner sigma under a ground acceleration a/g.
    double acceleration(double theta, int sigma, double a_g) const;
    // The rate of theta'' under a ground acceleration a/g changing at a_rate (1/s):
    //   linearised: p^2 (theta' + a')
    //   full:       p^2 [(a' + theta') cos(sigma alpha - theta) + a theta' sin(sigma alpha - theta)]
    double jerk(double theta, double omega, int sigma, double a_g, double a_rate) const;
    // Energy per unit inertia with the ground at rest, and its value at the
    // unstable equilibrium theta = sigma alpha (the top).
    double energy(double theta, double omega, int sigma) const;
    double barrier() const;  // on corner +; barrier_on(sigma) for either
    double barrier_on(int sigma) const;
    // With the ground at rest, whether the block on corner sigma can still
    // overturn: on the near side of the top (sigma theta <= alpha) only with
    // its energy at or above the barrier (impacts only take energy away); on
    // the far side always, and below the barrier for certain, since it
    // cannot come back over the top.
    bool may_overturn(double theta, double omega, int sigma) const;
    std::string describe() const;
};

}  // namespace rocking::dynamics
