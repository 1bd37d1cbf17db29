// What the module's fragility results hold beside the document's fits
// (json/fragility_json.hpp): ln L at each fit, the bootstrap's ranges and the
// stripes as NumPy arrays.
#pragma once

#include "common.hpp"
#include "studies/ida.hpp"

namespace rocking::python {

// [lo, hi] as an array of two.
py::array_t<double> range_array(const studies::Range& r);

// Into a fit converted from the document (a Result, or None for no fit): its
// bootstrap's "median" and "beta" as arrays of two, and "log_likelihood", ln
// L at the fit, after its members.
void add_fit_members(py::handle fit, double log_likelihood, const studies::BootstrapInterval& interval);

// Into a block converted from the document: the fits' members above, and with
// the three capacities "stripes" as arrays q, from, to, share.
void add_block_fit_members(py::dict& block, const studies::BlockFragility& f);

}  // namespace rocking::python
