#pragma once
#include <cstddef>
#include <map>
#include <string>
#include <vector>

#include "io/BagTypes.hpp"

namespace unimap::io {

struct BagClockOptions {
  bool align = true;                    // streams on different clocks are moved onto the receive clock;
                                        // false: that is an InputError
  std::size_t messages_per_topic = 20;  // offsets are the median over a topic's first this many messages
  double window_s = 10.0;               // ... or over those received in the first this many seconds
  double tolerance_s = 1.0;             // topics whose offsets differ by at most this share a clock
};

// Puts the streams of a bag on one clock. A topic's offset is the median
// of (receive time - header stamp) over its first messages. When the offsets
// of the topics differ by more than the tolerance (a sensor stamping with its
// own uptime, another topic without a header stamped on receipt), every
// topic's times are moved by its offset onto the bag's receive clock; the
// note says which topic moved by how much. Topics that agree are not moved.
// Messages come out in the order they went in.
class BagClockAligner {
 public:
  // notes receives the decision, once.
  BagClockAligner(BagClockOptions options, std::vector<std::string>* notes);

  // Takes a message; appends to *ready those whose times are now settled.
  // Throws InputError (naming the topics and their offsets) when clocks
  // disagree and options.align is false.
  void Push(RosbagMessage message, std::vector<RosbagMessage>* ready);
  // Settles and appends everything still held.
  void Finish(std::vector<RosbagMessage>* ready);

 private:
  void Decide();
  // Decide(), then releases everything held, in order.
  void DecideAndRelease(std::vector<RosbagMessage>* ready);
  void Release(RosbagMessage message, std::vector<RosbagMessage>* ready);

  BagClockOptions options_;
  std::vector<std::string>* notes_;
  bool decided_ = false;
  bool shift_ = false;                                  // move topics onto the receive clock
  std::vector<RosbagMessage> held_;                     // before the decision
  std::map<std::string, std::vector<double>> samples_;  // topic -> receive - stamp, first messages
  std::map<std::string, double> offsets_;               // topic -> offset applied (s)
};

// Adds offset_s to every time a message carries (its stamp and its data's).
void ShiftMessageTimes(RosbagMessage* message, double offset_s);

}  // namespace unimap::io
