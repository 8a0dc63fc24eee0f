#pragma once
// penumbra's shadow core, the high-level API: ShadowMaps and everything it
// takes and gives (see docs/library.md). Link penumbra::shadows. The
// low-level building blocks (penumbra/gl/, penumbra/shadow/,
// penumbra/filter/) are included one by one by those who need them.
#include "error.hpp"
#include "light.hpp"
#include "position_span.hpp"
#include "settings.hpp"
#include "shadow_block.hpp"
#include "shadow_maps.hpp"
// Generated into the build's include root, installed beside this header.
#include "penumbra/version.hpp"
