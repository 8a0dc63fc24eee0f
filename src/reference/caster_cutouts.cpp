#include "reference/caster_cutouts.hpp"

#include <cstring>

#include "scene/texture.hpp"

namespace penumbra {

CasterCutouts::CasterCutouts(const TriangleMesh& mesh, const std::vector<Material>& materials)
    : mesh_(mesh), materials_(materials), cut_(materials.size(), false) {
  for (std::size_t i = 0; i < materials.size(); ++i) {
    cut_[i] = coverage_cutoff(materials[i]) >= 0.0f || !materials[i].double_sided;
  }
  for (const Vertex& v : mesh.vertices) {
    if (v.material < cut_.size() && cut_[v.material]) {
      any_ = true;
      break;
    }
  }
}

bool CasterCutouts::passes(std::uint32_t triangle, float u, float v,
                           const glm::vec3& direction) const {
  const std::size_t first = 3 * static_cast<std::size_t>(triangle);
  if (first + 2 >= mesh_.indices.size()) return false;
  const Vertex& a = mesh_.vertices[mesh_.indices[first]];
  const Vertex& b = mesh_.vertices[mesh_.indices[first + 1]];
  const Vertex& c = mesh_.vertices[mesh_.indices[first + 2]];
  if (a.material >= cut_.size() || !cut_[a.material]) return false;
  const Material& m = materials_[a.material];
  if (!m.double_sided) {
    // The shadow pass draws a triangle's front (counter-clockwise) as the
    // light sees it: the light lies on the side its normal points to,
    // which is where the ray is heading.
    const glm::vec3 n = glm::cross(b.position - a.position, c.position - a.position);
    if (glm::dot(n, direction) <= 0.0f) return true;
  }
  if (coverage_cutoff(m) < 0.0f) return false;
  const float w = 1.0f - u - v;
  const glm::vec2 uv = w * a.uv + u * b.uv + v * c.uv;
  const float alpha =
      w * unpack_color(a.color).a + u * unpack_color(b.color).a + v * unpack_color(c.color).a;
  return is_cut_out(m, alpha, uv);
}

std::uint64_t CasterCutouts::hash() const {
  if (!any_) return 0;
  std::uint64_t h = 0xcbf29ce484222325ull;
  const auto bytes = [&](const void* data, std::size_t size) {
    const auto* p = static_cast<const unsigned char*>(data);
    for (std::size_t i = 0; i < size; ++i) {
      h ^= p[i];
      h *= 0x100000001b3ull;
    }
  };
  for (const Vertex& v : mesh_.vertices) {
    bytes(&v.material, sizeof v.material);
    bytes(&v.uv, sizeof v.uv);
    bytes(&v.color, sizeof v.color);
  }
  for (const Material& m : materials_) {
    const float cutoff = coverage_cutoff(m);
    bytes(&cutoff, sizeof cutoff);
    bytes(&m.alpha, sizeof m.alpha);
    bytes(&m.double_sided, sizeof m.double_sided);
    bytes(&m.wrap_s, sizeof m.wrap_s);
    bytes(&m.wrap_t, sizeof m.wrap_t);
    bytes(&m.nearest_magnification, sizeof m.nearest_magnification);
    bytes(&m.uv_transform, sizeof m.uv_transform);
    if (m.texture != nullptr) {
      bytes(&m.texture->width, sizeof m.texture->width);
      bytes(&m.texture->height, sizeof m.texture->height);
      bytes(m.texture->rgba.data(), m.texture->rgba.size());
    }
  }
  return h;
}

}  // namespace penumbra
