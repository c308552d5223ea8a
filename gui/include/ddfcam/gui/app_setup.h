// SPDX-License-Identifier: MIT
// ddfcam gui: process-wide setup that must happen before the QApplication exists.
#pragma once

namespace ddfcam::gui {

/// @brief Sets the default QSurfaceFormat VTK 9.1 needs (OpenGL 3.2 core, RGBA8, depth 24,
/// stencil 8, double buffer). Call before constructing QApplication (in a Qt Test: initMain()).
void setDefaultSurfaceFormat();

/// @brief True if an X11 or Wayland display is named in the environment (DISPLAY or
/// WAYLAND_DISPLAY). QOpenGLWidget cannot run on the offscreen platform, so the workbench
/// refuses to start without one.
bool hasDisplay();

}  // namespace ddfcam::gui
