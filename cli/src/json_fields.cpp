// SPDX-License-Identifier: MIT
// ddfcam-cli run: strict reading of JSON objects.
#include "json_fields.h"

#include <ddfcam/error.h>

#include <cmath>
#include <sstream>

namespace ddfcam::cli {

namespace {

std::string describe(double v) {
  std::ostringstream s;
  s << v;
  return s.str();
}

}  // namespace

JsonFields::JsonFields(const nlohmann::json& value, std::string path, const std::string& source)
    : value_(value), path_(std::move(path)), source_(source) {
  if (!value_.is_object())
    throw InvalidInput(source_ + ": " + (path_.empty() ? std::string("job") : path_) +
                       ": expected an object");
}

std::string JsonFields::keyPath(const std::string& key) const {
  return path_.empty() ? key : path_ + "." + key;
}

void JsonFields::fail(const std::string& key, const std::string& what) const {
  throw InvalidInput(source_ + ": " + keyPath(key) + ": " + what);
}

const nlohmann::json* JsonFields::find(const std::string& key) {
  read_.insert(key);
  const auto it = value_.find(key);
  return it == value_.end() ? nullptr : &*it;
}

double JsonFields::number(const std::string& key, double fallback, double lo, double hi) {
  const nlohmann::json* v = find(key);
  if (!v) return fallback;
  if (!v->is_number()) fail(key, "expected a number");
  const double x = v->get<double>();
  if (!std::isfinite(x) || x < lo || x > hi)
    fail(key, describe(x) + " is outside [" + describe(lo) + ", " + describe(hi) + "]");
  return x;
}

int JsonFields::integer(const std::string& key, int fallback, int lo, int hi) {
  const nlohmann::json* v = find(key);
  if (!v) return fallback;
  if (!v->is_number_integer()) fail(key, "expected an integer");
  const auto x = v->get<std::int64_t>();
  if (x < lo || x > hi)
    fail(key, std::to_string(x) + " is outside [" + std::to_string(lo) + ", " + std::to_string(hi) +
                  "]");
  return static_cast<int>(x);
}

bool JsonFields::flag(const std::string& key, bool fallback) {
  const nlohmann::json* v = find(key);
  if (!v) return fallback;
  if (!v->is_boolean()) fail(key, "expected true or false");
  return v->get<bool>();
}

std::string JsonFields::text(const std::string& key, const std::string& fallback) {
  const nlohmann::json* v = find(key);
  if (!v) return fallback;
  if (!v->is_string()) fail(key, "expected a string");
  return v->get<std::string>();
}

int JsonFields::choice(const std::string& key, const std::vector<std::string>& names,
                       int fallback) {
  const nlohmann::json* v = find(key);
  if (!v) return fallback;
  std::string list;
  for (std::size_t i = 0; i < names.size(); ++i) list += (i ? "|" : "") + names[i];
  if (!v->is_string()) fail(key, "expected one of " + list);
  const std::string s = v->get<std::string>();
  for (std::size_t i = 0; i < names.size(); ++i)
    if (s == names[i]) return static_cast<int>(i);
  fail(key, "'" + s + "': expected one of " + list);
}

std::vector<double> JsonFields::numbers(const std::string& key,
                                        const std::vector<double>& fallback) {
  const nlohmann::json* v = find(key);
  if (!v) return fallback;
  if (!v->is_array()) fail(key, "expected a list of numbers");
  std::vector<double> out;
  for (const nlohmann::json& x : *v) {
    if (!x.is_number() || !std::isfinite(x.get<double>())) fail(key, "expected finite numbers");
    out.push_back(x.get<double>());
  }
  return out;
}

std::optional<std::filesystem::path> JsonFields::path(const std::string& key,
                                                      const std::filesystem::path& base) {
  const nlohmann::json* v = find(key);
  if (!v) return std::nullopt;
  if (!v->is_string() || v->get<std::string>().empty()) fail(key, "expected a file name");
  const std::filesystem::path p = v->get<std::string>();
  return p.is_absolute() ? p : base / p;
}

void JsonFields::finish() const {
  for (auto it = value_.begin(); it != value_.end(); ++it)
    if (!read_.contains(it.key())) fail(it.key(), "unknown key");
}

}  // namespace ddfcam::cli
