#include "jobs/spectrum_plan.hpp"

#include <cstdio>
#include <cstdlib>
#include <stdexcept>

#include "batch/manifest.hpp"
#include "batch/sha256.hpp"
#include "harness/table.hpp"
#include "jobs/row_cells.hpp"
#include "studies/record_order.hpp"

namespace rocking::jobs {

namespace {

using harness::format_number;
using studies::Boundary;
using studies::Interval;
using studies::SpectrumPoint;

const char kColumns[] =
    "job,alpha,lifts,simulations,check_simulations,boundaries,table1_found,table1_p,table1_p_safe,table1_simulations,"
    "intervals,points,first_overturning_p,overturns,first_robust_p,robustly,bands,refined,samples,accepted,at_width,"
    "with_margins,unguaranteed_from,error\n";
constexpr std::size_t kCells = 24, kError = kCells - 1;
constexpr std::size_t kIntervalFields = 10, kPointFields = 8;

std::string yes_no(bool v) { return v ? "yes" : "no"; }
std::string bit(bool v) { return v ? "1" : "0"; }

// A detail is free text inside fields split by '|' and ';'.
std::string escaped(const std::string& text) {
    std::string out;
    for (char c : text) {
        if (c == '%') out += "%25";
        else if (c == '|') out += "%7C";
        else if (c == ';') out += "%3B";
        else if (c == '\n') out += "%0A";
        else if (c == '\r') out += "%0D";
        else out += c;
    }
    return out;
}

std::string unescaped(const std::string& text, const std::string& where) {
    std::string out;
    for (std::size_t i = 0; i < text.size(); ++i) {
        if (text[i] != '%') {
            out += text[i];
            continue;
        }
        const std::string code = text.substr(i + 1, 2);
        if (code == "25") out += '%';
        else if (code == "7C") out += '|';
        else if (code == "3B") out += ';';
        else if (code == "0A") out += '\n';
        else if (code == "0D") out += '\r';
        else throw std::runtime_error(where + ": an unknown escape '%" + code + "' in a detail");
        i += 2;
    }
    return out;
}

std::string boundary_fields(bool has, const Boundary& b) {
    if (!has) return "|||";
    return format_number(b.p_safe) + "|" + format_number(b.p_collapse) + "|" +
           studies::confirmation_name(b.confirmation) + "|" + escaped(b.detail);
}

std::string intervals_cell(const std::vector<Interval>& intervals) {
    std::string text;
    for (const Interval& in : intervals)
        text += (text.empty() ? "" : ";") + format_number(in.from) + "|" + format_number(in.to) + "|" +
                boundary_fields(in.has_lower, in.lower) + "|" + boundary_fields(in.has_upper, in.upper);
    return text;
}

std::string points_cell(const std::vector<SpectrumPoint>& points) {
    std::string text;
    for (const SpectrumPoint& pt : points)
        text += (text.empty() ? "" : ";") + format_number(pt.p) + "|" + studies::grid_kind_name(pt.grid) + "|" +
                format_number(pt.max_theta) + "|" + bit(pt.final_rotation) + "|" + bit(pt.peak_rotation) + "|" +
                bit(pt.overturning) + "|" + bit(pt.collapse) + "|" + format_number(pt.t_overturn);
    return text;
}

// An empty error cell would read as a row that did not fail.
std::string failed_row(std::size_t job, double alpha, const std::string& error) {
    const std::string said = error.empty() ? "failed without a message" : one_line(error);
    return std::to_string(job) + "," + format_number(alpha) + "," + std::string(kCells - 3, ',') + batch::csv_cell(said);
}

// alpha as the user gave it (0.1, not %.17g's 0.10000000000000001): the
// fewest digits that read back to the same double.
std::string shortest(double v) {
    char text[40];
    for (int digits = 1; digits <= 17; ++digits) {
        std::snprintf(text, sizeof text, "%.*g", digits, v);
        if (std::strtod(text, nullptr) == v) break;
    }
    return text;
}

bool yes_no_of(const std::string& cell, const std::string& where) {
    if (cell == "yes" || cell == "no") return cell == "yes";
    throw std::runtime_error(where + ": '" + cell + "' where yes or no");
}

bool bit_of(const std::string& field, const std::string& where) {
    if (field == "1" || field == "0") return field == "1";
    throw std::runtime_error(where + ": '" + field + "' where 1 or 0");
}

studies::GridKind grid_kind_of(const std::string& name, const std::string& where) {
    using studies::GridKind;
    for (GridKind g : {GridKind::main, GridKind::offset, GridKind::extra})
        if (studies::grid_kind_name(g) == name) return g;
    throw std::runtime_error(where + ": an unknown grid '" + name + "'");
}

// fields[at..at+4): a boundary, or four empty fields for the grid's own end.
bool boundary_of(const std::vector<std::string>& fields, std::size_t at, Boundary& b, const std::string& where) {
    if (fields[at].empty()) return false;
    b.p_safe = number_of(fields[at], where);
    b.p_collapse = number_of(fields[at + 1], where);
    b.confirmation = confirmation_of(fields[at + 2]);
    b.detail = unescaped(fields[at + 3], where);
    return true;
}

// The parts of a list cell; none for an empty cell.
std::vector<std::string> items_of(const std::string& cell) {
    return cell.empty() ? std::vector<std::string>{} : split(cell, ';');
}

std::vector<std::string> fields_of(const std::string& item, std::size_t count, const std::string& what,
                                   const std::string& where) {
    std::vector<std::string> fields = split(item, '|');
    if (fields.size() != count)
        throw std::runtime_error(where + ": " + what + " of " + std::to_string(fields.size()) + " fields, not " +
                                 std::to_string(count));
    return fields;
}

std::vector<Interval> intervals_of(const std::string& cell, const std::string& where) {
    std::vector<Interval> out;
    for (const std::string& item : items_of(cell)) {
        const std::vector<std::string> f = fields_of(item, kIntervalFields, "an interval", where);
        Interval in;
        in.from = number_of(f[0], where);
        in.to = number_of(f[1], where);
        in.has_lower = boundary_of(f, 2, in.lower, where);
        in.has_upper = boundary_of(f, 6, in.upper, where);
        out.push_back(in);
    }
    return out;
}

// from|to|share;... for every band of the main grid.
std::string bands_cell(const std::vector<studies::Band>& bands) {
    std::string text;
    for (const studies::Band& b : bands)
        text += (text.empty() ? "" : ";") + format_number(b.from) + "|" + format_number(b.to) + "|" + format_number(b.share);
    return text;
}

std::vector<studies::Band> bands_of(const std::string& cell, const std::string& where) {
    std::vector<studies::Band> out;
    for (const std::string& item : items_of(cell)) {
        const std::vector<std::string> f = fields_of(item, 3, "a band", where);
        out.push_back({number_of(f[0], where), number_of(f[1], where), number_of(f[2], where)});
    }
    return out;
}

std::vector<SpectrumPoint> points_of(const std::string& cell, const std::string& where) {
    std::vector<SpectrumPoint> out;
    for (const std::string& item : items_of(cell)) {
        const std::vector<std::string> f = fields_of(item, kPointFields, "a point", where);
        SpectrumPoint pt;
        pt.p = number_of(f[0], where);
        pt.grid = grid_kind_of(f[1], where);
        pt.max_theta = number_of(f[2], where);
        pt.final_rotation = bit_of(f[3], where);
        pt.peak_rotation = bit_of(f[4], where);
        pt.overturning = bit_of(f[5], where);
        pt.collapse = bit_of(f[6], where);
        pt.t_overturn = number_of(f[7], where);
        out.push_back(pt);
    }
    return out;
}

// The plan's identity: a resume must find the rows of this very study.
std::string digest_of(const batch::BatchPlan& plan, const SpectrumJobs& jobs) {
    batch::Sha256 identity;
    identity.update(plan.header);
    for (double alpha : jobs.alphas) identity.update(format_number(alpha) + ";");
    const studies::SpectrumOptions& g = jobs.grid;
    identity.update(format_number(g.p_min) + "," + format_number(g.p_max) + "," + std::to_string(g.points) + "," +
                    bit(g.offset_grid) + "," + format_number(g.rel_tol) + "," + bit(g.confirm) + "," +
                    format_number(g.probe) + ";" + bit(g.method == studies::SpectrumOptions::Method::refine) + "," +
                    format_number(g.width) + "," + format_number(g.robust_width) + "," + format_number(g.slope_step) + ";");
    identity.update(g.describe_grid() + g.describe_model() + g.describe_refinement());
    return identity.hex();
}

}  // namespace

SpectrumStudy spectrum_study(const dynamics::GroundInput& input, double alpha, const studies::SpectrumOptions& grid) {
    const records::CollapseResult table1 = records::smallest_collapse_p(input, alpha, grid.model);
    studies::SpectrumOptions with_table1 = grid;
    if (table1.found) with_table1.extra_points = {table1.p};
    if (table1.found && !table1.below_range()) with_table1.extra_points.push_back(table1.p_safe);
    return {studies::rocking_spectrum(input, alpha, with_table1), table1};
}

batch::BatchPlan spectrum_plan(const SpectrumJobs& jobs) {
    batch::BatchPlan plan;
    plan.jobs = jobs.alphas.size();
    plan.header = jobs.description + "# one row per alpha, in the order given; columns: docs/batch.md (\"Studies on "
                                     "the engine\")\n" +
                  kColumns;
    plan.digest = digest_of(plan, jobs);
    plan.inputs.push_back({jobs.name, studies::sample_digest(*jobs.input)});
    plan.run = [&jobs](std::size_t k) {
        try {
            return batch::JobRow{study_row(k, spectrum_study(*jobs.input, jobs.alphas[k], jobs.grid)), false};
        } catch (const std::exception& e) {
            return batch::JobRow{failed_row(k, jobs.alphas[k], e.what()), true};
        }
    };
    return plan;
}

std::string study_row(std::size_t job, const SpectrumStudy& study) {
    const studies::Spectrum& s = study.spectrum;
    const records::CollapseResult& t = study.table1;
    return std::to_string(job) + "," + format_number(s.alpha) + "," + yes_no(s.lifts) + "," +
           std::to_string(s.simulations) + "," + std::to_string(s.check_simulations) + "," +
           std::to_string(s.boundaries) + "," + yes_no(t.found) + "," + format_number(t.p) + "," +
           format_number(t.p_safe) + "," + std::to_string(t.simulations) + "," +
           batch::csv_cell(intervals_cell(s.intervals)) + "," + batch::csv_cell(points_cell(s.points)) + "," +
           format_number(s.first_overturning.p) + "," + yes_no(s.first_overturning.found) + "," +
           format_number(s.first_robust_collapse.p) + "," + yes_no(s.first_robust_collapse.found) + "," +
           bands_cell(s.bands) + "," + yes_no(s.refined) + "," + std::to_string(s.samples) + "," +
           std::to_string(s.accepted) + "," + std::to_string(s.at_width) + "," + yes_no(s.with_margins) + "," +
           format_number(s.unguaranteed_from) + ",";
}

SpectrumStudy study_from_row(const std::string& row, std::size_t job, const SpectrumJobs& jobs) {
    const std::string where = "row " + std::to_string(job) + " of the spectra";
    std::vector<std::string> c;
    try {
        c = batch::split_csv_line(row);
    } catch (const std::invalid_argument& e) {
        throw std::runtime_error(where + ": " + e.what());
    }
    if (c.size() != kCells)
        throw std::runtime_error(where + ": " + std::to_string(c.size()) + " cells, not " + std::to_string(kCells));
    if (job >= jobs.alphas.size())
        throw std::runtime_error(where + ": the study has " + std::to_string(jobs.alphas.size()) + " alphas");
    if (whole_of(c[0], where) != static_cast<long>(job)) throw std::runtime_error(where + ": holds job " + c[0]);
    SpectrumStudy study;
    studies::Spectrum& s = study.spectrum;
    s.alpha = number_of(c[1], where);
    if (s.alpha != jobs.alphas[job])
        throw std::runtime_error(where + ": alpha " + c[1] + " where the study has " + format_number(jobs.alphas[job]));
    if (!c[kError].empty()) throw std::runtime_error("the spectrum at alpha " + shortest(s.alpha) + ": " + c[kError]);
    s.lifts = yes_no_of(c[2], where);
    s.simulations = whole_of(c[3], where);
    s.check_simulations = whole_of(c[4], where);
    s.boundaries = static_cast<int>(whole_of(c[5], where));
    records::CollapseResult& t = study.table1;
    t.found = yes_no_of(c[6], where);
    t.p = number_of(c[7], where);
    t.p_safe = number_of(c[8], where);
    t.simulations = static_cast<int>(whole_of(c[9], where));
    s.intervals = intervals_of(c[10], where);
    s.points = points_of(c[11], where);
    s.first_overturning = {number_of(c[12], where), yes_no_of(c[13], where)};
    s.first_robust_collapse = {number_of(c[14], where), yes_no_of(c[15], where)};
    s.bands = bands_of(c[16], where);
    s.refined = yes_no_of(c[17], where);
    s.samples = whole_of(c[18], where);
    s.accepted = whole_of(c[19], where);
    s.at_width = whole_of(c[20], where);
    s.with_margins = yes_no_of(c[21], where);
    s.unguaranteed_from = number_of(c[22], where);
    return study;
}

}  // namespace rocking::jobs
