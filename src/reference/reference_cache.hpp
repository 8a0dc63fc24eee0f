#pragma once
// Traced references kept on disk, so that a second `penumbra compare` of
// the same scene, view and light skips the tracing. A reference is keyed
// by a hash of everything that decides it: the tracer's format version,
// the scene's triangles, the light as sampled, the samples per pixel, and
// the surface points themselves (which carry the camera, the image size
// and whatever the GPU rasterized).
#include <cstdint>
#include <optional>
#include <string>

#include "io/image.hpp"
#include "reference/shadow_ray_tracer.hpp"
#include "render/surface_points.hpp"
#include "scene/mesh.hpp"

namespace penumbra {

// Bumped whenever the tracer's output for the same inputs changes (2: the
// radiometric shadow factor and ray origins offset by the position's error
// bound).
inline constexpr std::uint32_t kReferenceFormatVersion = 2;

std::uint64_t reference_key(const TriangleMesh& mesh, const SurfacePoints& surfaces,
                            const ReferenceLight& light, int samples);

// $XDG_CACHE_HOME/penumbra, else $HOME/.cache/penumbra; empty if neither
// variable is set.
std::string default_cache_dir();

// The file a reference of that key lives in, inside `dir`.
std::string cached_reference_path(const std::string& dir, std::uint64_t key);

// The cached reference, or nullopt if there is none of this key and size
// (or it cannot be read: a damaged entry is a miss, never an error).
std::optional<Image> load_cached_reference(const std::string& dir, std::uint64_t key, int width,
                                           int height);

// Stores the reference atomically, creating `dir` as needed. Throws
// RuntimeError if it cannot.
void store_cached_reference(const std::string& dir, std::uint64_t key, const Image& reference);

}  // namespace penumbra
