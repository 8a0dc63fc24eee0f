#pragma once
// The shadow core's settings: ShadowSettings (technique, map size, biases,
// filter, cascades; every field documented with its default), the
// technique and filter enums with their names, and the parameter tables
// that give each parameter its flag name, help text and range, so an
// engine's UI can offer them exactly as penumbra's own command line does.
// validate(const ShadowSettings&) throws UsageError naming the parameter
// out of range.
#include "core/settings.hpp"
