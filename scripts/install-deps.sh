#!/usr/bin/env bash
# Installs every Debian package Contessa needs (idempotent; quick when already installed).
# Run as root on Debian bookworm, or as a user with sudo. gmsh (the command line, for the user guide's worked
# examples that mesh a .geo) is the only one no test needs.
set -euo pipefail

packages=(
  build-essential cmake pkg-config git
  trilinos-all-dev libptscotch-dev
  libexodusii-dev libmetis-dev libmumps-dev libgmsh-dev libopenblas-dev
  libopenmpi-dev openmpi-bin libhdf5-openmpi-dev
  netcdf-bin python3-netcdf4 python3-matplotlib python3-numpy
  libgtest-dev googletest
  paraview python3-paraview xvfb xauth
  slurm-wlm munge
  calculix-ccx
  gmsh
)

missing=()
for p in "${packages[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed"; then
    missing+=("$p")
  fi
done

if [ ${#missing[@]} -eq 0 ]; then
  echo "install-deps: all ${#packages[@]} packages already installed"
  exit 0
fi

sudo_cmd=()
if [ "$(id -u)" -ne 0 ]; then sudo_cmd=(sudo); fi
echo "install-deps: installing ${missing[*]}"
export DEBIAN_FRONTEND=noninteractive
"${sudo_cmd[@]}" apt-get update -q
"${sudo_cmd[@]}" apt-get install -y -q --no-install-recommends "${missing[@]}"
