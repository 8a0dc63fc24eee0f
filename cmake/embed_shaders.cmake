# Embeds every file under SHADER_DIR into OUTPUT as a C++ table of
# (relative path, contents), so the installed tool needs no data directory.
# Run as: cmake -DSHADER_DIR=... -DOUTPUT=... -P embed_shaders.cmake
file(GLOB_RECURSE shader_files RELATIVE "${SHADER_DIR}"
     "${SHADER_DIR}/*.glsl" "${SHADER_DIR}/*.vert" "${SHADER_DIR}/*.frag"
     "${SHADER_DIR}/*.comp" "${SHADER_DIR}/*.h")
list(SORT shader_files)

set(body "")
set(table "")
set(index 0)
foreach(rel IN LISTS shader_files)
  file(READ "${SHADER_DIR}/${rel}" hex HEX)
  string(LENGTH "${hex}" hex_len)
  math(EXPR size "${hex_len} / 2")
  string(REGEX REPLACE "([0-9a-f][0-9a-f])" "0x\\1," bytes "${hex}")
  string(APPEND body "static const unsigned char shader_${index}[] = {${bytes}0x00};\n")
  string(APPEND table "    {\"${rel}\", std::string_view(reinterpret_cast<const char*>(shader_${index}), ${size})},\n")
  math(EXPR index "${index} + 1")
endforeach()

set(content "// Generated from shaders/ by cmake/embed_shaders.cmake. Do not edit.
#include \"gl/embedded_shaders.hpp\"

namespace penumbra::gl {
namespace {
${body}
const EmbeddedFile files[] = {
${table}};
}  // namespace

std::span<const EmbeddedFile> embedded_shader_files() { return files; }
}  // namespace penumbra::gl
")

# Only touch the output when it changes, so unrelated rebuilds stay quick.
if(EXISTS "${OUTPUT}")
  file(READ "${OUTPUT}" old)
  if(old STREQUAL content)
    return()
  endif()
endif()
file(WRITE "${OUTPUT}" "${content}")
