#pragma once
// The ground truth every technique is measured against: shadow rays from
// the surfaces the camera sees (rebuilt from the G-buffer) to the light,
// traced with Intel Embree 3 through the very triangles the GPU draws.
//
// The shadow factor is radiometric: the irradiance a point receives from
// the light's source with the occluders, over the irradiance without them.
// Each point of a Lambertian source adds L cos(theta_source)
// cos(theta_receiver) / d^2 dA (the point-to-area form factor's kernel);
// parts of the source below the receiver's tangent plane, or whose
// emitting side faces away from the receiver, add nothing with or without
// occluders, so they are in neither sum. Both sums use the same stratified
// samples (a ratio estimator): an unoccluded point reads exactly 1, and
// only the occluded part carries noise. A point light (size 0) takes one
// ray per pixel: the exact hard shadow.
#include <cstdint>
#include <functional>
#include <glm/glm.hpp>
#include <memory>
#include <vector>

#include "io/image.hpp"
#include "penumbra/settings.hpp"
#include "penumbra/shadow/light_view.hpp"
#include "reference/caster_cutouts.hpp"
#include "render/surface_points.hpp"
#include "scene/mesh.hpp"
#include "scene/scene.hpp"

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
  // Spot: the width of a square source facing `direction`, in world
  // units. Point: the diameter of a spherical source. Directional: the
  // angular diameter, in radians, of the disc of directions the sun fills
  // (a cone around -direction). 0: a point.
  float size = 0.0f;
  // Spot: cos of the cone's half-angle; points outside the cone receive no
  // light, so their shadow is not judged (alpha 0). -1: no cone.
  float cos_cone = -1.0f;
};

// The scene's light with the source size the techniques give it (its own,
// or the settings' where they set one: with_source_size): a spot light's
// square is `light_size` wide, a point light's sphere `light_size` in
// diameter, a directional light's disc of directions `sun_angle` degrees
// across. The square is oriented like the light's
// fitted shadow map.
ReferenceLight make_reference_light(const Light& light, const LightView& view,
                                    const ShadowSettings& settings);

// The largest |x|, |y| or |z| of the mesh's corners: the scene's extent
// (0 for an empty mesh).
float mesh_extent(const TriangleMesh& mesh);

// Whether a surface point can be traced: its position, normal and error
// bound are finite, the normal is a unit vector, and neither the position
// nor the bound is absurd: the point lies within 10^4 times the scene's
// extent (the G-buffer's points lie on the scene's triangles; tests trace
// points on planes the mesh leaves out) and its bound is no larger than
// twice the extent (with no triangles, both within Embree's range of
// coordinates). Points that are not are not traced: not judged.
bool traceable_point(const glm::vec3& p, const glm::vec3& n, float error, float extent);

// How many covered pixels of `surfaces` hold a point that is not
// traceable in a scene of that extent.
std::int64_t untraceable_points(const SurfacePoints& surfaces, float extent);

// Called from worker threads, possibly at once: rows done so far, of total.
using TraceProgress = std::function<void(std::int64_t done, std::int64_t total)>;

// What a trace did, for reporting its speed.
struct TraceStats {
  std::int64_t rays = 0;  // shadow rays traced (source points below a tangent plane take none)
  std::int64_t untraceable = 0;  // covered pixels not traced (traceable_point)
};

// A triangle mesh's corners (xyz floats per vertex, three indices per
// triangle) and its vertex normals: the smooth surface the normals
// describe, which the shadow rays start on.
struct SmoothMesh {
  const float* positions = nullptr;
  const std::uint32_t* indices = nullptr;
  const glm::vec3* normals = nullptr;
};

class ShadowRayTracer {
 public:
  // Builds Embree's BVH over the mesh. Throws RuntimeError if Embree fails.
  explicit ShadowRayTracer(const TriangleMesh& mesh);
  // The same, with the scene's materials: shadow rays pass through the
  // holes of alpha-tested casters and the backs of single-sided ones
  // (caster_cutouts.hpp). Keeps references to both.
  ShadowRayTracer(const TriangleMesh& mesh, const std::vector<Material>& materials);
  ~ShadowRayTracer();
  ShadowRayTracer(const ShadowRayTracer&) = delete;
  ShadowRayTracer& operator=(const ShadowRayTracer&) = delete;

  // The shadow factor of each pixel's surface point (1 = lit) in r, g and
  // b: irradiance from the light's source with occluders over without.
  // Alpha: 1 where the pixel sees geometry the light reaches (inside a
  // spot's cone, and some of the source above the tangent plane of the
  // surface's shading normal), 0 elsewhere; where no light arrives the
  // factor is undefined and reads 0 (as the `shadow` view has surfaces
  // facing away), and so it does where the surface point is not
  // traceable (traceable_point: not finite, or absurd); background pixels
  // read (1, 1, 1, 0), as in the `shadow` view. `samples` rays per pixel
  // for an area light, 1 for a point. Shadow rays start above the surface
  // by the surface point's position_error plus the rounding bound below,
  // and near a smooth-shaded terminator from the smooth surface
  // (reference/terminator_offset.hpp).
  // Uses every core; fills `stats` if given.
  [[nodiscard]] Image trace(const SurfacePoints& surfaces, const ReferenceLight& light, int samples,
                            const TraceProgress& progress = {}, TraceStats* stats = nullptr) const;

  // A bound of the rounding error of the point p (normal n) as stored and
  // as Embree tests a ray from it against a triangle, along n: pbrt-v4's
  // gamma(7) times the point's coordinates seen along n (its bound for a
  // point interpolated on a triangle), plus gamma(7) of the largest vertex
  // coordinate, since Embree's robust test works in coordinates relative
  // to the ray's origin that reach the far corners of a large triangle
  // such as a ground plane.
  [[nodiscard]] float rounding_error(const glm::vec3& p, const glm::vec3& n) const;

 private:
  RTCDeviceTy* device_ = nullptr;
  RTCSceneTy* scene_ = nullptr;
  float max_coordinate_ = 0.0f;  // the largest |x|, |y| or |z| of a vertex
  // The vertex normals, and with Embree's vertex and index buffers the
  // smooth surface the shadow rays start on (trace()).
  std::vector<glm::vec3> vertex_normals_;
  SmoothMesh smooth_;
  std::unique_ptr<CasterCutouts> cutouts_;  // null: nothing to cut
  // Rays per occlusion packet: the widest the device's instruction set
  // traces natively (16 with AVX-512, 8 with AVX2, 4 with SSE).
  int packet_width_ = 16;
};

}  // namespace penumbra
