// SPDX-License-Identifier: MIT
// ddfcam: progress reporting and cancellation through a plain callback.
#pragma once

#include <functional>

namespace ddfcam {

/// @brief Called with the fraction done in [0, 1]; returns false to request cancellation.
/// Long operations call it at least every few hundred milliseconds and throw ddfcam::Cancelled
/// when it returns false, leaving their inputs unchanged.
using ProgressCallback = std::function<bool(double fraction)>;

/// @brief Reports @p fraction to @p progress (if any) and throws Cancelled if it asks to stop.
void reportProgress(const ProgressCallback& progress, double fraction);

}  // namespace ddfcam
