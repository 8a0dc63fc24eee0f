#pragma once
// Move-only ownership of one OpenGL object name.
#include <epoxy/gl.h>

#include <utility>

#include "penumbra/gl/current_context.hpp"

namespace penumbra::gl {

template <void (*Delete)(GLuint)>
class Handle {
 public:
  Handle() = default;
  explicit Handle(GLuint id) : id_(id) {}
  ~Handle() { reset(); }
  Handle(const Handle&) = delete;
  Handle& operator=(const Handle&) = delete;
  Handle(Handle&& other) noexcept : id_(std::exchange(other.id_, 0)) {}
  Handle& operator=(Handle&& other) noexcept {
    if (this != &other) {
      reset();
      id_ = std::exchange(other.id_, 0);
    }
    return *this;
  }

  [[nodiscard]] GLuint id() const { return id_; }
  [[nodiscard]] explicit operator bool() const { return id_ != 0; }
  // Deletes the object while a context is current; with none (the engine
  // destroyed it first, and the object with it) it only forgets the name.
  void reset() {
    if (id_ != 0 && has_current_context()) Delete(id_);
    id_ = 0;
  }

 private:
  GLuint id_ = 0;
};

}  // namespace penumbra::gl
