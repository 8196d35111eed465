// Errors that reach the user as one line: what is wrong, and where possible how to fix it.
#pragma once

#include <stdexcept>
#include <string>

namespace tidepool {

// Any failure the user can act on (bad input, missing file, unsupported driver...).
// main() prints what() on one line and exits non-zero.
class Error : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

}  // namespace tidepool
