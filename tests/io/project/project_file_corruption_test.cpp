// SPDX-License-Identifier: MIT
#include <ddfcam/error.h>
#include <ddfcam/io/mesh/ddf_file.h>
#include <ddfcam/io/project/project_file.h>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cstdio>
#include <cstdlib>
#include <map>
#include <random>

#include "../io_test_support.h"
#include "common/byte_codec.h"
#include "project/project_chunks.h"
#include "project/project_layout.h"
#include "project_test_support.h"

namespace ddfcam::io {
namespace {

using ::testing::HasSubstr;

std::string smallFile() {
  return encodeProject(test::makeSmallProject());
}

std::string decodeError(const std::string& bytes) {
  return test::ioErrorMessage([&] { decodeProject(bytes, "p.ddfproj"); });
}

/// Offset of the header of the @p n-th chunk (0-based) of a well-formed file.
std::size_t chunkOffset(const std::string& bytes, int n) {
  std::size_t at = detail::kProjectHeaderBytes;
  for (int i = 0; i < n; ++i) at += 12 + detail::getU64(bytes.data() + at + 4);
  return at;
}

/// A file whose chunks are written here by hand, with a correct envelope.
std::string forged(const std::vector<std::pair<std::string, std::string>>& chunks) {
  detail::ProjectEncoder encoder;
  for (const auto& [tag, payload] : chunks) encoder.beginChunk(tag).append(payload);
  return encoder.finish();
}

std::string infoPayload() {
  std::string out;
  detail::putProjectInfo(out, planning::Project{});
  return out;
}

TEST(ProjectFileCorruption, MissingAndEmptyFiles) {
  test::ScratchDir dir;
  EXPECT_THAT(test::ioErrorMessage([&] { readProject(dir / "none.ddfproj"); }),
              HasSubstr("none.ddfproj does not exist"));
  test::writeBytes(dir / "empty.ddfproj", "");
  EXPECT_THAT(test::ioErrorMessage([&] { readProject(dir / "empty.ddfproj"); }),
              HasSubstr("empty.ddfproj: file is empty"));
}

TEST(ProjectFileCorruption, TruncationAtEveryByteIsReported) {
  const std::string bytes = smallFile();
  for (std::size_t size = 1; size < bytes.size(); ++size) {
    const std::string message = decodeError(bytes.substr(0, size));
    EXPECT_THAT(message, HasSubstr("p.ddfproj: truncated project file")) << "size " << size;
  }
  // A cut inside the field chunk (the 6th: PROJ PART DSGN TOOL PATH FELD ...) names it.
  const std::size_t field = chunkOffset(bytes, 5);
  ASSERT_EQ(bytes.substr(field, 4), "FELD");
  EXPECT_THAT(decodeError(bytes.substr(0, field + 20)), HasSubstr("it ends in chunk 6 ('FELD')"));
  EXPECT_THAT(decodeError(bytes.substr(0, field)), HasSubstr("it ends after chunk 5 ('PATH')"));
  EXPECT_THAT(decodeError(bytes.substr(0, bytes.size() - 2)), HasSubstr("ends in the checksum"));
}

TEST(ProjectFileCorruption, EveryFlippedByteIsDetected) {
  const std::string bytes = smallFile();
  for (std::size_t at = 0; at < bytes.size(); ++at)
    for (const unsigned char mask : {0x01, 0x80, 0xFF}) {
      std::string bad = bytes;
      bad[at] = static_cast<char>(bad[at] ^ mask);
      const std::string message = decodeError(bad);
      EXPECT_THAT(message, HasSubstr("p.ddfproj: ")) << "byte " << at;
      if (at >= 12 && (at < 16 || at >= 24)) {
        EXPECT_THAT(message, HasSubstr("damaged project file (checksum mismatch)")) << at;
      }
    }
}

TEST(ProjectFileCorruption, HeaderProblemsAreNamed) {
  const std::string bytes = smallFile();
  std::string magic = bytes;
  magic[3] = 'X';
  EXPECT_THAT(decodeError(magic), HasSubstr("p.ddfproj: not a ddfcam project file"));
  EXPECT_THAT(decodeError("solid cube\n facet normal 0 0 1\n"),
              HasSubstr("not a ddfcam project file (wrong magic)"));
  ddf::PlanePatchParams params;
  params.cellsX = params.cellsY = 1;
  EXPECT_THAT(decodeError(encodeDdf(ddf::planePatch(params).ddf)),
              HasSubstr("it is a .ddf field file"));
  std::string newer = bytes;
  test::putLeAt(newer, 8, 5, 4);
  const std::string newerMessage =
      "p.ddfproj: written by a newer ddfcam (format version 5, this build reads up to 4)";
  EXPECT_THAT(decodeError(newer), HasSubstr(newerMessage));
  EXPECT_THAT(decodeError(test::resealed(newer)), HasSubstr(newerMessage));
  std::string zero = bytes;
  test::putLeAt(zero, 8, 0, 4);
  EXPECT_THAT(decodeError(test::resealed(zero)), HasSubstr("invalid format version 0"));
  EXPECT_THAT(decodeError(bytes + "x"), HasSubstr("damaged project file"));
  std::string count = bytes;
  test::putLeAt(count, 12, 99, 4);
  EXPECT_THAT(decodeError(test::resealed(count)),
              HasSubstr("announces 99 chunks, the file holds 9"));
}

TEST(ProjectFileCorruption, UnknownAndMisplacedChunksAreRejected) {
  const std::string bytes = smallFile();
  std::string unknown = bytes;
  unknown.replace(chunkOffset(bytes, 3), 4, "TOOX");
  const std::string message = decodeError(test::resealed(unknown));
  EXPECT_THAT(message, HasSubstr("chunk 4 ('TOOX')"));
  EXPECT_THAT(message, HasSubstr("unknown chunk type in format version 4"));
  EXPECT_THAT(decodeError(forged({})), HasSubstr("no 'PROJ' chunk"));
  EXPECT_THAT(decodeError(forged({{"TOOL", ""}, {"PROJ", infoPayload()}})),
              HasSubstr("the first chunk must be 'PROJ'"));
  EXPECT_THAT(decodeError(forged({{"PROJ", infoPayload()}, {"PROJ", infoPayload()}})),
              HasSubstr("chunk 2 ('PROJ'): a second project header"));
  const std::string part = encodeDdf(*test::makeSmallProject().part);
  EXPECT_THAT(decodeError(forged({{"PROJ", infoPayload()}, {"PART", part}, {"PART", part}})),
              HasSubstr("a second part"));
  EXPECT_THAT(decodeError(forged({{"PROJ", infoPayload() + "z"}})),
              HasSubstr("1 unexpected bytes at the end of the payload"));
}

TEST(ProjectFileCorruption, HostileLengthsFailWithoutHugeAllocations) {
  std::string hugeString = infoPayload();
  test::putLeAt(hugeString, 0, 0xFFFFFFFFu, 4);
  EXPECT_THAT(decodeError(forged({{"PROJ", hugeString}})),
              HasSubstr("the part name claims 4294967295 bytes"));
  std::string field;
  detail::putString(field, "f");
  detail::putString(field, "");
  field += '\0';
  detail::putU64(field, std::uint64_t{1} << 61);
  EXPECT_THAT(decodeError(forged({{"PROJ", infoPayload()}, {"FELD", field}})),
              HasSubstr("the field values count 2305843009213693952 needs more than"));
  std::string mesh;
  detail::putU64(mesh, 1);
  detail::putU64(mesh, ~std::uint64_t{0} / 12);
  EXPECT_THAT(decodeError(forged({{"PROJ", infoPayload()}, {"DSGN", mesh + std::string(24, 0)}})),
              HasSubstr("the design mesh claims 1 vertices"));
  std::string chunkLength = forged({{"PROJ", infoPayload()}});
  test::putLeAt(chunkLength, 24 + 4, ~std::uint64_t{0}, 8);
  EXPECT_THAT(decodeError(test::resealed(chunkLength)),
              HasSubstr("chunk 1 ('PROJ') claims 18446744073709551615 payload bytes"));
  std::string path;
  detail::putString(path, "p");
  detail::putU32(path, 0);
  detail::putF64(path, 1.0);
  detail::putU64(path, std::uint64_t{1} << 60);
  EXPECT_THAT(decodeError(forged({{"PROJ", infoPayload()}, {"PATH", path}})),
              HasSubstr("the path poses count"));
}

TEST(ProjectFileCorruption, InvalidValuesWithAValidChecksumAreNamed) {
  planning::Project project = test::makeSmallProject();
  planning::ToolPath path = project.paths[0];
  path.tool = 7;
  std::string payload;
  detail::putPath(payload, path);
  const std::string part = encodeDdf(*project.part);
  std::string tool;
  detail::putTool(tool, project.tools[0]);
  const std::string message = decodeError(
      forged({{"PROJ", infoPayload()}, {"PART", part}, {"TOOL", tool}, {"PATH", payload}}));
  EXPECT_THAT(message, HasSubstr("p.ddfproj: the project in the file is invalid"));
  EXPECT_THAT(message, HasSubstr("path 'p': tool index 7 out of range (1 tools)"));
  std::string state;
  detail::putState(state, {"stock", {1.0f, 2.0f}});
  EXPECT_THAT(decodeError(forged({{"PROJ", infoPayload()}, {"PART", part}, {"STAT", state}})),
              HasSubstr("state 'stock': 2 values, expected 12"));
  std::string badPart = part;
  badPart[50] ^= 1;
  const std::string partMessage = decodeError(forged({{"PROJ", infoPayload()}, {"PART", badPart}}));
  EXPECT_THAT(partMessage, HasSubstr("chunk 2 ('PART'): the embedded part is not a valid .ddf"));
  EXPECT_THAT(partMessage, HasSubstr("checksum mismatch"));
  std::string field;
  detail::putField(field, {"f", "", false, {}});
  field[4 + 1 + 4] = 2;
  EXPECT_THAT(decodeError(forged({{"PROJ", infoPayload()}, {"FELD", field}})),
              HasSubstr("signed flag 2 is neither 0 nor 1"));
}

TEST(ProjectFileCorruption, DamagedRegionPlansAreNamed) {
  const planning::Project project = test::makeSmallProject();
  const std::string part = encodeDdf(*project.part);
  std::string tool;
  detail::putTool(tool, project.tools[0]);
  auto decodeRegion = [&](const std::string& region) {
    return decodeError(
        forged({{"PROJ", infoPayload()}, {"PART", part}, {"TOOL", tool}, {"REGN", region}}));
  };
  planning::Region region = project.regions[0];
  std::string good;
  detail::putRegion(good, region);
  // Plan offset: name (4 + 1), colour (12), faces (8 + 4); the stroke count sits after
  // 4 + 4 + 24 + 1 + 8 + 4 + 8 + 8 + 4 + 4 = 69 plan bytes.
  const std::size_t planAt = 5 + 12 + 12;
  std::string flag = good;
  flag[planAt + 32] = 2;
  EXPECT_THAT(decodeRegion(flag), HasSubstr("chunk 4 ('REGN'): region 'r': smoothing flag 2"));
  std::string strokes = good;
  test::putLeAt(strokes, planAt + 69, std::uint64_t{1} << 61, 8);
  EXPECT_THAT(decodeRegion(strokes), HasSubstr("the plan stroke count 2305843009213693952"));
  std::string points = good;
  test::putLeAt(points, planAt + 77, ~std::uint64_t{0}, 8);
  EXPECT_THAT(decodeRegion(points), HasSubstr("the plan stroke point count"));
  EXPECT_THAT(decodeRegion(good.substr(0, good.size() - 3)), HasSubstr("the plan stroke point"));
  region.plan.feedSign = 0;
  std::string sign;
  detail::putRegion(sign, region);
  const std::string message = decodeRegion(sign);
  EXPECT_THAT(message, HasSubstr("p.ddfproj: the project in the file is invalid"));
  EXPECT_THAT(message, HasSubstr("region 'r' plan: feed sign 0 must be +1 or -1"));
  region.plan.feedSign = 1;
  region.plan.linking = static_cast<planning::LinkingOrder>(9);
  std::string linking;
  detail::putRegion(linking, region);
  EXPECT_THAT(decodeRegion(linking), HasSubstr("region 'r' plan: unknown linking order 9"));
}

/// Header offset of the chunk whose payload holds byte @p at of a well-formed file, or 0.
std::size_t payloadOwner(const std::string& bytes, std::size_t at) {
  for (std::size_t chunk = detail::kProjectHeaderBytes; chunk + 4 < bytes.size();) {
    const std::size_t end = chunk + 12 + detail::getU64(bytes.data() + chunk + 4);
    if (at >= chunk + 12 && at < end) return chunk;
    chunk = end;
  }
  return 0;
}

/// One random edit: flipped bits, an overwritten number (often an extreme count), bytes
/// inserted into or removed from a payload (usually with the chunk length adjusted); then the
/// header size and the CRC are usually repaired so that the structural checks behind them run.
std::string mutate(std::string bytes, std::mt19937& rng) {
  auto pick = [&](std::size_t n) {
    return std::uniform_int_distribution<std::size_t>(0, n - 1)(rng);
  };
  const std::size_t at = detail::kProjectHeaderBytes + pick(bytes.size() - 28);
  const std::size_t owner = payloadOwner(bytes, at);
  const bool adjustLength = owner != 0 && pick(4) != 0;
  std::int64_t delta = 0;
  switch (pick(5)) {
    case 0:
      for (std::size_t i = 0, n = 1 + pick(4); i < n; ++i)
        bytes[at + pick(bytes.size() - at - 4)] ^= static_cast<char>(1 << pick(8));
      break;
    case 1: {
      static constexpr std::uint64_t kValues[] = {
          0, 1, 2, 3, 7, 0xFF, 0xFFFF, 0xFFFFFFFFu, 1ull << 32, 1ull << 62, ~0ull};
      const int width = pick(2) ? 4 : 8;
      if (at + width + 4 <= bytes.size())
        test::putLeAt(bytes, at, kValues[pick(std::size(kValues))], width);
      break;
    }
    case 2: {
      const std::size_t n = 1 + pick(16);
      bytes.insert(at, std::string(n, static_cast<char>(pick(256))));
      delta = static_cast<std::int64_t>(n);
      break;
    }
    case 3: {
      const std::size_t n = std::min<std::size_t>(1 + pick(16), bytes.size() - at - 4);
      const std::size_t kept =
          owner ? std::min(n, owner + 12 + detail::getU64(bytes.data() + owner + 4) - at) : n;
      bytes.erase(at, kept);
      delta = -static_cast<std::int64_t>(kept);
      break;
    }
    default:
      bytes[at] = static_cast<char>(pick(256));
  }
  if (adjustLength && delta != 0)
    test::putLeAt(bytes, owner + 4, detail::getU64(bytes.data() + owner + 4) + delta, 8);
  return pick(10) == 0 ? bytes : test::resized(std::move(bytes));
}

TEST(ProjectFileCorruption, RandomMutationsThrowIoErrorOrDecodeToAValidProject) {
  const std::string bytes = smallFile();
  // DDFCAM_FUZZ_SEED runs a different (and longer) sequence, e.g. under the sanitizer build.
  const char* seed = std::getenv("DDFCAM_FUZZ_SEED");
  std::mt19937 rng(seed ? static_cast<unsigned>(std::strtoul(seed, nullptr, 10)) : 20240611u);
  const int trials = seed ? 30000 : 3000;
  int decoded = 0;
  int payloadErrors = 0;  // failures inside a chunk payload, past the envelope checks
  int invalid = 0;        // failures of planning::validateProject
  for (int trial = 0; trial < trials; ++trial) {
    const std::string bad = mutate(bytes, rng);
    try {
      const planning::Project project = decodeProject(bad, "fuzz.ddfproj");
      ++decoded;
      EXPECT_NO_THROW(planning::validateProject(project)) << "trial " << trial;
      EXPECT_TRUE(planning::projectsEqual(project, decodeProject(encodeProject(project), "again")))
          << "trial " << trial;
    } catch (const IoError& e) {
      EXPECT_THAT(e.what(), HasSubstr("fuzz.ddfproj: ")) << "trial " << trial;
      payloadErrors += std::string_view(e.what()).starts_with("fuzz.ddfproj: chunk ");
      invalid += std::string_view(e.what()).find("the project in the file is invalid") !=
                 std::string_view::npos;
    } catch (const std::exception& e) {
      ADD_FAILURE() << "trial " << trial << ": " << typeid(e).name() << ": " << e.what();
    }
  }
  // The repaired sizes and CRCs let most edits through the envelope to the parsers behind it.
  EXPECT_GT(decoded, 100);
  EXPECT_GT(payloadErrors, 300);
  EXPECT_GT(invalid, 10);
}

}  // namespace
}  // namespace ddfcam::io
