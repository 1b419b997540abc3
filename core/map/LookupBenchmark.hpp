#pragma once
#include <cstddef>
#include <cstdint>

#include "map/DistanceField.hpp"

namespace unimap::map {

// Average wall time (ns) of one DistanceField::Distance lookup, over lookups
// queries at uniformly random points of the field's box (fixed seed), the
// points generated before timing. For `unimap bench`; never for tests.
double MeasureLookupNs(const DistanceField& field, std::size_t lookups, std::uint32_t seed);

// The same for DistanceField::DistanceTrilinear with its gradient.
double MeasureTrilinearLookupNs(const DistanceField& field, std::size_t lookups, std::uint32_t seed);

}  // namespace unimap::map
