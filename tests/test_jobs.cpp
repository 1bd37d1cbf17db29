// A batch manifest's meaning (src/jobs/): its columns read into typed jobs
// with the single commands' defaults, each bad cell refused with its column
// named, the jobs run through the library giving what the library gives when
// called directly, records read once for all their jobs, and a plan whose
// rows do not depend on the order or the company the jobs run in.
#include <gtest/gtest.h>

#include <stdlib.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <regex>
#include <string>
#include <vector>

#include "batch/manifest.hpp"
#include "batch/sha256.hpp"
#include "jobs/batch_plan.hpp"
#include "jobs/job.hpp"
#include "jobs/record_store.hpp"
#include "jobs/result_row.hpp"
#include "jobs/run_job.hpp"
#include "records/collapse.hpp"
#include "records/record.hpp"
#include "studies/ida.hpp"
#include "studies/spectrum.hpp"
#include "test_util.hpp"

using namespace rocking;
using jobs::Columns;
using jobs::Job;
using jobs::Kind;
using jobs::parse_job;

namespace {

std::string temp_dir() { return rocking::testing::temp_folder("rocking-jobs-test"); }

// A decaying 1 Hz sine of 0.3 g, 10 s at dt = 0.01 s, one column in g: it
// lifts blocks of alpha 0.1 and overturns some.
std::string write_sine(const std::string& dir, const std::string& name = "sine.txt") {
    const std::string path = dir + "/" + name;
    std::FILE* f = std::fopen(path.c_str(), "w");
    for (int k = 0; k < 1000; ++k) {
        const double t = k * 0.01;
        std::fprintf(f, "%.17g\n", 0.3 * std::sin(2 * M_PI * t) * std::exp(-t / 3));
    }
    std::fclose(f);
    return path;
}

dynamics::SampledInput read_sine(const std::string& path) {
    const records::Record r = records::read_plain(path, "g", 0.01);
    return dynamics::SampledInput(r.in_g(dynamics::kGravity), r.dt, r.name);
}

const std::vector<std::string> kHeader = {"id", "kind", "record", "unit", "record_dt", "alpha", "p", "height",
                                          "scaling", "model", "solver", "rtol", "atol", "restitution", "criterion",
                                          "q_max", "points", "p_min", "p_max"};

// A row under kHeader from "column=value" pairs.
std::vector<std::string> row(const std::vector<std::pair<std::string, std::string>>& cells) {
    std::vector<std::string> out(kHeader.size());
    for (const auto& [name, value] : cells)
        for (std::size_t c = 0; c < kHeader.size(); ++c)
            if (kHeader[c] == name) out[c] = value;
    return out;
}

std::string refusal(const std::vector<std::pair<std::string, std::string>>& cells) {
    try {
        parse_job(Columns(kHeader), row(cells), "/data");
    } catch (const std::invalid_argument& e) {
        return e.what();
    }
    return "accepted";
}

}  // namespace

TEST(Jobs, TheHeaderMustNameKnownColumnsAndARecordAndAlpha) {
    EXPECT_NO_THROW(Columns{kHeader});
    EXPECT_NO_THROW(Columns{std::vector<std::string>({"record", "alpha"})});
    try {
        Columns({"record", "alpha", "pga"});
        ADD_FAILURE() << "an unknown column accepted";
    } catch (const std::invalid_argument& e) {
        EXPECT_NE(std::string(e.what()).find("unknown column 'pga' (the columns: id, kind, record"), std::string::npos)
            << e.what();
    }
    EXPECT_THROW(Columns({"kind", "alpha"}), std::invalid_argument);
    EXPECT_THROW(Columns({"kind", "record"}), std::invalid_argument);
}

