// rocking spectrum --png (issue 40): one panel per alpha, all on one y range.
// The line is max |theta|/alpha during the input of the runs that do not
// overturn; an overturned run has no such maximum worth drawing (theta runs
// to the fall angle, pi/2 / alpha on this scale), so it is a point in a strip
// above the data, said in the key.  The top axis gives, for the panel's alpha,
// the height H of the block whose pulsation is p (eqs. 2, 4:
// studies::height_at_p); a block marked with --mark is a vertical line at its
// p with its outcome, a run at its own p (studies::mark_block).
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <sstream>
#include <string>
#include <vector>

#include "cli/plots.hpp"
#include "dynamics/model.hpp"
#include "studies/spectrum_mark.hpp"

namespace rocking::cli {

namespace {

using jobs::SpectrumStudy;

constexpr int kWidth = PanelLayout::width, kLeft = PanelLayout::left, kRight = PanelLayout::right;
constexpr int kHeader = PanelLayout::header, kAbove = PanelLayout::above, kArea = PanelLayout::area;
constexpr int kPanel = PanelLayout::panel, kFooter = PanelLayout::footer;

std::string g7(double v) { return significant(v, 7); }

struct HeightTic {
    double height, p;
};

// Round heights (plots.hpp, round_values) within the heights of [p_min,
// p_max] at alpha, each at its p: H = c / p^2 with c = height_at_p(alpha, 1),
// so p = sqrt(c / H).
std::vector<HeightTic> height_tics(double alpha, double p_min, double p_max) {
    const double c = studies::height_at_p(alpha, 1.0);
    std::vector<HeightTic> tics;
    for (double h : round_values(c / (p_max * p_max), c / (p_min * p_min))) tics.push_back({h, std::sqrt(c / h)});
    return tics;
}

std::string x2tics(const std::vector<HeightTic>& tics) {
    std::string text = "set x2tics (";
    for (std::size_t i = 0; i < tics.size(); ++i) {
        char label[32];
        std::snprintf(label, sizeof label, "%g", tics[i].height);
        text += (i ? ", " : "") + gp_text(label) + " " + gp_number(tics[i].p);
    }
    return text + ")\n";
}

// One y range for every panel: from the decade below the smallest maximum of
// a run that does not overturn (not below 1e-3) to the decade above the
// largest (not below 1, where theta reaches alpha); the strip of overturned
// runs above it.
struct YRange {
    double lo = 1e-3, top = 1;
    bool clamped = false;  // some run's maximum lies below lo
    double strip() const { return 2 * top; }
    double max() const { return 4 * top; }
};

YRange y_range(const std::vector<SpectrumStudy>& studies) {
    double lo = std::numeric_limits<double>::infinity(), hi = 0;
    bool below = false;
    for (const SpectrumStudy& s : studies)
        for (const studies::SpectrumPoint& pt : s.spectrum.points) {
            if (pt.overturning || !std::isfinite(pt.max_theta)) continue;
            hi = std::max(hi, pt.max_theta);
            if (pt.max_theta > 0) lo = std::min(lo, pt.max_theta);
            below = below || pt.max_theta < 1e-3;
        }
    YRange y;
    if (std::isfinite(lo)) y.lo = std::max(1e-3, std::pow(10.0, std::floor(std::log10(lo))));
    if (hi > 1) y.top = std::pow(10.0, std::ceil(std::log10(hi)));
    y.clamped = below;
    return y;
}

std::string outcome(const studies::SpectrumMark& m) {
    const std::string name = m.block.built.empty() ? "p " + g7(m.block.p) : m.block.built;
    return name + ": " + (m.overturns ? "overturns" : "safe");
}

std::string panel_title(const SpectrumStudy& s) {
    const std::size_t n = s.spectrum.intervals.size();
    std::string text = "α = " + g7(s.spectrum.alpha) + ": ";
    if (!s.spectrum.lifts) return text + "the record never lifts the block";
    return text + std::to_string(n) + " overturning interval" + (n == 1 ? "" : "s");
}

// The caption, below the key: what the axes and marks mean (screen labels,
// drawn with the last panel).
std::string caption_labels(const Figure& fig, const YRange& y) {
    std::string caption = "Top axis: H = 2R cos α, R = 3g/(4p²) (eqs. 2, 4), the block of the panel's α whose "
                          "pulsation is p. Dotted: max |θ| = α; above the grey line, the strip of overturned runs.";
    if (y.clamped) caption += " Maxima below " + g7(y.lo) + " are drawn at " + g7(y.lo) + ".";
    const std::vector<std::string> lines = wrapped(caption, 150);
    std::string text;
    for (std::size_t i = 0; i < lines.size(); ++i)
        text += "set label " + std::to_string(100 + i) + " " + gp_text(lines[i]) + " at " +
                fig.screen(kWidth / 2, fig.height - 40 + 16 * static_cast<int>(i)) + " center font ',10'\n";
    return text;
}

}  // namespace

std::string spectrum_panels(const Figure& fig, int first_top, const studies::SpectrumOptions& o,
                   const std::vector<SpectrumStudy>& studies, const std::vector<studies::SpectrumMark>& marks) {
    const int n = static_cast<int>(studies.size());
    const YRange y = y_range(studies);
    std::ostringstream gp;
    for (int k = 0; k < n; ++k) {
        std::vector<std::vector<double>> rows;
        for (const studies::SpectrumPoint& pt : studies[k].spectrum.points)
            rows.push_back({pt.p, pt.max_theta, pt.overturning ? 1.0 : 0.0});
        gp << datablock("spectrum" + std::to_string(k), rows);
    }
    gp << "set logscale xy\nset logscale x2\nset grid\n"
       << "set xrange [" << gp_number(o.p_min) << ":" << gp_number(o.p_max) << "]\n"
       << "set x2range [" << gp_number(o.p_min) << ":" << gp_number(o.p_max) << "]\n"
       << "set yrange [" << gp_number(y.lo) << ":" << gp_number(y.max()) << "]\n"
       << log_tics("x", o.p_min, o.p_max) << "set xtics nomirror\nset ytics nomirror\nset format x '%g'\nset format y '%g'\n"
       << "set xlabel 'p [rad/s]'\nset ylabel 'max |θ|/α during the input'\n";
    const bool any_mark = !marks.empty();
    // assess draws the record's spectrum without Table 1's search: no key for a line not drawn.
    bool any_table1 = false;
    for (const SpectrumStudy& s : studies) any_table1 = any_table1 || s.table1.found;
    for (int k = 0; k < n; ++k) {
        const SpectrumStudy& s = studies[k];
        const int top = first_top + k * kPanel + kAbove;
        gp << fig.area(kLeft, top, kRight, top + kArea) << "unset object\nunset arrow\nunset label\n";
        int objects = 0, arrows = 0, labels = 0;
        for (const studies::Interval& in : s.spectrum.intervals)
            gp << "set object " << ++objects << " rect from " << gp_number(in.from) << ", graph 0 to "
               << gp_number(in.to) << ", graph 1 fc rgb '#e06060' fs transparent solid 0.3 noborder behind\n";
        // theta = alpha, and the strip of the overturned runs above the data.
        gp << "set arrow " << ++arrows << " from graph 0, first 1 to graph 1, first 1 nohead dt 3 lc rgb 'gray40'\n";
        gp << "set arrow " << ++arrows << " from graph 0, first " << gp_number(y.top) << " to graph 1, first "
           << gp_number(y.top) << " nohead lc rgb 'gray60'\n";
        int in_panel = 0;
        for (const studies::SpectrumMark& m : marks) {
            if (m.block.alpha != s.spectrum.alpha) continue;
            gp << "set arrow " << ++arrows << " from " << gp_number(m.block.p) << ", graph 0 to "
               << gp_number(m.block.p) << ", graph 1 nohead lw 4 lc rgb '#008000' front\n";
            gp << "set label " << ++labels << " " << gp_text(outcome(m)) << " at " << gp_number(m.block.p)
               << ", graph " << g7(0.08 + 0.1 * (in_panel++ % 4))
               << " left offset 0.4,0 front tc rgb '#006000' font ',10'\n";
        }
        // After the marks, dashed over their wider line: a block marked at
        // Table 1's own p hid it.
        if (s.table1.found)
            gp << "set arrow " << ++arrows << " from " << gp_number(s.table1.p) << ", graph 0 to "
               << gp_number(s.table1.p) << ", graph 1 nohead lw 2 dt 2 lc rgb 'blue' front\n";
        gp << x2tics(height_tics(s.spectrum.alpha, o.p_min, o.p_max))
           << "set x2label " << gp_text("H [m]: the height of the block of α = " + g7(s.spectrum.alpha) + " at this p")
           << "\nset title " << gp_text(panel_title(s)) << " offset 0,0.2\n";
        const bool last = k == n - 1;
        if (last)
            gp << "set key at " << fig.screen(kWidth / 2, first_top + n * kPanel + 12)
               << " center top horizontal maxcols 3 samplen 2.5 spacing 1.1 font ',10' opaque box lc rgb 'gray80'\n";
        else gp << "unset key\n";
        if (last) gp << caption_labels(fig, y);
        const std::string data = "$spectrum" + std::to_string(k);
        gp << "plot " << data << " using 1:($3 != 0 ? 1/0 : ($2 > " << gp_number(y.lo) << " ? $2 : " << gp_number(y.lo)
           << ")) with lines lw 2 lc rgb 'black' title 'max |θ|/α, a run that does not overturn', " << data
           << " using 1:($3 != 0 ? " << gp_number(y.strip())
           << " : 1/0) with points pt 7 ps 0.5 lc rgb '#c00000' title 'overturned run (θ reaches the fall angle)'";
        if (last)
            gp << ", NaN with boxes fs transparent solid 0.3 lc rgb '#e06060' title 'overturning interval (ends bisected)'"
               << (any_table1 ? ", NaN with lines lw 2 dt 2 lc rgb 'blue' title \"Table 1's p (its upward search's first collapse)\""
                              : "")
               << (any_mark ? ", NaN with lines lw 4 lc rgb '#008000' title 'marked block: its outcome at its p'" : "");
        gp << "\n";
    }
    return gp.str();
}

namespace {

std::string script(const std::string& output, const records::Record& r, const studies::SpectrumOptions& o,
                   const std::vector<SpectrumStudy>& studies, const std::vector<studies::SpectrumMark>& marks) {
    const Figure fig{kWidth, kHeader + static_cast<int>(studies.size()) * kPanel + kFooter};
    return fig.terminal(output) + "set termoption noenhanced\nset multiplot title " +
           gp_string("Rocking spectrum: " + r.name) + "\n" + spectrum_panels(fig, kHeader, o, studies, marks) + "unset multiplot\n";
}

}  // namespace

void write_spectrum_png(const std::string& png, const records::Record& r, const studies::SpectrumOptions& o,
                        const std::vector<SpectrumStudy>& studies, const std::vector<studies::SpectrumMark>& marks) {
    draw_png(png, [&](const std::string& output) { return script(output, r, o, studies, marks); });
}

}  // namespace rocking::cli
