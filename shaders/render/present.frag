// Shows a view's texture in a window with the encoding read_view() and the
// PNG writer apply (see ViewEncoding in render/renderer.hpp), so the window
// shows what `penumbra render` writes.
#include "../shared/bindings.h"
#include "../shadow/msm.glsl"

in vec2 v_uv;
layout(location = 0) out vec4 out_color;

layout(binding = UNIT_PRESENT_SOURCE) uniform sampler2D source;
layout(location = 0) uniform int encoding;
layout(location = 1) uniform float log_scale;
layout(location = 2) uniform float log_offset;

float srgb_encode(float linear) {
  linear = clamp(linear, 0.0, 1.0);
  return linear <= 0.0031308 ? 12.92 * linear : 1.055 * pow(linear, 1.0 / 2.4) - 0.055;
}

void main() {
  vec3 value = texture(source, v_uv).rgb;
  if (encoding == VIEW_ENCODING_DEPTH) {
    value = vec3(value.r);
  } else if (encoding == VIEW_ENCODING_LOG_DEPTH) {
    value = vec3(value.r > 0.0 ? log(value.r) * log_scale + log_offset : 0.0);
  } else if (encoding == VIEW_ENCODING_SIGNED_MOMENTS) {
    value = msm_moments_from_signed(texture(source, v_uv)).rgb;
  }
  // The PNG writer stores non-finite values as 0.
  for (int c = 0; c < 3; ++c) {
    if (isnan(value[c]) || isinf(value[c])) value[c] = 0.0;
  }
  if (encoding == VIEW_ENCODING_LINEAR_COLOR) {
    value = vec3(srgb_encode(value.r), srgb_encode(value.g), srgb_encode(value.b));
  }
  out_color = vec4(clamp(value, 0.0, 1.0), 1.0);
}
