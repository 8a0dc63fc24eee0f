#pragma once
// What the traced reference must see as the shadow maps do: the holes of
// alpha-tested casters (glTF MASK, BLEND as MASK at 0.5, OBJ map_d), read
// from the same texture at the same texture coordinates as the shadow
// depth pass (shaders/scene/material.glsl), and single-sided surfaces that
// cast only from their front. The tracer asks it about every occluder a
// shadow ray meets (an Embree occlusion filter).
#include <cstdint>
#include <glm/glm.hpp>
#include <vector>

#include "scene/mesh.hpp"
#include "scene/scene.hpp"

namespace penumbra {

class CasterCutouts {
 public:
  // Keeps references to both: they must outlive this.
  CasterCutouts(const TriangleMesh& mesh, const std::vector<Material>& materials);

  // Whether any triangle has a hole or a back (if not, the tracer needs no
  // filter).
  [[nodiscard]] bool any() const { return any_; }

  // Whether a shadow ray travelling along `direction` (towards the light)
  // passes through triangle `triangle` at barycentrics (u, v) (Embree's:
  // the point is (1-u-v) v0 + u v1 + v v2): a hole, or the back of a
  // single-sided surface as the light sees it.
  [[nodiscard]] bool passes(std::uint32_t triangle, float u, float v,
                            const glm::vec3& direction) const;

  // A hash of everything passes() reads, for the reference cache's key
  // (0 when there is nothing to cut).
  [[nodiscard]] std::uint64_t hash() const;

 private:
  const TriangleMesh& mesh_;
  const std::vector<Material>& materials_;
  std::vector<bool> cut_;  // per material: alpha-tested or single-sided
  bool any_ = false;
};

}  // namespace penumbra
