#pragma once
// One frame: shadow maps, G-buffer, lighting. Wires the passes together and
// owns the per-frame uniform blocks; the algorithms live in the passes and
// the shaders.
#include <array>
#include <memory>
#include <optional>
#include <vector>

#include "io/image.hpp"
#include "penumbra/filter/depth_hierarchy_pass.hpp"
#include "penumbra/filter/fused_filter_pass.hpp"
#include "penumbra/filter/gaussian_blur_pass.hpp"
#include "penumbra/filter/mip_chain_pass.hpp"
#include "penumbra/filter/summed_area_table_pass.hpp"
#include "penumbra/gl/gpu_profiler.hpp"
#include "penumbra/gl/resources.hpp"
#include "penumbra/settings.hpp"
#include "penumbra/shadow/light_view.hpp"
#include "penumbra/shadow/moment_resolve_pass.hpp"
#include "penumbra/shadow/shadow_map_pass.hpp"
#include "penumbra/shadow/shadow_views.hpp"
#include "penumbra/shadow/view_cache.hpp"
#include "penumbra/shadow/virtual_shadow_pass.hpp"
#include "penumbra/shared/bindings.h"
#include "penumbra/shared/gpu_types.h"
#include "render/gbuffer_pass.hpp"
#include "render/gpu_scene.hpp"
#include "render/lighting_pass.hpp"
#include "render/scene_shadow_casters.hpp"
#include "render/ssao_pass.hpp"
#include "render/surface_points.hpp"
#include "render/view_tiling_pass.hpp"
#include "scene/mesh.hpp"
#include "scene/scene.hpp"

namespace penumbra {

// How a view's values become 8-bit PNG: colour through the sRGB curve,
// data (shadow factors, depths, moments, normals) as they are.
PngEncoding png_encoding_for(View view);
// How a view's texture holds its values, for display and read-back alike.
enum class ViewEncoding {
  // the final image: linear RGB, shown through the sRGB curve
  LinearColor = VIEW_ENCODING_LINEAR_COLOR,
  // shadow factor, normals, albedo, moments: shown as stored, clamped to [0, 1]
  Data = VIEW_ENCODING_DATA,
  // a depth texture: z-bar in its one channel, shown as grey
  Depth = VIEW_ENCODING_DEPTH,
  // an exponential map in red: shown in depth units as log(map) * log_scale
  // + log_offset (ESM's exp(c (z - 1)): 1/c and 1; EVSM's positive warp
  // exp(c+ (2 z - 1)): 1/(2 c+) and 1/2)
  LogDepth = VIEW_ENCODING_LOG_DEPTH,
  // msm's 32-bit moments of u = 2 z - 1: shown as the moments of z
  // (E[z], E[z^2], E[z^3]), the colour image of the seed's assignment
  SignedMoments = VIEW_ENCODING_SIGNED_MOMENTS,
};

struct ViewSource {
  const gl::Texture* texture = nullptr;
  ViewEncoding encoding = ViewEncoding::LinearColor;
  float log_scale = 1.0f;  // for LogDepth
  float log_offset = 1.0f;
};

// A view's texture read back as an image, its values decoded as
// Renderer::read_view() documents.
[[nodiscard]] Image read_view_source(const ViewSource& source);

class Renderer {
 public:
  // Uploads the scene. Needs a current OpenGL 4.5 context.
  explicit Renderer(const Scene& scene);

