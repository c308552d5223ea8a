// SPDX-License-Identifier: MIT
// Tests of field ranges and histograms against brute-force counts.
#include <ddfcam/error.h>
#include <ddfcam/planning/model/field_statistics.h>

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>
#include <vector>

namespace ddfcam::planning {
namespace {

constexpr float kNaN = std::numeric_limits<float>::quiet_NaN();
constexpr float kInf = std::numeric_limits<float>::infinity();

// Random values around [lo, hi] with NaN and infinities mixed in.
std::vector<float> randomField(std::mt19937& rng, double lo, double hi, std::size_t count) {
  const double margin = 0.2 * (hi - lo);
  std::uniform_real_distribution<double> u(lo - margin, hi + margin);
  std::vector<float> values(count);
  for (std::size_t l = 0; l < count; ++l) {
    const std::size_t r = rng() % 50;
    values[l] = r == 0 ? kNaN : r == 1 ? kInf : r == 2 ? -kInf : static_cast<float>(u(rng));
  }
  return values;
}

// The documented bins, checked one value against every bin.
Histogram bruteForce(const std::vector<float>& values, int bins, double lo, double hi) {
  Histogram h;
  h.lo = lo, h.hi = hi;
  h.counts.assign(bins, 0);
  const double w = (hi - lo) / bins;
  for (const float f : values) {
    const double x = f;
    if (std::isnan(x) || std::isinf(x)) {
      ++h.invalid;
      continue;
    }
    if (x < lo) ++h.below;
    if (x > hi) ++h.above;
    for (int b = 0; b < bins; ++b) {
      const bool last = b == bins - 1;
      if (x >= lo + b * w && (x < lo + (b + 1) * w || (last && x <= hi))) ++h.counts[b];
    }
  }
  return h;
}

void expectSame(const Histogram& a, const Histogram& b) {
  EXPECT_EQ(a.counts, b.counts);
  EXPECT_EQ(a.below, b.below);
  EXPECT_EQ(a.above, b.above);
  EXPECT_EQ(a.invalid, b.invalid);
  EXPECT_EQ(a.lo, b.lo);
  EXPECT_EQ(a.hi, b.hi);
}

TEST(FieldStatistics, HistogramMatchesBruteForceOnRandomData) {
  std::mt19937 rng(11);
  for (int trial = 0; trial < 20; ++trial) {
    const double lo = std::uniform_real_distribution<double>(-3.0, 1.0)(rng);
    const double hi = lo + std::uniform_real_distribution<double>(0.01, 4.0)(rng);
    const int bins = 1 + static_cast<int>(rng() % 40);
    const std::vector<float> values = randomField(rng, lo, hi, 5000);
    const Histogram h = histogram(values, bins, lo, hi);
    expectSame(h, bruteForce(values, bins, lo, hi));
    std::size_t total = h.below + h.above + h.invalid;
    for (std::size_t c : h.counts) total += c;
    EXPECT_EQ(total, values.size());
  }
}

TEST(FieldStatistics, HistogramEdgesFollowTheDocumentedBins) {
  // Edges -1, -0.75, ..., 1 are exact in float and double.
  const std::vector<float> values = {-1.0f,    -0.75f,  -0.5f, 0.0f, 0.25f, 0.999f, 1.0f,
                                     -1.0001f, 1.0001f, kNaN,  kInf, -kInf, 0.7499f};
  const Histogram h = histogram(values, 8, -1.0, 1.0);
  const std::vector<std::size_t> expected = {1, 1, 1, 0, 1, 1, 1, 2};
  EXPECT_EQ(h.counts, expected);
  EXPECT_EQ(h.below, 1u);
  EXPECT_EQ(h.above, 1u);
  EXPECT_EQ(h.invalid, 3u);
  EXPECT_DOUBLE_EQ(h.binWidth(), 0.25);
  EXPECT_DOUBLE_EQ(h.binCentre(0), -0.875);
  EXPECT_DOUBLE_EQ(h.binCentre(7), 0.875);
  expectSame(h, bruteForce(values, 8, -1.0, 1.0));
}

TEST(FieldStatistics, SingleBinHoldsTheClosedRange) {
  const std::vector<float> values = {0.0f, 0.5f, 1.0f, 1.5f, -0.5f};
  const Histogram h = histogram(values, 1, 0.0, 1.0);
  EXPECT_EQ(h.counts, std::vector<std::size_t>{3});
  EXPECT_EQ(h.below, 1u);
  EXPECT_EQ(h.above, 1u);
}

TEST(FieldStatistics, HistogramRejectsInvalidArguments) {
  const std::vector<float> values = {1.0f};
  EXPECT_THROW(histogram(values, 0, 0.0, 1.0), InvalidInput);
  EXPECT_THROW(histogram(values, -3, 0.0, 1.0), InvalidInput);
  EXPECT_THROW(histogram(values, 4, 1.0, 1.0), InvalidInput);
  EXPECT_THROW(histogram(values, 4, 2.0, 1.0), InvalidInput);
  EXPECT_THROW(histogram(values, 4, std::nan(""), 1.0), InvalidInput);
  EXPECT_THROW(histogram(values, 4, 0.0, std::numeric_limits<double>::infinity()), InvalidInput);
  EXPECT_THROW(histogram(values, 4, -1e308, 1e308), InvalidInput);
  EXPECT_NO_THROW(histogram({}, 4, 0.0, 1.0));
}

TEST(FieldStatistics, RangeIgnoresNonFiniteValues) {
  std::mt19937 rng(12);
  const std::vector<float> values = randomField(rng, -2.0, 5.0, 3000);
  double lo = std::numeric_limits<double>::infinity(), hi = -lo;
  std::size_t finite = 0;
  for (const float x : values) {
    if (std::isnan(x) || std::isinf(x)) continue;
    lo = std::min<double>(lo, x), hi = std::max<double>(hi, x), ++finite;
  }
  const auto range = fieldRange(values);
  ASSERT_TRUE(range);
  EXPECT_EQ(range->min, lo);
  EXPECT_EQ(range->max, hi);
  EXPECT_EQ(range->finiteCount, finite);
  EXPECT_EQ(range->invalidCount, values.size() - finite);

  const std::vector<float> none = {kNaN, kInf, -kInf};
  EXPECT_FALSE(fieldRange(none));
  EXPECT_FALSE(fieldRange({}));
  const std::vector<float> one = {kNaN, 2.5f};
  ASSERT_TRUE(fieldRange(one));
  EXPECT_EQ(fieldRange(one)->min, 2.5);
  EXPECT_EQ(fieldRange(one)->max, 2.5);
}

}  // namespace
}  // namespace ddfcam::planning

