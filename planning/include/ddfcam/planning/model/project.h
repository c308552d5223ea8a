// SPDX-License-Identifier: MIT
// ddfcam: everything a session of work produces, as plain values (the workbench document).
#pragma once

#include <ddfcam/ddf/displacement_field.h>
#include <ddfcam/ddf/triangle_mesh.h>
#include <ddfcam/length_unit.h>
#include <ddfcam/planning/model/region_plan.h>
#include <ddfcam/planning/model/scalar_field.h>
#include <ddfcam/planning/model/tool_path.h>
#include <ddfcam/planning/mould/mould_study.h>
#include <ddfcam/planning/tools/tool.h>

#include <array>
#include <optional>
#include <string>
#include <vector>

namespace ddfcam::planning {

/// @brief A named region of the part: a set of support faces.
struct Region {
  std::string name;                                 ///< shown in lists
  std::vector<int> faces;                           ///< support face indices, ascending, unique
  std::array<float, 3> color = {0.9f, 0.6f, 0.2f};  ///< display colour, RGB in [0, 1]
  RegionPlan plan;                                  ///< tool, flow field, spacing, feed

  bool operator==(const Region&) const = default;
};

/// @brief A named snapshot of the part's heights (e.g. before and after a simulated pass).
struct SimulationState {
  std::string name;            ///< e.g. "stock", "after roll pass 1"
  std::vector<float> heights;  ///< F * pointsPerFace values, layout of allHeights()

  bool operator==(const SimulationState&) const = default;
};

/// @brief A named DDF besides the part, e.g. a deformed or a mould surface.
struct NamedSurface {
  std::string name;            ///< shown in lists
  ddf::DisplacementField ddf;  ///< the surface; its support need not match the part's
};

/// @brief The document of a workbench session.
struct Project {
  std::string partName;    ///< "demo part" or the source file name
  std::string sourcePath;  ///< file the part came from; empty for generated parts
  /// Unit the part's file was read in (the part itself is always in mm). Default mm.
  LengthUnit sourceUnit = LengthUnit::Millimetre;
  /// Per support face of the part, the CAD face it came from (CAD input; empty otherwise).
  std::vector<int> cadFaceOfSupportFace;
  /// Display names of the CAD faces, indexed by the values of cadFaceOfSupportFace.
  std::vector<std::string> cadFaceNames;
  std::optional<ddf::DisplacementField> part;  ///< the part with its current heights
  /// Reference (design) surface the part is compared with: the mesh it was converted from, or
  /// a triangulation of a generated part's design surface. Empty if there is none.
  std::optional<ddf::TriangleMesh> designMesh;
  std::vector<ScalarField> fields;      ///< computed fields, all sized like the part's heights
  std::vector<Region> regions;          ///< segmented regions
  std::vector<Tool> tools;              ///< tools referenced by paths
  std::vector<ToolPath> paths;          ///< tool paths
  std::vector<SimulationState> states;  ///< height snapshots, e.g. "stock" first
  std::vector<NamedSurface> surfaces;   ///< deformed / mould surfaces
  std::optional<MouldStudy> mould;      ///< mould planning: comparison, compensation
};

/// @brief Checks the invariants a Project must hold before it is saved or shown: every
/// field and state has F * pointsPerFace values; region faces are ascending, unique and in
/// range; every path's tool index is valid and its passStarts are strictly ascending, in range
/// and start with 0 when the path has poses, its raw lines have finite coordinates on faces of
/// the part (checked when there is a part) and its linked idle length is finite and >= 0; every
/// tool passes validateTool(); the design mesh's triangles reference existing vertices;
/// fields, states or regions without a part are an error; the mould study, if any, passes
/// validateMouldStudy() (it needs no part).
/// @throws InvalidInput naming the first offending item (e.g. "field 'height': 12 values,
/// expected 1536").
void validateProject(const Project& project);

/// @brief Exact equality of two projects: every value bit-identical (heights, positions,
/// vectors and face vertex order of all DDFs included, the mould study by mouldStudiesEqual()).
/// NaN equals NaN at the same place.
bool projectsEqual(const Project& a, const Project& b);

}  // namespace ddfcam::planning
