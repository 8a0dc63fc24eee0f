#include "report/shader_rehearsal.hpp"

#include <malloc.h>

#include <cstdlib>
#include <exception>
#include <filesystem>
#include <string_view>
#include <system_error>

#include "report/study_run.hpp"

namespace penumbra {

namespace {

// Mesa reads MESA_SHADER_CACHE_DISABLE as a boolean ("true", "1", "yes",
// "y"; gl::Context sets "true" where the cache's folder cannot be made).
bool mesa_shader_cache_disabled() {
  const char* value = std::getenv("MESA_SHADER_CACHE_DISABLE");
  if (value == nullptr) return false;
  const std::string_view v(value);
  return v == "true" || v == "1" || v == "yes" || v == "y";
}

// A new empty folder for the rehearsal's files (the foliage scene it
// reads back), or an empty string if none can be made.
std::string new_temporary_folder() {
  std::error_code ec;
  const std::filesystem::path base = std::filesystem::temp_directory_path(ec);
  if (ec) return {};
  std::string pattern = (base / "penumbra-rehearsal-XXXXXX").string();
  return mkdtemp(pattern.data()) != nullptr ? pattern : std::string();
}

}  // namespace

bool ShaderRehearsal::helps(const gl::Context& study_context) {
  return gl::is_cpu_rasterizer(study_context.renderer()) && !mesa_shader_cache_disabled();
}

ShaderRehearsal::ShaderRehearsal(const Scene& scene, const StudyOptions& options,
                                 gl::Context& study_context)
    : folder_(new_temporary_folder()) {
  if (folder_.empty()) return;
  remove_on_signal_ = std::make_unique<RemoveOnSignal>(folder_, true);
  // Made here, not on the rehearsal's thread: making a context sets
  // environment variables (gl::Context::create_headless), which another
  // thread's getenv must not race.
  std::unique_ptr<gl::Context> context;
  try {
    context = gl::Context::create_headless();
  } catch (const std::exception&) {
    // No second context: the study compiles its shaders itself.
  }
  study_context.make_current();
  if (!context) return;
  StudyOptions rehearsed = options;
  rehearsed.output_dir = folder_;
  thread_ = std::thread([this, &scene, rehearsed, context = std::move(context)]() mutable {
    try {
      context->make_current();
      Study(scene, rehearsed, *context, StudyMode::Rehearsal, &stop_).run();
    } catch (const std::exception&) {
      // Stopped, or failed: what it compiled is compiled; the study
      // compiles the rest itself.
    }
    context.reset();
  });
}

ShaderRehearsal::~ShaderRehearsal() {
  stop_ = true;
  if (thread_.joinable()) {
    thread_.join();
    // Its thread allocated from a malloc arena of its own, which keeps what
    // was freed: given back, so that the study's later peaks do not sit on
    // top of the rehearsal's.
    malloc_trim(0);
  }
  if (!folder_.empty()) {
    std::error_code ec;
    std::filesystem::remove_all(folder_, ec);
  }
}

}  // namespace penumbra
