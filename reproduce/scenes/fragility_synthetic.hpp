// The fragility scene's fixed synthetic set (docs/fragility.md, "The
// synthetic set"): near-fault pulses and stochastic records made by the
// generators beside the readers (records/synthetic.hpp), so that the scene
// has a study to diff without the shared records.  Used by its grid half
// (fragility.cpp) and its refine half (fragility_capacities.cpp).
#pragma once

#include <array>
#include <cmath>
#include <string>
#include <vector>

#include "fragility_scene.hpp"
#include "records/record.hpp"

namespace rocking::scenes {

// Mavroeidis & Papageorgiou (2003) pulses: five pulse periods T_p = 1/fp from
// 0.5 to 3.125 s (a factor 1.6 apart), each with two (gamma, nu): a two-cycle
// pulse in cosine phase and a three-cycle one in sine phase.  The amplitude
// does not matter (the IDA scales the record); 2 s of rest before and after
// the pulse, as docs/synthetic.md's study of the half-periods.
inline constexpr std::array<double, 5> kPulseFp = {2.0, 1.25, 0.8, 0.5, 0.32};  // Hz
struct PulseShape {
    double gamma, nu;
};
inline const std::array<PulseShape, 2> kPulseShapes = {{{2.0, 0.0}, {3.0, M_PI / 2}}};
inline constexpr double kPulseA = 0.5;      // m/s
inline constexpr double kPulseRest = 2.0;   // s before and after the pulse's support
inline constexpr double kPulseDt = 0.005;   // s
// Rezaeian & Der Kiureghian (2008) stochastic records: the documented defaults
// (records::StochasticDefaults), seeds 1 to 10, 40 s at 0.01 s (seed 1's record
// is the one SyntheticStochastic.DefaultRecordIsPinned pins).
inline constexpr int kStochasticSeeds = 10;
inline constexpr double kStochasticDt = 0.01, kStochasticDuration = 40.0;  // s
// A to_k "recovers" the pulse's half-period 1/(2 fp) within this relative gap.
inline constexpr double kRecoverTol = 0.05;

struct Synthetic {
    std::string set;  // pulse, stochastic
    records::Record record;
    double duration = 0;    // s, as asked of the generator
    double pulse_half = 0;  // 1/(2 fp) for a pulse
};

// The fixed synthetic set, pulses first (by T_p, then shape), then the seeds.
std::vector<Synthetic> synthetic_set();

// The k whose to_k lies within kRecoverTol of the pulse's half-period, as "5 7 9" ("none").
std::string recovering(const fragility_scene::HalfPeriodArray& to, double half);

}  // namespace rocking::scenes
