#include "ui/kit/theme_style.h"

namespace swarmlab {
namespace {

void set_colours(ImGuiStyle& style, const Palette& p, Theme theme) {
  if (theme == Theme::light)
    ImGui::StyleColorsLight(&style);
  else
    ImGui::StyleColorsDark(&style);
  ImVec4* c = style.Colors;
  auto set = [c](ImGuiCol slot, Colour colour) { c[slot] = colour_vec4(colour); };
  set(ImGuiCol_Text, p.text);
  set(ImGuiCol_TextDisabled, p.text_disabled);
  set(ImGuiCol_WindowBg, p.window);
  c[ImGuiCol_ChildBg] = ImVec4(0, 0, 0, 0);
  set(ImGuiCol_PopupBg, p.popup);
  set(ImGuiCol_Border, p.border);
  set(ImGuiCol_FrameBg, p.frame);
  set(ImGuiCol_FrameBgHovered, p.frame_hovered);
  set(ImGuiCol_FrameBgActive, p.frame_active);
  set(ImGuiCol_TitleBg, p.title);
  set(ImGuiCol_TitleBgCollapsed, p.title);
  set(ImGuiCol_TitleBgActive, p.title_active);
  set(ImGuiCol_MenuBarBg, p.menu_bar);
  set(ImGuiCol_ScrollbarBg, p.window);
  set(ImGuiCol_ScrollbarGrab, p.scrollbar_grab);
  set(ImGuiCol_ScrollbarGrabHovered, p.slider_grab);
  set(ImGuiCol_ScrollbarGrabActive, p.slider_grab);
  set(ImGuiCol_CheckMark, p.check_mark);
  set(ImGuiCol_SliderGrab, p.slider_grab);
  set(ImGuiCol_SliderGrabActive, p.check_mark);
  set(ImGuiCol_Button, p.button);
  set(ImGuiCol_ButtonHovered, p.button_hovered);
  set(ImGuiCol_ButtonActive, p.button_active);
  set(ImGuiCol_Header, p.header);
  set(ImGuiCol_HeaderHovered, p.header_hovered);
  set(ImGuiCol_HeaderActive, p.header_active);
  set(ImGuiCol_Separator, p.border);
  set(ImGuiCol_Tab, p.tab);
  set(ImGuiCol_TabHovered, p.tab_hovered);
  set(ImGuiCol_TabActive, p.tab_active);
  set(ImGuiCol_TabUnfocused, p.tab);
  set(ImGuiCol_TabUnfocusedActive, p.tab_active);
  set(ImGuiCol_TableHeaderBg, p.title);
  set(ImGuiCol_NavHighlight, p.nav_highlight);
  set(ImGuiCol_NavWindowingHighlight, p.nav_highlight);
  Colour selection = p.header_active;
  selection.a = 160;
  set(ImGuiCol_TextSelectedBg, selection);
}

}  // namespace

void apply_style(float scale, Theme theme) {
  ImGuiStyle style;
  set_colours(style, palette(theme), theme);
  style.WindowRounding = 4;
  style.FrameRounding = 3;
  style.GrabRounding = 3;
  style.TabRounding = 3;
  style.WindowBorderSize = 0;
  style.FramePadding = ImVec2(6, 4);
  style.ItemSpacing = ImVec2(8, 5);
  if (theme == Theme::light) {
    // On a washed-out projector, outlines keep fields and buttons apart from the page.
    style.WindowBorderSize = 1;
    style.FrameBorderSize = 1;
  }
  style.ScaleAllSizes(scale);
  ImGui::GetStyle() = style;
}

}  // namespace swarmlab
