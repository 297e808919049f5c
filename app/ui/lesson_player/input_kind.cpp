#include "ui/lesson_player/input_kind.h"

#include <imgui.h>

namespace swarmlab {

InputKind input_kind(const AppState& state) {
  if (state.layout.touch) return InputKind::touch;
  return ImGui::GetIO().NavVisible ? InputKind::keyboard : InputKind::mouse;
}

}  // namespace swarmlab
