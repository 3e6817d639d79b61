# Sourced by the shell tests: MPI environment, pass/fail bookkeeping, and a Python with
# h5py and numpy in $python. Without one the numeric checks that need it are skipped, and said:
# a SKIP line, and a test that passed what it could check ends with 77, which CTest counts as
# skipped (SKIP_RETURN_CODE, tests/CMakeLists.txt): never a silent pass.
source "$(dirname "${BASH_SOURCE[0]}")/../scripts/mpi-env.sh"

fails=0
fail() { echo "FAIL: $*"; fails=$((fails + 1)); }
pass() { echo "ok:   $*"; }

skipped=0
skip() { echo "SKIP: $*"; skipped=$((skipped + 1)); }
# lib_exit_trap [COMMANDS]: on exit run COMMANDS, then turn a passing exit into 77 if anything was skipped
lib_exit_trap() { trap "rc=\$?; $1; ((rc == 0 && skipped > 0)) && exit 77; exit \$rc" EXIT; }
lib_exit_trap :

python=""
for p in /usr/bin/python3 python3; do
  if command -v "$p" >/dev/null && "$p" -c "import h5py, numpy" 2>/dev/null; then python=$p; break; fi
done
[[ -n $python ]] || skip "the checks that read HDF5 files with h5py: no python3 with h5py and numpy (Debian: python3-h5py python3-numpy)"

# Killing a running sweep (sweep_resume.sh, sweep_io.sh):
# sweep_progress LOG PID: waits (at most 12 s) until the sweep logging to LOG reports at least 4
# points done or the launcher PID has ended; prints the last count reported (0 if none).
sweep_progress() {
  local log=$1 pid=$2 seen=0 i
  for ((i = 0; i < 600; ++i)); do
    seen=$(sed -nE 's/^sweep: ([0-9]+)\/[0-9]+ points.*/\1/p' "$log" | tail -1)
    seen=${seen:-0}
    ((seen >= 4)) && break
    kill -0 "$pid" 2>/dev/null || break
    sleep 0.02
  done
  echo "$seen"
}
# descendants PID: every process below PID (Open MPI puts each rank in its own process group,
# so a process-group kill would miss them).
descendants() { local c; for c in $(ps -o pid= --ppid "$1"); do echo "$c"; descendants "$c"; done; }
# output_until PATTERN SECONDS CMD...: runs CMD (its stdout and stderr together) until a line
# matches the extended regex PATTERN or SECONDS have passed, then stops it; prints what it
# wrote. For a run meant to be cut short once it has said something (a cost line): quick on a
# quiet machine, patient on a loaded one.
output_until() {
  local pattern=$1 seconds=$2 log pid i
  shift 2
  log=$(mktemp)
  "$@" >"$log" 2>&1 &
  pid=$!
  for ((i = 0; i < seconds * 20; ++i)); do
    grep -qE "$pattern" "$log" && break
    kill -0 "$pid" 2>/dev/null || break
    sleep 0.05
  done
  kill "$pid" 2>/dev/null
  wait "$pid" 2>/dev/null
  cat "$log"
  rm -f "$log"
}
