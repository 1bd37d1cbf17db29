// rocking assess: the engineer's check of a block against one record or
// several (issue 40): the paper's eq. 27 check with its ratio and margin,
// and what the model says of the same block (studies/assessment.hpp).
#include <cmath>
#include <cstdio>
#include <iostream>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include "cli/distinct_inputs.hpp"
#include "cli/geometry.hpp"
#include "cli/help.hpp"
#include "cli/imperfection.hpp"
#include "cli/json_text.hpp"
#include "cli/options.hpp"
#include "cli/plots.hpp"
#include "cli/set_words.hpp"
#include "json/assess_json.hpp"
#include "jobs/spectrum_plan.hpp"
#include "qfactor/superposition.hpp"
#include "studies/assessment.hpp"
#include "studies/scaled_response.hpp"
#include "studies/search_alpha.hpp"

namespace rocking::cli {

namespace {

// PGA, PGV and to_5 alone: the CWT and the Fourier peaks of the eleven half-periods
// took 1.1 s of a 30,001-sample record and assess reports none of them.
records::PeakMotion peak_motion_of(const records::Record& r, const std::string& path) {
    refuse_overflowing_velocity(r, path);
    try {
        return records::peak_motion(r.accel, r.dt);
    } catch (const std::invalid_argument& e) {
        throw std::runtime_error(path + ": " + e.what());
    }
}

// %f of a margin of -6.6e302 printed 300 digits into 40 characters.
std::string percent(double v) {
    char text[40];
    std::snprintf(text, sizeof text, std::fabs(100 * v) < 1e5 ? "%+.1f %%" : "%+.3g %%", 100 * v);
    return text;
}

// With the interval that starts there: a first overturning on an island
// 1e-6 wide in q, printed to four digits, did not overturn in simulate --q.
// The interval is the search's, to w: gaps narrower than w may lie inside.
std::string scale_text(const studies::IdaPoint& at, double scale, double q_record, double to, bool open, double w) {
    if (!at.collapsed)
        return "no scale up to " + four(at.q / q_record) + " times the record (q = " + four(at.q) + ", the search's end)";
    char text[300];
    if (open)
        std::snprintf(text, sizeof text, "%s times the record (q = %.10g; it overturns on to the search's end, q = %.6g, "
                      "gaps narrower than w = %g aside)", four(scale).c_str(), at.q, to, w);
    else
        std::snprintf(text, sizeof text, "%s times the record (q = %.10g; it overturns up to q = %.10g, %.2g in ln q, "
                      "gaps narrower than w = %g aside)", four(scale).c_str(), at.q, to, std::log(to / at.q), w);
    return text;
}

void print_text(const std::vector<std::string>& files, const std::vector<std::string>& names, const GivenBlock& given,
                const studies::Assessment& s, const studies::AssessOptions& o, const std::string& floor) {
    std::printf("assess: %s\n  model: %s\n", describe_block(given).c_str(), o.describe().c_str());
    if (!floor.empty()) std::printf("  input: %s\n", floor.c_str());
    // The answer over several records before each record's evidence.
    if (files.size() > 1) {
        if (s.fitted)
            std::printf("fragility over the %zu records (first overturnings, each record's IDA to q = max(20, twice "
                        "its own q)): lognormal median q = %s, beta = %s (from %zu records: fragility --bootstrap gives "
                        "its uncertainty)\n",
                        files.size(), four(s.fit.median).c_str(), four(s.fit.beta).c_str(), files.size());
        else
            std::printf("fragility over the %zu records: no fit (%s)\n", files.size(), s.no_fit.c_str());
    }
    for (std::size_t k = 0; k < files.size(); ++k) {
        const studies::RecordAssessment& r = s.records[k];
        std::printf("%s%s: eq. 27 check %s (the %s q is %s eq. 27's: ratio %s, margin %s)\n", files[k].c_str(),
                    floor.empty() ? "" : " at the floor", r.passes ? "PASSES" : "FAILS", floor.empty() ? "record's" : "floor's",
                    r.passes ? "below" : "at or above", four(r.ratio).c_str(), percent(r.margin).c_str());
        if (r.eq27_passes_alpha || r.eq27_strikes)
            std::printf("  warning: at x = %s eq. 27's own input (case 2, 6 pulses) %s before t_fin, so its closed form "
                        "does not hold there (rocking q --case 2 --pulses 6 --x %s says where)\n", four(r.x).c_str(),
                        r.eq27_passes_alpha ? "takes theta past alpha" : "brings the block down to the ground",
                        four(r.x).c_str());
        if (o.model.imperfection.any())
            std::printf("  eq. 27 on the imperfect block: toward each corner, q2_n6(p_sigma to_5) alpha_sigma/alpha, the "
                        "smaller (toward theta %s 0) = %s; as printed, at the nominal alpha and p, q2_n6(x) = %s\n",
                        r.eq27_side > 0 ? ">" : "<", four(r.q_eq27).c_str(), four(r.q_eq27_as_printed).c_str());
        std::printf("  input: %s\n", names[k].c_str());
        std::printf("  %s: PGA = %s g, to_5 = pi PGV/PGA = %s s; x = p to_5 = %s; q from eq. 27 = %s; the "
                    "input's q = PGA/(alpha g) = %s\n", floor.empty() ? "record" : "floor motion",
                    four(r.motion.pga / dynamics::kGravity).c_str(), four(r.motion.to5).c_str(), four(r.x).c_str(),
                    four(r.q_eq27).c_str(), four(r.q_record).c_str());
        if (r.fell_during_input)
            std::printf("  the model on this record: OVERTURNS (falls during the input)\n");
        else
            std::printf("  the model on this record: %s (peak |theta|/alpha during the input %s)\n",
                        r.overturns ? "OVERTURNS (in the free rocking after the input)" : "does not overturn",
                        four(r.peak_theta_over_alpha).c_str());
        std::printf("  the record scaled: the block first overturns at %s\n    and first robustly collapses at %s\n",
                    scale_text(r.ida.first_overturning, r.scale_first_overturning, r.q_record, r.first_overturning_to,
                               r.first_overturning_open, o.width).c_str(),
                    scale_text(r.ida.first_robust_collapse, r.scale_first_robust, r.q_record, r.first_robust_to,
                               r.first_robust_open, o.width).c_str());
        // Said where it bears on the numbers above: the record's own q or its first overturning beyond it.
        const double bound = r.ida.unguaranteed_from;
        if (std::isfinite(bound) && (r.q_record >= bound || r.ida.first_overturning.q >= bound))
            std::printf("  the scaled search finds every island wider than w only below q = %s ((pi/2 - alpha)/alpha: "
                        "above it a run can overturn with no flight's margin above 0), so above it islands may be "
                        "missed\n", four(r.ida.unguaranteed_from).c_str());
        std::printf("  blocks of this alpha:\n");
        for (const std::string& line : studies::describe_mark_lines(r.mark)) std::printf("    %s\n", line.c_str());
        if (r.has_probability)
            std::printf("  fragility over the %zu records: P(overturn) at this record's q = %s\n", files.size(),
                        four(r.probability).c_str());
    }
}

}  // namespace

int cmd_assess(int argc, char** argv) {
    int first = 0;
    const std::vector<std::string> files = file_arguments(argc, argv, first, usage_line("assess"));
    if (files.size() > 1000) throw UsageError("at most 1000 files");
    std::vector<std::string> allowed = {"--unit", "--dt", "--width", "--floor", "--restitution", "--friction", "--png"};
    allowed.insert(allowed.end(), imperfection_flags().begin(), imperfection_flags().end());
    allowed.insert(allowed.end(), geometry_flags().begin(), geometry_flags().end());
    const Args a = parse(argc, argv, first, allowed);
    const GivenBlock given = block_option(a);
    // The option that set the block's p, for the refusals of a p no search reads.
    const std::string size_flag = a.values.count("--height") ? "--height" : a.values.count("--half-height") ? "--half-height" : "--p";
    // The plot is the check on one record: its response scaled and its spectrum.
    if (a.values.count("--png") && files.size() != 1)
        throw UsageError("--png draws the check on one record: give one FILE (fragility --png draws several)");
    check_outputs(a, {"--png"}, files);
    require_gnuplot(a);
    const double alpha = given.alpha;
    studies::AssessOptions o;
    restitution_into(a, o.model);
    friction_into(a, o.model);
    imperfection_into(a, o.model);
    if (a.values.count("--width")) {
        o.width = number("--width", a.values.at("--width"));
        if (!(o.width >= 1e-7 && o.width <= 0.1)) throw UsageError("--width: must be in [1e-7, 0.1] (got " + a.values.at("--width") + ")");
    }
    if (!studies::in_search_alpha_range(alpha))
        throw UsageError("the block's alpha, " + significant(alpha, 6) + " rad, is outside the searches' " +
                         studies::kSearchAlphaRange);
    if (!studies::in_search_p_range(given.block.p))
        throw UsageError(size_flag +
                         ": the block's p, " + significant(given.block.p, 6) + " rad/s, is outside the searches' " +
                         studies::kSearchPRange);
    std::vector<records::Record> records;
    std::vector<std::unique_ptr<dynamics::SampledInput>> inputs;
    std::vector<const dynamics::SampledInput*> views;
    std::vector<records::PeakMotion> motions;
    for (const std::string& path : files) {
        records.push_back(load_record(path, a));
        const records::Record& r = records.back();
        motions.push_back(peak_motion_of(r, path));
        inputs.push_back(std::make_unique<dynamics::SampledInput>(r.in_g(dynamics::kGravity), r.dt, r.name));
        const studies::Refusal refused = studies::refusal_of(*inputs.back(), motions.back(), studies::BlockShape{alpha, given.block.p});
        if (refused.blame == studies::Refusal::Blame::block)
            throw UsageError(size_flag +
                             ": " + refused.why);
        if (refused.blame == studies::Refusal::Blame::record) throw std::runtime_error(path + ": " + refused.why);
        refuse_unresolvable_run(o.spectrum_options(given.block.p, given.alpha).p_max, inputs.back()->t_end(), a, {"--dt"}, path);
        views.push_back(inputs.back().get());
    }
    // As fragility: a record given twice (the same samples, whatever the path) would count twice in the fit.
    refuse_repeated_records(files, views);
    // The block's name in the outputs that list blocks (the plot's mark): its dimensions where given.
    const std::string name = given.given == GivenBlock::Given::dimensions
                                 ? significant(given.thickness, 6) + "x" + significant(given.height, 6)
                                 : given.label;
    const studies::Assessment s = studies::assess_block(views, motions, studies::BlockShape{alpha, given.block.p, name}, o);
    std::vector<std::string> names;
    for (const records::Record& r : records) names.push_back(r.name);
    if (a.values.count("--png")) {
        // 300 runs across the IDA's range: the curve between the outcomes it found.
        const studies::RecordAssessment& r = s.records[0];
        const std::vector<studies::ScaledRun> response =
            studies::scaled_response(*views[0], alpha, given.block.p, o.model, 1, o.ida_q_max(r.q_record), 300);
        write_assess_png(a.values.at("--png"), records[0], r, response, o.spectrum_options(given.block.p, given.alpha));
    }
    if (a.json) std::cout << json_text(json::assess_json(files, names, given, s, o, floor_input_note(a))) << "\n";
    else print_text(files, names, given, s, o, floor_input_note(a));
    if (!a.json && a.values.count("--png")) std::printf("plot: %s (the check above, the spectrum below)\n", a.values.at("--png").c_str());
    return 0;
}

}  // namespace rocking::cli
