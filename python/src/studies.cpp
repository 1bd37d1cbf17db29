// The studies over many runs (rocking spectrum, fragility; eq27 in eq27.cpp):
// src/studies.  Each runs without the GIL, on `jobs` threads of the batch
// engine; the results do not depend on them.
#include <algorithm>
#include <array>
#include <cmath>

#include "batch/pool.hpp"
#include "common.hpp"
#include "records/floor_motion.hpp"
#include "studies/spectrum_mark.hpp"
#include "studies/blocks_as_built.hpp"
#include "fragility_fits.hpp"
#include "study_arguments.hpp"
#include "dynamics/ground_input.hpp"
#include "dynamics/imperfect_block.hpp"
#include "jobs/spectrum_plan.hpp"
#include "json/fragility_json.hpp"
#include "json/spectrum_json.hpp"
#include "records/collapse.hpp"
#include "studies/distinct_inputs.hpp"
#include "studies/ida.hpp"
#include "studies/nrml.hpp"
#include "studies/spectrum.hpp"
#include "studies/search_alpha.hpp"

namespace rocking::python {

namespace {

using studies::BlockFragility;
using studies::Ida;

// ---- rocking spectrum ----

using Study = jobs::SpectrumStudy;

py::dict spectrum(py::handle record, const py::object& alpha, const std::optional<Real>& p_min, const Real& p_max, const Whole& points,
                  const std::optional<Whole>& jobs, const Text& method_given, const std::optional<Real>& width_given,
                  const std::optional<Real>& robust_width_given, const std::optional<Text>& mark_given,
                  const py::object& restitution, const py::object& friction, const py::object& imperfection,
                  const std::optional<Text>& floor, const py::kwargs& extra) {
    no_other_keywords(extra, "spectrum", "spectrum");
    // As rocking spectrum --mark: the marked blocks' alphas join alpha's.
    std::vector<double> alphas;
    if (!alpha.is_none()) {
        alphas = values_in(alpha, "alpha", 0, studies::kSearchAlphaMax, studies::kSearchAlphaRange, 20);
        studies::refuse_repeated_values("alpha", alphas);
    }
    std::vector<studies::BlockShape> marks;
    if (const std::optional<std::string> text_given = string_argument(mark_given, "mark")) {
        try {
            marks = studies::blocks_as_built(*text_given, "mark");
        } catch (const std::invalid_argument& e) {
            refuse(e.what());
        }
        for (const studies::BlockShape& b : marks)
            if (std::find(alphas.begin(), alphas.end(), b.alpha) == alphas.end()) alphas.push_back(b.alpha);
        if (alphas.size() > 20) refuse("alpha and mark: at most 20 alphas in all");
    }
    if (alphas.empty()) refuse("give alpha, or mark='BxH,...' for the alphas of the blocks marked");
    studies::SpectrumOptions o;
    if (p_min) o.p_min = *number(p_min, "p_min");
    o.p_max = number(p_max, "p_max");
    const long long points_given = whole(points, "points");
    if (points_given < 2 || points_given > 100000) refuse("points: must be between 2 and 100000");
    o.points = static_cast<int>(points_given);
    if (!(o.p_min >= 0.01 && o.p_min <= 1000)) refuse("p_min: must be in [0.01, 1000] rad/s");
    if (!(o.p_max >= 0.01 && o.p_max <= 1000)) refuse("p_max: must be in [0.01, 1000] rad/s");
    if (!(o.p_max > o.p_min)) refuse("p_max: must be above p_min (" + g7(o.p_min) + " rad/s)");
    const MethodChoice m = method_argument(method_given, width_given, robust_width_given, "p");
    if (m.refine) o.method = studies::SpectrumOptions::Method::refine;
    o.width = m.width;
    o.robust_width = m.robust_width;
    restitution_into(restitution, o.model);
    friction_into(friction, restitution, o.model);
    imperfection_into(imperfection, o.model);
    // As rocking spectrum: with fc the tallest blocks crush, and without p_min the range starts where they stand.
    if (!p_min) {
        o.p_min = std::fmax(o.p_min, dynamics::lowest_standing_p(alphas, o.model.imperfection));
        if (!(o.p_max > o.p_min))
            refuse("imperfection fc: the blocks of these alphas stand only above p = " + g7(o.p_min) +
                   " rad/s, at or above p_max (" + g7(o.p_max) + " rad/s)");
    }
    for (const studies::BlockShape& b : marks) {
        const std::string why = studies::why_not_markable(b, o);
        if (!why.empty()) refuse("mark " + b.built + ": " + why + " (p_min, p_max)");
    }
    const int threads = jobs_argument(jobs);
    const RecordPtr r = with_floor(record_argument(record, "record"), floor);
    std::vector<Study> found;
    std::vector<studies::SpectrumMark> marked;
    {
        py::gil_scoped_release unlocked;
        const auto input = input_of(*r);
        refuse_unresolvable_run(o.p_max, input->t_end(), "p_max with record " + label_of(*r));
        // As rocking spectrum: Table 1's bracket joins each alpha's grid.
        batch::run_ordered<Study>(
            alphas.size(), batch::PoolOptions{threads},
            [&](std::size_t k) { return jobs::spectrum_study(*input, alphas[k], o); },
            [&](std::size_t, Study& s) { found.push_back(std::move(s)); });
        for (const studies::BlockShape& b : marks)
            for (const Study& st : found)
                if (st.spectrum.alpha == b.alpha) marked.push_back(studies::mark_block(*input, st.spectrum, b, o));
    }
    json::Json doc = json::spectrum_document(label_of(*r), *r, o, found, marked);
    // The points go to Python as columns (below), not as the document's list of objects.
    for (json::Json& sp : doc["spectra"]) sp["points"] = nullptr;
    py::dict out = to_python(doc);
    out["file"] = file_of(*r);  // a path as os.fsdecode gives it
    // The module's own order: the refine method's members before rel_tol.
    if (m.refine) out = with_keys_before(out, {"method", "width", "robust_width", "refine_note"}, "rel_tol");
    py::list spectra = out["spectra"];
    for (std::size_t s = 0; s < found.size(); ++s) {
        const studies::Spectrum& sp = found[s].spectrum;
        py::dict d = spectra[s];
        if (sp.refined) d["unguaranteed_from"] = none_if_nan(sp.unguaranteed_from);  // None where --json has null
        // The grid as arrays, one per --json points' field (the plot's data).
        const std::size_t n = sp.points.size();
        py::array_t<double> p(n), max_theta(n), t_overturn(n);
        py::array_t<bool> final_rotation(n), peak_rotation(n), overturning(n);
        py::list kinds;
        for (std::size_t k = 0; k < n; ++k) {
            const studies::SpectrumPoint& pt = sp.points[k];
            p.mutable_at(k) = pt.p;
            max_theta.mutable_at(k) = pt.max_theta;
            t_overturn.mutable_at(k) = pt.t_overturn;
            final_rotation.mutable_at(k) = pt.final_rotation;
            peak_rotation.mutable_at(k) = pt.peak_rotation;
            overturning.mutable_at(k) = pt.overturning;
            kinds.append(studies::grid_kind_name(pt.grid));
        }
        py::dict pts = result();
        pts["p"] = p;
        pts["grid"] = kinds;
        pts["max_theta"] = max_theta;
        pts["final_rotation"] = final_rotation;
        pts["peak_rotation"] = peak_rotation;
        pts["overturning"] = overturning;
        pts["t_overturn"] = t_overturn;  // NaN where --json writes null
        d["points"] = pts;
    }
    return out;
}

// ---- rocking fragility ----

py::dict fragility(const py::object& records_given, const py::object& alpha, const py::object& p, const Real& q_max,
                   const Whole& points, const std::optional<Whole>& bootstrap, const std::optional<Whole>& seed,
                   const std::optional<Whole>& jobs, const Text& method_given, const std::optional<Real>& width_given,
                   const std::optional<Real>& robust_width_given, const std::optional<Text>& block_given,
                   const py::object& restitution, const py::object& friction, const py::object& imperfection, const Flag& nrml_given, const std::optional<Text>& floor,
                   const py::kwargs& extra) {
    no_other_keywords(extra, "fragility", "fragility");
    const bool nrml = flag(nrml_given, "nrml");
    // The blocks as rocking fragility's: --block BxH,... or every --alpha with every --p.
    std::vector<studies::BlockShape> built;
    if (const std::optional<std::string> text_given = string_argument(block_given, "block")) {
        if (!alpha.is_none() || !p.is_none()) refuse("block gives each block's alpha and p: give it without alpha and p");
        try {
            built = studies::blocks_as_built(*text_given, "block");
        } catch (const std::invalid_argument& e) {
            refuse(e.what());
        }
    } else if (alpha.is_none() || p.is_none()) {
        refuse("give alpha and p, or block='BxH,...'");
    }
    const std::vector<double> alphas =
        built.empty() ? values_in(alpha, "alpha", 0, studies::kSearchAlphaMax, studies::kSearchAlphaRange, 50) : std::vector<double>{};
    const std::vector<double> ps = built.empty() ? values_in(p, "p", 0.01, 1000, "(0.01, 1000) rad/s", 50) : std::vector<double>{};
    studies::refuse_repeated_values("alpha", alphas);
    studies::refuse_repeated_values("p", ps);
    studies::FragilityStudyOptions o;
    o.ida.q_max = number(q_max, "q_max");
    if (!(o.ida.q_max > o.ida.q_min && o.ida.q_max <= 1e4)) refuse("q_max: must be in (1, 10000]");
    const long long points_given = whole(points, "points");
    if (points_given < 2 || points_given > 10000) refuse("points: must be between 2 and 10000");
    o.ida.points = static_cast<int>(points_given);
    // As rocking fragility's --method, --width and --robust-width.
    method_argument(method_given, width_given, robust_width_given, o.ida);
    const bool refine = o.ida.method == studies::IdaOptions::Method::refine;
    o.resamples = bootstrap_argument(bootstrap, seed, o.seed);
    if (o.resamples < 0 || o.resamples > 100000) refuse("bootstrap: must be between 0 and 100000");
    o.threads = jobs_argument(jobs);
    std::vector<RecordPtr> recs = record_list(records_given, "records");
    if (recs.size() > 1000) refuse("records: at most 1000");
    for (RecordPtr& r : recs) r = with_floor(r, floor);
    if (floor) {
        if (nrml) refuse("nrml with floor: the fit is in the floor's PGA, which OpenQuake would read as the ground's");
        o.ida.input_note = records::describe_as_input(records::parse_floor_model(*string_argument(floor, "floor")));
    }
    std::vector<studies::BlockShape> blocks = built;
    for (double a : alphas)
        for (double v : ps) blocks.push_back({a, v, ""});
    restitution_into(restitution, o.ida.model);
    friction_into(friction, restitution, o.ida.model);
    imperfection_into(imperfection, o.ida.model);
    std::vector<BlockFragility> study;
    {
        py::gil_scoped_release unlocked;
        std::vector<std::unique_ptr<dynamics::SampledInput>> inputs;
        std::vector<std::string> labels;
        double p_max = 0;
        for (const studies::BlockShape& b : blocks) p_max = std::max(p_max, b.p);
        for (const RecordPtr& r : recs) {
            inputs.push_back(input_of(*r));
            labels.push_back(label_of(*r));
            if (!(inputs.back()->peak() > 0)) throw std::runtime_error(labels.back() + ": the record never moves (PGA 0)");
            refuse_unresolvable_run(p_max, inputs.back()->t_end(), "p with record " + labels.back());
        }
        std::vector<const dynamics::SampledInput*> given;
        std::vector<const dynamics::GroundInput*> views;
        for (const auto& in : inputs) given.push_back(in.get()), views.push_back(in.get());
        // As rocking fragility: a record given twice would count as two independent records in the fit.
        studies::refuse_repeated_records(labels, given);
        study = studies::fragility_study(views, blocks, o);
    }
    std::vector<std::string> labels;
    for (const RecordPtr& r : recs) labels.push_back(label_of(*r));
    json::Json doc = json::fragility_document(labels, o, study);
    // The empirical shares and the stripes go to Python as NumPy columns (below), not as lists of objects.
    for (json::Json& b : doc["blocks"]) {
        b["empirical"] = nullptr;
        if (b.contains("stripes")) b["stripes"] = nullptr;
    }
    py::dict out = to_python(doc);
    py::list blocks_out = out["blocks"];
    for (std::size_t i = 0; i < study.size(); ++i) {
        const BlockFragility& f = study[i];
        py::dict b = blocks_out[i];
        py::list rows = b["records"];
        for (std::size_t k = 0; k < recs.size(); ++k) {
            py::dict d = rows[k];
            d["file"] = file_of(*recs[k]);  // a path as os.fsdecode gives it
            if (refine) d["unguaranteed_from"] = none_if_nan(f.idas[k].unguaranteed_from);  // None where --json has null
        }
        add_block_fit_members(b, f);
        std::vector<double> q, share;
        for (const studies::EmpiricalPoint& e : f.empirical) q.push_back(e.q), share.push_back(e.share);
        py::dict empirical = result();
        empirical["q"] = to_array(q);
        empirical["share"] = to_array(share);
        b["empirical"] = empirical;
    }
    if (nrml) {
        // rocking fragility --nrml's file, its blocks without a fit as --nrml's warnings.
        std::vector<std::string> names;
        for (const RecordPtr& r : recs) names.push_back(label_of(*r));
        const studies::NrmlModel model = studies::fragility_nrml(study, o, names);
        for (const std::string& why : model.unfitted)
            if (PyErr_WarnEx(PyExc_RuntimeWarning, ("fragility: nrml: " + why + "; the model has no function for it, "
                                                    "only a comment").c_str(), 1) != 0)
                throw py::error_already_set();
        out["nrml"] = model.xml;
    }
    return out;
}

}  // namespace

void init_studies(py::module_& m) {
    using namespace py::literals;
    m.def("spectrum", gsl_checked(&spectrum), "record"_a, py::kw_only(), "alpha"_a = py::none(), "p_min"_a = py::none(), "p_max"_a = 30.0,
          "points"_a = 200, "jobs"_a = py::none(), "method"_a = "grid", "width"_a = py::none(),
          "robust_width"_a = py::none(), "mark"_a = py::none(), "restitution"_a = "housner", "friction"_a = py::none(), "imperfection"_a = py::none(), "floor"_a = py::none(),
          R"(`rocking spectrum --json`: for each alpha (a number or a list), the overturning intervals in p
(rad/s), each end bisected to 1e-6 and checked, beside Table 1's first collapse, and the grid: each
spectrum's points as arrays (p, grid, max_theta, final_rotation, peak_rotation, overturning,
t_overturn with NaN for null).  p_min: 0.3 by default, or where the blocks stand with imperfection
fc (the tallest crush).  jobs: threads (default: the cores this process may use).
method='refine' (width=w in ln p, default 1e-5; robust_width, default 5e-3) finds every island
wider than w and adds first_overturning (p, found, boundary), first_robust_collapse, bands (from,
to, share), samples, accepted, at_width, with_margins and unguaranteed_from, as --method refine
does.  mark='0.6x4,0.45x3' (thickness x height, m) reads those blocks against the spectra of their
alphas (added to alpha's), as --mark: marks (each block's run at its own p, the nearest
overturning p on either side and their heights).  An alpha given twice is refused.  Releases the GIL.)");
    m.def("fragility", gsl_checked(&fragility), "records"_a, py::kw_only(), "alpha"_a = py::none(), "p"_a = py::none(),
          "q_max"_a = 20.0, "points"_a = 100, "bootstrap"_a = py::none(), "seed"_a = py::none(), "jobs"_a = py::none(),
          "method"_a = "grid", "width"_a = py::none(), "robust_width"_a = py::none(), "block"_a = py::none(),
          "restitution"_a = "housner", "friction"_a = py::none(), "imperfection"_a = py::none(), "nrml"_a = false, "floor"_a = py::none(),
          R"(`rocking fragility --json`: for each block (every alpha with every p) and record, the IDA's
overturning intervals in q = PGA/(alpha g), the first collapse q or a censored point, the lognormal
fit with a bootstrap interval (bootstrap=K, seed=S) and the empirical curve (as arrays q, share).
method='refine' (width=w in ln q, default 1e-5; robust_width, default 5e-3) adds each record's
first_overturning (bracket, check), first_robust_collapse, bands (from, to, share), samples,
with_margins and unguaranteed_from, as --method refine does; the block's fit takes the first overturning,
and each block's fits (first_overturning, first_robust_collapse, stripes: fit and no_fit) and stripes
(arrays q, from, to, share) fit the capacity three ways.
Each record's sha256 sets the order the bootstraps draw the records in.  nrml=True adds "nrml",
the text `rocking fragility --nrml` writes: each block's fit as an OpenQuake NRML 0.5 continuous
fragility function (PGA in g), a RuntimeWarning for each block without a fit.
An alpha, a p or a record (by its step and samples) given twice is refused.  Releases the GIL.)");
}

}  // namespace rocking::python
