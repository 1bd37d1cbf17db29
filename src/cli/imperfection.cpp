#include "cli/imperfection.hpp"

#include <optional>
#include <cmath>
#include <stdexcept>

namespace rocking::cli {

const std::vector<std::string>& imperfection_flags() {
    static const std::vector<std::string> flags = {"--lean", "--out-of-plumb", "--fc", "--density"};
    return flags;
}

dynamics::Imperfection imperfection_option(const Args& a) {
    auto given = [&](const char* f) -> std::optional<double> {
        if (!a.values.count(f)) return std::nullopt;
        return number(f, a.values.at(f));
    };
    dynamics::ImperfectionSpec spec{given("--lean"), given("--out-of-plumb"), given("--fc"), given("--density")};
    dynamics::Imperfection imp;
    try {
        imp = dynamics::imperfection_of(spec, [](const std::string& n) {
            return n == "out_of_plumb" ? std::string("--out-of-plumb") : "--" + n;
        });
    } catch (const std::invalid_argument& e) {
        throw UsageError(e.what());
    }
    if (imp.any() && a.values.count("--friction"))
        throw UsageError("--friction does not apply to an imperfect block (--lean, --out-of-plumb, --fc): the "
                         "sliding-rocking model's block is a perfect rectangle");
    return imp;
}

void imperfection_into(const Args& a, records::CollapseOptions& model) {
    model.imperfection = imperfection_option(a);
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

std::string imperfection_flags_text(const Args& a) {
    std::string text;
    for (const std::string& f : imperfection_flags())
        if (a.values.count(f)) text += " " + f + " " + a.values.at(f);
    return text;
}

}  // namespace rocking::cli
