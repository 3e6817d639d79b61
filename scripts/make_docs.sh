#!/usr/bin/env bash
# Rewrites the references generated from the program's tables: docs/options.md (every option's
# row: beamimpact -help_markdown options) and docs/results.md (every task's results columns:
# beamimpact -help_markdown results). Run it after changing an option row or a results column,
# or after a merge that added some; the CTest test docs_generated fails until it is run.
#
#   scripts/make_docs.sh [EXE] [DIR]
#   cmake --build --preset dev --target docs     # the same, the executable built first
#
# EXE: the executable (default build/dev/beamimpact); DIR: where to write (default the
# repository's docs/; the test docs_generated writes into its build directory and compares).
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
exe=${1:-$root/build/dev/beamimpact}
dir=${2:-$root/docs}
[[ -x $exe ]] || { echo "make_docs.sh: $exe is not an executable (build it: cmake --build --preset dev)" >&2; exit 1; }
mkdir -p "$dir"
source "$root/scripts/mpi-env.sh" # the executable may run as root
for ref in options results; do
  # PETSC_OPTIONS unset: the references depend on the tables alone
  env -u PETSC_OPTIONS "$exe" -help_markdown "$ref" >"$dir/$ref.md.tmp"
  mv "$dir/$ref.md.tmp" "$dir/$ref.md"
  echo "wrote $dir/$ref.md"
done
