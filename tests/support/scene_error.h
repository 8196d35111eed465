// The one-line error of loading a scene given as JSON text, for tests of what a scene can state
// wrongly; "" when it loads.
#pragma once

#include <string>

#include "base/error.h"
#include "scene/scene.h"

namespace tidepool::test {

inline std::string sceneError(const std::string& json, const std::string& where = "s.json") {
  try {
    parseScene(io::parseJson(json, where), where);
  } catch (const Error& e) {
    return e.what();
  }
  return "";
}

}  // namespace tidepool::test