TEST(Jobs, EmptyCellsTakeTheDefaultsOfTheCommandThatRunsTheStudyAlone) {
    const Columns c(kHeader);
    // rocking simulate (issue 40: one model by default): Housner's restitution, overturning,
    // exact for the linearised equation, dopri5 for the full one.
    Job s = parse_job(c, row({{"record", "r.txt"}, {"alpha", "0.1"}, {"p", "2"}}), "/data");
    EXPECT_EQ(s.kind, Kind::simulate);
    EXPECT_EQ(s.record.path, "/data/r.txt");
    EXPECT_EQ(s.restitution_factor(), dynamics::housner_restitution(0.1));
    EXPECT_EQ(s.criterion, dynamics::Criterion::overturning);
    EXPECT_EQ(s.solver_text(), "exact");
    EXPECT_EQ(s.block->p, 2.0);
    Job full = parse_job(c, row({{"record", "/abs/r.txt"}, {"alpha", "0.1"}, {"height", "3"}, {"model", "full"}}), "/data");
    EXPECT_EQ(full.record.path, "/abs/r.txt");
    EXPECT_EQ(full.solver_text(), "dopri5 rtol 1e-06 atol 1e-06 alpha");
    EXPECT_EQ(full.block->p, dynamics::Block::from_full_height(3, 0.1).p);
    Job tol = parse_job(c, row({{"record", "r"}, {"alpha", "0.2"}, {"p", "2"}, {"solver", "rkf78"}, {"rtol", "1e-8"},
                                {"atol", "1e-10"}}),
                        ".");
    EXPECT_EQ(tol.solver.rtol, 1e-8);
    EXPECT_DOUBLE_EQ(tol.solver.atol_alpha, 1e-10 / 0.2);
    // collapse, ida, spectrum: Table 1's model (Housner's restitution, overturning, exact).
    for (const char* kind : {"collapse", "ida", "spectrum"}) {
        Job j = parse_job(c, row({{"kind", kind}, {"record", "r"}, {"alpha", "0.15"}, {"p", kind == std::string("ida") ? "2" : ""}}), ".");
        EXPECT_DOUBLE_EQ(j.restitution_factor(), dynamics::housner_restitution(0.15)) << kind;
        EXPECT_EQ(j.criterion, dynamics::Criterion::overturning) << kind;
        EXPECT_EQ(j.solver_text(), "exact") << kind;
    }
    Job ida = parse_job(c, row({{"kind", "ida"}, {"record", "r"}, {"alpha", "0.1"}, {"p", "2"}}), ".");
    EXPECT_EQ(ida.points, 100);
    EXPECT_EQ(ida.q_max, 20);
    Job sp = parse_job(c, row({{"kind", "spectrum"}, {"record", "r"}, {"alpha", "0.1"}}), ".");
    EXPECT_EQ(sp.points, 200);
    EXPECT_EQ(sp.p_min, 0.3);
    EXPECT_EQ(sp.p_max, 30);
    Job scaled = parse_job(c, row({{"record", "r"}, {"alpha", "0.1"}, {"p", "2"}, {"scaling", "pga=0.25"}}), ".");
    EXPECT_EQ(scaled.scaling.by, jobs::Scaling::By::pga);
    EXPECT_EQ(scaled.scaling.value, 0.25);
}

