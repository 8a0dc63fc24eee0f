#pragma once
// A scene's triangles, materials and base-colour textures on the GPU, drawn
// with one call per texture.
#include <cstdint>
#include <span>
#include <vector>

#include "penumbra/gl/resources.hpp"
#include "penumbra/shadow/caster_bounds.hpp"
#include "scene/mesh.hpp"
#include "scene/scene.hpp"

namespace penumbra {

// Mirrors the Material struct of shaders/scene/material.glsl (std430).
struct GpuMaterial {
  glm::vec4 albedo;              // rgb: linear albedo, a: coverage factor
  glm::vec4 specular_shininess;  // rgb: specular colour, w: Blinn-Phong exponent
  // xyz: the rows of Material::uv_transform; row0.w: the coverage cutoff
  // (negative: opaque), row1.w: MATERIAL_* flags
  glm::vec4 uv_row0;
  glm::vec4 uv_row1;
};
static_assert(sizeof(GpuMaterial) == 64);

// The material as the shaders read it.
GpuMaterial gpu_material(const Material& m);

// Which surfaces a draw covers. Passes draw cut-out surfaces (alpha-tested
// or single-sided: their fragment shaders may discard) with a program of
// their own, so that opaque surfaces keep early depth testing.
enum class SurfaceSet { All, Opaque, CutOut };

// Whether a material's fragments may be discarded (a hole, or a back).
bool is_cut_out_material(const Material& m);

class GpuScene {
 public:
  // `max_storage_block_bytes`: the largest storage block the shaders may
  // read (negative: the GPU's MAX_SHADER_STORAGE_BLOCK_SIZE).
  // `shape_first_vertex` (optional: each shape's first vertex in the
  // mesh, and one past the last) splits the batches into one indirect
  // draw per shape, which virtual shadow maps cull per page.
  GpuScene(const Scene& scene, const TriangleMesh& mesh, std::int64_t max_storage_block_bytes = -1,
           std::span<const std::size_t> shape_first_vertex = {});

  // Binds the vertex array, the materials and each batch's texture (units
  // UNIT_BASE_COLOR and UNIT_BASE_ALPHA), and draws the triangles of the set. With
  // Corners::Read the bound program reads each triangle's corners by
  // gl_PrimitiveID: the vertices and indices are bound as storage buffers
  // too, and each batch's first index goes to its uniform
  // LOCATION_FIRST_INDEX.
  enum class Corners { Unread, Read };
  void draw(SurfaceSet set = SurfaceSet::All, Corners corners = Corners::Unread) const;
  // The same with glDrawElementsIndirect, one draw per batch and shape:
  // draw d's command is the DrawElementsIndirectCommand at byte `offset` +
  // 20 d of the buffer bound to GL_DRAW_INDIRECT_BUFFER
  // (indirect_commands() gives their first index and count; the instance
  // count is the caller's), and d goes to the bound program's uniform
  // `draw_location` (unless -1).
  void draw_indirect(SurfaceSet set, std::size_t offset, GLint draw_location = -1) const;
  // One DrawElementsIndirectCommand {count, instance count 0, first index,
  // base vertex 0, base instance 0} per draw, in draw_indirect()'s order.
  [[nodiscard]] std::vector<std::uint32_t> indirect_commands() const;
  // Each indirect draw's world bounds, as the mesh was given (or last
  // updated), and the shape it draws.
  [[nodiscard]] std::vector<CasterBounds> draw_bounds(const TriangleMesh& mesh) const;
  [[nodiscard]] std::size_t draw_shape(std::size_t draw) const { return draws_[draw].shape; }
  [[nodiscard]] std::size_t draw_count() const { return draws_.size(); }
  // Replaces vertices [first, first + vertices.size()) (a shape moved).
  void update_vertices(std::size_t first, std::span<const Vertex> vertices);
  [[nodiscard]] std::size_t triangle_count() const { return index_count_ / 3; }
  // Whether the vertices and indices each fit in one storage block, so
  // that shaders can read a triangle's corners (else draw() passes
  // SCENE_CORNERS_UNREADABLE as the first index).
  [[nodiscard]] bool corners_readable() const { return corners_readable_; }

 private:
  // Triangles whose materials share a texture and sampler, contiguous in
  // the index buffer.
  struct Batch {
    std::size_t first_index = 0;
    std::size_t index_count = 0;
    const gl::Texture* texture = nullptr;
    const gl::Sampler* sampler = nullptr;
    const gl::Sampler* alpha_sampler = nullptr;  // for the alpha test (UNIT_BASE_ALPHA)
    bool cut_out = false;
  };
  // Binds a batch's textures when `set` draws it; false: it draws nothing.
  static bool bind_batch(const Batch& batch, SurfaceSet set);
  // A batch's triangles of one shape, contiguous in the index buffer.
  struct Draw {
    std::size_t batch = 0;
    std::size_t first_index = 0;
    std::size_t index_count = 0;
    std::size_t shape = 0;
  };
  std::vector<Draw> draws_;
  std::vector<std::uint32_t> draw_indices_;  // the index buffer's contents
  gl::Buffer vertices_;
  gl::Buffer indices_;
  gl::Buffer materials_;
  gl::VertexArray vao_;
  std::size_t index_count_ = 0;
  bool corners_readable_ = true;
  std::vector<gl::Texture> textures_;  // [0]: 1x1 white, for untextured materials
  std::vector<gl::Sampler> samplers_;
  std::vector<gl::Sampler> alpha_samplers_;
  std::vector<Batch> batches_;
};

}  // namespace penumbra
