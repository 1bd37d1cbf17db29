// What a run is of, read as the command line reads it: the block as built
// or by alpha (dynamics/block_geometry.hpp), and a floor's motion in place
// of the ground's (records/floor_motion.hpp).
#include "common.hpp"
#include "json/pieces.hpp"
#include "records/floor_motion.hpp"
#include "records/synthetic.hpp"

namespace rocking::python {

dynamics::GivenBlock block_argument(const std::optional<Real>& thickness, const std::optional<Real>& height,
                                    const std::optional<Real>& half_height, const std::optional<Real>& alpha,
                                    const std::optional<Real>& p) {
    dynamics::BlockSpec s;
    s.thickness = number(thickness, "thickness");
    s.height = number(height, "height");
    s.half_height = number(half_height, "half_height");
    s.alpha = number(alpha, "alpha");
    s.p = number(p, "p");
    try {
        return dynamics::given_block(s, [](const std::string& name) { return name; });
    } catch (const std::invalid_argument& e) {
        refuse(e.what());
    }
}

void add_block_members(py::dict& out, const dynamics::GivenBlock& b) {
    json::Json members;
    json::add_block(members, b);
    for (auto [key, value] : to_python(members).cast<py::dict>()) out[key] = value;
}

RecordPtr with_floor(const RecordPtr& ground, const std::optional<Text>& floor) {
    const std::optional<std::string> text_given = string_argument(floor, "floor");
    if (!text_given) return ground;
    records::FloorModel m;
    try {
        m = records::parse_floor_model(*text_given);
    } catch (const std::invalid_argument& e) {
        refuse("floor: " + std::string(e.what()) + " (T1,G[,zeta]: the building's first period in s, the floor's "
               "participation Gamma phi, the damping ratio)");
    }
    try {
        auto floor_motion = std::make_shared<const records::Record>(records::floor_record(*ground, m));
        // As record_synth: the sampling's warning reaches the caller.
        for (const std::string& w : records::warnings_of(*floor_motion))
            if (PyErr_WarnEx(PyExc_RuntimeWarning, ("floor: " + w).c_str(), 1) != 0) throw py::error_already_set();
        return floor_motion;
    } catch (const std::invalid_argument& e) {
        refuse("floor " + *text_given + " on " + label_of(*ground) + ": " + e.what());
    }
}

}  // namespace rocking::python
