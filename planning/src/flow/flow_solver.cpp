// SPDX-License-Identifier: MIT
// ddfcam: Ceres solves of the flow-field least-squares problem: direct, and coarse to fine.
#include "flow_solver.h"

#include <ddfcam/error.h>

#include <ceres/ceres.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <ctime>
#include <deque>
#include <thread>

namespace ddfcam::planning::detail {

namespace {

using Complex = std::complex<double>;

// r = w (z - t): ties a point's doubled-angle vector to its target.
class DataCost final : public ceres::SizedCostFunction<2, 2> {
 public:
  DataCost(double weight, Complex target) : w_(weight), t_(target) {}
  bool Evaluate(double const* const* x, double* r, double** jac) const override {
    r[0] = w_ * (x[0][0] - t_.real());
    r[1] = w_ * (x[0][1] - t_.imag());
    if (jac && jac[0]) jac[0][0] = w_, jac[0][1] = 0.0, jac[0][2] = 0.0, jac[0][3] = w_;
    return true;
  }

 private:
  double w_;
  Complex t_;
};

// r = s (z_q - e^{i phi} z_p + o): the line at q against the line at p transported to q.
class EdgeCost final : public ceres::SizedCostFunction<2, 2, 2> {
 public:
  EdgeCost(double weight, Complex turn, Complex offset)
      : s_(weight), c_(turn.real()), n_(turn.imag()), o_(offset) {}
  bool Evaluate(double const* const* x, double* r, double** jac) const override {
    const double* zp = x[0];
    const double* zq = x[1];
    r[0] = s_ * (zq[0] - (c_ * zp[0] - n_ * zp[1]) + o_.real());
    r[1] = s_ * (zq[1] - (n_ * zp[0] + c_ * zp[1]) + o_.imag());
    if (jac && jac[0])
      jac[0][0] = -s_ * c_, jac[0][1] = s_ * n_, jac[0][2] = -s_ * n_, jac[0][3] = -s_ * c_;
    if (jac && jac[1]) jac[1][0] = s_, jac[1][1] = 0.0, jac[1][2] = 0.0, jac[1][3] = s_;
    return true;
  }

 private:
  double s_, c_, n_;
  Complex o_;
};

// Forwards Ceres iterations to the progress callback; a refusal aborts the solve.
class ProgressForwarder final : public ceres::IterationCallback {
 public:
  explicit ProgressForwarder(const ProgressCallback& progress) : progress_(progress) {}
  ceres::CallbackReturnType operator()(const ceres::IterationSummary& summary) override {
    if (progress_ && !progress_(std::min(1.0, 0.5 * (summary.iteration + 1.0)))) {
      cancelled_ = true;
      return ceres::SOLVER_ABORT;
    }
    return ceres::SOLVER_CONTINUE;
  }
  bool cancelled() const { return cancelled_; }

