// Numbers in what the engine tells a user (refused input, diagnostics): one spelling, four significant digits.
#pragma once
#include <cstdio>
#include <string>

namespace shotlab {

inline std::string message_number(double v) {
  char text[32];
  std::snprintf(text, sizeof text, "%.4g", v);
  return text;
}

}  // namespace shotlab
