// rocking_q.eq27: `rocking eq27 --json` from Python (src/studies/
// eq27_at_scale.hpp), the same fields; with method='refine' the shares under
// each capacity (issue 39), as --method refine gives them.  Runs without the
// GIL, on `jobs` threads of the batch engine; the result does not depend on them.
#include <array>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "dynamics/imperfect_block.hpp"
#include "common.hpp"
#include "fragility_fits.hpp"
#include "json/eq27_json.hpp"
#include "studies/distinct_inputs.hpp"
#include "studies/eq27_at_scale.hpp"
#include "studies/search_alpha.hpp"
#include "study_arguments.hpp"

namespace rocking::python {

namespace {

using studies::Eq27Study;
using studies::kEq27NoBootstrap;
using studies::kEq27Verdict;
using studies::kEq27WilsonNote;

py::array_t<int> counts(const std::array<int, studies::kHalfPeriods>& c) {
    py::array_t<int> a(studies::kHalfPeriods);
    for (int k = 0; k < studies::kHalfPeriods; ++k) a.mutable_at(k) = c[k];
    return a;
}

// What the module holds of a study beside the document's (json::add_eq27_study),
// into the converted study: the intervals and counts as NumPy arrays, paths as
// os.fsdecode gives them, and after the map each case's capacity q (or q_max,
// censored), record-major, for a plot of one's own.
void add_study_members(py::dict out, const Eq27Study& s, const std::vector<RecordPtr>& recs) {
    const bool boot = s.bootstrap.resamples > 0;
    py::list shares = out["shares"];
    for (int k = 0; k < studies::kHalfPeriods; ++k) {
        const studies::Eq27Share& sh = s.shares[k];
        py::dict d = shares[k];
        if (boot) d["bootstrap"] = range_array(sh.bootstrap);
        d["wilson"] = to_array({sh.wilson.lo, sh.wilson.hi});
    }
    std::vector<std::array<int, studies::kHalfPeriods>> by_record(s.records, std::array<int, studies::kHalfPeriods>{});
    for (const studies::Eq27Case& c : s.cases)
        for (int k = 0; k < studies::kHalfPeriods; ++k) by_record[c.record][k] += c.non_conservative[k];
    py::list records_out = out["by_record"];
    for (std::size_t r = 0; r < by_record.size(); ++r) {
        py::dict d = records_out[r];
        d["file"] = file_of(*recs[r]);
        d["non_conservative"] = counts(by_record[r]);
    }
    py::list map = out["map"];
    for (std::size_t c = 0; c < s.map.size(); ++c) {
        py::dict cell = map[c];
        cell["non_conservative"] = counts(s.map[c].non_conservative);
    }
    const std::size_t n = s.cases.size();
    py::array_t<double> q(n);
    py::array_t<bool> collapsed(n);
    for (std::size_t k = 0; k < n; ++k) q.mutable_at(k) = s.cases[k].point.q, collapsed.mutable_at(k) = s.cases[k].point.collapsed;
    py::dict cases = result();
    cases["q"] = q;
    cases["collapsed"] = collapsed;
    out["case_points"] = cases;
}

py::dict eq27(const py::object& records_given, const py::object& alpha, const std::optional<Real>& p_min_given,
              const std::optional<Real>& p_max_given, const Whole& p_points_given, const Real& q_max_given,
              const std::optional<Whole>& bootstrap, const std::optional<Whole>& seed, const std::optional<Whole>& jobs,
              const Text& method_given, const std::optional<Real>& width_given,
              const std::optional<Real>& robust_width_given, const py::object& restitution, const py::object& friction, const py::object& imperfection,
              const py::kwargs& extra) {
    no_other_keywords(extra, "eq27", "eq27");
    const std::optional<double> p_min = number(p_min_given, "p_min"), p_max = number(p_max_given, "p_max");
    const long long p_points_long = whole(p_points_given, "p_points");
    const double q_max = number(q_max_given, "q_max");
    studies::Eq27Options o;
    if (!alpha.is_none()) o.grid.alphas = values_in(alpha, "alpha", 0, studies::kSearchAlphaMax, studies::kSearchAlphaRange, 50);
    auto bounded = [](double v, const std::string& what, double lo, double hi, const std::string& range) {
        if (!(v > lo && v <= hi)) refuse(what + ": must be in " + range + " (got " + g7(v) + ")");
        return v;
    };
    // As rocking eq27's --p-min, --p-max: the grid's defaults when not given, and one
    // p_points is p_min alone unless p_max is given too (then it must be p_min).
    if (p_min) o.grid.p_min = bounded(*p_min, "p_min", 0.01, 1000, "(0.01, 1000] rad/s");
    if (p_max) o.grid.p_max = bounded(*p_max, "p_max", 0.01, 1000, "(0.01, 1000] rad/s");
    if (p_points_long < 1 || p_points_long > 1000) refuse("p_points: must be between 1 and 1000");
    o.grid.p_points = static_cast<int>(p_points_long);
    if (o.grid.p_points == 1 && p_min && !p_max) o.grid.p_max = o.grid.p_min;
    o.grid.check();  // a repeated alpha or p, one p with a range: ValueError in the keywords' names
    o.ida.q_max = bounded(q_max, "q_max", o.ida.q_min, 1e4, "(1, 10000]");
    restitution_into(restitution, o.ida.model);
    friction_into(friction, restitution, o.ida.model);
    imperfection_into(imperfection, o.ida.model);
    // As rocking eq27: with fc the tallest blocks crush, and without p_min the grid starts where they stand.
    if (!p_min) {
        o.grid.p_min = std::fmax(o.grid.p_min, dynamics::lowest_standing_p(o.grid.alphas, o.ida.model.imperfection));
        if (!(o.grid.p_max > o.grid.p_min))
            refuse("imperfection fc: the blocks of these alphas stand only above p = " + g7(o.grid.p_min) +
                   " rad/s, at or above p_max (" + g7(o.grid.p_max) + " rad/s)");
    }
    method_argument(method_given, width_given, robust_width_given, o.ida);
    const bool refine = o.ida.method == studies::IdaOptions::Method::refine;
    o.bootstrap.resamples = bootstrap_argument(bootstrap, seed, o.bootstrap.seed);
    if (o.bootstrap.resamples != 0 && (o.bootstrap.resamples < 2 || o.bootstrap.resamples > 100000))
        refuse("bootstrap: must be 0 or between 2 and 100000");
    o.threads = jobs_argument(jobs);
    const std::vector<RecordPtr> recs = record_list(records_given, "records");
    if (recs.size() > 1000) refuse("records: at most 1000");
    std::vector<std::unique_ptr<dynamics::SampledInput>> inputs;
    std::vector<studies::Eq27Record> rows;
    studies::Eq27ByCapacity by;
    {
        py::gil_scoped_release unlocked;  // the half-periods' CWT too
        std::vector<std::string> labels;
        std::vector<const dynamics::SampledInput*> given;
        for (const RecordPtr& r : recs) {
            labels.push_back(label_of(*r));
            inputs.push_back(input_of(*r));
            refuse_unresolvable_run(o.grid.p_max, inputs.back()->t_end(), "p_max with record " + labels.back());
            const records::HalfPeriods h = checked_half_periods(*r);
            if (!(inputs.back()->peak() > 0)) throw std::runtime_error(labels.back() + ": the record never moves (PGA 0)");
            rows.push_back({inputs.back().get(), h.to});
            given.push_back(inputs.back().get());
        }
        studies::refuse_repeated_records(labels, given);  // as rocking eq27: its cases would count twice
        by = studies::eq27_at_scale_by_capacity(rows, o);
    }
    std::vector<std::string> labels;
    for (const RecordPtr& r : recs) labels.push_back(label_of(*r));
    // The by-record and map counts come back as NumPy arrays (add_study_members): not converted first.
    json::Json doc = json::eq27_document(labels, o, by);
    for (json::Json* study : {&doc, refine ? &doc["first_robust_collapse"] : nullptr}) {
        if (!study) continue;
        for (json::Json& row : (*study)["by_record"]) row["non_conservative"] = nullptr;
        for (json::Json& cell : (*study)["map"]) cell["non_conservative"] = nullptr;
    }
    py::dict out = to_python(doc);
    py::list files = out["files"];
    for (std::size_t k = 0; k < recs.size(); ++k) files[k] = file_of(*recs[k]);  // paths as os.fsdecode gives them
    add_study_members(out, by.first_overturning, recs);
    if (refine) {
        out = with_keys_before(out, {"case_points"}, "first_robust_collapse");  // each study's own, as before
        add_study_members(out["first_robust_collapse"], by.first_robust_collapse, recs);
    }
    return out;
}

}  // namespace

void init_eq27(py::module_& m) {
    using namespace py::literals;
    m.def("eq27", gsl_checked(&eq27), "records"_a, py::kw_only(), "alpha"_a = py::none(), "p_min"_a = py::none(),
          "p_max"_a = py::none(), "p_points"_a = 10, "q_max"_a = 20.0, "bootstrap"_a = py::none(), "seed"_a = py::none(),
          "jobs"_a = py::none(), "method"_a = "grid", "width"_a = py::none(), "robust_width"_a = py::none(),
          "restitution"_a = "housner", "friction"_a = py::none(), "imperfection"_a = py::none(),
          R"(`rocking eq27 --json`: each record's first collapse q on every block of the grid against eq. 27
at x = p to_k; per to_k the share of non-conservative cases with its Wilson and bootstrap
intervals, by record and the map over blocks.  p: p_points log-spaced from p_min (default 0.5, or where the blocks stand with imperfection fc) to
p_max (default 10); p_points=1 is p_min alone (p_max, if given, must equal it).  method='refine'
(width=w in ln q, default 1e-5; robust_width, default 5e-3), as --method refine: the shares,
by_record, map and case_points under the first overturning (capacity, capacity_note), and the
same under the first robust collapse in first_robust_collapse; both bootstraps draw the same
records.  An alpha or a record given twice is refused (its cases would count twice), as is a
p_max times a record's duration the solvers cannot follow.  Releases the GIL.)");
}

}  // namespace rocking::python
