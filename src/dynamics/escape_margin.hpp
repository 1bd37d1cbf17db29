// The escape margin of each flight of a run on a record (issue 39; the
// derivations are in docs/overturning_set.md, section 1 for the margin and
// section 5 for its slope): how near a flight comes to leaving for the fall,
// with its sensitivity to the record's scale.  On corner sigma, with
// y = sigma theta - alpha, eq. 3 is y'' = p^2 (y + sigma a/g), and
//   J(t) = p int_t^T e^{-p (s - t)} a(s)/g ds     (0 after the input's end T),
//   Xi   = (y + y'/p + sigma J(t)) / alpha
// obeys Xi' = p Xi while the flight lasts: a flight can fall without another
// impact only if Xi > 0, and after the input Xi > 0 is the model's own
// energy test.  M = max over the flights of Xi (each at its start) has the
// sign of the outcome wherever no flight is turned back by the input.
//
// In dynamics/, beside the kernel that reports the flights: the margin and
// its tangent are properties of eq. 3 and of the impact law, not of a study;
// the studies' search over q or p (studies/) is built on them.
#pragma once

#include <cstddef>
#include <vector>

#include "dynamics/exact_record.hpp"
#include "dynamics/ground_input.hpp"
#include "dynamics/model.hpp"
#include "dynamics/simulate.hpp"

namespace rocking::dynamics {

// p int_0^u e^{-p s} (a0 + c1 s) ds for a record piece a0 + c1 s: the
// contribution of one piece to J (and, read backwards, to L below).
double piece_integral(double a0, double c1, double u, double p);

// J(t) and its forward twin
//   L(t) = p int_0^t e^{-p (t - s)} a(s)/g ds
// of a record (in g, linear between samples, 0 after its end) at pulsation
// p, each by one exact recursion over the samples (backward for J, forward
// for L) and inside a piece by the piece's own integral.  Both are linear in
// the record: for the record times q they are q times these, so one
// RestOfInput serves a whole IDA.  It reads the record's samples in place:
// the record must outlive it.  A search over p retunes one RestOfInput
// (`retune`) instead of building one per p, so that the record's length in
// doubles is allocated once.  L serves only the tangent in q (stable_gain,
// past); built without it (`with_past` false) a RestOfInput costs half.
class RestOfInput {
public:
    RestOfInput(const SampledInput& record, double p, bool with_past = true);
    void retune(double p);  // J (and L) at another p, in place
    double p() const { return p_; }
    bool has_past() const { return with_past_; }
    double t_end() const { return dt_ * (n_ - 1); }
    double at(double t) const;    // J(t)
    double past(double t) const;  // L(t)
    double accel(double t) const; // a(t)/g, 0 after the end
    double slope(double t) const; // the slope of the piece holding t (1/s), 0 after the end
    // What the input adds from t0 to t1 >= t0 to the unstable and stable
    // coordinates of a motion under eq. 3 (u = x + x'/p, v = x - x'/p with
    // x'' = p^2 (x + a/g)): u(t1) = u(t0) e^{p d} + unstable_gain,
    // v(t1) = v(t0) e^{-p d} + stable_gain (d = t1 - t0), i.e.
    //   J(t0) e^{p d} - J(t1)  and  L(t0) e^{-p d} - L(t1),
    // from the piece's own integral where both ends lie in one piece (an
    // impact cascade's short flights), without the differences' cancellation.
    double unstable_gain(double t0, double t1) const;
    double stable_gain(double t0, double t1) const;

private:
    std::size_t piece(double t) const;
    const double* a_;
    std::size_t n_;
    std::vector<double> J_, L_;
    double dt_, p_ = 0;
    bool with_past_;
};

// The escape margin Xi of the state (theta, theta') on corner sigma at t,
// for the record times `scale`.
double escape_margin(const Model& model, const RestOfInput& rest, double scale, double t, double theta, double omega,
                     int sigma);

// One flight: its start, its margin there, and the margin's derivative with
// respect to ln q (q: the record's scale), the flight's start moving with q.
struct FlightMargin {
    double t;      // the start, s
    int sigma;     // the corner
    double xi;     // Xi at the start
    double slope;  // dXi / d ln q
};

// The flights of one run (a FlightObserver for simulate_record_kernel), the
// run's input being rest's record times `scale`.  The tangent of the state
// with respect to ln q, (theta_q, theta'_q), obeys
//   theta_q'' = p^2 (theta_q + a/g)
// (eq. 3 differentiated: the input is linear in q, the corner's term is not
// in it), whatever the corner; between impacts it is carried in closed form
// by its unstable and stable coordinates, u = theta_q + theta_q'/p and
// v = theta_q - theta_q'/p, whose sums with J and L evolve as e^{+p t} and
// e^{-p t}.  At an impact the time moves by t_q = -theta_q / theta' and
// theta' jumps (the saltation): theta_q+ = e theta_q-,
//   theta'_q+ = e (theta'_q- + theta''- t_q) - theta''+ t_q.
// At an uplift the tangent is 0 (the block rests before it for every q
// near), and the start moves by t_q = -a / a' (the input reaches the
// threshold).  A rest ends a flight without a successor; the next flight is
// an uplift.
//
// Without `slopes` (a search over p, whose slopes come from a second run) the
// tangent is not carried and each flight's slope is NaN.
class FlightMargins : public FlightObserver {
public:
    FlightMargins(const Model& model, const RestOfInput& rest, double scale, bool slopes = true);
    void flight(const FlightStart& start) override;

    const std::vector<FlightMargin>& flights() const { return flights_; }
    // M: the largest Xi over the flights (-infinity without a flight).
    double max_margin() const;
    void clear();

private:
    struct Tangent {
        double t = 0, theta = 0, omega = 0;  // the tangent's state just after the flight's start at t
    };
    Tangent carried_to(double t) const;

    Model model_;
    const RestOfInput& rest_;
    double scale_;
    bool slopes_;
    Tangent tangent_;
    std::vector<FlightMargin> flights_;
};

// The run and its flights: simulate_record_kernel with FlightMargins, on
// rest's record times `scale` (which the caller has built as `input`).
// Throws std::invalid_argument where the record kernel does not apply.
SimulationResult simulate_with_margins(const Model& model, const SampledInput& input, const SimulationOptions& options,
                                       FlightMargins& margins);

}  // namespace rocking::dynamics
