// Test kernel: evaluates the shadow-factor includes on a buffer of inputs,
// so that tests/gpu/moment_shader_test.cpp can compare them with the
// double-precision references in src/shadow/moment_math.cpp.
#include "../shadow/msm.glsl"
#include "../shadow/vsm.glsl"
#include "../shadow/esm.glsl"
#include "../shadow/evsm.glsl"

layout(local_size_x = 64) in;

// What each mode reads from a case (a, b, c) and writes to its result r.
#define MODE_MSM 0         // a: moments of u; b.xy: (u_f, alpha); c: bias vector
                           // r = msm_hamburger with (MSM_BIAS_32, MSM_BIAS_16, c), 0
#define MODE_VSM 1         // a.xy: moments; b: (z_f, min variance, bleed reduction)
                           // r.x = shadow_vsm
#define MODE_ESM 2         // b: (filtered, z_f, c); r = (shadow_esm, esm_encode(z_f, c), 0, 0)
#define MODE_QUANTIZE 3    // a: moments; r = msm_quantize(a)
#define MODE_DEQUANTIZE 4  // a: quantized; r = msm_dequantize(a)
#define MODE_BLEEDING 5    // b.xy: (lit, amount); r.x = reduce_light_bleeding
#define MODE_MSM_MIX 6     // a: relative depths (d1, d2), weight w of d1, receiver z_f;
                           // b.x: alpha. Two texels' 32-bit moments as the resolve
                           // makes them, mixed as a filter does: r.x = msm_intensity32
#define MODE_MSM16_MIX 7   // a, c: two RGBA16 texels; b.xyz: (weight w of a, z_f, alpha)
                           // r.x = msm_intensity16 of their mixture, dequantized
#define MODE_MSM_BLOCKER 8 // a: moments of u; b.xy: (u_f, alpha)
                           // r.xy = msm_blocker_search with MSM_BIAS_32
#define MODE_EVSM 9        // a: relative depths (d1, d2), weight w of d1, receiver z_f;
                           // b.xyz: (c+, c-, min variance). Two texels' warped moments
                           // mixed as a filter does: r.xy = (shadow_evsm2, shadow_evsm4)

struct Case {
  vec4 a;
  vec4 b;
  vec4 c;
};

layout(std430, binding = 0) readonly buffer Cases { Case cases[]; };
layout(std430, binding = 1) writeonly buffer Results { vec4 results[]; };

layout(location = 0) uniform int mode;
layout(location = 1) uniform uint count;

void main() {
  uint i = gl_GlobalInvocationID.x;
  if (i >= count) return;
  Case k = cases[i];
  vec4 r = vec4(0.0);
  switch (mode) {
    case MODE_MSM:
      r.x = msm_hamburger(k.a, k.b.x, k.b.y, MSM_BIAS_32);
      r.y = msm_hamburger(k.a, k.b.x, k.b.y, MSM_BIAS_16);
      r.z = msm_hamburger(k.a, k.b.x, k.b.y, k.c);
      break;
    case MODE_VSM:
      r.x = shadow_vsm(k.a.xy, k.b.x, k.b.y, k.b.z);
      break;
    case MODE_ESM:
      r.x = shadow_esm(k.b.x, k.b.y, k.b.z);
      r.y = esm_encode(k.b.y, k.b.z);
      break;
    case MODE_QUANTIZE:
      r = msm_quantize(k.a);
      break;
    case MODE_DEQUANTIZE:
      r = msm_dequantize(k.a);
      break;
    case MODE_BLEEDING:
      r.x = reduce_light_bleeding(k.b.x, k.b.y);
      break;
    case MODE_MSM_MIX:
      r.x = msm_intensity32(k.a.z * msm_moments(k.a.x) + (1.0 - k.a.z) * msm_moments(k.a.y),
                            k.a.w, k.b.x);
      break;
    case MODE_MSM16_MIX:
      r.x = msm_intensity16(msm_dequantize(k.b.x * k.a + (1.0 - k.b.x) * k.c), k.b.y, k.b.z);
      break;
    case MODE_MSM_BLOCKER:
      r.xy = msm_blocker_search(k.a, k.b.x, k.b.y, MSM_BIAS_32);
      break;
    case MODE_EVSM: {
      vec2 w1 = evsm_warp(k.a.x, k.b.x, k.b.y), w2 = evsm_warp(k.a.y, k.b.x, k.b.y);
      vec4 m = k.a.z * vec4(w1.x, w1.x * w1.x, w1.y, w1.y * w1.y) +
               (1.0 - k.a.z) * vec4(w2.x, w2.x * w2.x, w2.y, w2.y * w2.y);
      r.x = shadow_evsm2(m.xy, k.a.w, k.b.x, k.b.z);
      r.y = shadow_evsm4(m, k.a.w, k.b.x, k.b.y, k.b.z);
      break;
    }
  }
  results[i] = r;
}
