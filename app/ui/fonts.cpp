#include "fonts.h"

#include <imgui.h>

#include <cstddef>

extern const unsigned char dejavu_sans_ttf[];
extern const std::size_t dejavu_sans_ttf_size;

namespace swarmlab {
namespace {

void set_style(float scale) {
  ImGuiStyle style;
  ImGui::StyleColorsDark(&style);
  style.WindowRounding = 4;
  style.FrameRounding = 3;
  style.GrabRounding = 3;
  style.TabRounding = 3;
  style.WindowBorderSize = 0;
  style.FramePadding = ImVec2(6, 4);
  style.ItemSpacing = ImVec2(8, 5);
  ImVec4* c = style.Colors;
  c[ImGuiCol_WindowBg] = ImVec4(0.09f, 0.10f, 0.13f, 0.97f);
  c[ImGuiCol_ChildBg] = ImVec4(0.0f, 0.0f, 0.0f, 0.0f);
  c[ImGuiCol_Header] = ImVec4(0.20f, 0.32f, 0.48f, 0.75f);
  c[ImGuiCol_HeaderHovered] = ImVec4(0.26f, 0.42f, 0.62f, 0.85f);
  c[ImGuiCol_FrameBg] = ImVec4(0.16f, 0.18f, 0.24f, 1.0f);
  c[ImGuiCol_MenuBarBg] = ImVec4(0.12f, 0.13f, 0.17f, 1.0f);
  style.ScaleAllSizes(scale);
  ImGui::GetStyle() = style;
}

}  // namespace

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
  set_style(scale);
}

}  // namespace swarmlab
