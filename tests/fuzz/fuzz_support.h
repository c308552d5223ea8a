// SPDX-License-Identifier: MIT
// ddfcam fuzzing: the shared body of the reader targets; only ddfcam::Error may leave a reader.
#pragma once

#include <ddfcam/error.h>

#include "fuzz_inputs.h"

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <string_view>

namespace ddfcam::fuzz {

/// @brief File name the targets pass to the readers; error messages must start with it.
inline const std::string kSourceName = "fuzz-input";

/// @brief False when DDFCAM_FUZZ_CONTRACT=0: then only crashes, sanitizer reports, foreign
/// exceptions and timeouts count, not broken messages or programs.
inline bool checkContract() {
  static const bool check = [] {
    const char* value = std::getenv("DDFCAM_FUZZ_CONTRACT");
    return !value || std::string_view(value) != "0";
  }();
  return check;
}

[[noreturn]] inline void contractBroken(const std::string& what, std::string_view text) {
  std::fprintf(stderr, "ddfcam reader contract broken: %s\ninput: \"%s\"\n", what.c_str(),
               test::escaped(text).c_str());
  std::abort();
}

/// @brief Runs @p read on the input as text. ddfcam::Error is the expected outcome of bad input;
/// anything else propagates and terminates (libFuzzer reports it with its stack). With the
/// contract check on, an error message must name the file and a line in range, and a program
/// read must satisfy test::programViolation.
template <class Read>
int fuzzReader(const std::uint8_t* data, std::size_t size, Read&& read) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  try {
    const auto result = read(text);
    if (checkContract())
      if (const auto broken = test::programViolation(result, text)) contractBroken(*broken, text);
  } catch (const Error& e) {
    if (checkContract())
      if (const auto broken = test::messageViolation(e.what(), text, kSourceName))
        contractBroken(*broken, text);
  }
  return 0;
}

}  // namespace ddfcam::fuzz
