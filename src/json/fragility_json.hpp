// rocking fragility's document: each block's IDA on every record, the
// lognormal fit of its capacities and the empirical shares
// (studies/fragility.hpp, studies/ida.hpp).
#pragma once

#include <string>
#include <vector>

#include "json/document.hpp"
#include "studies/fragility.hpp"
#include "studies/ida.hpp"

namespace rocking::json {

// The bootstrap of a fit: {"resamples", "seed" (integers), "level", "median"
// and "beta" ([lo, hi])}, or null without one.
Json bootstrap_json(bool bootstrapped, const studies::BootstrapInterval& b);

// A censored lognormal fit: {"median", "beta", "collapsed", "censored" (integers), "bootstrap"}.
Json lognormal_json(const studies::LognormalFragility& fit, bool bootstrapped, const studies::BootstrapInterval& interval);

// One record's member of a block's "records": {"file", "sha256", "q_input",
// "q", "collapsed", "point_check" ({"confirmation", "detail"} or null),
// "simulations", "check_simulations", "intervals" (each {"from", "to",
// "lower", "upper"}, a bracket {"q_safe", "q_collapse"} or null)}, and with
// the refine method "first_overturning" ({"q", "collapsed", "bracket",
// "check"}), "first_robust_collapse" ({"q", "collapsed"}), "bands",
// "method", "samples", "accepted", "at_width", "with_margins" and
// "unguaranteed_from" (a double, NaN where the guarantee holds to q_max).
Json ida_record_json(const std::string& file, const std::string& identity, const studies::Ida& ida, bool refine);

// One block's member of "blocks": {"alpha", "p", "built" (a block as built),
// "q_start" and, refined, "stripe_half_width" (an imperfect block's grid),
// "records" (files[k] as ida_record_json), "fit" (lognormal_json, or null
// beside "no_fit", why not), "no_fit", "empirical" ([{"q", "share"}, ...]),
// and with the three capacities "fits" ({"first_overturning",
// "first_robust_collapse", "stripes"}: each {"fit", "no_fit"}, the stripes'
// fit {"median", "beta", "stripes", "records", "bootstrap"}) and "stripes"
// ([{"q", "from", "to", "share"}, ...])}.
Json fragility_block_json(const std::vector<std::string>& files, const studies::FragilityStudyOptions& o,
                          const studies::BlockFragility& f);

// The grid in words, as the text output and "grid"'s "note" say it.
std::string fragility_grid_note(const studies::FragilityStudyOptions& o);

// The whole document: {"model", "grid": {"q_min", "q_max", "points",
// "rel_tol", "note", and with the refine method "method", "width",
// "robust_width", "fit_capacity", "stripe_half_width", "refine_note"},
// "blocks"}.
Json fragility_document(const std::vector<std::string>& files, const studies::FragilityStudyOptions& o,
                        const std::vector<studies::BlockFragility>& study);

}  // namespace rocking::json
