#include "io/CarmenReader.hpp"

#include <charconv>
#include <cmath>
#include <limits>

#include <Eigen/Geometry>

#include "io/NumberText.hpp"
#include "io/TextLineSource.hpp"
#include "unimap/Errors.hpp"

namespace unimap::io {
namespace {

// Splits on spaces and tabs; views point into `text`.
void SplitFields(const std::string& text, std::vector<std::string_view>* fields) {
  fields->clear();
  std::size_t i = 0;
  const std::size_t n = text.size();
  while (i < n) {
    while (i < n && (text[i] == ' ' || text[i] == '\t')) ++i;
    const std::size_t start = i;
    while (i < n && text[i] != ' ' && text[i] != '\t') ++i;
    if (i > start) fields->emplace_back(text.data() + start, i - start);
  }
}

// A parse failure of one field, turned into an InputError by the caller.
struct FieldError {
  std::string reason;
};

double ParseDouble(std::string_view field, const char* what) {
  double value = 0.0;
  const char* first = field.data();
  if (!field.empty() && field.front() == '+') ++first;
  const auto result = std::from_chars(first, field.data() + field.size(), value);
  if (result.ec != std::errc() || result.ptr != field.data() + field.size() || !std::isfinite(value)) {
    throw FieldError{std::string(what) + " '" + std::string(field) + "' is not a finite number"};
  }
  return value;
}

// Planar pose (x, y, theta) as a 3D transform: rotation theta about +z.
Eigen::Isometry3d PlanarPose(double x, double y, double theta) {
  Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
  T.translation() = Eigen::Vector3d(x, y, 0.0);
  T.linear() = Eigen::AngleAxisd(theta, Eigen::Vector3d::UnitZ()).toRotationMatrix();
  return T;
}

// Fields after the message content: ipc_ts host logger_ts.
constexpr std::size_t kTrailerFields = 3;

}  // namespace

CarmenReader::CarmenReader(const std::filesystem::path& file, CarmenReaderOptions options)
    : options_(options), source_(std::make_unique<TextLineSource>(file)) {
  if (!(options_.fov_rad > 0.0) || !(options_.range_max_m > options_.range_min_m) ||
      !(options_.max_time_step_s > 0.0) || !(options_.max_abs_time_s > 0.0)) {
    throw InputError(file.string() +
                     ": CARMEN reader options need fov_rad > 0, range_max_m > range_min_m and positive time limits");
  }
}

CarmenReader::~CarmenReader() = default;

void CarmenReader::SetBeamLayout(std::size_t beams, double fov_rad, LineScan* scan) {
  const std::size_t steps = (beams % 2 == 1 && beams > 1) ? beams - 1 : beams;
  scan->angle_min_rad = -0.5 * fov_rad;
  scan->angle_increment_rad = fov_rad / static_cast<double>(steps);
}

void CarmenReader::CheckTime(double time_s) const {
  if (!(std::abs(time_s) <= options_.max_abs_time_s)) {
    throw FieldError{"ipc timestamp " + NumberString(time_s) + " s is beyond +-" +
                     NumberString(options_.max_abs_time_s) + " s (not a plausible clock)"};
  }
  if (has_last_time_ && time_s - last_time_s_ > options_.max_time_step_s) {
    throw FieldError{"ipc timestamp " + NumberString(time_s) + " s jumps " + NumberString(time_s - last_time_s_) +
                     " s past the previous message's (" + NumberString(last_time_s_) + " s), more than " +
                     NumberString(options_.max_time_step_s) + " s: a clock jump"};
  }
}

bool CarmenReader::AtDamagedEnd() const { return !source_->ended_with_newline(); }

CarmenLaser CarmenReader::ParseLaser(const std::vector<std::string_view>& fields) const {
  if (fields.size() < 2) throw FieldError{"FLASER line without a beam count"};
  const double count = ParseDouble(fields[1], "beam count");
  if (count < 1.0 || count > 100000.0 || count != std::floor(count)) {
    throw FieldError{"beam count '" + std::string(fields[1]) + "' is not a positive integer"};
  }
  const auto beams = static_cast<std::size_t>(count);
  const std::size_t expected = 2 + beams + 6 + kTrailerFields;
  if (fields.size() != expected) {
    throw FieldError{"FLASER with " + std::to_string(beams) + " beams needs " + std::to_string(expected) +
                     " fields, found " + std::to_string(fields.size())};
  }
  CarmenLaser laser;
  laser.line = source_->line_number();
  LineScan& scan = laser.scan;
  SetBeamLayout(beams, options_.fov_rad, &scan);
  scan.range_min_m = options_.range_min_m;
  scan.range_max_m = options_.range_max_m;
  scan.time_increment_s = 0.0;
  scan.ranges_m.resize(beams);
  for (std::size_t i = 0; i < beams; ++i) {
    scan.ranges_m[i] = static_cast<float>(ParseDouble(fields[2 + i], "range"));
  }
  double pose[6];
  for (std::size_t k = 0; k < 6; ++k) pose[k] = ParseDouble(fields[2 + beams + k], "pose field");
  const double ipc_time_s = ParseDouble(fields[2 + beams + 6], "ipc timestamp");
  ParseDouble(fields[2 + beams + 8], "logger timestamp");
  CheckTime(ipc_time_s);
  scan.start_time_s = ipc_time_s;
  laser.pose_xytheta = Eigen::Vector3d(pose[0], pose[1], pose[2]);
  laser.odometry.time_s = ipc_time_s;
  laser.odometry.T_odom_body = PlanarPose(pose[3], pose[4], pose[5]);
  return laser;
}

CarmenOdometry CarmenReader::ParseOdometry(const std::vector<std::string_view>& fields) const {
  const std::size_t expected = 1 + 6 + kTrailerFields;
  if (fields.size() != expected) {
    throw FieldError{"ODOM needs " + std::to_string(expected) + " fields, found " + std::to_string(fields.size())};
  }
  double values[6];
  for (std::size_t k = 0; k < 6; ++k) values[k] = ParseDouble(fields[1 + k], "ODOM field");
  CarmenOdometry odometry;
  odometry.line = source_->line_number();
  odometry.odometry.time_s = ParseDouble(fields[7], "ipc timestamp");
  ParseDouble(fields[9], "logger timestamp");
  CheckTime(odometry.odometry.time_s);
  odometry.odometry.T_odom_body = PlanarPose(values[0], values[1], values[2]);
  odometry.tv_m_s = values[3];
  odometry.rv_rad_s = values[4];
  odometry.accel_m_s2 = values[5];
  return odometry;
}

std::optional<CarmenMessage> CarmenReader::Next() {
  while (source_->Next(&line_)) {
    ++stats_.lines;
    SplitFields(line_, &fields_);
    if (fields_.empty() || fields_.front().front() == '#') {
      ++stats_.comments;
      continue;
    }
    const std::string_view type = fields_.front();
    const bool laser = type == "FLASER";
    if (!laser && type != "ODOM") {
      ++stats_.other_messages[std::string(type)];
      continue;
    }
    try {
      if (laser) {
        CarmenLaser message = ParseLaser(fields_);
        ++stats_.laser_scans;
        last_time_s_ = message.scan.start_time_s;
        has_last_time_ = true;
        return message;
      }
      CarmenOdometry message = ParseOdometry(fields_);
      ++stats_.odometry;
      last_time_s_ = message.odometry.time_s;
      has_last_time_ = true;
      return message;
    } catch (const FieldError& error) {
      if (!AtDamagedEnd()) {
        throw InputError(source_->label() + ":" + std::to_string(source_->line_number()) + ": " + error.reason);
      }
      const std::string reason = "truncated last line (" + std::string(type) + ")";
      ++stats_.skipped[reason];
      if (stats_.skipped_lines.size() < CarmenReaderStats::kMaxListedSkips) {
        stats_.skipped_lines.push_back({source_->line_number(), reason + ": " + error.reason});
      }
    }
  }
  stats_.truncated_input = source_->truncated();
  return std::nullopt;
}

bool CarmenReader::HasOdometryLines(const std::filesystem::path& file) {
  TextLineSource source(file);
  std::string line;
  while (source.Next(&line)) {
    if (line.rfind("ODOM", 0) == 0 && (line.size() == 4 || line[4] == ' ' || line[4] == '\t')) return true;
  }
  return false;
}

}  // namespace unimap::io
