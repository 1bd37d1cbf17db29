// The Python module's shared pieces (common.hpp).
#include "common.hpp"

#include <pybind11/eval.h>

#include <gsl/gsl_errno.h>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <cfloat>
#include <cstdlib>
#include <cstring>
#include <mutex>
#include <stdexcept>

#include "batch/pool.hpp"

namespace rocking::python {

using namespace py::literals;

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

    @staticmethod
    def _unexpected(function, shown, keys):
        """The TypeError's text for keywords the function does not take, as Python words it."""
        import difflib
        import re
        head = (function.__doc__ or "").split("\n", 1)[0]
        known = [k for k in re.findall(r"[(,]\s*(\w+)\s*:", head) if k != "self"]
        close = difflib.get_close_matches(keys[0], known, n=1)
        hint = " (did you mean '%s'?)" % close[0] if close else ""
        return "%s() got an unexpected keyword argument '%s'%s" % (shown, keys[0], hint)
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

py::module_* module_handle = nullptr;  // set once at import, never freed

std::string type_name(py::handle o) { return py::str(py::type::of(o).attr("__name__")); }

bool is_numpy(py::handle o) {
    const py::module_ np = py::module_::import("numpy");
    return py::isinstance(o, np.attr("ndarray")) || py::isinstance(o, np.attr("generic"));
}

bool is_bool(py::handle o) {
    return PyBool_Check(o.ptr()) || py::isinstance(o, py::module_::import("numpy").attr("bool_"));
}

std::string shape_of(const py::array& a) {
    std::string shape = "(";
    for (py::ssize_t k = 0; k < a.ndim(); ++k) shape += (k ? ", " : "") + std::to_string(a.shape(k));
    return shape + (a.ndim() == 1 ? ",)" : ")");
}

// "str '0.15'", "list", "an array of shape (1,)": what was given, for a TypeError.
std::string given(py::handle o) {
    if (py::isinstance<py::str>(o)) {
        std::string shown = py::repr(o);
        if (shown.size() > 40) shown = shown.substr(0, 37) + "...";
        return type_name(o) + " " + shown;
    }
    if (py::isinstance<py::array>(o) && py::reinterpret_borrow<py::array>(o).ndim() > 0)
        return "an array of shape " + shape_of(py::reinterpret_borrow<py::array>(o));
    return o.is_none() ? "None" : type_name(o);
}

// A numpy scalar or array as a 0-d array of an integer or real dtype, or a TypeError.
py::object numpy_item(py::handle o, const std::string& name, const std::string& expected, bool reals) {
    const py::array a = py::array::ensure(o);
    if (!a || a.ndim() != 0) throw py::type_error(name + ": expected " + expected + ", got " + given(o));
    const char kind = a.dtype().kind();
    const bool ok = kind == 'i' || kind == 'u' || (reals && kind == 'f' && a.dtype().itemsize() <= 8);
    if (!ok) throw py::type_error(name + ": expected " + expected + ", got " + std::string(py::str(a.dtype())));
    return a.attr("item")();
}

std::string not_finite(double v) { return std::isnan(v) ? "nan" : v > 0 ? "inf" : "-inf"; }

// The shortest text that reads back as v: 0.5 as "0.5", as a user types it.
std::string shortest(double v) {
    char text[32];
    const auto end = std::to_chars(text, text + sizeof text, v).ptr;
    return std::string(text, end);
}

}  // namespace

void set_module(py::module_& m) { module_handle = new py::module_(m); }

