// The cluster over MPI (cluster.hpp).  The protocol, on MPI_COMM_WORLD:
//   a rank other than 0 sends rank 0 requests for work, two in flight; a
//     chunk it has run goes back as the next request: its summary (first
//     job, count, failed, bytes, checksum) when the ranks write their own
//     rows, its rows too when they pass through rank 0;
//   rank 0 answers each request with a chunk {first job, count}, or count 0
//     when none is left; it places each chunk, in the jobs' order, at the end
//     of those before it and sends the rank the offset; about once a second
//     it asks each rank that wrote since the last time to sync, and once
//     every answer is in the state counts the chunks synced (results_file);
//     at the end it tells every rank to quit.
// Rank 0's main thread alone calls MPI (MPI_THREAD_FUNNELED).  What it
// spends on a chunk is a message, a place in the order and an offset sent:
// a chunk is as many jobs as a rank runs in about kChunkSeconds, so that
// cheap jobs come in large chunks and costly ones one by one, and a row
// costs rank 0 a share of a chunk, not its bytes.  The bytes go through rank
// 0 only when the ranks cannot open its file (a folder not shared), or when
// the rows go to standard output or to the front end.
#include <fcntl.h>
#include <mpi.h>
#include <time.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <condition_variable>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <deque>
#include <exception>
#include <map>
#include <mutex>
#include <random>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include "batch/cluster.hpp"
#include "batch/pool.hpp"

namespace rocking::batch {

namespace {

constexpr int kToLead = 11, kToRank = 12;
// To rank 0: {what, wanted, first, count, failed, bytes, digest}, then for
// kRows the rows' lengths and text.  kSynced carries the epoch in `first`.
enum : std::uint64_t { kAsk = 1, kRows = 2, kRan = 3, kSynced = 4 };
constexpr std::size_t kHead = 7;
// To a rank: {what, a, b}: kGive {first, count (0: no more)}, kPlace {first,
// offset}, kSync {epoch}, kQuit.  Sent in order, read in order.
enum : std::uint64_t { kGive = 1, kPlace = 2, kSync = 3, kQuit = 4 };
// Requests each rank keeps in flight: while it runs one chunk, the next is on its way.
constexpr int kInFlight = 2;
// The time a chunk should take a rank, and the bounds of its size: long enough
// that a chunk's fixed costs vanish beside its jobs, short enough that a kill
// loses little and no rank is left with a long tail while the others wait.
constexpr double kChunkSeconds = 0.02;
constexpr std::size_t kMaxChunk = 4096, kFirstChunk = 4;

// The chunk size that takes about kChunkSeconds at `seconds` for `jobs` jobs.
std::size_t wanted_after(std::size_t jobs, double seconds) {
    if (jobs == 0) return kFirstChunk;
    const double each = std::max(seconds / static_cast<double>(jobs), 1e-9);
    return static_cast<std::size_t>(std::clamp(kChunkSeconds / each, 1.0, static_cast<double>(kMaxChunk)));
}

std::string pack(std::uint64_t what, std::size_t wanted, const RowChunk& chunk) {
    const std::uint64_t head[kHead] = {what, wanted, chunk.first, chunk.count(), chunk.failed, chunk.text.size(), chunk.digest};
    std::string out(reinterpret_cast<const char*>(head), sizeof head);
    if (what != kRows) return out;
    out.append(reinterpret_cast<const char*>(chunk.lengths.data()), chunk.count() * sizeof(std::uint32_t));
    return out += chunk.text;
}

// A message to rank 0: its head, and for kRows the chunk's rows into `chunk`.
void unpack(const std::vector<char>& in, std::uint64_t (&head)[kHead], RowChunk& chunk) {
    std::memcpy(head, in.data(), sizeof head);
    chunk.first = head[2], chunk.failed = head[4], chunk.digest = head[6];
    if (head[0] != kRows) return;
    chunk.lengths.resize(head[3]);
    const char* at = in.data() + sizeof head;
    std::memcpy(chunk.lengths.data(), at, head[3] * sizeof(std::uint32_t));
    chunk.text.assign(at + head[3] * sizeof(std::uint32_t), head[5]);
}

void send_to_rank(int rank, std::uint64_t what, std::uint64_t a = 0, std::uint64_t b = 0) {
    const std::uint64_t message[3] = {what, a, b};
    MPI_Send(message, 3, MPI_UINT64_T, rank, kToRank, MPI_COMM_WORLD);
}

void write_fully(int fd, const std::string& text, std::uint64_t offset, const std::string& path) {
    for (std::size_t at = 0; at < text.size();) {
        const ssize_t n = ::pwrite(fd, text.data() + at, text.size() - at, static_cast<off_t>(offset + at));
        if (n < 0 && errno == EINTR) continue;
        if (n <= 0) throw std::runtime_error(path + ": cannot write: " + std::strerror(n < 0 ? errno : ENOSPC));
        at += static_cast<std::size_t>(n);
    }
}

// Whether the file at `path` holds `probe` at `offset`: the one rank 0 wrote,
// not another of the same name on this node's disk.
bool sees_probe(int fd, std::uint64_t offset, const std::string& probe) {
    std::string read(probe.size(), '\0');
    return fd >= 0 && ::pread(fd, read.data(), read.size(), static_cast<off_t>(offset)) == static_cast<ssize_t>(read.size()) &&
           read == probe;
}

double thread_cpu_seconds() {
    timespec t{};
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
    return static_cast<double>(t.tv_sec) + 1e-9 * static_cast<double>(t.tv_nsec);
}

std::string random_probe() {
    std::random_device device;
    std::string probe = "rocking batch probe ";
    for (int k = 0; k < 4; ++k) probe += std::to_string(device());
    return probe;
}

class MpiRanks : public Ranks {
public:
    MpiRanks() {
        int provided = 0;
        MPI_Init_thread(nullptr, nullptr, MPI_THREAD_FUNNELED, &provided);
        MPI_Comm_rank(MPI_COMM_WORLD, &rank_);
        MPI_Comm_size(MPI_COMM_WORLD, &size_);
    }
    ~MpiRanks() override { MPI_Finalize(); }

