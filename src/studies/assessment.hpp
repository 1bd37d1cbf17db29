// The engineer's check of a block against records (issue 40, `rocking
// assess`): the paper's eq. 27 check with its margin, and what the model
// itself says of the same block and record, each a number with its method:
//   - eq. 27: x = p to_5 (to_5 = pi PGV/PGA, eq. 31), q_27 = q2_n6(x) (eq. 27),
//     the record's q = PGA/(alpha g); ratio q/q_27 and margin 1 - q/q_27
//     (positive: the record's q lies below eq. 27's, the check passes); an
//     imperfect block's q_27 toward each corner (studies/eq27_of_block.hpp);
//   - the run on the record as recorded: peak |theta|/alpha and overturning
//     (linearised eq. 3, exact solver, Housner's restitution, the free
//     rocking after the input followed: Table 1's model);
//   - the factor by which the record must be scaled for the block to first
//     overturn, and to first robustly collapse (the IDA's first overturning
//     and first robust collapse, refine method of docs/overturning_set.md at
//     width w, over q in [q_min, q_max]), divided by the record's q;
//   - the nearest overturning block of this alpha, above and below in size
//     (the record's rocking spectrum at alpha, refine method at w, the block
//     marked: studies/spectrum_mark.hpp);
//   - with several records, the lognormal fragility of the block over them
//     (its first overturnings) and its probability of overturning at each
//     record's own q (eq. F1 of studies/fragility.hpp).
#pragma once

#include <string>
#include <vector>

#include "dynamics/ground_input.hpp"
#include "records/measures.hpp"
#include "studies/ida.hpp"
#include "studies/spectrum_mark.hpp"

namespace rocking::studies {

struct AssessOptions {
    records::CollapseOptions model{};  // Table 1's
    double width = 1e-3;               // the refine searches' w, in ln q and ln p
    double q_max = 20;                 // the IDA's range, from q = 1, or to twice the record's q where higher (at most 1e4)
    double p_min = 0.3, p_max = 30;    // the spectrum's range, rad/s
    std::string describe() const;
    // The IDA's upper q for a record of this q: q_max, or twice the record's
    // q where higher, at most 1e4.
    double ida_q_max(double q_record) const;
    // The check, in words: eq. 27 as printed, or toward each corner of an imperfect block.
    std::string describe_check() const;
    // The spectrum's: the model, [p_min, p_max] widened to hold the block's p
    // with a factor 1.5 to spare (within [0.01, 1000] rad/s), and the refine
    // search at width.
    // alpha: the block's (with --fc the range starts above the blocks of
    // that slenderness that crush under their own weight).
    SpectrumOptions spectrum_options(double block_p, double alpha) const;
};

struct RecordAssessment {
    records::PeakMotion motion;
    double x = 0, q_eq27 = 0, q_record = 0, ratio = 0, margin = 0;
    bool passes = false;  // q_record < q_eq27
    // An imperfect block's q_eq27 is eq. 27 toward each corner, the smaller
    // (studies/eq27_of_block.hpp); beside it the paper's, at the nominal
    // alpha and p, and the corner it overturns toward (+1 or -1).
    double q_eq27_as_printed = 0;
    int eq27_side = +1;
    // Where eq. 27's own closed form stops holding at this x (its train, case
    // 2 with 6 pulses, at its collapse q: qfactor/superposition.hpp): theta
    // passes alpha before t_fin (from x = 0.8 on), or the block strikes the
    // ground before it.  rocking q prints the same warnings.
    bool eq27_passes_alpha = false, eq27_strikes = false;
    // The run on the record as recorded.
    double peak_theta_over_alpha = 0;  // max |theta|/alpha during the input (the fall angle's where it fell)
    bool overturns = false;
    bool fell_during_input = false;
    // The IDA: the scale factors (q / q_record) of its first overturning and
    // first robust collapse, found false (censored at q_max) without one.
    Ida ida;
    double scale_first_overturning = 0, scale_first_robust = 0;
    // The overturning intervals (in q) that start at each: the first
    // overturning is often an island 1e-6 wide, which a q rounded to four
    // digits misses.  {0, 0} where not found.
    double first_overturning_to = 0, first_robust_to = 0;
    bool first_overturning_open = false, first_robust_open = false;  // the interval runs to the search's end
    // The block on the record's spectrum at its alpha, and that spectrum (its options: spectrum_options).
    SpectrumMark mark;
    Spectrum spectrum;
    // With several records: P(overturn) of the fragility at q_record.
    bool has_probability = false;
    double probability = 0;
};

struct Assessment {
    BlockShape block;
    std::vector<RecordAssessment> records;  // in the inputs' order
    bool fitted = false;                    // with two records or more, where the fit has a maximum
    std::string no_fit;                     // why not, otherwise
    LognormalFragility fit;
};

// Why the block cannot be assessed on this record, or none: eq. 27's x =
// p to_5 below 1e-150, where q2_n6 overflows (the block's fault: its p),
// the record's q = PGA/(alpha g) overflowing a double, or a record that
// never moves (the record's).  The front ends name the option or the file.
struct Refusal {
    enum class Blame { none, block, record } blame = Blame::none;
    std::string why;
};
Refusal refusal_of(const dynamics::SampledInput& input, const records::PeakMotion& m, const BlockShape& block);

// The inputs in g (each a record), their peak motions (PGA in m/s^2, as
// records::peak_motion measures them), the block.  Throws
// std::invalid_argument where eq. 27 cannot be evaluated (x below 1e-150).
Assessment assess_block(const std::vector<const dynamics::SampledInput*>& inputs,
                        const std::vector<records::PeakMotion>& motions, const BlockShape& block, const AssessOptions& o);

}  // namespace rocking::studies