  // Renders one frame. Throws UsageError for settings the GPU cannot honour
  // (a shadow map larger than its texture limit, a light index out of range).
  // SSAO runs for the final and ao views only. The G-buffer and the AO of
  // the last frame are reused when the camera, the image size (and the
  // SSAO settings) are the same. With a profiler, each pass drawn is timed
  // (the caller begins and ends the frame).
  void render(const RenderSettings& render, const ShadowSettings& shadow,
              const SsaoSettings& ssao = {}, gl::GpuProfiler* profiler = nullptr);
  // The next render() draws the G-buffer and the AO anew, whatever it
  // reused before: for timing every pass of a frame.
  void forget_surfaces() {
    gbuffer_for_.reset();
    ao_for_.reset();
  }
  // The shadow maps are cached: render() draws a shadow view again only
  // when its view (its light, its fit, the map size) changed or a shape it
  // sees moved (move_shape), and runs the resolve and filter passes only
  // when a view was drawn or the shadow settings changed. The next
  // render() draws them all anew: for timing the full shadow pass.
  void forget_shadow_maps() {
    shadow_cache_.invalidate();
    filtered_for_.reset();
    virtual_pass_.invalidate();
  }
  // Frees the maps made from the depth maps and the map views' image (the
  // resolve, filter, summed-area-table, hierarchy and tiling outputs:
  // arrays as large as the depth maps, in up to 16 bytes a texel, which a
  // technique used once would otherwise hold until the renderer goes).
  // The next render() makes what it needs again; the depth maps, the
  // G-buffer and the programs stay. Until then shade() is not available,
  // nor read_view() of a map view.
  void release_filtered_maps();
  // The shadow views the last render() drew (0: the maps were cached).
  [[nodiscard]] int shadow_views_drawn() const { return shadow_views_drawn_; }
  // --shadow-maps virtual: the directional light that reads virtual maps
  // in the last render() (the first; -1: none), its clipmap, every light's
  // virtual maps (that light's and each spot light's, in the order of
  // their levels), and the pass that holds their page table and pool.
  [[nodiscard]] int virtual_light() const { return virtual_light_; }
  [[nodiscard]] const VirtualClipmap& virtual_clipmap() const { return virtual_clipmap_; }
  [[nodiscard]] const std::vector<VirtualLightMaps>& virtual_lights() const {
    return virtual_lights_;
  }
  [[nodiscard]] const VirtualShadowPass& virtual_shadows() const { return virtual_pass_; }
  // Its pages after the last render(), read back from the GPU (benchmarks, tests).
  [[nodiscard]] VirtualPageStats virtual_page_stats() const { return virtual_pass_.read_stats(); }

  // Moves scene shape `shape` by `offset` (world units): its vertices on
  // the CPU and the GPU, the lights' fits, and the shadow views that see it
  // before or after. Throws UsageError for a shape the scene lacks.
  void move_shape(std::size_t shape, const glm::vec3& offset);
  // The world-space bounds of scene shape `shape`'s triangles.
  [[nodiscard]] Bounds shape_bounds(std::size_t shape) const;

  // Shades the last render()'s camera view again as `view`, from the
  // shadow maps, the filter's output and the G-buffer it left, without
  // rendering them again: the image render() with the same settings and
  // this view makes, for the cost of the lighting pass alone (one setting
  // read as its lit image, its shadow factor and its filtered reference).
  // `view` must be a camera view that needs no ambient occlusion the last
  // render() did not compute (shadow and shadow-reference always do).
  // Throws std::logic_error after a map view, for an --accumulate
  // sub-frame, or for a view that needs SSAO the last render() skipped.
  void shade(View view);

  // The last render()'s camera view as texel densities of its light
  // (render.light_index): per pixel, the shadow-map texels that fall into
  // its footprint on the receiver (shaders/shadow/texel_density.glsl, the
  // values --view texel-density colours) in every colour channel, 0 where
  // no shadow view covers the point; alpha 1 where the pixel sees
  // geometry. Reuses the frame as shade() does; read_view() returns these
  // values until the next render(). Throws std::logic_error after a map
  // view.
  [[nodiscard]] Image read_texel_density();

