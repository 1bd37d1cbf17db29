// A fragility study's speed (a benchmark, not a test), issue 28's target:
// 20 records x 25 blocks, a full IDA each (100 q and the offset grid, every
// boundary bisected to 1e-6, the first collapse's bracket probed and checked
// by rk8pd), the lognormal fit and a 1000-resample bootstrap per block, in
// under 10 s on 2 cores.  Times the study on 1 and 2 threads (and the grid's
// size on one), simulations per second per core, and writes the figures to
// out/bench/fragility.txt.
//
//   bench_fragility [--records DIR] [--out DIR] [--repeats K]
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "batch/pool.hpp"
#include "records/record.hpp"
#include "scenes/records_analysis.hpp"
#include "studies/ida.hpp"

using namespace rocking;
namespace fs = std::filesystem;

namespace {

struct Run {
    double seconds = INFINITY;  // the fastest repeat: the machine's other work only adds time
    long simulations = 0, checks = 0;
};

Run time_study(const std::vector<const dynamics::GroundInput*>& inputs, const std::vector<studies::BlockShape>& blocks,
               const studies::FragilityStudyOptions& o, int repeats) {
    Run run;
    for (int k = 0; k < repeats; ++k) {
        Run one;
        const auto start = std::chrono::steady_clock::now();
        const std::vector<studies::BlockFragility> study = studies::fragility_study(inputs, blocks, o);
        one.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        for (const auto& f : study)
            for (const auto& ida : f.idas) one.simulations += ida.simulations, one.checks += ida.check_simulations;
        if (one.seconds < run.seconds) run = one;
    }
    return run;
}

}  // namespace

int main(int argc, char** argv) {
    std::string records = scenes::records_dir(), out = "out/bench";
    int repeats = 3;
    for (int i = 1; i < argc; ++i) {
        const std::string a = argv[i];
        if (a == "--records" && i + 1 < argc) records = argv[++i];
        else if (a == "--out" && i + 1 < argc) out = argv[++i];
        else if (a == "--repeats" && i + 1 < argc) repeats = std::max(1, std::atoi(argv[++i]));
        else {
            std::fprintf(stderr, "usage: bench_fragility [--records DIR] [--out DIR] [--repeats K]\n");
            return 2;
        }
    }
    // The first 20 records of esm/ then esm-extra/, by name.
    std::vector<std::string> files;
    for (const char* sub : {"esm", "esm-extra"}) {
        const fs::path dir = fs::path(records) / sub;
        if (!fs::is_directory(dir)) continue;
        std::vector<std::string> here;
        for (const auto& e : fs::directory_iterator(dir))
            if (e.is_regular_file()) here.push_back(e.path().string());
        std::sort(here.begin(), here.end());
        files.insert(files.end(), here.begin(), here.end());
    }
    if (files.size() < 20) {
        std::fprintf(stderr, "bench_fragility: %s holds %zu records in esm/ and esm-extra/, 20 needed\n",
                     records.c_str(), files.size());
        return 1;
    }
    files.resize(20);
    std::vector<std::unique_ptr<dynamics::SampledInput>> owned;
    std::vector<const dynamics::GroundInput*> inputs;
    long samples = 0;
    for (const std::string& f : files) {
        const records::Record r = records::read_any(f);
        owned.push_back(std::make_unique<dynamics::SampledInput>(r.in_g(9.81), r.dt, r.name));
        inputs.push_back(owned.back().get());
        samples += static_cast<long>(r.accel.size());
    }
    std::vector<studies::BlockShape> blocks;
    for (double alpha : {0.05, 0.1, 0.15, 0.2, 0.25})
        for (double p : {1.0, 2.0, 3.0, 5.0, 8.0}) blocks.push_back({alpha, p, ""});

    fs::create_directories(out);
    std::FILE* summary = std::fopen((out + "/fragility.txt").c_str(), "w");
    if (!summary) {
        std::fprintf(stderr, "bench_fragility: cannot write %s/fragility.txt\n", out.c_str());
        return 1;
    }
    auto say = [&](const char* fmt, auto... args) {
        std::printf(fmt, args...);
        std::fprintf(summary, fmt, args...);
    };
    studies::FragilityStudyOptions o;  // the library's defaults: a full IDA, first collapse checked
    o.resamples = 1000;
    o.seed = 1;
    say("records: the first 20 of esm/ and esm-extra/ (%ld samples in all); blocks: alpha 0.05-0.25 x p 1, 2, 3, 5, "
        "8 rad/s (25); IDA: %s; %s; fit and %d-resample bootstrap per block; fastest of %d; usable cores: %d\n",
        samples, o.ida.describe_grid().c_str(), o.ida.describe_checks().c_str(), o.resamples, repeats,
        batch::default_threads());
    double one_thread = 0;
    for (int threads : {1, 2}) {
        o.threads = threads;
        const Run r = time_study(inputs, blocks, o, repeats);
        if (threads == 1) one_thread = r.seconds;
        say("study on %d thread%s: %.2f s (target: under 10 s on 2 cores), %ld simulations + %ld by rk8pd, %.0f "
            "simulations per second per core; speed-up %.2f\n",
            threads, threads > 1 ? "s" : "", r.seconds, r.simulations, r.checks,
            (r.simulations + r.checks) / r.seconds / threads, one_thread / r.seconds);
    }
    o.threads = 1;
    o.resamples = 0;
    const Run no_boot = time_study(inputs, blocks, o, repeats);
    say("  without the bootstrap, 1 thread: %.2f s\n", no_boot.seconds);
    o.ida.checks = studies::IdaOptions::Checks::none;
    const Run bare = time_study(inputs, blocks, o, repeats);
    say("  without the bootstrap and the bracket checks, 1 thread: %.2f s, %ld simulations (%.0f per second)\n",
        bare.seconds, bare.simulations, bare.simulations / bare.seconds);
    for (int points : {50, 200}) {
        o.ida.points = points;
        const Run g = time_study(inputs, blocks, o, 1);
        say("  the same with %d q per grid: %.2f s, %ld simulations\n", points, g.seconds, g.simulations);
    }
    std::fclose(summary);
    std::printf("wrote %s/fragility.txt\n", out.c_str());
    return 0;
}
