#pragma once
#include <cstdint>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "options/FieldVisitor.hpp"
#include "unimap/BodyScan.hpp"
#include "unimap/LineScan.hpp"

namespace unimap::map {

// Settings of LineGapFill.
struct LineGapFillOptions {
  double step_m = 0.05;                     // spacing of the filled points along a gap
  double max_gap_m = 1.0;                   // longer gaps between a beam's two returns stay open
  double max_incidence_deg = 75.0;          // a gap more nearly along the beams than this is a depth jump ...
  double max_grazing_incidence_deg = 85.0;  // ... unless it is at most this and continues the beam's
                                            // previous gap (a wall seen at a grazing angle)
  double max_turn_deg = 45.0;               // continues: the two gaps' directions differ by at most this
  double max_line_interval_s = 0.1;         // lines further apart in time are not consecutive

  // Every field by name, for the platform file's `mapper:` section (SettingsOverrides).
  void VisitFields(options::FieldVisitor& v);
  bool IsValid(std::string* why) const;
};

// One beam's return in the map frame.
struct BeamReturn {
  std::uint16_t beam = 0;  // index of the beam within its line
  Eigen::Vector3f p_map = Eigen::Vector3f::Zero();
};

// Each map point of a deskewed line (points_map[i] is body.points[i] in the
// map frame) with its beam, from its firing time (which deskewing keeps);
// empty when the line does not time its beams (time_increment_s 0).
std::vector<BeamReturn> LineReturns(const LineScan& line, const BodyScan& body,
                                    const std::vector<Eigen::Vector3f>& points_map);

// Surface between consecutive lines of a rotating line scanner. Each line
// leaves a stripe of returns; the stripes of one sweep lie an azimuth step
// apart (0.29 m at 3.7 m for 4.5 deg), so a distance map built from them
// measures the distance to the nearest stripe, which pulls a point along the
// surface towards the stripes already seen (docs/mapping.md, stripe bias).
// Filling the gap between the two returns of the same beam in consecutive
// lines, where they plausibly lie on one surface, makes the map's surfaces
// continuous. A gap running nearly along the beams is a depth jump, except
// where the same beam's gap in the previous pair of lines ran the same way:
// a surface seen at a grazing angle (a corridor's walls far ahead).
class LineGapFill {
 public:
  explicit LineGapFill(LineGapFillOptions options);

  // Adds the line taken at time_s from sensor_map and returns the points
  // filled between it and the previous line (none for the first line, after
  // a pause or for beams with no return in either line).
  std::vector<Eigen::Vector3f> Add(double time_s, const Eigen::Vector3f& sensor_map,
                                   const std::vector<BeamReturn>& returns);

 private:
  LineGapFillOptions options_;
  double cos_min_beam_angle_;          // cos(90 deg - max incidence)
  double cos_min_grazing_beam_angle_;  // cos(90 deg - max grazing incidence)
  double cos_max_turn_;                // cos(max turn)
  bool have_previous_ = false;
  double previous_time_s_ = 0.0;
  Eigen::Vector3f previous_sensor_map_ = Eigen::Vector3f::Zero();
  std::vector<Eigen::Vector3f> previous_;      // by beam; NaN where the beam had no return
  std::vector<Eigen::Vector3f> previous_gap_;  // by beam: its last gap (unit), NaN when none
};

}  // namespace unimap::map
