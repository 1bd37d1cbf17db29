#include "batch/progress.hpp"

#include <unistd.h>

#include <cmath>
#include <cstdio>

namespace rocking::batch {

bool stderr_is_terminal() { return ::isatty(STDERR_FILENO) == 1; }

Progress::Progress(std::size_t total, std::size_t skipped, bool enabled)
    : total_(total), skipped_(skipped), enabled_(enabled), start_(std::chrono::steady_clock::now()), last_(start_) {}

namespace {

std::string duration(double s) {
    char text[40];
    if (!std::isfinite(s)) return "?";
    if (s < 60) std::snprintf(text, sizeof text, "%.0f s", s);
    else if (s < 3600) std::snprintf(text, sizeof text, "%.0f min %02.0f s", std::floor(s / 60), std::fmod(s, 60.0));
    else std::snprintf(text, sizeof text, "%.0f h %02.0f min", std::floor(s / 3600), std::floor(std::fmod(s, 3600.0) / 60));
    return text;
}

}  // namespace

std::string Progress::line(std::size_t done, std::size_t failed, std::size_t total, std::size_t skipped, double seconds) {
    const double ran = static_cast<double>(done - skipped);
    const double rate = seconds > 0 ? ran / seconds : 0;
    char text[200];
    std::snprintf(text, sizeof text, "batch: %zu/%zu jobs, %zu failed, %.3g jobs/s, %s left", done, total, failed, rate,
                  rate > 0 ? duration(static_cast<double>(total - done) / rate).c_str() : "?");
    return text;
}

void Progress::draw(std::size_t done, std::size_t failed) {
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
    std::fprintf(stderr, "\r%s\033[K", line(done, failed, total_, skipped_, seconds).c_str());
    std::fflush(stderr);
    drawn_ = true;
}

void Progress::update(std::size_t done, std::size_t failed) {
    if (!enabled_) return;
    const auto now = std::chrono::steady_clock::now();
    if (drawn_ && now - last_ < std::chrono::milliseconds(200)) return;
    last_ = now;
    draw(done, failed);
}

void Progress::finish(std::size_t done, std::size_t failed) {
    if (!enabled_) return;
    draw(done, failed);
    std::fputc('\n', stderr);
}

}  // namespace rocking::batch
