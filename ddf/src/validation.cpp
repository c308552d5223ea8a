// SPDX-License-Identifier: MIT
// ddfcam: validation of the DDF constraints 1-3.
#include <ddfcam/ddf/crust.h>
#include <ddfcam/ddf/crust_hash.h>
#include <ddfcam/ddf/validation.h>

#include <Eigen/Geometry>

#include <algorithm>
#include <array>
#include <cmath>
#include <sstream>

namespace ddfcam::ddf {
namespace {

std::string num(double x) {
  std::ostringstream s;
  s.precision(4);
  s << x;
  return s.str();
}

class IssueSink {
 public:
  IssueSink(ValidationReport& report, int maxIssues) : report_(report), max_(maxIssues) {}
  void add(int constraint, std::vector<int> vertices, std::vector<int> faces, std::string message) {
    if (static_cast<int>(report_.issues.size()) >= max_) {
      ++report_.suppressedIssues;
      return;
    }
    report_.issues.push_back({constraint, std::move(vertices), std::move(faces),
                              "constraint " + std::to_string(constraint) + ": " + message});
  }

 private:
  ValidationReport& report_;
  int max_;
};

/// Constraint 1; returns per face whether it holds.
std::vector<char> checkFrontSide(const DisplacementField& ddf, IssueSink& sink) {
  for (int v = 0; v < ddf.vertexCount(); ++v)
    if (!(ddf.vector(v).norm() > 0.0))
      sink.add(1, {v}, {}, "vertex " + std::to_string(v) + " has a zero (or invalid) vector");
  std::vector<char> valid(ddf.faceCount(), 1);
  for (int f = 0; f < ddf.faceCount(); ++f) {
    const auto& fv = ddf.faceVertices(f);
    const Vec3 e1 = ddf.position(fv[1]) - ddf.position(fv[0]);
    const Vec3 e2 = ddf.position(fv[2]) - ddf.position(fv[0]);
    const Vec3 n = e1.cross(e2);
    const double longest = std::max({e1.squaredNorm(), e2.squaredNorm(), (e2 - e1).squaredNorm()});
    if (!(n.norm() > 1e-12 * longest)) {
      valid[f] = 0;
      sink.add(1, {fv[0], fv[1], fv[2]}, {f},
               "face " + std::to_string(f) + " has zero area, so it has no front side");
      continue;
    }
    for (int v : fv) {
      const double c = ddf.vector(v).dot(n.normalized());
      if (c > 0.0) continue;
      valid[f] = 0;
      if (!(ddf.vector(v).norm() > 0.0)) continue;  // already reported as zero
      sink.add(1, {v}, {f},
               "the vector of vertex " + std::to_string(v) + " points to the back side of face " +
                   std::to_string(f) + " (v . n = " + num(c) + ")");
    }
  }
  return valid;
}

/// Constraint 2: coincident vertices (same class) whose vector differs from the class
/// representative's. Returns the classes for the non-adjacency test.
std::vector<int> checkCoincident(const DisplacementField& ddf, const ValidationParams& params,
                                 IssueSink& sink) {
  auto classes = coincidentVertexClasses(ddf, params.coincidentToleranceMm);
  for (int b = 0; b < ddf.vertexCount(); ++b) {
    const int a = classes[b];
    if (a == b) continue;
    const Vec3 &va = ddf.vector(a), &vb = ddf.vector(b);
    if ((va - vb).norm() <= params.vectorTolerance * std::max(va.norm(), vb.norm())) continue;
    sink.add(2, {a, b}, {},
             "vertices " + std::to_string(a) + " and " + std::to_string(b) +
                 " coincide but carry different vectors");
  }
  return classes;
}

/// Constraint 3 per face; returns the smallest crust height seen.
double checkCrustHeights(const DisplacementField& ddf, const ValidationParams& params,
                         const std::vector<char>& valid, IssueSink& sink) {
  const auto heights = allCrustHeights(ddf);
  double smallest = std::numeric_limits<double>::infinity();
  for (int f = 0; f < ddf.faceCount(); ++f) {
    if (!valid[f]) continue;
    smallest = std::min(smallest, heights[f].min());
    if (heights[f].min() >= params.minCrustHeight) continue;
    const auto& fv = ddf.faceVertices(f);
    sink.add(3, {fv[0], fv[1], fv[2]}, {f},
             "face " + std::to_string(f) + " has crust heights h0+ = " + num(heights[f].positive) +
                 ", h0- = " + num(heights[f].negative) + " below " + num(params.minCrustHeight) +
                 ": its stubbles cross in the crust");
  }
  return smallest;
}

void checkNonAdjacent(const DisplacementField& ddf, const std::vector<int>& classes,
                      IssueSink& sink) {
  const CrustHash hash(ddf);
  for (const auto& [s, t] : findAllCrustConflicts(ddf, hash, {}, classes))
    sink.add(3, {}, {s, t},
             "the +-1 crusts of faces " + std::to_string(s) + " and " + std::to_string(t) +
                 " intersect although the faces share no vertex");
}

}  // namespace

int ValidationReport::count(int c) const {
  return static_cast<int>(std::count_if(
      issues.begin(), issues.end(), [c](const ValidationIssue& i) { return i.constraint == c; }));
}

ValidationReport validate(const DisplacementField& ddf, const ValidationParams& params) {
  ValidationReport report;
  IssueSink sink(report, params.maxIssues);
  const auto valid = checkFrontSide(ddf, sink);
  const auto classes = checkCoincident(ddf, params, sink);
  report.minCrustHeight = checkCrustHeights(ddf, params, valid, sink);
  if (params.checkNonAdjacent && ddf.faceCount() > 0) checkNonAdjacent(ddf, classes, sink);
  return report;
}

}  // namespace ddfcam::ddf
