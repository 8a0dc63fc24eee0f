#pragma once
// The `penumbra render` command line that re-makes an image: the scene,
// every setting that differs from its default (read from the parameter
// tables, so new parameters appear by themselves), and the output.
#include <string>

#include "core/settings.hpp"

namespace penumbra {

std::string render_command_line(const std::string& scene, const RenderSettings& render,
                                const ShadowSettings& shadow, const std::string& output);

}  // namespace penumbra
