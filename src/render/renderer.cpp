#include "render/renderer.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <glm/gtc/matrix_transform.hpp>
#include <stdexcept>
#include <string>

#include "penumbra/error.hpp"
#include "penumbra/filter/gaussian.hpp"
#include "penumbra/shadow/moment_math.hpp"
#include "penumbra/shadow/poisson_disc.hpp"
#include "penumbra/shadow/representation.hpp"
#include "penumbra/shadow/shadow_block_data.hpp"
#include "penumbra/shared/bindings.h"
#include "penumbra/shared/gpu_types.h"
#include "render/camera_depth.hpp"
#include "render/depth_position_error.hpp"

namespace penumbra {

static_assert(sizeof(gpu::GpuLight) == 6 * 16, "GpuLight must match std140");
static_assert(sizeof(gpu::GpuShadowView) == 3 * 64 + 2 * 16, "GpuShadowView must match std140");
static_assert(sizeof(gpu::GpuFrame) == 3 * 64 + 5 * 16, "GpuFrame must match std140");
static_assert(sizeof(gpu::GpuShadow) == 144, "GpuShadow must match std140");

namespace {

// The lighting pass's virtual maps: penumbra's own bindings, with the
// pages' depth bounds backprojection reads.
const VirtualBindings kVirtualBindings{.block = BINDING_VIRTUAL_UBO,
                                       .page_table_unit = UNIT_VIRTUAL_PAGE_TABLE,
                                       .pool_unit = UNIT_VIRTUAL_POOL,
                                       .bounds_unit = UNIT_VIRTUAL_BOUNDS};

// The shadow block's fields for --accumulate's sub-frame (the renderer's
// own: ShadowMaps leaves them 0).
void set_subframe_params(gpu::GpuShadow& block, const ShadowSettings& shadow) {
  block.accumulate_u = shadow.subframe_u;
  block.accumulate_v = shadow.subframe_v;
  block.accumulate_normal_x = shadow.subframe_normal[0];
  block.accumulate_normal_y = shadow.subframe_normal[1];
  block.accumulate_normal_z = shadow.subframe_normal[2];
  block.accumulate_frame = shadow.subframe;
  block.accumulate_cell_x = shadow.subframe_cell[0];
  block.accumulate_cell_y = shadow.subframe_cell[1];
  block.accumulate_cell_width = shadow.subframe_cell[2];
  block.accumulate_cell_height = shadow.subframe_cell[3];
  block.accumulate_column = shadow.subframe_cell_index[0];
  block.accumulate_columns = shadow.subframe_cell_index[1];
  block.accumulate_row = shadow.subframe_cell_index[2];
  block.accumulate_rows = shadow.subframe_cell_index[3];
}

// One layer (0 for a 2D texture) of a texture as an image.
Image read_texture(GLuint texture, int width, int height, GLenum format, int layer = 0) {
  Image image(width, height);
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  if (format != GL_DEPTH_COMPONENT) {
    // Straight into the image, then its rows swapped in place: a second
    // copy of a large view (a point light's six faces tiled are 400 MB of
    // RGBA32F) would double the read-back's memory.
    glGetTextureSubImage(texture, 0, 0, 0, layer, width, height, 1, GL_RGBA, GL_FLOAT,
                         static_cast<GLsizei>(image.rgba.size() * sizeof(float)),
                         image.rgba.data());
    // GL rows run bottom to top; images run top to bottom.
    const std::size_t row = static_cast<std::size_t>(width) * 4;
    for (int y = 0; y < height / 2; ++y) {
      std::swap_ranges(image.rgba.begin() + static_cast<std::ptrdiff_t>(y * row),
                       image.rgba.begin() + static_cast<std::ptrdiff_t>((y + 1) * row),
                       image.rgba.begin() + static_cast<std::ptrdiff_t>((height - 1 - y) * row));
    }
    return image;
  }
  // A depth texture: its one channel as grey.
  std::vector<float> raw(static_cast<std::size_t>(width) * height);
  glGetTextureSubImage(texture, 0, 0, 0, layer, width, height, 1, GL_DEPTH_COMPONENT, GL_FLOAT,
                       static_cast<GLsizei>(raw.size() * sizeof(float)), raw.data());
  for (int y = 0; y < height; ++y) {
    const float* src = raw.data() + static_cast<std::size_t>(height - 1 - y) * width;
    for (int x = 0; x < width; ++x) {
      float* dst = image.pixel(x, y);
      dst[0] = dst[1] = dst[2] = src[x];
      dst[3] = 1.0f;
    }
  }
  return image;
}

int view_define(View view) {
  switch (view) {
    case View::Shadow:
      return VIEW_SHADOW;
    case View::ShadowReference:
      return VIEW_SHADOW_REFERENCE;
    case View::Normals:
      return VIEW_NORMALS;
    case View::Albedo:
      return VIEW_ALBEDO;
    case View::Ao:
      return VIEW_AO;
    case View::Cascades:
      return VIEW_CASCADES;
    case View::Pages:
      return VIEW_PAGES;
    case View::TexelDensity:
      return VIEW_TEXEL_DENSITY;
    default:
      return VIEW_FINAL;
  }
}

}  // namespace

PngEncoding png_encoding_for(View view) {
  return view == View::Final || view == View::Albedo ? PngEncoding::Srgb : PngEncoding::Linear;
}

Renderer::Renderer(const Scene& scene)
    : scene_(scene),
      mesh_(build_scene_mesh(scene, &shape_first_vertex_)),
      bounds_(mesh_.bounds()),
      gpu_scene_(scene_, mesh_, -1, shape_first_vertex_),
      frame_ubo_(sizeof(gpu::GpuFrame), nullptr, true, "frame block"),
      lights_ubo_(sizeof(gpu::GpuLight) * MAX_LIGHTS, nullptr, true, "lights block"),
      shadow_ubo_(sizeof(gpu::GpuShadow), nullptr, true, "shadow block"),
      views_ubo_(sizeof(gpu::GpuShadowView) * MAX_SHADOW_VIEWS, nullptr, true,
                 "shadow views block"),
      reference_weights_(sizeof(float) * (2 * kMaxBlur + 1), nullptr, true,
                         "reference filter weights"),
      poisson_(gl::Buffer::from(std::span<const glm::vec2>(poisson_square_samples()),
                                "poisson samples")) {
  virtual_pass_.set_draws(gpu_scene_.indirect_commands(), gpu_scene_.draw_bounds(mesh_));
  // Queried once: a query in the frame loop would stall a GPU's pipeline.
  glGetIntegerv(GL_MAX_TEXTURE_SIZE, &max_texture_size_);
  set_lights(scene_.lights);
}

void Renderer::set_lights(const std::vector<Light>& lights) {
  if (lights.size() > MAX_LIGHTS) {
    throw UsageError("scene '" + scene_.name + "' has " + std::to_string(lights.size()) +
                     " lights; at most " + std::to_string(MAX_LIGHTS) + " are supported");
  }
  scene_.lights = lights;
}

void Renderer::fit_virtual_lights(const ShadowSettings& shadow, const CameraFrustum& camera,
                                  int image_height) {
  // Last frame's maps per light: a spot map keeps its depth range while
  // it serves (fit_virtual_spot_map).
  std::vector<VirtualLightMaps> previous = std::move(virtual_lights_);
  virtual_lights_.clear();
  if (shadow.shadow_maps != ShadowMapKind::Virtual) return;
  const auto previous_of = [&](int light) -> const VirtualClipmap* {
    for (const VirtualLightMaps& p : previous)
      if (p.light_index == light) return &p.maps;
    return nullptr;
  };
  if (virtual_light_ >= 0) {
    virtual_lights_.push_back(
        {virtual_light_,
         with_source_size(scene_.lights[static_cast<std::size_t>(virtual_light_)], shadow),
         virtual_clipmap_});
  }
  for (std::size_t i = 0; i < scene_.lights.size(); ++i) {
    const Light& light = scene_.lights[i];
    if (light.type != LightType::Spot) continue;
    const int index = static_cast<int>(i);
    virtual_lights_.push_back({index, with_source_size(light, shadow),
                               fit_virtual_spot_map(light_views_[i].views.front(), camera,
                                                    image_height, previous_of(index))});
  }
}

Bounds Renderer::shape_bounds(std::size_t shape) const {
  if (shape >= scene_.shapes.size()) {
    throw UsageError("scene '" + scene_.name + "' has no shape " + std::to_string(shape));
  }
  Bounds bounds;
  for (std::size_t v = shape_first_vertex_[shape]; v < shape_first_vertex_[shape + 1]; ++v) {
    bounds.extend(mesh_.vertices[v].position);
  }
  return bounds;
}

void Renderer::move_shape(std::size_t shape, const glm::vec3& offset) {
  const Bounds before = shape_bounds(shape);
  const std::size_t first = shape_first_vertex_[shape];
  const std::size_t count = shape_first_vertex_[shape + 1] - first;
  for (std::size_t v = first; v < first + count; ++v) mesh_.vertices[v].position += offset;
  scene_.shapes[shape].position += offset;
  gpu_scene_.update_vertices(first, std::span<const Vertex>(mesh_.vertices).subspan(first, count));
  const Bounds after = shape_bounds(shape);
  shadow_cache_.caster_moved({before.min, before.max}, {after.min, after.max});
  virtual_pass_.caster_moved(before.min, before.max, after.min, after.max);
  const std::vector<CasterBounds> draw_bounds = gpu_scene_.draw_bounds(mesh_);
  for (std::size_t d = 0; d < draw_bounds.size(); ++d) {
    if (gpu_scene_.draw_shape(d) == shape) virtual_pass_.set_draw_bounds(d, draw_bounds[d]);
  }
  bounds_ = mesh_.bounds();
  // Every fit read the old position: the lights' views, the camera's
  // depth range, and the G-buffer drawn from it.
  std::fill(fit_inputs_.begin(), fit_inputs_.end(), std::nullopt);
  caster_bounds_.clear();
  depth_range_.valid = false;
  forget_surfaces();
}

glm::mat4 Renderer::camera_view() const {
  return glm::lookAt(scene_.camera.position, scene_.camera.target, scene_.camera.up);
}

void Renderer::camera_depth_range(int width, int height, float& near_plane,
                                  float& far_plane) const {
  // Near and far planes hug the geometry inside the view frustum, so depth
  // precision is not wasted: the nearest bounding-box corner is often
  // behind the camera, and a near plane at 1e-4 of the far one put the
  // default scene's far ground 4e-3 units off once rebuilt from the depth
  // buffer (more than the reference tracer's ray offset).
  if (depth_range_.valid && depth_range_.camera == scene_.camera && depth_range_.width == width &&
      depth_range_.height == height) {
    near_plane = depth_range_.near_plane;
    far_plane = depth_range_.far_plane;
    return;
  }
  const glm::mat4 view = camera_view();
  const float fov_y = glm::radians(scene_.camera.fov_y_degrees);
  const float aspect = static_cast<float>(width) / static_cast<float>(height);
  const float ky = std::tan(0.5f * fov_y);
  float zmin = 1e30f, zmax = 0.0f;
  const CasterHierarchy& bounds =
      caster_bounds_.bounds(PositionSpan(mesh_.vertices), mesh_.indices, glm::mat4(1.0f));
  if (!frustum_depth_range(view, aspect * ky, ky, mesh_.vertices, mesh_.indices, bounds, zmin,
                           zmax)) {
    zmin = 0.1f;  // nothing in view
    zmax = 1.0f;
  }
  far_plane = std::max(zmax * 1.01f, 1e-2f);
  near_plane = std::max(zmin * 0.99f, far_plane * 1e-4f);
  // A scene file's own clip planes (glTF's znear, zfar) bound the fit.
  if (scene_.camera.far_plane > 0.0f) far_plane = std::min(far_plane, scene_.camera.far_plane);
  if (scene_.camera.near_plane > 0.0f) near_plane = std::max(near_plane, scene_.camera.near_plane);
  if (!(near_plane < far_plane)) far_plane = 2.0f * near_plane;  // nothing between them
  depth_range_ = {.valid = true,
                  .camera = scene_.camera,
                  .width = width,
                  .height = height,
                  .near_plane = near_plane,
                  .far_plane = far_plane};
}

glm::mat4 Renderer::camera_projection(int width, int height) const {
  float near_plane = 0.0f, far_plane = 0.0f;
  camera_depth_range(width, height, near_plane, far_plane);
  const float aspect = static_cast<float>(width) / static_cast<float>(height);
  return camera_perspective(glm::radians(scene_.camera.fov_y_degrees), aspect, near_plane,
                            far_plane);
}

CameraFrustum Renderer::camera_frustum(int width, int height) const {
  CameraFrustum c;
  c.position = scene_.camera.position;
  c.forward = glm::normalize(scene_.camera.target - scene_.camera.position);
  c.up = scene_.camera.up;
  c.fov_y = glm::radians(scene_.camera.fov_y_degrees);
  c.aspect = static_cast<float>(width) / static_cast<float>(height);
  camera_depth_range(width, height, c.near_plane, c.far_plane);
  return c;
}

void Renderer::render(const RenderSettings& render, const ShadowSettings& shadow,
                      const SsaoSettings& ssao, gl::GpuProfiler* profiler) {
  validate(render);
  validate(shadow);
  validate(ssao);
  const int max_texture = max_texture_size_;
  if (shadow.map_size > max_texture) {
    throw UsageError("--shadow-map-size " + std::to_string(shadow.map_size) +
                     " exceeds this GPU's limit of " + std::to_string(max_texture));
  }
  if (render.width > max_texture || render.height > max_texture) {
    throw UsageError("image size " + std::to_string(render.width) + "x" +
                     std::to_string(render.height) + " exceeds this GPU's limit of " +
                     std::to_string(max_texture));
  }
  const int light_count = static_cast<int>(scene_.lights.size());
  if (render.light_index >= light_count &&
      (render.view == View::Shadow || render.view == View::ShadowReference ||
       render.view == View::Cascades || render.view == View::TexelDensity ||
       is_map_view(render.view))) {
    throw UsageError("--light-index " + std::to_string(render.light_index) + ": scene '" +
                     scene_.name + "' has " + std::to_string(light_count) + " light(s)");
  }
  if ((render.view == View::Moments || render.view == View::MomentsFiltered) &&
      !is_filterable(shadow.technique)) {
    throw UsageError("--view " + std::string(enum_name<View>(kViewNames, render.view)) +
                     " needs a filterable technique (vsm, esm, msm, msm16, evsm2 or evsm4)");
  }
  if (render.view == View::Ao && !ssao.enabled) {
    throw UsageError("--view ao needs --ssao on");
  }
  const bool virtual_maps = shadow.shadow_maps == ShadowMapKind::Virtual;
  if (virtual_maps && is_map_view(render.view)) {
    throw UsageError("--view " + std::string(enum_name<View>(kViewNames, render.view)) +
                     " shows whole shadow maps; with --shadow-maps virtual use --view pages");
  }
  if (render.view == View::Pages && !virtual_maps) {
    throw UsageError("--view pages needs --shadow-maps virtual");
  }
  if (virtual_maps && shadow.accumulate > 1) {
    throw UsageError("--accumulate needs --shadow-maps cascades");
  }
  const bool ambient_occlusion =
      ssao.enabled && (render.view == View::Final || render.view == View::Ao);
  last_render_ = render;
  last_shadow_ = shadow;

  // Per-frame blocks: each light's shadow views, fitted to the scene (and
  // a directional light's cascades to the camera), numbered across lights.
  const CameraFrustum camera = camera_frustum(render.width, render.height);
  gpu::GpuLight lights[MAX_LIGHTS] = {};
  gpu::GpuShadowView views[MAX_SHADOW_VIEWS] = {};
  light_views_.resize(static_cast<std::size_t>(light_count));
  fit_inputs_.resize(static_cast<std::size_t>(light_count));
  first_views_.resize(static_cast<std::size_t>(light_count));
  view_count_ = 0;
  for (int i = 0; i < light_count; ++i) {
    const auto index = static_cast<std::size_t>(i);
    const Light light = with_source_size(scene_.lights[index], shadow);
    ShadowViewInputs inputs = shadow_view_inputs(light, camera, shadow);
    if (fit_inputs_[index] != inputs) {
      light_views_[index] =
          fit_shadow_views(inputs, PositionSpan(mesh_.vertices), mesh_.indices, caster_bounds_);
      fit_inputs_[index] = std::move(inputs);
    }
    const LightShadowViews& fitted = light_views_[index];
    first_views_[index] = view_count_;
    lights[i] = gpu_light(light, fitted, view_count_, shadow);
    for (const LightView& view : fitted.views) {
      if (view_count_ >= MAX_SHADOW_VIEWS) throw std::logic_error("too many shadow views");
      views[view_count_++] = gpu_shadow_view(light, view, shadow);
    }
  }
  // Second surfaces (backprojection) for every view; on a point light's
  // six faces (their fragments write their radial depth) they add 96 MB of
  // depth and 67 MB of hierarchy at 2048^2, for RMSE 0.0070 -> 0.0053 on
  // the default scene's point light at 1.5 (640x360).
  const bool second_surfaces = draws_second_surfaces(shadow) && view_count_ > 0;
  if (second_surfaces) {
    for (int i = 0; i < view_count_; ++i) {
      views[i].second_layer = ShadowMapPass::second_layer(i, view_count_);
    }
  }
  lights_ubo_.update(lights, sizeof lights);
  views_ubo_.update(views, sizeof views);
  // Virtual maps for the first directional light and every spot light
  // (their conventional views stay in the block, undrawn); the others keep
  // their views.
  virtual_light_ = -1;
  if (virtual_maps) {
    for (int i = 0; i < light_count && virtual_light_ < 0; ++i) {
      if (scene_.lights[static_cast<std::size_t>(i)].type == LightType::Directional)
        virtual_light_ = i;
    }
  }
  if (virtual_light_ >= 0) {
    const Light& light = scene_.lights[static_cast<std::size_t>(virtual_light_)];
    virtual_clipmap_ = fit_virtual_clipmap(
        light, camera, render.height, PositionSpan(mesh_.vertices), mesh_.indices,
        caster_bounds_.bounds(PositionSpan(mesh_.vertices), mesh_.indices,
                              cascade_light_frame(light)),
        &virtual_clipmap_);
  }
  fit_virtual_lights(shadow, camera, render.height);
  if (maps_kind_for_ != shadow.shadow_maps) {
    shadow_cache_.invalidate();
    maps_kind_for_ = shadow.shadow_maps;
  }

  gpu::GpuFrame frame{};
  frame.view = camera_view();
  frame.projection = camera_projection(render.width, render.height);
  // Inverted in double: the float inverse's own rounding would add to the
  // depth buffer's in every position rebuilt from it.
  frame.inverse_view_projection =
      glm::mat4(glm::inverse(glm::dmat4(frame.projection) * glm::dmat4(frame.view)));
  frame.camera_position = glm::vec4(scene_.camera.position, 1.0f);
  frame.viewport = glm::vec4(render.width, render.height, 1.0f / static_cast<float>(render.width),
                             1.0f / static_cast<float>(render.height));
  frame.options = glm::ivec4(light_count, view_define(render.view), render.light_index,
                             ambient_occlusion ? 1 : 0);
  frame.ambient = glm::vec4(0.06f, 0.065f, 0.08f, 0.0f);
  frame.contact_length = shadow.contact_shadow_length;
  frame.contact_thickness = shadow.contact_shadow_thickness;
  frame.contact_steps = shadow.contact_shadow_steps;
  frame_ubo_.update(&frame, sizeof frame);

  gpu::GpuShadow shadow_block = gpu_shadow_params(shadow);
  set_subframe_params(shadow_block, shadow);
  shadow_block.accumulate_weighted = shadow.accumulate > 1 && render.view == View::Shadow ? 1 : 0;
  shadow_ubo_.update(&shadow_block, sizeof shadow_block);

  bind_frame_blocks();

  const bool shadows = shadow.technique != Technique::None || is_map_view(render.view);
  shadow_views_drawn_ = 0;
  std::span<const std::uint8_t> stale;
  if (shadows && !virtual_lights_.empty()) {
    // Marking reads the camera's depth: the G-buffer first.
    ensure_gbuffer(frame, render, profiler);
    // Marked from the G-buffer's reversed-Z depth (render/camera_depth.hpp)
    // and its facet normals, the ones the lighting's lookup is given.
    const CameraDepthBuffer depth{.texture = gbuffer_pass_.depth().id(),
                                  .width = render.width,
                                  .height = render.height,
                                  .view_projection = frame.projection * frame.view,
                                  .clip_depth = ClipDepth::ZeroToOne,
                                  .background_depth = static_cast<float>(CAMERA_FAR_DEPTH),
                                  .normal_texture = gbuffer_pass_.facet().id()};
    virtual_pass_.update(virtual_lights_, shadow, depth, profiler);
    {
      gl::GpuPassScope timed(profiler, gl::GpuPass::VirtualPages);
      draw_virtual_pages();
    }
    virtual_pass_.build_bounds();
    virtual_pass_.bind(kVirtualBindings);
  }
  if (shadows) {
    // Only the views whose depths changed (view_cache.hpp); a light with
    // virtual maps draws none of its views.
    stale = shadow_cache_.stale_views(
        std::span<const gpu::GpuShadowView>(views, static_cast<std::size_t>(view_count_)),
        shadow.map_size);
    if (!virtual_lights_.empty()) {
      stale_without_virtual_.assign(stale.begin(), stale.end());
      stale_without_virtual_.resize(static_cast<std::size_t>(view_count_), 1);
      for (const VirtualLightMaps& maps : virtual_lights_) {
        const auto light = static_cast<std::size_t>(maps.light_index);
        for (std::size_t v = 0; v < light_views_[light].views.size(); ++v) {
          stale_without_virtual_[static_cast<std::size_t>(first_views_[light]) + v] = 0;
        }
      }
      stale = stale_without_virtual_;
    }
    gl::GpuPassScope timed(profiler, gl::GpuPass::ShadowDepth);
    const std::span<const gpu::GpuShadowView> drawn(views, static_cast<std::size_t>(view_count_));
    // A view whose fragments write their depth (a cube face's radial one).
    const auto radial = [&](int view) { return caster_depth(views[view]) == CasterDepth::Written; };
    shadow_views_drawn_ = shadow_pass_.execute(
        [&](int view) {
          shadow_casters_.draw(gpu_scene_, view, radial(view), depth_samples(shadow));
        },
        drawn, shadow.map_size, stale, depth_samples(shadow),
        second_surfaces ? ShadowMapPass::DrawCasters([&](int view) {
          shadow_casters_.draw_second_surfaces(gpu_scene_, view, radial(view));
        })
                        : ShadowMapPass::DrawCasters());
  }
  // The resolve and the filters run again when a view was drawn (over the
  // drawn views' layers; filter/layer_runs.hpp) or the settings changed
  // (over every layer), else their output is current. The summed-area
  // tables, the depth hierarchy and the mip chains take every layer.
  const bool settings_changed = filtered_for_ != shadow;
  const bool filter_maps = shadow_views_drawn_ > 0 || settings_changed;
  const std::span<const std::uint8_t> filter_layers =
      settings_changed ? std::span<const std::uint8_t>() : stale;
  filtered_for_ = shadow;
  const gl::Texture* filtered = nullptr;
  const bool fused = is_filterable(shadow.technique) && uses_fused_filter(shadow);
  if (fused) {
    if (filter_maps) {
      gl::GpuPassScope timed(profiler, gl::GpuPass::FusedFilter);
      fused_pass_.execute(shadow_pass_.sampled_depth_maps(), shadow, filter_layers);
    }
    filtered = &fused_pass_.output();
    // The moments view shows the unfiltered representation, which the
    // fused pass never writes.
    if (render.view == View::Moments)
      resolve_pass_.execute(shadow_pass_.sampled_depth_maps(), shadow);
  } else if (is_filterable(shadow.technique)) {
    if (filter_maps) {
      gl::GpuPassScope timed(profiler, gl::GpuPass::Resolve);
      resolve_pass_.execute(shadow_pass_.sampled_depth_maps(), shadow, filter_layers);
    }
    const gl::Texture& representation = resolve_pass_.representation();
    filtered = &representation;
    const int filter = filter_define(shadow);
    if (filter == FILTER_GAUSSIAN) {
      if (filter_maps) {
        blur_pass_.execute(
            representation, shadow.blur, profiler,
            filtered_map_levels(shadow, representation.width(), representation.height()),
            filter_layers);
      }
      filtered = &blur_pass_.output();
    } else if (filter == FILTER_SAT) {
      if (filter_maps) sat_pass_.execute(representation, profiler);
      filtered = &sat_pass_.table();
    }
  }
  if (shadow.technique == Technique::Backprojection) {
    // Backprojection's blocker regions (shaders/shadow/backprojection.glsl),
    // built again only when the depth maps changed.
    if (filter_maps) {
      gl::GpuPassScope timed(profiler, gl::GpuPass::DepthHierarchy);
      hierarchy_pass_.execute(shadow_pass_.depth_maps());
    }
    filtered = &hierarchy_pass_.hierarchy();
  }
  if (filtered != nullptr && uses_shadow_mips(shadow) && filter_maps) {
    gl::GpuPassScope timed(profiler, gl::GpuPass::Mips);
    mip_pass_.execute(*filtered);
  }
  if (is_map_view(render.view)) {
    const gl::Texture* maps = &shadow_pass_.depth_maps();
    if (render.view != View::ShadowMap) {
      maps = &resolve_pass_.representation();
      const int filter = filter_define(shadow);
      if (render.view == View::MomentsFiltered && fused) {
        maps = &fused_pass_.output();
      } else if (render.view == View::MomentsFiltered && filter == FILTER_GAUSSIAN) {
        maps = &blur_pass_.output();
      } else if (render.view == View::MomentsFiltered && filter == FILTER_SAT) {
        maps = &sat_pass_.box_filtered(shadow.blur);
      }
    }
    const auto light = static_cast<std::size_t>(render.light_index);
    tiling_pass_.execute(*maps, first_views_[light],
                         static_cast<int>(light_views_[light].views.size()));
  }
  if (render.view == View::ShadowReference) bind_reference_weights(shadow);
  gbuffer_current_ = !is_map_view(render.view);
  if (gbuffer_current_) {
    last_view_projection_ = frame.projection * frame.view;
    ensure_gbuffer(frame, render, profiler);
    GLuint ao = 0;
    if (ambient_occlusion) {
      if (ao_for_ != ssao) {
        gl::GpuPassScope timed(profiler, gl::GpuPass::AmbientOcclusion);
        ssao_pass_.execute(gbuffer_pass_, frame.view, frame.projection, ssao);
        ao_for_ = ssao;
      }
      ao = ssao_pass_.output().id();
    }
    gl::GpuPassScope timed(profiler, gl::GpuPass::Lighting);
    const GLuint filtered_id = filtered != nullptr ? filtered->id() : 0;
    lighting_pass_.execute(gbuffer_pass_, shadows ? &shadow_pass_.depth_maps() : nullptr,
                           filtered_id, shadow, frame.options.y, ao, render.width, render.height);
    last_frame_ = frame;
    last_filtered_ = filtered_id;
    last_ao_ = ao;
    last_shadows_ = shadows;
  }
}

void Renderer::draw_virtual_pages() {
  if (!virtual_page_programs_[0][0]) {
    // The orthographic levels' pages keep the rasterizer's depth; the
    // perspective levels' fragments write their z-bar (virtual_page.vert).
    for (int list = 0; list < 2; ++list) {
      for (int cut_outs = 0; cut_outs < 2; ++cut_outs) {
        const char* written = list != 0 ? "1" : "0";
        virtual_page_programs_[list][cut_outs] =
            gl::Program::graphics("shadow/virtual_page.vert", "shadow/shadow_depth.frag",
                                  {{"RADIAL_DEPTH", written},
                                   {"VIRTUAL_PAGE", written},
                                   {"CUT_OUTS", cut_outs != 0 ? "1" : "0"}});
      }
    }
  }
  virtual_pass_.begin_pages();
  for (int list = 0; list < 2; ++list) {
    virtual_pass_.clear_listed_pages(list);
    const std::size_t offset = virtual_pass_.draws_offset(list);
    for (int cut_outs = 0; cut_outs < 2; ++cut_outs) {
      const gl::Program& program = virtual_page_programs_[list][cut_outs];
      program.use();
      glProgramUniform1i(program.id(), LOCATION_VIRTUAL_LIST, list);
      gpu_scene_.draw_indirect(cut_outs == 0 ? SurfaceSet::Opaque : SurfaceSet::CutOut, offset,
                               LOCATION_VIRTUAL_DRAW);
    }
  }
  glBindBuffer(GL_DRAW_INDIRECT_BUFFER, 0);
  virtual_pass_.end_pages();
}

void Renderer::release_filtered_maps() {
  resolve_pass_.release();
  blur_pass_.release();
  fused_pass_.release();
  hierarchy_pass_.release();
  sat_pass_.release();
  tiling_pass_.release();
  filtered_for_.reset();
  gbuffer_current_ = false;  // shade() would read the freed maps
}

void Renderer::ensure_gbuffer(const gpu::GpuFrame& frame, const RenderSettings& render,
                              gl::GpuProfiler* profiler) {
  const SurfaceKey surfaces{frame.view, frame.projection, render.width, render.height};
  if (gbuffer_for_ != surfaces) {
    gl::GpuPassScope timed(profiler, gl::GpuPass::GBuffer);
    gbuffer_pass_.execute(gpu_scene_, render.width, render.height);
    gbuffer_for_ = surfaces;
    ao_for_.reset();
  }
}

void Renderer::bind_frame_blocks() {
  glBindBufferBase(GL_UNIFORM_BUFFER, BINDING_FRAME_UBO, frame_ubo_.id());
  glBindBufferBase(GL_UNIFORM_BUFFER, BINDING_LIGHTS_UBO, lights_ubo_.id());
  glBindBufferBase(GL_UNIFORM_BUFFER, BINDING_SHADOW_UBO, shadow_ubo_.id());
  glBindBufferBase(GL_UNIFORM_BUFFER, BINDING_SHADOW_VIEWS_UBO, views_ubo_.id());
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, BINDING_POISSON_SSBO, poisson_.id());
}

