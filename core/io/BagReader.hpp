#pragma once
#include <optional>
#include <string>
#include <vector>

#include "io/BagTypes.hpp"

namespace unimap::io {

// What a bag reader knows of its bag: the topics, the choice, the counts.
struct BagState {
  std::vector<RosbagTopicInfo> topics;  // every topic in the bag
  RosbagTopics selected;                // resolved choice ("" = not read)
  RosbagReaderStats stats;              // delivered and skipped so far
};

// A bag (ROS 1: RosbagReader, ROS 2: Ros2BagReader) read one message at a
// time into unimap's types.
class BagReader {
 public:
  virtual ~BagReader() = default;

  // Every topic in the bag.
  const std::vector<RosbagTopicInfo>& topics() const { return state().topics; }
  // The topics chosen (empty string = that stream is not read).
  const RosbagTopics& selected() const { return state().selected; }
  // What has been delivered and skipped so far.
  const RosbagReaderStats& stats() const { return state().stats; }
  // The message type of a topic of the bag, "" when it has none of that name.
  std::string DatatypeOf(const std::string& topic) const {
    for (const RosbagTopicInfo& t : topics()) {
      if (t.topic == topic) return t.datatype;
    }
    return "";
  }

  // The next message of a selected topic; std::nullopt at the end. A message
  // that cannot be converted is a counted skip (stats()); a damaged bag or a
  // malformed message throws InputError naming the file, topic and time.
  virtual std::optional<RosbagMessage> Next() = 0;

 protected:
  virtual const BagState& state() const = 0;
};

}  // namespace unimap::io
