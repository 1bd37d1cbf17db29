#include "studies/scaled_input.hpp"

#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <string>
#include <vector>

namespace rocking::studies {

using dynamics::GroundInput;
using dynamics::InputPiece;

namespace {

std::string factor_text(double factor) {
    char text[40];
    std::snprintf(text, sizeof text, "%.17g", factor);
    return text;
}

// Every piece's polynomial and sine scaled; times, breaks and the sine's
// phase are the input's own, so the scaled run meets the same events.
class ScaledView : public GroundInput {
public:
    ScaledView(const GroundInput& input, double factor) : input_(input), factor_(factor) {}
    std::string describe() const override { return input_.describe() + ", scaled by " + factor_text(factor_); }
    double t_end() const override { return input_.t_end(); }
    InputPiece piece_at(double t) const override {
        InputPiece piece = input_.piece_at(t);
        piece.c0 *= factor_;
        piece.c1 *= factor_;
        piece.s *= factor_;
        return piece;
    }
    std::vector<double> discontinuities() const override { return input_.discontinuities(); }
    double peak() const override { return input_.peak() * factor_; }

private:
    const GroundInput& input_;
    double factor_;
};

}  // namespace

std::unique_ptr<GroundInput> scaled(const GroundInput& input, double factor) {
    if (!(std::isfinite(factor) && factor > 0))
        throw std::invalid_argument("scaled input: the factor must be finite and > 0 (got " + factor_text(factor) + ")");
    if (const auto* record = dynamic_cast<const dynamics::SampledInput*>(&input))
        return std::make_unique<dynamics::SampledInput>(
            record->scaled_by(factor, record->describe() + ", scaled by " + factor_text(factor)));
    return std::make_unique<ScaledView>(input, factor);
}

}  // namespace rocking::studies
