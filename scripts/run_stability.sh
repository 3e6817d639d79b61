#!/usr/bin/env bash
# The stability study (issue 5): every stiff and extreme case against every advertised
# integrator, each cell verified against a reference or a clear diagnosis; writes
# out/stability.h5 and docs/stability.md. See scripts/stability_matrix.py.
#
#   scripts/run_stability.sh [path/to/beamimpact] [stability_matrix.py options ...]
#   scripts/run_stability.sh build/dev/beamimpact --jobs 2 --cases k-1e+08,double
#
# Without an executable it uses build/release/beamimpact, else the first
# build/*/beamimpact (build one with: cmake --preset release && cmake --build --preset release).
# Takes about 15 minutes on 2 cores (the stiff grids with explicit RK dominate).
# Exit status: 0 when no cell is wrong.
set -euo pipefail

here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
root="$(dirname "$here")"
source "$here/find-exe.sh"
arg=""
if [[ $# -gt 0 && "$1" != -* ]]; then arg=$1; shift; fi
exe=$(find_beamimpact run_stability.sh "$arg") || exit 2

# Debian's python has numpy and h5py; the script re-executes itself with it otherwise.
python=python3
if [[ -x /usr/bin/python3 ]] && /usr/bin/python3 -c "import numpy, h5py" 2>/dev/null; then python=/usr/bin/python3; fi

source "$here/mpi-env.sh"
cd "$root"
echo "stability study with $exe"
exec "$python" "$here/stability_matrix.py" --exe "$exe" "$@"