    int rank() const override { return rank_; }
    int size() const override { return size_; }

    int agree(int status) override {
        int all = 0;
        MPI_Allreduce(&status, &all, 1, MPI_INT, MPI_MAX, MPI_COMM_WORLD);
        return all;
    }

    std::string broadcast(const std::string& text) override {
        unsigned long long size = text.size();
        MPI_Bcast(&size, 1, MPI_UNSIGNED_LONG_LONG, 0, MPI_COMM_WORLD);
        std::string out = rank_ == 0 ? text : std::string(size, '\0');
        MPI_Bcast(out.data(), static_cast<int>(size), MPI_CHAR, 0, MPI_COMM_WORLD);
        return out;
    }

    void run(std::size_t first, std::size_t n, int threads, std::size_t window, const JobFunction& job,
             const Delivery& delivery, const std::string& command) override {
        // Once the chunks go out no rank can leave alone: the others would wait for it forever.
        try {
            const std::string path = open_shared(delivery);
            if (rank_ != 0) follow(threads, job, path);
            else lead(first, n, threads, window, job, delivery, !path.empty());
        } catch (const std::exception& e) {
            if (rank_ == 0 && delivery.file) delivery.file->discard_unless_rows_kept();
            std::fprintf(stderr, "%s: %s%s\n", command.c_str(),
                         rank_ == 0 ? "" : ("rank " + std::to_string(rank_) + ": ").c_str(), e.what());
            MPI_Abort(MPI_COMM_WORLD, 1);
        }
        if (fd_ >= 0) ::close(fd_);
        fd_ = -1;
    }

private:
    // Collective: whether every rank opens rank 0's partial file (fd_ on the
    // others): its path then, else "".  Rank 0 writes a probe where no row is
    // yet and each rank reads it back: a file of the same name on a node's own
    // disk would take rows that never reach the results.
    std::string open_shared(const Delivery& delivery) {
        std::string offer;
        if (rank_ == 0 && delivery.file && delivery.file->on_disk()) {
            const std::string probe = random_probe();
            offer = std::to_string(delivery.file->write_probe(probe)) + "\n" + probe + "\n" + delivery.file->partial_path();
        }
        offer = broadcast(offer);
        if (offer.empty()) return "";
        std::istringstream in(offer);
        std::string offset, probe, path;
        std::getline(in, offset), std::getline(in, probe), std::getline(in, path, '\0');
        if (rank_ != 0) fd_ = ::open(path.c_str(), O_RDWR | O_CLOEXEC);
        const bool shared = agree(rank_ == 0 || sees_probe(fd_, std::stoull(offset), probe) ? 0 : 1) == 0;
        if (rank_ == 0) delivery.file->clear_probe();
        if (shared) return path;
        if (fd_ >= 0) ::close(fd_);
        fd_ = -1;
        return "";
    }

