#include "reference/shadow_ray_tracer.hpp"

#include <embree3/rtcore.h>
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <atomic>
#include <bit>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <iterator>
#include <limits>
#include <string>
#include <type_traits>

#include "core/light_sampling.hpp"
#include "penumbra/error.hpp"
#include "reference/source_point_sets.hpp"
#include "reference/terminator_offset.hpp"

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

// Embree's device configuration: PENUMBRA_EMBREE_CONFIG when set (for
// example "isa=avx2" to run the kernels another CPU would; the tests force
// each instruction set this way), else Embree's defaults.
const char* embree_device_config() {
  const char* config = std::getenv("PENUMBRA_EMBREE_CONFIG");
  return config != nullptr && config[0] != '\0' ? config : nullptr;
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

// Lane `lane` of a packet (RTCRay4, RTCRay8 or RTCRay16): a ray from
// `origin` along `direction` (not necessarily unit) up to tfar.
template <class Rays>
void set_ray(Rays& rays, int lane, const glm::vec3& origin, const glm::vec3& direction,
             float tfar) {
  rays.org_x[lane] = origin.x;
  rays.org_y[lane] = origin.y;
  rays.org_z[lane] = origin.z;
  rays.tnear[lane] = 0.0f;
  rays.dir_x[lane] = direction.x;
  rays.dir_y[lane] = direction.y;
  rays.dir_z[lane] = direction.z;
  rays.time[lane] = 0.0f;
  rays.tfar[lane] = tfar;
  rays.mask[lane] = 0xffffffffu;
  rays.id[lane] = static_cast<unsigned>(lane);
  rays.flags[lane] = 0;
}

// Lane `lane` of a packet, explicitly inactive: a finite ray whose
// interval is empty (tnear > tfar). Embree 3 traces a 16-wide packet on a
// CPU without a native 16-wide kernel (AVX2, SSE) through a fallback that
// takes every lane whose tnear <= tfar as active, whatever the valid mask
// says, and Debian builds Embree with its asserts on: a lane left holding
// an earlier packet's ray, or uninitialized memory, is traced or aborts the
// program ("all(valid, ray.valid())"). So no lane is left to the mask.
template <class Rays>
void set_inactive(Rays& rays, int lane) {
  set_ray(rays, lane, glm::vec3(0.0f), glm::vec3(0.0f, 0.0f, 1.0f), -1.0f);
}

// The valid mask of a packet whose first `size` lanes are filled (the
// others are made inactive in `rays` too), and the context for its rays,
// which share an origin or nearly a direction.
template <class Rays>
RTCIntersectContext coherent_packet(int* valid, int size, Rays& rays) {
  constexpr int kLanes = static_cast<int>(std::size(Rays{}.tfar));
  for (int lane = 0; lane < kLanes; ++lane) {
    valid[lane] = lane < size ? -1 : 0;
    if (lane >= size) set_inactive(rays, lane);
  }
  RTCIntersectContext context;
  rtcInitIntersectContext(&context);
  context.flags = RTC_INTERSECT_CONTEXT_FLAG_COHERENT;
  return context;
}

// Embree's ray packet of N lanes and its occlusion query.
template <int N>
struct RayPacket;
template <>
struct RayPacket<4> {
  using Rays = RTCRay4;
  static void occluded(const int* valid, RTCScene scene, RTCIntersectContext* context, Rays* rays) {
    rtcOccluded4(valid, scene, context, rays);
  }
};
template <>
struct RayPacket<8> {
  using Rays = RTCRay8;
  static void occluded(const int* valid, RTCScene scene, RTCIntersectContext* context, Rays* rays) {
    rtcOccluded8(valid, scene, context, rays);
  }
};
template <>
struct RayPacket<16> {
  using Rays = RTCRay16;
  static void occluded(const int* valid, RTCScene scene, RTCIntersectContext* context, Rays* rays) {
    rtcOccluded16(valid, scene, context, rays);
  }
};

// Shadow rays traced N at a time with Embree's rtcOccludedN (one call per
// packet instead of per ray; Embree traverses the packet's rays together,
// and a pixel's rays to one light share their origin and nearly their
// direction). N is the widest packet the device's instruction set traces
// natively (packet_width_): Embree 3 hands a wider packet to its stream
// fallback, which repacks it into native packets and back. (On the
// default scene with isa=avx2 on a Xeon both ran at 51 M rays per
// CPU-second; the native width saves the repacking wherever it costs.)
// Each ray remembers the pixel it serves and the weight of its source
// point; one that reaches the light adds the weight to that pixel's lit
// sum, in the order the rays were added, so the sums do not depend on N.
// An occlusion filter attached to a geometry sees these packets.
template <int N>
class OcclusionPackets {
 public:
  static constexpr int kWidth = N;

  // `lit`: the pixels' lit sums, indexed as add() is given them.
  OcclusionPackets(RTCScene scene, double* lit) : scene_(scene), lit_(lit) {}

  void add(const glm::vec3& origin, const glm::vec3& direction, float tfar, int pixel,
           float weight) {
    const int lane = size_;
    set_ray(rays_, lane, origin, direction, tfar);
    pixel_[lane] = pixel;
    weight_[lane] = weight;
    if (++size_ == kWidth) flush();
  }

  // Traces the rays added since the last flush.
  void flush() {
    if (size_ == 0) return;
    RTCIntersectContext context = coherent_packet(valid_, size_, rays_);
    RayPacket<N>::occluded(valid_, scene_, &context, &rays_);
    // rtcOccludedN sets tfar to -inf where it finds a hit.
    for (int lane = 0; lane < size_; ++lane) {
      if (rays_.tfar[lane] >= 0.0f) lit_[pixel_[lane]] += weight_[lane];
    }
    traced_ += size_;
    size_ = 0;
  }

  [[nodiscard]] std::int64_t traced() const { return traced_; }

 private:
  RTCScene scene_;
  double* lit_;
  typename RayPacket<N>::Rays rays_{};
  alignas(64) int valid_[kWidth] = {};
  int pixel_[kWidth] = {};
  float weight_[kWidth] = {};
  int size_ = 0;
  std::int64_t traced_ = 0;
};

// The geometric normals of the triangles under receivers, 16 at a time
// (rtcIntersect16): for a point p within `reach` of its triangle along n,
// the triangle's normal facing n's side; n itself if no triangle is there
// (a point not on the mesh).
class FacetPackets {
 public:
  static constexpr int kWidth = 16;

  // `normals` and `lifts`: where each receiver's triangle normal and the
  // lift of its ray origin go, indexed as add() is given them; `mesh`: the
  // triangles' corners and vertex normals.
  FacetPackets(RTCScene scene, const SmoothMesh& mesh, glm::vec3* normals, glm::vec3* lifts)
      : scene_(scene), mesh_(mesh), normals_(normals), lifts_(lifts) {}

  void add(const glm::vec3& p, const glm::vec3& n, float reach, int index) {
    const int lane = size_;
    set_ray(hits_.ray, lane, p + reach * n, -n, 2.0f * reach);
    hits_.hit.geomID[lane] = RTC_INVALID_GEOMETRY_ID;
    normal_[lane] = n;
    index_[lane] = index;
    if (++size_ == kWidth) flush();
  }

  void flush() {
    if (size_ == 0) return;
    RTCIntersectContext context = coherent_packet(valid_, size_, hits_.ray);
    rtcIntersect16(valid_, scene_, &context, &hits_);
    for (int lane = 0; lane < size_; ++lane) {
      const glm::vec3 n = normal_[lane];
      glm::vec3 ng = n, lift(0.0f);
      if (hits_.hit.geomID[lane] != RTC_INVALID_GEOMETRY_ID) {
        const glm::vec3 g(hits_.hit.Ng_x[lane], hits_.hit.Ng_y[lane], hits_.hit.Ng_z[lane]);
        const float length = glm::length(g);
        if (length > 0.0f) ng = glm::dot(g, n) < 0.0f ? -g / length : g / length;
        lift = terminator_lift(hits_.hit.primID[lane], hits_.hit.u[lane], hits_.hit.v[lane], n);
      }
      normals_[index_[lane]] = ng;
      lifts_[index_[lane]] = lift;
    }
    size_ = 0;
  }

 private:
  // The rise of triangle `triangle`'s point at barycentrics (1 - u - v, u,
  // v) to the smooth surface its vertex normals describe, as a vector
  // along its shading normal n (reference/terminator_offset.hpp);
  // trace() applies the part of it the light's direction calls for. 0 on a
  // flat mesh, whose vertex normals are the triangles'.
  glm::vec3 terminator_lift(unsigned triangle, float u, float v, const glm::vec3& n) const {
    if (mesh_.positions == nullptr || mesh_.indices == nullptr) return glm::vec3(0.0f);
    glm::vec3 corners[3], normals[3];
    for (std::size_t c = 0; c < 3; ++c) {
      const std::uint32_t vertex = mesh_.indices[3 * static_cast<std::size_t>(triangle) + c];
      const float* position = mesh_.positions + 3 * static_cast<std::size_t>(vertex);
      corners[c] = glm::vec3(position[0], position[1], position[2]);
      normals[c] = mesh_.normals[vertex];
    }
    return smooth_surface_rise(corners, normals, glm::vec3(1.0f - u - v, u, v), n) * n;
  }

  RTCScene scene_;
  const SmoothMesh& mesh_;
  glm::vec3* normals_;
  glm::vec3* lifts_;
  RTCRayHit16 hits_{};
  alignas(64) int valid_[kWidth] = {};
  glm::vec3 normal_[kWidth];
  int index_[kWidth] = {};
  int size_ = 0;
};

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
  const Light sized = with_source_size(light, settings);
  r.size = light.type != LightType::Directional ? sized.light_size : glm::radians(sized.sun_angle);
  r.cos_cone = light.type == LightType::Spot ? std::cos(glm::radians(light.cone_degrees)) : -1.0f;
  return r;
}

