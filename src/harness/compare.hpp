// Comparing a scene's CSV with its expected file under stated tolerances
// (in the manner of numdiff, with LAMMPS's one-file-per-reference epsilons).
//
// expected/<scene>/TOLERANCES lists, one per line,
//     <file> <column> <abs> <rel> <reason...>
//     <file> <column> exact <reason...>
//     <file> <column> reference <reason...>
// Column '*' is the default for the file's other columns.  A number passes
// when |actual - expected| <= abs + rel |expected|; an 'exact' cell must be
// the same text.  A 'reference' cell is a second method's verdict: the same
// text in a --reference run, and "not checked" in any other (a "yes" there
// would claim a check that did not run).  Every file named there is compared; a file the scene does
// not write is a failure.
#pragma once

#include <map>
#include <string>
#include <vector>

#include "harness/table.hpp"

namespace rocking::harness {

struct Tolerance {
    bool exact = false;
    bool reference = false;  // exact in a --reference run, "not checked" otherwise
    double abs = 0.0;
    double rel = 0.0;
    std::string reason;
};

class ToleranceSpec {
public:
    // Throws std::runtime_error naming path:line on a malformed line.
    static ToleranceSpec read(const std::string& path);

    std::vector<std::string> files() const;
    // Whether any column is of the 'reference' kind (its values come from a --reference run).
    bool has_reference_columns() const;
    // Throws std::runtime_error when the file has no rule for the column and no '*'.
    const Tolerance& of(const std::string& file, const std::string& column) const;

private:
    std::string path_;
    std::vector<std::string> order_;
    std::map<std::string, std::map<std::string, Tolerance>> rules_;
};

struct Deviation {
    std::string column;
    int line = 0;           // line in the expected file
    std::string expected;
    std::string actual;
    double deviation = 0.0; // |actual - expected| (numbers), 1 for differing text
    double allowed = 0.0;   // abs + rel |expected|
    double ratio = 0.0;     // deviation / allowed (0 when both are 0; inf when allowed is 0)
};

struct Comparison {
    std::string file;
    std::string problem;              // structural mismatch (columns, row count); empty if none
    long cells = 0;
    long failed = 0;
    Deviation worst;                  // largest ratio seen, passing or not
    std::vector<Deviation> failures;  // the first few failing cells
    bool match() const { return problem.empty() && failed == 0; }
};

// reference_run: the scene ran with its reference method (reproduce --reference).
Comparison compare(const CsvFile& expected, const CsvFile& actual, const ToleranceSpec& spec,
                   const std::string& file, bool reference_run = false);

// What a 'reference' cell reads in a run without the reference method.
inline constexpr const char* kNotChecked = "not checked";

}  // namespace rocking::harness
