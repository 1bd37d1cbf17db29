// The Python module's shared pieces: results, arrays, records, trains and the
// options every area parses alike.  Each area is one file (qfactor.cpp,
// records.cpp, dynamics.cpp, studies.cpp) over the library; module.cpp only
// calls their init functions.  The names and units are the command line's
// (src/cli/*.cpp), so that a result equals the same command's --json.
#pragma once

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "dynamics/simulate.hpp"
#include "pulse/pulse_train.hpp"
#include "records/measures.hpp"
#include "records/record.hpp"

namespace rocking::python {

namespace py = pybind11;

// rocking_q.Result: a dict of the command's JSON fields, also readable as
// attributes (as scipy's OptimizeResult).  Defined once, at import.
void define_result(py::module_& m);
py::dict result();            // an empty Result, to fill as a dict
py::object none_if_nan(double v);  // JSON's null: a value that is not finite

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
PulseTrain train_argument(const py::object& which_case, const std::optional<int>& pulses, const py::object& train,
                          std::string& equation);

// --restitution: a factor in [0, 1] or "housner" (NaN).
double restitution_argument(const py::object& value);
// --rtol and --atol (rad) into the solver's options, as tolerance_options.
void tolerance_arguments(const std::optional<double>& rtol, const std::optional<double>& atol, double alpha,
                         dynamics::SolverOptions& solver);
// --jobs: the threads of a study, by default the cores this process may use.
int jobs_argument(const std::optional<int>& jobs);

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
void init_batch(py::module_& m);

}  // namespace rocking::python
