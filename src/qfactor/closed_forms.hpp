// The paper's closed forms q1..q5 (eqs. 12, 15, 19, 22, 24) and the 6 + 1
// pulse forms (eqs. 27, 28), each evaluated in a form that is accurate over
// the whole axis x = p*to > 0.
//
// With c = cosh x and u = e^{-x}, each printed ratio of cosh polynomials has
// the root c = 1 of its denominator factored out (c - 1 = 2 sinh^2(x/2)), and
// numerator and denominator are divided by their common growth e^{nx}.  What
// is left is a rational function of u times 1/(1 - u)^2, with 1 - u =
// -expm1(-x): no cancellation as x -> 0, no overflow as x -> infinity.
// Each function states its limits: q x^2 -> 2/M1 as x -> 0 and q -> 1/A_0 as
// x -> infinity (see superposition.hpp).
#pragma once

namespace rocking {

// Eq. 12, case 1 (+1, -1):  q1 = (2c^2 - 1) / (2c(c - 1))
//   = (1 + u^4) / ((1 + u^2)(1 - u)^2).   x->0: 1/x^2.  x->inf: 1.
double q1(double x);
// Eq. 15, case 2 (+1, -1/2):  q2 = (4c^2 - 2) / (4c^2 - 3c - 1)
//   = 2(1 + u^4) / ((2 + u + 2u^2)(1 - u)^2).   x->0: 0.8/x^2.  x->inf: 1.
double q2(double x);
// Eq. 19, case 3 (+1/2, -1):  q3 = (4c^2 - 2) / (2c^2 - 3c + 1)
//   = 2(1 + u^4) / ((1 - u + u^2)(1 - u)^2).   x->0: 4/x^2.  x->inf: 2.
double q3(double x);
// Eq. 22, case 4 (+1, -1/2 for 2 to):  q4 = 2cosh3x / (2cosh3x - 3cosh2x + 1)
//   = (1 + u^6) / ((1 + u/2 + u^3/2 + u^4)(1 - u)^2).   x->0: (2/3)/x^2.  x->inf: 1.
double q4(double x);
// Eq. 24, case 5 (+1/2 for 2 to, -1):  q5 = 2cosh3x / (cosh3x - 3cosh x + 2)
//   = 2(1 + u^6) / ((1 + 2u + 2u^3 + u^4)(1 - u)^2).   x->0: (2/3)/x^2.  x->inf: 2.
double q5(double x);
// q_i for i = 1..5; throws std::invalid_argument for another i.
double q_case(int which, double x);

// Eq. 27: case 2 repeated, N = 6 pulses, collapse at the onset of the 7th.
// x->0: (4/27)/x^2 (M1 = 13.5).  x->inf: 1.
double q2_n6(double x);
// Eq. 28: case 4 repeated, N = 6 pulses (t_fin = 9 to).
// x->0: (2/9)/x^2 (M1 = 9).  x->inf: 1.
double q4_n6(double x);

}  // namespace rocking