  // The view chosen in the last render(): the lighting pass's output for
  // camera views; for map views, the light's z-bar maps (shadow-map) or
  // their representation before or after the filter (moments,
  // moments-filtered; for esm and evsm shown in depth units, see LogDepth),
  // the light's shadow views tiled three to a row (ViewTilingPass).
  // The ao view is the AO texture as the lighting pass reads it.
  [[nodiscard]] Image read_view();
  // Renders the frame again in the lookups' fetch-counting variant
  // (LightingPass::count_fetches; for the settings that
  // LightingPass::counts_fetches() names) and returns their texel reads
  // per pixel that sees geometry, all lights together: {min, mean, max}.
  [[nodiscard]] std::array<double, 3> count_lookup_fetches(const RenderSettings& render,
                                                           const ShadowSettings& shadow);
  // The texture read_view() reads, left on the GPU (a window shows it),
  // and how its values are encoded. Valid until the next render().
  [[nodiscard]] ViewSource view_source();
  // Shadow view v's map (z-bar in every channel; v indexes all lights'
  // views, see first_view()), as last rendered.
  [[nodiscard]] Image read_shadow_view(int view) const;
  // The world positions and normals the last render()'s camera view shaded,
  // rebuilt from the G-buffer depth (through the inverse view-projection,
  // in double) and normals. Throws std::logic_error after a map view.
  [[nodiscard]] SurfacePoints read_surfaces() const;
  // The G-buffer's triangle normals (unit; 0 where no geometry), ordered as
  // read_surfaces()' points: what the virtual maps pick each pixel's level
  // with.
  [[nodiscard]] std::vector<glm::vec3> read_facet_normals() const;

  // Every shadow view's map as the filters see it, one layer per view: the
  // technique's representation for vsm/esm/msm/msm16 (filtered, when the
  // fused pass made it: the same size and format), the z-bar depth maps
  // otherwise. As last rendered.
  [[nodiscard]] const gl::Texture& shadow_maps() const;

  // The camera and the lights may change between frames (the viewer moves
  // them), and the shapes' positions (move_shape). set_lights throws
  // UsageError for more lights than the shaders hold.
  void set_camera(const Camera& camera) { scene_.camera = camera; }
  void set_lights(const std::vector<Light>& lights);

  [[nodiscard]] const Scene& scene() const { return scene_; }
  [[nodiscard]] const TriangleMesh& mesh() const { return mesh_; }
  // The camera's G-buffer, as last rendered.
  [[nodiscard]] const GBufferPass& gbuffer() const { return gbuffer_pass_; }
  // Light i's shadow views as last fitted, and the index of its first one
  // among all lights' views (its layer in the shadow-map arrays).
  [[nodiscard]] const LightShadowViews& shadow_views(int light) const {
    return light_views_.at(light);
  }
  [[nodiscard]] int first_view(int light) const { return first_views_.at(light); }
  // Light i's first shadow view (its only one for a spot light).
  [[nodiscard]] const LightView& light_view(int light) const {
    return light_views_.at(light).views.front();
  }
  // The camera as the cascades follow it, for an image of this size.
  [[nodiscard]] CameraFrustum camera_frustum(int width, int height) const;
  [[nodiscard]] glm::mat4 camera_view() const;
  [[nodiscard]] glm::mat4 camera_projection(int width, int height) const;
  // Near and far planes of camera_projection().
  void camera_depth_range(int width, int height, float& near_plane, float& far_plane) const;

