#pragma once
// How a filter pass's workgroups read their taps: through a tile staged in
// shared memory (GPUs), or straight from memory (CPU rasterizers such as
// llvmpipe, where a barrier switches between coroutines and each lane's
// shared load is a scalar one, so the staging costs more than it saves).
// Each pass sums the same texels in the same order either way: the same
// floats.

namespace penumbra {

enum class FilterStaging { Automatic, SharedMemory, Direct };

// Whether `staging` stages in shared memory; Automatic asks the current
// context's GL_RENDERER (shared memory but on a CPU rasterizer).
bool stages_in_shared_memory(FilterStaging staging);

}  // namespace penumbra
