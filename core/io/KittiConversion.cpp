// ConvertKitti (io/DatasetConversion.hpp): a KITTI odometry sequence into a dataset.
#include "io/DatasetConversion.hpp"

namespace unimap::io {

ConversionReport ConvertKitti(const ConversionOptions& options) {
  ConversionReport report;
  KittiReader reader(options.input, options.kitti);
  report.notes.push_back("calibration Tr (T_cam_lidar): " + reader.calibration_source());
  if (reader.has_poses()) {
    report.notes.push_back("groundtruth.tum: LiDAR poses, T_lidar0_lidar = Tr^-1 * T_cam0_cam * Tr");
  } else {
    report.notes.push_back("no poses file: no ground truth written");
  }

  DatasetMetadata metadata;
  metadata.source = "kitti";
  metadata.payload = options.payload.empty() ? "fixed_3d" : options.payload;
  metadata.scan_rate_hz = 1.0 / options.kitti.scan_period_s;
  // Tr, so that runs can also write their trajectory in KITTI's camera frame.
  const Eigen::Matrix<double, 3, 4> Tr = reader.T_cam_lidar().matrix().topRows<3>();
  for (int r = 0; r < 3; ++r) {
    for (int c = 0; c < 4; ++c) metadata.camera_from_lidar.push_back(Tr(r, c));
  }
  report.payload = metadata.payload;
  const std::unique_ptr<DatasetSink> writer = OpenDatasetSink(options, metadata);
  // Ground truth first, for every frame of the sequence: a run reading the
  // sequence directly (LiveConversion) has it even when it stops early.
  for (std::size_t i = 0; i < reader.lidar_poses().size() && i < reader.size(); ++i) {
    writer->WriteGroundTruth(reader.lidar_poses()[i]);
    ++report.groundtruth;
  }
  // Frames are in file order and times.txt is checked non-decreasing: no reordering needed.
  for (std::size_t i = 0; i < reader.size(); ++i) {
    if (options.stop != nullptr && options.stop->load()) {
      report.interrupted = true;
      break;
    }
    KittiFrame frame = reader.Read(i);
    report.dropped_points += frame.dropped_points;
    writer->WriteScan(std::move(frame.scan));
    ++report.scans;
  }
  writer->Finish();
  return report;
}

}  // namespace unimap::io
