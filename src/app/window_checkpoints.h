// The window's checkpoints: F6 saves one, and an autosave period (simulated seconds, 0: off; the
// panel edits it) saves one whenever the run passes a multiple of it. The window only asks after
// each frame; this is the logic, tested without a window.
#pragma once

#include <filesystem>
#include <optional>
#include <string>

#include "scene/checkpoint.h"

namespace tidepool {

class WindowCheckpoints {
 public:
  struct Saved {
    std::string message;  // for the panel: "saved ..." or why not
    bool error = false;
  };

  // `file` empty: "<scene name>.ckpt" in the working folder.
  WindowCheckpoints(const Scene& scene, std::filesystem::path file, double autosaveEvery, double time);

  // After a frame, `frame` as render numbers it (steps since t = 0): saves when `requested` (F6) or
  // when the autosave is due. A failure (a diverged state, a full disk) is a message, never an
  // exception: the window runs on.
  std::optional<Saved> afterFrame(Stage& stage, std::uint64_t frame, bool requested);
  float& autosaveEvery() { return m_every; }  // the panel's field; a change starts a new period now
  const std::filesystem::path& file() const { return m_file; }

 private:
  const Scene& m_scene;
  std::filesystem::path m_file;
  float m_every = 0;
  CheckpointSchedule m_schedule;
};

}  // namespace tidepool