 private:
  Scene scene_;
  // Shape i's vertices: [i], [i + 1]); filled by mesh_'s initializer, so
  // declared before it.
  std::vector<std::size_t> shape_first_vertex_;
  TriangleMesh mesh_;
  Bounds bounds_;
  GpuScene gpu_scene_;
  SceneShadowCasters shadow_casters_;
  ShadowMapPass shadow_pass_;
  MomentResolvePass resolve_pass_;
  GaussianBlurPass blur_pass_;
  FusedFilterPass fused_pass_;
  MipChainPass mip_pass_;
  DepthHierarchyPass hierarchy_pass_;
  SummedAreaTablePass sat_pass_;
  GBufferPass gbuffer_pass_;
  SsaoPass ssao_pass_;
  LightingPass lighting_pass_;
  ViewTilingPass tiling_pass_;
  VirtualShadowPass virtual_pass_;
  // The scene's casters into the pages: [list: orthographic, perspective
  // levels][opaque, cut-outs].
  gl::Program virtual_page_programs_[2][2];
  VirtualClipmap virtual_clipmap_;
  int virtual_light_ = -1;
  std::vector<VirtualLightMaps> virtual_lights_;
  // The kind of maps the shadow views' cache holds (a switch redraws them).
  std::optional<ShadowMapKind> maps_kind_for_;
  gl::Buffer frame_ubo_, lights_ubo_, shadow_ubo_, views_ubo_;
  gl::Buffer reference_weights_;
  gl::Buffer poisson_;  // the PCF/PCSS sample set (std430 vec2 array)
  // The reference's kernel weights for the shadow-reference view.
  // Binds the frame's uniform blocks and the sample set the lighting pass
  // reads (render() fills them; shade() reuses them).
  void bind_frame_blocks();
  void bind_reference_weights(const ShadowSettings& shadow);
  // The lights' virtual maps for this frame (virtual_lights_): the
  // directional light's clipmap fitted as virtual_clipmap_, and a map for
  // each spot light over its fitted view.
  void fit_virtual_lights(const ShadowSettings& shadow, const CameraFrustum& camera,
                          int image_height);
  // Draws the camera's G-buffer unless it holds this frame's surfaces.
  void ensure_gbuffer(const gpu::GpuFrame& frame, const RenderSettings& render,
                      gl::GpuProfiler* profiler);
  // The lighting pass again on the last frame's inputs, writing VIEW_*
  // define `define` (with the AO of the last render() if asked).
  void shade_as(int define, bool ambient_occlusion);
  // Draws the scene's casters into the virtual pages the last update of
  // virtual_pass_ listed, each draw into the pages its bounds cover.
  void draw_virtual_pages();
  // Each light's views and the camera's depth range are kept and refitted
  // only when what they depend on changes (the geometry: only through
  // move_shape(), which also forgets the caster bounds below).
  std::vector<LightShadowViews> light_views_;
  std::vector<std::optional<ShadowViewInputs>> fit_inputs_;
  // Bounds over the scene's triangles (in each light's cascade frame, and
  // the world's for the camera's planes), so that fitting after a camera
  // move does not grow with the triangle count.
  mutable CasterBoundsCache caster_bounds_;
  struct DepthRange {
    bool valid = false;
    Camera camera;
    int width = 0, height = 0;
    float near_plane = 0.0f, far_plane = 0.0f;
  };
  mutable DepthRange depth_range_;
  std::vector<int> first_views_;
  int view_count_ = 0;
  // What the shadow maps and the filtered maps hold (forget_shadow_maps()).
  ViewCache shadow_cache_;
  // The stale views less those of the lights with virtual maps (kept to
  // allocate nothing per frame).
  std::vector<std::uint8_t> stale_without_virtual_;
  std::optional<ShadowSettings> filtered_for_;
  int shadow_views_drawn_ = 0;
  RenderSettings last_render_;
  ShadowSettings last_shadow_;
  glm::mat4 last_view_projection_{1.0f};
  bool gbuffer_current_ = false;
  // What the G-buffer and the AO texture hold: the camera and size they
  // were rendered for, and the SSAO settings of the AO (none: stale). A
  // frame for the same camera and size reuses them (the geometry never
  // changes): an --accumulate sub-frame or another setting of the report
  // redraws only the shadow maps and the lighting.
  struct SurfaceKey {
    glm::mat4 view{1.0f}, projection{1.0f};
    int width = 0, height = 0;
    bool operator==(const SurfaceKey&) const = default;
  };
  std::optional<SurfaceKey> gbuffer_for_;
  std::optional<SsaoSettings> ao_for_;
  // What the last render()'s lighting pass read, for shade().
  gpu::GpuFrame last_frame_{};
  GLuint last_filtered_ = 0;
  GLuint last_ao_ = 0;
  bool last_shadows_ = false;
  int max_texture_size_ = 0;  // GL_MAX_TEXTURE_SIZE
};

}  // namespace penumbra
