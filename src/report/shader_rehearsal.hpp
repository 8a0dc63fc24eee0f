#pragma once
// The study rehearsed on a second context and thread, so that the
// report's thread finds the shaders it draws with already compiled.
//
// llvmpipe compiles a shader variant the first time a draw or a dispatch
// uses it, on the thread that issues it, per state it runs in (the
// formats, samplers and targets bound), and keeps it in Mesa's shader
// cache on disk. Compiling a technique's programs takes seconds on the
// CPU; drawing it at the report's size takes about as long again, on
// llvmpipe's own threads, while the report's thread waits. So the
// rehearsal draws every frame of the study in the same order and state at
// a size where drawing costs nothing (StudyMode::Rehearsal), and what it
// compiles, written to the shader cache, is read back by the report's
// thread when it gets there instead of compiled again. Its first section
// goes through the techniques from the last, so that the two threads meet
// in the middle rather than compile the same technique at once.
#include <atomic>
#include <memory>
#include <string>
#include <thread>

#include "io/signal_cleanup.hpp"
#include "penumbra/gl/context.hpp"
#include "report/study.hpp"
#include "scene/scene.hpp"

namespace penumbra {

class ShaderRehearsal {
 public:
  // Whether rehearsing saves the study time: on a rasterizer that runs on
  // the CPU (where compiling is dear and done at the first draw) with
  // Mesa's shader cache on.
  static bool helps(const gl::Context& study_context);

  // Starts rehearsing the study of `scene` with `options` (its output
  // folder aside: the rehearsal writes into a temporary one). Makes
  // `study_context` current on this thread again after making its own.
  // `scene` must outlive the rehearsal.
  ShaderRehearsal(const Scene& scene, const StudyOptions& options, gl::Context& study_context);
  // Stops the rehearsal at its next section, waits for its thread, and
  // removes its folder.
  ~ShaderRehearsal();
  ShaderRehearsal(const ShaderRehearsal&) = delete;
  ShaderRehearsal& operator=(const ShaderRehearsal&) = delete;

 private:
  std::string folder_;
  std::unique_ptr<RemoveOnSignal> remove_on_signal_;  // the folder, on SIGINT or SIGTERM
  std::atomic<bool> stop_{false};
  std::thread thread_;
};

}  // namespace penumbra
