#include "cli/set_words.hpp"

#include "cli/options.hpp"

namespace rocking::cli {

std::string bands_text(const std::vector<studies::Band>& bands) {
    std::string text;
    for (const studies::Band& b : bands)
        if (b.share > 0)
            text += (text.empty() ? "[" : " [") + significant(b.from, 7) + ", " + significant(b.to, 7) + "]:" +
                    significant(b.share, 7);
    return text.empty() ? "none" : text;
}

std::string bands_summary(const std::vector<studies::Band>& bands, const char* variable) {
    int whole = 0, partial = 0;
    double from = 0, to = 0;
    for (const studies::Band& b : bands) {
        if (b.share >= 1) ++whole;
        else if (b.share > 0) {
            if (partial++ == 0) from = b.from;
            to = b.to;
        }
    }
    if (whole + partial == 0) return "none";
    std::string text = std::to_string(whole) + " of " + std::to_string(bands.size()) + " bands wholly overturned, " +
                       std::to_string(partial) + " in part";
    if (partial > 0)
        text += std::string(" (between ") + variable + " = " + significant(from, 7) + " and " + significant(to, 7) + ")";
    return text + "; each band's share in --json and --output";
}

}  // namespace rocking::cli
