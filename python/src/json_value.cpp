// The library's documents as Python values (common.hpp, to_python).
#include "common.hpp"

#include <algorithm>
#include <cstdint>

namespace rocking::python {

py::object to_python(const json::Json& v, Dicts dicts) {
    using Type = json::Json::value_t;
    switch (v.type()) {
    case Type::object: {
        py::dict d = dicts == Dicts::results ? result() : py::dict();
        for (auto member = v.begin(); member != v.end(); ++member) d[text(member.key())] = to_python(member.value(), dicts);
        return std::move(d);
    }
    case Type::array: {
        py::list l(v.size());
        for (std::size_t k = 0; k < v.size(); ++k) l[k] = to_python(v[k], dicts);
        return std::move(l);
    }
    case Type::string: return text(v.get_ref<const std::string&>());
    case Type::boolean: return py::bool_(v.get<bool>());
    case Type::number_integer: return py::int_(v.get<std::int64_t>());
    case Type::number_unsigned: return py::int_(v.get<std::uint64_t>());
    // A value that is not finite stays a float: the command line's null beside it says why.
    case Type::number_float: return py::float_(v.get<double>());
    case Type::null: return py::none();
    case Type::binary:
    case Type::discarded: break;
    }
    throw std::logic_error("to_python: a value JSON has no Python value for");
}

py::dict with_keys_before(const py::dict& d, const std::vector<const char*>& keys, const char* before) {
    if (!d.contains(before)) return d;
    py::dict out = py::type::of(d)();
    for (auto [key, value] : d) {
        const std::string name = py::str(key);
        if (name == before)
            for (const char* k : keys)
                if (d.contains(k)) out[k] = d[k];
        if (std::find(keys.begin(), keys.end(), name) == keys.end()) out[key] = value;
    }
    return out;
}

}  // namespace rocking::python
