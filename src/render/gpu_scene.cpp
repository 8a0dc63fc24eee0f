#include "render/gpu_scene.hpp"

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <map>
#include <tuple>
#include <utility>
#include <vector>

#include "penumbra/shared/bindings.h"
#include "scene/coverage_mips.hpp"

namespace penumbra {

// The G-buffer pass reads vertices from the vertex buffer by these offsets
// (shaders/scene/smooth_surface.glsl).
static_assert(sizeof(Vertex) == SCENE_VERTEX_FLOATS * sizeof(float));
static_assert(offsetof(Vertex, position) == SCENE_VERTEX_POSITION * sizeof(float));
static_assert(offsetof(Vertex, normal) == SCENE_VERTEX_NORMAL * sizeof(float));
// smooth_surface.glsl reads a vertex's position and normal as two vec4s.
static_assert(SCENE_VERTEX_FLOATS % 2 == 0 && SCENE_VERTEX_POSITION % 2 == 0 &&
              SCENE_VERTEX_NORMAL == SCENE_VERTEX_POSITION + 3);

namespace {

GLenum gl_wrap(TextureWrap wrap) {
  switch (wrap) {
    case TextureWrap::ClampToEdge:
      return GL_CLAMP_TO_EDGE;
    case TextureWrap::MirroredRepeat:
      return GL_MIRRORED_REPEAT;
    default:
      return GL_REPEAT;
  }
}

int mip_levels(int width, int height) {
  int levels = 1;
  while ((std::max(width, height) >> levels) > 0) ++levels;
  return levels;
}

// An sRGB texture with its full mip chain: the colour is decoded to linear
// before filtering (OpenGL 4.5, section 8.24), so that minified texels
// average light, not its encoding. A texture whose alpha is tested against
// `cutoff` (> 0) gets the chain of scene/coverage_mips.hpp instead, each
// level keeping level 0's coverage, so that the G-buffer and every shadow
// pass (which pick their level from their own pixel's or texel's
// footprint) see as many leaves at every distance and map size.
gl::Texture upload(const TextureImage& image, float cutoff) {
  const int levels = mip_levels(image.width, image.height);
  gl::Texture texture(gl::TextureInfo{.format = GL_SRGB8_ALPHA8,
                                      .width = image.width,
                                      .height = image.height,
                                      .levels = levels,
                                      .label = image.name});
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  if (cutoff > 0.0f) {
    const std::vector<MipLevel> chain = coverage_mip_chain(image, cutoff);
    for (int level = 0; level < levels && level < static_cast<int>(chain.size()); ++level) {
      const MipLevel& l = chain[static_cast<std::size_t>(level)];
      glTextureSubImage2D(texture.id(), level, 0, 0, l.width, l.height, GL_RGBA, GL_UNSIGNED_BYTE,
                          l.rgba.data());
    }
  } else {
    glTextureSubImage2D(texture.id(), 0, 0, 0, image.width, image.height, GL_RGBA, GL_UNSIGNED_BYTE,
                        image.rgba.data());
    glGenerateTextureMipmap(texture.id());
  }
  glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
  return texture;
}

// What a batch's texture is sampled for: its colour, trilinear and
// anisotropic (the ground and leaf cards are seen at grazing angles), or
// the alpha test, bilinear within the nearest level and not anisotropic,
// so that the coverage each level keeps is the coverage the test sees
// (shaders/scene/surface.glsl).
enum class SampledFor { Colour, AlphaTest };

gl::Sampler make_sampler(TextureWrap s, TextureWrap t, bool nearest, SampledFor use) {
  const bool colour = use == SampledFor::Colour;
  gl::Sampler sampler(gl::SamplerInfo{
      .min_filter =
          static_cast<GLenum>(colour ? GL_LINEAR_MIPMAP_LINEAR : GL_LINEAR_MIPMAP_NEAREST),
      .mag_filter = static_cast<GLenum>(nearest ? GL_NEAREST : GL_LINEAR),
      .wrap = gl_wrap(s),
      .label = colour ? "base colour" : "base alpha"});
  glSamplerParameteri(sampler.id(), GL_TEXTURE_WRAP_T, static_cast<GLint>(gl_wrap(t)));
  // Anisotropic filtering: core in OpenGL 4.6, an extension before.
  if (colour && (epoxy_has_gl_extension("GL_ARB_texture_filter_anisotropic") ||
                 epoxy_has_gl_extension("GL_EXT_texture_filter_anisotropic"))) {
    float most = 1.0f;
    glGetFloatv(GL_MAX_TEXTURE_MAX_ANISOTROPY_EXT, &most);
    glSamplerParameterf(sampler.id(), GL_TEXTURE_MAX_ANISOTROPY_EXT, std::min(16.0f, most));
  }
  return sampler;
}

}  // namespace

bool is_cut_out_material(const Material& m) {
  return coverage_cutoff(m) >= 0.0f || !m.double_sided;
}

GpuMaterial gpu_material(const Material& m) {
  const glm::mat3x2& t = m.uv_transform;
  int flags = 0;
  if (m.texture != nullptr) flags |= MATERIAL_TEXTURED;
  if (m.double_sided) flags |= MATERIAL_DOUBLE_SIDED;
  return {glm::vec4(m.albedo, m.alpha), glm::vec4(m.specular, m.shininess),
          glm::vec4(t[0][0], t[1][0], t[2][0], coverage_cutoff(m)),
          glm::vec4(t[0][1], t[1][1], t[2][1], static_cast<float>(flags))};
}

GpuScene::GpuScene(const Scene& scene, const TriangleMesh& mesh,
                   std::int64_t max_storage_block_bytes,
                   std::span<const std::size_t> shape_first_vertex)
    : vertices_(mesh.vertices.size() * sizeof(Vertex), mesh.vertices.data(), true,
                "scene vertices"),
      vao_("scene"),
      index_count_(mesh.indices.size()) {
  if (max_storage_block_bytes < 0) {
    GLint64 limit = 0;
    glGetInteger64v(GL_MAX_SHADER_STORAGE_BLOCK_SIZE, &limit);
    max_storage_block_bytes = limit;
  }
  const auto fits = [&](std::size_t bytes) {
    return bytes <= static_cast<std::uint64_t>(max_storage_block_bytes);
  };
  corners_readable_ = fits(mesh.vertices.size() * sizeof(Vertex)) &&
                      fits(mesh.indices.size() * sizeof(std::uint32_t));
  std::vector<GpuMaterial> materials;
  for (const Material& m : scene.materials) materials.push_back(gpu_material(m));
  if (materials.empty()) materials.push_back(gpu_material(Material{}));
  materials_ = gl::Buffer::from(std::span<const GpuMaterial>(materials), "materials");

  // Batch b of each material: untextured opaque ones share batch 0 (and
  // a white texel); the others share a batch per texture, sampler and
  // whether they are cut out.
  TextureImage white;
  white.name = "white";
  white.width = white.height = 1;
  white.rgba = {255, 255, 255, 255};
  textures_.push_back(upload(white, -1.0f));
  std::vector<std::size_t> batch_of(scene.materials.size(), 0);
  // One upload per image and alpha cutoff: the coverage a chain keeps
  // depends on the cutoff its alpha is tested against.
  std::map<std::pair<const TextureImage*, float>, std::size_t> texture_index;
  using Key = std::tuple<std::size_t, TextureWrap, TextureWrap, bool, bool>;
  std::map<Key, std::size_t> batch_index;
  const auto batch_for = [&](const Key& key) {
    auto [b, added] = batch_index.try_emplace(key, batches_.size());
    if (added) {
      samplers_.push_back(
          make_sampler(std::get<1>(key), std::get<2>(key), std::get<3>(key), SampledFor::Colour));
      alpha_samplers_.push_back(make_sampler(std::get<1>(key), std::get<2>(key), std::get<3>(key),
                                             SampledFor::AlphaTest));
      batches_.push_back({.cut_out = std::get<4>(key)});
    }
    return b->second;
  };
  batch_for({0, TextureWrap::Repeat, TextureWrap::Repeat, false, false});
  for (std::size_t i = 0; i < scene.materials.size(); ++i) {
    const Material& m = scene.materials[i];
    std::size_t texture = 0;
    if (m.texture != nullptr && m.texture->width > 0 && m.texture->height > 0) {
      const float cutoff = texture_alpha_cutoff(m);
      auto [t, added] = texture_index.try_emplace({m.texture.get(), cutoff}, textures_.size());
      if (added) textures_.push_back(upload(*m.texture, cutoff));
      texture = t->second;
    }
    batch_of[i] = texture == 0 ? batch_for({0, TextureWrap::Repeat, TextureWrap::Repeat, false,
                                            is_cut_out_material(m)})
                               : batch_for({texture, m.wrap_s, m.wrap_t, m.nearest_magnification,
                                            is_cut_out_material(m)});
  }
  // Triangles ordered by batch (a counting sort; the order within a batch
  // is the mesh's).
  const auto triangle_batch = [&](std::size_t triangle) {
    const std::uint32_t material = mesh.vertices[mesh.indices[3 * triangle]].material;
    return material < batch_of.size() ? batch_of[material] : 0;
  };
  const std::size_t triangles = mesh.indices.size() / 3;
  for (std::size_t i = 0; i < triangles; ++i) batches_[triangle_batch(i)].index_count += 3;
  for (std::size_t b = 1; b < batches_.size(); ++b) {
    batches_[b].first_index = batches_[b - 1].first_index + batches_[b - 1].index_count;
  }
  // With one batch drawn (one material kind: a scanned model on the
  // ground), the mesh's own order is the batch order: no copy.
  const bool one_batch = std::count_if(batches_.begin(), batches_.end(),
                                       [](const Batch& b) { return b.index_count > 0; }) <= 1;
  std::vector<std::uint32_t> ordered(one_batch ? 0 : mesh.indices.size());
  if (!one_batch) {
    std::vector<std::size_t> next(batches_.size());
    for (std::size_t b = 0; b < batches_.size(); ++b) next[b] = batches_[b].first_index;
    for (std::size_t i = 0; i < triangles; ++i) {
      std::size_t& at = next[triangle_batch(i)];
      std::copy_n(mesh.indices.begin() + static_cast<std::ptrdiff_t>(3 * i), 3,
                  ordered.begin() + static_cast<std::ptrdiff_t>(at));
      at += 3;
    }
  }
  const std::vector<std::uint32_t>& drawn = one_batch ? mesh.indices : ordered;
  indices_ = gl::Buffer::from(std::span<const std::uint32_t>(drawn), "scene indices");
  // One draw per run of a batch's triangles of one shape (the mesh holds
  // the shapes one after another, and a batch keeps the mesh's order).
  const auto shape_of = [&](std::uint32_t vertex) -> std::size_t {
    if (shape_first_vertex.size() < 2) return 0;
    const auto next = std::upper_bound(shape_first_vertex.begin(), shape_first_vertex.end(),
                                       static_cast<std::size_t>(vertex));
    return static_cast<std::size_t>(next - shape_first_vertex.begin()) - 1;
  };
  for (std::size_t b = 0; b < batches_.size(); ++b) {
    const Batch& batch = batches_[b];
    for (std::size_t i = batch.first_index; i < batch.first_index + batch.index_count; i += 3) {
      const std::size_t shape = shape_of(drawn[i]);
      if (draws_.empty() || draws_.back().batch != b || draws_.back().shape != shape) {
        draws_.push_back({.batch = b, .first_index = i, .index_count = 0, .shape = shape});
      }
      draws_.back().index_count += 3;
    }
  }
  draw_indices_ = drawn;
  // Batch b uses samplers_[b] and the texture of its key.
  for (const auto& [key, b] : batch_index) {
    batches_[b].texture = &textures_[std::get<0>(key)];
    batches_[b].sampler = &samplers_[b];
    batches_[b].alpha_sampler = &alpha_samplers_[b];
  }

  const GLuint vao = vao_.id();
  glVertexArrayVertexBuffer(vao, 0, vertices_.id(), 0, sizeof(Vertex));
  glVertexArrayElementBuffer(vao, indices_.id());
  glEnableVertexArrayAttrib(vao, 0);
  glVertexArrayAttribFormat(vao, 0, 3, GL_FLOAT, GL_FALSE, offsetof(Vertex, position));
  glVertexArrayAttribBinding(vao, 0, 0);
  glEnableVertexArrayAttrib(vao, 1);
  glVertexArrayAttribFormat(vao, 1, 3, GL_FLOAT, GL_FALSE, offsetof(Vertex, normal));
  glVertexArrayAttribBinding(vao, 1, 0);
  glEnableVertexArrayAttrib(vao, 2);
  glVertexArrayAttribIFormat(vao, 2, 1, GL_UNSIGNED_INT, offsetof(Vertex, material));
  glVertexArrayAttribBinding(vao, 2, 0);
  glEnableVertexArrayAttrib(vao, 3);
  glVertexArrayAttribFormat(vao, 3, 2, GL_FLOAT, GL_FALSE, offsetof(Vertex, uv));
  glVertexArrayAttribBinding(vao, 3, 0);
  glEnableVertexArrayAttrib(vao, 4);
  glVertexArrayAttribFormat(vao, 4, 4, GL_UNSIGNED_BYTE, GL_TRUE, offsetof(Vertex, color));
  glVertexArrayAttribBinding(vao, 4, 0);
}

void GpuScene::update_vertices(std::size_t first, std::span<const Vertex> vertices) {
  vertices_.update(vertices.data(), vertices.size_bytes(), first * sizeof(Vertex));
}

bool GpuScene::bind_batch(const Batch& batch, SurfaceSet set) {
  if (batch.index_count == 0) return false;
  if ((set == SurfaceSet::Opaque && batch.cut_out) ||
      (set == SurfaceSet::CutOut && !batch.cut_out)) {
    return false;
  }
  glBindTextureUnit(UNIT_BASE_COLOR, batch.texture->id());
  glBindSampler(UNIT_BASE_COLOR, batch.sampler->id());
  glBindTextureUnit(UNIT_BASE_ALPHA, batch.texture->id());
  glBindSampler(UNIT_BASE_ALPHA, batch.alpha_sampler->id());
  return true;
}

void GpuScene::draw_indirect(SurfaceSet set, std::size_t offset, GLint draw_location) const {
  glBindVertexArray(vao_.id());
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, BINDING_MATERIALS_SSBO, materials_.id());
  std::size_t bound = batches_.size();
  for (std::size_t d = 0; d < draws_.size(); ++d) {
    const Batch& batch = batches_[draws_[d].batch];
    if (draws_[d].batch != bound) {
      if (!bind_batch(batch, set)) continue;
      bound = draws_[d].batch;
    }
    if (draw_location >= 0) glUniform1i(draw_location, static_cast<GLint>(d));
    glDrawElementsIndirect(GL_TRIANGLES, GL_UNSIGNED_INT,
                           reinterpret_cast<const void*>(offset + d * 5 * sizeof(std::uint32_t)));
  }
  glBindSampler(UNIT_BASE_COLOR, 0);
  glBindSampler(UNIT_BASE_ALPHA, 0);
}

