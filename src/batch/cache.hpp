// A cache shared by a batch's threads: each value (a record, for the jobs
// over it) is loaded once, by the first job that needs it, while the others
// that ask meanwhile wait for it; a load that throws is remembered and its
// exception rethrown to every job that asks for that key.  It knows keys and
// values, not what they hold.
//
// Memory is bounded by a budget in bytes: past it, the values least recently
// asked for are dropped (a job holding one keeps it alive) and loaded again
// when asked for.  Loading must give the same value each time, so that what
// the cache keeps never changes a result, only how often a file is read.
#pragma once

#include <cstddef>
#include <functional>
#include <future>
#include <list>
#include <map>
#include <memory>
#include <mutex>
#include <string>

namespace rocking::batch {

template <class Value>
class SharedCache {
public:
    using Loader = std::function<Value()>;
    using SizeOf = std::function<std::size_t(const Value&)>;

    SharedCache(std::size_t budget_bytes, SizeOf size_of) : budget_(budget_bytes), size_of_(std::move(size_of)) {}

    std::shared_ptr<const Value> get(const std::string& key, const Loader& load) {
        std::shared_future<std::shared_ptr<const Value>> future;
        std::promise<std::shared_ptr<const Value>> promise;
        bool mine = false;
        {
            std::lock_guard<std::mutex> lock(mutex_);
            auto it = entries_.find(key);
            if (it == entries_.end()) {
                mine = true;
                ++loads_;
                future = promise.get_future().share();
                lru_.push_front(key);
                entries_.emplace(key, Entry{future, 0, lru_.begin(), false});
            } else {
                future = it->second.value;
                lru_.splice(lru_.begin(), lru_, it->second.place);  // most recently asked for
            }
        }
        if (mine) {
            // The load runs outside the lock: other keys load in parallel.
            std::size_t size = 0;
            try {
                auto value = std::make_shared<const Value>(load());
                size = size_of_(*value);
                promise.set_value(std::move(value));
            } catch (...) {
                size = 256;  // a failure is remembered too, and counted, so that many of them stay bounded
                promise.set_exception(std::current_exception());
            }
            size += key.size();
            std::lock_guard<std::mutex> lock(mutex_);
            auto it = entries_.find(key);
            it->second.size = size;
            it->second.ready = true;
            held_ += size;
            evict(key);
        }
        return future.get();  // rethrows a failed load's exception
    }

    std::size_t loads() const {
        std::lock_guard<std::mutex> lock(mutex_);
        return loads_;
    }
    std::size_t held_bytes() const {
        std::lock_guard<std::mutex> lock(mutex_);
        return held_;
    }

private:
    struct Entry {
        std::shared_future<std::shared_ptr<const Value>> value;
        std::size_t size;
        typename std::list<std::string>::iterator place;
        bool ready;
    };

    // Drops the least recently asked-for loaded values until within budget,
    // never the one just loaded.
    void evict(const std::string& keep) {
        for (auto it = lru_.end(); held_ > budget_ && it != lru_.begin();) {
            --it;
            auto e = entries_.find(*it);
            if (*it == keep || !e->second.ready) continue;
            held_ -= e->second.size;
            entries_.erase(e);
            it = lru_.erase(it);
        }
    }

    mutable std::mutex mutex_;
    std::size_t budget_, held_ = 0, loads_ = 0;
    SizeOf size_of_;
    std::map<std::string, Entry> entries_;
    std::list<std::string> lru_;  // most recently asked for first
};

}  // namespace rocking::batch
