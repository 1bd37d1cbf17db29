// Helpers shared by the tests: scratch files, the message of an exception,
// bisection in long double (the reference root of the closed-form tests) and
// (S1) summed in long double (the reference response to a pulse train).
#pragma once

#include <stdlib.h>
#include <sys/resource.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <functional>
#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

#include "pulse/pulse_train.hpp"

#ifndef ROCKING_SOURCE_DIR
#define ROCKING_SOURCE_DIR "."
#endif

namespace rocking::testing {

// Caps this process's address space at what it holds now plus `headroom`
// bytes (200 MiB: room for about 25 thread stacks of 8 MiB), so that threads
// beyond it cannot start.  For a child of EXPECT_EXIT: the limit is the process's.
inline void limit_address_space(std::size_t headroom = std::size_t{200} << 20) {
    std::size_t pages = 0;
    std::ifstream("/proc/self/statm") >> pages;
    const rlimit limit{pages * static_cast<std::size_t>(sysconf(_SC_PAGESIZE)) + headroom, RLIM_INFINITY};
    setrlimit(RLIMIT_AS, &limit);
}

// A record of the shared folder beside the checkout, ../shared/records/RELATIVE
// (the tests that need one skip, saying so, where it is absent).
inline std::string shared_record(const std::string& relative) {
    return std::string(ROCKING_SOURCE_DIR) + "/../shared/records/" + relative;
}

inline std::string write_temp(const std::string& folder, const std::string& name, const std::string& text) {
    const std::filesystem::path dir = std::filesystem::temp_directory_path() / folder;
    std::filesystem::create_directories(dir);
    const std::string path = (dir / name).string();
    std::ofstream(path) << text;
    return path;
}

// A new folder /tmp/STEM.XXXXXX of the test's own, removed with everything in
// it when the test binary ends.
inline std::string temp_folder(const std::string& stem) {
    struct Folders {
        std::vector<std::string> made;
        ~Folders() {
            for (const std::string& dir : made) std::filesystem::remove_all(dir);
        }
    };
    static Folders folders;
    std::string pattern = "/tmp/" + stem + ".XXXXXX";
    if (!mkdtemp(pattern.data())) throw std::runtime_error("mkdtemp failed");
    folders.made.push_back(pattern);
    return pattern;
}

// The what() of the exception f throws, or "" when it throws none.
inline std::string error_of(const std::function<void()>& f) {
    try {
        f();
    } catch (const std::exception& e) {
        return e.what();
    }
    return "";
}

// The root of f on [lo, hi] (f(lo), f(hi) of opposite signs), by bisection to
// the last bit of long double.
template <class F>
long double bisect(F f, long double lo, long double hi) {
    const bool rising = f(lo) < 0;
    for (int i = 0; i < 200 && lo < hi; ++i) {
        const long double mid = (lo + hi) / 2;
        if (mid == lo || mid == hi) break;
        ((f(mid) < 0) == rising ? lo : hi) = mid;
    }
    return (lo + hi) / 2;
}

// (S1) in long double: the linearised block rocking on corner + from rest
// at t = 0, before any impact, under pulse k of the train from start(k) to
// (rounded in double, as PulseInput rounds it) at level F(k) = a/(alpha g) - 1,
//   phi(t) = theta/alpha = sum_{t_j <= t} dF_j (cosh p(t - t_j) - 1),  cosh y - 1 = 2 sinh^2(y/2),
// and the sum's condition, sum |dF_j| (cosh p(t - t_j) - 1): a relative
// change eps in each term moves phi by at most eps times it.  In the
// superposition engine's units (tau = t/to): to = 1, p = x, F(k) = q A_k - 1.
struct S1Sum {
    long double phi = 0, condition = 0;
};
template <class Level>
S1Sum s1_sum(const PulseTrain& train, Level F, double to, double p, double t) {
    S1Sum v;
    long double previous = 0;
    for (std::size_t k = 0; k < train.size() && train.start(k) * to <= t; ++k) {
        const long double level = F(k);
        const long double u = static_cast<long double>(p) * (static_cast<long double>(t) - train.start(k) * to);
        const long double h = std::sinh(u / 2);
        v.phi += (level - previous) * 2 * h * h;
        v.condition += std::fabs(level - previous) * 2 * h * h;
        previous = level;
    }
    return v;
}

// n identities that sort in their given order ("r0000", "r0001", ...): the
// draw order (studies/record_order.hpp) of records given as data, for the
// tests that compare a study's fits with the fits of its points as listed.
inline std::vector<std::string> listed_order(std::size_t n) {
    std::vector<std::string> out;
    for (std::size_t k = 0; k < n; ++k) {
        std::string digits = std::to_string(k);
        out.push_back("r" + std::string(digits.size() < 4 ? 4 - digits.size() : 0, '0') + digits);
    }
    return out;
}

}  // namespace rocking::testing
