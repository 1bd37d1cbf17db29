#include "jobs/fragility_plan.hpp"

#include <stdexcept>

#include "batch/manifest.hpp"
#include "batch/sha256.hpp"
#include "harness/table.hpp"
#include "jobs/row_cells.hpp"
#include "studies/record_order.hpp"

namespace rocking::jobs {

namespace {

using harness::format_number;
using studies::Ida;
using studies::IdaInterval;

const char kColumns[] =
    "job,alpha,p,record,q_input,q,collapsed,simulations,check_simulations,point_confirmation,point_detail,intervals,"
    "robust_q,robust_collapsed,bands,refined,samples,accepted,at_width,with_margins,unguaranteed_from,error\n";
constexpr std::size_t kCells = 22;

std::string bracket_cells(bool has, const studies::Bracket& b) {
    return has ? format_number(b.safe) + "|" + format_number(b.collapse) : "|";
}

std::string intervals_cell(const Ida& ida) {
    std::string text;
    for (const IdaInterval& in : ida.intervals)
        text += (text.empty() ? "" : ";") + format_number(in.from) + "|" + format_number(in.to) + "|" +
                bracket_cells(in.has_lower, in.lower) + "|" + bracket_cells(in.has_upper, in.upper);
    return text;
}

std::string bands_cell(const Ida& ida) {
    std::string text;
    for (const studies::IdaBand& b : ida.bands)
        text += (text.empty() ? "" : ";") + format_number(b.from) + "|" + format_number(b.to) + "|" + format_number(b.share);
    return text;
}

const char* yes_no(bool v) { return v ? "yes" : "no"; }

bool yes_no_of(const std::string& cell, const std::string& where) {
    if (cell != "yes" && cell != "no") throw std::runtime_error(where + ": '" + cell + "' where yes or no");
    return cell == "yes";
}

std::string ida_row(std::size_t job, std::size_t record, const Ida& ida) {
    const bool checked = !ida.intervals.empty() && ida.intervals.front().has_lower;
    const studies::Checked none;
    const studies::Checked& check = checked ? ida.intervals.front().lower_check : none;
    return std::to_string(job) + "," + format_number(ida.alpha) + "," + format_number(ida.p) + "," +
           std::to_string(record) + "," + format_number(ida.q_input) + "," + format_number(ida.point.q) + "," +
           (ida.point.collapsed ? "yes" : "no") + "," + std::to_string(ida.simulations) + "," +
           std::to_string(ida.check_simulations) + "," + batch::csv_cell(studies::confirmation_name(check.confirmation)) +
           "," + batch::csv_cell(one_line(check.detail)) + "," + intervals_cell(ida) + "," +
           format_number(ida.first_robust_collapse.q) + "," + yes_no(ida.first_robust_collapse.collapsed) + "," +
           bands_cell(ida) + "," + yes_no(ida.refined) + "," + std::to_string(ida.samples) + "," +
           std::to_string(ida.accepted) + "," + std::to_string(ida.at_width) + "," + yes_no(ida.with_margins) + "," +
           format_number(ida.unguaranteed_from) + ",";
}

std::string failed_row(std::size_t job, const studies::BlockShape& block, std::size_t record, const std::string& error) {
    return std::to_string(job) + "," + format_number(block.alpha) + "," + format_number(block.p) + "," +
           std::to_string(record) + ",,,,,,,,,,,,,,,,,," + batch::csv_cell(one_line(error));
}

}  // namespace

batch::BatchPlan fragility_plan(const FragilityJobs& jobs) {
    batch::BatchPlan plan;
    const std::size_t n = jobs.inputs.size();
    plan.jobs = jobs.blocks.size() * n;
    plan.header = jobs.description + "# one row per IDA, block by block, the records in the order given; columns: "
                                     "docs/batch.md (\"Studies on the engine\")\n" +
                  kColumns;
    batch::Sha256 identity;
    identity.update(plan.header);
    for (const studies::BlockShape& b : jobs.blocks) identity.update(format_number(b.alpha) + "," + format_number(b.p) + ";");
    // The method and its width are in describe_grid; the robust width sets each row's first robust collapse.
    identity.update(jobs.ida.describe_grid() + jobs.ida.describe_model() + jobs.ida.describe_checks() +
                    "; robust width " + format_number(jobs.ida.robust_width));
    plan.digest = identity.hex();
    for (std::size_t k = 0; k < n; ++k)
        plan.inputs.push_back({k < jobs.names.size() ? jobs.names[k] : "record " + std::to_string(k),
                               studies::sample_digest(*jobs.inputs[k])});
    plan.run = [&jobs, n](std::size_t j) {
        const studies::BlockShape& block = jobs.blocks[j / n];
        try {
            const Ida ida = studies::incremental_dynamic_analysis(*jobs.inputs[j % n], block.alpha, block.p, jobs.ida);
            return batch::JobRow{ida_row(j, j % n, ida), false};
        } catch (const std::exception& e) {
            return batch::JobRow{failed_row(j, block, j % n, e.what()), true};
        }
    };
    return plan;
}

Ida ida_from_row(const std::string& row, std::size_t job, const FragilityJobs& jobs) {
    const std::string where = "row " + std::to_string(job) + " of the IDAs";
    const std::vector<std::string> c = batch::split_csv_line(row);
    if (c.size() != kCells) throw std::runtime_error(where + ": " + std::to_string(c.size()) + " cells, not " +
                                                     std::to_string(kCells));
    if (whole_of(c[0], where) != static_cast<long>(job)) throw std::runtime_error(where + ": holds job " + c[0]);
    const std::size_t n = jobs.inputs.size();
    if (!c[21].empty()) throw std::runtime_error("the IDA of record " + std::to_string(job % n + 1) + " on alpha " + c[1] +
                                                 ", p " + c[2] + ": " + c[21]);
    Ida ida;
    ida.alpha = number_of(c[1], where);
    ida.p = number_of(c[2], where);
    ida.q_input = number_of(c[4], where);
    ida.point = {number_of(c[5], where), c[6] == "yes"};
    ida.simulations = whole_of(c[7], where);
    ida.check_simulations = whole_of(c[8], where);
    if (!c[11].empty())
        for (const std::string& text : split(c[11], ';')) {
            const std::vector<std::string> v = split(text, '|');
            if (v.size() != 6) throw std::runtime_error(where + ": an interval of " + std::to_string(v.size()) + " numbers");
            IdaInterval in;
            in.from = number_of(v[0], where);
            in.to = number_of(v[1], where);
            in.has_lower = !v[2].empty();
            if (in.has_lower) in.lower = {number_of(v[2], where), number_of(v[3], where)};
            in.has_upper = !v[4].empty();
            if (in.has_upper) in.upper = {number_of(v[4], where), number_of(v[5], where)};
            ida.intervals.push_back(in);
        }
    if (!ida.intervals.empty()) ida.intervals.front().lower_check = {confirmation_of(c[9]), c[10]};
    // The first overturning is the first collapse (studies/ida.cpp, summarise), for both methods.
    ida.first_overturning = ida.point;
    ida.first_robust_collapse = {number_of(c[12], where), yes_no_of(c[13], where)};
    if (!c[14].empty())
        for (const std::string& text : split(c[14], ';')) {
            const std::vector<std::string> v = split(text, '|');
            if (v.size() != 3) throw std::runtime_error(where + ": a band of " + std::to_string(v.size()) + " numbers");
            ida.bands.push_back({number_of(v[0], where), number_of(v[1], where), number_of(v[2], where)});
        }
    ida.refined = yes_no_of(c[15], where);
    ida.samples = whole_of(c[16], where);
    ida.accepted = whole_of(c[17], where);
    ida.at_width = whole_of(c[18], where);
    ida.with_margins = yes_no_of(c[19], where);
    ida.unguaranteed_from = number_of(c[20], where);
    const studies::BlockShape& block = jobs.blocks[job / n];
    if (ida.alpha != block.alpha || ida.p != block.p)
        throw std::runtime_error(where + ": alpha " + c[1] + ", p " + c[2] + " where the study has " +
                                 format_number(block.alpha) + ", " + format_number(block.p));
    // Not in the row: the grid's start is the study's (an imperfect block's from where it
    // lifts), and the stripes and their half-width are taken from it.
    ida.q_start = jobs.ida.q_start(block.alpha, block.p);
    return ida;
}

}  // namespace rocking::jobs
