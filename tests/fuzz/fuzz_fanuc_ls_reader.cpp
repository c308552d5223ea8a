// SPDX-License-Identifier: MIT
// ddfcam fuzzing: the FANUC TP .ls reader (decodeFanucLs) on arbitrary bytes.
#include <ddfcam/io/programs/fanuc_ls_reader.h>

#include "fuzz_support.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  return ddfcam::fuzz::fuzzReader(data, size, [](std::string_view text) {
    return ddfcam::io::decodeFanucLs(text, ddfcam::fuzz::kSourceName);
  });
}
