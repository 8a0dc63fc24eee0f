#pragma once
// Whether this thread has an OpenGL context current, asked without calling
// GL: a GL function called with none current aborts inside libepoxy (it
// cannot find a provider), and an engine may well destroy its context
// before the objects that hold GL names (see Handle::reset).

namespace penumbra::gl {

// True when a context is current on this thread through EGL or GLX (the
// window-system libraries already loaded into the process are asked; none
// loaded means none current).
bool has_current_context();

}  // namespace penumbra::gl
