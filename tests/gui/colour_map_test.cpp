// SPDX-License-Identifier: MIT
// Colour maps against published end colours and the properties each map is designed to have.
#include <ddfcam/error.h>
#include <ddfcam/gui/adapters/colour_map.h>

#include <QtTest/QtTest>

#include <vtkLookupTable.h>

#include <cmath>
#include <cstdio>
#include <limits>
#include <set>
#include <string>

using ddfcam::gui::colourAt;
using ddfcam::gui::ColourMap;

namespace {

using Rgb = std::array<double, 3>;

double maxDiff(const Rgb& a, const Rgb& b) {
  return std::max({std::abs(a[0] - b[0]), std::abs(a[1] - b[1]), std::abs(a[2] - b[2])});
}

/// Relative luminance of sRGB-encoded values (Rec. 709 weights after linearisation).
double luminance(const Rgb& c) {
  auto linear = [](double v) {
    return v <= 0.04045 ? v / 12.92 : std::pow((v + 0.055) / 1.055, 2.4);
  };
  return 0.2126 * linear(c[0]) + 0.7152 * linear(c[1]) + 0.0722 * linear(c[2]);
}

Rgb lutColour(vtkLookupTable* table, double value) {
  double rgb[3];
  table->GetColor(value, rgb);
  return {rgb[0], rgb[1], rgb[2]};
}

}  // namespace

class ColourMapTest : public QObject {
  Q_OBJECT

 private slots:
  void endsMatchPublishedColours();
  void sequentialMapsGrowLighter();
  void coolWarmIsWhiteInTheMiddleAndSymmetric();
  void parameterIsClampedAndContinuous();
  void namesRoundTrip();
  void defaultRangeIsSymmetricForSignedFields();
  void scaleLabelsStayShort();
  void lookupTableMapsRangeEndsToMapEnds();
  void lookupTableRejectsBadRanges();
};

void ColourMapTest::endsMatchPublishedColours() {
  // matplotlib's viridis and magma (entries 0 and 255) and Google's Turbo table.
  QVERIFY(maxDiff(colourAt(ColourMap::Viridis, 0.0), {0.267004, 0.004874, 0.329415}) < 1e-6);
  QVERIFY(maxDiff(colourAt(ColourMap::Viridis, 1.0), {0.993248, 0.906157, 0.143936}) < 1e-6);
  QVERIFY(maxDiff(colourAt(ColourMap::Magma, 0.0), {0.001462, 0.000466, 0.013866}) < 1e-6);
  QVERIFY(maxDiff(colourAt(ColourMap::Magma, 1.0), {0.987053, 0.991438, 0.749504}) < 1e-6);
  QVERIFY(maxDiff(colourAt(ColourMap::Turbo, 0.0), {0.18995, 0.07176, 0.23217}) < 1e-6);
  QVERIFY(maxDiff(colourAt(ColourMap::Turbo, 1.0), {0.47960, 0.01583, 0.01055}) < 1e-6);
  // Viridis entry 128 of 255 (t = 0.50196) is (0.127568, 0.566949, 0.550556).
  QVERIFY(maxDiff(colourAt(ColourMap::Viridis, 128.0 / 255.0), {0.127568, 0.566949, 0.550556}) <
          1e-6);
  // Turbo is green-yellow in the middle: green dominates.
  const Rgb mid = colourAt(ColourMap::Turbo, 0.5);
  QVERIFY(mid[1] > mid[0] && mid[1] > mid[2]);
}

void ColourMapTest::sequentialMapsGrowLighter() {
  for (ColourMap map : {ColourMap::Viridis, ColourMap::Magma, ColourMap::Grey}) {
    double previous = -1.0;
    for (int i = 0; i <= 64; ++i) {
      const double l = luminance(colourAt(map, i / 64.0));
      QVERIFY2(l > previous, qPrintable(QString("map %1 at %2").arg(static_cast<int>(map)).arg(i)));
      previous = l;
    }
  }
}

