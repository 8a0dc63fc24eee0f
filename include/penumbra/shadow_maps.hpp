#pragma once
// penumbra's shadow core as an engine uses it. ShadowMaps
//   - fits each light's shadow views to the engine's camera and casters
//     (update): a spot light's perspective view, a point light's six cube
//     faces (widened by a guard band), a directional light's cascades
//     (stable: snapped to texels, sized by their slice's bounding sphere,
//     or with tight_cascades fitted to what their slice sees),
//     each view's depth range bounded by what it must shadow;
//   - owns the maps: a depth-texture array, one layer per view, into which
//     the engine draws its casters through a callback (render), and the
//     technique's representation (VSM/ESM/EVSM/MSM moments) filtered by a
//     Gaussian or summed into summed-area tables (settings.filter);
//   - binds them, with one uniform block, for the lookup in the engine's
//     own lighting shader (bind, shadow_lookup_glsl(): penumbra_shadow()).
// The engine owns its context, framebuffers, meshes, camera and lighting;
// ShadowMaps never draws anything but through the callback.
//
// This header and the others penumbra.hpp includes bring no GL loader and
// no GL header: OpenGL names are std::uint32_t (GLuint) and locations
// std::int32_t (GLint), so they go with glad, GLEW, epoxy or the engine's
// own loader. The library resolves its own GL functions (libepoxy, linked
// inside it). The low-level headers (penumbra/gl/, shadow/, filter/)
// include <epoxy/gl.h>.
#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <string_view>

#include "camera_depth_buffer.hpp"
#include "light.hpp"
#include "position_span.hpp"
#include "settings.hpp"
#include "shadow_block.hpp"

namespace penumbra {

// The casters (and receivers) the views are fitted to, in world space: a
// triangle list over the engine's vertex positions, indexed by 32-bit
// vertex numbers (an engine with 16-bit indices widens them, or passes
// boxes: the update() overload over CasterBounds). Coarse stand-ins fit
// views as well as the real meshes. When they change, update() refits
// every light and draws every view again. It tells a change by
// `generation` when the engine gives one: a number the engine bumps
// whenever it changes the positions or indices (O(1) per frame; the
// engine's own dirty flag or frame counter). Without one it hashes every
// vertex and index (O(n) per frame: safe whatever the engine does).
struct CasterGeometry {
  PositionSpan positions;
  std::span<const std::uint32_t> indices;  // three per triangle
  std::optional<std::uint64_t> generation = std::nullopt;
};

// One shadow view as the caster callback sees it: a view of the depth
// array, or with virtual maps one page of the light's clipmap.
struct CasterView {
  int index = 0;  // the view: the layer of the depth array (-1: a virtual page)
  int light = 0;  // the light it belongs to
  // world -> clip, for the engine's own culling: the view's, or the
  // virtual page's (an orthographic box over the page's 128^2 texels:
  // casters outside it need not be drawn).
  glm::mat4 view_projection{1.0f};
  // penumbra's caster program, bound: its vertex shader reads the position
  // at attribute location 0 and places it in the world with the mat4
  // uniform "model" at location kModelLocation (identity until the
  // callback sets it, for each view). set_model() sets it; so does an
  // engine's glUniformMatrix4fv(glGetUniformLocation(program, "model"), ...).
  std::uint32_t program = 0;                         // a GLuint
  static constexpr std::int32_t kModelLocation = 1;  // a GLint
  int page = -1;  // a virtual page: its index among the pages render() draws, else -1
  // Places the next draws' vertices in the world (object -> world).
  void set_model(const glm::mat4& model) const;
};

// Draws the engine's casters for one view: binds its vertex arrays (and
// sets the model matrix per object) and issues its draws. The program,
// the framebuffer (the view's layer, or the virtual page's, cleared) and
// the viewport are set; the callback must not change them. Called only
// for the views (and virtual pages) whose maps must be drawn again
// (render()); it draws every caster the view sees, static ones included.
using DrawCasters = std::function<void(const CasterView&)>;

// What render() and bind() do with the engine's GL state. Full (the
// default): they read what they are about to change (only that: nothing on
// a frame whose maps are cached) and put it back. None: for an engine
// that sets all the state it draws with itself before each of its passes
// (as most engines do); they read no state, and leave what they set
// (docs/library.md, "GL state": framebuffers, viewport 0, program, vertex
// array, depth, cull, scissor, clip distances, compute units and images,
// the generic and indexed buffer bindings they use). Queries cost nothing
// on llvmpipe but can stall a driver that runs ahead of the application.
enum class StateRestore { Full, None };

class ShadowMaps {
 public:
  // Needs a current OpenGL 4.5 core context (the one the engine renders
  // with). Compiles penumbra's programs: throws RuntimeError if they fail.
  // `bindings`: where bind() puts the block, the maps and the sample set
  // (and render() the block); the lookup must be generated with the same
  // (shadow_lookup_glsl(bindings)). Throws UsageError if two texture units
  // coincide or a binding is past the context's limit.
  // `restore`: see StateRestore.
  explicit ShadowMaps(const ShadowBindings& bindings = {},
                      StateRestore restore = StateRestore::Full);
  // Frees the GL objects if a context is current (it must be the one they
  // were made in); without a current context (the engine destroyed it
  // first) or after release() it calls no GL function and leaves the
  // objects to the context's destruction.
  ~ShadowMaps();
  ShadowMaps(ShadowMaps&&) noexcept;
  ShadowMaps& operator=(ShadowMaps&&) noexcept;
  ShadowMaps(const ShadowMaps&) = delete;
  ShadowMaps& operator=(const ShadowMaps&) = delete;

