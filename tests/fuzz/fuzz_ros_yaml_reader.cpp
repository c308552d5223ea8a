// SPDX-License-Identifier: MIT
// ddfcam fuzzing: the ROS toolpath YAML reader (decodeRosToolpathYaml) on arbitrary bytes.
#include <ddfcam/io/programs/ros_toolpath_reader.h>

#include "fuzz_support.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  return ddfcam::fuzz::fuzzReader(data, size, [](std::string_view text) {
    return ddfcam::io::decodeRosToolpathYaml(text, ddfcam::fuzz::kSourceName);
  });
}
