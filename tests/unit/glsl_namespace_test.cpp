// The lookup's private GLSL namespace (src/shadow/glsl_namespace.hpp) and
// the lookup text an engine gets (shadow_lookup_glsl(),
// insert_shadow_lookup()): what it declares, the prefix, the bindings and
// the #line directives. Compiled in an engine's shader on the GPU by
// tests/gpu/shadow_lookup_test.cpp.
#include <gtest/gtest.h>

#include <algorithm>
#include <regex>
#include <set>
#include <string>

#include "penumbra/error.hpp"
#include "penumbra/gl/shader_source.hpp"
#include "penumbra/shadow_maps.hpp"
#include "shadow/glsl_namespace.hpp"

namespace penumbra {
namespace {

using Names = std::set<std::string>;

// Every kind of global declaration, and local and member names that are not.
const char* const kSample = R"(#version 450 core
#define OBJECT_MACRO 3
#define function_macro(x) ((x) * OBJECT_MACRO)
#ifdef ENGINE_OPTION
#endif
#if defined(OTHER_OPTION) && GL_ES
#endif
struct Record {
  vec4 member;              // a member, not a global
  float values[OBJECT_MACRO];
};
struct Pair { int a, b; } pair_variable;
layout(std140, binding = 1) uniform NamedBlock {
  Record block_member;
} block_instance;
layout(std430, binding = 2) readonly buffer AnonymousBlock {
  vec2 anonymous_member[];
};
layout(binding = 3) uniform sampler2DArray a_sampler;
const float kConstant = 0.5, SECOND_CONSTANT = 2.0;
const ivec2 an_array[2] = ivec2[](ivec2(0), ivec2(1));
float prototype(Record r, in vec3 direction);
layout(local_size_x = 8) in;
precision highp float;
out vec4 gl_out_like;
float definition(Record r, in vec3 direction, out float result) {
  float local_value = r.member.x + block_instance.block_member.member.y;
  result = local_value;
  return prototype(r, direction) + kConstant;
}
)";

TEST(GlslNamespace, FindsEveryKindOfGlobalDeclaration) {
  const glsl::Declarations d = glsl::global_declarations(kSample);
  EXPECT_EQ(d.macros, (Names{"OBJECT_MACRO", "function_macro", "ENGINE_OPTION", "OTHER_OPTION"}));
  EXPECT_EQ(d.types, (Names{"Record", "Pair"}));
  EXPECT_EQ(d.blocks, (Names{"NamedBlock", "AnonymousBlock"}));
  EXPECT_EQ(d.functions, (Names{"prototype", "definition"}));
  EXPECT_EQ(d.variables, (Names{"pair_variable", "block_instance", "anonymous_member", "a_sampler",
                                "kConstant", "SECOND_CONSTANT", "an_array"}));
}

TEST(GlslNamespace, PrefixesByTheNamesCase) {
  EXPECT_EQ(glsl::prefixed_name("MAX_LIGHTS"), "PENUMBRA_MAX_LIGHTS");
  EXPECT_EQ(glsl::prefixed_name("MSM_BIAS_32"), "PENUMBRA_MSM_BIAS_32");
  EXPECT_EQ(glsl::prefixed_name("GpuLight"), "PenumbraGpuLight");
  EXPECT_EQ(glsl::prefixed_name("shadow_pcf"), "penumbra_impl_shadow_pcf");
  EXPECT_EQ(glsl::prefixed_name("kR2Step"), "penumbra_impl_kR2Step");
  EXPECT_EQ(glsl::prefixed_name("penumbra_shadow"), "penumbra_shadow");
  EXPECT_EQ(glsl::prefixed_name("PenumbraShadowBlock"), "PenumbraShadowBlock");
  EXPECT_TRUE(glsl::has_namespace_prefix("PENUMBRA_SHADOW_DEPTH_UNIT"));
  EXPECT_FALSE(glsl::has_namespace_prefix("penumbra"));
}

TEST(GlslNamespace, RenamesDeclaredNamesNotMembersCommentsOrLocals) {
  const std::string out = glsl::prefix_declarations(kSample);
  // Declarations and their uses.
  for (const char* expected :
       {"#define PENUMBRA_OBJECT_MACRO 3",
        "#define penumbra_impl_function_macro(x) ((x) * PENUMBRA_OBJECT_MACRO)",
        "#ifdef PENUMBRA_ENGINE_OPTION", "#if defined(PENUMBRA_OTHER_OPTION) && GL_ES",
        "struct PenumbraRecord {", "float values[PENUMBRA_OBJECT_MACRO];",
        "struct PenumbraPair { int a, b; } penumbra_impl_pair_variable;",
        "uniform PenumbraNamedBlock {", "PenumbraRecord block_member;",
        "} penumbra_impl_block_instance;", "buffer PenumbraAnonymousBlock {",
        "vec2 penumbra_impl_anonymous_member[];", "uniform sampler2DArray penumbra_impl_a_sampler;",
        "const float penumbra_impl_kConstant = 0.5, PENUMBRA_SECOND_CONSTANT = 2.0;",
        "float penumbra_impl_prototype(PenumbraRecord r, in vec3 direction);",
        "out vec4 gl_out_like;",
        "float penumbra_impl_definition(PenumbraRecord r, in vec3 direction, out float result) {",
        // Members after '.', locals, parameters: as they were.
        "float local_value = r.member.x + penumbra_impl_block_instance.block_member.member.y;",
        "return penumbra_impl_prototype(r, direction) + penumbra_impl_kConstant;",
        // Comments are left alone.
        "vec4 member;              // a member, not a global"}) {
    EXPECT_NE(out.find(expected), std::string::npos) << expected << "\nin:\n" << out;
  }
  EXPECT_EQ(glsl::global_declarations(out).all().size(),
            glsl::global_declarations(kSample).all().size());
}

TEST(GlslNamespace, RefusesWhatItCannotRead) {
  // A new name that the text already uses.
  EXPECT_THROW(glsl::prefix_declarations("float f() { return 1.0; }\nfloat penumbra_impl_f;\n"),
               RuntimeError);
  // Statements it does not understand are errors, not leaks.
  EXPECT_THROW(glsl::global_declarations("float x = 1.0\n"), RuntimeError);
  EXPECT_THROW(glsl::global_declarations("= { 1 };\n"), RuntimeError);
  EXPECT_THROW(glsl::global_declarations("void f() {\n"), RuntimeError);
}

TEST(GlslNamespace, StripsTheCppHalfOfSharedHeaders) {
  const std::string out = glsl::strip_cplusplus_sections(
      "a\n#ifdef __cplusplus\nnamespace x {\n#if 1\ny\n#endif\n#else\nglsl\n#endif\n"
      "#ifndef __cplusplus\nkept\n#endif\n#ifdef OTHER\nz\n#endif\n");
  EXPECT_EQ(out, "a\n\n\n\n\n\n\nglsl\n\n\nkept\n\n#ifdef OTHER\nz\n#endif\n");
}

TEST(GlslNamespace, DropsTheMacrosNothingUses) {
  const std::string out = glsl::drop_unused_macros(
      "#ifndef GUARD_H\n#define GUARD_H\n#define UNUSED 1 // why\n#define ONLY_BY_UNUSED 2\n"
      "#define CHAIN (ONLY_BY_UNUSED + 1)\n#define USED 3\n#define LONG \\\n  4\n"
      "// USED, UNUSED in a comment\nint x = USED;\n\n"
      "// A paragraph about unused macros alone\n#define NOBODY 1\n#define NOR_THIS 2\n\n"
      "#endif\n");
  EXPECT_EQ(out,
            "#ifndef GUARD_H\n#define GUARD_H\n#define USED 3\n"
            "// USED, UNUSED in a comment\nint x = USED;\n\n#endif\n");
}

// The lookup as an engine gets it declares nothing outside the namespace
// but its entry points, whatever the shaders add later.
TEST(ShadowLookupGlsl, DeclaresNothingOutsideItsNamespace) {
  const std::string lookup = shadow_lookup_glsl();
  const glsl::Declarations declared = glsl::global_declarations(lookup);
  for (const std::string& name : declared.all()) {
    EXPECT_TRUE(glsl::has_namespace_prefix(name)) << name;
  }
  // Read with a second, plainer reader too: every #define, struct and
  // block name, and every function defined at the start of a line.
  const std::regex plain(
      R"((?:^|\n)\s*#\s*define\s+(\w+)|\bstruct\s+(\w+)|\b(?:uniform|buffer)\s+(\w+)\s*\{|\n\w+\s+(\w+)\s*\()");
  int count = 0;
  for (auto it = std::sregex_iterator(lookup.begin(), lookup.end(), plain);
       it != std::sregex_iterator(); ++it) {
    for (std::size_t group = 1; group < it->size(); ++group) {
      if ((*it)[group].matched) {
        ++count;
        EXPECT_TRUE(glsl::has_namespace_prefix((*it)[group].str())) << (*it)[group].str();
      }
    }
  }
  EXPECT_GT(count, 100);
  // The renderer's own bindings are not in it.
  EXPECT_EQ(lookup.find("PENUMBRA_UNIT_SHADOW_DEPTH"), std::string::npos);
  EXPECT_EQ(lookup.find("PENUMBRA_VIEW_FINAL"), std::string::npos);
  // Not vacuous: the shaders it is made of declare the names an engine
  // is likely to use, and the lookup has them prefixed.
  const glsl::Declarations source = glsl::global_declarations(
      glsl::strip_cplusplus_sections(gl::expand_shader_includes("shadow/penumbra_shadows.glsl")));
  for (const char* name : {"MAX_LIGHTS", "TECHNIQUE_PCF"}) {
    EXPECT_TRUE(source.macros.contains(name)) << name;
    EXPECT_TRUE(declared.macros.contains(glsl::prefixed_name(name))) << name;
  }
  for (const char* name : {"GpuLight", "GpuShadowBlock", "ShadowLookup"}) {
    EXPECT_TRUE(source.types.contains(name)) << name;
    EXPECT_TRUE(declared.types.contains(glsl::prefixed_name(name))) << name;
  }
  for (const char* name : {"shadow_bias", "cube_face", "shadow_pcf"}) {
    EXPECT_TRUE(source.functions.contains(name)) << name;
    EXPECT_TRUE(declared.functions.contains(glsl::prefixed_name(name))) << name;
  }
  EXPECT_TRUE(declared.blocks.contains("PenumbraPoissonSamples"));
  EXPECT_TRUE(declared.variables.contains("penumbra_impl_poisson_samples"));
  // The entry points, as documented.
  for (const char* entry :
       {"penumbra_shadow", "penumbra_shadow_at", "penumbra_shadow_hard", "penumbra_shadow_pcf",
        "penumbra_shadow_pcss", "penumbra_shadow_backprojection", "penumbra_shadow_vsm",
        "penumbra_shadow_esm", "penumbra_shadow_evsm2", "penumbra_shadow_evsm4",
        "penumbra_shadow_msm", "penumbra_shadow_msm16"}) {
    EXPECT_TRUE(declared.functions.contains(entry)) << entry;
  }
}

TEST(ShadowLookupGlsl, DeclaresTheBindingsItIsGiven) {
  const ShadowBindings moved{.block = 3,
                             .depth_unit = 2,
                             .filtered_unit = 5,
                             .compare_unit = 6,
                             .sat_unit = 9,
                             .poisson_buffer = 11};
  const std::string lookup = shadow_lookup_glsl(moved);
  for (const char* expected :
       {"#define PENUMBRA_SHADOW_BLOCK_BINDING 3\n", "#define PENUMBRA_SHADOW_DEPTH_UNIT 2\n",
        "#define PENUMBRA_SHADOW_FILTERED_UNIT 5\n", "#define PENUMBRA_SHADOW_COMPARE_UNIT 6\n",
        "#define PENUMBRA_SHADOW_SAT_UNIT 9\n", "#define PENUMBRA_POISSON_BINDING 11\n",
        "binding = PENUMBRA_SHADOW_BLOCK_BINDING) uniform PenumbraShadowBlock",
        "binding = PENUMBRA_SHADOW_DEPTH_UNIT) uniform sampler2DArray ",
        "binding = PENUMBRA_SHADOW_FILTERED_UNIT) uniform sampler2DArray ",
        "binding = PENUMBRA_SHADOW_COMPARE_UNIT) uniform sampler2DArrayShadow ",
        "binding = PENUMBRA_SHADOW_SAT_UNIT) uniform usampler2DArray ",
        "binding = PENUMBRA_POISSON_BINDING) readonly buffer "}) {
    EXPECT_NE(lookup.find(expected), std::string::npos) << expected;
  }
  // Each macro defined once (the poisson one's fallback is the renderer's).
  EXPECT_EQ(lookup.find("#define PENUMBRA_SHADOW_DEPTH_UNIT"),
            lookup.rfind("#define PENUMBRA_SHADOW_DEPTH_UNIT"));
  EXPECT_NE(shadow_lookup_glsl(), lookup);
  EXPECT_THROW(shadow_lookup_glsl(ShadowBindings{.filtered_unit = 15}), UsageError);
}

int line_count(const std::string& text) {
  return static_cast<int>(std::count(text.begin(), text.end(), '\n'));
}

TEST(ShadowLookupGlsl, CarriesLineDirectives) {
  const std::string lookup = shadow_lookup_glsl();
  // Ends in "#line 2": pasted after the engine's #version line, the
  // engine's next line is its line 2.
  EXPECT_TRUE(lookup.ends_with("\n#line 2\n"));
  // Inside, the driver's line numbers are the lookup's own: the one
  // #line before the text numbers the line after it as what it is.
  std::smatch first;
  ASSERT_TRUE(std::regex_search(lookup, first, std::regex(R"(\n#line (\d+)\n)")));
  const std::string before = lookup.substr(0, static_cast<std::size_t>(first.position(0)) + 1);
  EXPECT_EQ(std::stoi(first[1].str()), line_count(before) + 2);
}

TEST(ShadowLookupGlsl, InsertsAfterTheVersionAndExtensionsAndRestoresTheLines) {
  const std::string engine =
      "// engine shader\n#version 450 core\n#extension GL_ARB_gpu_shader5 : enable\n\n"
      "#extension GL_ARB_shader_ballot : enable\nconst int MAX_LIGHTS = 8;\nvoid main() {}\n";
  const std::string out = insert_shadow_lookup(engine);
  const std::string head =
      "// engine shader\n#version 450 core\n#extension GL_ARB_gpu_shader5 : enable\n\n"
      "#extension GL_ARB_shader_ballot : enable\n";
  ASSERT_TRUE(out.starts_with(head));
  const std::string lookup = shadow_lookup_glsl();
  const std::string body = lookup.substr(0, lookup.size() - std::string("#line 2\n").size());
  EXPECT_EQ(out, head + body + "#line 6\nconst int MAX_LIGHTS = 8;\nvoid main() {}\n");
  // The engine's configuration of the lookup stays before it.
  const std::string configured = insert_shadow_lookup(
      "#version 450 core\n#define PENUMBRA_NO_FRAGMENT_ENTRY_POINTS\n#define MINE 1\n");
  EXPECT_TRUE(configured.starts_with(
      "#version 450 core\n#define PENUMBRA_NO_FRAGMENT_ENTRY_POINTS\n" + body + "#line 3\n"))
      << configured.substr(0, 200);
  EXPECT_TRUE(configured.ends_with("#line 3\n#define MINE 1\n"));
  // No #version: nowhere to put it.
  EXPECT_THROW(insert_shadow_lookup("void main() {}\n"), UsageError);
  // A #version alone, without its newline.
  EXPECT_TRUE(insert_shadow_lookup("#version 450 core").ends_with("\n#line 2\n"));
}

}  // namespace
}  // namespace penumbra
