#include "penumbra/gl/shader_source.hpp"

#include <filesystem>
#include <regex>
#include <set>
#include <sstream>

#include "gl/embedded_shaders.hpp"
#include "penumbra/error.hpp"

namespace penumbra::gl {

std::string_view embedded_shader_text(const std::string& path) {
  for (const EmbeddedFile& file : embedded_shader_files()) {
    if (file.path == path) return file.text;
  }
  throw RuntimeError("shader file '" + path + "' is not embedded in this build");
}

namespace {

std::string directory_of(const std::string& path) {
  auto slash = path.rfind('/');
  return slash == std::string::npos ? std::string() : path.substr(0, slash + 1);
}

bool is_embedded(const std::string& path) {
  for (const EmbeddedFile& file : embedded_shader_files()) {
    if (file.path == path) return true;
  }
  return false;
}

// Resolves an include relative to the including file first, then to shaders/.
std::string resolve_include(const std::string& from, const std::string& name) {
  std::string relative =
      std::filesystem::path(directory_of(from) + name).lexically_normal().string();
  if (is_embedded(relative)) return relative;
  if (is_embedded(name)) return name;
  throw RuntimeError(from + ": cannot find include \"" + name + "\"");
}

class Assembler {
 public:
  ShaderSource result;
  bool line_directives = true;  // "#line N file-id", for map_compile_log()

  void expand(const std::string& path, int depth) {
    if (depth > 32) throw RuntimeError(path + ": #include nested too deeply");
    if (!included_.insert(path).second) return;  // every file once
    const int id = static_cast<int>(result.files.size());
    result.files.push_back(path);
    std::istringstream in{std::string(embedded_shader_text(path))};
    std::string line;
    int number = 0;
    if (line_directives) result.text += "#line 1 " + std::to_string(id) + "\n";
    static const std::regex include_re(R"(^\s*#\s*include\s+"([^"]+)\"\s*$)");
    static const std::regex once_re(R"(^\s*#\s*pragma\s+once\s*$)");
    while (std::getline(in, line)) {
      ++number;
      std::smatch match;
      if (std::regex_match(line, match, include_re)) {
        expand(resolve_include(path, match[1].str()), depth + 1);
        if (line_directives) {
          result.text += "#line " + std::to_string(number + 1) + " " + std::to_string(id) + "\n";
        }
      } else if (std::regex_match(line, once_re)) {
        result.text += "\n";
      } else {
        result.text += line + "\n";
      }
    }
  }

 private:
  std::set<std::string> included_;
};

}  // namespace

ShaderSource assemble_shader(const std::string& path, const Defines& defines) {
  Assembler assembler;
  assembler.result.text = "#version 450 core\n";
  for (const auto& [name, value] : defines) {
    assembler.result.text += "#define " + name + " " + value + "\n";
  }
  assembler.expand(path, 0);
  return std::move(assembler.result);
}

std::string expand_shader_includes(const std::string& path) {
  Assembler assembler;
  assembler.line_directives = false;
  assembler.expand(path, 0);
  return std::move(assembler.result.text);
}

std::string map_compile_log(const std::string& log, const std::vector<std::string>& files) {
  static const std::regex mesa_re(R"(^(\d+):(\d+)\(\d+\):\s*(.*)$)");
  static const std::regex nvidia_re(R"(^(\d+)\((\d+)\)\s*:\s*(.*)$)");
  std::istringstream in(log);
  std::string line;
  std::string out;
  while (std::getline(in, line)) {
    std::smatch match;
    if (std::regex_match(line, match, mesa_re) || std::regex_match(line, match, nvidia_re)) {
      std::size_t id = std::stoul(match[1].str());
      std::string file = id < files.size() ? files[id] : "source " + match[1].str();
      out += file + ":" + match[2].str() + ": " + match[3].str() + "\n";
    } else if (!line.empty()) {
      out += line + "\n";
    }
  }
  return out;
}

}  // namespace penumbra::gl
