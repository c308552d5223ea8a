// SPDX-License-Identifier: MIT
// Tests of stale-field detection: the heights digest against exact comparison of the heights.
#include <ddfcam/ddf/analytic_generators.h>
#include <ddfcam/planning/model/builtin_fields.h>
#include <ddfcam/planning/model/field_freshness.h>

#include <gtest/gtest.h>

#include <bit>
#include <cstdint>
#include <random>
#include <set>
#include <vector>

namespace ddfcam::planning {
namespace {

// Every single-bit change of every height, on a raster of a size that exercises both the
// lanes and the tail, changes the digest; equal heights give equal digests.
TEST(FieldFreshness, EverySingleBitChangeOfAHeightChangesTheDigest) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<float> h(-1.0f, 1.0f);
  std::vector<float> heights(21);
  for (float& value : heights) value = h(rng);
  const std::uint64_t reference = heightsDigest(heights);
  EXPECT_EQ(heightsDigest(std::vector<float>(heights)), reference);
  std::set<std::uint64_t> seen{reference};
  for (std::size_t i = 0; i < heights.size(); ++i)
    for (int bit = 0; bit < 32; ++bit) {
      std::vector<float> changed = heights;
      changed[i] = std::bit_cast<float>(std::bit_cast<std::uint32_t>(changed[i]) ^ (1u << bit));
      const std::uint64_t digest = heightsDigest(changed);
      EXPECT_NE(digest, reference) << "height " << i << " bit " << bit;
      seen.insert(digest);
    }
  // No two of the 672 changed rasters collide either.
  EXPECT_EQ(seen.size(), 1 + heights.size() * 32);
}

TEST(FieldFreshness, SwappedHeightsAndOtherSizesChangeTheDigest) {
  const std::vector<float> heights = {0.1f, 0.2f, 0.3f, 0.4f, 0.5f, 0.6f, 0.7f, 0.8f, 0.9f};
  std::vector<float> swapped = heights;
  std::swap(swapped[0], swapped[5]);
  EXPECT_NE(heightsDigest(swapped), heightsDigest(heights));
  std::vector<float> longer = heights;
  longer.push_back(0.0f);
  EXPECT_NE(heightsDigest(longer), heightsDigest(heights));
  EXPECT_NE(heightsDigest(std::vector<float>{0.0f}), heightsDigest(std::vector<float>{-0.0f}));
  EXPECT_NE(heightsDigest({}), heightsDigest(std::vector<float>{0.0f}));
}

TEST(FieldFreshness, AFieldIsStaleOnceThePartHeightsChangeAndFreshWhenTheyReturn) {
  auto gen = ddf::planePatch({.cellsX = 3, .cellsY = 2, .m = 5, .planeZMm = 0.4});
  ddf::DisplacementField& part = gen.ddf;
  ScalarField field = heightMmField(part);
  EXPECT_FALSE(isStale(field, part)) << "a field without a digest is never stale";
  markComputedFrom(field, part);
  EXPECT_FALSE(isStale(field, part));
  const std::vector<float> before = part.allHeights();
  part.allHeights()[17] -= 0.01f;
  EXPECT_TRUE(isStale(field, part));
  EXPECT_TRUE(isStale(field, heightsDigest(part.allHeights())));
  ScalarField recomputed = heightMmField(part);
  markComputedFrom(recomputed, part);
  EXPECT_FALSE(isStale(recomputed, part));
  part.allHeights() = before;  // an undo
  EXPECT_FALSE(isStale(field, part));
  EXPECT_TRUE(isStale(recomputed, part));
}

}  // namespace
}  // namespace ddfcam::planning
