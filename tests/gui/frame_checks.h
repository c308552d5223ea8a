// SPDX-License-Identifier: MIT
// Pixel statistics of a rendered frame, to tell a real picture from a blank or garbage frame.
#pragma once

#include <QColor>
#include <QDir>
#include <QImage>
#include <QString>

#include <cstdlib>

namespace ddfcam::test {

/// True if @p a and @p b differ by at most @p tolerance in every RGB channel.
inline bool sameColor(QRgb a, const QColor& b, int tolerance = 3) {
  return std::abs(qRed(a) - b.red()) <= tolerance && std::abs(qGreen(a) - b.green()) <= tolerance &&
         std::abs(qBlue(a) - b.blue()) <= tolerance;
}

/// What a person would notice about a frame of a 3D view with a uniform background.
struct FrameStats {
  double centreForeground = 0;     ///< fraction of non-background pixels in the central third
  double borderBackground = 0;     ///< fraction of background pixels on the outermost 2-pixel frame
  bool cornersBackground = false;  ///< all four corner pixels are background
};

inline FrameStats frameStats(const QImage& image, const QColor& background) {
  FrameStats s;
  const int w = image.width(), h = image.height();
  if (w < 8 || h < 8) return s;
  long fg = 0, total = 0;
  for (int y = h / 3; y < 2 * h / 3; ++y)
    for (int x = w / 3; x < 2 * w / 3; ++x, ++total)
      if (!sameColor(image.pixel(x, y), background)) ++fg;
  s.centreForeground = static_cast<double>(fg) / static_cast<double>(total);
  long bg = 0, border = 0;
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      if (x >= 2 && x < w - 2 && y >= 2 && y < h - 2) continue;
      ++border;
      if (sameColor(image.pixel(x, y), background)) ++bg;
    }
  s.borderBackground = static_cast<double>(bg) / static_cast<double>(border);
  s.cornersBackground = sameColor(image.pixel(0, 0), background) &&
                        sameColor(image.pixel(w - 1, 0), background) &&
                        sameColor(image.pixel(0, h - 1), background) &&
                        sameColor(image.pixel(w - 1, h - 1), background);
  return s;
}

/// Fraction of pixels that differ (beyond @p tolerance) between two frames of equal size.
inline double changedFraction(const QImage& a, const QImage& b, int tolerance = 8) {
  if (a.size() != b.size() || a.isNull()) return 1.0;
  long changed = 0;
  for (int y = 0; y < a.height(); ++y)
    for (int x = 0; x < a.width(); ++x)
      if (!sameColor(a.pixel(x, y), QColor(b.pixel(x, y)), tolerance)) ++changed;
  return static_cast<double>(changed) / (static_cast<double>(a.width()) * a.height());
}

/// Writes @p image as <name>.png into $DDFCAM_GUI_TEST_OUTPUT when that variable names a folder,
/// so a failing frame can be looked at; does nothing otherwise.
inline void dumpFrame(const QImage& image, const QString& name) {
  const QString dir = qEnvironmentVariable("DDFCAM_GUI_TEST_OUTPUT");
  if (!dir.isEmpty() && QDir(dir).exists()) image.save(QDir(dir).filePath(name + ".png"));
}

}  // namespace ddfcam::test
