#pragma once
// The shadow lookup's private GLSL namespace. The lookup is a guest in an
// engine's shader, so every name it declares carries penumbra's prefix
// (PENUMBRA_ for macros and constants in capitals, Penumbra for type and
// block names in CamelCase, penumbra_impl_ for the rest). penumbra's own
// shaders keep their short names; the prefix is put on when the lookup is
// emitted (shadow_lookup_glsl()), by a small tokenizer that finds what the
// expanded text declares and rewrites those names, whole tokens only.
#include <set>
#include <string>
#include <string_view>

namespace penumbra::glsl {

// Names a GLSL text declares, by kind.
struct Declarations {
  std::set<std::string> macros;     // #define NAME, and names tested by #if/#ifdef/#ifndef
  std::set<std::string> types;      // struct NAME
  std::set<std::string> blocks;     // uniform/buffer NAME { ... }
  std::set<std::string> functions;  // definitions and prototypes
  // Global variables and constants, block instances, and the members of a
  // block without an instance name (they are globals).
  std::set<std::string> variables;

  [[nodiscard]] std::set<std::string> all() const;
};

// What `text` (GLSL, preprocessor lines included) declares at global
// scope. Throws RuntimeError for a global statement it cannot read, so a
// construct it does not know is a build error, never a leaked name.
Declarations global_declarations(std::string_view text);

// Whether `name` is in penumbra's namespace: it begins with penumbra_,
// PENUMBRA_ or Penumbra.
bool has_namespace_prefix(std::string_view name);

// `name` in the namespace: CAPITALS_1 -> PENUMBRA_CAPITALS_1, CamelCase ->
// PenumbraCamelCase, anything else -> penumbra_impl_name (not penumbra_name:
// the helpers shadow_pcf, shadow_hard... would become the entry points
// penumbra_shadow_pcf...); a name already in it is returned as it is.
std::string prefixed_name(std::string_view name);

// `text` with every name it declares (global_declarations()) that is not in
// the namespace renamed to prefixed_name(), whole tokens only: not inside
// comments, not after '.' (members, swizzles) and not where a struct or
// named block declares its members. Names reserved to GLSL (gl_*, __*) are
// left alone. Throws RuntimeError if a new name is already used in `text`.
std::string prefix_declarations(std::string_view text);

// `text` without the #define directives of macros it never uses (repeated
// until none is left: a macro used only by an unused one goes too), so that
// an engine reading the lookup sees only what it needs. Comments stay.
std::string drop_unused_macros(std::string_view text);

// `text` without its `#ifdef __cplusplus` sections (the C++ half of the
// headers shared by C++ and GLSL, which a GLSL compiler skips), their
// `#else` branches kept; lines removed are left empty.
std::string strip_cplusplus_sections(std::string_view text);

}  // namespace penumbra::glsl
