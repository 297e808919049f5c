// The C side of web/parallel_dom.js: the items the front end drew in the last frame, as JSON,
// and what the page's mirrored elements ask of them (app/ui/parallel_dom/parallel_dom.h).

#include <emscripten.h>

#include <nlohmann/json.hpp>
#include <string>

#include "ui/parallel_dom/parallel_dom.h"
#include "web_app.h"

namespace {

std::string items_text;  // valid until the next call

nlohmann::json item_json(const swarmlab::MirroredItem& m) {
  nlohmann::json j = {{"id", m.id},
                      {"role", swarmlab::role_name(m.role)},
                      {"name", m.name},
                      {"region", m.region},
                      {"x", m.x},
                      {"y", m.y},
                      {"width", m.width},
                      {"height", m.height}};
  if (m.role == swarmlab::ItemRole::number || m.role == swarmlab::ItemRole::slider) j["numeric"] = true;
  if (!m.description.empty()) j["description"] = m.description;
  if (!m.value.empty()) j["value"] = m.value;
  if (m.checked) j["checked"] = true;
  if (m.expanded) j["expanded"] = true;
  if (m.openable) j["openable"] = true;
  if (m.has_popup) j["popup"] = true;
  if (m.disabled) j["disabled"] = true;
  if (m.clipped) j["clipped"] = true;
  return j;
}

}  // namespace

extern "C" {

/// {"items": [...], "editing": id, "text": "...", "nav": id, "touch": bool}: the items of the
/// last frame in reading order (web/README.md, "Parallel DOM"), the text field being edited
/// (0 when none) with its text, the item ImGui's keyboard focus is on.
EMSCRIPTEN_KEEPALIVE const char* swarmlab_dom_items() {
  const swarmlab::ParallelDom& dom = swarmlab::parallel_dom();
  nlohmann::json items = nlohmann::json::array();
  for (const swarmlab::MirroredItem& m : dom.items()) items.push_back(item_json(m));
  swarmlab::App* app = swarmlab::web_app();
  items_text = nlohmann::json{{"items", std::move(items)},
                              {"editing", dom.editing_id()},
                              {"text", dom.editing_text()},
                              {"nav", dom.nav_id()},
                              {"touch", app && app->state().layout.touch}}
                   .dump(-1, ' ', false, nlohmann::json::error_handler_t::replace);
  return items_text.c_str();
}

/// Presses the item (a click, Enter or Space on its element).
EMSCRIPTEN_KEEPALIVE void swarmlab_dom_activate(unsigned id) { swarmlab::parallel_dom().request_activate(id); }

/// Puts ImGui's keyboard focus on the item and scrolls it into view; ring: with its focus ring
/// (the page's last input was a key).
EMSCRIPTEN_KEEPALIVE void swarmlab_dom_focus(unsigned id, int ring) {
  swarmlab::parallel_dom().request_focus(id, ring != 0);
}

/// Types text into the field and commits it, with Enter when `enter` is 1.
EMSCRIPTEN_KEEPALIVE void swarmlab_dom_type(unsigned id, const char* text, int enter) {
  swarmlab::parallel_dom().request_text(id, text ? text : "", enter != 0);
}

}  // extern "C"
