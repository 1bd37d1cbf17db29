#include "fragility_synthetic.hpp"

#include "records/synthetic.hpp"

namespace rocking::scenes {

std::vector<Synthetic> synthetic_set() {
    std::vector<Synthetic> out;
    for (double fp : kPulseFp)
        for (const PulseShape& shape : kPulseShapes) {
            records::PulseParameters p{kPulseA, fp, shape.nu, shape.gamma, 0};
            const double half = shape.gamma / (2 * fp);
            p.t0 = kPulseRest + half;
            const double duration = p.t0 + half + kPulseRest;
            out.push_back({"pulse", records::pulse_record(p, kPulseDt, duration), duration, 1 / (2 * fp)});
        }
    const records::StochasticParameters d = records::default_stochastic_parameters();
    for (int seed = 1; seed <= kStochasticSeeds; ++seed)
        out.push_back({"stochastic", records::stochastic_record(d, seed, kStochasticDt, kStochasticDuration),
                       kStochasticDuration, 0});
    return out;
}

std::string recovering(const fragility_scene::HalfPeriodArray& to, double half) {
    std::string out;
    for (int k = 0; k < studies::kHalfPeriods; ++k)
        if (std::fabs(to[k] / half - 1) <= kRecoverTol) out += (out.empty() ? "" : " ") + std::to_string(k + 1);
    return out.empty() ? "none" : out;
}

}  // namespace rocking::scenes
