#pragma once
// Targets a finger can hit: in a touch or compact layout every frame (button, field, slider,
// a window's close button) is at least kTouchTargetPx tall (app.cpp sets the frame padding),
// target_width() makes a button with a short label at least as wide as it is tall, and
// same_line_if_fits() wraps a row rather than clip its last target. 44 CSS
// pixels: WCAG 2.2's 2.5.5 and the platforms' guides; ImGui's pixels in the browser are CSS
// pixels.

#include <imgui.h>

#include <algorithm>

namespace swarmlab {

inline constexpr float kTouchTargetPx = 44;

/// The width of a button labelled `label` (text after "##" hidden), at least its height.
inline float target_width(const char* label) {
  return std::max(
      ImGui::CalcTextSize(label, nullptr, true).x + 2 * ImGui::GetStyle().FramePadding.x,
      ImGui::GetFrameHeight());
}

/// The width of a radio button or checkbox labelled `label`: its box and its text.
inline float radio_width(const char* label) {
  return ImGui::GetFrameHeight() + ImGui::GetStyle().ItemInnerSpacing.x +
         ImGui::CalcTextSize(label, nullptr, true).x;
}

/// Continues the row when an item `width` wide still fits beside the last one, else starts the
/// next row: on a phone a row of buttons wraps instead of cutting off its end.
inline void same_line_if_fits(float width) {
  const float right = ImGui::GetWindowPos().x + ImGui::GetWindowContentRegionMax().x;
  if (ImGui::GetItemRectMax().x + ImGui::GetStyle().ItemSpacing.x + width <= right)
    ImGui::SameLine();
}

/// A radio button that goes to the next row when it would not fit beside the last item (the
/// rows of choices that a longer language, or a phone, makes too long).
inline bool wrapping_radio(const char* label, int* value, int choice) {
  same_line_if_fits(radio_width(label));
  return ImGui::RadioButton(label, value, choice);
}

/// The same for a checkbox.
inline bool wrapping_checkbox(const char* label, bool* value) {
  same_line_if_fits(radio_width(label));
  return ImGui::Checkbox(label, value);
}

}  // namespace swarmlab
