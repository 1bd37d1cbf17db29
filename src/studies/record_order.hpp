// The order in which every bootstrap over records draws them (issue 40,
// item 6).  A bootstrap draws record indices from a seeded mt19937
// (resampling.hpp): index k is whichever record stands k-th.  Had that been
// the order the records were given in, the same seed would give another
// interval for the same records listed otherwise (a shell glob sorts by the
// locale), and two users could not compare intervals.  So the studies draw
// the records in the order of their identities, a digest of what they are,
// never of how they were named or listed:
//   - a record read from a file or given as samples: sample_digest, the
//     SHA-256 of its step and its samples in g (the identity that the
//     studies' rows files already keep, jobs/fragility_plan.hpp, and that
//     refuses a record given twice, distinct_inputs.hpp);
//   - any other input (a pulse train, a one-sine pulse): the SHA-256 of its
//     description;
//   - a caller may give its own identities instead: the fragility scene
//     names each record generated at run time by its generator's definition,
//     since such a record's last bits follow the libm (docs/synthetic.md).
// Equal identities (the same record twice, which the front ends refuse but
// the library takes) keep their given order among themselves: the records
// are then the same samples, the same IDAs and the same data, so which
// stands first changes no draw's outcome.  The listing of every output stays
// in the given order; only the fits and their bootstraps see this one.
#pragma once

#include <cstddef>
#include <stdexcept>
#include <string>
#include <vector>

#include "dynamics/ground_input.hpp"

namespace rocking::studies {

// The SHA-256, in 64 lowercase hex digits, of the step's %.17g text and ';'
// followed by the samples in g as doubles (their 8 bytes each, in this
// machine's order: little-endian IEEE on every platform built here).  A file
// reformatted with the same samples is the same record; a pipe, read once,
// has one too.
std::string sample_digest(const dynamics::SampledInput& input);

// sample_digest for a sampled input; for any other, the SHA-256 of
// "input: " followed by describe().
std::string input_digest(const dynamics::GroundInput& input);
std::vector<std::string> input_digests(const std::vector<const dynamics::GroundInput*>& inputs);

// The SHA-256 of a text, in hex (a generated record's definition).
std::string text_digest(const std::string& text);

// The draw order: the positions 0 .. n-1 sorted by their identities (as
// byte strings; hex digests sort as their numbers), equal identities in
// their given order.
std::vector<std::size_t> draw_order(const std::vector<std::string>& identities);

// v's elements in `order` (one of draw_order's).  Throws
// std::invalid_argument when the sizes differ.
template <class T>
std::vector<T> in_draw_order(const std::vector<T>& v, const std::vector<std::size_t>& order) {
    if (order.size() != v.size())
        throw std::invalid_argument("draw order: " + std::to_string(order.size()) + " identities for " +
                                    std::to_string(v.size()) + " records");
    std::vector<T> out;
    out.reserve(v.size());
    for (const std::size_t k : order) out.push_back(v.at(k));
    return out;
}

}  // namespace rocking::studies
