// SPDX-License-Identifier: MIT
// ddfcam gui: glyphs of the tool flow field and of both principal directions, and singularity
// markers, as overlays of the part view (figs. 8.6/8.7).
#pragma once

#include <ddfcam/ddf/displacement_field.h>
#include <ddfcam/gui/adapters/line_glyphs.h>
#include <ddfcam/planning/analysis/curvature.h>
#include <ddfcam/planning/flow/flow_field.h>

#include <array>
#include <string>
#include <vector>

namespace ddfcam::gui {

class PartScene;

/// @brief The line fields the display can show as glyphs.
enum class GlyphField {
  Flow = 0,      ///< the tool flow field
  MaxDirection,  ///< direction of k_max (umbilic points left out)
  MinDirection,  ///< direction of k_min (umbilic points left out)
};
constexpr int kGlyphFieldCount = 3;

/// @brief Shows line-field glyphs (sign-free segments centred on subsampled raster points,
/// lifted slightly off the surface) and singularity markers in a PartScene, one overlay per
/// field and one per sign of the singularity index, each with its own colour and toggle.
/// Knows nothing of documents: the owner hands it the fields and clears it when the part goes.
class FlowFieldDisplay {
 public:
  /// @param scene the scene to draw in; must outlive the display.
  explicit FlowFieldDisplay(PartScene& scene);

  /// @brief Overlay name of glyph field @p which ("flow field glyphs", "k_max glyphs",
  /// "k_min glyphs").
  static std::string overlayName(GlyphField which);
  /// @brief Overlay names of the singularity markers with positive and negative index.
  static constexpr const char* kPositiveSingularities = "singularities +";
  static constexpr const char* kNegativeSingularities = "singularities -";
  /// @brief Colour of glyph field @p which, RGB in [0, 1].
  static std::array<double, 3> colour(GlyphField which);
  /// @brief Colour of singularity markers with index of sign @p positive.
  static std::array<double, 3> singularityColour(bool positive);

  /// @brief Replaces everything shown: glyphs of @p flow and of @p curvature's principal
  /// directions (entries flagged umbilic are undefined) on @p part, and markers at
  /// @p singularities. Visibility toggles are kept.
  /// @throws InvalidInput if a field size does not match the part.
  void show(const ddf::DisplacementField& part, const planning::LineField& flow,
            const planning::CurvatureField& curvature,
            std::vector<planning::FieldSingularity> singularities,
            const LineGlyphParams& params = {});
  /// @brief Removes every overlay of the display (e.g. when the part changed).
  void clear();
  /// @brief True while fields are shown (show() called and not cleared).
  bool hasFields() const { return shown_; }

  /// @brief Shows or hides the glyphs of @p which.
  void setVisible(GlyphField which, bool visible);
  bool isVisible(GlyphField which) const { return visible_[static_cast<int>(which)]; }
  /// @brief Shows or hides the singularity markers.
  void setSingularitiesVisible(bool visible);
  bool singularitiesVisible() const { return singularitiesVisible_; }

  /// @brief The glyphs last shown for @p which.
  const LineGlyphs& glyphs(GlyphField which) const { return glyphs_[static_cast<int>(which)]; }
  /// @brief The singularities last shown.
  const std::vector<planning::FieldSingularity>& singularities() const { return singularities_; }

 private:
  void applyVisibility();

  PartScene& scene_;
  bool shown_ = false;
  std::array<bool, kGlyphFieldCount> visible_ = {true, false, false};
  bool singularitiesVisible_ = true;
  std::array<LineGlyphs, kGlyphFieldCount> glyphs_;
  std::vector<planning::FieldSingularity> singularities_;
};

}  // namespace ddfcam::gui
