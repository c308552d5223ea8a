// SPDX-License-Identifier: MIT
// ddfcam gui: makeScalarBar, the look of the field scalar bar.
#include "scalar_bar.h"

#include <vtkCoordinate.h>
#include <vtkTextProperty.h>

#include <filesystem>
#include <initializer_list>
#include <string>
#include <system_error>

namespace ddfcam::gui {

namespace {

std::string firstExisting(std::initializer_list<const char*> candidates) {
  std::error_code error;
  for (const char* path : candidates)
    if (std::filesystem::exists(path, error)) return path;
  return {};
}

void styleText(vtkTextProperty* text, bool bold) {
  // VTK's embedded Arial has no square brackets (it draws "[mm]" as "(mm)"), and units are
  // written in brackets; DejaVu Sans where installed, else VTK's embedded Times, which has them.
  static const std::string regular = firstExisting(
      {"/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf", "/usr/share/fonts/TTF/DejaVuSans.ttf",
       "/usr/share/fonts/dejavu/DejaVuSans.ttf"});
  static const std::string boldFile = firstExisting(
      {"/usr/share/fonts/truetype/dejavu/DejaVuSans-Bold.ttf",
       "/usr/share/fonts/TTF/DejaVuSans-Bold.ttf", "/usr/share/fonts/dejavu/DejaVuSans-Bold.ttf"});
  const std::string& file = bold && !boldFile.empty() ? boldFile : regular;
  if (!file.empty()) {
    text->SetFontFamily(VTK_FONT_FILE);
    text->SetFontFile(file.c_str());
  } else {
    text->SetFontFamilyToTimes();
  }
  text->SetColor(0.93, 0.93, 0.93);
  text->SetBold(bold ? 1 : 0);
  text->SetItalic(0);
  text->SetShadow(0);
}

}  // namespace

vtkSmartPointer<vtkScalarBarActor> makeScalarBar() {
  auto bar = vtkSmartPointer<vtkScalarBarActor>::New();
  // Horizontal along the bottom edge, below a part that the camera fit centres: there the
  // title ("material removed [mm]") gets the width to stay legible, and the out-of-range
  // swatches sit left of the minimum and right of the maximum, where one reads them.
  bar->SetOrientationToHorizontal();
  bar->GetPositionCoordinate()->SetCoordinateSystemToNormalizedViewport();
  bar->GetPositionCoordinate()->SetValue(0.2, 0.012);
  bar->SetWidth(0.60);
  bar->SetHeight(0.11);
  bar->SetNumberOfLabels(5);
  // Three significant digits read well from microns (0.0123) to part sizes (123).
  bar->SetLabelFormat("%.3g");
  bar->SetBarRatio(0.3);
  bar->SetTextPositionToPrecedeScalarBar();
  bar->DrawBelowRangeSwatchOn();
  bar->DrawAboveRangeSwatchOn();
  bar->SetBelowRangeAnnotation("below");
  bar->SetAboveRangeAnnotation("above");
  bar->DrawAnnotationsOff();
  styleText(bar->GetTitleTextProperty(), true);
  styleText(bar->GetLabelTextProperty(), false);
  bar->SetVisibility(0);
  bar->PickableOff();
  return bar;
}

}  // namespace ddfcam::gui
