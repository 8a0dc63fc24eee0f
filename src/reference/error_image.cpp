#include "reference/error_image.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

#include "penumbra/error.hpp"

namespace penumbra {

namespace {

// Colour conversions of Moreland 2009, Section 6: sRGB (D65 white) through
// CIE XYZ to CIELAB, and CIELAB in polar form, Msh: M = |Lab|, s = angle
// from the L axis (saturation), h = hue angle.
constexpr glm::dvec3 kWhite{0.9505, 1.0, 1.089};

double srgb_to_linear(double c) {
  return c <= 0.04045 ? c / 12.92 : std::pow((c + 0.055) / 1.055, 2.4);
}

double linear_to_srgb(double c) {
  c = std::clamp(c, 0.0, 1.0);
  return c <= 0.0031308 ? 12.92 * c : 1.055 * std::pow(c, 1.0 / 2.4) - 0.055;
}

double lab_f(double t) {
  return t > 0.008856 ? std::cbrt(t) : 7.787 * t + 16.0 / 116.0;
}

double lab_f_inverse(double f) {
  const double t = f * f * f;
  return t > 0.008856 ? t : (f - 16.0 / 116.0) / 7.787;
}

glm::dvec3 srgb_to_msh(const glm::dvec3& srgb) {
  const glm::dvec3 rgb(srgb_to_linear(srgb.r), srgb_to_linear(srgb.g), srgb_to_linear(srgb.b));
  const glm::dvec3 xyz(0.4124 * rgb.r + 0.3576 * rgb.g + 0.1805 * rgb.b,
                       0.2126 * rgb.r + 0.7152 * rgb.g + 0.0722 * rgb.b,
                       0.0193 * rgb.r + 0.1192 * rgb.g + 0.9505 * rgb.b);
  const double fx = lab_f(xyz.x / kWhite.x), fy = lab_f(xyz.y / kWhite.y),
               fz = lab_f(xyz.z / kWhite.z);
  const double l = 116.0 * fy - 16.0, a = 500.0 * (fx - fy), b = 200.0 * (fy - fz);
  const double m = std::sqrt(l * l + a * a + b * b);
  return {m, std::acos(l / m), std::atan2(b, a)};
}

glm::dvec3 msh_to_srgb(const glm::dvec3& msh) {
  const double l = msh.x * std::cos(msh.y);
  const double a = msh.x * std::sin(msh.y) * std::cos(msh.z);
  const double b = msh.x * std::sin(msh.y) * std::sin(msh.z);
  const double fy = (l + 16.0) / 116.0, fx = fy + a / 500.0, fz = fy - b / 200.0;
  const glm::dvec3 xyz(kWhite.x * lab_f_inverse(fx), kWhite.y * lab_f_inverse(fy),
                       kWhite.z * lab_f_inverse(fz));
  const glm::dvec3 rgb(3.2406 * xyz.x - 1.5372 * xyz.y - 0.4986 * xyz.z,
                       -0.9689 * xyz.x + 1.8758 * xyz.y + 0.0415 * xyz.z,
                       0.0557 * xyz.x - 0.2040 * xyz.y + 1.0570 * xyz.z);
  return {linear_to_srgb(rgb.r), linear_to_srgb(rgb.g), linear_to_srgb(rgb.b)};
}

// Moreland 2009, "AdjustHue": when one end is unsaturated, give it a hue
// that spins away from the saturated end's, so the interpolation does not
// pass through a distracting hue.
double adjust_hue(const glm::dvec3& msh, double unsaturated_m) {
  if (msh.x >= unsaturated_m) return msh.z;
  const double spin =
      msh.y * std::sqrt(unsaturated_m * unsaturated_m - msh.x * msh.x) / (msh.x * std::sin(msh.y));
  return msh.z > -std::numbers::pi / 3.0 ? msh.z + spin : msh.z - spin;
}

// Moreland 2009, "InterpolateColor", for the map's two end colours, whose
// hues differ by more than 60 degrees: through white (s = 0) at the
// middle, at M = max(M1, M2, 88).
glm::dvec3 interpolate(const glm::dvec3& srgb1, const glm::dvec3& srgb2, double u) {
  glm::dvec3 a = srgb_to_msh(srgb1), b = srgb_to_msh(srgb2);
  const double middle = std::max({a.x, b.x, 88.0});
  if (u < 0.5) {
    b = {middle, 0.0, 0.0};
    u = 2.0 * u;
  } else {
    a = {middle, 0.0, 0.0};
    u = 2.0 * u - 1.0;
  }
  if (a.y < 0.05 && b.y > 0.05) a.z = adjust_hue(b, a.x);
  if (b.y < 0.05 && a.y > 0.05) b.z = adjust_hue(a, b.x);
  return msh_to_srgb((1.0 - u) * a + u * b);
}

}  // namespace

glm::vec3 diverging_color(float t) {
  const glm::dvec3 cool = glm::dvec3(59.0, 76.0, 192.0) / 255.0;
  const glm::dvec3 warm = glm::dvec3(180.0, 4.0, 38.0) / 255.0;
  const double u = 0.5 * (std::clamp(static_cast<double>(t), -1.0, 1.0) + 1.0);
  return glm::vec3(interpolate(cool, warm, u));
}

Image error_image(const Image& technique, const Image& reference, float range) {
  if (technique.width != reference.width || technique.height != reference.height) {
    throw RuntimeError("images to compare differ in size");
  }
  // The map is smooth: a table of 513 colours, read with linear
  // interpolation, is exact to well under an 8-bit step and saves the
  // conversions per pixel.
  constexpr int kSteps = 512;
  std::vector<glm::vec3> table(kSteps + 1);
  for (int i = 0; i <= kSteps; ++i) table[i] = diverging_color(2.0f * i / kSteps - 1.0f);
  Image out(technique.width, technique.height);
  for (int y = 0; y < out.height; ++y) {
    for (int x = 0; x < out.width; ++x) {
      const float* t = technique.pixel(x, y);
      const float* r = reference.pixel(x, y);
      float* o = out.pixel(x, y);
      if (t[3] < 0.5f || r[3] < 0.5f) {
        o[0] = o[1] = o[2] = kErrorImageBackground;
        o[3] = 0.0f;
        continue;
      }
      float error = (t[0] - r[0]) / range;
      if (!std::isfinite(error)) error = 1.0f;  // a NaN shows as the worst error
      const float u = std::clamp(0.5f * (error + 1.0f), 0.0f, 1.0f) * kSteps;
      const int i = std::min(static_cast<int>(u), kSteps - 1);
      const glm::vec3 c = glm::mix(table[i], table[i + 1], u - static_cast<float>(i));
      o[0] = c.r;
      o[1] = c.g;
      o[2] = c.b;
      o[3] = 1.0f;
    }
  }
  return out;
}

}  // namespace penumbra
