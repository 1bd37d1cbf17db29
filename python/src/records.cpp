// Records (rocking record info, record synth, record floor), the collapse search
// (rocking collapse) and the paper's check (rocking assess): src/records.
#include <cmath>
#include <cstdio>
#include <map>

#include "common.hpp"
#include "studies/distinct_inputs.hpp"
#include "study_arguments.hpp"
#include "studies/assessment.hpp"
#include "json/assess_json.hpp"
#include "json/collapse_json.hpp"
#include "json/record_json.hpp"
#include "dynamics/ground_input.hpp"
#include "qfactor/closed_forms.hpp"
#include "qfactor/superposition.hpp"
#include "records/collapse.hpp"
#include "records/floor_motion.hpp"
#include "records/synthetic.hpp"
#include "studies/search_alpha.hpp"

namespace rocking::python {

namespace {

using records::Record;

// A unit's factor to m/s^2, as the plain-text reader applies it (records/record.cpp).
double unit_scale(const std::string& unit) {
    if (unit == "g") return 9.81;
    if (unit == "m/s2" || unit == "m/s^2") return 1.0;
    if (unit == "cm/s2" || unit == "cm/s^2") return 0.01;
    refuse("unit: '" + unit + "' is not a unit it knows (g, m/s2, cm/s2)");
}

// Record(accel, dt, unit=, name=): the samples times the unit's factor, as
// the plain-text reader multiplies a file's values, so that the same numbers
// give the same record bit for bit.
std::shared_ptr<Record> record_from_array(py::handle accel, const Real& dt_given, const Text& unit_given,
                                          const Text& name_given, const py::kwargs& extra) {
    no_other_keywords(extra, "Record.__init__", "Record");
    const double dt = number(dt_given, "dt");
    const std::string unit = string_argument(unit_given, "unit"), name = string_argument(name_given, "name");
    const double scale = unit_scale(unit);
    std::vector<double> a = real_vector(accel, "accel");
    if (!(dt > 0)) refuse(name + ": dt must be > 0 (got " + significant(dt, 17) + ")");
    if (a.size() < 2) refuse(name + ": a record needs at least 2 samples (got " + std::to_string(a.size()) + ")");
    for (std::size_t k = 0; k < a.size(); ++k) {
        const double given = a[k];
        a[k] *= scale;
        if (!std::isfinite(a[k]))
            refuse(name + ": accel[" + std::to_string(k) + "] = " + significant(given, 17) + " " + unit +
                   (std::isfinite(given) ? " is out of range for a double in m/s^2" : " is not finite"));
    }
    auto r = std::make_shared<Record>();
    r->format = "array";
    r->name = name;
    r->dt = dt;
    r->accel = std::move(a);
    return r;
}

std::shared_ptr<Record> read_record(py::handle path, const std::optional<Text>& unit_given,
                                    const std::optional<Real>& dt_given, const py::kwargs& extra) {
    no_other_keywords(extra, "read_record", "read_record");
    const std::optional<std::string> unit = string_argument(unit_given, "unit");
    const std::optional<double> dt = number(dt_given, "dt");
    if (!unit && !dt) {
        RecordPtr r = record_argument(path, "path");
        return std::const_pointer_cast<Record>(r);
    }
    // A plain-text file, as --unit and --dt read it (src/cli/options.cpp, load_record).
    if (!unit) refuse("unit is required for a plain-text record (g, m/s2, cm/s2)");
    unit_scale(*unit);
    if (dt && !(*dt > 0)) refuse("dt: must be > 0 (got " + significant(*dt, 17) + ")");
    if (!py::isinstance<py::str>(path) && !py::isinstance<py::bytes>(path) && !py::hasattr(path, "__fspath__"))
        throw py::type_error("path: expected a file's path");
    const std::string file = file_argument(path, "path");
    py::gil_scoped_release unlocked;
    return std::make_shared<Record>(records::read_plain(file, *unit, dt.value_or(0.0)));
}

// A Record from its pickled state, checked as the constructor checks its arguments: a
// state made by hand (or a corrupted pickle) must not give a record no constructor gives.
std::shared_ptr<Record> record_from_state(const py::object& state) {
    const char* what = "Record.__setstate__";
    auto r = std::make_shared<Record>();
    py::object accel;
    try {
        if (!py::isinstance<py::tuple>(state) || py::len(state) != 6) throw py::cast_error();
        const py::tuple t = py::reinterpret_borrow<py::tuple>(state);
        for (int k : {0, 1, 2})
            if (!py::isinstance<py::bytes>(t[k])) throw py::cast_error();
        r->path = t[0].cast<std::string>();
        r->format = t[1].cast<std::string>();
        r->name = t[2].cast<std::string>();
        if (!py::isinstance<py::float_>(t[3])) throw py::cast_error();
        r->dt = t[3].cast<double>();
        if (!py::isinstance<py::dict>(t[5])) throw py::cast_error();
        for (auto [key, value] : py::reinterpret_borrow<py::dict>(t[5])) {
            if (!py::isinstance<py::bytes>(key) || !py::isinstance<py::bytes>(value)) throw py::cast_error();
            r->header[key.cast<std::string>()] = value.cast<std::string>();
        }
        accel = t[4];
    } catch (const py::cast_error&) {
        throw py::type_error(std::string(what) + ": not the state of a pickled rocking_q.Record (path, format, "
                                                 "name as bytes, dt, accel, header as a dict of bytes)");
    }
    r->accel = real_vector(accel, std::string(what) + ": accel");
    if (!(r->dt > 0) || !std::isfinite(r->dt)) refuse(std::string(what) + ": dt must be > 0 (got " + significant(r->dt, 17) + ")");
    if (r->accel.size() < 2)
        refuse(std::string(what) + ": a record needs at least 2 samples (got " + std::to_string(r->accel.size()) + ")");
    for (std::size_t k = 0; k < r->accel.size(); ++k)
        if (!std::isfinite(r->accel[k])) refuse(std::string(what) + ": accel[" + std::to_string(k) + "] is not finite");
    return r;
}

// A read-only view of the samples that keeps the record alive.
py::array_t<double> accel_view(py::handle self) {
    const Record& r = *held(self);
    py::array_t<double> a({static_cast<py::ssize_t>(r.accel.size())}, {static_cast<py::ssize_t>(sizeof(double))},
                          r.accel.data(), self);
    a.attr("flags").attr("writeable") = false;
    return a;
}

py::dict record_info(py::handle record) {
    const RecordPtr r = record_argument(record, "record");
    records::HalfPeriods h;
    {
        py::gil_scoped_release unlocked;  // the CWT: seconds on 10^6 samples
        h = checked_half_periods(*r);
    }
    py::dict out = to_python(json::record_info_json(label_of(*r), *r, h));
    // A path as os.fsdecode gives it; NumPy arrays where the command's --json has lists; then the module's own members.
    out["file"] = file_of(*r);
    out["to"] = to_array(std::vector<double>(h.to.begin(), h.to.end()));
    out["cwt_band_hz"] = to_array({h.cwt_band_hz[0], h.cwt_band_hz[1]});
    out["f_fourier_acc"] = h.f_fourier_acc;
    out["f_fourier_vel"] = h.f_fourier_vel;
    out["f_cwt"] = to_array({h.f_cwt[0], h.f_cwt[1], h.f_cwt[2], h.f_cwt[3]});
    return out;
}

py::array_t<double> half_periods(py::handle record) {
    const RecordPtr r = record_argument(record, "record");
    records::HalfPeriods h;
    {
        py::gil_scoped_release unlocked;
        h = checked_half_periods(*r);
    }
    return to_array(std::vector<double>(h.to.begin(), h.to.end()));
}

records::PeakMotion checked_peak_motion(const Record& r) {
    double bound = 0;
    for (double a : r.accel) bound += std::fabs(a) * r.dt;
    if (!std::isfinite(bound))
        throw std::runtime_error(label_of(r) + ": the record's velocity overflows a double (the sum of |a| dt exceeds "
                                               "1.8e308 m/s); scale the record down");
    try {
        return records::peak_motion(r.accel, r.dt);
    } catch (const std::invalid_argument& e) {
        throw std::runtime_error(label_of(r) + ": " + e.what());
    }
}

py::dict peak_motion(py::handle record) {
    const RecordPtr r = record_argument(record, "record");
    const records::PeakMotion m = checked_peak_motion(*r);
    py::dict out = result();
    out["pga_ms2"] = m.pga;
    out["pgv_ms"] = m.pgv;
    out["to5_s"] = m.to5;
    return out;
}

// rocking record synth: --pulse A,fp,nu,gamma[,t0] or --stochastic SEED [--params K=V,...].
// params: a dict of the command line's --params keys and numbers.
std::optional<std::map<std::string, double>> params_argument(const py::object& given) {
    if (given.is_none()) return std::nullopt;
    if (!py::isinstance<py::dict>(given))
        throw py::type_error("params: expected a dict of {key: number}, got " + std::string(py::str(py::type::of(given).attr("__name__"))));
    std::map<std::string, double> kv;
    for (auto [key_given, value] : py::reinterpret_borrow<py::dict>(given)) {
        const std::string key = string_argument(Text{py::reinterpret_borrow<py::object>(key_given)}, "params: a key");
        kv[key] = number(Real{py::reinterpret_borrow<py::object>(value)}, "params " + key);
    }
    return kv;
}

std::shared_ptr<Record> record_synth(const py::object& pulse_given, const std::optional<Whole>& stochastic_given,
                                     const py::object& params_given, const Real& dt_given, const Real& duration_given,
                                     const py::kwargs& extra) {
    no_other_keywords(extra, "record_synth", "record_synth");
    std::vector<double> pulse_values;
    const bool has_pulse = !pulse_given.is_none();
    if (has_pulse) pulse_values = real_vector(pulse_given, "pulse");
    const std::optional<long long> stochastic = whole(stochastic_given, "stochastic");
    const std::optional<std::map<std::string, double>> params = params_argument(params_given);
    const double dt = number(dt_given, "dt"), duration = number(duration_given, "duration");
    if (has_pulse == stochastic.has_value()) refuse("give exactly one of pulse=(A, fp, nu, gamma[, t0]) and stochastic=SEED");
    if (has_pulse && params) refuse("params goes with stochastic");
    if (!(dt > 0)) refuse("dt: must be > 0 (got " + significant(dt, 17) + ")");
    if (!(duration > 0)) refuse("duration: must be > 0 (got " + significant(duration, 17) + ")");
    const std::string flag = has_pulse ? "pulse" : params ? "params" : "stochastic";
    records::PulseParameters pp{};
    // default_stochastic_parameters and with_arias_modulation swap GSL's process-wide error
    // handler and put it back: they run with the GIL held, so that two Python threads never
    // swap it at once.
    records::StochasticParameters sp = records::default_stochastic_parameters();
    std::uint64_t seed = 0;
    if (has_pulse) {
        const std::vector<double>& v = pulse_values;
        if (v.size() != 4 && v.size() != 5)
            refuse("pulse: takes (A, fp, nu, gamma[, t0]) (m/s, Hz, rad, -, s), got " + std::to_string(v.size()) + " values");
        pp = {v[0], v[1], v[2], v[3], 0};
        pp.t0 = v.size() == 5 ? v[4] : (pp.fp > 0 ? pp.gamma / (2 * pp.fp) : 0);
    } else {
        if (*stochastic < 1 || *stochastic > 4294967295LL)
            refuse("stochastic: the seed must be a whole number from 1 to 4294967295 (got " + std::to_string(*stochastic) + ")");
        seed = static_cast<std::uint64_t>(*stochastic);
        if (params) {
            try {
                sp = records::stochastic_parameters_from(*params);
            } catch (const std::invalid_argument& e) {
                refuse(std::string("params: ") + e.what());
            }
        }
    }
    std::string error;
    std::shared_ptr<Record> r;
    {
        py::gil_scoped_release unlocked;
        try {
            r = std::make_shared<Record>(has_pulse ? records::pulse_record(pp, dt, duration)
                                               : records::stochastic_record(sp, seed, dt, duration));
        } catch (const records::SamplingError& e) {
            // The argument that set the frequency, as the command line names it: params when
            // it gave one of the frequency's keys, dt for a default's.
            bool given = has_pulse;
            for (const std::string& key : e.parameters) given = given || (params && params->count(key));
            error = std::string(has_pulse ? "pulse" : given ? "params" : "dt") + ": " + e.what();
        } catch (const std::invalid_argument& e) {
            // The argument to change, as the command line names it.
            const std::string what = e.what();
            error = (what.rfind("duration/dt", 0) == 0 ? std::string("duration") : flag) + ": " + what;
        }
    }
    if (!error.empty()) refuse(error);
    // The command line's warnings on standard error, as Python's (the record's header keeps them).
    for (const std::string& w : records::warnings_of(*r))
        if (PyErr_WarnEx(PyExc_RuntimeWarning, ("record_synth: " + w).c_str(), 1) != 0) throw py::error_already_set();
    return r;
}

// rocking record floor: the floor's Record of a ground record (records/floor_motion.hpp).
// A model out of range is a ValueError naming the keyword as the command line names its option
// (period, damping, participation); a floor beyond a double's range a RuntimeError naming the
// record, as the command's exit 1.
const char* floor_keyword(const std::string& parameter) {
    return parameter == "T1" ? "period" : parameter == "zeta" ? "damping" : "participation";
}

std::shared_ptr<Record> record_floor(py::handle record, const Real& period_given, const Real& participation_given,
                                     const Real& damping_given, const py::kwargs& extra) {
    no_other_keywords(extra, "record_floor", "record_floor");
    const records::FloorModel m{number(period_given, "period"), number(participation_given, "participation"),
                                number(damping_given, "damping")};
    try {
        records::check_floor_model(m);
    } catch (const records::FloorModelError& e) {
        refuse(std::string(floor_keyword(e.parameter)) + ": " + e.what());
    }
    const RecordPtr ground = record_argument(record, "record");
    std::string refused, overflow;
    std::shared_ptr<Record> r;
    {
        py::gil_scoped_release unlocked;
        try {
            r = std::make_shared<Record>(records::floor_record(*ground, m));
        } catch (const records::FloorModelError& e) {
            refused = std::string(floor_keyword(e.parameter)) + ": " + e.what();
        } catch (const std::overflow_error& e) {
            overflow = label_of(*ground) + ": " + e.what();
        }
    }
    if (!refused.empty()) refuse(refused);
    if (!overflow.empty()) throw std::runtime_error(overflow);
    for (const std::string& w : records::warnings_of(*r))
        if (PyErr_WarnEx(PyExc_RuntimeWarning, ("record_floor: " + w).c_str(), 1) != 0) throw py::error_already_set();
    return r;
}

// --alpha of collapse, the options of its search.
records::CollapseOptions collapse_options(const Real& alpha_given, const Text& model_given,
                                          const std::optional<Text>& solver_given,
                                          const std::optional<Text>& criterion_given, const py::object& restitution, const py::object& friction,
                                          const py::object& imperfection, const std::optional<Real>& rtol_given, const std::optional<Real>& atol_given) {
    const double alpha = number(alpha_given, "alpha");
    const std::string model = string_argument(model_given, "model");
    const std::optional<std::string> solver = string_argument(solver_given, "solver"),
                                     criterion = string_argument(criterion_given, "criterion");
    const std::optional<double> rtol = number(rtol_given, "rtol"), atol = number(atol_given, "atol");
    if (!studies::in_search_alpha_range(alpha))
        refuse("alpha: must be in " + std::string(studies::kSearchAlphaRange) + " (got " + significant(alpha, 17) + ")");
    records::CollapseOptions o;
    if (model == "full") o.equation = dynamics::Equation::full, o.solver.kind = dynamics::SolverKind::dopri5;
    else if (model != "linearised") refuse("model: linearised or full (got '" + model + "')");
    try {
        if (solver) o.solver.kind = dynamics::parse_solver(*solver);
    } catch (const std::invalid_argument& e) {
        refuse(std::string("solver: ") + e.what());
    }
    try {
        if (criterion) o.criterion = dynamics::parse_criterion(*criterion);
    } catch (const std::invalid_argument& e) {
        refuse(std::string("criterion: ") + e.what());
    }
    tolerance_arguments(rtol, atol, alpha, o.solver);
    const double e = restitution_argument(restitution);
    o.housner_restitution = std::isnan(e);
    if (!o.housner_restitution) o.restitution = e;
    friction_into(friction, restitution, o);
    imperfection_into(imperfection, o);
    if (o.friction > 0 && (model != "linearised" || solver))
        refuse("model and solver do not apply with friction: the sliding-rocking model has its full equations and its "
               "event-driven solver");
    if (o.friction > 0 && rtol) o.sliding_rtol = o.solver.rtol;
    if (o.equation == dynamics::Equation::full && o.solver.kind == dynamics::SolverKind::exact)
        refuse("the exact solver handles the linearised equation only");
    return o;
}

py::dict collapse(py::handle record, const Real& alpha_given, const Text& model, const std::optional<Text>& solver,
                  const std::optional<Text>& criterion, const py::object& restitution, const py::object& friction,
                  const py::object& imperfection, const std::optional<Real>& rtol,
                  const std::optional<Real>& atol, const py::kwargs& extra) {
    no_other_keywords(extra, "collapse", "collapse");
    const records::CollapseOptions o = collapse_options(alpha_given, model, solver, criterion, restitution, friction, imperfection, rtol, atol);
    const double alpha = number(alpha_given, "alpha");
    const RecordPtr r = record_argument(record, "record");
    records::CollapseResult c;
    {
        py::gil_scoped_release unlocked;
        const dynamics::SampledInput input(r->in_g(dynamics::kGravity), r->dt, r->name);
        refuse_unresolvable_run(o.p_max, input.t_end(), "record " + label_of(*r));  // the search's p_max is its own
        c = records::smallest_collapse_p(input, alpha, o);
    }
    const json::Json doc = json::collapse_json(label_of(*r), alpha, c, o, nullptr);
    py::dict out = to_python(doc);
    out["file"] = file_of(*r);  // a path as os.fsdecode gives it
    if (o.imperfection.any()) out["imperfection"] = to_python(doc["imperfection"], Dicts::plain);
    return out;
}

// `rocking assess --json`: one record or several (studies/assessment.hpp).
py::dict assess(py::handle records_given, const std::optional<Real>& thickness, const std::optional<Real>& height,
                const std::optional<Real>& half_height, const std::optional<Real>& alpha_given,
                const std::optional<Real>& p_given, const Real& width_given, const py::object& restitution, const py::object& friction,
                const py::object& imperfection, const std::optional<Text>& floor, const py::kwargs& extra) {
    no_other_keywords(extra, "assess", "assess");
    const dynamics::GivenBlock given = block_argument(thickness, height, half_height, alpha_given, p_given);
    const double alpha = given.alpha;
    const std::string size_name = height ? "height" : half_height ? "half_height" : "p";  // what set the block's p
    studies::AssessOptions o;
    restitution_into(restitution, o.model);
    friction_into(friction, restitution, o.model);
    imperfection_into(imperfection, o.model);
    o.width = number(width_given, "width");
    if (!(o.width >= 1e-7 && o.width <= 0.1)) refuse("width: must be in [1e-7, 0.1] (got " + significant(o.width, 17) + ")");
    if (!studies::in_search_alpha_range(alpha))
        refuse("the block's alpha, " + significant(alpha, 6) + " rad, is outside the searches' " + studies::kSearchAlphaRange);
    if (!studies::in_search_p_range(given.block.p))
        refuse(size_name + ": the block's p, " +
               significant(given.block.p, 6) + " rad/s, is outside the searches' " + studies::kSearchPRange);
    // One record (a Record or a path) or a list of them.
    std::vector<RecordPtr> held;
    if (py::isinstance<py::list>(records_given) || py::isinstance<py::tuple>(records_given)) held = record_list(records_given, "record");
    else held.push_back(record_argument(records_given, "record"));
    for (RecordPtr& r : held) r = with_floor(r, floor);
    std::vector<records::PeakMotion> motions;
    std::vector<std::unique_ptr<dynamics::SampledInput>> inputs;
    std::vector<const dynamics::SampledInput*> views;
    for (const RecordPtr& r : held) {
        motions.push_back(checked_peak_motion(*r));
        inputs.push_back(std::make_unique<dynamics::SampledInput>(r->in_g(dynamics::kGravity), r->dt, r->name));
        const studies::Refusal refused = studies::refusal_of(*inputs.back(), motions.back(), studies::BlockShape{alpha, given.block.p});
        if (refused.blame == studies::Refusal::Blame::block)
            refuse(size_name + ": " + refused.why);
        if (refused.blame == studies::Refusal::Blame::record) throw std::invalid_argument(label_of(*r) + ": " + refused.why);
        refuse_unresolvable_run(o.spectrum_options(given.block.p, given.alpha).p_max, inputs.back()->t_end(), "record " + label_of(*r));
        views.push_back(inputs.back().get());
    }
    std::vector<std::string> labels;
    for (const RecordPtr& r : held) labels.push_back(label_of(*r));
    try {
        studies::refuse_repeated_records(labels, views);  // as rocking assess: it would count twice in the fit
    } catch (const std::invalid_argument& e) {
        refuse(e.what());
    }
    studies::Assessment a;
    {
        py::gil_scoped_release unlocked;
        a = studies::assess_block(views, motions, studies::BlockShape{alpha, given.block.p, given.label}, o);
    }
    std::vector<std::string> names;
    for (const RecordPtr& r : held) names.push_back(r->name);
    // As rocking assess --json: the floor's model where the records are a floor's motion.
    const std::string input =
        floor ? records::describe_as_input(records::parse_floor_model(*string_argument(floor, "floor"))) : std::string();
    const json::Json doc = json::assess_json(labels, names, given, a, o, input);
    py::dict out = to_python(doc);
    // The module's own order of a record's members (eq. 27's two flags beside its q) and paths as os.fsdecode gives them.
    py::list rows = out["records"];
    for (std::size_t k = 0; k < held.size(); ++k) {
        py::dict row = with_keys_before(rows[k], {"eq27_passes_alpha_before_t_fin", "eq27_impact_before_t_fin"}, "q_record");
        row["file"] = file_of(*held[k]);
        rows[k] = row;
    }
    if (o.model.imperfection.any()) out["imperfection"] = to_python(doc["imperfection"], Dicts::plain);
    return out;
}

}  // namespace

void init_records(py::module_& m) {
    using namespace py::literals;
    // RecordError's messages reach Python through the module's translator (common.cpp): a file's
    // name in them need not be UTF-8.
    static py::exception<records::RecordError> record_error(m, "RecordError", PyExc_ValueError);
    install_exception_translator(record_error);

    // Every method takes the Record through held(): one made by Record.__new__ without its
    // constructor has no Record behind it, and pybind11 would hand the method unwritten memory.
    py::class_<Record, std::shared_ptr<Record>>(m, "Record", R"(A strong-motion record: samples in m/s^2 every dt seconds.

Record(accel, dt, unit="m/s2", name="array") makes one from a 1-D array in unit
(g, m/s2 or cm/s2), multiplied to m/s^2 as the plain-text reader does; read_record(path)
reads a file.  Immutable: accel is a read-only view.)")
        .def(py::init(&record_from_array), "accel"_a, "dt"_a, py::kw_only(), "unit"_a = "m/s2", "name"_a = "array")
        .def_property_readonly("path", [](py::handle self) { return path_of(*held(self)); }, "the file as given; None for an array")
        .def_property_readonly("format", [](py::handle self) { return text(held(self)->format); })
        .def_property_readonly("name", [](py::handle self) { return text(held(self)->name); })
        .def_property_readonly("dt", [](py::handle self) { return held(self)->dt; }, "s")
        .def_property_readonly("accel", [](py::handle self) { return accel_view(self); }, "the samples, m/s^2 (read-only)")
        .def_property_readonly("samples", [](py::handle self) { return held(self)->accel.size(); }, "how many samples")
        .def_property_readonly("header", [](py::handle self) {
            py::dict h;
            for (const auto& [key, value] : held(self)->header) h[text(key)] = text(value);
            return h;
        }, "the source's header fields (text)")
        .def_property_readonly("duration", [](py::handle self) { return held(self)->duration(); }, "s")
        .def_property_readonly("pga_ms2", [](py::handle self) { return held(self)->pga(); }, "max |a|, m/s^2")
        .def_property_readonly("pga_g", [](py::handle self) { return held(self)->pga() / dynamics::kGravity; }, "max |a|, g")
        .def("in_g", [](py::handle self) { return to_array(held(self)->in_g(dynamics::kGravity)); }, "the samples in g (a copy)")
        .def("__len__", [](py::handle self) { return held(self)->accel.size(); })
        // Pickled whole, so that a ProcessPoolExecutor can send one to its workers.
        .def(py::pickle(
            [](py::handle self) {
                const RecordPtr r = held(self);
                py::dict header;  // bytes, as read: a file's header need not be UTF-8
                for (const auto& [key, value] : r->header) header[py::bytes(key)] = py::bytes(value);
                return py::object(py::make_tuple(py::bytes(r->path), py::bytes(r->format), py::bytes(r->name), r->dt,
                                                 to_array(r->accel), header));
            },
            &record_from_state))
        .def("__repr__", [](py::handle self) -> py::str {
            // Not a refusal: a debugger, a traceback or pytest shows it.
            if (!py::isinstance<Record>(self) || !reinterpret_cast<py::detail::instance*>(self.ptr())
                                                       ->get_value_and_holder()
                                                       .holder_constructed())
                return py::str("<rocking_q.Record, not initialised>");
            const RecordPtr r = held(self);
            return text("<rocking_q.Record '" + r->name + "' (" + r->format + "): " + std::to_string(r->accel.size()) +
                        " samples, dt = " + significant(r->dt, 6) + " s>");
        });

    m.def("read_record", gsl_checked(&read_record), "path"_a, py::kw_only(), "unit"_a = py::none(), "dt"_a = py::none(),
          R"(A record file, as `rocking record info FILE` reads it: ESM/ITACA ASCII or PEER AT2 by content,
or plain one- or two-column text with unit (g, m/s2, cm/s2) and, for one column, dt.
A malformed file raises RecordError naming the file and line.)");
    m.def("record_info", gsl_checked(&record_info), "record"_a,
          "`rocking record info --json`: PGA, PGV, Amax and the eleven half-periods to_1..to_11 (s) of a Record or a path.");
    m.def("half_periods", gsl_checked(&half_periods), "record"_a, "to_1..to_11 (s) of a record, as an array of 11 (records/measures.hpp).");
    m.def("peak_motion", gsl_checked(&peak_motion), "record"_a, "PGA (m/s^2), PGV (m/s) and to_5 = pi PGV/PGA (s), as assess measures them.");
    m.def("record_synth", gsl_checked(&record_synth), py::kw_only(), "pulse"_a = py::none(), "stochastic"_a = py::none(),
          "params"_a = py::none(), "dt"_a, "duration"_a,
          R"(`rocking record synth`: a synthetic Record (docs/synthetic.md).

pulse=(A, fp, nu, gamma[, t0]): Mavroeidis & Papageorgiou's velocity pulse (m/s, Hz, rad, -, s);
stochastic=SEED with params={"Ia": ..., "D5_95": ..., ...}: Rezaeian & Der Kiureghian's filtered noise.)");
    m.def("record_floor", gsl_checked(&record_floor), "record"_a, py::kw_only(), "period"_a, "participation"_a,
          "damping"_a = records::FloorModel{}.zeta,
          R"(`rocking record floor`: the floor's Record of a ground record (a Record or a path), the building
idealised as its first mode (docs/floor_motion.md): a linear oscillator of period (s) and damping
ratio, with the floor's participation G = Gamma phi(z); a_f = a_g + G D'', exact for the record read
linear between samples (Nigam & Jennings 1969), at its samples.  Releases the GIL.)");
    m.def("collapse", gsl_checked(&collapse), "record"_a, py::kw_only(), "alpha"_a, "model"_a = "linearised", "solver"_a = py::none(),
          "criterion"_a = py::none(), "restitution"_a = "housner", "friction"_a = py::none(), "imperfection"_a = py::none(), "rtol"_a = py::none(), "atol"_a = py::none(),
          R"(`rocking collapse --json`: Table 1's search, the first p (rad/s) raised from 0.3 by 1 % at which the
record overturns the block, then refined.  Not a bound (docs/findings.md, T1b).  Releases the GIL.)");
    m.def("assess", gsl_checked(&assess), "record"_a, py::kw_only(), "thickness"_a = py::none(), "height"_a = py::none(),
          "half_height"_a = py::none(), "alpha"_a = py::none(), "p"_a = py::none(), "width"_a = 1e-3,
          "restitution"_a = "housner", "friction"_a = py::none(), "imperfection"_a = py::none(), "floor"_a = py::none(),
          R"(`rocking assess --json`: the block (thickness and height in m, or alpha with height, half_height or p)
against one record or a list: eq. 27's check with its ratio and margin, the run on each record, the
scale factors at which the block first overturns and first robustly collapses, the nearest
overturning blocks of its alpha, and with several records the fragility's P(overturn) at each
record's q (docs/assess.md).  Releases the GIL.)");
}

}  // namespace rocking::python
