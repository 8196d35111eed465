// The "swarm" model in a scene: the simulation (sim/swarm) and its renderer
// (render/swarm_renderer) tied together, with the mouse attractor and image drag-and-drop.
//
//   { "model": "swarm",
//     "params": { "particles": 1048576, "preset": "orbit", "integrator": "symplectic_euler",
//                 "view": { "color_mode": "image", "image": "colors", "opacity": 0.1 } } }
#pragma once

#include "scene/stage.h"

namespace tidepool {

ModelEntry swarmModel();  // "swarm" in scene files

}  // namespace tidepool
