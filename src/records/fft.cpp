#include "records/fft.hpp"

#include <new>
#include <stdexcept>

namespace rocking::records {

Fft::Fft(std::size_t n)
    : n_(n), table_(gsl_fft_complex_wavetable_alloc(n)), work_(gsl_fft_complex_workspace_alloc(n)) {
    if (!table_ || !work_) {
        if (table_) gsl_fft_complex_wavetable_free(table_);
        if (work_) gsl_fft_complex_workspace_free(work_);
        throw std::bad_alloc();
    }
}

Fft::~Fft() {
    gsl_fft_complex_workspace_free(work_);
    gsl_fft_complex_wavetable_free(table_);
}

void Fft::forward(std::vector<double>& z) const {
    if (z.size() != 2 * n_) throw std::invalid_argument("Fft: wrong length");
    gsl_fft_complex_forward(z.data(), 1, n_, table_, work_);
}

void Fft::inverse(std::vector<double>& z) const {
    if (z.size() != 2 * n_) throw std::invalid_argument("Fft: wrong length");
    gsl_fft_complex_inverse(z.data(), 1, n_, table_, work_);
}

}  // namespace rocking::records
