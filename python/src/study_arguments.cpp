#include "study_arguments.hpp"

#include <cmath>

#include "json/pieces.hpp"
#include "studies/overturning_set.hpp"

namespace rocking::python {

std::string g7(double v) { return significant(v, 7); }

std::vector<double> values_in(const py::object& given, const std::string& what, double lo, double hi,
                              const std::string& range, std::size_t most) {
    std::vector<double> v;
    const py::module_ np = py::module_::import("numpy");
    const bool one = (PyFloat_Check(given.ptr()) || PyLong_Check(given.ptr()) || PyComplex_Check(given.ptr()) ||
                      py::isinstance(given, np.attr("generic")) ||
                      (py::isinstance<py::array>(given) && py::reinterpret_borrow<py::array>(given).ndim() == 0));
    if (given.is_none() || PyBool_Check(given.ptr()) || py::isinstance(given, np.attr("bool_")) ||
        py::isinstance<py::str>(given) || py::isinstance<py::bytes>(given) || (!one && !py::isinstance<py::iterable>(given)))
        throw py::type_error(what + ": expected a number or a list of numbers, got " +
                             std::string(py::str(py::type::of(given).attr("__name__"))));
    if (one) v = {number(Real{given}, what)};  // a numpy scalar or a 0-d array is one number too
    else v = real_vector(given, what);
    if (v.empty() || v.size() > most) refuse(what + ": from 1 to " + std::to_string(most) + " values");
    for (double x : v)
        if (!(x > lo && x < hi)) refuse(what + ": each must be in " + range + " (got " + g7(x) + ")");
    return v;
}

std::unique_ptr<dynamics::SampledInput> input_of(const records::Record& r) {
    return std::make_unique<dynamics::SampledInput>(r.in_g(dynamics::kGravity), r.dt, r.name);
}

int bootstrap_argument(const std::optional<Whole>& bootstrap_given, const std::optional<Whole>& seed_given,
                       std::uint64_t& seed_out) {
    const std::optional<long long> bootstrap = whole(bootstrap_given, "bootstrap"), seed = whole(seed_given, "seed");
    // Out of int's range, as just out of the callers' (which refuse it in their own words).
    const long long b = bootstrap.value_or(0);
    const int resamples = b < 0 ? -1 : b > 100000 ? 100001 : static_cast<int>(b);
    if (seed && !bootstrap) refuse("seed goes with bootstrap");
    if (resamples > 0 && !seed) refuse("bootstrap needs seed (the interval is reproducible only from a stated seed)");
    if (seed) {
        if (*seed < 1 || *seed > 4294967295LL)
            refuse("seed: the seed must be a whole number from 1 to 4294967295 (got " + std::to_string(*seed) + ")");
        seed_out = static_cast<std::uint64_t>(*seed);
    }
    return resamples;
}

MethodChoice method_argument(const Text& method_given, const std::optional<Real>& width_given,
                             const std::optional<Real>& robust_width_given, const std::string& unit) {
    MethodChoice m;
    const std::string method = string_argument(method_given, "method");
    if (method != "grid" && method != "refine") refuse("method: grid or refine (got '" + method + "')");
    m.refine = method == "refine";
    const std::optional<double> width = number(width_given, "width"), robust_width = number(robust_width_given, "robust_width");
    if (width && !m.refine) refuse("width goes with method='refine'");
    if (robust_width && !m.refine) refuse("robust_width goes with method='refine'");
    if (width) {
        if (!studies::in_width_range(*width))
            refuse(std::string("width: must be in ") + studies::kWidthRange + " (in ln " + unit + ")");
        m.width = *width;
    }
    if (robust_width) {
        if (!studies::in_robust_width_range(*robust_width))
            refuse(std::string("robust_width: must be in ") + studies::kRobustWidthRange + " (in ln " + unit + ")");
        m.robust_width = *robust_width;
    }
    return m;
}

void method_argument(const Text& method_given, const std::optional<Real>& width_given,
                     const std::optional<Real>& robust_width_given, studies::IdaOptions& ida) {
    const MethodChoice m = method_argument(method_given, width_given, robust_width_given, "q");
    if (m.refine) ida.method = studies::IdaOptions::Method::refine;
    ida.width = m.width;
    ida.robust_width = m.robust_width;
}

py::dict nearest_side(const studies::SpectrumFirst& f, double height) { return to_python(json::nearest_json(f, height)); }

void friction_into(const py::object& value, const py::object& restitution, records::CollapseOptions& model) {
    if (value.is_none()) return;
    double mu;
    try {
        mu = number(Real{value}, "friction");
    } catch (const py::type_error&) {
        throw py::type_error("friction: expected a number in (0, 1e6], got " + std::string(py::str(py::type::of(value).attr("__name__"))));
    }
    if (!(mu > 0 && mu <= 1e6)) refuse("friction: the friction coefficient must be in (0, 1e6] (got " + significant(mu, 17) + ")");
    if (!restitution.is_none() && !py::isinstance<py::str>(restitution))
        refuse("restitution: does not apply with friction (the sliding-rocking model's impacts follow from impulse and "
               "momentum)");
    model.friction = mu;
}

dynamics::Imperfection imperfection_argument(const py::object& value, const records::CollapseOptions& model) {
    if (value.is_none()) return {};
    if (!py::isinstance<py::dict>(value))
        throw py::type_error("imperfection: expected a dict of lean, out_of_plumb (rad), fc (MPa), density (kg/m3), got " +
                             std::string(py::str(py::type::of(value).attr("__name__"))));
    dynamics::ImperfectionSpec spec;
    for (const auto& [key, item] : py::cast<py::dict>(value)) {
        const std::string k = py::str(key);
        std::optional<double>* slot = k == "lean" ? &spec.lean : k == "out_of_plumb" ? &spec.out_of_plumb
                                    : k == "fc" ? &spec.fc_mpa : k == "density" ? &spec.density : nullptr;
        if (!slot) refuse("imperfection: unknown key '" + k + "' (lean, out_of_plumb, fc, density)");
        *slot = number(py::cast<Real>(item), "imperfection['" + k + "']");
    }
    dynamics::Imperfection imp;
    try {
        imp = dynamics::imperfection_of(spec, [](const std::string& n) { return "imperfection['" + n + "']"; });
    } catch (const std::invalid_argument& e) {
        refuse(e.what());
    }
    if (imp.any() && model.friction > 0)
        refuse("imperfection: friction does not apply to an imperfect block (the sliding-rocking model's block is a "
               "perfect rectangle)");
    return imp;
}

py::dict imperfection_dict(const dynamics::Imperfection& imp, const dynamics::Block& base, double restitution) {
    return to_python(json::imperfection_json(imp, base, restitution), Dicts::plain);
}

void imperfection_into(const py::object& value, records::CollapseOptions& model) {
    model.imperfection = imperfection_argument(value, model);
}

void restitution_into(const py::object& value, records::CollapseOptions& model) {
    const double e = restitution_argument(value);
    model.housner_restitution = std::isnan(e);
    if (!model.housner_restitution) model.restitution = e;
}

}  // namespace rocking::python
