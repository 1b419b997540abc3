#include "io/RosbagReader.hpp"

#include <cmath>
#include <cstring>
#include <deque>
#include <optional>

#include "io/BagSupport.hpp"
#include "io/Ros1MessageDefinition.hpp"
#include "io/Ros2BagMetadata.hpp"
#include "io/RosbagRecords.hpp"
#include "unimap/Errors.hpp"

#if UNIMAP_WITH_ROSBAG
#include <geometry_msgs/PoseStamped.h>
#include <nav_msgs/Odometry.h>
#include <ros/serialization.h>
#include <rosbag/bag.h>
#include <rosbag/exceptions.h>
#include <rosbag/view.h>
#include <sensor_msgs/Imu.h>
#include <sensor_msgs/JointState.h>
#include <sensor_msgs/LaserScan.h>
#include <sensor_msgs/PointCloud2.h>
#endif

namespace unimap::io {
namespace {

// A ROS 2 bag given to this reader: InputError saying which format reads it.
void RejectRos2Bag(const std::filesystem::path& bag) {
  if (IsRos2Bag(bag)) {
    throw InputError(bag.string() +
                     ": a ROS 2 bag (rosbag2 metadata.yaml or .db3 file): convert it with --format ros2");
  }
}

}  // namespace

#if UNIMAP_WITH_ROSBAG
namespace {

// What a selected topic is read as (kLaserWithAngle: one message gives a
// line and the motor angle).
enum class Stream { kCloud, kLaser, kImu, kJoint, kOdometry, kGroundTruth, kAngle, kLaserWithAngle };

constexpr const char* kPointCloud2 = "sensor_msgs/PointCloud2";
constexpr const char* kLaserScan = "sensor_msgs/LaserScan";
constexpr const char* kImu = "sensor_msgs/Imu";
constexpr const char* kJointState = "sensor_msgs/JointState";
constexpr const char* kOdometry = "nav_msgs/Odometry";
constexpr const char* kPoseStamped = "geometry_msgs/PoseStamped";
constexpr const char* kFloat32 = "std_msgs/Float32";
constexpr const char* kFloat64 = "std_msgs/Float64";
constexpr const char* kInt32 = "std_msgs/Int32";

// The definition of a topic's type, or nullptr when it cannot be parsed.
std::unique_ptr<Ros1MessageDefinition> ParseDefinition(const RosbagTopicInfo& t) {
  try {
    return std::make_unique<Ros1MessageDefinition>(t.datatype, t.definition);
  } catch (const InputError&) {
    return nullptr;
  }
}

// The path of the one LaserScan field a custom type holds, "" if none or several.
std::string LaserField(const Ros1MessageDefinition& d) {
  const std::vector<std::string> paths = d.FieldsOfType(kLaserScan);
  return paths.size() == 1 ? paths.front() : "";
}

// A number type the angle may have.
bool IsNumber(const std::string& type) {
  return type == "float64" || type == "float32" || type == "int8" || type == "uint8" || type == "int16" ||
         type == "uint16" || type == "int32" || type == "uint32" || type == "int64" || type == "uint64";
}

// Header stamp in seconds, or the bag's receive time when the stamp is zero.
double StampOr(const ros::Time& stamp, const rosbag::MessageInstance& m) {
  return stamp.isZero() ? m.getTime().toSec() : stamp.toSec();
}

// Pose from a ROS position and orientation; false for a quaternion that cannot be normalized.
bool ToIsometry(const geometry_msgs::Pose& pose, Eigen::Isometry3d* T) {
  return PoseToIsometry(
      Eigen::Vector3d(pose.position.x, pose.position.y, pose.position.z),
      Eigen::Quaterniond(pose.orientation.w, pose.orientation.x, pose.orientation.y, pose.orientation.z), T);
}

}  // namespace

class RosbagReader::Impl : public BagState {
 public:
  std::string label;  // bag path, for messages
  RosbagReaderOptions options;
  rosbag::Bag bag;
  std::map<std::string, Stream> stream_of;  // selected topic -> stream
  std::unique_ptr<rosbag::View> view;       // messages of the selected topics
  rosbag::View::iterator it;                // next message
  // Custom messages read by their definition: topic -> definition, and the
  // paths of the LaserScan and of the angle within them.
  std::map<std::string, std::unique_ptr<Ros1MessageDefinition>> definitions;
  std::string laser_path;             // "" : the laser topic is a sensor_msgs/LaserScan
  std::string angle_path = "data";    // the angle topic's number field
  std::deque<RosbagMessage> pending;  // second outputs of a message (the angle beside its line)
  std::vector<std::uint8_t> buffer;   // one serialized message

