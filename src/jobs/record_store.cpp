#include "jobs/record_store.hpp"

#include <sys/stat.h>

#include <cstdio>
#include <filesystem>
#include <stdexcept>

#include "batch/ranks.hpp"
#include "batch/sha256.hpp"
#include "dynamics/model.hpp"
#include "harness/table.hpp"
#include "records/record.hpp"

namespace rocking::jobs {

RecordStore::RecordStore(std::size_t budget_bytes)
    : cache_(budget_bytes, [](const dynamics::SampledInput& r) { return r.size() * 8 + r.size() / 4 + r.describe().size(); }) {}

namespace {

void replace_all(std::string& text, const std::string& from, const std::string& to) {
    if (from.empty()) return;
    for (std::size_t at = 0; (at = text.find(from, at)) != std::string::npos; at += to.size()) text.replace(at, from.size(), to);
}

}  // namespace

std::string RecordStore::canonical(const std::string& path) {
    {
        std::lock_guard<std::mutex> lock(canonical_mutex_);
        const auto it = canonical_.find(path);
        if (it != canonical_.end()) return it->second;
    }
    std::error_code error;
    const std::filesystem::path p = std::filesystem::weakly_canonical(path, error);
    const std::string found = error ? std::filesystem::absolute(path, error).lexically_normal().string() : p.string();
    std::lock_guard<std::mutex> lock(canonical_mutex_);
    if (canonical_.size() >= 100000) canonical_.clear();  // bounded: a batch over as many files reads each rarely
    canonical_.emplace(path, found);
    return found;
}

std::string RecordStore::pin(const std::string& path) {
    const std::string file = canonical(path);
    {
        std::lock_guard<std::mutex> lock(pinned_mutex_);
        const auto it = pinned_.find(file);
        if (it != pinned_.end()) return it->second;
    }
    struct stat s {};
    if (::stat(file.c_str(), &s) == 0 && !S_ISREG(s.st_mode) && !S_ISDIR(s.st_mode)) return "";
    std::string digest;
    try {
        digest = batch::sha256_hex(records::read_text(file));
    } catch (const std::exception&) {
        digest = "unreadable";  // its jobs say why
    }
    std::lock_guard<std::mutex> lock(pinned_mutex_);
    pinned_.emplace(file, digest);
    return digest;
}

std::shared_ptr<const dynamics::SampledInput> RecordStore::get(const RecordSource& source) {
    if (refuse_unshareable_ && batch::unshareable_by_ranks(source.path))
        throw std::runtime_error(batch::unshareable_text(source.cell) + " and name that file in the manifest");
    const std::string path = canonical(source.path);
    const std::string key = path + "\n" + source.unit + "\n" + harness::format_number(source.dt);
    std::string pinned;
    {
        std::lock_guard<std::mutex> lock(pinned_mutex_);
        const auto it = pinned_.find(path);
        if (it != pinned_.end()) pinned = it->second;
    }
    try {
        return cache_.get(key, [&] {
            const std::string text = records::read_text(path);
            if (!pinned.empty() && batch::sha256_hex(text) != pinned)
                throw std::runtime_error(path + ": has changed since the batch began (its sha256 was " + pinned +
                                         ", it is now " + batch::sha256_hex(text) +
                                         "): the results' header names the file as it was");
            // A unit reads a plain-text record only, as the commands' --unit does.
            const records::Record r = source.unit.empty() || records::states_its_units(text)
                                          ? records::parse_any(text, path)
                                          : records::parse_plain(text, path, source.unit, source.dt);
            return dynamics::SampledInput(r.in_g(dynamics::kGravity), r.dt, r.name);
        });
    } catch (const std::exception& e) {
        // The message of the first job's read names the canonical path: each
        // job's names the file as its own row does, whichever job read it.
        std::string what = e.what();
        if (what.find(path) != std::string::npos) replace_all(what, path, source.cell);
        else what = source.cell + ": " + what;
        throw std::runtime_error(what);
    }
}

}  // namespace rocking::jobs
