// Stand-in for the browser build of Swarm Lab: proves the web plumbing end to end (SDL2 built
// for wasm, a WebGL2 / GL ES 3 context, Dear ImGui, the frame loop, nlohmann-json from the
// Debian headers, and the window.swarmlab JS API) until the real app replaces it through
// SWARMLAB_WEB_SOURCES in web/CMakeLists.txt.
//
// The JS API contract (web/swarmlab_api.js wraps these with ccall into window.swarmlab):
//   extern "C" double      swarmlab_time();                 // simulated clock, advances per frame
//   extern "C" const char* swarmlab_preset();               // current preset as a JSON text
//   extern "C" const char* swarmlab_load(const char* json); // "" on success, else an error message
#include <GLES3/gl3.h>
#include <SDL.h>
#include <emscripten.h>

#include <cmath>
#include <cstdio>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "imgui.h"
#include "imgui_impl_opengl3.h"
#include "imgui_impl_sdl.h"
#include "swarmlab_web_mainloop.h"

namespace {

// A harmonic swarm: under a linear (spring-like) force law every particle oscillates about the
// centre of mass with the same period, so x(t) = a cos(w t) + b sin(w t) per axis, exactly.
struct Particle {
  float ax, bx, ay, by;
};

struct StandIn {
  std::string preset_name = "stand-in";
  int count = 48;
  double omega = 1.0;    // rad per simulated second
  double dt = 1.0 / 60;  // simulated seconds per frame
  double time = 0.0;
  long frames = 0;
  std::vector<Particle> particles;
  std::vector<float> energy_trace = std::vector<float>(240, 0.0f);
  int trace_head = 0;

  void seed() {
    particles.clear();
    unsigned s = 12345u;
    auto rnd = [&s] {
      s = s * 1664525u + 1013904223u;
      return (s >> 8) / float(1u << 24) * 2.0f - 1.0f;
    };
    for (int i = 0; i < count; ++i) particles.push_back({rnd(), rnd(), rnd(), rnd()});
  }
  nlohmann::json to_json() const {
    return {{"name", preset_name}, {"count", count}, {"omega", omega}, {"dt", dt}};
  }
};

StandIn g_app;
std::string g_preset_text;
std::string g_load_error;

}  // namespace

extern "C" {

EMSCRIPTEN_KEEPALIVE double swarmlab_time() { return g_app.time; }

EMSCRIPTEN_KEEPALIVE const char* swarmlab_preset() {
  g_preset_text = g_app.to_json().dump();
  return g_preset_text.c_str();
}

EMSCRIPTEN_KEEPALIVE const char* swarmlab_load(const char* text) {
  g_load_error.clear();
  nlohmann::json j = nlohmann::json::parse(text ? text : "", nullptr, /*allow_exceptions=*/false);
  if (j.is_discarded() || !j.is_object()) {
    g_load_error = "not a JSON object";
    return g_load_error.c_str();
  }
  StandIn next = g_app;
  if (j.contains("name")) {
    if (!j["name"].is_string()) return (g_load_error = "name: expected a string").c_str();
    next.preset_name = j["name"].get<std::string>();
  }
  if (j.contains("count")) {
    if (!j["count"].is_number_integer() || j["count"].get<int>() < 1 ||
        j["count"].get<int>() > 5000)
      return (g_load_error = "count: expected an integer in 1..5000").c_str();
    next.count = j["count"].get<int>();
  }
  if (j.contains("omega")) {
    if (!j["omega"].is_number() || j["omega"].get<double>() <= 0)
      return (g_load_error = "omega: expected a positive number").c_str();
    next.omega = j["omega"].get<double>();
  }
  next.time = 0.0;
  next.frames = 0;
  next.trace_head = 0;
  next.seed();
  g_app = std::move(next);
  return g_load_error.c_str();
}

}  // extern "C"

