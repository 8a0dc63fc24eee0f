#pragma once
// Which parameters apply to what is shown: the panel offers only those
// (pcf's samples while pcf is selected, ESM's c while esm is, cascades
// while a directional light casts shadows), so that what it lists changes
// the image.
#include <string_view>
#include <vector>

#include "penumbra/settings.hpp"
#include "scene/scene.hpp"

namespace penumbra {

// Whether the parameter named `name` (a flag name of the settings tables,
// without "--") changes the frame for these settings and lights. Unknown
// names apply (a new parameter is shown until it is told otherwise).
bool parameter_applies(std::string_view name, const ShadowSettings& shadow,
                       const SsaoSettings& ssao, const std::vector<Light>& lights);

}  // namespace penumbra
