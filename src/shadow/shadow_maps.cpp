// ShadowMaps (include/penumbra/shadow_maps.hpp): the shadow core's passes
// wired for an engine, in the order penumbra's renderer runs them
// (src/render/renderer.cpp): fit, depth maps, resolve + filter.
#include "penumbra/shadow_maps.hpp"

#include <algorithm>
#include <array>
#include <cstring>
#include <glm/gtc/matrix_transform.hpp>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "penumbra/error.hpp"
#include "penumbra/filter/depth_hierarchy_pass.hpp"
#include "penumbra/filter/fused_filter_pass.hpp"
#include "penumbra/filter/gaussian_blur_pass.hpp"
#include "penumbra/filter/summed_area_table_pass.hpp"
#include "penumbra/gl/program.hpp"
#include "penumbra/gl/resources.hpp"
#include "penumbra/gl/shader_source.hpp"
#include "penumbra/shadow/moment_resolve_pass.hpp"
#include "penumbra/shadow/poisson_disc.hpp"
#include "penumbra/shadow/representation.hpp"
#include "penumbra/shadow/shadow_block_data.hpp"
#include "penumbra/shadow/shadow_map_pass.hpp"
#include "penumbra/shadow/shadow_views.hpp"
#include "penumbra/shadow/view_cache.hpp"
#include "shadow/gl_state_guard.hpp"
#include "shadow/shadow_lookup.hpp"
#include "shadow/shadow_maps_virtual.hpp"

namespace penumbra {

namespace {

gl::Program caster_depth_program(const ShadowBindings& bindings, bool radial) {
  gl::Defines defines = shadow_binding_defines(bindings);
  defines.emplace_back("RADIAL_DEPTH", radial ? "1" : "0");
  return gl::Program::graphics("shadow/caster_depth.vert", "shadow/caster_depth.frag", defines);
}

}  // namespace

struct ShadowMaps::Impl {
  Impl(const ShadowBindings& b, StateRestore r) : bindings(b), restore(r) {}

  ShadowBindings bindings;
  StateRestore restore;
  // The caster programs declare the block at the engine's binding. Early
  // depth for every view but a point light's faces, which write their
  // radial depth (shadow/shadow_map_pass.hpp).
  gl::Program caster_program = caster_depth_program(bindings, false);
  gl::Program radial_caster_program = caster_depth_program(bindings, true);
  ShadowMapPass map_pass;
  MomentResolvePass resolve_pass;
  GaussianBlurPass blur_pass;
  FusedFilterPass fused_pass;
  SummedAreaTablePass sat_pass;
  DepthHierarchyPass hierarchy_pass;
  gl::Buffer block_buffer{sizeof(ShadowBlock), nullptr, true, "penumbra shadow block"};
  gl::Buffer poisson = gl::Buffer::from(std::span<const glm::vec2>(poisson_square_samples()),
                                        "penumbra poisson samples");
  gl::Sampler nearest{gl::SamplerInfo{
      .min_filter = GL_NEAREST, .mag_filter = GL_NEAREST, .label = "penumbra nearest clamp"}};
  gl::Sampler bilinear{gl::SamplerInfo{.label = "penumbra bilinear clamp"}};
  gl::Sampler compare{gl::SamplerInfo{.compare_mode = GL_COMPARE_REF_TO_TEXTURE,
                                      .label = "penumbra depth compare"}};

  ShadowMapSettings settings;
  ShadowBlock block{};
  std::vector<int> view_light;  // the light of each view
  std::vector<LightShadowViews> fitted;
  std::vector<std::optional<ShadowViewInputs>> fit_inputs;
  CasterBoundsCache caster_bounds;  // of the casters last fitted to
  GLuint filtered = 0;
  bool updated = false;
  bool rendered = false;

