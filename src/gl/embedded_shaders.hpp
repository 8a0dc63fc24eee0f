#pragma once
// The GLSL files under shaders/, compiled into the binary at build time
// (see cmake/embed_shaders.cmake).
#include <span>
#include <string_view>

namespace penumbra::gl {

struct EmbeddedFile {
  std::string_view path;  // relative to shaders/, e.g. "shadow/hard.glsl"
  std::string_view text;
};

std::span<const EmbeddedFile> embedded_shader_files();

}  // namespace penumbra::gl
