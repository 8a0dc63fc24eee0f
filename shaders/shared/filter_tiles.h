// Workgroup tiles of the filter passes, shared by the C++ host (dispatch
// sizes, the bytes each pass moves) and the compute shaders.
#ifndef PENUMBRA_FILTER_TILES_H
#define PENUMBRA_FILTER_TILES_H

// The separable Gaussian (shaders/filter/gaussian_blur.comp): a workgroup
// filters GAUSSIAN_TILE_ALONG texels along the axis in GAUSSIAN_TILE_ACROSS
// rows, staging them with their apron in shared memory.
#define GAUSSIAN_TILE_ALONG 64
#define GAUSSIAN_TILE_ACROSS 8

// Without a tile in shared memory (CPU rasterizers: the direct passes of
// the Gaussian and of the fused filter, shaders/filter/fused_filter.comp),
// an invocation filters FILTER_DIRECT_RUN consecutive texels from one read
// of their window.
#define FILTER_DIRECT_RUN 4

// The parallel summed-area table (shaders/filter/sat_scan.comp): a
// workgroup scans SAT_TILE_ACROSS lines, SAT_TILE_ALONG texels at a time,
// with SAT_THREADS_ALONG threads a line, each scanning a run of SAT_RUN
// consecutive texels.
#define SAT_THREADS_ALONG 8
#define SAT_RUN 16
#define SAT_TILE_ALONG (SAT_THREADS_ALONG * SAT_RUN)
#define SAT_TILE_ACROSS 8

#endif
