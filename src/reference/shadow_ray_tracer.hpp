#pragma once
// The ground truth every technique is measured against: shadow rays from
// the surfaces the camera sees (rebuilt from the G-buffer) to the light,
// traced with Intel Embree 3 through the very triangles the GPU draws.
//
// A point light (size 0) takes one ray per pixel: the exact hard shadow. An
// area light takes stratified rays to points spread over it: the fraction
// of the light visible, the physically right soft shadow (the visibility
// alone, not weighted by distance or angle, so it stays comparable with a
// shadow factor).
#include <cstdint>
#include <functional>
#include <glm/glm.hpp>

#include "core/settings.hpp"
#include "io/image.hpp"
#include "render/surface_points.hpp"
#include "scene/mesh.hpp"
#include "scene/scene.hpp"
#include "shadow/light_view.hpp"

// Embree's handle types (RTCDevice, RTCScene), so this header needs no
// Embree include.
struct RTCDeviceTy;
struct RTCSceneTy;

namespace penumbra {

// A light as the tracer samples it.
struct ReferenceLight {
  LightType type = LightType::Spot;
  glm::vec3 position{0.0f};                // spot, point: the centre of the light
  glm::vec3 direction{0.0f, -1.0f, 0.0f};  // unit: the way the light shines
  // Unit axes of the light's square, perpendicular to `direction`: the
  // shadow map's x and y, so the square lines up with the map's texels.
  glm::vec3 axis_u{1.0f, 0.0f, 0.0f};
  glm::vec3 axis_v{0.0f, 0.0f, 1.0f};
  // Spot: the square's width in world units. Point: the diameter of a
  // spherical source. Directional: the square of directions' width at unit
  // distance (2 tan(angular width / 2)). 0: a point.
  float size = 0.0f;
  // Spot: cos of the cone's half-angle; points outside the cone receive no
  // light, so their shadow is not judged (alpha 0). -1: no cone.
  float cos_cone = -1.0f;
};

// The scene's light with the source size the techniques give it (as PCSS
// models it, shaders/shadow/penumbra.glsl): a spot light's square is
// `light_size` wide, a point light's sphere `light_size` in diameter; a
// directional light's square of directions is
// 2 tan(sun_angle / 2) wide at unit distance. Oriented like its fitted
// shadow map.
ReferenceLight make_reference_light(const Light& light, const LightView& view,
                                    const ShadowSettings& settings);

// Called from worker threads, possibly at once: rows done so far, of total.
using TraceProgress = std::function<void(std::int64_t done, std::int64_t total)>;

class ShadowRayTracer {
 public:
  // Builds Embree's BVH over the mesh. Throws RuntimeError if Embree fails.
  explicit ShadowRayTracer(const TriangleMesh& mesh);
  ~ShadowRayTracer();
  ShadowRayTracer(const ShadowRayTracer&) = delete;
  ShadowRayTracer& operator=(const ShadowRayTracer&) = delete;

  // The visible fraction of the light from each pixel's surface point (1 =
  // lit) in r, g and b; 0 where the surface faces away from the light (as
  // the `shadow` view has it), and for an area light, the samples below the
  // surface's tangent plane count as hidden. Alpha: 1 where the pixel sees
  // geometry the light reaches (inside a spot's cone), 0 elsewhere;
  // background pixels read (1, 1, 1, 0), as in the `shadow` view.
  // `samples` rays per pixel for an area light, 1 for a point. Uses every
  // core.
  [[nodiscard]] Image trace(const SurfacePoints& surfaces, const ReferenceLight& light, int samples,
                            const TraceProgress& progress = {}) const;

  // How far shadow rays start from the surface, along its normal, to clear
  // the surface's own triangles: 1e-4 of the scene's bounding-box diagonal.
  [[nodiscard]] float ray_offset() const { return ray_offset_; }

 private:
  RTCDeviceTy* device_ = nullptr;
  RTCSceneTy* scene_ = nullptr;
  float ray_offset_ = 0.0f;
};

}  // namespace penumbra
