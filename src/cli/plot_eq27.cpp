// rocking eq27 --png (issue 40): two panels.  Left, the non-conservative
// share per to_k with the intervals the text prints: the bootstrap over
// records where --bootstrap ran it, and Wilson's (the cases taken as
// independent); under --method refine both capacities side by side.  Right,
// every case (record x block) at to_5, the paper's recommendation: the
// record's capacity q against eq. 27's q at x = p to_5, the 1:1 line, the
// non-conservative cases (capacity below eq. 27's q, under the line) marked,
// the censored ones (no overturning up to q_max) drawn at q_max.
#include <algorithm>
#include <cmath>
#include <sstream>
#include <string>
#include <vector>

#include "cli/plots.hpp"

namespace rocking::cli {

namespace {

using studies::Eq27Study;
using studies::kHalfPeriods;

constexpr int kPanelWidth = 600, kLeft = 75, kRight = 25;
constexpr int kHeader = 36, kAbove = 40, kArea = 360, kBelow = 55, kKey = 64;
constexpr int kTo5 = 4;  // to_5's index: the paper's recommended half-period

std::string g4(double v) { return significant(v, 4); }

bool refined(const studies::Eq27Options& o) { return o.ida.method == studies::IdaOptions::Method::refine; }
bool bootstrapped(const Eq27Study& s) { return s.bootstrap.resamples > 0; }

// One capacity's shares: k, share, the bootstrap's ends (0 without one), Wilson's ends, the counts.
std::vector<std::vector<double>> share_rows(const Eq27Study& s) {
    std::vector<std::vector<double>> rows;
    for (int k = 0; k < kHalfPeriods; ++k) {
        const studies::Eq27Share& sh = s.shares[k];
        rows.push_back({static_cast<double>(k + 1), sh.share, sh.bootstrap.lo, sh.bootstrap.hi, sh.wilson.lo,
                        sh.wilson.hi, static_cast<double>(sh.non_conservative), static_cast<double>(sh.cases)});
    }
    return rows;
}

struct Series {
    const Eq27Study* study;
    std::string name;  // the capacity, in the key
    const char* colour;
};

std::string shares_panel(const studies::Eq27Options& o, const studies::Eq27ByCapacity& by) {
    std::vector<Series> series{{&by.first_overturning, refined(o) ? "first overturning" : "first collapse", "#2040a0"}};
    if (refined(o)) series.push_back({&by.first_robust_collapse, "first robust collapse", "#c06000"});
    const bool boot = bootstrapped(by.first_overturning);
    // Each capacity's bars side by side at its k: the bootstrap's (filled) then Wilson's (open).
    const int per_k = static_cast<int>(series.size()) * (boot ? 2 : 1);
    const double step = 0.18, first = -step * (per_k - 1) / 2;
    std::ostringstream gp;
    std::vector<std::string> plots;
    int slot = 0;
    for (std::size_t i = 0; i < series.size(); ++i) {
        const std::string data = "$shares" + std::to_string(i);
        gp << datablock("shares" + std::to_string(i), share_rows(*series[i].study));
        const std::string colour = std::string(" lc rgb '") + series[i].colour + "'";
        if (boot)
            plots.push_back(data + " using ($1 + " + g4(first + step * slot++) +
                            "):2:3:4 with yerrorbars pt 7 ps 0.8 lw 2" + colour + " title " +
                            gp_text(series[i].name + ": " + g4(100 * by.first_overturning.bootstrap.level) +
                                    " % bootstrap over records"));
        plots.push_back(data + " using ($1 + " + g4(first + step * slot++) + "):2:5:6 with yerrorbars pt 6 ps 0.8 lw 1" +
                        colour + " title " +
                        gp_text(series[i].name + ": " + g4(100 * by.first_overturning.level) +
                                " % Wilson (cases as independent)"));
    }
    const Eq27Study& s = by.first_overturning;
    gp << "set title " << gp_text("non-conservative share per to_k: " + std::to_string(s.records) + " records x " +
                                  std::to_string(s.blocks.size()) + " blocks = " + std::to_string(s.cases.size()) +
                                  " cases") << "\n"
       << "unset logscale\nset xrange [0.4:11.6]\nset yrange [0:1]\nset ytics 0.2\nset xtics 1\nset format x 'to_%g'\n"
       << "set xlabel 'the half-period to_k at which eq. 27 is evaluated'\n"
       << "set ylabel 'share of cases non-conservative'\nplot ";
    for (std::size_t i = 0; i < plots.size(); ++i) gp << (i ? ", " : "") << plots[i];
    gp << "\n";
    return gp.str();
}

// Each case at to_5: x = p to_5, eq. 27's q there, the capacity q, and 0
// (conservative), 1 (non-conservative) or 2 (censored).
std::vector<std::vector<double>> case_rows(const Eq27Study& s,
                                           const std::vector<std::array<double, kHalfPeriods>>& to) {
    std::vector<std::vector<double>> rows;
    for (const studies::Eq27Case& c : s.cases) {
        const double flag = !c.point.collapsed ? 2 : c.non_conservative[kTo5] ? 1 : 0;
        rows.push_back({s.blocks[c.block].p * to[c.record][kTo5], c.q_eq27[kTo5], c.point.q, flag});
    }
    return rows;
}

std::string cases_panel(const studies::Eq27Options& o, const Eq27Study& s,
                        const std::vector<std::array<double, kHalfPeriods>>& to) {
    const std::vector<std::vector<double>> rows = case_rows(s, to);
    double lo = o.ida.q_min, hi = o.ida.q_max;
    int counts[3] = {0, 0, 0};
    for (const std::vector<double>& r : rows) {
        lo = std::min({lo, r[1], r[2]});
        hi = std::max({hi, r[1], r[2]});
        ++counts[static_cast<int>(r[3])];
    }
    lo /= 1.1;
    hi *= 1.1;
    const std::string capacity = refined(o) ? "first overturning q" : "first collapse q";
    std::ostringstream gp;
    gp << datablock("cases", rows) << "set title "
       << gp_text("each record x block at to_5: " + std::to_string(counts[1]) + " of " + std::to_string(rows.size()) +
                  " non-conservative") << "\n"
       << "set logscale xy\nset xrange [" << gp_number(lo) << ":" << gp_number(hi) << "]\nset yrange ["
       << gp_number(lo) << ":" << gp_number(hi) << "]\n" << log_tics("x", lo, hi) << log_tics("y", lo, hi)
       << "set format x '%g'\n"
       << "set format y '%g'\nset xlabel \"eq. 27's q at x = p·to_5\"\nset ylabel "
       << gp_text("the record's " + capacity + " (its capacity)") << "\n"
       << "plot x with lines dt 2 lc rgb 'gray30' title '1:1 (under it: non-conservative)', "
       << "$cases using 2:($4 == 0 ? $3 : 1/0) with points pt 7 ps 0.6 lc rgb '#2040a0' title "
       << gp_text("conservative (" + std::to_string(counts[0]) + ")") << ", "
       << "$cases using 2:($4 == 1 ? $3 : 1/0) with points pt 5 ps 0.7 lc rgb '#c00000' title "
       << gp_text("non-conservative: capacity below eq. 27's q (" + std::to_string(counts[1]) + ")") << ", "
       << "$cases using 2:($4 == 2 ? $3 : 1/0) with points pt 8 ps 0.9 lc rgb 'gray40' title "
       << gp_text("censored at q_max = " + g4(o.ida.q_max) + ", conservative (" + std::to_string(counts[2]) + ")")
       << "\n";
    return gp.str();
}

std::string caption(const studies::Eq27Options& o, const studies::Eq27ByCapacity& by) {
    const Eq27Study& s = by.first_overturning;
    std::string text = "A case is non-conservative when the record overturns the block at a q below eq. 27's at "
                       "x = p·to_k; a record that never overturns it up to q_max is censored and counted as "
                       "conservative. Bars: ";
    if (bootstrapped(s))
        text += "filled, the " + g4(100 * s.bootstrap.level) + " % bootstrap over records (" +
                std::to_string(s.bootstrap.resamples) + " resamples, seed " + std::to_string(s.bootstrap.seed) +
                ", the interval to quote); open, ";
    text += "Wilson's " + g4(100 * s.level) + " % interval, which takes the cases as independent and is too narrow";
    text += bootstrapped(s) ? "." : " (the bootstrap over records was not run: --bootstrap K --seed S).";
    if (refined(o))
        text += " Capacities: the first overturning (every island wider than w = " + g4(o.ida.width) +
                " in ln q) and the first robust collapse (the first interval wider than " + g4(o.ida.robust_width) +
                "); the right panel shows the first overturning.";
    // With --floor the intensities are the floor's: said in the figure itself.
    if (!o.ida.input_note.empty()) text += " Input: " + typographic_quotes(o.ida.input_note) + ".";
    return text;
}

std::string script(const std::string& output, const std::vector<std::string>& files, const studies::Eq27Options& o,
                   const studies::Eq27ByCapacity& by, const std::vector<std::array<double, kHalfPeriods>>& to) {
    const int width = 2 * kPanelWidth;
    const std::vector<std::string> lines = wrapped(caption(o, by), width / 7);
    const int footer = 24 + 16 * static_cast<int>(lines.size());
    const Figure fig{width, kHeader + kAbove + kArea + kBelow + kKey + footer};
    const int key_top = kHeader + kAbove + kArea + kBelow;
    std::ostringstream gp;
    gp << fig.terminal(output) << "set termoption noenhanced\n"
       << "set multiplot title " << gp_text("Eq. 27 at scale: " + std::to_string(files.size()) + " record(s) x " +
                                           std::to_string(by.first_overturning.blocks.size()) + " block(s)") << "\n"
       << "set grid\n";
    gp << fig.area(kLeft, kHeader + kAbove, kPanelWidth - kRight, kHeader + kAbove + kArea)
       << "set key at " << fig.screen(kLeft - 40, key_top) << " left top vertical maxrows 4 Left reverse font ',9' "
       << "samplen 1.5 spacing 0.9 width -4\n"
       << shares_panel(o, by);
    gp << fig.area(kPanelWidth + kLeft, kHeader + kAbove, width - kRight, kHeader + kAbove + kArea)
       << "set key at " << fig.screen(kPanelWidth + kLeft - 40, key_top)
       << " left top vertical maxrows 4 Left reverse font ',9' samplen 1.5 spacing 0.9 width -4\n"
       << cases_panel(o, by.first_overturning, to);
    gp << caption_and_end(fig, lines, footer);
    return gp.str();
}

}  // namespace

void write_eq27_png(const std::string& png, const std::vector<std::string>& files, const studies::Eq27Options& o,
                    const studies::Eq27ByCapacity& by, const std::vector<std::array<double, kHalfPeriods>>& to) {
    draw_png(png, [&](const std::string& output) { return script(output, files, o, by, to); });
}

}  // namespace rocking::cli
