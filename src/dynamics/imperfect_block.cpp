#include "dynamics/imperfect_block.hpp"

#include <cmath>
#include <cstdio>
#include <stdexcept>

namespace rocking::dynamics {

namespace {

void refuse(bool bad, const std::string& why) {
    if (bad) throw std::invalid_argument("imperfect block: " + why);
}

struct Vec {
    double x, y;
};

}  // namespace

Imperfection imperfection_of(const ImperfectionSpec& spec, const std::function<std::string(const std::string&)>& name) {
    Imperfection imp;
    auto angle = [&](const std::optional<double>& v, const char* what) {
        if (!v) return 0.0;
        if (!(std::fabs(*v) < M_PI / 4)) {
            char text[160];
            std::snprintf(text, sizeof text, "%s: an angle in rad within (-pi/4, pi/4), toward theta > 0 (got %.6g)",
                          name(what).c_str(), *v);
            throw std::invalid_argument(text);
        }
        return *v;
    };
    imp.lean = angle(spec.lean, "lean");
    imp.out_of_plumb = angle(spec.out_of_plumb, "out_of_plumb");
    if (spec.density && !spec.fc_mpa)
        throw std::invalid_argument(name("density") + " goes with " + name("fc") +
                                    ": it gives the axial stress that sets the pivots back");
    char text[200];
    if (spec.fc_mpa) {
        std::snprintf(text, sizeof text, "%s: the masonry's compressive strength in MPa, in (0, 1000] (got %.17g)",
                      name("fc").c_str(), *spec.fc_mpa);
        if (!(*spec.fc_mpa > 0 && *spec.fc_mpa <= 1e3)) throw std::invalid_argument(text);
        imp.fc = *spec.fc_mpa * 1e6;
    }
    if (spec.density) {
        std::snprintf(text, sizeof text, "%s: the masonry's density in kg/m3, in (0, 1e5] (got %.17g)",
                      name("density").c_str(), *spec.density);
        if (!(*spec.density > 0 && *spec.density <= 1e5)) throw std::invalid_argument(text);
        imp.density = *spec.density;
    }
    return imp;
}

ImperfectGeometry imperfect_geometry(double b, double h, const Imperfection& imp) {
    refuse(!(std::isfinite(b) && std::isfinite(h) && b > 0 && h > 0), "half-width and half-height must be > 0");
    refuse(!(std::isfinite(imp.lean) && std::fabs(imp.lean) < M_PI / 4), "the lean must be within (-pi/4, pi/4) rad");
    refuse(!(std::isfinite(imp.out_of_plumb) && std::fabs(imp.out_of_plumb) < M_PI / 4),
           "the out-of-plumb angle must be within (-pi/4, pi/4) rad");
    refuse(!(std::isfinite(imp.fc) && imp.fc >= 0), "the compressive strength must be >= 0 (0: rigid corners)");
    refuse(!(std::isfinite(imp.density) && imp.density > 0), "the density must be > 0");
    ImperfectGeometry g;
    g.b = b;
    g.h = h;
    if (imp.fc > 0) {
        g.sigma0 = 2 * imp.density * kGravity * h;
        char text[400];
        std::snprintf(text, sizeof text,
                      "the block's weight crushes its base: sigma0 = 2 rho g h = %.4g Pa is not below 0.85 fc = %.4g Pa "
                      "(at this fc and density a block stands up to a height 2h of %.4g m: at this slenderness, p above "
                      "%.4g rad/s, where a range over p such as --p-min must start)",
                      g.sigma0, 0.85 * imp.fc, 0.85 * imp.fc / (imp.density * kGravity),
                      crushing_p(std::atan(b / h), imp));
        refuse(!(g.sigma0 < 0.85 * imp.fc), text);
        g.setback = b * g.sigma0 / (0.85 * imp.fc);
    }
    const double e = h * std::tan(imp.out_of_plumb), bp = b - g.setback;
    g.k2 = (b * b + e * e + h * h) / 3.0;
    // From pivot sigma (at x = sigma bp on the bed) to the centre of gravity
    // (e, h), turned by the lean: the centre moves toward theta > 0.
    const double c = std::cos(imp.lean), s = std::sin(imp.lean);
    auto r_of = [&](int sigma) {
        const double x = e - sigma * bp, y = h;
        return Vec{x * c + y * s, -x * s + y * c};
    };
    const Vec rp = r_of(1), rm = r_of(-1);
    const double dot = rp.x * rm.x + rp.y * rm.y;
    auto corner = [&](const Vec& r, int sigma) {
        CornerGeometry k;
        k.alpha = std::atan2(-sigma * r.x, r.y);
        k.R = std::hypot(r.x, r.y);
        k.p = std::sqrt(kGravity * k.R / (g.k2 + k.R * k.R));
        k.restitution_onto = (g.k2 + dot) / (g.k2 + k.R * k.R);
        return k;
    };
    g.plus = corner(rp, 1);
    g.minus = corner(rm, -1);
    for (const CornerGeometry* k : {&g.plus, &g.minus}) {
        const char* side = k == &g.plus ? "theta > 0" : "theta < 0";
        char text[240];
        std::snprintf(text, sizeof text,
                      "on its corner %s alpha = %.6g rad: %s", side, k->alpha == 0 ? 0.0 : k->alpha,
                      k->alpha <= 0 ? "the centre of gravity is beyond the pivot, the block cannot stand"
                                    : "beyond pi/4, not a slender block (the engine's range is (0, pi/4))");
        refuse(!(k->alpha > 0 && k->alpha < M_PI / 4), text);
    }
    return g;
}

double crushing_p(double alpha, const Imperfection& imp) {
    if (!(imp.fc > 0)) return 0.0;
    return std::sqrt(3 * imp.density * kGravity * kGravity * std::cos(alpha) / (1.7 * imp.fc));
}

double lowest_standing_p(double alpha, const Imperfection& imp) {
    if (!imp.any()) return 0.0;
    auto stands = [&](double p) {
        try {
            imperfect_geometry(Block::from_p(p, alpha), imp);
            return true;
        } catch (const std::invalid_argument&) {
            return false;
        }
    };
    // A larger p is a smaller block: less weight on its base, a smaller setback.
    double lo = crushing_p(alpha, imp), hi = 1000.0;
    if (lo == 0.0 && stands(1e-300)) return 0.0;
    if (!stands(hi)) return INFINITY;
    if (!(lo > 0)) lo = 1e-3;
    while (stands(lo) && lo > 1e-12) lo /= 2;
    while (hi - lo > 1e-12 * hi) {
        const double mid = 0.5 * (lo + hi);
        (stands(mid) ? hi : lo) = mid;
    }
    return hi;
}

double lowest_standing_p(const std::vector<double>& alphas, const Imperfection& imp) {
    double p = 0.0;
    for (double alpha : alphas) p = std::fmax(p, lowest_standing_p(alpha, imp));
    return p;
}

ImperfectGeometry imperfect_geometry(const Block& base, const Imperfection& imp) {
    const double R = base.R > 0 ? base.R : 3.0 * kGravity / (4.0 * base.p * base.p);
    return imperfect_geometry(R * std::sin(base.alpha), R * std::cos(base.alpha), imp);
}

Model imperfect_model(Equation equation, const Block& base, const Imperfection& imp, double restitution) {
    const ImperfectGeometry g = imperfect_geometry(base, imp);
    Model m;
    m.equation = equation;
    m.block = {g.plus.alpha, g.plus.p, g.plus.R};
    m.restitution = std::isnan(restitution) ? g.plus.restitution_onto : restitution;
    if (imp.lean != 0 || imp.out_of_plumb != 0)
        m.minus = {g.minus.alpha, g.minus.p, std::isnan(restitution) ? g.minus.restitution_onto : restitution};
    return m;
}

double peak_over_own_alpha(const SimulationResult& r, const Model& model) {
    if (model.symmetric()) return r.max_abs_theta_input / model.block.alpha;
    return std::max(r.peak_plus_input / model.block.alpha, r.peak_minus_input / model.minus.alpha);
}

bool input_lifts(const GroundInput& input, const Model& model) {
    if (model.symmetric()) return input.peak() > model.uplift_threshold();
    return first_beyond(input, 0.0, input.t_end(), model.uplift_threshold_on(1), model.uplift_threshold_on(-1)) <
           input.t_end();
}

std::string describe_imperfection(const Imperfection& imp, const ImperfectGeometry& g, double restitution) {
    char text[600];
    int n = std::snprintf(text, sizeof text, "imperfect block:");
    if (imp.lean != 0) n += std::snprintf(text + n, sizeof text - n, " lean %.6g rad (bed inclined),", imp.lean);
    if (imp.out_of_plumb != 0)
        n += std::snprintf(text + n, sizeof text - n, " out of plumb %.6g rad (centre of gravity %.4g m off the base's centre),",
                           imp.out_of_plumb, g.h * std::tan(imp.out_of_plumb));
    if (imp.fc != 0)
        n += std::snprintf(text + n, sizeof text - n,
                           " fc %.4g MPa, density %.5g kg/m3: sigma0 %.4g kPa, pivot set back %.4g mm (NTC 2018 eq. 7.8.2 "
                           "stress block, 0.85 fc),",
                           imp.fc / 1e6, imp.density, g.sigma0 / 1e3, g.setback * 1e3);
    const bool own = std::isnan(restitution);
    std::snprintf(text + n, sizeof text - n,
                  " corner theta > 0: alpha %.6g, p %.6g rad/s, e onto it %.6g; corner theta < 0: alpha %.6g, p %.6g rad/s, "
                  "e onto it %.6g%s",
                  g.plus.alpha, g.plus.p, own ? g.plus.restitution_onto : restitution, g.minus.alpha, g.minus.p,
                  own ? g.minus.restitution_onto : restitution, own ? " (each corner's own, from its geometry)" : " (given)");
    return text;
}

}  // namespace rocking::dynamics