namespace {

// Above this many triangles the BVH is built at Embree's medium quality
// (binned SAH without spatial splits): the high quality's spatial splits
// make the build of a multi-million-triangle model take longer than the
// rays it saves on a reference's few million rays.
constexpr std::size_t kHighQualityBuildTriangles = std::size_t{1} << 20;

// The mesh's triangles as one Embree geometry attached to `scene`: the one
// place the tracer's geometry is set up (and where per-geometry state,
// such as the occlusion filter of `cutouts`, when given, belongs). Returns
// false if Embree cannot allocate its buffers.
bool attach_triangles(RTCDevice device, RTCScene scene, const TriangleMesh& mesh,
                      const CasterCutouts* cutouts) {
  RTCGeometry geometry = rtcNewGeometry(device, RTC_GEOMETRY_TYPE_TRIANGLE);
  const std::size_t triangles = mesh.indices.size() / 3;
  rtcSetGeometryBuildQuality(geometry, triangles > kHighQualityBuildTriangles
                                           ? RTC_BUILD_QUALITY_MEDIUM
                                           : RTC_BUILD_QUALITY_HIGH);
  auto* vertices = static_cast<float*>(rtcSetNewGeometryBuffer(geometry, RTC_BUFFER_TYPE_VERTEX, 0,
                                                               RTC_FORMAT_FLOAT3, 3 * sizeof(float),
                                                               mesh.vertices.size()));
  auto* indices = static_cast<std::uint32_t*>(rtcSetNewGeometryBuffer(
      geometry, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3, 3 * sizeof(std::uint32_t), triangles));
  if (vertices == nullptr || indices == nullptr) {
    rtcReleaseGeometry(geometry);
    return false;
  }
  for (std::size_t i = 0; i < mesh.vertices.size(); ++i) {
    std::memcpy(vertices + 3 * i, &mesh.vertices[i].position, 3 * sizeof(float));
  }
  std::memcpy(indices, mesh.indices.data(), triangles * 3 * sizeof(std::uint32_t));
  if (cutouts != nullptr) {
    // Const for the filter, which only reads it; Embree's user data is void*.
    rtcSetGeometryUserData(geometry, const_cast<CasterCutouts*>(cutouts));
    rtcSetGeometryOccludedFilterFunction(geometry, pass_cutouts);
  }
  rtcCommitGeometry(geometry);
  rtcAttachGeometry(scene, geometry);
  rtcReleaseGeometry(geometry);
  return true;
}

}  // namespace