namespace ddfcam::planning {
namespace {

TEST(FieldStatistics, RobustRangeDropsFewSpikesButKeepsBroadData) {
  std::vector<float> values;
  for (int i = 0; i <= 1000; ++i) values.push_back(static_cast<float>(i) / 1000.0f - 0.5f);
  values.push_back(std::numeric_limits<float>::quiet_NaN());
  // No outliers: the full range.
  auto range = robustFieldRange(values);
  ASSERT_TRUE(range);
  EXPECT_FLOAT_EQ(range->min, -0.5f);
  EXPECT_FLOAT_EQ(range->max, 0.5f);
  EXPECT_EQ(range->invalidCount, 1u);
  // Five spikes of 100 among 1,001 values: the 1 % and 99 % quantiles, found by sorting.
  for (int i = 0; i < 5; ++i) values.push_back(100.0f);
  std::vector<float> sorted;
  for (const float v : values)
    if (std::isfinite(v)) sorted.push_back(v);
  std::sort(sorted.begin(), sorted.end());
  const auto last = static_cast<double>(sorted.size() - 1);
  range = robustFieldRange(values);
  ASSERT_TRUE(range);
  EXPECT_FLOAT_EQ(range->min, sorted[static_cast<std::size_t>(std::floor(0.01 * last))]);
  EXPECT_FLOAT_EQ(range->max, sorted[static_cast<std::size_t>(std::floor(0.99 * last))]);
  EXPECT_EQ(range->finiteCount, sorted.size());
  // Mostly zeros with a small cut area: the quantiles are degenerate, the full range stays.
  std::vector<float> removal(1000, 0.0f);
  removal[3] = 0.2f;
  range = robustFieldRange(removal);
  EXPECT_FLOAT_EQ(range->max, 0.2f);
  EXPECT_THROW(robustFieldRange(values, {.lowerFraction = 0.6}), InvalidInput);
  EXPECT_FALSE(robustFieldRange(std::vector<float>{}));
}

}  // namespace
}  // namespace ddfcam::planning
