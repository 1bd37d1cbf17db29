// Eq. 27's non-conservative share per to_k with friction (issue 41, item 4):
// the fragility scene's 64 cases (the shared records on its four blocks),
// each record's first collapse q under five models: the ideal one (Table 1's:
// linearised eq. 3, Housner's restitution, the exact solver), the rocking-only
// full one (the sliding engine at mu = 1e6, its bracket checked by the full
// model's dopri5), and the block on friction mu = 0.8, 0.6, 0.4.  The first
// collapse is the IDA's grid method's (studies/ida.hpp): the same 100 + 99
// log-spaced q from 1 to 20, the first that overturns, its bracket bisected
// to 1e-6, so the ideal column is the fragility scene's first collapse; the
// scan stops there (eq. 27's verdict needs no more of the set).
//
// A friction run that never slipped is the same run at any larger mu (the
// stuck corner's |f| <= mu n, the rest threshold and a stuck impact's
// |p_t| <= mu p_n hold a fortiori): the models run in increasing mu, and an
// outcome a smaller mu decided that way is taken, not run again; every 8th such
// taking is run anyway and must give the same bits (sliding_eq27_points.csv).
#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <map>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include "batch/pool.hpp"
#include "fragility_scene.hpp"
#include "harness/table.hpp"
#include "qfactor/closed_forms.hpp"
#include "records/collapse.hpp"
#include "records/measures.hpp"
#include "records/record.hpp"
#include "records_analysis.hpp"
#include "sliding_scene.hpp"
#include "studies/eq27_at_scale.hpp"
#include "studies/intervals.hpp"

