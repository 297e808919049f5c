#include "ui/platform/fonts.h"

#include <imgui.h>

#include <cstddef>
#include <string_view>

#include "i18n/translator.h"
#include "ui/classroom/theme_style.h"
#include "ui/platform/cjk_font.h"

extern const unsigned char dejavu_sans_ttf[];
extern const std::size_t dejavu_sans_ttf_size;
extern const unsigned char noto_sans_sc_names_otf[];
extern const std::size_t noto_sans_sc_names_otf_size;

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
  // Chinese glyphs merged into the same font, where DejaVu has none: the whole subset for
  // Chinese, else the few of the languages' names. The full CJK ranges cost nothing extra:
  // only the glyphs a subset holds are drawn into the atlas.
  std::string_view cjk(reinterpret_cast<const char*>(noto_sans_sc_names_otf),
                       noto_sans_sc_names_otf_size);
  if (translator().language().needs_cjk_font) {
    if (cjk_font().empty())
      request_cjk_font();  // the atlas is built again when it arrives
    else
      cjk = cjk_font();
  }
  ImFontConfig merge;
  merge.MergeMode = true;
  merge.FontDataOwnedByAtlas = false;
  io.Fonts->AddFontFromMemoryTTF(const_cast<char*>(cjk.data()), int(cjk.size()), 16.0f * scale,
                                 &merge, io.Fonts->GetGlyphRangesChineseFull());
  io.Fonts->Build();
  apply_style(scale);
}

}  // namespace swarmlab
