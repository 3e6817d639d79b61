#!/usr/bin/env bash
# Builds beamimpact (release preset), runs the default scene -- the ACOR sweep along the
# 1.1 m free beam, options/default.opts -- on all local cores, and plots it.
# Output: out/default.h5 and out/default.png. Rerunning resumes/skips finished points.
# Usage: scripts/run-default.sh [extra beamimpact options]   (installs missing Debian packages first)
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/setup-debian.sh
source scripts/mpi-env.sh
cmake --preset release >/dev/null
cmake --build --preset release -j "$(nproc)"
mkdir -p out
mpirun -n "$(nproc)" build/release/beamimpact -options_file options/default.opts -output out/default.h5 "$@"
scripts/plot_sweep.py out/default.h5 -o out/default.png
echo "plot: out/default.png"
