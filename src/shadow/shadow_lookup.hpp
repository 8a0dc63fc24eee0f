#pragma once
// The shadow core's side of the lookup an engine includes
// (shadow_lookup_glsl() in penumbra/shadow_maps.hpp): the binding points
// as GLSL macros, for the lookup's text and for the core's own programs
// that declare the block (the caster program).
#include "penumbra/gl/shader_source.hpp"
#include "penumbra/shadow_block.hpp"

namespace penumbra {

// PENUMBRA_SHADOW_BLOCK_BINDING, PENUMBRA_SHADOW_DEPTH_UNIT, ..._COMPARE_UNIT,
// ..._FILTERED_UNIT, ..._SAT_UNIT and PENUMBRA_POISSON_BINDING, as
// `bindings` sets them (shaders/shadow/penumbra_shadows.glsl reads them).
gl::Defines shadow_binding_defines(const ShadowBindings& bindings);

// Throws UsageError if two of the texture units are the same.
void check_distinct_units(const ShadowBindings& bindings);

// `bindings`, after check_distinct_units() and a check of each binding
// against the current context's limits (UsageError past one).
const ShadowBindings& checked_bindings(const ShadowBindings& bindings);

}  // namespace penumbra
