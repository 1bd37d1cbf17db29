// reproduce: runs the scenes, writes their CSV and PNG under out/, diffs each
// CSV against expected/ under its tolerances and prints a summary.
//
//   reproduce [--out DIR] [--expected DIR] [--no-plot] [--list] [SCENE...]
//   reproduce --bless SCENE      rewrite expected/SCENE from a fresh run
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <map>
#include <set>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "harness/plot_file.hpp"
#include "harness/compare.hpp"
#include "scene.hpp"

#ifndef ROCKING_SOURCE_DIR
#define ROCKING_SOURCE_DIR "."
#endif

namespace fs = std::filesystem;
using namespace rocking;

namespace {

struct Options {
    std::string out = "out";
    std::string expected = std::string(ROCKING_SOURCE_DIR) + "/expected";
    std::string plots = std::string(ROCKING_SOURCE_DIR) + "/reproduce/plots";
    bool plot = true;
    bool bless = false;
    bool reference = false;
    std::vector<std::string> scenes;
};

struct Outcome {
    std::string scene;
    std::string status;  // match, differs, error
    double seconds = 0.0;
    std::string detail;
};

std::string short_number(double v) {
    char b[32];
    std::snprintf(b, sizeof b, "%.3g", v);
    return b;
}

std::string describe(const harness::Deviation& d) {
    return d.column + " line " + std::to_string(d.line) + ": " + short_number(d.deviation) + " (allowed " +
           short_number(d.allowed) + ")";
}

std::string quote(const std::string& s) { return "'" + s + "'"; }

// A word for sh whatever it holds: single quotes, inner ones closed, escaped and reopened.
std::string shell_quote(const std::string& s) {
    std::string out = "'";
    for (char c : s) out += c == '\'' ? std::string("'\\''") : std::string(1, c);
    return out + "'";
}

// Plots with gnuplot when a script exists; a missing gnuplot is said, not
// fatal, but a plot that fails or is not written whole is the scene's error.
// gnuplot draws into a temporary file (its script's png variable) that
// replaces <scene>.png only once gnuplot has succeeded and the PNG is whole
// (harness/plot_file.hpp): a failed, killed or starved plot left half a PNG.
std::string plot(const Options& o, const std::string& scene, const std::string& dir) {
    const std::string script = o.plots + "/" + scene + ".gp";
    if (!o.plot || !fs::exists(script)) return "";
    if (std::system("command -v gnuplot >/dev/null 2>&1") != 0) return "plot skipped: gnuplot not installed (make deps)";
    harness::PlotFile png(dir + "/" + scene + ".png");
    // gnuplot runs in the scene's folder (where it draws) and names every file relative
    // to it: neither --out's spelling nor the PNG's reaches its quoting (PlotFile::draw_name).
    const std::string cmd = "cd " + shell_quote(png.draw_folder()) + " && gnuplot -e \"dir='.'; png='" +
                            png.draw_name() + "'\" " + shell_quote(fs::absolute(script).string()) + " 2>gnuplot.log";
    if (std::system(cmd.c_str()) != 0) throw std::runtime_error("plot failed: see " + dir + "/gnuplot.log");
    png.commit();
    return "";
}

// Compares every file named in expected/<scene>/TOLERANCES.
bool compare_scene(const Options& o, const std::string& scene, const std::string& dir, Outcome& outcome,
                   bool verbose, const std::vector<std::pair<std::string, std::string>>& skipped = {}) {
    const std::string spec_path = o.expected + "/" + scene + "/TOLERANCES";
    const harness::ToleranceSpec spec = harness::ToleranceSpec::read(spec_path);
    bool all = true;
    double worst_ratio = -1.0;
    long cells = 0;
    // The skipped files, named together under their reason (a scene may skip some of its files and write others).
    std::vector<std::pair<std::string, std::string>> skipped_here;  // reason, files
    for (const std::string& file : spec.files()) {
        const std::string actual_path = dir + "/" + file;
        bool skip = false;
        for (const auto& [name, why] : skipped)
            if (name == file) {
                skip = true;
                auto same = std::find_if(skipped_here.begin(), skipped_here.end(),
                                         [&](const auto& s) { return s.first == why; });
                if (same == skipped_here.end()) skipped_here.emplace_back(why, file);
                else same->second += ", " + file;
            }
        if (skip) continue;
        if (!fs::exists(o.expected + "/" + scene + "/" + file)) {
            all = false;
            outcome.detail = file + ": no expected file yet (make bless SCENE=" + scene + ")";
            continue;
        }
        if (!fs::exists(actual_path)) {
            all = false;
            outcome.detail = file + ": not written by the scene";
            continue;
        }
        const harness::Comparison c = harness::compare(harness::read_csv(o.expected + "/" + scene + "/" + file),
                                                       harness::read_csv(actual_path), spec, file, o.reference);
        if (!c.match()) {
            all = false;
            outcome.detail = file + ": " + (c.problem.empty() ? std::to_string(c.failed) + " of " +
                                                                    std::to_string(c.cells) + " cells out of tolerance, worst " +
                                                                    describe(c.worst)
                                                              : c.problem);
            if (verbose)
                for (const auto& f : c.failures)
                    std::cout << "    " << file << " " << f.column << " line " << f.line << ": expected " << f.expected
                              << ", got " << f.actual << " (deviation " << short_number(f.deviation) << ", allowed "
                              << short_number(f.allowed) << ")\n";
        } else if (all && c.worst.ratio > worst_ratio) {
            worst_ratio = c.worst.ratio;
            outcome.detail = file + " " + describe(c.worst);
        }
        cells += c.cells;
    }
    if (all && cells == 0) outcome.detail = "no cell compared";
    else if (all && worst_ratio == 0.0) outcome.detail = "identical in all " + std::to_string(cells) + " cells";
    else if (all) outcome.detail += ", " + short_number(100.0 * worst_ratio) + "% of tolerance";
    for (const auto& [why, files] : skipped_here) outcome.detail += "; skipped " + files + ": " + why;
    return all;
}

std::string reference_of(const std::string& scene) {
    for (const auto& s : scenes::all_scenes())
        if (s.name == scene) return s.reference;
    return "";
}

std::string self_path() { return fs::read_symlink("/proc/self/exe").string(); }

int bless(const Options& o) {
    if (o.scenes.size() != 1) {
        std::cerr << "reproduce --bless: name exactly one scene\n";
        return 2;
    }
    const std::string scene = o.scenes[0];
    const std::string dir = o.out + "/" + scene;
    const std::string target = o.expected + "/" + scene;
    const std::string spec_path = target + "/TOLERANCES";
    if (!fs::exists(spec_path)) {
        std::cerr << "reproduce --bless: " << spec_path
                  << " is missing: write it first (file, column, abs, rel, reason for each output)\n";
        return 2;
    }
    Outcome outcome{scene, "", 0.0, ""};
    std::cout << "bless " << scene << ": differences against the current expected files\n";
    const bool same = compare_scene(o, scene, dir, outcome, true);
    std::cout << (same ? "  all within tolerance (" + outcome.detail + ")\n" : "  " + outcome.detail + "\n");
    const harness::ToleranceSpec spec = harness::ToleranceSpec::read(spec_path);
    // A 'reference' column holds the reference method's verdicts, which a
    // plain run writes as "not checked": those files come from a --reference
    // run (the same values elsewhere), and the checks below then hold the
    // verdicts to the reference method, the plain run to "not checked".
    std::string source = dir;
    if (spec.has_reference_columns()) {
        if (reference_of(scene).empty()) {
            std::cerr << "reproduce --bless: " << spec_path << " has 'reference' columns but " << scene
                      << " has no reference method\n";
            return 2;
        }
        source = o.out + "/" + scene + "-reference";
        const std::string none = o.out + "/.bless-no-expected";
        fs::create_directories(none);
        const std::string cmd = quote(self_path()) + " --reference --no-plot --out " + quote(o.out) + " --expected " +
                                quote(none) + " " + scene + " >/dev/null";
        std::cout << "the reference method's verdicts: " << cmd << "\n";
        (void)std::system(cmd.c_str());  // differs from the empty expected folder by design
        fs::remove_all(none);
        for (const std::string& file : spec.files())
            if (!fs::exists(source + "/" + file)) {
                std::cerr << "reproduce --bless: the reference run wrote no " << source + "/" + file << "\n";
                return 1;
            }
    }
    const std::string backup = target + ".before-bless";
    fs::remove_all(backup);
    fs::copy(target, backup, fs::copy_options::recursive);
    for (const std::string& file : spec.files())
        fs::copy_file(source + "/" + file, target + "/" + file, fs::copy_options::overwrite_existing);
    // The new values must pass the scene's independent checks: its second
    // implementation (independent.py) and its second method at a much
    // tighter tolerance (--reference), each one the scene has.
    auto refuse = [&](const std::string& why) {
        fs::remove_all(target);
        fs::rename(backup, target);
        std::cerr << "bless refused: " << why << "; expected/" << scene << " is unchanged\n";
        return 1;
    };
    const std::string check = target + "/independent.py";
    const bool has_script = fs::exists(check), has_reference = !reference_of(scene).empty();
    if (has_script) {
        const std::string cmd = "/usr/bin/python3 " + quote(check) + " " + quote(target);
        std::cout << "independent check: " << cmd << "\n";
        if (std::system(cmd.c_str()) != 0) return refuse("the new values fail the independent check");
    }
    if (has_reference) {
        const std::string cmd = quote(self_path()) + " --reference --no-plot --out " + quote(o.out) + " --expected " +
                                quote(o.expected) + " " + scene;
        std::cout << "independent check: " << cmd << "\n";
        if (std::system(cmd.c_str()) != 0) return refuse("the reference method disagrees with the new values");
    }
    if (!has_script && !has_reference)
        std::cout << "no independent check for " << scene
                  << ": record in PROVENANCE.md how the new values were checked\n";
    fs::remove_all(backup);
    std::cout << "blessed expected/" << scene << "; review with: git diff -- expected/" << scene << "\n";
    return 0;
}

int run(int argc, char** argv) {
    Options o;
    for (int i = 1; i < argc; ++i) {
        const std::string a = argv[i];
        auto value = [&]() -> std::string {
            if (i + 1 >= argc) {
                std::cerr << "reproduce: " << a << " needs a value\n";
                std::exit(2);
            }
            return argv[++i];
        };
        if (a == "--out") o.out = value();
        else if (a == "--expected") o.expected = value();
        else if (a == "--plots") o.plots = value();
        else if (a == "--no-plot") o.plot = false;
        else if (a == "--bless") o.bless = true;
        else if (a == "--reference") o.reference = true;
        else if (a == "--list") {
            for (const auto& s : scenes::all_scenes()) std::cout << s.name << "\t" << s.title << "\n";
            return 0;
        } else if (a == "--help" || a == "-h") {
            std::cout << "usage: reproduce [--out DIR] [--expected DIR] [--no-plot] [--list] [SCENE...]\n"
                         "       reproduce --reference SCENE...   recompute with each scene's reference method\n"
                         "       reproduce --bless SCENE\n";
            return 0;
        } else if (!a.empty() && a[0] == '-') {
            std::cerr << "reproduce: unknown option " << a << " (see --help)\n";
            return 2;
        } else o.scenes.push_back(a);
    }
    std::set<std::string> known;
    for (const auto& s : scenes::all_scenes()) known.insert(s.name);
    for (const auto& s : o.scenes)
        if (!known.count(s)) {
            std::cerr << "reproduce: unknown scene '" << s << "' (see --list)\n";
            return 2;
        }

    // --reference: the scenes that have a reference method (all of them when
    // none is named); naming one without is a bad argument, not a difference.
    if (o.reference) {
        std::string with;
        for (const auto& s : scenes::all_scenes())
            if (!s.reference.empty()) with += " " + s.name;
        for (const auto& name : o.scenes)
            if (reference_of(name).empty()) {
                std::cerr << "reproduce: scene '" << name << "' has no reference method (expected/" << name
                          << "/independent.py checks it); scenes with one:" << with << "\n";
                return 2;
            }
        if (o.scenes.empty())
            for (const auto& s : scenes::all_scenes())
                if (!s.reference.empty()) o.scenes.push_back(s.name);
    }

    std::vector<Outcome> outcomes;
    for (const auto& scene : scenes::all_scenes()) {
        if (!o.scenes.empty() && std::find(o.scenes.begin(), o.scenes.end(), scene.name) == o.scenes.end()) continue;
        Outcome outcome{scene.name, "match", 0.0, ""};
        const std::string dir = o.out + "/" + scene.name + (o.reference ? "-reference" : "");
        std::cout << "[" << scene.name << "] " << scene.title << "\n"
                  << "    model:  " << scene.model << "\n"
                  << "    solver: " << (o.reference ? scene.reference + " (reference)" : scene.solver) << "\n"
                  << std::flush;
        const auto start = std::chrono::steady_clock::now();
        try {
            fs::create_directories(dir);
            scenes::SceneContext ctx(dir, o.reference);
            scene.run(ctx);
            outcome.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
            const std::string plot_note = plot(o, scene.name, dir);
            if (!plot_note.empty()) std::cout << "    " << plot_note << "\n";
            for (const auto& [file, why] : ctx.skipped()) std::cout << "    skipped " << file << ": " << why << "\n";
            if (!o.bless) {
                if (!compare_scene(o, scene.name, dir, outcome, true, ctx.skipped())) outcome.status = "differs";
            }
        } catch (const std::exception& e) {
            outcome.status = "error";
            outcome.detail = e.what();
        }
        std::cout << "    " << outcome.status << " in " << short_number(outcome.seconds) << " s; data and plots in "
                  << dir << "/\n";
        outcomes.push_back(outcome);
    }
    if (o.bless) return bless(o);

    std::cout << "\nsummary (largest deviation against its tolerance; expected files in " << o.expected << ")\n";
    std::printf("%-8s %-8s %8s  %s\n", "scene", "status", "time", "largest deviation");
    bool ok = true;
    for (const auto& r : outcomes) {
        std::printf("%-8s %-8s %7.2fs  %s\n", r.scene.c_str(), r.status.c_str(), r.seconds, r.detail.c_str());
        ok = ok && r.status == "match";
    }
    std::cout << (ok ? "all scenes match\n" : "some scenes differ: see above\n");
    // The summary, for the report.
    if (o.scenes.empty() && !o.reference) {
        harness::Table summary({"scene", "status", "seconds", "largest_deviation"});
        summary.note("expected", o.expected);
        for (const auto& r : outcomes) summary.row().add(r.scene).add(r.status).add(r.seconds).add(r.detail);
        try {
            summary.write(o.out + "/summary.csv");
        } catch (const std::exception& e) {
            // The scenes matched, but the report would read a summary that is not there.
            std::cerr << "reproduce: " << e.what() << "\n";
            ok = false;
        }
    }
    return ok ? 0 : 1;
}

}  // namespace

// A summary that never reached a full disk (reproduce > FILE) exited 0.
int main(int argc, char** argv) { return harness::finish_standard_output("reproduce", run(argc, argv)); }