void Renderer::bind_reference_weights(const ShadowSettings& shadow) {
  // The kernel the filter applies, as 1D weights for the reference's
  // brute-force average of depth tests.
  const int radius = is_filterable(shadow.technique) ? shadow.blur : 0;
  std::vector<float> weights =
      shadow.filter == Filter::Sat
          ? std::vector<float>(2 * static_cast<std::size_t>(radius) + 1, 1.0f)
          : gaussian_weights(radius);
  reference_weights_.update(weights.data(), weights.size() * sizeof(float));
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, BINDING_FILTER_WEIGHTS_SSBO, reference_weights_.id());
}

void Renderer::shade(View view) {
  if (!gbuffer_current_ || is_map_view(view)) {
    throw std::logic_error("shade() needs a camera view rendered and a camera view to shade");
  }
  if (last_shadow_.accumulate > 1) throw std::logic_error("shade() of an --accumulate frame");
  const bool ambient_occlusion = view == View::Final || view == View::Ao;
  if (ambient_occlusion && last_ao_ == 0) {
    throw std::logic_error("shade() of a view that needs SSAO the last render() skipped");
  }
  last_render_.view = view;
  // The lit image's pass left the shadow view already (read_view() reads
  // it from there).
  if (view == View::Shadow && lighting_pass_.shadow_view_written()) return;
  shade_as(view_define(view), ambient_occlusion);
}

