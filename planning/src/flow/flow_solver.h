// SPDX-License-Identifier: MIT
// ddfcam: internal least-squares solvers of the smoothed tool flow field (Ceres, multigrid).
#pragma once

#include <ddfcam/progress.h>

#include <complex>
#include <cstdint>
#include <vector>

namespace ddfcam::planning::detail {

/// One coupling of the smoothness term: weight2 |z_q - e^{i phase} z_p + offset|^2.
struct FieldEdge {
  std::uint32_t p = 0;
  std::uint32_t q = 0;
  double weight2 = 0.0;               ///< squared residual weight (lambda on the finest level)
  double phase = 0.0;                 ///< doubled transport angle from p to q, rad
  std::complex<double> offset = 0.0;  ///< 0 on the finest level; residuals on coarse levels
  std::complex<double> turn = 1.0;    ///< e^{i phase}
};

/// The quadratic problem min sum_p weight2_p |z_p - target_p|^2 + sum_e (edge terms) over one
/// complex (doubled-angle) unknown per point.
struct FieldProblem {
  std::vector<std::complex<double>> target;  ///< per point; any magnitude
  std::vector<double> weight2;               ///< per point; 0 = no data term
  std::vector<FieldEdge> edges;              ///< p != q, both < target.size()
};

/// How to solve a FieldProblem.
struct FieldSolveSettings {
  bool direct = false;        ///< one Ceres sparse Cholesky solve of the whole problem
  int directSolveLimit = 0;   ///< multilevel: the coarsest level has at most this many points
  int sweeps = 10;            ///< multilevel: symmetric Gauss-Seidel sweeps per finer level
  int iterations = 10;        ///< direct: largest number of Ceres iterations
  ProgressCallback progress;  ///< progress in [0, 1] of the solve; false cancels
};

/// @brief The least-squares solution z. Direct: Ceres from @p start (same size as the target).
/// Multilevel: nested iteration over an aggregation hierarchy (the coarsest level by Ceres,
/// each finer one from the prolongated, smoothed and optimally scaled coarse solution, then
/// Gauss-Seidel); @p start is not used.
/// @throws Cancelled if the progress callback asks to stop.
std::vector<std::complex<double>> solveFieldProblem(const FieldProblem& problem,
                                                    std::vector<std::complex<double>> start,
                                                    const FieldSolveSettings& settings);

/// @brief Ceres sparse Cholesky solve of @p problem from @p z, in place, with at most
/// @p iterations Levenberg-Marquardt iterations (the problem is linear: 1-2 suffice).
void solveWithCeres(const FieldProblem& problem, std::vector<std::complex<double>>& z,
                    const ProgressCallback& progress, int iterations);

/// One level of the aggregation hierarchy: the fine problem's points grouped into aggregates
/// (z_p = e^{i phase_p} Z_{group_p}) and the coarse problem's fixed structure.
struct FieldLevel {
  std::vector<std::uint32_t> group;          ///< per fine point: its aggregate
  std::vector<double> phase;                 ///< per fine point: transport from the seed, rad
  FieldProblem coarse;                       ///< weights and phases; targets/offsets per cycle
  std::vector<std::uint32_t> link;           ///< per fine edge: coarse edge or UINT32_MAX
  std::vector<std::complex<double>> factor;  ///< per fine edge: its residual's share of the offset
};

/// @brief Groups the points of @p problem into connected aggregates of graph radius @p radius
/// and builds the coarse structure (exact data weights, one merged edge per neighbouring pair).
FieldLevel buildLevel(const FieldProblem& problem, int radius);

/// @brief Sets the targets and offsets of @p level.coarse so that its solution is the best
/// piecewise-constant correction of the fine field @p z.
void restrictResidual(const FieldProblem& fine, const std::vector<std::complex<double>>& z,
                      FieldLevel& level);

/// @brief The fine field e^{i phase_p} delta_{group_p}.
std::vector<std::complex<double>> prolongate(const FieldLevel& level,
                                             const std::vector<std::complex<double>>& delta);

/// @brief The step alpha minimising the objective of @p problem at z + alpha d.
double bestStep(const FieldProblem& problem, const std::vector<std::complex<double>>& z,
                const std::vector<std::complex<double>>& d);

/// Both directions of every edge of a FieldProblem, in compressed rows per point.
struct FieldAdjacency {
  std::vector<std::uint32_t> start;  ///< offsets, size N + 1
  std::vector<std::uint32_t> other;  ///< the neighbour
  std::vector<std::uint32_t> edge;   ///< index into FieldProblem::edges
  std::vector<std::uint8_t> isP;     ///< the point is the edge's p (else its q)
};

/// @brief The adjacency of @p problem's edges.
FieldAdjacency adjacencyOf(const FieldProblem& problem);

/// @brief @p sweeps symmetric Gauss-Seidel sweeps on @p z (each point in turn takes the
/// minimiser of its own terms given its neighbours).
void relax(const FieldProblem& problem, const FieldAdjacency& adjacency,
           std::vector<std::complex<double>>& z, int sweeps);

/// @brief @p passes damped Jacobi passes of the homogeneous operator on correction @p d.
void smoothCorrection(const FieldProblem& problem, const FieldAdjacency& adjacency,
                      std::vector<std::complex<double>>& d, int passes);

}  // namespace ddfcam::planning::detail
