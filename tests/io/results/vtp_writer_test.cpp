// SPDX-License-Identifier: MIT
// Tests of the .vtp writer: the written XML parsed back by an independent minimal reader.
#include <ddfcam/io/results/vtp_writer.h>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <map>
#include <random>
#include <sstream>

#include "../io_test_support.h"

namespace ddfcam::io {
namespace {

using ::testing::HasSubstr;

/// An XML element as the minimal reader sees it.
struct XmlElement {
  std::string name;
  std::map<std::string, std::string> attributes;
  std::string text;  ///< character data directly inside the element
  std::vector<XmlElement> children;

  const XmlElement& child(const std::string& childName) const {
    for (const XmlElement& c : children)
      if (c.name == childName) return c;
    throw std::runtime_error("no <" + childName + "> in <" + name + ">");
  }
};

/// Reads the element starting at text[at] == '<' (no comments, CDATA or entities: the writer
/// emits none, so meeting one is a test failure through the exception).
XmlElement parseElement(const std::string& text, std::size_t& at) {
  XmlElement e;
  std::size_t end = text.find_first_of(" \t\n/>", ++at);
  e.name = text.substr(at, end - at);
  at = end;
  for (;;) {
    at = text.find_first_not_of(" \t\n", at);
    if (text.compare(at, 2, "/>") == 0) {
      at += 2;
      return e;
    }
    if (text[at] == '>') break;
    const std::size_t eq = text.find('=', at);
    const std::size_t close = text.find('"', eq + 2);
    if (text[eq + 1] != '"') throw std::runtime_error("unquoted attribute in <" + e.name + ">");
    e.attributes[text.substr(at, eq - at)] = text.substr(eq + 2, close - eq - 2);
    at = close + 1;
  }
  ++at;
  for (;;) {
    const std::size_t lt = text.find('<', at);
    e.text += text.substr(at, lt - at);
    at = lt;
    if (text.compare(at, 2, "</") == 0) break;
    e.children.push_back(parseElement(text, at));
  }
  const std::string closing = "</" + e.name + ">";
  if (text.compare(at, closing.size(), closing) != 0)
    throw std::runtime_error("<" + e.name + "> not closed");
  at += closing.size();
  return e;
}

XmlElement parseDocument(const std::string& text) {
  std::size_t at = 0;
  if (text.compare(0, 5, "<?xml") == 0) at = text.find("?>") + 2;
  at = text.find('<', at);
  return parseElement(text, at);
}

std::vector<std::string> words(const std::string& text) {
  std::istringstream in(text);
  std::vector<std::string> out;
  for (std::string w; in >> w;) out.push_back(w);
  return out;
}

/// DataArray contents parsed with the C library's own conversion (independent of to_chars).
std::vector<double> doubles(const XmlElement& array) {
  std::vector<double> out;
  for (const std::string& w : words(array.text)) out.push_back(std::strtod(w.c_str(), nullptr));
  return out;
}

std::vector<float> floats(const XmlElement& array) {
  std::vector<float> out;
  for (const std::string& w : words(array.text)) out.push_back(std::strtof(w.c_str(), nullptr));
  return out;
}

/// Bitwise equality, so that -0.0 and NaN are checked too.
bool sameFloat(float a, float b) {
  return std::isnan(a) ? std::isnan(b) : a == b && std::signbit(a) == std::signbit(b);
}

ddf::TriangleMesh twoTriangles() {
  ddf::TriangleMesh mesh;
  mesh.vertices = {{0.0, 0.0, 0.0}, {1.0 / 3.0, 0.0, 1e-300}, {1.0, 2.0, -7.25}, {-0.1, 1e17, 3.0}};
  mesh.triangles = {{0, 1, 2}, {0, 2, 3}};
  return mesh;
}

TEST(VtpWriter, HeaderCountsAndArrayNamesReadBack) {
  test::ScratchDir dir;
  const ddf::TriangleMesh mesh = twoTriangles();
  VtpPointData data;
  data.scalars = {{"k_max", {0.5f, -0.25f, 1e-30f, 3.0f}}, {"max tool radius", {1, 2, 3, 4}}};
  data.vectors = {{"dir_max", {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {0.6, 0.8, 0}}}};
  writeVtp(mesh, data, dir / "two.vtp");
  const XmlElement root = parseDocument(test::readBytes(dir / "two.vtp"));
  EXPECT_EQ(root.name, "VTKFile");
  EXPECT_EQ(root.attributes.at("type"), "PolyData");
  EXPECT_EQ(root.attributes.at("version"), "0.1");
  const XmlElement& piece = root.child("PolyData").child("Piece");
  EXPECT_EQ(piece.attributes.at("NumberOfPoints"), "4");
  EXPECT_EQ(piece.attributes.at("NumberOfPolys"), "2");
  const XmlElement& pointData = piece.child("PointData");
  EXPECT_EQ(pointData.attributes.at("Scalars"), "k_max");
  EXPECT_EQ(pointData.attributes.at("Vectors"), "dir_max");
  ASSERT_EQ(pointData.children.size(), 3u);
  EXPECT_EQ(pointData.children[0].attributes.at("Name"), "k_max");
  EXPECT_EQ(pointData.children[1].attributes.at("Name"), "max tool radius");
  EXPECT_EQ(pointData.children[2].attributes.at("Name"), "dir_max");
  EXPECT_EQ(pointData.children[2].attributes.at("NumberOfComponents"), "3");
  for (const XmlElement& a : pointData.children) {
    EXPECT_EQ(a.attributes.at("type"), "Float32");
    EXPECT_EQ(a.attributes.at("format"), "ascii");
  }
  const XmlElement& polys = piece.child("Polys");
  ASSERT_EQ(polys.children.size(), 2u);
  EXPECT_EQ(polys.children[0].attributes.at("Name"), "connectivity");
  EXPECT_EQ(doubles(polys.children[0]), (std::vector<double>{0, 1, 2, 0, 2, 3}));
  EXPECT_EQ(polys.children[1].attributes.at("Name"), "offsets");
  EXPECT_EQ(doubles(polys.children[1]), (std::vector<double>{3, 6}));
}

TEST(VtpWriter, PointsAndValuesRoundTripExactly) {
  test::ScratchDir dir;
  std::mt19937 random(7);
  std::uniform_real_distribution<double> mantissa(-1.0, 1.0);
  std::uniform_int_distribution<int> exponent(-40, 40);
  const auto number = [&] { return mantissa(random) * std::pow(10.0, exponent(random)); };
  ddf::TriangleMesh mesh;
  VtpPointData data{{{"a", {}}, {"b", {}}}, {{"v", {}}}};
  for (int v = 0; v < 500; ++v) {
    mesh.vertices.emplace_back(number(), number(), number());
    for (VtpScalarArray& a : data.scalars) a.values.push_back(static_cast<float>(number()));
    data.vectors[0].values.emplace_back(number(), number(), number());
  }
  data.scalars[0].values[3] = std::nanf("");
  data.scalars[0].values[4] = -0.0f;
  data.scalars[1].values[5] = std::numeric_limits<float>::denorm_min();
  for (int t = 0; t + 2 < 500; t += 3) mesh.triangles.push_back({t, t + 1, t + 2});
  writeVtp(mesh, data, dir / "many.vtp");
  const XmlElement piece =
      parseDocument(test::readBytes(dir / "many.vtp")).child("PolyData").child("Piece");
  const std::vector<double> points = doubles(piece.child("Points").child("DataArray"));
  ASSERT_EQ(points.size(), 1500u);
  for (std::size_t i = 0; i < points.size(); ++i)
    ASSERT_EQ(points[i], mesh.vertices[i / 3][i % 3]) << "coordinate " << i;
  const XmlElement& pointData = piece.child("PointData");
  for (std::size_t a = 0; a < 2; ++a) {
    const std::vector<float> read = floats(pointData.children[a]);
    ASSERT_EQ(read.size(), 500u);
    for (std::size_t i = 0; i < read.size(); ++i)
      ASSERT_TRUE(sameFloat(read[i], data.scalars[a].values[i])) << a << " " << i;
  }
  const std::vector<float> vectors = floats(pointData.children[2]);
  ASSERT_EQ(vectors.size(), 1500u);
  for (std::size_t i = 0; i < vectors.size(); ++i)
    ASSERT_TRUE(sameFloat(vectors[i], static_cast<float>(data.vectors[0].values[i / 3][i % 3])));
}

TEST(VtpWriter, EmptyMeshGivesAnEmptyPiece) {
  const XmlElement piece = parseDocument(formatVtp({}, {})).child("PolyData").child("Piece");
  EXPECT_EQ(piece.attributes.at("NumberOfPoints"), "0");
  EXPECT_EQ(piece.attributes.at("NumberOfPolys"), "0");
  EXPECT_TRUE(words(piece.child("Points").child("DataArray").text).empty());
}

std::string invalidInputMessage(const ddf::TriangleMesh& mesh, const VtpPointData& data,
                                const std::filesystem::path& path) {
  try {
    writeVtp(mesh, data, path);
  } catch (const InvalidInput& e) {
    return e.what();
  }
  ADD_FAILURE() << "expected InvalidInput";
  return "";
}

TEST(VtpWriter, RejectsBadArraysAndIndicesWithoutWriting) {
  test::ScratchDir dir;
  const auto path = dir / "bad.vtp";
  const ddf::TriangleMesh mesh = twoTriangles();
  EXPECT_THAT(invalidInputMessage(mesh, {{{"k_min", {1, 2, 3}}}, {}}, path),
              HasSubstr("'k_min' has 3 values for 4 vertices"));
  EXPECT_THAT(invalidInputMessage(mesh, {{{"x", {1, 2, 3, 4}}}, {{"x", {{}, {}, {}, {}}}}}, path),
              HasSubstr("'x' is used twice"));
  EXPECT_THAT(invalidInputMessage(mesh, {{{"a<b", {1, 2, 3, 4}}}, {}}, path), HasSubstr("'a<b'"));
  EXPECT_THAT(invalidInputMessage(mesh, {{{"", {1, 2, 3, 4}}}, {}}, path), HasSubstr("empty name"));
  ddf::TriangleMesh broken = mesh;
  broken.triangles[1][2] = 4;
  EXPECT_THAT(invalidInputMessage(broken, {}, path), HasSubstr("triangle 1"));
  EXPECT_FALSE(std::filesystem::exists(path));
}

TEST(VtpWriter, ReplacesAFileWholeAndNamesAnUnwritablePath) {
  test::ScratchDir dir;
  const auto path = dir / "out.vtp";
  test::writeBytes(path, std::string(100000, 'x'));
  writeVtp(twoTriangles(), {}, path);
  EXPECT_EQ(test::readBytes(path), formatVtp(twoTriangles(), {}));
  const auto missingDir = dir / "no_such_dir" / "out.vtp";
  EXPECT_THAT(test::ioErrorMessage([&] { writeVtp(twoTriangles(), {}, missingDir); }),
              HasSubstr("out.vtp"));
}

}  // namespace
}  // namespace ddfcam::io