void ColourMapTest::coolWarmIsWhiteInTheMiddleAndSymmetric() {
  const Rgb low = colourAt(ColourMap::CoolWarm, 0.0);
  const Rgb mid = colourAt(ColourMap::CoolWarm, 0.5);
  const Rgb high = colourAt(ColourMap::CoolWarm, 1.0);
  QVERIFY(low[2] > low[0] + 0.3);    // blue end
  QVERIFY(high[0] > high[2] + 0.3);  // red end
  for (double c : mid) QVERIFY(c > 0.8);
  QVERIFY(maxDiff(mid, {mid[0], mid[0], mid[0]}) < 0.02);  // neutral, no tint
  // Equal distance from zero, equal lightness: neither sign looks more important.
  for (int i = 0; i <= 16; ++i) {
    const double t = i / 32.0;
    const double a = luminance(colourAt(ColourMap::CoolWarm, t));
    const double b = luminance(colourAt(ColourMap::CoolWarm, 1.0 - t));
    QVERIFY2(std::abs(a - b) < 0.06, qPrintable(QString("t %1: %2 vs %3").arg(t).arg(a).arg(b)));
  }
}

void ColourMapTest::parameterIsClampedAndContinuous() {
  for (ColourMap map : ddfcam::gui::kColourMaps) {
    QCOMPARE(colourAt(map, -3.0), colourAt(map, 0.0));
    QCOMPARE(colourAt(map, 7.0), colourAt(map, 1.0));
    QCOMPARE(colourAt(map, std::numeric_limits<double>::quiet_NaN()), colourAt(map, 0.0));
    for (int i = 0; i < 1000; ++i) {
      const Rgb a = colourAt(map, i / 1000.0), b = colourAt(map, (i + 1) / 1000.0);
      QVERIFY(maxDiff(a, b) < 0.02);
      for (double c : a) QVERIFY(c >= 0.0 && c <= 1.0);
    }
  }
}

void ColourMapTest::namesRoundTrip() {
  std::set<std::string> names;
  for (ColourMap map : ddfcam::gui::allColourMaps()) {
    const std::string name = ddfcam::gui::colourMapName(map);
    QVERIFY(!name.empty());
    names.insert(name);
    QCOMPARE(ddfcam::gui::colourMapFromName(name), std::optional<ColourMap>(map));
  }
  QCOMPARE(names.size(), ddfcam::gui::kColourMaps.size());
  QVERIFY(!ddfcam::gui::colourMapFromName("jet").has_value());
  QCOMPARE(ddfcam::gui::defaultColourMap(true), ColourMap::CoolWarm);
  QCOMPARE(ddfcam::gui::defaultColourMap(false), ColourMap::Viridis);
}

void ColourMapTest::defaultRangeIsSymmetricForSignedFields() {
  using ddfcam::gui::defaultRange;
  auto same = [](ddfcam::gui::ValueRange r, double lo, double hi) {
    return std::abs(r.lo - lo) < 1e-12 && std::abs(r.hi - hi) < 1e-12;
  };
  QVERIFY(same(defaultRange(2.0, 5.0, false), 2.0, 5.0));
  QVERIFY(same(defaultRange(-1.0, 3.0, true), -3.0, 3.0));
  QVERIFY(same(defaultRange(-0.2, 0.05, true), -0.2, 0.2));
  QVERIFY(same(defaultRange(0.0, 0.0, true), -1.0, 1.0));
  QVERIFY(same(defaultRange(4.0, 4.0, false), 3.8, 4.2));
  QVERIFY(same(defaultRange(0.0, 0.0, false), -0.5, 0.5));
  const double nan = std::numeric_limits<double>::quiet_NaN();
  QVERIFY_THROWS_EXCEPTION(ddfcam::InvalidInput, defaultRange(nan, 1.0, false));
  QVERIFY_THROWS_EXCEPTION(ddfcam::InvalidInput, defaultRange(2.0, 1.0, true));
}

