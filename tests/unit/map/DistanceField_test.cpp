#include "map/DistanceField.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <vector>

#include <gtest/gtest.h>

#include "unimap/Errors.hpp"

namespace unimap::map {
namespace {

using V3 = Eigen::Vector3f;

// A 3 x 4 x 5 grid of 0.5 m cells from (-1, 0, 2) holding a linear field
// f(p) = 0.1 + 0.05 x + 0.02 y + 0.03 z (cell centres), clamp 2 m.
constexpr float kClamp = 2.0f;
const V3 kOrigin(-1.0f, 0.0f, 2.0f);
const Eigen::Vector3i kDims(3, 4, 5);

float Linear(const V3& p) { return 0.1f + 0.05f * p.x() + 0.02f * p.y() + 0.03f * p.z(); }

DistanceField LinearField() {
  std::vector<std::uint16_t> cells;
  for (int x = 0; x < kDims.x(); ++x) {
    for (int y = 0; y < kDims.y(); ++y) {
      for (int z = 0; z < kDims.z(); ++z) {
        const V3 center = kOrigin + (Eigen::Vector3i(x, y, z).cast<float>().array() + 0.5f).matrix() * 0.5f;
        cells.push_back(DistanceField::Quantise(Linear(center), kClamp));
      }
    }
  }
  return DistanceField(kOrigin, kDims, 0.5f, kClamp, std::move(cells), 7);
}

TEST(DistanceField, LookupReturnsTheValueOfTheVoxelContainingThePoint) {
  const DistanceField field = LinearField();
  const float step = kClamp / 65535.0f;
  for (int x = 0; x < kDims.x(); ++x) {
    for (int y = 0; y < kDims.y(); ++y) {
      for (int z = 0; z < kDims.z(); ++z) {
        const V3 center = field.CellCenter(Eigen::Vector3i(x, y, z));
        // Anywhere inside the voxel, not only at its centre.
        const V3 corner = center + V3(0.24f, -0.24f, 0.2f);
        EXPECT_NEAR(field.Distance(center), Linear(center), step);
        EXPECT_NEAR(field.Distance(corner), Linear(center), step);
        EXPECT_NEAR(field.CellDistance(Eigen::Vector3i(x, y, z)), Linear(center), step);
      }
    }
  }
  EXPECT_EQ(field.sequence(), 7u);
  EXPECT_EQ(field.CellCount(), 60u);
  // One block of codes and the block table's one entry.
  EXPECT_EQ(field.StoredBlocks(), 1u);
  EXPECT_EQ(field.MemoryBytes(),
            DistanceField::kBlockCells * sizeof(std::uint16_t) + sizeof(std::shared_ptr<const DistanceField::Block>));
  EXPECT_TRUE(field.box_max().isApprox(V3(0.5f, 2.0f, 4.5f)));
}

TEST(DistanceField, OutsideTheBoxAndNaNReadTheClamp) {
  const DistanceField field = LinearField();
  const float nan = std::numeric_limits<float>::quiet_NaN();
  EXPECT_FLOAT_EQ(field.Distance(V3(-1.01f, 0.1f, 2.1f)), kClamp);  // just below x
  EXPECT_FLOAT_EQ(field.Distance(V3(0.5f, 0.1f, 2.1f)), kClamp);    // max face is open
  EXPECT_FLOAT_EQ(field.Distance(V3(0.0f, 2.0f, 2.1f)), kClamp);
  EXPECT_FLOAT_EQ(field.Distance(V3(0.0f, 1.0f, 4.5f)), kClamp);
  EXPECT_FLOAT_EQ(field.Distance(V3(nan, 1.0f, 3.0f)), kClamp);
  EXPECT_FALSE(field.Contains(V3(nan, 1.0f, 3.0f)));
  EXPECT_TRUE(field.Contains(V3(-1.0f, 0.0f, 2.0f)));  // min face is closed
  EXPECT_NEAR(field.Distance(V3(-1.0f, 0.0f, 2.0f)), Linear(V3(-0.75f, 0.25f, 2.25f)), 1e-4f);
  EXPECT_FLOAT_EQ(field.CellDistance(Eigen::Vector3i(3, 0, 0)), kClamp);
  EXPECT_FLOAT_EQ(DistanceField(1.5f).Distance(V3::Zero()), 1.5f);
}

TEST(DistanceField, QuantisationIsExactToOneStepAndSaturatesAtTheClamp) {
  EXPECT_EQ(DistanceField::Quantise(0.0f, 1.0f), 0u);
  EXPECT_EQ(DistanceField::Quantise(-0.5f, 1.0f), 0u);
  EXPECT_EQ(DistanceField::Quantise(1.0f, 1.0f), DistanceField::kMaxSteps);
  EXPECT_EQ(DistanceField::Quantise(7.0f, 1.0f), DistanceField::kMaxSteps);
  EXPECT_EQ(DistanceField::Quantise(std::numeric_limits<float>::quiet_NaN(), 1.0f), DistanceField::kMaxSteps);
  EXPECT_EQ(DistanceField::Quantise(0.5f, 1.0f), 32768u);  // round(32767.5)
}

TEST(DistanceField, TrilinearInterpolationIsExactOnALinearField) {
  const DistanceField field = LinearField();
  // Inside the hull of the voxel centres, a linear field interpolates exactly.
  const V3 gradient_truth(0.05f, 0.02f, 0.03f);
  for (const V3& p : {V3(-0.6f, 0.4f, 2.4f), V3(0.1f, 1.6f, 4.1f), V3(-0.3f, 1.0f, 3.3f)}) {
    V3 gradient;
    EXPECT_NEAR(field.DistanceTrilinear(p, &gradient), Linear(p), 1e-4f) << p.transpose();
    EXPECT_LT((gradient - gradient_truth).cwiseAbs().maxCoeff(), 2e-4f) << gradient.transpose();
    EXPECT_NEAR(field.DistanceTrilinear(p, nullptr), Linear(p), 1e-4f);
  }
  // Between the last centres and the box face, the missing neighbours count
  // as the clamp: 30 % clamp + 70 % the first layer along x.
  const V3 edge(-0.9f, 1.0f, 3.3f);
  EXPECT_NEAR(field.DistanceTrilinear(edge, nullptr), 0.3f * kClamp + 0.7f * Linear(V3(-0.75f, 1.0f, 3.3f)), 1e-4f);
  V3 gradient = V3::Ones();
  EXPECT_FLOAT_EQ(field.DistanceTrilinear(V3(9.0f, 0.0f, 0.0f), &gradient), kClamp);
  EXPECT_TRUE(gradient.isZero());
}

// A signed field: s(p) = z - 3.1 (a plane between the centres z = 3.0 and
// 3.25 ... of LinearField's grid), negative below.
float Plane(const V3& p) { return p.z() - 3.1f; }

DistanceField SignedField(float (*value)(const V3&)) {
  std::vector<std::uint16_t> cells;
  for (int x = 0; x < kDims.x(); ++x) {
    for (int y = 0; y < kDims.y(); ++y) {
      for (int z = 0; z < kDims.z(); ++z) {
        const V3 center = kOrigin + (Eigen::Vector3i(x, y, z).cast<float>().array() + 0.5f).matrix() * 0.5f;
        cells.push_back(DistanceField::QuantiseSigned(value(center), kClamp));
      }
    }
  }
  return DistanceField(kOrigin, kDims, 0.5f, kClamp, std::move(cells), 1, DistanceField::Encoding::kSigned);
}

TEST(DistanceField, SignedQuantisationCoversPlusMinusTheClampIn15Bits) {
  const float step = 2.0f * kClamp / 32767.0f;
  const std::uint16_t plus_clamp = DistanceField::kMaxSignedSteps << 1;  // bit 0: stencil flag
  EXPECT_EQ(DistanceField::QuantiseSigned(-kClamp, kClamp), 0u);
  EXPECT_EQ(DistanceField::QuantiseSigned(-9.0f, kClamp), 0u);
  EXPECT_EQ(DistanceField::QuantiseSigned(kClamp, kClamp), plus_clamp);
  EXPECT_EQ(DistanceField::QuantiseSigned(std::numeric_limits<float>::quiet_NaN(), kClamp), plus_clamp);
  EXPECT_EQ(DistanceField::QuantiseSigned(0.0f, kClamp), 16384u << 1);  // round(16383.5)
  const DistanceField field = SignedField(Plane);
  EXPECT_EQ(field.encoding(), DistanceField::Encoding::kSigned);
  EXPECT_EQ(LinearField().encoding(), DistanceField::Encoding::kUnsigned);
  for (int z = 0; z < kDims.z(); ++z) {
    const Eigen::Vector3i cell(1, 2, z);
    const float truth = Plane(field.CellCenter(cell));
    EXPECT_NEAR(field.CellValue(cell), truth, step);
    EXPECT_NEAR(field.CellDistance(cell), std::abs(truth), step);
    EXPECT_NEAR(field.Distance(field.CellCenter(cell)), std::abs(truth), step);
  }
  EXPECT_FLOAT_EQ(field.CellValue(Eigen::Vector3i(0, 0, -1)), kClamp);  // outside
}

TEST(DistanceField, SignedTrilinearReadsZeroOnTheSurfaceBetweenCenters) {
  const DistanceField field = SignedField(Plane);
  for (const V3& p : {V3(-0.6f, 0.4f, 3.1f), V3(0.1f, 1.6f, 2.9f), V3(-0.3f, 1.0f, 3.3f), V3(-0.3f, 1.1f, 3.6f)}) {
    V3 gradient;
    EXPECT_NEAR(field.DistanceTrilinear(p, &gradient), std::abs(Plane(p)), 1e-4f) << p.transpose();
    if (std::abs(Plane(p)) < 0.01f) continue;  // on it the gradient's sign is arbitrary
    // The gradient of |s|: away from the plane on both sides.
    EXPECT_TRUE(gradient.isApprox(V3(0.0f, 0.0f, Plane(p) < 0.0f ? -1.0f : 1.0f), 1e-3f)) << gradient.transpose();
  }
  // Unsigned, the same distances cannot: between the centres on either
  // side (0.35 m below, 0.15 m above) the plane reads 0.35 + 0.7 (0.15 - 0.35).
  std::vector<std::uint16_t> cells;
  for (int x = 0; x < kDims.x(); ++x) {
    for (int y = 0; y < kDims.y(); ++y) {
      for (int z = 0; z < kDims.z(); ++z) {
        const V3 center = kOrigin + (Eigen::Vector3i(x, y, z).cast<float>().array() + 0.5f).matrix() * 0.5f;
        cells.push_back(DistanceField::Quantise(std::abs(Plane(center)), kClamp));
      }
    }
  }
  const DistanceField unsigned_field(kOrigin, kDims, 0.5f, kClamp, std::move(cells), 1);
  EXPECT_NEAR(unsigned_field.DistanceTrilinear(V3(-0.3f, 1.0f, 3.1f), nullptr), 0.21f, 1e-4f);
}

// +-0.4 m on the two ends of a 0.5 m edge: no surface between them could
// make both ends that far from it (|a| + |b| > kMaxCrossingSum x 0.5 m), so
// the magnitudes are interpolated; +-0.3 m could be one, and is crossed.
float Jump(const V3& p) { return p.z() < 3.1f ? -0.4f : 0.4f; }
float Crossing(const V3& p) { return p.z() < 3.1f ? -0.3f : 0.3f; }

TEST(DistanceField, SignChangesNoSurfaceCanExplainInterpolateMagnitudes) {
  EXPECT_NEAR(SignedField(Jump).DistanceTrilinear(V3(-0.3f, 1.0f, 3.0f), nullptr), 0.4f, 1e-4f);
  EXPECT_NEAR(SignedField(Crossing).DistanceTrilinear(V3(-0.3f, 1.0f, 3.0f), nullptr), 0.0f, 1e-4f);
  EXPECT_NEAR(SignedField(Crossing).DistanceTrilinear(V3(-0.3f, 1.0f, 2.9f), nullptr), 0.12f, 1e-4f);
}

TEST(DistanceField, PlanesGiveTheSignedHeightAboveTheCellsPlane) {
  DistanceField field = LinearField();
  EXPECT_FALSE(field.HasPlanes());
  V3 normal;
  float offset = 0.0f;
  EXPECT_FALSE(field.PlaneAt(V3(-0.7f, 0.3f, 2.2f), &normal, &offset));  // no planes attached
  CellPlanes planes(field.CellCount());
  // Cell (0, 0, 0), centre (-0.75, 0.25, 2.25): a plane through (-0.75, 0.25, 2.15), normal +z.
  planes.Set(0, V3::UnitZ(), 0.1f);
  field.SetPlanes(std::move(planes));
  EXPECT_TRUE(field.HasPlanes());
  EXPECT_EQ(field.MemoryBytes(), DistanceField::kBlockCells * sizeof(std::uint16_t) +
                                     sizeof(std::shared_ptr<const DistanceField::Block>) +
                                     field.CellCount() * sizeof(std::uint32_t));
  const V3 p(-0.6f, 0.1f, 2.4f);  // same cell
  ASSERT_TRUE(field.PlaneAt(p, &normal, &offset));
  EXPECT_LT((normal - V3::UnitZ()).norm(), 1e-6f);
  EXPECT_NEAR(normal.dot(p) + offset, 2.4f - 2.15f, 1e-4f);
  EXPECT_FALSE(field.PlaneAt(V3(-0.2f, 0.3f, 2.2f), &normal, &offset));  // cell (1, 0, 0): none
  EXPECT_FALSE(field.PlaneAt(V3(-1.2f, 0.3f, 2.2f), &normal, &offset));  // outside the box
  EXPECT_THROW(field.SetPlanes(CellPlanes(7)), InputError);
}

// A field of 2 x 2 x 2 blocks of 0.1 m cells from the origin where only
// blocks (0, 0, 0) and (1, 1, 1) are stored: f(p) = 0.01 + 0.02 |p| there.
DistanceField TwoBlockField() {
  constexpr int kEdge = DistanceField::kBlockEdge;
  std::vector<std::shared_ptr<const DistanceField::Block>> blocks(8);
  for (const int b : {0, 7}) {
    auto block = std::make_shared<DistanceField::Block>(DistanceField::kBlockCells);
    const Eigen::Vector3i first = Eigen::Vector3i(b >> 2, (b >> 1) & 1, b & 1) * kEdge;
    for (int x = 0; x < kEdge; ++x) {
      for (int y = 0; y < kEdge; ++y) {
        for (int z = 0; z < kEdge; ++z) {
          const V3 center = ((first + Eigen::Vector3i(x, y, z)).cast<float>().array() + 0.5f).matrix() * 0.1f;
          (*block)[DistanceField::BlockOffset(x, y, z)] = DistanceField::Quantise(0.01f + 0.02f * center.norm(), 0.5f);
        }
      }
    }
    blocks[static_cast<std::size_t>(b)] = std::move(block);
  }
  return DistanceField(V3::Zero(), Eigen::Vector3i(2, 2, 2), 0.1f, 0.5f, std::move(blocks), 3);
}

TEST(DistanceField, BlocksNotStoredReadTheClamp) {
  const DistanceField field = TwoBlockField();
  EXPECT_EQ(field.dims(), Eigen::Vector3i(16, 16, 16));
  EXPECT_EQ(field.StoredBlocks(), 2u);
  const float step = 0.5f / 65535.0f;
  const V3 in_first(0.35f, 0.25f, 0.45f);    // cell (3, 2, 4) of block (0, 0, 0)
  const V3 in_last(1.25f, 0.95f, 1.55f);     // cell (12, 9, 15) of block (1, 1, 1)
  const V3 in_missing(1.25f, 0.25f, 0.45f);  // block (1, 0, 0)
  EXPECT_NEAR(field.Distance(in_first), 0.01f + 0.02f * in_first.norm(), step);
  EXPECT_NEAR(field.Distance(in_last), 0.01f + 0.02f * in_last.norm(), step);
  EXPECT_EQ(field.Distance(in_missing), 0.5f);
  EXPECT_EQ(field.CellDistance(Eigen::Vector3i(12, 2, 4)), 0.5f);
  V3 gradient = V3::Ones();
  EXPECT_EQ(field.DistanceTrilinear(in_missing, &gradient), 0.5f);
  EXPECT_TRUE(gradient.isZero());
}

TEST(DistanceField, TrilinearAcrossABlockBoundaryUsesBothBlocks) {
  const DistanceField field = TwoBlockField();
  // Between the centres x = 0.75 (block 0) and 0.85 (block 1, missing): a
  // quarter of the way, the missing side counts as the clamp.
  const V3 p(0.775f, 0.25f, 0.45f);
  const float inside = field.CellDistance(Eigen::Vector3i(7, 2, 4));
  V3 gradient;
  EXPECT_NEAR(field.DistanceTrilinear(p, &gradient), 0.75f * inside + 0.25f * 0.5f, 1e-5f);
  EXPECT_NEAR(gradient.x(), (0.5f - inside) / 0.1f, 1e-3f);
  // Inside one block the interpolation of the stored values is as before.
  const V3 q(0.3f, 0.3f, 0.3f);
  EXPECT_NEAR(field.DistanceTrilinear(q, nullptr), 0.01f + 0.02f * q.norm(), 2e-4f);
}

// The batch lookup is the single lookup, value for value: clusters of
// points (the particles of one scan point) in and across stencils, blocks,
// missing blocks, the box's edge and outside it; signed fields with jumping
// stencils too. The clusters also go in shuffled, so that stencils cached
// for one point are reused by later ones and evicted by stencils whose
// cells share their low bits.
TEST(DistanceField, BatchTrilinearEqualsSingleLookups) {
  std::mt19937 rng(5);
  std::uniform_real_distribution<float> box(-0.3f, 1.9f);
  std::normal_distribution<float> spread(0.0f, 0.04f);
  std::vector<V3> points;
  for (int cluster = 0; cluster < 300; ++cluster) {
    const V3 center(box(rng), box(rng), box(rng));
    for (int k = 0; k < 20; ++k) points.push_back(center + V3(spread(rng), spread(rng), spread(rng)));
  }
  points.push_back(V3(std::nanf(""), 0.5f, 0.5f));
  std::vector<V3> shuffled = points;
  std::shuffle(shuffled.begin(), shuffled.end(), rng);
  points.insert(points.end(), shuffled.begin(), shuffled.end());
  for (const DistanceField& field : {TwoBlockField(), SignedField(Jump), SignedField(Crossing), LinearField()}) {
    std::vector<float> batch(points.size());
    field.DistancesTrilinear(points.data(), static_cast<int>(points.size()), batch.data());
    for (std::size_t i = 0; i < points.size(); ++i) {
      ASSERT_EQ(batch[i], field.DistanceTrilinear(points[i], nullptr)) << points[i].transpose();
    }
  }
}

TEST(DistanceField, InconsistentConstructionIsAnInputError) {
  EXPECT_THROW(DistanceField(kOrigin, kDims, 0.5f, kClamp, std::vector<std::uint16_t>(59), 0), InputError);
  EXPECT_THROW(DistanceField(kOrigin, kDims, 0.0f, kClamp, std::vector<std::uint16_t>(60), 0), InputError);
  EXPECT_THROW(DistanceField(kOrigin, kDims, 0.5f, -1.0f, std::vector<std::uint16_t>(60), 0), InputError);
  EXPECT_THROW(DistanceField(std::numeric_limits<float>::infinity()), InputError);
  EXPECT_THROW(DistanceField(V3::Zero(), Eigen::Vector3i(2, 1, 1), 0.1f, 0.5f,
                             std::vector<std::shared_ptr<const DistanceField::Block>>(1), 0),
               InputError);
  std::vector<std::shared_ptr<const DistanceField::Block>> short_block{std::make_shared<DistanceField::Block>(10)};
  EXPECT_THROW(DistanceField(V3::Zero(), Eigen::Vector3i(1, 1, 1), 0.1f, 0.5f, short_block, 0), InputError);
}

}  // namespace
}  // namespace unimap::map