Image Renderer::read_texel_density() {
  if (!gbuffer_current_)
    throw std::logic_error("read_texel_density() needs a camera view rendered");
  // The lighting output holds the values now, not the view last_render_
  // names: read_view() returns them too, until the next render().
  shade_as(VIEW_TEXEL_DENSITY_VALUES, false);
  return read_texture(lighting_pass_.output().id(), last_render_.width, last_render_.height,
                      GL_RGBA);
}

void Renderer::shade_as(int define, bool ambient_occlusion) {
  last_frame_.options.y = define;
  last_frame_.options.w = ambient_occlusion ? 1 : 0;
  frame_ubo_.update(&last_frame_, sizeof last_frame_);
  bind_frame_blocks();
  if (last_shadow_.shadow_maps == ShadowMapKind::Virtual) virtual_pass_.bind(kVirtualBindings);
  if (define == VIEW_SHADOW_REFERENCE) bind_reference_weights(last_shadow_);
  lighting_pass_.execute(gbuffer_pass_, last_shadows_ ? &shadow_pass_.depth_maps() : nullptr,
                         last_filtered_, last_shadow_, define, ambient_occlusion ? last_ao_ : 0,
                         last_render_.width, last_render_.height);
}

ViewSource Renderer::view_source() {
  const View view = last_render_.view;
  if (view == View::ShadowMap) return {&tiling_pass_.output(), ViewEncoding::Depth};
  if (view == View::Moments || view == View::MomentsFiltered) {
    if (last_shadow_.technique == Technique::Esm) {
      return {&tiling_pass_.output(), ViewEncoding::LogDepth, 1.0f / last_shadow_.esm_c, 1.0f};
    }
    if (last_shadow_.technique == Technique::Evsm2 || last_shadow_.technique == Technique::Evsm4) {
      return {&tiling_pass_.output(), ViewEncoding::LogDepth, 0.5f / last_shadow_.evsm_positive,
              0.5f};
    }
    if (last_shadow_.technique == Technique::Msm && !uses_quantized_moments(last_shadow_)) {
      return {&tiling_pass_.output(), ViewEncoding::SignedMoments};
    }
    return {&tiling_pass_.output(), ViewEncoding::Data};
  }
  // The shadow view from the lit image's second target, unless another
  // view's pass (read_texel_density()) came after it.
  if (view == View::Shadow && lighting_pass_.shadow_view_written()) {
    return {&lighting_pass_.shadow_output(), ViewEncoding::Data};
  }
  return {&lighting_pass_.output(),
          view == View::Final ? ViewEncoding::LinearColor : ViewEncoding::Data};
}