std::vector<std::uint32_t> GpuScene::indirect_commands() const {
  std::vector<std::uint32_t> commands;
  for (const Draw& draw : draws_) {
    commands.insert(commands.end(), {static_cast<std::uint32_t>(draw.index_count), 0u,
                                     static_cast<std::uint32_t>(draw.first_index), 0u, 0u});
  }
  return commands;
}

std::vector<CasterBounds> GpuScene::draw_bounds(const TriangleMesh& mesh) const {
  std::vector<CasterBounds> bounds;
  for (const Draw& draw : draws_) {
    CasterBounds b{glm::vec3(1e30f), glm::vec3(-1e30f)};
    for (std::size_t i = draw.first_index; i < draw.first_index + draw.index_count; ++i) {
      const glm::vec3& p = mesh.vertices[draw_indices_[i]].position;
      b.min = glm::min(b.min, p);
      b.max = glm::max(b.max, p);
    }
    bounds.push_back(b);
  }
  return bounds;
}

void GpuScene::draw(SurfaceSet set, Corners corners) const {
  glBindVertexArray(vao_.id());
  if (corners == Corners::Read) {
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, BINDING_SCENE_VERTICES_SSBO, vertices_.id());
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, BINDING_SCENE_INDICES_SSBO, indices_.id());
  }
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, BINDING_MATERIALS_SSBO, materials_.id());
  for (const Batch& batch : batches_) {
    if (!bind_batch(batch, set)) continue;
    if (corners == Corners::Read) {
      glUniform1ui(LOCATION_FIRST_INDEX, corners_readable_
                                             ? static_cast<GLuint>(batch.first_index)
                                             : static_cast<GLuint>(SCENE_CORNERS_UNREADABLE));
    }
    glDrawElements(GL_TRIANGLES, static_cast<GLsizei>(batch.index_count), GL_UNSIGNED_INT,
                   reinterpret_cast<const void*>(batch.first_index * sizeof(std::uint32_t)));
  }
  glBindSampler(UNIT_BASE_COLOR, 0);
  glBindSampler(UNIT_BASE_ALPHA, 0);
}

}  // namespace penumbra
