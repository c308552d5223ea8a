// SPDX-License-Identifier: MIT
// ddfcam-cli: command-line argument parsing.
#include "arguments.h"

#include <charconv>
#include <cmath>

namespace ddfcam::cli {
namespace {

const OptionSpec* findSpec(std::span<const OptionSpec> specs, const std::string& word) {
  static const OptionSpec kHelp{"help", 'h', false};
  const bool isLong = word.rfind("--", 0) == 0;
  const std::string key = isLong ? word.substr(2) : word.substr(1);
  if (key == "help" || key == "h") return &kHelp;
  for (const OptionSpec& spec : specs)
    if ((isLong && spec.name == key) || (!isLong && key.size() == 1 && spec.shortName == key[0]))
      return &spec;
  return nullptr;
}

}  // namespace

Arguments::Arguments(std::span<const std::string> args, std::span<const OptionSpec> specs,
                     std::string command)
    : command_(std::move(command)) {
  for (std::size_t i = 0; i < args.size(); ++i) {
    std::string word = args[i];
    if (word.size() < 2 || word[0] != '-') {
      positionals_.push_back(word);
      continue;
    }
    std::optional<std::string> inlineValue;
    if (const auto eq = word.find('='); word.rfind("--", 0) == 0 && eq != std::string::npos) {
      inlineValue = word.substr(eq + 1);
      word.resize(eq);
    }
    const OptionSpec* spec = findSpec(specs, word);
    if (!spec) throw UsageError("unknown option " + word + " for '" + command_ + "'");
    if (values_.count(spec->name)) throw UsageError("option " + word + " given twice");
    if (!spec->takesValue) {
      if (inlineValue) throw UsageError("option " + word + " takes no value");
      values_[spec->name] = "";
    } else if (inlineValue) {
      values_[spec->name] = *inlineValue;
    } else {
      if (i + 1 >= args.size()) throw UsageError("option " + word + " needs a value");
      values_[spec->name] = args[++i];
    }
  }
}

std::optional<std::string> Arguments::value(const std::string& name) const {
  const auto it = values_.find(name);
  if (it == values_.end()) return std::nullopt;
  return it->second;
}

std::string Arguments::required(const std::string& name) const {
  const auto v = value(name);
  if (!v || v->empty()) throw UsageError("'" + command_ + "' needs --" + name);
  return *v;
}

int Arguments::integer(const std::string& name, int fallback, int minValue, int maxValue) const {
  const auto text = value(name);
  if (!text) return fallback;
  int v = 0;
  const auto [end, ec] = std::from_chars(text->data(), text->data() + text->size(), v);
  if (ec != std::errc() || end != text->data() + text->size() || v < minValue || v > maxValue)
    throw UsageError("--" + name + " expects an integer in [" + std::to_string(minValue) + ", " +
                     std::to_string(maxValue) + "], got '" + *text + "'");
  return v;
}

std::optional<double> Arguments::positiveNumber(const std::string& name) const {
  const auto text = value(name);
  if (!text) return std::nullopt;
  double v = 0.0;
  const auto [end, ec] = std::from_chars(text->data(), text->data() + text->size(), v);
  if (ec != std::errc() || end != text->data() + text->size() || !std::isfinite(v) || v <= 0.0)
    throw UsageError("--" + name + " expects a positive number, got '" + *text + "'");
  return v;
}

void Arguments::expectPositionals(std::size_t count, const std::string& what) const {
  if (positionals_.size() < count) throw UsageError("'" + command_ + "' needs " + what);
  if (positionals_.size() > count)
    throw UsageError("'" + command_ + "': unexpected argument '" + positionals_[count] + "'");
}

}  // namespace ddfcam::cli
