#pragma once
// When the window cannot be drawn into, and what is made again afterwards.
//
// A browser may take the WebGL context away (a phone's or a Chromebook's GPU reset, memory
// running short, a tab long in the background: "webglcontextlost") and later give back a new,
// empty one ("webglcontextrestored"): every GL object of the old context is gone, and using one
// of its names on the new one is an INVALID_OPERATION. A desktop window that is minimised keeps
// its OpenGL context (GLX, WGL and CGL contexts survive it), but nothing drawn into it is seen.
// In both cases no frame runs meanwhile (web/context_loss.cpp, app/desktop/desktop.cpp): the
// run and the student's edits wait where they were, and go on from there.
//
// The GL objects, all of them: ImGui's OpenGL3 backend holds a shader program, a vertex and an
// index buffer and the font atlas texture (and makes and deletes a vertex array in every
// frame); the 3D view's ParticleRenderer holds two programs, the corner and the instance
// buffers and two vertex arrays. Nothing else in app/ or web/ makes one: a screenshot or a
// saved plot only reads the frame (glReadPixels).
//
// SDL's SDL_RENDER_DEVICE_RESET and SDL_RENDER_TARGETS_RESET concern SDL_Renderer's own
// textures (a Direct3D device lost, render targets after a resize). The app draws with its own
// OpenGL context and no SDL_Renderer, so they never come, and nothing here waits for them.

#include "ui/main_loop.h"

namespace swarmlab {

/// The context was lost: deletes every GL object. The calls go to the lost context, which
/// ignores them (WebGL generates no error there), and Emscripten forgets the names, so none of
/// them is used again. Call once per loss, with no frame running until create_gl_objects().
void release_gl_objects(Frontend& frontend);

/// The context is back, empty: starts ImGui's OpenGL3 backend afresh (its program, buffers and
/// font atlas texture are made by the next frame's ImGui_ImplOpenGL3_NewFrame) and makes the
/// particle renderer's objects. The next frame's clock starts now, so the time the picture was
/// away is not taken as one long frame, and a frame is due (FrameDemand::wake): the picture
/// must be drawn again even when the run is paused and nothing else changes.
void create_gl_objects(Frontend& frontend);

/// The desktop, before each frame: while the window is minimised or hidden (SDL's
/// SDL_WINDOW_MINIMIZED or SDL_WINDOW_HIDDEN, set by SDL_WINDOWEVENT_MINIMIZED or _HIDDEN and
/// cleared by _RESTORED or _SHOWN), runs no frame and draws nothing: it sleeps until events
/// come. The events that come meanwhile are handed, in their order, to the frames after.
/// Returns when the window shows again, or when it is asked to close (the next frame handles
/// that). Says on stdout when it holds the frames and when they go on, with the run's time.
void hold_while_minimised(Frontend& frontend);

}  // namespace swarmlab
