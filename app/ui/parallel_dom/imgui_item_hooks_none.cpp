// Debian's packaged libimgui (the desktop app) is built without item hooks: the parallel DOM
// stays empty there; the desktop has ImGui's own keyboard navigation and no DOM to fill.
#include "ui/parallel_dom/parallel_dom.h"

bool swarmlab::ParallelDom::hooks_compiled() { return false; }
