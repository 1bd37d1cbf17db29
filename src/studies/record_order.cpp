#include "studies/record_order.hpp"

#include <algorithm>
#include <numeric>

#include "batch/sha256.hpp"
#include "harness/table.hpp"

namespace rocking::studies {

std::string sample_digest(const dynamics::SampledInput& input) {
    batch::Sha256 identity;
    identity.update(harness::format_number(input.dt()) + ";");
    identity.update(input.samples().data(), input.samples().size() * sizeof(double));
    return identity.hex();
}

std::string input_digest(const dynamics::GroundInput& input) {
    if (const auto* sampled = dynamic_cast<const dynamics::SampledInput*>(&input)) return sample_digest(*sampled);
    return text_digest("input: " + input.describe());
}

std::vector<std::string> input_digests(const std::vector<const dynamics::GroundInput*>& inputs) {
    std::vector<std::string> out;
    for (const dynamics::GroundInput* in : inputs) {
        if (!in) throw std::invalid_argument("draw order: a record without an input");
        out.push_back(input_digest(*in));
    }
    return out;
}

std::string text_digest(const std::string& text) { return batch::sha256_hex(text); }

std::vector<std::size_t> draw_order(const std::vector<std::string>& identities) {
    std::vector<std::size_t> order(identities.size());
    std::iota(order.begin(), order.end(), std::size_t{0});
    std::stable_sort(order.begin(), order.end(),
                     [&](std::size_t a, std::size_t b) { return identities[a] < identities[b]; });
    return order;
}

}  // namespace rocking::studies
