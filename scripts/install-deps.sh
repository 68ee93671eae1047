#!/usr/bin/env bash
# Installs the Debian packages the build, the tests and the headless renderer need; a no-op when all are present.
# --fuzz adds what the fuzz build needs (clang and libFuzzer, see fuzz/README.md), which nothing else uses.
set -euo pipefail

packages=(
  build-essential cmake pkg-config
  libglfw3-dev libimgui-dev libglm-dev python3-glad libstb-dev libtinygltf-dev nlohmann-json3-dev
  doctest-dev libtinyexr-dev libwebp-dev libmeshoptimizer-dev libdraco-dev python3-matplotlib
  libegl-dev libgl-dev libegl-mesa0 libgl1-mesa-dri
  xvfb xauth parallel
)
if [[ "${1:-}" == "--fuzz" ]]; then
  packages+=(clang-14 libfuzzer-14-dev)
fi

missing=()
for p in "${packages[@]}"; do
  status=$(dpkg-query -W -f='${Status}' "$p" 2>/dev/null || true)
  [[ "$status" == "install ok installed" ]] || missing+=("$p")
done

if ((${#missing[@]} == 0)); then
  exit 0
fi

echo "install-deps: installing ${missing[*]}" >&2
sudo=()
if [[ $(id -u) -ne 0 ]]; then
  sudo=(sudo)
fi
export DEBIAN_FRONTEND=noninteractive
"${sudo[@]}" apt-get update -q
"${sudo[@]}" apt-get install -y -q --no-install-recommends "${missing[@]}"
