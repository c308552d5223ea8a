// SPDX-License-Identifier: MIT
// ddfcam-cli: command-line front end (convert, extract, info, demo) over the ddfcam libraries.
#include <ddfcam/error.h>

#include "arguments.h"
#include "commands.h"
#include "console.h"

#include <array>
#include <cstdio>
#include <string>
#include <vector>

namespace {

using ddfcam::cli::Command;

constexpr std::array<const Command*, 11> kCommands = {
    &ddfcam::cli::kConvertCommand,  &ddfcam::cli::kExtractCommand,   &ddfcam::cli::kInfoCommand,
    &ddfcam::cli::kDemoCommand,     &ddfcam::cli::kCurvatureCommand, &ddfcam::cli::kPlanCommand,
    &ddfcam::cli::kSimulateCommand, &ddfcam::cli::kRunCommand,       &ddfcam::cli::kPathsCommand,
    &ddfcam::cli::kCompareCommand,  &ddfcam::cli::kCompensateCommand};

void printUsage(std::FILE* out) {
  std::fprintf(out,
               "usage: ddfcam-cli <command> [options]\n\n"
               "Discrete Displacement Field tools for grinding path planning.\n\ncommands:\n");
  for (const Command* c : kCommands) std::fprintf(out, "  %-10s %s\n", c->name, c->summary);
  std::fprintf(out, "\nRun 'ddfcam-cli <command> --help' for the options of a command.\n");
}

bool wantsHelp(const std::vector<std::string>& words) {
  for (const std::string& w : words)
    if (w == "--help" || w == "-h") return true;
  return false;
}

/// The unrolled message ("what failed" then "why") on one line.
std::string oneLine(const std::exception& e) {
  std::string text = ddfcam::unrollMessage(e);
  for (std::size_t at = text.find('\n'); at != std::string::npos; at = text.find('\n', at))
    text.replace(at, 1, ": ");
  return text;
}

int run(const std::vector<std::string>& words) {
  if (words.empty()) throw ddfcam::cli::UsageError("missing command");
  if (words[0] == "--help" || words[0] == "-h" || words[0] == "help") {
    printUsage(stdout);
    return 0;
  }
  for (const Command* c : kCommands) {
    if (words[0] != c->name) continue;
    const std::vector<std::string> args(words.begin() + 1, words.end());
    if (wantsHelp(args)) {
      std::fputs(c->help().c_str(), stdout);
      return 0;
    }
    return c->run(args);
  }
  throw ddfcam::cli::UsageError("unknown command '" + words[0] + "'");
}

}  // namespace

int main(int argc, char** argv) {
  ddfcam::cli::installLogSink();
  try {
    return run(std::vector<std::string>(argv + 1, argv + argc));
  } catch (const ddfcam::cli::UsageError& e) {
    ddfcam::cli::endProgressLine();
    std::fprintf(stderr, "ddfcam-cli: %s (see ddfcam-cli --help)\n", oneLine(e).c_str());
    return 2;
  } catch (const ddfcam::Cancelled& e) {
    ddfcam::cli::endProgressLine();
    std::fprintf(stderr, "ddfcam-cli: %s\n", e.what());
    return 130;
  } catch (const ddfcam::Error& e) {
    ddfcam::cli::endProgressLine();
    std::fprintf(stderr, "ddfcam-cli: error: %s\n", oneLine(e).c_str());
    return 1;
  } catch (const std::exception& e) {
    ddfcam::cli::endProgressLine();
    std::fprintf(stderr, "ddfcam-cli: internal error: %s\n", oneLine(e).c_str());
    return 1;
  }
}
