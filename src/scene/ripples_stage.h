// The ripples scene: the heightfield model, its 2D view and the mouse (press: a bump of the
// touch depth; drag: a tenth of it each frame, as in water-simulation-gpu).
#pragma once

#include "scene/stage.h"

namespace tidepool {

std::unique_ptr<Stage> createRipplesStage(const io::Json& params, const std::string& where, gl::ShaderLibrary& shaders);

}  // namespace tidepool
