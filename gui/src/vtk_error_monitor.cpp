// SPDX-License-Identifier: MIT
// ddfcam gui: VtkErrorMonitor, a vtkOutputWindow forwarding to the ddfcam log facade.
#include <ddfcam/gui/vtk_error_monitor.h>

#include <ddfcam/log.h>

#include <vtkObjectFactory.h>
#include <vtkOutputWindow.h>
#include <vtkSmartPointer.h>

#include <string>

namespace ddfcam::gui {

namespace {

std::atomic<int> gErrors{0};
std::atomic<int> gWarnings{0};

class CountingOutputWindow : public vtkOutputWindow {
 public:
  static CountingOutputWindow* New();
  vtkTypeMacro(CountingOutputWindow, vtkOutputWindow)

      void DisplayText(const char* text) override {
    log(LogLevel::Info, prefixed(text));
  }
  void DisplayErrorText(const char* text) override {
    ++gErrors;
    log(LogLevel::Error, prefixed(text));
  }
  void DisplayWarningText(const char* text) override {
    ++gWarnings;
    log(LogLevel::Warning, prefixed(text));
  }
  void DisplayGenericWarningText(const char* text) override { DisplayWarningText(text); }
  void DisplayDebugText(const char* text) override { log(LogLevel::Debug, prefixed(text)); }

 private:
  static std::string prefixed(const char* text) {
    return std::string("VTK: ") + (text ? text : "");
  }
};

vtkStandardNewMacro(CountingOutputWindow)

}  // namespace

void VtkErrorMonitor::install() {
  static const bool installed = [] {
    auto window = vtkSmartPointer<CountingOutputWindow>::New();
    vtkOutputWindow::SetInstance(window);
    return true;
  }();
  (void)installed;
}

int VtkErrorMonitor::errorCount() {
  return gErrors.load();
}
int VtkErrorMonitor::warningCount() {
  return gWarnings.load();
}

void VtkErrorMonitor::reset() {
  gErrors = 0;
  gWarnings = 0;
}

}  // namespace ddfcam::gui
