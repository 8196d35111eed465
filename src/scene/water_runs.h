// The water stage's two models behind one interface (scene/water_stage.cpp): a WaterRun holds one
// model's parameters and, while it is the one running, the model itself. Both runs live as long
// as the stage: the idle one keeps its own keys (contact law, or the PBF solver) and its last
// statistics for a later switch, which hands it the running one's water setup and particles.
#pragma once

#include <array>
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "base/param.h"
#include "gl/shader_library.h"
#include "render/export_source.h"
#include "sim/balls/balls_params.h"
#include "sim/fluid/fluid_params.h"
#include "sim/model.h"
#include "sim/model_state.h"
#include "sim/water/bodies.h"
#include "sim/water/particle_water.h"

namespace tidepool {

enum class WaterModel { Balls, Fluid };
constexpr std::array<const char*, 2> kWaterModelNames = {"balls", "fluid"};

class WaterRun {
 public:
  virtual ~WaterRun() = default;
  // The parameters: the running model's (edits apply to it), else the ones kept for a switch.
  virtual water::Setup& setup() = 0;
  virtual void visitParams(ParamVisitor& v) = 0;  // the model's keys, groups and all
  virtual water::Setup runningSetup() = 0;        // setup() as the model runs it (balls::resolved)
  virtual water::Packing packing() const = 0;
  virtual void refine(double factor) = 0;  // the parameters, by the model's refine(); throws Error
  virtual void save() = 0;                 // a copy of the parameters ...
  virtual void restore() = 0;              // ... put back
  // Builds the model from the parameters (with `pos`, taking over those particles) and replaces
  // the running one; throws Error and then keeps it. stop() keeps the parameters, drops the model.
  virtual void start(gl::ShaderLibrary& shaders, const std::vector<glm::vec4>* pos,
                     const std::vector<glm::vec4>* vel) = 0;
  virtual void stop() = 0;
  virtual sim::Model* model() = 0;  // null while idle
  virtual const sim::Model* model() const = 0;
  virtual water::ParticleWater* water() = 0;
  virtual std::uint64_t frameSteps(std::uint64_t before) const = 0;  // steps of the frame just run
  virtual std::optional<ExportSource> exportSource() = 0;
  // Statistics, read back every few frames; saved by name in checkpoints whether it runs or not.
  virtual void refreshStats() = 0;
  virtual void visitStats(sim::StateVisitor& v) = 0;
  virtual std::string statsLine() const = 0;                      // "; KE ..., ..."
  virtual std::pair<std::string, double> liveMetric() const = 0;  // name and value
  virtual water::Bodies* bodies() = 0;  // the running model's dynamic obstacles, or null before it runs
};

// Both runs, indexed by WaterModel, from one scene's parameters (the other model's follow by asFluid
// or asBalls).
std::array<std::unique_ptr<WaterRun>, 2> waterRuns(const balls::Params& balls, const fluid::Params& fluid);

// The balls parameters a fluid scene's particles would be as balls, and the fluid parameters of a
// balls scene's: `own` with the water setup of the other (water::switched: the same water volume).
balls::Params asBalls(const fluid::Params& f, balls::Params own);
fluid::Params asFluid(const balls::Params& b, fluid::Params own);

}  // namespace tidepool
