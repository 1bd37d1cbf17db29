// Helpers shared by the tests: scratch files, the message of an exception, and
// bisection in long double (the reference root of the closed-form tests).
#pragma once

#include <filesystem>
#include <fstream>
#include <functional>
#include <string>

namespace rocking::testing {

inline std::string write_temp(const std::string& folder, const std::string& name, const std::string& text) {
    const std::filesystem::path dir = std::filesystem::temp_directory_path() / folder;
    std::filesystem::create_directories(dir);
    const std::string path = (dir / name).string();
    std::ofstream(path) << text;
    return path;
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

}  // namespace rocking::testing
