#pragma once
#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <vector>

namespace unimap::io {

// Restores time order of a stream whose items arrive slightly out of order
// (real logs: a late laser message, bag order vs header stamps) with bounded
// memory: an item is held until an item more than window_s newer has arrived,
// then released earliest first (ties in arrival order). An item older than
// one already released cannot be placed any more and is refused.
template <typename T>
class TimeReorderBuffer {
 public:
  // window_s >= 0: how far back in time an item may arrive late.
  explicit TimeReorderBuffer(double window_s) : window_s_(window_s) {}

  // Adds an item; false (item dropped) when time_s is before the last released time.
  bool Push(double time_s, T item) {
    if (has_released_ && time_s < released_time_s_) return false;
    newest_s_ = has_pushed_ ? std::max(newest_s_, time_s) : time_s;
    has_pushed_ = true;
    heap_.push_back(Entry{time_s, sequence_++, std::make_unique<T>(std::move(item))});
    std::push_heap(heap_.begin(), heap_.end(), Later);
    return true;
  }

  // The earliest held item if it is more than window_s older than the newest
  // pushed one, or (flush) any held item; nullptr otherwise. (Items are held
  // on the heap: moving a std::variant through the heap algorithms trips
  // GCC 12's -Wuninitialized false positive.)
  std::unique_ptr<T> Pop(bool flush = false) {
    if (heap_.empty()) return nullptr;
    if (!flush && !(heap_.front().time_s < newest_s_ - window_s_)) return nullptr;
    std::pop_heap(heap_.begin(), heap_.end(), Later);
    Entry entry = std::move(heap_.back());
    heap_.pop_back();
    released_time_s_ = entry.time_s;
    has_released_ = true;
    return std::move(entry.item);
  }

  // Items held.
  std::size_t size() const { return heap_.size(); }

 private:
  struct Entry {
    double time_s;           // the item's time
    std::uint64_t sequence;  // arrival order, breaks ties
    std::unique_ptr<T> item;
  };
  // Heap order: the root is the earliest (then first arrived) entry.
  static bool Later(const Entry& a, const Entry& b) {
    return a.time_s > b.time_s || (a.time_s == b.time_s && a.sequence > b.sequence);
  }

  double window_s_;
  std::vector<Entry> heap_;       // held items, a heap under Later
  std::uint64_t sequence_ = 0;    // next arrival number
  double newest_s_ = 0.0;         // latest time pushed
  bool has_pushed_ = false;       // newest_s_ is set
  double released_time_s_ = 0.0;  // time of the last released item
  bool has_released_ = false;     // released_time_s_ is set
};

}  // namespace unimap::io
