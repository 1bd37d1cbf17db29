// The module's members of the fragility fits beside the document's (fragility_fits.hpp).
#include "fragility_fits.hpp"

namespace rocking::python {

py::array_t<double> range_array(const studies::Range& r) { return to_array({r.lo, r.hi}); }

void add_fit_members(py::handle fit, double log_likelihood, const studies::BootstrapInterval& interval) {
    if (fit.is_none()) return;
    py::dict d = py::reinterpret_borrow<py::dict>(fit);
    if (!d["bootstrap"].is_none()) {
        py::dict b = d["bootstrap"];
        b["median"] = range_array(interval.median);
        b["beta"] = range_array(interval.beta);
    }
    d["log_likelihood"] = log_likelihood;
}

void add_block_fit_members(py::dict& block, const studies::BlockFragility& f) {
    add_fit_members(block["fit"], f.fit.log_likelihood, f.interval);
    if (!f.three_ways) return;
    py::dict fits = block["fits"];
    add_fit_members(fits["first_overturning"]["fit"], f.fit.log_likelihood, f.interval);
    add_fit_members(fits["first_robust_collapse"]["fit"], f.robust.fit.log_likelihood, f.robust.interval);
    const studies::StripeFit& s = f.stripes;
    add_fit_members(fits["stripes"]["fit"], s.fit.log_likelihood, s.interval);
    std::vector<double> q, share;
    for (const studies::Stripe& st : s.stripes) q.push_back(st.q), share.push_back(st.overturned / st.records);
    py::dict stripes = result();
    stripes["q"] = to_array(q);
    stripes["from"] = to_array(s.shares.from);
    stripes["to"] = to_array(s.shares.to);
    stripes["share"] = to_array(share);
    block["stripes"] = stripes;
}

}  // namespace rocking::python
