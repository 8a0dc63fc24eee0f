#pragma once
// Assembles GLSL source from the embedded shaders/ tree: prepends the
// version and the defines, expands #include "path" (each file once), and
// keeps a table of source-string numbers so that compiler messages can be
// reported as file:line.
#include <string>
#include <utility>
#include <vector>

namespace penumbra::gl {

using Defines = std::vector<std::pair<std::string, std::string>>;

struct ShaderSource {
  std::string text;
  std::vector<std::string> files;  // files[i] is the path of source string i
};

// Throws RuntimeError if `path` or one of its includes does not exist.
ShaderSource assemble_shader(const std::string& path, const Defines& defines);

// The embedded file's text with its includes expanded (each file once)
// and no #version, defines or #line directives: a self-contained include
// for another program's shaders. Throws RuntimeError as assemble_shader().
std::string expand_shader_includes(const std::string& path);

// Looks up an embedded file's text; throws RuntimeError if absent.
std::string_view embedded_shader_text(const std::string& path);

// Rewrites a driver's compile log so that each "S:L(C)" (Mesa) or "S(L)"
// (NVIDIA) location reads "file:L". Lines it does not recognise pass through.
std::string map_compile_log(const std::string& log, const std::vector<std::string>& files);

}  // namespace penumbra::gl
