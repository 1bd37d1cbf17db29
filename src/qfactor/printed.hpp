// The paper's formulas exactly as printed (as extracted from the published
// text: ../shared/paper/buildings-2025-15-2622.txt), kept apart from the
// library so that the errata scene can evaluate them against the
// superposition engine.  Nothing else should call these: where a printed
// formula is wrong, the engine and closed_forms.hpp hold the correct one.
//
// phi = theta/alpha, dphi = (dtheta/dt)/(alpha p), x = p to, tau = t/to.
#pragma once

namespace rocking::printed {

// Eq. 3 as printed:  theta'' - p^2 (alpha - theta) = -p^2 a/g, solved for
// theta''/(alpha p^2) given phi and the input a/(alpha g) = qa.
double eq03_accel(double phi, double qa);
// Eqs. 6, 9, 13 as printed: theta'' + p^2 (alpha - theta) = p^2 a/g.
double eq06_accel(double phi, double qa);

double eq07_phi(double q, double x, double tau);    // cases 1, 2, 4, tau <= 1
double eq08_dphi(double q, double x, double tau);   // cases 1, 2, 4, tau <= 1
double eq10_phi(double q, double x, double tau);    // case 1, 1 <= tau <= 2
double eq12_q(double x);
double eq14_phi(double q, double x, double tau);    // case 2, 1 <= tau <= 2
double eq15_q(double x);
double eq16_phi(double q, double x, double tau);    // case 3, tau <= 1
double eq17_dphi(double q, double x, double tau);   // case 3, tau <= 1
double eq18_phi(double q, double x, double tau);    // case 3, 1 <= tau <= 2
double eq19_q(double x);
double eq20_phi(double q, double x, double tau);    // case 4, 1 <= tau <= 3
double eq22_q(double x);
double eq23_phi(double q, double x, double tau);    // case 5, 2 <= tau <= 3
double eq24_q(double x);
double eq27_q(double x);
// Eq. 28 as the text prints it: the denominator's cosh(9 p to) has no 2/3.
double eq28_q(double x);

// The corrected forms, where the printed one differs (derived by hand from
// (S1), see expected/errata/PROVENANCE.md).
double eq23_phi_corrected(double q, double x, double tau);  // (q5 - 2) sinh^2(pt/2) - 3 q5 sinh^2(p(t-2to)/2)
double eq28_q_corrected(double x);                          // 2/3 cosh(9x) in the denominator
double eq03_accel_corrected(double phi, double qa);         // theta'' - p^2 theta = p^2 (a/g - alpha)

}  // namespace rocking::printed
