#include "studies/eq27_at_scale.hpp"

#include <gsl/gsl_cdf.h>

#include <cmath>
#include <cstdio>
#include <stdexcept>

#include "batch/pool.hpp"
#include "qfactor/closed_forms.hpp"
#include "studies/distinct_inputs.hpp"
#include "studies/record_order.hpp"
#include "studies/resampling.hpp"

namespace rocking::studies {

const char* const kEq27Verdict =
    "non-conservative: the record overturns the block at a q below eq. 27's at x = p to_k "
    "(collapse q < q2_n6(p to_k)); a record that never overturns the block up to q_max is censored "
    "and counted as conservative";
const char* const kEq27WilsonNote =
    "the Wilson interval takes every (record, block) case as independent; the cases of one record are "
    "correlated, so it misstates the uncertainty (as a rule too narrow): quote the bootstrap over records";
const char* const kEq27NoBootstrap = "bootstrap over records not run (--bootstrap K --seed S)";

WilsonInterval wilson_interval(int successes, int trials, double level) {
    if (trials < 1) throw std::invalid_argument("wilson_interval: trials must be at least 1");
    if (successes < 0 || successes > trials) throw std::invalid_argument("wilson_interval: successes must be in [0, trials]");
    if (!(level > 0 && level < 1)) throw std::invalid_argument("wilson_interval: level must be in (0, 1)");
    const double z = gsl_cdf_ugaussian_Pinv(0.5 + level / 2);
    const double n = trials, phat = successes / n, z2n = z * z / n;
    const double centre = (phat + z2n / 2) / (1 + z2n);
    const double half = z * std::sqrt(phat * (1 - phat) / n + z2n / (4 * n)) / (1 + z2n);
    // At 0 and n successes the bound is exactly 0 or 1; rounding must not move it.
    return {successes == 0 ? 0.0 : centre - half, successes == trials ? 1.0 : centre + half};
}

std::vector<double> Eq27Grid::ps() const {
    if (!(p_min > 0 && std::isfinite(p_max) && p_max >= p_min)) throw std::invalid_argument("eq27: the grid needs 0 < p_min <= p_max");
    if (p_points < 1) throw std::invalid_argument("eq27: the grid needs at least 1 p");
    if (p_points == 1 && p_max != p_min) throw std::invalid_argument("eq27: one p needs p_max equal to p_min");
    if (p_points == 1) return {p_min};
    std::vector<double> out;
    for (int i = 0; i < p_points; ++i) out.push_back(p_min * std::pow(p_max / p_min, double(i) / (p_points - 1)));
    // The last point is p_max itself, not its rounded power.
    out.back() = p_max;
    return out;
}

std::vector<BlockShape> Eq27Grid::blocks() const {
    if (alphas.empty()) throw std::invalid_argument("eq27: the grid needs at least 1 alpha");
    check();
    std::vector<BlockShape> out;
    const std::vector<double> p = ps();
    for (double a : alphas)
        for (double pi : p) out.push_back({a, pi, ""});
    return out;
}

void Eq27Grid::check(const Eq27GridNames& names) const {
    auto g7 = [](double v) {
        char t[40];
        std::snprintf(t, sizeof t, "%.7g", v);
        return std::string(t);
    };
    refuse_repeated_values(names.alpha, alphas);
    if (p_max < p_min)
        throw std::invalid_argument(names.p_max + ": must not be below " + names.p_min + " (" + g7(p_min) + ")");
    if (p_points == 1 && p_max != p_min)
        throw std::invalid_argument(names.p_points + names.equals + "1: one p, but the range runs from " + g7(p_min) +
                                    " to " + g7(p_max) + " rad/s: give the p as " + names.p_min + names.equals +
                                    "P alone, or more points");
    if (p_points > 1 && p_max == p_min)
        throw std::invalid_argument(names.p_points + ": more than 1 needs " + names.p_max + " above " + names.p_min);
    // A range too narrow for its points would repeat a p, and count its cases twice.
    const std::vector<double> p = ps();
    for (std::size_t i = 1; i < p.size(); ++i)
        if (!(p[i] > p[i - 1]))
            throw std::invalid_argument(names.p_points + ": " + std::to_string(p_points) + " points from " + g7(p_min) +
                                        " to " + g7(p_max) + " rad/s repeat p = " + g7(p[i]) +
                                        ": widen the range or take fewer points");
}

std::string Eq27Grid::describe() const {
    std::string a;
    for (double v : alphas) {
        char t[32];
        std::snprintf(t, sizeof t, "%g", v);
        a += (a.empty() ? "" : ", ") + std::string(t);
    }
    char text[200];
    std::snprintf(text, sizeof text, "; p: %d log-spaced from %g to %g rad/s", p_points, p_min, p_max);
    return "alpha " + a + text;
}

bool non_conservative(const IdaPoint& point, double q_eq27) { return point.collapsed && point.q < q_eq27; }

namespace {

Eq27Case case_of(int r, int b, const IdaPoint& point, const std::array<double, kHalfPeriods>& to, const BlockShape& block) {
    Eq27Case c;
    c.record = r;
    c.block = b;
    c.point = point;
    for (int k = 0; k < kHalfPeriods; ++k) {
        const double x = block.p * to[k];
        if (!(std::isfinite(x) && x > 0)) throw std::invalid_argument("eq27: p to_k must be finite and > 0 (record " +
                                                                      std::to_string(r) + ", to_" + std::to_string(k + 1) + ")");
        c.q_eq27[k] = q2_n6(x);
        c.non_conservative[k] = non_conservative(point, c.q_eq27[k]);
    }
    return c;
}

void check_bootstrap(const Eq27Bootstrap& b) {
    if (b.resamples < 2) throw std::invalid_argument("eq27 bootstrap: at least 2 resamples");
    if (!(b.level > 0 && b.level < 1)) throw std::invalid_argument("eq27 bootstrap: the level must be in (0, 1)");
}

void tally(Eq27Study& s, const Eq27Bootstrap& bootstrap) {
    s.map.assign(s.blocks.size(), Eq27Cell{});
    for (std::size_t b = 0; b < s.blocks.size(); ++b) s.map[b].block = s.blocks[b];
    // per_record[r][k]: record r's non-conservative cases for k.
    std::vector<std::array<int, kHalfPeriods>> per_record(s.records, std::array<int, kHalfPeriods>{});
    for (const Eq27Case& c : s.cases) {
        Eq27Cell& cell = s.map[c.block];
        ++cell.records;
        if (!c.point.collapsed) ++cell.censored, ++s.censored;
        for (int k = 0; k < kHalfPeriods; ++k) {
            ++s.shares[k].cases;
            if (c.non_conservative[k])
                ++cell.non_conservative[k], ++s.shares[k].non_conservative, ++per_record[c.record][k];
        }
    }
    for (int k = 0; k < kHalfPeriods; ++k) {
        Eq27Share& share = s.shares[k];
        share.share = double(share.non_conservative) / share.cases;
        share.wilson = wilson_interval(share.non_conservative, share.cases, s.level);
        share.records = s.records;
        for (const auto& r : per_record) share.records_with_any += r[k] > 0;
    }
    if (bootstrap.resamples == 0) return;
    const std::array<Range, kHalfPeriods> boot =
        record_bootstrap(in_draw_order(per_record, draw_order(s.identities)), int(s.blocks.size()), bootstrap);
    for (int k = 0; k < kHalfPeriods; ++k) s.shares[k].bootstrap = boot[k];
    s.bootstrap = bootstrap;
}

}  // namespace

std::array<Range, kHalfPeriods> record_bootstrap(const std::vector<std::array<int, kHalfPeriods>>& counts, int blocks,
                                                 const Eq27Bootstrap& b) {
    if (counts.empty()) throw std::invalid_argument("eq27 bootstrap: at least 1 record");
    if (blocks < 1) throw std::invalid_argument("eq27 bootstrap: at least 1 block per record");
    for (const auto& r : counts)
        for (int c : r)
            if (c < 0 || c > blocks) throw std::invalid_argument("eq27 bootstrap: a record's count must be in [0, blocks]");
    check_bootstrap(b);
    const std::size_t n = counts.size();
    // Every resample holds n records of `blocks` cases: the share is an
    // integer count over this one denominator, a single rounding.
    const double cases = double(n) * blocks;
    SeededRng rng(b.seed);
    std::array<std::vector<double>, kHalfPeriods> shares;
    for (auto& v : shares) v.reserve(b.resamples);
    for (int i = 0; i < b.resamples; ++i) {
        std::array<long, kHalfPeriods> sum{};
        for (std::size_t r = 0; r < n; ++r) {
            const auto& drawn = counts[rng.index(n)];
            for (int k = 0; k < kHalfPeriods; ++k) sum[k] += drawn[k];
        }
        for (int k = 0; k < kHalfPeriods; ++k) shares[k].push_back(double(sum[k]) / cases);
    }
    std::array<Range, kHalfPeriods> out;
    for (int k = 0; k < kHalfPeriods; ++k) out[k] = percentile_interval(shares[k], b.level);
    return out;
}

Eq27Study eq27_from_points(const std::vector<std::vector<IdaPoint>>& points,
                           const std::vector<std::array<double, kHalfPeriods>>& to,
                           const std::vector<std::string>& identities, const std::vector<BlockShape>& blocks,
                           double level, const Eq27Bootstrap& bootstrap) {
    if (points.empty() || blocks.empty()) throw std::invalid_argument("eq27: at least 1 record and 1 block");
    if (to.size() != points.size()) throw std::invalid_argument("eq27: one set of half-periods per record");
    if (identities.size() != points.size()) throw std::invalid_argument("eq27: one identity per record");
    Eq27Study s;
    s.blocks = blocks;
    s.records = int(points.size());
    s.identities = identities;
    s.level = level;
    for (std::size_t r = 0; r < points.size(); ++r) {
        if (points[r].size() != blocks.size()) throw std::invalid_argument("eq27: one point per record and block");
        for (std::size_t b = 0; b < blocks.size(); ++b)
            s.cases.push_back(case_of(int(r), int(b), points[r][b], to[r], blocks[b]));
    }
    tally(s, bootstrap);
    return s;
}

Eq27Capacities capacities_of(const Ida& ida) { return {ida.first_overturning, ida.first_robust_collapse}; }

const char* const kEq27FirstOverturningNote =
    "first overturning: the lowest q at which the record overturns the block (with the refine method every island "
    "wider than w in ln q found); a case is non-conservative when the record at some q below eq. 27's overturns the "
    "block: the share to design with";
const char* const kEq27RobustCollapseNote =
    "first robust collapse: the start of the first interval of overturning wider than the robust width in ln q "
    "(about what the grid method reports); the islands of overturning below it are left out, so its share can "
    "understate how often eq. 27 calls a block safe at a q that overturns it";

std::string eq27_refine_note(const IdaOptions& ida) {
    return ida.describe_guarantee() + "; the shares under each capacity, their bootstraps drawing the same records";
}

Eq27ByCapacity eq27_by_capacity(const std::vector<std::vector<Eq27Capacities>>& capacities,
                                const std::vector<std::array<double, kHalfPeriods>>& to,
                                const std::vector<std::string>& identities, const std::vector<BlockShape>& blocks,
                                double level, const Eq27Bootstrap& bootstrap) {
    std::vector<std::vector<IdaPoint>> first(capacities.size()), robust(capacities.size());
    for (std::size_t r = 0; r < capacities.size(); ++r)
        for (std::size_t b = 0; b < capacities[r].size(); ++b) {
            const Eq27Capacities& c = capacities[r][b];
            // An IDA's robust collapse is the start of one of its intervals, the first overturning the lowest's.
            if (c.first_robust_collapse.collapsed &&
                !(c.first_overturning.collapsed && c.first_overturning.q <= c.first_robust_collapse.q))
                throw std::invalid_argument("eq27: record " + std::to_string(r) + ", block " + std::to_string(b) +
                                            ": a first robust collapse below the first overturning");
            first[r].push_back(c.first_overturning);
            robust[r].push_back(c.first_robust_collapse);
        }
    return {eq27_from_points(first, to, identities, blocks, level, bootstrap),
            eq27_from_points(robust, to, identities, blocks, level, bootstrap)};
}

Eq27ByCapacity eq27_at_scale_by_capacity(const std::vector<Eq27Record>& records, const Eq27Options& o) {
    const std::vector<BlockShape> blocks = o.grid.blocks();
    if (o.bootstrap.resamples != 0) check_bootstrap(o.bootstrap);  // before the IDAs, not after
    std::vector<std::array<double, kHalfPeriods>> to;
    std::vector<std::string> identities;
    for (const Eq27Record& r : records) {
        if (!r.input) throw std::invalid_argument("eq27: a record without an input");
        to.push_back(r.to);
        identities.push_back(input_digest(*r.input));
    }
    // Every (record, block) IDA a job of the batch engine, in this order.
    std::vector<std::vector<Eq27Capacities>> capacities(records.size());
    const std::size_t n = blocks.size();
    batch::run_ordered<Eq27Capacities>(
        records.size() * n, batch::PoolOptions{o.threads},
        [&](std::size_t job) {
            const BlockShape& b = blocks[job % n];
            return capacities_of(incremental_dynamic_analysis(*records[job / n].input, b.alpha, b.p, o.ida));
        },
        [&](std::size_t job, Eq27Capacities& c) { capacities[job / n].push_back(c); });
    return eq27_by_capacity(capacities, to, identities, blocks, o.level, o.bootstrap);
}

// The IDA's point is its first overturning (studies/ida.cpp, summarise).
Eq27Study eq27_at_scale(const std::vector<Eq27Record>& records, const Eq27Options& o) {
    return eq27_at_scale_by_capacity(records, o).first_overturning;
}

}  // namespace rocking::studies
