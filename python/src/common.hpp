// The Python module's shared pieces: results, arrays, records, trains and the
// options every area parses alike.  Each area is one file (qfactor.cpp,
// records.cpp, dynamics.cpp, studies.cpp, eq27.cpp, batch.cpp) over the
// library; module.cpp only calls their init functions.  The names and units are the command line's
// (src/cli/*.cpp), so that a result equals the same command's --json.
#pragma once

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "dynamics/block_geometry.hpp"
#include "dynamics/simulate.hpp"
#include "json/document.hpp"
#include "pulse/pulse_train.hpp"
#include "records/measures.hpp"
#include "records/record.hpp"

namespace rocking::python {

namespace py = pybind11;

// Arguments converted in the function's body, not by pybind11's overload
// resolution: a wrong type there is "incompatible function arguments" with the
// whole signature, naming no argument (or "Unable to cast Python instance to
// C++ type").  Each of these loads any object and shows in signatures as the
// type it stands for (float, int, str, bool); number(), whole(),
// string_argument() and flag() convert it or refuse it naming the keyword.
struct Real {
    py::object value;
};
struct Whole {
    py::object value;
};
struct Text {
    py::object value;
};
struct Flag {
    py::object value;
};

// A finite double, normal or 0 (the command line's rule for a parameter,
// numerics/number_text.hpp, in its words): Python's and numpy's real numbers
// and 0-d arrays, anything with __float__ or __index__; not bool, str, bytes,
// complex or an array of more than 0 dimensions (TypeError); nan, inf and
// subnormals are a ValueError,
// "x: inf is not a finite number" as the command line's "--x: 'inf' is not a
// finite number".
double number(const Real& a, const std::string& name);
std::optional<double> number(const std::optional<Real>& a, const std::string& name);
// An integer (Python's, numpy's, anything with __index__; not bool or float),
// a ValueError beyond the range of long long.
long long whole(const Whole& a, const std::string& name);
std::optional<long long> whole(const std::optional<Whole>& a, const std::string& name);
// A str as its UTF-8 bytes (surrogates from os.fsdecode back to their bytes);
// a NUL in it is refused.
std::string string_argument(const Text& a, const std::string& name);
std::optional<std::string> string_argument(const std::optional<Text>& a, const std::string& name);
// True or False (bool, numpy.bool_, or the integers 0 and 1).
bool flag(const Flag& a, const std::string& name);
// The keywords a function does not take, caught by its **kwargs: a TypeError
// as Python's own, "simulate() got an unexpected keyword argument 'aplha' (did
// you mean 'alpha'?)".  function is the module's attribute ("simulate",
// "Record.__init__"), shown as shown.
void no_other_keywords(const py::kwargs& extra, const char* function, const char* shown);
void set_module(py::module_& m);

// rocking_q.Result: a dict of the command's JSON fields, also readable as
// attributes (as scipy's OptimizeResult).  Defined once, at import.
void define_result(py::module_& m);
py::dict result();            // an empty Result, to fill as a dict
py::object none_if_nan(double v);  // JSON's null: a value that is not finite

// A document of the library (src/json/document.hpp), the command's --json, as
// Python values: an object a Result (or, Dicts::plain, a dict) with the keys
// in the document's order, an array a list, a string as text() decodes it, an
// integer an int, a double a float (nan and inf too: where the command line
// prints null, the caller says what Python holds), null None.  What Python
// gives otherwise (NumPy arrays, a file's path as os.fsdecode gives it, the
// order of some keys) each function puts in place after.
enum class Dicts { results, plain };
py::object to_python(const json::Json& v, Dicts dicts = Dicts::results);
// d (a dict or a Result) with those of keys it has moved to stand before the
// key `before`, the others in their order: the module's order where it has its own.
py::dict with_keys_before(const py::dict& d, const std::vector<const char*>& keys, const char* before);

// A bad argument, said as the command line says it with the keyword's name:
// a ValueError.
[[noreturn]] void refuse(const std::string& message);

// The module's C++ exceptions as Python's, as pybind11 maps them (ValueError for
// invalid_argument, RuntimeError for runtime_error, ...; record_error for
// records::RecordError), but with each message decoded as os.fsdecode decodes a
// file's name: a message that holds a name whose bytes are not UTF-8 came
// through pybind11 as an exception with no message at all.
void install_exception_translator(py::handle record_error);

// A real array (integer or floating dtype, at most 64 bits) as float64,
// C-contiguous; anything else (bool, complex, object, text, dates, long
// double) is refused with a TypeError naming `what`, its dtype and the one expected.
py::array_t<double> real_array(py::handle obj, const std::string& what);
// The same, 1-D, as a vector; a TypeError names the shape when it is not 1-D.
std::vector<double> real_vector(py::handle obj, const std::string& what);
// A vector as a new float64 array (the caller owns it).
py::array_t<double> to_array(const std::vector<double>& v);

// A record argument: a rocking_q.Record, or a path (str or os.PathLike) read
// as `rocking record info FILE` reads it (ESM or PEER by content).
using RecordPtr = std::shared_ptr<const records::Record>;
// A Record method's self: a TypeError when it was made by Record.__new__ without
// its constructor (no Record behind it: pybind11 would give the method unwritten memory).
RecordPtr held(py::handle self);
RecordPtr record_argument(py::handle obj, const std::string& what);
// A path (str, bytes or os.PathLike) as os.fsencode gives it; a NUL in it is refused.
std::string file_argument(py::handle obj, const std::string& what);
std::vector<RecordPtr> record_list(py::handle obj, const std::string& what);
// floor="T1,G[,zeta]" as the command line's --floor: the floor's record of
// the building's first mode in place of the ground's (records/floor_motion.hpp);
// the record itself without it.
RecordPtr with_floor(const RecordPtr& ground, const std::optional<Text>& floor);
// The record's file as given, or its name when it was made from an array:
// what the command line's messages and "file" fields hold.
std::string label_of(const records::Record& r);
// The same as Python text: a file's path as os.fsdecode gives it, a name decoded.
py::object file_of(const records::Record& r);
// None for a record made from an array or synthesised, else the file's path.
py::object path_of(const records::Record& r);
// Bytes from a file (a record's name, a header value) as text: ill-formed
// UTF-8 becomes U+FFFD, as the command line's JSON writes it.
py::str text(const std::string& s);
// The record's half-periods, refused with its label where they cannot be
// measured (the command line's half_periods_of, src/cli/options.cpp).
records::HalfPeriods checked_half_periods(const records::Record& r);

// The input train from case/pulses or train, as `rocking q` takes
// --case/--pulses or --train, and the equation it names.  train is a string
// "A:d,A:d,..." or a sequence of (amplitude, duration) pairs (an (n, 2) array).
PulseTrain train_argument(const std::optional<Whole>& which_case, const std::optional<Whole>& pulses,
                          const py::object& train, std::string& equation);
// case: an integer 1..5 (bool and float refused with a TypeError).
int case_argument(const py::object& which_case);

// A run the solvers cannot follow (dynamics::unresolvable_run: p times the
// input's duration above 1e9), refused before it starts with a ValueError
// (std::invalid_argument, so that it may be thrown without the GIL) naming
// `given`, the arguments that set p and the input ("p_max with record
// wave.txt"), as the command line names its options; the solver's "no
// progress" deep in the run named neither.
void refuse_unresolvable_run(double p, double duration, const std::string& given);

// --restitution: a factor in [0, 1] or "housner" (NaN).
double restitution_argument(const py::object& value);
// The block from thickness and height (m) or alpha with p, half_height or
// height, as the command line reads it (dynamics/block_geometry.hpp), refused
// naming the keywords; its members (given, thickness, height, R) added to out.
dynamics::GivenBlock block_argument(const std::optional<Real>& thickness, const std::optional<Real>& height,
                                    const std::optional<Real>& half_height, const std::optional<Real>& alpha,
                                    const std::optional<Real>& p);
void add_block_members(py::dict& out, const dynamics::GivenBlock& b);
// --rtol and --atol (rad) into the solver's options, as tolerance_options.
void tolerance_arguments(const std::optional<double>& rtol, const std::optional<double>& atol, double alpha,
                         dynamics::SolverOptions& solver);
// --jobs: the threads of a study, by default the cores this process may use.
int jobs_argument(const std::optional<Whole>& jobs);

// GSL errors.  GSL's default handler aborts the process: from Python, the
// interpreter with every result in it.  At import the module installs a
// handler that, while a call of the module runs (a GslWatch is alive, in any
// thread), records the error and lets GSL return its error code; outside the
// module's calls it does what the handler it replaced did (GSL's default:
// the message, then abort), so other users of GSL in the process see no
// change.  The handler cannot tell which call an error belongs to: one raised
// while two calls run in two threads fails both.
void install_gsl_handler();
void on_gsl_error(const char* reason, const char* file, int line, int code);
class GslWatch {
public:
    GslWatch();
    ~GslWatch();
    GslWatch(const GslWatch&) = delete;
    GslWatch& operator=(const GslWatch&) = delete;
    // A RuntimeError (std::runtime_error) with GSL's first message if GSL reported an error since construction.
    void check() const;

private:
    friend void on_gsl_error(const char*, const char*, int, int);
    std::string message_;  // GSL's first error during the call, under the handler's mutex
};
// f as a function that raises GSL's error, if GSL reported one during the call,
// in place of its result or of the exception the library threw after it.
template <class R, class... A>
auto gsl_checked(R (*f)(A...)) {
    return [f](A... args) -> R {
        const GslWatch watch;
        try {
            R r = f(std::forward<A>(args)...);
            watch.check();
            return r;
        } catch (...) {
            watch.check();
            throw;
        }
    };
}

// %.*g, as the command line's significant().
std::string significant(double v, int n);

void init_qfactor(py::module_& m);
void init_records(py::module_& m);
void init_dynamics(py::module_& m);
void init_studies(py::module_& m);
void init_eq27(py::module_& m);
void init_batch(py::module_& m);

}  // namespace rocking::python

