// The ripples scene: the heightfield model, its 2D view and the mouse (press: a bump of the
// touch depth; drag: a tenth of it each frame, as in water-simulation-gpu).
#pragma once

#include "scene/stage.h"

namespace tidepool {

ModelEntry ripplesModel();  // "ripples" in scene files

}  // namespace tidepool