float mesh_extent(const TriangleMesh& mesh) {
  float extent = 0.0f;
  for (const Vertex& v : mesh.vertices) {
    const glm::vec3 a = glm::abs(v.position);
    extent = std::max({extent, a.x, a.y, a.z});
  }
  return extent;
}

bool traceable_point(const glm::vec3& p, const glm::vec3& n, float error, float extent) {
  // Embree asserts |origin| and |direction| <= 1.844e18 (FLT_LARGE) for
  // every active lane: stay well inside that whatever the scene.
  constexpr float kEmbreeRange = 1e17f;
  const float limit = extent > 0.0f ? std::min(2.0f * extent, kEmbreeRange) : kEmbreeRange;
  const float far = extent > 0.0f ? std::min(1e4f * extent, kEmbreeRange) : kEmbreeRange;
  const glm::vec3 a = glm::abs(p);
  const bool inside = a.x <= far && a.y <= far && a.z <= far;  // false for NaN
  // A unit normal, within any storage's rounding (false for NaN and inf).
  const float length2 = glm::dot(n, n);
  const bool normal = length2 > 0.25f && length2 < 4.0f;
  return inside && normal && error >= 0.0f && error <= limit;
}

namespace {

// Whether pixel i of `surfaces` sees geometry it can trace from.
bool traceable_pixel(const SurfacePoints& surfaces, std::size_t i, float extent) {
  return surfaces.covered[i] &&
         traceable_point(surfaces.position[i], surfaces.normal[i], surfaces.error_bound(i), extent);
}

}  // namespace

