#pragma once
// What the shadow core throws: penumbra::UsageError for a bad argument
// (settings out of range, too many lights), penumbra::RuntimeError for a
// failure doing the work (a shader that does not compile, a GPU without
// OpenGL 4.5). Both are std::runtime_error.
#include "core/error.hpp"
