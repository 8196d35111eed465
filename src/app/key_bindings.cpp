#include "app/key_bindings.h"

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

#include <array>

namespace tidepool {
namespace {

constexpr std::array kBindings = {
    KeyBinding{GLFW_KEY_ESCAPE, KeyAction::Quit, "Esc"},       // quit
    KeyBinding{GLFW_KEY_SPACE, KeyAction::Pause, "Space"},     // the original's pause
    KeyBinding{GLFW_KEY_PERIOD, KeyAction::StepOnce, "."},     // while paused
    KeyBinding{GLFW_KEY_R, KeyAction::Restart, "R"},           // the original's Restart
    KeyBinding{GLFW_KEY_F5, KeyAction::ReloadShaders, "F5"},   // hot reload
    KeyBinding{GLFW_KEY_F6, KeyAction::SaveCheckpoint, "F6"},  // checkpoint
    KeyBinding{GLFW_KEY_F11, KeyAction::Fullscreen, "F11"},    // fullscreen / windowed
    KeyBinding{GLFW_KEY_F12, KeyAction::Screenshot, "F12"},    // PNG of the window
    KeyBinding{GLFW_KEY_S, KeyAction::TogglePanel, "S"},       // the original's panel key
    KeyBinding{GLFW_KEY_H, KeyAction::TogglePanel, "H"},       // tidepool's, kept
    KeyBinding{GLFW_KEY_D, KeyAction::ToggleTimings, "D"},     // the original's debug panel
};

}  // namespace

std::span<const KeyBinding> keyBindings() { return kBindings; }

std::optional<KeyAction> appAction(int key) {
  for (const KeyBinding& b : kBindings)
    if (b.key == key) return b.action;
  return std::nullopt;
}

}  // namespace tidepool
