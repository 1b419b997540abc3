#include "io/Ros2BagReader.hpp"

#include <cmath>

#include "unimap/Errors.hpp"

#if UNIMAP_WITH_ROS2BAG
#include <algorithm>
#include <map>

#include "io/BagSupport.hpp"
#include "io/CdrMessages.hpp"
#include "io/Ros2BagDatabase.hpp"
#include "io/Ros2BagMetadata.hpp"
#endif

namespace unimap::io {

#if UNIMAP_WITH_ROS2BAG
namespace {

namespace fs = std::filesystem;

// What a selected topic is read as.
enum class Stream { kCloud, kLaser, kImu, kJoint, kOdometry, kGroundTruth, kAngle };

constexpr const char* kPointCloud2 = "sensor_msgs/msg/PointCloud2";
constexpr const char* kLaserScan = "sensor_msgs/msg/LaserScan";
constexpr const char* kImu = "sensor_msgs/msg/Imu";
constexpr const char* kJointState = "sensor_msgs/msg/JointState";
constexpr const char* kOdometry = "nav_msgs/msg/Odometry";
constexpr const char* kPoseStamped = "geometry_msgs/msg/PoseStamped";
constexpr const char* kFloat32 = "std_msgs/msg/Float32";
constexpr const char* kFloat64 = "std_msgs/msg/Float64";
constexpr const char* kInt32 = "std_msgs/msg/Int32";

// A selected topic: its stream and message type.
struct Selection {
  Stream stream;
  std::string type;
};

// One .db3 of the bag with its current row.
struct BagFile {
  std::unique_ptr<Ros2BagDatabase> db;
  std::map<std::int64_t, std::string> topic_of;  // selected topic id -> name
  bool pending = false;                          // db->row() holds an unread message
};

}  // namespace

class Ros2BagReader::Impl : public BagState {
 public:
  std::string label;  // bag path, for messages
  RosbagReaderOptions options;
  std::vector<BagFile> files;                  // the bag's .db3 files
  std::map<std::string, Selection> selection;  // selected topic -> stream and type

  [[noreturn]] void Fail(const std::string& reason) const { throw InputError(label + ": " + reason); }

  RosbagTopicInfo* Find(const std::string& topic) {
    for (RosbagTopicInfo& t : topics) {
      if (t.topic == topic) return &t;
    }
    return nullptr;
  }

  // Opens the .db3 files (the folder's, or the one given) and lists the topics.
  void Open(const fs::path& bag) {
    std::vector<fs::path> paths = {bag};
    const bool has_metadata = !fs::is_regular_file(bag) || bag.filename() == "metadata.yaml";
    if (has_metadata) {
      const Ros2BagMetadata metadata = ReadRos2BagMetadata(bag);
      paths = metadata.files;
      topics = metadata.topics;
    }
    for (const fs::path& path : paths) {
      BagFile file;
      file.db = std::make_unique<Ros2BagDatabase>(path);
      for (const Ros2BagDatabase::Topic& t : file.db->topics()) {
        RosbagTopicInfo* info = Find(t.name);
        if (info == nullptr) info = &topics.emplace_back(RosbagTopicInfo{t.name, t.type, 0, ""});
        if (info->datatype != t.type) {
          throw InputError(path.string() + ": topic " + t.name + " is " + t.type + ", elsewhere in the bag " +
                           info->datatype);
        }
      }
      if (!has_metadata) {
        for (const auto& [id, count] : file.db->CountMessages()) {
          for (const Ros2BagDatabase::Topic& t : file.db->topics()) {
            if (t.id == id) Find(t.name)->messages += count;
          }
        }
      }
      files.push_back(std::move(file));
    }
  }

  // Resolves one stream's request (see RosbagTopics) to a topic or "".
  std::string Resolve(const std::string& request, const std::vector<std::string>& types, const char* option,
                      bool allow_auto) const {
    return ResolveBagTopic(label, topics, request, types, option, allow_auto, selected.groundtruth);
  }

