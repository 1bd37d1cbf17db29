// The cluster over MPI (cluster.hpp).  The protocol, on MPI_COMM_WORLD:
//   a rank other than 0 sends kRows to rank 0: the chunk of rows it was
//     given, packed (none for its first two), with the chunk size it would
//     like next; that is also its request for another chunk;
//   rank 0 answers each with kChunk: {first job, count}, or count 0 to stop.
// Rank 0 answers a request at once when the window has room, and later
// otherwise; its main thread alone calls MPI (MPI_THREAD_FUNNELED), polling
// for requests and for its own threads' chunks in turn.  Rows travel and
// wait a chunk at a time: rank 0's cost is a chunk's (one message, one place
// in the order, one append to the file) plus the copy of its bytes, and a
// chunk is as many jobs as a rank runs in about kChunkSeconds, so that cheap
// jobs come in large chunks and costly ones one by one.
#include <mpi.h>

#include <algorithm>
#include <chrono>
#include <condition_variable>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <deque>
#include <map>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

#include "batch/cluster.hpp"
#include "batch/pool.hpp"

namespace rocking::batch {

namespace {

constexpr int kRows = 11, kChunk = 12;
// Requests each rank keeps in flight (each kRows message is one).
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

// {first, count, failed, text bytes, wanted}, the lengths, the text.
std::string pack(const RowChunk& chunk, std::size_t wanted) {
    const std::uint64_t head[5] = {chunk.first, chunk.count(), chunk.failed, chunk.text.size(), wanted};
    std::string out;
    out.reserve(sizeof head + chunk.count() * sizeof(std::uint32_t) + chunk.text.size());
    out.append(reinterpret_cast<const char*>(head), sizeof head);
    out.append(reinterpret_cast<const char*>(chunk.lengths.data()), chunk.count() * sizeof(std::uint32_t));
    out += chunk.text;
    return out;
}

// The chunk in `in` (none when it holds only a request) and the size wanted next.
std::size_t unpack(const std::vector<char>& in, RowChunk& chunk) {
    std::uint64_t head[5] = {0, 0, 0, 0, kFirstChunk};
    if (in.size() < sizeof head) return kFirstChunk;
    std::memcpy(head, in.data(), sizeof head);
    chunk.first = head[0];
    chunk.failed = head[2];
    chunk.lengths.resize(head[1]);
    const char* at = in.data() + sizeof head;
    std::memcpy(chunk.lengths.data(), at, head[1] * sizeof(std::uint32_t));
    at += head[1] * sizeof(std::uint32_t);
    chunk.text.assign(at, head[3]);
    return head[4];
}

// A receive that sleeps between its polls: a blocking MPI_Recv spins a core,
// which on a machine with more ranks than cores takes it from a rank at work.
void patient_receive(void* buffer, int count, MPI_Datatype type, int source, int tag) {
    MPI_Request request;
    MPI_Irecv(buffer, count, type, source, tag, MPI_COMM_WORLD, &request);
    for (int done = 0;;) {
        MPI_Test(&request, &done, MPI_STATUS_IGNORE);
        if (done) return;
        std::this_thread::sleep_for(std::chrono::microseconds(50));
    }
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
             const DeliverChunk& deliver, const std::string& command) override {
        // Once the chunks go out no rank can leave alone: the others would wait for it forever.
        try {
            if (rank_ != 0) follow(threads, job);
            else lead(first, n, threads, window, job, deliver);
        } catch (const std::exception& e) {
            std::fprintf(stderr, "%s: %s%s\n", command.c_str(),
                         rank_ == 0 ? "" : ("rank " + std::to_string(rank_) + ": ").c_str(), e.what());
            MPI_Abort(MPI_COMM_WORLD, 1);
        }
    }

private:
    // Two requests in flight: while a rank runs one chunk, the next is on its
    // way, and it never waits for rank 0 between chunks.
    void follow(int threads, const JobFunction& job) {
        for (int k = 0; k < kInFlight; ++k) MPI_Send(nullptr, 0, MPI_CHAR, 0, kRows, MPI_COMM_WORLD);
        for (int outstanding = kInFlight; outstanding > 0;) {
            std::uint64_t given[2] = {0, 0};
            patient_receive(given, 2, MPI_UINT64_T, 0, kChunk);
            if (given[1] == 0) {  // no more jobs: one request fewer in flight
                --outstanding;
                continue;
            }
            const auto began = std::chrono::steady_clock::now();
            RowChunk chunk;
            chunk.first = given[0];
            chunk.lengths.reserve(given[1]);
            run_ordered<JobRow>(
                given[1], PoolOptions{threads}, [&](std::size_t k) { return job(given[0] + k); },
                [&](std::size_t, JobRow& row) { chunk.add(row); });
            const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - began).count();
            // Its threads ran the chunk together: a chunk of `threads` times the jobs takes the same time.
            const std::string packed = pack(chunk, wanted_after(given[1], seconds) * static_cast<std::size_t>(threads));
            MPI_Send(packed.data(), static_cast<int>(packed.size()), MPI_CHAR, 0, kRows, MPI_COMM_WORLD);
        }
    }

