#include "studies/assessment.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>

#include "qfactor/closed_forms.hpp"
#include "pulse/pulse_train.hpp"
#include "qfactor/superposition.hpp"
#include "records/collapse.hpp"
#include "studies/eq27_of_block.hpp"

namespace rocking::studies {

std::string AssessOptions::describe() const {
    IdaOptions ida;
    ida.model = model;
    char range[300];
    std::snprintf(range, sizeof range, "q in [1, %g] (or to twice the record's q, at most 1e4)%s", q_max,
                  model.imperfection.any() ? "; from the block's lowest corner's uplift, min alpha_sigma/alpha, where below 1"
                                           : "");
    char p_range[200];
    std::snprintf(p_range, sizeof p_range, "p in [%g, %g] rad/s (or wider, to hold the block's p%s)", p_min, p_max,
                  model.imperfection.fc > 0 ? "; from above the blocks that crush under their own weight" : "");
    char w[40];
    std::snprintf(w, sizeof w, "%g", width);
    return ida.describe_model() + "; the scale factors from the IDA over " + range +
           " and the nearest overturning blocks from the spectrum over " + p_range +
           ", both by the refine search at w = " + w + " (islands narrower than w may be missed)";
}

std::string AssessOptions::describe_check() const {
    return model.imperfection.any()
               ? "eq. 27 toward each corner: the record's q below min over sigma of q2_n6(p_sigma to_5) alpha_sigma/alpha"
               : "eq. 27: the record's q below q2_n6(p to_5)";
}

double AssessOptions::ida_q_max(double q_record) const { return std::min(1e4, std::max(q_max, 2 * q_record)); }

SpectrumOptions AssessOptions::spectrum_options(double block_p, double alpha) const {
    SpectrumOptions sp;
    sp.model = model;
    // A block outside [0.3, 30] rad/s (H above 160 m or below 2 cm at small
    // alpha) read the range's end as its nearest change of outcome.
    sp.p_min = std::max({0.01, std::min(p_min, block_p / 1.5), dynamics::lowest_standing_p(alpha, model.imperfection)});
    sp.p_max = std::min(1000.0, std::max(p_max, block_p * 1.5));
    sp.method = SpectrumOptions::Method::refine;
    sp.width = width;
    return sp;
}

Refusal refusal_of(const dynamics::SampledInput& input, const records::PeakMotion& m, const BlockShape& block) {
    char text[200];
    if (!(block.p * m.to5 >= kSmallestX)) {
        std::snprintf(text, sizeof text, "the block's p (%.3g rad/s) times the record's to_5 (%.3g s) is below 1e-150, "
                      "where eq. 27 overflows", block.p, m.to5);
        return {Refusal::Blame::block, text};
    }
    // A PGA near the largest double over a tiny alpha printed "q_record": inf.
    if (!std::isfinite(m.pga / (block.alpha * dynamics::kGravity))) {
        std::snprintf(text, sizeof text, "the record's q = PGA/(alpha g) overflows a double at alpha = %.6g "
                      "(PGA = %.4g m/s^2)", block.alpha, m.pga);
        return {Refusal::Blame::record, text};
    }
    if (!(input.peak() > 0)) return {Refusal::Blame::record, "the record never moves (PGA 0)"};
    return {};
}

namespace {

RecordAssessment assess_record(const dynamics::SampledInput& input, const records::PeakMotion& m,
                               const BlockShape& block, const AssessOptions& o) {
    RecordAssessment a;
    a.motion = m;
    const Refusal refused = refusal_of(input, m, block);
    if (refused.blame != Refusal::Blame::none) throw std::invalid_argument(refused.why);
    a.x = block.p * m.to5;
    const Eq27OfBlock q27 = eq27_of_block(block.alpha, block.p, o.model, m.to5);
    a.q_eq27 = q27.q;
    a.q_eq27_as_printed = q27.q_as_printed;
    a.eq27_side = q27.side;
    const Excursion& e = q27.excursion;
    a.eq27_passes_alpha = e.onset && e.passes_alpha();
    a.eq27_strikes = !e.stays_positive();
    a.q_record = m.pga / (block.alpha * dynamics::kGravity);
    a.ratio = a.q_record / a.q_eq27;
    a.margin = 1 - a.ratio;
    a.passes = a.q_record < a.q_eq27;

    const dynamics::SimulationResult run = records::simulate_block(input, block.alpha, block.p, o.model);
    a.peak_theta_over_alpha = run.max_abs_theta_input / block.alpha;
    a.overturns = records::run_collapses(run, o.model.criterion, block.alpha, block.p, o.model);
    a.fell_during_input = run.overturned_during_input;

    IdaOptions ida;
    ida.model = o.model;
    // The scale factors of interest lie about 1: the search reaches twice the
    // record's own q where that is above q_max (a block far weaker than the record).
    ida.q_max = o.ida_q_max(a.q_record);
    ida.method = IdaOptions::Method::refine;
    ida.width = o.width;
    a.ida = incremental_dynamic_analysis(input, block.alpha, block.p, ida);
    a.scale_first_overturning = a.ida.first_overturning.q / a.q_record;
    a.scale_first_robust = a.ida.first_robust_collapse.q / a.q_record;
    for (const IdaInterval& in : a.ida.intervals) {
        if (a.ida.first_overturning.collapsed && in.from == a.ida.first_overturning.q)
            a.first_overturning_to = in.to, a.first_overturning_open = !in.has_upper;
        if (a.ida.first_robust_collapse.collapsed && in.from == a.ida.first_robust_collapse.q)
            a.first_robust_to = in.to, a.first_robust_open = !in.has_upper;
    }

    const SpectrumOptions sp = o.spectrum_options(block.p, block.alpha);
    a.spectrum = rocking_spectrum(input, block.alpha, sp);
    a.mark = mark_block(input, a.spectrum, block, sp);
    return a;
}

}  // namespace

Assessment assess_block(const std::vector<const dynamics::SampledInput*>& inputs,
                        const std::vector<records::PeakMotion>& motions, const BlockShape& block, const AssessOptions& o) {
    if (inputs.size() != motions.size() || inputs.empty())
        throw std::invalid_argument("assess_block: one peak motion per input, at least one input");
    Assessment out;
    out.block = block;
    for (std::size_t k = 0; k < inputs.size(); ++k) out.records.push_back(assess_record(*inputs[k], motions[k], block, o));
    if (inputs.size() < 2) {
        out.no_fit = "one record: no fragility";
        return out;
    }
    std::vector<IdaPoint> points;
    for (const RecordAssessment& r : out.records) points.push_back(r.ida.first_overturning);
    out.no_fit = why_no_maximum(points);
    if (!out.no_fit.empty()) return out;
    out.fit = fit_lognormal(points);
    out.fitted = true;
    for (RecordAssessment& r : out.records) {
        r.has_probability = true;
        r.probability = overturning_probability(out.fit, r.q_record);
    }
    return out;
}

}  // namespace rocking::studies
