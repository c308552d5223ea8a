// SPDX-License-Identifier: MIT
// ddfcam: conversion reports in numbers and words.
#include <ddfcam/ddf/conversion_report.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <set>

namespace ddfcam::ddf {
namespace {

std::string plural(long long n, const std::string& one, const std::string& many) {
  return std::to_string(n) + " " + (n == 1 ? one : many);
}

void addIf(std::vector<std::string>& lines, long long n, const std::string& one,
           const std::string& many, const std::string& what) {
  if (n > 0) lines.push_back(plural(n, one, many) + " " + what);
}

/// Where the issues of @p f lie, e.g. "12 vertices, 7 faces".
std::string where(const ConstraintFailure& f) {
  std::vector<std::string> parts;
  if (f.vertices > 0) parts.push_back(plural(f.vertices, "vertex", "vertices"));
  if (f.faces > 0) parts.push_back(plural(f.faces, "face", "faces"));
  if (f.facePairs > 0) parts.push_back(plural(f.facePairs, "face pair", "face pairs"));
  std::string out;
  for (const auto& p : parts) out += (out.empty() ? "" : ", ") + p;
  return out;
}

/// What a violation of constraint @p c means for the user and what to change.
std::string consequence(int c) {
  switch (c) {
    case 1:
      return "the mesh folds back on itself there (the triangles around a vertex face in "
             "directions with no common front side) or a triangle has no area, so the stubbles "
             "of those faces do not cross the surface once; heights, cuts and projections there "
             "are wrong. Change: remove or remesh the folded triangles (look at the first one "
             "named), or fill the holes and remove the fins around them";
    case 2:
      return "vertices at the same position are not joined and carry different vectors, so "
             "the surface can open along that seam. Change: weld the mesh (a larger weld "
             "tolerance) or join the seam in the modeller";
    default:
      return "stubbles of different faces cross inside the +-1 crust, so a point can belong "
             "to two faces and the represented surface can fold over; this happens at thin "
             "walls, sharp edges and parts that come closer than the vector length. Change: a "
             "smaller maximum vector length, or a coarser mesh where it is folded";
  }
}

std::string number(double x, const char* unit) {
  char text[48];
  std::snprintf(text, sizeof text, "%.4g%s", x, unit);
  return text;
}

std::string reductionLine(const SupportReductionReport& r) {
  return "support reduced from " + plural(r.inputFaces, "face", "faces") + " to " +
         std::to_string(r.supportFaces) + " in " + number(r.seconds, " s") + " (" +
         plural(r.contractions, "edge contraction", "edge contractions") + ", " +
         plural(r.sweeps, "sweep", "sweeps") + ")";
}

std::string accuracyLine(const ConversionAccuracy& a) {
  std::string text =
      "distance to the input, measured on sample points at m = " + std::to_string(a.resolution) +
      ": input -> DDF " + number(a.inputToDdfMm, " mm") + ", DDF -> input " +
      number(a.ddfToInputMm, " mm");
  if (a.toleranceMm > 0.0)
    text += a.toleranceMet ? " (within the tolerance " + number(a.toleranceMm, " mm") + ", " +
                                 plural(a.resolutionTries, "resolution", "resolutions") + " tried)"
                           : " (NOT within the tolerance " + number(a.toleranceMm, " mm") + ")";
  return text;
}

std::string stockLine(const StockFit& s) {
  if (s.holds)
    return "stock allowance " + number(s.requestedMm, " mm") +
           ": the crust holds it (smallest reach above the surface " +
           number(s.reach.minAboveMm, " mm") + ")";
  std::string text = "stock allowance " + number(s.requestedMm, " mm") +
                     " NOT held by the crust (smallest reach above the surface " +
                     number(s.reach.minAboveMm, " mm") + ")";
  if (s.limit) text += ": " + s.limit->message;
  return text;
}

}  // namespace

std::vector<std::string> conversionSummaryLines(const ConversionReport& r) {
  std::vector<std::string> lines;
  if (r.reducedSupport) lines.push_back(reductionLine(r.reduction));
  if (r.resolution >= 2)
    lines.push_back("raster resolution m = " + std::to_string(r.resolution) + ", raster spacing " +
                    number(r.rasterSpacingMm, " mm") + " on the longest support edge");
  if (r.accuracy.measured) lines.push_back(accuracyLine(r.accuracy));
  if (!r.accuracy.note.empty()) lines.push_back(r.accuracy.note);
  if (r.stock) lines.push_back(stockLine(*r.stock));
  return lines;
}

std::vector<ConstraintFailure> constraintFailures(const ValidationReport& report) {
  std::vector<ConstraintFailure> out;
  for (int c = 1; c <= 3; ++c) {
    ConstraintFailure f;
    f.constraint = c;
    std::set<int> vertices, faces;
    for (const auto& issue : report.issues) {
      if (issue.constraint != c) continue;
      if (f.issues++ == 0) f.first = issue.message;
      vertices.insert(issue.vertices.begin(), issue.vertices.end());
      faces.insert(issue.faces.begin(), issue.faces.end());
      f.facePairs += issue.faces.size() == 2;
    }
    if (f.issues == 0) continue;
    f.vertices = static_cast<int>(vertices.size());
    f.faces = static_cast<int>(faces.size());
    out.push_back(f);
  }
  return out;
}

std::string constraintName(int c) {
  switch (c) {
    case 1:
      return "constraint 1 (front-facing vectors)";
    case 2:
      return "constraint 2 (one vector per position)";
    default:
      return "constraint 3 (crusts without foldover)";
  }
}

std::vector<std::string> conversionRepairLines(const ConversionReport& r) {
  std::vector<std::string> lines;
  addIf(lines, r.weldedVertices, "vertex", "vertices", "welded into a coincident one");
  addIf(lines, r.unusedVertices, "unused vertex", "unused vertices",
        "dropped (no triangle refers to them)");
  addIf(lines, r.orphanedVertices, "vertex", "vertices",
        "dropped because all their triangles were dropped");
  addIf(lines, r.degenerateFaces, "degenerate triangle", "degenerate triangles",
        "dropped (repeated corner or zero area)");
  addIf(lines, r.duplicateFaces, "duplicate triangle", "duplicate triangles",
        "dropped (same corners as an earlier one)");
  addIf(lines, r.backToBackFaces, "back-to-back triangle", "back-to-back triangles",
        "removed in pairs (same corners facing opposite ways, a zero-thickness membrane)");
  addIf(lines, r.droppedFaces, "triangle", "triangles",
        "dropped that made the support non-manifold or flipped its orientation");
  addIf(lines, r.nonManifoldEdges, "non-manifold edge", "non-manifold edges",
        "in the input (more than two triangles each); triangles were dropped there");
  addIf(lines, r.boundaryLoops, "boundary loop", "boundary loops",
        "(holes or open borders), left open: the support ends there");
  addIf(lines, r.repairedDirections, "vector direction", "vector directions",
        "turned off the pseudo-normal to face all incident triangles (constraint 1)");
  addIf(lines, r.unifiedVectors, "coincident vertex", "coincident vertices",
        "given the vector of the vertex at the same position (constraint 2)");
  addIf(lines, r.shortenedVectors, "vector", "vectors",
        "shortened so that the crusts do not fold over (constraint 3, sec. 4.4)");
  addIf(lines, r.lengthRetries, "extra vector length choice", "extra vector length choices",
        "made with shorter vectors to repair constraint 3");
  addIf(lines, static_cast<long long>(r.unfilledPoints), "height", "heights",
        "not reached by the input along its stubble, kept on the support (h = 0)");
  return lines;
}

std::vector<std::string> conversionProblemLines(const ConversionReport& r) {
  std::vector<std::string> lines;
  if (!r.validated) {
    lines.push_back("the result was not checked against the DDF constraints");
    return lines;
  }
  for (const ConstraintFailure& f : constraintFailures(r.validation))
    lines.push_back(constraintName(f.constraint) + " fails at " + where(f) + " (" +
                    plural(f.issues, "issue", "issues") + "; first: " + f.first +
                    "): " + consequence(f.constraint));
  if (r.validation.suppressedIssues > 0)
    lines.push_back(std::to_string(r.validation.suppressedIssues) +
                    " further issues were not listed, so the counts above are lower bounds");
  if (r.infeasibleVertices > 0)
    lines.push_back(plural(r.infeasibleVertices, "vertex has", "vertices have") +
                    " no direction that faces all the triangles around it; no choice of vectors "
                    "can satisfy constraint 1 there without changing the mesh");
  return lines;
}

std::string conversionVerdict(const ConversionReport& r) {
  if (!r.validated) return "unchecked DDF: the constraints of chapter 3 were not checked";
  if (r.valid()) {
    std::string text = "valid DDF: constraints 1, 2 and 3 hold";
    if (std::isfinite(r.validation.minCrustHeight))
      text += " (smallest crust height " + std::to_string(r.validation.minCrustHeight) + ")";
    return text;
  }
  std::string names;
  const auto failures = constraintFailures(r.validation);
  for (std::size_t i = 0; i < failures.size(); ++i)
    names += (i == 0                     ? ""
              : i + 1 == failures.size() ? " and "
                                         : ", ") +
             constraintName(failures[i].constraint);
  return "INVALID DDF: violates " + (names.empty() ? std::string("the constraints") : names);
}

}  // namespace ddfcam::ddf
