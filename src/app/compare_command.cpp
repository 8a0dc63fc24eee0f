#include "app/compare_command.hpp"

#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <optional>
#include <sstream>

#include "app/help_formatter.hpp"
#include "app/light_choice.hpp"
#include "app/option_style.hpp"
#include "app/options.hpp"
#include "app/scene_source.hpp"
#include "core/number_text.hpp"
#include "io/atomic_file.hpp"
#include "io/image.hpp"
#include "io/progress_bar.hpp"
#include "io/staged_folder.hpp"
#include "penumbra/error.hpp"
#include "penumbra/gl/context.hpp"
#include "reference/distance_halves.hpp"
#include "reference/error_image.hpp"
#include "reference/ground_pixels.hpp"
#include "reference/reference_cache.hpp"
#include "reference/shadow_metrics.hpp"
#include "reference/shadow_ray_tracer.hpp"
#include "reference/texel_density_stats.hpp"
#include "reference/traced_reference.hpp"
#include "render/accumulation.hpp"
#include "render/renderer.hpp"
#include "report/edge_errors.hpp"
#include "scene/scene_file.hpp"

namespace penumbra {

namespace fs = std::filesystem;
using nlohmann::json;

namespace {

// One row group of the table: a technique with one filter (or none).
struct Item {
  ShadowSettings settings;
  std::string skipped;  // why the item cannot run (a usage error); empty if it runs
  std::optional<ShadowMetrics> traced, filtered;
  // Against the traced reference on the near and far halves of the view.
  std::optional<ShadowMetrics> traced_near, traced_far;
  // Against the traced reference within 2 pixels of its edges (where it
  // steps by more than a half): where the maps' texels alias.
  std::optional<ShadowMetrics> traced_edges;
  // --shadow-maps virtual: the page pool after the item's frame.
  std::optional<VirtualPageStats> pages;
  json images = json::object();
};

std::string technique_name(Technique t) {
  return std::string(enum_name<Technique>(kTechniqueNames, t));
}

std::string filter_name(Filter f) {
  return std::string(enum_name<Filter>(kFilterNames, f));
}

// File-name stem of an item's images: "hard", "vsm-gaussian-w2", "msm-sat-w2-soft".
std::string item_stem(const ShadowSettings& s) {
  std::string stem = technique_name(s.technique);
  if (is_filterable(s.technique)) {
    stem += "-" + filter_name(s.filter) + "-w" + std::to_string(s.blur);
  }
  if (s.soft) stem += "-soft";
  const bool msm = s.technique == Technique::Msm || s.technique == Technique::Msm16;
  if (s.soft && s.soft_two_moment_blockers && msm) stem += "-2m";
  return stem;
}

// The filter cell of the table: "sat", "sat, soft", "-" for unfiltered techniques.
std::string filter_cell(const ShadowSettings& s) {
  if (!is_filterable(s.technique)) return "-";
  return filter_name(s.filter) + (s.soft ? ", soft" : "");
}

// The output folder: an existing writable folder, or one to be created in
// an existing writable folder. Checked before any work, created after.
void check_output_dir(const std::string& dir) {
  std::error_code ec;
  if (fs::exists(dir, ec)) {
    if (!fs::is_directory(dir, ec)) throw UsageError("output '" + dir + "' is not a folder");
    if (access(dir.c_str(), W_OK) != 0) {
      throw UsageError("output folder '" + dir + "' is not writable");
    }
    return;
  }
  fs::path parent = fs::path(dir).lexically_normal().parent_path();
  if (parent.empty()) parent = ".";
  if (!fs::is_directory(parent, ec)) {
    throw UsageError("output folder '" + parent.string() + "' does not exist");
  }
  if (access(parent.c_str(), W_OK) != 0) {
    throw UsageError("output folder '" + parent.string() + "' is not writable");
  }
}

// Whether the filtered hard-shadow reference (the `shadow-reference` view:
// the map's depth tests averaged with the technique's kernel) is the
// technique's target: for the filterable techniques with a fixed kernel.
// Soft moment shadows (--soft, with the summed-area table) choose each
// pixel's kernel from a penumbra estimate, which that view does not model.
bool has_filtered_reference(const ShadowSettings& s) {
  return is_filterable(s.technique) && !(s.soft && s.filter == Filter::Sat);
}

// Pixels not compared in `mask` (alpha 0) become not compared in `image`.
void restrict_to(Image& image, const Image& mask) {
  for (std::size_t i = 3; i < image.rgba.size(); i += 4) {
    image.rgba[i] = std::min(image.rgba[i], mask.rgba[i]);
  }
}

json metrics_json(const ShadowMetrics& m) {
  return {{"pixels", m.pixels},
          {"mae", m.mean_absolute_error},
          {"rmse", m.rmse},
          {"max_error", m.max_error},
          {"leak_fraction", m.leak_fraction},
          {"over_dark_fraction", m.over_dark_fraction}};
}

// The reason in a validate() message, without its explanation.
std::string short_reason(const std::string& message) {
  const std::size_t colon = message.find(": ");
  return colon == std::string::npos ? message : message.substr(0, colon);
}

// A table row. In a row that `spans`, the last cell runs on past the
// columns (a note) and does not widen them.
struct Row {
  std::vector<std::string> cells;
  bool spans = false;
};

// Prints the rows in aligned columns; columns from `first_numeric` on are
// right-aligned.
void print_table(const std::vector<Row>& rows, std::size_t first_numeric) {
  std::vector<std::size_t> widths;
  for (const Row& row : rows) {
    const std::size_t n = row.cells.size() - (row.spans ? 1 : 0);
    widths.resize(std::max(widths.size(), n), 0);
    for (std::size_t c = 0; c < n; ++c) widths[c] = std::max(widths[c], row.cells[c].size());
  }
  for (const Row& row : rows) {
    std::string line;
    for (std::size_t c = 0; c < row.cells.size(); ++c) {
      const std::string& cell = row.cells[c];
      if (c > 0) line += "  ";
      const bool last = c + 1 == row.cells.size();
      const std::size_t pad = last && row.spans ? 0 : widths[c] - cell.size();
      if (c >= first_numeric) line.append(pad, ' ');
      line += cell;
      if (c < first_numeric && !last) line.append(pad, ' ');
    }
    std::printf("%s\n", line.c_str());
  }
}

std::string percent(double fraction) {
  return fixed(100.0 * fraction, 3) + "%";
}

std::vector<std::string> metrics_row(const Item& item, const char* reference,
                                     const ShadowMetrics& m, bool first) {
  const ShadowSettings& s = item.settings;
  const bool filtered = is_filterable(s.technique);
  return {first ? technique_name(s.technique) : "",
          first ? filter_cell(s) : "",
          first ? (filtered ? std::to_string(s.blur) : "-") : "",
          reference,
          fixed(m.mean_absolute_error, 4),
          fixed(m.rmse, 4),
          fixed(m.max_error, 3),
          percent(m.leak_fraction),
          percent(m.over_dark_fraction)};
}

}  // namespace

void add_compare_command_options(CLI::App& command, CompareArgs& args) {
  add_scene_source_options(command, args.scene, args.model, args.camera_index, args.ground);
  add_light_choice_option(command, args.light);
  // The camera and light flags `render` takes, so that the view a user
  // rendered can be measured as it is.
  add_scene_options(command, args.scene_options);
  add_list(command, "technique", args.techniques,
           "techniques to measure (all: every technique but none)", technique_names(),
           OptionGroup::Technique, "techniques");
  add_list(command, "filter", args.filters,
           "filters of the vsm, esm, msm, msm16, evsm2 and evsm4 maps, each measured",
           filter_names(), OptionGroup::Filter);
  in_group(command
               .add_option("-o,--output", args.output_dir,
                           "folder for the images (created if missing): each technique's shadow, "
                           "its references and error maps (technique - reference: blue too dark, "
                           "red too light, saturating at +-0.5)")
               ->type_name("FOLDER"),
           OptionGroup::Output);
  in_group(command.add_option("--json", args.json, "write the numbers to this file as JSON")
               ->type_name("FILE"),
           OptionGroup::Output);
  in_group(command.add_flag("--verbose", args.verbose, "print the GPU in use and driver messages"),
           OptionGroup::Output);
  in_group(command.add_flag("--by-distance", args.by_distance,
                            "also measure the near and far halves of the compared pixels, split "
                            "at their median distance from the camera (the JSON always has them)"),
           OptionGroup::Output);
  in_group(command
               .add_option("--cache-dir", args.cache_dir,
                           "where traced references are kept (default: $XDG_CACHE_HOME/penumbra, "
                           "or ~/.cache/penumbra)")
               ->type_name("FOLDER"),
           OptionGroup::Reference);
  add_switch(command, "cache",
             "reuse a traced reference cached by an earlier run (--no-cache: trace it again)",
             args.cache, OptionGroup::Reference);
  add_render_parameters(command, args.render);
  add_shadow_maps_option(command, args.shadow, args.shadow_maps,
                         "; the other techniques in the list are skipped");
  add_shadow_parameters(command, args.shadow);
  add_accumulate_option(command, args.shadow);
  add_reference_options(command, args.reference);
  command.footer(examples_footer(
      {
          {"every technique against the traced reference, images in a folder",
           "penumbra compare -o compare"},
          {"two moment techniques with both filters, numbers as JSON",
           "penumbra compare --technique vsm,msm --filter all --json compare.json"},
          {"soft shadows of a light 0.8 wide, against the traced area light",
           "penumbra compare --technique pcss,msm --filter sat --soft --light-size 0.8"},
      },
      "--soft applies to vsm, msm and msm16 with --filter sat, which are then measured soft "
      "(against the traced reference only: the filtered reference has one fixed kernel); the "
      "other techniques and filters in the lists are measured as usual, and the table marks "
      "the soft rows. At least one chosen technique and filter must be able to be soft."));
}

namespace {

// The items to run: each technique once, or once per filter for the
// filterable ones; an item the settings forbid is kept, marked skipped.
std::vector<Item> plan_items(const CompareArgs& args) {
  std::vector<Item> items;
  for (Technique t : parse_technique_list(args.techniques, "--technique")) {
    for (Filter f : parse_filter_list(args.filters, "--filter")) {
      Item item;
      item.settings = args.shadow;
      item.settings.technique = t;
      item.settings.filter = f;
      // --soft is for the techniques that can be soft; the rest run as usual.
      item.settings.soft = args.shadow.soft && supports_soft_shadows(t, f);
      try {
        validate(item.settings);
      } catch (const UsageError& e) {
        item.skipped = e.what();
      }
      items.push_back(item);
      if (!is_filterable(t)) break;  // the filter does not apply: one item
    }
  }
  const bool any =
      std::any_of(items.begin(), items.end(), [](const Item& i) { return i.skipped.empty(); });
  if (!any) throw UsageError("nothing to compare: " + items.front().skipped);
  const bool any_soft = std::any_of(items.begin(), items.end(), [](const Item& i) {
    return i.skipped.empty() && i.settings.soft;
  });
  if (args.shadow.soft && !any_soft) {
    throw UsageError(
        "--soft needs vsm, msm or msm16 in --technique and sat in --filter (the penumbra-sized "
        "filter is read from the summed-area table)");
  }
  return items;
}

// Renders each item's shadow (and its filtered reference), measures them
// against the references and writes the images into `folder` (none if
// null), naming their final paths in the items.
void measure_items(Renderer& renderer, const CompareArgs& args, const Image& traced,
                   const DistanceHalves& halves, std::vector<Item>& items,
                   const StagedFolder* folder) {
  // The images compared (shadows and references) also go out as 32-bit
  // float EXR, unclamped and unquantized, for measuring them elsewhere;
  // the error images are colour maps and go out as PNG only.
  auto write = [&](const Image& image, const std::string& name, Item* item, const char* role,
                   bool compared) {
    if (folder == nullptr) return;
    write_png(image, (fs::path(folder->path()) / (name + ".png")).string(), PngEncoding::Linear);
    if (compared) write_exr(image, (fs::path(folder->path()) / (name + ".exr")).string());
    if (item != nullptr) item->images[role] = folder->final_path(name + ".png");
  };
  write(traced, "reference-traced", nullptr, "", true);
  RenderSettings view = args.render;
  for (Item& item : items) {
    if (!item.skipped.empty()) continue;
    const std::string stem = item_stem(item.settings);
    view.view = View::Shadow;
    Image shadow = render_accumulated(renderer, view, item.settings);
    if (!renderer.virtual_lights().empty()) item.pages = renderer.virtual_page_stats();
    restrict_to(shadow, traced);
    item.traced = compare_shadow(shadow, traced);
    item.traced_near = compare_shadow(only_half(shadow, halves, false), traced);
    item.traced_far = compare_shadow(only_half(shadow, halves, true), traced);
    item.traced_edges = compare_shadow(at_reference_edges(shadow, traced, 2), traced);
    write(shadow, stem, &item, "shadow", true);
    write(error_image(shadow, traced), stem + "-error-traced", &item, "error_traced", false);
    if (has_filtered_reference(item.settings)) {
      view.view = View::ShadowReference;
      renderer.render(view, item.settings);
      Image filtered = renderer.read_view();
      restrict_to(filtered, traced);
      item.filtered = compare_shadow(shadow, filtered);
      write(filtered, stem + "-reference-filtered", &item, "reference_filtered", true);
      write(error_image(shadow, filtered), stem + "-error-filtered", &item, "error_filtered",
            false);
    }
  }
}

// What the view itself measures, whatever the technique: its near and far
// halves, and the light's shadow-map texels per pixel.
struct ViewMeasures {
  DistanceHalves halves;
  TexelDensityStats density;
};

// The light's texel densities in the view (Renderer::read_texel_density)
// at the settings of the last item measured (its maps are still current),
// over the reference's pixels; with a folder, their false colour image too.
TexelDensityStats measure_texel_density(Renderer& renderer, const CompareArgs& args,
                                        const std::vector<Item>& items, const Image& traced,
                                        const std::vector<std::uint8_t>& ground,
                                        const StagedFolder* folder) {
  ShadowSettings shadow = args.shadow;
  for (const Item& item : items) {
    if (item.skipped.empty()) shadow = item.settings;
  }
  shadow.accumulate = 1;
  RenderSettings view = args.render;
  view.view = View::TexelDensity;
  renderer.render(view, shadow);
  if (folder != nullptr) {
    write_png(renderer.read_view(), (fs::path(folder->path()) / "texel-density.png").string(),
              PngEncoding::Linear);
  }
  return texel_density_stats(renderer.read_texel_density(), traced, ground);
}

json share_json(const TexelDensityShare& s) {
  return {{"pixels", s.pixels}, {"median", s.median}, {"at_least_one", s.at_least_one}};
}

std::string light_type_name(LightType type) {
  return std::string(enum_name<LightType>(kLightTypeNames, type));
}

// Shadow rays traced per second of `seconds` (0 if it took no measurable
// time).
double rays_per_second(const TracedReference& reference, double seconds) {
  return seconds > 0.0 ? static_cast<double>(reference.rays_traced) / seconds : 0.0;
}

void print_report(const CompareArgs& args, const Scene& scene, const TracedReference& reference,
                  const ViewMeasures& measures, const std::vector<Item>& items) {
  const int light_index = args.render.light_index;
  std::printf("scene %s, light %d (%s), %dx%d pixels, %d^2 shadow maps\n", scene.name.c_str(),
              light_index,
              light_type_name(scene.lights[static_cast<std::size_t>(light_index)].type).c_str(),
              args.render.width, args.render.height, args.shadow.map_size);
  const ReferenceLight& light = reference.light;
  if (light.size > 0.0f && light.type == LightType::Spot) {
    std::printf("traced reference: square light %g wide, %d rays per pixel", light.size,
                reference.rays);
  } else if (light.size > 0.0f && light.type == LightType::Point) {
    std::printf("traced reference: spherical light %g in diameter, %d rays per pixel", light.size,
                reference.rays);
  } else if (light.size > 0.0f) {
    std::printf("traced reference: sun %g degrees wide, %d rays per pixel",
                static_cast<double>(glm::degrees(light.size)), reference.rays);
  } else {
    std::printf("traced reference: point light, 1 ray per pixel");
  }
  const std::string how =
      reference.cached
          ? "cached"
          : fixed(reference.seconds, 1) + " s, " +
                fixed(rays_per_second(reference, reference.trace_seconds) * 1e-6, 1) + " M rays/s";
  std::printf(", %s; %ld pixels compared (geometry the light reaches)", how.c_str(),
              reference.pixels);
  if (reference.unjudged_pixels > 0) {
    std::printf("; %lld not judged (surface point not finite or outside the scene)",
                static_cast<long long>(reference.unjudged_pixels));
  }
  std::printf("\n\n");
  std::vector<Row> rows = {
      {{"technique", "filter", "W", "reference", "MAE", "RMSE", "max", "leak", "over-dark"}}};
  for (const Item& item : items) {
    if (!item.skipped.empty()) {
      rows.push_back(
          {{technique_name(item.settings.technique), filter_cell(item.settings),
            std::to_string(item.settings.blur), "skipped: " + short_reason(item.skipped)},
           true});
      continue;
    }
    rows.push_back({metrics_row(item, "traced", *item.traced, true)});
    if (args.by_distance) {
      rows.push_back({metrics_row(item, "traced, near", *item.traced_near, false)});
      rows.push_back({metrics_row(item, "traced, far", *item.traced_far, false)});
    }
    if (item.filtered) rows.push_back({metrics_row(item, "filtered", *item.filtered, false)});
  }
  print_table(rows, 4);
  std::printf(
      "\ntraced: against the ray-traced shadow; filtered: against the map's own depth tests "
      "averaged with the technique's filter kernel. leak: reference < %.1f while the technique "
      "> %.1f; over-dark: reference > %.1f while the technique < %.1f.\n",
      kLeakReferenceBelow, kLeakTechniqueAbove, kOverDarkReferenceAbove, kOverDarkTechniqueBelow);
  if (args.by_distance) {
    std::printf(
        "near, far: the compared pixels up to and beyond their median distance from the camera, "
        "%s units (%ld and %ld pixels).\n",
        fixed(measures.halves.median_distance, 3).c_str(), measures.halves.near_pixels,
        measures.halves.far_pixels);
  }
  const TexelDensityStats& d = measures.density;
  std::printf(
      "texel density (shadow-map texels per pixel, an area ratio): median %s; at least 1 on "
      "%s of the compared pixels and on %s of the %ld shadowed ones (reference < 1).\n",
      fixed(d.judged.median, 3).c_str(), percent(d.judged.at_least_one).c_str(),
      percent(d.shadowed.at_least_one).c_str(), d.shadowed.pixels);
  if (d.shadowed_ground.pixels > 0) {
    std::printf("On the ground (its plane): at least 1 on %s of the %ld shadowed pixels.\n",
                percent(d.shadowed_ground.at_least_one).c_str(), d.shadowed_ground.pixels);
  }
  for (const Item& item : items) {
    if (!item.pages) continue;
    std::printf(
        "virtual pages after %s: %d of the pool's %d resident, %d rendered in its frame, %d "
        "requested pages left without one; levels %g finer than one texel per pixel.\n",
        technique_name(item.settings.technique).c_str(), item.pages->resident,
        item.pages->pool_pages, item.pages->rendered, item.pages->unserved, 0.5 * item.pages->bias);
  }
  std::fflush(stdout);
}

json json_report(const CompareArgs& args, const Scene& scene, const TracedReference& reference,
                 const ViewMeasures& measures, const std::vector<Item>& items) {
  json results = json::array();
  for (const Item& item : items) {
    const ShadowSettings& s = item.settings;
    json r = {{"technique", technique_name(s.technique)}};
    r["filter"] = is_filterable(s.technique) ? json(filter_name(s.filter)) : json(nullptr);
    r["blur"] = is_filterable(s.technique) ? json(s.blur) : json(nullptr);
    r["soft"] = s.soft;
    r["soft_two_moment_blockers"] = s.soft && s.soft_two_moment_blockers;
    r["contact_shadows"] = s.contact_shadows;
    if (!item.skipped.empty()) {
      r["status"] = "skipped";
      r["reason"] = item.skipped;
    } else {
      r["status"] = "ok";
      r["traced"] = metrics_json(*item.traced);
      r["traced_edges"] = metrics_json(*item.traced_edges);
      r["filtered"] = item.filtered ? metrics_json(*item.filtered) : json(nullptr);
      r["traced_near"] = metrics_json(*item.traced_near);
      r["traced_far"] = metrics_json(*item.traced_far);
      r["virtual_pages"] = item.pages ? json{{"pool", item.pages->pool_pages},
                                             {"resident", item.pages->resident},
                                             {"rendered", item.pages->rendered},
                                             {"unserved", item.pages->unserved},
                                             {"level_bias", 0.5 * item.pages->bias}}
                                      : json(nullptr);
      if (!args.output_dir.empty()) r["images"] = item.images;
    }
    results.push_back(r);
  }
  const int light_index = args.render.light_index;
  return {
      {"scene", scene.name},
      {"light_index", light_index},
      {"light_type", light_type_name(scene.lights[static_cast<std::size_t>(light_index)].type)},
      {"camera",
       {{"position", {scene.camera.position.x, scene.camera.position.y, scene.camera.position.z}},
        {"target", {scene.camera.target.x, scene.camera.target.y, scene.camera.target.z}},
        {"fov_y_degrees", scene.camera.fov_y_degrees}}},
      {"width", args.render.width},
      {"height", args.render.height},
      {"shadow_map_size", args.shadow.map_size},
      {"shadow_msaa", args.shadow.shadow_msaa},
      {"shadow_maps", args.shadow_maps},
      {"page_pool_mib", args.shadow.page_pool_mib},
      {"tight_cascades", args.shadow.tight_cascades},
      // The judged light's own source size, under --light-size/--sun-angle.
      {"light_size",
       with_source_size(scene.lights[static_cast<std::size_t>(light_index)], args.shadow)
           .light_size},
      {"sun_angle",
       with_source_size(scene.lights[static_cast<std::size_t>(light_index)], args.shadow)
           .sun_angle},
      {"reference",
       {{"rays_per_pixel", reference.rays},
        {"pixels", reference.pixels},
        // Pixels seeing geometry whose surface point is not finite or lies
        // outside the scene: not traced, not judged.
        {"unjudged_pixels", reference.unjudged_pixels},
        {"cached", reference.cached},
        {"seconds", reference.seconds},
        // The tracer's speed (null when the reference came from the cache).
        {"rays_traced", reference.cached ? json(nullptr) : json(reference.rays_traced)},
        {"rays_per_second", reference.cached
                                ? json(nullptr)
                                : json(rays_per_second(reference, reference.trace_seconds))},
        {"rays_per_cpu_second",
         reference.cached ? json(nullptr)
                          : json(rays_per_second(reference, reference.trace_cpu_seconds))},
        {"image", args.output_dir.empty()
                      ? json(nullptr)
                      : json((fs::path(args.output_dir) / "reference-traced.png").string())}}},
      // The compared pixels split at their median distance from the camera
      // (results' traced_near and traced_far).
      {"distance_halves",
       {{"median_distance", measures.halves.median_distance},
        {"near_pixels", measures.halves.near_pixels},
        {"far_pixels", measures.halves.far_pixels}}},
      // Shadow-map texels per pixel of the light, over the compared pixels
      // and the shadowed ones (reference below 1).
      {"texel_density",
       {{"judged", share_json(measures.density.judged)},
        {"shadowed", share_json(measures.density.shadowed)},
        {"shadowed_ground", share_json(measures.density.shadowed_ground)},
        {"image", args.output_dir.empty()
                      ? json(nullptr)
                      : json((fs::path(args.output_dir) / "texel-density.png").string())}}},
      {"results", results},
  };
}

}  // namespace

int run_compare_command(CompareArgs& args) {
  // Every usage error first, so that none leaves output behind. The
  // technique, filter and --soft are checked per item (plan_items).
  validate(args.render);
  args.shadow.shadow_maps = parse_shadow_map_kind(args.shadow_maps);
  ShadowSettings common = args.shadow;
  common.soft = false;
  validate(common);
  validate(args.reference);
  std::vector<Item> items = plan_items(args);
  if (!args.output_dir.empty()) check_output_dir(args.output_dir);
  if (!args.json.empty()) check_output_path(args.json);
  Scene scene = resolve_scene_source(args.scene, args.model, args.camera_index, args.ground);
  apply_light_choice(args.light, scene);
  const int light_index = args.render.light_index;
  check_light_index(light_index, scene);
  apply_scene_options(args.scene_options, light_index, scene);
  const std::string cache_dir =
      !args.cache ? std::string() : (args.cache_dir.empty() ? default_cache_dir() : args.cache_dir);

  auto context = gl::Context::create_headless({.debug = true, .verbose = args.verbose});
  if (args.verbose) {
    std::fprintf(stderr, "penumbra: %s via %s (%s)\n", context->renderer().c_str(),
                 context->platform().c_str(), context->version().c_str());
  }
  Renderer renderer(scene);
  const TracedReference reference =
      traced_reference(renderer, args.render, args.shadow, args.reference.samples, cache_dir);
  // The images go to a temporary folder, moved into place once all are
  // written: a failure or an interrupt leaves no partial folder.
  std::optional<StagedFolder> folder;
  if (!args.output_dir.empty()) folder.emplace(args.output_dir);
  ViewMeasures measures;
  const SurfacePoints surfaces = renderer.read_surfaces();
  measures.halves =
      split_at_median_distance(surfaces, renderer.scene().camera.position, reference.image);
  const std::vector<std::uint8_t> ground = ground_pixels(renderer.scene(), surfaces);
  measure_items(renderer, args, reference.image, measures.halves, items,
                folder ? &*folder : nullptr);
  measures.density = measure_texel_density(renderer, args, items, reference.image, ground,
                                           folder ? &*folder : nullptr);
  if (context->error_count() > 0) {
    throw RuntimeError("OpenGL reported " + std::to_string(context->error_count()) +
                       " error(s); last: " + context->last_error());
  }
  if (folder) folder->publish();
  print_report(args, scene, reference, measures, items);
  if (!args.json.empty()) {
    write_file_atomically(args.json,
                          json_report(args, scene, reference, measures, items).dump(2) + "\n");
  }
  return 0;
}

}  // namespace penumbra
