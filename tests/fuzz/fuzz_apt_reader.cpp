// SPDX-License-Identifier: MIT
// ddfcam fuzzing: the APT/CLDATA reader (decodeApt) on arbitrary bytes.
#include <ddfcam/io/programs/apt_reader.h>

#include "fuzz_support.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  // The chord tolerance follows from the input size, so the corpus stays plain APT text.
  constexpr double kChordTolerancesMm[] = {0.005, 0.0001, 0.5};
  ddfcam::io::AptReadParams params;
  params.chordToleranceMm = kChordTolerancesMm[size % 3];
  return ddfcam::fuzz::fuzzReader(data, size, [&params](std::string_view text) {
    return ddfcam::io::decodeApt(text, ddfcam::fuzz::kSourceName, params);
  });
}
