#!/usr/bin/env bash
# Installs what luxplan builds and tests with: Debian 12 packages (the C++ libraries,
# Chromium for the report's browser test and report.pdf, poppler-utils to read
# report.pdf back in the tests, DejaVu fonts for the plan's labels, Python for
# scripts/ and the Python module (pybind11, numpy, pytest, dask.distributed: python/,
# docs/python.md), Node.js and npm where they are missing), then the report viewer's and the
# glTF validator's npm packages (web/package-lock.json) into web/node_modules.
# Idempotent: what is already present is skipped, so a second run does nothing and
# needs no network.
set -euo pipefail
cd "$(dirname "$0")/.."

packages=(
  build-essential cmake pkg-config
  libembree-dev libtbb-dev
  nlohmann-json3-dev libcli11-dev
  libtinyobjloader-dev libtinygltf-dev libstb-dev
  libgtest-dev libgmock-dev libbenchmark-dev
  chromium poppler-utils
  fonts-dejavu-core
  python3
  pybind11-dev python3-dev python3-numpy python3-pytest python3-distributed
)
# Node.js may come from elsewhere than Debian (a newer release); only install Debian's
# when there is none.
if ! command -v npm > /dev/null; then packages+=(nodejs npm); fi

missing=()
for p in "${packages[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed"; then
    missing+=("$p")
  fi
done

if [ ${#missing[@]} -eq 0 ]; then
  echo "install-deps: all ${#packages[@]} packages present"
else
  echo "install-deps: installing ${missing[*]}"
  sudo_cmd=()
  if [ "$(id -u)" -ne 0 ]; then sudo_cmd=(sudo); fi
  export DEBIAN_FRONTEND=noninteractive
  "${sudo_cmd[@]}" apt-get update -qq
  "${sudo_cmd[@]}" apt-get install -y -qq --no-install-recommends "${missing[@]}"
fi

# The report's 3D viewer (three.js) and the glTF validator `make test` runs
# (gltf-validator, a dev dependency), exactly as web/package-lock.json pins them.
pinned() {  # whether web/node_modules holds the version of package $1 that web/package.json names
  local want
  want=$(sed -n "s/.*\"$1\": \"\(.*\)\".*/\1/p" web/package.json)
  [ -n "$want" ] && [ -f "web/node_modules/$1/package.json" ] &&
    grep -q "\"version\": \"$want\"" "web/node_modules/$1/package.json"
}
if ! pinned three || ! pinned gltf-validator; then
  echo "install-deps: npm ci (web/: the report viewer, the glTF validator)"
  npm ci --prefix web --no-audit --no-fund --loglevel=error
else
  echo "install-deps: web/node_modules up to date"
fi
