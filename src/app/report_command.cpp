#include "app/report_command.hpp"

#include <sys/resource.h>

#include <chrono>
#include <cstdio>
#include <filesystem>

#include "app/help_formatter.hpp"
#include "app/light_choice.hpp"
#include "app/option_style.hpp"
#include "app/scene_source.hpp"
#include "io/image.hpp"
#include "io/staged_folder.hpp"
#include "penumbra/error.hpp"
#include "penumbra/gl/context.hpp"
#include "report/study.hpp"
#include "scene/scene_file.hpp"

namespace penumbra {

namespace fs = std::filesystem;

void add_report_command_options(CLI::App& command, ReportArgs& args) {
  add_scene_source_options(command, args.scene, args.model, args.camera_index, args.ground);
  add_light_choice_option(command, args.light);
  in_group(command.add_option("-o,--output", args.output, "folder for index.html and its images")
               ->required()
               ->type_name("FOLDER"),
           OptionGroup::Output);
  in_group(command.add_flag("--quick", args.quick, "smaller images and fewer sweeps"),
           OptionGroup::Output);
  command.footer(examples_footer({
      {"the whole study of the default scene", "penumbra report -o study"},
      {"a quicker draft: smaller images, fewer sweeps", "penumbra report --quick -o draft"},
      {"the study of a model under a point light alone",
       "penumbra report --model scenes/models/bunny.obj --light point -o bunny-study"},
  }));
}

namespace {

// What the command took, on stderr: wall clock, CPU time of all its
// threads, and peak resident memory.
void print_resources_used(const char* what, std::chrono::steady_clock::time_point start) {
  const double wall =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  const auto seconds = [](const timeval& t) { return t.tv_sec + t.tv_usec / 1e6; };
  std::fprintf(stderr, "%s: %.1f s wall, %.1f s CPU, %.0f MB peak memory\n", what, wall,
               seconds(usage.ru_utime) + seconds(usage.ru_stime), usage.ru_maxrss / 1024.0);
}

}  // namespace

int run_report_command(const ReportArgs& args) {
  std::error_code ec;
  if (fs::exists(args.output, ec) && !fs::is_directory(args.output, ec)) {
    throw UsageError("output '" + args.output + "' exists and is not a folder");
  }
  // The folder may be new, but its parent must exist and be writable.
  check_output_path(fs::is_directory(args.output, ec)
                        ? (fs::path(args.output) / "index.html").string()
                        : args.output);
  const auto start = std::chrono::steady_clock::now();
  Scene scene = resolve_scene_source(args.scene, args.model, args.camera_index, args.ground);
  apply_light_choice(args.light, scene);
  auto context = gl::Context::create_headless();
  // Built in a temporary folder, moved into place when the page is
  // written: a failure or an interrupt leaves no partial report.
  StagedFolder folder(args.output);
  const StudyResult result = write_study(scene,
                                         {.scene_argument = args.scene,
                                          .model_argument = args.model,
                                          .light_choice = args.light,
                                          .output_dir = folder.path(),
                                          .quick = args.quick},
                                         *context);
  folder.publish();
  const std::string index_path = folder.final_path("index.html");
  std::printf("%s\n", index_path.c_str());
  print_resources_used("report", start);
  if (result.failed > 0) {
    std::fprintf(stderr,
                 "penumbra: error: %d of %d report items failed; the report says which: %s\n",
                 result.failed, result.items, index_path.c_str());
    return 1;
  }
  return 0;
}

}  // namespace penumbra
