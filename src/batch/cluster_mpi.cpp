// The cluster over MPI (cluster.hpp).  The protocol, on MPI_COMM_WORLD:
//   a rank other than 0 sends kRows to rank 0: the rows of the chunk it was
//     given (none for its first two), which is also its request for another;
//   rank 0 answers each with kChunk: {first job, count}, or count 0 to stop.
// Rank 0 answers a request at once when the window has room, and later
// otherwise; its main thread alone calls MPI (MPI_THREAD_FUNNELED), polling
// for requests and for its own threads' rows in turn.
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
// The largest chunk a rank is given: the last chunks of a batch must be small
// so that no rank is left with a long tail of jobs while the others wait.
constexpr std::size_t kMaxChunk = 32;

void append_bytes(std::string& out, const void* data, std::size_t size) {
    out.append(static_cast<const char*>(data), size);
}

// index, failed, length, text; one after the other.
std::string pack(std::size_t first, std::vector<JobRow>& rows) {
    std::string out;
    for (std::size_t k = 0; k < rows.size(); ++k) {
        const std::uint64_t index = first + k, length = rows[k].text.size();
        const std::uint8_t failed = rows[k].failed;
        append_bytes(out, &index, sizeof index);
        append_bytes(out, &failed, sizeof failed);
        append_bytes(out, &length, sizeof length);
        out += rows[k].text;
    }
    return out;
}

template <class Add>
void unpack(const std::vector<char>& in, Add add) {
    for (std::size_t at = 0; at < in.size();) {
        std::uint64_t index, length;
        std::uint8_t failed;
        std::memcpy(&index, in.data() + at, sizeof index), at += sizeof index;
        std::memcpy(&failed, in.data() + at, sizeof failed), at += sizeof failed;
        std::memcpy(&length, in.data() + at, sizeof length), at += sizeof length;
        add(static_cast<std::size_t>(index), JobRow{std::string(in.data() + at, length), failed != 0});
        at += length;
    }
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
             const DeliverRow& deliver, const std::string& command) override {
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
        std::vector<JobRow> rows;
        for (int outstanding = kInFlight; outstanding > 0;) {
            std::uint64_t chunk[2] = {0, 0};
            patient_receive(chunk, 2, MPI_UINT64_T, 0, kChunk);
            if (chunk[1] == 0) {  // no more jobs: one request fewer in flight
                --outstanding;
                continue;
            }
            rows.assign(chunk[1], JobRow{});
            run_ordered<JobRow>(
                chunk[1], PoolOptions{threads}, [&](std::size_t k) { return job(chunk[0] + k); },
                [&](std::size_t k, JobRow& row) { rows[k] = std::move(row); });
            const std::string packed = pack(chunk[0], rows);
            MPI_Send(packed.data(), static_cast<int>(packed.size()), MPI_CHAR, 0, kRows, MPI_COMM_WORLD);
        }
    }

    void lead(std::size_t first, std::size_t n, int threads, std::size_t window, const JobFunction& job,
              const DeliverRow& deliver) {
        std::mutex mutex;
        std::condition_variable arrived, room;
        std::size_t next = first, delivered = first;
        std::map<std::size_t, JobRow> ready;  // rows waiting for their turn
        bool stop = false;
        const std::size_t ranks = static_cast<std::size_t>(size_), workers = ranks - 1;

        // A guided chunk: a share of what is left, so that the chunks shrink towards the end.
        auto take = [&](std::size_t& from) {  // under the lock; 0 when none may be taken now
            if (next >= n || next >= delivered + window) return std::size_t{0};
            const std::size_t share = (n - next) / (2 * (ranks + threads));
            const std::size_t count = std::min({std::max<std::size_t>(share, 1), kMaxChunk, delivered + window - next});
            from = next;
            next += count;
            return count;
        };
        // Rank 0's own threads take chunks as the others do, without messages.
        auto work = [&] {
            for (;;) {
                std::size_t from = 0, count = 0;
                {
                    std::unique_lock<std::mutex> lock(mutex);
                    room.wait(lock, [&] { return stop || next >= n || next < delivered + window; });
                    if (stop || next >= n) return;
                    count = take(from);
                }
                std::vector<JobRow> rows;
                for (std::size_t i = from; i < from + count; ++i) rows.push_back(job(i));
                std::lock_guard<std::mutex> lock(mutex);
                for (std::size_t k = 0; k < count; ++k) ready.emplace(from + k, std::move(rows[k]));
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

        std::deque<int> waiting;  // ranks that asked for work
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
                std::lock_guard<std::mutex> lock(mutex);
                unpack(buffer, [&](std::size_t i, JobRow row) { ready.emplace(i, std::move(row)); });
                waiting.push_back(status.MPI_SOURCE);
                busy = true;
            }
            for (std::size_t k = waiting.size(); k > 0; --k) {
                const int to = waiting.front();
                waiting.pop_front();
                std::uint64_t chunk[2] = {0, 0};
                {
                    std::lock_guard<std::mutex> lock(mutex);
                    std::size_t from = 0;
                    const std::size_t count = take(from);
                    if (count == 0 && next < n) {
                        waiting.push_back(to);  // the window is full: it waits for room
                        continue;
                    }
                    chunk[0] = from, chunk[1] = count;
                }
                MPI_Send(chunk, 2, MPI_UINT64_T, to, kChunk, MPI_COMM_WORLD);
                stopped += chunk[1] == 0;
                busy = true;
            }
            for (;;) {
                JobRow row;
                std::size_t i;
                {
                    std::lock_guard<std::mutex> lock(mutex);
                    auto it = ready.find(delivered);
                    if (it == ready.end()) break;
                    row = std::move(it->second);
                    ready.erase(it);
                    i = delivered++;
                }
                room.notify_all();
                deliver(i, row);
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
