#include "viewer/key_bindings.hpp"

#include <GLFW/glfw3.h>

namespace penumbra {

const std::array<KeyBinding, 13> kKeyBindings{{
    {GLFW_KEY_T, false, KeyAction::NextTechnique, "T, Right", "next technique"},
    {GLFW_KEY_RIGHT, false, KeyAction::NextTechnique, "", ""},
    {GLFW_KEY_T, true, KeyAction::PreviousTechnique, "Shift+T, Left", "previous technique"},
    {GLFW_KEY_LEFT, false, KeyAction::PreviousTechnique, "", ""},
    {GLFW_KEY_V, false, KeyAction::NextView, "V, Down", "next display mode"},
    {GLFW_KEY_DOWN, false, KeyAction::NextView, "", ""},
    {GLFW_KEY_V, true, KeyAction::PreviousView, "Shift+V, Up", "previous display mode"},
    {GLFW_KEY_UP, false, KeyAction::PreviousView, "", ""},
    {GLFW_KEY_P, false, KeyAction::Screenshot, "P", "screenshot (PNG in the current folder)"},
    {GLFW_KEY_C, false, KeyAction::CopyCommand, "C", "copy the 'penumbra render' command"},
    {GLFW_KEY_R, false, KeyAction::Reset, "R", "reset the camera and the lights"},
    {GLFW_KEY_H, false, KeyAction::TogglePanel, "H", "hide or show the panel"},
    {GLFW_KEY_ESCAPE, false, KeyAction::Quit, "Esc", "quit"},
}};

std::optional<KeyAction> action_for_key(int key, int mods) {
  const bool shift = (mods & GLFW_MOD_SHIFT) != 0;
  for (const KeyBinding& b : kKeyBindings) {
    if (b.key == key && b.shift == shift) return b.action;
  }
  return std::nullopt;
}

}  // namespace penumbra