  [[noreturn]] void Fail(const std::string& reason) const { throw InputError(label + ": " + reason); }

  const RosbagTopicInfo* Find(const std::string& topic) const {
    for (const RosbagTopicInfo& t : topics) {
      if (t.topic == topic) return &t;
    }
    return nullptr;
  }

  // Resolves one stream's request (see RosbagTopics) to a topic or "".
  std::string Resolve(const std::string& request, const std::vector<std::string>& types, const char* option,
                      bool allow_auto) const {
    return ResolveBagTopic(label, topics, request, types, option, allow_auto, selected.groundtruth);
  }

  void ListTopics() {
    rosbag::View all(bag);
    for (const rosbag::ConnectionInfo* c : all.getConnections()) {
      if (Find(c->topic) != nullptr) continue;
      RosbagTopicInfo info;
      info.topic = c->topic;
      info.datatype = c->datatype;
      info.messages = rosbag::View(bag, rosbag::TopicQuery(c->topic)).size();
      info.definition = c->msg_def;
      topics.push_back(info);
    }
  }

  void Select() {
    const RosbagTopics& request = options.topics;
    selected.groundtruth = Resolve(request.groundtruth, {kOdometry, kPoseStamped}, "--groundtruth-topic", false);
    selected.cloud = Resolve(request.cloud, {kPointCloud2}, "--cloud-topic", true);
    // Custom types read by definition: those holding one LaserScan can be
    // the laser topic; with --angle-field, those with that number field the
    // angle topic.
    std::vector<std::string> laser_types = {kLaserScan};
    std::vector<std::string> angle_types = {kFloat32, kFloat64, kInt32};
    if (!options.angle_field.empty()) angle_types.clear();
    std::map<std::string, std::unique_ptr<Ros1MessageDefinition>> parsed;  // topic -> its definition, if readable
    for (const RosbagTopicInfo& t : topics) {
      std::unique_ptr<Ros1MessageDefinition> d = ParseDefinition(t);
      if (!d) continue;
      if (t.datatype != kLaserScan && !LaserField(*d).empty()) laser_types.push_back(t.datatype);
      if (t.datatype != kLaserScan && !options.angle_field.empty() && IsNumber(d->TypeOf(options.angle_field))) {
        angle_types.push_back(t.datatype);
      }
      parsed.emplace(t.topic, std::move(d));
    }
    selected.laser = Resolve(request.laser, laser_types, "--laser-topic", true);
    selected.imu = Resolve(request.imu, {kImu}, "--imu-topic", true);
    selected.joint = Resolve(request.joint, {kJointState}, "--joint-topic", true);
    selected.odometry = Resolve(request.odometry, {kOdometry}, "--odometry-topic", true);
    if (!options.angle_field.empty() && parsed.count(request.angle) > 0) {
      const std::string type = parsed.at(request.angle)->TypeOf(options.angle_field);
      if (!IsNumber(type)) {
        Fail("--angle-field " + options.angle_field + ": topic " + request.angle + " (" +
             Find(request.angle)->datatype + ") has " +
             (type.empty() ? "no field of that name" : "it as " + type + ", not a number"));
      }
    }
    // The angle is never picked by itself from a custom type: only std_msgs scalars are auto.
    selected.angle =
        angle_types.empty() ? "" : Resolve(request.angle, angle_types, "--angle-topic", options.angle_field.empty());
    if (!options.angle_field.empty() && selected.angle.empty()) {
      Fail("--angle-field " + options.angle_field +
           ": name the topic with --angle-topic (no topic's message has "
           "a number field of that name, or none was named)");
    }
    if (!selected.angle.empty() && !selected.joint.empty()) {
      Fail("both " + selected.joint + " (JointState) and " + selected.angle +
           " (angle) give the motor angle; choose one with --joint-topic none or --angle-topic none");
    }
    if (!selected.angle.empty() && options.angle_unit == AngleUnit::kUnset) {
      Fail("angle topic " + selected.angle +
           " carries a bare number: give its unit with --angle-unit deg|rad "
           "(or --angle-topic none)");
    }
    // The definitions the chosen custom (and std_msgs scalar) topics are read by.
    for (const std::string* topic : {&selected.laser, &selected.angle}) {
      if (topic->empty() || Find(*topic)->datatype == kLaserScan || definitions.count(*topic) > 0) continue;
      const auto d = parsed.find(*topic);
      if (d == parsed.end()) {
        Fail("topic " + *topic + " (" + Find(*topic)->datatype + "): its message definition cannot be read");
      }
      definitions.emplace(*topic, std::move(d->second));
    }
    if (!selected.laser.empty() && definitions.count(selected.laser) > 0) {
      laser_path = LaserField(*definitions.at(selected.laser));
    }
    if (!options.angle_field.empty()) angle_path = options.angle_field;
    const bool laser_with_angle = !selected.laser.empty() && selected.laser == selected.angle;
    const std::pair<const std::string*, Stream> choices[] = {
        {&selected.cloud, Stream::kCloud},
        {&selected.laser, laser_with_angle ? Stream::kLaserWithAngle : Stream::kLaser},
        {&selected.imu, Stream::kImu},
        {&selected.joint, Stream::kJoint},
        {&selected.odometry, Stream::kOdometry},
        {&selected.groundtruth, Stream::kGroundTruth},
        {&selected.angle, Stream::kAngle}};  // skipped below when it is the laser topic
    std::vector<std::string> names;
    for (const auto& [topic, stream] : choices) {
      if (topic->empty() || (stream == Stream::kAngle && laser_with_angle)) continue;
      if (!stream_of.emplace(*topic, stream).second) Fail("topic " + *topic + " is chosen for two streams");
      names.push_back(*topic);
    }
    if (names.empty()) return;
    view = std::make_unique<rosbag::View>(bag, rosbag::TopicQuery(names));
    it = view->begin();
  }

