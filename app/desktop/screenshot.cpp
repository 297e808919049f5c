#include "desktop/screenshot.h"

#include <stb_image_write.h>

#include <cstring>
#include <vector>

#include "files/atomic_file.h"
#include "ui/kit/gl_api.h"

namespace swarmlab {

std::string save_screenshot(const std::string& path, int width, int height) {
  if (width <= 0 || height <= 0) return path + ": the window has no pixels";
  const std::size_t row = std::size_t(width) * 4;
  std::vector<unsigned char> pixels(row * std::size_t(height));
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glReadPixels(0, 0, width, height, GL_RGBA, GL_UNSIGNED_BYTE, pixels.data());
  // OpenGL's rows start at the bottom, PNG's at the top; the alpha channel is made opaque
  // because the window's is meaningless.
  std::vector<unsigned char> image(pixels.size());
  for (int y = 0; y < height; ++y)
    std::memcpy(&image[std::size_t(y) * row], &pixels[std::size_t(height - 1 - y) * row], row);
  for (std::size_t i = 3; i < image.size(); i += 4) image[i] = 255;

  std::string png;
  const auto append = [](void* context, void* data, int size) {
    static_cast<std::string*>(context)->append(static_cast<const char*>(data), std::size_t(size));
  };
  if (!stbi_write_png_to_func(append, &png, width, height, 4, image.data(), int(row)))
    return path + ": cannot encode the PNG";
  return write_file_atomically(path, png);
}

}  // namespace swarmlab
