// The PNGs of rocking spectrum, fragility and eq27 (issue 40): what the three
// plots share (a script's strings and numbers, a figure laid out in pixels,
// gnuplot run on a script whose data are inline, the PNG landing whole or not
// at all through harness::PlotFile), and each plot's entry point, one file
// each (plot_spectrum.cpp, plot_fragility.cpp, plot_eq27.cpp).
//
// The data go into the script as datablocks ($name << EOD), so that one file
// holds all a plot draws: with ROCKING_PLOT_SCRIPT=FILE in the environment the
// script is also written to FILE, for the tests to read what was drawn
// (the marked block's p, the height tics, the fitted curve's points).
#pragma once

#include <array>
#include <functional>
#include <string>
#include <vector>

#include "cli/options.hpp"
#include "jobs/spectrum_plan.hpp"
#include "records/record.hpp"
#include "studies/assessment.hpp"
#include "studies/eq27_at_scale.hpp"
#include "studies/ida.hpp"
#include "studies/scaled_response.hpp"
#include "studies/spectrum.hpp"
#include "studies/spectrum_mark.hpp"

namespace rocking::cli {

// A string in a gnuplot script: single quotes, inner ones doubled, and only
// printable ASCII (a name's control bytes or invalid UTF-8 must not reach the
// script or cairo).
std::string gp_string(const std::string& s);

// Our own words in a script (UTF-8 kept: θ, α): single quotes, inner ones
// doubled.  Never a name from the inputs: those go through gp_string.
std::string gp_text(const std::string& s);

// Our own words with each ' as ’ (a note's D'' for a second derivative, the
// floor's "floor's"): gnuplot's single-quoted strings split on runs of them.
std::string typographic_quotes(const std::string& s);

// A number in a script or a datablock, to the last bit (%.17g).
std::string gp_number(double v);

// A datablock: "$name << EOD", one line a row of numbers, "EOD".
std::string datablock(const std::string& name, const std::vector<std::vector<double>>& rows);

// Before any work, for a command given --png: gnuplot on PATH, or a
// runtime_error "--png PNG: gnuplot is not installed (make deps)" (exit 1).
void require_gnuplot(const Args& a);

// A figure of width x height pixels whose panels are placed by their plot
// area in pixels from its top left, so that a key or a caption outside them
// takes no panel's room and every panel of a figure gets the same area.
struct Figure {
    int width = 0, height = 0;
    // The terminal (pngcairo at this size) and its output, named as given.
    std::string terminal(const std::string& output) const;
    // The margins that make the next plot's area [left, right] x [top, bottom].
    std::string area(int left, int top, int right, int bottom) const;
    // screen coordinates of a pixel.
    std::string screen(int x, int y) const;
};

// Draws the PNG at `png` with gnuplot from script(output), `output` the name
// the script must draw to (harness::PlotFile::draw_name: gnuplot runs in the
// PNG's folder and never sees the target's own name); the PNG lands whole
// or not at all.  Throws std::runtime_error naming --png PNG.
void draw_png(const std::string& png, const std::function<std::string(const std::string& output)>& script);

// Round numbers (1, 2, 5 x 10^k; finer where the range holds fewer than
// three) in [lo, hi], each the double its shortest text reads back as; the
// range's ends and middle on a log scale, to four digits, where no round
// number falls in it.  Expects 0 < lo < hi.
std::vector<double> round_values(double lo, double hi);

// "set AXIStics (v, v, ...)" at round_values(lo, hi): the tics of a log axis,
// where gnuplot's own give only the decades.
std::string log_tics(const std::string& axis, double lo, double hi);

// The text cut into lines of at most `width` characters at spaces.
std::vector<std::string> wrapped(const std::string& text, std::size_t width);

// A multiplot's end: the caption's lines centred in its footer (`footer`
// pixels above the bottom), drawn by an empty plot, and unset multiplot.
std::string caption_and_end(const Figure& fig, const std::vector<std::string>& lines, int footer);

// ---- The plots ----

// rocking spectrum --png: per alpha, max |theta|/alpha of the runs that do
// not overturn against p, the overturned runs in a strip at the panel's top,
// the overturning intervals shaded, Table 1's p, the marked blocks, and the
// block height H of that alpha on the top axis; one y range for all.
void write_spectrum_png(const std::string& png, const records::Record& r, const studies::SpectrumOptions& o,
                        const std::vector<jobs::SpectrumStudy>& studies, const std::vector<studies::SpectrumMark>& marks);

// The layout, in pixels, of a figure of panels above one another (the
// spectrum's, assess's): a title, the panels (each its title and top axis,
// its plot area, its bottom axis), then the key and the caption.
struct PanelLayout {
    static constexpr int width = 1000, left = 80, right = 970;
    static constexpr int header = 36;   // the figure's title
    static constexpr int above = 80;    // a panel's title, top axis label and tics
    static constexpr int area = 220;    // a panel's plot area
    static constexpr int below = 50;    // its bottom tics and label
    static constexpr int panel = above + area + below;
    static constexpr int footer = 110;  // the key (two rows) and the caption
};

// The spectrum panels of write_spectrum_png, the first `first_top` pixels
// from the figure's top, with their data, axes, key and caption: for a
// figure that draws other panels above them (assess's).
std::string spectrum_panels(const Figure& fig, int first_top, const studies::SpectrumOptions& o,
                            const std::vector<jobs::SpectrumStudy>& studies,
                            const std::vector<studies::SpectrumMark>& marks);

// rocking assess --png: the check on one record.  Above, the block's
// response along the record's scale (peak |theta|/alpha of runs at
// log-spaced q, studies::scaled_response) with the IDA's overturning
// intervals, the record's own q, eq. 27's q and the first overturning and
// robust collapse, the scale factor on the top axis; below, the record's
// spectrum at the block's alpha with the block marked.
void write_assess_png(const std::string& png, const records::Record& r, const studies::RecordAssessment& a,
                      const std::vector<studies::ScaledRun>& response, const studies::SpectrumOptions& o);

// rocking fragility --png: per block, the fitted lognormal curves, the
// empirical points, the censored records and the bootstrap's band.
void write_fragility_png(const std::string& png, const std::vector<std::string>& files,
                         const studies::FragilityStudyOptions& o, const std::vector<studies::BlockFragility>& study);

// rocking fragility --fits CSV: each block's fits as columns (one row per
// block and capacity): median, beta, the bootstrap's ends, or why no fit.
void write_fragility_fits(const std::string& csv, const std::vector<std::string>& files,
                          const studies::FragilityStudyOptions& o, const std::vector<studies::BlockFragility>& study);

// rocking eq27 --png: the non-conservative share per to_k with its
// intervals, and every case's capacity q against eq. 27's q at x = p to_5.
void write_eq27_png(const std::string& png, const std::vector<std::string>& files, const studies::Eq27Options& o,
                    const studies::Eq27ByCapacity& by,
                    const std::vector<std::array<double, studies::kHalfPeriods>>& to);

}  // namespace rocking::cli
