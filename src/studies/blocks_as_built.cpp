#include "studies/blocks_as_built.hpp"

#include <cstdio>
#include <stdexcept>

#include "dynamics/block_geometry.hpp"
#include "studies/search_alpha.hpp"

namespace rocking::studies {

std::vector<BlockShape> blocks_as_built(const std::string& text, const std::string& what) {
    std::vector<BlockShape> out;
    char number[40];
    for (const dynamics::GivenBlock& g : dynamics::block_list(text, what)) {
        if (!in_search_alpha_range(g.block.alpha)) {
            std::snprintf(number, sizeof number, "%.6g", g.block.alpha);
            throw std::invalid_argument(what + " " + g.label + ": alpha = atan(B/H) = " + number +
                                        " rad, outside the searches' " + kSearchAlphaRange);
        }
        if (!in_search_p_range(g.block.p)) {
            std::snprintf(number, sizeof number, "%.6g", g.block.p);
            throw std::invalid_argument(what + " " + g.label + ": p = " + number + " rad/s, outside the studies' " +
                                        kSearchPRange);
        }
        out.push_back({g.block.alpha, g.block.p, g.label});
    }
    return out;
}

}  // namespace rocking::studies
