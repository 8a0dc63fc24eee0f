#!/usr/bin/env bash
# Installs the shadow core from the build tree into a fresh prefix, builds
# examples/embed against that prefix alone (find_package(penumbra)), and
# renders its scene headless into WORK/images.
# Usage: embed_example.sh BUILD_DIR SOURCE_DIR WORK_DIR [COMPILER_LAUNCHER]
set -euo pipefail
build=$1 source=$2 work=$3 launcher=${4:-}
rm -rf "$work"
mkdir -p "$work/images"
# Only the core's component: no renderer, tool or their dependencies.
cmake --install "$build" --prefix "$work/prefix" --component shadows >"$work/install.log"
cmake -S "$source/examples/embed" -B "$work/build" -DCMAKE_BUILD_TYPE=Release \
  -DCMAKE_PREFIX_PATH="$work/prefix" -DCMAKE_FIND_PACKAGE_NO_PACKAGE_REGISTRY=ON \
  ${launcher:+-DCMAKE_CXX_COMPILER_LAUNCHER=$launcher} >"$work/configure.log"
cmake --build "$work/build" -j2 >"$work/build.log"
# The same prefix through pkg-config: a program that includes every public
# header and prints the lookup's GLSL (no GL context needed).
cat >"$work/lookup.cpp" <<'CPP'
#include <penumbra/penumbra.hpp>
#include <iostream>
int main() { std::cout << penumbra::shadow_lookup_glsl(); }
CPP
export PKG_CONFIG_PATH="$(dirname "$(find "$work/prefix" -name penumbra-shadows.pc)")"
${launcher} c++ -std=c++20 "$work/lookup.cpp" -o "$work/lookup" \
  $(pkg-config --cflags --libs penumbra-shadows)
# (Into a file first: `lookup | grep -q` fails at random under pipefail when
# grep exits before the program has written everything.)
"$work/lookup" >"$work/lookup.glsl"
grep -q "float penumbra_shadow(int light, vec3 world_position, vec3 world_normal)" "$work/lookup.glsl"
cmp "$work/lookup.glsl" "$work/prefix/share/penumbra/penumbra_shadows.glsl"
# Every installed header, both levels, compiles on its own against the
# prefix alone: none needs a private header of the source tree or another
# header included before it.
headers=$(cd "$work/prefix/include" && find penumbra -name '*.hpp' -o -name '*.h' | sort)
[ "$(echo "$headers" | wc -l)" -ge 30 ] || { echo "too few installed headers: $headers"; exit 1; }
for header in $headers; do
  echo "#include <$header>" >"$work/header.cpp"
  c++ -std=c++20 -fsyntax-only "$work/header.cpp" $(pkg-config --cflags penumbra-shadows) ||
    { echo "installed $header does not compile on its own"; exit 1; }
done

# The example again, built through pkg-config alone (penumbra-shadows and
# the engine's own GLEW and EGL): its loader is not penumbra's.
${launcher} c++ -std=c++20 -O2 "$source"/examples/embed/*.cpp -o "$work/embed-pkg-config" \
  $(pkg-config --cflags --libs penumbra-shadows glew egl)

embed=$work/build/embed
common=(--headless --width 320 --height 180 --map-size 512 --view shadow)
"$embed" "${common[@]}" --lights spot \
  --technique hard,pcf,pcss,backprojection,vsm,esm,evsm2,evsm4,msm,msm16 -o "$work/images/spot.png"
"$work/embed-pkg-config" "${common[@]}" --lights spot --technique pcf -o "$work/pkg-config-pcf.png"
cmp "$work/pkg-config-pcf.png" "$work/images/spot-pcf.png"
"$embed" "${common[@]}" --lights sun --technique pcf,pcss,vsm -o "$work/images/sun.png"
"$embed" "${common[@]}" --lights spot --filter sat --technique vsm,msm,msm16 \
  -o "$work/images/spot-sat.png"
"$embed" "${common[@]}" --lights spot --filter sat --soft --technique vsm,msm \
  -o "$work/images/spot-soft.png"
"$embed" --headless --width 320 --height 180 --map-size 512 --technique msm \
  -o "$work/images/final.png"
