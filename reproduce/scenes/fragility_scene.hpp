// What the fragility scene's two halves share: its blocks, its bootstrap and
// its model (reproduce/scenes/fragility.cpp, the grid method's files, and
// reproduce/scenes/fragility_capacities.cpp, the refine method's), so that
// both run the same study on the same records and say so in the same words.
#pragma once

#include <array>
#include <cstdint>
#include <cstdio>
#include <string>
#include <vector>

#include "dynamics/ground_input.hpp"
#include "records/collapse.hpp"
#include "records_analysis.hpp"
#include "studies/eq27_at_scale.hpp"
#include "studies/ida.hpp"
#include "studies/record_order.hpp"
#include "studies/scaled_input.hpp"

namespace rocking::scenes::fragility_scene {

using HalfPeriodArray = std::array<double, studies::kHalfPeriods>;

// Two slendernesses by two sizes: a slender and a stockier block, a large
// (p = 1.5 rad/s, about 4.4 m half-diagonal) and a small one (p = 3 rad/s,
// about 1.1 m).  Chosen so that the scene runs in a few seconds on 2 cores.
inline const std::vector<studies::BlockShape> kBlocks = {{0.1, 1.5}, {0.1, 3.0}, {0.2, 1.5}, {0.2, 3.0}};
inline constexpr int kResamples = 500;
inline constexpr std::uint64_t kSeed = 1;
inline constexpr double kBootstrapLevel = 0.9;
inline constexpr double kWilsonLevel = 0.95;

inline std::string label(double v) {
    char b[16];
    std::snprintf(b, sizeof b, "%.2f", v);
    return b;
}

// The grid method's study, the scene's first half.
inline studies::FragilityStudyOptions study_options() {
    studies::FragilityStudyOptions o;
    o.ida.model = table1_search();  // Table 1's model and solver (its scan fields are unused by the IDA)
    o.ida.checks = studies::IdaOptions::Checks::first_collapse;
    o.resamples = kResamples;
    o.seed = kSeed;
    o.level = kBootstrapLevel;
    return o;
}

// The reference method on a bracket in q: both ends re-simulated through
// records::collapses_at with table1_check() (GSL rk8pd at rtol = atol = 1e-13
// alpha) on the input scaled to each end's q, not through the IDA's own check
// path; "yes" when it sees the same bracket.
inline std::string reference_verdict(const dynamics::GroundInput& input, double alpha, double p,
                                     const studies::Bracket& b) {
    const records::CollapseOptions check = table1_check();
    auto at = [&](double q) {
        return records::collapses_at(*studies::scaled(input, q * alpha / input.peak()), alpha, p, check);
    };
    return at(b.collapse) && !at(b.safe) ? "yes" : "no";
}

// A record's identity, by whose order every bootstrap of the scene draws the
// records (studies/record_order.hpp), so that no interval depends on the
// order the records are listed in: a shared record's is the digest of its
// step and samples; a generated one's the digest of its label, which names
// every parameter of its generator, since its samples' last bits follow the
// libm (docs/synthetic.md) and their digest would reorder the draws on
// another machine.
inline std::string identity_of(const dynamics::SampledInput& input, bool generated, const std::string& label) {
    return generated ? studies::text_digest(label) : studies::sample_digest(input);
}

inline const char* kIdentityNote =
    "the SHA-256 (hex) by whose order every bootstrap draws the records, in place of the order listed: "
    "of the record's step (%.17g text and ';') and samples in g as doubles (studies::sample_digest) for a shared "
    "record, of its label for a generated one";

inline std::string bootstrap_text() {
    char boot[300];
    std::snprintf(boot, sizeof boot,
                  "%d resamples of the records with replacement, GSL mt19937 seeded %llu (machine-independent), "
                  "the records drawn in the order of their identities (the points file's identity column), "
                  "percentile interval at %.0f %%",
                  kResamples, static_cast<unsigned long long>(kSeed), 100 * kBootstrapLevel);
    return boot;
}

inline std::string blocks_text() {
    std::string blocks = "blocks (alpha, p rad/s):";
    for (const studies::BlockShape& b : kBlocks) blocks += " (" + label(b.alpha) + ", " + label(b.p) + ")";
    return blocks;
}

inline std::string wilson_note() {
    char wil[160];
    std::snprintf(wil, sizeof wil,
                  "wilson_lo..hi: Wilson score interval at %.0f %%, the cases taken as independent (they are not: "
                  "the blocks share their records)", 100 * kWilsonLevel);
    return wil;
}

}  // namespace rocking::scenes::fragility_scene
