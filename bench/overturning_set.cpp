// The refine method's cost (a benchmark, not a test; issue 39, docs/overturning_set.md
// section 4): one IDA of Norcia 2016-10-30 HGE (alpha 0.10, p 2.5 rad/s) over
// q in [1, 20], and one spectrum of the same record (alpha 0.10, p in [0.3,
// 30] rad/s, 200 points), each at several widths w against the grid: runs,
// seconds, islands, the first overturning and the first robust collapse; and
// the spectrum stopped at its first overturning (first_only, Table 1's p).
// Writes out/bench/overturning_set.txt.
//
//   bench_overturning_set [--records DIR] [--out DIR] [--widths W1,W2,...]
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <sstream>
#include <string>
#include <vector>

#include "records/record.hpp"
#include "scenes/records_analysis.hpp"
#include "studies/ida.hpp"
#include "studies/spectrum.hpp"

using namespace rocking;
namespace fs = std::filesystem;

int main(int argc, char** argv) {
    std::string records = scenes::records_dir(), out = "out/bench";
    std::vector<double> widths = {1e-3, 1e-4, 1e-5};
    for (int i = 1; i < argc; ++i) {
        const std::string a = argv[i];
        if (a == "--records" && i + 1 < argc) records = argv[++i];
        else if (a == "--out" && i + 1 < argc) out = argv[++i];
        else if (a == "--widths" && i + 1 < argc) {
            widths.clear();
            std::stringstream list(argv[++i]);
            for (std::string w; std::getline(list, w, ',');) widths.push_back(std::stod(w));
        } else {
            std::fprintf(stderr, "usage: bench_overturning_set [--records DIR] [--out DIR] [--widths W1,W2,...]\n");
            return 2;
        }
    }
    const fs::path file = fs::path(records) / "esm" / "IT.NRC..HGE.D.20161030.064018.C.ACC.ASC";
    if (!fs::exists(file)) {
        std::fprintf(stderr, "bench_overturning_set: %s absent\n", file.string().c_str());
        return 1;
    }
    const records::Record r = records::read_any(file.string());
    const dynamics::SampledInput input(r.in_g(9.81), r.dt, r.name);
    fs::create_directories(out);
    std::FILE* summary = std::fopen((out + "/overturning_set.txt").c_str(), "w");
    if (!summary) {
        std::fprintf(stderr, "bench_overturning_set: cannot write %s/overturning_set.txt\n", out.c_str());
        return 1;
    }
    auto say = [&](const char* fmt, auto... args) {
        std::printf(fmt, args...);
        std::fprintf(summary, fmt, args...);
        std::fflush(stdout);
    };
    say("IDA of %s, alpha 0.10, p 2.5 rad/s, q in [1, 20]; one thread; the first overturning's bracket checked "
        "(probe and rk8pd)\n",
        r.name.c_str());
    say("%-8s %10s %10s %9s %8s %8s %14s %14s %10s\n", "method", "w", "runs", "samples", "s", "islands",
        "first_over", "first_robust", "at_width");
    auto run = [&](studies::IdaOptions o, const char* name, double w) {
        const auto start = std::chrono::steady_clock::now();
        const studies::Ida ida = studies::incremental_dynamic_analysis(input, 0.10, 2.5, o);
        const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        say("%-8s %10.0e %10ld %9ld %8.2f %8zu %14.9g %14.9g %10ld\n", name, w, ida.simulations, ida.samples, s,
            ida.intervals.size(), ida.first_overturning.q, ida.first_robust_collapse.q, ida.at_width);
    };
    run(studies::IdaOptions{}, "grid", 0);
    for (double w : widths) {
        studies::IdaOptions o;
        o.method = studies::IdaOptions::Method::refine;
        o.width = w;
        run(o, "refine", w);
    }
    say("\nspectrum of %s, alpha 0.10, p in [0.3, 30] rad/s, 200 points; one thread; every boundary checked "
        "(probe and rk8pd)\n",
        r.name.c_str());
    say("%-10s %10s %10s %9s %8s %8s %14s %14s %10s\n", "method", "w", "runs", "samples", "s", "islands",
        "first_over", "first_robust", "at_width");
    auto spectrum = [&](studies::SpectrumOptions o, const char* name, double w) {
        const auto start = std::chrono::steady_clock::now();
        const studies::Spectrum sp = studies::rocking_spectrum(input, 0.10, o);
        const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        say("%-10s %10.0e %10ld %9ld %8.2f %8zu %14.9g %14.9g %10ld\n", name, w, sp.simulations, sp.samples, s,
            sp.intervals.size(), sp.first_overturning.p, sp.first_robust_collapse.p, sp.at_width);
    };
    spectrum(studies::SpectrumOptions{}, "grid", 0);
    for (const bool first_only : {false, true})
        for (double w : widths) {
            studies::SpectrumOptions o;
            o.method = studies::SpectrumOptions::Method::refine;
            o.width = w;
            o.first_only = first_only;
            spectrum(o, first_only ? "first-only" : "refine", w);
        }
    std::fclose(summary);
    std::printf("wrote %s/overturning_set.txt\n", out.c_str());
    return 0;
}
