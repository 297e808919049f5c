// A field for a double. On the page a finger or a keyboard types into it through the parallel
// DOM's <input> (app/ui/parallel_dom/), which types into this field as a person would.

#include <imgui.h>

#include "ui/panels/panels.h"

namespace swarmlab {

bool input_double(const char* label, double* value, const char* format) {
  ImGui::InputDouble(label, value, 0, 0, format);
  return committed();
}

}  // namespace swarmlab
