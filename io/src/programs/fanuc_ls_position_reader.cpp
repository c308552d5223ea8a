// SPDX-License-Identifier: MIT
// ddfcam: the /POS section of a FANUC TP program (.ls): Cartesian positions P[n] of group GP1.
#include "fanuc_ls_position_reader.h"

#include "path_file_limits.h"

#include <algorithm>
#include <cmath>

namespace ddfcam::io::detail {

void LsPositionReader::line(std::string_view line, int number) {
  if (!entryOpen_) {
    const std::string_view t = lsTrim(line);
    if (t.empty()) return;
    if (!lsStartsWith(t, "P["))
      errors_.fail(number, "expected a position entry 'P[n]{', found '" + lsClip(t) + "'");
    entryOpen_ = true;
    entryLine_ = number;
    entryText_.clear();
  }
  entryText_ += line;
  entryText_ += '\n';
  if (entryText_.size() > kMaxLsStatementBytes) errors_.fail(entryLine_, "position entry too long");
  if (line.find('}') == std::string_view::npos) return;
  entryOpen_ = false;
  entry(entryText_, entryLine_);
}

void LsPositionReader::entry(std::string_view text, int line) {
  std::string_view s = text;
  const long index = lsPointRef(s, line, errors_).value_or(-1);  // the "P[" prefix was checked
  s = lsTrim(s);
  const std::size_t close = s.rfind('}');
  if (s.empty() || s.front() != '{' || close == std::string_view::npos || close == 0)
    errors_.fail(line, "expected '{' after P[" + std::to_string(index) + "]");
  const std::string_view after = lsTrim(s.substr(close + 1));
  if (!after.empty() && after != ";") errors_.fail(line, "unexpected text after '}'");
  const std::string_view body = s.substr(1, close - 1);
  const std::size_t gp1 = body.find("GP1");
  if (gp1 == std::string_view::npos)
    errors_.fail(line, "P[" + std::to_string(index) + "] has no group GP1");
  std::string_view group = body.substr(gp1 + 3);
  group = lsTrim(group);
  if (group.empty() || group.front() != ':') errors_.fail(line, "expected ':' after GP1");
  group.remove_prefix(1);
  const std::size_t next = group.find("GP");
  if (next != std::string_view::npos) group = group.substr(0, next);
  LsPosition position = parseGroup(group, text, line, index);
  if (!positions_.emplace(index, position).second)
    errors_.fail(line, "P[" + std::to_string(index) + "] is defined twice");
}

LsPosition LsPositionReader::parseGroup(std::string_view group, std::string_view text, int line,
                                        long index) const {
  LsPosition position;
  position.line = line;
  bool seen[6] = {false, false, false, false, false, false};
  bool joints = false;
  std::size_t start = 0;
  bool quoted = false;
  for (std::size_t i = 0; i <= group.size(); ++i) {
    if (i < group.size() && group[i] == '\'') quoted = !quoted;
    if (i < group.size() && (quoted || group[i] != ',')) continue;
    const std::string_view item = lsTrim(group.substr(start, i - start));
    start = i + 1;
    if (item.empty()) continue;
    const int itemLine = line + static_cast<int>(std::count(text.data(), item.data(), '\n'));
    joints |= groupItem(item, itemLine, position, seen);
  }
  static constexpr const char* kNames[] = {"X", "Y", "Z", "W", "P", "R"};
  const bool any = std::count(seen, seen + 6, true) > 0;
  if (!any && joints) {
    position.joint = true;
    return position;
  }
  for (int k = 0; k < 6; ++k)
    if (!seen[k])
      errors_.fail(line, "P[" + std::to_string(index) + "] has no " + kNames[k] + " value");
  return position;
}

bool LsPositionReader::groupItem(std::string_view item, int line, LsPosition& position,
                                 bool* seen) const {
  const std::size_t eq = item.find('=');
  if (eq == std::string_view::npos) {
    const std::size_t colon = item.find(':');
    if (colon == std::string_view::npos) errors_.fail(line, "unexpected '" + lsClip(item) + "'");
    if (lsTrim(item.substr(0, colon)) == "UF") {
      std::string_view v = lsTrim(item.substr(colon + 1));
      const auto uf = lsLeadingNumber(v);
      if (!uf || !lsTrim(v).empty() || *uf < 0 || *uf > 1000 || *uf != std::floor(*uf))
        errors_.fail(line, "bad user frame '" + lsClip(item) + "'");
      position.userFrame = static_cast<int>(*uf);
    }
    return false;
  }
  const std::string_view name = lsTrim(item.substr(0, eq));
  std::string_view value = lsTrim(item.substr(eq + 1));
  const auto number = lsLeadingNumber(value);
  if (!number)
    errors_.fail(line, "expected a number for " + std::string(name) + ", found '" +
                           lsClip(lsTrim(item.substr(eq + 1))) + "'");
  const std::string_view unit = lsTrim(value);
  static constexpr std::string_view kNames = "XYZWPR";
  const std::size_t k = name.size() == 1 ? kNames.find(name[0]) : std::string_view::npos;
  if (k == std::string_view::npos) return lsStartsWith(name, "J");
  const std::string_view expected = k < 3 ? "mm" : "deg";
  if (!unit.empty() && unit != expected)
    errors_.fail(line, std::string(name) + " must be in " + std::string(expected) + ", found '" +
                           lsClip(unit) + "'");
  if (k < 3 && !(std::abs(*number) <= kMaxCoordinateMm))
    errors_.fail(line, std::string(name) + " = " + lsClip(lsTrim(item.substr(eq + 1))) +
                           " is beyond 1e12 mm; not a robot position");
  position.value[k] = *number;
  seen[k] = true;
  return false;
}

}  // namespace ddfcam::io::detail
