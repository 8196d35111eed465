// The "swarm" model in a scene: the simulation (sim/swarm) and its renderer
// (render/swarm_renderer) tied together, with the mouse attractor and image drag-and-drop.
//
//   { "model": "swarm",
//     "params": { "particles": 1048576, "preset": "orbit", "integrator": "symplectic_euler",
//                 "view": { "color_mode": "image", "image": "colors", "opacity": 0.1 } } }
#pragma once

#include "scene/stage.h"
#include "sim/swarm/swarm_params.h"

namespace tidepool {

SceneParams parseSwarmParams(const io::Json& params, const std::string& where);
std::unique_ptr<Stage> createSwarmStage(const SceneParams& params, const std::string& where,
                                        gl::ShaderLibrary& shaders);

sim::SwarmParams& swarmParams(SceneParams& params);  // the model's part (method auto edits it)
const sim::SwarmParams& swarmParams(const SceneParams& params);

}  // namespace tidepool