TEST(Jobs, EachBadCellIsRefusedNamingItsColumn) {
    const std::pair<std::string, std::string> rec{"record", "r.txt"}, a{"alpha", "0.1"}, p{"p", "2"};
    EXPECT_EQ(refusal({rec, {"alpha", "0"}, p}), "alpha: must be in (0, pi/4) (got 0)");
    EXPECT_EQ(refusal({rec, {"alpha", "-0.1"}, p, {"kind", "collapse"}}).substr(0, 7), "p: does");
    EXPECT_EQ(refusal({rec, {"alpha", "-0.1"}, {"kind", "collapse"}}), "alpha: must be in (0, pi/4) (got -0.1)");
    EXPECT_EQ(refusal({rec, {"alpha", "abc"}, p}), "alpha: 'abc' is not a number");
    EXPECT_EQ(refusal({rec, {"alpha", "0.1x"}, p}), "alpha: '0.1x' is not a number");
    // The command line's number reader and messages (numerics/number_text.hpp), in every numeric column.
    EXPECT_EQ(refusal({rec, {"alpha", "1e400"}, p}),
              "alpha: '1e400' is too large for a double (magnitude beyond 1.7976931348623157e+308)");
    EXPECT_EQ(refusal({rec, a, {"p", "-1e400"}}),
              "p: '-1e400' is too large for a double (magnitude beyond 1.7976931348623157e+308)");
    EXPECT_EQ(refusal({rec, {"alpha", "1e-320"}, p}), "alpha: '1e-320' is below the smallest normal double, 2.2250738585072014e-308");
    EXPECT_EQ(refusal({rec, a, p, {"rtol", "nan"}}), "rtol: 'nan' is not a finite number");
    EXPECT_EQ(refusal({rec, a, p, {"scaling", "q=0x10"}}), "scaling: '0x10' is not a number (hexadecimal is not read)");
    EXPECT_EQ(refusal({rec, a, {"kind", "spectrum"}, {"p_max", "1,5"}}), "p_max: '1,5' is not a number (decimal commas are not read)");
    EXPECT_EQ(refusal({rec, a, {"kind", "ida"}, p, {"points", "1e400"}}),
              "points: must be a whole number from 2 to 10000 (got '1e400')");
    EXPECT_EQ(refusal({rec, a, {"kind", "ida"}, p, {"points", "2.5"}}), "points: must be a whole number from 2 to 10000 (got 2.5)");
    // Blanks around a cell's number, at either end alike.
    EXPECT_EQ(refusal({rec, {"alpha", "0.1 "}, p}), "accepted");
    EXPECT_EQ(refusal({rec, {"alpha", " 0.1"}, p}), "accepted");
    EXPECT_EQ(refusal({rec, a}), "p: give exactly one of p (rad/s), height and half_height (m) for a simulate job");
    EXPECT_EQ(refusal({rec, a, p, {"height", "2"}}).substr(0, 24), "p, height, half_height: ");
    EXPECT_EQ(refusal({rec, a, p, {"solver", "rk45"}}),
              "solver: unknown solver 'rk45' (exact, dopri5, rkf78, bulirsch-stoer, gsl-rk8pd)");
    EXPECT_EQ(refusal({rec, a, p, {"model", "full"}, {"solver", "exact"}}),
              "solver: the exact solver handles the linearised equation only (model full)");
    EXPECT_EQ(refusal({rec, a, p, {"model", "nonlinear"}}), "model: linearised or full (got 'nonlinear')");
    EXPECT_EQ(refusal({rec, a, p, {"kind", "simulation"}}), "kind: 'simulation' is not a kind (simulate, collapse, ida, spectrum)");
    EXPECT_EQ(refusal({rec, a, p, {"restitution", "1.5"}}), "restitution: must be in [0, 1] or housner (got 1.5)");
    EXPECT_EQ(refusal({rec, a, p, {"criterion", "fall"}}).substr(0, 11), "criterion: ");
    EXPECT_EQ(refusal({rec, a, p, {"rtol", "1e-20"}}).substr(0, 17), "rtol: must be in ");
    EXPECT_EQ(refusal({rec, a, p, {"scaling", "2"}}),
              "scaling: '2' is not q=Q (PGA = Q alpha g) or pga=G (in g), or empty (as recorded)");
    EXPECT_EQ(refusal({rec, a, p, {"scaling", "q=-1"}}), "scaling: q must be > 0 (got -1)");
    EXPECT_EQ(refusal({rec, a, {"kind", "collapse"}, p}), "p: does not apply to a collapse job (it searches p)");
    EXPECT_EQ(refusal({rec, a, {"kind", "ida"}, p, {"scaling", "q=2"}}),
              "scaling: does not apply to an ida job (the IDA scales the record itself, over q)");
    EXPECT_EQ(refusal({rec, a, p, {"q_max", "10"}}), "q_max: does not apply to a simulate job (not one of its columns)");
    EXPECT_EQ(refusal({rec, a, {"kind", "ida"}, p, {"q_max", "1"}}), "q_max: must be in (1, 10000] (got 1)");
    EXPECT_EQ(refusal({rec, a, {"kind", "ida"}, {"p", "0.001"}}).substr(0, 42), "p: the block's p must be in (0.01, 1000) r");
    EXPECT_EQ(refusal({rec, a, {"kind", "spectrum"}, {"points", "1"}}), "points: must be a whole number from 2 to 100000 (got 1)");
    EXPECT_EQ(refusal({rec, a, {"kind", "spectrum"}, {"p_min", "5"}, {"p_max", "4"}}), "p_max: must be above p_min (5 rad/s)");
    EXPECT_EQ(refusal({{"record", ""}, a, p}), "record: empty: every job needs a record file");
    EXPECT_EQ(refusal({rec, a, p, {"unit", "gal"}}), "unit: 'gal' is not a unit it knows (g, m/s2, cm/s2)");
    EXPECT_EQ(refusal({rec, a, p, {"record_dt", "0.01"}}),
              "record_dt: goes with unit (a plain-text record in g, m/s2 or cm/s2)");
    EXPECT_EQ(refusal({rec, a, p, {"p", "-2"}}), "p: p must be > 0");
    try {
        parse_job(Columns(kHeader), {"a", "simulate"}, ".");
        ADD_FAILURE() << "a short row accepted";
    } catch (const std::invalid_argument& e) {
        EXPECT_STREQ(e.what(), "2 cells, the header has 19");
    }
}

