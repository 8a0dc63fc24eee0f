// Sample points in the square kernel of PCSS's filter. A square light
// source whose sides run along the shadow map's axes (as penumbra.glsl and
// the traced reference model it) spreads a point's shadow over an
// axis-aligned square, so the kernel stays one: rotating the sample set
// per pixel, as PCF does, would turn the square and add an error of its
// own at the corners.
//
// The points are the R2 sequence (Roberts, "The Unreasonable Effectiveness
// of Quasirandom Sequences", 2018), the 2D Kronecker sequence of the
// plastic number phi_2 = 1.3247...: x_i = fract(1/2 + i (1/phi_2,
// 1/phi_2^2)). Every prefix of it is evenly spread over the square, so a
// sample count that follows the penumbra's size still covers the whole
// kernel. Each pixel shifts the set toroidally (a Cranley-Patterson
// rotation, which keeps the set's spacing) by a shift of its own.

const vec2 kR2Step = vec2(0.7548776662466927, 0.5698402909980532);

// The pixel's shift from its noise value in [0, 1): the R2 point of index
// floor(4096 noise). The R2 points are evenly spread, so pixels whose noise
// differs (interleaved gradient noise makes neighbours' differ) sample
// different parts of the kernel.
vec2 square_sample_shift(float noise) {
  return fract(floor(noise * 4096.0) * kR2Step);
}

// Point i of the set shifted by `shift`, in [-1, 1]^2.
vec2 square_sample(int i, vec2 shift) {
  return fract(0.5 + float(i) * kR2Step + shift) * 2.0 - 1.0;
}
