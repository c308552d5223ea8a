// SPDX-License-Identifier: MIT
// ddfcam: recognising the columns of tool-path CSVs written here and elsewhere.
#include "tool_path_csv_columns.h"

#include <algorithm>
#include <array>
#include <utility>

namespace ddfcam::io::detail {
namespace {

struct Name {
  std::string_view text;
  CsvColumn column;
};

// Names seen in robot, CAM and spreadsheet exports (compared after lower-casing, with blanks and
// '-' as '_' and the unit suffix removed).
constexpr std::array kNames = {
    Name{"path", CsvColumn::Path},
    Name{"path_index", CsvColumn::Path},
    Name{"pathindex", CsvColumn::Path},
    Name{"path_id", CsvColumn::Path},
    Name{"pass", CsvColumn::Path},
    Name{"pass_index", CsvColumn::Path},
    Name{"segment", CsvColumn::Path},
    Name{"point", CsvColumn::Point},
    Name{"point_index", CsvColumn::Point},
    Name{"pointindex", CsvColumn::Point},
    Name{"x", CsvColumn::X},
    Name{"y", CsvColumn::Y},
    Name{"z", CsvColumn::Z},
    Name{"px", CsvColumn::X},
    Name{"py", CsvColumn::Y},
    Name{"pz", CsvColumn::Z},
    Name{"pos_x", CsvColumn::X},
    Name{"pos_y", CsvColumn::Y},
    Name{"pos_z", CsvColumn::Z},
    Name{"position_x", CsvColumn::X},
    Name{"position_y", CsvColumn::Y},
    Name{"position_z", CsvColumn::Z},
    Name{"i", CsvColumn::I},
    Name{"j", CsvColumn::J},
    Name{"k", CsvColumn::K},
    Name{"axis_i", CsvColumn::I},
    Name{"axis_j", CsvColumn::J},
    Name{"axis_k", CsvColumn::K},
    Name{"axis_x", CsvColumn::I},
    Name{"axis_y", CsvColumn::J},
    Name{"axis_z", CsvColumn::K},
    Name{"ax", CsvColumn::I},
    Name{"ay", CsvColumn::J},
    Name{"az", CsvColumn::K},
    Name{"nx", CsvColumn::Nx},
    Name{"ny", CsvColumn::Ny},
    Name{"nz", CsvColumn::Nz},
    Name{"normal_x", CsvColumn::Nx},
    Name{"normal_y", CsvColumn::Ny},
    Name{"normal_z", CsvColumn::Nz},
    Name{"normal_i", CsvColumn::Nx},
    Name{"normal_j", CsvColumn::Ny},
    Name{"normal_k", CsvColumn::Nz},
    Name{"n_x", CsvColumn::Nx},
    Name{"n_y", CsvColumn::Ny},
    Name{"n_z", CsvColumn::Nz},
    Name{"feed", CsvColumn::Feed},
    Name{"feedrate", CsvColumn::Feed},
    Name{"feed_rate", CsvColumn::Feed},
    Name{"f", CsvColumn::Feed},
    Name{"move", CsvColumn::Move},
    Name{"move_type", CsvColumn::Move},
    Name{"motion", CsvColumn::Move},
    Name{"type", CsvColumn::Move},
};

std::string_view trimmed(std::string_view s) {
  while (!s.empty() && (s.front() == ' ' || s.front() == '\t' || s.front() == '\r'))
    s.remove_prefix(1);
  while (!s.empty() && (s.back() == ' ' || s.back() == '\t' || s.back() == '\r'))
    s.remove_suffix(1);
  return s;
}

std::string normalised(std::string_view name) {
  name = trimmed(name);
  if (name.size() >= 2 && (name.front() == '"' || name.front() == '\'') &&
      name.back() == name.front())
    name = trimmed(name.substr(1, name.size() - 2));
  std::string out;
  for (const char c : name) out += (c >= 'A' && c <= 'Z') ? static_cast<char>(c - 'A' + 'a') : c;
  return out;
}

std::optional<LengthUnit> unitFromText(std::string_view text) {
  if (text.size() > 4 && text.substr(text.size() - 4) == "/min") text.remove_suffix(4);
  if (text == "mm" || text == "millimetre" || text == "millimeter" || text == "millimetres" ||
      text == "millimeters")
    return LengthUnit::Millimetre;
  if (text == "in" || text == "inch" || text == "inches") return LengthUnit::Inch;
  if (text == "m" || text == "metre" || text == "meter" || text == "metres" || text == "meters")
    return LengthUnit::Metre;
  return std::nullopt;
}

/// One parsed header name: its column, stated unit and point kind.
struct ParsedName {
  CsvColumn column = CsvColumn::Ignore;
  std::optional<LengthUnit> unit;
  std::optional<planning::ClPointKind> kind;
  std::string error;
};

/// Splits a unit suffix ("x [mm]", "x(mm)", "x_mm", "feed_mm_per_min") off @p base.
std::string splitUnit(std::string base, ParsedName& out) {
  const auto ends = [&](std::string_view s) {
    return base.size() >= s.size() && std::string_view(base).substr(base.size() - s.size()) == s;
  };
  if (ends("_per_min")) base.resize(base.size() - 8);
  if (!base.empty() && (base.back() == ']' || base.back() == ')')) {
    const std::size_t open = base.find_last_of(base.back() == ']' ? '[' : '(');
    if (open == std::string::npos) return base;
    const std::string text(
        trimmed(std::string_view(base).substr(open + 1, base.size() - open - 2)));
    out.unit = unitFromText(text);
    if (!out.unit) out.error = "unknown unit '" + text + "'";
    base = std::string(trimmed(std::string_view(base).substr(0, open)));
    while (!base.empty() && base.back() == '_') base.pop_back();
    return base;
  }
  const std::size_t underscore = base.rfind('_');
  if (underscore != std::string::npos && underscore > 0) {
    const auto unit = unitFromText(std::string_view(base).substr(underscore + 1));
    if (unit) {
      out.unit = unit;
      base.resize(underscore);
    }
  }
  return base;
}

ParsedName parseName(std::string_view raw) {
  ParsedName out;
  std::string base = normalised(raw);
  std::replace(base.begin(), base.end(), ' ', '_');
  std::replace(base.begin(), base.end(), '-', '_');
  base = splitUnit(base, out);
  std::optional<planning::ClPointKind> kind;
  for (const auto& [prefix, k] :
       {std::pair{std::string_view("contact_"), planning::ClPointKind::Contact},
        std::pair{std::string_view("tool_"), planning::ClPointKind::ToolReference}})
    if (base.size() > prefix.size() && std::string_view(base).substr(0, prefix.size()) == prefix) {
      const std::string rest = base.substr(prefix.size());
      if (rest == "x" || rest == "y" || rest == "z") {
        kind = k;
        base = rest;
      }
    }
  for (const Name& n : kNames)
    if (base == n.text) out.column = n.column;
  if (out.column == CsvColumn::X || out.column == CsvColumn::Y || out.column == CsvColumn::Z)
    out.kind = kind;
  return out;
}

bool has(const std::vector<CsvColumn>& columns, CsvColumn c) {
  return std::find(columns.begin(), columns.end(), c) != columns.end();
}

/// Checks that the group @p a, @p b, @p c is all there or all absent.
std::string groupError(const std::vector<CsvColumn>& columns, std::array<CsvColumn, 3> group,
                       const char* what, bool required) {
  const int count =
      static_cast<int>(has(columns, group[0])) + has(columns, group[1]) + has(columns, group[2]);
  if (count == 3 || (count == 0 && !required)) return {};
  return std::string("the header has ") + std::to_string(count) + " of the 3 " + what + " columns";
}

}  // namespace

CsvLayoutResult layoutFromHeader(const std::vector<std::string_view>& names) {
  CsvLayout layout;
  for (const std::string_view raw : names) {
    const ParsedName name = parseName(raw);
    const std::string shown(trimmed(raw));
    if (!name.error.empty()) return {std::nullopt, "column '" + shown + "': " + name.error};
    if (name.column != CsvColumn::Ignore && has(layout.columns, name.column))
      return {std::nullopt, "column '" + shown + "' names a quantity a previous column gives"};
    layout.columns.push_back(name.column);
    if (name.column == CsvColumn::Ignore) layout.ignoredColumns.push_back(shown);
    const bool position =
        name.column == CsvColumn::X || name.column == CsvColumn::Y || name.column == CsvColumn::Z;
    std::optional<LengthUnit>& unit = position ? layout.unit : layout.feedUnit;
    if (name.unit && (position || name.column == CsvColumn::Feed)) {
      if (unit && *unit != *name.unit)
        return {std::nullopt, "column '" + shown + "': unit differs from the other columns'"};
      unit = name.unit;
    }
    if (name.kind) {
      if (layout.kind && *layout.kind != *name.kind)
        return {std::nullopt, "column '" + shown + "': contact and tool positions mixed"};
      layout.kind = name.kind;
    }
  }
  using C = CsvColumn;
  for (std::string error : {groupError(layout.columns, {C::X, C::Y, C::Z}, "x y z", true),
                            groupError(layout.columns, {C::I, C::J, C::K}, "axis", false),
                            groupError(layout.columns, {C::Nx, C::Ny, C::Nz}, "normal", false)})
    if (!error.empty()) return {std::nullopt, error};
  return {std::move(layout), {}};
}

std::optional<CsvLayout> layoutFromFieldCount(std::size_t fields) {
  using C = CsvColumn;
  CsvLayout layout;
  switch (fields) {
    case 3:
      layout.columns = {C::X, C::Y, C::Z};
      break;
    case 4:
      layout.columns = {C::Path, C::X, C::Y, C::Z};
      break;
    case 6:
      layout.columns = {C::X, C::Y, C::Z, C::I, C::J, C::K};
      break;
    case 7:
      layout.columns = {C::Path, C::X, C::Y, C::Z, C::I, C::J, C::K};
      break;
    case 13:
      layout.columns = {C::Path, C::Point, C::X,  C::Y,  C::Z,    C::I,   C::J,
                        C::K,    C::Nx,    C::Ny, C::Nz, C::Feed, C::Move};
      break;
    default:
      return std::nullopt;
  }
  return layout;
}

std::string headerlessLayouts() {
  return "3 (x,y,z), 4 (path,x,y,z), 6 (x,y,z,i,j,k), 7 (path,x,y,z,i,j,k) or 13 (ddfcam's "
         "columns)";
}

}  // namespace ddfcam::io::detail
