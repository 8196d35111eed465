// Pointer and keyboard state handed to a stage each frame, free of any window library.
#pragma once

#include <glm/glm.hpp>

namespace tidepool {

struct Input {
  glm::vec2 cursor{0.0f};                            // pixels, origin top-left
  glm::vec2 cursorDelta{0.0f};                       // pixels since the last frame
  glm::ivec2 viewport{1, 1};                         // pixels
  bool left = false, right = false, middle = false;  // buttons held (and not captured by the UI)
  float scroll = 0.0f;                               // wheel steps since the last frame
  float dt = 0.0f;                                   // real seconds since the last frame (eased moves)
};

}  // namespace tidepool
