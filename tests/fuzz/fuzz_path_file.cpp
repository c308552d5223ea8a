// SPDX-License-Identifier: MIT
// ddfcam fuzzing: format detection and dispatch of readPathFile on arbitrary files.
#include <ddfcam/io/programs/path_file.h>

#include "fuzz_support.h"

#include <unistd.h>
#include <array>
#include <cstdlib>
#include <filesystem>
#include <fstream>

namespace {

/// The first input byte picks the file name extension; the rest is the file's content.
constexpr std::array<const char*, 12> kExtensions = {
    ".csv", ".txt", ".apt", ".cls", ".ncl", ".yaml", ".yml", ".ls", ".LS", ".ngc", ".dat", ""};

/// The directory for the one file each input is written to (readPathFile reads files):
/// $DDFCAM_FUZZ_SCRATCH if set (scripts/fuzz-readers makes one in /dev/shm and removes it), else a
/// per-process directory in /dev/shm or the temporary directory, removed at a normal exit.
class ScratchDirectory {
 public:
  ScratchDirectory() {
    if (const char* given = std::getenv("DDFCAM_FUZZ_SCRATCH")) {
      path_ = given;
    } else {
      const bool shm = std::filesystem::is_directory("/dev/shm");
      path_ = (shm ? std::filesystem::path("/dev/shm") : std::filesystem::temp_directory_path()) /
              ("ddfcam-fuzz-path-file-" + std::to_string(::getpid()));
      owned_ = true;
    }
    std::filesystem::create_directories(path_);
  }
  ~ScratchDirectory() {
    std::error_code ignored;
    if (owned_) std::filesystem::remove_all(path_, ignored);
  }
  const std::filesystem::path& path() const { return path_; }

 private:
  std::filesystem::path path_;
  bool owned_ = false;
};

const std::filesystem::path& scratchDirectory() {
  static const ScratchDirectory dir;
  return dir.path();
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size == 0) return 0;
  const std::filesystem::path file =
      scratchDirectory() / (std::string("input") + kExtensions[data[0] % kExtensions.size()]);
  return ddfcam::fuzz::fuzzReader(data + 1, size - 1, [&file](std::string_view text) {
    std::ofstream(file, std::ios::binary | std::ios::trunc)
        .write(text.data(), static_cast<std::streamsize>(text.size()));
    // Messages name the file; the contract check expects them to start with kSourceName.
    try {
      return ddfcam::io::readPathFile(file).program;
    } catch (const ddfcam::Error& e) {
      const std::string message = e.what();
      for (const std::string& name : {file.string(), file.filename().string()})
        if (message.rfind(name, 0) == 0)
          throw ddfcam::IoError(ddfcam::fuzz::kSourceName + message.substr(name.size()));
      throw;
    }
  });
}