    // A rank's main thread talks to rank 0 and writes; one thread of its own
    // runs the chunks given (on `threads` threads), so that an offset or a
    // sync is answered while a long chunk runs.
    void follow(int threads, const JobFunction& job, const std::string& path) {
        std::mutex mutex;
        std::condition_variable changed;
        std::deque<std::pair<std::uint64_t, std::uint64_t>> given;  // {first, count}
        std::deque<std::pair<RowChunk, double>> ran;                // and the seconds each took
        std::size_t running = 0;
        bool quit = false;
        std::exception_ptr failure;
        std::thread runner([&] {
            for (;;) {
                std::pair<std::uint64_t, std::uint64_t> chunk;
                {
                    std::unique_lock<std::mutex> lock(mutex);
                    changed.wait(lock, [&] { return quit || !given.empty(); });
                    if (quit) return;
                    chunk = given.front();
                    given.pop_front();
                }
                const auto began = std::chrono::steady_clock::now();
                RowChunk rows;
                rows.first = chunk.first;
                rows.lengths.reserve(chunk.second);
                try {
                    run_ordered<JobRow>(
                        chunk.second, PoolOptions{threads}, [&](std::size_t k) { return job(chunk.first + k); },
                        [&](std::size_t, JobRow& row) { rows.add(row); });
                } catch (...) {
                    std::lock_guard<std::mutex> lock(mutex);
                    failure = std::current_exception();
                    changed.notify_all();
                    return;
                }
                const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - began).count();
                std::lock_guard<std::mutex> lock(mutex);
                ran.emplace_back(std::move(rows), seconds);
                --running;
                changed.notify_all();
            }
        });
        struct Stop {
            std::mutex& mutex;
            bool& quit;
            std::condition_variable& changed;
            std::thread& runner;
            ~Stop() {
                {
                    std::lock_guard<std::mutex> lock(mutex);
                    quit = true;
                }
                changed.notify_all();
                runner.join();
            }
        } stop{mutex, quit, changed, runner};