Image Renderer::read_view() {
  return read_view_source(view_source());
}

std::array<double, 3> Renderer::count_lookup_fetches(const RenderSettings& render,
                                                     const ShadowSettings& shadow) {
  gl::Texture counts(gl::TextureInfo{.format = GL_R32UI,
                                     .width = render.width,
                                     .height = render.height,
                                     .label = "shadow lookup fetch counts"});
  const GLuint zero = 0;
  glClearTexImage(counts.id(), 0, GL_RED_INTEGER, GL_UNSIGNED_INT, &zero);
  lighting_pass_.count_fetches(counts.id());
  this->render(render, shadow);
  lighting_pass_.count_fetches(0);
  glMemoryBarrier(GL_TEXTURE_UPDATE_BARRIER_BIT);
  const auto texels = static_cast<std::size_t>(render.width) * render.height;
  std::vector<GLuint> values(texels);
  glGetTextureImage(counts.id(), 0, GL_RED_INTEGER, GL_UNSIGNED_INT,
                    static_cast<GLsizei>(values.size() * sizeof(GLuint)), values.data());
  const Image seen = read_view();
  double low = 0.0, sum = 0.0, high = 0.0;
  long pixels = 0;
  for (int y = 0; y < render.height; ++y) {
    for (int x = 0; x < render.width; ++x) {
      if (seen.pixel(x, y)[3] < 0.5f) continue;
      // Rows bottom to top on the GPU, top to bottom in Image.
      const double v = values[static_cast<std::size_t>(render.height - 1 - y) * render.width + x];
      low = pixels == 0 ? v : std::min(low, v);
      high = std::max(high, v);
      sum += v;
      ++pixels;
    }
  }
  return {low, pixels > 0 ? sum / static_cast<double>(pixels) : 0.0, high};
}

