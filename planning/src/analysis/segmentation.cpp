// SPDX-License-Identifier: MIT
// ddfcam: automatic segmentation of a part by curvature type and tool-size class (sec. 8.1).
#include <ddfcam/error.h>
#include <ddfcam/planning/analysis/segmentation.h>

#include "hsv_color.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <numeric>
#include <set>
#include <sstream>
#include <tuple>

namespace ddfcam::planning {
namespace {

void checkLayout(const ddf::DisplacementField& ddf, const CurvatureField& curvature) {
  const std::size_t expected = ddf.allHeights().size();
  if (ddf.faceCount() == 0) throw InvalidInput("segmentation: the DDF has no faces");
  if (curvature.kMax.size() != expected || curvature.kMin.size() != expected)
    throw InvalidInput("segmentation: curvature field has " +
                       std::to_string(curvature.kMax.size()) + " k_max and " +
                       std::to_string(curvature.kMin.size()) + " k_min values, expected " +
                       std::to_string(expected));
}

// Most frequent label among each face's raster points (ties: the lowest label).
std::vector<int> faceMajority(const ddf::DisplacementField& ddf, const std::vector<int>& labels,
                              int labelCount) {
  const std::size_t perFace = ddf.pointsPerFace();
  std::vector<int> out(ddf.faceCount());
  std::vector<int> counts(labelCount);
  for (int f = 0; f < ddf.faceCount(); ++f) {
    std::fill(counts.begin(), counts.end(), 0);
    for (std::size_t l = 0; l < perFace; ++l) ++counts[labels[f * perFace + l]];
    out[f] = static_cast<int>(std::max_element(counts.begin(), counts.end()) - counts.begin());
  }
  return out;
}

// HSV -> RGB with the hue stepped by the golden ratio, so neighbouring indices differ clearly
// and no two indices share a hue.
std::array<float, 3> regionColor(int index) {
  return detail::hsvColor(0.08 + 0.6180339887498949 * index, 0.6, 0.92);
}

// A connected set of faces while merging.
struct Component {
  int label = 0;
  int faces = 0;
  double areaMm2 = 0.0;
  int firstFace = 0;
  std::map<int, double> boundaryMm;  // neighbouring component -> shared edge length
};

// Connected components of equally labelled faces; returns the component of every face.
std::vector<int> labelComponents(const ddf::DisplacementField& ddf,
                                 const std::vector<int>& faceLabels, std::vector<Component>& out) {
  const auto& mesh = ddf.support();
  std::vector<int> component(ddf.faceCount(), -1);
  std::vector<int> stack;
  for (int seed = 0; seed < ddf.faceCount(); ++seed) {
    if (component[seed] >= 0) continue;
    const int id = static_cast<int>(out.size());
    out.emplace_back();
    out.back().label = faceLabels[seed];
    out.back().firstFace = seed;
    component[seed] = id;
    stack.assign(1, seed);
    while (!stack.empty()) {
      const int f = stack.back();
      stack.pop_back();
      for (auto nb : mesh.ff_range(mesh.face_handle(f))) {
        if (component[nb.idx()] >= 0 || faceLabels[nb.idx()] != faceLabels[seed]) continue;
        component[nb.idx()] = id;
        stack.push_back(nb.idx());
      }
    }
  }
  return component;
}

void measureComponents(const ddf::DisplacementField& ddf, const std::vector<int>& component,
                       std::vector<Component>& comps) {
  for (int f = 0; f < ddf.faceCount(); ++f) {
    const auto& v = ddf.faceVertices(f);
    const ddf::Vec3 e1 = ddf.position(v[1]) - ddf.position(v[0]);
    const ddf::Vec3 e2 = ddf.position(v[2]) - ddf.position(v[0]);
    Component& c = comps[component[f]];
    ++c.faces;
    c.areaMm2 += 0.5 * e1.cross(e2).norm();
  }
  const auto& mesh = ddf.support();
  for (auto e : mesh.edges()) {
    if (mesh.is_boundary(e)) continue;
    const int a = component[mesh.face_handle(e.h0()).idx()];
    const int b = component[mesh.face_handle(e.h1()).idx()];
    if (a == b) continue;
    const double length = mesh.calc_edge_length(e);
    comps[a].boundaryMm[b] += length;
    comps[b].boundaryMm[a] += length;
  }
}

// The neighbour of component @p a with the longest shared boundary (ties: more faces, then
// the lower first face).
int strongestNeighbour(const std::vector<Component>& comps, int a) {
  const auto weaker = [&](const auto& x, const auto& y) {
    const Component &cx = comps[x.first], &cy = comps[y.first];
    return std::tuple(x.second, cx.faces, -cx.firstFace) <
           std::tuple(y.second, cy.faces, -cy.firstFace);
  };
  const auto& boundary = comps[a].boundaryMm;
  return std::max_element(boundary.begin(), boundary.end(), weaker)->first;
}

// Moves component @p a into @p b, rerouting a's boundaries to b.
void absorb(std::vector<Component>& comps, int a, int b) {
  Component &from = comps[a], &into = comps[b];
  for (const auto& [c, length] : from.boundaryMm) {
    if (c == b) continue;
    into.boundaryMm[c] += length;
    comps[c].boundaryMm.erase(a);
    comps[c].boundaryMm[b] += length;
  }
  into.boundaryMm.erase(a);
  into.faces += from.faces;
  into.areaMm2 += from.areaMm2;
  into.firstFace = std::min(into.firstFace, from.firstFace);
  from.boundaryMm.clear();
}

// Merges small components smallest first; returns the surviving component of each one.
std::vector<int> mergeSmall(std::vector<Component>& comps, const SegmentationParams& params) {
  const auto isSmall = [&](int id) {
    const Component& c = comps[id];
    return (c.faces < params.minFaces || c.areaMm2 < params.minAreaMm2) && !c.boundaryMm.empty();
  };
  using Key = std::tuple<int, double, int, int>;
  const auto key = [&](int id) {
    return Key{comps[id].faces, comps[id].areaMm2, comps[id].firstFace, id};
  };
  std::set<Key> queue;
  for (int id = 0; id < static_cast<int>(comps.size()); ++id)
    if (isSmall(id)) queue.insert(key(id));
  std::vector<int> parent(comps.size());
  std::iota(parent.begin(), parent.end(), 0);
  const std::size_t initial = queue.size();
  while (!queue.empty()) {
    const int a = std::get<3>(*queue.begin());
    queue.erase(queue.begin());
    const int b = strongestNeighbour(comps, a);
    queue.erase(key(b));  // b's key changes below
    absorb(comps, a, b);
    parent[a] = b;
    if (isSmall(b)) queue.insert(key(b));
    if (params.progress && queue.size() % 256 == 0)
      reportProgress(params.progress, 0.5 + 0.45 * (1.0 - double(queue.size()) / initial));
  }
  for (int& root : parent)
    while (parent[root] != root) root = parent[root];
  return parent;
}

void checkSegmentInput(const ddf::DisplacementField& ddf, const std::vector<int>& faceLabels,
                       const std::vector<std::string>& labelNames,
                       const SegmentationParams& params) {
  if (ddf.faceCount() == 0) throw InvalidInput("segmentation: the DDF has no faces");
  if (faceLabels.size() != static_cast<std::size_t>(ddf.faceCount()))
    throw InvalidInput("segmentation: " + std::to_string(faceLabels.size()) +
                       " face labels, expected " + std::to_string(ddf.faceCount()));
  for (std::size_t f = 0; f < faceLabels.size(); ++f)
    if (faceLabels[f] < 0 || faceLabels[f] >= static_cast<int>(labelNames.size()))
      throw InvalidInput("segmentation: face " + std::to_string(f) + " has label " +
                         std::to_string(faceLabels[f]) + ", expected 0.." +
                         std::to_string(static_cast<int>(labelNames.size()) - 1));
  if (params.minFaces < 1)
    throw InvalidInput("segmentation: minFaces " + std::to_string(params.minFaces) +
                       " must be >= 1");
  if (!(params.minAreaMm2 >= 0.0)) throw InvalidInput("segmentation: minAreaMm2 must be >= 0");
}

// params with the progress of a sub-step mapped to [from, to] of the caller's range.
SegmentationParams subRange(const SegmentationParams& params, double from, double to) {
  SegmentationParams sub = params;
  if (params.progress)
    sub.progress = [&params, from, to](double x) {
      return params.progress(from + (to - from) * x);
    };
  return sub;
}

}  // namespace

const char* curvatureTypeName(CurvatureType type) {
  switch (type) {
    case CurvatureType::Flat:
      return "flat";
    case CurvatureType::Convex:
      return "convex";
    case CurvatureType::Concave:
      return "concave";
    case CurvatureType::Saddle:
      return "saddle";
  }
  return "unknown";
}

std::vector<std::uint8_t> classifyCurvature(const CurvatureField& curvature,
                                            const CurvatureTypeParams& params) {
  const double zero = params.flatCurvaturePerMm;
  if (!(zero >= 0.0) || !std::isfinite(zero))
    throw InvalidInput("classifyCurvature: flatCurvaturePerMm must be finite and >= 0");
  std::vector<std::uint8_t> out(curvature.size());
  for (std::size_t p = 0; p < out.size(); ++p) {
    // NaN compares false, so a point without curvature falls through to Flat.
    const bool bendsAway = curvature.kMax[p] > zero;
    const bool bendsToward = curvature.kMin[p] < -zero;
    const CurvatureType type = bendsAway
                                   ? (bendsToward ? CurvatureType::Saddle : CurvatureType::Convex)
                                   : (bendsToward ? CurvatureType::Concave : CurvatureType::Flat);
    out[p] = static_cast<std::uint8_t>(type);
  }
  return out;
}

ScalarField curvatureTypeField(const CurvatureField& curvature, const CurvatureTypeParams& params) {
  const std::vector<std::uint8_t> types = classifyCurvature(curvature, params);
  ScalarField field;
  field.name = "curvature type";
  field.values.assign(types.begin(), types.end());
  return field;
}

ScalarField maxToolRadiusField(const CurvatureField& curvature, double capMm) {
  if (!(capMm > 0.0) || !std::isfinite(capMm))
    throw InvalidInput("maxToolRadiusField: the cap must be positive and finite");
  ScalarField field;
  field.name = "max tool radius";
  field.unit = "mm";
  field.values.resize(curvature.size());
  for (std::size_t p = 0; p < field.values.size(); ++p) {
    const double k = curvature.kMin[p];
    const double radius = std::isnan(k) ? k : k < 0.0 ? std::min(capMm, -1.0 / k) : capMm;
    field.values[p] = static_cast<float>(radius);
  }
  return field;
}

std::vector<int> classifyToolRadius(const CurvatureField& curvature,
                                    const std::vector<double>& toolRadiiMm,
                                    double relativeTolerance) {
  if (toolRadiiMm.empty()) throw InvalidInput("classifyToolRadius: no tool radii given");
  for (std::size_t i = 0; i < toolRadiiMm.size(); ++i)
    if (!(toolRadiiMm[i] > 0.0) || !std::isfinite(toolRadiiMm[i]) ||
        (i > 0 && !(toolRadiiMm[i] > toolRadiiMm[i - 1])))
      throw InvalidInput("classifyToolRadius: tool radius " + std::to_string(i) + " (" +
                         std::to_string(toolRadiiMm[i]) +
                         " mm) is not positive or not above the previous one");
  if (!(relativeTolerance >= 0.0))
    throw InvalidInput("classifyToolRadius: relativeTolerance must be >= 0");
  std::vector<int> out(curvature.size());
  for (std::size_t p = 0; p < out.size(); ++p) {
    const double k = curvature.kMin[p];
    if (std::isnan(k)) {
      out[p] = kNoToolFits;
      continue;
    }
    // r <= (1 + tol) / |k|  <=>  r |k| <= 1 + tol, which also covers k >= 0 without division.
    const double bendsToward = std::max(0.0, -k);
    const auto fits = [&](double r) { return r * bendsToward <= 1.0 + relativeTolerance; };
    const auto firstMisfit = std::partition_point(toolRadiiMm.begin(), toolRadiiMm.end(), fits);
    out[p] = static_cast<int>(firstMisfit - toolRadiiMm.begin()) - 1;
  }
  return out;
}

std::vector<Region> segmentFaces(const ddf::DisplacementField& ddf,
                                 const std::vector<int>& faceLabels,
                                 const std::vector<std::string>& labelNames,
                                 const SegmentationParams& params) {
  checkSegmentInput(ddf, faceLabels, labelNames, params);
  reportProgress(params.progress, 0.0);
  std::vector<Component> comps;
  const std::vector<int> component = labelComponents(ddf, faceLabels, comps);
  measureComponents(ddf, component, comps);
  reportProgress(params.progress, 0.5);
  const std::vector<int> root = mergeSmall(comps, params);

  std::vector<Region> regions;
  std::vector<int> regionOf(comps.size(), -1);
  for (int f = 0; f < ddf.faceCount(); ++f) {
    const int r = root[component[f]];
    if (regionOf[r] < 0) {
      regionOf[r] = static_cast<int>(regions.size());
      Region& region = regions.emplace_back();
      region.name = labelNames[comps[r].label] + " " + std::to_string(regionOf[r] + 1);
      region.color = regionColor(regionOf[r]);
    }
    regions[regionOf[r]].faces.push_back(f);
  }
  reportProgress(params.progress, 1.0);
  return regions;
}

std::vector<Region> segmentByCurvatureType(const ddf::DisplacementField& ddf,
                                           const CurvatureField& curvature,
                                           const SegmentationParams& params) {
  checkLayout(ddf, curvature);
  reportProgress(params.progress, 0.0);
  const std::vector<std::uint8_t> types = classifyCurvature(curvature, params.type);
  const std::vector<int> labels(types.begin(), types.end());
  std::vector<std::string> names;
  for (auto t :
       {CurvatureType::Flat, CurvatureType::Convex, CurvatureType::Concave, CurvatureType::Saddle})
    names.emplace_back(curvatureTypeName(t));
  const std::vector<int> faceLabels = faceMajority(ddf, labels, static_cast<int>(names.size()));
  return segmentFaces(ddf, faceLabels, names, subRange(params, 0.2, 1.0));
}

std::vector<Region> segmentByToolRadius(const ddf::DisplacementField& ddf,
                                        const CurvatureField& curvature,
                                        const std::vector<double>& toolRadiiMm,
                                        const SegmentationParams& params) {
  checkLayout(ddf, curvature);
  reportProgress(params.progress, 0.0);
  std::vector<int> labels =
      classifyToolRadius(curvature, toolRadiiMm, params.relativeRadiusTolerance);
  // Label 0 is "no tool", label i + 1 tool radius i, so majority ties favour smaller tools.
  for (int& l : labels) ++l;
  std::vector<std::string> names{"no tool"};
  for (double r : toolRadiiMm) {
    std::ostringstream name;
    name << "radius " << r << " mm";
    names.push_back(name.str());
  }
  const std::vector<int> faceLabels = faceMajority(ddf, labels, static_cast<int>(names.size()));
  return segmentFaces(ddf, faceLabels, names, subRange(params, 0.2, 1.0));
}

}  // namespace ddfcam::planning
