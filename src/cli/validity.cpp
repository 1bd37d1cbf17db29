#include "cli/validity.hpp"

#include <cmath>
#include <cstdio>
#include <string>

namespace rocking::cli {

namespace {

// %.3g, or the side of the double range a value left it by.
std::string bounded(double v) {
    if (std::isinf(v)) return v > 0 ? "beyond +1.8e308" : "beyond -1.8e308";
    char text[32];
    std::snprintf(text, sizeof text, "%.3g", v);
    return text;
}

}  // namespace

// Where the closed forms hold at this q (Excursion), as q and response print
// it, each line after prefix: they hold only while the block rocks on one
// corner, from the first pulse lifting it to t_fin.
void print_validity(const Excursion& e, const char* prefix) {
    std::printf("%srocking starts: %s; impact-free up to t_fin: %s; motion reverses before t_fin: %s; "
                "theta passes alpha before t_fin: %s\n",
                prefix, e.onset ? "yes" : "no (q A_0 <= 1)", e.stays_positive() ? "yes" : "no",
                e.min_dphi < 0 ? "yes" : "no", e.passes_alpha() ? "yes" : "no");
    if (!e.onset)
        std::printf("%swarning: the input does not lift the block (q A_0 <= 1), so the closed form does not apply: "
                    "its theta < 0 would press the block into the ground\n",
                    prefix);
    else if (!e.stays_positive())
        std::printf("%swarning: theta goes down to %s alpha (at t/to = %.4g): the block hits the ground before t_fin, "
                    "and the closed form does not apply from there (rocking simulate follows the impacts)\n",
                    prefix, bounded(e.min_phi).c_str(), e.tau_at_min);
    // Past alpha the weight no longer pulls the block back (eq. 3): the
    // paper's condition theta(t_fin) = alpha assumes theta gets there first.
    if (e.onset && e.passes_alpha())
        std::printf("%swarning: theta passes alpha before t_fin, reaching %s alpha at t/to = %.4g: the block would "
                    "overturn before the instant where the paper imposes theta = alpha (rocking simulate follows it)\n",
                    prefix, bounded(e.max_phi).c_str(), e.tau_at_max);
}

}  // namespace rocking::cli
