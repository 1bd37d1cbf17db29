// A block marked on a rocking spectrum (issue 40): the engineer's own block
// (alpha, p) read against the spectrum of its alpha.  Its outcome is a run
// at its own p, not a reading of the spectrum's set, which holds only the
// islands its method resolved; beside it, the nearest overturning p of the
// set on either side, as block sizes: for one alpha, p = sqrt(3 g/(4 R))
// (eq. 4) gives R = 3 g/(4 p^2) and the height H = 2 R cos(alpha) (eq. 2),
// so a higher p is a smaller block.
#pragma once

#include <string>

#include "dynamics/ground_input.hpp"
#include "studies/ida.hpp"
#include "studies/spectrum.hpp"

namespace rocking::studies {

struct SpectrumMark {
    BlockShape block;
    bool overturns = false;        // a run at the block's p, the spectrum's model
    bool in_set = false;           // the spectrum's set (its intervals) holds p
    // The nearest p of the set at or below p (the larger blocks) and at or
    // above it (the smaller), found false where the set has none on that side.
    SpectrumFirst below, above;
    // The heights (m) of the blocks of this alpha at below.p and above.p
    // (H = 2 R cos alpha, R = 3 g/(4 p^2)); 0 where not found.
    double height_below = 0, height_above = 0;
};

// H = 2 R cos(alpha), R = 3 g / (4 p^2): the height of the block of slenderness alpha whose pulsation is p (eqs. 2, 4).
double height_at_p(double alpha, double p);

// The block against the spectrum of its alpha (s.alpha must be block.alpha).
SpectrumMark mark_block(const dynamics::GroundInput& input, const Spectrum& s, const BlockShape& block,
                        const SpectrumOptions& o);

// One line: "block 0.6x4 (p 1.90737 rad/s): overturns (a run at its p); the set holds it ..."
std::string describe_mark(const SpectrumMark& m);

}  // namespace rocking::studies