Image read_view_source(const ViewSource& source) {
  const gl::Texture& map = *source.texture;
  Image image = read_texture(map.id(), map.width(), map.height(), GL_RGBA);
  if (source.encoding == ViewEncoding::Depth) {
    // The tiled depth maps hold z-bar in red: grey, as a depth texture reads.
    for (std::size_t p = 0; p < image.rgba.size(); p += 4) {
      image.rgba[p + 1] = image.rgba[p + 2] = image.rgba[p];
      image.rgba[p + 3] = 1.0f;
    }
  }
  if (source.encoding == ViewEncoding::LogDepth) {
    // log(map) / c + 1 is the occluder depth for an unfiltered ESM map;
    // after the blur it is log(blur(exp(c z))) / c + 1, which is not blur(z).
    for (std::size_t p = 0; p < image.rgba.size(); p += 4) {
      const float v = image.rgba[p];
      const float depth = v > 0.0f ? std::log(v) * source.log_scale + source.log_offset : 0.0f;
      image.rgba[p] = image.rgba[p + 1] = image.rgba[p + 2] = depth;
      image.rgba[p + 3] = 1.0f;
    }
  }
  if (source.encoding == ViewEncoding::SignedMoments) {
    for (std::size_t p = 0; p < image.rgba.size(); p += 4) {
      const glm::dvec4 z = msm_moments_from_signed(
          {image.rgba[p], image.rgba[p + 1], image.rgba[p + 2], image.rgba[p + 3]});
      for (int c = 0; c < 3; ++c) image.rgba[p + c] = static_cast<float>(z[c]);
      image.rgba[p + 3] = 1.0f;
    }
  }
  return image;
}

