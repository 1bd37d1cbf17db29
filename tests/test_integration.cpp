// Independent truth: a direct numerical integration of eq. 3 (GSL's rk8pd,
// pulse by pulse so that no step straddles a jump) gives the same q and the
// same theta(t) as the superposition engine.
#include <gtest/gtest.h>
#include <gsl/gsl_errno.h>
#include <gsl/gsl_odeiv2.h>

#include <cmath>

#include "pulse/pulse_train.hpp"
#include "qfactor/superposition.hpp"

using namespace rocking;

namespace {

struct Params {
    double x2;  // x^2
    double F;   // q A - 1 on the current pulse
};

int rhs(double, const double y[], double dydt[], void* params) {
    const auto* p = static_cast<Params*>(params);
    dydt[0] = y[1];
    dydt[1] = p->x2 * (y[0] + p->F);  // phi'' = x^2 (phi + q A - 1), eq. 3 in tau
    return GSL_SUCCESS;
}

// phi at the end of each pulse, integrated from rest.
std::vector<double> integrate(const PulseTrain& train, double x, double q) {
    Params params{x * x, 0.0};
    gsl_odeiv2_system sys = {rhs, nullptr, 2, &params};
    gsl_odeiv2_driver* d = gsl_odeiv2_driver_alloc_y_new(&sys, gsl_odeiv2_step_rk8pd, 1e-4, 1e-15, 1e-14);
    double y[2] = {0.0, 0.0}, tau = 0.0;
    std::vector<double> ends;
    for (const Pulse& p : train.pulses()) {
        params.F = q * p.amplitude - 1.0;
        gsl_odeiv2_driver_reset(d);
        const int status = gsl_odeiv2_driver_apply(d, &tau, tau + p.duration, y);
        EXPECT_EQ(status, GSL_SUCCESS);
        ends.push_back(y[0]);
    }
    gsl_odeiv2_driver_free(d);
    return ends;
}

}  // namespace

TEST(Integration, QFromIntegratingEquationThreeMatchesTheEngine) {
    std::vector<std::pair<PulseTrain, std::vector<double>>> trains = {
        {pulse_case(1), {0.2, 0.8, 2.0}}, {pulse_case(2), {0.2, 0.8, 2.0}},
        {pulse_case(3), {0.2, 0.8, 2.0}}, {pulse_case(4), {0.2, 0.8, 2.0}},
        {pulse_case(5), {0.2, 0.8, 2.0}}, {repeated_case(2, 6), {0.3, 0.8}},
        {repeated_case(4, 6), {0.3, 0.8}}, {repeated_case(1, 12), {0.25}},
        {parse_train("1:0.7,-0.3:1.1,0.8:0.4,-1:0.9"), {0.5, 1.0}}};
    for (const auto& [train, xs] : trains)
        for (double x : xs) {
            // phi(t_fin) is affine in q: two integrations give the root.
            const double qa = 2.0, qb = 20.0;
            const double fa = integrate(train, x, qa).back() - 1.0, fb = integrate(train, x, qb).back() - 1.0;
            const double q_integrated = qa - fa * (qb - qa) / (fb - fa);
            const double q_engine = q_factor(train, x).q;
            EXPECT_NEAR(q_integrated / q_engine, 1.0, 1e-9) << train.name() << " x = " << x;
            // And the whole response, at the end of every pulse.
            const auto ends = integrate(train, x, q_engine);
            for (std::size_t k = 0; k < ends.size(); ++k)
                EXPECT_NEAR(ends[k], response(train, x, q_engine, train.start(k + 1)).phi, 1e-9)
                    << train.name() << " x = " << x << " pulse " << k + 1;
        }
}
