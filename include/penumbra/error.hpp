#pragma once
// What the shadow core throws: penumbra::UsageError for a bad argument
// (settings out of range, too many lights), penumbra::RuntimeError for a
// failure doing the work (a shader that does not compile, a GPU without
// OpenGL 4.5). Both are std::runtime_error. penumbra's CLI turns each into
// one line "penumbra: error: <message>" and an exit status chosen by its
// kind.
#include <stdexcept>
#include <string>

namespace penumbra {

// A bad argument: a flag, a name or a number that can be judged without
// doing the work. The CLI exits with status 2.
class UsageError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// A failure while doing the work: a file that cannot be read or written, a
// GPU that lacks a feature, a shader that does not compile. Exit status 1.
class RuntimeError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

}  // namespace penumbra
