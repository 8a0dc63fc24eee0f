#pragma once
// The SSAO sample kernel, computed on the CPU once per sample count.
#include <glm/glm.hpp>
#include <vector>

namespace penumbra {

// k points of the unit hemisphere around +z, as (direction, distance):
// xyz is a unit direction, w a distance along it as a fraction of the
// radius, in (0, 1). The directions are the 2D Hammersley set mapped to the
// hemisphere by the area-preserving map (u, v) -> (cos theta = u,
// phi = 2 pi v), so they are uniform in solid angle and stratified in
// cos theta: weighting each by its cosine, as seed 003 does, then estimates
// the cosine-weighted visibility with low discrepancy. The distances are
// the base-3 radical inverse, uniform along each direction's segment [0, r].
std::vector<glm::vec4> ssao_kernel(int samples);

// Van der Corput radical inverse of i in the given base: the digits of i
// mirrored about the radix point. In [0, 1).
double radical_inverse(unsigned base, unsigned i);

}  // namespace penumbra