TEST(Jobs, EachKindGivesWhatTheLibraryGivesWhenCalledDirectly) {
    const std::string dir = temp_dir(), path = write_sine(dir);
    const dynamics::SampledInput input = read_sine(path);
    const Columns c(kHeader);
    jobs::RecordStore store;
    auto run = [&](const std::vector<std::pair<std::string, std::string>>& cells) {
        std::vector<std::pair<std::string, std::string>> all = {{"record", "sine.txt"}, {"unit", "g"}, {"record_dt", "0.01"}};
        all.insert(all.end(), cells.begin(), cells.end());
        return jobs::run_job(parse_job(c, row(all), dir), store);
    };

    // simulate, scaled to q = 2.5 as rocking simulate --q scales it: the samples times PGA/peak.
    {
        const jobs::Figures f = run({{"alpha", "0.1"}, {"p", "2"}, {"scaling", "q=2.5"}, {"restitution", "housner"},
                                     {"criterion", "overturning"}});
        std::vector<double> g = records::read_plain(path, "g", 0.01).in_g(dynamics::kGravity);
        const double peak = input.peak();
        for (double& v : g) v *= 0.25 / peak;
        const dynamics::SampledInput scaled(g, 0.01, "scaled");
        dynamics::Model model;
        model.block = dynamics::Block::from_p(2, 0.1);
        model.restitution = dynamics::housner_restitution(0.1);
        const dynamics::SimulationResult r = dynamics::simulate(model, scaled, {});
        EXPECT_EQ(*f.max_theta, r.max_abs_theta_input / 0.1);
        EXPECT_EQ(*f.theta_tfin, r.theta_at_tfin / 0.1);
        EXPECT_EQ(*f.impacts, r.impacts);
        EXPECT_EQ(f.collapse, r.collapse(dynamics::Criterion::overturning, 0.1));
        EXPECT_GT(*f.impacts, 0);
    }
    // collapse: Table 1's search.
    {
        const jobs::Figures f = run({{"kind", "collapse"}, {"alpha", "0.1"}});
        const records::CollapseResult r = records::smallest_collapse_p(input, 0.1, {});
        ASSERT_TRUE(r.found);
        EXPECT_TRUE(f.collapse);
        EXPECT_EQ(*f.p_collapse, r.p);
        EXPECT_EQ(*f.p_safe, r.p_safe);
        EXPECT_EQ(*f.simulations, r.simulations);
    }
    // ida: one record and block of the fragility study.
    {
        const jobs::Figures f = run({{"kind", "ida"}, {"alpha", "0.1"}, {"p", "2"}, {"points", "30"}, {"q_max", "10"}});
        studies::IdaOptions o;
        o.points = 30;
        o.q_max = 10;
        const studies::Ida r = studies::incremental_dynamic_analysis(input, 0.1, 2, o);
        ASSERT_TRUE(r.point.collapsed);
        EXPECT_EQ(*f.q_collapse, r.point.q);
        EXPECT_EQ(*f.q_safe, r.intervals.front().lower.safe);
        EXPECT_EQ(*f.intervals, static_cast<long>(r.intervals.size()));
        EXPECT_EQ(*f.simulations, r.simulations);
    }
    // spectrum: Table 1's bracket joining the grid, as rocking spectrum does.
    {
        const jobs::Figures f = run({{"kind", "spectrum"}, {"alpha", "0.1"}, {"points", "40"}});
        studies::SpectrumOptions o;
        o.points = 40;
        const records::CollapseResult t1 = records::smallest_collapse_p(input, 0.1, {});
        o.extra_points = {t1.p, t1.p_safe};
        const studies::Spectrum s = studies::rocking_spectrum(input, 0.1, o);
        ASSERT_FALSE(s.intervals.empty());
        EXPECT_EQ(*f.p_collapse, s.intervals.front().from);
        EXPECT_EQ(*f.intervals, static_cast<long>(s.intervals.size()));
        EXPECT_EQ(*f.simulations, s.simulations);
    }
    EXPECT_EQ(store.reads(), 1u);  // one record, read once for all of them
}

