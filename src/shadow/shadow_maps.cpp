// ShadowMaps (include/penumbra/shadow_maps.hpp): the shadow core's passes
// wired for an engine, in the order penumbra's renderer runs them
// (src/render/renderer.cpp): fit, depth maps, resolve + filter.
#include "penumbra/shadow_maps.hpp"

#include <algorithm>
#include <array>
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
#include "shadow/gl_state_guard.hpp"
#include "shadow/shadow_lookup.hpp"

namespace penumbra {

struct ShadowMaps::Impl {
  explicit Impl(const ShadowBindings& b) : bindings(b) {}

  ShadowBindings bindings;
  // The caster program declares the block at the engine's binding.
  gl::Program caster_program = gl::Program::graphics(
      "shadow/caster_depth.vert", "shadow/caster_depth.frag", shadow_binding_defines(bindings));
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

  ShadowSettings settings;
  ShadowBlock block{};
  std::vector<int> view_light;  // the light of each view
  std::vector<LightShadowViews> fitted;
  std::vector<std::optional<ShadowViewInputs>> fit_inputs;
  GLuint filtered = 0;
  bool updated = false;
  bool rendered = false;
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

}  // namespace

ShadowMaps::ShadowMaps(const ShadowBindings& bindings)
    : impl_(std::make_unique<Impl>(checked_bindings(bindings))) {}
// The GL objects' handles delete them only while a context is current
// (gl::Handle::reset): destroyed without one, they are forgotten.
ShadowMaps::~ShadowMaps() = default;
ShadowMaps::ShadowMaps(ShadowMaps&&) noexcept = default;
ShadowMaps& ShadowMaps::operator=(ShadowMaps&&) noexcept = default;

void ShadowMaps::update(std::span<const Light> lights, const CameraFrustum& camera,
                        const CasterGeometry& casters, const ShadowSettings& settings) {
  validate(settings);
  if (settings.accumulate > 1) throw UsageError("ShadowMaps: accumulate is the renderer's");
  if (lights.size() > static_cast<std::size_t>(kMaxLights)) {
    throw UsageError("ShadowMaps: " + std::to_string(lights.size()) + " lights; at most " +
                     std::to_string(kMaxLights) + " are supported");
  }
  Impl& m = live(impl_, "update");
  m.settings = settings;
  m.fitted.resize(lights.size());
  m.fit_inputs.resize(lights.size());
  m.view_light.clear();
  ShadowBlock block{};
  int view_count = 0;
  for (std::size_t i = 0; i < lights.size(); ++i) {
    ShadowViewInputs inputs = shadow_view_inputs(lights[i], camera, settings);
    if (m.fit_inputs[i] != inputs) {
      m.fitted[i] = fit_shadow_views(inputs, casters.positions, casters.indices);
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
  // Saved besides the fixed state GlStateGuard always saves: the compute
  // passes' input unit and output images, the block, the Gaussian's weights.
  const std::array<GLuint, 1> texture_units{UNIT_COMPUTE_INPUT};
  const std::array<GLuint, 2> image_units{IMAGE_OUTPUT, IMAGE_OUTPUT_2};
  const std::array<GLuint, 1> uniform_buffers{m.bindings.block};
  const std::array<GLuint, 1> storage_buffers{BINDING_FILTER_WEIGHTS_SSBO};
  const GlStateGuard saved({texture_units, image_units, uniform_buffers, storage_buffers});
  set_caster_pass_state();
  glBindBufferBase(GL_UNIFORM_BUFFER, m.bindings.block, m.block_buffer.id());

  const ShadowSettings& s = m.settings;
  const int view_count = m.block.counts.y;
  // An array needs at least one layer: with no lights the lookup reads none.
  const GLuint program = m.caster_program.id();
  m.map_pass.execute(
      [&](int view) {
        const glm::mat4 identity(1.0f);
        glProgramUniform1i(program, 0, view);
        glProgramUniformMatrix4fv(program, CasterView::kModelLocation, 1, GL_FALSE,
                                  &identity[0][0]);
        m.caster_program.use();
        if (view < static_cast<int>(m.view_light.size())) {
          draw(CasterView{.index = view,
                          .light = m.view_light[static_cast<std::size_t>(view)],
                          .view_projection = m.block.views[view].view_projection,
                          .program = program});
        }
      },
      std::max(view_count, 1), s.map_size);

  m.filtered = 0;
  if (is_filterable(s.technique)) {
    if (uses_fused_filter(s)) {
      m.fused_pass.execute(m.map_pass.depth_maps(), s);
      m.filtered = m.fused_pass.output().id();
    } else {
      m.resolve_pass.execute(m.map_pass.depth_maps(), s);
      m.filtered = m.resolve_pass.representation().id();
      if (filter_define(s) == FILTER_GAUSSIAN) {
        m.blur_pass.execute(m.resolve_pass.representation(), s.blur);
        m.filtered = m.blur_pass.output().id();
      } else if (filter_define(s) == FILTER_SAT) {
        m.sat_pass.execute(m.resolve_pass.representation());
        m.filtered = m.sat_pass.table().id();
      }
    }
  } else if (s.technique == Technique::Backprojection) {
    // Read in the filtered maps' place (bind()).
    m.hierarchy_pass.execute(m.map_pass.depth_maps());
    m.filtered = m.hierarchy_pass.hierarchy().id();
  }
  m.rendered = true;
}

void ShadowMaps::bind() const {
  const Impl& m = live(impl_, "bind");
  if (!m.rendered) throw std::logic_error("ShadowMaps::bind() before render()");
  // The indexed bindings and units below stay bound; glBindBufferBase
  // also moves the generic bindings, which the guard puts back.
  const GenericBufferBindingsGuard saved;
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
std::uint32_t ShadowMaps::depth_maps() const {
  return live(impl_, "depth_maps").map_pass.depth_maps().id();
}
std::uint32_t ShadowMaps::filtered_maps() const {
  return live(impl_, "filtered_maps").filtered;
}

}  // namespace penumbra