std::int64_t untraceable_points(const SurfacePoints& surfaces, float extent) {
  std::int64_t count = 0;
  for (std::size_t i = 0; i < surfaces.size(); ++i) {
    count += surfaces.covered[i] && !traceable_pixel(surfaces, i, extent);
  }
  return count;
}

ShadowRayTracer::ShadowRayTracer(const TriangleMesh& mesh)
    : ShadowRayTracer(mesh, std::vector<Material>{}) {}

ShadowRayTracer::ShadowRayTracer(const TriangleMesh& mesh, const std::vector<Material>& materials) {
  if (CasterCutouts cutouts(mesh, materials); cutouts.any()) {
    cutouts_ = std::make_unique<CasterCutouts>(mesh, materials);
  }
  const char* config = embree_device_config();
  device_ = rtcNewDevice(config);
  if (device_ == nullptr) {
    throw RuntimeError(embree_error(
        nullptr, config == nullptr
                     ? std::string("creating a device")
                     : std::string("creating a device with PENUMBRA_EMBREE_CONFIG=") + config));
  }
  rtcSetDeviceErrorFunction(device_, on_embree_error, nullptr);
  // The widest packet the device traces natively (OcclusionPackets).
  packet_width_ =
      rtcGetDeviceProperty(device_, RTC_DEVICE_PROPERTY_NATIVE_RAY16_SUPPORTED) != 0  ? 16
      : rtcGetDeviceProperty(device_, RTC_DEVICE_PROPERTY_NATIVE_RAY8_SUPPORTED) != 0 ? 8
                                                                                      : 4;

  scene_ = rtcNewScene(device_);
  // Robust traversal: no ray slips through the shared edge of two
  // triangles, so a closed mesh never leaks light.
  rtcSetSceneFlags(scene_, RTC_SCENE_FLAG_ROBUST);
  const bool large = mesh.indices.size() / 3 > kHighQualityBuildTriangles;
  rtcSetSceneBuildQuality(scene_, large ? RTC_BUILD_QUALITY_MEDIUM : RTC_BUILD_QUALITY_HIGH);
  if (!mesh.indices.empty() && !attach_triangles(device_, scene_, mesh, cutouts_.get())) {
    const std::string message = embree_error(device_, "allocating the mesh");
    rtcReleaseScene(scene_);
    rtcReleaseDevice(device_);
    throw RuntimeError(message);
  }
  rtcCommitScene(scene_);
  if (rtcGetDeviceError(device_) != RTC_ERROR_NONE) {
    const std::string message = embree_error(device_, "building the scene");
    rtcReleaseScene(scene_);
    rtcReleaseDevice(device_);
    throw RuntimeError(message);
  }
  max_coordinate_ = mesh_extent(mesh);
  // The corners are Embree's own copies; only the normals are kept here.
  if (!mesh.indices.empty()) {
    RTCGeometry geometry = rtcGetGeometry(scene_, 0);
    smooth_.positions =
        static_cast<const float*>(rtcGetGeometryBufferData(geometry, RTC_BUFFER_TYPE_VERTEX, 0));
    smooth_.indices = static_cast<const std::uint32_t*>(
        rtcGetGeometryBufferData(geometry, RTC_BUFFER_TYPE_INDEX, 0));
  }
  vertex_normals_.reserve(mesh.vertices.size());
  for (const Vertex& v : mesh.vertices) vertex_normals_.push_back(v.normal);
  smooth_.normals = vertex_normals_.data();
}

