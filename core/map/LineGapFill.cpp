#include "map/LineGapFill.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <utility>

namespace unimap::map {
namespace {

constexpr double kPi = 3.14159265358979323846;

}  // namespace

std::vector<BeamReturn> LineReturns(const LineScan& line, const BodyScan& body,
                                    const std::vector<Eigen::Vector3f>& points_map) {
  std::vector<BeamReturn> out;
  if (!(line.time_increment_s > 0.0) || body.points.size() != points_map.size()) return out;
  out.reserve(points_map.size());
  const double beams = std::min(static_cast<double>(line.ranges_m.size()), 65536.0);  // BeamReturn::beam is 16 bits
  for (std::size_t i = 0; i < points_map.size(); ++i) {
    const double beam = std::round((body.points[i].time_s - line.start_time_s) / line.time_increment_s);
    if (beam >= 0.0 && beam < beams) out.push_back({static_cast<std::uint16_t>(beam), points_map[i]});
  }
  return out;
}

bool LineGapFillOptions::IsValid(std::string* why) const {
  std::string local_why;
  if (why == nullptr) why = &local_why;
  if (!(step_m > 0.0) || !(max_gap_m >= step_m)) {
    *why = "step_m must be > 0 and max_gap_m >= step_m";
    return false;
  }
  if (!(max_incidence_deg > 0.0 && max_incidence_deg < 90.0)) {
    *why = "max_incidence_deg must be in (0, 90)";
    return false;
  }
  if (!(max_grazing_incidence_deg >= max_incidence_deg && max_grazing_incidence_deg < 90.0)) {
    *why = "max_grazing_incidence_deg must be in [max_incidence_deg, 90)";
    return false;
  }
  if (!(max_turn_deg >= 0.0 && max_turn_deg < 90.0)) {
    *why = "max_turn_deg must be in [0, 90)";
    return false;
  }
  if (!(max_line_interval_s > 0.0)) {
    *why = "max_line_interval_s must be > 0";
    return false;
  }
  return true;
}

LineGapFill::LineGapFill(LineGapFillOptions options) : options_(options) {
  std::string why;
  if (!options_.IsValid(&why)) throw std::invalid_argument("LineGapFillOptions: " + why);
  cos_min_beam_angle_ = std::cos((90.0 - options_.max_incidence_deg) * kPi / 180.0);
  cos_min_grazing_beam_angle_ = std::cos((90.0 - options_.max_grazing_incidence_deg) * kPi / 180.0);
  cos_max_turn_ = std::cos(options_.max_turn_deg * kPi / 180.0);
}

std::vector<Eigen::Vector3f> LineGapFill::Add(double time_s, const Eigen::Vector3f& sensor_map,
                                              const std::vector<BeamReturn>& returns) {
  std::vector<Eigen::Vector3f> filled;
  const bool consecutive =
      have_previous_ && time_s > previous_time_s_ && time_s - previous_time_s_ <= options_.max_line_interval_s;
  const float max_gap = static_cast<float>(options_.max_gap_m);
  const float step = static_cast<float>(options_.step_m);
  const float cos_min = static_cast<float>(cos_min_beam_angle_);
  const float cos_min_grazing = static_cast<float>(cos_min_grazing_beam_angle_);
  const float cos_max_turn = static_cast<float>(cos_max_turn_);
  const float nan = std::numeric_limits<float>::quiet_NaN();
  std::vector<Eigen::Vector3f> gaps(previous_gap_.size(), Eigen::Vector3f::Constant(nan));
  if (consecutive) {
    for (const BeamReturn& r : returns) {
      if (r.beam >= previous_.size() || !previous_[r.beam].allFinite() || !r.p_map.allFinite()) continue;
      const Eigen::Vector3f& a = previous_[r.beam];
      const Eigen::Vector3f gap = r.p_map - a;
      const float length = gap.norm();
      if (!(length > step) || length > max_gap) continue;  // touching, or a hole
      if (r.beam >= gaps.size()) gaps.resize(r.beam + 1u, Eigen::Vector3f::Constant(nan));
      gaps[r.beam] = gap / length;
      // A depth jump runs along the beams: the gap then is no surface, unless
      // it continues the previous gap (a surface at a grazing angle).
      const Eigen::Vector3f beam = ((a - previous_sensor_map_) + (r.p_map - sensor_map)).normalized();
      const float along = std::abs(gap.dot(beam));
      if (along > cos_min * length) {
        const bool continues = r.beam < previous_gap_.size() && previous_gap_[r.beam].allFinite() &&
                               previous_gap_[r.beam].dot(gap) >= cos_max_turn * length;
        if (!continues || along > cos_min_grazing * length) continue;
      }
      const int inner = static_cast<int>(std::floor(length / step));
      for (int k = 1; k <= inner; ++k) {
        const float s = static_cast<float>(k) / static_cast<float>(inner + 1);
        filled.push_back(a + s * gap);
      }
    }
  }
  // Keep this line and its gaps, by beam.
  previous_gap_ = std::move(gaps);
  previous_.assign(previous_.size(), Eigen::Vector3f::Constant(nan));
  for (const BeamReturn& r : returns) {
    if (r.beam >= previous_.size()) previous_.resize(r.beam + 1u, Eigen::Vector3f::Constant(nan));
    previous_[r.beam] = r.p_map;
  }
  have_previous_ = true;
  previous_time_s_ = time_s;
  previous_sensor_map_ = sensor_map;
  return filled;
}

void LineGapFillOptions::VisitFields(options::FieldVisitor& v) {
  v.Field("step_m", &step_m, "m");
  v.Field("max_gap_m", &max_gap_m, "m");
  v.Field("max_incidence_deg", &max_incidence_deg, "deg");
  v.Field("max_grazing_incidence_deg", &max_grazing_incidence_deg, "deg");
  v.Field("max_turn_deg", &max_turn_deg, "deg");
  v.Field("max_line_interval_s", &max_line_interval_s, "s");
}

}  // namespace unimap::map
