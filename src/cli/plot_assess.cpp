// rocking assess --png (issue 40): the check on one record, in two panels.
// The paper's verdict compares two q's (the record's and eq. 27's); the
// model's answer is where the runs of the scaled record overturn.  The upper
// panel puts both on one axis of q, the record's scale factor on top, so
// that the margin and the first overturning read off one picture; the lower
// is the record's spectrum at the block's alpha with the block marked, as
// `rocking spectrum --mark` draws it (its key serves both panels: the same
// line, points and shading).
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <sstream>
#include <string>
#include <vector>

#include "cli/plots.hpp"

namespace rocking::cli {

namespace {

using L = PanelLayout;

std::string g4(double v) { return significant(v, 4); }

// As the spectrum's: from the decade below the smallest peak of a run that
// does not overturn (not below 1e-3) to the decade above the largest (not
// below 1); the overturned runs in a strip above.
struct YRange {
    double lo = 1e-3, top = 1;
};

YRange y_range(const std::vector<studies::ScaledRun>& runs) {
    double lo = std::numeric_limits<double>::infinity(), hi = 0;
    for (const studies::ScaledRun& r : runs) {
        if (r.overturns || !(r.peak_theta_over_alpha > 0)) continue;
        lo = std::min(lo, r.peak_theta_over_alpha);
        hi = std::max(hi, r.peak_theta_over_alpha);
    }
    YRange y;
    if (std::isfinite(lo)) y.lo = std::max(1e-3, std::pow(10.0, std::floor(std::log10(lo))));
    if (hi > 1) y.top = std::pow(10.0, std::ceil(std::log10(hi)));
    return y;
}

struct Line {
    double q;
    std::string label, style;
};

std::string response_panel(const Figure& fig, const studies::RecordAssessment& a,
                           const std::vector<studies::ScaledRun>& runs) {
    const double q_lo = runs.front().q, q_hi = runs.back().q;
    const YRange y = y_range(runs);
    std::vector<std::vector<double>> rows;
    for (const studies::ScaledRun& r : runs) rows.push_back({r.q, r.peak_theta_over_alpha, r.overturns ? 1.0 : 0.0});
    std::ostringstream gp;
    gp << datablock("response", rows);
    const int top = L::header + L::above;
    gp << fig.area(L::left, top, L::right, top + L::area) << "unset key\n"
       << "set logscale xy\nset logscale x2\nset grid\n"
       << "set xrange [" << gp_number(q_lo) << ":" << gp_number(q_hi) << "]\n"
       << "set x2range [" << gp_number(q_lo / a.q_record) << ":" << gp_number(q_hi / a.q_record) << "]\n"
       << "set yrange [" << gp_number(y.lo) << ":" << gp_number(4 * y.top) << "]\n"
       << log_tics("x", q_lo, q_hi) << log_tics("x2", q_lo / a.q_record, q_hi / a.q_record)
       << "set xtics nomirror\nset x2tics nomirror\nset ytics nomirror\nset format x '%g'\nset format x2 '%g'\n"
       << "set format y '%g'\nset xlabel " << gp_text(typographic_quotes("q = PGA/(α g) of the record scaled (" + std::to_string(runs.size()) +
                                                                 " runs; shaded: the IDA's overturning intervals)")) << "\n"
       << "set x2label " << gp_text(typographic_quotes("the record's scale factor (q / the record's q = " + g4(a.q_record) + ")")) << "\n"
       << "set ylabel 'max |θ|/α during the input'\n";
    int objects = 0, arrows = 0;
    for (const studies::IdaInterval& in : a.ida.intervals)
        gp << "set object " << ++objects << " rect from " << gp_number(std::max(in.from, q_lo)) << ", graph 0 to "
           << gp_number(std::min(in.to, q_hi)) << ", graph 1 fc rgb '#e06060' fs transparent solid 0.3 noborder behind\n";
    gp << "set arrow " << ++arrows << " from graph 0, first 1 to graph 1, first 1 nohead dt 3 lc rgb 'gray40'\n";
    gp << "set arrow " << ++arrows << " from graph 0, first " << gp_number(y.top) << " to graph 1, first "
       << gp_number(y.top) << " nohead lc rgb 'gray60'\n";
    // The check's two q's and the model's two, each a line named in the
    // panel's own key (q and the scale factor alike): labels on the lines
    // crossed each other where the record's q and eq. 27's lie 0.3 % apart.
    std::vector<Line> lines = {{a.q_record, "the record: q = " + g4(a.q_record) + " (x1)", "lw 2 lc rgb '#1f5fbf'"},
                               {a.q_eq27, "eq. 27: q = " + g4(a.q_eq27), "lw 2 dt 2 lc rgb '#d07000'"}};
    if (a.ida.first_overturning.collapsed)
        lines.push_back({a.ida.first_overturning.q, "first overturning: q = " + g4(a.ida.first_overturning.q) + " (x" +
                                                        g4(a.scale_first_overturning) + ")",
                         "lw 2 lc rgb '#b00000'"});
    if (a.ida.first_robust_collapse.collapsed)
        lines.push_back({a.ida.first_robust_collapse.q, "first robust collapse: q = " + g4(a.ida.first_robust_collapse.q) +
                                                            " (x" + g4(a.scale_first_robust) + ")",
                         "lw 2 dt 3 lc rgb '#600000'"});
    std::string keyed;
    for (Line& l : lines) {
        if (l.q >= q_lo && l.q <= q_hi)
            gp << "set arrow " << ++arrows << " from " << gp_number(l.q) << ", graph 0 to " << gp_number(l.q)
               << ", graph 1 nohead " << l.style << " back\n";  // under the opaque key
        else l.label += " (off the axis)";  // eq. 27's q can lie off the IDA's range
        keyed += ", NaN with lines " + l.style + " title " + gp_text(l.label);
    }
    char margin[40];
    std::snprintf(margin, sizeof margin, std::fabs(100 * a.margin) < 1e5 ? "%+.1f %%" : "%+.3g %%", 100 * a.margin);
    const std::string verdict = std::string("eq. 27 check ") + (a.passes ? "PASSES" : "FAILS") + " (margin " + margin +
                                "); the model: the record " + (a.overturns ? "overturns" : "does not overturn") +
                                " the block";
    gp << "set title " << gp_text(verdict) << " offset 0,0.2\n"
       << "set key top left opaque box lc rgb 'gray80' font ',9' samplen 2 spacing 1\n"
       << "plot $response using 1:($3 != 0 ? 1/0 : ($2 > " << gp_number(y.lo) << " ? $2 : " << gp_number(y.lo)
       << ")) with lines lw 2 lc rgb 'black' notitle, $response using 1:($3 != 0 ? " << gp_number(2 * y.top)
       << " : 1/0) with points pt 7 ps 0.5 lc rgb '#c00000' notitle" << keyed << "\n";
    // The spectrum's panels set their own tics and key; the top axis here is the scale's.
    gp << "unset x2tics\nunset label\nunset arrow\nunset object\nunset title\n";
    return gp.str();
}

}  // namespace

void write_assess_png(const std::string& png, const records::Record& r, const studies::RecordAssessment& a,
                      const std::vector<studies::ScaledRun>& response, const studies::SpectrumOptions& o) {
    const Figure fig{L::width, L::header + 2 * L::panel + L::footer};
    const std::vector<jobs::SpectrumStudy> spectra = {jobs::SpectrumStudy{a.spectrum, records::CollapseResult{}}};
    draw_png(png, [&](const std::string& output) {
        return fig.terminal(output) + "set termoption noenhanced\nset multiplot title " +
               gp_string("The check of " + (a.mark.block.built.empty() ? std::string("the block") : a.mark.block.built + " m") +
                         " on " + r.name) +
               "\n" + response_panel(fig, a, response) + spectrum_panels(fig, L::header + L::panel, o, spectra, {a.mark}) +
               "unset multiplot\n";
    });
}

}  // namespace rocking::cli
