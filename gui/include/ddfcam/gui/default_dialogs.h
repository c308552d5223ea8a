// SPDX-License-Identifier: MIT
// ddfcam gui: the real dialogs behind WorkbenchDialogs (file choosers and message boxes).
#pragma once

#include <ddfcam/gui/project_actions.h>

class QWidget;

namespace ddfcam::gui {

/// @brief @p dialogs with every empty member filled by its interactive default over
/// @p parent: QFileDialog for paths, a file dialog plus a size prompt for screenshots,
/// QMessageBox for unsaved changes, recovery and errors, PathExportDialog and
/// PathImportDialog for tool-path export and import.
WorkbenchDialogs withDefaultDialogs(WorkbenchDialogs dialogs, QWidget* parent);

}  // namespace ddfcam::gui
