// SPDX-License-Identifier: MIT
// ddfcam-cli: the option table of a subcommand over CLI11, and its --help text.
#include "arguments.h"

#include <charconv>
#include <cmath>

namespace ddfcam::cli {
namespace {

/// The help layout of every command: the usage line, the description, the positionals and
/// options ("-o, --output FILE  text (default X)"), the footer.
class HelpFormatter : public CLI::Formatter {
 public:
  explicit HelpFormatter(std::string usage) : usage_(std::move(usage)) {
    column_width(29);
    label("Positionals", "arguments");
  }

  std::string make_help(const CLI::App* app, std::string, CLI::AppFormatMode mode) const override {
    std::string out = "usage: ddfcam-cli " + usage_ + "\n";
    if (!app->get_description().empty()) out += "\n" + app->get_description() + "\n";
    out += make_positionals(app) + make_groups(app, mode);
    if (!app->get_footer().empty()) out += "\n" + app->get_footer() + "\n";
    // One blank line between groups (CLI11 puts one after a group and one before the next).
    for (std::size_t at = out.find("\n\n\n"); at != std::string::npos; at = out.find("\n\n\n"))
      out.erase(at, 1);
    return out;
  }

  std::string make_option_name(const CLI::Option* opt, bool positional) const override {
    std::string name = Formatter::make_option_name(opt, positional);
    for (std::size_t at = name.find(','); at != std::string::npos; at = name.find(',', at + 2))
      name.insert(at + 1, " ");
    return name;
  }

  std::string make_option_desc(const CLI::Option* opt) const override {
    std::string text = opt->get_description();
    if (!opt->get_default_str().empty()) text += " (default " + opt->get_default_str() + ")";
    return text;
  }

 private:
  std::string usage_;
};

template <class T>
std::optional<T> parseWhole(const std::string& text) {
  T v{};
  const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), v);
  if (ec != std::errc() || end != text.data() + text.size()) return std::nullopt;
  if constexpr (std::is_floating_point_v<T>)
    if (!std::isfinite(v)) return std::nullopt;
  return v;
}

std::string numberText(double v) {
  char text[32];
  return std::string(text, std::to_chars(text, text + sizeof text, v).ptr);
}

}  // namespace

// CLI11 would name the option by its long name, and takes "--flag=text" as a count; the user
// wants the word they typed.
void Arguments::rejectValueMismatch(std::span<const std::string> words) const {
  for (std::size_t i = 0; i < words.size(); ++i) {
    const std::string& word = words[i];
    if (word.size() < 2 || word[0] != '-') continue;
    const std::size_t eq = word.rfind("--", 0) == 0 ? word.find('=') : std::string::npos;
    const std::string name = word.substr(0, eq);
    const CLI::Option* opt = app_->get_option_no_throw(name);
    if (!opt || opt->get_positional()) continue;
    const bool takesValue = opt->get_items_expected_min() > 0;
    if (!takesValue && eq != std::string::npos)
      throw UsageError("option " + name + " takes no value");
    if (takesValue && eq == std::string::npos && i + 1 == words.size())
      throw UsageError("option " + word + " needs a value");
  }
}

// The messages start with "expects": parse() joins them to the option's name.
CLI::Validator integerIn(int minValue, int maxValue) {
  const std::string range = "[" + std::to_string(minValue) + ", " + std::to_string(maxValue) + "]";
  return CLI::Validator(
      [=](std::string& text) -> std::string {
        const std::optional<int> v = parseWhole<int>(text);
        if (v && *v >= minValue && *v <= maxValue) return {};
        return "expects an integer in " + range + ", got '" + text + "'";
      },
      "INT in " + range);
}

CLI::Validator positiveNumber() {
  return CLI::Validator(
      [](std::string& text) -> std::string {
        const std::optional<double> v = parseWhole<double>(text);
        if (v && *v > 0.0) return {};
        return "expects a positive number, got '" + text + "'";
      },
      "POSITIVE");
}

CLI::Validator numberIn(double minValue, double maxValue) {
  const std::string range = "[" + numberText(minValue) + ", " + numberText(maxValue) + "]";
  return CLI::Validator(
      [=](std::string& text) -> std::string {
        const std::optional<double> v = parseWhole<double>(text);
        if (v && *v >= minValue && *v <= maxValue) return {};
        return "expects a number in " + range + ", got '" + text + "'";
      },
      "NUMBER in " + range);
}

