// SPDX-License-Identifier: MIT
// ddfcam: the one exception hierarchy shared by every library and front end.
#pragma once

#include <exception>
#include <stdexcept>
#include <string>

namespace ddfcam {

/// @brief Base of every error ddfcam throws; front ends catch this once per user action.
class Error : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// @brief Input that violates a documented precondition (bad mesh, bad parameter, bad DDF).
class InvalidInput : public Error {
 public:
  using Error::Error;
};

/// @brief Reading or writing a file failed (missing, truncated, corrupted, foreign).
class IoError : public Error {
 public:
  using Error::Error;
};

/// @brief The user cancelled a long operation through its progress callback. A normal outcome.
class Cancelled : public Error {
 public:
  Cancelled() : Error("cancelled by the user") {}
};

/// @brief Message of @p e followed by the messages of every nested exception, one per line,
/// outermost first ("what failed" then "why").
std::string unrollMessage(const std::exception& e);

}  // namespace ddfcam