float ShadowRayTracer::rounding_error(const glm::vec3& p, const glm::vec3& n) const {
  return gamma(7) * (glm::dot(glm::abs(n), glm::abs(p)) + max_coordinate_);
}

ShadowRayTracer::~ShadowRayTracer() {
  rtcReleaseScene(scene_);
  rtcReleaseDevice(device_);
}

namespace {

// The receiver as its shadow rays see it.
struct Receiver {
  glm::vec3 p;       // the surface point
  glm::vec3 n;       // its shading normal
  glm::vec3 ng;      // its triangle's normal, on n's side
  glm::vec3 origin;  // where its rays start: p raised by its error bound
  float offset;      // how far: the bound of p's error along n
};

// `value` where `keep`, else 0: a select written as a bit mask, which the
// compiler vectorizes (it keeps a ?: between floats a branch, since a
// float comparison may trap).
float keep_if(bool keep, float value) {
  return std::bit_cast<float>(std::bit_cast<std::uint32_t>(value) &
                              (0u - static_cast<std::uint32_t>(keep)));
}

// One pixel's shadow rays, one per source point: from the receiver's
// origin towards the point (the direction is not normalized: t = tfar
// reaches the point; the sun's rays are unit and unbounded) and the
// point's weight in the irradiance, 0 where it sends the receiver no
// light with or without occluders: the part of the source below the
// shading normal's tangent plane (Cycles' test for reflection, whatever
// the triangle's plane), or the source's back. Struct of arrays, written
// by branch-free loops the compiler vectorizes (the arrays are passed as
// restrict parameters so that it knows they do not overlap).
struct PixelRays {
  std::vector<float> x, y, z, tfar, weight;
  explicit PixelRays(std::size_t n) : x(n), y(n), z(n), tfar(n), weight(n) {}
};

// A square facing `facing` (a spot light; its `direction`), or a point
// (facing 0): each point of the source weighs cos(theta_source)
// cos(theta_receiver) / d^2 dA; a point light's source has no side, so
// cos(theta_source) = 1. The cosines are taken times d, so that a
// square's weights need no square root.
template <bool kOneSided>
void square_rays(const float* __restrict sx, const float* __restrict sy, const float* __restrict sz,
                 std::uint32_t count, const Receiver& r, glm::vec3 facing, float* __restrict x,
                 float* __restrict y, float* __restrict z, float* __restrict tfar,
                 float* __restrict weight) {
  const glm::vec3 n = r.n, p = r.p, o = r.origin, l = facing;
  for (std::uint32_t s = 0; s < count; ++s) {
    const float tx = sx[s] - p.x, ty = sy[s] - p.y, tz = sz[s] - p.z;
    const float d2 = tx * tx + ty * ty + tz * tz;
    const float receiver = n.x * tx + n.y * ty + n.z * tz;  // d cos(theta_receiver)
    const float source = kOneSided ? -(l.x * tx + l.y * ty + l.z * tz) : std::sqrt(d2);
    const float inv_d2 = 1.0f / d2;
    // Bitwise, not short-circuit: no branch in the loop.
    const bool lit = (receiver > 0.0f) & (source > 0.0f);
    weight[s] = keep_if(lit, (source * inv_d2) * (receiver * inv_d2));
    // Aim from the raised origin at the same point of the source.
    x[s] = sx[s] - o.x;
    y[s] = sy[s] - o.y;
    z[s] = sz[s] - o.z;
    tfar[s] = 1.0f;
  }
}

// The sun: its disc of directions, uniform in solid angle, each weighing
// cos(theta_receiver) d(omega).
void sun_rays(const float* __restrict sx, const float* __restrict sy, const float* __restrict sz,
              std::uint32_t count, const Receiver& r, float* __restrict x, float* __restrict y,
              float* __restrict z, float* __restrict tfar, float* __restrict weight) {
  const glm::vec3 n = r.n;
  const float infinity = std::numeric_limits<float>::infinity();
  for (std::uint32_t s = 0; s < count; ++s) {
    const float wx = sx[s], wy = sy[s], wz = sz[s];
    const float receiver = n.x * wx + n.y * wy + n.z * wz;
    weight[s] = keep_if(receiver > 0.0f, receiver);
    x[s] = wx;
    y[s] = wy;
    z[s] = wz;
    tfar[s] = infinity;
  }
}

// A sphere of uniform radiance sends p L cos(theta_receiver) d(omega) from
// each direction of the cone it subtends (the form factor's kernel over
// its visible half, in solid angle): the cone sampled uniformly, up to the
// sphere's near side. False if p is inside the sphere (nothing can shade
// it).
bool sphere_rays(const ReferenceLight& light, const SourcePointSets::Set& set, std::uint32_t count,
                 const Receiver& r, PixelRays& out) {
  const float radius = 0.5f * light.size;
  const glm::vec3 to_centre = light.position - r.p;
  const float d = glm::length(to_centre);
  if (d <= radius) return false;
  const glm::vec3 w = to_centre / d;
  glm::vec3 a, b;
  frame_around(w, a, b);
  const float sin2 = (radius / d) * (radius / d);
  const float cone = sin2 / (1.0f + std::sqrt(1.0f - sin2));  // 1 - cos(theta_max)
  for (std::uint32_t s = 0; s < count; ++s) {
    const glm::vec3 c = uniform_cone_from_disk(glm::vec2(set.x[s], set.y[s]), cone);
    const glm::vec3 direction = glm::normalize(c.x * a + c.y * b + c.z * w);
    const float along = d * glm::dot(direction, w);
    const float distance =
        along - std::sqrt(std::max(0.0f, radius * radius - (d * d - along * along)));
    const float receiver = glm::dot(r.n, direction);
    out.weight[s] = receiver > 0.0f ? receiver : 0.0f;
    // Aim from the raised origin at the same point of the sphere.
    const glm::vec3 to_target = r.p + distance * direction - r.origin;
    out.x[s] = to_target.x;
    out.y[s] = to_target.y;
    out.z[s] = to_target.z;
    out.tfar[s] = 1.0f;
  }
  return true;
}

}  // namespace

