// Per-pass GPU times from GL_TIME_ELAPSED queries. Query results are read two frames late
// (three frame slots), so reading them never stalls the pipeline; if a slot's results are still
// not ready when it comes round again, that frame's times are dropped (counted in dropped()).
//
//   profiler.beginFrame();
//   { auto s = profiler.scope("grid.scan"); scan(); }   // GL timer queries cannot nest
//   profiler.endFrame();
//   for (const auto& p : profiler.passes()) printf("%s %.3f ms\n", p.name.c_str(), p.smoothedMs);
#pragma once

#include <array>
#include <deque>
#include <string>
#include <string_view>
#include <vector>

#include "gl/framebuffer.h"

namespace tidepool::gl {

class GpuProfiler {
 public:
  struct Pass {
    std::string name;
    double ms = 0;          // last completed frame
    double smoothedMs = 0;  // exponential moving average (for the UI)
  };
  struct FrameTimes {
    std::vector<std::pair<std::string, double>> passes;  // name, ms (in issue order)
  };

  class Scope {
   public:
    explicit Scope(GpuProfiler* p) : m_profiler(p) {}
    Scope(Scope&& o) noexcept : m_profiler(std::exchange(o.m_profiler, nullptr)) {}
    Scope(const Scope&) = delete;
    ~Scope();

   private:
    GpuProfiler* m_profiler;
  };

  void setEnabled(bool enabled) { m_enabled = enabled; }
  bool enabled() const { return m_enabled; }

  void beginFrame();  // harvests finished frames without waiting
  [[nodiscard]] Scope scope(std::string_view name);
  void endFrame();
  void finish();  // waits for every pending frame (benchmarks only)

  const std::vector<Pass>& passes() const { return m_passes; }
  double totalMs() const;  // sum of the last completed frame's passes
  double totalSmoothedMs() const;
  std::vector<FrameTimes> takeCompleted();  // completed frames since the last call (benchmarks)
  int dropped() const { return m_dropped; }

 private:
  struct Slot {
    std::vector<std::string> names;
    std::vector<Query> queries;  // pooled; names.size() of them are in use
    bool pending = false;
  };
  bool ready(const Slot& slot) const;
  void harvest(Slot& slot);
  void endScope();

  std::array<Slot, 3> m_slots;
  int m_current = 0;
  bool m_inFrame = false, m_inScope = false, m_enabled = true;
  int m_dropped = 0;
  std::vector<Pass> m_passes;
  std::deque<FrameTimes> m_completed;
};

}  // namespace tidepool::gl