  // Counts a skipped message; returns false (Convert's "skipped").
  bool Skip(const std::string& reason) {
    ++stats.skipped[reason];
    return false;
  }

  // The serialized bytes of a message, in `buffer`.
  void ReadBytes(const rosbag::MessageInstance& m) {
    buffer.resize(m.size());
    ros::serialization::OStream stream(buffer.data(), static_cast<std::uint32_t>(buffer.size()));
    m.write(stream);
  }

  // A message of the generated type T, deserialized from its bytes once
  // they have been checked against T's own definition: ROS 1's deserializer
  // sizes each array by the count it reads before it knows whether the
  // bytes are there (a damaged LaserScan claiming 2^30 ranges allocated
  // 4 GiB). Null when the message is not a T (its md5 differs); throws
  // InputError naming the topic and the receive time when the message is
  // shorter than its definition says.
  template <class T>
  boost::shared_ptr<T> Instantiate(const rosbag::MessageInstance& m) {
    if (!m.isType<T>()) return nullptr;
    static const Ros1MessageDefinition definition(ros::message_traits::DataType<T>::value(),
                                                  ros::message_traits::Definition<T>::value());
    ReadBytes(m);
    try {
      definition.Locate(buffer.data(), buffer.size(), "");
    } catch (const InputError& e) {
      throw InputError(m.getTopic() + " message received at " + std::to_string(m.getTime().toSec()) +
                       " s: " + e.what());
    }
    auto message = boost::make_shared<T>();
    ros::serialization::IStream in(buffer.data(), static_cast<std::uint32_t>(buffer.size()));
    ros::serialization::deserialize(in, *message);
    return message;
  }

  // A header stamp at `path` ("" or a time field), 0 when there is none.
  double StampAt(const Ros1MessageDefinition& d, const std::string& path) const {
    if (d.TypeOf(path) != "time") return 0.0;
    const Ros1MessageDefinition::Span span = d.Locate(buffer.data(), buffer.size(), path);
    std::uint32_t sec = 0, nsec = 0;
    std::memcpy(&sec, buffer.data() + span.offset, 4);
    std::memcpy(&nsec, buffer.data() + span.offset + 4, 4);
    return static_cast<double>(sec) + 1e-9 * static_cast<double>(nsec);
  }

  // The motor angle of a message read by definition (ReadBytes first), in
  // radians; false (a counted skip) when it is not finite.
  bool AngleOf(const Ros1MessageDefinition& d, const std::string& topic, double* angle_rad) {
    const double value = d.ReadNumber(buffer.data(), buffer.size(), angle_path);
    if (!std::isfinite(value)) return Skip(topic + ": non-finite angle");
    *angle_rad = options.angle_unit == AngleUnit::kDegrees ? value * M_PI / 180.0 : value;
    return true;
  }

