// What the sliding scene's parts share (issue 41, items 4-5): its block
// family, its friction coefficients and tolerances, one run of each model in
// the same terms, and the rule that tells a sliding effect from a near-tie of
// the rocking model itself.  The parts: sliding_truth.cpp (the closed forms),
// sliding_claim.cpp (the paper's "sliding can be neglected below alpha =
// 0.35" on the shared records), sliding_eq27.cpp (eq. 27's non-conservative
// share with friction), sliding_fig05.cpp (Figure 5's Rd < 1 with friction).
#pragma once

#include <array>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "dynamics/ground_input.hpp"
#include "dynamics/simulate.hpp"
#include "records/record.hpp"
#include "scene.hpp"

namespace rocking::scenes::sliding_scene {

// Every block of the claim and Figure 5 parts stands H = 2 m tall (full
// height): alpha sets its width, R = (H/2)/cos(alpha), p = sqrt(3 g/(4 R)),
// 2.6-2.7 rad/s from alpha 0.05 to 0.3.  The eq. 27 part keeps the fragility
// scene's four blocks (alpha, p), so that its ideal share is that scene's.
inline constexpr double kHeight = 2.0;
inline constexpr double kGravity = 9.81;  // m/s^2, the engine's
inline constexpr std::array<double, 3> kFrictions = {0.8, 0.6, 0.4};
// The block that never slides: the sliding engine with this mu reproduces
// the rocking-only full model (docs/sliding.md), the scene's control.
inline constexpr double kControlMu = 1e6;
// Every run twice, at these rtol = atol (in alpha): the sliding engine's
// event-driven Dormand-Prince and the rocking-only full model's dopri5 alike.
inline constexpr double kRtol = 1e-9, kRtolTight = 1e-11;
// A change of the peak rotation that counts (the 5 %).
inline constexpr double kPeakChange = 0.05;

double half_diagonal(double alpha);  // R = (H/2)/cos(alpha), m

// The shared records as the record parts run them: each as read, as an
// input in g (as table1 makes it) and labelled by its path under root.
struct SceneRecords {
    std::vector<records::Record> read;
    std::vector<std::unique_ptr<dynamics::SampledInput>> inputs;
    std::vector<std::string> labels;
};
// The shared records (records_analysis.hpp's record_files), or none, with
// each of `outputs` skipped (kNoRecords), when the records folder is absent.
std::optional<SceneRecords> scene_records(SceneContext& ctx, const std::vector<std::string>& outputs);
double pulsation(double alpha);      // p = sqrt(3 g/(4 R)), rad/s (eq. 4)
std::string number_label(double v);  // %g: "0.4", "1e+06"
std::string digits10(double v);      // %.10g: the tables' rotations and slips (tolerances far wider)

// One run in the terms every part reads.  A sliding run the model cannot
// follow has `outside` set and nothing else: free flight (the block leaves
// the ground, n = 0 at its pivot) or no contact force consistent with
// Coulomb's law (the Painleve case of slide-rock, met at mu = 1e6 where n
// nears 0: friction_block.hpp).
struct Run {
    bool outside = false;
    bool overturned = false;       // at any time, the free rocking after the input included
    bool fell_during_input = false;
    bool final_rotation = false;   // |theta(t_fin)| >= alpha (or fell during the input): the paper's criterion
    bool peak_rotation = false;    // |theta| reached alpha during the input
    double peak = 0;               // max |theta|/alpha during the input
    double theta_tfin = 0;         // theta(t_fin)/alpha (0 when it fell during the input)
    bool slid = false;             // slipped at some time (the sliding engine)
    double max_slip = 0;           // largest |slip| of the base, m
    int impacts = 0, slipping_impacts = 0;
    bool collapse(dynamics::Criterion c) const;
};

// The rocking-only full model (eq. 1 in the standard Housner form, Housner's
// restitution 1 - 1.5 sin^2 alpha, overturning followed after the input),
// Odeint dopri5 at rtol = atol = rtol (in alpha); the block of slenderness
// alpha and pulsation p.
Run rocking_run(const dynamics::GroundInput& input, double alpha, double p, double rtol);
// The sliding-rocking engine (dynamics/sliding/) on Coulomb friction mu, the
// same block (R = 3 g/(4 p^2)), its event-driven solver at rtol = atol.
Run friction_run(const dynamics::GroundInput& input, double alpha, double p, double mu, double rtol);

// What sliding does to one case, from the rocking-only model's four runs
// (the full model at kRtol and kRtolTight, the control mu = 1e6 at both) and
// the friction's two (kRtol, kRtolTight):
//   outside_control the control is outside the model: the rocking-only model's contact fails, nothing
//                   is compared;
//   outside         a friction run is outside the model;
//   rocking_tie     the four rocking-only runs disagree on the outcome, or (safe) their peaks spread
//                   by more than kPeakChange: the rocking model's own sensitivity, not sliding's;
//   sliding_tie     the friction's two runs disagree on the outcome;
//   outcome         both give the outcome opposite to all four;
//   peak_tie        safe, and the peak differs by more than kPeakChange from some of the eight pairs
//                   (friction run, rocking-only run) but not from all: at the 5 % line;
//   peak            from all eight, on the same side;
//   same            otherwise.
enum class Effect { same, outcome, peak, rocking_tie, sliding_tie, peak_tie, outside, outside_control };
Effect classify(const std::array<Run, 4>& rocking, const std::array<Run, 2>& friction);
const char* effect_name(Effect e);
// An effect of sliding (outcome or peak), as opposed to sameness, a tie or a run outside the model.
inline bool is_sliding_effect(Effect e) { return e == Effect::outcome || e == Effect::peak; }

// The parts, each writing its files (or skipping them, saying why).
void write_truth(SceneContext& ctx);
void write_claim(SceneContext& ctx);
void write_eq27(SceneContext& ctx);
void write_fig05(SceneContext& ctx);

}  // namespace rocking::scenes::sliding_scene
