// SPDX-License-Identifier: MIT
// ddfcam: error maps: signed deviation of a produced from a desired surface on one support
// (sec. 8.4.1).
#pragma once

#include <ddfcam/ddf/displacement_field.h>
#include <ddfcam/ddf/surface_sampling.h>
#include <ddfcam/planning/model/scalar_field.h>
#include <ddfcam/planning/model/tool_path.h>

#include <cstddef>
#include <span>
#include <vector>

namespace ddfcam::planning {

/// @brief Tolerance band [e_l, e_u] of the deviation, mm, with e_l <= 0 <= e_u. Deviations above
/// e_u are material left (undercut), below e_l overcut (gouge), inside the band in tolerance.
struct ToleranceBand {
  double lowerMm = -0.01;  ///< e_l <= 0, mm (default -0.01)
  double upperMm = 0.01;   ///< e_u >= 0, mm (default 0.01)
};

/// @brief Checks e_l <= 0 <= e_u and both finite.
/// @throws InvalidInput naming the offending bound.
void validateToleranceBand(const ToleranceBand& band);

/// @brief Where a deviation lies with respect to a ToleranceBand (colours of the error map:
/// blue = material left, green = in tolerance, red = overcut).
enum class ToleranceClass {
  MaterialLeft,  ///< deviation > e_u: the surface is short of the desired one (undercut)
  InTolerance,   ///< e_l <= deviation <= e_u
  Overcut        ///< deviation < e_l: material removed below the desired surface
};

/// @brief Class of @p deviationMm in @p band (the bounds themselves are in tolerance). NaN is
/// reported as InTolerance; callers skip NaN ("no value") before classifying.
ToleranceClass classify(double deviationMm, const ToleranceBand& band);

/// @brief Signed deviation of the produced surface from the desired surface at every raster
/// point, mm along the unit normal n of the desired surface: (h_produced - h_desired) (v . n),
/// v the interpolated displacement vector (sec. 8.4.1: both surfaces as height fields on the same
/// support and resolution). Positive = material left (undercut), negative = overcut. n is the
/// area-weighted mean of the normals of the desired surface's raster triangles (fig. 7.1a) around
/// the raster point, over all faces sharing it, oriented to the side v points to (the tool
/// side). Name "deviation", unit "mm", signed; NaN where either height is not finite.
/// @param produced the simulated part; its support, vectors and resolution define the raster.
/// @param desiredHeights heights of the desired surface on the same DDF, laid out like
/// produced.allHeights() (e.g. the "design" SimulationState).
/// @return F * pointsPerFace values, layout of allHeights().
/// @throws InvalidInput if desiredHeights has the wrong size.
ScalarField deviationMap(const ddf::DisplacementField& produced,
                         std::span<const float> desiredHeights);

/// @brief As above with the desired surface given as a DDF on the same support.
/// @throws InvalidInput if the face count, vertex count or resolution differ.
ScalarField deviationMap(const ddf::DisplacementField& produced,
                         const ddf::DisplacementField& desired);

/// @brief Unit normal of the represented surface of @p ddf at every raster point copy, laid out
/// like allHeights(): the area-weighted mean of the normals of the raster triangles (fig. 7.1a)
/// around the raster point, summed over all faces sharing it, oriented to the side the copy's
/// interpolated displacement vector v points to. Where no valid raster triangle surrounds the
/// point (non-finite heights), v's direction stands in. The normals deviationMap() uses.
/// @return F * pointsPerFace unit vectors, part frame.
std::vector<ddf::Vec3> rasterPointNormals(const ddf::DisplacementField& ddf);

/// @brief Area of the represented surface of @p ddf that belongs to each raster point copy, mm^2,
/// laid out like allHeights(): each raster triangle of a face gives a third of its area to each
/// of its three corners. A shared point's area is thus split among its copies and counts once in
/// total; the sum over all entries is the area of the raster mesh. Raster triangles with a
/// corner of non-finite height are left out.
std::vector<double> rasterPointAreas(const ddf::DisplacementField& ddf);

/// @brief Area-weighted statistics of an error map (over a region or the whole part).
struct ErrorStatistics {
  double maxMm = 0.0;                ///< largest deviation, mm
  double minMm = 0.0;                ///< smallest deviation, mm
  double meanMm = 0.0;               ///< area-weighted mean, mm
  double rmsMm = 0.0;                ///< area-weighted root mean square, mm
  double sigmaMm = 0.0;              ///< area-weighted standard deviation about the mean, mm
  double inTolerancePercent = 0.0;   ///< % of the area with e_l <= deviation <= e_u
  double materialLeftPercent = 0.0;  ///< % of the area with deviation > e_u
  double overcutPercent = 0.0;       ///< % of the area with deviation < e_l
  double areaMm2 = 0.0;              ///< area with a finite deviation, mm^2
  std::size_t points = 0;            ///< distinct raster points (PointId) with a finite value
};

/// @brief Statistics of @p deviation (e.g. deviationMap()) weighted by rasterPointAreas(@p ddf)
/// (pass the desired surface's DDF, or the produced one: the weights differ by the area change).
/// Only copies with a finite value and a positive area weight take part (max, min and points too).
/// @param faces support faces of the region to evaluate (e.g. Region::faces); empty = all faces.
/// @throws InvalidInput if @p deviation is not sized like ddf.allHeights(), a face is out of
/// range, the band is invalid, or no finite value with positive area lies in the region.
ErrorStatistics errorStatistics(const ScalarField& deviation, const ddf::DisplacementField& ddf,
                                const ToleranceBand& band, std::span<const int> faces = {});

/// @brief Raster points of a simulated part where a cut was clamped at the crust bottom.
struct CrustClamping {
  std::size_t points = 0;  ///< distinct raster points (PointId)
  double areaMm2 = 0.0;    ///< their area, mm^2 (weights rasterPointAreas() of the produced part)
};

/// @brief The raster points of the simulated part @p produced that lie at the crust bottom
/// (h <= -1) with a finite negative @p deviation. The depth buffer and Preston removal clamp
/// every cut deeper than the crust to h = -1 (ddf::cutByMesh), so the true overcut there is
/// deeper than the map shows, and an error map's minMm is then only an upper bound of the
/// deepest gouge (a 5 mm and a 0.5 mm plunge below the crust give the same minimum).
/// @param faces region faces; empty = all faces.
/// @throws InvalidInput if @p deviation is not sized like produced.allHeights() or a face is out
/// of range.
CrustClamping crustClamping(const ScalarField& deviation, const ddf::DisplacementField& produced,
                            std::span<const int> faces = {});

/// @brief Area per deviation bin.
struct AreaHistogram {
  double lowerMm = 0.0;         ///< lower edge of bin 0, mm
  double upperMm = 0.0;         ///< upper edge of the last bin, mm
  std::vector<double> areaMm2;  ///< #bins areas; bin b is [lo + b w, lo + (b+1) w), the last
                                ///< bin also holds upperMm (w = (upper - lower) / bins)
  double belowMm2 = 0.0;        ///< area with deviation < lowerMm
  double aboveMm2 = 0.0;        ///< area with deviation > upperMm
  /// @brief Bin width w, mm.
  double binWidthMm() const {
    return areaMm2.empty() ? 0.0 : (upperMm - lowerMm) / static_cast<double>(areaMm2.size());
  }
};

/// @brief Area-weighted histogram of @p deviation over [lowerMm, upperMm] with @p bins bins;
/// weights as errorStatistics(). The bins plus belowMm2 and aboveMm2 sum to the region area.
/// @param faces region faces; empty = all faces.
/// @throws InvalidInput for bins < 1, a non-finite or empty range, a wrong field size or a face
/// out of range.
AreaHistogram errorHistogram(const ScalarField& deviation, const ddf::DisplacementField& ddf,
                             int bins, double lowerMm, double upperMm,
                             std::span<const int> faces = {});

/// @brief One sample of the deviation along a path.
struct PathDeviationSample {
  int pass = 0;                         ///< pass index (ToolPath::passStarts), 0 for locations
  double arcLengthMm = 0.0;             ///< arc length from the first sample, mm (see below)
  ddf::Vec3 point = ddf::Vec3::Zero();  ///< sample point, mm, part frame
  double deviationMm = 0.0;             ///< interpolated deviation, mm; NaN if not located
};

/// @brief Deviation along a polyline of surface locations: interpolateOnFace() of @p deviation
/// at every location; arc length = cumulative distance between consecutive location points.
/// @param ddf the DDF @p deviation is laid out for (the locations' faces index it).
/// @throws InvalidInput if @p deviation has the wrong size or a location's face is out of range.
std::vector<PathDeviationSample> deviationAlongLocations(
    const ScalarField& deviation, const ddf::DisplacementField& ddf,
    std::span<const ddf::SurfaceLocation> locations);

/// @brief Deviation at every contact of @p path: each contact is located on the DDF (the support
/// face whose V-projection of the contact lies nearest to it, ddf::locateOnFace) and the
/// deviation interpolated there. Arc length accumulates along the contacts of each pass; the
/// lift between passes adds nothing, so a plot over arc length shows the passes one after the
/// other. A contact that cannot be located gets NaN.
/// @param ddf the DDF @p deviation is laid out for, whose surface the contacts lie on (the
/// desired surface's DDF).
/// @throws InvalidInput if @p deviation has the wrong size.
std::vector<PathDeviationSample> deviationAlongPath(const ScalarField& deviation,
                                                    const ddf::DisplacementField& ddf,
                                                    const ToolPath& path);

/// @brief Convenience: deviationMap(produced, desired) sampled along @p path's contacts.
/// @throws InvalidInput as deviationMap() and deviationAlongPath().
std::vector<PathDeviationSample> deviationAlongPath(const ddf::DisplacementField& produced,
                                                    const ddf::DisplacementField& desired,
                                                    const ToolPath& path);

}  // namespace ddfcam::planning
