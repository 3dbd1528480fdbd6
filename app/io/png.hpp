// PNG files with libpng: fast (zlib level 1) for frame dumps, as docs/platform.md ("Images and
// video") measured.
#pragma once

#include <cstdint>
#include <filesystem>
#include <vector>

namespace springlab::app {

struct Image {
  int width = 0, height = 0;
  std::vector<std::uint8_t> rgba;  // rows from the top, or from the bottom (as GL reads them)
  bool bottom_up = false;

  // Row y counted from the top, whichever way the rows are stored.
  const std::uint8_t* row(int y) const {
    return rgba.data() + static_cast<std::size_t>(bottom_up ? height - 1 - y : y) * width * 4;
  }
};

// Writes atomically (temporary name, then rename). Throws on failure.
void write_png(const std::filesystem::path& path, const Image& image, int compression = 1);
// Throws std::runtime_error naming the file when it cannot be read as a PNG.
Image read_png(const std::filesystem::path& path);

}  // namespace springlab::app
