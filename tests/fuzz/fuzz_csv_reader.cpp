// SPDX-License-Identifier: MIT
// ddfcam fuzzing: the tool-path CSV reader (decodeToolPathCsv) on arbitrary bytes.
#include <ddfcam/io/programs/tool_path_csv.h>

#include "fuzz_support.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  // The reader options follow from the input size, so the corpus stays plain CSV text.
  ddfcam::io::CsvReadParams params;
  constexpr ddfcam::io::LengthUnit kUnits[] = {ddfcam::io::LengthUnit::Millimetre,
                                               ddfcam::io::LengthUnit::Inch,
                                               ddfcam::io::LengthUnit::Metre};
  params.unitIfUnstated = kUnits[size % 3];
  params.kindIfUnstated = size / 3 % 2 ? ddfcam::planning::ClPointKind::Contact
                                       : ddfcam::planning::ClPointKind::ToolReference;
  return ddfcam::fuzz::fuzzReader(data, size, [&params](std::string_view text) {
    return ddfcam::io::decodeToolPathCsv(text, ddfcam::fuzz::kSourceName, params);
  });
}
