#include "cli/nrml_output.hpp"

#include <cstdio>
#include <stdexcept>

#include "harness/atomic_file.hpp"
#include "studies/nrml.hpp"

namespace rocking::cli {

void write_nrml(const std::string& path, const std::vector<std::string>& files,
                const studies::FragilityStudyOptions& options, const std::vector<studies::BlockFragility>& study) {
    const studies::NrmlModel model = studies::fragility_nrml(study, options, files);
    try {
        harness::AtomicFile file(path);
        file.write(model.xml);
        file.commit();
    } catch (const std::runtime_error& e) {
        throw std::runtime_error(std::string("--nrml: ") + e.what());
    }
    for (const std::string& why : model.unfitted)
        std::fprintf(stderr, "rocking fragility: --nrml %s: %s; the file has no function for it, only a comment\n",
                     path.c_str(), why.c_str());
    if (model.unfitted.size() == study.size())
        std::fprintf(stderr, "rocking fragility: --nrml %s: no block has a fit: the model holds no fragility function\n",
                     path.c_str());
}

}  // namespace rocking::cli
