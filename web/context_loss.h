#pragma once
// A lost WebGL context survived (context_loss.cpp): the frames wait until the browser gives the
// context back, then every GL object is made again and the app goes on where it was.

#include "ui/main_loop.h"

namespace swarmlab {

/// From now on, when the canvas (a CSS selector, "#canvas") loses its WebGL context the app's
/// GL objects are released and the page says so in one calm line (Module.onContextLost in
/// shell.html); when it is restored they are made again and the line goes
/// (Module.onContextRestored). The loss's default action is prevented, so that the browser
/// may restore the context.
void survive_context_loss(const char* canvas, Frontend& frontend);

/// True from a loss until its restore: the main loop runs no frame then (web_main.cpp), so no
/// GL call reaches the lost context and the run waits where it was.
bool context_lost();

}  // namespace swarmlab
