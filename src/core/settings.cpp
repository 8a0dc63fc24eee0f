#include "penumbra/settings.hpp"

#include <cmath>
#include <sstream>
#include <string>

#include "penumbra/error.hpp"

namespace penumbra {

namespace {

template <class Settings, class T, std::size_t N>
void check_ranges(const Settings& settings,
                  const std::array<NumericParam<Settings, T>, N>& params) {
  for (const auto& p : params) {
    const T value = settings.*(p.field);
    bool ok = value >= p.min && value <= p.max;
    if constexpr (std::is_floating_point_v<T>) ok = ok && std::isfinite(value);
    if (!ok) {
      std::ostringstream msg;
      msg << "--" << p.name << " must be between " << p.min << " and " << p.max << " (got " << value
          << ")";
      throw UsageError(msg.str());
    }
  }
}

}  // namespace

void validate(const ShadowSettings& settings) {
  check_ranges(settings, kShadowFloatParams);
  check_ranges(settings, kShadowIntParams);
  check_ranges(settings, kAccumulateParams);
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
