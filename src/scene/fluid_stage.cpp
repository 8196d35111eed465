#include "scene/fluid_stage.h"

#include "io/echo.h"
#include "scene/water_stage.h"

namespace tidepool {

void visit(ParamVisitor& v, FluidSceneParams& p) {
  fluid::visit(v, p.model);
  visitViewGroup(v, p.view);
}

const FluidSceneParams& fluidScene(const Scene& scene) {
  if (scene.model != "fluid")
    throw Error(io::shownPath(scene.file) + ": not a fluid scene (model " + scene.model + ")");
  return scene.params.as<FluidSceneParams>();
}

namespace {

SceneParams parseFluidParams(const io::Json& params, const std::string& where) {
  return readSceneParams<FluidSceneParams>(params, where);
}

std::unique_ptr<Stage> createFluidStage(const SceneParams& params, const std::string& where,
                                        gl::ShaderLibrary& shaders) {
  const FluidSceneParams& p = params.as<FluidSceneParams>();
  return createWaterStage(shaders, p.model, p.view, where);
}

}  // namespace

ModelEntry fluidModel() {
  return {"fluid",
          "incompressible water: position-based fluids (Macklin & Mueller 2013) on the balls' particles",
          parseFluidParams,
          createFluidStage,
          {{"particles", "the particles' spacing, domain and initial water"}}};
}

}  // namespace tidepool
