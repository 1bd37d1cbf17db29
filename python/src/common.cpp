// The Python module's shared pieces (common.hpp).
#include "common.hpp"

#include <pybind11/eval.h>

#include <gsl/gsl_errno.h>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <mutex>

#include "batch/pool.hpp"

namespace rocking::python {

namespace {

// The Result class, in Python: a dict (the command's JSON, field for field)
// whose keys read as attributes too.  Keys that are Python keywords ("from")
// stay reachable as r["from"].
const char* kResultSource = R"py(
class Result(dict):
    """A rocking_q result: the command line's --json fields, as a dict and as attributes.

    r["collapse"] and r.collapse are the same value; keys that are Python
    keywords (an interval's "from") read as r["from"].  Arrays (t, theta, ...)
    are NumPy arrays; JSON's null is None.
    """

    __slots__ = ()

    def __getattr__(self, name):
        try:
            return self[name]
        except KeyError:
            raise AttributeError(name) from None

    def __dir__(self):
        return sorted(set(dir(dict)) | set(self.keys()))

    def __repr__(self):
        return "Result(" + dict.__repr__(self) + ")"
)py";

// Set once at import and never freed: a static py::object would be released
// after the interpreter has gone.
py::object* result_type = nullptr;

}  // namespace

void define_result(py::module_& m) {
    py::dict scope;
    scope["__builtins__"] = py::module_::import("builtins");
    scope["__name__"] = m.attr("__name__");
    py::exec(kResultSource, scope);
    py::object type = scope["Result"];
    type.attr("__module__") = m.attr("__name__");
    m.attr("Result") = type;
    result_type = new py::object(type);
}

py::dict result() { return py::dict((*result_type)()); }

py::object none_if_nan(double v) { return std::isfinite(v) ? py::object(py::float_(v)) : py::object(py::none()); }

void refuse(const std::string& message) { throw py::value_error(message); }

namespace {
PyObject* record_error_type = nullptr;  // set once at import, never freed

void set_error(PyObject* type, const char* what) {
    PyObject* message = PyUnicode_DecodeFSDefault(what);  // surrogateescape: never fails on bytes
    if (!message) {
        PyErr_Clear();
        message = PyUnicode_DecodeUTF8(what, static_cast<Py_ssize_t>(std::strlen(what)), "replace");
    }
    PyErr_SetObject(type, message);
    Py_XDECREF(message);
}
}  // namespace

void install_exception_translator(py::handle record_error) {
    record_error_type = record_error.inc_ref().ptr();
    py::register_local_exception_translator([](std::exception_ptr p) {
        try {
            if (p) std::rethrow_exception(p);
        } catch (const py::error_already_set&) {
            throw;
        } catch (const records::RecordError& e) {
            set_error(record_error_type, e.what());
        } catch (const py::value_error& e) {
            set_error(PyExc_ValueError, e.what());
        } catch (const py::type_error& e) {
            set_error(PyExc_TypeError, e.what());
        } catch (const py::builtin_exception&) {
            throw;  // pybind11's own (cast_error, index_error, ...): its translator
        } catch (const std::bad_alloc&) {
            throw;
        } catch (const std::invalid_argument& e) {
            set_error(PyExc_ValueError, e.what());
        } catch (const std::domain_error& e) {
            set_error(PyExc_ValueError, e.what());
        } catch (const std::length_error& e) {
            set_error(PyExc_ValueError, e.what());
        } catch (const std::range_error& e) {
            set_error(PyExc_ValueError, e.what());
        } catch (const std::out_of_range& e) {
            set_error(PyExc_IndexError, e.what());
        } catch (const std::overflow_error& e) {
            set_error(PyExc_OverflowError, e.what());
        } catch (const std::exception& e) {
            set_error(PyExc_RuntimeError, e.what());
        }
    });
}

