// rocking_q: the Python front end of the one library (rocking_core), with the
// command line's names and units; docs/python.md.
#include <gsl/gsl_cdf.h>

#include "common.hpp"

PYBIND11_MODULE(rocking_q, m) {
    using namespace rocking::python;
    m.doc() = R"(rocking_q: Housner's rocking block and the q-factor of Coccia (Buildings 2025, 15, 2622).

The command line's subcommands as functions, with its option names (--half-height as half_height)
and units, returning its --json fields as a Result (a dict readable by attribute) with NumPy arrays:
q, q_info, response, q1..q5, q_case, q2_n6, q4_n6; simulate, block; Record, read_record,
record_info, half_periods, peak_motion, record_synth; collapse, assess; spectrum, fragility, eq27;
batch (a manifest of jobs to a results file).
Errors raise ValueError (RecordError for a malformed file, naming file and line), TypeError, or
RuntimeError, with the library's message.  Long calls release the GIL.  docs/python.md)";
    set_module(m);
    install_gsl_handler();
    define_result(m);
    init_qfactor(m);
    init_records(m);
    init_dynamics(m);
    init_studies(m);
    init_eq27(m);
    init_batch(m);
    // For the tests (test_hostile.py): an error inside GSL during a call of the module, which no
    // argument of the public functions is known to reach (GSL's gamma inverse at the shape 1e7).
    m.def("_provoke_gsl_error", gsl_checked(+[]() -> double { return gsl_cdf_gamma_Pinv(0.95, 1e7, 1.0); }),
          "For the tests: makes GSL report an error during a call; raises RuntimeError.");
}