TEST(Jobs, ARecordIsReadOnceUnderAnySpellingAndItsErrorNamesEachRowsOwn) {
    const std::string dir = temp_dir();
    write_sine(dir);
    jobs::RecordStore store;
    auto source = [&](const std::string& cell) {
        return jobs::RecordSource{cell, dir + "/" + cell, "g", 0.01};
    };
    const auto a = store.get(source("sine.txt")), b = store.get(source("./sine.txt")),
               c = store.get(source("../" + dir.substr(dir.rfind('/') + 1) + "/sine.txt"));
    EXPECT_EQ(a.get(), b.get());
    EXPECT_EQ(a.get(), c.get());
    EXPECT_EQ(store.reads(), 1u);
    for (const char* cell : {"missing.txt", "./missing.txt"}) {
        try {
            store.get(source(cell));
            ADD_FAILURE() << "a missing record read";
        } catch (const std::runtime_error& e) {
            EXPECT_EQ(std::string(e.what()).rfind(std::string(cell) + ": cannot open", 0), 0u) << e.what();
        }
    }
    EXPECT_EQ(store.reads(), 2u);  // the failure is remembered, not read again
}

TEST(Jobs, APlansRowsDoNotDependOnTheirOrderOrCompany) {
    const std::string dir = temp_dir();
    write_sine(dir);
    const std::vector<std::string> rows = {
        "simulate,sine.txt,g,0.01,0.1,2,q=2",  "collapse,sine.txt,g,0.01,0.12,,",
        "ida,sine.txt,g,0.01,0.1,3,",          "simulate,missing.txt,g,0.01,0.1,2,",
        "simulate,sine.txt,g,0.01,0,2,",       "simulate,sine.txt,g,0.01,0.1",
        "spectrum,sine.txt,g,0.01,0.08,,q=1.5"};
    auto rows_of = [&](const std::vector<std::size_t>& order) {
        std::string text = "kind,record,unit,record_dt,alpha,p,scaling\n";
        for (std::size_t i : order) text += rows[i] + "\n";
        const batch::Manifest m = batch::Manifest::parse(text, dir + "/m.csv");
        jobs::RecordStore store;
        const batch::BatchPlan plan = jobs::make_plan(m, store);
        std::vector<batch::JobRow> out(rows.size());
        for (std::size_t k = 0; k < order.size(); ++k) {
            out[order[k]] = plan.run(k);
            // The line number is the manifest's: drop it to compare rows across orders.
            out[order[k]].text = std::regex_replace(out[order[k]].text.substr(out[order[k]].text.find(',')),
                                                    std::regex("manifest line [0-9]+"), "manifest line N");
        }
        return out;
    };
    const auto forward = rows_of({0, 1, 2, 3, 4, 5, 6}), backward = rows_of({6, 5, 4, 3, 2, 1, 0}),
               alone = rows_of({2});
    for (std::size_t i = 0; i < rows.size(); ++i) {
        EXPECT_EQ(forward[i].text, backward[i].text) << rows[i];
        EXPECT_EQ(forward[i].failed, backward[i].failed) << rows[i];
    }
    EXPECT_EQ(alone[2].text, forward[2].text);
    EXPECT_FALSE(forward[0].failed);
    EXPECT_TRUE(forward[3].failed);
    EXPECT_NE(forward[3].text.find(",error,"), std::string::npos);
    EXPECT_NE(forward[3].text.find("manifest line N: missing.txt"), std::string::npos) << forward[3].text;
    EXPECT_NE(forward[3].text.find("missing.txt: cannot open"), std::string::npos) << forward[3].text;
    EXPECT_NE(forward[4].text.find("alpha: must be in (0, pi/4) (got 0)"), std::string::npos) << forward[4].text;
    EXPECT_NE(forward[5].text.find("5 cells, the header has 7"), std::string::npos) << forward[5].text;
    const batch::Manifest m = batch::Manifest::parse("kind,record,alpha\n\n# c\nsimulate,nope.txt,0\n", dir + "/m.csv");
    jobs::RecordStore store;
    EXPECT_NE(jobs::make_plan(m, store).run(0).text.find("manifest line 4: alpha:"), std::string::npos);
    const batch::Manifest unknown = batch::Manifest::parse("kind,record,alpha,mass\n", dir + "/m.csv");
    EXPECT_THROW(jobs::make_plan(unknown, store), std::invalid_argument);
}