Image ShadowRayTracer::trace(const SurfacePoints& surfaces, const ReferenceLight& light,
                             int samples, const TraceProgress& progress, TraceStats* stats) const {
  const int width = surfaces.width, height = surfaces.height;
  Image image(width, height);
  const bool spot = light.type == LightType::Spot;
  const auto covered = static_cast<std::uint32_t>(
      std::count(surfaces.covered.begin(), surfaces.covered.end(), std::uint8_t{1}));
  const SourcePointSets sources(light, static_cast<std::uint32_t>(std::max(samples, 1)),
                                std::max(covered, 1u));
  const std::uint32_t count = sources.count();
  std::atomic<std::int64_t> rows_done{0}, rays_traced{0}, untraceable{0};

  // The direction from p to the source's centre, which decides how much
  // of the terminator lift a receiver's rays get.
  auto light_centre_direction = [&](const glm::vec3& p) {
    return light.type == LightType::Directional ? -light.direction
                                                : glm::normalize(light.position - p);
  };

  // Receiver i as far as it needs no ray: its facet normal comes later.
  auto receiver = [&](std::size_t i) {
    Receiver r;
    r.p = surfaces.position[i];
    r.n = surfaces.normal[i];
    const float error = surfaces.error_bound(i);
    // pbrt-v4's spawned ray origin: p moved along the normal by the bound
    // of its error, so that the ray starts on the light's side of the
    // surface it lies on however the rounding fell.
    r.offset = error + rounding_error(r.p, r.n);
    r.origin = r.p + r.offset * r.n;
    return r;
  };

  // Irradiance with occluders over without, for pixel i (column x of its
  // row): adds its source points' weights to `total` and queues their
  // shadow rays, which add them to lit[x] when they reach the light.
  auto sample_pixel = [&](std::size_t i, int x, const Receiver& r, PixelRays& rays, double& total,
                          double& lit, auto& packets) {
    const SourcePointSets::Set set = sources.set_for(static_cast<std::uint32_t>(i));
    float *rx = rays.x.data(), *ry = rays.y.data(), *rz = rays.z.data();
    switch (sources.kind()) {
      case SourcePointKind::SquarePoint:
        if (light.type == LightType::Spot && light.size > 0.0f) {
          square_rays<true>(set.x, set.y, set.z, count, r, light.direction, rx, ry, rz,
                            rays.tfar.data(), rays.weight.data());
        } else {
          square_rays<false>(set.x, set.y, set.z, count, r, glm::vec3(0.0f), rx, ry, rz,
                             rays.tfar.data(), rays.weight.data());
        }
        break;
      case SourcePointKind::SunDirection:
        sun_rays(set.x, set.y, set.z, count, r, rx, ry, rz, rays.tfar.data(), rays.weight.data());
        break;
      case SourcePointKind::SphereDiskPoint:
        if (!sphere_rays(light, set, count, r, rays)) {
          // Inside the light: every direction sends light, unoccluded.
          if (glm::dot(r.ng, r.n) > 0.0f) total = lit = static_cast<double>(count);
          return;
        }
        break;
    }
    for (std::uint32_t s = 0; s < count; ++s) {
      const float weight = rays.weight[s];
      if (!(weight > 0.0f)) continue;
      total += weight;
      packets.add(r.origin, glm::vec3(rx[s], ry[s], rz[s]), rays.tfar[s], x, weight);
    }
  };

  // The rows, with occlusion packets of N rays.
  const auto trace_rows = [&]<int N>(const tbb::blocked_range<int>& rows,
                                     std::integral_constant<int, N>) {
    PixelRays rays(count);
    const auto w = static_cast<std::size_t>(width);
    std::vector<Receiver> receivers(w);
    std::vector<glm::vec3> facets(w), lifts(w);
    std::vector<std::uint8_t> traced(w);  // covered and traceable
    std::vector<double> total(w), lit(w);
    FacetPackets facet_packets(scene_, smooth_, facets.data(), lifts.data());
    OcclusionPackets<N> packets(scene_, lit.data());
    for (int y = rows.begin(); y != rows.end(); ++y) {
      std::fill(total.begin(), total.end(), 0.0);
      std::fill(lit.begin(), lit.end(), 0.0);
      const std::size_t row = static_cast<std::size_t>(y) * width;
      for (int x = 0; x < width; ++x) {
        const std::size_t i = row + x;
        traced[x] = traceable_pixel(surfaces, i, max_coordinate_);
        if (surfaces.covered[i] && !traced[x]) ++untraceable;
        if (!traced[x]) continue;
        Receiver& r = receivers[x];
        r = receiver(i);
        // The G-buffer's normal is interpolated from the vertices' (a
        // smooth sphere's), while the rays meet the flat triangles: near a
        // terminator a direction above the shading normal's tangent plane
        // can be below the triangle's own (the "shadow terminator"
        // artefact). The triangle's normal decides how far the rays start
        // above it (the terminator model, reference/terminator_offset.hpp).
        facet_packets.add(r.p, r.n, 2.0f * r.offset + 1e-6f, x);
      }
      facet_packets.flush();
      for (int x = 0; x < width; ++x) {
        if (!traced[x]) continue;
        receivers[x].ng = facets[x];
        receivers[x].origin += terminator_offset_amount(receivers[x].n, facets[x],
                                                        light_centre_direction(receivers[x].p)) *
                               lifts[x];
        sample_pixel(row + x, x, receivers[x], rays, total[x], lit[x], packets);
      }
      packets.flush();
      for (int x = 0; x < width; ++x) {
        const std::size_t i = row + x;
        float* out = image.pixel(x, y);
        if (!surfaces.covered[i]) {
          out[0] = out[1] = out[2] = 1.0f;
          out[3] = 0.0f;
          continue;
        }
        // No light reaches the point, occluders or not (all of the source
        // is below the shading normal's horizon): the ratio is undefined
        // (not judged). An untraceable point has no rays, so it is not
        // judged either.
        const bool reached = traced[x] && total[x] > 0.0;
        out[0] = out[1] = out[2] = reached ? static_cast<float>(lit[x] / total[x]) : 0.0f;
        const bool inside_cone = !spot || !reached ||
                                 glm::dot(glm::normalize(surfaces.position[i] - light.position),
                                          light.direction) >= light.cos_cone;
        out[3] = inside_cone && reached ? 1.0f : 0.0f;
      }
      const std::int64_t done = ++rows_done;
      if (progress) progress(done, height);
    }
    rays_traced += packets.traced();
  };
  tbb::parallel_for(tbb::blocked_range<int>(0, height), [&](const tbb::blocked_range<int>& rows) {
    switch (packet_width_) {
      case 16:
        trace_rows(rows, std::integral_constant<int, 16>{});
        break;
      case 8:
        trace_rows(rows, std::integral_constant<int, 8>{});
        break;
      default:
        trace_rows(rows, std::integral_constant<int, 4>{});
        break;
    }
  });
  if (stats != nullptr) {
    stats->rays = rays_traced.load();
    stats->untraceable = untraceable.load();
  }
  return image;
}

}  // namespace penumbra
