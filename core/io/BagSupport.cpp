#include "io/BagSupport.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "unimap/Errors.hpp"

namespace unimap::io {

std::string BagTopicList(const std::vector<RosbagTopicInfo>& topics) {
  std::ostringstream out;
  for (const RosbagTopicInfo& t : topics) out << "\n  " << t.topic << " (" << t.datatype << ", " << t.messages << ")";
  return out.str();
}

std::string ResolveBagTopic(const std::string& bag, const std::vector<RosbagTopicInfo>& topics,
                            const std::string& request, const std::vector<std::string>& types, const char* option,
                            bool allow_auto, const std::string& excluded) {
  auto accepted = [&](const std::string& type) { return std::find(types.begin(), types.end(), type) != types.end(); };
  auto fail = [&](const std::string& reason) {
    throw InputError(bag + ": " + reason + "; its topics:" + BagTopicList(topics));
  };
  if (request == "none" || (request.empty() && !allow_auto)) return "";
  if (!request.empty()) {
    const auto info = std::find_if(topics.begin(), topics.end(), [&](const auto& t) { return t.topic == request; });
    if (info == topics.end()) fail("no topic " + request + " in the bag");
    if (!accepted(info->datatype)) fail("topic " + request + " is " + info->datatype + ", not usable for " + option);
    return request;
  }
  std::vector<std::string> candidates;
  for (const RosbagTopicInfo& t : topics) {
    if (accepted(t.datatype) && t.topic != excluded) candidates.push_back(t.topic);
  }
  if (candidates.size() > 1) fail("several " + types.front() + " topics; choose one with " + option + " (or 'none')");
  return candidates.empty() ? "" : candidates.front();
}

bool PoseToIsometry(const Eigen::Vector3d& position, const Eigen::Quaterniond& orientation, Eigen::Isometry3d* T) {
  const double norm = orientation.norm();
  if (!std::isfinite(norm) || norm < 1e-6) return false;
  *T = Eigen::Isometry3d::Identity();
  T->linear() = orientation.normalized().toRotationMatrix();
  T->translation() = position;
  return T->matrix().allFinite();
}

std::optional<double> JointAngle(const std::vector<std::string>& names, const std::vector<double>& positions,
                                 const std::string& joint, std::string* reason) {
  std::size_t index = 0;
  if (!joint.empty()) {
    const auto found = std::find(names.begin(), names.end(), joint);
    if (found == names.end()) {
      *reason = "JointState without joint " + joint;
      return std::nullopt;
    }
    index = static_cast<std::size_t>(found - names.begin());
  }
  if (index >= positions.size() || !std::isfinite(positions[index])) {
    *reason = "JointState without a finite position";
    return std::nullopt;
  }
  return positions[index];
}

std::string BagMessageError(const std::string& bag, const std::string& topic, double time_s,
                            const std::string& reason) {
  std::ostringstream where;
  where.precision(17);
  where << bag << ": " << topic << " at t=" << time_s << ": " << reason;
  return where.str();
}

}  // namespace unimap::io