// Issue 38, item 2: the plan keeps each record's SHA-256 for the results'
// header (a resume then proves the records unchanged), and a record whose
// bytes change while the batch runs fails its jobs rather than mixing them in.
TEST(Jobs, APlanKeepsEachRecordsDigestAndRefusesARecordChangedSince) {
    const std::string dir = temp_dir();
    write_sine(dir, "a.txt");
    write_sine(dir, "b.txt");
    std::ifstream in(dir + "/a.txt", std::ios::binary);
    const std::string a_bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    const batch::Manifest m = batch::Manifest::parse(
        "record,unit,record_dt,alpha,p\na.txt,g,0.01,0.1,2\n./b.txt,g,0.01,0.1,2\na.txt,g,0.01,0.12,2\n"
        "none.txt,g,0.01,0.1,2\n" + dir + "/a.txt,g,0.01,0.1,2\nb.txt,g,0.01,0.1,2\n",
        dir + "/m.csv");
    jobs::RecordStore store;
    const batch::BatchPlan plan = jobs::make_plan(m, store);
    const std::string a = batch::sha256_hex(a_bytes);
    ASSERT_EQ(plan.inputs.size(), 5u);  // each record cell once, in the order first named
    const std::vector<std::pair<std::string, std::string>> want = {
        {"a.txt", a}, {"./b.txt", a}, {"none.txt", "unreadable"}, {dir + "/a.txt", a}, {"b.txt", a}};
    for (std::size_t k = 0; k < want.size(); ++k) {
        EXPECT_EQ(plan.inputs[k].name, want[k].first);
        EXPECT_EQ(plan.inputs[k].digest, want[k].second) << want[k].first;  // a.txt and b.txt hold the same bytes
    }
    const std::vector<jobs::NamedRecord> named = jobs::named_records(m);
    ASSERT_EQ(named.size(), 5u);
    EXPECT_EQ(named[2].path, dir + "/none.txt");
    EXPECT_EQ(named[2].line, 5);
    EXPECT_FALSE(plan.run(0).failed);
    // b.txt edited (samples x 1.1) after the plan began: its jobs fail, naming it.
    const records::Record b = records::read_plain(dir + "/b.txt", "g", 0.01);
    std::FILE* f = std::fopen((dir + "/b.txt").c_str(), "w");
    for (double v : b.in_g()) std::fprintf(f, "%.17g\n", 1.1 * v);
    std::fclose(f);
    const batch::JobRow row = plan.run(1);
    EXPECT_TRUE(row.failed);
    EXPECT_NE(row.text.find("manifest line 3: ./b.txt: has changed since the batch began (its sha256 was " + a),
              std::string::npos) << row.text;
}

// The records a plan pins are the cells its jobs read, split_csv_line's reading of each
// row, whether the row is cut at its commas in place (no quote) or split (a quote).
TEST(Jobs, TheNamedRecordsAreTheCellsTheRowsJobsRead) {
    const batch::Manifest m = batch::Manifest::parse(
        "kind, record ,alpha\n"
        "simulate, a.txt ,0.1\n"          // spaces around the cell
        "simulate,\ta.txt\t,0.2\n"        // tabs: the same record
        "\"simulate\",b.txt,0.1\n"        // a quote elsewhere in the row
        "simulate,\"c, d.txt\",0.1\n"     // a comma inside the quoted name
        "simulate,\"e \"\"q\"\".txt\" ,0.1\n"
        "simulate,,0.1\n"                 // no record: no input
        "simulate\n"                      // too short: no input
        "simulate,\"f.txt\"g,0.1\n"       // text after a closing quote: the row is refused
        "simulate,h.txt\n"
        "simulate,b.txt,0.3\n",
        "/tmp/m.csv");
    const std::vector<jobs::NamedRecord> named = jobs::named_records(m);
    const std::vector<std::string> want = {"a.txt", "b.txt", "c, d.txt", "e \"q\".txt", "h.txt"};
    ASSERT_EQ(named.size(), want.size());
    for (std::size_t k = 0; k < want.size(); ++k) {
        EXPECT_EQ(named[k].cell, want[k]);
        EXPECT_EQ(named[k].path, "/tmp/" + want[k]);
    }
    EXPECT_EQ(named[3].line, 6);
    EXPECT_EQ(named[4].line, 10);
}

