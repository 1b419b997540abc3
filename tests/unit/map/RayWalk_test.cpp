#include "map/RayWalk.hpp"

#include <map>
#include <random>
#include <set>
#include <vector>

#include <gtest/gtest.h>

namespace unimap::map {
namespace {

using Mask = std::array<std::uint64_t, DistanceField::kBlockCells / 64>;

std::uint64_t PackBlock(const Eigen::Vector3i& b) {
  return (static_cast<std::uint64_t>(b.x()) << 32) | (static_cast<std::uint64_t>(b.y()) << 16) |
         static_cast<std::uint64_t>(b.z());
}

// Occupied voxels scattered around key 1000 (a few per block, some blocks empty).
std::map<std::uint64_t, Mask> RandomOccupancy(std::uint32_t seed, int count, std::vector<Eigen::Vector3i>* voxels) {
  std::mt19937 rng(seed);
  std::uniform_int_distribution<int> coordinate(960, 1040);
  std::map<std::uint64_t, Mask> masks;
  for (int i = 0; i < count; ++i) {
    const Eigen::Vector3i v(coordinate(rng), coordinate(rng), coordinate(rng));
    const Eigen::Vector3i b = v.unaryExpr([](int c) { return c >> DistanceField::kBlockShift; });
    const auto bit = static_cast<std::size_t>(DistanceField::BlockOffset(v.x() & 7, v.y() & 7, v.z() & 7));
    masks[PackBlock(b)][bit / 64] |= std::uint64_t{1} << (bit % 64);
    voxels->push_back(v);
  }
  return masks;
}

// Every ray visits the same occupied voxels, in the same order, whether it
// skips empty blocks and quarters or walks every voxel; sparse occupancy
// (most blocks and quarters empty) and dense (few are).
void ExpectSameVisits(int occupied, int min_visits) {
  std::vector<Eigen::Vector3i> voxels;
  const std::map<std::uint64_t, Mask> masks = RandomOccupancy(3, occupied, &voxels);
  const auto skipping = [&](const Eigen::Vector3i& block) {
    BlockOccupancy out;
    const auto it = masks.find(PackBlock(block));
    if (it != masks.end()) {
      out.mask = &it->second;
      out.quarters = QuarterMask(it->second);
    }
    return out;
  };
  const Mask empty{};
  const auto every_voxel = [&](const Eigen::Vector3i& block) {
    BlockOccupancy out;
    const auto it = masks.find(PackBlock(block));
    out.mask = it != masks.end() ? &it->second : &empty;  // never null: no block skipped
    out.quarters = 0xff;                                  // no quarter skipped
    return out;
  };
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> origin_coordinate(990.0, 1010.0);
  std::uniform_int_distribution<int> pick(0, static_cast<int>(voxels.size()) - 1);
  int visits = 0;
  for (int ray = 0; ray < 2000; ++ray) {
    const Eigen::Vector3d origin(origin_coordinate(rng), origin_coordinate(rng), origin_coordinate(rng));
    const Eigen::Vector3i end = voxels[static_cast<std::size_t>(pick(rng))];
    std::vector<Eigen::Vector3i> a, b;
    WalkRay(origin, end, skipping, [&](const Eigen::Vector3i& v) {
      a.push_back(v);
      return false;
    });
    WalkRay(origin, end, every_voxel, [&](const Eigen::Vector3i& v) {
      b.push_back(v);
      return false;
    });
    ASSERT_EQ(a, b) << "ray " << ray;
    visits += static_cast<int>(a.size());
  }
  EXPECT_GT(visits, min_visits);  // the rays did pass occupied voxels
}

TEST(RayWalk, SkippingEmptySpaceVisitsTheSameVoxelsAsAVoxelByVoxelWalk) {
  ExpectSameVisits(3000, 500);
  ExpectSameVisits(20000, 2000);
}

// Settled voxels (BlockOccupancy::settled) are left out of a walk and
// nothing else is: the walk visits what an unsettled walk visits minus them.
TEST(RayWalk, SettledVoxelsAreNotVisited) {
  std::vector<Eigen::Vector3i> voxels;
  const std::map<std::uint64_t, Mask> masks = RandomOccupancy(5, 20000, &voxels);
  std::map<std::uint64_t, Mask> settled;
  std::set<std::uint64_t> settled_voxels;
  for (std::size_t i = 0; i < voxels.size(); i += 2) {  // every other voxel settled
    const Eigen::Vector3i& v = voxels[i];
    const auto bit = static_cast<std::size_t>(DistanceField::BlockOffset(v.x() & 7, v.y() & 7, v.z() & 7));
    settled[PackBlock(v.unaryExpr([](int c) { return c >> DistanceField::kBlockShift; }))][bit / 64] |= std::uint64_t{1}
                                                                                                        << (bit % 64);
    settled_voxels.insert(PackBlock(v));
  }
  const auto lookup = [&](const Eigen::Vector3i& block, bool with_settled) {
    BlockOccupancy out;
    const auto it = masks.find(PackBlock(block));
    if (it != masks.end()) {
      out.mask = &it->second;
      out.quarters = QuarterMask(it->second);
      const auto s = settled.find(PackBlock(block));
      if (with_settled && s != settled.end()) out.settled = &s->second;
    }
    return out;
  };
  std::mt19937 rng(13);
  std::uniform_real_distribution<double> origin_coordinate(990.0, 1010.0);
  std::uniform_int_distribution<int> pick(0, static_cast<int>(voxels.size()) - 1);
  int left_out = 0;
  for (int ray = 0; ray < 2000; ++ray) {
    const Eigen::Vector3d origin(origin_coordinate(rng), origin_coordinate(rng), origin_coordinate(rng));
    const Eigen::Vector3i end = voxels[static_cast<std::size_t>(pick(rng))];
    std::vector<Eigen::Vector3i> all, unsettled;
    WalkRay(
        origin, end, [&](const Eigen::Vector3i& b) { return lookup(b, false); },
        [&](const Eigen::Vector3i& v) {
          all.push_back(v);
          return false;
        });
    WalkRay(
        origin, end, [&](const Eigen::Vector3i& b) { return lookup(b, true); },
        [&](const Eigen::Vector3i& v) {
          unsettled.push_back(v);
          return false;
        });
    std::vector<Eigen::Vector3i> expected;
    for (const Eigen::Vector3i& v : all) {
      if (settled_voxels.count(PackBlock(v)) == 0) expected.push_back(v);
    }
    left_out += static_cast<int>(all.size() - expected.size());
    ASSERT_EQ(unsettled, expected) << "ray " << ray;
  }
  EXPECT_GT(left_out, 1000);  // settled voxels were on the rays
}

TEST(RayWalk, QuarterMaskMarksTheQuartersHoldingAVoxel) {
  Mask mask{};
  const auto set = [&](int x, int y, int z) {
    const auto bit = static_cast<std::size_t>(DistanceField::BlockOffset(x, y, z));
    mask[bit / 64] |= std::uint64_t{1} << (bit % 64);
  };
  EXPECT_EQ(QuarterMask(mask), 0);
  set(0, 0, 0);
  EXPECT_EQ(QuarterMask(mask), 1u << QuarterIndex(Eigen::Vector3i(0, 0, 0)));
  set(7, 5, 2);  // x high, y high, z low
  EXPECT_EQ(QuarterMask(mask),
            (1u << QuarterIndex(Eigen::Vector3i(0, 0, 0))) | (1u << QuarterIndex(Eigen::Vector3i(7, 5, 2))));
  EXPECT_EQ(QuarterIndex(Eigen::Vector3i(7, 5, 2)), 0b110);
}

}  // namespace
}  // namespace unimap::map
