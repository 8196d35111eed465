// What a refusal says: the tests check the words of tidepool's errors, not only that one was thrown.
#pragma once

#include <functional>
#include <string>

#include "base/error.h"

namespace tidepool::test {

// The message of the tidepool::Error that `f` throws; "" when it throws none.
inline std::string errorOf(const std::function<void()>& f) {
  try {
    f();
  } catch (const Error& e) {
    return e.what();
  }
  return "";
}

}  // namespace tidepool::test