// A relative record that is not there: the message says the folder it was
// looked for in (issue 38: a manifest read from /dev/stdin or through a link).
TEST(Jobs, AMissingRelativeRecordNamesTheFolderItWasResolvedFrom) {
    const std::string dir = temp_dir();
    const batch::Manifest m =
        batch::Manifest::parse("record,unit,record_dt,alpha,p\nnone.txt,g,0.01,0.1,2\n/no/such.txt,g,0.01,0.1,2\n",
                               "m.csv", {dir, dir + ", the folder of the link"});
    jobs::RecordStore store;
    const batch::BatchPlan plan = jobs::make_plan(m, store);
    EXPECT_NE(plan.run(0).text.find("none.txt: cannot open the file (No such file or directory); none.txt is resolved "
                                    "from " + dir + ", the folder of the link\""),
              std::string::npos) << plan.run(0).text;
    EXPECT_EQ(plan.run(1).text.find("resolved from"), std::string::npos) << "an absolute path needs no folder";
}

TEST(Jobs, AResultRowHasTheHeadersColumnsAndQuotesWhatNeedsIt) {
    const std::vector<std::string> header = {"kind", "record", "alpha"};
    const std::string head = jobs::results_header("m.csv", 1, header);
    const std::string columns = head.substr(head.rfind('\n', head.size() - 2) + 1);
    const std::string r = jobs::result_row(7, {"simulate", "a, b.txt", "0.1"}, nullptr, nullptr, "line\nbreak, and \"quote\"");
    EXPECT_EQ(batch::split_csv_line(columns.substr(0, columns.size() - 1)).size(), batch::split_csv_line(r).size());
    EXPECT_EQ(r.find('\n'), std::string::npos);
    EXPECT_EQ(batch::split_csv_line(r)[2], "a, b.txt");
    EXPECT_EQ(batch::split_csv_line(r).back(), "line break, and \"quote\"");
}

// The searches' slenderness is one range, studies::kSearchAlphaMax: a batch
// row of each search, and the library's spectrum and IDA (which took (0, 1)
// where every command took (0, pi/4)), refuse alpha = 0.72 alike.
TEST(Jobs, EverySearchTakesTheCommandsAlphaRange) {
    const std::pair<std::string, std::string> rec{"record", "r.txt"}, alpha{"alpha", "0.8"};
    EXPECT_EQ(refusal({rec, alpha, {"kind", "collapse"}}), "alpha: must be in (0, pi/4) (got 0.8)");
    EXPECT_EQ(refusal({rec, alpha, {"kind", "spectrum"}}), "alpha: must be in (0, pi/4) (got 0.8)");
    EXPECT_EQ(refusal({rec, alpha, {"kind", "ida"}, {"p", "2"}}), "alpha: must be in (0, pi/4) (got 0.8)");
    for (const char* kind : {"collapse", "spectrum"})
        EXPECT_EQ(refusal({rec, {"alpha", "0.72"}, {"kind", kind}}), "accepted") << kind;
    for (const char* kind : {"simulate", "ida"})
        EXPECT_EQ(refusal({rec, {"alpha", "0.72"}, {"kind", kind}, {"p", "2"}}), "accepted") << kind;
    const dynamics::PulseInput pulse(PulseTrain({{1.0, 1.0}}), 0.15, 1.0);
    EXPECT_NO_THROW(studies::incremental_dynamic_analysis(pulse, 0.72, 2.0, studies::IdaOptions{}));
    for (double a : {0.8, 0.9}) {
        try {
            studies::rocking_spectrum(pulse, a, studies::SpectrumOptions{});
            ADD_FAILURE() << "spectrum took alpha = " << a;
        } catch (const std::invalid_argument& e) {
            EXPECT_STREQ(e.what(), "spectrum: alpha must be in (0, pi/4)");
        }
        try {
            studies::incremental_dynamic_analysis(pulse, a, 2.0, studies::IdaOptions{});
            ADD_FAILURE() << "ida took alpha = " << a;
        } catch (const std::invalid_argument& e) {
            EXPECT_STREQ(e.what(), "ida: alpha must be in (0, pi/4)");
        }
    }
}
