#include "screenshot.hpp"

#include <stb_image_write.h>

#include <algorithm>
#include <cstddef>
#include <stdexcept>
#include <vector>

#include "gl.hpp"

namespace cosmems::viewer {

void WriteScreenshot(const std::string& path, int width, int height) {
  const std::size_t row = 3 * static_cast<std::size_t>(width);
  std::vector<unsigned char> pixels(row * static_cast<std::size_t>(height));
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glReadBuffer(GL_BACK);
  glReadPixels(0, 0, width, height, GL_RGB, GL_UNSIGNED_BYTE, pixels.data());
  // OpenGL's rows run bottom to top, an image file's top to bottom.
  std::vector<unsigned char> flipped(pixels.size());
  for (int y = 0; y < height; ++y) {
    std::copy_n(pixels.begin() + static_cast<std::ptrdiff_t>(row * (height - 1 - y)), row,
                flipped.begin() + static_cast<std::ptrdiff_t>(row * y));
  }
  if (stbi_write_png(path.c_str(), width, height, 3, flipped.data(), static_cast<int>(row)) == 0) {
    throw std::runtime_error("--screenshot: cannot write " + path);
  }
}

}  // namespace cosmems::viewer