  void Select() {
    const RosbagTopics& request = options.topics;
    selected.groundtruth = Resolve(request.groundtruth, {kOdometry, kPoseStamped}, "--groundtruth-topic", false);
    selected.cloud = Resolve(request.cloud, {kPointCloud2}, "--cloud-topic", true);
    selected.laser = Resolve(request.laser, {kLaserScan}, "--laser-topic", true);
    selected.imu = Resolve(request.imu, {kImu}, "--imu-topic", true);
    selected.joint = Resolve(request.joint, {kJointState}, "--joint-topic", true);
    selected.odometry = Resolve(request.odometry, {kOdometry}, "--odometry-topic", true);
    selected.angle = Resolve(request.angle, {kInt32, kFloat32, kFloat64}, "--angle-topic", true);
    if (!selected.angle.empty() && !selected.joint.empty()) {
      Fail("both " + selected.joint + " (JointState) and " + selected.angle +
           " (scalar angle) give the motor angle; choose one with --joint-topic none or --angle-topic none");
    }
    if (!selected.angle.empty() && options.angle_unit == AngleUnit::kUnset) {
      Fail("angle topic " + selected.angle + " (" + Find(selected.angle)->datatype +
           ") is a bare number: give its unit with --angle-unit deg|rad (or --angle-topic none)");
    }
    const std::pair<const std::string*, Stream> choices[] = {
        {&selected.cloud, Stream::kCloud},       {&selected.laser, Stream::kLaser},
        {&selected.imu, Stream::kImu},           {&selected.joint, Stream::kJoint},
        {&selected.odometry, Stream::kOdometry}, {&selected.groundtruth, Stream::kGroundTruth},
        {&selected.angle, Stream::kAngle}};
    for (const auto& [topic, stream] : choices) {
      if (topic->empty()) continue;
      if (!selection.emplace(*topic, Selection{stream, Find(*topic)->datatype}).second) {
        Fail("topic " + *topic + " is chosen for two streams");
      }
    }
    for (BagFile& file : files) {
      std::vector<std::int64_t> ids;
      for (const Ros2BagDatabase::Topic& t : file.db->topics()) {
        if (selection.count(t.name) == 0) continue;
        if (t.serialization_format != "cdr") {
          throw InputError(file.db->file().string() + ": topic " + t.name + " is serialized as '" +
                           t.serialization_format + "'; only cdr is read");
        }
        ids.push_back(t.id);
        file.topic_of[t.id] = t.name;
      }
      file.db->Query(ids);
      file.pending = file.db->Step();
    }
  }

  // Counts a skipped message; returns false (Convert's "skipped").
  bool Skip(const std::string& reason) {
    ++stats.skipped[reason];
    return false;
  }

