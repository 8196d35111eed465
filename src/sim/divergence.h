// Watching a simulation for divergence without stalling the GPU: one component serves every
// model. Every few frames the model's health kernel reduces its state to four words on the GPU
// (shaders/common/health.glsl: NaN count, largest magnitude, a flagged count) and the watch
// copies the state buffers as they are at that moment ("pending"). The words come back one to two
// frames later through an AsyncReadback and are judged: a healthy verdict promotes the pending
// copies to "last good state"; a failed one becomes a report, and recover() puts the good copies
// back so that the model resumes, with half its time step, exactly where it was judged good.
//
//   frame k:      reduce + copy (pending, t_k)     frame k+1/k+2: words back -> judged
//     healthy:    good = pending (t_k)             failed: report "... by t = t_k ..."
//     recover():  good copies -> the state buffers, the model takes t_k and halves its dt
//
// A model supplies only what it checks and how it words a failure (Subject): its state buffers,
// its health kernel, the verdict on the words, its method; sim::Model (sim/model.h) wires it up.
#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "common/health_layout.glsl"
#include "gl/async_readback.h"
#include "gl/buffer.h"
#include "gl/buffer_ops.h"
#include "gl/kernel.h"
#include "gl/shader_library.h"
#include "gl/window.h"
#include "sim/model_state.h"

namespace tidepool {

struct DivergenceReport {
  std::string message;  // what failed, with method and time step, and what to do
  double time = 0;      // simulated seconds of the failed check
};

// The report of a failed check, worded alike for every model:
//   "<model> diverged by t = <time> s: <what> (<method>); halve the time step and resume from the
//   last good state" (or "... and reset" when no good state was kept).
DivergenceReport divergenceReport(const std::string& model, double time, const std::string& what,
                                  const std::string& method, bool hasGood);

namespace sim {

// One buffer of a model's state, by name: what a renderer reads, a check copies, a checkpoint saves.
struct StateBuffer {
  const char* name;    // "positions", "velocities", "state"
  gl::Buffer* buffer;  // the live buffer (of double-buffered state: the current one)
  std::size_t bytes;   // in use, from the start (the buffer may hold spare capacity)
};

// The uniforms of common/health.glsl: the elements [first, count) of the window checked.
struct HealthUniforms {
  GLuint first = 0, count = 0;
  HealthUniforms() = default;
  explicit HealthUniforms(const gl::Window& w) : first(GLuint(w.first)), count(GLuint(w.end())) {}
  static constexpr auto fields() {
    return std::tuple{gl::field("uFirst", &HealthUniforms::first), gl::field("uCount", &HealthUniforms::count)};
  }
};

// The scalars that go with a copy of the state buffers.
struct StateStamp {
  double time = 0;          // simulated s
  std::size_t count = 0;    // particles or cells (what the health kernel checks)
  std::uint64_t steps = 0;  // steps taken, for models that count them
};

class DivergenceWatch {
 public:
  using Words = std::array<std::uint32_t, 4>;  // indexed by HEALTH_* (common/health_layout.glsl)
  // Reading the words: "<n> <elements> are NaN or infinite" (nullopt when none are), the largest
  // watched magnitude (a speed, a height), the count the model flags.
  static std::optional<std::string> nonFinite(const Words& words, const char* elements);
  static float largest(const Words& words);
  static std::uint32_t flagged(const Words& words);
  // The verdict of particle water (balls, fluid): NaN particles, particles flagged outside the
  // walls, or a speed above `bound` m/s ("a <one> moves at 3.1 m/s, more than <limit> (2 m/s)").
  static std::optional<std::string> particles(const Words& words, const char* many, const char* one, const char* limit,
                                              double bound);

  // What a model supplies to its watch.
  class Subject {
   public:
    virtual StateStamp stamp() const = 0;                 // now
    virtual std::vector<StateBuffer> stateBuffers() = 0;  // what a check copies and recovery restores
    // Runs its health.comp over the elements of window w: binds that window of its state and
    // dispatches one invocation per element, HealthUniforms{w} among its uniforms (the watch has
    // bound the words at HEALTH_BINDING).
    virtual void checkHealth(const gl::Window& w) = 0;
    // State larger than one storage block is checked a window at a time (gl/window.h): these
    // windows. By default all of it at once.
    virtual std::vector<gl::Window> healthWindows(std::size_t count) const { return {{0, count}}; }
    virtual std::optional<std::string> unhealthy(const Words& words) = 0;  // what failed; nullopt: healthy
    virtual std::string method() const = 0;                                // method and time step, for a report
    virtual void resume(const StateStamp& good) = 0;  // after the copies are back: its clock, half its dt

   protected:
    ~Subject() = default;
  };

  // No copies of more than `maxCopied` elements (a blow-up is still reported, recovery refused).
  DivergenceWatch(gl::ShaderLibrary& shaders, std::string model, std::size_t maxCopied, int interval = 8);

  void frame(Subject& s);  // once per frame, after its steps: judges a check that came back, starts one when due
  void flush(Subject& s);  // waits for the check in flight and judges it (end of a headless run, tests)
  // Back to the last good state (see above): how many frames back it lies; nullopt if nothing
  // failed or none was kept.
  std::optional<std::uint64_t> recover(Subject& s);
  void restart();  // a new state (reset, upload): forgets the check in flight, the good state, the report
  const std::optional<DivergenceReport>& report() const { return m_report; }
  // The verdict on the state as it is now, waiting for it (a checkpoint refuses a diverged state).
  std::optional<std::string> checkNow(Subject& s);
  // Checkpoints: the frame phase of the checks, the report and the last good copy with its stamp
  // (each buffer at most the size of `s`'s live one). Loading has nothing in flight: the next
  // check starts when the saved phase says, and a failure before it recovers to the saved copy.
  void visitState(StateVisitor& v, Subject& s);

 private:
  // The state buffers copied at one check, and their stamp.
  struct Copy {
    std::vector<gl::Buffer> buffers;
    std::vector<std::size_t> bytes;  // copied into each
    StateStamp stamp;
    std::uint64_t frames = 0;  // frames since it was copied
    bool kept = false;         // false: too large to copy
  };
  void start(Subject& s, const StateStamp& now);
  void reduce(Subject& s, std::size_t count, gl::Buffer& words);  // the health kernel into `words`
  void judge(Subject& s, const Words& words);
  void dropCheck();  // waits out the check in flight without judging it; counts frames from 0

  gl::BufferOps m_ops;
  std::string m_model;
  std::size_t m_maxCopied;
  int m_interval;
  int m_frames = 0;
  gl::Buffer m_health, m_healthNow;  // HEALTH_WORDS words: of the check in flight, of checkNow()
  gl::AsyncReadback m_readback;
  Copy m_pending, m_good;
  bool m_hasGood = false;
  std::optional<DivergenceReport> m_report;
};

}  // namespace sim
}  // namespace tidepool
