// The closed forms and any train's q (rocking q), vectorised over x, and the
// motion up to t_fin (rocking response): src/qfactor, src/pulse.
#include <cmath>
#include <functional>
#include <stdexcept>

#include "common.hpp"
#include "qfactor/closed_forms.hpp"
#include "json/qfactor_json.hpp"
#include "qfactor/superposition.hpp"

namespace rocking::python {

namespace {

// f over every element of x (any shape, a real dtype), as a float for a
// scalar and an array of x's shape otherwise.  The library's refusal of an
// element comes back as a ValueError naming it (x[3] of a 1-D array).
py::object over_x(py::handle x, const std::function<double(double)>& f) {
    const py::array_t<double> in = real_array(x, "x");
    py::array_t<double> out(std::vector<py::ssize_t>(in.shape(), in.shape() + in.ndim()));
    const double* from = in.data();
    double* to = out.mutable_data();
    const py::ssize_t n = in.size();
    std::string error;
    {
        py::gil_scoped_release unlocked;
        for (py::ssize_t k = 0; k < n && error.empty(); ++k) {
            // As the command line's --x: q(inf) is the limit 1, but an infinite x is no input.
            if (!std::isfinite(from[k])) {
                error = std::string(in.ndim() == 0 ? "x" : "x[" + std::to_string(k) + "]") + ": " +
                        (std::isnan(from[k]) ? "nan" : from[k] > 0 ? "inf" : "-inf") + " is not a finite number";
                break;
            }
            try {
                to[k] = f(from[k]);
            } catch (const std::exception& e) {  // domain_error, invalid_argument: the value is refused
                error = (in.ndim() == 0 ? std::string() : "x[" + std::to_string(k) + "]: ") + e.what();
            }
        }
    }
    if (!error.empty()) throw py::value_error(error);
    if (in.ndim() == 0) return py::float_(to[0]);
    return std::move(out);
}

double x_argument(double x) {
    if (!(x > 0)) refuse("x: must be > 0 (got " + significant(x, 17) + ")");
    if (x < kSmallestX)
        refuse("x: must be >= 1e-150, below which q ~ 2/(M1 x^2) overflows (got " + significant(x, 17) + ")");
    return x;
}

py::object q_of(py::handle x, const std::optional<Whole>& which_case, const std::optional<Whole>& pulses, const py::object& train,
                const py::kwargs& extra) {
    no_other_keywords(extra, "q", "q");
    std::string equation;
    const PulseTrain t = train_argument(which_case, pulses, train, equation);
    return over_x(x, [&](double v) { return q_factor(t, v).q; });
}

py::dict q_info(const Real& x_given, const std::optional<Whole>& which_case, const std::optional<Whole>& pulses,
                const py::object& train, const py::kwargs& extra) {
    no_other_keywords(extra, "q_info", "q_info");
    std::string equation;
    const PulseTrain t = train_argument(which_case, pulses, train, equation);
    const double x = x_argument(number(x_given, "x"));
    const QFactor q = q_factor(t, x);
    const Excursion e = collapse_excursion(t, x);
    py::dict r = to_python(json::q_json(t, x, q, equation, e));
    r["t_fin_over_to"] = t.t_fin();  // the module's own member: not in the command's --json
    return r;
}

py::dict response_of(const Real& x_given, const std::optional<Whole>& which_case, const std::optional<Whole>& pulses,
                     const py::object& train, const std::optional<Real>& q_argument, const Whole& steps_given,
                     const py::kwargs& extra) {
    no_other_keywords(extra, "response", "response");
    std::string equation;
    const PulseTrain t = train_argument(which_case, pulses, train, equation);
    const double x = x_argument(number(x_given, "x"));
    const std::optional<double> q_given = number(q_argument, "q");
    const long long steps_long = whole(steps_given, "steps");
    const bool at_collapse = !q_given;
    const double q = at_collapse ? q_factor(t, x).q : *q_given;
    if (!(q > 0)) refuse("q: must be > 0");
    if (steps_long < 1 || steps_long > 1000000) refuse("steps: must be between 1 and 1000000");
    const int steps = static_cast<int>(steps_long);
    // As rocking response: the rows stop where theta leaves the double range.
    std::vector<ResponseState> rows;
    Excursion e;
    {
        py::gil_scoped_release unlocked;
        e = at_collapse ? collapse_excursion(t, x) : excursion(t, x, q);
        for (int k = 0; k <= steps; ++k) {
            const double tau = t.t_fin() * k / steps;
            const ResponseState s = at_collapse ? collapse_response(t, x, tau) : response(t, x, q, tau);
            if (!std::isfinite(s.phi) || !std::isfinite(s.dphi)) break;
            rows.push_back(s);
        }
    }
    const int last = static_cast<int>(rows.size()) - 1;
    py::array_t<double> samples({static_cast<py::ssize_t>(rows.size()), py::ssize_t{3}});
    auto cell = samples.mutable_unchecked<2>();
    for (int k = 0; k <= last; ++k) {
        cell(k, 0) = t.t_fin() * k / steps;
        cell(k, 1) = rows[k].phi;
        cell(k, 2) = rows[k].dphi;
    }
    py::dict r = to_python(json::response_json(t, x, q, at_collapse, e, rows, steps));
    r["samples"] = samples;  // an (n, 3) array where the command's --json has a list of rows
    // The columns of rocking response's text output, t/to, theta/alpha, theta'/(alpha p).
    py::object columns = samples.attr("T");
    r["t_over_to"] = columns[py::int_(0)];
    r["theta_over_alpha"] = columns[py::int_(1)];
    r["omega_over_alpha_p"] = columns[py::int_(2)];
    return r;
}

}  // namespace

void init_qfactor(py::module_& m) {
    using namespace py::literals;
    auto closed = [&](const char* name, double (*f)(double), const char* doc) {
        m.def(name, [f](py::handle x) { return over_x(x, f); }, "x"_a, doc);
    };
    closed("q1", q1, "Eq. 12, case 1 (+1, -1): q over x = p*to (a float or an array of any shape).");
    closed("q2", q2, "Eq. 15, case 2 (+1, -1/2).");
    closed("q3", q3, "Eq. 19, case 3 (+1/2, -1).");
    closed("q4", q4, "Eq. 22, case 4 (+1, -1/2 for 2 to).");
    closed("q5", q5, "Eq. 24, case 5 (+1/2 for 2 to, -1).");
    closed("q2_n6", q2_n6, "Eq. 27: case 2 repeated to 6 pulses, collapse at the onset of the 7th (the design value).");
    closed("q4_n6", q4_n6, "Eq. 28 (corrected): case 4 repeated to 6 pulses.");
    m.def(
        "q_case", [](const Whole& which_case, py::handle x) {
            const int which = case_argument(which_case.value);
            return over_x(x, [which](double v) { return q_case(which, v); });
        },
        "case"_a, "x"_a, "The closed form q_i (eqs. 12, 15, 19, 22, 24) of case i = 1..5 over x.");
    m.def("q", &q_of, "x"_a, py::kw_only(), "case"_a = py::none(), "pulses"_a = py::none(), "train"_a = py::none(),
          R"(q = PGA/(alpha g) of a case or a train at x = p*to, as `rocking q` computes it (superposition (S2)).

x: a float or an array of any shape (a float or an array of that shape comes back).
case: 1..5 (Figure 3), with pulses (default 2; case=2, pulses=6 is eq. 27);
or train: "A:d,A:d,..." or (amplitude, duration) pairs, in PGA and to.)");
    m.def("q_info", &q_info, "x"_a, py::kw_only(), "case"_a = py::none(), "pulses"_a = py::none(),
          "train"_a = py::none(),
          "`rocking q --json` at one x: q, its condition number, the equation, the model, and where the closed form holds.");
    m.def("response", &response_of, "x"_a, py::kw_only(), "case"_a = py::none(), "pulses"_a = py::none(),
          "train"_a = py::none(), "q"_a = py::none(), "steps"_a = 20,
          R"(`rocking response --json`: theta/alpha and theta'/(alpha p) over [0, t_fin] in steps + 1 rows.

At the collapse q (evaluated exactly) unless q is given.  samples is an (n, 3) array
(t/to, theta/alpha, theta'/(alpha p)), also as t_over_to, theta_over_alpha, omega_over_alpha_p.)");
}

}  // namespace rocking::python
