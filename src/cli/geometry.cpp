#include "cli/geometry.hpp"

#include "studies/search_alpha.hpp"

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

std::vector<GivenBlock> block_list_option(const Args& a, const std::string& flag) {
    try {
        return dynamics::block_list(a.values.at(flag), flag);
    } catch (const std::invalid_argument& e) {
        throw UsageError(e.what());
    }
}

std::vector<studies::BlockShape> study_blocks(const Args& a, const std::string& flag) {
    if (flag == "--block" && (a.values.count("--alpha") || a.values.count("--p")))
        throw UsageError("--block gives each block's alpha and p: give it without --alpha and --p");
    std::vector<studies::BlockShape> out;
    for (const GivenBlock& g : block_list_option(a, flag)) {
        if (!studies::in_search_alpha_range(g.block.alpha))
            throw UsageError(flag + " " + g.label + ": alpha = atan(B/H) = " + significant(g.block.alpha, 6) +
                             " rad, outside the searches' " + studies::kSearchAlphaRange);
        if (!(g.block.p > 0.01 && g.block.p < 1000))
            throw UsageError(flag + " " + g.label + ": p = " + significant(g.block.p, 6) +
                             " rad/s, outside the studies' (0.01, 1000) rad/s");
        out.push_back({g.block.alpha, g.block.p, g.label});
    }
    return out;
}

std::string block_json(const GivenBlock& b) {
    const bool sized = b.sized();
    return std::string("\"given\": \"") + dynamics::given_name(b) + "\", \"thickness\": " +
           (sized ? json_number(b.thickness) : std::string("null")) +
           ", \"height\": " + (sized ? json_number(b.height) : std::string("null")) +
           ", \"R\": " + (sized ? json_number(b.block.R) : std::string("null"));
}

}  // namespace rocking::cli
