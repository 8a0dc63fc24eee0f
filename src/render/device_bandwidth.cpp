#include "render/device_bandwidth.hpp"

#include <array>

namespace penumbra {

namespace {

struct Part {
  std::string_view name;  // found in the board's name
  double gb_per_second;   // 0: the name covers parts of different bandwidths
};

// Peak memory bandwidth from NVIDIA's data sheets, in GB/s (10^9 bytes).
// Searched in order, so a name that contains another comes first (H100
// PCIe before H100, L40S before L40 before L4).
constexpr std::array kParts = {
    Part{"GH200", 0.0},  // 4000 with HBM3, 4900 with HBM3e
    Part{"B200", 8000.0},
    Part{"H200", 4800.0},
    Part{"H100 PCIe", 2000.0},
    Part{"H100 NVL", 3900.0},
    Part{"H100", 3350.0},  // SXM5, HBM3
    Part{"A100-SXM4-80GB", 2039.0},
    Part{"A100 80GB PCIe", 1935.0},
    Part{"A100", 1555.0},  // the 40 GB parts
    Part{"L40S", 864.0},
    Part{"L40", 864.0},
    Part{"L4", 300.0},
    Part{"A10G", 600.0},
    Part{"A10", 600.0},
    Part{"T4", 320.0},
    Part{"V100S", 1134.0},
    Part{"V100", 900.0},
    Part{"RTX 6000 Ada", 960.0},
    Part{"RTX A6000", 768.0},
    Part{"RTX 4090", 1008.0},
    Part{"RTX 3090 Ti", 1008.0},
    Part{"RTX 3090", 936.0},
};

}  // namespace

std::optional<DeviceBandwidth> known_device_bandwidth(std::string_view renderer) {
  const std::string_view board = renderer.substr(0, renderer.find('/'));
  if (board.find("NVIDIA") == std::string_view::npos) return std::nullopt;
  for (const Part& part : kParts) {
    if (board.find(part.name) == std::string_view::npos) continue;
    if (part.gb_per_second <= 0.0) return std::nullopt;
    return DeviceBandwidth{part.name, part.gb_per_second};
  }
  return std::nullopt;
}

}  // namespace penumbra
