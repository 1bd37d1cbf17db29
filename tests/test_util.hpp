// Helpers shared by the tests: scratch files and the message of an exception.
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

}  // namespace rocking::testing
