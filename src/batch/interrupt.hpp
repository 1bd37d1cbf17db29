// Ctrl-C (SIGINT) and SIGTERM during a batch: the results written so far
// are made durable and the process then ends by the signal, as it would
// have, so that --resume can complete them.
//
// block_interrupts() blocks both signals in the calling thread before any
// other is started (threads inherit the mask: the pool's, MPI's), so that
// none of them is stopped in the middle of a write; an InterruptWatch then
// waits for them in a thread of its own and runs its handler there, in
// ordinary code (it may lock and write, as a signal handler may not).  A
// signal that came before the watch started is waiting for it.
#pragma once

#include <atomic>
#include <functional>
#include <thread>

namespace rocking::batch {

void block_interrupts();

class InterruptWatch {
public:
    // on_signal(sig) runs once, in the watch's thread; then the process ends
    // by sig (its default action).  A second signal during on_signal waits.
    explicit InterruptWatch(std::function<void(int)> on_signal);
    ~InterruptWatch();  // stops watching (a signal after it stays blocked, pending)
    InterruptWatch(const InterruptWatch&) = delete;
    InterruptWatch& operator=(const InterruptWatch&) = delete;

private:
    std::atomic<bool> stop_{false};
    std::thread thread_;
};

}  // namespace rocking::batch
