// The view panel: how the 3D view draws the system, and the size of the whole UI.

#include <imgui.h>

#include "i18n/translator.h"
#include "ui/kit/touch_target.h"
#include "ui/panels/panels.h"

namespace swarmlab {

void draw_view_panel(AppState& state) {
  ViewOptions& v = state.view;
  int colour = int(v.colour_by);
  ImGui::TextUnformatted(tr("Colour by"));
  wrapping_radio(tr_id("speed"), &colour, int(ColourBy::speed));
  wrapping_radio(tr_id("mass"), &colour, int(ColourBy::mass));
  wrapping_radio(tr_id("energy"), &colour, int(ColourBy::energy));
  if (colour != int(v.colour_by)) {
    v.colour_by = ColourBy(colour);
    state.colour_scale = ColourScale{};
  }
  ImGui::Checkbox(tr_id("lock colour scale"), &state.colour_scale.locked);
  help_marker(
      tr("Keep the colour scale's ends where they are, so that a colour means one value for the "
         "whole run (it never rescales while paused). Choosing another quantity unlocks it."));
  wrapping_checkbox(tr_id("reframe when it flies apart"), &v.auto_reframe);
  help_marker(
      tr("Back the camera away when an isolated run grows past the view (Euler, J < 0), so that "
         "the particles stay in sight."));
  ImGui::SetNextItemWidth(0.5f * ImGui::GetContentRegionAvail().x);
  ImGui::SliderFloat(tr_id("particle size"), &v.particle_size, 0.1f, 5.0f, "x %.2f",
                     ImGuiSliderFlags_Logarithmic);
  help_marker(tr("The radius grows as the cube root of the mass (spheres of equal density)."));

  ImGui::Checkbox(tr_id("container"), &v.container);
  wrapping_checkbox(tr_id("centre of mass"), &v.centre_of_mass);
  wrapping_checkbox(tr_id("axes"), &v.axes);
  ImGui::Checkbox(tr_id("trails"), &v.trails);
  help_marker(
      tr("Every particle of a system of up to 20 leaves a trail; in a larger swarm, the "
         "selected one (click a particle)."));
  wrapping_checkbox(tr_id("orbit ahead"), &v.orbit);
  help_marker(
      tr("The analytic orbit of the selected particle about the moving centre of mass, "
         "from now on: r(t) = R(t) + x cos(wt) + (u / w) sin(wt). In a container it holds "
         "until the particle's next wall hit."));
  wrapping_checkbox(tr_id("ghosts"), &v.ghosts);
  help_marker(
      tr("Hollow rings at the positions of the exact solution, when a numerical method "
         "runs side by side with 'analytic'."));
  if (ImGui::Checkbox(tr_id("follow the centre of mass"), &v.follow_cm)) state.reframe = true;

  int springs = int(v.springs);
  ImGui::TextUnformatted(tr("Springs"));
  wrapping_radio(tr_id("off"), &springs, int(SpringOverlay::off));
  wrapping_radio(tr_id("every pair"), &springs, int(SpringOverlay::pairs));
  wrapping_radio(tr_id("to CM"), &springs, int(SpringOverlay::to_cm));
  v.springs = SpringOverlay(springs);
  help_marker(
      tr("The paper's Fig. 1 (up to 30 particles). Left: a spring k_ij = J m_i m_j between "
         "every pair. Right: the same forces as one spring k_i = J M m_i from each particle "
         "to the centre of mass. Line width is proportional to k; red: J < 0 (the springs "
         "push)."));

  ImGui::Separator();
  ImGui::SetNextItemWidth(0.5f * ImGui::GetContentRegionAvail().x);
  ImGui::SliderFloat(tr_id("UI scale"), &state.layout.pending_ui_scale, Layout::kMinUiScale,
                     Layout::kMaxUiScale, "%.2f");
  help_marker(tr("Larger text and controls for a projector (Ctrl + and Ctrl -)."));
  if (ImGui::Button(tr_id("Reframe camera"))) state.reframe = true;
}

}  // namespace swarmlab
