#pragma once
// The caster geometry the view fitting reads: the positions of a triangle
// list, read in place from the engine's own vertex array (any vertex
// layout: a pointer, a count and a stride), never copied; or, coarser,
// one bounding box per caster (CasterBounds).
#include <concepts>
#include <cstddef>
#include <glm/glm.hpp>
#include <ranges>
#include <type_traits>

namespace penumbra {

class PositionSpan {
 public:
  constexpr PositionSpan() = default;
  // `count` positions, the first at `first`, each `stride` bytes after the
  // one before (sizeof(Vertex) for an array of vertices).
  PositionSpan(const glm::vec3* first, std::size_t count, std::size_t stride = sizeof(glm::vec3))
      : first_(reinterpret_cast<const std::byte*>(first)), count_(count), stride_(stride) {}

  // A contiguous array of glm::vec3.
  template <std::ranges::contiguous_range R>
  requires std::same_as<std::remove_cvref_t<std::ranges::range_value_t<R>>, glm::vec3> PositionSpan(
      const R& positions)  // NOLINT: implicit, as std::span converts
      : PositionSpan(std::ranges::data(positions), std::ranges::size(positions)) {}

  // The `position` members of a contiguous array of vertices.
  template <std::ranges::contiguous_range R>
  requires requires(const std::ranges::range_value_t<R>& v) {
    { v.position } -> std::convertible_to<glm::vec3>;
  } && std::same_as<decltype(std::ranges::range_value_t<R>::position), glm::vec3> PositionSpan(
      const R& vertices)  // NOLINT: implicit, as std::span converts
      : PositionSpan(
            std::ranges::empty(vertices) ? nullptr : &std::ranges::data(vertices)->position,
            std::ranges::size(vertices), sizeof(std::ranges::range_value_t<R>)) {
  }

  [[nodiscard]] std::size_t size() const { return count_; }
  [[nodiscard]] bool empty() const { return count_ == 0; }
  // Position i (i < size()).
  [[nodiscard]] const glm::vec3& operator[](std::size_t i) const {
    return *reinterpret_cast<const glm::vec3*>(first_ + i * stride_);
  }

 private:
  const std::byte* first_ = nullptr;
  std::size_t count_ = 0;
  std::size_t stride_ = sizeof(glm::vec3);
};

// A caster's world-space axis-aligned bounding box.
struct CasterBounds {
  glm::vec3 min{0.0f};
  glm::vec3 max{0.0f};
  bool operator==(const CasterBounds&) const = default;
};

}  // namespace penumbra
