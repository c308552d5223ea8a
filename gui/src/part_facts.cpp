// SPDX-License-Identifier: MIT
// ddfcam gui: part facts for the Part panel and the status bar.
#include <ddfcam/gui/part_facts.h>

#include <algorithm>
#include <iomanip>
#include <limits>
#include <sstream>

namespace ddfcam::gui {
namespace {

std::string withThousands(long long value) {
  const std::string digits = std::to_string(value);
  std::string out;
  for (std::size_t i = 0; i < digits.size(); ++i) {
    if (i > 0 && (digits.size() - i) % 3 == 0) out += ',';
    out += digits[i];
  }
  return out;
}

std::string mm(double value) {
  std::ostringstream out;
  out << std::setprecision(3) << value << " mm";
  return out.str();
}

}  // namespace

std::array<double, 3> PartFacts::sizeMm() const {
  const ddf::Vec3 d = boundsMm[1] - boundsMm[0];
  return {d.x(), d.y(), d.z()};
}

PartFacts partFacts(const ddf::DisplacementField& ddf) {
  PartFacts facts;
  const int m = ddf.resolution();
  ddf::Vec3 lo = ddf::Vec3::Constant(std::numeric_limits<double>::infinity());
  ddf::Vec3 hi = -lo;
  double longestEdge = 0.0;
  for (int f = 0; f < ddf.faceCount(); ++f) {
    for (int i = 0; i < m; ++i)
      for (int k = 0; i + k < m; ++k) {
        const ddf::Vec3 q = ddf.surfacePoint(f, i, k);
        lo = lo.cwiseMin(q);
        hi = hi.cwiseMax(q);
      }
    const auto& v = ddf.faceVertices(f);
    for (int e = 0; e < 3; ++e)
      longestEdge =
          std::max(longestEdge, (ddf.position(v[e]) - ddf.position(v[(e + 1) % 3])).norm());
  }
  if (ddf.faceCount() == 0) return facts;
  facts.boundsMm = {lo, hi};
  facts.rasterSpacingMm = m > 1 ? longestEdge / (m - 1) : 0.0;
  facts.reach = ddf::crustReach(ddf);
  return facts;
}

std::string sizeLine(const std::array<double, 3>& sizeMm) {
  std::ostringstream out;
  out << std::setprecision(3) << sizeMm[0] << " x " << sizeMm[1] << " x " << sizeMm[2] << " mm";
  return out.str();
}

std::string supportLine(const ddf::DisplacementField& ddf, const PartFacts& facts) {
  return "support " + withThousands(ddf.faceCount()) +
         " faces, m = " + std::to_string(ddf.resolution()) + ", spacing " +
         mm(facts.rasterSpacingMm);
}

std::string reachLine(const ddf::CrustReach& reach, bool above) {
  return "min " + mm(above ? reach.minAboveMm : reach.minBelowMm) + ", median " +
         mm(above ? reach.medianAboveMm : reach.medianBelowMm);
}

}  // namespace ddfcam::gui
