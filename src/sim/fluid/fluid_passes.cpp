// The fluid step as a list of passes (Macklin & Müller 2013, algorithm 1). Each pass binds what
// its kernel reads and writes and ends with the barrier its readers need; stepOnce() only names
// them. Buffers swap roles instead of being copied: after sortByCell m_x and m_pred are in the
// step's cell order, and stay in it.
#include <algorithm>
#include <cmath>
#include <memory>
#include <utility>

#include "fluid/bindings.glsl"
#include "sim/fluid/fluid.h"

namespace tidepool::fluid {
namespace {

gl::GpuProfiler::Scope timed(gl::GpuProfiler* profiler, const char* name) {
  return profiler ? profiler->scope(name) : gl::GpuProfiler::Scope(nullptr);
}

}  // namespace

void Fluid::stepOnce(gl::GpuProfiler* profiler) {
  calibrate();
  if (m_grid->params().cellSize != cellSize()) {  // h or the grid cell edited
    grid::GridParams gp = m_grid->params();
    gp.cellSize = cellSize();
    m_grid = std::make_unique<grid::UniformGrid>(m_shaders, gp, m_capacity);
  }
  if (std::string error; m_obstacles.update(m_params.obstacles, m_params.radius, error)) {
    m_obstacleError = error;
  }
  emitFromTap();
  m_walls = water::wallsAt(m_params, m_time + m_params.dt);  // the collisions see the walls at the step's end
  m_coupling.sync(m_params.obstacles);
  const water::LoadsWanted want = water::loadsWanted(m_params.probes, m_coupling.any());
  m_loadsOn = want.any;
  if (m_loadsOn) m_loads.begin(m_count, want.walls, m_obstacles);
  // Neither predict nor the sort reads the obstacles: the GPU runs them while the bodies wait
  // for the last step's loads.
  if (m_count > 0) {
    predict(profiler);
    sortByCell(profiler);
  }
  m_coupling.move(m_params.dt, loadScale(), glm::dvec3(gravity()), m_walls,
                  water::posesAt(m_params.obstacles, m_time + m_params.dt));
  // Placed where they are at the step's end, when the collisions see them (timed as "balls.obstacles").
  m_obstacles.place(m_params.obstacles, bodies().poses(m_params.obstacles, m_time + m_params.dt), m_params.domainMin,
                    m_params.domainMax, profiler);
  if (m_count > 0) solve(profiler);
  if (m_loadsOn) m_loads.sum(m_obstacles);
  m_densitiesValid = m_count > 0 && m_params.iterations > 0;
  m_coupling.requestLoads(m_densitiesValid);  // complete: on their way back while the velocities follow
  if (m_count > 0) updateVelocities(profiler);
  m_time += m_params.dt;
  ++m_steps;
}

void Fluid::step(gl::GpuProfiler& profiler) {
  for (int i = 0; i < m_params.substeps; ++i) stepOnce(&profiler);
  watch();
}

SphUniforms Fluid::sph() const { return sphUniforms(m_params.h(), m_rest); }

WallUniforms Fluid::walls() const {
  return {m_walls.min, m_walls.max, float(m_rest.wallScale), 0.5f * m_params.spacing()};
}

NeighbourUniforms Fluid::bindNeighbours() const {
  m_grid->cellStart().bindBase(GL_SHADER_STORAGE_BUFFER, FLUID_CELL_START);
  return {kGridReach, m_grid->uniforms()};
}

std::vector<gl::ShaderDefine> Fluid::bindWallLoads() const {
  if (!m_loadsOn || !m_loads.walls()) return {};
  m_loads.bindWalls(FLUID_LOADS);
  return {{"LOADS_WALLS", ""}};
}

void Fluid::predict(gl::GpuProfiler* profiler) {
  auto scope = timed(profiler, "fluid.predict");
  const gl::Kernel<PredictUniforms> predict(m_shaders, "fluid/predict.comp",
                                            {FLUID_POS, FLUID_VEL_IN, FLUID_OUT, FLUID_LOADS}, bindWallLoads());
  m_x.bindBase(GL_SHADER_STORAGE_BUFFER, FLUID_POS);
  m_v.bindBase(GL_SHADER_STORAGE_BUFFER, FLUID_VEL_IN);
  m_pred.bindBase(GL_SHADER_STORAGE_BUFFER, FLUID_OUT);
  predict.dispatchThreads(m_count, {.count = GLuint(m_count),
                                    .dt = m_params.dt,
                                    .gravity = gravity(),
                                    .decay = std::exp(-m_params.damping * m_params.dt),
                                    .sph = sph(),
                                    .walls = walls()});
  glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
}

void Fluid::sortByCell(gl::GpuProfiler* profiler) {
  {
    auto scope = timed(profiler, "fluid.count");
    m_grid->countParticles(m_pred, m_count);
  }
  {
    auto scope = timed(profiler, "fluid.scan");
    m_grid->scanCells();
  }
  auto scope = timed(profiler, "fluid.reorder");
  m_grid->setStable(m_params.deterministic);
  m_grid->reorder(m_pred, {{&m_pred, &m_scratch[0]}, {&m_x, &m_scratch[1]}}, m_trackOrder ? &m_permutation : nullptr);
  std::swap(m_pred, m_scratch[0]);
  std::swap(m_x, m_scratch[1]);
}

void Fluid::solve(gl::GpuProfiler* profiler) {
  const Params& q = m_params;
  const float dq = q.scorrDq;
  const std::vector<gl::ShaderDefine> boundary = boundaryDefines(m_obstacles);
  std::vector<gl::ShaderDefine> deltaDefines = boundary;
  if (q.scorrN == 4.0f) deltaDefines.push_back({"SCORR_N4", ""});
  for (const gl::ShaderDefine& d : bindWallLoads()) deltaDefines.push_back(d);
  const bool obstacleLoads = m_loadsOn && m_loads.obstacles();
  if (obstacleLoads) {
    deltaDefines.push_back({"OBSTACLE_LOADS", ""});
    if (m_unpushed.size() < m_capacity * sizeof(glm::vec4)) m_unpushed = gl::Buffer(m_capacity * sizeof(glm::vec4));
  }
  const gl::Kernel<LambdaUniforms> lambda(m_shaders, "fluid/lambda.comp",
                                          {FLUID_CELL_START, FLUID_PRED, FLUID_LAMBDA, FLUID_PRESSURE}, boundary);
  const gl::Kernel<DeltaUniforms> delta(
      m_shaders, "fluid/delta.comp",
      {FLUID_CELL_START, FLUID_PRED, FLUID_LAMBDA, FLUID_OUT, FLUID_LOADS, FLUID_UNPUSHED}, deltaDefines);
  for (int k = 0; k < q.iterations; ++k) {
    {
      auto scope = timed(profiler, "fluid.lambda");
      m_pred.bindBase(GL_SHADER_STORAGE_BUFFER, FLUID_PRED);
      m_lambda.bindBase(GL_SHADER_STORAGE_BUFFER, FLUID_LAMBDA);
      m_lambdaSum.bindBase(GL_SHADER_STORAGE_BUFFER, FLUID_PRESSURE);
      lambda.dispatchThreads(m_count, {.count = GLuint(m_count),
                                       .epsilon = float(q.relaxation * m_rest.gradients),
                                       .firstIteration = k == 0,
                                       .sph = sph(),
                                       .walls = walls(),
                                       .neighbours = bindNeighbours(),
                                       .boundary = bindBoundary(m_obstacles, q.h())});
      glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
    }
    {
      auto scope = timed(profiler, "fluid.delta");
      bindWallLoads();  // the obstacles' loads bind their own there
      if (obstacleLoads) m_unpushed.bindBase(GL_SHADER_STORAGE_BUFFER, FLUID_UNPUSHED);
      m_pred.bindBase(GL_SHADER_STORAGE_BUFFER, FLUID_PRED);
      m_lambda.bindBase(GL_SHADER_STORAGE_BUFFER, FLUID_LAMBDA);
      m_scratch[0].bindBase(GL_SHADER_STORAGE_BUFFER, FLUID_OUT);
      // s_corr in the units of λ (m²): k times the λ a unit compression gives a resting particle, so k
      // is the compression one close pair pushes with (Macklin's k = 0.1 is dimensionless only in the
      // paper's units, where the mass is 1 and ρ0 sets the scale).
      delta.dispatchThreads(m_count, {.count = GLuint(m_count),
                                      .scorrK = float(q.scorrK / m_rest.gradients),
                                      .scorrN = q.scorrN,
                                      .scorrInvQ = 1.0f / (1.0f - dq * dq),
                                      .contact = kObstacleContact * q.spacing(),
                                      .sph = sph(),
                                      .walls = walls(),
                                      .neighbours = bindNeighbours(),
                                      .boundary = bindBoundary(m_obstacles, q.h())});
      glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
    }
    if (obstacleLoads) measureObstacleLoads(k > 0, profiler);  // from the iteration's inputs, m_pred
    std::swap(m_pred, m_scratch[0]);
  }
}

// The obstacles' shares of the iteration just run (fluid/obstacle_loads.comp): after Δp, from its
// inputs p (m_pred), λ and its positions before the push; `add` to the earlier iterations'.
void Fluid::measureObstacleLoads(bool add, gl::GpuProfiler* profiler) {
  auto scope = timed(profiler, "fluid.loads");
  const gl::Kernel<ObstacleLoadsUniforms> kernel(
      m_shaders, "fluid/obstacle_loads.comp",
      {FLUID_CELL_START, FLUID_PRED, FLUID_LAMBDA, FLUID_UNPUSHED, FLUID_OBSTACLE_PLACED, FLUID_OBSTACLE_VOLUMES,
       FLUID_SHARES, FLUID_MOMENTS},
      boundaryDefines(m_obstacles));
  m_pred.bindBase(GL_SHADER_STORAGE_BUFFER, FLUID_PRED);
  m_lambda.bindBase(GL_SHADER_STORAGE_BUFFER, FLUID_LAMBDA);
  m_unpushed.bindBase(GL_SHADER_STORAGE_BUFFER, FLUID_UNPUSHED);
  m_obstacles.placed().bindBase(GL_SHADER_STORAGE_BUFFER, FLUID_OBSTACLE_PLACED);
  if (const gl::Buffer* volumes = m_obstacles.bodyVolumes())
    volumes->bindBase(GL_SHADER_STORAGE_BUFFER, FLUID_OBSTACLE_VOLUMES);
  m_loads.bindShares(FLUID_SHARES, FLUID_MOMENTS);
  m_obstacles.bind();
  NeighbourUniforms neighbours = bindNeighbours();
  ++neighbours.reach;  // the particles moved since the sort (fluid/obstacle_loads.comp)
  kernel.dispatchThreads(m_obstacles.particles(), {.particles = GLuint(m_obstacles.particles()),
                                                   .add = GLuint(add),
                                                   .contact = kObstacleContact * m_params.spacing(),
                                                   .sph = sph(),
                                                   .neighbours = neighbours});
  glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
}

void Fluid::updateVelocities(gl::GpuProfiler* profiler) {
  {
    auto scope = timed(profiler, "fluid.velocity");
    const gl::Kernel<VelocityUniforms> velocity(m_shaders, "fluid/velocity.comp",
                                                {FLUID_POS, FLUID_PRED, FLUID_OUT, FLUID_LAMBDA});
    m_x.bindBase(GL_SHADER_STORAGE_BUFFER, FLUID_POS);
    m_pred.bindBase(GL_SHADER_STORAGE_BUFFER, FLUID_PRED);
    m_v.bindBase(GL_SHADER_STORAGE_BUFFER, FLUID_OUT);
    m_lambda.bindBase(GL_SHADER_STORAGE_BUFFER, FLUID_LAMBDA);
    velocity.dispatchThreads(m_count, {.count = GLuint(m_count),
                                       .dt = m_params.dt,
                                       .foamGain = m_params.foamGain,
                                       // the seed's decay per 0.5 ms
                                       .foamDecay = std::pow(m_params.foamDecay, m_params.dt / 0.0005f),
                                       .sprayDensity = m_params.sprayDensity});
    glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
  }
  std::swap(m_x, m_pred);  // the corrected positions are the new state (w = 1)
  const bool vorticity = m_params.vorticity > 0;
  if (m_params.viscosity > 0 || vorticity) {
    auto scope = timed(profiler, "fluid.viscosity");
    std::vector<gl::ShaderDefine> defines;
    if (vorticity) defines.push_back({"VORTICITY", ""});
    const gl::Kernel<ViscosityUniforms> viscosity(m_shaders, "fluid/viscosity.comp",
                                                  {FLUID_CELL_START, FLUID_PRED, FLUID_VEL_IN, FLUID_OUT, FLUID_LAMBDA},
                                                  defines);
    m_x.bindBase(GL_SHADER_STORAGE_BUFFER, FLUID_PRED);
    m_v.bindBase(GL_SHADER_STORAGE_BUFFER, FLUID_VEL_IN);
    m_scratch[0].bindBase(GL_SHADER_STORAGE_BUFFER, FLUID_OUT);
    if (vorticity) m_scratch[1].bindBase(GL_SHADER_STORAGE_BUFFER, FLUID_LAMBDA);
    viscosity.dispatchThreads(m_count, {GLuint(m_count), m_params.viscosity, sph(), bindNeighbours()});
    glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
    std::swap(m_v, m_scratch[0]);
  }
  if (vorticity) {
    auto scope = timed(profiler, "fluid.vorticity");
    const gl::Kernel<VorticityUniforms> kernel(m_shaders, "fluid/vorticity.comp",
                                               {FLUID_CELL_START, FLUID_PRED, FLUID_VEL_IN, FLUID_LAMBDA, FLUID_OUT});
    m_x.bindBase(GL_SHADER_STORAGE_BUFFER, FLUID_PRED);
    m_v.bindBase(GL_SHADER_STORAGE_BUFFER, FLUID_VEL_IN);
    m_scratch[1].bindBase(GL_SHADER_STORAGE_BUFFER, FLUID_LAMBDA);
    m_scratch[0].bindBase(GL_SHADER_STORAGE_BUFFER, FLUID_OUT);
    kernel.dispatchThreads(m_count, {GLuint(m_count), m_params.dt, m_params.vorticity, sph(), bindNeighbours()});
    glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
    std::swap(m_v, m_scratch[0]);
  }
}

}  // namespace tidepool::fluid
