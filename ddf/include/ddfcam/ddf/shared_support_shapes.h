// SPDX-License-Identifier: MIT
// ddfcam: two shapes on one support and vector field (cube/sphere morph, figs. 9.1/9.3) and the
// engraved plate of fig. 9.2 a.
#pragma once

#include <ddfcam/ddf/displacement_field.h>
#include <ddfcam/ddf/triangle_mesh.h>

#include <span>
#include <vector>

namespace ddfcam::ddf {

/// @brief Parameters of cubeSphereMorph().
struct CubeSphereParams {
  double edgeMm = 100.0;         ///< cube edge length, mm, > 0. Default 100.
  int subdivisions = 8;          ///< support grid cells per cube side edge, >= 1. Default 8.
  int resolution = 5;            ///< raster resolution m, >= 2. Default 5.
  Vec3 centreMm = Vec3::Zero();  ///< common centre of cube and sphere, mm. Default origin.
  /// Sphere radius R, mm; 0 = edgeMm (a sphere enclosing the cube). Must lie outside
  /// [edge/2, edge sqrt(3)/2] so that no radial vector has length 0. Default 0.
  double sphereRadiusMm = 0.0;
  /// Vector length = vectorReach x |R - |p - c||: more than 1 so the crust (h <= 1) contains the
  /// polygonal sphere between the vertices too; the sphere then has heights about 1/vectorReach.
  /// > 1. Default 1.25.
  double vectorReach = 1.25;
  /// Subdivision level of the icosphere the sphere heights are filled from (20 x 4^level
  /// triangles), 1..7. Default 4.
  int sphereLevel = 4;
};

/// @brief The cube and the sphere over the same support and vectors (fig. 9.3).
struct CubeSphereMorph {
  /// Support = the cube surface (outward counter-clockwise triangles, welded), vectors radial
  /// from the centre; heights = cubeHeights.
  DisplacementField ddf;
  std::vector<float> cubeHeights;    ///< per raster point copy (allHeights() layout): all 0
  std::vector<float> sphereHeights;  ///< per copy: the sphere mesh along the stubbles
  TriangleMesh sphereMesh;           ///< the icosphere the sphere heights were filled from, mm
  double sphereRadiusMm = 0.0;       ///< R actually used (vertices of sphereMesh lie at R), mm
};

/// @brief Builds the morphing demo of figs. 9.1/9.3 as the dissertation did: a DDF of the cube
/// (heights 0) whose vectors are radial from the centre with length vectorReach |R - |p - c||,
/// and the sphere's heights by the DDF depth buffer (fillFromMesh with a CrustHash) from an
/// icosphere of radius R. At a support vertex p the sphere point is c + (|p - c| + h1 |v|) u
/// exactly, u = (p - c)/|p - c|.
/// @throws InvalidInput for parameters out of range, or (never for valid ones) if a stubble
/// misses the sphere mesh; the message names the count.
CubeSphereMorph cubeSphereMorph(const CubeSphereParams& params = {});

/// @brief Linear height interpolation of sec. 9: (1 - t) h0 + t h1 per value; t outside [0, 1]
/// extrapolates.
/// @throws InvalidInput if the sizes differ.
std::vector<float> morphHeights(std::span<const float> h0, std::span<const float> h1, double t);

/// @brief Parameters of engravedPlate() (fig. 9.2 a): a flat square plate in the z = 0 plane,
/// centred on the origin, vectors +z, engraved with concentric ring grooves of a cos^2 profile
/// around the plate centre and one straight groove along the x axis.
struct EngravedPlateParams {
  double sizeMm = 100.0;        ///< plate edge length, mm, > 0. Default 100.
  int subdivisions = 10;        ///< support grid cells per plate edge, >= 1. Default 10.
  int resolution = 17;          ///< raster resolution m, >= 2. Default 17.
  double depthMm = 2.0;         ///< groove depth at the groove centre line, mm, > 0. Default 2.
  double grooveWidthMm = 6.0;   ///< full groove width (profile cos^2(pi d / w)), mm. Default 6.
  double ringSpacingMm = 12.0;  ///< ring k has radius k x ringSpacing (k >= 1), mm. Default 12.
  int ringCount = 3;            ///< number of rings, >= 0. Default 3.
  bool straightGroove = true;   ///< add the groove along y = 0. Default true.
  /// Length of the +z vectors, mm; must exceed depthMm so the grooves lie in the crust. Default 5.
  double vectorLengthMm = 5.0;
};

/// @brief Engraving depth (>= 0, mm, measured downwards) of @p params at plate point (x, y):
/// the deepest of the ring and straight grooves there (grooves do not add).
double engravingDepthMm(const EngravedPlateParams& params, double x, double y);

/// @brief The flat DDF with engravings of fig. 9.2 a: support = the plate grid (counter-clockwise
/// seen from +z), vectors (0, 0, vectorLengthMm), heights h = -engravingDepthMm(x, y) /
/// vectorLengthMm at every raster point.
/// @throws InvalidInput for parameters out of range.
DisplacementField engravedPlate(const EngravedPlateParams& params = {});

}  // namespace ddfcam::ddf
