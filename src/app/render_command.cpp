#include "app/render_command.hpp"

#include <cstdio>
#include <optional>
#include <string>

#include "app/help_formatter.hpp"
#include "app/light_choice.hpp"
#include "app/option_style.hpp"
#include "app/scene_source.hpp"
#include "io/image.hpp"
#include "penumbra/error.hpp"
#include "penumbra/gl/context.hpp"
#include "reference/texel_density_stats.hpp"
#include "render/accumulation.hpp"
#include "render/renderer.hpp"
#include "scene/builtin_scenes.hpp"
#include "scene/scene_file.hpp"

namespace penumbra {

void add_render_command_options(CLI::App& command, RenderArgs& args) {
  add_scene_source_options(command, args.scene, args.model, args.camera_index, args.ground);
  add_light_choice_option(command, args.light);
  in_group(command
               .add_option("-o,--output", args.output,
                           "output image: .png, or .exr for raw 32-bit floats")
               ->required()
               ->type_name("FILE"),
           OptionGroup::Output);
  in_group(command.add_flag("--verbose", args.verbose, "print the GPU in use and driver messages"),
           OptionGroup::Output);
  in_group(command.add_flag("--quiet", args.quiet,
                            "print nothing on success (by default one line: the file written)"),
           OptionGroup::Output);
  add_render_options(command, args.render, args.named);
  add_shadow_options(command, args.shadow, args.named);
  add_accumulate_option(command, args.shadow);
  add_ssao_options(command, args.ssao);
  add_scene_options(command, args.scene_options);
  command.footer(examples_footer({
      {"the default scene, hard shadows", "penumbra render -o hard.png"},
      {"soft shadows from a light 1 unit wide, by PCSS",
       "penumbra render --technique pcss --light-size 1 -o pcss.png"},
      {"moment shadows whose penumbra grows with the blocker distance",
       "penumbra render --technique msm --filter sat --soft -o msm-soft.png"},
  }));
}

int run_render_command(RenderArgs& args) {
  parse_named_options(args.named, args.shadow, args.render);
  validate(args.render);
  validate(args.shadow);
  validate(args.ssao);
  image_format_for(args.output);
  check_output_path(args.output);
  Scene scene = resolve_scene_source(args.scene, args.model, args.camera_index, args.ground);
  apply_light_choice(args.light, scene);
  check_light_index(args.render.light_index, scene);
  apply_scene_options(args.scene_options, args.render.light_index, scene);

  auto context = gl::Context::create_headless({.debug = true, .verbose = args.verbose});
  if (args.verbose) {
    std::fprintf(stderr, "penumbra: %s via %s (%s)\n", context->renderer().c_str(),
                 context->platform().c_str(), context->version().c_str());
  }
  Renderer renderer(scene);
  Image image = render_accumulated(renderer, args.render, args.shadow, args.ssao);
  std::optional<TexelDensityShare> density;
  if (args.render.view == View::TexelDensity) {
    density = texel_density_share(renderer.read_texel_density());
  }
  if (context->error_count() > 0) {
    throw RuntimeError("OpenGL reported " + std::to_string(context->error_count()) +
                       " error(s); last: " + context->last_error());
  }
  write_image(image, args.output, png_encoding_for(args.render.view));
  if (!args.quiet) {
    // One line on stdout, so a script can read the path and a person sees
    // that something was written and what.
    std::printf("wrote %s (%dx%d, %s, technique %s)\n", args.output.c_str(), image.width,
                image.height, std::string(enum_name<View>(kViewNames, args.render.view)).c_str(),
                std::string(enum_name<Technique>(kTechniqueNames, args.shadow.technique)).c_str());
    if (density) {
      std::printf(
          "texel density (shadow-map texels per pixel, an area ratio): median %.3f; at least 1 "
          "on %.1f%% of the %ld pixels that see geometry\n",
          density->median, 100.0 * density->at_least_one, density->pixels);
    }
  }
  return 0;
}

}  // namespace penumbra
