#include "viewer/panel_relevance.hpp"

#include <algorithm>

namespace penumbra {

namespace {

bool has_light(const std::vector<Light>& lights, LightType type) {
  return std::any_of(lights.begin(), lights.end(),
                     [type](const Light& l) { return l.type == type; });
}

}  // namespace

bool parameter_applies(std::string_view name, const ShadowSettings& shadow,
                       const SsaoSettings& ssao, const std::vector<Light>& lights) {
  const Technique t = shadow.technique;
  const bool shadowed = t != Technique::None;
  const bool moments = t == Technique::Msm || t == Technique::Msm16;
  // The source size matters where a technique or --soft makes a penumbra.
  const bool sized_source = t == Technique::Pcss || t == Technique::Backprojection || shadow.soft;
  const bool positional = has_light(lights, LightType::Spot) || has_light(lights, LightType::Point);
  const bool directional = has_light(lights, LightType::Directional);

  if (name == "shadow-map-size" || name == "constant-bias" || name == "slope-bias" ||
      name == "max-slope" || name == "normal-offset") {
    return shadowed;
  }
  if (name == "filter" || name == "blur" || name == "filter-slope-bias" || name == "shadow-msaa") {
    return is_filterable(t);
  }
  if (name == "pcf-width" || name == "pcf-samples") return t == Technique::Pcf;
  if (name == "pcss-blocker-samples" || name == "pcss-filter-samples")
    return t == Technique::Pcss || t == Technique::Backprojection;
  if (name == "backprojection-cells") return t == Technique::Backprojection;
  if (name == "esm-c") return t == Technique::Esm;
  const bool evsm = t == Technique::Evsm2 || t == Technique::Evsm4;
  if (name == "evsm-positive") return evsm;
  if (name == "evsm-negative") return t == Technique::Evsm4;
  if (name == "fused" || name == "shadow-mips") {
    return is_filterable(t) && shadow.filter == Filter::Gaussian;
  }
  if (name == "shadow-anisotropy") {
    return is_filterable(t) && shadow.filter == Filter::Gaussian && shadow.shadow_mips;
  }
  if (name == "vsm-min-variance") return t == Technique::Vsm || evsm;
  // 32-bit float moments are biased by msm-alpha; 16-bit ones and those
  // summed in the fixed-point summed-area table by msm16-alpha.
  if (name == "msm-alpha") return t == Technique::Msm && shadow.filter != Filter::Sat;
  if (name == "msm16-alpha")
    return t == Technique::Msm16 || (moments && shadow.filter == Filter::Sat);
  if (name == "bleed-reduction") return t == Technique::Vsm || moments || evsm;
  if (name == "soft") return supports_soft_shadows(t, shadow.filter);
  if (name == "soft-two-moment-blockers") return moments && shadow.soft;
  if (name == "light-size") return sized_source && positional;
  if (name == "sun-angle") return sized_source && directional;
  if (name == "cascades" || name == "cascade-lambda" || name == "cascade-blend" ||
      name == "tight-cascades") {
    return shadowed && directional;
  }
  if (name == "guard-band") return shadowed && has_light(lights, LightType::Point);
  if (name.rfind("contact-shadow-", 0) == 0) return shadow.contact_shadows;
  if (name != "ssao" && name.rfind("ssao", 0) == 0) return ssao.enabled;
  return true;
}

}  // namespace penumbra
