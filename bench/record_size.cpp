// How the eleven half-periods (what `rocking record info` computes) grow with the
// record's length (a benchmark, not a test): synthetic records of N samples, the
// time of half_periods() and the peak resident memory of the process that ran it,
// and the growth exponent of the time in N.  Issue 31's goal: 10^6 samples in
// under 10 s and under 1 GB (10^7 had taken 18 minutes and 6.5 GB).
//
//   bench_record_size [--out DIR] [--sizes N,N,...]
//
// Each N runs in its own child process, so that its peak RSS (getrusage's
// ru_maxrss, the record itself included) is its own.  The time is the fastest of
// several runs (this machine is shared).  Writes DIR/record_size.csv and
// DIR/record_size_summary.txt.
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "records/measures.hpp"

using namespace rocking;

namespace {

constexpr double kDt = 0.005;  // the ESM records' step: 129 CWT scales, 0.1 to 25 Hz

// Noise through a resonator at 2 Hz (damping 5 %) plus one Gaussian-windowed pulse
// per 20,000 samples: a broad spectrum with its energy near 2 Hz, as a record's.
// xorshift64, so that every run sees the same record.
std::vector<double> synthetic_record(std::size_t n) {
    std::uint64_t seed = 88172645463325252ull;
    auto uniform = [&seed] {
        seed ^= seed << 13, seed ^= seed >> 7, seed ^= seed << 17;
        return static_cast<double>(seed >> 11) / 9007199254740992.0 - 0.5;
    };
    const double w = 2 * M_PI * 2.0 * kDt, r = std::exp(-0.05 * w);
    std::vector<double> a(n);
    double y1 = 0, y2 = 0;
    for (std::size_t k = 0; k < n; ++k) {
        const double y = 2 * r * std::cos(w) * y1 - r * r * y2 + uniform();
        y2 = y1, y1 = y, a[k] = 0.05 * y;
    }
    for (std::size_t p = 0; p < std::max<std::size_t>(1, n / 20000); ++p) {
        const double t0 = (uniform() + 0.5) * n * kDt, fp = 0.5 + 2.5 * (uniform() + 0.5);
        const std::size_t from = static_cast<std::size_t>(std::max(0.0, (t0 - 6 / fp) / kDt));
        for (std::size_t k = from; k < n && k * kDt < t0 + 6 / fp; ++k) {
            const double u = k * kDt - t0;
            a[k] += 1.5 * std::exp(-fp * fp * u * u) * std::cos(2 * M_PI * fp * u);
        }
    }
    return a;
}

struct Point {
    std::size_t n = 0;
    double seconds = NAN;  // fastest half_periods()
    double rss_mb = NAN;   // the child's peak RSS
    int runs = 0;
};

// In the child: the record, then half_periods() until 3 runs and 2 s (at most 20 runs).
void measure_in_child(std::size_t n, int fd) {
    const std::vector<double> a = synthetic_record(n);
    double best = INFINITY, spent = 0;
    int runs = 0;
    double to5 = 0;
    while (runs < 3 || (spent < 2.0 && runs < 20)) {
        const auto t0 = std::chrono::steady_clock::now();
        const records::HalfPeriods h = records::half_periods(a, kDt);
        const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
        best = std::min(best, s), spent += s, ++runs, to5 = h.to[4];
    }
    rusage u{};
    getrusage(RUSAGE_SELF, &u);
    char line[200];
    const int len = std::snprintf(line, sizeof line, "%.6g %.6g %d %.6g\n", best, u.ru_maxrss / 1024.0, runs, to5);
    if (write(fd, line, len) != len) _exit(1);
    _exit(0);
}

Point measure(std::size_t n) {
    int fds[2];
    if (pipe(fds) != 0) throw std::runtime_error("pipe failed");
    const pid_t pid = fork();
    if (pid < 0) throw std::runtime_error("fork failed");
    if (pid == 0) {
        close(fds[0]);
        measure_in_child(n, fds[1]);
    }
    close(fds[1]);
    std::string text;
    char buf[256];
    for (ssize_t got; (got = read(fds[0], buf, sizeof buf)) > 0;) text.append(buf, got);
    close(fds[0]);
    int status = 0;
    waitpid(pid, &status, 0);
    Point p;
    p.n = n;
    double to5 = 0;
    std::istringstream in(text);
    if (!(in >> p.seconds >> p.rss_mb >> p.runs >> to5) || !WIFEXITED(status) || WEXITSTATUS(status) != 0)
        throw std::runtime_error("the child measuring N = " + std::to_string(n) + " failed");
    return p;
}

// The least-squares slope of log(seconds) on log(N): time ~ N^slope.
double growth_exponent(const std::vector<Point>& points) {
    double sx = 0, sy = 0, sxx = 0, sxy = 0;
    const double m = static_cast<double>(points.size());
    for (const Point& p : points) {
        const double x = std::log(static_cast<double>(p.n)), y = std::log(p.seconds);
        sx += x, sy += y, sxx += x * x, sxy += x * y;
    }
    return (m * sxy - sx * sy) / (m * sxx - sx * sx);
}

}  // namespace