namespace rocking::scenes::sliding_scene {

namespace {

using fragility_scene::kBlocks;

const std::array<const char*, 2> kFiles = {"sliding_eq27_points.csv", "sliding_eq27.csv"};
// The friction models in increasing mu (the order the identity rule needs),
// the last the control: the rocking-only full model.
constexpr std::array<double, 4> kByMu = {0.4, 0.6, 0.8, kControlMu};
constexpr int kModels = 5;  // ideal, then kByMu's in the table's order below
const std::array<std::string, kModels> kModelNames = {"ideal", "full", "0.8", "0.6", "0.4"};
constexpr int kCheckEvery = 8;

struct FirstCollapse {
    bool collapsed = false, outside = false;
    double q_collapse = 0, q_safe = 0;  // q_safe 0: collapse at the grid's start
    long runs = 0, taken = 0, checked = 0, check_failed = 0;
    std::string check = "-";  // the bracket seen by a second run: yes/no
};

struct Case {
    std::size_t record = 0, block = 0;
    std::array<FirstCollapse, kModels> first;  // in kModelNames's order
};

struct Outcome {
    bool overturned = false, slid = false, outside = false;
    double peak = 0, theta_tfin = 0;
};

const std::vector<studies::GridPoint>& q_grid() {
    static const std::vector<studies::GridPoint> g = studies::log_grid(1.0, 20.0, 100, true, {});
    return g;
}

// The first collapse of one model on the grid and its bisection (the IDA's,
// studies::bisect_boundary), `at` giving the outcome at q; a run outside the model stops it.
FirstCollapse first_collapse(const std::function<Outcome(double)>& at) {
    FirstCollapse f;
    const auto& g = q_grid();
    bool out = false;
    const auto collapses = [&](double q) {
        const Outcome o = at(q);
        out = out || o.outside;
        return o.overturned;
    };
    for (std::size_t k = 0; k < g.size(); ++k) {
        if (!collapses(g[k].x)) {
            if (out) break;
            continue;
        }
        f.collapsed = true;
        if (k == 0) {
            f.q_collapse = g[0].x;
            break;
        }
        long runs = 0;
        const studies::Bracket b = studies::bisect_boundary(collapses, g[k - 1].x, false, g[k].x, 1e-6, runs);
        f.q_collapse = b.collapse, f.q_safe = b.safe;
        break;
    }
    if (out) f.collapsed = false, f.outside = true;
    return f;
}

Outcome outcome_of(const Run& r) { return {r.overturned, r.slid, r.outside, r.peak, r.theta_tfin}; }

void run_case(Case& c, const dynamics::SampledInput& record) {
    const double alpha = kBlocks[c.block].alpha, p = kBlocks[c.block].p;
    auto scaled = [&](double q) { return record.scaled_by(q * alpha / record.peak(), record.describe()); };
    // The ideal model: Table 1's search options.
    const records::CollapseOptions ideal = table1_search();
    c.first[0] = first_collapse([&](double q) {
        Outcome o;
        o.overturned = records::collapses_at(scaled(q), alpha, p, ideal);
        return o;
    });
    std::array<std::map<double, Outcome>, kByMu.size()> memo;
    for (std::size_t m = 0; m < kByMu.size(); ++m) {
        FirstCollapse& f = c.first[kByMu[m] == kControlMu ? 1 : 4 - m];
        long runs = 0, taken = 0, checked = 0, failed = 0;
        f = first_collapse([&](double q) {
            const auto run = [&] {
                ++runs;
                return outcome_of(friction_run(scaled(q), alpha, p, kByMu[m], kRtol));
            };
            for (std::size_t j = 0; j < m; ++j) {
                const auto it = memo[j].find(q);
                if (it == memo[j].end() || it->second.overturned || it->second.slid || it->second.outside) continue;
                if (++taken % kCheckEvery == 0) {
                    const Outcome o = run();
                    ++checked;
                    failed += o.overturned || o.slid || o.outside || o.peak != it->second.peak ||
                              o.theta_tfin != it->second.theta_tfin;
                }
                return memo[m][q] = it->second;
            }
            return memo[m][q] = run();
        });
        f.runs = runs, f.taken = taken, f.checked = checked, f.check_failed = failed;
    }
    // The brackets seen again: the full one by the rocking-only full model
    // (dopri5 at 1e-11), each friction one by the engine 100 times tighter.
    for (int k = 1; k < kModels; ++k) {
        FirstCollapse& f = c.first[k];
        if (!f.collapsed || f.q_safe <= 0) continue;
        const double mu = k == 1 ? kControlMu : std::stod(kModelNames[k]);
        const auto over = [&](double q) {
            return k == 1 ? rocking_run(scaled(q), alpha, p, kRtolTight).overturned
                          : friction_run(scaled(q), alpha, p, mu, kRtolTight).overturned;
        };
        f.check = over(f.q_collapse) && !over(f.q_safe) ? "yes" : "no";
    }
}

const char* kModelNote =
    "ideal: linearised eq. 3, Housner's restitution, the exact solver (the record kernel), as the fragility scene; "
    "full: the rocking-only full model, run as the sliding engine at mu = 1e6 (docs/sliding.md; it reproduces "
    "eq. 1 with Housner's restitution, sliding_control.csv), rtol = atol = 1e-9 alpha; 0.8, 0.6, 0.4: the block on "
    "Coulomb friction mu, the same engine and tolerance; overturning at any time (free rocking included)";
const char* kSolverNote =
    "each model's first collapse as the IDA's grid method finds it: 100 q log-spaced from 1 to 20 and 99 offset by "
    "half a step (studies::log_grid), the first that overturns, its bracket bisected to 1e-6 relative "
    "(studies::bisect_boundary); the scan stops there or at a run outside the model; a friction outcome at q taken from a "
    "smaller mu's run that never slipped (the same run), every 8th such run again and compared bit for bit";

}  // namespace

void write_eq27(SceneContext& ctx) {
    const std::optional<SceneRecords> loaded = scene_records(ctx, {kFiles.begin(), kFiles.end()});
    if (!loaded) return;
    const auto& inputs = loaded->inputs;
    const auto& labels = loaded->labels;
    const auto& recs = loaded->read;
    std::vector<std::array<double, 11>> to(recs.size());
    batch::run_ordered<std::array<double, 11>>(
        recs.size(), batch::PoolOptions{batch::default_threads()},
        [&](std::size_t i) { return records::half_periods(recs[i]).to; },
        [&](std::size_t i, std::array<double, 11>& v) { to[i] = v; });
    std::vector<Case> cases;
    for (std::size_t b = 0; b < kBlocks.size(); ++b)
        for (std::size_t r = 0; r < recs.size(); ++r) cases.push_back(Case{r, b, {}});
    batch::run_ordered<Case>(
        cases.size(), batch::PoolOptions{batch::default_threads()},
        [&](std::size_t i) {
            Case c = cases[i];
            try {
                run_case(c, *inputs[c.record]);
            } catch (const std::exception& e) {
                throw std::runtime_error("sliding eq. 27: " + labels[c.record] + ": " + e.what());
            }
            return c;
        },
        [&](std::size_t i, Case& c) { cases[i] = std::move(c); });

    const std::string inputs_text =
        "every record of the records folder (../shared/records or $ROCKING_RECORDS: esm/ and peer/, as table1), in g "
        "with g = 9.81 m/s^2, scaled to q = PGA/(alpha g); " + fragility_scene::blocks_text() +
        " (the fragility scene's); to_k: the records' half-periods (records::half_periods, as table2)";
    harness::Table pt({"record", "alpha", "p", "model", "outcome", "q_collapse", "q_safe", "check", "runs", "taken",
                       "identity_checked", "identity_failed"});
    pt.note("scene", "sliding: each record's first collapse q on each block, per model");
    pt.note("model", kModelNote);
    pt.note("solver", kSolverNote);
    pt.note("inputs", inputs_text);
    pt.note("columns",
            "outcome: collapsed, censored (none up to q = 20) or outside (a friction run outside the model, free "
            "flight or the Painleve case, before the first collapse); q_collapse / q_safe: the first collapse's bracket ('-' for "
            "q_safe at the grid's start); check: both ends run again, full by the rocking-only full model (Odeint "
            "dopri5 at rtol = atol = 1e-11 alpha), mu by the sliding engine at 1e-11: yes when they see the same "
            "bracket; runs: simulations of this model; taken: outcomes taken from a smaller mu's run that never "
            "slipped; identity_*: of those, run again (every 8th) and differing in any bit");
    std::array<std::array<int, 11>, kModels> non{};
    std::array<std::array<int, 11>, kModels> more{}, fewer{};
    std::array<std::array<std::vector<bool>, 11>, kModels> any_record;
    for (auto& m : any_record)
        for (auto& k : m) k.assign(recs.size(), false);
    std::array<int, kModels> outside{};
    for (const Case& c : cases) {
        const studies::BlockShape& b = kBlocks[c.block];
        std::array<std::array<bool, 11>, kModels> nc{};
        for (int m = 0; m < kModels; ++m) {
            const FirstCollapse& f = c.first[m];
            pt.row().add(labels[c.record]).add(fragility_scene::label(b.alpha)).add(fragility_scene::label(b.p));
            pt.add(kModelNames[m]).add(f.outside ? "outside" : f.collapsed ? "collapsed" : "censored");
            if (f.collapsed) pt.add(f.q_collapse);
            else pt.add("-");
            if (f.collapsed && f.q_safe > 0) pt.add(f.q_safe);
            else pt.add("-");
            pt.add(f.check).add(static_cast<int>(f.runs)).add(static_cast<int>(f.taken));
            pt.add(static_cast<int>(f.checked)).add(static_cast<int>(f.check_failed));
            outside[m] += f.outside;
            for (int k = 0; k < 11; ++k) {
                nc[m][k] = studies::non_conservative({f.q_collapse, f.collapsed}, q2_n6(b.p * to[c.record][k]));
                non[m][k] += nc[m][k];
                if (nc[m][k]) any_record[m][k][c.record] = true;
            }
        }
        for (int m = 0; m < kModels; ++m)
            for (int k = 0; k < 11; ++k) {
                more[m][k] += nc[m][k] && !nc[1][k];
                fewer[m][k] += !nc[m][k] && nc[1][k];
            }
    }
    harness::Table et({"k", "model", "non_conservative", "cases", "share", "more_than_full", "fewer_than_full",
                       "records_with_any", "records", "outside"});
    et.note("scene", "sliding: eq. 27's share of non-conservative cases per to_k, per model");
    et.note("model", std::string("eq. 27 (q2_n6 at x = p to_k) against each record's first collapse q "
                                 "(sliding_eq27_points.csv) under each model: ") + kModelNote);
    et.note("solver", kSolverNote);
    et.note("inputs", inputs_text);
    et.note("columns",
            "a case (record, block) is non-conservative for k when its first collapse q < eq. 27's q; a censored "
            "case never is, nor one outside the model (outside: such cases, counted in cases); "
            "more_than_full / fewer_than_full: cases non-conservative under this model and not under full, and the "
            "reverse; records_with_any: records non-conservative on at least one block");
    for (int k = 0; k < 11; ++k)
        for (int m = 0; m < kModels; ++m) {
            const int n = static_cast<int>(cases.size());
            et.row().add(k + 1).add(kModelNames[m]).add(non[m][k]).add(n).add(static_cast<double>(non[m][k]) / n);
            et.add(more[m][k]).add(fewer[m][k]);
            et.add(static_cast<int>(std::count(any_record[m][k].begin(), any_record[m][k].end(), true)));
            et.add(static_cast<int>(recs.size())).add(outside[m]);
        }
    ctx.write(pt, "sliding_eq27_points.csv");
    ctx.write(et, "sliding_eq27.csv");
}

}  // namespace rocking::scenes::sliding_scene
