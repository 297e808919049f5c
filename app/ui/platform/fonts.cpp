#include "ui/platform/fonts.h"

#include <imgui.h>

#include <cstddef>
#include <string>
#include <string_view>

#include "i18n/translator.h"
#include "ui/kit/theme_style.h"
#include "ui/platform/cjk_font.h"
#include "ui/platform/font_file_check.h"

extern const unsigned char dejavu_sans_ttf[];
extern const std::size_t dejavu_sans_ttf_size;
extern const unsigned char noto_sans_sc_names_otf[];
extern const std::size_t noto_sans_sc_names_otf_size;

namespace swarmlab {
namespace {

/// Builds the atlas anew: DejaVu Sans with the Chinese glyphs of `cjk` merged in. False when
/// stb_truetype (ImGui 1.86's font builder here; FreeType is not built in) refused a font.
bool build_atlas(float scale, std::string_view cjk) {
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
  // Chinese glyphs merged into the same font, where DejaVu has none. The full CJK ranges cost
  // nothing extra: only the glyphs a subset holds are drawn into the atlas.
  ImFontConfig merge;
  merge.MergeMode = true;
  merge.FontDataOwnedByAtlas = false;
  io.Fonts->AddFontFromMemoryTTF(const_cast<char*>(cjk.data()), int(cjk.size()), 16.0f * scale,
                                 &merge, io.Fonts->GetGlyphRangesChineseFull());
  return io.Fonts->Build();
}

}  // namespace

void apply_ui_scale(float scale, Theme theme) {
  // The glyphs of the languages' names, built in; the whole subset for Chinese.
  const std::string_view names(reinterpret_cast<const char*>(noto_sans_sc_names_otf),
                               noto_sans_sc_names_otf_size);
  const std::string_view cjk = translator().language().needs_cjk_font ? cjk_font() : "";
  if (translator().language().needs_cjk_font && cjk.empty())
    request_cjk_font();  // the atlas is built again when it arrives
  if (!cjk.empty()) {
    // The page fetched it: it reaches stb_truetype, which trusts every offset in it, only
    // checked; refused there all the same, the atlas is built again with the fonts it had.
    std::string problem = font_file_problem(cjk);
    if (problem.empty() && !build_atlas(scale, cjk))
      problem = "stb_truetype could not read the font";
    if (problem.empty()) {
      apply_style(scale, theme);
      return;
    }
    refuse_cjk_font(problem);
  }
  build_atlas(scale, names);
  apply_style(scale, theme);
}

}  // namespace swarmlab
