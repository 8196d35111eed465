// The one surface every model offers (balls, life, ripples, swarm), so that stages, benchmarks,
// studies and checkpoints treat models alike: a frame of stepping (how much simulated time a frame
// is comes from the model's own parameters, never from the caller), the clock and the size, a
// status line, the state buffers by name, and the divergence watch (sim/divergence.h), which
// this base owns and serves for every model.
//
//   model.step(profiler);   // one frame: model.frameSeconds() of simulated time, then the watch
//   if (model.divergence()) model.recover();
//
// A model implements the public virtuals below and, privately, what its watch needs
// (DivergenceWatch::Subject: its health kernel, the verdict on the words, its method, and how it
// resumes from a good state with half its time step); it calls watch() once per frame.
// Model-specific stepping stays on the model: stepOnce() is one step of the model's own kind.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "gl/gpu_profiler.h"
#include "sim/divergence.h"

namespace tidepool::sim {

class Model : private DivergenceWatch::Subject {
 public:
  virtual ~Model() = default;

  virtual void step(gl::GpuProfiler& profiler) = 0;      // one frame: substeps, then watch()
  virtual double frameSeconds() const = 0;               // simulated s one step() advances, from the parameters
  virtual void reset() = 0;                              // the initial state, t = 0
  virtual double time() const = 0;                       // simulated s since reset
  virtual std::size_t count() const = 0;                 // particles or cells
  virtual std::string status() const = 0;                // one line for the UI
  virtual std::uint64_t stepCount() const { return 0; }  // steps taken, where the model counts them
  using Subject::stateBuffers;  // the live state, named, with the bytes in use (renderers, checkpoints)

  // The divergence watch: a non-blocking check every 8 frames, a frame or two late.
  std::optional<DivergenceReport> divergence() const { return m_watch.report(); }
  // The last good state with half the time step: how many frames back it lies; nullopt if none.
  std::optional<std::uint64_t> recover() { return m_watch.recover(*this); }
  void flushChecks() { m_watch.flush(*this); }  // waits for the check in flight (end of a headless run)

  // Checkpoints (scene/checkpoint.h): everything a later step reads beyond the parameters — the
  // model's own state (visitOwnState: clock, counters, RNG, extra buffers), the watch's phase
  // and last good copy, then the stateBuffers(). Loading expects the model reset() at the checkpoint's parameters.
  // Saving first judges the state now and refuses a diverged one (Error), so that a periodic save
  // never replaces a good checkpoint with a blown-up state.
  void visitState(StateVisitor& v) {
    if (!v.loading())
      if (std::optional<std::string> bad = m_watch.checkNow(*this)) v.fail(std::string(m_name) + " state: " + *bad);
    visitOwnState(v);
    m_watch.visitState(v, *this);  // after the own state, which may resize the live buffers
    for (const StateBuffer& b : stateBuffers()) v.buffer((std::string("model.") + b.name).c_str(), *b.buffer, b.bytes);
  }

 protected:
  // `name` words the reports ("balls diverged by ..."); no copies of more than maxCopied elements.
  Model(gl::ShaderLibrary& shaders, const char* name, std::size_t maxCopied)
      : m_name(name), m_watch(shaders, name, maxCopied) {}
  void watch() { m_watch.frame(*this); }      // once per frame, after its steps
  void restartWatch() { m_watch.restart(); }  // a new state (reset, upload): nothing judged yet
  // The model's state besides its stateBuffers(): the clock first, then counts (checked against
  // the capacity) before anything sized by them. Loading may reallocate to the parameters' size.
  virtual void visitOwnState(StateVisitor& v) = 0;

 private:
  StateStamp stamp() const final { return {time(), count(), stepCount()}; }

  const char* m_name;
  DivergenceWatch m_watch;
};

}  // namespace tidepool::sim