void ColourMapTest::lookupTableMapsRangeEndsToMapEnds() {
  for (ColourMap map : ddfcam::gui::kColourMaps) {
    auto table = ddfcam::gui::makeLookupTable(map, -2.0, 6.0);
    // A mapper calls Build(); it must not replace the colours with VTK's default HSV ramp.
    table->Build();
    QCOMPARE(table->GetNumberOfTableValues(), vtkIdType{256});
    QCOMPARE(table->GetRange()[0], -2.0);
    QCOMPARE(table->GetRange()[1], 6.0);
    // Table entries are quantised to 8 bits and 256 steps.
    const double tol = 2.5 / 255.0 + 1.0 / 256.0;
    QVERIFY(maxDiff(lutColour(table, -2.0), colourAt(map, 0.0)) < tol);
    QVERIFY(maxDiff(lutColour(table, 6.0), colourAt(map, 1.0)) < tol);
    QVERIFY(maxDiff(lutColour(table, 2.0), colourAt(map, 0.5)) < 0.02);
    QVERIFY(maxDiff(lutColour(table, -2.5), ddfcam::gui::belowRangeColour(map)) < tol);
    QVERIFY(maxDiff(lutColour(table, 6.5), ddfcam::gui::aboveRangeColour(map)) < tol);
    // The out-of-range colours are not colours of the map.
    double nearestBelow = 1.0, nearestAbove = 1.0;
    for (int i = 0; i <= 255; ++i) {
      nearestBelow = std::min(
          nearestBelow, maxDiff(colourAt(map, i / 255.0), ddfcam::gui::belowRangeColour(map)));
      nearestAbove = std::min(
          nearestAbove, maxDiff(colourAt(map, i / 255.0), ddfcam::gui::aboveRangeColour(map)));
    }
    QVERIFY2(nearestBelow > 0.1 && nearestAbove > 0.1, qPrintable(QString("map %1: %2 %3")
                                                                      .arg(static_cast<int>(map))
                                                                      .arg(nearestBelow)
                                                                      .arg(nearestAbove)));
  }
  auto small = ddfcam::gui::makeLookupTable(ColourMap::Grey, 0.0, 1.0, 2);
  QCOMPARE(small->GetNumberOfTableValues(), vtkIdType{2});
}

void ColourMapTest::lookupTableRejectsBadRanges() {
  using ddfcam::gui::makeLookupTable;
  QVERIFY_THROWS_EXCEPTION(ddfcam::InvalidInput, makeLookupTable(ColourMap::Viridis, 1.0, 1.0));
  QVERIFY_THROWS_EXCEPTION(ddfcam::InvalidInput, makeLookupTable(ColourMap::Viridis, 2.0, 1.0));
  QVERIFY_THROWS_EXCEPTION(
      ddfcam::InvalidInput,
      makeLookupTable(ColourMap::Viridis, 0.0, std::numeric_limits<double>::infinity()));
  QVERIFY_THROWS_EXCEPTION(ddfcam::InvalidInput, makeLookupTable(ColourMap::Viridis, 0.0, 1.0, 1));
}

void ColourMapTest::scaleLabelsStayShort() {
  using ddfcam::gui::scaleLabelFormat;
  QCOMPARE(QString::fromStdString(scaleLabelFormat(-1305.0, 1305.0)), QString("%.0f"));
  QCOMPARE(QString::fromStdString(scaleLabelFormat(0.0, 0.25)), QString("%.3f"));
  QCOMPARE(QString::fromStdString(scaleLabelFormat(-554.5, 554.5)), QString("%.0f"));
  QCOMPARE(QString::fromStdString(scaleLabelFormat(2.0, 5.0)), QString("%.2f"));
  QCOMPARE(QString::fromStdString(scaleLabelFormat(-1e6, 1e6)), QString("%.2e"));
  QCOMPARE(QString::fromStdString(scaleLabelFormat(0.0, 1e-4)), QString("%.2e"));
  // Every label of five over a range keeps three significant digits of the larger end, without
  // an exponent, in at most 8 characters.
  for (const double hi : {1e-3, 0.0123, 0.25, 1.0, 7.5, 42.0, 554.5, 1305.0, 99999.0}) {
    const std::string format = scaleLabelFormat(-hi, hi);
    for (int i = 0; i < 5; ++i) {
      char text[64];
      std::snprintf(text, sizeof text, format.c_str(), -hi + i * hi / 2.0);
      QVERIFY2(std::string(text).find('e') == std::string::npos, text);
      QVERIFY2(std::string(text).size() <= 8, text);
    }
  }
}

QTEST_APPLESS_MAIN(ColourMapTest)
#include "colour_map_test.moc"
