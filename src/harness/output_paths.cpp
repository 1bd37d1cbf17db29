#include "harness/output_paths.hpp"

#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <stdexcept>

#include <sys/stat.h>
#include <unistd.h>

#include "harness/atomic_file.hpp"

namespace rocking::harness {

namespace {

bool regular(const std::string& path, struct stat& s) { return ::stat(path.c_str(), &s) == 0 && S_ISREG(s.st_mode); }

// An output that does not exist yet, as its folder's real path and its name:
// "out/x.csv" and "./out/../out/x.csv" are one file before either is written.
std::string future_identity(const std::string& path) {
    const auto slash = path.find_last_of('/');
    const std::string folder = slash == std::string::npos ? "." : slash == 0 ? "/" : path.substr(0, slash);
    const std::string name = slash == std::string::npos ? path : path.substr(slash + 1);
    char* real = ::realpath(folder.c_str(), nullptr);
    if (!real) return path;  // check_writable says what is wrong with the folder
    std::string out = std::string(real) + "/" + name;
    std::free(real);
    return out;
}

std::string quoted(const NamedPath& p) { return p.role + " '" + p.path + "'"; }

}  // namespace

bool same_file(const std::string& a, const std::string& b) {
    struct stat sa {}, sb {};
    return regular(a, sa) && regular(b, sb) && sa.st_dev == sb.st_dev && sa.st_ino == sb.st_ino;
}

void refuse_outputs_over_inputs(const std::vector<NamedPath>& outputs, const std::vector<NamedPath>& inputs) {
    for (const NamedPath& out : outputs)
        for (const NamedPath& in : inputs)
            if (same_file(out.path, in.path))
                throw std::invalid_argument(quoted(out) + " is the input " + quoted(in) +
                                            ": writing it would replace the input; choose another file");
    for (std::size_t i = 0; i < outputs.size(); ++i)
        for (std::size_t j = i + 1; j < outputs.size(); ++j) {
            struct stat s {};
            const std::string& a = outputs[i].path;
            const std::string& b = outputs[j].path;
            const bool one = same_file(a, b) ||
                             (::stat(a.c_str(), &s) != 0 && ::stat(b.c_str(), &s) != 0 &&
                              future_identity(a) == future_identity(b));
            if (one)
                throw std::invalid_argument(quoted(outputs[i]) + " and " + quoted(outputs[j]) +
                                            " are one file: the second would replace the first");
        }
}

void refuse_empty_name(const NamedPath& output) {
    if (output.path.empty()) throw std::invalid_argument(output.role + ": an empty file name");
}

void check_writable(const NamedPath& output) {
    refuse_empty_name(output);
    struct stat s {};
    if (::stat(output.path.c_str(), &s) == 0 && !S_ISREG(s.st_mode) && !S_ISDIR(s.st_mode)) {
        if (::access(output.path.c_str(), W_OK) != 0)
            throw std::runtime_error(output.role + ": " + output.path + ": cannot write: " + std::strerror(errno));
        return;
    }
    try {
        AtomicFile probe(output.path);  // its temporary file is removed when it goes
    } catch (const std::runtime_error& e) {
        throw std::runtime_error(output.role + ": " + e.what());
    }
}

void check_outputs(const std::vector<NamedPath>& outputs, const std::vector<NamedPath>& inputs) {
    for (const NamedPath& out : outputs) refuse_empty_name(out);
    refuse_outputs_over_inputs(outputs, inputs);
    for (const NamedPath& out : outputs) check_writable(out);
}

}  // namespace rocking::harness
