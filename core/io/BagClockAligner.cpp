#include "io/BagClockAligner.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <type_traits>
#include <utility>
#include <variant>

#include "unimap/Errors.hpp"

namespace unimap::io {
namespace {

double Median(std::vector<double> values) {
  const std::size_t mid = values.size() / 2;
  std::nth_element(values.begin(), values.begin() + static_cast<std::ptrdiff_t>(mid), values.end());
  return values[mid];
}

std::string Seconds(double s) {
  char text[64];
  std::snprintf(text, sizeof(text), "%.3f s", s);
  return text;
}

}  // namespace

void ShiftMessageTimes(RosbagMessage* message, double offset_s) {
  message->stamp_s += offset_s;
  std::visit(
      [offset_s](auto& data) {
        using T = std::decay_t<decltype(data)>;
        if constexpr (std::is_same_v<T, RawScan>) {
          data.start_time_s += offset_s;
          data.end_time_s += offset_s;
          for (Point& p : data.points) p.time_s += offset_s;
        } else if constexpr (std::is_same_v<T, LineScan>) {
          data.start_time_s += offset_s;
        } else {
          data.time_s += offset_s;
        }
      },
      message->data);
}

BagClockAligner::BagClockAligner(BagClockOptions options, std::vector<std::string>* notes)
    : options_(options), notes_(notes) {}

void BagClockAligner::Push(RosbagMessage message, std::vector<RosbagMessage>* ready) {
  if (decided_) {
    Release(std::move(message), ready);
    return;
  }
  std::vector<double>& samples = samples_[message.topic];
  if (samples.size() < options_.messages_per_topic) samples.push_back(message.receive_s - message.stamp_s);
  const double first_receive_s = held_.empty() ? message.receive_s : held_.front().receive_s;
  held_.push_back(std::move(message));
  const bool enough = std::all_of(samples_.begin(), samples_.end(), [&](const auto& topic) {
    return topic.second.size() >= options_.messages_per_topic;
  });
  if (enough || held_.back().receive_s - first_receive_s > options_.window_s) DecideAndRelease(ready);
}

void BagClockAligner::Finish(std::vector<RosbagMessage>* ready) {
  if (!decided_) DecideAndRelease(ready);
}

void BagClockAligner::DecideAndRelease(std::vector<RosbagMessage>* ready) {
  Decide();
  std::vector<RosbagMessage> held;
  held.swap(held_);
  for (RosbagMessage& m : held) Release(std::move(m), ready);
}

void BagClockAligner::Decide() {
  decided_ = true;
  if (samples_.empty()) return;
  double low = 0.0;
  double high = 0.0;
  std::string low_topic;
  std::string high_topic;
  for (const auto& [topic, samples] : samples_) {
    const double offset = Median(samples);
    offsets_[topic] = offset;
    if (low_topic.empty() || offset < low) low = offset, low_topic = topic;
    if (high_topic.empty() || offset > high) high = offset, high_topic = topic;
  }
  if (high - low <= options_.tolerance_s) {
    if (samples_.size() > 1) {
      notes_->push_back("clocks: the topics' stamps agree (receive time - stamp within " + Seconds(high - low) +
                        " of each other): times kept as stamped");
    }
    return;
  }
  const std::string disagreement = high_topic + " is stamped " + Seconds(high) + " behind its receive times, " +
                                   low_topic + " " + Seconds(low) + " (medians over the first " +
                                   std::to_string(options_.messages_per_topic) + " messages)";
  if (!options_.align) {
    throw InputError("the topics are on different clocks: " + disagreement +
                     "; convert without --no-clock-alignment to move every topic onto the bag's receive clock");
  }
  shift_ = true;
  notes_->push_back("clocks: the topics' stamps disagree (" + disagreement +
                    "): every topic moved onto the bag's receive clock");
  for (const auto& [topic, offset] : offsets_) {
    if (std::abs(offset) > options_.tolerance_s) {
      notes_->push_back("clocks: " + topic + " moved by +" + Seconds(offset));
    }
  }
}

void BagClockAligner::Release(RosbagMessage message, std::vector<RosbagMessage>* ready) {
  if (shift_) {
    auto it = offsets_.find(message.topic);
    if (it == offsets_.end()) {  // a topic first seen after the decision: its first message's offset
      it = offsets_.emplace(message.topic, message.receive_s - message.stamp_s).first;
      notes_->push_back("clocks: " + message.topic + " (first seen later) moved onto the bag's receive clock by " +
                        Seconds(it->second));
    }
    ShiftMessageTimes(&message, it->second);
  }
  ready->push_back(std::move(message));
}

}  // namespace unimap::io
