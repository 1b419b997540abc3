#pragma once
// The one place that reads world YAML (the `world:` list of a scenario file).
#include <string>

#include <yaml-cpp/yaml.h>

#include "World.hpp"

namespace unimap::sim {

// Builds a World from a YAML list of primitives, one map per entry:
//   - {type: box, center: [x, y, z], size: [lx, ly, lz], rpy_deg: [r, p, y]}   (rpy_deg optional)
//   - {type: plane, center: [x, y, z], size: [lx, ly], rpy_deg: [r, p, y]}     (bounded rectangle,
//                                                                               plane = local z = 0)
//   - {type: cylinder, base: [x, y, z], axis: [ax, ay, az], radius: r, height: h}
//   - {type: sphere, center: [x, y, z], radius: r}
//   - {type: heightfield, center: [x, y, z], size: [lx, ly], z0: z,
//      waves: [[amplitude, kx, ky, phi, psi], ...]}                            (z0, waves optional)
// Any entry may add `repeat: {count: n, step: [dx, dy, dz]}`: n copies, copy i
// moved by i * step. Orientation R = Rz(yaw) Ry(pitch) Rx(roll); lengths in m,
// wavenumbers in rad/m, phases in rad. The returned world is built.
// Throws ConfigError(file_label, line, key, reason) for a node that is not a
// list, an entry that is not a map, an unknown or missing type, unknown,
// duplicate or missing keys, non-numbers, non-finite numbers, lists of the
// wrong length, non-positive sizes/radii/heights, a zero axis, or a repeat
// count outside [1, 100000]. Lines are 1-based (0 when unknown).
World LoadWorld(const YAML::Node& primitives_list, const std::string& file_label);

// A one-line summary: "<n> primitives (<k> box, ...), bounds [x0, y0, z0] .. [x1, y1, z1] m".
std::string DescribeWorld(const World& world);

}  // namespace unimap::sim
