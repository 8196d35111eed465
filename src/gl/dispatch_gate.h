// Passes that run only when the GPU says so, without the CPU waiting to read its answer: a
// section of dispatches is recorded once (run directly, each dispatch's group counts noted), and
// later replayed through glDispatchComputeIndirect from an arguments buffer that a kernel of the
// caller's fills — the recorded counts when the section should run, zeros when it should not.
//
//   gate.record([&] { grid.build(pos, n); buildLists(); });  // runs, notes N dispatches
//   decide kernel: gateArgs(open) writes args = open ? recorded : 0   (common/dispatch_gate.glsl)
//   gate.replay([&] { grid.build(pos, n); buildLists(); });  // the same N dispatches, indirect
//
// The replayed section must issue the same dispatches as the recorded one (same sizes: the
// counts are not re-derived); a replay that differs throws Error, and record() again makes a new
// template. Only dispatches are gated: a section must hold no other GL command that changes data
// (uploads, copies, clears), or those would run every time.
#pragma once

#include <functional>
#include <glm/glm.hpp>
#include <vector>

#include "gl/buffer.h"

namespace tidepool::gl {

class DispatchGate {
 public:
  void record(const std::function<void()>& section);  // runs it, notes its dispatches, uploads them
  void note(const std::function<void()>& section);    // notes them without running it (a restore)
  void replay(const std::function<void()>& section);  // runs it through the arguments buffer
  bool recorded() const { return !m_template.empty(); }
  void forget() { m_template.clear(); }
  std::size_t dispatches() const { return m_template.size(); }
  // What the deciding kernel reads and writes (common/dispatch_gate.glsl): the recorded group
  // counts (uvec4 each: x, y, z, 0) and the indirect arguments (three uints each).
  const Buffer& recordedGroups() const { return m_groups; }
  Buffer& arguments() { return m_args; }

  // Program's dispatch: directly, or noted / replayed when a section is active on this thread.
  static void dispatch(glm::uvec3 groups);

 private:
  enum class Mode { Record, Note, Replay };
  void run(Mode mode, const std::function<void()>& section);
  void keep();  // the noted dispatches as the template
  void onDispatch(glm::uvec3 groups);

  std::vector<glm::uvec3> m_template, m_seen;
  Buffer m_groups, m_args;
  Mode m_mode = Mode::Record;
};

}  // namespace tidepool::gl
