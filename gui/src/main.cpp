// SPDX-License-Identifier: MIT
// ddfcam: the workbench executable (interactive, or --screenshot for scripts).
#include <ddfcam/error.h>
#include <ddfcam/gui/app_setup.h>
#include <ddfcam/gui/main_window.h>
#include <ddfcam/gui/part_view.h>
#include <ddfcam/gui/vtk_error_monitor.h>
#include <ddfcam/log.h>

#include <QApplication>
#include <QCheckBox>
#include <QElapsedTimer>
#include <QImage>
#include <QString>
#include <QWindow>

#include <cstdio>
#include <cstring>
#include <iostream>
#include <memory>
#include <optional>
#include <string>

namespace {

constexpr const char* kUsage =
    "usage: ddfcam [--screenshot OUT.png [--field NAME [--band LO,HI]]] [PART]\n"
    "  PART                 a project (.ddfproj), a .ddf file or a mesh (.stl .obj .ply .off)\n"
    "                       converted to a DDF; without it the built-in demo part is shown\n"
    "  --screenshot OUT.png load PART, render one frame of the window to OUT.png and exit\n"
    "  --field NAME         with --screenshot: colour the part by the project's field NAME\n"
    "                       (e.g. the error map 'deviation' of a batch job)\n"
    "  --band LO,HI         with --field: colour by the tolerance band LO <= 0 <= HI, mm\n"
    "  -h, --help           this text\n";

struct Options {
  std::optional<std::string> screenshot;
  std::optional<std::string> part;
  std::optional<std::string> field;
  std::optional<ddfcam::planning::ToleranceBand> band;
};

/// "LO,HI" as a tolerance band, or nullopt if it is not two numbers.
std::optional<ddfcam::planning::ToleranceBand> parseBand(const std::string& text) {
  double lo = 0.0, hi = 0.0;
  char rest = 0;
  if (std::sscanf(text.c_str(), "%lf,%lf%c", &lo, &hi, &rest) != 2) return std::nullopt;
  return ddfcam::planning::ToleranceBand{lo, hi};
}

/// Parsed before QApplication exists, so that --help and argument errors need no display.
std::optional<Options> parseArguments(int argc, char** argv, int& exitCode) {
  Options options;
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    if (arg == "-h" || arg == "--help") {
      std::fputs(kUsage, stdout);
      exitCode = 0;
      return std::nullopt;
    }
    if (arg == "--screenshot" && i + 1 < argc) {
      options.screenshot = argv[++i];
    } else if (arg == "--field" && i + 1 < argc) {
      options.field = argv[++i];
    } else if (arg == "--band" && i + 1 < argc && (options.band = parseBand(argv[i + 1]))) {
      ++i;
    } else if (!arg.empty() && arg[0] != '-' && !options.part) {
      options.part = arg;
    } else {
      std::fprintf(stderr, "ddfcam: unexpected argument '%s'\n%s", arg.c_str(), kUsage);
      exitCode = 1;
      return std::nullopt;
    }
  }
  return options;
}

/// Colours the part by the field that @p options name (and its tolerance band), if any.
/// @return false, with a message on stderr, if the project has no such field.
bool showRequestedField(ddfcam::gui::MainWindow& window, const Options& options) {
  if (!options.field) return true;
  // The region colours lie over the part's surface; a person unticks them to see a field.
  if (auto* regions = window.findChild<QCheckBox*>("showRegionColours")) regions->setChecked(false);
  try {
    window.partView().showField(*options.field);
    if (options.band) window.partView().setToleranceBand(*options.band);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "ddfcam: --field: %s\n", ddfcam::unrollMessage(e).c_str());
    return false;
  }
  return true;
}

/// Shows the window until it is exposed, colours the part by the requested field, grabs the
/// window (3D view included) and writes the screenshot.
int writeScreenshot(ddfcam::gui::MainWindow& window, const Options& options) {
  const QString out = QString::fromStdString(*options.screenshot);
  window.show();
  QElapsedTimer timer;
  timer.start();
  while (!(window.windowHandle() && window.windowHandle()->isExposed()) && timer.elapsed() < 5000)
    QApplication::processEvents(QEventLoop::AllEvents, 50);
  QApplication::processEvents();
  if (!showRequestedField(window, options)) return 1;
  QApplication::processEvents();
  const QImage image = window.grab().toImage();
  if (image.isNull() || !image.save(out)) {
    std::fprintf(stderr, "ddfcam: cannot write the screenshot to '%s'\n", qPrintable(out));
    return 1;
  }
  return 0;
}

/// Batch mode (--screenshot): nothing modal; errors go to stderr, since the console dock takes
/// over the log, and set @p failed.
ddfcam::gui::WorkbenchDialogs batchDialogs(bool& failed) {
  ddfcam::gui::WorkbenchDialogs dialogs;
  dialogs.error = [&failed](const QString& title, const QString& message) {
    failed = true;
    std::fprintf(stderr, "ddfcam: %s: %s\n", qPrintable(title), qPrintable(message));
  };
  dialogs.offerRecovery = [](const QStringList&) { return -1; };
  dialogs.unsavedChanges = [] { return ddfcam::gui::UnsavedChoice::Discard; };
  return dialogs;
}

/// Creates the window on @p options' part, then either writes the screenshot or runs the UI.
int runWorkbench(QApplication& app, const Options& options) {
  bool failed = false;
  ddfcam::gui::WorkbenchDialogs dialogs;
  if (options.screenshot) dialogs = batchDialogs(failed);
  ddfcam::gui::WorkbenchOptions workbench;
  workbench.openDemoAtStart = !options.part;
  std::unique_ptr<ddfcam::gui::MainWindow> window;
  try {
    window = std::make_unique<ddfcam::gui::MainWindow>(dialogs, workbench);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "ddfcam: cannot start the workbench: %s\n",
                 ddfcam::unrollMessage(e).c_str());
    return 1;
  }
  if (options.part) window->openPath(QString::fromStdString(*options.part));
  if (options.screenshot) {
    if (!window->waitForJobs(600'000) || failed) return 1;
    return writeScreenshot(*window, options);
  }
  window->show();
  return app.exec();
}

}  // namespace

int main(int argc, char** argv) {
  int exitCode = 0;
  const std::optional<Options> options = parseArguments(argc, argv, exitCode);
  if (!options) return exitCode;
  if (!ddfcam::gui::hasDisplay()) {
    std::fputs(
        "ddfcam: no display (neither DISPLAY nor WAYLAND_DISPLAY is set). The workbench needs an\n"
        "X11 or Wayland display with OpenGL 3.2; on a headless machine run it under\n"
        "  xvfb-run -a -s '-screen 0 1280x800x24' ddfcam ...\n"
        "or use the command-line tool instead, e.g. `ddfcam-cli demo`.\n",
        stderr);
    return 2;
  }

  ddfcam::setLogSink([](ddfcam::LogLevel level, const std::string& message) {
    if (level != ddfcam::LogLevel::Debug) std::cerr << "ddfcam: " << message << '\n';
  });
  ddfcam::gui::setDefaultSurfaceFormat();
  QApplication app(argc, argv);
  QApplication::setApplicationName("ddfcam");
  QApplication::setOrganizationName("ddfcam");
  ddfcam::gui::VtkErrorMonitor::install();

  return runWorkbench(app, *options);
}
