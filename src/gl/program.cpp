#include "penumbra/gl/program.hpp"

#include <vector>

#include "penumbra/error.hpp"
#include "penumbra/gl/resources.hpp"

namespace penumbra::gl {

namespace {

GLuint compile_stage(GLenum stage, const std::string& path, const Defines& defines) {
  ShaderSource source = assemble_shader(path, defines);
  GLuint shader = glCreateShader(stage);
  const char* text = source.text.c_str();
  glShaderSource(shader, 1, &text, nullptr);
  glCompileShader(shader);
  GLint ok = GL_FALSE;
  glGetShaderiv(shader, GL_COMPILE_STATUS, &ok);
  if (ok != GL_TRUE) {
    GLint length = 0;
    glGetShaderiv(shader, GL_INFO_LOG_LENGTH, &length);
    std::string log(static_cast<std::size_t>(length > 0 ? length : 1), '\0');
    glGetShaderInfoLog(shader, length, nullptr, log.data());
    glDeleteShader(shader);
    throw RuntimeError("shader '" + path + "' failed to compile:\n" +
                       map_compile_log(log.c_str(), source.files));
  }
  return shader;
}

GLuint link(const std::vector<GLuint>& shaders, const std::string& label) {
  GLuint program = glCreateProgram();
  for (GLuint shader : shaders) glAttachShader(program, shader);
  glLinkProgram(program);
  for (GLuint shader : shaders) {
    glDetachShader(program, shader);
    glDeleteShader(shader);
  }
  GLint ok = GL_FALSE;
  glGetProgramiv(program, GL_LINK_STATUS, &ok);
  if (ok != GL_TRUE) {
    GLint length = 0;
    glGetProgramiv(program, GL_INFO_LOG_LENGTH, &length);
    std::string log(static_cast<std::size_t>(length > 0 ? length : 1), '\0');
    glGetProgramInfoLog(program, length, nullptr, log.data());
    glDeleteProgram(program);
    throw RuntimeError("program '" + label + "' failed to link:\n" + log.c_str());
  }
  set_label(GL_PROGRAM, program, label);
  return program;
}

}  // namespace

Program Program::graphics(const std::string& vertex, const std::string& fragment,
                          const Defines& defines) {
  GLuint vs = compile_stage(GL_VERTEX_SHADER, vertex, defines);
  GLuint fs = 0;
  try {
    fs = compile_stage(GL_FRAGMENT_SHADER, fragment, defines);
  } catch (...) {
    glDeleteShader(vs);
    throw;
  }
  Program program;
  program.handle_ = Handle<detail::delete_program>(link({vs, fs}, vertex + "+" + fragment));
  return program;
}

Program Program::compute(const std::string& compute, const Defines& defines) {
  GLuint cs = compile_stage(GL_COMPUTE_SHADER, compute, defines);
  Program program;
  program.handle_ = Handle<detail::delete_program>(link({cs}, compute));
  return program;
}

}  // namespace penumbra::gl
