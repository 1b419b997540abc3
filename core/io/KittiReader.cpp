#include "io/KittiReader.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <sstream>

#include "io/PcdPointLoader.hpp"
#include "io/TextLineSource.hpp"
#include "unimap/Errors.hpp"

namespace unimap::io {
namespace {

namespace fs = std::filesystem;

// Reads every whitespace-separated number of a line; false if one is not a number.
bool ParseNumbers(const std::string& text, std::vector<double>* values) {
  values->clear();
  std::istringstream in(text);
  in.imbue(std::locale::classic());
  std::string token;
  while (in >> token) {
    char* end = nullptr;
    const double v = std::strtod(token.c_str(), &end);
    if (end != token.c_str() + token.size() || !std::isfinite(v)) return false;
    values->push_back(v);
  }
  return true;
}

bool IsSkippable(const std::string& line) {
  const auto first = line.find_first_not_of(" \t");
  return first == std::string::npos || line[first] == '#';
}

// A 3x4 row-major [R | t] as an isometry, R re-orthonormalised (KITTI stores
// 7 significant digits, so R^T R differs from I by ~1e-7).
Eigen::Isometry3d FromRowMajor3x4(const double* v) {
  Eigen::Matrix3d R;
  R << v[0], v[1], v[2], v[4], v[5], v[6], v[8], v[9], v[10];
  Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
  T.linear() = Eigen::Quaterniond(R).normalized().toRotationMatrix();
  T.translation() = Eigen::Vector3d(v[3], v[7], v[11]);
  return T;
}

// First existing file among dir/name for dir in dirs, name in names.
fs::path FindSideFile(const std::vector<fs::path>& dirs, const std::vector<const char*>& names) {
  for (const fs::path& dir : dirs) {
    for (const char* name : names) {
      std::error_code ec;
      if (fs::is_regular_file(dir / name, ec)) return dir / name;
    }
  }
  return {};
}

// Frame number from a name like "000015": all digits, else std::nullopt.
std::optional<std::size_t> FrameNumber(const fs::path& file) {
  const std::string stem = file.stem().string();
  if (stem.empty() || stem.size() > 12 ||
      !std::all_of(stem.begin(), stem.end(), [](char c) { return c >= '0' && c <= '9'; })) {
    return std::nullopt;
  }
  return static_cast<std::size_t>(std::stoull(stem));
}

// Reads a .bin scan: float32 x y z reflectance per point, little-endian.
void LoadBinXyzi(const fs::path& file, std::vector<Eigen::Vector4f>* xyzi) {
  const std::string name = file.string();
  std::error_code ec;
  const auto bytes = fs::file_size(file, ec);
  if (ec) throw InputError(name + ": cannot read file size: " + ec.message());
  if (bytes % (4 * sizeof(float)) != 0) {
    throw InputError(name + ": size " + std::to_string(bytes) +
                     " bytes is not a multiple of 16 (float32 x y z reflectance)");
  }
  xyzi->resize(static_cast<std::size_t>(bytes / (4 * sizeof(float))));
  std::FILE* in = std::fopen(name.c_str(), "rb");
  if (in == nullptr) throw InputError(name + ": cannot open file: " + std::strerror(errno));
  const std::size_t read = std::fread(xyzi->data(), 4 * sizeof(float), xyzi->size(), in);
  std::fclose(in);
  if (read != xyzi->size()) throw InputError(name + ": short read (file changed or damaged)");
}

}  // namespace

Eigen::Isometry3d KittiReader::DefaultTcamLidar() {
  // Sequence 00 calib.txt, "Tr:" (velodyne -> left camera).
  const double v[12] = {4.276802385584e-04,  -9.999672484946e-01, -8.084491683471e-03, -1.198459927713e-02,
                        -7.210626507497e-03, 8.081198471645e-03,  -9.999413164504e-01, -5.403984729748e-02,
                        9.999738645903e-01,  4.859485810390e-04,  -7.206933692422e-03, -2.921968648686e-01};
  return FromRowMajor3x4(v);
}

std::vector<Eigen::Isometry3d> KittiReader::ReadPoses(const fs::path& file) {
  TextLineSource source(file);
  std::vector<Eigen::Isometry3d> poses;
  std::string line;
  std::vector<double> values;
  while (source.Next(&line)) {
    if (IsSkippable(line)) continue;
    if (!ParseNumbers(line, &values) || values.size() != 12) {
      throw InputError(source.label() + ":" + std::to_string(source.line_number()) +
                       ": a pose line needs 12 numbers (3x4 row-major)");
    }
    poses.push_back(FromRowMajor3x4(values.data()));
  }
  return poses;
}

Eigen::Isometry3d KittiReader::ReadCalibration(const fs::path& file) {
  TextLineSource source(file);
  std::string line;
  std::vector<double> values;
  while (source.Next(&line)) {
    for (const char* key : {"Tr:", "Tr_velo_to_cam:"}) {
      if (line.rfind(key, 0) != 0) continue;
      if (!ParseNumbers(line.substr(std::strlen(key)), &values) || values.size() != 12) {
        throw InputError(source.label() + ":" + std::to_string(source.line_number()) + ": " + key +
                         " needs 12 numbers (3x4 row-major)");
      }
      return FromRowMajor3x4(values.data());
    }
  }
  throw InputError(file.string() + ": no \"Tr:\" line (velodyne to camera transform)");
}

std::vector<double> KittiReader::ReadTimes(const fs::path& file) {
  TextLineSource source(file);
  std::vector<double> times;
  std::string line;
  std::vector<double> values;
  while (source.Next(&line)) {
    if (IsSkippable(line)) continue;
    if (!ParseNumbers(line, &values) || values.size() != 1) {
      throw InputError(source.label() + ":" + std::to_string(source.line_number()) + ": expected one time in seconds");
    }
    if (!times.empty() && values[0] < times.back()) {
      throw InputError(source.label() + ":" + std::to_string(source.line_number()) + ": time goes backwards");
    }
    times.push_back(values[0]);
  }
  return times;
}

KittiReader::KittiReader(const fs::path& folder, KittiReaderOptions options) : options_(std::move(options)) {
  if (!(options_.scan_period_s > 0.0)) throw InputError("KITTI reader: scan_period_s must be positive");
  std::error_code ec;
  if (!fs::is_directory(folder, ec)) throw InputError(folder.string() + ": not a folder");
  fs::path scan_dir = folder;
  if (fs::is_directory(folder / "velodyne", ec)) scan_dir = folder / "velodyne";
  bool has_bin = false, has_pcd = false;
  for (const fs::directory_entry& entry : fs::directory_iterator(scan_dir)) {
    if (!entry.is_regular_file()) continue;
    const std::string ext = entry.path().extension().string();
    if (ext != ".bin" && ext != ".pcd") continue;
    (ext == ".bin" ? has_bin : has_pcd) = true;
    files_.push_back(entry.path());
  }
  if (files_.empty()) throw InputError(scan_dir.string() + ": no KITTI scans (*.bin or *.pcd)");
  if (has_bin && has_pcd) throw InputError(scan_dir.string() + ": holds both .bin and .pcd scans; keep one kind");
  std::sort(files_.begin(), files_.end());
  for (std::size_t i = 0; i < files_.size(); ++i) indices_.push_back(FrameNumber(files_[i]).value_or(i));
  const std::size_t needed = *std::max_element(indices_.begin(), indices_.end()) + 1;

  const std::vector<fs::path> dirs = {scan_dir, scan_dir.parent_path()};
  const fs::path times_file = options_.times_file.empty() ? FindSideFile(dirs, {"times.txt"}) : options_.times_file;
  std::vector<double> times;
  if (!times_file.empty()) {
    times = ReadTimes(times_file);
    if (times.size() < needed) {
      throw InputError(times_file.string() + ": " + std::to_string(times.size()) + " times, but frame " +
                       std::to_string(needed - 1) + " needs " + std::to_string(needed));
    }
  }
  for (std::size_t i = 0; i < files_.size(); ++i) {
    times_s_.push_back(times.empty() ? static_cast<double>(indices_[i]) * options_.scan_period_s : times[indices_[i]]);
  }

  const fs::path calib_file = options_.calib_file.empty() ? FindSideFile(dirs, {"calib.txt"}) : options_.calib_file;
  T_cam_lidar_ = calib_file.empty() ? DefaultTcamLidar() : ReadCalibration(calib_file);
  calibration_source_ = calib_file.empty() ? std::string("sequence 00 default Tr") : calib_file.string();

  const fs::path poses_file =
      options_.poses_file.empty() ? FindSideFile(dirs, {"poses_camera_frame.txt", "poses.txt"}) : options_.poses_file;
  if (!poses_file.empty()) {
    const std::vector<Eigen::Isometry3d> T_cam0_cam = ReadPoses(poses_file);
    if (T_cam0_cam.size() < needed) {
      throw InputError(poses_file.string() + ": " + std::to_string(T_cam0_cam.size()) + " poses, but frame " +
                       std::to_string(needed - 1) + " needs " + std::to_string(needed));
    }
    const Eigen::Isometry3d T_lidar_cam = T_cam_lidar_.inverse();
    for (std::size_t i = 0; i < files_.size(); ++i) {
      // T_lidar0_lidari = Tr^-1 * T_cam0_cami * Tr (change of frame, Tr = T_cam_lidar).
      StampedPose pose;
      pose.time_s = times_s_[i];
      pose.T_map_body = T_lidar_cam * T_cam0_cam[indices_[i]] * T_cam_lidar_;
      lidar_poses_.push_back(pose);
    }
  }
}

KittiFrame KittiReader::Read(std::size_t i) const {
  if (i >= files_.size()) throw InputError("KITTI reader: frame " + std::to_string(i) + " out of range");
  std::vector<Eigen::Vector4f> xyzi;
  if (files_[i].extension() == ".bin") {
    LoadBinXyzi(files_[i], &xyzi);
  } else {
    LoadPcdXyzi(files_[i], &xyzi);
  }
  KittiFrame frame;
  frame.index = indices_[i];
  frame.file = files_[i];
  frame.scan.start_time_s = times_s_[i];
  frame.scan.end_time_s = times_s_[i] + options_.scan_period_s;
  frame.scan.has_point_time = false;
  frame.scan.points.reserve(xyzi.size());
  for (const Eigen::Vector4f& p : xyzi) {
    if (!p.allFinite()) {
      ++frame.dropped_points;
      continue;
    }
    Point point;
    point.position_m = p.head<3>().cast<double>();
    point.time_s = frame.scan.start_time_s;
    point.intensity = p.w();
    frame.scan.points.push_back(point);
  }
  return frame;
}

std::optional<KittiFrame> KittiReader::Next() {
  if (next_ >= files_.size()) return std::nullopt;
  return Read(next_++);
}

}  // namespace unimap::io
