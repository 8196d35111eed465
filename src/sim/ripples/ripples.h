// Heightfield water ("ripples"): height and vertical velocity on a grid, advanced by the wave
// equation (5-point Laplacian, symplectic Euler) or by water-simulation-gpu's spring + tension
// model. Owns its state buffers (ping-pong) and compute passes; renderers read state().
//   After water-simulation-gpu (Piellard, 2016) and Müller, "Fast Water Simulation for Games
//   Using Height Fields" (GDC 2008).
#pragma once

#include <cmath>
#include <optional>
#include <random>
#include <string>

#include "gl/buffer.h"
#include "gl/gpu_profiler.h"
#include "gl/kernel.h"
#include "sim/model.h"
#include "sim/ripples/ripples_params.h"

namespace tidepool::ripples {

class Ripples final : public sim::Model {
 public:
  Ripples(gl::ShaderLibrary& shaders, const Params& params);  // throws Error when too large

  Params& params() { return m_params; }  // edits apply at the next step (size changes re-allocate)
  const Params& params() const { return m_params; }

  // sim::Model. A frame is substepsFor() steps of params().frameSeconds in all (and the rain's drops).
  void reset() override;  // flat water at rest
  void step(gl::GpuProfiler& profiler) override;
  double frameSeconds() const override { return m_params.frameSeconds; }
  double time() const override { return m_time; }
  std::size_t count() const override { return std::size_t(m_width) * std::size_t(m_height); }  // cells
  std::string status() const override;                    // one line: size, substeps, C, warnings
  std::vector<sim::StateBuffer> stateBuffers() override;  // the state (h, v) per cell

  void stepOnce(double dt);  // exactly one step of dt seconds
  // Adds the cosine bump at (x, y) in [0,1]^2 of the grid; depth in metres, radius in grid widths.
  void touch(float x, float y, float radius, float depth);

  const gl::Buffer& state() const { return m_state[m_current]; }  // vec2 (h, v) per cell
  int width() const { return m_width; }                           // cells of the state now (params() may differ)
  int height() const { return m_height; }
  void upload(const std::vector<float>& heightAndVelocity);  // 2 floats per cell
  std::vector<float> download() const;                       // 2 floats per cell
  bool sphereActive() const { return m_params.sphere; }
  glm::vec3 sphereCentre() const { return ripples::sphereCentre(m_params, m_time); }  // m, see Params

  // The divergence watch (sim::Model): recover() goes back to the last good state with half the time step.
  double heightBound() const;                               // |h| above this counts as a blow-up (m, or seed units)
  double lastMaxHeight() const { return m_lastMaxHeight; }  // max |h| of the last check (NaN before)

 private:
  // The divergence watch (sim::Model): NaN cells, |h| above heightBound().
  void checkHealth(const gl::Window& w) override;
  std::optional<std::string> unhealthy(const sim::DivergenceWatch::Words& words) override;
  std::string method() const override;
  void resume(const sim::StateStamp& good) override;
  // Checkpoints: the clock, the rain's debt and random generator, the last step's figures.
  void visitOwnState(sim::StateVisitor& v) override;

  void pushBody(double dt);       // the sphere's displacement change over the next step
  void allocate();                // the state buffers at params()' size, then reset()
  glm::uvec3 cellGroups() const;  // one invocation per cell, RIPPLES_TILE² per group
  template <class U>
  void dispatchCells(const gl::Kernel<U>& kernel, const U& uniforms) const {  // then a barrier
    kernel.dispatch(cellGroups(), uniforms);
    glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
  }

  gl::ShaderLibrary& m_shaders;
  Params m_params;
  int m_width = 0, m_height = 0;  // allocated size
  gl::Buffer m_state[2];
  int m_current = 0;
  double m_time = 0;
  int m_lastSubsteps = 0;
  float m_lastCourant = 0;
  double m_rainDebt = 0;
  double m_lastDt = 0;
  double m_lastMaxHeight = NAN;
  std::mt19937 m_rng{12345};
};

}  // namespace tidepool::ripples
