// shadow_lookup_glsl() and insert_shadow_lookup() (penumbra/shadow_maps.hpp):
// shaders/shadow/penumbra_shadows.glsl with its includes expanded, its
// binding macros defined as the engine chose, every name it declares in
// penumbra's namespace (shadow/glsl_namespace.hpp) and #line directives
// that keep the engine's line numbers.
#include "shadow/shadow_lookup.hpp"

#include <epoxy/gl.h>
#include <array>
#include <sstream>
#include <utility>

#include "penumbra/error.hpp"
#include "penumbra/shadow_maps.hpp"
#include "penumbra/version.hpp"
#include "shadow/glsl_namespace.hpp"

namespace penumbra {
namespace {

// The lookup up to the #line that restores the engine's numbering: a
// header whose own #line makes the line numbers the driver reports inside
// the lookup those of this text (of share/penumbra/penumbra_shadows.glsl),
// the binding macros, then the expanded, prefixed lookup (without the
// macros of bindings.h that only penumbra's renderer uses).
std::string lookup_text(const ShadowBindings& bindings) {
  check_distinct_units(bindings);
  std::string defines;
  for (const auto& [name, value] : shadow_binding_defines(bindings)) {
    defines += "#define " + name + " " + value + "\n";
  }
  const std::string expanded =
      glsl::strip_cplusplus_sections(gl::expand_shader_includes("shadow/penumbra_shadows.glsl"));
  return "// penumbra " PENUMBRA_VERSION_STRING
         " shadow lookup (shaders/shadow/penumbra_shadows.glsl, includes expanded, every name\n"
         "// it declares prefixed PENUMBRA_, Penumbra or penumbra_). Ends in \"#line 2\".\n"
         "#line 4\n" +
         glsl::drop_unused_macros(glsl::prefix_declarations(defines + expanded));
}

}  // namespace

gl::Defines shadow_binding_defines(const ShadowBindings& b) {
  return {{"PENUMBRA_SHADOW_BLOCK_BINDING", std::to_string(b.block)},
          {"PENUMBRA_SHADOW_DEPTH_UNIT", std::to_string(b.depth_unit)},
          {"PENUMBRA_SHADOW_COMPARE_UNIT", std::to_string(b.compare_unit)},
          {"PENUMBRA_SHADOW_FILTERED_UNIT", std::to_string(b.filtered_unit)},
          {"PENUMBRA_SHADOW_SAT_UNIT", std::to_string(b.sat_unit)},
          {"PENUMBRA_POISSON_BINDING", std::to_string(b.poisson_buffer)},
          {"PENUMBRA_SHADOW_VIRTUAL_BLOCK_BINDING", std::to_string(b.virtual_block)},
          {"PENUMBRA_SHADOW_PAGE_TABLE_UNIT", std::to_string(b.page_table_unit)},
          {"PENUMBRA_SHADOW_PAGE_POOL_UNIT", std::to_string(b.page_pool_unit)}};
}

void check_distinct_units(const ShadowBindings& b) {
  const std::array<std::pair<const char*, unsigned>, 6> units = {
      {{"depth_unit", b.depth_unit},
       {"compare_unit", b.compare_unit},
       {"filtered_unit", b.filtered_unit},
       {"sat_unit", b.sat_unit},
       {"page_table_unit", b.page_table_unit},
       {"page_pool_unit", b.page_pool_unit}}};
  for (std::size_t i = 0; i < units.size(); ++i) {
    for (std::size_t j = i + 1; j < units.size(); ++j) {
      if (units[i].second == units[j].second) {
        throw UsageError(std::string("ShadowBindings: ") + units[i].first + " and " +
                         units[j].first + " are both texture unit " +
                         std::to_string(units[i].second));
      }
    }
  }
}

const ShadowBindings& checked_bindings(const ShadowBindings& b) {
  check_distinct_units(b);
  const auto check = [](const char* field, unsigned value, GLenum limit_name) {
    GLint limit = 0;
    glGetIntegerv(limit_name, &limit);
    if (value >= static_cast<unsigned>(limit)) {
      throw UsageError("ShadowBindings: " + std::string(field) + " " + std::to_string(value) +
                       " is past this context's limit (" + std::to_string(limit) + ")");
    }
  };
  check("block", b.block, GL_MAX_UNIFORM_BUFFER_BINDINGS);
  check("poisson_buffer", b.poisson_buffer, GL_MAX_SHADER_STORAGE_BUFFER_BINDINGS);
  check("virtual_block", b.virtual_block, GL_MAX_UNIFORM_BUFFER_BINDINGS);
  for (auto [field, unit] : {std::pair{"depth_unit", b.depth_unit},
                             {"compare_unit", b.compare_unit},
                             {"filtered_unit", b.filtered_unit},
                             {"sat_unit", b.sat_unit},
                             {"page_table_unit", b.page_table_unit},
                             {"page_pool_unit", b.page_pool_unit}}) {
    check(field, unit, GL_MAX_COMBINED_TEXTURE_IMAGE_UNITS);
  }
  return b;
}

std::string shadow_lookup_glsl(const ShadowBindings& bindings) {
  return lookup_text(bindings) + "#line 2\n";
}

std::string insert_shadow_lookup(std::string_view source, const ShadowBindings& bindings) {
  // After the #version line, the #extension lines that follow it (they
  // must precede every declaration) and the engine's #define PENUMBRA_...
  // lines that configure the lookup (PENUMBRA_NO_FRAGMENT_ENTRY_POINTS);
  // comments and blank lines may come between.
  std::size_t insert_at = 0;  // where the engine's first line after the head starts
  int lines_before = 0;
  bool version = false;
  int line = 0;
  for (std::size_t offset = 0; offset < source.size();) {
    std::size_t end = source.find('\n', offset);
    end = end == std::string_view::npos ? source.size() : end + 1;
    ++line;
    std::istringstream words{std::string(source.substr(offset, end - offset))};
    std::string first, second;
    words >> first >> second;
    if (first == "#") {  // "# version 450"
      first += second;
      words >> second;
    }
    offset = end;
    if (first.empty() || first.starts_with("//")) continue;
    const bool head = first == "#version"
                          ? !version
                          : version && (first == "#extension" ||
                                        (first == "#define" && second.starts_with("PENUMBRA_")));
    if (!head) break;
    version = true;
    insert_at = end;
    lines_before = line;
  }
  if (!version) throw UsageError("insert_shadow_lookup: the shader has no #version line");
  std::string head(source.substr(0, insert_at));
  if (!head.ends_with('\n')) head += '\n';
  return head + lookup_text(bindings) + "#line " + std::to_string(lines_before + 1) + "\n" +
         std::string(source.substr(insert_at));
}

}  // namespace penumbra
