#pragma once
#include <array>
#include <cstddef>
#include <deque>
#include <optional>
#include <utility>

#include "io/DatasetReader.hpp"

namespace unimap::api {

// The streams of a mapper, in their tie-breaking order (as DatasetReader
// merges a dataset: IMU, encoder, odometry, scans).
enum class Stream { kImu = 0, kEncoder = 1, kOdometry = 2, kScan = 3 };
inline constexpr std::size_t kStreams = 4;

// Merges events arriving per stream (each in time order, the streams in any
// order relative to each other) into one time-ordered sequence: the k-way
// merge DatasetReader::NextEvent does, so the same events give the same
// order however their Push calls interleave. An event is released once
// every expected stream holds an event (so none can still arrive before
// it), or when flushing. Not thread-safe.
class EventMerge {
 public:
  // expected[s]: Pop waits for stream s.
  explicit EventMerge(const std::array<bool, kStreams>& expected) : expected_(expected) {}

  // Queues an event of stream s at time_s (scans: their end time). Throws
  // InputError, naming the stream, when time_s is not finite or is before
  // that stream's previous event.
  void Push(Stream s, double time_s, io::DatasetEvent event);
  // The earliest queued event (ties by stream order) when it is final, or
  // any queued one when flush; nullopt when none is.
  std::optional<io::DatasetEvent> Pop(bool flush);
  // Events queued.
  std::size_t size() const { return size_; }

 private:
  std::array<std::deque<std::pair<double, io::DatasetEvent>>, kStreams> queues_;
  std::array<bool, kStreams> expected_;
  std::array<std::optional<double>, kStreams> last_time_s_;
  std::size_t size_ = 0;
};

}  // namespace unimap::api
