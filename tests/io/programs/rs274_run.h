// SPDX-License-Identifier: MIT
// Test support: LinuxCNC's stand-alone RS274NGC interpreter (`rs274`, Debian package
// linuxcnc-uspace) run on a program file, as the oracle for written G-code.
#pragma once

#include <cstdlib>
#include <filesystem>
#include <sstream>
#include <string>

#include <sys/wait.h>

#include "../io_test_support.h"

namespace ddfcam::test {

/// The interpreter's path (tests skip when it is not installed).
inline const std::filesystem::path kRs274Path = "/usr/bin/rs274";

/// What one rs274 run printed.
struct Rs274Run {
  int exitCode = -1;   ///< the interpreter's exit code; -1 when it died on a signal
  std::string out;     ///< canonical calls (stdout)
  std::string errors;  ///< stderr without the "executing" banner and empty lines
};

/// Runs rs274 -g on the program text @p program in a scratch directory of its own.
///
/// rs274 creates $HOME/.tool.mmap with O_TRUNC and maps it; two runs sharing a HOME (tests run
/// in parallel processes under ctest -j) truncate each other's mapping and one dies with
/// SIGBUS, printing nothing. So every run gets its scratch directory as HOME.
inline Rs274Run runRs274(const std::string& program) {
  const ScratchDir dir;
  writeBytes(dir / "program.ngc", program);
  std::ostringstream command;
  command << "HOME='" << dir.path().string() << "' " << kRs274Path.string() << " -g '"
          << (dir / "program.ngc").string() << "' > '" << (dir / "out").string() << "' 2> '"
          << (dir / "err").string() << "' < /dev/null";
  const int status = std::system(command.str().c_str());
  Rs274Run run;
  // The shell reports a child killed by signal s as exit code 128 + s.
  if (WIFEXITED(status) && WEXITSTATUS(status) < 128) run.exitCode = WEXITSTATUS(status);
  run.out = readBytes(dir / "out");
  std::istringstream lines(readBytes(dir / "err"));
  for (std::string line; std::getline(lines, line);)
    if (line != "executing" && !line.empty()) run.errors += line + "\n";
  return run;
}

}  // namespace ddfcam::test
