// SPDX-License-Identifier: MIT
// ddfcam: table-table kinematics against closed-form rotations, round trips and limits.
#include <ddfcam/error.h>
#include <ddfcam/planning/placement/machine_kinematics.h>

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>

namespace ddfcam::planning {
namespace {

constexpr double kPi = std::numbers::pi;

double rad(double deg) {
  return deg * kPi / 180.0;
}

/// Oracle: the part-to-machine map written out with explicit matrices (no Eigen::AngleAxis).
ddf::Vec3 machineOf(const TableKinematics& k, const ddf::Vec3& part, double tiltDeg, double cDeg) {
  const double t = rad(tiltDeg), c = rad(cDeg);
  Eigen::Matrix3d rz;
  rz << std::cos(c), -std::sin(c), 0, std::sin(c), std::cos(c), 0, 0, 0, 1;
  Eigen::Matrix3d tilt;
  if (k.pair == RotaryPair::AC) {
    tilt << 1, 0, 0, 0, std::cos(t), -std::sin(t), 0, std::sin(t), std::cos(t);
  } else {
    tilt << std::cos(t), 0, std::sin(t), 0, 1, 0, -std::sin(t), 0, std::cos(t);
  }
  const ddf::Vec3 q = k.pivotMm + k.rotaryOffsetMm;
  return tilt * (rz * (part - q) + q - k.pivotMm) + k.pivotMm;
}

TableKinematics machine(RotaryPair pair) {
  TableKinematics k;
  k.pair = pair;
  k.pivotMm = {12.5, -40.0, -150.0};
  k.rotaryOffsetMm = {3.0, -7.5, 20.0};
  return k;
}

ddf::Vec3 randomAxis(std::mt19937& rng, double maxTiltDeg) {
  std::uniform_real_distribution<double> u(0.0, 1.0);
  const double tilt = rad(maxTiltDeg) * u(rng);
  const double phi = 2.0 * kPi * u(rng);
  return {std::sin(tilt) * std::cos(phi), std::sin(tilt) * std::sin(phi), std::cos(tilt)};
}

class MachineKinematicsPairs : public ::testing::TestWithParam<RotaryPair> {};

TEST_P(MachineKinematicsPairs, ForwardOfInverseReturnsTipAndAxis) {
  const TableKinematics k = machine(GetParam());
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> coord(-200.0, 200.0);
  MachinePose previous;
  for (int i = 0; i < 2000; ++i) {
    const ddf::Vec3 tip(coord(rng), coord(rng), coord(rng));
    const ddf::Vec3 axis = randomAxis(rng, 115.0);
    const InverseKinematicsResult r = inverseKinematics(k, tip, axis, previous);
    ASSERT_TRUE(r.pose) << r.reason;
    const PartToolPose back = forwardKinematics(k, *r.pose);
    EXPECT_LT((back.tipMm - tip).norm(), 1e-9) << i;
    EXPECT_LT((back.axis - axis).norm(), 1e-9) << i;
    // Independent oracle: the machine position maps the part tip onto the written X Y Z.
    EXPECT_LT((machineOf(k, tip, r.pose->tiltDeg, r.pose->rotaryDeg) - r.pose->xyzMm).norm(), 1e-9);
    // The axis is turned onto machine +Z.
    const ddf::Vec3 up = machineOf(k, tip + axis, r.pose->tiltDeg, r.pose->rotaryDeg) -
                         machineOf(k, tip, r.pose->tiltDeg, r.pose->rotaryDeg);
    EXPECT_LT((up - ddf::Vec3::UnitZ()).norm(), 1e-9);
    previous = *r.pose;
  }
}

TEST_P(MachineKinematicsPairs, CircleOfAxesMovesCContinuously) {
  const TableKinematics k = machine(GetParam());
  MachinePose previous;
  const int steps = 720;
  double lastC = 0.0;
  double firstC = 0.0;
  for (int turn = 0; turn < 3 * steps; ++turn) {
    const double phi = 2.0 * kPi * turn / steps;
    const ddf::Vec3 axis(std::sin(rad(30)) * std::cos(phi), std::sin(rad(30)) * std::sin(phi),
                         std::cos(rad(30)));
    const InverseKinematicsResult r = inverseKinematics(k, ddf::Vec3(1, 2, 3), axis, previous);
    ASSERT_TRUE(r.pose);
    if (turn > 0) {
      EXPECT_LT(std::abs(r.pose->rotaryDeg - lastC), 1.0) << turn;  // 0.5 deg per step
      EXPECT_NEAR(r.pose->tiltDeg, previous.tiltDeg, 1e-9);
    }
    if (turn == 0) firstC = r.pose->rotaryDeg;
    lastC = r.pose->rotaryDeg;
    previous = *r.pose;
  }
  // Three turns of the axis are three turns of C, unwrapped (no jump back by 360).
  EXPECT_GT(std::abs(lastC - firstC), 3 * 360.0 - 2.0);
}

INSTANTIATE_TEST_SUITE_P(Pairs, MachineKinematicsPairs,
                         ::testing::Values(RotaryPair::AC, RotaryPair::BC), [](const auto& info) {
                           return std::string(info.param == RotaryPair::AC ? "AC" : "BC");
                         });

TEST(MachineKinematics, AxisTiltedTowardsYIsPlusThirtyA) {
  const TableKinematics k;  // A/C, pivot at origin
  const ddf::Vec3 axis(0.0, std::sin(rad(30)), std::cos(rad(30)));
  const InverseKinematicsResult r = inverseKinematics(k, ddf::Vec3(0, 0, 0), axis, {});
  ASSERT_TRUE(r.pose);
  EXPECT_NEAR(r.pose->tiltDeg, 30.0, 1e-12);
  EXPECT_NEAR(r.pose->rotaryDeg, 0.0, 1e-12);
  // From a previous pose near A = -30, C = 180 the other solution is the nearer one.
  const InverseKinematicsResult other = inverseKinematics(k, {0, 0, 0}, axis, {{}, -29.0, 175.0});
  ASSERT_TRUE(other.pose);
  EXPECT_NEAR(other.pose->tiltDeg, -30.0, 1e-12);
  EXPECT_NEAR(other.pose->rotaryDeg, 180.0, 1e-12);
}

TEST(MachineKinematics, BTiltTowardsMinusXIsPlusThirtyB) {
  TableKinematics k;
  k.pair = RotaryPair::BC;
  const ddf::Vec3 axis(-std::sin(rad(30)), 0.0, std::cos(rad(30)));
  const InverseKinematicsResult r = inverseKinematics(k, {0, 0, 0}, axis, {});
  ASSERT_TRUE(r.pose);
  EXPECT_NEAR(r.pose->tiltDeg, 30.0, 1e-12);
  EXPECT_NEAR(r.pose->rotaryDeg, 0.0, 1e-12);
}

TEST(MachineKinematics, PointOnPivotAxisDoesNotMoveUnderTilt) {
  TableKinematics k;
  k.pivotMm = {0.0, 10.0, -50.0};
  // A part point on the A axis stays put whatever A; the tool must sit right there.
  const ddf::Vec3 tip(5.0, 10.0, -50.0);
  const ddf::Vec3 axis(0.0, std::sin(rad(45)), std::cos(rad(45)));
  const InverseKinematicsResult r = inverseKinematics(k, tip, axis, {});
  ASSERT_TRUE(r.pose);
  EXPECT_NEAR(r.pose->tiltDeg, 45.0, 1e-12);
  EXPECT_LT((r.pose->xyzMm - tip).norm(), 1e-12);
  // A point 10 above the pivot tilts about X by 45 deg: (5, 10 - 10 sin45, -50 + 10 cos45).
  const InverseKinematicsResult up = inverseKinematics(k, {5.0, 10.0, -40.0}, axis, {});
  ASSERT_TRUE(up.pose);
  const double s = 10.0 * std::sin(rad(45));
  EXPECT_LT((up.pose->xyzMm - ddf::Vec3(5.0, 10.0 - s, -50.0 + s)).norm(), 1e-12);
}

TEST(MachineKinematics, SingularAxisKeepsPreviousC) {
  const TableKinematics k;
  const InverseKinematicsResult r =
      inverseKinematics(k, {1, 2, 3}, ddf::Vec3::UnitZ(), {{}, 10.0, 437.0});
  ASSERT_TRUE(r.pose);
  EXPECT_TRUE(r.singular);
  EXPECT_EQ(r.pose->tiltDeg, 0.0);
  EXPECT_EQ(r.pose->rotaryDeg, 437.0);
  EXPECT_LT((forwardKinematics(k, *r.pose).tipMm - ddf::Vec3(1, 2, 3)).norm(), 1e-12);
}

TEST(MachineKinematics, LimitsAreRefusedWithAReason) {
  TableKinematics k;
  k.tiltMinDeg = -30.0;
  k.tiltMaxDeg = 90.0;
  const ddf::Vec3 steep(0.0, std::sin(rad(100)), std::cos(rad(100)));
  const InverseKinematicsResult r = inverseKinematics(k, {0, 0, 0}, steep, {});
  EXPECT_FALSE(r.pose);
  EXPECT_NE(r.reason.find("A = +-100"), std::string::npos) << r.reason;
  // Within +-30 only the negative side exists beyond 30: A = -40 is refused, A = +40 with C
  // 180 taken instead.
  const ddf::Vec3 minus(0.0, -std::sin(rad(40)), std::cos(rad(40)));
  const InverseKinematicsResult m = inverseKinematics(k, {0, 0, 0}, minus, {});
  ASSERT_TRUE(m.pose);
  EXPECT_NEAR(m.pose->tiltDeg, 40.0, 1e-12);
  EXPECT_NEAR(std::abs(m.pose->rotaryDeg), 180.0, 1e-12);
  // Limited C: the value nearest the previous C within the range.
  k.rotaryLimited = true;
  k.rotaryMinDeg = -90.0;
  k.rotaryMaxDeg = 400.0;
  const ddf::Vec3 towardsX(std::sin(rad(20)), 0.0, std::cos(rad(20)));  // C = 90 or -90 + ...
  const InverseKinematicsResult c = inverseKinematics(k, {0, 0, 0}, towardsX, {{}, 0.0, 380.0});
  ASSERT_TRUE(c.pose);
  EXPECT_NEAR(c.pose->rotaryDeg, 270.0, 1e-9);  // (-20, 270) is nearer than (20, 450 > 400)
  EXPECT_NEAR(c.pose->tiltDeg, -20.0, 1e-9);
}

/// Oracle of reversed axes: the Haas UMC convention written out, axis = (sin B cos C,
/// sin B sin C, cos B) for a B/C table whose B and C count against the right-hand rule.
ddf::Vec3 reversedBcAxis(double bDeg, double cDeg) {
  const double b = rad(bDeg), c = rad(cDeg);
  return {std::sin(b) * std::cos(c), std::sin(b) * std::sin(c), std::cos(b)};
}

TEST(MachineKinematics, ReversedDirectionsNegateTheRightHandedAngles) {
  TableKinematics right = machine(RotaryPair::BC);
  TableKinematics reversed = right;
  reversed.tiltDirection = -1.0;
  reversed.rotaryDirection = -1.0;
  std::mt19937 rng(7);
  for (int i = 0; i < 200; ++i) {
    const ddf::Vec3 axis = randomAxis(rng, 100.0);
    const ddf::Vec3 tip(10.0 * i, -3.0, 40.0);
    const InverseKinematicsResult a = inverseKinematics(right, tip, axis, {});
    const InverseKinematicsResult b = inverseKinematics(reversed, tip, axis, {});
    ASSERT_TRUE(a.pose && b.pose) << i;
    EXPECT_NEAR(b.pose->tiltDeg, -a.pose->tiltDeg, 1e-9) << i;
    EXPECT_NEAR(b.pose->rotaryDeg, -a.pose->rotaryDeg, 1e-9) << i;
    EXPECT_LT((b.pose->xyzMm - a.pose->xyzMm).norm(), 1e-9) << i;
    // Against the written-out convention, and forward of inverse.
    EXPECT_LT((reversedBcAxis(b.pose->tiltDeg, b.pose->rotaryDeg) - axis).norm(), 1e-9) << i;
    const PartToolPose back = forwardKinematics(reversed, *b.pose);
    EXPECT_LT((back.axis - axis).norm(), 1e-9) << i;
    EXPECT_LT((back.tipMm - tip).norm(), 1e-9) << i;
  }
}

TEST(MachineKinematics, PreferredSolutionChoosesTheTiltSign) {
  TableKinematics k;
  k.pair = RotaryPair::BC;
  const ddf::Vec3 axis(std::sin(rad(25)) * std::cos(rad(10)), std::sin(rad(25)) * std::sin(rad(10)),
                       std::cos(rad(25)));
  for (const RotarySolution s : {RotarySolution::PositiveTilt, RotarySolution::NegativeTilt}) {
    k.solution = s;
    // From a previous pose that favours the other branch, the preference still wins.
    const MachinePose previous{{}, s == RotarySolution::PositiveTilt ? -25.0 : 25.0, 0.0};
    const InverseKinematicsResult r = inverseKinematics(k, {0, 0, 0}, axis, previous);
    ASSERT_TRUE(r.pose);
    EXPECT_NEAR(std::abs(r.pose->tiltDeg), 25.0, 1e-9);
    EXPECT_EQ(r.pose->tiltDeg > 0.0, s == RotarySolution::PositiveTilt);
    EXPECT_LT((forwardKinematics(k, *r.pose).axis - axis).norm(), 1e-9);
  }
  // When the preferred branch is beyond the limits, the other one is taken.
  k.solution = RotarySolution::PositiveTilt;
  k.tiltMinDeg = -90.0;
  k.tiltMaxDeg = 20.0;
  const InverseKinematicsResult r = inverseKinematics(k, {0, 0, 0}, axis, {});
  ASSERT_TRUE(r.pose);
  EXPECT_NEAR(r.pose->tiltDeg, -25.0, 1e-9);
  k.tiltDirection = 0.5;
  EXPECT_THROW(validateKinematics(k), InvalidInput);
}

TEST(MachineKinematics, UnreachableAxisSaysWhatWouldReachIt) {
  TableKinematics k;
  const InverseKinematicsResult down = inverseKinematics(k, {0, 0, 0}, {0, 0, -1}, {});
  ASSERT_FALSE(down.pose);
  EXPECT_NE(down.reason.find("turn the part over"), std::string::npos) << down.reason;
  const ddf::Vec3 steep(0.0, std::sin(rad(130)), std::cos(rad(130)));
  const InverseKinematicsResult far = inverseKinematics(k, {0, 0, 0}, steep, {});
  ASSERT_FALSE(far.pose);
  EXPECT_NE(far.reason.find("limits include +130"), std::string::npos) << far.reason;
  // The advice holds: a machine tilting to 130 reaches it.
  k.tiltMaxDeg = 135.0;
  EXPECT_TRUE(inverseKinematics(k, {0, 0, 0}, steep, {}).pose);
}

TEST(MachineKinematics, BadInputThrows) {
  const TableKinematics k;
  EXPECT_THROW(inverseKinematics(k, {0, 0, 0}, {0, 0, 2}, {}), InvalidInput);
  EXPECT_THROW(inverseKinematics(k, {NAN, 0, 0}, {0, 0, 1}, {}), InvalidInput);
  EXPECT_THROW(forwardKinematics(k, {{0, 0, INFINITY}, 0, 0}), InvalidInput);
  TableKinematics bad;
  bad.tiltMinDeg = 10.0;
  bad.tiltMaxDeg = -10.0;
  EXPECT_THROW(validateKinematics(bad), InvalidInput);
}

}  // namespace
}  // namespace ddfcam::planning
