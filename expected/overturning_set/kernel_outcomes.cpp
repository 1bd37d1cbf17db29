// The library's outcome at each q (IDA) or p (spectrum) of a list, for the
// comparison of PROVENANCE.md: the record kernel (exact solver, Table 1's
// model) or, with --rk8pd, GSL rk8pd at rtol = atol = 1e-13 alpha, each run
// as studies::incremental_dynamic_analysis and studies::rocking_spectrum take
// it (records::collapses_at; the record scaled by q alpha / peak).  Not built
// by CMake; compiled by hand against build/ (PROVENANCE.md says how).
//   kernel_outcomes RECORD ida ALPHA P [--rk8pd] < xs > outcomes
//   kernel_outcomes RECORD spectrum ALPHA [--rk8pd] [--factor F] < xs > outcomes
// --factor: the record times F (the probe of a spectrum's boundary; an IDA's
// probe is q times it).
#include <cstdio>
#include <cstring>
#include <iostream>
#include <string>

#include "dynamics/ground_input.hpp"
#include "records/collapse.hpp"
#include "records/record.hpp"
#include "studies/scaled_input.hpp"
#include "studies/spectrum.hpp"

using namespace rocking;

int main(int argc, char** argv) {
    if (argc < 4) return 2;
    const records::Record r = records::read_esm(argv[1]);
    const dynamics::SampledInput input(r.in_g(9.81), r.dt, r.name);
    const bool ida = std::string(argv[2]) == "ida";
    const double alpha = std::stod(argv[3]);
    const double p_ida = ida ? std::stod(argv[4]) : 0;
    records::CollapseOptions o;  // Table 1's model: linearised, Housner, overturning, exact
    double factor = 1.0;
    for (int k = 4; k < argc; ++k) {
        if (!std::strcmp(argv[k], "--rk8pd")) o.solver = studies::SpectrumOptions::rk8pd_check();
        if (!std::strcmp(argv[k], "--factor") && k + 1 < argc) factor = std::stod(argv[k + 1]);
    }
    const auto at_factor = studies::scaled(input, factor);
    double x;
    while (std::cin >> x) {
        const bool over = ida ? records::collapses_at(*studies::scaled(input, x * alpha / input.peak()), alpha, p_ida, o)
                              : records::collapses_at(factor == 1.0 ? static_cast<const dynamics::GroundInput&>(input) : *at_factor, alpha, x, o);
        std::printf("%d\n", over ? 1 : 0);
    }
    return 0;
}