double number(const Real& a, const std::string& name) {
    const char* expected = "a number";
    py::object o = a.value;
    if (o.is_none() || is_bool(o) || py::isinstance<py::str>(o) || py::isinstance<py::bytes>(o) ||
        PyByteArray_Check(o.ptr()))
        throw py::type_error(name + ": expected " + expected + ", got " + given(o));
    if (PyComplex_Check(o.ptr())) throw py::type_error(name + ": expected a real number, got " + given(o));
    if (is_numpy(o)) o = numpy_item(o, name, expected, true);
    double v;
    if (PyFloat_Check(o.ptr())) {
        v = PyFloat_AS_DOUBLE(o.ptr());
    } else {
        PyObject* f = PyNumber_Float(o.ptr());  // int, __index__, __float__ (Fraction, Decimal, mpf)
        if (!f) {
            const bool overflow = PyErr_ExceptionMatches(PyExc_OverflowError);
            PyErr_Clear();
            if (overflow) refuse(name + ": " + std::string(py::str(o)).substr(0, 40) + " is too large for a double");
            throw py::type_error(name + ": expected " + expected + ", got " + given(a.value));
        }
        v = PyFloat_AS_DOUBLE(f);
        Py_DECREF(f);
    }
    if (!std::isfinite(v)) refuse(name + ": " + not_finite(v) + " is not a finite number");
    if (v != 0 && std::fabs(v) < DBL_MIN)
        refuse(name + ": " + shortest(v) + " is below the smallest normal double, " + significant(DBL_MIN, 17));
    return v;
}

std::optional<double> number(const std::optional<Real>& a, const std::string& name) {
    if (!a) return std::nullopt;
    return number(*a, name);
}

long long whole(const Whole& a, const std::string& name) {
    const char* expected = "a whole number";
    py::object o = a.value;
    if (o.is_none() || is_bool(o) || PyFloat_Check(o.ptr()) || py::isinstance<py::str>(o) || py::isinstance<py::bytes>(o))
        throw py::type_error(name + ": expected " + expected + ", got " + given(o));
    if (is_numpy(o)) o = numpy_item(o, name, expected, false);
    PyObject* index = PyNumber_Index(o.ptr());
    if (!index) {
        PyErr_Clear();
        throw py::type_error(name + ": expected " + expected + ", got " + given(a.value));
    }
    int overflow = 0;
    const long long v = PyLong_AsLongLongAndOverflow(index, &overflow);
    const std::string shown = py::str(py::handle(index));
    Py_DECREF(index);
    if (overflow) refuse(name + ": " + shown + " is out of range");
    return v;
}

std::optional<long long> whole(const std::optional<Whole>& a, const std::string& name) {
    if (!a) return std::nullopt;
    return whole(*a, name);
}

std::string string_argument(const Text& a, const std::string& name) {
    if (!py::isinstance<py::str>(a.value)) throw py::type_error(name + ": expected a string, got " + given(a.value));
    std::string s;
    try {
        s = a.value.attr("encode")("utf-8", "surrogateescape").cast<std::string>();
    } catch (const py::error_already_set&) {  // a lone surrogate that stands for no byte
        refuse(name + ": not text that UTF-8 can hold (a lone surrogate)");
    }
    if (s.find('\0') != std::string::npos) refuse(name + ": embedded null character");
    return s;
}

std::optional<std::string> string_argument(const std::optional<Text>& a, const std::string& name) {
    if (!a) return std::nullopt;
    return string_argument(*a, name);
}

bool flag(const Flag& a, const std::string& name) {
    if (is_bool(a.value)) return PyObject_IsTrue(a.value.ptr()) == 1;
    if (PyLong_Check(a.value.ptr())) {
        int overflow = 0;
        const long long v = PyLong_AsLongLongAndOverflow(a.value.ptr(), &overflow);
        if (!overflow && (v == 0 || v == 1)) return v == 1;
    }
    throw py::type_error(name + ": expected True or False, got " + given(a.value));
}

