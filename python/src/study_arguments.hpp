// The arguments the studies of the Python module (studies.cpp, eq27.cpp)
// read alike, in the command line's words (src/cli/fragility.cpp, eq27.cpp).
#pragma once

#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "common.hpp"
#include "dynamics/ground_input.hpp"
#include "studies/ida.hpp"
#include "studies/spectrum.hpp"

namespace rocking::python {

std::string g7(double v);

// A list of numbers, or one number, each in (lo, hi): --alpha A[,A...], --p P[,P...].
std::vector<double> values_in(const py::object& given, const std::string& what, double lo, double hi,
                              const std::string& range, std::size_t most);

// The record in g, as the commands read it.
std::unique_ptr<dynamics::SampledInput> input_of(const records::Record& r);

// bootstrap=K and seed=S as --bootstrap K --seed S: the resamples (0 when not
// asked, -1 or 100001 beyond the callers' range, which they refuse), the seed
// into seed_out.
int bootstrap_argument(const std::optional<Whole>& bootstrap_given, const std::optional<Whole>& seed_given,
                       std::uint64_t& seed_out);

// How a study finds its set of collapse (issue 39), as the command line's
// --method, --width and --robust-width (cli::method_options), in ln of the
// study's parameter `unit` ("q" or "p").
struct MethodChoice {
    bool refine = false;
    double width = 1e-5, robust_width = 5e-3;
};
MethodChoice method_argument(const Text& method_given, const std::optional<Real>& width_given,
                             const std::optional<Real>& robust_width_given, const std::string& unit);
// The same into an IDA's options (unit q).
void method_argument(const Text& method_given, const std::optional<Real>& width_given,
                     const std::optional<Real>& robust_width_given, studies::IdaOptions& ida);

// The nearest overturning p of a spectrum on one side, as --json writes it
// (json::nearest_json), a Result.
py::dict nearest_side(const studies::SpectrumFirst& f, double height);

// restitution=E|"housner" into a study's model, as the command line's --restitution.
void restitution_into(const py::object& value, records::CollapseOptions& model);
// friction=MU (None: no sliding) into a study's model, as --friction: in
// (0, 1e6], refused beside a numeric restitution (the sliding-rocking
// model's impacts follow from impulse and momentum).
void friction_into(const py::object& value, const py::object& restitution, records::CollapseOptions& model);
// imperfection={"lean": rad, "out_of_plumb": rad, "fc": MPa, "density": kg/m3}
// (None: the perfect block), as --lean, --out-of-plumb, --fc, --density:
// ValueError naming the key, refused beside friction.
dynamics::Imperfection imperfection_argument(const py::object& value, const records::CollapseOptions& model);
void imperfection_into(const py::object& value, records::CollapseOptions& model);
// As rocking simulate --json's "imperfection" (json::imperfection_json), as
// plain dicts (the module's results have always held it so).
py::dict imperfection_dict(const dynamics::Imperfection& imp, const dynamics::Block& base, double restitution);

}  // namespace rocking::python
