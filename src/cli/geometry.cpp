#include "cli/geometry.hpp"

#include "studies/blocks_as_built.hpp"

#include <optional>
#include <stdexcept>

namespace rocking::cli {

namespace {

std::optional<double> optional_number(const Args& a, const std::string& flag) {
    if (!a.values.count(flag)) return std::nullopt;
    return number(flag, a.values.at(flag));
}

std::string flag_of(const std::string& argument) {
    return argument == "half_height" ? "--half-height" : "--" + argument;
}

}  // namespace

const std::vector<std::string>& geometry_flags() {
    static const std::vector<std::string> flags = {"--thickness", "--height", "--half-height", "--alpha", "--p"};
    return flags;
}

GivenBlock block_option(const Args& a) {
    dynamics::BlockSpec s;
    s.thickness = optional_number(a, "--thickness");
    s.height = optional_number(a, "--height");
    s.half_height = optional_number(a, "--half-height");
    s.alpha = optional_number(a, "--alpha");
    s.p = optional_number(a, "--p");
    try {
        return dynamics::given_block(s, flag_of);
    } catch (const std::invalid_argument& e) {
        throw UsageError(e.what());
    }
}

std::vector<studies::BlockShape> study_blocks(const Args& a, const std::string& flag) {
    if (flag == "--block" && (a.values.count("--alpha") || a.values.count("--p")))
        throw UsageError("--block gives each block's alpha and p: give it without --alpha and --p");
    try {
        return studies::blocks_as_built(a.values.at(flag), flag);
    } catch (const std::invalid_argument& e) {
        throw UsageError(e.what());
    }
}

}  // namespace rocking::cli
