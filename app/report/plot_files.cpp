#include "report/plot_files.h"

#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#ifndef __EMSCRIPTEN__
#include <spawn.h>
#include <sys/wait.h>
extern char** environ;
#endif

#include "report/figure_csv.h"
#include "report/png_text.h"
#include "report/svg_plot.h"

namespace swarmlab::report {
namespace {

namespace fs = std::filesystem;

[[maybe_unused]] constexpr const char* kRenderer = "rsvg-convert";

/// Runs rsvg-convert as a child process: librsvg is the SVG renderer Debian ships, and a
/// process keeps its libraries out of the binary.
std::string render_png(const fs::path& svg, const fs::path& png) {
#ifdef __EMSCRIPTEN__
  (void)svg, (void)png;
  return "PNG output is not available in the wasm build";
#else
  const std::string in = svg.string(), out = png.string();
  const char* argv[] = {kRenderer, "--background-color=white", "-o", out.c_str(), in.c_str(),
                        nullptr};
  pid_t pid = 0;
  if (posix_spawnp(&pid, kRenderer, nullptr, nullptr, const_cast<char* const*>(argv), environ) != 0)
    return std::string("cannot run ") + kRenderer;
  int status = 0;
  if (waitpid(pid, &status, 0) < 0 || !WIFEXITED(status) || WEXITSTATUS(status) != 0)
    return std::string(kRenderer) + " failed on " + in;
  return {};
#endif
}

/// Rewrites the PNG file at path with lines as its text (png_text.h).
std::string with_text(const fs::path& path, const std::vector<std::string>& lines) {
  std::ifstream in(path, std::ios::binary);
  const std::string png{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  out << png_with_text(png, png_text_of(lines));
  out.close();
  return in && out ? std::string() : "cannot add the provenance to " + path.string();
}

}  // namespace

std::string prepare_plot_dir(const std::string& dir) {
  std::error_code ec;
  if (fs::exists(dir, ec) && !fs::is_directory(dir, ec))
    return dir + ": exists and is not a directory";
  fs::create_directories(dir, ec);
  if (ec) return dir + ": cannot create the directory (" + ec.message() + ")";
  if (::access(dir.c_str(), W_OK | X_OK) != 0) return dir + ": cannot write files here";
  return {};
}

std::string png_unavailable_reason() {
#ifdef __EMSCRIPTEN__
  return "--png is not available in the wasm build";
#else
  const char* path = std::getenv("PATH");
  std::string dirs = path ? path : "/usr/bin:/bin";
  for (std::size_t a = 0; a <= dirs.size();) {
    std::size_t b = dirs.find(':', a);
    if (b == std::string::npos) b = dirs.size();
    const fs::path candidate = fs::path(dirs.substr(a, b - a)) / kRenderer;
    if (::access(candidate.c_str(), X_OK) == 0) return {};
    a = b + 1;
  }
  return std::string("--png needs ") + kRenderer + " (Debian package librsvg2-bin)";
#endif
}

std::string stage_figures(OutputFiles& files, const std::string& dir,
                          const std::vector<NamedFigure>& figures, bool png,
                          const std::vector<std::string>& made_by) {
  for (const NamedFigure& named : figures) {
    NamedFigure f = named;
    f.figure.made_by = made_by;
    const std::string stem = (fs::path(dir) / f.name).string();
    if (std::string e = files.stage(stem + ".svg", svg_of(f.figure)); !e.empty()) return e;
    if (std::string e = files.stage(stem + ".csv", csv_of(f.figure)); !e.empty()) return e;
    if (png) {
      const fs::path svg = files.temp_of(stem + ".svg");
      // rsvg-convert drops the SVG's metadata: the PNG gets it as text chunks.
      const auto render = [&](const std::string& temp) {
        const std::string e = render_png(svg, temp);
        return e.empty() ? with_text(temp, f.figure.made_by) : e;
      };
      if (std::string e = files.stage(stem + ".png", render); !e.empty()) return e;
    }
  }
  return {};
}

}  // namespace swarmlab::report
