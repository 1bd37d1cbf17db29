// A batch's progress on stderr: jobs done of the total, failed, the rate and
// the time left, on one line rewritten in place at most 5 times a second.
// Only where stderr is a terminal (a log file would fill with carriage
// returns) and not asked to be quiet.
#pragma once

#include <chrono>
#include <cstddef>
#include <string>

namespace rocking::batch {

class Progress {
public:
    // `skipped`: jobs written before (a resume); the rate counts this run's.
    Progress(std::size_t total, std::size_t skipped, bool enabled);
    void update(std::size_t done, std::size_t failed);
    // The last line, kept on the terminal.
    void finish(std::size_t done, std::size_t failed);
    bool enabled() const { return enabled_; }
    // The line itself (tests): "batch: 120/1000 jobs, 3 failed, 45.2 jobs/s, 19 s left".
    static std::string line(std::size_t done, std::size_t failed, std::size_t total, std::size_t skipped, double seconds);

private:
    void draw(std::size_t done, std::size_t failed);
    std::size_t total_, skipped_;
    bool enabled_;
    bool drawn_ = false;
    std::chrono::steady_clock::time_point start_, last_;
};

// Whether stderr is a terminal.
bool stderr_is_terminal();

}  // namespace rocking::batch
