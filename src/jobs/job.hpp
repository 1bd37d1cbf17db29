// A job of a batch manifest, typed: which study (simulate, collapse, ida,
// spectrum), on which record, block, scaling, model, solver, restitution,
// criterion and method (grid or refine).  parse_job() reads one manifest row into a job, filling what the
// row leaves empty with the defaults of the command that runs the same study
// alone (rocking simulate, collapse, fragility, spectrum); the columns, their
// defaults and which kinds take them: docs/batch.md.
#pragma once

#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "dynamics/imperfect_block.hpp"
#include "dynamics/model.hpp"
#include "dynamics/simulate.hpp"

namespace rocking::jobs {

enum class Kind { simulate, collapse, ida, spectrum };
std::string kind_name(Kind kind);

// Every column a manifest may name, in the order docs/batch.md lists them.
const std::vector<std::string>& manifest_columns();

// The manifest's header, checked: every column known, `record` and `alpha`
// present.  Throws std::invalid_argument naming the column.
class Columns {
public:
    explicit Columns(const std::vector<std::string>& header);
    std::size_t size() const { return names_.size(); }
    const std::vector<std::string>& names() const { return names_; }
    // The row's cell under `name`, or "" when the manifest has no such column.
    const std::string& cell(const std::vector<std::string>& row, const std::string& name) const;

private:
    std::vector<std::string> names_;
};

struct RecordSource {
    std::string cell;  // as the manifest names it
    std::string path;  // resolved against the manifest's folder
    std::string unit;  // "" for ESM or PEER by content; g, m/s2 or cm/s2 for plain text
    double dt = 0;     // a one-column plain-text record's step, s
};

// A record cell (not empty) as a path: an absolute one as it is, a relative
// one from `folder` (the manifest's; batch::Manifest::folder()).
std::string record_path(const std::string& cell, const std::string& folder);

struct Scaling {
    enum class By { as_recorded, q, pga } by = By::as_recorded;
    double value = 0;  // q = PGA/(alpha g), or the PGA in g
};

struct Job {
    Kind kind = Kind::simulate;
    RecordSource record;
    double alpha = 0;
    std::optional<dynamics::Block> block;  // simulate and ida: from p, height or half_height
    // The column that set the highest p the job's runs reach (p, height,
    // half_height, p_max), "" for a default: what a refused run names.
    std::string p_column;
    Scaling scaling;                       // simulate, collapse and spectrum
    dynamics::Equation equation = dynamics::Equation::linearised;
    dynamics::SolverOptions solver;
    bool housner = false;                  // restitution 1 - 1.5 sin^2 alpha
    double restitution = 1;                // otherwise
    dynamics::Criterion criterion = dynamics::Criterion::final_rotation;
    double friction = 0;                   // > 0: the sliding-rocking model (issue 41), rtol from the rtol column
    dynamics::Imperfection imperfection{}; // lean, out_of_plumb, fc, density columns (issue 41)
    double q_max = 20;                     // ida
    int points = 0;                        // ida (q) and spectrum (p): the grid's points
    double p_min = 0.3, p_max = 30;        // spectrum, rad/s
    // ida and spectrum (issue 39): the grid method, or the refine method down
    // to `width` in ln q (ln p); an interval wider than robust_width there is
    // a robust collapse (both methods).  The defaults are IdaOptions' and
    // SpectrumOptions'.
    bool refine = false;
    double width = 1e-5, robust_width = 5e-3;

    double restitution_factor() const;     // the one applied
    std::string solver_text() const;       // "exact", or "dopri5 rtol 1e-06 atol 1e-06 alpha"
};

// One row's cells (as many as the header's) into a job.  Throws
// std::invalid_argument naming the column and the problem.
Job parse_job(const Columns& columns, const std::vector<std::string>& row, const std::string& folder);

}  // namespace rocking::jobs
