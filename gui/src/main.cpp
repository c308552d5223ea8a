// SPDX-License-Identifier: MIT
// ddfcam: the workbench executable (interactive, or --screenshot for scripts).
#include <ddfcam/error.h>
#include <ddfcam/gui/app_setup.h>
#include <ddfcam/gui/main_window.h>
#include <ddfcam/gui/vtk_error_monitor.h>
#include <ddfcam/log.h>

#include <QApplication>
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
    "usage: ddfcam [--screenshot OUT.png] [PART]\n"
    "  PART                 a project (.ddfproj), a .ddf file or a mesh (.stl .obj .ply .off)\n"
    "                       converted to a DDF; without it the built-in demo part is shown\n"
    "  --screenshot OUT.png load PART, render one frame of the window to OUT.png and exit\n"
    "  -h, --help           this text\n";

struct Options {
  std::optional<std::string> screenshot;
  std::optional<std::string> part;
};

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

/// Shows the window until it is exposed, grabs it (3D view included) and writes @p out.
int writeScreenshot(ddfcam::gui::MainWindow& window, const QString& out) {
  window.show();
  QElapsedTimer timer;
  timer.start();
  while (!(window.windowHandle() && window.windowHandle()->isExposed()) && timer.elapsed() < 5000)
    QApplication::processEvents(QEventLoop::AllEvents, 50);
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
    return writeScreenshot(*window, QString::fromStdString(*options.screenshot));
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
