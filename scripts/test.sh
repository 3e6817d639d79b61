#!/usr/bin/env bash
# Builds beamimpact with the dev preset (warnings as errors) and runs the whole test suite.
# Usage: scripts/test.sh [extra ctest arguments]      (installs missing Debian packages first)
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/setup-debian.sh
source scripts/mpi-env.sh
cmake --preset dev >/dev/null
cmake --build --preset dev -j "$(nproc)"
ctest --preset dev "$@"
