#!/usr/bin/env bash
# Builds beamimpact (release preset) and runs the default scene on all local cores.
# Usage: scripts/run-default.sh [extra beamimpact options]   (installs missing Debian packages first)
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/setup-debian.sh
source scripts/mpi-env.sh
cmake --preset release >/dev/null
cmake --build --preset release -j "$(nproc)"
mkdir -p out
mpirun -n "$(nproc)" build/release/beamimpact -options_file options/default.opts -output out/default.h5 "$@"