int main(int argc, char** argv) {
    std::string out = "out/bench";
    std::vector<std::size_t> sizes = {10000, 100000, 1000000};
    for (int i = 1; i < argc; ++i) {
        const std::string a = argv[i];
        if (a == "--out" && i + 1 < argc) out = argv[++i];
        else if (a == "--sizes" && i + 1 < argc) {
            sizes.clear();
            std::istringstream list(argv[++i]);
            for (std::string item; std::getline(list, item, ',');) sizes.push_back(std::stoull(item));
        } else {
            std::fprintf(stderr, "usage: bench_record_size [--out DIR] [--sizes N,N,...]\n");
            return 2;
        }
    }
    std::filesystem::create_directories(out);
    std::vector<Point> points;
    for (std::size_t n : sizes) {
        points.push_back(measure(n));
        const Point& p = points.back();
        std::printf("N = %9zu: %8.3f s (fastest of %d), peak RSS %7.1f MB\n", p.n, p.seconds, p.runs, p.rss_mb);
        std::fflush(stdout);
    }
    std::ofstream csv(out + "/record_size.csv");
    csv << "# bench: half_periods() of synthetic records (resonator noise at 2 Hz and pulses, dt = 0.005 s)\n"
        << "# seconds: the fastest run; peak_rss_mb: the child process's getrusage ru_maxrss, the record included;\n"
        << "# exponent_from_previous: log(seconds ratio) / log(N ratio) against the row above\n"
        << "samples,seconds,peak_rss_mb,runs,exponent_from_previous\n";
    for (std::size_t i = 0; i < points.size(); ++i) {
        const Point& p = points[i];
        csv << p.n << "," << p.seconds << "," << p.rss_mb << "," << p.runs << ",";
        if (i > 0)
            csv << std::log(p.seconds / points[i - 1].seconds) /
                       std::log(static_cast<double>(p.n) / static_cast<double>(points[i - 1].n));
        csv << "\n";
    }
    std::ofstream summary(out + "/record_size_summary.txt");
    char line[400];
    for (const Point& p : points) {
        std::snprintf(line, sizeof line, "N = %zu: %.3f s, peak RSS %.1f MB\n", p.n, p.seconds, p.rss_mb);
        summary << line;
    }
    if (points.size() >= 2) {
        std::snprintf(line, sizeof line, "time ~ N^%.3f (least squares over the %zu sizes)\n", growth_exponent(points),
                      points.size());
        summary << line;
        std::printf("%s", line);
    }
    for (const Point& p : points)
        if (p.n == 1000000) {
            std::snprintf(line, sizeof line, "goal at 10^6 samples (under 10 s and 1 GB): %s\n",
                          p.seconds < 10 && p.rss_mb < 1024 ? "met" : "MISSED");
            summary << line;
            std::printf("%s", line);
        }
    std::printf("written: %s/record_size.csv, %s/record_size_summary.txt\n", out.c_str(), out.c_str());
    return 0;
}
