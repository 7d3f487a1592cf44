#!/usr/bin/env bash
# Installs the Debian 12 packages luxplan builds with. Idempotent: packages
# already present are skipped, so a second run does nothing and needs no network.
set -euo pipefail

packages=(
  build-essential cmake pkg-config
  libembree-dev libtbb-dev
  nlohmann-json3-dev libcli11-dev
  libtinyobjloader-dev libtinygltf-dev libstb-dev
  libgtest-dev libgmock-dev libbenchmark-dev
)

missing=()
for p in "${packages[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed"; then
    missing+=("$p")
  fi
done

if [ ${#missing[@]} -eq 0 ]; then
  echo "install-deps: all ${#packages[@]} packages present"
  exit 0
fi

echo "install-deps: installing ${missing[*]}"
sudo_cmd=()
if [ "$(id -u)" -ne 0 ]; then sudo_cmd=(sudo); fi
export DEBIAN_FRONTEND=noninteractive
"${sudo_cmd[@]}" apt-get update -qq
"${sudo_cmd[@]}" apt-get install -y -qq --no-install-recommends "${missing[@]}"
