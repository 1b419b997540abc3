#include "io/CdrMessages.hpp"

#if UNIMAP_WITH_ROS2BAG
#include <fastcdr/Cdr.h>
#include <fastcdr/FastBuffer.h>
#include <fastcdr/exceptions/Exception.h>
#include <fastcdr/exceptions/NotEnoughMemoryException.h>

#include <array>

#include "unimap/Errors.hpp"

namespace unimap::io {
namespace {

using eprosima::fastcdr::Cdr;

// Decodes `size` bytes at `data` as `type` with read(cdr, &message) after the encapsulation header.
template <class Message, class Read>
Message Decode(const std::uint8_t* data, std::size_t size, const char* type, Read read) {
  Message message{};
  // FastBuffer takes a mutable pointer; deserializing only reads through it.
  eprosima::fastcdr::FastBuffer buffer(reinterpret_cast<char*>(const_cast<std::uint8_t*>(data)), size);
  Cdr cdr(buffer, Cdr::DEFAULT_ENDIAN, Cdr::DDS_CDR);
  try {
    cdr.read_encapsulation();
    read(cdr, &message);
  } catch (const eprosima::fastcdr::exception::NotEnoughMemoryException&) {
    throw InputError("truncated CDR message: its " + std::to_string(size) + " bytes end before the last field of " +
                     type);
  } catch (const eprosima::fastcdr::exception::Exception& e) {
    throw InputError(std::string("malformed CDR message (") + type + "): " + e.what());
  }
  return message;
}

// std_msgs/msg/Header: the stamp (frame_id read past).
CdrTime ReadHeader(Cdr& cdr) {
  CdrTime stamp;
  std::string frame_id;
  cdr >> stamp.sec >> stamp.nanosec >> frame_id;
  return stamp;
}

// geometry_msgs/msg/Vector3 or Point.
Eigen::Vector3d ReadVector3(Cdr& cdr) {
  double x = 0.0, y = 0.0, z = 0.0;
  cdr >> x >> y >> z;
  return {x, y, z};
}

// geometry_msgs/msg/Quaternion (x, y, z, w on the wire).
Eigen::Quaterniond ReadQuaternion(Cdr& cdr) {
  double x = 0.0, y = 0.0, z = 0.0, w = 0.0;
  cdr >> x >> y >> z >> w;
  return Eigen::Quaterniond(w, x, y, z);
}

// A float64[N] covariance, read past.
template <std::size_t N>
void SkipCovariance(Cdr& cdr) {
  std::array<double, N> covariance{};
  cdr >> covariance;
}

// geometry_msgs/msg/Pose into a CdrPoseStamped.
void ReadPose(Cdr& cdr, CdrPoseStamped* pose) {
  pose->position = ReadVector3(cdr);
  pose->orientation = ReadQuaternion(cdr);
}

}  // namespace

CdrLaserScan DecodeLaserScan(const std::uint8_t* data, std::size_t size) {
  return Decode<CdrLaserScan>(data, size, "sensor_msgs/msg/LaserScan", [](Cdr& cdr, CdrLaserScan* scan) {
    scan->stamp = ReadHeader(cdr);
    cdr >> scan->angle_min >> scan->angle_max >> scan->angle_increment >> scan->time_increment >> scan->scan_time >>
        scan->range_min >> scan->range_max >> scan->ranges >> scan->intensities;
  });
}

CdrImu DecodeImu(const std::uint8_t* data, std::size_t size) {
  return Decode<CdrImu>(data, size, "sensor_msgs/msg/Imu", [](Cdr& cdr, CdrImu* imu) {
    imu->stamp = ReadHeader(cdr);
    ReadQuaternion(cdr);
    SkipCovariance<9>(cdr);
    imu->angular_velocity = ReadVector3(cdr);
    SkipCovariance<9>(cdr);
    imu->linear_acceleration = ReadVector3(cdr);
    SkipCovariance<9>(cdr);
  });
}

CdrJointState DecodeJointState(const std::uint8_t* data, std::size_t size) {
  return Decode<CdrJointState>(data, size, "sensor_msgs/msg/JointState", [](Cdr& cdr, CdrJointState* joints) {
    std::vector<double> velocity, effort;
    joints->stamp = ReadHeader(cdr);
    cdr >> joints->name >> joints->position >> velocity >> effort;
  });
}

CdrPoseStamped DecodePoseStamped(const std::uint8_t* data, std::size_t size) {
  return Decode<CdrPoseStamped>(data, size, "geometry_msgs/msg/PoseStamped", [](Cdr& cdr, CdrPoseStamped* pose) {
    pose->stamp = ReadHeader(cdr);
    ReadPose(cdr, pose);
  });
}

CdrPoseStamped DecodeOdometry(const std::uint8_t* data, std::size_t size) {
  return Decode<CdrPoseStamped>(data, size, "nav_msgs/msg/Odometry", [](Cdr& cdr, CdrPoseStamped* pose) {
    std::string child_frame_id;
    pose->stamp = ReadHeader(cdr);
    cdr >> child_frame_id;
    ReadPose(cdr, pose);
    SkipCovariance<36>(cdr);
    ReadVector3(cdr);  // twist.twist.linear
    ReadVector3(cdr);  // twist.twist.angular
    SkipCovariance<36>(cdr);
  });
}

CdrPointCloud2 DecodePointCloud2(const std::uint8_t* data, std::size_t size) {
  return Decode<CdrPointCloud2>(data, size, "sensor_msgs/msg/PointCloud2", [size](Cdr& cdr, CdrPointCloud2* cloud) {
    cloud->stamp = ReadHeader(cdr);
    std::uint32_t fields = 0;
    cdr >> cloud->height >> cloud->width >> fields;
    // Each PointField takes at least 16 bytes: a count beyond the data is a truncation, not an allocation.
    const char* end = cdr.getBufferPointer() + size;
    if (static_cast<std::size_t>(fields) > static_cast<std::size_t>(end - cdr.getCurrentPosition())) {
      throw eprosima::fastcdr::exception::NotEnoughMemoryException("field count past the end");
    }
    for (std::uint32_t k = 0; k < fields; ++k) {
      CloudField field;
      cdr >> field.name >> field.offset >> field.datatype >> field.count;
      cloud->fields.push_back(field);
    }
    bool is_dense = false;
    cdr >> cloud->is_bigendian >> cloud->point_step >> cloud->row_step >> cloud->data >> is_dense;
  });
}

double DecodeScalar(CdrScalar type, const std::uint8_t* data, std::size_t size) {
  switch (type) {
    case CdrScalar::kFloat32:
      return Decode<float>(data, size, "std_msgs/msg/Float32", [](Cdr& cdr, float* value) { cdr >> *value; });
    case CdrScalar::kFloat64:
      return Decode<double>(data, size, "std_msgs/msg/Float64", [](Cdr& cdr, double* value) { cdr >> *value; });
    case CdrScalar::kInt32:
      return Decode<std::int32_t>(data, size, "std_msgs/msg/Int32",
                                  [](Cdr& cdr, std::int32_t* value) { cdr >> *value; });
  }
  return 0.0;
}

}  // namespace unimap::io
#endif  // UNIMAP_WITH_ROS2BAG
