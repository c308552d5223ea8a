// SPDX-License-Identifier: MIT
// ddfcam gui: routes VTK's error and warning output into the ddfcam log and counts it.
#pragma once

#include <atomic>

namespace ddfcam::gui {

/// @brief Installs (once per process) a vtkOutputWindow that forwards VTK errors and warnings
/// to ddfcam::log instead of stderr or a popup, and counts them. Tests use the counters to
/// assert that a frame rendered without VTK complaining.
class VtkErrorMonitor {
 public:
  /// @brief Installs the output window if not yet installed; idempotent.
  static void install();
  /// @brief Number of VTK errors reported since install() (or the last reset()).
  static int errorCount();
  /// @brief Number of VTK warnings reported since install() (or the last reset()).
  static int warningCount();
  /// @brief Sets both counters to zero.
  static void reset();
};

}  // namespace ddfcam::gui