  // Converts one message; false when it was skipped. Throws InputError for undecodable data.
  bool Convert(const Ros2BagDatabase::Row& row, const Selection& selected_as, RosbagMessage* out) {
    const double receive_s = static_cast<double>(row.timestamp_ns) / 1e9;
    const auto stamp = [&](const CdrTime& t) { return t.IsZero() ? receive_s : t.Seconds(); };
    const std::string& topic = out->topic;
    out->receive_s = receive_s;
    switch (selected_as.stream) {
      case Stream::kCloud: {
        const CdrPointCloud2 cloud = DecodePointCloud2(row.data, row.size);
        out->stamp_s = stamp(cloud.stamp);
        const PointCloud2Decoder decoder(cloud.fields, cloud.point_step, cloud.is_bigendian);
        CloudDecoding decoded = decoder.Decode(cloud.data.data(), cloud.data.size(), cloud.width, cloud.height,
                                               cloud.row_step, out->stamp_s);
        out->dropped_points = decoded.dropped;
        out->time_convention = decoded.time_convention;
        stats.dropped_points += decoded.dropped;
        out->data = std::move(decoded.scan);
        return true;
      }
      case Stream::kLaser: {
        const CdrLaserScan scan = DecodeLaserScan(row.data, row.size);
        out->stamp_s = stamp(scan.stamp);
        std::optional<LineScan> line = ToLineScan(scan, out->stamp_s);
        if (!line) return Skip(topic + ": LaserScan without beams");
        out->data = std::move(*line);
        return true;
      }
      case Stream::kImu: {
        const CdrImu imu = DecodeImu(row.data, row.size);
        out->stamp_s = stamp(imu.stamp);
        if (!imu.linear_acceleration.allFinite() || !imu.angular_velocity.allFinite()) {
          return Skip(topic + ": Imu with non-finite values");
        }
        out->data = ImuSample{out->stamp_s, imu.linear_acceleration, imu.angular_velocity};
        return true;
      }
      case Stream::kJoint: {
        const CdrJointState joints = DecodeJointState(row.data, row.size);
        std::string reason;
        const std::optional<double> angle = JointAngle(joints.name, joints.position, options.joint_name, &reason);
        if (!angle) return Skip(topic + ": " + reason);
        out->stamp_s = stamp(joints.stamp);
        out->data = EncoderSample{out->stamp_s, *angle};
        return true;
      }
      case Stream::kOdometry:
      case Stream::kGroundTruth: {
        const CdrPoseStamped pose = selected_as.type == kPoseStamped ? DecodePoseStamped(row.data, row.size)
                                                                     : DecodeOdometry(row.data, row.size);
        Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
        if (!PoseToIsometry(pose.position, pose.orientation, &T))
          return Skip(topic + ": pose with an invalid quaternion");
        out->stamp_s = stamp(pose.stamp);
        if (selected_as.stream == Stream::kOdometry) {
          out->data = OdometrySample{out->stamp_s, T};
        } else {
          out->data = StampedPose{out->stamp_s, T};
        }
        return true;
      }
      case Stream::kAngle: {
        const CdrScalar type = selected_as.type == kInt32     ? CdrScalar::kInt32
                               : selected_as.type == kFloat32 ? CdrScalar::kFloat32
                                                              : CdrScalar::kFloat64;
        const double value = DecodeScalar(type, row.data, row.size);
        if (!std::isfinite(value)) return Skip(topic + ": non-finite angle");
        out->stamp_s = receive_s;  // no header: the bag's receive time
        out->data = EncoderSample{receive_s, options.angle_unit == AngleUnit::kDegrees ? value * M_PI / 180.0 : value};
        return true;
      }
    }
    return false;
  }
};

Ros2BagReader::Ros2BagReader(const std::filesystem::path& bag, RosbagReaderOptions options)
    : impl_(std::make_unique<Impl>()) {
  impl_->label = bag.string();
  impl_->options = std::move(options);
  impl_->Open(bag);
  impl_->Select();
}

bool Ros2BagReader::Supported() { return true; }

std::optional<RosbagMessage> Ros2BagReader::Next() {
  while (true) {
    BagFile* next = nullptr;  // the file whose current message is the earliest (the first file on a tie)
    for (BagFile& file : impl_->files) {
      if (file.pending && (next == nullptr || file.db->row().timestamp_ns < next->db->row().timestamp_ns)) {
        next = &file;
      }
    }
    if (next == nullptr) return std::nullopt;
    const Ros2BagDatabase::Row& row = next->db->row();
    RosbagMessage message;
    message.topic = next->topic_of.at(row.topic_id);
    bool converted = false;
    try {
      converted = impl_->Convert(row, impl_->selection.at(message.topic), &message);
    } catch (const InputError& e) {
      throw InputError(BagMessageError(next->db->file().string(), message.topic,
                                       static_cast<double>(row.timestamp_ns) / 1e9, e.what()));
    }
    next->pending = next->db->Step();
    if (!converted) continue;
    ++impl_->stats.delivered[message.topic];
    return message;
  }
}

#else  // !UNIMAP_WITH_ROS2BAG

class Ros2BagReader::Impl : public BagState {};

Ros2BagReader::Ros2BagReader(const std::filesystem::path& bag, RosbagReaderOptions /*options*/) {
  throw InputError(bag.string() +
                   ": this build of unimap cannot read ROS 2 bags (configured without UNIMAP_WITH_ROS2BAG; install "
                   "libsqlite3-dev and libfastcdr-dev, see scripts/install-deps.sh)");
}

bool Ros2BagReader::Supported() { return false; }
std::optional<RosbagMessage> Ros2BagReader::Next() { return std::nullopt; }

#endif

Ros2BagReader::~Ros2BagReader() = default;

const BagState& Ros2BagReader::state() const { return *impl_; }

}  // namespace unimap::io
