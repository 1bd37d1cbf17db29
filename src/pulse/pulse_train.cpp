#include "pulse/pulse_train.hpp"

#include <cmath>
#include <sstream>
#include <stdexcept>

#include "numerics/number_text.hpp"

namespace rocking {

PulseTrain::PulseTrain(std::vector<Pulse> pulses, std::string name)
    : pulses_(std::move(pulses)), name_(std::move(name)) {
    if (pulses_.empty()) throw std::invalid_argument("pulse train: no pulses");
    for (std::size_t k = 0; k < pulses_.size(); ++k) {
        const Pulse& p = pulses_[k];
        if (!std::isfinite(p.amplitude))
            throw std::invalid_argument("pulse train: pulse " + std::to_string(k + 1) +
                                        " has a non-finite amplitude");
        if (!std::isfinite(p.duration) || p.duration <= 0.0)
            throw std::invalid_argument("pulse train: pulse " + std::to_string(k + 1) +
                                        " needs a finite duration > 0");
    }
    // Rocking on the theta > 0 corner needs a positive first pulse; a train
    // starting negative is the mirror image (symmetry under sign flip).
    if (pulses_.front().amplitude <= 0.0)
        throw std::invalid_argument(
            "pulse train: the first pulse must be positive (flip the signs of a train that starts "
            "negative: the response is the mirror image)");
}

double PulseTrain::t_fin() const { return start(pulses_.size()); }

double PulseTrain::start(std::size_t k) const {
    double t = 0.0;
    for (std::size_t j = 0; j < k && j < pulses_.size(); ++j) t += pulses_[j].duration;
    return t;
}

double PulseTrain::amplitude_at(double tau) const {
    if (tau < 0.0) return 0.0;
    double t = 0.0;
    for (const Pulse& p : pulses_) {
        t += p.duration;
        if (tau < t) return p.amplitude;
    }
    return 0.0;
}

double PulseTrain::peak() const {
    double m = 0.0;
    for (const Pulse& p : pulses_) m = std::fmax(m, std::fabs(p.amplitude));
    return m;
}

namespace {
std::vector<Pulse> case_pattern(int which) {
    switch (which) {
        case 1: return {{1.0, 1.0}, {-1.0, 1.0}};
        case 2: return {{1.0, 1.0}, {-0.5, 1.0}};
        case 3: return {{0.5, 1.0}, {-1.0, 1.0}};
        case 4: return {{1.0, 1.0}, {-0.5, 2.0}};
        case 5: return {{0.5, 2.0}, {-1.0, 1.0}};
        default:
            throw std::invalid_argument("case must be 1, 2, 3, 4 or 5 (got " +
                                        std::to_string(which) + ")");
    }
}
}  // namespace

PulseTrain pulse_case(int which) {
    return PulseTrain(case_pattern(which), "case " + std::to_string(which));
}

PulseTrain repeated_case(int which, int n_pulses) {
    if (n_pulses < 1 || n_pulses > 1000)
        throw std::invalid_argument("number of pulses must be between 1 and 1000 (got " +
                                    std::to_string(n_pulses) + ")");
    const std::vector<Pulse> pattern = case_pattern(which);
    std::vector<Pulse> pulses;
    for (int k = 0; k < n_pulses; ++k) pulses.push_back(pattern[k % pattern.size()]);
    return PulseTrain(pulses, "case " + std::to_string(which) + ", N = " + std::to_string(n_pulses));
}

PulseTrain parse_train(const std::string& text) {
    std::vector<Pulse> pulses;
    std::stringstream ss(text);
    std::string item;
    int index = 0;
    while (std::getline(ss, item, ',')) {
        ++index;
        const auto colon = item.find(':');
        if (colon == std::string::npos)
            throw std::invalid_argument("train item " + std::to_string(index) + " '" + item +
                                        "': expected amplitude:duration");
        const auto part = [&](const std::string& text, const char* what) {
            try {
                return numerics::parameter_number(text);
            } catch (const std::invalid_argument& e) {
                throw std::invalid_argument("train item " + std::to_string(index) + " '" + item + "': " + what + " " +
                                            e.what());
            }
        };
        const double amplitude = part(item.substr(0, colon), "amplitude");
        pulses.push_back({amplitude, part(item.substr(colon + 1), "duration")});
    }
    return PulseTrain(pulses, text);
}

}  // namespace rocking
