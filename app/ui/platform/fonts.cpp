#include "ui/platform/fonts.h"

#include <imgui.h>

#include <cstddef>

#include "ui/classroom/theme_style.h"

extern const unsigned char dejavu_sans_ttf[];
extern const std::size_t dejavu_sans_ttf_size;

namespace swarmlab {

void apply_ui_scale(float scale) {
  ImGuiIO& io = ImGui::GetIO();
  io.Fonts->Clear();
  // Latin-1, Greek and the mathematical signs of the read-outs (omega, square root, minus,
  // superscripts, arrows, the play and pause symbols).
  static const ImWchar ranges[] = {0x0020, 0x00FF, 0x0370, 0x03FF, 0x2000, 0x206F,
                                   0x2070, 0x209F, 0x2190, 0x21FF, 0x2200, 0x22FF,
                                   0x1D00, 0x1D7F, 0x25A0, 0x25FF, 0};
  ImFontConfig config;
  config.FontDataOwnedByAtlas = false;  // the bytes live in the binary
  config.OversampleH = 2;
  io.Fonts->AddFontFromMemoryTTF(const_cast<unsigned char*>(dejavu_sans_ttf),
                                 int(dejavu_sans_ttf_size), 16.0f * scale, &config, ranges);
  io.Fonts->Build();
  apply_style(scale);
}

}  // namespace swarmlab
