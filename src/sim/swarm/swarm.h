// The swarm model: N independent 2D particles pulled by up to 8 attractors (the seed's law),
// one compute pass per integrator step. It owns one state SSBO updated in place, one particle
// per slot: fp32 {vec2 pos (NDC), vec2 vel (world units/s)} = 16 B, or fp16 {packHalf2x16(pos),
// packHalf2x16(vel)} = 8 B. Renderers read that buffer directly (state(), storage()).
//
//   Swarm swarm(shaders, params);   // allocates params.particles and scatters them (reset)
//   swarm.setAspect(16.0 / 9.0);    // world = ndc * (aspect, 1)
//   swarm.step(profiler);           // one frame: swarmSubsteps() steps of speed * frame_seconds, then the watch
//   swarm.stepOnce(1.0 / 120.0);    // or one integrator step of simulated time ...
//   swarm.watch();                  // ... and the divergence watch once per frame (non-blocking)
//
// Step: world x = pos * (aspect, 1); integrate (x, v) with forces evaluated at the right times
// (t, t + dt/2, t + dt); v *= exp(-friction dt); back to NDC; mirror at the walls if bouncing.
#pragma once

#include <optional>
#include <span>
#include <string>
#include <vector>

#include "gl/buffer.h"
#include "gl/gpu_profiler.h"
#include "gl/shader_library.h"
#include "sim/model.h"
#include "sim/swarm/attractors.h"
#include "sim/swarm/swarm_params.h"

namespace tidepool::sim {

struct SwarmParticle {  // the CPU view of one particle (fp16 storage is converted)
  glm::vec2 pos;        // NDC
  glm::vec2 vel;        // world units / s
};

std::size_t swarmBytesPerParticle(Storage storage);  // 16 or 8

// Throws Error (one line, before anything is allocated) when `count` particles cannot fit:
// more than GL_MAX_SHADER_STORAGE_BLOCK_SIZE, or more than the free memory where the driver says.
void checkSwarmFits(std::size_t count, Storage storage, std::size_t extraBytesPerParticle = 0);

class Swarm final : public Model {
 public:
  Swarm(gl::ShaderLibrary& shaders, const SwarmParams& params);

  SwarmParams& params() { return m_params; }  // read at the next step; count/storage at reset()
  const SwarmParams& params() const { return m_params; }

  // sim::Model. A frame is swarmSubsteps() steps of speed * params().frameSeconds in all.
  void reset() override;  // (re)allocates if needed, scatters uniformly, v = 0, t = 0
  void step(gl::GpuProfiler& profiler) override;
  double frameSeconds() const override { return swarmFrameSeconds(m_params); }
  double time() const override { return m_time; }         // simulated seconds since reset
  std::size_t count() const override { return m_count; }  // particles
  std::string status() const override;                    // count, storage, integrator, state size
  std::vector<sim::StateBuffer> stateBuffers() override;  // the state (pos, vel) per particle

  void stepOnce(double dt);                               // one integrator step of dt simulated seconds
  void step(double dt) { stepOnce(dt); }                  // the same (benchmarks and studies call it so)
  void upload(std::span<const SwarmParticle> particles);  // replaces the state (count = size), t = 0
  std::vector<SwarmParticle> download() const;            // reads back (tests, tools)

  void setAspect(double aspect) { m_aspect = aspect; }                           // image width / height
  void setMouse(std::optional<glm::dvec2> worldPos) { m_mouse = worldPos; }      // strength from params
  void setExtraAttractors(std::vector<Attractor> a) { m_extra = std::move(a); }  // fixed, after the preset's
  std::vector<Attractor> attractorsAt(double t) const;                           // preset(t) + extra + mouse, at most 8

  double aspect() const { return m_aspect; }
  Storage storage() const { return m_storage; }
  const gl::Buffer& state() const { return m_state; }
  std::size_t stateBytes() const { return m_count * swarmBytesPerParticle(m_storage); }

  // The divergence watch (sim::Model). watch() once per frame after stepOnce() calls (step()
  // calls it itself): a non-blocking check every 8 calls. recover() goes back to the last good
  // state with half the time step (twice the substeps, or half the speed at 64 substeps).
  using Model::watch;
  // World units/s: ten times the fastest a particle starting at rest anywhere in the box can
  // move in the static field of the attractors now (preset, extra and mouse at full strength):
  // sqrt(S·ln((D² + ε')/ε') + 2·g·2), S = Σ|s_k|, D = the box diagonal, ε' = max(ε, 10⁻⁶).
  double speedBound() const;

 private:
  // The divergence watch (sim::Model): NaN particles, speed above speedBound().
  void checkHealth(const gl::Window& w) override;
  std::optional<std::string> unhealthy(const DivergenceWatch::Words& words) override;
  std::string method() const override;
  void resume(const StateStamp& good) override;
  // Checkpoints: the clock, the aspect, the mouse and the extra attractors, the last dt.
  void visitOwnState(StateVisitor& v) override;

  void allocate(std::size_t count, Storage storage);
  const char* storageDefine() const { return m_storage == Storage::Fp16 ? "1" : "0"; }  // STORAGE_FP16

  gl::ShaderLibrary& m_shaders;
  SwarmParams m_params;
  gl::Buffer m_state;
  std::size_t m_count = 0;
  Storage m_storage = Storage::Fp32;
  double m_time = 0.0, m_aspect = 16.0 / 9.0;
  std::optional<glm::dvec2> m_mouse;
  std::vector<Attractor> m_extra;
  double m_lastDt = 0;
};

}  // namespace tidepool::sim
