// SPDX-License-Identifier: MIT
#include <ddfcam/error.h>

namespace ddfcam {
namespace {

void appendNested(const std::exception& e, std::string& out) {
  if (!out.empty()) out += '\n';
  out += e.what();
  try {
    std::rethrow_if_nested(e);
  } catch (const std::exception& inner) {
    appendNested(inner, out);
  } catch (...) {
    out += "\nunknown error";
  }
}

}  // namespace

std::string unrollMessage(const std::exception& e) {
  std::string out;
  appendNested(e, out);
  return out;
}

}  // namespace ddfcam
