#pragma once
#include <memory>

#include "map/DistanceField.hpp"

namespace unimap::map {

// A coarser view of a distance field for a wide search (re-acquiring a
// pose whose prediction was far off): cells of factor x factor x factor fine
// cells, a coarse cell holding a surface when one of its fine cells lies
// within half a fine cell of one, and every coarse cell the exact Euclidean
// distance from its centre to the nearest such cell's centre (separable
// squared-distance transform, Felzenszwalb & Huttenlocher 2012), up to
// clamp_m. Its basin reaches clamp_m where the fine field's ends at its
// clamp. An empty fine field gives an empty field. factor >= 1, clamp_m > 0.
std::shared_ptr<const DistanceField> CoarsenField(const DistanceField& fine, int factor, float clamp_m);

}  // namespace unimap::map
