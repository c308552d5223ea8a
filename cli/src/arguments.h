// SPDX-License-Identifier: MIT
// ddfcam-cli: the option table of a subcommand (a CLI11 app): it parses the command's words
// (positionals, --name value, --name=value, flags) and generates the command's --help.
#pragma once

#include <ddfcam/error.h>

#include <CLI/CLI.hpp>

#include <climits>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <vector>

namespace ddfcam::cli {

/// @brief Wrong command-line usage; main() prints it and exits with code 2.
class UsageError : public InvalidInput {
 public:
  using InvalidInput::InvalidInput;
};

/// @brief Check of an option: an integer in [@p minValue, @p maxValue].
CLI::Validator integerIn(int minValue, int maxValue);
/// @brief Check of an option: a positive finite number.
CLI::Validator positiveNumber();
/// @brief Check of an option: a finite number in [@p minValue, @p maxValue].
CLI::Validator numberIn(double minValue, double maxValue);
/// @brief Check of an option: one of @p choices ("expects a, b or c, got 'x'").
CLI::Validator oneOf(std::vector<std::string> choices);

/// @brief One subcommand's options, with their descriptions, defaults and checks, and the
/// parsed command line. Declare the options, then parse(), then read the values.
class Arguments {
 public:
  /// @param command the subcommand's name, used in messages
  /// @param usage the usage line after "usage: ddfcam-cli "
  /// @param description what the command does, printed under the usage line by help()
  Arguments(std::string command, std::string usage, std::string description);
  Arguments(Arguments&&) noexcept;
  Arguments& operator=(Arguments&&) noexcept;
  ~Arguments();

  /// @brief Adds an option with a value, e.g. option("-o,--output", "FILE", "output file").
  /// @return the option, for ->check(...) and ->default_str(...) (shown as "(default X)").
  CLI::Option* option(const std::string& names, const std::string& valueName,
                      const std::string& description);
  /// @brief Adds a flag (an option without a value).
  CLI::Option* flag(const std::string& names, const std::string& description);
  /// @brief Adds a positional argument; with @p many it takes all remaining positionals.
  CLI::Option* positional(const std::string& name, const std::string& description,
                          bool many = false);
  /// @brief Text printed after the options by help(), e.g. notes on several options.
  void footer(const std::string& text);
  /// @brief The --help text generated from the table, ending in "\n".
  std::string help() const;

  /// @brief Parses @p words (those after the subcommand name).
  /// @throws UsageError for an unknown option, a missing value, a failed check or an
  /// unexpected positional; the message names the option.
  void parse(std::span<const std::string> words);

  const std::vector<std::string>& positionals() const { return positionals_; }
  /// @brief True if the flag or option @p name (long name without dashes) was given; an option
  /// the table lacks is never given (shared parsers read options some commands do not have).
  bool has(const std::string& name) const;
  /// @brief Value of option @p name if given, else its default if it has one.
  std::optional<std::string> value(const std::string& name) const;
  /// @brief Value of a required option.
  /// @throws UsageError if it is missing.
  std::string required(const std::string& name) const;
  /// @brief Integer value of @p name, or @p fallback if absent. The table checks a fixed
  /// range; @p minValue and @p maxValue check one that depends on other options.
  /// @throws UsageError if it is not an integer in [minValue, maxValue].
  int integer(const std::string& name, int fallback, int minValue = INT_MIN,
              int maxValue = INT_MAX) const;
  /// @brief Number given for @p name (its range is checked by the table), or std::nullopt.
  std::optional<double> number(const std::string& name) const;
  /// @brief Requires exactly @p count positionals, named in @p what for the message.
  /// @throws UsageError otherwise.
  void expectPositionals(std::size_t count, const std::string& what) const;

 private:
  const CLI::Option* find(const std::string& name) const;
  void rejectValueMismatch(std::span<const std::string> words) const;

  std::string command_;
  std::unique_ptr<CLI::App> app_;
  std::vector<CLI::Option*> positionalOptions_;
  std::vector<std::string> positionals_;
};

}  // namespace ddfcam::cli
