#include "penumbra/settings.hpp"

#include <cmath>
#include <sstream>
#include <string>

#include "penumbra/error.hpp"

namespace penumbra {

namespace {

template <class T>
void check_range(std::string_view name, T value, T min, T max) {
  bool ok = value >= min && value <= max;
  if constexpr (std::is_floating_point_v<T>) ok = ok && std::isfinite(value);
  if (!ok) {
    std::ostringstream msg;
    msg << "--" << name << " must be between " << min << " and " << max << " (got " << value << ")";
    throw UsageError(msg.str());
  }
}

template <class Owner, class Settings, class T, std::size_t N>
void check_ranges(const Owner& settings, const std::array<NumericParam<Settings, T>, N>& params) {
  for (const auto& p : params) check_range<T>(p.name, settings.*(p.field), p.min, p.max);
}

}  // namespace

void validate(const ShadowSettings& settings) {
  validate(static_cast<const ShadowMapSettings&>(settings));
  check_ranges(settings, kAccumulateParams);
  check_ranges(settings, kRendererShadowIntParams);
  check_ranges(settings, kRendererShadowFloatParams);
  for (const SourceSizeParam& p : kSourceSizeParams) {
    check_range<float>(p.name, settings.*(p.override_field), p.min, p.max);
  }
}

void validate(const Light& light) {
  for (const SourceSizeParam& p : kSourceSizeParams) {
    check_range<float>(p.name, light.*(p.light_field), p.min, p.max);
  }
}

void validate(const ShadowMapSettings& settings) {
  check_ranges(settings, kShadowFloatParams);
  check_ranges(settings, kShadowIntParams);
  if (settings.shadow_maps == ShadowMapKind::Virtual &&
      !supports_virtual_maps(settings.technique)) {
    throw UsageError(
        "--shadow-maps virtual needs --technique hard, pcf, pcss or backprojection: the "
        "moment techniques filter their maps as whole textures (blurred or summed across page "
        "borders), so they use --shadow-maps cascades");
  }
  if ((settings.shadow_msaa & (settings.shadow_msaa - 1)) != 0) {
    throw UsageError("--shadow-msaa must be 1, 2, 4 or 8 (got " +
                     std::to_string(settings.shadow_msaa) + ")");
  }
  if (settings.soft && !supports_soft_shadows(settings.technique, settings.filter)) {
    throw UsageError(
        "--soft needs --technique vsm, msm or msm16 with --filter sat (the penumbra-sized "
        "filter is read from the summed-area table)");
  }
  if (settings.technique == Technique::Esm && settings.filter == Filter::Sat && settings.blur > 0) {
    throw UsageError(
        "--technique esm cannot use --filter sat: exp(c*z) spans exp(-c) to 1 (1e-26 at c = 60), "
        "far beyond the 17 bits per texel a 32-bit summed-area table keeps; use --filter "
        "gaussian, or vsm/msm/msm16 with sat");
  }
  if ((settings.technique == Technique::Evsm2 || settings.technique == Technique::Evsm4) &&
      settings.filter == Filter::Sat && settings.blur > 0) {
    throw UsageError(
        "--technique evsm2/evsm4 cannot use --filter sat: exp(c u)^2 spans exp(-2c) to exp(2c) "
        "(1e-35 to 1e35 at c = 40), far beyond the 17 bits per texel a 32-bit summed-area table "
        "keeps; use --filter gaussian, or vsm/msm/msm16 with sat");
  }
}

void validate(const RenderSettings& settings) {
  check_ranges(settings, kRenderIntParams);
}

void validate(const SsaoSettings& settings) {
  check_ranges(settings, kSsaoIntParams);
  check_ranges(settings, kSsaoFloatParams);
}

void validate(const ReferenceSettings& settings) {
  check_ranges(settings, kReferenceIntParams);
}

}  // namespace penumbra
