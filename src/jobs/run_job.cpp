#include "jobs/run_job.hpp"

#include <algorithm>
#include <cmath>
#include <memory>
#include <stdexcept>

#include "records/collapse.hpp"
#include "studies/ida.hpp"
#include "jobs/spectrum_plan.hpp"
#include "studies/spectrum.hpp"

namespace rocking::jobs {

namespace {

using dynamics::SampledInput;

// The record as recorded, or scaled as rocking simulate --pga/--q scales it
// (the samples times PGA / peak: SampledInput::scaled_by is that, bit for bit).
std::shared_ptr<const SampledInput> input_of(const Job& job, RecordStore& records) {
    std::shared_ptr<const SampledInput> record = records.get(job.record);
    if (job.scaling.by == Scaling::By::as_recorded) return record;
    if (!(record->peak() > 0)) throw std::runtime_error(job.record.cell + ": the record is zero throughout and cannot be scaled");
    const double pga = job.scaling.by == Scaling::By::q ? job.scaling.value * job.alpha : job.scaling.value;
    return std::make_shared<const SampledInput>(record->scaled_by(pga / record->peak(), record->describe()));
}

records::CollapseOptions search_model(const Job& job) {
    records::CollapseOptions o;
    o.equation = job.equation;
    o.solver = job.solver;
    o.housner_restitution = job.housner;
    o.restitution = job.restitution;
    o.criterion = job.criterion;
    o.friction = job.friction;
    o.imperfection = job.imperfection;
    if (job.friction > 0 && job.solver.rtol != dynamics::SolverOptions{}.rtol) o.sliding_rtol = job.solver.rtol;
    return o;
}

Figures simulate(const Job& job, const SampledInput& input) {
    // A friction row runs as the searches run it (records::simulate_block), in a rocking run's terms.
    const dynamics::SimulationResult r = [&] {
        if (job.friction > 0 || job.imperfection.any())
            return records::simulate_block(input, job.alpha, job.block->p, search_model(job));
        dynamics::Model model;
        model.equation = job.equation;
        model.block = *job.block;
        model.restitution = job.restitution_factor();
        dynamics::SimulationOptions options;
        options.solver = job.solver;
        return dynamics::simulate(model, input, options);
    }();
    Figures f;
    f.collapse = job.imperfection.any() ? records::run_collapses(r, job.criterion, job.alpha, job.block->p, search_model(job))
                                        : r.collapse(job.criterion, job.alpha);
    f.max_theta = r.max_abs_theta_input / job.alpha;
    if (!r.overturned_during_input) f.theta_tfin = r.theta_at_tfin / job.alpha;
    // As rocking simulate refuses them: a rotation beyond a double in units of alpha.
    if (!std::isfinite(*f.max_theta) || (f.theta_tfin && !std::isfinite(*f.theta_tfin)))
        throw std::runtime_error("the rotation in units of alpha overflows a double");
    if (!std::isnan(r.t_overturn)) f.t_overturn = r.t_overturn;
    f.impacts = r.impacts;
    return f;
}

Figures collapse(const Job& job, const SampledInput& input) {
    const records::CollapseResult c = records::smallest_collapse_p(input, job.alpha, search_model(job));
    Figures f;
    f.collapse = c.found;
    if (c.found) f.p_collapse = c.p;
    if (c.found && !c.below_range()) f.p_safe = c.p_safe;
    f.simulations = c.simulations;
    return f;
}

Figures ida(const Job& job, const SampledInput& input) {
    studies::IdaOptions o;
    o.model = search_model(job);
    o.q_max = job.q_max;
    o.points = job.points;
    if (job.refine) o.method = studies::IdaOptions::Method::refine;
    o.width = job.width;
    o.robust_width = job.robust_width;
    const studies::Ida r = studies::incremental_dynamic_analysis(input, job.alpha, job.block->p, o);
    Figures f;
    f.collapse = r.point.collapsed;
    if (r.point.collapsed) {
        f.q_collapse = r.point.q;
        if (r.intervals.front().has_lower) f.q_safe = r.intervals.front().lower.safe;
    }
    f.intervals = static_cast<long>(r.intervals.size());
    f.simulations = r.simulations;
    f.robust = r.first_robust_collapse.collapsed;
    if (r.first_robust_collapse.collapsed) f.q_robust = r.first_robust_collapse.q;
    f.bands = r.bands;
    return f;
}

Figures spectrum(const Job& job, const SampledInput& input) {
    studies::SpectrumOptions o;
    o.model = search_model(job);
    o.p_min = job.p_min;
    o.p_max = job.p_max;
    o.points = job.points;
    if (job.refine) o.method = studies::SpectrumOptions::Method::refine;
    o.width = job.width;
    o.robust_width = job.robust_width;
    // Table 1's bracket joins the grid, as in rocking spectrum (docs/spectrum.md);
    // the refine method takes no extra points.
    const studies::Spectrum s = spectrum_study(input, job.alpha, o).spectrum;
    Figures f;
    f.collapse = !s.intervals.empty();
    if (f.collapse) {
        f.p_collapse = s.intervals.front().from;
        if (s.intervals.front().has_lower) f.p_safe = s.intervals.front().lower.p_safe;
    }
    f.intervals = static_cast<long>(s.intervals.size());
    f.simulations = s.simulations;
    f.robust = s.first_robust_collapse.found;
    if (s.first_robust_collapse.found) f.p_robust = s.first_robust_collapse.p;
    f.bands = s.bands;
    return f;
}

// The highest p the job's runs reach: its block's, or the top of its
// searches (Table 1's to 30 rad/s, a spectrum's grid).
double highest_p(const Job& job) {
    const double table1 = records::CollapseOptions{}.p_max;
    switch (job.kind) {
        case Kind::simulate:
        case Kind::ida: return job.block->p;
        case Kind::collapse: return table1;
        case Kind::spectrum: return std::max(job.p_max, table1);
    }
    return table1;
}

// As the commands refuse --p 1e300 or --dt 1e300 (dynamics::unresolvable_run):
// the row refused by its columns, not the solver's "no progress" from deep
// inside the run.  Which is at fault: a p above the commands' 1000 rad/s (no
// block is physical beyond), a record longer than any p up to it could
// follow; one of the two, since p t is then within the limit.  A duration
// from the record's own step (a file's header) is named by the record.
void refuse_unresolvable(const Job& job, const SampledInput& input) {
    const double p = highest_p(job), duration = input.t_end();
    const std::string why = dynamics::unresolvable_run(p, duration);
    if (why.empty()) return;
    constexpr double kHighestPhysicalP = 1000;
    std::string columns;
    if (p > kHighestPhysicalP) columns = job.p_column.empty() ? "p" : job.p_column;
    if (duration * kHighestPhysicalP > dynamics::kLongestRunTimesP || columns.empty())
        columns += (columns.empty() ? "" : ", ") + (job.record.dt > 0 ? std::string("record_dt") : "record " + job.record.cell);
    throw std::invalid_argument(columns + ": " + why);
}

}  // namespace

Figures run_job(const Job& job, RecordStore& records) {
    const std::shared_ptr<const SampledInput> input = input_of(job, records);
    refuse_unresolvable(job, *input);
    switch (job.kind) {
        case Kind::simulate: return simulate(job, *input);
        case Kind::collapse: return collapse(job, *input);
        case Kind::ida: return ida(job, *input);
        case Kind::spectrum: return spectrum(job, *input);
    }
    throw std::logic_error("run_job: unknown kind");
}

}  // namespace rocking::jobs
