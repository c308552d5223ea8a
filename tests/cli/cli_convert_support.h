// SPDX-License-Identifier: MIT
// Shared set-up of the ddfcam-cli convert tests: running the CLI and reading its verdicts.
#pragma once

#include <sys/wait.h>

#include <nlohmann/json.hpp>

#include <cstdlib>
#include <filesystem>
#include <regex>
#include <string>
#include <vector>

#include "../io/io_test_support.h"

namespace ddfcam::test {

/// Exit code, standard output and standard error of one ddfcam-cli run.
struct ConvertRun {
  int exitCode = -1;
  std::string out, err;
};

/// Runs ddfcam-cli with @p args (each word quoted, no shell expansion) in @p dir.
inline ConvertRun runCli(const ScratchDir& dir, const std::vector<std::string>& args) {
  std::string line = "'" DDFCAM_CLI_PATH "'";
  for (const std::string& a : args) line += " '" + a + "'";
  const auto out = dir / "stdout.txt", err = dir / "stderr.txt";
  line += " > '" + out.string() + "' 2> '" + err.string() + "' < /dev/null";
  const int status = std::system(line.c_str());
  return {WIFEXITED(status) ? WEXITSTATUS(status) : -1, readBytes(out), readBytes(err)};
}

/// The integer after "key": in the JSON of `info --json` (-1 if absent).
inline int jsonInteger(const std::string& json, const std::string& key) {
  std::smatch match;
  if (!std::regex_search(json, match, std::regex("\"" + key + "\": (-?[0-9]+)"))) return -1;
  return std::stoi(match[1]);
}

/// Whether `info --json` says the field satisfies all three constraints.
inline bool infoSaysValid(const std::string& json) {
  const nlohmann::json info = nlohmann::json::parse(json, nullptr, false);
  return info.is_object() && info.contains("validation") &&
         info["validation"].value("ok", false) == true;
}

}  // namespace ddfcam::test
