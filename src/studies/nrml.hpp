// A fragility study's curves as an OpenQuake fragility model (NRML 0.5, the
// Natural hazards' Risk Markup Language of the OpenQuake engine): one
// continuous lognormal fragility function per block, limit state
// "overturning", intensity measure PGA in g (docs/fragility.md, "The NRML
// export").
//
// The study's curve is P(overturn | q) = Phi(ln(q / median) / beta) with
// q = PGA/(alpha g), so in PGA (g) it is the lognormal of median
//     theta = median * alpha                                            (N1)
// and the same beta.  NRML's continuous functions take the mean and standard
// deviation of the intensity itself, not of its logarithm:
//     mean = theta e^(beta^2/2),   stddev = mean sqrt(e^(beta^2) - 1),   (N2)
// which the engine turns back into sigma = sqrt(ln(1 + stddev^2/mean^2)) =
// beta and scale = mean^2 / sqrt(mean^2 + stddev^2) = theta.
#pragma once

#include <string>
#include <vector>

#include "studies/ida.hpp"

namespace rocking::studies {

// (N2): the mean and standard deviation of X = median e^(beta Z), Z standard
// normal, with e^(beta^2) - 1 as expm1 (no cancellation at small beta).
struct LognormalMoments {
    double mean = 0, stddev = 0;
};
LognormalMoments lognormal_moments(double median, double beta);

// (N2) inverted: beta = sqrt(ln(1 + c^2)) (log1p), median = mean / sqrt(1 + c^2),
// c = stddev / mean.  Throws std::invalid_argument unless mean > 0 and
// stddev >= 0, both finite.
struct LognormalParameters {
    double median = 0, beta = 0;
};
LognormalParameters lognormal_from_moments(double mean, double stddev);

// A text as XML character data or an attribute value: & < > " ' as
// entities, every character beyond ASCII as a numeric reference (the file
// stays ASCII, as NRML asks of a description), and what XML 1.0 cannot hold
// (control characters, bytes that are not UTF-8) as '?'.
std::string xml_escaped(const std::string& text);

struct NrmlModel {
    std::string xml;                 // the whole file, "<?xml ..." to "</nrml>\n"
    std::vector<std::string> unfitted;  // per block without a fit: "alpha A, p P rad/s: no fit: WHY"
};

// The fragility model of the study's blocks: for each block with a fit, its
// block's fit (the first overturning's under the refine method, the
// conservative one of its three; the grid's first collapse otherwise) as
// theta = median alpha g (N1) and (N2), valid on the PGA the IDA scanned,
// minIML = alpha q_start (IdaOptions::q_start: q_min, or lower where an
// imperfect block lifts) to maxIML = alpha q_max (the engine holds a PGA above
// maxIML at maxIML, and so the probability at its value there, which the
// function's comment states), with noDamageLimit = alpha q_start (no block
// lifts below it: q = 1 is the linearised threshold, and q_min is 1 on every
// front end).  A block without a fit is a comment saying why, and a line of
// `unfitted`.  `records` name the study's records, as its front end lists
// them.  Every number in %.17g, which reads back to the same double.
NrmlModel fragility_nrml(const std::vector<BlockFragility>& study, const FragilityStudyOptions& options,
                         const std::vector<std::string>& records);

}  // namespace rocking::studies
