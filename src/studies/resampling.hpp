// The machinery of a seeded bootstrap, shared by the fragility fit's
// (studies/fragility.hpp) and eq. 27's share over records
// (studies/eq27_at_scale.hpp): GSL's mt19937 seeded (the same seed gives the
// same draws on any machine), a uniform index by gsl_rng_uniform_int, and the
// percentile interval with linear interpolation between order statistics.
#pragma once

#include <gsl/gsl_rng.h>

#include <cstddef>
#include <cstdint>
#include <vector>

namespace rocking::studies {

struct Range {
    double lo = 0, hi = 0;
};

// GSL's mt19937 after gsl_rng_set(seed).  Move-only.
class SeededRng {
public:
    explicit SeededRng(std::uint64_t seed);
    ~SeededRng();
    SeededRng(SeededRng&&) noexcept;
    SeededRng& operator=(SeededRng&&) noexcept;
    // gsl_rng_uniform_int(n): uniform on 0..n-1 (GSL's rejection rule, no
    // modulo bias).  Expects 1 <= n <= 2^32.
    std::size_t index(std::size_t n);

private:
    gsl_rng* rng_;
};

// The p-quantile of v (p in [0, 1]) by linear interpolation between the
// order statistics at p (size - 1): v(k) + (p (size - 1) - k) (v(k+1) - v(k)).
// Expects v not empty.
double percentile(std::vector<double> v, double p);

// The percentiles at (1 - level)/2 and (1 + level)/2 (the two-sided percentile
// interval at `level`).  Expects v not empty, level in (0, 1).
Range percentile_interval(const std::vector<double>& v, double level);

}  // namespace rocking::studies
