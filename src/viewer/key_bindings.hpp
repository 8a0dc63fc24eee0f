#pragma once
// The viewer's keys: one table, read by the key handler and the panel's
// help alike.
#include <array>
#include <optional>
#include <string_view>

namespace penumbra {

enum class KeyAction {
  NextTechnique,
  PreviousTechnique,
  NextView,
  PreviousView,
  Screenshot,
  CopyCommand,
  Reset,
  TogglePanel,
  Quit,
};

struct KeyBinding {
  int key;     // GLFW_KEY_*
  bool shift;  // with shift held
  KeyAction action;
  std::string_view keys;  // as the help shows it
  std::string_view what;
};

extern const std::array<KeyBinding, 13> kKeyBindings;

// The action of a key pressed with modifiers `mods` (GLFW_MOD_*).
std::optional<KeyAction> action_for_key(int key, int mods);

}  // namespace penumbra
