// Virtual shadow maps, allocation, in five dispatches (u_phase):
//  3 (one thread per page-table entry of the levels in use): counts the
//    pages each level bias wants (PAGE_WANTED, virtual_mark.comp);
//  4 (one thread): keeps the finest bias whose pages fit the pool (bias 0,
//    one texel per pixel, if none does), for this frame's allocation and
//    for every pass after it (the block's params.z);
//  0 (one thread per page-table entry): frees the resident pages no pixel
//    requested under that bias, whose slot scrolled to another world
//    page, or whose level changed as a whole, pushing their pool pages
//    onto the free list;
//  1 (the same threads): gives each requested page that has none a pool
//    page from the top of the free list (an atomic counter picks which),
//    and lists it, and each resident page marked dirty, for rendering;
//  2 (one thread): pops what phase 1 took from the free list, writes the
//    number of listed pages into the clearing draws' instance counts, and
//    zeroes the caster draws' (virtual_cull.comp counts them).
// Two lists: the orthographic levels' pages, whose casters' rasterized
// depth is z-bar, and the perspective (spot) levels', whose fragments
// write it (shadow_depth.frag): each has its own draws.
// No read-back: the GPU's own counters drive the draws.
#include "../shared/bindings.h"
#include "../shared/gpu_types.h"
#include "virtual_lookup.glsl"

layout(local_size_x = 8, local_size_y = 8, local_size_z = 1) in;

layout(location = 0) uniform int u_phase;
layout(r32ui, binding = IMAGE_OUTPUT) uniform uimage2DArray page_table;

layout(std430, binding = BINDING_VIRTUAL_COUNTERS_SSBO) buffer Counters {
  uint free_count;  // pool pages on the free list
  uint taken;       // phase 1: pages taken from its top
  uint rendered;    // pages listed for rendering this frame
  uint unserved;    // requested pages the pool had no page for
  uint rendered_written;  // perspective pages listed (from render_list[pool pages])
  uint bias;              // the level bias phase 4 chose
  uint wanted[VIRTUAL_LEVEL_BIASES];  // phase 3: pages each bias wants
};
// The block the passes read (its params.z: the level bias).
layout(std430, binding = BINDING_VIRTUAL_BLOCK_SSBO) buffer VirtualBlockOut {
  GpuVirtualShadow virtual_shadow_out;
};
layout(std430, binding = BINDING_VIRTUAL_FREE_LIST_SSBO) buffer FreeList { uint free_list[]; };
// x: level, yz: world page, w: pool page; the orthographic levels' pages
// from 0, the perspective levels' from the pool's page count.
layout(std430, binding = BINDING_VIRTUAL_RENDER_LIST_SSBO) buffer RenderList {
  ivec4 render_list[];
};
// [0, 4), [4, 8): the clearing draws (DrawArraysIndirectCommand) of the
// two lists; then one DrawElementsIndirectCommand (5 words) per caster
// draw for the first list, and as many for the second.
layout(std430, binding = BINDING_VIRTUAL_COMMANDS_SSBO) buffer Commands { uint commands[]; };

// The world page slot `slot` of level l stands for, with its first page at `origin`.
ivec2 world_page_of(ivec2 slot, ivec2 origin) {
  return origin + ((slot - origin) & (VIRTUAL_PAGES - 1));
}

void list_for_rendering(int level, ivec2 slot, uint page) {
  uint i = virtual_shadow.levels[level].perspective != 0
               ? uint(virtual_shadow.counts.z) + atomicAdd(rendered_written, 1u)
               : atomicAdd(rendered, 1u);
  render_list[i] = ivec4(level, world_page_of(slot, virtual_shadow.origins[level].xy), int(page));
}

void main() {
  if (u_phase == 4) {
    if (gl_GlobalInvocationID != uvec3(0u)) return;
    uint chosen = 0u;
    for (uint k = 1u; k < uint(VIRTUAL_LEVEL_BIASES); ++k) {
      if (wanted[k] <= uint(virtual_shadow.counts.z)) chosen = k;
    }
    for (int k = 0; k < VIRTUAL_LEVEL_BIASES; ++k) wanted[k] = 0u;
    bias = chosen;
    virtual_shadow_out.params.z = float(chosen);
    return;
  }
  if (u_phase == 2) {
    if (gl_GlobalInvocationID != uvec3(0u)) return;
    uint popped = min(taken, free_count);
    free_count -= popped;
    taken = 0u;
    commands[1] = rendered;
    commands[4 + 1] = rendered_written;
    int draws = virtual_shadow.counts.w;
    for (int d = 0; d < 2 * draws; ++d) commands[8 + 5 * d + 1] = 0u;
    return;
  }
  ivec2 slot = ivec2(gl_GlobalInvocationID.xy);
  int level = int(gl_GlobalInvocationID.z);
  // Phase 0 runs over every layer, so the levels a new fit no longer has
  // give their pages back.
  bool in_use = level < virtual_shadow.counts.y;
  if (!in_use && u_phase != 0) return;
  ivec3 at = ivec3(slot, level);
  uint entry = imageLoad(page_table, at).r;
  if (u_phase == 3) {
    for (int k = 0; k < VIRTUAL_LEVEL_BIASES; ++k) {
      if ((entry & PAGE_WANTED(k)) != 0u) atomicAdd(wanted[k], 1u);
    }
    return;
  }
  bool resident = (entry & PAGE_RESIDENT) != 0u;
  bool requested = in_use && (entry & (PAGE_WANTED(bias) | PAGE_REQUESTED)) != 0u;
  if (u_phase == 0) {
    ivec4 origin = virtual_shadow.origins[level];
    bool scrolled = world_page_of(slot, origin.xy) !=
                    world_page_of(slot, virtual_shadow.previous_origins[level].xy);
    if (resident && (!requested || origin.z != 0 || scrolled)) {
      free_list[atomicAdd(free_count, 1u)] = entry & PAGE_INDEX_MASK;
      entry = 0u;
    }
    entry &= ~(PAGE_RENDERED | PAGE_WANTED_ALL | PAGE_REQUESTED);
    imageStore(page_table, at, uvec4(entry | (requested ? PAGE_REQUESTED : 0u)));
    return;
  }
  // Phase 1.
  if (requested && !resident) {
    uint k = atomicAdd(taken, 1u);
    uint available = free_count;
    if (k < available) {
      uint page = free_list[available - 1u - k];
      entry = PAGE_RESIDENT | PAGE_RENDERED | page;
      list_for_rendering(level, slot, page);
    } else {
      atomicAdd(unserved, 1u);
      entry = 0u;
    }
  } else if (resident && (entry & PAGE_DIRTY) != 0u) {
    entry |= PAGE_RENDERED;
    list_for_rendering(level, slot, entry & PAGE_INDEX_MASK);
  }
  imageStore(page_table, at, uvec4(entry & ~(PAGE_REQUESTED | PAGE_DIRTY)));
}
