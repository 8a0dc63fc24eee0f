// Binding points shared by the C++ host and the GLSL shaders: this file is
// included by both, so a binding has one number in one place.
#ifndef PENUMBRA_BINDINGS_H
#define PENUMBRA_BINDINGS_H

// Uniform blocks
#define BINDING_FRAME_UBO 0
#define BINDING_LIGHTS_UBO 1
#define BINDING_SHADOW_UBO 2
#define BINDING_PASS_UBO 3
#define BINDING_SSAO_UBO 4
#define BINDING_SHADOW_VIEWS_UBO 5
#define BINDING_VIRTUAL_UBO 6  // GpuVirtualShadow: the virtual lights' levels

// Storage buffers
#define BINDING_MATERIALS_SSBO 0
#define BINDING_FILTER_WEIGHTS_SSBO 1
#define BINDING_POISSON_SSBO 2
#define BINDING_SCENE_VERTICES_SSBO 3  // the scene's vertices (GpuScene), read by triangle
#define BINDING_SCENE_INDICES_SSBO 4   // and its indices, three per triangle
// Virtual shadow maps (penumbra/shadow/virtual_shadow_pass.hpp): the page
// counters (VirtualPageCounters), the free list of pool pages, the list of
// pages to render, and the indirect draw commands.
#define BINDING_VIRTUAL_COUNTERS_SSBO 5
#define BINDING_VIRTUAL_FREE_LIST_SSBO 6
#define BINDING_VIRTUAL_RENDER_LIST_SSBO 7
#define BINDING_VIRTUAL_COMMANDS_SSBO 8
// The GpuVirtualShadow block itself, where the allocation writes the
// level bias it chose (params.z) for the passes after it.
#define BINDING_VIRTUAL_BLOCK_SSBO 9
// Per-page caster culling: each draw's world bounds (two vec4), and the
// listed pages each draw covers (pool pages x draws entries).
#define BINDING_VIRTUAL_DRAW_BOUNDS_SSBO 10
#define BINDING_VIRTUAL_DRAW_PAGES_SSBO 11
// The vertices' layout in that buffer, in floats (src/scene/mesh.hpp:
// Vertex, whose offsets src/render/gpu_scene.cpp checks against these).
#define SCENE_VERTEX_FLOATS 10
#define SCENE_VERTEX_POSITION 0
#define SCENE_VERTEX_NORMAL 3
// The first index GpuScene::draw passes when the buffers are larger than
// one storage block may be (MAX_SHADER_STORAGE_BLOCK_SIZE: 128 MiB on
// Mesa): the corners cannot be read.
#define SCENE_CORNERS_UNREADABLE 0xffffffffu

// Texture units
#define UNIT_GBUFFER_DEPTH 0
#define UNIT_GBUFFER_NORMAL 1
#define UNIT_GBUFFER_ALBEDO 2
#define UNIT_GBUFFER_SPECULAR 3
#define UNIT_AMBIENT_OCCLUSION 4  // the AO texture: read by the lighting pass and the SSAO blur
#define UNIT_BASE_COLOR 5         // the scene's base-colour texture of the batch drawn
#define UNIT_GBUFFER_FACET 6      // the G-buffer's triangle normal and smooth-surface height
#define UNIT_BASE_ALPHA 7  // the same texture, for the alpha test: nearest level, not anisotropic
// The shadow maps of every light's views, one array layer per view:
#define UNIT_SHADOW_DEPTH 8     // z-bar depth maps
#define UNIT_SHADOW_FILTERED 9  // the filtered representations (or summed-area tables)
#define UNIT_SHADOW_COMPARE 10  // the depth maps with a comparison sampler
// Virtual shadow maps: the page table (usampler2DArray, one layer per
// level) and the physical page pool (a depth array, one layer per page).
#define UNIT_VIRTUAL_PAGE_TABLE 11
#define UNIT_VIRTUAL_POOL 12
// Each pool page's nearest and farthest depth per cell (virtual_bounds.comp)
#define UNIT_VIRTUAL_BOUNDS 13
#define UNIT_COMPUTE_INPUT 0
#define UNIT_PRESENT_SOURCE 0

// Uniform locations
#define LOCATION_FIRST_INDEX 0   // GpuScene::draw: the batch's first index, for gl_PrimitiveID
#define LOCATION_VIRTUAL_DRAW 5  // virtual_page.vert: the caster draw, for its pages
#define LOCATION_VIRTUAL_LIST 6  // virtual_page.vert: the page list (orthographic, perspective)

// Image units (compute)
#define IMAGE_OUTPUT 0
#define IMAGE_OUTPUT_2 1

#define MAX_LIGHTS 4
// Shadow views of all lights together: six per light, a point light's cube.
#define MAX_SHADOW_VIEWS 24
// Cascades of a directional light.
#define MAX_CASCADES 4

