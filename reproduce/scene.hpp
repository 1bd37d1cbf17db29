// A scene reproduces one figure or table of the paper: it composes a model,
// an input and a solver, and writes its data as CSV tables under out/<scene>/.
#pragma once

#include <functional>
#include <utility>
#include <string>
#include <vector>

#include "harness/table.hpp"

namespace rocking::scenes {

class SceneContext {
public:
    explicit SceneContext(std::string dir, bool reference = false) : dir_(std::move(dir)), reference_(reference) {}
    // true: the scene computes with its reference solver (a second method at a
    // much tighter tolerance), to check the expected files independently.
    bool reference() const { return reference_; }
    // Writes the table as <dir>/<file>; throws std::runtime_error on failure.
    void write(const harness::Table& table, const std::string& file);
    const std::string& dir() const { return dir_; }
    const std::vector<std::string>& written() const { return written_; }
    // A file the scene cannot write here (its input is absent), with the reason:
    // the diff reports it as skipped instead of failing.
    void skip(const std::string& file, const std::string& reason) { skipped_.emplace_back(file, reason); }
    const std::vector<std::pair<std::string, std::string>>& skipped() const { return skipped_; }

private:
    std::string dir_;
    bool reference_;
    std::vector<std::string> written_;
    std::vector<std::pair<std::string, std::string>> skipped_;
};

struct Scene {
    std::string name;    // fig04, fig07, errata, ...
    std::string title;   // what it reproduces
    std::string model;   // equation of motion and assumptions
    std::string solver;  // how the numbers are computed, with its tolerance
    std::string reference;  // the second method used by --reference ("" when the scene has none)
    std::function<void(SceneContext&)> run;
};

const std::vector<Scene>& all_scenes();

// The x = p*to grid shared by the q-factor figures: 0.05 to 2.00, step 0.01.
std::vector<double> x_grid();

void run_fig04(SceneContext& ctx);
void run_fig07(SceneContext& ctx);
void run_errata(SceneContext& ctx);
void run_fig05(SceneContext& ctx);
void run_fig06(SceneContext& ctx);
void run_table1(SceneContext& ctx);
void run_table2(SceneContext& ctx);
void run_fig11(SceneContext& ctx);
void run_fig12(SceneContext& ctx);
void run_fig08(SceneContext& ctx);
void run_spectrum(SceneContext& ctx);
void run_fragility(SceneContext& ctx);
void run_imperfection(SceneContext& ctx);
void run_sliding(SceneContext& ctx);

}  // namespace rocking::scenes
