#include "batch/pool.hpp"

#include <sched.h>

#include <cerrno>
#include <climits>
#include <cstdlib>
#include <stdexcept>
#include <string>

#include "numerics/number_text.hpp"

namespace rocking::batch {

int default_threads() {
    // hardware_concurrency counts the machine's cores, not those this
    // process may use: under taskset or a container's cpuset it would start
    // more threads than cores.
    cpu_set_t set;
    if (sched_getaffinity(0, sizeof set, &set) == 0) {
        const int n = CPU_COUNT(&set);
        if (n > 0) return n;
    }
    const unsigned n = std::thread::hardware_concurrency();
    return n > 0 ? static_cast<int>(n) : 1;
}

void start_threads(std::vector<std::thread>& pool, std::size_t count, const std::function<void()>& work) {
    pool.reserve(count);
    for (std::size_t k = 0; k < count; ++k) {
        try {
            pool.emplace_back(work);
        } catch (const std::system_error& e) {
            throw ThreadsUnavailable("--jobs: " + std::to_string(count) + " threads were needed and the system " +
                                     "refused one after " + std::to_string(k) + " had started (" + e.code().message() +
                                     ": a limit on processes, ulimit -u, or on memory, ulimit -v, of which each "
                                     "thread's stack takes 8 MiB); no job was run: give a smaller --jobs");
        }
    }
}

// The whole-number rule of every option (numerics::whole_number: "8", "8.0", "1e2").
int parse_threads(const std::string& text) {
    try {
        return static_cast<int>(numerics::whole_number(text, 1, 4096));
    } catch (const std::invalid_argument& e) {
        throw std::invalid_argument(std::string("--jobs: ") + e.what());
    }
}

}  // namespace rocking::batch
