// The view panel: how the 3D view draws the system, and the size of the whole UI.

#include <imgui.h>

#include "ui/panels/panels.h"

namespace swarmlab {

void draw_view_panel(AppState& state) {
  ViewOptions& v = state.view;
  int colour = int(v.colour_by);
  ImGui::TextUnformatted("Colour by");
  ImGui::SameLine();
  ImGui::RadioButton("speed", &colour, int(ColourBy::speed));
  ImGui::SameLine();
  ImGui::RadioButton("mass", &colour, int(ColourBy::mass));
  ImGui::SameLine();
  ImGui::RadioButton("energy", &colour, int(ColourBy::energy));
  if (colour != int(v.colour_by)) {
    v.colour_by = ColourBy(colour);
    state.colour_scale = ColourScale{};
  }
  ImGui::Checkbox("lock colour scale", &state.colour_scale.locked);
  help_marker(
      "Keep the colour scale's ends where they are, so that a colour means one value for the "
      "whole run (it never rescales while paused). Choosing another quantity unlocks it.");
  ImGui::SameLine();
  ImGui::Checkbox("reframe when it flies apart", &v.auto_reframe);
  help_marker(
      "Back the camera away when an isolated run grows past the view (Euler, J < 0), so that "
      "the particles stay in sight.");
  ImGui::SetNextItemWidth(0.5f * ImGui::GetContentRegionAvail().x);
  ImGui::SliderFloat("particle size", &v.particle_size, 0.1f, 5.0f, "x %.2f",
                     ImGuiSliderFlags_Logarithmic);
  help_marker("The radius grows as the cube root of the mass (spheres of equal density).");

  ImGui::Checkbox("container", &v.container);
  ImGui::SameLine();
  ImGui::Checkbox("centre of mass", &v.centre_of_mass);
  ImGui::SameLine();
  ImGui::Checkbox("axes", &v.axes);
  ImGui::Checkbox("trails", &v.trails);
  help_marker(
      "Every particle of a system of up to 20 leaves a trail; in a larger swarm, the "
      "selected one (click a particle).");
  ImGui::SameLine();
  ImGui::Checkbox("orbit ahead", &v.orbit);
  help_marker(
      "The analytic orbit of the selected particle about the moving centre of mass, "
      "from now on: r(t) = R(t) + x cos(wt) + (u / w) sin(wt). In a container it holds "
      "until the particle's next wall hit.");
  ImGui::SameLine();
  ImGui::Checkbox("ghosts", &v.ghosts);
  help_marker(
      "Hollow rings at the positions of the exact solution, when a numerical method "
      "runs side by side with 'analytic'.");
  if (ImGui::Checkbox("follow the centre of mass", &v.follow_cm)) state.reframe = true;

  int springs = int(v.springs);
  ImGui::TextUnformatted("Springs");
  ImGui::SameLine();
  ImGui::RadioButton("off", &springs, int(SpringOverlay::off));
  ImGui::SameLine();
  ImGui::RadioButton("every pair", &springs, int(SpringOverlay::pairs));
  ImGui::SameLine();
  ImGui::RadioButton("to CM", &springs, int(SpringOverlay::to_cm));
  v.springs = SpringOverlay(springs);
  help_marker(
      "The paper's Fig. 1 (up to 30 particles). Left: a spring k_ij = J m_i m_j between "
      "every pair. Right: the same forces as one spring k_i = J M m_i from each particle "
      "to the centre of mass. Line width is proportional to k; red: J < 0 (the springs "
      "push).");

  ImGui::Separator();
  ImGui::SetNextItemWidth(0.5f * ImGui::GetContentRegionAvail().x);
  ImGui::SliderFloat("UI scale", &state.layout.pending_ui_scale, Layout::kMinUiScale,
                     Layout::kMaxUiScale, "%.2f");
  help_marker("Larger text and controls for a projector (Ctrl + and Ctrl -).");
  if (ImGui::Button("Reframe camera")) state.reframe = true;
}

}  // namespace swarmlab
