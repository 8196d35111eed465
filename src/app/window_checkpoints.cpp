#include "app/window_checkpoints.h"

#include <cstdio>

#include "base/log.h"

namespace tidepool {

WindowCheckpoints::WindowCheckpoints(const Scene& scene, std::filesystem::path file, double autosaveEvery, double time)
    : m_scene(scene),
      m_file(file.empty() ? defaultCheckpointPath({}, {}, scene.file) : std::move(file)),
      m_every(float(autosaveEvery)),
      m_schedule(autosaveEvery, time) {}

std::optional<WindowCheckpoints::Saved> WindowCheckpoints::afterFrame(Stage& stage, std::uint64_t frame,
                                                                      bool requested) {
  const double now = stage.simTime();
  if (double(m_every) != m_schedule.every()) m_schedule.reset(m_every, now);
  const bool due = m_schedule.due(now);
  if (!requested && !due) return std::nullopt;
  try {
    saveCheckpoint(stage, m_scene, m_file, frame);
    char what[64];
    std::snprintf(what, sizeof what, " at t = %.3f s", now);
    Saved s{std::string(due && !requested ? "autosaved " : "saved ") + m_file.string() + what, false};
    log::info(s.message);
    return s;
  } catch (const Error& e) {
    log::error(e.what());
    return Saved{e.what(), true};
  }
}

}  // namespace tidepool