void no_other_keywords(const py::kwargs& extra, const char* function, const char* shown) {
    if (extra.empty()) return;
    py::object f = *module_handle;
    std::string path = function;
    for (std::size_t at = 0; at != std::string::npos;) {
        const std::size_t dot = path.find('.', at);
        f = f.attr(path.substr(at, dot == std::string::npos ? std::string::npos : dot - at).c_str());
        at = dot == std::string::npos ? dot : dot + 1;
    }
    const py::object message = module_handle->attr("Result").attr("_unexpected")(f, shown, py::list(extra.attr("keys")()));
    throw py::type_error(message.cast<std::string>());
}

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
    // A masked array's mask would be dropped, and the values under it used.
    const py::module_ np = py::module_::import("numpy");
    if (py::isinstance(obj, np.attr("ma").attr("MaskedArray"))) {
        const long long masked = np.attr("ma").attr("count_masked")(obj).cast<long long>();
        if (masked)
            refuse(what + ": a masked array with " + std::to_string(masked) + " masked element" + (masked == 1 ? "" : "s") +
                   "; give " + what + ".filled(value) or " + what + ".compressed()");
    }
    // As float64 in C order; numpy's own MemoryError (a broadcast view of 10^12 elements) with the
    // argument's name: pybind11's ensure() swallowed it ("cannot create a pybind11::array_t from a nullptr").
    try {
        return np.attr("asarray")(a, "dtype"_a = "float64", "order"_a = "C");
    } catch (py::error_already_set& e) {
        if (!e.matches(PyExc_MemoryError)) throw;
        const std::string message = what + ": " + py::str(e.value()).cast<std::string>();
        PyErr_SetString(PyExc_MemoryError, message.c_str());
        throw py::error_already_set();
    }
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
    if (!py::isinstance<py::iterable>(obj))
        throw py::type_error(what + ": expected a list of records or paths, got " + given(obj));
    std::vector<RecordPtr> out;
    std::size_t k = 0;
    for (py::handle item : py::iter(obj)) out.push_back(record_argument(item, what + "[" + std::to_string(k++) + "]"));
    if (out.empty()) refuse(what + ": no record given");
    return out;
}

void refuse_unresolvable_run(double p, double duration, const std::string& given) {
    const std::string why = dynamics::unresolvable_run(p, duration);
    if (!why.empty()) throw std::invalid_argument(given + ": " + why);
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


int case_argument(const py::object& which_case) {
    const bool integer = !is_bool(which_case) && (PyLong_Check(which_case.ptr()) ||
                                                  py::isinstance(which_case, py::module_::import("numpy").attr("integer")));
    if (!integer) throw py::type_error("case: expected an integer 1..5, got " + given(which_case));
    int overflow = 0;
    const py::object index = py::reinterpret_steal<py::object>(PyNumber_Index(which_case.ptr()));
    const long long which = PyLong_AsLongLongAndOverflow(index.ptr(), &overflow);
    if (overflow || which < 1 || which > 5)
        refuse("case: must be 1, 2, 3, 4 or 5 (got " + std::string(py::str(index)) + ")");
    return static_cast<int>(which);
}

PulseTrain train_argument(const std::optional<Whole>& which_case, const std::optional<Whole>& pulses_given,
                          const py::object& train, std::string& equation) {
    const std::optional<long long> pulses = whole(pulses_given, "pulses");
    const bool has_case = which_case.has_value(), has_train = !train.is_none();
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
    const int which = case_argument(which_case->value);
    const long long pulses_or_2 = pulses.value_or(2);
    if (pulses_or_2 < 1 || pulses_or_2 > 1000) refuse("pulses: must be between 1 and 1000");
    const int n = static_cast<int>(pulses_or_2);
    static const char* eq[] = {"", "eq. 12", "eq. 15", "eq. 19", "eq. 22", "eq. 24"};
    equation = n == 2 ? eq[which] : (n == 6 && which == 2) ? "eq. 27" : (n == 6 && which == 4) ? "eq. 28 (corrected)"
                                                                                             : "superposition (S2)";
    return repeated_case(which, n);
}

double restitution_argument(const py::object& value) {
    if (py::isinstance<py::str>(value)) {
        const std::string word = string_argument(Text{value}, "restitution");
        if (word == "housner") return NAN;
        refuse("restitution: a factor in [0, 1] or 'housner' (got '" + word + "')");
    }
    double e;
    try {
        e = number(Real{value}, "restitution");
    } catch (const py::type_error&) {
        throw py::type_error("restitution: expected a factor in [0, 1] or 'housner', got " + type_name(value));
    }
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

int jobs_argument(const std::optional<Whole>& given) {
    const std::optional<long long> jobs = whole(given, "jobs");
    if (!jobs) return batch::default_threads();
    if (*jobs < 1 || *jobs > 4096) refuse("jobs: must be between 1 and 4096 (got " + std::to_string(*jobs) + ")");
    return static_cast<int>(*jobs);
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
