#include "cli/imperfection.hpp"

#include <cmath>
#include <stdexcept>

namespace rocking::cli {

const std::vector<std::string>& imperfection_flags() {
    static const std::vector<std::string> flags = {"--lean", "--out-of-plumb", "--fc", "--density"};
    return flags;
}

dynamics::Imperfection imperfection_option(const Args& a) {
    dynamics::Imperfection imp;
    auto has = [&](const char* f) { return a.values.count(f) > 0; };
    auto angle = [&](const char* f) {
        const double v = number(f, a.values.at(f));
        if (!(std::fabs(v) < M_PI / 4))
            throw UsageError(std::string(f) + ": an angle in rad within (-pi/4, pi/4), toward theta > 0 (got " +
                             a.values.at(f) + ")");
        return v;
    };
    if (has("--lean")) imp.lean = angle("--lean");
    if (has("--out-of-plumb")) imp.out_of_plumb = angle("--out-of-plumb");
    if (has("--density") && !has("--fc"))
        throw UsageError("--density goes with --fc: it gives the axial stress that sets the pivots back");
    if (has("--fc")) {
        const double fc = number("--fc", a.values.at("--fc"));
        if (!(fc > 0 && fc <= 1e3))
            throw UsageError("--fc: the masonry's compressive strength in MPa, in (0, 1000] (got " + a.values.at("--fc") +
                             ")");
        imp.fc = fc * 1e6;
    }
    if (has("--density")) {
        const double rho = number("--density", a.values.at("--density"));
        if (!(rho > 0 && rho <= 1e5))
            throw UsageError("--density: the masonry's density in kg/m3, in (0, 1e5] (got " + a.values.at("--density") + ")");
        imp.density = rho;
    }
    if (imp.any() && has("--friction"))
        throw UsageError("--friction does not apply to an imperfect block (--lean, --out-of-plumb, --fc): the "
                         "sliding-rocking model's block is a perfect rectangle");
    return imp;
}

void imperfection_into(const Args& a, records::CollapseOptions& model) {
    model.imperfection = imperfection_option(a);
}

dynamics::ImperfectGeometry geometry_of(const dynamics::Imperfection& imp, const dynamics::Block& base) {
    const double R = base.R > 0 ? base.R : 3.0 * dynamics::kGravity / (4.0 * base.p * base.p);
    return dynamics::imperfect_geometry(R * std::sin(base.alpha), R * std::cos(base.alpha), imp);
}

dynamics::Model imperfect_model_option(const Args& a, dynamics::Equation equation, const dynamics::GivenBlock& given,
                                       double restitution) {
    const dynamics::Imperfection imp = imperfection_option(a);
    try {
        return dynamics::imperfect_model(equation, given.block, imp, restitution);
    } catch (const std::invalid_argument& e) {
        throw UsageError(std::string(e.what()) + " (--lean, --out-of-plumb, --fc, --density on the block given)");
    }
}

std::string imperfection_json(const dynamics::Imperfection& imp, const dynamics::Block& base) {
    const dynamics::ImperfectGeometry g = geometry_of(imp, base);
    auto corner = [](const dynamics::CornerGeometry& k) {
        return "{\"alpha\": " + json_number(k.alpha) + ", \"p\": " + json_number(k.p) + ", \"R\": " + json_number(k.R) +
               ", \"restitution_onto\": " + json_number(k.restitution_onto) + "}";
    };
    return "\"imperfection\": {\"lean\": " + json_number(imp.lean) + ", \"out_of_plumb\": " + json_number(imp.out_of_plumb) +
           ", \"fc_mpa\": " + json_number(imp.fc / 1e6) + ", \"density\": " + json_number(imp.density) +
           ", \"sigma0_kpa\": " + json_number(g.sigma0 / 1e3) + ", \"setback_m\": " + json_number(g.setback) +
           ", \"corner_plus\": " + corner(g.plus) + ", \"corner_minus\": " + corner(g.minus) + "}";
}

}  // namespace rocking::cli
