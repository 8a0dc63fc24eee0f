#pragma once
// --light spot|directional|point: the scene lit by one light of that type
// alone, for quick comparisons of the light types on the same scene.
#include <CLI/CLI.hpp>
#include <string>

#include "scene/scene.hpp"

namespace penumbra {

// Registers --light; `choice` stays empty when it is not given.
void add_light_choice_option(CLI::App& app, std::string& choice);

// The scene's own first light of that type if it has one; otherwise one
// made from its first light: a spot or point light where its first
// positional light is (or, with only directional lights, as far from the
// scene's centre as the scene is wide, against the light's direction),
// aimed at the centre. Either way its intensity is set so that it gives
// the scene's centre the irradiance of the scene's key light (the light
// that gives the centre the most), so the types compare at equal exposure.
Light single_light(const Scene& scene, LightType type);

// Replaces the scene's lights with single_light() of the named type; no
// change for an empty choice. Throws UsageError for an unknown name or a
// scene without lights.
void apply_light_choice(const std::string& choice, Scene& scene);

// Throws UsageError when --light-index names a light the scene (after
// --light) does not have, whatever the view.
void check_light_index(int light_index, const Scene& scene);

}  // namespace penumbra