  // Fits every light's shadow views for this frame (at most kMaxLights
  // lights; a directional light takes settings.cascades views, a point
  // light 6, a spot light 1; kMaxShadowViews in all) and fills the block.
  // A light is refitted only when its inputs change (a spot or point light
  // not when the camera moves). Each light's own source size
  // (Light::light_size, sun_angle) sets its penumbrae. Throws UsageError
  // for settings or a light's source size out of range (validate()), or
  // too many lights or views.
  //
  // settings.shadow_maps == ShadowMapKind::Virtual: the first directional
  // light's shadow comes from virtual maps (docs/library.md, "Virtual
  // shadow maps"), a clipmap fitted to `camera` and `depth`, the engine's
  // depth buffer of this frame's camera, whose pixels render() marks the
  // pages from (`depth.texture` must hold the frame's depth when render()
  // runs; its size, projection and depth convention are read here).
  // Throws UsageError when virtual maps are asked for without a depth
  // buffer.
  void update(std::span<const Light> lights, const CameraFrustum& camera,
              const CasterGeometry& casters, const ShadowMapSettings& settings,
              const CameraDepthBuffer& depth = {});
  // The same with the casters' world-space bounding boxes, one per object
  // (its index is the caster's id): the views are fitted to the boxes, and
  // a caster whose box changed since the last update() has the views that
  // see it (before or after) drawn again, and no other.
  void update(std::span<const Light> lights, const CameraFrustum& camera,
              std::span<const CasterBounds> casters, const ShadowMapSettings& settings,
              const CameraDepthBuffer& depth = {});
  // Caster `id` of the bounds form changed inside an unchanged box (it
  // turned, or its mesh changed): the views that see it are drawn again at
  // the next update() and render(). Throws UsageError for an id the last
  // update() did not have.
  void moved(int caster);
  // The next update() refits every light and render() draws every view:
  // for casters that changed in a way update() cannot see.
  void invalidate();

  // Renders the maps for the last update(): draw(view) for every view
  // whose depths changed (its light or its fit changed, a caster it sees
  // moved, the map size or the view count changed; every view on the
  // first call), then, when a view was drawn or the settings changed, the
  // technique's resolve and filter passes (compute). A frame where nothing
  // changed draws nothing and touches no GL state (views_drawn() says how
  // many it drew). Sets the state it needs for viewport 0 (scissor and
  // rasterizer discard off, fill, depth test LESS with writes, no culling,
  // no polygon offset or depth clamp, clip distances 0-7 off, clip control
  // lower-left / 0..1, depth range 0..1; the callback sees them so) and,
  // with StateRestore::Full, leaves every piece of GL state it touches as
  // it found it: the table in docs/library.md ("GL state") lists them.
  //
  // With virtual maps it also, every frame, marks the pages the depth
  // buffer's pixels read, allocates them in the page pool and lists those
  // to draw (compute passes; pages cached from earlier frames are not
  // drawn again), reads that list back (a few bytes: the one wait of the
  // frame), and calls draw() once per listed page (CasterView::page)
  // into its pool page.
  void render(const DrawCasters& draw);

