#include "EventMerge.hpp"

#include <cmath>
#include <sstream>

#include "unimap/Errors.hpp"

namespace unimap::api {
namespace {

const char* StreamName(Stream s) {
  switch (s) {
    case Stream::kImu:
      return "IMU";
    case Stream::kEncoder:
      return "encoder";
    case Stream::kOdometry:
      return "odometry";
    case Stream::kScan:
      return "scan";
  }
  return "?";
}

}  // namespace

void EventMerge::Push(Stream s, double time_s, io::DatasetEvent event) {
  const auto i = static_cast<std::size_t>(s);
  if (!std::isfinite(time_s)) {
    throw InputError(std::string(StreamName(s)) + " sample with a non-finite time: ignored");
  }
  if (last_time_s_[i] && time_s < *last_time_s_[i]) {
    std::ostringstream why;
    why.precision(17);
    why << StreamName(s) << " time " << time_s << " s is before the stream's previous " << *last_time_s_[i]
        << " s: ignored (each stream must be added in time order)";
    throw InputError(why.str());
  }
  last_time_s_[i] = time_s;
  queues_[i].emplace_back(time_s, std::move(event));
  ++size_;
}

std::optional<io::DatasetEvent> EventMerge::Pop(bool flush) {
  std::optional<std::size_t> first;
  for (std::size_t i = 0; i < kStreams; ++i) {
    if (queues_[i].empty()) {
      if (expected_[i] && !flush) return std::nullopt;  // it may still deliver something earlier
      continue;
    }
    if (!first || queues_[i].front().first < queues_[*first].front().first) first = i;
  }
  if (!first) return std::nullopt;
  io::DatasetEvent event = std::move(queues_[*first].front().second);
  queues_[*first].pop_front();
  --size_;
  return event;
}

}  // namespace unimap::api
