#include "cli/validity.hpp"

#include <cstdio>

namespace rocking::cli {

const char* kModel = "linearised eq. 3, one corner, no impact, collapse theta(t_fin) = alpha";

// Where the closed forms hold at this q (Excursion), as q and response print
// it, each line after prefix: they hold only while the block rocks on one
// corner, from the first pulse lifting it to t_fin.
void print_validity(const Excursion& e, const char* prefix) {
    std::printf("%srocking starts: %s; impact-free up to t_fin: %s; motion reverses before t_fin: %s\n", prefix,
                e.onset ? "yes" : "no (q A_0 <= 1)", e.stays_positive() ? "yes" : "no", e.min_dphi < 0 ? "yes" : "no");
    if (!e.onset)
        std::printf("%swarning: the input does not lift the block (q A_0 <= 1), so the closed form does not apply: "
                    "its theta < 0 would press the block into the ground\n",
                    prefix);
    else if (!e.stays_positive())
        std::printf("%swarning: theta goes down to %.3g alpha (at t/to = %.4g): the block hits the ground before t_fin, "
                    "and the closed form does not apply from there (rocking simulate follows the impacts)\n",
                    prefix, e.min_phi, e.tau_at_min);
}

std::string json_validity(const Excursion& e) {
    return std::string(", \"rocking_starts\": ") + (e.onset ? "true" : "false") +
           ", \"impact_free\": " + (e.stays_positive() ? "true" : "false") +
           ", \"motion_reverses\": " + (e.min_dphi < 0 ? "true" : "false");
}

}  // namespace rocking::cli
