// The "blank" model: no simulation state at all; its renderer clears the image to a colour.
// It exists so the shell (window, headless renderer, CLI) can run before any real model.
#pragma once

#include "scene/stage.h"

namespace tidepool {

struct BlankParams {
  glm::vec3 color{0.05f, 0.09f, 0.14f};  // linear RGB clear colour
  double frameSeconds = 1.0 / 30;        // s its clock advances per frame
};
void visit(ParamVisitor& v, BlankParams& p);

ModelEntry blankModel();  // "blank" in scene files

}  // namespace tidepool