 private:
  const ProgressCallback& progress_;
  bool cancelled_ = false;
};

// The cost functions live in deques owned here, not one heap object per residual in Ceres.
struct CeresModel {
  std::deque<DataCost> data;
  std::deque<EdgeCost> edges;
  ceres::Problem problem{[] {
    ceres::Problem::Options o;
    o.cost_function_ownership = ceres::DO_NOT_TAKE_OWNERSHIP;
    o.disable_all_safety_checks = true;
    return o;
  }()};
};

void buildModel(const FieldProblem& fp, double* z, CeresModel& m) {
  const std::size_t n = fp.target.size();
  for (std::size_t p = 0; p < n; ++p) m.problem.AddParameterBlock(z + 2 * p, 2);
  for (std::size_t p = 0; p < n; ++p)
    if (fp.weight2[p] > 0.0) {
      m.data.emplace_back(std::sqrt(fp.weight2[p]), fp.target[p]);
      m.problem.AddResidualBlock(&m.data.back(), nullptr, z + 2 * p);
    }
  for (const FieldEdge& e : fp.edges) {
    m.edges.emplace_back(std::sqrt(e.weight2), e.turn, e.offset);
    m.problem.AddResidualBlock(&m.edges.back(), nullptr, z + 2 * e.p, z + 2 * e.q);
  }
}

// Aggregates of graph radius 2 hold about 15 raster points.
constexpr int kAggregateRadius = 2;
// Damped Jacobi passes that smooth a prolongated piecewise-constant solution.
constexpr int kJacobiPasses = 4;

// The hierarchy from the finest problem down to one of at most directSolveLimit points.
struct Hierarchy {
  std::vector<FieldLevel> levels;
  std::vector<FieldAdjacency> adjacency;  // per problem above each level
};

Hierarchy buildHierarchy(const FieldProblem& fine, std::size_t limit) {
  Hierarchy h;
  const FieldProblem* current = &fine;
  while (current->target.size() > limit) {
    FieldLevel level = buildLevel(*current, kAggregateRadius);
    if (level.coarse.target.size() * 2 > current->target.size()) break;  // does not coarsen
    h.adjacency.push_back(adjacencyOf(*current));
    h.levels.push_back(std::move(level));
    current = &h.levels.back().coarse;
  }
  return h;
}

const FieldProblem& problemAt(const FieldProblem& fine, Hierarchy& h, std::size_t i) {
  return i == 0 ? fine : h.levels[i - 1].coarse;
}

// Nested iteration: the coarse problem's solution, prolongated, smoothed and scaled, then
// relaxed on the fine level; each coarse level is solved the same way down to Ceres.
void nested(const FieldProblem& fine, Hierarchy& h, std::size_t i, std::vector<Complex>& z,
            const FieldSolveSettings& s) {
  const FieldProblem& fp = problemAt(fine, h, i);
  if (i == h.levels.size()) {
    z = fp.target;  // a start near the data keeps Ceres off its gradient-tolerance exit
    solveWithCeres(fp, z, s.progress, 10);
    return;
  }
  std::fill(z.begin(), z.end(), Complex(0.0));
  restrictResidual(fp, z, h.levels[i]);
  std::vector<Complex> coarse(h.levels[i].coarse.target.size(), 0.0);
  nested(fine, h, i + 1, coarse, s);
  std::vector<Complex> d = prolongate(h.levels[i], coarse);
  smoothCorrection(fp, h.adjacency[i], d, kJacobiPasses);
  const double alpha = bestStep(fp, z, d);
  for (std::size_t p = 0; p < z.size(); ++p) z[p] = alpha * d[p];
  relax(fp, h.adjacency[i], z, s.sweeps);
  reportProgress(s.progress, 1.0 - 0.5 * static_cast<double>(i) / h.levels.size());
}

std::vector<Complex> solveMultilevel(const FieldProblem& fp, const FieldSolveSettings& s) {
  Hierarchy h = buildHierarchy(fp, static_cast<std::size_t>(std::max(s.directSolveLimit, 1)));
  std::vector<Complex> z(fp.target.size(), 0.0);
  nested(fp, h, 0, z, s);
  return z;
}

}  // namespace

void solveWithCeres(const FieldProblem& fp, std::vector<Complex>& z,
                    const ProgressCallback& progress, int iterations) {
  CeresModel model;
  buildModel(fp, reinterpret_cast<double*>(z.data()), model);  // complex<double> is double[2]
  ceres::Solver::Options o;
  o.linear_solver_type = ceres::SPARSE_NORMAL_CHOLESKY;
  o.max_num_iterations = iterations;
  // The problem is linear: a huge trust region makes the first step the Gauss-Newton one.
  o.initial_trust_region_radius = 1e12;
  // Data weights can be tiny (anisotropy weighting on umbilic parts): no absolute exits.
  o.gradient_tolerance = 0.0;
  o.function_tolerance = 1e-12;
  o.num_threads = static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
  o.logging_type = ceres::SILENT;
  o.minimizer_progress_to_stdout = false;
  ProgressForwarder forwarder(progress);
  o.callbacks.push_back(&forwarder);
  ceres::Solver::Summary summary;
  ceres::Solve(o, &model.problem, &summary);
  if (forwarder.cancelled()) throw Cancelled();
}

std::vector<Complex> solveFieldProblem(const FieldProblem& problem, std::vector<Complex> start,
                                       const FieldSolveSettings& settings) {
  if (problem.target.empty()) return start;
  if (settings.direct) {
    solveWithCeres(problem, start, settings.progress, settings.iterations);
    return start;
  }
  return solveMultilevel(problem, settings);
}

}  // namespace ddfcam::planning::detail
