#include "ui/parallel_dom/items_json.h"

#include <nlohmann/json.hpp>

#include "ui/parallel_dom/parallel_dom.h"

namespace swarmlab {
namespace {

nlohmann::json item_json(const MirroredItem& m) {
  nlohmann::json j = {{"id", m.id},       {"role", role_name(m.role)}, {"name", m.name},
                      {"region", m.region}, {"x", m.x},                {"y", m.y},
                      {"width", m.width}, {"height", m.height}};
  if (m.role == ItemRole::number || m.role == ItemRole::slider) j["numeric"] = true;
  if (!m.description.empty()) j["description"] = m.description;
  if (!m.value.empty()) j["value"] = m.value;
  if (m.checked) j["checked"] = true;
  if (m.expanded) j["expanded"] = true;
  if (m.openable) j["openable"] = true;
  if (m.has_popup) j["popup"] = true;
  if (m.disabled) j["disabled"] = true;
  if (m.clipped) j["clipped"] = true;
  if (m.cut) j["cut"] = true;
  if (m.in_popup) j["in_popup"] = true;
  if (m.popup_of != 0) j["popup_of"] = m.popup_of;
  return j;
}

}  // namespace

std::string items_json(const ParallelDom& dom, bool touch) {
  nlohmann::json items = nlohmann::json::array();
  for (const MirroredItem& m : dom.items()) items.push_back(item_json(m));
  nlohmann::json frame{{"items", std::move(items)},
                        {"editing", dom.editing_id()},
                        {"text", dom.editing_text()},
                        {"nav", dom.nav_id()},
                        {"touch", touch}};
  // Plain text cut off, where there is any (the layout test reads it).
  for (const MirroredItem& m : dom.cut_text()) frame["cut_text"].push_back(item_json(m));
  return frame.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace);
}

}  // namespace swarmlab
