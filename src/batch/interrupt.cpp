#include "batch/interrupt.hpp"

#include <pthread.h>
#include <signal.h>

#include <cerrno>
#include <ctime>

namespace rocking::batch {

namespace {

sigset_t interrupts() {
    sigset_t set;
    sigemptyset(&set);
    sigaddset(&set, SIGINT);
    sigaddset(&set, SIGTERM);
    return set;
}

// Those not ignored: a batch started with SIGINT ignored (in the background
// of a script, or by its caller) keeps ignoring it, where Linux would keep a
// blocked one pending for the watch to take.
sigset_t watched() {
    sigset_t set;
    sigemptyset(&set);
    for (int sig : {SIGINT, SIGTERM}) {
        struct sigaction current {};
        if (sigaction(sig, nullptr, &current) == 0 && !(current.sa_flags & SA_SIGINFO) && current.sa_handler == SIG_IGN)
            continue;
        sigaddset(&set, sig);
    }
    return set;
}

}  // namespace

void block_interrupts() {
    const sigset_t set = interrupts();
    pthread_sigmask(SIG_BLOCK, &set, nullptr);
}

InterruptWatch::InterruptWatch(std::function<void(int)> on_signal) {
    block_interrupts();
    const sigset_t set = watched();
    thread_ = std::thread([this, set, on_signal = std::move(on_signal)] {
        // Woken every 100 ms to see whether the batch is over: a watch that
        // waited without end could only be stopped by a signal of its own.
        const timespec tick{0, 100 * 1000 * 1000};
        while (!stop_.load()) {
            const int sig = sigtimedwait(&set, nullptr, &tick);
            if (sig < 0) continue;  // EAGAIN: the tick; EINTR
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
}

}  // namespace rocking::batch
