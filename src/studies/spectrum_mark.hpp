// A block marked on a rocking spectrum (issue 40): the engineer's own block
// (alpha, p) read against the spectrum of its alpha.  Its outcome is a run
// at its own p, not a reading of the spectrum's set, which holds only the
// islands its method resolved; beside it, the nearest overturning p of the
// set on either side, as block sizes: for one alpha, p = sqrt(3 g/(4 R))
// (eq. 4) gives R = 3 g/(4 p^2) and the height H = 2 R cos(alpha) (eq. 2),
// so a higher p is a smaller block.
#pragma once

#include <string>
#include <vector>

#include "dynamics/ground_input.hpp"
#include "studies/ida.hpp"
#include "studies/spectrum.hpp"

namespace rocking::studies {

struct SpectrumMark {
    BlockShape block;
    bool overturns = false;        // a run at the block's p, the spectrum's model
    bool in_set = false;           // the spectrum's set (its intervals) holds p
    // The nearest p below p (the larger blocks) and above it (the smaller)
    // at which the set's outcome changes: outside the set, the nearest end
    // of an overturning interval; inside one, that interval's own ends (the
    // nearest surviving blocks lie just beyond them).  Found false where
    // there is none on that side (the spectrum's range ends first).
    SpectrumFirst below, above;
    // Outside the set: the far ends of those nearest overturning intervals
    // (the overturning blocks on that side span below.p back to below_far.p,
    // above.p on to above_far.p), found where they are boundaries: an island
    // 1e-3 wide in ln p, whose near end printed to four digits rounded off it.
    SpectrumFirst below_far, above_far;
    bool refined = false;  // the spectrum's method: refine (its set holds to w) or grid
    // The heights (m) of the blocks of this alpha at below.p and above.p
    // (H = 2 R cos alpha, R = 3 g/(4 p^2)); 0 where not found.
    double height_below = 0, height_above = 0;
    // Inside an interval: how far the surviving blocks beyond each end reach
    // before the set overturns them again (the next interval's end), found
    // false where nothing overturns up to the spectrum's range.  A band
    // narrower than the search's width may be one a finer search splits.
    SpectrumFirst survivors_below, survivors_above;
    double height_survivors_below = 0, height_survivors_above = 0;  // m, at their p; 0 where not found
    // How far the set's reading holds (the spectrum's method): a grid's
    // intervals join its sampled points and may hold survivors and miss
    // islands between them; refine's hold to its width w.
    std::string resolution;
};

// Why the block cannot be marked on a spectrum of these options ("" where
// it can): its p outside [p_min, p_max], where the set says nothing of it.
std::string why_not_markable(const BlockShape& block, const SpectrumOptions& o);

// The height at a far end of the mark's (0 where not found).
double far_height(const SpectrumMark& m, const SpectrumFirst& far);

// H = 2 R cos(alpha), R = 3 g / (4 p^2): the height of the block of slenderness alpha whose pulsation is p (eqs. 2, 4).
double height_at_p(double alpha, double p);

// The block against the spectrum of its alpha (s.alpha must be block.alpha;
// throws std::invalid_argument where why_not_markable says why not).
SpectrumMark mark_block(const dynamics::GroundInput& input, const Spectrum& s, const BlockShape& block,
                        const SpectrumOptions& o);

// The mark in lines: the block and its outcome; its interval's ends, or the
// nearest overturning block on each side, as heights; the surviving bands
// beyond an interval's ends; the set's resolution.  describe_mark joins them
// with "; " (JSON, CSV notes).
std::vector<std::string> describe_mark_lines(const SpectrumMark& m);
std::string describe_mark(const SpectrumMark& m);

}  // namespace rocking::studies
