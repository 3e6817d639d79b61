#!/usr/bin/env bash
# Installs the Debian 12 packages beamimpact needs, as root or with sudo.
# Safe to run again: it installs only what is missing (no apt-get update otherwise).
# libopenblas0: Debian's optimised BLAS/LAPACK, chosen by update-alternatives over the reference
# libblas3/liblapack3 that PETSc links (the dense decompositions of the modal engine: README, "Performance").
set -euo pipefail
pkgs=(cmake g++ make pkg-config
      libpetsc-real-dev libslepc-real-dev libhdf5-openmpi-dev libopenmpi-dev openmpi-bin
      liblapack-dev libopenblas0 libgsl-dev libgtest-dev hdf5-tools python3-numpy python3-matplotlib python3-h5py
      python3-scipy  # scipy: only the independent references in scripts/references/
      python3-xarray python3-h5netcdf)  # the results files as xarray datasets (tests/fields.sh)
missing=()
for p in "${pkgs[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -eq 0 ]; then
  echo "setup: all Debian packages present"
  exit 0
fi
SUDO=""
if [ "$(id -u)" -ne 0 ]; then
  command -v sudo >/dev/null || { echo "setup: need root or sudo to install: ${missing[*]}" >&2; exit 1; }
  SUDO=sudo
fi
echo "setup: installing ${missing[*]}"
$SUDO apt-get update -qq
DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}"
