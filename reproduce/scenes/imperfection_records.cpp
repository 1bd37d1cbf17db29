// The imperfection scene's second half: eq. 27's conservativeness on the
// shared records, as the fragility scene counts it, with imperfect blocks.
// Each record's incremental dynamic analysis on each of the fragility
// scene's four blocks, with each imperfection; a case is non-conservative
// for k when the record overturns the block at a q below eq. 27's, taken two
// ways: as the paper states it (the perfect block's alpha and p) and toward
// each corner of the imperfect block (qfactor/imperfect_q.hpp).
#include <algorithm>
#include <array>
#include <cmath>
#include <filesystem>
#include <memory>
#include <set>

#include "batch/pool.hpp"
#include "dynamics/ground_input.hpp"
#include "fragility_scene.hpp"
#include "imperfection.hpp"
#include "pulse/pulse_train.hpp"
#include "qfactor/closed_forms.hpp"
#include "qfactor/imperfect_q.hpp"
#include "records/measures.hpp"
#include "records/record.hpp"
#include "records_analysis.hpp"
#include "studies/eq27_at_scale.hpp"
#include "studies/eq27_of_block.hpp"
#include "studies/ida.hpp"

namespace rocking::scenes::imperfection_scene {

namespace {

using fragility_scene::HalfPeriodArray;
using fragility_scene::kBlocks;
using fragility_scene::label;


struct SharedRecord {
    std::string file;  // relative to the records folder
    std::unique_ptr<dynamics::SampledInput> input;
    HalfPeriodArray to{};
};

std::vector<SharedRecord> read_records(const std::vector<std::string>& files, const std::string& root) {
    std::vector<SharedRecord> out(files.size());
    batch::run_ordered<int>(
        files.size(), batch::PoolOptions{batch::default_threads()},
        [&](std::size_t i) {
            const records::Record rec = records::read_any(files[i]);
            out[i].file = std::filesystem::relative(files[i], root).string();
            out[i].input = std::make_unique<dynamics::SampledInput>(rec.in_g(9.81), rec.dt, rec.name);  // as table1
            out[i].to = records::half_periods(rec).to;
            return 0;
        },
        [](std::size_t, int&) {});
    return out;
}

studies::IdaOptions ida_options(const dynamics::Imperfection& imp) {
    studies::IdaOptions o = fragility_scene::study_options().ida;
    o.model.imperfection = imp;
    return o;
}

bool well_conditioned(studies::Confirmation c) {
    return c == studies::Confirmation::confirmed || c == studies::Confirmation::disagrees;
}

// An ill-conditioned first collapse is placed by rounding anywhere between
// the grid points around it (each well decided): the gap its q stands for.
struct Gap {
    double safe = 0, collapse = 0;
};
Gap grid_gap(const studies::Ida& ida) {
    const studies::Bracket& b = ida.intervals.front().lower;
    Gap g{0, INFINITY};
    for (const studies::IdaGridPoint& pt : ida.points) {
        if (pt.q <= b.safe && !pt.collapse) g.safe = std::max(g.safe, pt.q);
        if (pt.q >= b.collapse && pt.collapse) g.collapse = std::min(g.collapse, pt.q);
    }
    return g;
}

// Eq. 27's verdict on a case: 1 non-conservative, 0 not, -1 undecided (an
// ill-conditioned first collapse whose grid gap holds eq. 27's q).
int verdict(const studies::IdaPoint& point, bool ill, const Gap& gap, double q27) {
    if (ill && gap.safe < q27 && q27 <= gap.collapse) return -1;
    return studies::non_conservative(point, q27) ? 1 : 0;
}

}  // namespace

void run_records(SceneContext& ctx) {
    const std::string root = records_dir();
    const std::vector<std::string> files = record_files(root);
    if (files.empty()) {
        for (const char* f : {"imperfection_points.csv", "imperfection_eq27.csv"}) ctx.skip(f, kNoRecords);
        return;
    }
    const std::vector<SharedRecord> recs = read_records(files, root);
    const std::vector<NamedImperfection> imps = record_imperfections();
    const std::size_t nr = recs.size(), nb = kBlocks.size(), n = imps.size() * nb * nr;
    std::vector<studies::Ida> idas(n);
    batch::run_ordered<studies::Ida>(
        n, batch::PoolOptions{batch::default_threads()},
        [&](std::size_t j) {
            const studies::BlockShape& b = kBlocks[j / nr % nb];
            return studies::incremental_dynamic_analysis(*recs[j % nr].input, b.alpha, b.p,
                                                         ida_options(imps[j / (nr * nb)].imperfection));
        },
        [&](std::size_t j, studies::Ida& ida) { idas[j] = std::move(ida); });

    const studies::IdaOptions o0 = ida_options({});
    const std::string inputs =
        "every record of the records folder (../shared/records or $ROCKING_RECORDS: esm/ and peer/, as table1 and "
        "fragility), in g with g = 9.81 m/s^2; " + fragility_scene::blocks_text() +
        " (the fragility scene's); imperfections: none (perfect), lean 0.01 and 0.02 rad, out of plumb 0.01 rad, fc 1, "
        "2 and 5 MPa at density 1800 kg/m3 (imperfection_corners.csv gives each block's corners)";
    std::vector<std::string> pcols = kImperfectionColumns;
    for (const char* c : {"record", "alpha", "p", "outcome", "q_collapse", "q_safe", "q_ill_collapse", "q_ill_safe",
                          "q_gap_safe", "q_gap_collapse", "q_censored", "intervals", "check"})
        pcols.push_back(c);
    harness::Table pt(pcols);
    pt.note("scene", "imperfection: each record's first collapse q on each imperfect block (incremental dynamic analysis)");
    pt.note("model", "linearised eq. 3 on each corner with its own alpha and p, each corner's restitution from the "
                     "geometry (Housner's on the perfect block), overturning at any time (free rocking included)");
    pt.note("solver", "exact solver (the record kernel for a symmetric block, the general path for an asymmetric one); " +
                          o0.describe_grid() + "; an imperfect block's grid from where it lifts, q = min over its corners of "
                          "alpha_sigma/alpha when below 1 (IdaOptions::q_start); q = PGA / (alpha g) with the perfect "
                          "block's alpha, the record scaled");
    pt.note("check", o0.describe_checks());
    pt.note("inputs", inputs);
    pt.note("columns", "as fragility_points.csv: outcome collapsed (first collapse found) or censored (none up to "
                       "q_max: q_censored); q_collapse / q_safe: the first collapse's bracket where the check finds it "
                       "well conditioned, q_ill_*: where the probe (input x 1 +- 1e-13) flips an outcome; a first "
                       "collapse at the grid's start has q_collapse = the block's q_start and no bracket; intervals: the number of "
                       "overturning intervals up to q_max; check: the first bracket's verdict; q_gap_safe..collapse: "
                       "for an ill-conditioned one, the grid points around it (safe below, overturning above), "
                       "between which rounding places it");

    // Eq. 27's verdicts per imperfection and k, both ways.
    struct Count {
        int cases = 0, censored = 0, ill = 0;
        std::array<int, studies::kHalfPeriods> nominal{}, corners{}, undecided{}, undecided_corners{};
        std::array<std::set<std::size_t>, studies::kHalfPeriods> rec_nominal, rec_corners;
    };
    std::vector<Count> counts(imps.size());
    for (std::size_t i = 0; i < imps.size(); ++i)
        for (std::size_t b = 0; b < nb; ++b)
            for (std::size_t r = 0; r < nr; ++r) {
                const studies::Ida& ida = idas[(i * nb + b) * nr + r];
                const studies::IdaOptions o = ida_options(imps[i].imperfection);
                Count& c = counts[i];
                ++c.cases;
                pt.row();
                add_imperfection_cells(pt, imps[i]);
                pt.add(recs[r].file).add(label(ida.alpha)).add(label(ida.p));
                bool ill = false;
                Gap gap;
                if (!ida.point.collapsed) {
                    ++c.censored;
                    pt.add("censored").add("-").add("-").add("-").add("-").add("-").add("-").add(ida.point.q);
                    pt.add(static_cast<int>(ida.intervals.size())).add("-");
                } else {
                    const studies::IdaInterval& first = ida.intervals.front();
                    pt.add("collapsed");
                    if (!first.has_lower) {
                        pt.add(ida.point.q).add("-").add("-").add("-").add("-").add("-").add("-");
                        pt.add(static_cast<int>(ida.intervals.size())).add("grid start");
                    } else {
                        ill = !well_conditioned(first.lower_check.confirmation);
                        c.ill += ill;
                        if (!ill) {
                            pt.add(first.lower.collapse).add(first.lower.safe).add("-").add("-").add("-").add("-");
                        } else {
                            gap = grid_gap(ida);
                            pt.add("-").add("-").add(first.lower.collapse).add(first.lower.safe);
                            pt.add(gap.safe).add(gap.collapse);
                        }
                        pt.add("-").add(static_cast<int>(ida.intervals.size()));
                        pt.add(studies::confirmation_name(first.lower_check.confirmation));
                        if (!first.lower_check.detail.empty())
                            pt.note("detail " + imps[i].name + " " + recs[r].file + " alpha " + label(ida.alpha) +
                                        " p " + label(ida.p),
                                    first.lower_check.detail);
                    }
                }
                for (int k = 0; k < studies::kHalfPeriods; ++k) {
                    const double to = recs[r].to[k];
                    const int nominal = verdict(ida.point, ill, gap, q2_n6(ida.p * to));
                    const int corners = verdict(ida.point, ill, gap, studies::eq27_of_block(ida.alpha, ida.p, o.model, to).q);
                    c.nominal[k] += nominal == 1;
                    c.undecided[k] += nominal == -1;
                    if (nominal == 1) c.rec_nominal[k].insert(r);
                    c.corners[k] += corners == 1;
                    c.undecided_corners[k] += corners == -1;
                    if (corners == 1) c.rec_corners[k].insert(r);
                }
            }

    std::vector<std::string> ecols = kImperfectionColumns;
    for (const char* c : {"k", "cases", "censored", "ill_conditioned", "non_conservative", "undecided", "share",
                          "records_with_any", "non_conservative_corners", "undecided_corners", "share_corners",
                          "records_with_any_corners", "records"})
        ecols.push_back(c);
    harness::Table et(ecols);
    et.note("scene", "imperfection: eq. 27's share of non-conservative cases per to_k with imperfect blocks, beside "
                     "the perfect block's");
    et.note("model", "eq. 27 (case 2 repeated to 6 pulses, collapse at the onset of the 7th) against each record's "
                     "first collapse q (imperfection_points.csv)");
    et.note("solver", "counts of imperfection_points.csv's cases; eq. 27 by the closed form q2_n6 and, toward each "
                      "corner, by qfactor::imperfect_collapse");
    et.note("inputs", inputs + "; to_k: the records' half-periods (records::half_periods, as table2)");
    et.note("columns",
            "a case (record, block) is non-conservative for k when its first collapse q is below eq. 27's q "
            "(studies::non_conservative; a censored case never is), the fragility scene's rule: non_conservative with "
            "eq. 27 as the paper states it, q2_n6(p to_k) with the perfect block's p; non_conservative_corners with "
            "eq. 27 toward each corner of the imperfect block, min over sigma of q2_n6(p_sigma to_k) alpha_sigma / "
            "alpha; undecided*: cases whose first collapse is ill-conditioned (the probe flips its bracket: "
            "rounding places it within its grid gap, q_gap_safe..q_gap_collapse) and whose gap holds eq. 27's q, "
            "counted neither way; share* = non_conservative* / cases; records_with_any*: records non-conservative "
            "on at least one block, of records; ill_conditioned: the cases with an ill-conditioned first collapse");
    for (std::size_t i = 0; i < imps.size(); ++i)
        for (int k = 0; k < studies::kHalfPeriods; ++k) {
            const Count& c = counts[i];
            et.row();
            add_imperfection_cells(et, imps[i]);
            et.add(k + 1).add(c.cases).add(c.censored).add(c.ill).add(c.nominal[k]).add(c.undecided[k]);
            et.add(static_cast<double>(c.nominal[k]) / c.cases).add(static_cast<int>(c.rec_nominal[k].size()));
            et.add(c.corners[k]).add(c.undecided_corners[k]).add(static_cast<double>(c.corners[k]) / c.cases);
            et.add(static_cast<int>(c.rec_corners[k].size())).add(static_cast<int>(nr));
        }
    ctx.write(pt, "imperfection_points.csv");
    ctx.write(et, "imperfection_eq27.csv");
}

}  // namespace rocking::scenes::imperfection_scene
