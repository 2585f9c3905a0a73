#!/usr/bin/env bash
# Installs the Debian/Ubuntu packages the framework needs, if any are missing.
# As root it runs apt-get; with password-less sudo it uses sudo; otherwise it
# prints the exact command to run and stops with an error.
set -euo pipefail

packages=(g++ make cmake pkg-config libglm-dev libgtest-dev libstb-dev libcli11-dev nlohmann-json3-dev)

if ! command -v dpkg-query >/dev/null 2>&1; then
    echo "install-deps: this is not a Debian/Ubuntu system; install by hand: ${packages[*]} (C++20 compiler, CMake >= 3.22, GLM, GoogleTest, stb, CLI11, nlohmann-json)" >&2
    exit 0
fi

missing=()
for package in "${packages[@]}"; do
    if ! dpkg-query -W -f='${Status}' "$package" 2>/dev/null | grep -q "install ok installed"; then
        missing+=("$package")
    fi
done
[ ${#missing[@]} -eq 0 ] && exit 0

export DEBIAN_FRONTEND=noninteractive
if [ "$(id -u)" -eq 0 ]; then
    echo "install-deps: installing ${missing[*]}"
    apt-get update -qq
    apt-get install -y -qq --no-install-recommends "${missing[@]}"
elif command -v sudo >/dev/null 2>&1 && sudo -n true 2>/dev/null; then
    echo "install-deps: installing ${missing[*]} with sudo"
    sudo -E apt-get update -qq
    sudo -E apt-get install -y -qq --no-install-recommends "${missing[@]}"
else
    echo "install-deps: missing packages. Run this, then try again:" >&2
    echo "    sudo apt-get install -y ${missing[*]}" >&2
    exit 1
fi
