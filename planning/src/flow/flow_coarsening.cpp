// SPDX-License-Identifier: MIT
// ddfcam: aggregation multigrid pieces of the flow-field solve: levels, transfer, relaxation.
#include "flow_solver.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <utility>

namespace ddfcam::planning::detail {

namespace {

using Complex = std::complex<double>;
constexpr std::uint32_t kNone = std::numeric_limits<std::uint32_t>::max();

// Transport angle along adjacency entry s, from its point to the neighbour.
double entryPhase(const FieldProblem& fp, const FieldAdjacency& a, std::uint32_t s) {
  const double phi = fp.edges[a.edge[s]].phase;
  return a.isP[s] ? phi : -phi;
}

// Grows aggregate g from seed breadth first over unassigned points up to radius hops.
void grow(const FieldProblem& fp, const FieldAdjacency& a, std::uint32_t seed, int radius,
          std::uint32_t g, FieldLevel& out, std::vector<std::pair<std::uint32_t, int>>& queue) {
  queue.clear();
  queue.emplace_back(seed, 0);
  out.group[seed] = g;
  out.phase[seed] = 0.0;
  for (std::size_t head = 0; head < queue.size(); ++head) {
    const auto [p, depth] = queue[head];
    if (depth >= radius) continue;
    for (std::uint32_t s = a.start[p]; s < a.start[p + 1]; ++s) {
      const std::uint32_t q = a.other[s];
      if (out.group[q] != kNone) continue;
      out.group[q] = g;
      out.phase[q] = out.phase[p] + entryPhase(fp, a, s);
      queue.emplace_back(q, depth + 1);
    }
  }
}

// Seeds only where the seed and all its neighbours are free, so aggregates do not leave
// slivers; leftover points join a neighbouring aggregate, isolated ones become their own.
std::uint32_t aggregate(const FieldProblem& fp, const FieldAdjacency& a, int radius,
                        FieldLevel& out) {
  const std::uint32_t n = static_cast<std::uint32_t>(fp.target.size());
  out.group.assign(n, kNone);
  out.phase.assign(n, 0.0);
  std::uint32_t count = 0;
  std::vector<std::pair<std::uint32_t, int>> queue;
  for (std::uint32_t p = 0; p < n; ++p) {
    bool free = out.group[p] == kNone;
    for (std::uint32_t s = a.start[p]; s < a.start[p + 1] && free; ++s)
      free = out.group[a.other[s]] == kNone;
    if (free) grow(fp, a, p, radius, count++, out, queue);
  }
  for (bool changed = true; changed;) {
    changed = false;
    for (std::uint32_t p = 0; p < n; ++p)
      for (std::uint32_t s = a.start[p]; s < a.start[p + 1] && out.group[p] == kNone; ++s)
        if (out.group[a.other[s]] != kNone) {
          out.group[p] = out.group[a.other[s]];
          out.phase[p] = out.phase[a.other[s]] - entryPhase(fp, a, s);
          changed = true;
        }
  }
  for (std::uint32_t p = 0; p < n; ++p)
    if (out.group[p] == kNone) out.group[p] = count++, out.phase[p] = 0.0;
  return count;
}

struct Crossing {
  std::uint64_t key;
  std::uint32_t edge;
  double phase;  // coarse transport, oriented from the lower aggregate to the higher
  bool flipped;
};

}  // namespace

FieldAdjacency adjacencyOf(const FieldProblem& problem) {
  const std::size_t n = problem.target.size();
  FieldAdjacency a;
  a.start.assign(n + 1, 0);
  for (const FieldEdge& e : problem.edges) ++a.start[e.p + 1], ++a.start[e.q + 1];
  for (std::size_t p = 0; p < n; ++p) a.start[p + 1] += a.start[p];
  a.other.resize(a.start[n]);
  a.edge.resize(a.start[n]);
  a.isP.resize(a.start[n]);
  std::vector<std::uint32_t> fill(a.start.begin(), a.start.end() - 1);
  for (std::uint32_t i = 0; i < problem.edges.size(); ++i) {
    const FieldEdge& e = problem.edges[i];
    const std::uint32_t s = fill[e.p]++, t = fill[e.q]++;
    a.other[s] = e.q, a.edge[s] = i, a.isP[s] = 1;
    a.other[t] = e.p, a.edge[t] = i, a.isP[t] = 0;
  }
  return a;
}

// The fine edges between two different aggregates of @p level, sorted by aggregate pair (the
// lower aggregate first; phases rewritten from its side).
std::vector<Crossing> crossingsOf(const FieldProblem& problem, const FieldLevel& level) {
  std::vector<Crossing> crossings;
  for (std::uint32_t i = 0; i < problem.edges.size(); ++i) {
    const FieldEdge& e = problem.edges[i];
    std::uint32_t a = level.group[e.p], b = level.group[e.q];
    if (a == b) continue;
    const double phase = e.phase + level.phase[e.p] - level.phase[e.q];
    const bool flipped = a > b;
    if (flipped) std::swap(a, b);
    crossings.push_back({(std::uint64_t{a} << 32) | b, i, flipped ? -phase : phase, flipped});
  }
  std::sort(crossings.begin(), crossings.end(),
            [](const Crossing& x, const Crossing& y) { return x.key < y.key; });
  return crossings;
}

// Edges between two aggregates merge into one with the mean weight: a piecewise-constant
// field on the coarse graph then has about the fine field's Dirichlet energy (2D scale
// invariance), where the Galerkin sum would overweight smoothness by the aggregate diameter
// and slow the cycles down. Data weights add up exactly.
FieldLevel buildLevel(const FieldProblem& problem, int radius) {
  FieldLevel level;
  const std::uint32_t count = aggregate(problem, adjacencyOf(problem), radius, level);
  level.coarse.target.assign(count, 0.0);
  level.coarse.weight2.assign(count, 0.0);
  for (std::size_t p = 0; p < level.group.size(); ++p)
    level.coarse.weight2[level.group[p]] += problem.weight2[p];
  const std::vector<Crossing> crossings = crossingsOf(problem, level);
  level.link.assign(problem.edges.size(), kNone);
  level.factor.assign(problem.edges.size(), 0.0);
  for (std::size_t i = 0; i < crossings.size();) {
    std::size_t j = i;
    Complex sum = 0.0;
    double w2 = 0.0;
    for (; j < crossings.size() && crossings[j].key == crossings[i].key; ++j) {
      const double w = problem.edges[crossings[j].edge].weight2;
      sum += w * std::polar(1.0, crossings[j].phase), w2 += w;
    }
    const auto c = static_cast<std::uint32_t>(level.coarse.edges.size());
    level.coarse.edges.push_back({static_cast<std::uint32_t>(crossings[i].key >> 32),
                                  static_cast<std::uint32_t>(crossings[i].key & 0xffffffffu),
                                  w2 / static_cast<double>(j - i), std::arg(sum), 0.0,
                                  std::polar(1.0, std::arg(sum))});
    // The correction residual e^{i theta_q} (d_B - e^{i Phi} d_A + e^{-i theta_q} r), rewritten
    // from the lower aggregate's side when the fine edge runs the other way.
    for (std::size_t k = i; k < j; ++k) {
      const FieldEdge& e = problem.edges[crossings[k].edge];
      const Complex toQ = std::polar(1.0, -level.phase[e.q]);
      level.link[crossings[k].edge] = c;
      level.factor[crossings[k].edge] =
          crossings[k].flipped ? -std::polar(1.0, crossings[k].phase) * toQ : toQ;
      level.factor[crossings[k].edge] *= e.weight2 / w2;
    }
    i = j;
  }
  return level;
}

void restrictResidual(const FieldProblem& fine, const std::vector<Complex>& z, FieldLevel& level) {
  FieldProblem& coarse = level.coarse;
  std::fill(coarse.target.begin(), coarse.target.end(), Complex(0.0));
  for (std::size_t p = 0; p < z.size(); ++p)
    if (fine.weight2[p] > 0.0)
      coarse.target[level.group[p]] +=
          fine.weight2[p] * std::polar(1.0, -level.phase[p]) * (fine.target[p] - z[p]);
  for (std::size_t g = 0; g < coarse.target.size(); ++g)
    if (coarse.weight2[g] > 0.0) coarse.target[g] /= coarse.weight2[g];
  for (FieldEdge& e : coarse.edges) e.offset = 0.0;
  for (std::size_t i = 0; i < fine.edges.size(); ++i) {
    if (level.link[i] == std::numeric_limits<std::uint32_t>::max()) continue;
    const FieldEdge& e = fine.edges[i];
    const Complex r = z[e.q] - e.turn * z[e.p] + e.offset;
    coarse.edges[level.link[i]].offset += level.factor[i] * r;
  }
}

std::vector<Complex> prolongate(const FieldLevel& level, const std::vector<Complex>& delta) {
  std::vector<Complex> d(level.group.size());
  for (std::size_t p = 0; p < d.size(); ++p)
    d[p] = std::polar(1.0, level.phase[p]) * delta[level.group[p]];
  return d;
}

// Edge term for p as the edge's p: |z_p - e^{-i phi} (z_q + c)|^2; as its q: |z_q - (e^{i phi}
// z_p - c)|^2. Forward then backward keeps the smoother symmetric.
void relax(const FieldProblem& fp, const FieldAdjacency& a, std::vector<Complex>& z, int sweeps) {
  const std::size_t n = z.size();
  auto update = [&](std::size_t p) {
    Complex sum = fp.weight2[p] * fp.target[p];
    double diag = fp.weight2[p];
    for (std::uint32_t s = a.start[p]; s < a.start[p + 1]; ++s) {
      const FieldEdge& e = fp.edges[a.edge[s]];
      const Complex rot = a.isP[s] ? std::conj(e.turn) : e.turn;
      sum += e.weight2 *
             (a.isP[s] ? rot * (z[a.other[s]] + e.offset) : rot * z[a.other[s]] - e.offset);
      diag += e.weight2;
    }
    if (diag > 0.0) z[p] = sum / diag;
  };
  for (int sweep = 0; sweep < sweeps; ++sweep) {
    for (std::size_t p = 0; p < n; ++p) update(p);
    for (std::size_t p = n; p-- > 0;) update(p);
  }
}

// Damped Jacobi on the homogeneous operator: takes the jumps out of a piecewise-constant
// correction, as smoothed aggregation does.
void smoothCorrection(const FieldProblem& fp, const FieldAdjacency& a, std::vector<Complex>& d,
                      int passes) {
  constexpr double kOmega = 2.0 / 3.0;
  std::vector<Complex> next(d.size());
  for (int pass = 0; pass < passes; ++pass) {
    for (std::size_t p = 0; p < d.size(); ++p) {
      Complex sum = 0.0;
      double diag = fp.weight2[p];
      for (std::uint32_t s = a.start[p]; s < a.start[p + 1]; ++s) {
        const FieldEdge& e = fp.edges[a.edge[s]];
        sum += e.weight2 * (a.isP[s] ? std::conj(e.turn) : e.turn) * d[a.other[s]];
        diag += e.weight2;
      }
      next[p] = diag > 0.0 ? (1.0 - kOmega) * d[p] + kOmega * sum / diag : d[p];
    }
    d.swap(next);
  }
}

double bestStep(const FieldProblem& fp, const std::vector<Complex>& z,
                const std::vector<Complex>& d) {
  double slope = 0.0, curvature = 0.0;
  for (std::size_t p = 0; p < z.size(); ++p) {
    slope += fp.weight2[p] * (std::conj(z[p] - fp.target[p]) * d[p]).real();
    curvature += fp.weight2[p] * std::norm(d[p]);
  }
  for (const FieldEdge& e : fp.edges) {
    const Complex dr = d[e.q] - e.turn * d[e.p];
    slope += e.weight2 * (std::conj(z[e.q] - e.turn * z[e.p] + e.offset) * dr).real();
    curvature += e.weight2 * std::norm(dr);
  }
  return curvature > 0.0 ? -slope / curvature : 0.0;
}

}  // namespace ddfcam::planning::detail
