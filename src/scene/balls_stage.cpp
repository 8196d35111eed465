#include "scene/balls_stage.h"

#include <cmath>
#include <cstdio>
#include <filesystem>

#include "io/echo.h"
#include "scene/water_stage.h"

namespace tidepool {
namespace {

void visitAll(ParamVisitor& v, balls::Params& model, BallsViewSettings& view) {
  balls::visit(v, model);
  visitViewGroup(v, view);
}

}  // namespace

void visit(ParamVisitor& v, BallsViewSettings& s) {
  visit(v, s.look);
  if (v.beginGroup({"camera", "Camera", "left drag rotates, right drag pans, wheel zooms"})) {
    visit(v, s.camera);
    v.endGroup();
  }
}

void visitViewGroup(ParamVisitor& v, BallsViewSettings& s) {
  if (v.beginGroup({"view", "View", "how the water is drawn"})) {
    visit(v, s);
    v.endGroup();
  }
}

void visit(ParamVisitor& v, BallsSceneParams& p) { visitAll(v, p.model, p.view); }

const BallsSceneParams& ballsScene(const Scene& scene) {
  if (scene.model != "balls")
    throw Error(io::shownPath(scene.file) + ": not a balls scene (model " + scene.model + ")");
  return scene.params.as<BallsSceneParams>();
}

balls::Params ballsParams(const Scene& scene) { return ballsScene(scene).model; }

namespace {

SceneParams parseBallsParams(const io::Json& params, const std::string& where) {
  return readSceneParams<BallsSceneParams>(params, where);
}

std::unique_ptr<Stage> createBallsStage(const SceneParams& params, const std::string& where,
                                        gl::ShaderLibrary& shaders) {
  const BallsSceneParams& p = params.as<BallsSceneParams>();
  return createWaterStage(shaders, p.model, p.view, where);
}

}  // namespace

ModelEntry ballsModel() {
  return {"balls",
          "water as equal balls colliding: grid neighbours, three contact laws, three integrators",
          parseBallsParams,
          createBallsStage,
          {{"particles", "the particles' count, size, domain and initial water"}}};
}

}  // namespace tidepool
