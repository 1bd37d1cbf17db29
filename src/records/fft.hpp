// GSL's mixed-radix complex FFT of one length, its tables made once: the CWT
// transforms hundreds of blocks of the same length, and GSL's table of 2^21
// points takes longer to make (its sines and cosines) than the transform itself.
#pragma once

#include <gsl/gsl_fft_complex.h>

#include <cstddef>
#include <vector>

namespace rocking::records {

class Fft {
public:
    explicit Fft(std::size_t n);
    ~Fft();
    Fft(const Fft&) = delete;
    Fft& operator=(const Fft&) = delete;

    std::size_t size() const { return n_; }
    // In place on n complex values stored (re, im, re, im, ...): sum_t z_t e^{-2 pi i k t / n}.
    void forward(std::vector<double>& z) const;
    // The inverse, with its 1/n.
    void inverse(std::vector<double>& z) const;

private:
    std::size_t n_;
    gsl_fft_complex_wavetable* table_;
    gsl_fft_complex_workspace* work_;
};

}  // namespace rocking::records
