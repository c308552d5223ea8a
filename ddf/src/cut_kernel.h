// SPDX-License-Identifier: MIT
// ddfcam (private): per-(support, tool) triangle coefficients and row kernels of the DDF depth
// buffer (dissertation sec. 5.2).
#pragma once

#include <ddfcam/ddf/support_mesh.h>

#include <array>
#include <cstddef>
#include <optional>
#include <utility>

namespace ddfcam::ddf::detail {

/// @brief A linear form over the raster of one face: value(i, k) = base + k dk + i di.
struct LinearForm {
  double base = 0.0;
  double dk = 0.0;
  double di = 0.0;
  double at(double i, double k) const { return base + k * dk + i * di; }
};

/// @brief Corners and vectors of one support face in raster order.
struct FaceCorners {
  std::array<Vec3, 3> p;
  std::array<Vec3, 3> v;
};

/// @brief V-shooting of a whole raster at one tool triangle as linear forms (eq. 5.1/5.2 in
/// the translation-invariant form): h = N / D and lambda_j = A_j + h B_j.
struct PairForms {
  LinearForm n, d;
  std::array<LinearForm, 3> a, b;
};

/// @brief What a kernel does with a hit.
enum class KernelMode {
  Cut,  ///< entry hits only (stubble enters the tool), h = min(h, max(hit, -1))
  Fill  ///< hits of either orientation with |hit| <= 1, keep the one nearest the support
};

/// @brief Coefficients for face @p s against tool triangle (q1, q2, q3) at raster steps @p n.
/// nullopt when the tool triangle is degenerate or, in Cut mode, faces away from every vector.
std::optional<PairForms> makePairForms(const FaceCorners& s, const Vec3& q1, const Vec3& q2,
                                       const Vec3& q3, int n, KernelMode mode);

/// @brief The forms of one row in float for the kernel: value(i) = base + i step.
struct RowForms {
  float nb, ns, db, ds;
  std::array<float, 3> ab, as, bb, bs;
};

RowForms rowForms(const PairForms& forms, int k);

/// @brief Index ranges [first, last] of row @p k (points 0..rowLength-1) outside which no
/// raster point can be hit, from the roots of the linear and quadratic conditions (sec. 5.2).
/// Returns the number of ranges written to @p out (0..4).
/// @p tol is the kernel's barycentric tolerance.
int rowIntervals(const PairForms& forms, int k, int rowLength, KernelMode mode, double tol,
                 std::array<std::pair<int, int>, 5>& out);

/// @brief Counters of one kernel run.
struct KernelCounts {
  std::size_t lowered = 0;  ///< heights that changed
  std::size_t clamped = 0;  ///< hits below the crust bottom, clamped to -1
  std::size_t hits = 0;     ///< stubbles that meet the tool triangle at a height that matters
};

/// @brief Cut mode kernel on heights[first..last] of one row; counts.hits is only maintained
/// when @p countHits is set.
void cutRow(float* heights, int first, int last, const RowForms& row, float lambdaTolerance,
            KernelCounts& counts, bool countHits = true);
/// @brief Fill mode kernel on heights[first..last] of one row; heights hold NaN where no hit
/// was found yet.
void fillRow(float* heights, int first, int last, const RowForms& row, float lambdaTolerance,
             KernelCounts& counts);

}  // namespace ddfcam::ddf::detail
