#include "jobs/result_row.hpp"

#include <cstdio>

#include "records/collapse.hpp"

#include "batch/manifest.hpp"
#include "harness/table.hpp"

namespace rocking::jobs {

bool capacity_columns(const std::vector<std::string>& manifest_header) {
    for (const std::string& c : manifest_header)
        if (c == "method" || c == "width" || c == "robust_width") return true;
    return false;
}

const std::vector<std::string>& result_columns(bool capacities) {
    static const std::vector<std::string> names = {
        "status",   "model_used", "solver_used", "restitution_used", "criterion_used", "p_used",
        "collapse", "max_theta",  "theta_tfin",  "t_overturn",       "impacts",        "p_collapse",
        "p_safe",   "q_collapse", "q_safe",      "intervals",        "simulations",    "error"};
    static const std::vector<std::string> with_capacities = [] {
        std::vector<std::string> n = names;
        n.insert(n.end() - 1, {"robust_collapse", "q_robust", "p_robust", "bands"});
        return n;
    }();
    return capacities ? with_capacities : names;
}

std::string results_header(const std::string& manifest_path, std::size_t jobs,
                           const std::vector<std::string>& manifest_header) {
    std::string text = "# rocking batch: the results of " + manifest_path + ", one row per job (" + std::to_string(jobs) +
                       ") in the manifest's order\n";
    text += "# columns: line (the manifest's), the manifest's columns as written, then status (ok or error); model_used, "
            "solver_used, restitution_used, criterion_used and p_used (rad/s): what the job ran with, defaults filled in; "
            "collapse (yes/no; simulate: under its criterion, collapse: a p found, ida: below q_max, spectrum: an "
            "overturning interval); simulate: max_theta (max |theta|/alpha during the input), theta_tfin "
            "(theta(t_fin)/alpha, empty when it fell during the input), t_overturn (s, empty when it does not overturn "
            "or is taken to by its energy), impacts; collapse: p_collapse and p_safe (Table 1's bracket, rad/s); "
            "spectrum: p_collapse and p_safe (the lowest overturning interval's start and its safe end); ida: "
            "q_collapse and q_safe (the first collapse q = PGA/(alpha g) and its safe end), intervals, simulations; "
            "error (the manifest's line and the problem). See docs/batch.md\n";
    const bool capacities = capacity_columns(manifest_header);
    if (capacities)
        text += "# with method, width or robust_width in the manifest, before error (ida and spectrum, either method): "
                "q_collapse (ida) and p_collapse (spectrum) are the first overturning; robust_collapse (yes/no: an "
                "interval of overturning wider than the robust width in ln q or ln p), q_robust (ida) or p_robust "
                "(spectrum) its start, empty without one; bands: each step of the main grid that overturns at all, "
                "from|to|share (the share of the step, in ln q or ln p, that overturns), ';' between\n";
    std::string line = "line";
    for (const std::string& c : manifest_header) line += "," + batch::csv_cell(c);
    for (const std::string& c : result_columns(capacities)) line += "," + c;
    return text + line + "\n";
}

namespace {

std::string number(const std::optional<double>& v) { return v ? harness::format_number(*v) : ""; }
std::string count(const std::optional<long>& v) { return v ? std::to_string(*v) : ""; }

// The steps that overturn at all (the others' share is 0), as rocking
// fragility's rows write bands (jobs/fragility_plan.hpp).
std::string bands_cell(const std::vector<studies::Band>& bands) {
    std::string text;
    for (const studies::Band& b : bands)
        if (b.share > 0)
            text += (text.empty() ? "" : ";") + harness::format_number(b.from) + "|" + harness::format_number(b.to) + "|" +
                    harness::format_number(b.share);
    return text;
}

}  // namespace

std::string result_row(int line, const std::vector<std::string>& echo, const Job* job, const Figures* f,
                       const std::string& error, bool capacities) {
    std::string row = std::to_string(line);
    for (const std::string& cell : echo) batch::append_csv_cell(row, cell);
    std::vector<std::string> cells;
    cells.push_back(error.empty() ? "ok" : "error");
    if (job) {
        // A friction row's model, solver and impacts are the sliding-rocking model's own.
        if (job->friction > 0) {
            cells.push_back("sliding-rocking mu " + harness::format_number(job->friction));
            cells.push_back("event-driven dopri5 rtol " +
                            harness::format_number(job->solver.rtol != dynamics::SolverOptions{}.rtol ? job->solver.rtol
                                                                                                     : records::CollapseOptions{}.sliding_rtol));
            cells.push_back("impulse and momentum");
        } else {
            std::string model = job->equation == dynamics::Equation::linearised ? "linearised" : "full";
            const dynamics::Imperfection& imp = job->imperfection;
            if (imp.any()) {  // as the manifest's cells give them (%g: 0.03, not 0.029999999999999999)
                char text[160];
                std::snprintf(text, sizeof text, " imperfect lean %g out_of_plumb %g", imp.lean, imp.out_of_plumb);
                model += text;
                if (imp.fc > 0) {
                    std::snprintf(text, sizeof text, " fc %g density %g", imp.fc / 1e6, imp.density);
                    model += text;
                }
            }
            cells.push_back(model);
            cells.push_back(job->solver_text());
            // An imperfect block's Housner restitution is each corner's own (docs/imperfect.md).
            cells.push_back(imp.any() && job->housner ? std::string("per corner")
                                                      : harness::format_number(job->restitution_factor()));
        }
        cells.push_back(dynamics::criterion_name(job->criterion));
        cells.push_back(job->block ? harness::format_number(job->block->p) : "");
    } else
        cells.insert(cells.end(), 5, "");
    if (f) {
        cells.push_back(f->collapse ? "yes" : "no");
        for (const auto* v : {&f->max_theta, &f->theta_tfin, &f->t_overturn}) cells.push_back(number(*v));
        cells.push_back(count(f->impacts));
        for (const auto* v : {&f->p_collapse, &f->p_safe, &f->q_collapse, &f->q_safe}) cells.push_back(number(*v));
        cells.push_back(count(f->intervals));
        cells.push_back(count(f->simulations));
    } else
        cells.insert(cells.end(), 11, "");
    if (capacities && f) {
        cells.push_back(f->robust ? (*f->robust ? "yes" : "no") : "");
        cells.push_back(number(f->q_robust));
        cells.push_back(number(f->p_robust));
        cells.push_back(bands_cell(f->bands));
    } else if (capacities)
        cells.insert(cells.end(), 4, "");
    std::string one_line = error;  // a row is one line
    for (char& c : one_line)
        if (c == '\n' || c == '\r') c = ' ';
    cells.push_back(one_line);
    for (const std::string& c : cells) batch::append_csv_cell(row, c);
    return row;
}

}  // namespace rocking::jobs
