#pragma once
// penumbra's shadow core: everything an engine includes (see
// docs/library.md). Link penumbra::shadows.
#include "error.hpp"
#include "light.hpp"
#include "position_span.hpp"
#include "settings.hpp"
#include "shadow_block.hpp"
#include "shadow_maps.hpp"
#include "version.hpp"
