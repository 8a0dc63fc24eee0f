#pragma once
// Writes 8-bit RGB pixels (rows top to bottom) as a PNG file: a few dozen
// lines of its own (uncompressed deflate blocks), so the example needs no
// image library.
#include <cstdint>
#include <string>
#include <vector>

namespace embed {

// Writes to a temporary name and renames; throws std::runtime_error if the
// file cannot be written.
void write_png(const std::string& path, int width, int height,
               const std::vector<std::uint8_t>& rgb);

}  // namespace embed
