#pragma once
// ShadowMaps' virtual shadow maps (ShadowMapKind::Virtual; include/
// penumbra/shadow_maps.hpp): the first directional light's clipmap,
// fitted in update(), its pages marked, allocated and drawn in render()
// through the engine's caster callback, one call per page to draw
// (VirtualShadowPass holds the pages; docs/library.md, "Virtual shadow
// maps").
#include <optional>
#include <span>
#include <vector>

#include "penumbra/camera_depth_buffer.hpp"
#include "penumbra/gl/program.hpp"
#include "penumbra/gl/resources.hpp"
#include "penumbra/shadow/caster_bounds.hpp"
#include "penumbra/shadow/virtual_shadow_pass.hpp"
#include "penumbra/shadow_maps.hpp"

namespace penumbra {

class ShadowMapsVirtual {
 public:
  explicit ShadowMapsVirtual(const ShadowBindings& bindings);

  // The light with virtual maps for these settings (the first directional
  // light; -1: none), and its clipmap fitted to the camera and the
  // engine's depth buffer. Throws UsageError for virtual maps without a
  // depth buffer.
  void fit(std::span<const Light> lights, const CameraFrustum& camera, PositionSpan positions,
           std::span<const std::uint32_t> indices, CasterBoundsCache& bounds,
           const ShadowMapSettings& settings, const CameraDepthBuffer& depth);
  [[nodiscard]] int light() const { return light_; }

  // A caster's box changed (the pages it covers, before and after, are
  // drawn again), or every page must be.
  void caster_moved(const CasterBounds& before, const CasterBounds& after);
  void invalidate();

  // The GL state render() touches for the virtual pass (GlStateScope).
  [[nodiscard]] static std::span<const GLuint> storage_buffers();
  [[nodiscard]] static std::span<const GLuint> texture_2d_units();

  // Marks, allocates and draws the listed pages through `draw` (with the
  // caster pass's state set by the caller). Returns the pages drawn.
  int render(const DrawCasters& draw, const ShadowMapSettings& settings, GLuint shadow_block);
  // Binds the block (a block with no light when there are no virtual
  // maps), the page table and the pool at the engine's bindings.
  void bind() const;
  [[nodiscard]] int pages_resident() const;

 private:
  ShadowBindings bindings_;
  std::optional<VirtualShadowPass> pass_;  // made for the first virtual frame
  std::optional<gl::Program> caster_program_;
  gl::Buffer no_virtual_block_;
  std::optional<VirtualClipmap> clipmap_;
  CameraDepthBuffer depth_;
  Light light_data_;
  int light_ = -1;
};

}  // namespace penumbra
