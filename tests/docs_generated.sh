#!/usr/bin/env bash
# The documentation generated from the program's tables, and the design's citations (issue 35,
# "docs drift").
#
#   tests/docs_generated.sh path/to/beamimpact scratch_dir [include_dir ...]
#
# 1. docs/options.md and docs/results.md are what `beamimpact -help_markdown options|results`
#    prints now (scripts/make_docs.sh writes them into scratch_dir): a row or column changed or
#    added without regenerating them fails with the diff and the command that rewrites them.
# 2. docs/design.md cites only what exists: every path (`system/force_elastic.cpp`, `src/...`,
#    `tests/...`; `{hpp,cpp}` expanded, a stem such as `run/free_flight` as its .hpp or .cpp) is
#    a file or folder of the repository, and every name of code (`BeamSystemBuild`,
#    `Stepper::SetState`, `ContactWall*` as a prefix) a word of src/ or tests/ or of the headers in
#    include_dir (PETSc's and SLEPc's: `TSSetEventHandler`); the count of the Stepper's methods
#    it states is the count in src/solvers/stepper.hpp.
# 3. docs/model.md numbers its sections once each, in order (1, 2, 3, ...), and every path it
#    cites exists.
set -uo pipefail

exe=${1:?usage: docs_generated.sh beamimpact scratch_dir [include_dir ...]}
dir=${2:?usage: docs_generated.sh beamimpact scratch_dir [include_dir ...]}
shift 2
includes=("$@")
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
source "$root/tests/lib.sh"
rm -rf "$dir" && mkdir -p "$dir"

# 1. The generated references.
if "$root/scripts/make_docs.sh" "$exe" "$dir" >/dev/null; then
  for ref in options results; do
    if diff -u "$root/docs/$ref.md" "$dir/$ref.md" >"$dir/$ref.diff"; then
      pass "docs/$ref.md is what -help_markdown $ref prints"
    else
      fail "docs/$ref.md differs from the program's tables (rewrite it: cmake --build --preset dev --target docs, or scripts/make_docs.sh):"
      head -60 "$dir/$ref.diff"
    fi
  done
else
  fail "scripts/make_docs.sh $exe $dir failed"
fi

# A cited path (relative to the repository, or to src/ for a layer's folder) exists; `{a,b}` and
# a stem without its extension allowed.
path_exists() {
  local p=$1 head alts tail alt
  if [[ $p =~ ^(.*)\{([^}]*)\}(.*)$ ]]; then
    head=${BASH_REMATCH[1]} alts=${BASH_REMATCH[2]} tail=${BASH_REMATCH[3]}
    IFS=, read -ra parts <<<"$alts"
    for alt in "${parts[@]}"; do path_exists "$head$alt$tail" || return 1; done
    return 0
  fi
  [[ $p =~ ^(app|base|io|model|run|solvers|studies|system)/ ]] && p=src/$p
  [[ -e $root/$p || -e $root/$p.hpp || -e $root/$p.cpp ]]
}

# check_paths FILE: every backquoted path of FILE exists (placeholders such as NAME.cpp,
# force_<name>.cpp and globs skipped).
check_paths() {
  local md=$1 n=0 p
  while IFS= read -r p; do
    [[ $p =~ (NAME|\<|\*|XXXX) ]] && continue
    n=$((n + 1))
    path_exists "$p" || fail "${md#"$root"/} cites \`$p\`, which is no file of the repository"
  done < <(grep -oE '`[^`]+`' "$md" | tr -d '`' | grep -E '^(src/)?(app|base|io|model|run|solvers|studies|system|tests|scripts|options|docs)/[^ ]*$|^CMakeLists.txt$' | sort -u)
  pass "${md#"$root"/}: $n cited paths exist"
}

# 2. docs/design.md's citations.
design=$root/docs/design.md
check_paths "$design"
n=0
while IFS= read -r w; do
  n=$((n + 1))
  if [[ $w == *'*' ]]; then # a family: some word of src/ starts with it
    grep -rqE "\b${w%\*}[A-Za-z0-9_]+" "$root/src" || fail "docs/design.md cites \`$w\`: no name of src/ starts so"
    continue
  fi
  grep -rqw -- "$w" "$root/src" "$root/tests" "${includes[@]}" 2>/dev/null || fail "docs/design.md cites $w, which is no name of src/, tests/ or PETSc's headers"
done < <( {
  grep -oE '`[^`]+`' "$design" | tr -d '`' | grep -v '/'
  sed -n '/^```/,/^```/p' "$design" # the data-flow diagram
} | grep -oE '\b[A-Za-z_][A-Za-z0-9_]*\b\*?' | grep -E '^(k[A-Z]|[A-Z][A-Za-z0-9]*[a-z][A-Za-z0-9]*[A-Z]|[A-Z]{2,}[a-z])' | sort -u)
pass "docs/design.md: $n cited names checked"
virtuals=$(grep -cE '^\s*virtual .*\(' "$root/src/solvers/stepper.hpp")
virtuals=$((virtuals - $(grep -cE '^\s*virtual ~' "$root/src/solvers/stepper.hpp")))
stated=$(grep -oE 'Stepper` interface[^0-9]*[0-9]+ virtual methods' "$design" | grep -oE '[0-9]+ virtual' | grep -oE '[0-9]+')
[[ $stated == "$virtuals" ]] && pass "docs/design.md: the Stepper's $virtuals virtual methods" ||
  fail "docs/design.md states the Stepper interface has '${stated:-no count}' virtual methods; src/solvers/stepper.hpp has $virtuals"

# 3. docs/model.md: its sections numbered once each, in order, and its paths.
model=$root/docs/model.md
numbers=$(grep -oE '^## [0-9]+\.' "$model" | grep -oE '[0-9]+' | tr '\n' ' ')
expected=$(seq -s ' ' 1 "$(wc -w <<<"$numbers")")
[[ $numbers == "$expected " ]] && pass "docs/model.md: sections 1 to $(wc -w <<<"$numbers") numbered once each" ||
  fail "docs/model.md numbers its sections '$numbers', not '$expected'"
check_paths "$model"

if ((fails)); then
  echo "FAILED: $fails check(s)"
  exit 1
fi
echo "all passed"
