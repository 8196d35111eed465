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
  // Placed where they are at the step's end, when the collisions see them (timed as "balls.obstacles").
  m_obstacles.place(m_params.obstacles, m_time + m_params.dt, m_params.domainMin, m_params.domainMax, profiler);
  m_walls = water::wallsAt(m_params, m_time + m_params.dt);  // the collisions see the walls at the step's end
  if (m_count > 0) {
    predict(profiler);
    sortByCell(profiler);
    solve(profiler);
    updateVelocities(profiler);
  }
  m_densitiesValid = m_count > 0 && m_params.iterations > 0;
  m_time += m_params.dt;
  ++m_steps;
}

void Fluid::step(gl::GpuProfiler& profiler) {
  for (int i = 0; i < m_params.substeps; ++i) stepOnce(&profiler);
  watch();
}

gl::Program& Fluid::useKernel(const char* file, std::vector<gl::ShaderDefine> defines) {
  for (const gl::ShaderDefine& d : kernelDefines(m_obstacles)) defines.push_back(d);
  gl::Program& p = m_shaders.program({file}, defines);
  p.use();
  p.set("uCount", GLuint(m_count));
  p.set("uDt", m_params.dt);
  p.set("uWallMin", m_walls.min);
  p.set("uWallMax", m_walls.max);
  p.set("uWallInset", 0.5f * m_params.spacing());
  setKernelUniforms(p, m_params.h(), m_rest);
  bindBoundary(p, m_obstacles, m_params.h());
  m_grid->setUniforms(p);
  p.set("uReach", kGridReach);
  m_grid->cellStart().bindBase(GL_SHADER_STORAGE_BUFFER, FLUID_CELL_START);
  return p;
}

void Fluid::predict(gl::GpuProfiler* profiler) {
  auto scope = timed(profiler, "fluid.predict");
  gl::Program& p = useKernel("fluid/predict.comp");
  p.set("uGravity", gravity());
  p.set("uDecay", std::exp(-m_params.damping * m_params.dt));
  m_x.bindBase(GL_SHADER_STORAGE_BUFFER, FLUID_POS);
  m_v.bindBase(GL_SHADER_STORAGE_BUFFER, FLUID_VEL_IN);
  m_pred.bindBase(GL_SHADER_STORAGE_BUFFER, FLUID_OUT);
  p.dispatchThreads(m_count);
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
  for (int k = 0; k < q.iterations; ++k) {
    {
      auto scope = timed(profiler, "fluid.lambda");
      gl::Program& p = useKernel("fluid/lambda.comp");
      p.set("uEpsilon", float(q.relaxation * m_rest.gradients));
      m_pred.bindBase(GL_SHADER_STORAGE_BUFFER, FLUID_PRED);
      m_lambda.bindBase(GL_SHADER_STORAGE_BUFFER, FLUID_LAMBDA);
      p.dispatchThreads(m_count);
      glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
    }
    auto scope = timed(profiler, "fluid.delta");
    std::vector<gl::ShaderDefine> defines;
    if (q.scorrN == 4.0f) defines.push_back({"SCORR_N4", ""});
    gl::Program& p = useKernel("fluid/delta.comp", defines);
    // s_corr in the units of λ (m²): k times the λ a unit compression gives a resting particle, so k
    // is the compression one close pair pushes with (Macklin's k = 0.1 is dimensionless only in the
    // paper's units, where the mass is 1 and ρ0 sets the scale).
    p.set("uScorrK", float(q.scorrK / m_rest.gradients));
    p.set("uScorrN", q.scorrN);
    p.set("uScorrInvQ", 1.0f / (1.0f - dq * dq));
    p.set("uContact", kObstacleContact * q.spacing());
    m_pred.bindBase(GL_SHADER_STORAGE_BUFFER, FLUID_PRED);
    m_lambda.bindBase(GL_SHADER_STORAGE_BUFFER, FLUID_LAMBDA);
    m_scratch[0].bindBase(GL_SHADER_STORAGE_BUFFER, FLUID_OUT);
    p.dispatchThreads(m_count);
    glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
    std::swap(m_pred, m_scratch[0]);
  }
}

void Fluid::updateVelocities(gl::GpuProfiler* profiler) {
  {
    auto scope = timed(profiler, "fluid.velocity");
    gl::Program& p = useKernel("fluid/velocity.comp");
    p.set("uFoamGain", m_params.foamGain);
    p.set("uFoamDecay", std::pow(m_params.foamDecay, m_params.dt / 0.0005f));  // the seed's decay per 0.5 ms
    m_x.bindBase(GL_SHADER_STORAGE_BUFFER, FLUID_POS);
    m_pred.bindBase(GL_SHADER_STORAGE_BUFFER, FLUID_PRED);
    m_v.bindBase(GL_SHADER_STORAGE_BUFFER, FLUID_OUT);
    p.dispatchThreads(m_count);
    glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
  }
  std::swap(m_x, m_pred);  // the corrected positions are the new state (w = 1)
  const bool vorticity = m_params.vorticity > 0;
  if (m_params.viscosity > 0 || vorticity) {
    auto scope = timed(profiler, "fluid.viscosity");
    std::vector<gl::ShaderDefine> defines;
    if (vorticity) defines.push_back({"VORTICITY", ""});
    gl::Program& p = useKernel("fluid/viscosity.comp", defines);
    p.set("uViscosity", m_params.viscosity);
    m_x.bindBase(GL_SHADER_STORAGE_BUFFER, FLUID_PRED);
    m_v.bindBase(GL_SHADER_STORAGE_BUFFER, FLUID_VEL_IN);
    m_scratch[0].bindBase(GL_SHADER_STORAGE_BUFFER, FLUID_OUT);
    if (vorticity) m_scratch[1].bindBase(GL_SHADER_STORAGE_BUFFER, FLUID_LAMBDA);
    p.dispatchThreads(m_count);
    glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
    std::swap(m_v, m_scratch[0]);
  }
  if (vorticity) {
    auto scope = timed(profiler, "fluid.vorticity");
    gl::Program& p = useKernel("fluid/vorticity.comp");
    p.set("uVorticity", m_params.vorticity);
    m_x.bindBase(GL_SHADER_STORAGE_BUFFER, FLUID_PRED);
    m_v.bindBase(GL_SHADER_STORAGE_BUFFER, FLUID_VEL_IN);
    m_scratch[1].bindBase(GL_SHADER_STORAGE_BUFFER, FLUID_LAMBDA);
    m_scratch[0].bindBase(GL_SHADER_STORAGE_BUFFER, FLUID_OUT);
    p.dispatchThreads(m_count);
    glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
    std::swap(m_v, m_scratch[0]);
  }
}

}  // namespace tidepool::fluid
