#pragma once
// The parallel DOM's items as JSON, for what reads them from outside the frame: the page's
// mirrored elements (web/parallel_dom.js) and the desktop window's tests (swarmlab --items).

#include <string>

namespace swarmlab {

class ParallelDom;

/// {"items": [...], "editing": id, "text": "...", "nav": id, "touch": bool}: the items of the
/// last frame in reading order (web/README.md, "Parallel DOM"), the text field being edited
/// (0 when none) with its text, the item ImGui's keyboard focus is on, and whether the layout
/// is the touch one.
std::string items_json(const ParallelDom& dom, bool touch);

}  // namespace swarmlab