std::vector<glm::vec3> Renderer::read_facet_normals() const {
  if (!gbuffer_current_) {
    throw std::logic_error("read_facet_normals() needs a camera view rendered");
  }
  const int width = gbuffer_pass_.facet().width(), height = gbuffer_pass_.facet().height();
  const Image facet = read_texture(gbuffer_pass_.facet().id(), width, height, GL_RGBA);
  std::vector<glm::vec3> normals(static_cast<std::size_t>(width) * height, glm::vec3(0.0f));
  for (int y = 0; y < height; ++y) {
    for (int x = 0; x < width; ++x) {
      const float* n = facet.pixel(x, y);
      const glm::vec3 v(n[0], n[1], n[2]);
      if (glm::length(v) > 0.0f) {
        normals[static_cast<std::size_t>(y) * width + x] = glm::normalize(v);
      }
    }
  }
  return normals;
}

SurfacePoints Renderer::read_surfaces() const {
  if (!gbuffer_current_) throw std::logic_error("read_surfaces() needs a camera view rendered");
  const int width = gbuffer_pass_.depth().width(), height = gbuffer_pass_.depth().height();
  const Image depth = read_texture(gbuffer_pass_.depth().id(), width, height, GL_DEPTH_COMPONENT);
  const Image normal = read_texture(gbuffer_pass_.normal().id(), width, height, GL_RGBA);
  const glm::dmat4 inverse = glm::inverse(glm::dmat4(last_view_projection_));
  GLint subpixel_bits = 4;  // the least OpenGL allows
  glGetIntegerv(GL_SUBPIXEL_BITS, &subpixel_bits);
  SurfacePoints surfaces(width, height);
  for (int y = 0; y < height; ++y) {
    for (int x = 0; x < width; ++x) {
      const std::size_t i = static_cast<std::size_t>(y) * width + x;
      const float* n = normal.pixel(x, y);
      if (n[3] == 0.0f) continue;  // shininess 0 marks the background, as in lighting.frag
      // The pixel centre in NDC, as lighting.frag's world_position() (GL
      // rows run bottom to top, image rows top to bottom).
      const glm::dvec2 ndc((x + 0.5) / width * 2.0 - 1.0, (height - y - 0.5) / height * 2.0 - 1.0);
      const double window_depth = depth.pixel(x, y)[0];
      surfaces.position[i] = glm::vec3(position_from_depth(inverse, ndc, window_depth));
      surfaces.normal[i] = glm::normalize(glm::vec3(n[0], n[1], n[2]));
      surfaces.covered[i] = 1;
      surfaces.position_error[i] = depth_position_error(
          inverse, ndc, window_depth, surfaces.normal[i], width, height, subpixel_bits);
    }
  }
  return surfaces;
}

const gl::Texture& Renderer::shadow_maps() const {
  if (!is_filterable(last_shadow_.technique)) return shadow_pass_.depth_maps();
  return uses_fused_filter(last_shadow_) ? fused_pass_.output() : resolve_pass_.representation();
}

Image Renderer::read_shadow_view(int view) const {
  const gl::Texture& maps = shadow_pass_.depth_maps();
  if (view < 0 || view >= maps.layers()) throw std::out_of_range("no such shadow view");
  return read_texture(maps.id(), maps.width(), maps.height(), GL_DEPTH_COMPONENT, view);
}

}  // namespace penumbra