  // Binds what penumbra_shadow() reads, at bindings(), and leaves it
  // bound: the block (uniform buffer .block), the virtual maps' block,
  // page table and pool (.virtual_block, .page_table_unit,
  // .page_pool_unit; a block saying no light has them when none has),
  // the depth maps (units
  // .depth_unit, nearest, and .compare_unit, with a comparison sampler),
  // the filtered maps (unit .filtered_unit, bilinear), the summed-area
  // tables (unit .sat_unit; no texture without Filter::Sat) and PCF's
  // sample set (storage buffer .poisson_buffer). Everything else, the
  // generic GL_UNIFORM_BUFFER and GL_SHADER_STORAGE_BUFFER bindings
  // included, is left as it was (docs/library.md, "GL state"). Valid after
  // render().
  void bind() const;

  // The binding points given to the constructor.
  [[nodiscard]] const ShadowBindings& bindings() const;

  // Frees every GL object ShadowMaps owns; call it while the context is
  // still current, before the engine destroys it. Afterwards only the
  // destructor (which then calls no GL) and assignment are valid; the
  // other calls throw std::logic_error.
  void release();

  // The block as last uploaded, the views' count, and the textures (GL
  // names owned by ShadowMaps), for an engine that binds them itself.
  [[nodiscard]] const ShadowBlock& block() const;
  [[nodiscard]] int view_count() const;
  // The views the last render() drew (0: every map was cached).
  [[nodiscard]] int views_drawn() const;
  // The virtual pages the last render() drew (0: none, or every page the
  // camera reads was cached), and the pages resident in the pool then.
  [[nodiscard]] int pages_drawn() const;
  [[nodiscard]] int pages_resident() const;
  // The light with virtual maps in the last update() (-1: none).
  [[nodiscard]] int virtual_light() const;
  // The glGet* and glIsEnabled* calls the last render() made to save the
  // engine's state (0 when nothing was drawn or filtered, or with
  // StateRestore::None).
  [[nodiscard]] int state_queries() const;
  [[nodiscard]] std::uint32_t depth_maps() const;
  // The filtered maps, or with --filter sat the summed-area tables (an
  // unsigned-integer array); 0 for the techniques that read depth maps.
  [[nodiscard]] std::uint32_t filtered_maps() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

// The lookup's GLSL (shaders/shadow/penumbra_shadows.glsl with its
// includes expanded; with the default bindings, the same text is installed
// as share/penumbra/penumbra_shadows.glsl). It declares the block, the
// samplers and the sample set at `bindings` (which must be ShadowMaps'),
// and
//   float penumbra_shadow(int light, vec3 world_position, vec3 world_normal)
// (the fraction of the light that reaches the point, 1 = lit), with one
// entry point per technique (penumbra_shadow_pcf, ..._msm, ...).
// A guest in the engine's shader: every other name it declares (macros,
// structs, blocks, functions, constants) begins with PENUMBRA_, Penumbra
// or penumbra_, so it cannot collide with the engine's own. Insert it
// right after the engine's "#version 450 core" line: it ends with
// "#line 2", so the engine's following lines keep their own numbers in
// the driver's messages (inside the lookup, the numbers are the lookup
// text's own). Throws UsageError if two texture units coincide.
std::string shadow_lookup_glsl(const ShadowBindings& bindings = {});

// `shader` (an engine's GLSL source) with the lookup inserted after its
// #version line and the #extension and #define PENUMBRA_... lines that
// follow it (PENUMBRA_NO_FRAGMENT_ENTRY_POINTS), and a #line that restores
// the shader's own line numbers after it. Throws UsageError if
// `shader` has no #version line, or as shadow_lookup_glsl().
std::string insert_shadow_lookup(std::string_view shader, const ShadowBindings& bindings = {});

}  // namespace penumbra
