// The sliding-rocking run's cost (issue 41, item 6; a benchmark, not a
// test): on every record of the shared folder and three blocks, a run of
// dynamics/sliding/ at mu 0.6 and 1e6 against the rocking-only full model
// (dopri5) at the same tolerance, the goal being within 3x.  The
// fastest of the repeats is kept (the machine's other work only adds time).
// Figures to out/bench/sliding.txt and sliding_records.csv.
//
//   bench_sliding [--records DIR] [--out DIR] [--rtol R]
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <functional>
#include <string>
#include <vector>

#include "dynamics/simulate.hpp"
#include "dynamics/sliding/sliding_simulate.hpp"
#include "records/record.hpp"
#include "scenes/records_analysis.hpp"

using namespace rocking;
namespace fs = std::filesystem;

namespace {

// Seconds of the fastest of `repeats` calls.
double fastest(int repeats, const std::function<void()>& run) {
    double best = INFINITY;
    for (int k = 0; k < repeats; ++k) {
        const auto start = std::chrono::steady_clock::now();
        run();
        best = std::min(best, std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
    }
    return best;
}

struct BlockCase {
    const char* name;
    double thickness, height;  // m
};

}  // namespace

int main(int argc, char** argv) {
    std::string records = scenes::records_dir(), out = "out/bench";
    double rtol = 1e-9;
    for (int i = 1; i < argc; ++i) {
        const std::string a = argv[i];
        if (a == "--records" && i + 1 < argc) records = argv[++i];
        else if (a == "--out" && i + 1 < argc) out = argv[++i];
        else if (a == "--rtol" && i + 1 < argc) rtol = std::stod(argv[++i]);
        else {
            std::fprintf(stderr, "usage: bench_sliding [--records DIR] [--out DIR] [--rtol R]\n");
            return 2;
        }
    }
    const std::vector<std::string> files = scenes::record_files(records);
    if (files.empty()) {
        std::fprintf(stderr, "bench_sliding: no records under %s/esm or /peer (the shared records folder, or --records DIR)\n",
                     records.c_str());
        return 1;
    }
    fs::create_directories(out);
    std::FILE* summary = std::fopen((out + "/sliding.txt").c_str(), "w");
    std::FILE* csv = std::fopen((out + "/sliding_records.csv").c_str(), "w");
    if (!summary || !csv) {
        std::fprintf(stderr, "bench_sliding: cannot write in %s\n", out.c_str());
        return 1;
    }
    auto say = [&](const char* fmt, auto... args) {
        std::printf(fmt, args...);
        std::fprintf(summary, fmt, args...);
    };
    say("sliding-rocking (event-driven dopri5) against the rocking-only full model (dopri5), rtol = atol = %g alpha, "
        "one thread, the fastest of 3 repeats; %zu records\n", rtol, files.size());
    std::fprintf(csv, "record,block,mu,rocking_s,sliding_s,ratio,impacts_rocking,impacts_sliding,slid\n");
    const BlockCase blocks[] = {{"0.6x4", 0.6, 4.0}, {"0.3x2", 0.3, 2.0}, {"0.25x1", 0.25, 1.0}};
    double worst = 0, sum_log = 0;
    int n = 0;
    for (const std::string& f : files) {
        const records::Record r = records::read_any(f);
        const dynamics::SampledInput input(r.in_g(dynamics::kGravity), r.dt, r.name);
        for (const BlockCase& b : blocks) {
            const double alpha = std::atan(b.thickness / b.height), R = 0.5 * std::hypot(b.thickness, b.height);
            dynamics::Model model;
            model.equation = dynamics::Equation::full;
            model.block = dynamics::Block::from_half_dimensions(b.thickness / 2, b.height / 2);
            model.restitution = dynamics::housner_restitution(alpha);
            dynamics::SimulationOptions ro;
            ro.solver.kind = dynamics::SolverKind::dopri5;
            ro.solver.rtol = ro.solver.atol_alpha = rtol;
            dynamics::SimulationResult rock;
            const double t_rock = fastest(3, [&] { rock = dynamics::simulate(model, input, ro); });
            for (double mu : {0.6, 1e6}) {
                const dynamics::sliding::FrictionBlock block{alpha, R, mu};
                dynamics::sliding::SlidingOptions so;
                so.rtol = so.atol_alpha = rtol;
                dynamics::sliding::SlidingResult slide;
                const double t_slide = fastest(3, [&] { slide = dynamics::sliding::simulate_sliding(block, input, so); });
                const double ratio = t_slide / t_rock;
                worst = std::max(worst, ratio);
                sum_log += std::log(ratio);
                ++n;
                std::fprintf(csv, "%s,%s,%g,%.6g,%.6g,%.4g,%d,%d,%s\n", fs::path(f).filename().c_str(), b.name, mu, t_rock,
                             t_slide, ratio, rock.impacts, slide.impacts, slide.slid ? "yes" : "no");
            }
        }
    }
    say("%d runs: sliding over rocking-only, geometric mean %.3g, worst %.3g (goal: within 3)\n", n,
        std::exp(sum_log / n), worst);
    say("per run: out/bench/sliding_records.csv (record, block, mu, seconds of each, ratio, impacts, slid)\n");
    std::fclose(summary);
    std::fclose(csv);
    return 0;
}
