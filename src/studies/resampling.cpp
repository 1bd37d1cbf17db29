// Compiled with -ffp-contract=off (CMakeLists.txt): the interpolation of a
// percentile is the same three roundings on any machine, with or without FMA.
#include "studies/resampling.hpp"

#include <algorithm>
#include <cmath>
#include <new>
#include <stdexcept>
#include <utility>

namespace rocking::studies {

SeededRng::SeededRng(std::uint64_t seed) : rng_(gsl_rng_alloc(gsl_rng_mt19937)) {
    if (!rng_) throw std::bad_alloc();
    gsl_rng_set(rng_, static_cast<unsigned long>(seed));
}

SeededRng::~SeededRng() {
    if (rng_) gsl_rng_free(rng_);
}

SeededRng::SeededRng(SeededRng&& o) noexcept : rng_(o.rng_) { o.rng_ = nullptr; }

SeededRng& SeededRng::operator=(SeededRng&& o) noexcept {
    std::swap(rng_, o.rng_);
    return *this;
}

std::size_t SeededRng::index(std::size_t n) { return gsl_rng_uniform_int(rng_, n); }

double percentile(std::vector<double> v, double p) {
    if (v.empty()) throw std::invalid_argument("percentile: no values");
    std::sort(v.begin(), v.end());
    const double at = p * (v.size() - 1);
    const std::size_t k = static_cast<std::size_t>(std::floor(at));
    return k + 1 < v.size() ? v[k] + (at - k) * (v[k + 1] - v[k]) : v.back();
}

Range percentile_interval(const std::vector<double>& v, double level) {
    if (!(level > 0 && level < 1)) throw std::invalid_argument("percentile interval: the level must be in (0, 1)");
    const double tail = (1 - level) / 2;
    return {percentile(v, tail), percentile(v, 1 - tail)};
}

}  // namespace rocking::studies
