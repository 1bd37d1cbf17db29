#include "studies/nrml.hpp"

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <stdexcept>

#include "harness/table.hpp"

namespace rocking::studies {

namespace {

using harness::format_number;

std::string g6(double v) {
    char text[40];
    std::snprintf(text, sizeof text, "%.6g", v);
    return text;
}

// The shortest %g that reads back to v: a block's values as they were given.
std::string shortest(double v) {
    char text[40];
    for (int digits = 1; digits <= 17; ++digits) {
        std::snprintf(text, sizeof text, "%.*g", digits, v);
        if (std::strtod(text, nullptr) == v) break;
    }
    return text;
}

// NRML's ids take letters, digits, '-' and '_': a block's alpha and p with
// '.' as '_' and no '+' ("rocking_alpha_0_1_p_3").
std::string function_id(const BlockShape& b) {
    std::string id = "rocking_alpha_" + shortest(b.alpha) + "_p_" + shortest(b.p);
    std::string out;
    for (char c : id)
        if (c == '.') out += '_';
        else if (c != '+') out += c;
    return out;
}

// A comment's text: ASCII (other bytes as '?'), and never "--" or a final
// '-', which XML forbids inside a comment.
std::string comment_text(const std::string& text) {
    std::string out;
    for (unsigned char c : text) {
        const char ch = (c < 0x20 || c > 0x7e) ? '?' : static_cast<char>(c);
        if (ch == '-' && !out.empty() && out.back() == '-') out += ' ';
        out += ch;
    }
    if (!out.empty() && out.back() == '-') out += ' ';
    return out;
}

std::string block_text(const BlockShape& b) { return "alpha " + g6(b.alpha) + ", p " + g6(b.p) + " rad/s"; }

bool refined(const FragilityStudyOptions& o) { return o.ida.method == IdaOptions::Method::refine; }

std::string description(const FragilityStudyOptions& o, const std::vector<std::string>& records) {
    std::string text =
        "Overturning of a rigid block rocking on a rigid base (Housner's model, as in S. Coccia, q-factor for slender "
        "masonry structures, Buildings 2025), under PGA in g: one function per block of slenderness alpha (rad) and "
        "frequency parameter p (rad/s), its id rocking_alpha_A_p_P. Each is the lognormal maximum-likelihood fit, "
        "censored records kept, of the intensity q = PGA/(alpha g) at which each of " +
        std::to_string(records.size()) + " records, scaled in amplitude from q = " + g6(o.ida.q_min) +
        (o.ida.model.imperfection.any() ? " (an imperfect block from where it lifts, if lower: q_start)" : "") + " to " +
        g6(o.ida.q_max) + " (incremental dynamic analysis), ";
    text += refined(o) ? "first overturns the block, every island of overturning wider than " + g6(o.ida.width) +
                             " in ln q found (the refine method's fit on the first overturning, the conservative one "
                             "of its three fits; the first robust collapse's and the multiple-stripe fit are not "
                             "exported)"
                       : "first overturns the block on the IDA's grid (its first collapse; islands of overturning "
                         "narrower than half a grid step may lie below it)";
    text += ". The PGA's median is theta = median q times alpha; mean = theta exp(beta^2/2) and stddev = mean "
            "sqrt(exp(beta^2) - 1) are those of the PGA itself, not of its logarithm. Valid from PGA = alpha q_start "
            "(q_min, or where an imperfect block lifts if lower; below it no block lifts: noDamageLimit) to alpha q_max, the range the analysis scanned; above maxIML "
            "the engine holds the probability at its value there. Model: " +
            o.ida.describe_model() + ". Records:";
    for (std::size_t k = 0; k < records.size(); ++k) text += (k ? "; " : " ") + records[k];
    return xml_escaped(text + ".");
}

}  // namespace

LognormalMoments lognormal_moments(double median, double beta) {
    const double b2 = beta * beta;
    const double mean = median * std::exp(b2 / 2);
    return {mean, mean * std::sqrt(std::expm1(b2))};
}

LognormalParameters lognormal_from_moments(double mean, double stddev) {
    if (!(std::isfinite(mean) && mean > 0 && std::isfinite(stddev) && stddev >= 0))
        throw std::invalid_argument("lognormal moments: the mean must be > 0 and the stddev >= 0, both finite");
    const double c = stddev / mean;
    return {mean / std::sqrt(1 + c * c), std::sqrt(std::log1p(c * c))};
}

std::string xml_escaped(const std::string& text) {
    std::string out;
    const std::size_t n = text.size();
    for (std::size_t k = 0; k < n;) {
        const unsigned char c = static_cast<unsigned char>(text[k]);
        if (c < 0x80) {
            switch (c) {
                case '&': out += "&amp;"; break;
                case '<': out += "&lt;"; break;
                case '>': out += "&gt;"; break;
                case '"': out += "&quot;"; break;
                case '\'': out += "&apos;"; break;
                default: out += (c < 0x20 && c != '\t' && c != '\n' && c != '\r') ? '?' : static_cast<char>(c);
            }
            ++k;
            continue;
        }
        // A UTF-8 sequence: its length from the lead byte, its code point
        // from the continuation bytes; an overlong form, a surrogate, a code
        // point beyond U+10FFFF or one XML does not allow (U+FFFE, U+FFFF) is
        // not a character here.
        const int length = c >= 0xf8 ? 0 : c >= 0xf0 ? 4 : c >= 0xe0 ? 3 : c >= 0xc0 ? 2 : 0;
        unsigned long point = length == 4 ? c & 0x07u : length == 3 ? c & 0x0fu : c & 0x1fu;
        bool ok = length > 0 && k + length <= n;
        for (int i = 1; ok && i < length; ++i) {
            const unsigned char d = static_cast<unsigned char>(text[k + i]);
            ok = (d & 0xc0u) == 0x80u;
            point = (point << 6) | (d & 0x3fu);
        }
        const unsigned long least = length == 4 ? 0x10000 : length == 3 ? 0x800 : 0x80;
        ok = ok && point >= least && point <= 0x10ffff && !(point >= 0xd800 && point <= 0xdfff) && point != 0xfffe &&
             point != 0xffff;
        if (!ok) {
            out += '?';
            ++k;
            continue;
        }
        char ref[16];
        std::snprintf(ref, sizeof ref, "&#x%lX;", point);
        out += ref;
        k += length;
    }
    return out;
}

NrmlModel fragility_nrml(const std::vector<BlockFragility>& study, const FragilityStudyOptions& o,
                         const std::vector<std::string>& records) {
    NrmlModel out;
    std::string& x = out.xml;
    x = "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
        "<!-- rocking-q's fragility study as an OpenQuake fragility model (docs/fragility.md, 'The NRML export') -->\n"
        "<nrml xmlns=\"http://openquake.org/xmlns/nrml/0.5\">\n"
        "  <fragilityModel id=\"rocking-q_overturning\" assetCategory=\"buildings\" lossCategory=\"structural\">\n"
        "    <description>" +
        description(o, records) +
        "</description>\n"
        "    <limitStates>overturning</limitStates>\n";
    for (const BlockFragility& f : study) {
        const BlockShape& b = f.block;
        if (!f.fitted) {
            out.unfitted.push_back(block_text(b) + ": no fit: " + f.no_fit);
            x += "    <!-- " + comment_text(out.unfitted.back() + "; no fragility function for this block") + " -->\n";
            continue;
        }
        const double theta = f.fit.median * b.alpha;
        const LognormalMoments m = lognormal_moments(theta, f.fit.beta);
        const double lowest = b.alpha * o.ida.q_start(b.alpha, b.p), highest = b.alpha * o.ida.q_max;
        std::string note = block_text(b) + ": median q " + g6(f.fit.median) + ", beta " + g6(f.fit.beta) +
                           ", so theta = " + g6(theta) + " g; " + std::to_string(f.fit.collapsed) + " records overturned, " +
                           std::to_string(f.fit.censored) + " censored at q = " + g6(o.ida.q_max);
        if (f.bootstrapped)
            note += "; " + g6(100 * f.interval.level) + " % bootstrap of the median q [" + g6(f.interval.median.lo) + ", " +
                    g6(f.interval.median.hi) + "], of beta [" + g6(f.interval.beta.lo) + ", " +
                    g6(f.interval.beta.hi) + "] (" + std::to_string(f.interval.resamples) + " resamples, seed " +
                    std::to_string(f.interval.seed) + ")";
        note += "; P(overturning) at maxIML " + g6(overturning_probability(f.fit, o.ida.q_max));
        x += "    <!-- " + comment_text(note) + " -->\n";
        x += "    <fragilityFunction id=\"" + function_id(b) + "\" format=\"continuous\" shape=\"logncdf\">\n";
        x += "      <imls imt=\"PGA\" noDamageLimit=\"" + format_number(lowest) + "\" minIML=\"" + format_number(lowest) +
             "\" maxIML=\"" + format_number(highest) + "\"/>\n";
        x += "      <params ls=\"overturning\" mean=\"" + format_number(m.mean) + "\" stddev=\"" +
             format_number(m.stddev) + "\"/>\n";
        x += "    </fragilityFunction>\n";
    }
    x += "  </fragilityModel>\n</nrml>\n";
    return out;
}

}  // namespace rocking::studies
