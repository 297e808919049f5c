#include <imgui.h>

#include "i18n/translator.h"
#include "ui/panels/panels.h"
#include "ui/panels/window_placement.h"
#include "ui/panels/windows.h"

namespace swarmlab {

void draw_view_strips(AppState& state, const ScreenLayout& layout) {
  AppState& s = state;
  const ScreenLayout& l = layout;
  const ImGuiWindowFlags strip = ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_NoMove |
                                 ImGuiWindowFlags_NoSavedSettings |
                                 ImGuiWindowFlags_NoFocusOnAppearing;
  place(l.transport);
  if (ImGui::Begin(tr_id("Transport###transport"), nullptr, strip)) draw_transport_bar(s);
  s.layout.transport_height = content_height();
  record_panel(s, "Transport");
  ImGui::End();
  if (l.readouts.shown()) {
    place(l.readouts);
    if (ImGui::Begin(tr_id("Read-outs###readouts"), nullptr, strip)) draw_readouts(s);
    s.layout.readouts_height = content_height();
    record_panel(s, "Read-outs");
    ImGui::End();
  }
}

}  // namespace swarmlab
