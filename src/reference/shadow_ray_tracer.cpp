#include "reference/shadow_ray_tracer.hpp"

#include <embree3/rtcore.h>
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

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

// A point of the unit disk from a point of the unit square, area-uniform
// and keeping strata apart (Shirley & Chiu, "A Low Distortion Map Between
// Disk and Square", JGT 1997: concentric squares to concentric circles).
glm::vec2 concentric_disk(glm::vec2 u) {
  const glm::vec2 a = 2.0f * u - 1.0f;
  if (a.x == 0.0f && a.y == 0.0f) return glm::vec2(0.0f);
  const float quarter_pi = 0.78539816f;
  float r = 0.0f, phi = 0.0f;
  if (std::abs(a.x) > std::abs(a.y)) {
    r = a.x;
    phi = quarter_pi * (a.y / a.x);
  } else {
    r = a.y;
    phi = 2.0f * quarter_pi - quarter_pi * (a.x / a.y);
  }
  return r * glm::vec2(std::cos(phi), std::sin(phi));
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
  r.size = light.type != LightType::Directional
               ? settings.light_size
               : 2.0f * std::tan(glm::radians(0.5f * settings.sun_angle));
  r.cos_cone = light.type == LightType::Spot ? std::cos(glm::radians(light.cone_degrees)) : -1.0f;
  return r;
}

ShadowRayTracer::ShadowRayTracer(const TriangleMesh& mesh) {
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
  const Bounds bounds = mesh.bounds();
  ray_offset_ = bounds.empty() ? 1e-4f : 1e-4f * glm::length(bounds.max - bounds.min);
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
  const bool positional = light.type != LightType::Directional;
  const bool sphere = light.type == LightType::Point;
  const bool area = light.size > 0.0f;
  const auto count = static_cast<std::uint32_t>(area ? std::max(samples, 1) : 1);
  const float infinity = std::numeric_limits<float>::infinity();
  std::atomic<std::int64_t> rows_done{0};

  // Visible fraction of the light from point p with normal n.
  auto visibility = [&](const glm::vec3& p, const glm::vec3& n, std::uint32_t pattern) {
    const glm::vec3 origin = p + ray_offset_ * n;
    // A sphere seen from p is a disk facing p: sample that disk (its
    // projected solid angle differs from the disk's by O((r/d)^2)).
    glm::vec3 axis_u = light.axis_u, axis_v = light.axis_v;
    if (sphere) {
      const glm::vec3 w = glm::normalize(light.position - p);
      const glm::vec3 helper =
          std::abs(w.x) < 0.9f ? glm::vec3(1.0f, 0.0f, 0.0f) : glm::vec3(0.0f, 1.0f, 0.0f);
      axis_u = glm::normalize(glm::cross(w, helper));
      axis_v = glm::cross(w, axis_u);
    }
    std::uint32_t visible = 0;
    for (std::uint32_t s = 0; s < count; ++s) {
      glm::vec2 offset(0.0f);
      if (area && sphere) {
        offset = concentric_disk(cmj_sample(s, count, pattern)) * (0.5f * light.size);
      } else if (area) {
        offset = (cmj_sample(s, count, pattern) - 0.5f) * light.size;
      }
      const glm::vec3 across = offset.x * axis_u + offset.y * axis_v;
      glm::vec3 to_light;
      float distance = infinity;
      if (positional) {
        to_light = light.position + across - p;
        distance = glm::length(to_light);
        to_light /= distance;
      } else {
        to_light = glm::normalize(-light.direction + across);
      }
      // The surface hides the part of the light below its tangent plane.
      if (glm::dot(n, to_light) <= 0.0f) continue;
      if (positional) distance = glm::length(light.position + across - origin);
      if (!occluded(scene_, origin, to_light, distance)) ++visible;
    }
    return static_cast<float>(visible) / static_cast<float>(count);
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
        const float v = visibility(p, n, hash_pixel(static_cast<std::uint32_t>(i)));
        out[0] = out[1] = out[2] = v;
        const bool inside_cone = !spot || glm::dot(glm::normalize(p - light.position),
                                                   light.direction) >= light.cos_cone;
        out[3] = inside_cone ? 1.0f : 0.0f;
      }
      const std::int64_t done = ++rows_done;
      if (progress) progress(done, height);
    }
  });
  return image;
}

}  // namespace penumbra
