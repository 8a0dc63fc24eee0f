#pragma once
// The study behind `penumbra report`: every technique on one scene, the
// maps before and after filtering, sweeps of the filter width, the light
// size and the ESM exponent, errors against the filtered hard-shadow
// reference, and per-pass GPU times, written as one HTML page with its
// images.
#include <string>

#include "penumbra/gl/context.hpp"
#include "scene/scene.hpp"

namespace penumbra {

struct StudyOptions {
  std::string scene_argument = "default";  // as given on the command line
  std::string model_argument;              // --model as given, instead of the scene
  std::string light_choice;                // --light as given (empty: not given)
  std::string output_dir;
  bool quick = false;  // smaller images and fewer sweeps
};

struct StudyResult {
  std::string index_path;
  int items = 0;
  int failed = 0;
};

// Renders everything and writes output_dir/index.html. Items that fail are
// reported on the page and counted; the rest is still written.
StudyResult write_study(const Scene& scene, const StudyOptions& options, gl::Context& context);

}  // namespace penumbra