  // A LaserScan message, or the one inside a custom message.
  sensor_msgs::LaserScan::ConstPtr LaserOf(const rosbag::MessageInstance& m) {
    if (laser_path.empty()) return Instantiate<sensor_msgs::LaserScan>(m);
    ReadBytes(m);
    const Ros1MessageDefinition& d = *definitions.at(m.getTopic());
    const Ros1MessageDefinition::Span span = d.Locate(buffer.data(), buffer.size(), laser_path);
    auto scan = boost::make_shared<sensor_msgs::LaserScan>();
    ros::serialization::IStream in(buffer.data() + span.offset, static_cast<std::uint32_t>(span.length));
    ros::serialization::deserialize(in, *scan);
    return scan;
  }

  // Converts one message; false when it was skipped.
  bool Convert(const rosbag::MessageInstance& m, Stream stream, RosbagMessage* out) {
    out->topic = m.getTopic();
    out->receive_s = m.getTime().toSec();
    switch (stream) {
      case Stream::kAngle: {
        const auto d = definitions.find(out->topic);
        if (d == definitions.end()) {
          return Skip(out->topic + ": message definition differs from the angle topic's");
        }
        ReadBytes(m);
        double angle = 0.0;
        if (!AngleOf(*d->second, out->topic, &angle)) return false;
        const double stamp = StampAt(*d->second, "header.stamp");
        out->stamp_s = stamp > 0.0 ? stamp : out->receive_s;
        out->data = EncoderSample{out->stamp_s, angle};
        return true;
      }
      case Stream::kLaserWithAngle: {
        if (!Convert(m, Stream::kLaser, out)) return false;
        double angle = 0.0;
        if (!AngleOf(*definitions.at(out->topic), out->topic, &angle)) return false;
        RosbagMessage encoder = *out;  // the line's stamp: the angle it was taken at
        encoder.data = EncoderSample{out->stamp_s, angle};
        pending.push_back(std::move(encoder));
        return true;
      }
      case Stream::kCloud: {
        auto cloud = Instantiate<sensor_msgs::PointCloud2>(m);
        if (!cloud) return Skip(out->topic + ": message definition differs from sensor_msgs/PointCloud2");
        const double stamp = StampOr(cloud->header.stamp, m);
        out->stamp_s = stamp;
        try {
          std::vector<CloudField> fields;
          for (const sensor_msgs::PointField& f : cloud->fields)
            fields.push_back({f.name, f.offset, f.datatype, f.count});
          const PointCloud2Decoder decoder(fields, cloud->point_step, cloud->is_bigendian != 0);
          CloudDecoding decoded = decoder.Decode(cloud->data.data(), cloud->data.size(), cloud->width, cloud->height,
                                                 cloud->row_step, stamp);
          out->dropped_points = decoded.dropped;
          out->time_convention = decoded.time_convention;
          stats.dropped_points += decoded.dropped;
          out->data = std::move(decoded.scan);
        } catch (const InputError& e) {
          throw InputError(BagMessageError(label, out->topic, stamp, e.what()));
        }
        return true;
      }
      case Stream::kLaser: {
        auto scan = LaserOf(m);
        if (!scan) return Skip(out->topic + ": message definition differs from sensor_msgs/LaserScan");
        out->stamp_s = StampOr(scan->header.stamp, m);
        std::optional<LineScan> line = ToLineScan(*scan, out->stamp_s);
        if (!line) return Skip(out->topic + ": LaserScan without beams");
        out->data = std::move(*line);
        return true;
      }
      case Stream::kImu: {
        auto imu = Instantiate<sensor_msgs::Imu>(m);
        if (!imu) return Skip(out->topic + ": message definition differs from sensor_msgs/Imu");
        ImuSample sample;
        sample.time_s = StampOr(imu->header.stamp, m);
        out->stamp_s = sample.time_s;
        sample.accel_m_s2 = {imu->linear_acceleration.x, imu->linear_acceleration.y, imu->linear_acceleration.z};
        sample.gyro_rad_s = {imu->angular_velocity.x, imu->angular_velocity.y, imu->angular_velocity.z};
        if (!sample.accel_m_s2.allFinite() || !sample.gyro_rad_s.allFinite()) {
          return Skip(out->topic + ": Imu with non-finite values");
        }
        out->data = sample;
        return true;
      }
      case Stream::kJoint: {
        auto joints = Instantiate<sensor_msgs::JointState>(m);
        if (!joints) return Skip(out->topic + ": message definition differs from sensor_msgs/JointState");
        std::string reason;
        const std::optional<double> angle = JointAngle(joints->name, joints->position, options.joint_name, &reason);
        if (!angle) return Skip(out->topic + ": " + reason);
        out->stamp_s = StampOr(joints->header.stamp, m);
        out->data = EncoderSample{out->stamp_s, *angle};
        return true;
      }
      case Stream::kOdometry:
      case Stream::kGroundTruth: {
        Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
        double time_s = 0.0;
        if (m.getDataType() == kPoseStamped) {
          auto pose = Instantiate<geometry_msgs::PoseStamped>(m);
          if (!pose) return Skip(out->topic + ": message definition differs from geometry_msgs/PoseStamped");
          time_s = StampOr(pose->header.stamp, m);
          if (!ToIsometry(pose->pose, &T)) return Skip(out->topic + ": pose with an invalid quaternion");
        } else {
          auto odometry = Instantiate<nav_msgs::Odometry>(m);
          if (!odometry) return Skip(out->topic + ": message definition differs from nav_msgs/Odometry");
          time_s = StampOr(odometry->header.stamp, m);
          if (!ToIsometry(odometry->pose.pose, &T)) return Skip(out->topic + ": pose with an invalid quaternion");
        }
        out->stamp_s = time_s;
        if (stream == Stream::kOdometry) {
          out->data = OdometrySample{time_s, T};
        } else {
          out->data = StampedPose{time_s, T};
        }
        return true;
      }
    }
    return false;
  }
};

RosbagReader::RosbagReader(const std::filesystem::path& bag, RosbagReaderOptions options)
    : impl_(std::make_unique<Impl>()) {
  impl_->label = bag.string();
  impl_->options = std::move(options);
  RejectRos2Bag(bag);
  try {
    CheckRosbagRecords(bag);  // librosbag allocates the lengths it reads unchecked
    impl_->bag.open(impl_->label, rosbag::bagmode::Read);
    impl_->ListTopics();
    impl_->Select();
  } catch (const rosbag::BagException& e) {
    impl_->Fail(std::string("cannot read ROS bag: ") + e.what());
  }
}

bool RosbagReader::Supported() { return true; }

std::optional<RosbagMessage> RosbagReader::Next() {
  if (!impl_->pending.empty()) {
    RosbagMessage message = std::move(impl_->pending.front());
    impl_->pending.pop_front();
    ++impl_->stats.delivered[message.topic];
    return message;
  }
  if (!impl_->view) return std::nullopt;
  try {
    while (impl_->it != impl_->view->end()) {
      const rosbag::MessageInstance& m = *impl_->it;
      const Stream stream = impl_->stream_of.at(m.getTopic());
      RosbagMessage message;
      const bool converted = impl_->Convert(m, stream, &message);
      ++impl_->it;
      if (!converted) continue;
      ++impl_->stats.delivered[message.topic];
      return message;
    }
  } catch (const rosbag::BagException& e) {
    impl_->Fail(std::string("damaged bag data: ") + e.what());
  } catch (const ros::Exception& e) {
    impl_->Fail(std::string("cannot decode a message: ") + e.what());
  } catch (const InputError& e) {
    impl_->Fail(std::string("cannot decode a message by its definition: ") + e.what());
  }
  return std::nullopt;
}

#else  // !UNIMAP_WITH_ROSBAG

class RosbagReader::Impl : public BagState {};

RosbagReader::RosbagReader(const std::filesystem::path& bag, RosbagReaderOptions /*options*/) {
  RejectRos2Bag(bag);
  throw InputError(bag.string() +
                   ": this build of unimap cannot read ROS bags (configured without UNIMAP_WITH_ROSBAG; install "
                   "librosbag-storage-dev, libsensor-msgs-dev and libnav-msgs-dev, see scripts/install-deps.sh)");
}

bool RosbagReader::Supported() { return false; }
std::optional<RosbagMessage> RosbagReader::Next() { return std::nullopt; }

#endif

RosbagReader::~RosbagReader() = default;

const BagState& RosbagReader::state() const { return *impl_; }

}  // namespace unimap::io