py::array_t<double> real_array(py::handle obj, const std::string& what) {
    py::array a = py::array::ensure(obj);
    if (!a) throw py::type_error(what + ": expected an array of real numbers, got " + std::string(py::str(py::type::of(obj).attr("__name__"))));
    const char kind = a.dtype().kind();
    const bool real = kind == 'i' || kind == 'u' || (kind == 'f' && a.dtype().itemsize() <= 8);
    if (!real)
        throw py::type_error(what + ": dtype " + std::string(py::str(a.dtype())) +
                             " is not a real number type; give float64 (or integers, or float32)");
    return py::array_t<double, py::array::c_style | py::array::forcecast>::ensure(a);
}

std::vector<double> real_vector(py::handle obj, const std::string& what) {
    const py::array_t<double> a = real_array(obj, what);
    if (a.ndim() != 1) {
        std::string shape = "(";
        for (py::ssize_t k = 0; k < a.ndim(); ++k) shape += (k ? ", " : "") + std::to_string(a.shape(k));
        shape += a.ndim() == 1 ? ",)" : ")";
        throw py::value_error(what + ": expected a 1-D array, got " + std::to_string(a.ndim()) + "-D of shape " + shape);
    }
    return std::vector<double>(a.data(), a.data() + a.size());
}

py::array_t<double> to_array(const std::vector<double>& v) {
    py::array_t<double> a(static_cast<py::ssize_t>(v.size()));
    std::copy(v.begin(), v.end(), a.mutable_data());
    return a;
}

namespace {
bool from_file(const records::Record& r) { return !r.path.empty() && r.format != "synthetic"; }
}  // namespace

std::string label_of(const records::Record& r) { return from_file(r) ? r.path : r.name; }

py::object path_of(const records::Record& r) {
    if (!from_file(r)) return py::none();
    return py::module_::import("os").attr("fsdecode")(py::bytes(r.path));
}

py::object file_of(const records::Record& r) { return from_file(r) ? path_of(r) : py::object(text(r.name)); }

py::str text(const std::string& s) { return py::bytes(s).attr("decode")("utf-8", "replace"); }

namespace {
const char* kNeverInitialised = "(made by Record.__new__ without calling Record(...))";
}  // namespace

RecordPtr held(py::handle self) {
    if (!py::isinstance<records::Record>(self))
        throw py::type_error("expected a rocking_q.Record, got " + std::string(py::str(py::type::of(self).attr("__name__"))));
    try {
        return self.cast<std::shared_ptr<records::Record>>();
    } catch (const py::cast_error&) {  // no holder: __init__ never ran
        throw py::type_error(std::string("Record: not initialised ") + kNeverInitialised);
    }
}

std::string file_argument(py::handle obj, const std::string& what) {
    const std::string path = py::module_::import("os").attr("fsencode")(obj).cast<std::string>();
    // The reader would see the name up to its NUL, another file; open() refuses it so.
    if (path.find('\0') != std::string::npos) refuse(what + ": embedded null byte");
    return path;
}

RecordPtr record_argument(py::handle obj, const std::string& what) {
    if (py::isinstance<records::Record>(obj)) {
        try {
            return obj.cast<std::shared_ptr<records::Record>>();
        } catch (const py::cast_error&) {
            throw py::type_error(what + ": a rocking_q.Record never initialised " + kNeverInitialised);
        }
    }
    if (!py::isinstance<py::str>(obj) && !py::isinstance<py::bytes>(obj) && !py::hasattr(obj, "__fspath__"))
        throw py::type_error(what + ": expected a rocking_q.Record or a file's path, got " +
                             std::string(py::str(py::type::of(obj).attr("__name__"))));
    const std::string path = file_argument(obj, what);
    py::gil_scoped_release unlocked;  // a pipe may keep the reader waiting up to 10 s
    return std::make_shared<const records::Record>(records::read_any(path));
}

