#pragma once
// The peak memory bandwidth of a GPU, for the bandwidth floor `penumbra
// bench` puts under each pass: a few NVIDIA parts, recognized by their
// name in GL_RENDERER.
#include <optional>
#include <string_view>

namespace penumbra {

struct DeviceBandwidth {
  std::string_view part;  // the name it was recognized by
  double gb_per_second = 0.0;
};

// The bandwidth of the GPU a GL_RENDERER string names ("NVIDIA H100
// PCIe/PCIe/SSE2": the board's name before the first '/'), from its
// maker's published specification; nullopt for any other renderer.
std::optional<DeviceBandwidth> known_device_bandwidth(std::string_view renderer);

}  // namespace penumbra