int main(int, char**) {
  if (SDL_Init(SDL_INIT_VIDEO | SDL_INIT_TIMER) != 0) {
    std::printf("SDL_Init failed: %s\n", SDL_GetError());
    return 1;
  }
  // WebGL2 = OpenGL ES 3.0.
  SDL_GL_SetAttribute(SDL_GL_CONTEXT_FLAGS, 0);
  SDL_GL_SetAttribute(SDL_GL_CONTEXT_PROFILE_MASK, SDL_GL_CONTEXT_PROFILE_ES);
  SDL_GL_SetAttribute(SDL_GL_CONTEXT_MAJOR_VERSION, 3);
  SDL_GL_SetAttribute(SDL_GL_CONTEXT_MINOR_VERSION, 0);
  SDL_GL_SetAttribute(SDL_GL_DOUBLEBUFFER, 1);
  SDL_GL_SetAttribute(SDL_GL_DEPTH_SIZE, 0);
  SDL_GL_SetAttribute(SDL_GL_STENCIL_SIZE, 0);
  // RESIZABLE + a CSS-sized canvas: SDL follows the page's size (see web/shell.html).
  SDL_Window* window =
      SDL_CreateWindow("Swarm Lab", SDL_WINDOWPOS_CENTERED, SDL_WINDOWPOS_CENTERED, 1280, 720,
                       SDL_WINDOW_OPENGL | SDL_WINDOW_RESIZABLE | SDL_WINDOW_ALLOW_HIGHDPI);
  if (!window) {
    std::printf("SDL_CreateWindow failed: %s\n", SDL_GetError());
    return 1;
  }
  SDL_GLContext gl = SDL_GL_CreateContext(window);
  if (!gl) {
    std::printf("SDL_GL_CreateContext failed: %s\n", SDL_GetError());
    return 1;
  }
  SDL_GL_MakeCurrent(window, gl);
  SDL_GL_SetSwapInterval(1);

  IMGUI_CHECKVERSION();
  ImGui::CreateContext();
  ImGuiIO& io = ImGui::GetIO();
  io.IniFilename = nullptr;  // no imgui.ini in the browser
  ImGui::StyleColorsDark();
  ImGui_ImplSDL2_InitForOpenGL(window, gl);
  ImGui_ImplOpenGL3_Init("#version 300 es");

  g_app.seed();
  std::printf("Swarm Lab web stand-in: GL %s, ImGui %s\n",
              reinterpret_cast<const char*>(glGetString(GL_VERSION)), IMGUI_VERSION);

  SWARMLAB_MAINLOOP_BEGIN {
    SDL_Event event;
    while (SDL_PollEvent(&event)) ImGui_ImplSDL2_ProcessEvent(&event);

    // Simulate: the clock advances by one step each frame.
    StandIn& a = g_app;
    a.time += a.dt;
    ++a.frames;
    const float c = float(std::cos(a.omega * a.time)), s = float(std::sin(a.omega * a.time));
    float kinetic = 0.0f;
    for (const Particle& p : a.particles) {
      const float vx = float(a.omega) * (-p.ax * s + p.bx * c),
                  vy = float(a.omega) * (-p.ay * s + p.by * c);
      kinetic += 0.5f * (vx * vx + vy * vy);
    }
    a.energy_trace[a.trace_head] = kinetic;
    a.trace_head = (a.trace_head + 1) % int(a.energy_trace.size());

    ImGui_ImplOpenGL3_NewFrame();
    ImGui_ImplSDL2_NewFrame();
    ImGui::NewFrame();

    // The swarm, drawn behind the windows.
    const ImVec2 size = io.DisplaySize;
    const ImVec2 centre(size.x * 0.62f, size.y * 0.5f);
    const float scale = 0.28f * (size.x < size.y ? size.x : size.y);
    ImDrawList* bg = ImGui::GetBackgroundDrawList();
    bg->AddCircle(centre, 4.0f, IM_COL32(255, 255, 255, 120));
    for (const Particle& p : a.particles) {
      const ImVec2 q(centre.x + scale * (p.ax * c + p.bx * s),
                     centre.y + scale * (p.ay * c + p.by * s));
      bg->AddCircleFilled(q, 5.0f, IM_COL32(255, 196, 64, 230));
    }

    ImGui::SetNextWindowPos(ImVec2(16, 16), ImGuiCond_FirstUseEver);
    ImGui::SetNextWindowSize(ImVec2(380, 0), ImGuiCond_FirstUseEver);
    ImGui::Begin("Swarm Lab (web stand-in)");
    ImGui::TextWrapped("The browser build pipeline works: SDL2 + WebGL2 + Dear ImGui %s.",
                       IMGUI_VERSION);
    ImGui::Separator();
    ImGui::Text("preset: %s", a.preset_name.c_str());
    ImGui::Text("particles: %d   omega: %.3g", a.count, a.omega);
    ImGui::Text("simulated time: %.2f", a.time);
    ImGui::Text("frame %ld   %.1f fps", a.frames, io.Framerate);
    const int trace_n = int(a.energy_trace.size());
    const bool wrapped = a.frames >= trace_n;
    ImGui::PlotLines("kinetic energy", a.energy_trace.data(), wrapped ? trace_n : a.trace_head,
                     wrapped ? a.trace_head : 0, nullptr, 0.0f, FLT_MAX, ImVec2(0, 80));
    ImGui::End();

    ImGui::Render();
    int fb_w = 0, fb_h = 0;
    SDL_GL_GetDrawableSize(window, &fb_w, &fb_h);
    glViewport(0, 0, fb_w, fb_h);
    glClearColor(0.07f, 0.10f, 0.18f, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT);
    ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());
    SDL_GL_SwapWindow(window);
  };
  SWARMLAB_MAINLOOP_END;
  return 0;
}
