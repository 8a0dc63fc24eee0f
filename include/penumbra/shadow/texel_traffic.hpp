#pragma once
// The bytes a shadow-map pass moves per texel of the map array it
// processes. On a GPU the filters are memory-bound, so these bytes, not
// their arithmetic, set their cost: `penumbra bench` divides them by the
// measured time (the bandwidth achieved) and by the device's bandwidth
// (the floor no implementation of the pass can beat). Each pass counts
// its own from the formats, tile sizes and aprons it uses, taking every
// texel a workgroup loads as one read from memory (no reuse across
// workgroups through the caches) and every store as one write.
namespace penumbra {

struct TexelTraffic {
  double read = 0.0;     // bytes read per texel
  double written = 0.0;  // bytes written per texel
  [[nodiscard]] double total() const { return read + written; }
};

}  // namespace penumbra
