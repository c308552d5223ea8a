// SPDX-License-Identifier: MIT
// Tests of the ROS toolpath YAML reader and of the YAML subset parser under it.
#include <ddfcam/error.h>
#include <ddfcam/io/programs/ros_toolpath_reader.h>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "programs/yaml_subset.h"

namespace ddfcam::io {
namespace {

using ::testing::HasSubstr;

/// Message of the IoError that decoding @p text throws ("" if none is thrown).
std::string decodeError(const std::string& text) {
  try {
    decodeRosToolpathYaml(text, "t.yaml");
  } catch (const IoError& e) {
    return e.what();
  }
  return "";
}

// Two paths; keys in varied order, comments, a flow sequence and quoted strings in the
// ignored header, a flow mapping for one position.
const char* const kTwoPaths = R"(# a sanding job
- paths:
    - header:
        frame_id: "part # 1"   # not a comment inside quotes
        seq: [1, 2, 3]
      poses:
        - position:
            z: 0.003
            x: 0.001
            y: 0.002
          orientation: {w: 1, x: 0, y: 0, z: 0}
        - orientation:
            x: 0.7071067811865476
            y: 0
            z: 0
            w: 0.7071067811865476
          position: {x: -1, y: 0.5, z: 2.5e-3}
    - poses:
        - position: {x: 0, y: 0, z: 0}
          orientation: {x: 0, y: 1, z: 0, w: 0}
  process_type:
    val: "\x01"
)";

TEST(RosToolpathReader, ReadsPositionsInMillimetresAndAxesFromQuaternions) {
  const planning::ClProgram program = decodeRosToolpathYaml(kTwoPaths, "job.yaml");
  ASSERT_EQ(program.points.size(), 3u);
  EXPECT_EQ(program.sourceUnit, LengthUnit::Metre);
  EXPECT_EQ(program.pointKind, planning::ClPointKind::ToolReference);
  EXPECT_EQ(program.pathCount(), 2);
  const planning::ClPoint& a = program.points[0];
  EXPECT_EQ(a.path, 0);
  EXPECT_EQ(a.point, 0);
  EXPECT_TRUE(a.positionMm.isApprox(ddf::Vec3(1, 2, 3), 1e-12));
  ASSERT_TRUE(a.axis.has_value());
  EXPECT_TRUE(a.axis->isApprox(ddf::Vec3::UnitZ(), 1e-12));  // identity
  EXPECT_EQ(a.move, planning::MoveKind::Cut);
  EXPECT_EQ(a.feedMmPerMin, 0.0);
  EXPECT_EQ(a.sourceLine, 7);
  const planning::ClPoint& b = program.points[1];
  EXPECT_EQ(b.point, 1);
  EXPECT_TRUE(b.positionMm.isApprox(ddf::Vec3(-1000, 500, 2.5), 1e-12));
  // 90 degrees about +x turns +z into -y.
  EXPECT_LT((*b.axis - ddf::Vec3(0, -1, 0)).norm(), 1e-12);
  const planning::ClPoint& c = program.points[2];
  EXPECT_EQ(c.path, 1);
  EXPECT_EQ(c.point, 0);
  // 180 degrees about +y turns +z into -z.
  EXPECT_LT((*c.axis - ddf::Vec3(0, 0, -1)).norm(), 1e-12);
  ASSERT_EQ(program.comments.size(), 1u);
  EXPECT_EQ(program.comments[0], "frame_id: part # 1");
  EXPECT_TRUE(program.warnings.empty());
}

TEST(RosToolpathReader, AcceptsARootMappingAndNormalisesQuaternionsWithAWarning) {
  const std::string text =
      "paths:\n"
      "- poses:\n"
      "  - position: {x: 0, y: 0, z: 1}\n"
      "    orientation: {x: 0, y: 0, z: 0, w: 2}\n"
      "- poses: []\n";
  const planning::ClProgram program = decodeRosToolpathYaml(text, "t.yaml");
  ASSERT_EQ(program.points.size(), 1u);
  EXPECT_TRUE(program.points[0].axis->isApprox(ddf::Vec3::UnitZ(), 1e-15));
  ASSERT_EQ(program.warnings.size(), 2u);
  EXPECT_EQ(program.warnings[0].line, 4);
  EXPECT_THAT(program.warnings[0].text, HasSubstr("normalised"));
  EXPECT_THAT(program.warnings[1].text, HasSubstr("empty 'poses'"));
}

TEST(RosToolpathReader, RejectsBadStructureWithTheLine) {
  const std::string pose = "- paths:\n  - poses:\n    - position: {x: 0, y: 0, z: 0}\n";
  EXPECT_THAT(decodeError(pose + "      orientation: {x: 0, y: 0, z: 0, w: 0}\n"),
              HasSubstr("t.yaml: line 4: zero quaternion"));
  EXPECT_THAT(decodeError(pose + "      orientation: {x: 0, y: 0, z: 0}\n"),
              HasSubstr("line 4: missing 'w' in an orientation"));
  EXPECT_THAT(decodeError(pose + "      orientation: {x: a, y: 0, z: 0, w: 1}\n"),
              HasSubstr("line 4: expected a number for 'x'"));
  EXPECT_THAT(decodeError(pose + "      orientation: {x: \"1\", y: 0, z: 0, w: 1}\n"),
              HasSubstr("line 4: expected a number"));
  EXPECT_THAT(decodeError(pose), HasSubstr("line 3: missing 'orientation' in a pose"));
  EXPECT_THAT(decodeError("- paths:\n  - header: {}\n"), HasSubstr("line 2: missing 'poses'"));
  EXPECT_THAT(decodeError("- paths: 3\n"), HasSubstr("line 1: 'paths' must be a list"));
  EXPECT_THAT(decodeError("crs:\n  general: {}\n"), HasSubstr("not a ROS toolpath"));
  EXPECT_THAT(decodeError("- paths: []\n"), HasSubstr("t.yaml: no poses"));
  EXPECT_THAT(decodeError(""), HasSubstr("not a ROS toolpath"));
}

TEST(RosToolpathReader, RejectsYamlOutsideTheSubsetWithTheLine) {
  EXPECT_THAT(decodeError("a:\n\tb: 1\n"), HasSubstr("line 2: tab in indentation"));
  EXPECT_THAT(decodeError("a: 1\n  b: 2\n"), HasSubstr("line 2: unexpected indentation"));
  EXPECT_THAT(decodeError("a: 1\na: 2\n"), HasSubstr("line 2: duplicate key 'a'"));
  EXPECT_THAT(decodeError("a: [1, 2\n"), HasSubstr("line 1: flow sequence not closed"));
  EXPECT_THAT(decodeError("a: &x 1\n"), HasSubstr("line 1: unsupported YAML feature"));
  EXPECT_THAT(decodeError("a: |\n  text\n"), HasSubstr("unsupported YAML feature"));
  EXPECT_THAT(decodeError("a: \"open\n"), HasSubstr("line 1: quoted scalar not closed"));
  EXPECT_THAT(decodeError("a: b: c\n"), HasSubstr("line 1: a mapping value is not allowed"));
  EXPECT_THAT(decodeError("a: 1\n---\nb: 2\n"), HasSubstr("line 2: several documents"));
  EXPECT_THAT(decodeError("a: \"\\q\"\n"), HasSubstr("unknown escape"));
  EXPECT_THAT(decodeError(std::string("a: 1\n\0\n", 7)), HasSubstr("line 2: control character"));
  EXPECT_THAT(decodeError("- a\nb: 1\n"), HasSubstr("line 2: unexpected"));
}

TEST(YamlSubset, ParsesNestedBlocksFlowAndQuotedScalars) {
  const std::string text =
      "---\n"
      "list:\n"
      "- - a\n"
      "  - 'it''s'\n"
      "- {k: [1, [2, 3]], e: }\n"
      "map:\n"
      "  \"quoted key\": \"tab\\tand \\u00e9\"\n"
      "  empty:\n"
      "  n: ~\n"
      "...\n";
  const detail::YamlNode root = detail::parseYamlSubset(text, "t.yaml");
  ASSERT_EQ(root.kind, detail::YamlKind::Mapping);
  const detail::YamlNode& list = *root.find("list");
  ASSERT_EQ(list.items.size(), 2u);
  ASSERT_EQ(list.items[0].kind, detail::YamlKind::Sequence);
  EXPECT_EQ(list.items[0].items[1].text, "it's");
  const detail::YamlNode& flow = list.items[1];
  EXPECT_EQ(flow.find("k")->items[1].items[1].text, "3");
  EXPECT_EQ(flow.find("e")->kind, detail::YamlKind::Null);
  const detail::YamlNode& map = *root.find("map");
  EXPECT_EQ(map.find("quoted key")->text, "tab\tand \xC3\xA9");
  EXPECT_EQ(map.find("empty")->kind, detail::YamlKind::Null);
  EXPECT_EQ(map.find("n")->kind, detail::YamlKind::Null);
  EXPECT_EQ(map.entries[0].value.line, 7);
}

TEST(YamlSubset, GuardsDepthAndSize) {
  // Deep flow and block nesting: a clear error, not a stack overflow.
  const std::string flow = "a: " + std::string(100000, '[') + std::string(100000, ']') + "\n";
  EXPECT_THROW(detail::parseYamlSubset(flow, "t"), IoError);
  std::string block;
  for (int i = 0; i < 200; ++i) block += std::string(static_cast<std::size_t>(i), ' ') + "k:\n";
  EXPECT_THAT(decodeError(block), HasSubstr("nesting deeper than 64"));
  std::string dashes;
  for (int i = 0; i < 5000; ++i) dashes += "- ";
  EXPECT_THAT(decodeError(dashes + "x\n"), HasSubstr("nesting deeper than 64"));
  detail::YamlLimits limits;
  limits.maxNodes = 1000;
  std::string many = "a: [";
  for (int i = 0; i < 2000; ++i) many += "0, ";
  many += "0]\n";
  EXPECT_THROW(detail::parseYamlSubset(many, "t", limits), IoError);
  EXPECT_THAT(decodeError("a: " + std::string(5000, 'x') + "\n"), HasSubstr("longer than"));
}

TEST(RosToolpathReader, EveryTruncationOfAValidFileReadsOrFailsCleanly) {
  const std::string text = kTwoPaths;
  int failures = 0;
  for (std::size_t n = 0; n <= text.size(); ++n) {
    try {
      const planning::ClProgram program = decodeRosToolpathYaml(text.substr(0, n), "t.yaml");
      EXPECT_LE(program.points.size(), 3u);
      for (const planning::ClPoint& p : program.points) EXPECT_NEAR(p.axis->norm(), 1.0, 1e-12);
    } catch (const IoError&) {
      ++failures;
    }
  }
  EXPECT_GT(failures, 0);
}

}  // namespace
}  // namespace ddfcam::io
