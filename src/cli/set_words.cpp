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

std::string bands_json(const std::vector<studies::Band>& bands) {
    std::string text = "[";
    for (std::size_t i = 0; i < bands.size(); ++i)
        text += std::string(i ? ", " : "") + "{\"from\": " + json_number(bands[i].from) +
                ", \"to\": " + json_number(bands[i].to) + ", \"share\": " + json_number(bands[i].share) + "}";
    return text + "]";
}

std::string nearest_json(const studies::SpectrumFirst& f, double height) {
    return f.found ? "{\"found\": true, \"p\": " + json_number(f.p) + ", \"height\": " + json_number(height) + "}"
                   : std::string("{\"found\": false}");
}

}  // namespace rocking::cli