namespace pybind11::detail {
// Real, Whole, Text and Flag load any object (None too: the body says "alpha:
// expected a number, got None"); std::optional of them takes None as absent.
template <class T>
struct any_object_caster {
    bool load(handle src, bool) {
        if (!src) return false;
        value.value = reinterpret_borrow<object>(src);
        return true;
    }
    static handle cast(const T& v, return_value_policy, handle) { return v.value.inc_ref(); }
    T value;
    operator T*() { return &value; }
    operator T&() { return value; }
    operator T&&() && { return std::move(value); }
    template <typename U>
    using cast_op_type = pybind11::detail::movable_cast_op_type<U>;
};
template <>
struct type_caster<rocking::python::Real> : any_object_caster<rocking::python::Real> {
    static constexpr auto name = const_name("float");
};
template <>
struct type_caster<rocking::python::Whole> : any_object_caster<rocking::python::Whole> {
    static constexpr auto name = const_name("int");
};
template <>
struct type_caster<rocking::python::Text> : any_object_caster<rocking::python::Text> {
    static constexpr auto name = const_name("str");
};
template <>
struct type_caster<rocking::python::Flag> : any_object_caster<rocking::python::Flag> {
    static constexpr auto name = const_name("bool");
};
}  // namespace pybind11::detail
