// The ripples scene: the heightfield model, its 2D view and the mouse (press: a bump of the
// touch depth; drag: a tenth of it each frame, as in water-simulation-gpu).
#pragma once

#include "scene/stage.h"
#include "sim/ripples/ripples_params.h"

namespace tidepool {

SceneParams parseRipplesParams(const io::Json& params, const std::string& where);
std::unique_ptr<Stage> createRipplesStage(const SceneParams& params, const std::string& where,
                                          gl::ShaderLibrary& shaders);

ripples::Params& ripplesParams(SceneParams& params);  // the model's part (method auto edits it)
const ripples::Params& ripplesParams(const SceneParams& params);

}  // namespace tidepool
