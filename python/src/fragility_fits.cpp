// The fragility fits of a block as dicts, as rocking fragility --json writes
// them: the block's fit and, with the refine method, the three capacities'
// (issue 39, item 3).
#include "fragility_fits.hpp"

namespace rocking::python {

py::array_t<double> range_array(const studies::Range& r) { return to_array({r.lo, r.hi}); }

py::object bootstrap_dict(bool bootstrapped, const studies::BootstrapInterval& interval) {
    if (!bootstrapped) return py::none();
    py::dict b = result();
    b["resamples"] = interval.resamples;
    b["seed"] = interval.seed;
    b["level"] = interval.level;
    b["median"] = range_array(interval.median);
    b["beta"] = range_array(interval.beta);
    return std::move(b);
}

py::object lognormal(bool fitted, const studies::LognormalFragility& fit, bool bootstrapped,
                     const studies::BootstrapInterval& interval) {
    if (!fitted) return py::none();
    py::dict d = result();
    d["median"] = fit.median;
    d["beta"] = fit.beta;
    d["collapsed"] = fit.collapsed;
    d["censored"] = fit.censored;
    d["bootstrap"] = bootstrap_dict(bootstrapped, interval);
    d["log_likelihood"] = fit.log_likelihood;
    return std::move(d);
}

py::object block_fit(const studies::BlockFragility& f) {
    return lognormal(f.fitted, f.fit, f.bootstrapped, f.interval);
}

py::dict fit_entry(const py::object& fit, bool fitted, const std::string& no_fit) {
    py::dict d = result();
    d["fit"] = fit;
    d["no_fit"] = fitted ? py::object(py::none()) : py::object(text(no_fit));
    return d;
}

void add_three_ways(py::dict& b, const studies::BlockFragility& f) {
    py::dict fits = result();
    fits["first_overturning"] = fit_entry(block_fit(f), f.fitted, f.no_fit);
    const studies::CapacityFit& r = f.robust;
    fits["first_robust_collapse"] =
        fit_entry(lognormal(r.fitted, r.fit, r.bootstrapped, r.interval), r.fitted, r.no_fit);
    const studies::StripeFit& s = f.stripes;
    py::object stripe_fit = py::none();
    if (s.fitted) {
        py::dict d = result();
        d["median"] = s.fit.median;
        d["beta"] = s.fit.beta;
        d["stripes"] = s.stripes.size();
        d["records"] = s.shares.share.size();
        d["bootstrap"] = bootstrap_dict(s.bootstrapped, s.interval);
        d["log_likelihood"] = s.fit.log_likelihood;
        stripe_fit = std::move(d);
    }
    fits["stripes"] = fit_entry(stripe_fit, s.fitted, s.no_fit);
    b["fits"] = fits;
    std::vector<double> q, share;
    for (const studies::Stripe& st : s.stripes) q.push_back(st.q), share.push_back(st.overturned / st.records);
    py::dict stripes = result();
    stripes["q"] = to_array(q);
    stripes["from"] = to_array(s.shares.from);
    stripes["to"] = to_array(s.shares.to);
    stripes["share"] = to_array(share);
    b["stripes"] = stripes;
}

}  // namespace rocking::python
