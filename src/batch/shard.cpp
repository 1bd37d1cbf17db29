#include "batch/shard.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <map>
#include <stdexcept>

#include "batch/manifest.hpp"

namespace rocking::batch {

namespace {

constexpr char kDigestLine[] = "# manifest sha256: ";
constexpr std::size_t kMaxShards = 100000;

std::string why(int error) { return std::strerror(error); }

// One shard's file read in order: its first line, its header, its rows.
struct ShardFile {
    std::string path, digest;  // the manifest's, without the shard
    Shard shard;
    std::string header;        // the lines after the first, up to the column line, each ending '\n'
    std::ifstream in;
};

void open_shard(ShardFile& f) {
    f.in.open(f.path, std::ios::binary);
    if (!f.in) throw ResultsError(f.path + ": cannot read: " + why(errno));
    std::string line;
    if (!std::getline(f.in, line) || line.rfind(kDigestLine, 0) != 0)
        throw ResultsError(f.path + ": not a results file of rocking batch (no '" + std::string(kDigestLine) + "' line)");
    const std::string rest = line.substr(sizeof kDigestLine - 1);
    const std::size_t at = rest.find(" shard ");
    if (at == std::string::npos)
        throw ResultsError(f.path + ": the results of a whole batch, not of a shard (--shard I/N): nothing to join");
    f.digest = rest.substr(0, at);
    try {
        f.shard = parse_shard(rest.substr(at + 7));
    } catch (const std::invalid_argument& e) {
        throw ResultsError(f.path + ":1: " + e.what());
    }
    // The header: comments, then the column line, the first that is not one.
    while (std::getline(f.in, line)) {
        f.header += line + "\n";
        if (line.empty() || line[0] != '#') return;
    }
    throw ResultsError(f.path + ": ends inside its header");
}

// Copies the shard's rows to `out` and checks its end line against them.
std::pair<std::size_t, std::size_t> copy_rows(ShardFile& f, std::FILE* out, const std::string& tmp) {
    std::string line;
    std::size_t rows = 0;
    while (std::getline(f.in, line)) {
        if (line.rfind("# end: ", 0) == 0) {
            unsigned long long jobs = 0, failed = 0;
            std::string more;
            if (std::sscanf(line.c_str(), "# end: %llu jobs, %llu failed", &jobs, &failed) != 2 || jobs != rows ||
                std::getline(f.in, more))
                throw ResultsError(f.path + ": its end line '" + line + "' does not close its " + std::to_string(rows) +
                                   " rows: the file was changed or damaged");
            return {rows, failed};
        }
        // A quoted cell's line break belongs to the row (RFC 4180).
        for (std::string next; !csv_record_end(line, 0).closed && std::getline(f.in, next);) line += "\n" + next;
        line += '\n';
        if (std::fwrite(line.data(), 1, line.size(), out) != line.size())
            throw ResultsError(tmp + ": cannot write: " + why(errno));
        ++rows;
    }
    throw ResultsError(f.path + ": has no '# end' line: the shard has not finished (resume it: rocking batch MANIFEST "
                       "--shard " + std::to_string(f.shard.index) + "/" + std::to_string(f.shard.count) +
                       " --output FILE --resume)");
}

}  // namespace

Shard parse_shard(const std::string& text) {
    Shard s;
    const std::size_t slash = text.find('/');
    auto whole = [](const std::string& t, std::size_t& v) {
        if (t.empty() || t.size() > 6 || t.find_first_not_of("0123456789") != std::string::npos) return false;
        v = std::stoul(t);
        return true;
    };
    if (slash == std::string::npos || !whole(text.substr(0, slash), s.index) || !whole(text.substr(slash + 1), s.count) ||
        s.count < 1 || s.count > kMaxShards || s.index < 1 || s.index > s.count)
        throw std::invalid_argument("a shard is I/N, the I-th of N parts, 1 <= I <= N <= 100000 (got '" + text + "')");
    return s;
}

JobRange shard_jobs(std::size_t jobs, Shard s) {
    // floor(jobs i / N) without forming jobs i, which could overflow: (jobs mod N) i < N^2 <= 1e10.
    const auto at = [&](std::size_t i) { return jobs / s.count * i + jobs % s.count * i / s.count; };
    return {at(s.index - 1), at(s.index)};
}

BatchPlan shard_plan(const BatchPlan& plan, Shard s) {
    const JobRange r = shard_jobs(plan.jobs, s);
    BatchPlan part = plan;
    part.jobs = r.end - r.first;
    part.digest = plan.digest + " shard " + std::to_string(s.index) + "/" + std::to_string(s.count);
    part.run = [run = plan.run, first = r.first](std::size_t k) { return run(first + k); };
    return part;
}

JoinOutcome join_shards(const std::vector<std::string>& paths, const std::string& output) {
    if (paths.empty()) throw ResultsError("no shard to join");
    std::error_code ec;
    std::vector<ShardFile> files(paths.size());
    std::map<std::size_t, std::size_t> by_index;
    for (std::size_t k = 0; k < paths.size(); ++k) {
        if (std::filesystem::equivalent(paths[k], output, ec))
            throw ResultsError(output + ": is the shard " + paths[k] + " itself: give the joined results another name");
        files[k].path = paths[k];
        open_shard(files[k]);
        const ShardFile& f = files[k];
        const ShardFile& first = files[0];
        if (f.shard.count != first.shard.count)
            throw ResultsError(f.path + ": shard " + std::to_string(f.shard.index) + "/" + std::to_string(f.shard.count) +
                               " of another cut than " + first.path + "'s (of " + std::to_string(first.shard.count) + ")");
        if (f.digest != first.digest)
            throw ResultsError(f.path + ": the results of another manifest than " + first.path + "'s (sha256 " + f.digest +
                               " against " + first.digest + ")");
        if (f.header != first.header)
            throw ResultsError(f.path + ": its header (records' digests, columns) differs from " + first.path +
                               "'s: the shards read other records or ran another rocking");
        if (!by_index.emplace(f.shard.index, k).second)
            throw ResultsError(f.path + ": shard " + std::to_string(f.shard.index) + " given twice (also " +
                               files[by_index[f.shard.index]].path + ")");
    }
    const std::size_t n = files[0].shard.count;
    for (std::size_t i = 1; i <= n; ++i)
        if (!by_index.count(i))
            throw ResultsError("shard " + std::to_string(i) + "/" + std::to_string(n) + " is missing: join needs all " +
                               std::to_string(n) + " (" + std::to_string(paths.size()) + " given)");

    const std::string tmp = output + ".join.tmp";
    std::FILE* out = std::fopen(tmp.c_str(), "wb");
    if (!out) throw ResultsError(tmp + ": cannot create: " + why(errno));
    JoinOutcome o;
    o.shards = n;
    std::vector<std::size_t> counts(n + 1);
    try {
        const std::string head = kDigestLine + files[0].digest + "\n" + files[0].header;
        if (std::fwrite(head.data(), 1, head.size(), out) != head.size()) throw ResultsError(tmp + ": cannot write: " + why(errno));
        for (std::size_t i = 1; i <= n; ++i) {
            const auto [rows, failed] = copy_rows(files[by_index[i]], out, tmp);
            counts[i] = rows;
            o.jobs += rows, o.failed += failed;
        }
        // Each shard must hold its part of the whole: a shard of a cut of another manifest's size is not.
        for (std::size_t i = 1; i <= n; ++i) {
            const JobRange r = shard_jobs(o.jobs, Shard{i, n});
            if (counts[i] != r.end - r.first)
                throw ResultsError(files[by_index[i]].path + ": holds " + std::to_string(counts[i]) + " rows, but shard " +
                                   std::to_string(i) + "/" + std::to_string(n) + " of " + std::to_string(o.jobs) +
                                   " jobs has " + std::to_string(r.end - r.first));
        }
        const std::string end = "# end: " + std::to_string(o.jobs) + " jobs, " + std::to_string(o.failed) + " failed\n";
        if (std::fwrite(end.data(), 1, end.size(), out) != end.size() || std::fflush(out) != 0 || ::fsync(fileno(out)) != 0)
            throw ResultsError(tmp + ": cannot write: " + why(errno));
    } catch (...) {
        std::fclose(out);
        ::unlink(tmp.c_str());
        throw;
    }
    if (std::fclose(out) != 0 || std::rename(tmp.c_str(), output.c_str()) != 0) {
        const int error = errno;
        ::unlink(tmp.c_str());
        throw ResultsError(output + ": cannot write: " + why(error));
    }
    return o;
}

}  // namespace rocking::batch
