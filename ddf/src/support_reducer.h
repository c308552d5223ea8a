// SPDX-License-Identifier: MIT
// ddfcam (private): the state of the support reduction (sec. 6.1-6.2) and its steps; setup and
// sweeps in support_reduction.cpp, one tentative contraction in reduction_contraction.cpp.
#pragma once

#include "reduction_constraints.h"
#include "reduction_items.h"
#include "reduction_topology.h"

#include <ddfcam/ddf/support_reduction.h>

#include <span>
#include <vector>

namespace ddfcam::ddf::detail {

/// @brief Why a tentative contraction was refused.
enum class Refusal {
  None,
  Skipped,  // refused before and nothing around it changed since
  Boundary,
  Critical,
  EdgeLength,
  UniqueProjection,
  RayCoverage,
  Angle,
  InputCoverage,
  Containment,
  CrustConflict  // counted as UniqueProjection: a non-adjacent crust is met
};

/// @brief Lengths tried for a new vector whose crust meets a non-adjacent one: the cap, half
/// of it, a quarter.
inline constexpr int kLengthTries = 3;

/// @brief A tentative contraction: the region, the new vertex and the modified faces' new state.
struct Tentative {
  ContractionRegion region;
  Vec3 point = Vec3::Zero();
  Vec3 vector = Vec3::Zero();
  std::vector<NewFace> faces;               // parallel to region.modified
  std::vector<std::array<int, 3>> faceIds;  // their vertices after the collapse (a -> b)
  std::vector<FaceItems> items;             // parallel to region.modified
  std::vector<int> candidates;              // items offered to the re-assignment
  std::vector<int> touchedItems;            // items whose hit count the contraction changes
  std::vector<Refusal> why;                 // per new face, its refusal by rasterNewFaces

  /// @brief Empties the tentative for the next edge; the item buffers keep their capacity.
  void reset() { candidates.clear(), touchedItems.clear(); }
};

/// @brief The reduction's state: the shrinking support with its vectors, the item buffer of
/// every face, a hit counter per input triangle and the crust box hash.
class SupportReducer {
 public:
  SupportReducer(const SupportMesh& input, std::span<const Vec3> vectors,
                 std::span<const int> labels, const SupportReductionParams& params);
  SupportReductionResult run();

 private:
  void initialVectors(std::span<const Vec3> vectors);
  void initialItems();
  void rebuildHash();
  FaceCorners corners(int face) const;
  bool sweep();
  Refusal attempt(SupportMesh::EdgeHandle eh);
  bool unchangedSince(const ContractionRegion& r, long since) const;
  Refusal placeNewVertex(Tentative& t);
  Refusal checkEdgeLengths(const Tentative& t) const;
  Refusal evaluate(Tentative& t, double capScale);
  bool buildFaces(Tentative& t) const;
  Refusal chooseVector(Tentative& t, double capScale);
  void gatherCandidates(Tentative& t);
  Refusal rasterNewFaces(Tentative& t) const;
  Refusal checkInputCoverage(Tentative& t);
  void resetDelta(Tentative& t);
  bool contained(const Tentative& t);
  bool crustsFree(const Tentative& t);
  void commit(Tentative& t);
  void count(Refusal r);
  SupportReductionResult result() const;

  const SupportReductionParams& params_;
  SupportMesh mesh_;
  std::vector<Vec3> vectors_;
  std::vector<int> labels_;
  std::vector<char> kept_;
  detail::ReductionItems items_;
  // Per face its item set only: the per-point hits are needed just while a tentative face is
  // checked, so they live in scratch_ (for 10^4 input faces they would take hundreds of MB).
  std::vector<FaceItems> faceItems_;
  std::vector<int> hitCount_;
  std::vector<int> delta_;
  std::vector<unsigned> itemStamp_;
  unsigned stampNow_ = 0;
  std::vector<unsigned> vertexStamp_;
  unsigned vertexStampNow_ = 0;
  bool hasLabels_ = false;
  detail::CrustBoxHash hash_;
  std::vector<long> faceVersion_;
  std::vector<long> edgeRefusedAt_;
  std::vector<char> edgeModified_;
  long clock_ = 0;
  double minCosine_ = 0.0;
  SupportReductionReport report_;
  int attempts_ = 0;
  // Reused by every attempt: the per-point buffers of the new faces would otherwise be
  // allocated and faulted in again for each of the ~10^4 tentative contractions.
  Tentative scratch_;
};

}  // namespace ddfcam::ddf::detail
