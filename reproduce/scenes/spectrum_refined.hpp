// The spectrum scene's second view (issue 39, item 4): the refine method's
// overturning set beside the grid method's, per Norcia record and alpha.  The
// grids see an island only where one of their points falls on it; the refine
// method finds every island and gap wider than its width w in ln p
// (docs/overturning_set.md), so its first overturning may lie well below the
// grids' lowest p, and its first robust collapse (the start of the first
// interval wider than 5e-3 in ln p) is the capacity the grids approximate.
#pragma once

#include <string>
#include <vector>

#include "scene.hpp"
#include "studies/spectrum.hpp"

namespace rocking::scenes {

// The files this view writes (skipped with the scene's reason without the records).
inline constexpr const char* kRefinedFile = "spectrum_refined.csv";
inline constexpr const char* kRefinedIntervalsFile = "spectrum_refined_intervals.csv";

// The refine method on the grid method's p range and main grid, Table 1's
// model and checks, at the scene's width (expected/spectrum/PROVENANCE.md
// says why that width).
studies::SpectrumOptions refined_spectrum_options();

// One record and alpha: the grid method's spectrum and the refine method's.
struct RefinedPair {
    std::string record;
    double alpha = 0;
    const studies::Spectrum* grid = nullptr;
    studies::Spectrum refined;
};

// spectrum_refined.csv (one row per pair) and spectrum_refined_intervals.csv
// (the refined intervals each row's numbers are computed from).
void write_spectrum_refined(SceneContext& ctx, const std::vector<RefinedPair>& pairs, const std::string& inputs);

}  // namespace rocking::scenes
