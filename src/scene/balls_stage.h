// The balls scene: the ball model, its renderer and an orbit camera (left drag rotates, right
// drag pans, wheel zooms). Live statistics are refreshed every few frames for the status line.
#pragma once

#include "scene/stage.h"

namespace tidepool {

std::unique_ptr<Stage> createBallsStage(const io::Json& params, const std::string& where, gl::ShaderLibrary& shaders);

}  // namespace tidepool