std::vector<RecordPtr> record_list(py::handle obj, const std::string& what) {
    if (py::isinstance<py::str>(obj) || py::isinstance<records::Record>(obj) || py::hasattr(obj, "__fspath__"))
        throw py::type_error(what + ": expected a list of records or paths (one record: [r])");
    std::vector<RecordPtr> out;
    std::size_t k = 0;
    for (py::handle item : py::iter(obj)) out.push_back(record_argument(item, what + "[" + std::to_string(k++) + "]"));
    if (out.empty()) refuse(what + ": no record given");
    return out;
}

records::HalfPeriods checked_half_periods(const records::Record& r) {
    const std::string label = label_of(r);
    double bound = 0;
    for (double a : r.accel) bound += std::fabs(a) * r.dt;
    if (!std::isfinite(bound))
        throw std::runtime_error(label + ": the record's velocity overflows a double (the sum of |a| dt exceeds "
                                         "1.8e308 m/s); scale the record down");
    records::HalfPeriods h;
    try {
        h = records::half_periods(r);
    } catch (const std::invalid_argument& e) {
        throw std::runtime_error(label + ": " + e.what());
    }
    const char* names[] = {"to_1", "to_2", "to_3", "to_4", "to_5", "to_6", "to_7", "to_8", "to_9", "to_10", "to_11"};
    const char* bad = !std::isfinite(h.pga) ? "PGA" : !std::isfinite(h.pgv) ? "PGV" : !std::isfinite(h.amax) ? "Amax" : nullptr;
    for (int k = 0; !bad && k < 11; ++k)
        if (!std::isfinite(h.to[k])) bad = names[k];
    if (bad)
        throw std::runtime_error(label + ": the record's " + bad +
                                 " overflows a double; its samples are too large to measure (scale the record down)");
    return h;
}

namespace {
// The shortest text that reads back as v: 0.5 as "0.5", as a user types it.
std::string shortest(double v) {
    char text[32];
    const auto end = std::to_chars(text, text + sizeof text, v).ptr;
    return std::string(text, end);
}
}  // namespace

PulseTrain train_argument(const py::object& which_case, const std::optional<int>& pulses, const py::object& train,
                          std::string& equation) {
    const bool has_case = !which_case.is_none(), has_train = !train.is_none();
    if (has_case == has_train) refuse("give exactly one of case and train");
    if (has_train) {
        if (pulses) refuse("pulses goes with case");
        equation = "superposition (S2)";
        try {
            if (py::isinstance<py::str>(train)) return parse_train(train.cast<std::string>());
            const py::array_t<double> a = real_array(train, "train");
            if (a.ndim() != 2 || a.shape(1) != 2)
                throw py::value_error("train: expected (amplitude, duration) pairs, an (n, 2) array; got " +
                                      std::to_string(a.ndim()) + "-D" +
                                      (a.ndim() >= 1 ? " of length " + std::to_string(a.shape(0)) : std::string()));
            std::vector<Pulse> items;
            std::string name;
            for (py::ssize_t k = 0; k < a.shape(0); ++k) {
                items.push_back({a.at(k, 0), a.at(k, 1)});
                name += (k ? "," : "") + shortest(a.at(k, 0)) + ":" + shortest(a.at(k, 1));
            }
            return PulseTrain(items, name);
        } catch (const std::invalid_argument& e) {
            refuse(std::string("train: ") + e.what());
        }
    }
    if (!py::isinstance<py::int_>(which_case) || py::isinstance<py::bool_>(which_case))
        throw py::type_error("case: expected an integer 1..5");
    const int which = which_case.cast<int>();
    if (which < 1 || which > 5) refuse("case: must be 1, 2, 3, 4 or 5 (got " + std::to_string(which) + ")");
    const int n = pulses.value_or(2);
    if (n < 1 || n > 1000) refuse("pulses: must be between 1 and 1000");
    static const char* eq[] = {"", "eq. 12", "eq. 15", "eq. 19", "eq. 22", "eq. 24"};
    equation = n == 2 ? eq[which] : (n == 6 && which == 2) ? "eq. 27" : (n == 6 && which == 4) ? "eq. 28 (corrected)"
                                                                                             : "superposition (S2)";
    return repeated_case(which, n);
}

