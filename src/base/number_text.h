// A number for a message: printf's %g (six significant digits, no trailing zeros, an exponent
// only where it is shorter).
#pragma once

#include <cstdio>
#include <string>

namespace tidepool {

inline std::string numberText(double x) {
  char text[32];
  std::snprintf(text, sizeof text, "%g", x);
  return text;
}

}  // namespace tidepool
