#include "report/study_run.hpp"

#include <malloc.h>

#include <algorithm>
#include <filesystem>

#include "app/command_line.hpp"
#include "app/light_choice.hpp"
#include "io/atomic_file.hpp"
#include "io/image.hpp"
#include "penumbra/error.hpp"
#include "penumbra/shadow/representation.hpp"
#include "penumbra/shadow/shadow_map_pass.hpp"
#include "reference/reference_cache.hpp"

namespace penumbra {

std::string name_of(Technique t) {
  return std::string(enum_name<Technique>(kTechniqueNames, t));
}

int map_bytes_per_texel(Technique t) {
  return bytes_per_texel(is_filterable(t) ? representation_format(t) : ShadowMapPass::kDepthFormat);
}

std::string map_size_text(int size) {
  return std::to_string(size) + "^2";
}

HtmlFigure Study::figure(const std::string& file, const std::string& caption, RenderSettings render,
                         ShadowSettings shadow, std::optional<Image>* shadow_factor) {
  return figure(renderer_, options_.light_choice, file, caption, render, shadow, shadow_factor);
}
HtmlFigure Study::figure(Renderer& renderer, const std::string& light_choice,
                         const std::string& file, const std::string& caption, RenderSettings render,
                         ShadowSettings shadow, std::optional<Image>* shadow_factor) {
  return figure(renderer, options_.scene_argument, options_.model_argument, light_choice, file,
                caption, render, shadow, shadow_factor);
}
HtmlFigure Study::figure(Renderer& renderer, const std::string& scene_argument,
                         const std::string& model_argument, const std::string& light_choice,
                         const std::string& file, const std::string& caption, RenderSettings render,
                         ShadowSettings shadow, std::optional<Image>* shadow_factor) {
  HtmlFigure f;
  f.caption = caption;
  f.command = shell_command(render_command_args({.scene_argument = scene_argument,
                                                 .model_argument = model_argument,
                                                 .light = light_choice,
                                                 .render = render,
                                                 .shadow = shadow,
                                                 .ssao = {},
                                                 .original = nullptr,
                                                 .edited = nullptr,
                                                 .output = file}));
  step();
  try {
    renderer.render(render, drawn(shadow));
    const Image image = renderer.read_view();
    check_gl();
    write_report_png(image, file, png_encoding_for(render.view));
    f.image = file;
    f.width = image.width;
    f.height = image.height;
  } catch (const std::exception& e) {
    f.error = e.what();
    f.command.clear();
    ++failed_;
  }
  if (shadow_factor != nullptr) {
    *shadow_factor = std::nullopt;
    if (f.error.empty()) *shadow_factor = shaded(renderer, View::Shadow);
  }
  return f;
}

std::optional<Image> Study::shaded(Renderer& renderer, View view) {
  return image_or_failure([&] {
    renderer.shade(view);
    return renderer.read_view();
  });
}

HtmlFigure Study::written_figure(const Image& image, const std::string& file,
                                 const std::string& caption, PngEncoding encoding) {
  HtmlFigure f;
  f.caption = caption;
  try {
    write_report_png(image, file, encoding);
    f.image = file;
    f.width = image.width;
    f.height = image.height;
  } catch (const std::exception& e) {
    f.error = e.what();
    ++failed_;
  }
  return f;
}

ShadowSettings Study::drawn(ShadowSettings shadow) const {
  // A rehearsal draws no map larger than its own: what llvmpipe compiles
  // does not depend on the size (kRehearsalSize).
  if (rehearsal()) shadow.map_size = std::min(shadow.map_size, size().map_size);
  return shadow;
}

void Study::write_report_png(const Image& image, const std::string& file, PngEncoding encoding) {
  if (png_writer_) png_writer_->write(image, path_of(file), encoding);
}

TracedReference Study::trace(Renderer& renderer, const RenderSettings& render,
                             const ShadowSettings& shadow) {
  return traced_reference(renderer, render, shadow, traced_samples(),
                          rehearsal() ? std::string() : default_cache_dir());
}

std::string Study::path_of(const std::string& file) const {
  return (std::filesystem::path(options_.output_dir) / file).string();
}

void Study::section(HtmlPage& page, const std::string& id, const std::string& title) {
  if (stop_ != nullptr && *stop_) throw StudyStopped();
  // What compiling took on a rehearsal's thread stays in its own malloc
  // arena until given back: the report's peaks should not sit on it.
  if (rehearsal()) malloc_trim(0);
  // What the last section's techniques left (their filtered arrays) is
  // made again where this one needs it.
  renderer_.release_filtered_maps();
  page.section(id, title);
  if (progress_) progress_->step(title, items_, total_items());
}

void Study::step(int weight) {
  items_ += weight;
  if (progress_) progress_->update(items_, total_items());
}

void Study::check_gl() {
  if (context_.error_count() > errors_seen_) {
    errors_seen_ = context_.error_count();
    throw RuntimeError("OpenGL error: " + context_.last_error());
  }
}

ShadowSettings Study::with(Technique t) const {
  ShadowSettings s = base_shadow_;
  s.technique = t;
  if (is_filterable(t)) s.blur = 4;
  return s;
}
ShadowSettings Study::soft(Technique t) const {
  ShadowSettings s = with(t);
  s.filter = Filter::Sat;
  s.soft = true;
  s.blur = 1;
  return s;
}

const Study::LightAlone& Study::measured_light_alone() {
  if (light_alone_) return *light_alone_;
  LightAlone alone{options_.light_choice, scene_.lights};
  const auto index = static_cast<std::size_t>(base_render_.light_index);
  if (scene_.lights.size() > 1 && index < scene_.lights.size()) {
    // --light TYPE takes the scene's first light of that type.
    const LightType type = scene_.lights[index].type;
    const auto first = std::find_if(scene_.lights.begin(), scene_.lights.end(),
                                    [&](const Light& l) { return l.type == type; });
    if (first - scene_.lights.begin() == static_cast<std::ptrdiff_t>(index)) {
      alone.choice = std::string(enum_name<LightType>(kLightTypeNames, type));
      Scene scene = scene_;
      apply_light_choice(alone.choice, scene);
      alone.lights = scene.lights;
    }
  }
  light_alone_ = std::move(alone);
  return *light_alone_;
}

const TracedReference* Study::base_traced() {
  if (!traced_tried_) {
    traced_tried_ = true;
    step();
    try {
      traced_ = trace(renderer_, base_render_, base_shadow_);
      check_gl();
    } catch (const std::exception& e) {
      ++failed_;
      traced_error_ = e.what();
    }
  }
  return traced_ ? &*traced_ : nullptr;
}
std::optional<ShadowMetrics> Study::measure_against_filtered(
    const ShadowSettings& shadow, const std::optional<Image>& technique) {
  const Image* reference = filtered_reference(shadow);
  if (!technique || !reference) return std::nullopt;
  return compare_shadow(*technique, *reference);
}

const Image* Study::filtered_reference(const ShadowSettings& shadow) {
  ShadowSettings key = shadow;
  key.technique = Technique::Vsm;
  key.esm_c = ShadowSettings{}.esm_c;
  for (const auto& [settings, image] : filtered_references_) {
    if (settings.blur == key.blur && settings.filter == key.filter &&
        settings.map_size == key.map_size && settings.constant_bias == key.constant_bias &&
        settings.slope_bias == key.slope_bias && settings.normal_offset == key.normal_offset &&
        settings.max_slope == key.max_slope) {
      return &image;
    }
  }
  std::optional<Image> image = shadow_image(key, View::ShadowReference);
  if (!image) return nullptr;
  filtered_references_.emplace_back(key, std::move(*image));
  return &filtered_references_.back().second;
}

std::optional<Image> Study::technique_shadow(Technique t) {
  for (auto& [technique, image] : technique_shadows_) {
    if (technique == t) return image;
  }
  return shadow_image(with(t));
}

std::optional<Image> Study::shadow_image(const ShadowSettings& shadow, View view) {
  return shadow_image(renderer_, base_render_, shadow, view);
}
std::optional<Image> Study::shadow_image(Renderer& renderer, const RenderSettings& render,
                                         const ShadowSettings& shadow, View view) {
  const ShadowSettings s = drawn(shadow);
  return image_or_failure([&] {
    return with_light_alone(renderer, render.light_index, [&](int light) {
      RenderSettings r = render;
      r.view = view;
      r.light_index = light;
      renderer.render(r, s);
      return renderer.read_view();
    });
  });
}

}  // namespace penumbra
