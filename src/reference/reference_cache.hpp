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
#include <string_view>

#include "io/image.hpp"
#include "reference/shadow_ray_tracer.hpp"
#include "render/surface_points.hpp"
#include "scene/mesh.hpp"

namespace penumbra {

// Bumped whenever the tracer's output for the same inputs changes (2: the
// radiometric shadow factor and ray origins offset by the position's error
// bound; 3: source points from precomputed sets, other noise of the same
// size; 4: ray origins on the smooth surface of the vertex normals; 5: that
// rise bounded and applied only where the light grazes, as Cycles does, and
// the vertex normals part of the key).
inline constexpr std::uint32_t kReferenceFormatVersion = 5;

// `cutouts`: CasterCutouts::hash() of the scene (0: none).
std::uint64_t reference_key(const TriangleMesh& mesh, const SurfacePoints& surfaces,
                            const ReferenceLight& light, int samples, std::uint64_t cutouts = 0);

// $XDG_CACHE_HOME/penumbra, else $HOME/.cache/penumbra; empty if neither
// variable is set.
std::string default_cache_dir();

// The file a reference of that key lives in, inside `dir`.
std::string cached_reference_path(const std::string& dir, std::uint64_t key);

// The cached reference, or nullopt if there is none of this key and size.
// An entry is read only if it is a regular file of exactly the size its
// image needs; a damaged one (its payload does not match the checksum in
// its header, a value is not a visibility in [0, 1]) is a miss with one
// warning on stderr, never an error, and is replaced when re-traced.
std::optional<Image> load_cached_reference(const std::string& dir, std::uint64_t key, int width,
                                           int height);

// The entry's image from its bytes, or nullopt; `problem` says what is
// wrong with a damaged entry (empty for one of another format version,
// which is a plain miss).
std::optional<Image> parse_cached_reference(std::string_view bytes, std::uint64_t key, int width,
                                            int height, std::string& problem);

// 64-bit FNV-1a of an entry's payload, as its header keeps it.
std::uint64_t cache_checksum(std::string_view payload);

// Stores the reference atomically, creating `dir` as needed. Throws
// RuntimeError if it cannot.
void store_cached_reference(const std::string& dir, std::uint64_t key, const Image& reference);

}  // namespace penumbra
