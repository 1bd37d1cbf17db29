#include "batch/interrupt.hpp"

#include <fcntl.h>
#include <poll.h>
#include <pthread.h>
#include <signal.h>
#include <unistd.h>

#include <mutex>

namespace rocking::batch {

namespace {

constexpr int kSignals[2] = {SIGINT, SIGTERM};

// What the handler records: the first signal, and a byte down a pipe to wake the watch.
std::atomic<int> g_caught{0};
int g_wake[2] = {-1, -1};
struct sigaction g_before[2];

static_assert(std::atomic<int>::is_always_lock_free, "a signal handler may only touch lock-free atomics");

extern "C" void record_signal(int sig) {
    int none = 0;
    g_caught.compare_exchange_strong(none, sig);
    const char byte = 1;
    if (g_wake[1] >= 0) (void)!::write(g_wake[1], &byte, 1);
}

}  // namespace

InterruptWatch::InterruptWatch(std::function<void(int)> on_signal) {
    static std::once_flag once;
    std::call_once(once, [] {
        if (::pipe2(g_wake, O_CLOEXEC | O_NONBLOCK) != 0) g_wake[0] = g_wake[1] = -1;
    });
    for (int k = 0; k < 2; ++k) {
        struct sigaction current {};
        if (sigaction(kSignals[k], nullptr, &current) == 0 && !(current.sa_flags & SA_SIGINFO) &&
            current.sa_handler == SIG_IGN)
            continue;
        struct sigaction mine {};
        mine.sa_handler = record_signal;
        sigemptyset(&mine.sa_mask);
        mine.sa_flags = SA_RESTART;  // a write or a wait it interrupts goes on
        if (sigaction(kSignals[k], &mine, &g_before[k]) == 0) watched_[k] = true;
    }
    thread_ = std::thread([this, on_signal = std::move(on_signal)] {
        while (!stop_.load()) {
            // Woken by the handler's byte, or every 100 ms to see whether the batch is over.
            pollfd wake{g_wake[0], POLLIN, 0};
            ::poll(&wake, g_wake[0] >= 0 ? 1 : 0, 100);
            char drain[16];
            while (g_wake[0] >= 0 && ::read(g_wake[0], drain, sizeof drain) > 0) {}
            const int sig = g_caught.load();
            if (sig == 0) continue;
            on_signal(sig);
            // The default action ends the process, from this thread.
            signal(sig, SIG_DFL);
            sigset_t one;
            sigemptyset(&one);
            sigaddset(&one, sig);
            pthread_sigmask(SIG_UNBLOCK, &one, nullptr);
            raise(sig);
        }
    });
}

InterruptWatch::~InterruptWatch() {
    stop_ = true;
    if (thread_.joinable()) thread_.join();
    for (int k = 0; k < 2; ++k)
        if (watched_[k]) sigaction(kSignals[k], &g_before[k], nullptr);
}

}  // namespace rocking::batch
