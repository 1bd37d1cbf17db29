// rocking fragility --png (issue 40): one panel per block.  The fitted
// lognormal P(overturn | q) = Phi(ln(q / median) / beta) (studies/fragility.hpp,
// (F1)) sampled here, so that the script holds the points drawn; under
// --method refine beside it the fits on the first robust collapse and on the
// stripes, named.  The empirical points are each overturning record's share
// (studies::empirical_curve), the censored records (no overturning up to
// q_max) drawn apart at q_max.
//
// The bootstrap band: studies::BootstrapInterval keeps the percentile
// intervals of the median and of beta, not the resampled fits, so no
// pointwise band of the resampled curves can be drawn.  What is drawn is the
// envelope of the curves whose median and beta lie in those two intervals:
// at each q, Phi(ln(q/m)/b) is monotone in m and in b, so its least and
// greatest over the rectangle [median_lo, median_hi] x [beta_lo, beta_hi]
// are at its corners.  The caption says so.
#include <algorithm>
#include <cmath>
#include <sstream>
#include <string>
#include <vector>

#include "cli/plots.hpp"

namespace rocking::cli {

namespace {

using studies::BlockFragility;

constexpr int kPanelWidth = 760, kLeft = 70, kRight = 20;
constexpr int kHeader = 36, kAbove = 50, kArea = 300, kBelow = 50;
constexpr int kKey = 70;  // the panel's key, below its axis
constexpr int kPanelHeight = kAbove + kArea + kBelow + kKey;
constexpr int kCurvePoints = 241;  // log-spaced over [q_min, q_max], both included

std::string g4(double v) { return significant(v, 4); }

double lognormal(double q, double median, double beta) {
    return 0.5 * std::erfc(-std::log(q / median) / (beta * std::sqrt(2.0)));
}

int columns_for(std::size_t blocks) { return blocks == 1 ? 1 : 2; }
int rows_for(std::size_t blocks) {
    const std::size_t columns = columns_for(blocks);
    return static_cast<int>((blocks + columns - 1) / columns);
}

bool refined(const studies::FragilityStudyOptions& o) { return o.ida.method == studies::IdaOptions::Method::refine; }

// The headline fit's name: on the first overturning under refine (its capacity), else the first collapse.
std::string fit_name(const studies::FragilityStudyOptions& o) {
    return refined(o) ? "first overturning" : "lognormal fit";
}

std::string fit_words(double median, double beta) { return "median " + g4(median) + ", β " + g4(beta); }

int censored_of(const BlockFragility& f) {
    int n = 0;
    for (const studies::IdaPoint& p : f.points) n += !p.collapsed;
    return n;
}

// The curves' rows: q, the fit, the band's low and high ends, the robust
// collapse's fit, the stripes' fit (0 where a curve is not drawn).
std::vector<std::vector<double>> curve_rows(const BlockFragility& f, const studies::FragilityStudyOptions& o) {
    std::vector<std::vector<double>> rows;
    for (int i = 0; i < kCurvePoints; ++i) {
        const double lo = o.ida.q_start(f.block.alpha, f.block.p);  // where the block's grid started
        const double q = lo * std::pow(o.ida.q_max / lo, static_cast<double>(i) / (kCurvePoints - 1));
        std::vector<double> row{q, f.fitted ? studies::overturning_probability(f.fit, q) : 0.0, 0.0, 0.0, 0.0, 0.0};
        if (f.fitted && f.bootstrapped) {
            double lo = 1, hi = 0;
            for (double m : {f.interval.median.lo, f.interval.median.hi})
                for (double b : {f.interval.beta.lo, f.interval.beta.hi}) {
                    lo = std::min(lo, lognormal(q, m, b));
                    hi = std::max(hi, lognormal(q, m, b));
                }
            row[2] = lo;
            row[3] = hi;
        }
        if (f.three_ways && f.robust.fitted) row[4] = studies::overturning_probability(f.robust.fit, q);
        if (f.three_ways && f.stripes.fitted) row[5] = lognormal(q, f.stripes.fit.median, f.stripes.fit.beta);
        rows.push_back(row);
    }
    return rows;
}

std::string panel_title(const BlockFragility& f) {
    std::string text = "α = " + significant(f.block.alpha, 7) + ", p = " + significant(f.block.p, 7) + " rad/s";
    if (!f.block.built.empty()) text += " (block " + f.block.built + " m)";
    return text + ": n = " + std::to_string(f.points.size()) + " records, " + std::to_string(censored_of(f)) + " censored";
}

std::string caption(const studies::FragilityStudyOptions& o, const std::vector<BlockFragility>& study) {
    std::string text = "P(overturn | q) = Φ(ln(q/median)/β), q = PGA/(α g), fitted by maximum likelihood with the "
                       "censored records kept. Points: each overturning record at its " +
                       std::string(refined(o) ? "first overturning" : "first collapse") +
                       " q and the share of all records overturned at or below it; triangles: the records censored at "
                       "q_max = " + g4(o.ida.q_max) + " (no overturning up to it).";
    bool band = false;
    for (const BlockFragility& f : study) band = band || (f.fitted && f.bootstrapped);
    if (band)
        text += " Band: the envelope of the curves whose median and β lie in their " + g4(100 * o.level) +
                " % bootstrap percentile intervals (" + std::to_string(o.resamples) + " resamples, seed " +
                std::to_string(o.seed) + "), each interval taken apart: the resampled fits are not kept, so it is "
                "not a pointwise confidence band.";
    if (refined(o))
        text += " Squares: each stripe's mean overturned share, to which the multiple-stripe fit is fitted.";
    // With --floor the intensities are the floor's: said in the figure itself.
    if (!o.ida.input_note.empty()) text += " Input: " + typographic_quotes(o.ida.input_note) + ".";
    return text;
}

std::string panel(const Figure& fig, const BlockFragility& f, const studies::FragilityStudyOptions& o, int k,
                  int left, int top) {
    std::ostringstream gp;
    const std::string id = std::to_string(k);
    gp << datablock("curve" + id, curve_rows(f, o));
    std::vector<std::vector<double>> empirical, censored, stripes;
    for (const studies::EmpiricalPoint& e : f.empirical) empirical.push_back({e.q, e.share});
    const double reached = f.empirical.empty() ? 0.0 : f.empirical.back().share;
    for (const studies::IdaPoint& p : f.points)
        if (!p.collapsed) censored.push_back({p.q, reached});
    if (f.three_ways)
        for (const studies::Stripe& s : f.stripes.stripes) stripes.push_back({s.q, s.overturned / s.records});
    gp << datablock("empirical" + id, empirical) << datablock("censored" + id, censored);
    if (f.three_ways) gp << datablock("stripes" + id, stripes);
    gp << fig.area(left + kLeft, top + kAbove, left + kPanelWidth - kRight, top + kAbove + kArea)
       << "unset label\nset title " << gp_text(panel_title(f)) << "\n"
       << "set key at " << fig.screen(left + kLeft - 40, top + kAbove + kArea + kBelow + 4)
       << " left top vertical maxrows 4 Left reverse font ',9' samplen 1.5 spacing 0.9 width -4\n";
    if (!f.fitted) {
        const std::vector<std::string> lines = wrapped("no fit: " + f.no_fit, 60);
        for (std::size_t i = 0; i < lines.size(); ++i)
            gp << "set label " << i + 1 << " " << gp_text(lines[i]) << " at graph 0.03, graph "
               << significant(0.6 - 0.06 * i, 4) << " font ',9' tc rgb '#a00000'\n";
    }
    const std::string curve = "$curve" + id;
    std::vector<std::string> plots;
    if (f.fitted && f.bootstrapped)
        plots.push_back(curve + " using 1:3:4 with filledcurves fc rgb '#4060c0' fs transparent solid 0.2 noborder title " +
                        gp_text(g4(100 * f.interval.level) + " % bootstrap band, " +
                                (refined(o) ? "first overturning" : "this fit")));
    if (f.fitted)
        plots.push_back(curve + " using 1:2 with lines lw 2 lc rgb '#2040a0' title " +
                        gp_text(fit_name(o) + ": " + fit_words(f.fit.median, f.fit.beta)));
    if (f.three_ways && f.robust.fitted)
        plots.push_back(curve + " using 1:5 with lines lw 2 dt 2 lc rgb '#c06000' title " +
                        gp_text("first robust collapse: " + fit_words(f.robust.fit.median, f.robust.fit.beta)));
    if (f.three_ways && f.stripes.fitted)
        plots.push_back(curve + " using 1:6 with lines lw 2 dt 3 lc rgb '#008000' title " +
                        gp_text("stripes: " + fit_words(f.stripes.fit.median, f.stripes.fit.beta)));
    if (f.three_ways && !stripes.empty())
        // Grey, not the stripe fit's green: a newcomer read the two as one series.
        plots.push_back("$stripes" + id + " using 1:2 with points pt 5 ps 0.35 lc rgb '#808080' title " +
                        gp_text("stripes' mean share"));
    if (!empirical.empty())
        plots.push_back("$empirical" + id + " using 1:2 with points pt 7 ps 0.8 lc rgb 'black' title " +
                        gp_text("empirical (" + std::to_string(empirical.size()) + " overturned)"));
    if (!censored.empty())
        plots.push_back("$censored" + id + " using 1:2 with points pt 8 ps 1.4 lc rgb '#a00000' title " +
                        gp_text("censored at q_max (" + std::to_string(censored.size()) + ")"));
    if (plots.empty()) plots.push_back("NaN notitle");
    gp << "plot ";
    for (std::size_t i = 0; i < plots.size(); ++i) gp << (i ? ", " : "") << plots[i];
    gp << "\n";
    return gp.str();
}

std::string script(const std::string& output, const std::vector<std::string>& files,
                   const studies::FragilityStudyOptions& o, const std::vector<BlockFragility>& study) {
    const int columns = columns_for(study.size()), rows = rows_for(study.size());
    const int width = columns * kPanelWidth;
    // The caption below the panels, its lines as many as it takes at about 7 pixels a character.
    const std::vector<std::string> lines = wrapped(caption(o, study), width / 7);
    const int footer = 24 + 16 * static_cast<int>(lines.size());
    const Figure fig{width, kHeader + rows * kPanelHeight + footer};
    // From the lowest block's grid start: an imperfect block's lies below q_min.
    double q_lo = o.ida.q_min;
    for (const BlockFragility& f : study) q_lo = std::min(q_lo, o.ida.q_start(f.block.alpha, f.block.p));
    std::ostringstream gp;
    gp << fig.terminal(output) << "set termoption noenhanced\n"
       << "set multiplot title " << gp_text("Fragility of " + std::to_string(study.size()) + " block(s) over " +
                                           std::to_string(files.size()) + " record(s)") << "\n"
       << "set logscale x\nset grid\nset xrange [" << gp_number(q_lo) << ":" << gp_number(o.ida.q_max) << "]\n"
       << log_tics("x", q_lo, o.ida.q_max) << "set yrange [0:1.04]\nset ytics 0.2\nset format x '%g'\nset xlabel 'q = PGA/(α g)'\n"
       << "set ylabel 'P(overturn | q)'\n";
    for (std::size_t k = 0; k < study.size(); ++k) {
        const int column = static_cast<int>(k) % columns, row = static_cast<int>(k) / columns;
        gp << panel(fig, study[k], o, static_cast<int>(k), column * kPanelWidth, kHeader + row * kPanelHeight);
    }
    gp << "unset label\n";
    gp << caption_and_end(fig, lines, footer);
    return gp.str();
}

}  // namespace

void write_fragility_png(const std::string& png, const std::vector<std::string>& files,
                         const studies::FragilityStudyOptions& o, const std::vector<BlockFragility>& study) {
    draw_png(png, [&](const std::string& output) { return script(output, files, o, study); });
}

}  // namespace rocking::cli
