#!/usr/bin/env bash
# Installs exactly the Debian 12 packages simcap builds against; skips apt when all are present.
# --fuzz adds clang and its libFuzzer runtime, which only `make fuzz` needs.
set -euo pipefail

# slurmctld, slurmd, slurm-client, munge: the one-node cluster scripts/slurm_local.sh starts as
# the user in a folder of its own (for --submit on a workstation and tests/collect's Slurm test);
# the packages' services are not used.
# openimageio-tools: Debian's OpenImageIOConfig.cmake imports its programs (/usr/bin/iconvert),
# so find_package(OpenImageIO) fails without them, and libopenimageio-dev only recommends them.
packages=(
  build-essential cmake ninja-build pkg-config ccache
  libembree-dev libopenimageio-dev libassimp-dev libeigen3-dev libopencv-dev
  liburdfdom-dev liburdfdom-tools libtbb-dev libyaml-cpp-dev nlohmann-json3-dev
  libpugixml-dev libcli11-dev googletest libgtest-dev libbenchmark-dev libpng-dev
  openimageio-tools
  slurmctld slurmd slurm-client munge
)
if [ "${1:-}" = "--fuzz" ]; then
  packages+=(clang-14 libclang-rt-14-dev)
fi

missing=()
for p in "${packages[@]}"; do
  status=$(dpkg-query -W -f='${db:Status-Status}' "$p" 2>/dev/null || true)
  [ "$status" = "installed" ] || missing+=("$p")
done

if [ ${#missing[@]} -eq 0 ]; then
  exit 0
fi

echo "setup: installing ${#missing[@]} missing package(s): ${missing[*]}" >&2
if [ "$(id -u)" -ne 0 ]; then
  sudo=sudo
else
  sudo=
fi
export DEBIAN_FRONTEND=noninteractive
$sudo apt-get update -qq
$sudo apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
echo "setup: done" >&2
