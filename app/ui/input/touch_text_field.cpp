// Typing a number with fingers: a canvas cannot bring up a phone's on-screen keyboard, so the
// number field being edited is reported (where it is, its text) for the browser to place an
// HTML <input inputmode="decimal"> over it; what is typed there comes back as typed_text and
// is committed to the field like an Enter.

#include <imgui.h>
#include <imgui_internal.h>

#include <cstdio>
#include <cstdlib>

#include "ui/panels/panels.h"

namespace swarmlab {
namespace {

AppState* text_field_state = nullptr;

}  // namespace

void set_text_field_state(AppState* state) {
  text_field_state = state;
  if (state) state->layout.text_field.active = false;
}

bool input_double(const char* label, double* value, const char* format) {
  AppState* s = text_field_state;
  const ImGuiID id = ImGui::GetID(label);
  bool typed = false;
  if (s && s->layout.typed_text && ImGui::GetActiveID() == id) {
    // The whole number, or nothing: "1.2x" leaves the field as it was.
    const char* text = s->layout.typed_text->c_str();
    char* end = nullptr;
    const double v = std::strtod(text, &end);
    if (end != text && *end == '\0') *value = v, typed = true;
    s->layout.typed_text.reset();
    ImGui::ClearActiveID();
  }
  ImGui::InputDouble(label, value, 0, 0, format);
  if (s && ImGui::IsItemActive()) {
    const ImVec2 lo = ImGui::GetItemRectMin(), hi = ImGui::GetItemRectMax();
    char text[64];
    std::snprintf(text, sizeof text, format, *value);
    s->layout.text_field = {true, {lo.x, lo.y, hi.x - lo.x, hi.y - lo.y}, text};
  }
  return typed || committed();
}

}  // namespace swarmlab
