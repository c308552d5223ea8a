// SPDX-License-Identifier: MIT
// ddfcam: heightsDigest, markComputedFrom, isStale.
#include <ddfcam/planning/model/field_freshness.h>

#include <bit>
#include <cstring>

namespace ddfcam::planning {
namespace {

// The finaliser of SplitMix64: a bijective mix in which every input bit reaches every output
// bit, so that folding word after word keeps nearby heights apart.
std::uint64_t mix(std::uint64_t x) {
  x ^= x >> 30;
  x *= 0xbf58476d1ce4e5b9ULL;
  x ^= x >> 27;
  x *= 0x94d049bb133111ebULL;
  return x ^ (x >> 31);
}

}  // namespace

std::uint64_t heightsDigest(std::span<const float> heights) {
  // Four independent lanes keep the multiplications pipelined; the position of every word
  // enters through its lane and the order of folding.
  std::uint64_t lanes[4] = {0x243f6a8885a308d3ULL, 0x13198a2e03707344ULL,
                            0xa4093822299f31d0ULL, 0x082efa98ec4e6c89ULL};
  const std::size_t n = heights.size();
  std::size_t i = 0;
  for (; i + 8 <= n; i += 8) {
    std::uint64_t words[4];
    std::memcpy(words, heights.data() + i, sizeof words);
    for (int l = 0; l < 4; ++l) lanes[l] = mix(lanes[l] ^ words[l]);
  }
  std::uint64_t tail = 0x9e3779b97f4a7c15ULL;
  for (; i < n; ++i) tail = mix(tail ^ std::bit_cast<std::uint32_t>(heights[i]));
  std::uint64_t digest = mix(static_cast<std::uint64_t>(n));
  for (std::uint64_t lane : lanes) digest = mix(digest ^ lane);
  return mix(digest ^ tail);
}

void markComputedFrom(ScalarField& field, const ddf::DisplacementField& part) {
  field.heightsDigest = heightsDigest(part.allHeights());
}

bool isStale(const ScalarField& field, std::uint64_t partHeightsDigest) {
  return field.heightsDigest && *field.heightsDigest != partHeightsDigest;
}

bool isStale(const ScalarField& field, const ddf::DisplacementField& part) {
  return field.heightsDigest && isStale(field, heightsDigest(part.allHeights()));
}

}  // namespace ddfcam::planning