CLI::Validator oneOf(std::vector<std::string> choices) {
  std::string list;
  for (std::size_t i = 0; i < choices.size(); ++i)
    list += (i == 0 ? "" : i + 1 == choices.size() ? " or " : ", ") + choices[i];
  return CLI::Validator(
      [=](std::string& text) -> std::string {
        for (const std::string& choice : choices)
          if (text == choice) return {};
        return "expects " + list + ", got '" + text + "'";
      },
      list);
}

Arguments::Arguments(std::string command, std::string usage, std::string description)
    : command_(std::move(command)), app_(std::make_unique<CLI::App>(description, command_)) {
  app_->formatter(std::make_shared<HelpFormatter>(std::move(usage)));
  app_->option_defaults()->group("options");
  app_->set_help_flag("-h,--help", "show this help");
  // Unknown words are reported by parse() in the wording of this tool.
  app_->allow_extras();
}

Arguments::Arguments(Arguments&&) noexcept = default;
Arguments& Arguments::operator=(Arguments&&) noexcept = default;
Arguments::~Arguments() = default;

CLI::Option* Arguments::option(const std::string& names, const std::string& valueName,
                               const std::string& description) {
  return app_->add_option(names, description)->option_text(valueName);
}

CLI::Option* Arguments::flag(const std::string& names, const std::string& description) {
  return app_->add_flag(names, description);
}

CLI::Option* Arguments::positional(const std::string& name, const std::string& description,
                                   bool many) {
  CLI::Option* opt = app_->add_option(name, description);
  if (many) opt->expected(0, CLI::detail::expected_max_vector_size)->allow_extra_args();
  positionalOptions_.push_back(opt);
  return opt;
}

void Arguments::footer(const std::string& text) {
  app_->footer(text);
}

std::string Arguments::help() const {
  return app_->help();
}

void Arguments::parse(std::span<const std::string> words) {
  rejectValueMismatch(words);
  std::vector<std::string> reversed(words.rbegin(), words.rend());
  try {
    app_->parse(reversed);
  } catch (const CLI::ValidationError& e) {
    std::string text = e.what();
    if (const auto at = text.find(": expects "); at != std::string::npos) text.erase(at, 1);
    throw UsageError(text);
  } catch (const CLI::ParseError& e) {
    throw UsageError("'" + command_ + "': " + e.what());
  }
  // An unknown option says more than the positional it leaves over.
  const std::vector<std::string> extras = app_->remaining();
  for (const std::string& extra : extras)
    if (extra.size() > 1 && extra[0] == '-')
      throw UsageError("unknown option " + extra.substr(0, extra.find('=')) + " for '" + command_ +
                       "'");
  if (!extras.empty())
    throw UsageError("'" + command_ + "': unexpected argument '" + extras.front() + "'");
  positionals_.clear();
  for (const CLI::Option* opt : positionalOptions_)
    positionals_.insert(positionals_.end(), opt->results().begin(), opt->results().end());
}

const CLI::Option* Arguments::find(const std::string& name) const {
  return app_->get_option_no_throw("--" + name);
}

bool Arguments::has(const std::string& name) const {
  const CLI::Option* opt = find(name);
  return opt && opt->count() > 0;
}

std::optional<std::string> Arguments::value(const std::string& name) const {
  const CLI::Option* opt = find(name);
  if (!opt) return std::nullopt;
  if (opt->count() > 0 && !opt->results().empty()) return opt->results().back();
  if (!opt->get_default_str().empty()) return opt->get_default_str();
  return std::nullopt;
}

std::string Arguments::required(const std::string& name) const {
  const auto v = value(name);
  if (!v || v->empty()) throw UsageError("'" + command_ + "' needs --" + name);
  return *v;
}

int Arguments::integer(const std::string& name, int fallback, int minValue, int maxValue) const {
  std::optional<std::string> text = value(name);
  if (!text) return fallback;
  const std::string problem = integerIn(minValue, maxValue)(*text);
  if (!problem.empty()) throw UsageError("--" + name + " " + problem);
  return *parseWhole<int>(*text);
}

std::optional<double> Arguments::number(const std::string& name) const {
  const auto text = value(name);
  if (!text) return std::nullopt;
  const std::optional<double> v = parseWhole<double>(*text);
  if (!v) throw UsageError("--" + name + " expects a number, got '" + *text + "'");
  return v;
}

void Arguments::expectPositionals(std::size_t count, const std::string& what) const {
  if (positionals_.size() < count) throw UsageError("'" + command_ + "' needs " + what);
  if (positionals_.size() > count)
    throw UsageError("'" + command_ + "': unexpected argument '" + positionals_[count] + "'");
}

}  // namespace ddfcam::cli
