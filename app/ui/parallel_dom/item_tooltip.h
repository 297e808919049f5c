// The tooltip of the item just drawn: shown while the pointer rests on it, and said by the
// parallel DOM at all times (the item's description, or its name where its label is an icon).
// One call instead of `if (ImGui::IsItemHovered()) ImGui::SetTooltip(...)`, so that what a
// mouse user reads on hover a screen reader and a finger can reach too.
#pragma once

#include <imgui.h>

#include <string_view>

namespace swarmlab {

void item_tooltip(const char* format, ...) IM_FMTARGS(1);

/// The description of the item just drawn, where its tooltip is drawn apart from it (the
/// welcome shows a lesson's summary on hover over its title, beside its Start button).
void describe_item(std::string_view description);

/// The name of the item just drawn where it shows none (a field in a table cell, whose column
/// header is its label on screen): "r x of particle 2".
void name_item(std::string_view name);

}  // namespace swarmlab