  // What the maps hold, for caching them across frames (view_cache.hpp).
  ViewCache view_cache;
  std::optional<std::uint64_t> casters_hash;  // of the geometry last fitted to
  // The engine's generation of the geometry last fitted to, when it gave one
  // (casters_hash then unset).
  std::optional<std::uint64_t> casters_generation;
  std::vector<CasterBounds> bounds;    // the bounds form's boxes, by id
  std::vector<int> moved;              // ids marked by moved()
  std::vector<glm::vec3> box_corners;  // the boxes as triangles, for the fit
  std::vector<std::uint32_t> box_indices;
  std::optional<ShadowMapSettings> filtered_for;  // the settings the filtered maps hold
  int views_drawn = 0;
  int pages_drawn = 0;
  int state_queries = 0;  // the GL state the last render() read
  // The first directional light's virtual maps (ShadowMapKind::Virtual).
  ShadowMapsVirtual virtual_maps{bindings};
  // The stale views less those of the light with virtual maps.
  std::vector<std::uint8_t> stale_without_virtual;
  CameraDepthBuffer depth;  // the engine's, given to the last update()

  bool bounds_form = false;  // the last update() had caster bounds

  void update(std::span<const Light> lights, const CameraFrustum& camera, PositionSpan positions,
              std::span<const std::uint32_t> indices, const ShadowMapSettings& settings);
  // The technique's resolve and filter passes over the flagged layers
  // (filter/layer_runs.hpp; every layer without flags).
  void filter(const ShadowMapSettings& s, std::span<const std::uint8_t> layers);
};

namespace {

// The public header's GL-free types stand for these (OpenGL 4.5, table 2.2).
static_assert(sizeof(GLuint) == sizeof(std::uint32_t) && sizeof(GLint) == sizeof(std::int32_t));

// The implementation, or std::logic_error after release() (or a move).
template <typename ImplPtr>
auto& live(ImplPtr& impl, const char* call) {
  if (!impl) {
    throw std::logic_error(std::string("ShadowMaps::") + call + "() after release()");
  }
  return *impl;
}

// What update() refuses, checked before it changes anything.
void check_update(std::span<const Light> lights, const ShadowMapSettings& settings) {
  validate(settings);
  for (const Light& light : lights) validate(light);
  if (lights.size() > static_cast<std::size_t>(kMaxLights)) {
    throw UsageError("ShadowMaps: " + std::to_string(lights.size()) + " lights; at most " +
                     std::to_string(kMaxLights) + " are supported");
  }
}

// A hash of the caster geometry (positions and indices), so that update()
// refits when the engine's casters change: word by word, FNV-1a's
// constants on 32-bit words (cheaper than the fit it guards by far).
std::uint64_t hash_casters(PositionSpan positions, std::span<const std::uint32_t> indices) {
  std::uint64_t h = 0xcbf29ce484222325ull;
  auto mix = [&h](std::uint32_t word) { h = (h ^ word) * 0x100000001b3ull; };
  auto mix_float = [&mix](float f) {
    std::uint32_t word = 0;
    std::memcpy(&word, &f, sizeof word);
    mix(word);
  };
  mix(static_cast<std::uint32_t>(positions.size()));
  for (std::size_t i = 0; i < positions.size(); ++i) {
    const glm::vec3& p = positions[i];
    mix_float(p.x);
    mix_float(p.y);
    mix_float(p.z);
  }
  mix(static_cast<std::uint32_t>(indices.size()));
  for (const std::uint32_t index : indices) mix(index);
  return h;
}

// The boxes' twelve triangles each, for the fit (which reads triangles).
void box_triangles(std::span<const CasterBounds> boxes, std::vector<glm::vec3>& corners,
                   std::vector<std::uint32_t>& indices) {
  // The faces of the cube whose corner c has x, y, z from bits 0, 1, 2.
  static constexpr std::uint32_t kFaces[36] = {0, 2, 1, 1, 2, 3, 4, 5, 6, 5, 7, 6,
                                               0, 1, 4, 1, 5, 4, 2, 6, 3, 3, 6, 7,
                                               0, 4, 2, 2, 4, 6, 1, 3, 5, 3, 7, 5};
  corners.clear();
  indices.clear();
  for (const CasterBounds& box : boxes) {
    const auto first = static_cast<std::uint32_t>(corners.size());
    for (int c = 0; c < 8; ++c) {
      corners.emplace_back((c & 1) ? box.max.x : box.min.x, (c & 2) ? box.max.y : box.min.y,
                           (c & 4) ? box.max.z : box.min.z);
    }
    for (const std::uint32_t corner : kFaces) indices.push_back(first + corner);
  }
}

}  // namespace

void CasterView::set_model(const glm::mat4& model) const {
  glProgramUniformMatrix4fv(program, kModelLocation, 1, GL_FALSE, &model[0][0]);
}

ShadowMaps::ShadowMaps(const ShadowBindings& bindings, StateRestore restore)
    : impl_(std::make_unique<Impl>(checked_bindings(bindings), restore)) {}
// The GL objects' handles delete them only while a context is current
// (gl::Handle::reset): destroyed without one, they are forgotten.
ShadowMaps::~ShadowMaps() = default;
ShadowMaps::ShadowMaps(ShadowMaps&&) noexcept = default;
ShadowMaps& ShadowMaps::operator=(ShadowMaps&&) noexcept = default;

void ShadowMaps::update(std::span<const Light> lights, const CameraFrustum& camera,
                        const CasterGeometry& casters, const ShadowMapSettings& settings,
                        const CameraDepthBuffer& depth) {
  check_update(lights, settings);
  Impl& m = live(impl_, "update");
  // The engine's generation when it gives one, else a hash of every vertex.
  std::optional<std::uint64_t> hash, generation = casters.generation;
  if (!generation) hash = hash_casters(casters.positions, casters.indices);
  const bool same = generation ? m.casters_generation == generation : m.casters_hash == hash;
  if (!same || m.bounds_form) {
    // No objects to tell apart: every view may see the change.
    m.view_cache.invalidate();
    m.virtual_maps.invalidate();
    m.fit_inputs.clear();
    m.caster_bounds.clear();
  }
  m.casters_hash = hash;
  m.casters_generation = generation;
  m.bounds_form = false;
  m.bounds.clear();
  m.moved.clear();
  m.depth = depth;
  m.update(lights, camera, casters.positions, casters.indices, settings);
}

void ShadowMaps::update(std::span<const Light> lights, const CameraFrustum& camera,
                        std::span<const CasterBounds> casters, const ShadowMapSettings& settings,
                        const CameraDepthBuffer& depth) {
  check_update(lights, settings);
  Impl& m = live(impl_, "update");
  const bool same_objects = m.bounds_form && m.casters_hash && casters.size() == m.bounds.size();
  if (!same_objects) {
    m.view_cache.invalidate();
    m.virtual_maps.invalidate();
    m.fit_inputs.clear();
    m.caster_bounds.clear();
  } else {
    bool changed = false;
    for (std::size_t id = 0; id < casters.size(); ++id) {
      const bool marked =
          std::find(m.moved.begin(), m.moved.end(), static_cast<int>(id)) != m.moved.end();
      if (casters[id] != m.bounds[id] || marked) {
        m.view_cache.caster_moved(m.bounds[id], casters[id]);
        m.virtual_maps.caster_moved(m.bounds[id], casters[id]);
      }
      changed = changed || casters[id] != m.bounds[id];
    }
    // The fit reads the boxes: refitted when one moved.
    if (changed) {
      m.fit_inputs.clear();
      m.caster_bounds.clear();
    }
  }
  m.bounds_form = true;
  m.bounds.assign(casters.begin(), casters.end());
  m.moved.clear();
  box_triangles(casters, m.box_corners, m.box_indices);
  m.casters_hash = hash_casters(PositionSpan(m.box_corners), m.box_indices);
  m.casters_generation.reset();
  m.depth = depth;
  m.update(lights, camera, PositionSpan(m.box_corners), m.box_indices, settings);
}

void ShadowMaps::moved(int caster) {
  Impl& m = live(impl_, "moved");
  if (caster < 0 || static_cast<std::size_t>(caster) >= m.bounds.size()) {
    throw UsageError("ShadowMaps::moved(" + std::to_string(caster) + "): the last update() had " +
                     std::to_string(m.bounds.size()) + " caster bounds");
  }
  m.moved.push_back(caster);
}

void ShadowMaps::invalidate() {
  Impl& m = live(impl_, "invalidate");
  m.view_cache.invalidate();
  m.virtual_maps.invalidate();
  m.fit_inputs.clear();
  m.caster_bounds.clear();
  m.casters_hash.reset();
  m.casters_generation.reset();
  m.filtered_for.reset();
}

void ShadowMaps::Impl::update(std::span<const Light> lights, const CameraFrustum& camera,
                              PositionSpan positions, std::span<const std::uint32_t> indices,
                              const ShadowMapSettings& settings) {
  Impl& m = *this;
  m.virtual_maps.fit(lights, camera, positions, indices, m.caster_bounds, settings, m.depth);
  m.settings = settings;
  m.fitted.resize(lights.size());
  m.fit_inputs.resize(lights.size());
  m.view_light.clear();
  ShadowBlock block{};
  int view_count = 0;
  for (std::size_t i = 0; i < lights.size(); ++i) {
    ShadowViewInputs inputs = shadow_view_inputs(lights[i], camera, settings);
    if (m.fit_inputs[i] != inputs) {
      m.fitted[i] = fit_shadow_views(inputs, positions, indices, m.caster_bounds);
      m.fit_inputs[i] = std::move(inputs);
    }
    const LightShadowViews& views = m.fitted[i];
    if (view_count + static_cast<int>(views.views.size()) > kMaxShadowViews) {
      throw UsageError("ShadowMaps: the lights need more than " + std::to_string(kMaxShadowViews) +
                       " shadow views");
    }
    block.lights[i] = gpu_light(lights[i], views, view_count, settings);
    for (const LightView& view : views.views) {
      block.views[view_count++] = gpu_shadow_view(lights[i], view, settings);
      m.view_light.push_back(static_cast<int>(i));
    }
  }
  block.params = gpu_shadow_params(settings);
  block.camera_view = glm::lookAt(camera.position, camera.position + camera.forward, camera.up);
  block.counts =
      glm::ivec4(static_cast<int>(lights.size()), view_count, technique_define(settings.technique),
                 uses_quantized_moments(settings) ? 1 : 0);
  m.block = block;
  m.block_buffer.update(&m.block, sizeof m.block);
  m.updated = true;
}

void ShadowMaps::render(const DrawCasters& draw) {
  Impl& m = live(impl_, "render");
  if (!m.updated) throw std::logic_error("ShadowMaps::render() before update()");
  const ShadowMapSettings& s = m.settings;
  const int view_count = m.block.counts.y;
  // An array needs at least one layer: with no lights the lookup reads none.
  const std::span<const gpu::GpuShadowView> views(m.block.views,
                                                  static_cast<std::size_t>(view_count));
  std::span<const std::uint8_t> stale = m.view_cache.stale_views(views, s.map_size);
  const int virtual_light = m.virtual_maps.light();
  if (virtual_light >= 0) {
    // The light with virtual maps draws none of its cascades.
    m.stale_without_virtual.assign(stale.begin(), stale.end());
    m.stale_without_virtual.resize(static_cast<std::size_t>(view_count), 1);
    for (int v = 0; v < view_count; ++v) {
      if (m.view_light[static_cast<std::size_t>(v)] == virtual_light)
        m.stale_without_virtual[static_cast<std::size_t>(v)] = 0;
    }
    stale = m.stale_without_virtual;
  }
  // ShadowMapPass draws (and sets state) for a stale view, or for every
  // layer when there is no view (the cache flags every view of a new array).
  const bool draws = stale.empty() || std::find(stale.begin(), stale.end(), 1) != stale.end();
  // The resolve and the filter run again when a view is drawn (over the
  // drawn views' layers: the others' output is still current) or the
  // settings changed (over every layer).
  const bool settings_changed = m.filtered_for != s;
  const bool filters = draws || settings_changed;
  // Whether the technique has compute passes (filter()).
  const bool computes =
      filters && (is_filterable(s.technique) || s.technique == Technique::Backprojection);

  // What this frame's passes change, saved for the engine (GlStateGuard):
  // the caster pass's state, the block; the compute passes' input unit,
  // output images and the Gaussian's weights; nothing on a cached frame.
  const bool restore = m.restore == StateRestore::Full;
  static constexpr std::array<GLuint, 1> kComputeUnits{UNIT_COMPUTE_INPUT};
  static constexpr std::array<GLuint, 2> kImageUnits{IMAGE_OUTPUT, IMAGE_OUTPUT_2};
  static constexpr std::array<GLuint, 1> kStorageBuffers{BINDING_FILTER_WEIGHTS_SSBO};
  const std::array<GLuint, 1> uniform_buffers{m.bindings.block};
  // Virtual maps, every frame: marking (the camera's depth at a 2D unit,
  // the page table at an image unit), allocation and culling (their
  // storage buffers and block), and the pages' draws.
  const std::array<GLuint, 2> virtual_uniform_buffers{m.bindings.block, BINDING_VIRTUAL_UBO};
  std::vector<GLuint> virtual_storage_buffers;
  const bool virtual_pass = virtual_light >= 0;
  GlStateScope scope;
  if (restore && (draws || virtual_pass)) {
    scope.caster_pass = true;
    scope.uniform_buffers = uniform_buffers;
  }
  // The caster pass binds unit 0 too (ShadowMapPass's linearize pass).
  if (restore && (draws || computes)) scope.texture_units = kComputeUnits;
  if (restore && computes) {
    scope.image_units = kImageUnits;
    scope.storage_buffers = kStorageBuffers;
  }
  if (restore && virtual_pass) {
    scope.uniform_buffers = virtual_uniform_buffers;
    scope.image_units = kImageUnits;
    const std::span<const GLuint> buffers = ShadowMapsVirtual::storage_buffers();
    virtual_storage_buffers.assign(buffers.begin(), buffers.end());
    if (computes)
      virtual_storage_buffers.insert(virtual_storage_buffers.end(), kStorageBuffers.begin(),
                                     kStorageBuffers.end());
    scope.storage_buffers = virtual_storage_buffers;
    scope.texture_2d_units = ShadowMapsVirtual::texture_2d_units();
  }
  const GlStateGuard saved(scope);
  m.state_queries = saved.queries();

  m.views_drawn = 0;
  if (draws) {
    set_caster_pass_state();
    glBindBufferBase(GL_UNIFORM_BUFFER, m.bindings.block, m.block_buffer.id());
    m.views_drawn = m.map_pass.execute(
        [&](int view) {
          const gl::Program& caster =
              caster_depth(views[static_cast<std::size_t>(view)]) == CasterDepth::Written
                  ? m.radial_caster_program
                  : m.caster_program;
          const GLuint program = caster.id();
          const glm::mat4 identity(1.0f);
          glProgramUniform1i(program, 0, view);
          glProgramUniformMatrix4fv(program, CasterView::kModelLocation, 1, GL_FALSE,
                                    &identity[0][0]);
          caster.use();
          draw(CasterView{.index = view,
                          .light = m.view_light[static_cast<std::size_t>(view)],
                          .view_projection = m.block.views[view].view_projection,
                          .program = program});
        },
        views, s.map_size, stale, depth_samples(s));
  }
  m.pages_drawn = m.virtual_maps.render(draw, s, m.block_buffer.id());
  m.filtered_for = s;
  if (filters) m.filter(s, settings_changed ? std::span<const std::uint8_t>() : stale);
  m.rendered = true;
}

void ShadowMaps::Impl::filter(const ShadowMapSettings& s, std::span<const std::uint8_t> layers) {
  filtered = 0;
  if (s.technique == Technique::Backprojection) {
    // Backprojection's blocker regions, read in the filtered maps' place
    // (bind()).
    hierarchy_pass.execute(map_pass.depth_maps());
    filtered = hierarchy_pass.hierarchy().id();
    return;
  }
  if (!is_filterable(s.technique)) return;
  if (uses_fused_filter(s)) {
    fused_pass.execute(map_pass.sampled_depth_maps(), s, layers);
    filtered = fused_pass.output().id();
    return;
  }
  resolve_pass.execute(map_pass.sampled_depth_maps(), s, layers);
  filtered = resolve_pass.representation().id();
  if (filter_define(s) == FILTER_GAUSSIAN) {
    blur_pass.execute(resolve_pass.representation(), s.blur, nullptr, 1, layers);
    filtered = blur_pass.output().id();
  } else if (filter_define(s) == FILTER_SAT) {
    sat_pass.execute(resolve_pass.representation());
    filtered = sat_pass.table().id();
  }
}

void ShadowMaps::bind() const {
  const Impl& m = live(impl_, "bind");
  if (!m.rendered) throw std::logic_error("ShadowMaps::bind() before render()");
  // The indexed bindings and units below stay bound; glBindBufferBase
  // also moves the generic bindings, which the guard puts back.
  std::optional<GenericBufferBindingsGuard> saved;
  if (m.restore == StateRestore::Full) saved.emplace();
  const ShadowBindings& b = m.bindings;
  glBindBufferBase(GL_UNIFORM_BUFFER, b.block, m.block_buffer.id());
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, b.poisson_buffer, m.poisson.id());
  const GLuint depth = m.map_pass.depth_maps().id();
  glBindTextureUnit(b.depth_unit, depth);
  glBindSampler(b.depth_unit, m.nearest.id());
  glBindTextureUnit(b.compare_unit, depth);
  glBindSampler(b.compare_unit, m.compare.id());
  // The techniques that read no filtered map (or the summed-area tables
  // instead) have the depth maps stand in, so the sampler2DArray the
  // lookup declares is never left unbound.
  const bool sat = m.block.params.filter_type == FILTER_SAT;
  const bool filtered = m.filtered != 0 && !sat;
  glBindTextureUnit(b.filtered_unit, filtered ? m.filtered : depth);
  // Backprojection's depth hierarchy is read at every level (texelFetch):
  // its own mipmapped parameters, no sampler.
  const bool hierarchy = m.settings.technique == Technique::Backprojection;
  glBindSampler(b.filtered_unit, hierarchy ? 0 : (filtered ? m.bilinear.id() : m.nearest.id()));
  // The tables are read texel by texel (texelFetch: no sampler applies).
  glBindTextureUnit(b.sat_unit, sat ? m.filtered : 0);
  m.virtual_maps.bind();
}

const ShadowBindings& ShadowMaps::bindings() const {
  return live(impl_, "bindings").bindings;
}

void ShadowMaps::release() {
  impl_.reset();
}

const ShadowBlock& ShadowMaps::block() const {
  return live(impl_, "block").block;
}
int ShadowMaps::view_count() const {
  return live(impl_, "view_count").block.counts.y;
}
int ShadowMaps::views_drawn() const {
  return live(impl_, "views_drawn").views_drawn;
}
int ShadowMaps::pages_drawn() const {
  return live(impl_, "pages_drawn").pages_drawn;
}
int ShadowMaps::pages_resident() const {
  return live(impl_, "pages_resident").virtual_maps.pages_resident();
}
int ShadowMaps::virtual_light() const {
  return live(impl_, "virtual_light").virtual_maps.light();
}
int ShadowMaps::state_queries() const {
  return live(impl_, "state_queries").state_queries;
}
std::uint32_t ShadowMaps::depth_maps() const {
  return live(impl_, "depth_maps").map_pass.depth_maps().id();
}
std::uint32_t ShadowMaps::filtered_maps() const {
  return live(impl_, "filtered_maps").filtered;
}

}  // namespace penumbra