        const RowChunk none;
        for (int k = 0; k < kInFlight; ++k) {
            const std::string ask = pack(kAsk, kFirstChunk, none);
            MPI_Send(ask.data(), static_cast<int>(ask.size()), MPI_CHAR, 0, kToLead, MPI_COMM_WORLD);
        }
        std::map<std::uint64_t, std::string> unplaced;  // rows run, by first job, until rank 0 says where
        for (bool done = false; !done;) {
            bool busy = false;
            for (int flag = 1;;) {
                MPI_Iprobe(0, kToRank, MPI_COMM_WORLD, &flag, MPI_STATUS_IGNORE);
                if (!flag) break;
                std::uint64_t message[3];
                MPI_Recv(message, 3, MPI_UINT64_T, 0, kToRank, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
                busy = true;
                if (message[0] == kGive && message[2] > 0) {
                    std::lock_guard<std::mutex> lock(mutex);
                    given.emplace_back(message[1], message[2]);
                    ++running;
                    changed.notify_all();
                } else if (message[0] == kPlace) {
                    const auto it = unplaced.find(message[1]);
                    if (it == unplaced.end()) throw std::logic_error("an offset for a chunk this rank did not run");
                    write_fully(fd_, it->second, message[2], path);
                    unplaced.erase(it);
                } else if (message[0] == kSync) {
                    if (::fdatasync(fd_) != 0) throw std::runtime_error(path + ": cannot sync: " + std::strerror(errno));
                    RowChunk epoch;
                    epoch.first = message[1];
                    const std::string synced = pack(kSynced, 0, epoch);
                    MPI_Send(synced.data(), static_cast<int>(synced.size()), MPI_CHAR, 0, kToLead, MPI_COMM_WORLD);
                } else if (message[0] == kQuit)
                    done = true;
            }
            std::deque<std::pair<RowChunk, double>> finished;
            bool working = false;
            {
                std::lock_guard<std::mutex> lock(mutex);
                if (failure) std::rethrow_exception(failure);
                finished.swap(ran);
                working = running > 0;
            }
            for (auto& [rows, seconds] : finished) {
                // Its threads ran the chunk together: a chunk of `threads` times the jobs takes the same time.
                const std::size_t wanted = wanted_after(rows.count(), seconds) * static_cast<std::size_t>(threads);
                const std::string message = pack(path.empty() ? kRows : kRan, wanted, rows);
                MPI_Send(message.data(), static_cast<int>(message.size()), MPI_CHAR, 0, kToLead, MPI_COMM_WORLD);
                if (!path.empty()) unplaced.emplace(rows.first, std::move(rows.text));
                busy = true;
            }
            if (busy || done) continue;
            // While a chunk runs an offset or a sync may wait a millisecond; an idle rank waits
            // for its next chunk, which comes at once, so it looks often (a blocking receive
            // would spin a core, taken from a rank at work on a machine of fewer cores than ranks).
            std::unique_lock<std::mutex> lock(mutex);
            changed.wait_for(lock, working ? std::chrono::microseconds(1000) : std::chrono::microseconds(50),
                             [&] { return !ran.empty() || failure; });
        }
    }

    void lead(std::size_t first, std::size_t n, int threads, std::size_t window, const JobFunction& job,
              const Delivery& delivery, bool shared);

