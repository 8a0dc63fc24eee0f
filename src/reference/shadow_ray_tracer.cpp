#include "reference/shadow_ray_tracer.hpp"

#include <embree3/rtcore.h>
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstring>
#include <limits>
#include <string>

#include "core/error.hpp"
#include "reference/light_sampling.hpp"

namespace penumbra {

namespace {

void on_embree_error(void* /*user*/, RTCError /*code*/, const char* /*message*/) {
  // Errors are read back with rtcGetDeviceError where they matter; the
  // callback only keeps Embree from printing to stdout.
}

std::string embree_error(RTCDevice device, const std::string& what) {
  const RTCError code = rtcGetDeviceError(device);
  return "Embree: " + what + " failed (error " + std::to_string(static_cast<int>(code)) + ")";
}

// An unbiased, well-mixed 32-bit hash of the pixel index, so neighbouring
// pixels use unrelated sample patterns (noise rather than structured
// aliasing). The "lowbias32" finalizer (C. Wellons, hash-prospector).
std::uint32_t hash_pixel(std::uint32_t x) {
  x ^= x >> 16;
  x *= 0x7feb352du;
  x ^= x >> 15;
  x *= 0x846ca68bu;
  x ^= x >> 16;
  return x;
}

// A unit-sphere frame around w (unit): two axes perpendicular to it.
void frame_around(const glm::vec3& w, glm::vec3& u, glm::vec3& v) {
  const glm::vec3 helper =
      std::abs(w.x) < 0.9f ? glm::vec3(1.0f, 0.0f, 0.0f) : glm::vec3(0.0f, 1.0f, 0.0f);
  u = glm::normalize(glm::cross(w, helper));
  v = glm::cross(w, u);
}

// gamma(n) of Higham's error analysis, for float (pbrt-v4 section 6.8.1).
constexpr float gamma(int n) {
  constexpr float epsilon = 0x1p-24f;
  return static_cast<float>(n) * epsilon / (1.0f - static_cast<float>(n) * epsilon);
}

// 1 - cos(theta) of a cone of half-angle theta, without cancellation.
float one_minus_cos(float theta) {
  const float s = std::sin(0.5f * theta);
  return 2.0f * s * s;
}

bool occluded(RTCScene scene, const glm::vec3& origin, const glm::vec3& direction, float tfar) {
  RTCIntersectContext context;
  rtcInitIntersectContext(&context);
  RTCRay ray{};
  ray.org_x = origin.x;
  ray.org_y = origin.y;
  ray.org_z = origin.z;
  ray.tnear = 0.0f;
  ray.dir_x = direction.x;
  ray.dir_y = direction.y;
  ray.dir_z = direction.z;
  ray.time = 0.0f;
  ray.tfar = tfar;
  ray.mask = 0xffffffffu;
  ray.flags = 0;
  rtcOccluded1(scene, &context, &ray);
  // rtcOccluded1 sets tfar to -inf when it finds a hit.
  return ray.tfar < 0.0f;
}

// The geometric normal of the triangle under p (which lies within
// `reach` of it along n), facing n's side; n itself if no triangle is
// there (a point not on the mesh).
glm::vec3 facet_normal(RTCScene scene, const glm::vec3& p, const glm::vec3& n, float reach) {
  RTCIntersectContext context;
  rtcInitIntersectContext(&context);
  RTCRayHit hit{};
  const glm::vec3 origin = p + reach * n;
  hit.ray.org_x = origin.x;
  hit.ray.org_y = origin.y;
  hit.ray.org_z = origin.z;
  hit.ray.dir_x = -n.x;
  hit.ray.dir_y = -n.y;
  hit.ray.dir_z = -n.z;
  hit.ray.tnear = 0.0f;
  hit.ray.tfar = 2.0f * reach;
  hit.ray.mask = 0xffffffffu;
  hit.hit.geomID = RTC_INVALID_GEOMETRY_ID;
  rtcIntersect1(scene, &context, &hit);
  if (hit.hit.geomID == RTC_INVALID_GEOMETRY_ID) return n;
  glm::vec3 ng(hit.hit.Ng_x, hit.hit.Ng_y, hit.hit.Ng_z);
  const float length = glm::length(ng);
  if (!(length > 0.0f)) return n;
  ng /= length;
  return glm::dot(ng, n) < 0.0f ? -ng : ng;
}

// Embree's occlusion filter: a hit on a hole or on the back of a
// single-sided caster does not count.
void pass_cutouts(const RTCFilterFunctionNArguments* args) {
  const auto* cutouts = static_cast<const CasterCutouts*>(args->geometryUserPtr);
  for (unsigned i = 0; i < args->N; ++i) {
    if (args->valid[i] == 0) continue;
    const glm::vec3 direction(RTCRayN_dir_x(args->ray, args->N, i),
                              RTCRayN_dir_y(args->ray, args->N, i),
                              RTCRayN_dir_z(args->ray, args->N, i));
    if (cutouts->passes(RTCHitN_primID(args->hit, args->N, i), RTCHitN_u(args->hit, args->N, i),
                        RTCHitN_v(args->hit, args->N, i), direction)) {
      args->valid[i] = 0;
    }
  }
}

}  // namespace

ReferenceLight make_reference_light(const Light& light, const LightView& view,
                                    const ShadowSettings& settings) {
  ReferenceLight r;
  r.type = light.type;
  r.position = light.position;
  r.direction = glm::normalize(light.direction);
  // The view matrix's first two rows are the light's x and y axes in world
  // space.
  r.axis_u = glm::normalize(glm::vec3(view.view[0][0], view.view[1][0], view.view[2][0]));
  r.axis_v = glm::normalize(glm::vec3(view.view[0][1], view.view[1][1], view.view[2][1]));
  r.size =
      light.type != LightType::Directional ? settings.light_size : glm::radians(settings.sun_angle);
  r.cos_cone = light.type == LightType::Spot ? std::cos(glm::radians(light.cone_degrees)) : -1.0f;
  return r;
}

ShadowRayTracer::ShadowRayTracer(const TriangleMesh& mesh)
    : ShadowRayTracer(mesh, std::vector<Material>{}) {}

ShadowRayTracer::ShadowRayTracer(const TriangleMesh& mesh, const std::vector<Material>& materials) {
  if (CasterCutouts cutouts(mesh, materials); cutouts.any()) {
    cutouts_ = std::make_unique<CasterCutouts>(mesh, materials);
  }
  device_ = rtcNewDevice(nullptr);
  if (device_ == nullptr) throw RuntimeError(embree_error(nullptr, "creating a device"));
  rtcSetDeviceErrorFunction(device_, on_embree_error, nullptr);

  scene_ = rtcNewScene(device_);
  // Robust traversal: no ray slips through the shared edge of two
  // triangles, so a closed mesh never leaks light.
  rtcSetSceneFlags(scene_, RTC_SCENE_FLAG_ROBUST);
  rtcSetSceneBuildQuality(scene_, RTC_BUILD_QUALITY_HIGH);
  if (!mesh.indices.empty()) {
    RTCGeometry geometry = rtcNewGeometry(device_, RTC_GEOMETRY_TYPE_TRIANGLE);
    auto* vertices = static_cast<float*>(
        rtcSetNewGeometryBuffer(geometry, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3,
                                3 * sizeof(float), mesh.vertices.size()));
    auto* indices = static_cast<std::uint32_t*>(
        rtcSetNewGeometryBuffer(geometry, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3,
                                3 * sizeof(std::uint32_t), mesh.indices.size() / 3));
    if (vertices == nullptr || indices == nullptr) {
      rtcReleaseGeometry(geometry);
      const std::string message = embree_error(device_, "allocating the mesh");
      rtcReleaseScene(scene_);
      rtcReleaseDevice(device_);
      throw RuntimeError(message);
    }
    for (std::size_t i = 0; i < mesh.vertices.size(); ++i) {
      std::memcpy(vertices + 3 * i, &mesh.vertices[i].position, 3 * sizeof(float));
    }
    std::memcpy(indices, mesh.indices.data(),
                (mesh.indices.size() / 3) * 3 * sizeof(std::uint32_t));
    if (cutouts_ != nullptr) {
      rtcSetGeometryUserData(geometry, cutouts_.get());
      rtcSetGeometryOccludedFilterFunction(geometry, pass_cutouts);
    }
    rtcCommitGeometry(geometry);
    rtcAttachGeometry(scene_, geometry);
    rtcReleaseGeometry(geometry);
  }
  rtcCommitScene(scene_);
  if (rtcGetDeviceError(device_) != RTC_ERROR_NONE) {
    const std::string message = embree_error(device_, "building the scene");
    rtcReleaseScene(scene_);
    rtcReleaseDevice(device_);
    throw RuntimeError(message);
  }
  for (const Vertex& v : mesh.vertices) {
    const glm::vec3 a = glm::abs(v.position);
    max_coordinate_ = std::max({max_coordinate_, a.x, a.y, a.z});
  }
}

float ShadowRayTracer::rounding_error(const glm::vec3& p, const glm::vec3& n) const {
  return gamma(7) * (glm::dot(glm::abs(n), glm::abs(p)) + max_coordinate_);
}

ShadowRayTracer::~ShadowRayTracer() {
  rtcReleaseScene(scene_);
  rtcReleaseDevice(device_);
}

Image ShadowRayTracer::trace(const SurfacePoints& surfaces, const ReferenceLight& light,
                             int samples, const TraceProgress& progress) const {
  const int width = surfaces.width, height = surfaces.height;
  Image image(width, height);
  const bool spot = light.type == LightType::Spot;
  const bool area = light.size > 0.0f;
  const auto count = static_cast<std::uint32_t>(area ? std::max(samples, 1) : 1);
  const float infinity = std::numeric_limits<float>::infinity();
  const float radius = 0.5f * light.size;  // a point light's sphere
  // The sun's cone of directions around -direction.
  const float sun_one_minus_cos = one_minus_cos(0.5f * light.size);
  std::atomic<std::int64_t> rows_done{0};

  // A point of the source as seen from p: the unit direction towards it,
  // how far away it is, and its weight in the irradiance (0: it sends p
  // no light, occluders or not).
  struct SourcePoint {
    glm::vec3 direction{0.0f};
    float distance = 0.0f;
    float weight = 0.0f;
  };
  auto source_point = [&](const glm::vec3& p, const glm::vec3& n, glm::vec2 u) {
    SourcePoint q;
    if (light.type == LightType::Directional) {
      // The disc of directions, uniform in solid angle: each direction
      // weighs cos(theta_receiver) d(omega).
      q.direction = -light.direction;
      if (area) {
        const glm::vec3 c = uniform_cone(u, sun_one_minus_cos);
        q.direction =
            glm::normalize(c.x * light.axis_u + c.y * light.axis_v - c.z * light.direction);
      }
      q.distance = infinity;
      q.weight = glm::dot(n, q.direction);
    } else if (light.type == LightType::Point && area) {
      // A sphere of uniform radiance sends p L cos(theta_receiver) d(omega)
      // from each direction of the cone it subtends (the form factor's
      // kernel over its visible half, in solid angle): sample that cone
      // uniformly, up to the sphere's near side.
      const glm::vec3 to_centre = light.position - p;
      const float d = glm::length(to_centre);
      if (d <= radius) {  // inside the light: nothing can shade it
        q.direction = n;
        q.distance = 0.0f;
        q.weight = 1.0f;
        return q;
      }
      const glm::vec3 w = to_centre / d;
      glm::vec3 a, b;
      frame_around(w, a, b);
      const float sin2 = (radius / d) * (radius / d);
      const float cone = sin2 / (1.0f + std::sqrt(1.0f - sin2));  // 1 - cos(theta_max)
      const glm::vec3 c = uniform_cone(u, cone);
      q.direction = glm::normalize(c.x * a + c.y * b + c.z * w);
      const float along = d * glm::dot(q.direction, w);
      q.distance = along - std::sqrt(std::max(0.0f, radius * radius - (d * d - along * along)));
      q.weight = glm::dot(n, q.direction);
    } else {
      // A square facing `direction` (spot), or a point: each point weighs
      // cos(theta_source) cos(theta_receiver) / d^2 dA; a point light's
      // source has no side, so cos(theta_source) = 1.
      glm::vec3 target = light.position;
      if (area) {
        const glm::vec2 offset = (u - 0.5f) * light.size;
        target += offset.x * light.axis_u + offset.y * light.axis_v;
      }
      const glm::vec3 to_light = target - p;
      q.distance = glm::length(to_light);
      q.direction = to_light / q.distance;
      const float cos_source = spot && area ? -glm::dot(light.direction, q.direction) : 1.0f;
      q.weight = cos_source > 0.0f
                     ? cos_source * glm::dot(n, q.direction) / (q.distance * q.distance)
                     : 0.0f;
    }
    return q;
  };

  // Irradiance with occluders over without, from p with normal n whose
  // position is within `error` of its surface along n.
  auto shadow_factor = [&](const glm::vec3& p, const glm::vec3& n, float error,
                           std::uint32_t pattern) {
    // pbrt-v4's spawned ray origin: p moved along the normal by the bound
    // of its error, so that the ray starts on the light's side of the
    // surface it lies on however the rounding fell.
    const float offset = error + rounding_error(p, n);
    const glm::vec3 origin = p + offset * n;
    // The G-buffer's normal is interpolated from the vertices' (a smooth
    // sphere's), while the rays meet the flat triangles: near a terminator
    // a direction above the shading normal's tangent plane can be below
    // the triangle's own, and would be shadowed by the object's far side
    // (the "shadow terminator" artefact; Hanika, "Hacking the Shadow
    // Terminator", Ray Tracing Gems II, 2021). Such directions send no
    // light with or without occluders, as a path tracer's reflection
    // treats them (Cycles: no reflection below the geometric normal).
    const glm::vec3 ng = facet_normal(scene_, p, n, 2.0f * offset + 1e-6f);
    double with = 0.0, without = 0.0;
    for (std::uint32_t s = 0; s < count; ++s) {
      const SourcePoint q = source_point(p, n, cmj_sample(s, count, pattern));
      // Below either tangent plane, or the source's back: no light either
      // way.
      if (!(q.weight > 0.0f) || glm::dot(ng, q.direction) <= 0.0f) continue;
      without += q.weight;
      if (q.distance == 0.0f) {
        with += q.weight;
        continue;
      }
      glm::vec3 direction = q.direction;
      float distance = infinity;
      if (std::isfinite(q.distance)) {
        // Aim from the raised origin at the same point of the source.
        const glm::vec3 to_target = p + q.distance * q.direction - origin;
        distance = glm::length(to_target);
        direction = to_target / distance;
      }
      if (!occluded(scene_, origin, direction, distance)) with += q.weight;
    }
    // No light reaches the point, occluders or not: the ratio is
    // undefined (-1: not judged). On a smooth mesh's terminator the
    // triangle can face away from all of the source while the
    // interpolated normal a rasterizer shades with sees some of it.
    return without > 0.0 ? static_cast<float>(with / without) : -1.0f;
  };

  tbb::parallel_for(tbb::blocked_range<int>(0, height), [&](const tbb::blocked_range<int>& rows) {
    for (int y = rows.begin(); y != rows.end(); ++y) {
      for (int x = 0; x < width; ++x) {
        const std::size_t i = static_cast<std::size_t>(y) * width + x;
        float* out = image.pixel(x, y);
        if (!surfaces.covered[i]) {
          out[0] = out[1] = out[2] = 1.0f;
          out[3] = 0.0f;
          continue;
        }
        const glm::vec3 p = surfaces.position[i], n = surfaces.normal[i];
        const float error = i < surfaces.position_error.size() ? surfaces.position_error[i] : 0.0f;
        const float v = shadow_factor(p, n, error, hash_pixel(static_cast<std::uint32_t>(i)));
        out[0] = out[1] = out[2] = std::max(v, 0.0f);
        const bool inside_cone = !spot || glm::dot(glm::normalize(p - light.position),
                                                   light.direction) >= light.cos_cone;
        out[3] = inside_cone && v >= 0.0f ? 1.0f : 0.0f;
      }
      const std::int64_t done = ++rows_done;
      if (progress) progress(done, height);
    }
  });
  return image;
}

}  // namespace penumbra
