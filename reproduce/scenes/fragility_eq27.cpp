#include "fragility_eq27.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace rocking::scenes::fragility_scene {

studies::Eq27Study eq27_of(const Eq27Input& in) {
    return studies::eq27_from_points(in.points, in.to, in.identities, kBlocks, kWilsonLevel,
                                     {kResamples, kSeed, kBootstrapLevel});
}

void eq27_notes(harness::Table& et, const Eq27Input& in, const studies::Eq27Study& eq27, const std::string& suffix) {
    // How near a verdict is to flipping: the smallest |ln(collapse q / eq. 27's q)| over the collapsed cases.
    // The ill-conditioned first collapses, placed within their grid gap, apart.
    double margin = 1e300, margin_ill = 1e300;
    std::string margin_at;
    for (const studies::Eq27Case& c : eq27.cases) {
        if (!c.point.collapsed) continue;
        const bool ill = in.ill[c.record][c.block];
        for (int k = 0; k < studies::kHalfPeriods; ++k) {
            const double m = std::fabs(std::log(c.point.q / c.q_eq27[k]));
            if (ill) {
                margin_ill = std::min(margin_ill, m);
                continue;
            }
            if (m < margin) {
                margin = m;
                margin_at = in.names[c.record] + " alpha " + label(kBlocks[c.block].alpha) + " p " +
                            label(kBlocks[c.block].p) + " to_" + std::to_string(k + 1);
            }
        }
    }
    char mg[64], mgi[64];
    std::snprintf(mg, sizeof mg, "%.3g", margin);
    std::snprintf(mgi, sizeof mgi, "%.3g", margin_ill);
    et.note("margin" + suffix, std::string("the smallest |ln(collapse q / eq. 27's q)| over the collapsed cases with a "
                                           "well-conditioned first collapse: ") + mg + " (" + margin_at + "); over those with an "
                                           "ill-conditioned one: " + (margin_ill < 1e300 ? mgi : "none") +
                                   "; a verdict flips only if a collapse q moves by that much");
    // The two intervals at one level: Wilson's at the bootstrap's, width against width.
    double ratio_lo = 1e300, ratio_hi = 0;
    std::string zeros;
    for (int k = 0; k < studies::kHalfPeriods; ++k) {
        const studies::Eq27Share& s = eq27.shares[k];
        if (s.non_conservative == 0) {
            zeros += (zeros.empty() ? "to_" : ", to_") + std::to_string(k + 1);
            continue;
        }
        const studies::WilsonInterval w = studies::wilson_interval(s.non_conservative, s.cases, kBootstrapLevel);
        const double r = (s.bootstrap.hi - s.bootstrap.lo) / (w.hi - w.lo);
        ratio_lo = std::min(ratio_lo, r);
        ratio_hi = std::max(ratio_hi, r);
    }
    char lv[400];
    std::snprintf(lv, sizeof lv,
                  "the columns hold a %.0f %% bootstrap beside a %.0f %% Wilson interval; at %.0f %% both, the "
                  "bootstrap's width is %.3g to %.3g times Wilson's over the k with a non-conservative case",
                  100 * kBootstrapLevel, 100 * kWilsonLevel, 100 * kBootstrapLevel, ratio_lo, ratio_hi);
    et.note("levels" + suffix, lv);
    if (!zeros.empty()) {
        // Clopper-Pearson's upper bound for 0 of n at the two-sided level: 1 - ((1 - level)/2)^(1/n).
        char z[400];
        std::snprintf(z, sizeof z,
                      ": no case and no record non-conservative, so the bootstrap is [0, 0] (no resample can draw a "
                      "record that is not there); over records, 0 of %d bounds the share of records non-conservative "
                      "anywhere, and so the share of cases, by %.3g (Clopper-Pearson at %.0f %%)",
                      eq27.records, 1 - std::pow((1 - kBootstrapLevel) / 2, 1.0 / eq27.records), 100 * kBootstrapLevel);
        et.note("zero" + suffix, zeros + z);
    }
}

void eq27_rows(harness::Table& et, const studies::Eq27Study& eq27, const std::string& set) {
    for (int k = 0; k < studies::kHalfPeriods; ++k) {
        const studies::Eq27Share& s = eq27.shares[k];
        int with_any = 0;
        for (const studies::Eq27Cell& c : eq27.map) with_any += c.non_conservative[k] > 0;
        et.row();
        if (!set.empty()) et.add(set);
        et.add(k + 1).add(s.non_conservative).add(s.cases).add(s.share).add(s.wilson.lo).add(s.wilson.hi);
        et.add(with_any).add(s.records_with_any).add(s.records).add(s.bootstrap.lo).add(s.bootstrap.hi);
        et.add(eq27.bootstrap.level).add(eq27.bootstrap.resamples).add(std::to_string(eq27.bootstrap.seed));
    }
}

}  // namespace rocking::scenes::fragility_scene
