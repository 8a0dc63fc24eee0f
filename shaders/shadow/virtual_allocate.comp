// Virtual shadow maps, allocation, in three dispatches (u_phase):
//  0 (one thread per page-table entry): frees the resident pages no pixel
//    requested, whose slot scrolled to another world page, or whose level
//    changed as a whole, pushing their pool pages onto the free list;
//  1 (the same threads): gives each requested page that has none a pool
//    page from the top of the free list (an atomic counter picks which),
//    and lists it, and each resident page marked dirty, for rendering;
//  2 (one thread): pops what phase 1 took from the free list, and writes
//    the number of listed pages into the indirect draws' instance counts.
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
};
layout(std430, binding = BINDING_VIRTUAL_FREE_LIST_SSBO) buffer FreeList { uint free_list[]; };
// x: level, yz: world page, w: pool page; the orthographic levels' pages
// from 0, the perspective levels' from the pool's page count.
layout(std430, binding = BINDING_VIRTUAL_RENDER_LIST_SSBO) buffer RenderList {
  ivec4 render_list[];
};
// [0, 4), [4, 8): the clearing draws (DrawArraysIndirectCommand) of the
// two lists; then one DrawElementsIndirectCommand (5 words) per batch of
// casters for the first list, and as many for the second.
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
  if (u_phase == 2) {
    if (gl_GlobalInvocationID != uvec3(0u)) return;
    uint popped = min(taken, free_count);
    free_count -= popped;
    taken = 0u;
    commands[1] = rendered;
    commands[4 + 1] = rendered_written;
    int batches = virtual_shadow.counts.w;
    for (int b = 0; b < batches; ++b) {
      commands[8 + 5 * b + 1] = rendered;
      commands[8 + 5 * (batches + b) + 1] = rendered_written;
    }
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
  bool resident = (entry & PAGE_RESIDENT) != 0u;
  bool requested = in_use && (entry & PAGE_REQUESTED) != 0u;
  if (u_phase == 0) {
    ivec4 origin = virtual_shadow.origins[level];
    bool scrolled = world_page_of(slot, origin.xy) !=
                    world_page_of(slot, virtual_shadow.previous_origins[level].xy);
    if (resident && (!requested || origin.z != 0 || scrolled)) {
      free_list[atomicAdd(free_count, 1u)] = entry & PAGE_INDEX_MASK;
      entry = 0u;
    }
    imageStore(page_table, at, uvec4((entry & ~PAGE_RENDERED) | (requested ? PAGE_REQUESTED : 0u)));
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
