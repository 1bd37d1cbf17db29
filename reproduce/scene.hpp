// A scene reproduces one figure or table of the paper: it composes a model,
// an input and a solver, and writes its data as CSV tables under out/<scene>/.
#pragma once

#include <functional>
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

private:
    std::string dir_;
    bool reference_;
    std::vector<std::string> written_;
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

}  // namespace rocking::scenes