// Virtual shadow maps: texels per page side, pages per level side (a
// level is 16,384^2 virtual texels), most clipmap levels.
#define VIRTUAL_PAGE_TEXELS 128
#define VIRTUAL_PAGES 128
#define MAX_VIRTUAL_LEVELS 16
// A spot light's virtual map: mip levels of 16,384^2 down to one page.
#define VIRTUAL_SPOT_LEVELS 8
// Levels of all virtual lights together (one page-table layer each): a
// directional light's clipmap and a spot map for each other light.
#define MAX_VIRTUAL_VIEWS (MAX_VIRTUAL_LEVELS + (MAX_LIGHTS - 1) * VIRTUAL_SPOT_LEVELS)
// Cells per page side of the pages' depth bounds (16 x 16 texels each).
#define VIRTUAL_BOUNDS_CELLS 8
// A page-table entry: the pool page's index in the low bits, and flags.
#define PAGE_INDEX_MASK 0xffffu
#define PAGE_RESIDENT 0x80000000u   // the pool page holds the page's depths
#define PAGE_REQUESTED 0x40000000u  // a pixel of this frame reads it (marking)
#define PAGE_RENDERED 0x20000000u   // drawn this frame (else cached)
#define PAGE_DIRTY 0x10000000u      // a caster over it moved: draw it again
// Level biases the marking tries: bias k reads levels k/2 finer than the
// footprint's (k = 0: at least one texel per pixel); a pixel marks the
// page it reads under each with PAGE_WANTED(k), and the allocation keeps
// the finest bias whose pages fit the pool.
#define VIRTUAL_LEVEL_BIASES 5
#define PAGE_WANTED(k) (0x10000u << (k))
#define PAGE_WANTED_ALL 0x1f0000u

// Widest PCF / PCSS window, in texels.
#define MAX_PCF_WIDTH 128
// Virtual shadow maps: backprojection reads its region at the level where
// it spans at most this many texels, texel by texel (half a page, so the
// region reads at most 2 x 2 pages; shaders/shadow/virtual_shadow.glsl).
#define VIRTUAL_BACKPROJECTION_WINDOW 64
// Backprojection: the steepest slope tan(theta) its slope-scaled bias
// follows (shaders/shadow/backprojection.glsl says why; the settings'
// max_slope still caps its receiver's depth gradient). The help of
// --max-slope quotes it.
#define BACKPROJECTION_BIAS_MAX_SLOPE 2.0
// Virtual shadow maps: PCSS reads its blocker search and its filter from
// a level where each is at most this many texels wide (half a page, so a
// window reads at most 2 x 2 pages; a wider penumbra is read from a
// coarser level).
#define VIRTUAL_PCSS_WINDOW 64
// Largest box radius read from a summed-area table (its fixed-point scale
// is chosen so that a box this size cannot overflow 32 bits).
#define MAX_SOFT_RADIUS 64
// Most samples per pixel of the SSAO kernel (GpuSsao::kernel)
#define SSAO_MAX_SAMPLES 64

// The camera's window depth at its near and far planes: reversed-Z
// (src/render/camera_depth.hpp), read back only through
// position_from_depth (shaders/render/camera_depth.glsl)
#define CAMERA_NEAR_DEPTH 1.0
#define CAMERA_FAR_DEPTH 0.0

// Material flags (GpuMaterial::uv_row1.w)
#define MATERIAL_TEXTURED 1
#define MATERIAL_DOUBLE_SIDED 2

// Light types (GpuLight::position_type.w)
#define LIGHT_SPOT 0
#define LIGHT_DIRECTIONAL 1
#define LIGHT_POINT 2

// Views written by the lighting pass (GpuFrame::options.y)
#define VIEW_FINAL 0
#define VIEW_SHADOW 1
#define VIEW_NORMALS 2
#define VIEW_ALBEDO 3
#define VIEW_SHADOW_REFERENCE 4
#define VIEW_AO 5
#define VIEW_CASCADES 6  // the cascade (or cube face) each pixel reads, as a colour
#define VIEW_PAGES 7     // the virtual page each pixel reads: its level, cached or rendered
// Shadow-map texels per pixel (shaders/shadow/texel_density.glsl): in false
// colour, or the values themselves in red (Renderer::read_texel_density)
#define VIEW_TEXEL_DENSITY 8
#define VIEW_TEXEL_DENSITY_VALUES 9
// Which of those views a lighting program writes (compile-time define
// LIGHTING_VIEWS): the shaded ones, the filtered hard-shadow reference, or
// the views that inspect the frame without a technique's lookup. A CPU
// rasterizer (llvmpipe) runs the code of an `if` whether any pixel takes it
// or not, so a view's code in every program costs every frame.
#define LIGHTING_VIEWS_SHADED 0     // VIEW_FINAL, VIEW_SHADOW
#define LIGHTING_VIEWS_REFERENCE 1  // VIEW_SHADOW_REFERENCE
#define LIGHTING_VIEWS_INSPECT 2    // normals, albedo, AO, cascades, pages, texel density

// Shadow techniques (compile-time define SHADOW_TECHNIQUE)
// (the filterable ones, from TECHNIQUE_VSM on, last)
#define TECHNIQUE_NONE 0
#define TECHNIQUE_HARD 1
#define TECHNIQUE_PCF 2
#define TECHNIQUE_PCSS 3
#define TECHNIQUE_BACKPROJECTION 4
#define TECHNIQUE_VSM 5
#define TECHNIQUE_ESM 6
#define TECHNIQUE_MSM 7
#define TECHNIQUE_MSM16 8
#define TECHNIQUE_EVSM2 9
#define TECHNIQUE_EVSM4 10

// Filters of the filterable maps (compile-time define SHADOW_FILTER)
#define FILTER_NONE 0
#define FILTER_GAUSSIAN 1
#define FILTER_SAT 2

// Views of a light's map written by the map-view kernel
#define MAP_VIEW_RAW 0
#define MAP_VIEW_ESM_LOG 1

// How a view's texture holds its values (Renderer's ViewEncoding), for the
// present pass that shows it in a window
#define VIEW_ENCODING_LINEAR_COLOR 0
#define VIEW_ENCODING_DATA 1
#define VIEW_ENCODING_DEPTH 2
#define VIEW_ENCODING_LOG_DEPTH 3
#define VIEW_ENCODING_SIGNED_MOMENTS 4

#endif
