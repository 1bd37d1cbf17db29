// The planar rigid block on a ground with Coulomb friction mu (issue 41; the
// model of Shenton & Jones 1991 and Shenton 1996): four regimes, rest (both
// base corners stuck), slide (both corners on the ground, slipping), rock (on
// one corner, stuck) and slide-rock (on one corner, slipping), full
// nonlinear equations, no free flight.  Everything here is one instant's
// mechanics, derived by Newton-Euler in the ground's frame (where the ground
// acceleration is an inertial force -m a_ground, which in the paper's sign is
// +m A: A > 0 drives theta > 0); sliding_simulate.hpp follows a run.
//
// The block: half-width b = R sin(alpha), half-height h = R cos(alpha), mass
// m, I_G = m R^2/3 about its centre of gravity G.  theta > 0 is the block
// turned about its corner sigma = +1 (x = +b), G moving towards +x.  Forces
// per unit mass: n = N/m up and f = F/m along x at the pivot.  G relative
// to the pivot corner sigma, at theta:
//     dx = -sigma b cos(theta) + h sin(theta),   dy = sigma b sin(theta) + h cos(theta)      (S1)
// so that d(dx)/dtheta = dy and d(dy)/dtheta = -dx, and, the pivot at height
// 0 and at x_p,
//     x_G'' = x_p'' + dy theta'' - dx theta'^2,   y_G'' = -dx theta'' - dy theta'^2        (S2)
//     x_G'' = A + f,   y_G'' = -g + n,   (R^2/3) theta'' = dx n - dy f                     (S3)
#pragma once

namespace rocking::dynamics::sliding {

struct FrictionBlock {
    double alpha = 0.2;  // slenderness, rad: atan(b/h)
    double R = 1.0;      // corner to G, m
    double mu = 0.6;     // Coulomb friction coefficient, static = kinetic
    double b() const;
    double h() const;
    double p() const;    // sqrt(3 g/(4 R)) (eq. 4)
};

// Throws std::invalid_argument for alpha not in (0, pi/4), R not finite and
// > 0, mu not > 0 (mu = inf is the block that never slides).
void check_block(const FrictionBlock& block);

struct Lever {
    double dx, dy;
};
// (S1).
Lever centroid_from_pivot(const FrictionBlock& block, double theta, int sigma);

// One corner on the ground: theta'', the pivot's x_p'', and the contact
// force per unit mass (n, f) at the pivot.  A is the ground's inertial
// acceleration in m/s^2 (a/g times g, the paper's sign).
struct Contact {
    double theta_dd = 0, pivot_dd = 0, n = 0, f = 0;
};

// Rock: the pivot stuck (x_p'' = 0).  From (S2, S3) with R^2 + R^2/3 = 4 R^2/3:
//     theta'' = 3 (dx g + dy A)/(4 R^2),   f = dy theta'' - dx theta'^2 - A,   n = g - dx theta'' - dy theta'^2
// which for sigma = 1 is p^2 [(A/g) cos(alpha - theta) - sin(alpha - theta)], the full
// equation of dynamics/model.hpp.  Holds while n >= 0 and |f| <= mu n.
Contact stick_rocking(const FrictionBlock& block, double theta, double omega, int sigma, double A);

// Slide-rock: the pivot slipping in direction s (sgn x_p'), f = -mu n s.
// With c = dx + mu s dy, (S2, S3) give
//     theta'' = c (g - dy theta'^2)/(R^2/3 + dx c),   n = g - dx theta'' - dy theta'^2,
//     x_p'' = A - mu s n - dy theta'' + dx theta'^2.
// Throws std::domain_error where R^2/3 + dx c <= 0 (the Painleve paradox: no
// solution with a compressive contact force; not met below mu = 1/tan(...)
// of any block here, but said rather than divided by).
Contact slip_rocking(const FrictionBlock& block, double theta, double omega, int sigma, int s, double A);

// Slide: both corners on the ground, theta = theta' = 0, slipping in
// direction s: x'' = A - mu g s, and the corners' normal forces per unit
// mass, from the moment about G with f = -mu g s,
//     n_+ = (g + mu g s h/b)/2,   n_- = (g - mu g s h/b)/2,
// so the trailing corner (-s) lifts where mu > b/h = tan(alpha): the block
// then slide-rocks on its leading corner.
double sliding_accel(const FrictionBlock& block, int s, double A);
double trailing_normal(const FrictionBlock& block);  // n_(-s) per unit mass, either s

enum class Regime { rest, slide, rock, slide_rock };
const char* regime_name(Regime r);

// What a block flat on the ground (theta = theta' = 0) with base velocity v
// (m/s) does under A: the one regime of the four whose forces are
// consistent (n >= 0 at each corner in contact, |f| <= mu n when stuck,
// the friction opposing the slip, theta'' towards the side it turns to).
// sigma is the pivot (rock, slide-rock), s the slip direction (slide,
// slide-rock); 0 where they do not apply.
struct Start {
    Regime regime = Regime::rest;
    int sigma = 0, s = 0;
};
Start start_flat(const FrictionBlock& block, double A, double v);

// Rocking on one corner, at theta' = 0 after a slip stops (x_p' = 0): rock
// if the stuck pivot's friction is within mu n, else slide-rock in the
// direction the pivot is pushed (-sgn f).
Start start_on_corner(const FrictionBlock& block, double theta, double omega, int sigma, double A);

// The impact of corner -sigma as theta reaches 0 from the side of sigma
// (pre-impact velocities of G: xg_dot, yg_dot, and theta'), the new corner
// becoming the pivot with no rebound (its normal velocity 0 after) and the
// old one lifting: the impulse per unit mass (p_t, p_n) at the new corner,
//     x_G'+ = x_G'- + p_t,   y_G'+ = y_G'- + p_n,   (R^2/3)(theta'+ - theta'-) = dx' p_n - dy' p_t,
// with dx' = sigma b, dy' = h (G from the new corner at theta = 0).  Stuck
// (its tangential velocity 0 after):
//     theta'+ = (R^2/3 theta'- - dx' y_G'- + dy' x_G'-)/(4 R^2/3),
// which for a block rocking on a stuck corner is Housner's theta'+ = (1 - 1.5 sin^2 alpha) theta'-;
// kept while |p_t| <= mu p_n.  Otherwise it slips: p_t = mu p_n z with z the
// stuck impulse's sign, c' = dx' - mu z dy',
//     theta'+ = (R^2/3 theta'- - c' y_G'-)/(R^2/3 + c' dx'),   p_n = -dx' theta'+ - y_G'-.
struct Impact {
    double omega = 0;     // theta'+
    double pivot_v = 0;   // the new pivot's x velocity after (0 when stuck)
    double p_n = 0, p_t = 0;
    bool slipped = false;
};
// Throws std::domain_error where the slipping impact has no consistent
// solution (the slip it leaves runs with its friction impulse, or p_n < 0).
Impact corner_impact(const FrictionBlock& block, int sigma, double omega, double xg_dot, double yg_dot);

}  // namespace rocking::dynamics::sliding
