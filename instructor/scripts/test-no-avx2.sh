#!/usr/bin/env bash
# CI: the renderer on a CPU without AVX2 draws the very images it draws here.
# The BVH walks run a copy compiled for AVX2 only where the CPU has it
# (whitted/engine/wide_bvh.hpp); elsewhere the SSE2 walk must run, and give the
# same answers. qemu-user emulates a Nehalem (SSE4.2, no AVX): an AVX2
# instruction reached there stops the program (SIGILL), a wrong answer shows in
# the image. Renders of every primitive kind, natively (2 threads) and emulated
# (1 thread), must be byte-identical.
set -euo pipefail
cd "$(dirname "$0")/../.."
BUILD_DIR=${BUILD_DIR:-build}
bin=$BUILD_DIR/whitted
test -x "$bin" || { echo "test-no-avx2: $bin is missing: run make test first"; exit 1; }
command -v qemu-x86_64 > /dev/null || { echo "test-no-avx2: qemu-x86_64 is missing (apt-get install qemu-user)"; exit 1; }
emulated() { qemu-x86_64 -cpu Nehalem "$@"; }

# The emulated CPU must be one without AVX2, and whitted must know it.
emulated "$bin" --version | grep -q "box tests in SSE2" \
  || { echo "test-no-avx2: under qemu -cpu Nehalem, whitted --version does not say SSE2: $(emulated "$bin" --version)"; exit 1; }
native=$("$bin" --version)
echo "native: $native"

out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
"$bin" generate sphereflake --level 3 -o "$out/flake3.nff"
"$bin" generate tetra --level 4 -o "$out/tetra4.nff"
"$bin" generate soup --level 2 -o "$out/soup2.nff"
"$bin" generate torus --level 3 -o "$out/torus3.p3f"
scenes=("$out/flake3.nff" "$out/tetra4.nff" "$out/soup2.nff" "$out/torus3.p3f" scenes/whitted_1980.p3f scenes/course_features.p3f)
for scene in "${scenes[@]}"; do
  name=$(basename "$scene")
  "$bin" render "$scene" --width 96 --height 96 --threads 2 -q -o "$out/$name.native.pfm"
  emulated "$bin" render "$scene" --width 96 --height 96 --threads 1 -q -o "$out/$name.emulated.pfm" \
    || { echo "test-no-avx2: $name: the render failed on the emulated CPU"; exit 1; }
  cmp -s "$out/$name.native.pfm" "$out/$name.emulated.pfm" \
    || { echo "test-no-avx2: $name: the image on a CPU without AVX2 differs from this CPU's"; exit 1; }
  echo "same image without AVX2: $name"
done
echo "no-avx2: ${#scenes[@]} scenes render byte-identical on an emulated CPU without AVX2"
