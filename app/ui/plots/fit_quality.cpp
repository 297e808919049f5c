#include "ui/plots/fit_quality.h"

#include <imgui.h>

#include <cstdio>

#include "i18n/translator.h"
#include "ui/kit/theme_style.h"
#include "ui/parallel_dom/item_tooltip.h"
#include "ui/plots/plot_widget.h"
#include "ui/state/app_state.h"

namespace swarmlab {

void draw_fit_quality(const char* id, const std::vector<double>& x, const swarm::PowerLawFit& fit,
                      bool log_x, float height, AppState& state) {
  if (!fit.valid) return;
  const swarm::PowerLawAdequacy judged = swarm::judge_power_law(fit);
  static std::vector<double> used_x;
  used_x.clear();
  for (int i : fit.used) used_x.push_back(x[std::size_t(i)]);

  PlotSpec r;
  r.title = tr("Residuals");
  r.file_title = "Residuals";
  r.x = {"", log_x, std::nullopt, std::nullopt};
  r.y = {tr("ln y \u2212 fit"), false, std::nullopt, std::nullopt};
  r.y_from_zero = true;  // the zero line is in view: a wave or a trend about it shows
  r.series = {{tr("residual"), &used_x, &fit.residuals,
               palette(state.presentation.theme).residual.packed(), true, 2.0f}};
  draw_plot(id, r, height, state);

  char line[256];
  std::snprintf(line, sizeof line, tr("R\u00b2 = %.4f   Durbin-Watson = %.2f   (%zu stages)"),
                fit.r_squared, judged.durbin_watson, fit.used.size());
  ImGui::TextUnformatted(translator().numbers(line).c_str());
  item_tooltip("%s", tr(
        "R\u00b2: the share of the variance of ln y the line explains. Durbin-Watson: about 2 "
        "when the residuals scatter at random, near 0 when neighbours share their sign (a wave "
        "or a trend the power law does not follow)."));
  if (judged.poor()) {
    ImGui::PushStyleColor(ImGuiCol_Text,
                          colour_vec4(palette(state.presentation.theme).text_warning));
    ImGui::TextWrapped("%s",
                       judged.systematic
                           ? tr("The residuals wave or trend: a power law does not describe "
                                "these stages, whatever the exponent (paper, Appendix C).")
                           : tr("The stages scatter far from any line (R\u00b2 < 0.9): the "
                                "exponent means little."));
    ImGui::PopStyleColor();
  }
}

}  // namespace swarmlab
