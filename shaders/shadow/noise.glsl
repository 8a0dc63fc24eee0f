// Interleaved gradient noise (Jimenez, "Next Generation Post Processing in
// Call of Duty: Advanced Warfare", SIGGRAPH 2014): a per-pixel value in
// [0, 1) that depends only on the pixel, so images are reproducible, and
// whose neighbours differ enough to turn banding into fine noise.
float interleaved_gradient_noise(vec2 pixel) {
  return fract(52.9829189 * fract(dot(pixel, vec2(0.06711056, 0.00583715))));
}
