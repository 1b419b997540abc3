#pragma once
// Internal to unimap_io: file names and text headers of a dataset folder,
// shared by DatasetWriter and DatasetReader (docs/dataset-format.md).
#include <cstddef>

namespace unimap::io::layout {

constexpr const char* kMetadata = "metadata.yaml";
constexpr const char* kImu = "imu.csv";
constexpr const char* kEncoder = "encoder.csv";
constexpr const char* kOdometry = "odometry.csv";
constexpr const char* kScans = "scans.bin";
constexpr const char* kGroundTruth = "groundtruth.tum";

// First line of each text stream.
constexpr const char* kImuHeader = "# time_s ax_m_s2 ay_m_s2 az_m_s2 gx_rad_s gy_rad_s gz_rad_s\n";
constexpr const char* kEncoderHeader = "# time_s angle_rad\n";
constexpr const char* kPoseHeader = "# time_s x y z qx qy qz qw\n";

// Numbers per row of each text stream (time included).
constexpr std::size_t kImuColumns = 7;
constexpr std::size_t kEncoderColumns = 2;

}  // namespace unimap::io::layout
