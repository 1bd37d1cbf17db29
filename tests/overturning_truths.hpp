// What the tests of issue 39's searches share about their truths: the model
// the closed-form islands of narrow_islands_truth.hpp hold for (restitution 0),
// and the islands of the dense scans in expected/overturning_set/ (made by an
// independent model; PROVENANCE.md there).
#pragma once

#include <gtest/gtest.h>

#include <stdexcept>
#include <string>
#include <vector>

#include "harness/table.hpp"
#include "records/collapse.hpp"

#ifndef ROCKING_SOURCE_DIR
#define ROCKING_SOURCE_DIR "."
#endif

namespace rocking::testing {

// Table 1's model with restitution 0, the narrowed islands' model.
inline records::CollapseOptions restitution_zero() {
    records::CollapseOptions o;
    o.housner_restitution = false;
    o.restitution = 0.0;
    return o;
}

// An island of a dense scan: its ends (the brackets' overturning ends) and
// the brackets' safe ends, each 1e-10 away.
struct ScanIsland {
    double from, to, from_safe, to_safe;
};

// expected/overturning_set/<name> (ida_islands.csv, spectrum_islands.csv),
// each end checked as "agreed" by the kernel's rerun.
inline std::vector<ScanIsland> scan_islands(const std::string& name) {
    const std::string path = std::string(ROCKING_SOURCE_DIR) + "/expected/overturning_set/" + name;
    const harness::CsvFile f = harness::read_csv(path);
    auto column = [&](const std::string& wanted) {
        for (std::size_t k = 0; k < f.columns.size(); ++k)
            if (f.columns[k] == wanted) return k;
        throw std::runtime_error(path + ": no column " + wanted);
    };
    const std::size_t from = column("from"), to = column("to"), from_safe = column("from_safe"),
                      from_collapse = column("from_collapse"), to_collapse = column("to_collapse"),
                      to_safe = column("to_safe"), from_check = column("from_check"), to_check = column("to_check");
    std::vector<ScanIsland> out;
    for (const auto& row : f.rows) {
        EXPECT_EQ(row[from], row[from_collapse]) << name;
        EXPECT_EQ(row[to], row[to_collapse]) << name;
        EXPECT_EQ(row[from_check], "agreed") << name;
        EXPECT_EQ(row[to_check], "agreed") << name;
        out.push_back({std::stod(row[from]), std::stod(row[to]), std::stod(row[from_safe]), std::stod(row[to_safe])});
    }
    return out;
}

}  // namespace rocking::testing
