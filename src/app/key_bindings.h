// The window's keys in one table: what each app key does, for the loop, the tests and the README.
// Letters the table does not name go to the stage (Stage::key: life C, N, W; water M).
// As the original apps: S hides / shows the panels (H too), D the timings, Space pauses.
#pragma once

#include <optional>
#include <span>

namespace tidepool {

enum class KeyAction {
  Quit,            // Esc
  Pause,           // Space
  StepOnce,        // .
  Restart,         // R: the scene again (life: new random positions, same rules)
  ReloadShaders,   // F5
  SaveCheckpoint,  // F6
  Fullscreen,      // F11
  Screenshot,      // F12
  TogglePanel,     // S (and H): hide / show the panels
  ToggleTimings,   // D: hide / show the timings (FPS, steps/s, GPU passes)
};

struct KeyBinding {
  int key;  // GLFW key code
  KeyAction action;
  const char* name;  // as the README and the panel's buttons say it
};

std::span<const KeyBinding> keyBindings();    // every app key, in the order the README lists them
std::optional<KeyAction> appAction(int key);  // the app's action for a GLFW key; none: the stage's

}  // namespace tidepool
