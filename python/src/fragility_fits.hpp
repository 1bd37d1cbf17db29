// The fragility fits of a block as dicts, as rocking fragility --json writes
// them (src/cli/fragility.cpp): each fit with its bootstrap and ln L, or None.
#pragma once

#include <string>

#include "common.hpp"
#include "studies/ida.hpp"

namespace rocking::python {

// [lo, hi] as an array of two.
py::array_t<double> range_array(const studies::Range& r);

// The bootstrap's {resamples, seed, level, median, beta}, or None.
py::object bootstrap_dict(bool bootstrapped, const studies::BootstrapInterval& interval);

// A censored lognormal fit {median, beta, collapsed, censored, bootstrap, log_likelihood}, or None.
py::object lognormal(bool fitted, const studies::LognormalFragility& fit, bool bootstrapped,
                     const studies::BootstrapInterval& interval);

// The block's fit (on the first collapse, the first overturning with refine).
py::object block_fit(const studies::BlockFragility& f);

// {fit, no_fit}: the fit, or None and why.
py::dict fit_entry(const py::object& fit, bool fitted, const std::string& no_fit);

// The refine method's three fits, each named by its capacity, and the stripes
// (arrays q, from, to, share), as --json's "fits" and "stripes".
void add_three_ways(py::dict& b, const studies::BlockFragility& f);

}  // namespace rocking::python
