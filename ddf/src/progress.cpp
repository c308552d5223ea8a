// SPDX-License-Identifier: MIT
#include <ddfcam/error.h>
#include <ddfcam/progress.h>

namespace ddfcam {

void reportProgress(const ProgressCallback& progress, double fraction) {
  if (progress && !progress(fraction)) throw Cancelled();
}

}  // namespace ddfcam