    void lead(std::size_t first, std::size_t n, int threads, std::size_t window, const JobFunction& job,
              const DeliverChunk& deliver) {
        std::mutex mutex;
        std::condition_variable arrived, room;
        std::size_t next = first, delivered = first;
        std::map<std::size_t, RowChunk> ready;  // chunks waiting for their turn, by their first job
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
        // Rank 0's own threads take chunks as the others do, without messages.
        auto work = [&] {
            std::size_t wanted = kFirstChunk;
            for (;;) {
                std::size_t from = 0, count = 0;
                {
                    std::unique_lock<std::mutex> lock(mutex);
                    room.wait(lock, [&] { return stop || next >= n || next < delivered + window; });
                    if (stop || next >= n) return;
                    count = take(from, wanted);
                }
                const auto began = std::chrono::steady_clock::now();
                RowChunk chunk;
                chunk.first = from;
                chunk.lengths.reserve(count);
                for (std::size_t i = from; i < from + count; ++i) chunk.add(job(i));
                wanted = wanted_after(count, std::chrono::duration<double>(std::chrono::steady_clock::now() - began).count());
                std::lock_guard<std::mutex> lock(mutex);
                ready.emplace(from, std::move(chunk));
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
        std::vector<char> buffer;
        // Every rank ends once each of its requests in flight has been answered "stop".
        while (delivered < n || stopped < kInFlight * workers) {
            bool busy = false;
            for (int flag = 1; flag;) {
                MPI_Status status;
                MPI_Iprobe(MPI_ANY_SOURCE, kRows, MPI_COMM_WORLD, &flag, &status);
                if (!flag) break;
                int count = 0;
                MPI_Get_count(&status, MPI_CHAR, &count);
                buffer.resize(static_cast<std::size_t>(count));
                MPI_Recv(buffer.data(), count, MPI_CHAR, status.MPI_SOURCE, kRows, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
                RowChunk chunk;
                const std::size_t wanted = unpack(buffer, chunk);
                if (chunk.count() > 0) {
                    std::lock_guard<std::mutex> lock(mutex);
                    ready.emplace(chunk.first, std::move(chunk));
                }
                waiting.emplace_back(status.MPI_SOURCE, wanted);
                busy = true;
            }
            for (std::size_t k = waiting.size(); k > 0; --k) {
                const auto [to, wanted] = waiting.front();
                waiting.pop_front();
                std::uint64_t chunk[2] = {0, 0};
                {
                    std::lock_guard<std::mutex> lock(mutex);
                    std::size_t from = 0;
                    const std::size_t count = take(from, wanted);
                    if (count == 0 && next < n) {
                        waiting.emplace_back(to, wanted);  // the window is full: it waits for room
                        continue;
                    }
                    chunk[0] = from, chunk[1] = count;
                }
                MPI_Send(chunk, 2, MPI_UINT64_T, to, kChunk, MPI_COMM_WORLD);
                stopped += chunk[1] == 0;
                busy = true;
            }
            for (;;) {
                RowChunk chunk;
                {
                    std::lock_guard<std::mutex> lock(mutex);
                    auto it = ready.find(delivered);
                    if (it == ready.end()) break;
                    chunk = std::move(it->second);
                    ready.erase(it);
                    delivered += chunk.count();
                }
                room.notify_all();
                deliver(chunk);
                busy = true;
            }
            if (!busy) {
                std::unique_lock<std::mutex> lock(mutex);
                arrived.wait_for(lock, std::chrono::microseconds(100), [&] { return ready.count(delivered) > 0; });
            }
        }
    }

    int rank_ = 0, size_ = 1;
};

}  // namespace

bool built_with_mpi() { return true; }

std::unique_ptr<Ranks> join_cluster() { return std::make_unique<MpiRanks>(); }

}  // namespace rocking::batch
