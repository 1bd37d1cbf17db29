// rocking q's and rocking response's documents: a train's closed-form q and
// its motion up to t_fin (qfactor/superposition.hpp).
#pragma once

#include <string>
#include <vector>

#include "json/document.hpp"
#include "qfactor/superposition.hpp"

namespace rocking::json {

// The model the closed forms are of, as both documents name it.
extern const char* const kClosedFormModel;

// Where the closed forms hold at this q, as members of o: "rocking_starts",
// "impact_free", "motion_reverses", "passes_alpha_before_t_fin" (booleans).
void add_validity(Json& o, const Excursion& e);

// {"input", "pulses" (an integer), "x", "q", "condition", "equation", "model",
// then the four validity flags}: the collapse q of train at x and where it holds.
Json q_json(const PulseTrain& train, double x, const QFactor& q, const std::string& equation, const Excursion& e);

// {"input", "x", "q", "at_collapse_q", "model", the four validity flags,
// "rows_complete", "rows_end_at" and "rows_end_reason" (null when complete),
// "samples": [[t/to, theta/alpha, theta'/(alpha p)], ...]}.  rows are the
// states at t_fin k/steps for k = 0, 1, ..., as far as they stayed finite:
// fewer than steps + 1 end the rows, at t_fin rows.size()/steps.
Json response_json(const PulseTrain& train, double x, double q, bool at_collapse_q, const Excursion& e,
                   const std::vector<ResponseState>& rows, int steps);

// Why the rows of a response end early: theta overflows a double.
extern const char* const kRowsEndReason;

}  // namespace rocking::json
