#pragma once
// Base-colour textures: decoding image files once (stb_image), and
// sampling them on the CPU exactly where the GPU does, so that the traced
// reference sees the same holes in alpha-masked surfaces as the shadow
// maps.
#include <cstddef>
#include <cstdint>
#include <glm/glm.hpp>
#include <optional>
#include <string>

#include "scene/scene.hpp"

namespace penumbra {

// The largest texture side decoded: 8192 texels, 256 MiB of RGBA8 (the
// model reader's memory floor, model.hpp, leaves room for stb_image to
// decode one; a 16k texture would take 1 GiB and twice that decoding). A
// file that claims more is refused with a warning and the material's flat
// colour, read no further.
inline constexpr int kMaxTextureSide = 8192;
// The largest image file read for a texture, refused unread beyond: an
// image of kMaxTextureSide texels a side takes less even uncompressed.
inline constexpr std::uintmax_t kMaxTextureFileBytes = std::uintmax_t{512} << 20;

// Decodes a PNG, JPEG, TGA, BMP, ... file held in memory. On failure,
// nullopt and `error` says why.
std::optional<TextureImage> decode_texture(const std::uint8_t* bytes, std::size_t size,
                                           const std::string& name, std::string& error);

// Reads and decodes an image file. On failure, nullopt and `error`.
std::optional<TextureImage> read_texture(const std::string& path, std::string& error);

// The texture coordinate (in the image: (0, 0) is its top-left corner, 1
// its width or height) of a vertex uv under the material's transform.
glm::vec2 texture_coordinate(const Material& m, glm::vec2 uv);

// The material's texture at texture coordinate t, bilinear on the full
// resolution, with the material's wrap modes: linear RGB (sRGB decoded)
// and alpha. Without a texture, (1, 1, 1, 1).
glm::vec4 sample_texture(const Material& m, glm::vec2 t);

// Unpacks a vertex colour (Vertex::color).
glm::vec4 unpack_color(std::uint32_t rgba);
std::uint32_t pack_color(const glm::vec4& rgba);

// Whether a point of a triangle with this material, vertex colour alpha
// and uv is a hole of an alpha-tested surface.
bool is_cut_out(const Material& m, float vertex_alpha, glm::vec2 uv);

}  // namespace penumbra
