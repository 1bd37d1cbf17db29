// Ctrl-C (SIGINT) and SIGTERM during a batch: the results written so far
// are made durable and the process then ends by the signal, as it would
// have, so that --resume can complete them.
//
// The signals are caught by a handler that only records them (what a
// handler may do), whichever thread takes them: MPI starts threads of its
// own with every signal unblocked, so blocking them in ours would not keep
// a signal from ending the process there, unflushed.  A thread of the
// watch's own then runs the batch's response in ordinary code (it may lock
// and write), and ends the process by the signal.  A signal ignored when
// the watch starts (a script's background job ignores SIGINT) stays ignored.
#pragma once

#include <atomic>
#include <functional>
#include <thread>

namespace rocking::batch {

class InterruptWatch {
public:
    // on_signal(sig) runs once, in the watch's thread; then the process ends
    // by sig (its default action).
    explicit InterruptWatch(std::function<void(int)> on_signal);
    ~InterruptWatch();  // stops watching: the signals' former actions are back
    InterruptWatch(const InterruptWatch&) = delete;
    InterruptWatch& operator=(const InterruptWatch&) = delete;

private:
    std::atomic<bool> stop_{false};
    std::thread thread_;
    bool watched_[2] = {false, false};
};

}  // namespace rocking::batch
