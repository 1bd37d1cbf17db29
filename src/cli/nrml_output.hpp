// rocking fragility --nrml XML: the study's fits as an OpenQuake NRML 0.5
// fragility model (studies/nrml.hpp, docs/fragility.md "The NRML export").
#pragma once

#include <string>
#include <vector>

#include "studies/ida.hpp"

namespace rocking::cli {

// Writes the model to `path` whole or not at all (harness/atomic_file.hpp),
// and says on standard error which blocks it holds no function for and why
// (each is a comment in the file too).  A failed write is a runtime_error
// naming --nrml.
void write_nrml(const std::string& path, const std::vector<std::string>& files,
                const studies::FragilityStudyOptions& options, const std::vector<studies::BlockFragility>& study);

}  // namespace rocking::cli
