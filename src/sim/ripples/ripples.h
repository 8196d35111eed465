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
#include "gl/buffer_ops.h"
#include "gl/gpu_profiler.h"
#include "gl/shader_library.h"
#include "sim/divergence.h"
#include "sim/ripples/ripples_params.h"

namespace tidepool::ripples {

class Ripples {
 public:
  Ripples(gl::ShaderLibrary& shaders, const Params& params);  // throws Error when too large

  Params& params() { return m_params; }  // edits apply at the next step (size changes re-allocate)
  const Params& params() const { return m_params; }

  void reset();                                               // flat water at rest
  void step(double frameSeconds, gl::GpuProfiler& profiler);  // one frame = substepsFor() steps
  void stepOnce(double dt);                                   // exactly one step of dt seconds
  // Adds the cosine bump at (x, y) in [0,1]^2 of the grid; depth in metres, radius in grid widths.
  void touch(float x, float y, float radius, float depth);

  const gl::Buffer& state() const { return m_state[m_current]; }  // vec2 (h, v) per cell
  void upload(const std::vector<float>& heightAndVelocity);       // 2 floats per cell
  std::vector<float> download() const;                            // 2 floats per cell
  double time() const { return m_time; }
  bool sphereActive() const { return m_params.sphere; }
  glm::vec3 sphereCentre() const { return ripples::sphereCentre(m_params, m_time); }  // m, see Params
  int lastSubsteps() const { return m_lastSubsteps; }
  float lastCourant() const { return m_lastCourant; }  // wave rule, of the last step
  std::string status() const;                          // one line: size, substeps, C, warnings

  // Divergence watch (see sim/divergence.h): a non-blocking health check every few frames.
  std::optional<DivergenceReport> divergence() const { return m_divergence; }
  bool recover();              // back to the last good state with half the time step; false if none
  void flushChecks();          // waits for the check in flight (end of a headless run)
  double heightBound() const;  // |h| above this counts as a blow-up (m, or seed units)
  double lastMaxHeight() const { return m_lastMaxHeight; }  // max |h| of the last check (NaN before)

 private:
  void allocate();
  void watch();  // polls the check in flight, starts the next one
  void judge(const Health& health);
  CheckCycle::Judge judgeFn();  // decodes the health words for judge()
  void pushBody(double dt);     // the sphere's displacement change over the next step
  gl::Program& stepProgram();

  gl::ShaderLibrary& m_shaders;
  gl::BufferOps m_ops;  // checkpoint copies
  Params m_params;
  int m_width = 0, m_height = 0;  // allocated size
  gl::Buffer m_state[2];
  int m_current = 0;
  double m_time = 0;
  int m_lastSubsteps = 0;
  float m_lastCourant = 0;
  double m_rainDebt = 0;
  // Divergence watch: reduced values, the state copied at the check, the last state judged good.
  gl::Buffer m_health, m_pending, m_good;
  CheckCycle m_checks{8};  // a check every 8 frames
  double m_goodTime = 0;
  bool m_hasGood = false;
  double m_lastDt = 0;
  std::optional<DivergenceReport> m_divergence;
  double m_lastMaxHeight = NAN;
  std::mt19937 m_rng{12345};
};

}  // namespace tidepool::ripples
