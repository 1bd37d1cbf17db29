#include "jobs/job.hpp"

#include <cmath>
#include <cstdio>
#include <set>

#include "dynamics/stepper.hpp"
#include "numerics/number_text.hpp"
#include "studies/overturning_set.hpp"
#include "studies/search_alpha.hpp"

namespace rocking::jobs {

using dynamics::Block;
using dynamics::Equation;

std::string kind_name(Kind kind) {
    switch (kind) {
        case Kind::simulate: return "simulate";
        case Kind::collapse: return "collapse";
        case Kind::ida: return "ida";
        case Kind::spectrum: return "spectrum";
    }
    return "?";
}

const std::vector<std::string>& manifest_columns() {
    static const std::vector<std::string> names = {
        "id",   "kind",        "record",      "unit",   "record_dt", "alpha",     "p",      "height",
        "half_height", "scaling", "model", "solver", "rtol",      "atol",      "restitution", "criterion",
        "q_max", "points",     "p_min",       "p_max",  "method",    "width",     "robust_width", "friction",
        "lean", "out_of_plumb", "fc", "density"};
    return names;
}

Columns::Columns(const std::vector<std::string>& header) : names_(header) {
    std::string known;
    for (const std::string& n : manifest_columns()) known += (known.empty() ? "" : ", ") + n;
    for (const std::string& name : header) {
        bool ok = false;
        for (const std::string& n : manifest_columns()) ok = ok || n == name;
        if (!ok) throw std::invalid_argument("unknown column '" + name + "' (the columns: " + known + ")");
    }
    for (const char* needed : {"record", "alpha"}) {
        bool found = false;
        for (const std::string& name : header) found = found || name == needed;
        if (!found) throw std::invalid_argument(std::string("no '") + needed + "' column: every job needs one");
    }
}

const std::string& Columns::cell(const std::vector<std::string>& row, const std::string& name) const {
    static const std::string none;
    for (std::size_t c = 0; c < names_.size() && c < row.size(); ++c)
        if (names_[c] == name) return row[c];
    return none;
}

double Job::restitution_factor() const { return housner ? dynamics::housner_restitution(alpha) : restitution; }

std::string Job::solver_text() const {
    if (solver.kind == dynamics::SolverKind::exact) return "exact";
    char text[120];
    std::snprintf(text, sizeof text, "%s rtol %g atol %g alpha", dynamics::solver_name(solver.kind).c_str(), solver.rtol,
                  solver.atol_alpha);
    return text;
}

std::string record_path(const std::string& cell, const std::string& folder) {
    return cell.front() == '/' ? cell : folder + "/" + cell;
}

namespace {

[[noreturn]] void bad(const std::string& column, const std::string& problem) {
    throw std::invalid_argument(column + ": " + problem);
}

// The one number reader's rules and messages (numerics/number_text.hpp), under the column's name.
double number(const std::string& column, const std::string& text) {
    try {
        return numerics::parameter_number(text);
    } catch (const std::invalid_argument& e) {
        bad(column, e.what());
    }
}

int whole(const std::string& column, const std::string& text, int lo, int hi) {
    try {
        return static_cast<int>(numerics::whole_number(text, lo, hi));
    } catch (const std::invalid_argument& e) {
        bad(column, e.what());
    }
}

std::string g(double v) {
    char text[40];
    std::snprintf(text, sizeof text, "%.17g", v);
    return text;
}

// The columns each kind takes besides id, kind, record, unit, record_dt, alpha
// and the model's (model, solver, rtol, atol, restitution, criterion).
const std::set<std::string>& own_columns(Kind kind) {
    static const std::set<std::string> simulate = {"p", "height", "half_height", "scaling"};
    static const std::set<std::string> collapse = {"scaling"};
    static const std::set<std::string> ida = {"p", "height", "half_height", "q_max", "points", "method", "width",
                                              "robust_width"};
    static const std::set<std::string> spectrum = {"scaling", "points", "p_min", "p_max", "method", "width", "robust_width"};
    switch (kind) {
        case Kind::simulate: return simulate;
        case Kind::collapse: return collapse;
        case Kind::ida: return ida;
        case Kind::spectrum: return spectrum;
    }
    return simulate;
}

const char* why_not(Kind kind, const std::string& column) {
    if (column == "scaling" && kind == Kind::ida) return "the IDA scales the record itself, over q";
    if ((column == "p" || column == "height" || column == "half_height") &&
        (kind == Kind::collapse || kind == Kind::spectrum))
        return "it searches p";
    if ((column == "method" || column == "width" || column == "robust_width") &&
        (kind == Kind::simulate || kind == Kind::collapse))
        return "the method of an IDA or a spectrum";
    return "not one of its columns";
}

Kind kind_from(const std::string& text) {
    if (text.empty() || text == "simulate") return Kind::simulate;
    if (text == "collapse") return Kind::collapse;
    if (text == "ida") return Kind::ida;
    if (text == "spectrum") return Kind::spectrum;
    bad("kind", "'" + text + "' is not a kind (simulate, collapse, ida, spectrum)");
}

RecordSource record_from(const Columns& c, const std::vector<std::string>& row, const std::string& folder) {
    RecordSource r;
    r.cell = c.cell(row, "record");
    if (r.cell.empty()) bad("record", "empty: every job needs a record file");
    r.path = record_path(r.cell, folder);
    r.unit = c.cell(row, "unit");
    if (!r.unit.empty() && r.unit != "g" && r.unit != "m/s2" && r.unit != "cm/s2")
        bad("unit", "'" + r.unit + "' is not a unit it knows (g, m/s2, cm/s2)");
    const std::string& dt = c.cell(row, "record_dt");
    if (!dt.empty()) {
        if (r.unit.empty()) bad("record_dt", "goes with unit (a plain-text record in g, m/s2 or cm/s2)");
        r.dt = number("record_dt", dt);
        if (!(r.dt > 0)) bad("record_dt", "must be > 0 (got " + dt + ")");
    }
    return r;
}

Block block_from(const Columns& c, const std::vector<std::string>& row, Kind kind, double alpha) {
    const std::string &p = c.cell(row, "p"), &h = c.cell(row, "height"), &hh = c.cell(row, "half_height");
    if (!p.empty() + !h.empty() + !hh.empty() != 1)
        bad(p.empty() && h.empty() && hh.empty() ? "p" : "p, height, half_height",
            "give exactly one of p (rad/s), height and half_height (m) for " + std::string(kind == Kind::ida ? "an " : "a ") +
                kind_name(kind) + " job");
    Block b{};
    try {
        if (!p.empty()) b = Block::from_p(number("p", p), alpha);
        else if (!h.empty()) b = Block::from_full_height(number("height", h), alpha);
        else b = Block::from_half_height(number("half_height", hh), alpha);
    } catch (const std::invalid_argument& e) {
        const std::string what = e.what();
        if (what.rfind("p:", 0) == 0 || what.rfind("height:", 0) == 0 || what.rfind("half_height:", 0) == 0) throw;
        // Block's own message, "block: p must be > 0", under the column's name.
        bad(!p.empty() ? "p" : !h.empty() ? "height" : "half_height", what.rfind("block: ", 0) == 0 ? what.substr(7) : what);
    }
    // fragility's range: beyond it no block is physical and a run's free rocking grows without bound.
    if (kind == Kind::ida && !(b.p > 0.01 && b.p < 1000))
        bad(!p.empty() ? "p" : !h.empty() ? "height" : "half_height",
            "the block's p must be in (0.01, 1000) rad/s for an ida job (got " + g(b.p) + ")");
    return b;
}

Scaling scaling_from(const std::string& text) {
    Scaling s;
    if (text.empty()) return s;
    const auto eq = text.find('=');
    const std::string key = text.substr(0, eq);
    if (eq == std::string::npos || (key != "q" && key != "pga"))
        bad("scaling", "'" + text + "' is not q=Q (PGA = Q alpha g) or pga=G (in g), or empty (as recorded)");
    s.by = key == "q" ? Scaling::By::q : Scaling::By::pga;
    s.value = number("scaling", text.substr(eq + 1));
    if (!(s.value > 0)) bad("scaling", key + " must be > 0 (got " + text.substr(eq + 1) + ")");
    return s;
}

void model_from(const Columns& c, const std::vector<std::string>& row, Job& job) {
    const std::string& model = c.cell(row, "model");
    if (model == "full") job.equation = Equation::full;
    else if (!model.empty() && model != "linearised") bad("model", "linearised or full (got '" + model + "')");
    const std::string& solver = c.cell(row, "solver");
    job.solver.kind = job.equation == Equation::full ? dynamics::SolverKind::dopri5 : dynamics::SolverKind::exact;
    if (!solver.empty()) {
        try {
            job.solver.kind = dynamics::parse_solver(solver);
        } catch (const std::invalid_argument& e) {
            bad("solver", e.what());
        }
    }
    if (job.equation == Equation::full && job.solver.kind == dynamics::SolverKind::exact)
        bad("solver", "the exact solver handles the linearised equation only (model full)");
    // Formatted once: it is said only when a tolerance is refused, and every job passes here.
    static const std::string range = "[" + g(dynamics::kSmallestTolerance) + ", 1)";
    const std::string& rtol = c.cell(row, "rtol");
    if (!rtol.empty()) {
        const double r = number("rtol", rtol);
        if (!(r >= dynamics::kSmallestTolerance && r < 1)) bad("rtol", "must be in " + std::string(range) + " (got " + rtol + ")");
        job.solver.rtol = job.solver.atol_alpha = r;
    }
    const std::string& atol = c.cell(row, "atol");
    if (!atol.empty()) {
        const double in_alpha = number("atol", atol) / job.alpha;
        if (!(in_alpha >= dynamics::kSmallestTolerance && in_alpha < 1))
            bad("atol", "in rad, must be in " + std::string(range) + " times alpha (got " + atol + ")");
        job.solver.atol_alpha = in_alpha;
    }
    const std::string& e = c.cell(row, "restitution");
    // The commands' one default model (issue 40): Housner's restitution and overturning, every kind.
    job.housner = e.empty() || e == "housner";
    if (!e.empty() && !job.housner) {
        job.restitution = number("restitution", e);
        if (!(job.restitution >= 0 && job.restitution <= 1))
            bad("restitution", "must be in [0, 1] or housner (got " + e + ")");
    }
    // As --friction (issue 41): the sliding-rocking model, which keeps its own
    // equations, impact law and solver.
    const std::string& mu = c.cell(row, "friction");
    if (!mu.empty()) {
        job.friction = number("friction", mu);
        if (!(job.friction > 0 && job.friction <= 1e6))
            bad("friction", "the friction coefficient must be in (0, 1e6] (got " + mu + ")");
        for (const char* other : {"model", "solver", "restitution"})
            if (!c.cell(row, other).empty())
                bad(other, "does not apply with friction (the sliding-rocking model has its full equations, impact law "
                           "and event-driven solver)");
    }
    // As --lean, --out-of-plumb, --fc, --density (issue 41): an imperfect block.
    auto given = [&](const char* column) -> std::optional<double> {
        const std::string& v = c.cell(row, column);
        if (v.empty()) return std::nullopt;
        return number(column, v);
    };
    job.imperfection = dynamics::imperfection_of({given("lean"), given("out_of_plumb"), given("fc"), given("density")},
                                                 [](const std::string& n) { return n; });
    if (job.imperfection.any() && job.friction > 0)
        bad("friction", "does not apply to an imperfect block (lean, out_of_plumb, fc): the sliding-rocking model's block "
                        "is a perfect rectangle");
    const std::string& criterion = c.cell(row, "criterion");
    job.criterion = dynamics::Criterion::overturning;
    if (!criterion.empty()) {
        try {
            job.criterion = dynamics::parse_criterion(criterion);
        } catch (const std::invalid_argument& e) {
            bad("criterion", e.what());
        }
    }
}

// method, width and robust_width: rocking fragility's --method, --width and
// --robust-width, the same ranges, in ln q for an IDA and ln p for a spectrum.
void method_from(const Columns& c, const std::vector<std::string>& row, Job& job) {
    const std::string& method = c.cell(row, "method");
    if (!method.empty() && method != "grid" && method != "refine") bad("method", "grid or refine (got '" + method + "')");
    job.refine = method == "refine";
    for (const char* column : {"width", "robust_width"})
        if (!c.cell(row, column).empty() && !job.refine)
            bad(column, "goes with method refine (the grid method has no " + std::string(column) + ")");
    const std::string in = job.kind == Kind::ida ? " in ln q" : " in ln p";
    const std::string &w = c.cell(row, "width"), &r = c.cell(row, "robust_width");
    if (!w.empty()) {
        job.width = number("width", w);
        if (!studies::in_width_range(job.width))
            bad("width", std::string("must be in ") + studies::kWidthRange + in + " (got " + w + ")");
    }
    if (!r.empty()) {
        job.robust_width = number("robust_width", r);
        if (!studies::in_robust_width_range(job.robust_width))
            bad("robust_width", std::string("must be in ") + studies::kRobustWidthRange + in + " (got " + r + ")");
    }
}

}  // namespace

Job parse_job(const Columns& c, const std::vector<std::string>& row, const std::string& folder) {
    if (row.size() != c.size())
        throw std::invalid_argument(std::to_string(row.size()) + " cells, the header has " + std::to_string(c.size()));
    Job job;
    job.kind = kind_from(c.cell(row, "kind"));
    for (const std::string& name : c.names()) {
        static const std::set<std::string> common = {"id",  "kind", "record", "unit", "record_dt", "alpha", "model",
                                                     "solver", "rtol", "atol", "restitution", "criterion", "friction",
                                                     "lean", "out_of_plumb", "fc", "density"};
        if (!c.cell(row, name).empty() && !common.count(name) && !own_columns(job.kind).count(name))
            bad(name, "does not apply to " + std::string(job.kind == Kind::ida ? "an " : "a ") + kind_name(job.kind) + " job (" + why_not(job.kind, name) + ")");
    }
    job.record = record_from(c, row, folder);
    const std::string& alpha = c.cell(row, "alpha");
    if (alpha.empty()) bad("alpha", "empty: every job needs the block's slenderness");
    job.alpha = number("alpha", alpha);
    // simulate: the dynamics' own range; the searches: the commands' own.
    const bool simulate = job.kind == Kind::simulate;
    if (!(simulate ? job.alpha > 0 && job.alpha < M_PI / 4 : studies::in_search_alpha_range(job.alpha)))
        bad("alpha", "must be in " + std::string(simulate ? "(0, pi/4)" : studies::kSearchAlphaRange) + " (got " + alpha + ")");
    if (job.kind == Kind::simulate || job.kind == Kind::ida) {
        job.block = block_from(c, row, job.kind, job.alpha);
        for (const char* column : {"p", "height", "half_height"})
            if (!c.cell(row, column).empty()) job.p_column = column;
    }
    job.scaling = scaling_from(c.cell(row, "scaling"));
    model_from(c, row, job);
    if (job.kind == Kind::ida) {
        const std::string& q_max = c.cell(row, "q_max");
        if (!q_max.empty()) job.q_max = number("q_max", q_max);
        if (!(job.q_max > 1 && job.q_max <= 1e4)) bad("q_max", "must be in (1, 10000] (got " + q_max + ")");
    }
    if (job.kind == Kind::ida || job.kind == Kind::spectrum) {
        const std::string& points = c.cell(row, "points");
        const int most = job.kind == Kind::ida ? 10000 : 100000;
        job.points = points.empty() ? (job.kind == Kind::ida ? 100 : 200) : whole("points", points, 2, most);
    }
    if (job.kind == Kind::spectrum) {
        const std::string &lo = c.cell(row, "p_min"), &hi = c.cell(row, "p_max");
        if (!lo.empty()) job.p_min = number("p_min", lo);
        if (!hi.empty()) job.p_max = number("p_max", hi);
        if (!(job.p_min >= 0.01 && job.p_min <= 1000)) bad("p_min", "must be in [0.01, 1000] rad/s (got " + lo + ")");
        if (!(job.p_max >= 0.01 && job.p_max <= 1000)) bad("p_max", "must be in [0.01, 1000] rad/s (got " + hi + ")");
        if (!(job.p_max > job.p_min)) bad("p_max", "must be above p_min (" + g(job.p_min) + " rad/s)");
        if (!hi.empty()) job.p_column = "p_max";
    }
    if (job.kind == Kind::ida || job.kind == Kind::spectrum) method_from(c, row, job);
    return job;
}

}  // namespace rocking::jobs
