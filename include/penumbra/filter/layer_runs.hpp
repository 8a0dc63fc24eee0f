#pragma once
// The layers of a shadow-map array a compute pass processes: after a frame
// that drew some views again, only theirs (the others' filtered maps are
// still current). Each pass dispatches one run of consecutive layers at a
// time, its shader adding the run's first layer (uniform u_first_layer) to
// the workgroup's z.
#include <cstdint>
#include <span>

namespace penumbra {

// Calls run(first, count) for each run of consecutive layers flagged in
// `layers` (one flag per layer, nonzero: process), or once for all
// `layer_count` layers when `layers` is empty or `all` is set. Layers past
// the flags' end are processed.
template <class Run>
void for_each_layer_run(std::span<const std::uint8_t> layers, int layer_count, bool all, Run run) {
  if (layers.empty() || all) {
    run(0, layer_count);
    return;
  }
  int first = -1;
  for (int i = 0; i <= layer_count; ++i) {
    const bool flagged = i < layer_count && (static_cast<std::size_t>(i) >= layers.size() ||
                                             layers[static_cast<std::size_t>(i)] != 0);
    if (flagged && first < 0) first = i;
    if (!flagged && first >= 0) {
      run(first, i - first);
      first = -1;
    }
  }
}

}  // namespace penumbra
