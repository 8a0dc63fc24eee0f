#pragma once
// The points of a light's source that the traced reference aims a pixel's
// shadow rays at, precomputed once per trace: a few hundred stratified
// sets (correlated multi-jittered, Kensler 2013), each pixel using the set
// a hash of its index picks. Whatever about a point does not depend on the
// receiver is computed here once: a square's point in world space, a sun's
// direction, a sphere's point of the unit disk (the sphere's cone depends
// on the receiver). A pixel's rays then cost only their receiver-dependent
// part, and neighbouring pixels still use unrelated sets (noise, not
// aliasing): the pixels that share a set lie scattered across the image.
#include <cstdint>
#include <vector>

#include "reference/shadow_ray_tracer.hpp"

namespace penumbra {

// What a set's three coordinates mean for each kind of source.
enum class SourcePointKind {
  SquarePoint,      // a spot light: points of its square (a point light: its centre), world space
  SunDirection,     // a directional light: unit directions towards the sun, world space
  SphereDiskPoint,  // a point light's sphere: points of the unit disk (z unused)
};

class SourcePointSets {
 public:
  // `count` points per set (1 for a source of size 0: its centre); at most
  // `max_sets` sets (the pixels that will use them).
  SourcePointSets(const ReferenceLight& light, std::uint32_t count, std::uint32_t max_sets);

  // A set's points: three arrays of count() values.
  struct Set {
    const float* x;
    const float* y;
    const float* z;
  };

  [[nodiscard]] SourcePointKind kind() const { return kind_; }
  [[nodiscard]] std::uint32_t count() const { return count_; }
  [[nodiscard]] std::uint32_t set_count() const { return sets_; }
  // The set pixel `pixel` (its row-major index) uses.
  [[nodiscard]] Set set_for(std::uint32_t pixel) const;
  // Set k (0 <= k < set_count()).
  [[nodiscard]] Set set(std::uint32_t k) const;

 private:
  SourcePointKind kind_;
  std::uint32_t count_;
  std::uint32_t sets_;
  std::vector<float> values_;  // set after set: count_ x, count_ y, count_ z
};

}  // namespace penumbra
