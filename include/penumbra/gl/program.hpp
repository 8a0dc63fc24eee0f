#pragma once
// A linked GLSL program built from embedded shader files.
#include <string>

#include "penumbra/gl/handle.hpp"
#include "penumbra/gl/shader_source.hpp"

namespace penumbra::gl {

namespace detail {
inline void delete_program(GLuint id) {
  glDeleteProgram(id);
}
}  // namespace detail

class Program {
 public:
  Program() = default;
  // Compiles and links; throws RuntimeError with "file:line: message" lines
  // if a stage fails to compile or the program fails to link.
  static Program graphics(const std::string& vertex, const std::string& fragment,
                          const Defines& defines = {});
  static Program compute(const std::string& compute, const Defines& defines = {});

  void use() const { glUseProgram(handle_.id()); }
  [[nodiscard]] GLuint id() const { return handle_.id(); }
  [[nodiscard]] explicit operator bool() const { return static_cast<bool>(handle_); }

 private:
  Handle<detail::delete_program> handle_;
};

// The work groups of `local` invocations each that cover `size` along one
// axis of a compute dispatch: size / local, rounded up.
constexpr GLuint work_groups(int size, int local) {
  return static_cast<GLuint>((size + local - 1) / local);
}

}  // namespace penumbra::gl
