// rocking fragility --fits CSV (issue 40): each block's fits as columns, one
// row per block and capacity, where --output's CSV holds the records' points
// and gives the fits only in '#' notes.  The grid method has one capacity
// (the first collapse); --method refine three (docs/fragility.md, "Three
// capacities"): the first overturning, the first robust collapse, the stripes.
#include <string>
#include <vector>

#include "cli/plots.hpp"
#include "harness/table.hpp"

namespace rocking::cli {

namespace {

using studies::BlockFragility;

const std::string kNone = "-";

void add_bootstrap(harness::Table& t, bool bootstrapped, const studies::BootstrapInterval& b) {
    if (!bootstrapped) {
        for (int i = 0; i < 7; ++i) t.add(kNone);
        return;
    }
    t.add(b.median.lo).add(b.median.hi).add(b.beta.lo).add(b.beta.hi).add(b.resamples)
        .add(std::to_string(b.seed)).add(b.level);
}

// One capacity's fit of points: collapsed and censored counted from them.
void add_point_fit(harness::Table& t, const BlockFragility& f, const std::string& capacity,
                   const std::vector<studies::IdaPoint>& points, bool fitted, const std::string& no_fit,
                   const studies::LognormalFragility& fit, bool bootstrapped, const studies::BootstrapInterval& b) {
    int collapsed = 0;
    for (const studies::IdaPoint& p : points) collapsed += p.collapsed;
    t.row().add(f.block.alpha).add(f.block.p).add(f.block.built.empty() ? kNone : f.block.built).add(capacity)
        .add(static_cast<int>(points.size())).add(collapsed).add(static_cast<int>(points.size()) - collapsed).add(kNone);
    if (fitted) t.add(fit.median).add(fit.beta).add(fit.log_likelihood);
    else t.add(kNone).add(kNone).add(kNone);
    add_bootstrap(t, fitted && bootstrapped, b);
    t.add(fitted ? kNone : no_fit);
}

}  // namespace

void write_fragility_fits(const std::string& csv, const std::vector<std::string>& files,
                          const studies::FragilityStudyOptions& o, const std::vector<BlockFragility>& study) {
    harness::Table t({"alpha", "p", "block", "capacity", "records", "collapsed", "censored", "stripes", "median",
                      "beta", "log_likelihood", "median_lo", "median_hi", "beta_lo", "beta_hi", "resamples", "seed",
                      "level", "no_fit"});
    t.note("command", "rocking fragility --fits");
    t.note("model", o.ida.describe_model());
    std::string inputs;
    for (const std::string& f : files) inputs += (inputs.empty() ? "" : "; ") + f;
    t.note("inputs", inputs);
    t.note("grid", o.ida.describe_grid());
    t.note("columns",
           "P(overturn | q) = Phi(ln(q / median) / beta), q = PGA/(alpha g); capacity: first_collapse (the grid "
           "method's point), or with --method refine first_overturning (the fit the text heads), "
           "first_robust_collapse and stripes (the multiple-stripe fit, whose records and stripes are counted in "
           "records and stripes, collapsed and censored '-'); median_lo..hi, beta_lo..hi: the bootstrap's "
           "percentile interval at level over records ('-' without --bootstrap); log_likelihood: ln L at the fit "
           "(the stripes' without the binomial coefficients); no_fit: why ln L has no maximum ('-' when fitted); "
           "block: the block as built (BxH m), '-' where given by alpha and p");
    const bool three = o.ida.method == studies::IdaOptions::Method::refine;
    for (const BlockFragility& f : study) {
        add_point_fit(t, f, three ? "first_overturning" : "first_collapse", f.points, f.fitted, f.no_fit, f.fit,
                      f.bootstrapped, f.interval);
        if (!f.three_ways) continue;
        const studies::CapacityFit& r = f.robust;
        add_point_fit(t, f, "first_robust_collapse", r.points, r.fitted, r.no_fit, r.fit, r.bootstrapped, r.interval);
        const studies::StripeFit& s = f.stripes;
        t.row().add(f.block.alpha).add(f.block.p).add(f.block.built.empty() ? kNone : f.block.built).add("stripes")
            .add(static_cast<int>(s.shares.share.size())).add(kNone).add(kNone).add(static_cast<int>(s.stripes.size()));
        if (s.fitted) t.add(s.fit.median).add(s.fit.beta).add(s.fit.log_likelihood);
        else t.add(kNone).add(kNone).add(kNone);
        add_bootstrap(t, s.fitted && s.bootstrapped, s.interval);
        t.add(s.fitted ? kNone : s.no_fit);
    }
    try {
        t.write(csv);
    } catch (const std::runtime_error& e) {
        throw std::runtime_error(std::string("--fits: ") + e.what());
    }
}

}  // namespace rocking::cli
