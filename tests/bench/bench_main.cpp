// SPDX-License-Identifier: MIT
// ddfcam-bench entry point: records the build's CPU tuning in the benchmark context.
#include <benchmark/benchmark.h>

#include <thread>

int main(int argc, char** argv) {
#ifdef DDFCAM_NATIVE_BUILD
  benchmark::AddCustomContext("ddfcam_cpu_tuning", "native (-march=native)");
#else
  benchmark::AddCustomContext(
      "ddfcam_cpu_tuning",
      "portable (x86-64 baseline; row kernels also cloned for x86-64-v3, chosen at load time)");
#endif
  benchmark::AddCustomContext("ddfcam_hardware_threads",
                              std::to_string(std::thread::hardware_concurrency()));
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