    int rank_ = 0, size_ = 1;
    int fd_ = -1;  // rank 0's partial file, on a rank that writes its own rows
};

void MpiRanks::lead(std::size_t first, std::size_t n, int threads, std::size_t window, const JobFunction& job,
                    const Delivery& delivery, bool shared) {
    struct Ready {
        ChunkSummary summary;
        int rank = 0;
        RowChunk rows;  // when they came to rank 0: its own threads' chunks, and every chunk unless shared
    };
    // A chunk of its own threads, placed: the threads write it, not the main thread, so
    // that no row's bytes pass through the thread every chunk does.
    struct OwnWrite {
        ResultsFile::Placement at;
        std::string text;
    };
    std::mutex mutex;
    std::condition_variable arrived, room;
    std::size_t next = first, delivered = first;
    std::map<std::size_t, Ready> ready;  // chunks waiting for their turn, by their first job
    std::deque<OwnWrite> own_writes;
    std::size_t own_unwritten = 0;  // own chunks run and not yet written (shared only)
    std::exception_ptr failure;
    bool stop = false;
    const std::size_t ranks = static_cast<std::size_t>(size_), workers = ranks - 1;

    // A guided chunk: a share of what is left, so that the chunks shrink towards
    // the end, at most what the rank asked for.
    auto take = [&](std::size_t& from, std::size_t wanted) {  // under the lock; 0 when none may be taken now
        if (next >= n || next >= delivered + window) return std::size_t{0};
        const std::size_t share = (n - next) / (2 * (ranks + threads));
        const std::size_t count =
            std::min({std::max<std::size_t>(share, 1), std::max<std::size_t>(wanted, 1), delivered + window - next});
        from = next;
        next += count;
        return count;
    };
    // Rank 0's own threads take chunks as the others do, without messages, and
    // write them once placed; they end when no job is left and all they ran is written.
    auto work = [&] {
        std::size_t wanted = kFirstChunk;
        for (;;) {
            std::size_t from = 0, count = 0;
            OwnWrite write;
            bool writes = false;
            {
                std::unique_lock<std::mutex> lock(mutex);
                room.wait(lock, [&] {
                    return stop || !own_writes.empty() || (next >= n && own_unwritten == 0) ||
                           (next < n && next < delivered + window);
                });
                if (stop) return;
                if (!own_writes.empty()) {
                    write = std::move(own_writes.front());
                    own_writes.pop_front();
                    writes = true;
                } else if (next >= n)
                    return;
                else
                    count = take(from, wanted);
            }
            if (writes) {
                try {
                    delivery.file->write_own(write.at, write.text);
                } catch (...) {
                    std::lock_guard<std::mutex> lock(mutex);
                    failure = std::current_exception();
                    return;
                }
                std::lock_guard<std::mutex> lock(mutex);
                --own_unwritten;
                room.notify_all();  // the others may end now
                continue;
            }
            const auto began = std::chrono::steady_clock::now();
            Ready chunk;
            chunk.rows.first = from;
            chunk.rows.lengths.reserve(count);
            for (std::size_t i = from; i < from + count; ++i) chunk.rows.add(job(i));
            chunk.summary = chunk.rows.summary();
            wanted = wanted_after(count, std::chrono::duration<double>(std::chrono::steady_clock::now() - began).count());
            std::lock_guard<std::mutex> lock(mutex);
            ready.emplace(from, std::move(chunk));
            own_unwritten += shared;
            arrived.notify_one();
        }
    };
    std::vector<std::thread> pool;
    struct Joiner {
        std::vector<std::thread>& pool;
        std::mutex& mutex;
        bool& stop;
        std::condition_variable& room;
        ~Joiner() {
            {
                std::lock_guard<std::mutex> lock(mutex);
                stop = true;
            }
            room.notify_all();
            for (std::thread& t : pool) t.join();
        }
    } joiner{pool, mutex, stop, room};
    start_threads(pool, static_cast<std::size_t>(threads), work);

    std::deque<std::pair<int, std::size_t>> waiting;  // ranks that asked for work, and how many jobs
    std::size_t stopped = 0;
    // Shared: the chunks each rank was told to write and has not synced yet, as
    // {placed number, the first sync epoch that covers it}; the epochs asked of
    // each rank; the answers awaited; when the last round of syncs began.
    std::vector<std::deque<std::pair<std::size_t, std::uint64_t>>> unsynced(ranks);
    std::vector<std::uint64_t> epoch(ranks, 0);
    std::size_t unsynced_chunks = 0, syncs_awaited = 0;
    bool round_counted = true;
    auto round_began = std::chrono::steady_clock::now();
    std::vector<char> buffer;
    // When nothing came, a wait that grows to a millisecond: the ranks keep a request
    // in flight, so an answer a millisecond late costs them nothing, and an idle main
    // thread costs its core next to nothing.
    auto idle_wait = std::chrono::microseconds(50);
    for (;;) {
        const double cpu_began = delivery.busy_cpu ? thread_cpu_seconds() : 0;
        bool busy = false;
        for (int flag = 1; flag;) {
            MPI_Status status;
            MPI_Iprobe(MPI_ANY_SOURCE, kToLead, MPI_COMM_WORLD, &flag, &status);
            if (!flag) break;
            int count = 0;
            MPI_Get_count(&status, MPI_CHAR, &count);
            buffer.resize(static_cast<std::size_t>(count));
            MPI_Recv(buffer.data(), count, MPI_CHAR, status.MPI_SOURCE, kToLead, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
            std::uint64_t head[kHead];
            Ready chunk;
            unpack(buffer, head, chunk.rows);
            busy = true;
            if (head[0] == kSynced) {
                auto& own = unsynced[static_cast<std::size_t>(status.MPI_SOURCE)];
                for (; !own.empty() && own.front().second <= head[2]; own.pop_front(), --unsynced_chunks)
                    delivery.file->synced(own.front().first);
                --syncs_awaited;
                continue;
            }
            if (head[0] != kAsk) {
                chunk.summary = {head[2], head[3], head[4], head[5], head[6]};
                chunk.rank = status.MPI_SOURCE;
                std::lock_guard<std::mutex> lock(mutex);
                ready.emplace(chunk.summary.first, std::move(chunk));
            }
            waiting.emplace_back(status.MPI_SOURCE, head[1]);
        }
        for (std::size_t k = waiting.size(); k > 0; --k) {
            const auto [to, wanted] = waiting.front();
            waiting.pop_front();
            std::size_t from = 0, count = 0;
            {
                std::lock_guard<std::mutex> lock(mutex);
                count = take(from, wanted);
                if (count == 0 && next < n) {
                    waiting.emplace_back(to, wanted);  // the window is full: it waits for room
                    continue;
                }
            }
            send_to_rank(to, kGive, from, count);
            stopped += count == 0;
            busy = true;
        }
        for (;;) {
            Ready chunk;
            {
                std::lock_guard<std::mutex> lock(mutex);
                auto it = ready.find(delivered);
                if (it == ready.end()) break;
                chunk = std::move(it->second);
                ready.erase(it);
                delivered += chunk.summary.count;
            }
            room.notify_all();
            busy = true;
            if (!shared) {
                delivery.rows(chunk.rows);
                continue;
            }
            const ResultsFile::Placement at = delivery.file->place(chunk.summary);
            if (chunk.rank == 0) {
                std::lock_guard<std::mutex> lock(mutex);
                own_writes.push_back({at, std::move(chunk.rows.text)});
                room.notify_all();
            } else {
                send_to_rank(chunk.rank, kPlace, chunk.summary.first, at.offset);
                unsynced[static_cast<std::size_t>(chunk.rank)].emplace_back(at.number, epoch[static_cast<std::size_t>(chunk.rank)] + 1);
                ++unsynced_chunks;
            }
            delivery.placed(chunk.summary);
        }
        if (shared && syncs_awaited == 0) {
            // A round's answers are all in: the state counts what they synced (and rank 0's own rows).
            if (!round_counted) delivery.file->flush();
            round_counted = true;
            const auto now = std::chrono::steady_clock::now();
            if (std::chrono::duration<double>(now - round_began).count() >= delivery.flush_seconds ||
                (delivered == n && unsynced_chunks > 0)) {
                for (std::size_t r = 1; r < ranks; ++r)
                    if (!unsynced[r].empty() && unsynced[r].back().second > epoch[r]) {
                        send_to_rank(static_cast<int>(r), kSync, ++epoch[r]);
                        ++syncs_awaited;
                        busy = true;
                    }
                round_began = now;
                round_counted = false;
            }
        }
        {
            std::lock_guard<std::mutex> lock(mutex);
            if (failure) std::rethrow_exception(failure);
            if (delivered == n && stopped == kInFlight * workers &&
                (!shared || (unsynced_chunks == 0 && syncs_awaited == 0 && own_unwritten == 0)))
                break;
        }
        if (busy) {
            if (delivery.busy_cpu) *delivery.busy_cpu += thread_cpu_seconds() - cpu_began;
            idle_wait = std::chrono::microseconds(50);
            continue;
        }
        std::unique_lock<std::mutex> lock(mutex);
        arrived.wait_for(lock, idle_wait, [&] { return ready.count(delivered) > 0; });
        idle_wait = std::min(2 * idle_wait, std::chrono::microseconds(1000));
    }
    for (std::size_t r = 1; r < ranks; ++r) send_to_rank(static_cast<int>(r), kQuit);
}

}  // namespace

bool built_with_mpi() { return true; }

std::unique_ptr<Ranks> join_cluster() { return std::make_unique<MpiRanks>(); }

}  // namespace rocking::batch
