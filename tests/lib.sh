# Sourced by the shell tests: MPI environment, pass/fail bookkeeping, and a Python with
# h5py and numpy in $python (empty when there is none; tests then fall back to h5dump).
source "$(dirname "${BASH_SOURCE[0]}")/../scripts/mpi-env.sh"

fails=0
fail() { echo "FAIL: $*"; fails=$((fails + 1)); }
pass() { echo "ok:   $*"; }

python=""
for p in /usr/bin/python3 python3; do
  if command -v "$p" >/dev/null && "$p" -c "import h5py, numpy" 2>/dev/null; then python=$p; break; fi
done
