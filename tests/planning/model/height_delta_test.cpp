// SPDX-License-Identifier: MIT
// Tests of the compact height difference used for undo.
#include <ddfcam/error.h>
#include <ddfcam/planning/model/height_delta.h>

#include <gtest/gtest.h>

#include <bit>
#include <cstdint>
#include <limits>
#include <random>
#include <set>

#include "../../support/test_meshes.h"

namespace ddfcam::planning {
namespace {

/// 100 faces (a 5 x 10 grid) at m = 17: 153 heights per face, 15,300 in all.
ddf::DisplacementField smallField(std::mt19937& rng, int m = 17) {
  const auto mesh = test::gridMesh(5, 10);
  ddf::DisplacementField ddf(mesh, test::constantVectors(mesh), m);
  std::uniform_real_distribution<float> u(-1.0f, 1.0f);
  for (float& h : ddf.allHeights()) h = u(rng);
  for (std::size_t i = 0; i < ddf.allHeights().size(); i += 7) ddf.allHeights()[i] = 0.0f;
  return ddf;
}

std::vector<std::uint32_t> bits(const std::vector<float>& values) {
  std::vector<std::uint32_t> out;
  for (float v : values) out.push_back(std::bit_cast<std::uint32_t>(v));
  return out;
}

TEST(HeightDelta, ApplyAndRevertRoundTripBitExactly) {
  std::mt19937 rng(11);
  for (int trial = 0; trial < 20; ++trial) {
    ddf::DisplacementField ddf = smallField(rng);
    const std::vector<float> before = ddf.allHeights();
    std::vector<float> after = before;
    // Edits of every kind the bits can tell apart: values, NaN, one ulp, signed zero.
    std::uniform_int_distribution<std::size_t> at(0, after.size() - 1);
    const int edits = 1 + trial * 3;
    for (int e = 0; e < edits; ++e) {
      const std::size_t i = at(rng);
      switch (e % 4) {
        case 0:
          after[i] = -0.5f;
          break;
        case 1:
          after[i] = std::numeric_limits<float>::quiet_NaN();
          break;
        case 2:
          after[i] = std::nextafter(after[i], 2.0f);
          break;
        default:
          after[i] = -after[i];  // 0 -> -0 on the zeros smallField() plants
          break;
      }
    }
    // Oracle: the faces holding a value whose bits differ (a later edit may undo an earlier).
    std::set<std::size_t> changedFaces;
    for (std::size_t i = 0; i < after.size(); ++i)
      if (std::bit_cast<std::uint32_t>(before[i]) != std::bit_cast<std::uint32_t>(after[i]))
        changedFaces.insert(i / ddf.pointsPerFace());
    const HeightDelta delta = HeightDelta::between(before, after, ddf.pointsPerFace());
    EXPECT_EQ(delta.changedFaces(), changedFaces.size());
    delta.apply(ddf);
    EXPECT_EQ(bits(ddf.allHeights()), bits(after));
    delta.revert(ddf);
    EXPECT_EQ(bits(ddf.allHeights()), bits(before));
    delta.apply(ddf);
    EXPECT_EQ(bits(ddf.allHeights()), bits(after));
  }
}

TEST(HeightDelta, SignedZeroAndNanPayloadCountAsChanges) {
  std::vector<float> before(30, 0.0f), after = before;
  after[4] = -0.0f;
  after[25] = std::bit_cast<float>(std::uint32_t{0x7fc00001});
  before[25] = std::bit_cast<float>(std::uint32_t{0x7fc00002});
  const HeightDelta delta = HeightDelta::between(before, after, 10);
  EXPECT_EQ(delta.changedFaces(), 2u);
  EXPECT_TRUE(HeightDelta::between(before, before, 10).empty());
}

TEST(HeightDelta, MemoryIsProportionalToTheChangedFaces) {
  std::mt19937 rng(3);
  ddf::DisplacementField ddf = smallField(rng);
  const std::vector<float> before = ddf.allHeights();
  std::vector<float> after = before;
  after[17 * ddf.pointsPerFace() + 5] += 0.25f;
  after[80 * ddf.pointsPerFace() + 100] -= 0.25f;
  const HeightDelta delta = HeightDelta::between(before, after, ddf.pointsPerFace());
  ASSERT_EQ(delta.changedFaces(), 2u);
  const std::size_t fullCopy = before.size() * sizeof(float);
  EXPECT_LT(delta.memoryBytes(), fullCopy / 20) << "2 of 100 faces should cost < 5 %";
  // Both versions of both faces are held.
  EXPECT_GE(delta.memoryBytes(), 2 * 2 * ddf.pointsPerFace() * sizeof(float));
  EXPECT_LT(HeightDelta::between(before, before, ddf.pointsPerFace()).memoryBytes(), 256u);
}

TEST(HeightDelta, LayoutMismatchIsRejected) {
  std::mt19937 rng(5);
  ddf::DisplacementField ddf = smallField(rng);
  std::vector<float> after = ddf.allHeights();
  after[0] = 2.0f;
  const HeightDelta delta = HeightDelta::between(ddf.allHeights(), after, ddf.pointsPerFace());
  ddf::DisplacementField finer = smallField(rng, 9);
  EXPECT_THROW(delta.apply(finer), InvalidInput);
  EXPECT_THROW(delta.revert(finer), InvalidInput);
  const auto fewer = test::gridMesh(5, 9);
  ddf::DisplacementField smaller(fewer, test::constantVectors(fewer), 17);
  EXPECT_THROW(delta.apply(smaller), InvalidInput);
  const std::vector<float> a(30, 0.0f), b(31, 0.0f);
  EXPECT_THROW(HeightDelta::between(a, b, 10), InvalidInput);
  EXPECT_THROW(HeightDelta::between(a, a, 7), InvalidInput);
  EXPECT_THROW(HeightDelta::between(a, a, 0), InvalidInput);
  // A default delta was made for no field and changes nothing.
  const std::vector<float> untouched = ddf.allHeights();
  HeightDelta{}.apply(ddf);
  EXPECT_TRUE(ddf.allHeights() == untouched);
}

}  // namespace
}  // namespace ddfcam::planning