double restitution_argument(const py::object& value) {
    if (py::isinstance<py::str>(value)) {
        if (value.cast<std::string>() == "housner") return NAN;
        refuse("restitution: a factor in [0, 1] or 'housner' (got '" + value.cast<std::string>() + "')");
    }
    const double e = value.cast<double>();
    if (!(e >= 0 && e <= 1)) refuse("restitution: must be in [0, 1] or 'housner' (got " + significant(e, 17) + ")");
    return e;
}

void tolerance_arguments(const std::optional<double>& rtol, const std::optional<double>& atol, double alpha,
                         dynamics::SolverOptions& solver) {
    const double floor = dynamics::kSmallestTolerance;
    if (rtol) {
        if (!(*rtol >= floor && *rtol < 1))
            refuse("rtol: must be in [100 eps, 1) = [" + significant(floor, 17) + ", 1) (got " + significant(*rtol, 17) + ")");
        solver.rtol = solver.atol_alpha = *rtol;
    }
    if (!atol) return;
    const double in_alpha = *atol / alpha;
    if (!(in_alpha >= floor && in_alpha < 1)) {
        char range[200];
        std::snprintf(range, sizeof range, "[%.17g, %g) rad, [100 eps, 1) alpha at alpha = %g", floor * alpha, alpha, alpha);
        refuse("atol: must be in " + std::string(range) + " (got " + significant(*atol, 17) + ")");
    }
    solver.atol_alpha = in_alpha;
}

int jobs_argument(const std::optional<int>& jobs) {
    if (!jobs) return batch::default_threads();
    if (*jobs < 1 || *jobs > 4096) refuse("jobs: must be between 1 and 4096 (got " + std::to_string(*jobs) + ")");
    return *jobs;
}

namespace {
std::mutex gsl_mutex;
std::vector<GslWatch*> gsl_calls;  // the module's calls running now, under gsl_mutex
gsl_error_handler_t* gsl_previous = nullptr;
}  // namespace

void on_gsl_error(const char* reason, const char* file, int line, int code) {
    {
        char where[64];
        std::snprintf(where, sizeof where, ":%d", line);
        const std::string message = std::string("GSL error: ") + reason + " (" + file + where + ", " + gsl_strerror(code) + ")";
        std::lock_guard<std::mutex> lock(gsl_mutex);
        for (GslWatch* call : gsl_calls)
            if (call->message_.empty()) call->message_ = message;
        if (!gsl_calls.empty()) return;
    }
    // Not in a call of the module: as before it was imported.
    if (gsl_previous) return gsl_previous(reason, file, line, code);
    std::fprintf(stderr, "gsl: %s:%d: ERROR: %s\nDefault GSL error handler invoked.\n", file, line, reason);
    std::fflush(stderr);
    std::abort();
}

void install_gsl_handler() { gsl_previous = gsl_set_error_handler(&on_gsl_error); }

GslWatch::GslWatch() {
    std::lock_guard<std::mutex> lock(gsl_mutex);
    gsl_calls.push_back(this);
}

GslWatch::~GslWatch() {
    std::lock_guard<std::mutex> lock(gsl_mutex);
    gsl_calls.erase(std::find(gsl_calls.begin(), gsl_calls.end(), this));
}

void GslWatch::check() const {
    std::lock_guard<std::mutex> lock(gsl_mutex);
    if (message_.empty()) return;
    throw std::runtime_error(message_ + "; the call's result is not trusted (GSL's default handler would have "
                                        "aborted the process)");
}

std::string significant(double v, int n) {
    char text[48];
    std::snprintf(text, sizeof text, "%.*g", n, v);
    return text;
}

}  // namespace rocking::python
