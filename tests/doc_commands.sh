#!/usr/bin/env bash
# The documentation's commands run as written from a fresh clone (issue: "every command in the
# README and docs runs as written").
#
#   tests/doc_commands.sh path/to/beamimpact scratch_dir [mpiexec]
#
# 1. Every fenced ```sh block of README.md and docs/*.md runs, in the order of the file, in a
#    fresh copy of the repository's layout for that file: scratch_dir/<file>/ holds copies of
#    options/, scripts/ and docs/ and build/release/beamimpact (a link to the executable under
#    test), and nothing else (no out/), so the commands write there, never into the source
#    tree. `mpirun` and `mpiexec` are the given mpiexec. Blocks of one file share the
#    directory (a block may use what an earlier one wrote). Each block runs under
#    `bash -e -o pipefail`: a command that fails fails the test with the file and line.
#    A block that cannot run here (the set-up scripts, which build; long studies) carries a
#    marker just before it, at the start of a line (HTML comments do not show on the rendered
#    page):
#      <!-- doc_commands: skip (reason) -->
#      <!-- doc_commands: instead (reason)
#      cheaper commands that the test runs in place of the block
#      -->
#    and the test prints each such block with its reason. A marker must be followed by a
#    block, and the reason is required.
# 2. The "Run ..." commands in the header comments of options/**/*.opts (lines `#   mpirun
#    ...`, `#   build/release/beamimpact ...`, `#   scripts/...`, `#   ... more options`) are
#    checked without running them (the scenes test runs every scene): every option named is
#    one the program lists in -help (PETSc's -ts_/-snes_/-ksp_/-pc_ options excepted), every
#    options file, script and input file named exists, an -output directory exists in a fresh
#    clone or is made by an earlier `mkdir -p` of the header, and every .h5 a plot script reads
#    is written by an earlier command of the same header (its -output, or the -output in the
#    options file it runs).
set -uo pipefail

exe=${1:?usage: doc_commands.sh beamimpact scratch_dir [mpiexec]}
dir=${2:?usage: doc_commands.sh beamimpact scratch_dir [mpiexec]}
mpiexec=${3:-${MPIEXEC:-mpiexec}}
[[ -n $mpiexec ]] || mpiexec=mpiexec
exe=$(readlink -f "$exe")
[[ -x $exe ]] || { echo "FAIL: $1 is not an executable"; exit 1; }
mpiexec_path=$(command -v "$mpiexec") || { echo "FAIL: no mpiexec '$mpiexec'"; exit 1; }
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
mkdir -p "$dir" && dir=$(readlink -f "$dir")
source "$root/tests/lib.sh" # MPI environment, fail/pass
fails=${fails:-0}
t_start=$SECONDS
block_timeout=${DOC_COMMANDS_TIMEOUT:-120}

# mpirun/mpiexec as written in the docs -> the MPI this build uses
mkdir -p "$dir/bin"
for m in mpirun mpiexec; do
  printf '#!/bin/sh\nexec "%s" "$@"\n' "$mpiexec_path" >"$dir/bin/$m"
  chmod +x "$dir/bin/$m"
done

# fresh_layout NAME: scratch_dir/NAME as a fresh clone's layout; prints its path
fresh_layout() {
  local w="$dir/$1"
  rm -rf "${w:?}"
  mkdir -p "$w/build/release"
  cp -r "$root/options" "$root/scripts" "$root/docs" "$w/"
  ln -s "$exe" "$w/build/release/beamimpact"
  echo "$w"
}

# run_block FILE LINE0 WORKDIR: runs the lines in the global array blk (blk[0] is the markdown
# line LINE0) as one bash script in WORKDIR; on failure reports FILE:line of the command.
run_block() {
  local file=$1 line0=$2 work=$3 i n=${#blk[@]} script log t0=$SECONDS rc
  local -a start=()
  script="$work/.doc_block_$line0.sh"
  log="$work/.doc_block_$line0.log"
  printf '%s\n' "${blk[@]}" >"$script"
  for ((i = 0; i < n; i++)); do # the first line of each (backslash-continued) command
    if ((i > 0)) && [[ ${blk[i - 1]} == *\\ ]]; then start[i]=${start[i - 1]}; else start[i]=$i; fi
  done
  (cd "$work" && PATH="$dir/bin:$PATH" timeout "$block_timeout" bash -c \
    'set -eE -o pipefail; trap '\''echo "doc_commands: line $LINENO exited with $?" >&2'\'' ERR; source "$1"' \
    doc_block "$script") >"$log" 2>&1
  rc=$?
  if ((rc == 0)); then
    pass "$file:$line0 ($n lines, $((SECONDS - t0)) s)"
    return 0
  fi
  local at
  at=$(sed -n 's/^doc_commands: line \([0-9]*\) exited with.*/\1/p' "$log" | tail -1)
  if [[ -n $at ]] && ((at >= 1 && at <= n)); then
    local s=${start[at - 1]} cmd="" k # the whole command: from its first line to its last
    for ((k = s; k < n; k++)); do
      cmd+="${blk[k]}"$'\n'
      [[ ${blk[k]} == *\\ ]] || break
    done
    fail "$file:$((line0 + s)): exit status $rc"
    printf '%s' "$cmd" | sed 's/^/      $ /'
  elif ((rc == 124)); then
    fail "$file:$line0: the block took longer than $block_timeout s (mark it: <!-- doc_commands: skip (reason) --> or instead)"
  else
    fail "$file:$line0: the block failed (exit status $rc)"
  fi
  grep -v '^doc_commands: line' "$log" | tail -8 | sed 's/^/      /'
  return 1
}

# --- 1. the ```sh blocks of the markdown files ---------------------------------------------
n_run=0 n_skip=0 n_instead=0
mds=(README.md)
for f in "$root"/docs/*.md; do mds+=("docs/${f##*/}"); done
for md in "${mds[@]}"; do
  L=()
  mapfile -t L <"$root/$md" || { fail "$md: cannot read it"; continue; }
  nl=${#L[@]}
  name=${md//\//_}
  work=""
  used_markers=0 markers=0
  for ((i = 0; i < nl; i++)); do [[ ${L[i]} == "<!-- doc_commands:"* ]] && markers=$((markers + 1)); done
  i=0
  while ((i < nl)); do
    if [[ ! ${L[i]} =~ ^\`\`\`sh[[:space:]]*$ ]]; then
      # other fences: skip over their contents (```text and the like are not commands)
      if [[ ${L[i]} =~ ^\`\`\` ]]; then
        ((i++))
        while ((i < nl)) && [[ ! ${L[i]} =~ ^\`\`\` ]]; do ((i++)); done
      fi
      ((i++))
      continue
    fi
    open=$i
    blk=()
    ((i++))
    while ((i < nl)) && [[ ! ${L[i]} =~ ^\`\`\`[[:space:]]*$ ]]; do blk+=("${L[i]}"); ((i++)); done
    ((i >= nl)) && { fail "$md:$((open + 1)): unterminated \`\`\`sh block"; break; }
    ((i++))
    # the marker: an HTML comment ending on the last non-blank line before the fence
    kind="" reason="" mline=0
    j=$((open - 1))
    while ((j >= 0)) && [[ -z ${L[j]//[[:space:]]/} ]]; do ((j--)); done
    if ((j >= 0)) && [[ ${L[j]} == *"-->"* ]]; then
      k=$j
      while ((k >= 0)) && [[ ${L[k]} != *"<!--"* ]]; do ((k--)); done
      if ((k >= 0)) && [[ ${L[k]} == "<!-- doc_commands:"* ]]; then
        used_markers=$((used_markers + 1))
        mline=$((k + 1))
        head=${L[k]#*<!-- doc_commands:}
        head=${head%%-->*}
        if [[ $head =~ ^[[:space:]]*(skip|instead)[[:space:]]*\((.+)\)[[:space:]]*$ ]]; then
          kind=${BASH_REMATCH[1]} reason=${BASH_REMATCH[2]}
        else
          fail "$md:$mline: a doc_commands marker is 'skip (reason)' or 'instead (reason)', with the reason: $head"
          continue
        fi
        if [[ $kind == skip && $k -ne $j ]]; then
          fail "$md:$mline: 'skip' takes no commands (use 'instead')"
          continue
        fi
        if [[ $kind == instead ]]; then
          if ((k == j)) || [[ ${L[j]//[[:space:]]/} != "-->" ]]; then
            fail "$md:$mline: 'instead' gives its commands on the lines after it and ends with a line '-->'"
            continue
          fi
          alt=("${L[@]:k+1:j-k-1}")
        fi
      fi
    fi
    [[ -n $work ]] || work=$(fresh_layout "$name")
    case $kind in
      skip)
        echo "skip: $md:$((open + 1)) ($reason):"
        printf '%s\n' "${blk[@]}" | sed 's/^/      | /'
        n_skip=$((n_skip + 1))
        ;;
      instead)
        echo "instead of $md:$((open + 1)) ($reason), $md:$((mline + 1)):"
        printf '%s\n' "${alt[@]}" | sed 's/^/      | /'
        blk=("${alt[@]}")
        run_block "$md" $((mline + 1)) "$work"
        n_instead=$((n_instead + 1))
        ;;
      *)
        run_block "$md" $((open + 2)) "$work"
        n_run=$((n_run + 1))
        ;;
    esac
  done
  ((used_markers == markers)) || fail "$md: $((markers - used_markers)) doc_commands marker(s) not just before a \`\`\`sh block"
done
echo "markdown: $n_run block(s) run as written, $n_instead by their cheaper variant, $n_skip skipped ($((SECONDS - t_start)) s)"

# --- 2. the commands in the headers of options/**/*.opts (checked, not run) ---------------
helptext=$("$exe" -help 2>&1)
known_option() { # NAME without the dash
  case $1 in ts_* | snes_* | ksp_* | pc_* | mat_* | log_view | help) return 0 ;; esac
  grep -qE -- "(^|[[:space:]])-$1([[:space:]]|<|:|=|,|$)" <<<"$helptext"
}
n_hdr=0
while IFS= read -r f; do
  rel=${f#"$root/"}
  made_dirs=" . " outputs=" " cont="" ln=0 cmdline=0 prev_opts=()
  while IFS= read -r raw; do
    ln=$((ln + 1))
    [[ $raw == \#* ]] || break
    l=${raw#\#}
    if [[ -z $cont ]]; then
      [[ $l =~ ^[[:space:]]{2,}(mpirun|mpiexec|build/release/beamimpact|scripts/|mkdir|\.\.\.[[:space:]]) ]] || continue
      cmdline=$ln
    fi
    l=${l#"${l%%[![:space:]]*}"}
    if [[ $l == *\\ ]]; then cont+="${l%\\} "; continue; fi
    cmd="$cont$l" cont=""
    cmd=${cmd%%   (*}   # prose after the command: three spaces and a parenthesis
    cmd=${cmd%%#*}      # or a comment
    n_hdr=$((n_hdr + 1))
    where="$rel:$cmdline"
    read -r -a w <<<"$cmd"
    case ${w[0]} in
      mkdir)
        for a in "${w[@]:1}"; do
          [[ $a == -* ]] && continue
          while [[ $a != . && $a != / ]]; do made_dirs+="$a "; a=$(dirname "$a"); done
        done
        continue ;;
      scripts/*)
        [[ -x $root/${w[0]} ]] || { fail "$where: ${w[0]} does not exist"; continue; }
        if [[ ${w[0]} == scripts/plot_* ]]; then
          for a in "${w[@]:1}"; do
            [[ $a == *.h5 && $outputs != *" $a "* ]] && fail "$where: ${w[0]} reads $a, which no command before it writes (written:$outputs)"
          done
        fi
        continue ;;
      mpirun | mpiexec) w=("${w[@]:3}") ;; # mpirun -n N
      ...) w=(build/release/beamimpact "${prev_opts[@]}" "${w[@]:1}") ;;
    esac
    [[ ${w[0]} == build/release/beamimpact ]] || { fail "$where: not a beamimpact command: $cmd"; continue; }
    prev_opts=()
    out="" opts_out=""
    for ((a = 1; a < ${#w[@]}; a++)); do
      o=${w[a]}
      [[ $o == -* && ! $o =~ ^-[0-9.] ]] || continue
      known_option "${o#-}" || fail "$where: $o is not an option of beamimpact (-help does not list it)"
      v=${w[a + 1]:-}
      case $o in
        -options_file)
          [[ -f $root/$v ]] || fail "$where: -options_file $v does not exist"
          [[ -f $root/$v ]] && o2=$(sed -n 's/^-output[[:space:]]\+\([^[:space:]]*\).*/\1/p' "$root/$v" | tail -1) && [[ -n $o2 ]] && opts_out=$o2
          [[ $v == "$rel" ]] && prev_opts=(-options_file "$v")
          ;;
        -beam_profile | -beam_properties | -ball_cor_table)
          [[ -f $root/$v ]] || fail "$where: $o $v does not exist" ;;
        -output) out=$v ;;
      esac
    done
    out=${out:-$opts_out}
    if [[ -n $out && $out != none ]]; then
      d=$(dirname "$out")
      [[ $made_dirs == *" $d "* ]] || { [[ $d =~ ^(options|docs|scripts)(/|$) ]] && [[ -d $root/$d ]]; } ||
        fail "$where: -output $out: no directory $d in a fresh clone (add '#   mkdir -p $d' before it)"
      outputs+="$out "
    fi
  done <"$f"
  [[ -n $cont ]] && fail "$rel: the header ends inside a continued command"
done < <(find "$root/options" -name '*.opts' | sort)
echo "options headers: $n_hdr command(s) checked"

# No link leaves the repository: every relative markdown link of the README and docs/ names a
# file of the repository (an anchor after '#' is not checked), and no file points at ../shared.
n_links=0
while IFS= read -r md; do
  while IFS= read -r target; do
    n_links=$((n_links + 1))
    path=${target%%#*}
    [[ -z $path || $path =~ ^[a-z]+: ]] && continue # an anchor in the same file, or a URL
    full=$(realpath -m "$(dirname "$md")/$path")
    [[ $full == "$root"/* && -e $full ]] || fail "${md#"$root"/}: the link ($target) does not name a file of the repository"
  done < <(grep -o '\]([^)]*)' "$md" | sed 's/^](\(.*\))$/\1/')
done < <(find "$root" -maxdepth 2 -name '*.md' -not -path '*/build/*' | sort)
outside=$(grep -rln '\.\./shared' "$root/README.md" "$root/docs" "$root/options" "$root/src" "$root/scripts" 2>/dev/null)
[[ -z $outside ]] || fail "files pointing outside the repository (../shared): $outside"
echo "links: $n_links markdown link(s) checked"

# What the docs say about the program that can be checked against it (issue 22: six places where
# they contradicted it): every scene file is in docs/scenes.md; every option docs/model.md's
# options table (section 10) names is one -help lists; the planned extensions (the last section) name
# no option the program has; docs/sweep.md does not call a shipped scene unshipped; the swinging
# R161's q that docs/bats.md quotes is the program's.
help=$("$exe" -help 2>&1)
for f in "$root"/options/scenes/*.opts; do
  grep -q "$(basename "$f")" "$root/docs/scenes.md" || fail "docs/scenes.md does not list options/scenes/$(basename "$f")"
done
sec10=$(sed -n '/^## 10\./,/^## 11\./p' "$root/docs/model.md")
for o in $(grep -o '`-[a-z_0-9]*' <<<"$sec10" | tr -d '`' | sort -u); do
  [[ $o =~ ^-[a-z]+_$ || $o == -ts_dtt ]] && continue # a family (-convergence_*), or the example of a typo
  grep -q -- "^ *$o[ <:]" <<<"$help" || fail "docs/model.md section 10 names $o, which -help does not list"
done
sec12=$(sed -n '/^## [0-9]*\. Planned extensions/,$p' "$root/docs/model.md" | sed '/Nothing on this page/q')
for o in $(grep -o '`-[a-z_0-9]*' <<<"$sec12" | tr -d '`' | sort -u); do
  grep -q -- "^ *$o[ <:]" <<<"$help" && fail "docs/model.md's planned extensions (the last section) plan $o, which the program already has"
done
grep -q "does not model yet: it is not shipped" "$root/docs/sweep.md" && fail "docs/sweep.md calls the batting study unshipped (options/scenes/r161-bbs-map.opts)"
q=$(cd "$root" && "$exe" -options_file options/bats/r161.opts -options_file options/balls/baseball.opts -beam_theory timoshenko -options_file options/integrators/rk4.opts \
    -bat_speed 24 -bat_angular_velocity 51 -ball_speed 40 -impact_x 0.70 -output none 2>&1 | sed -nE 's/.*collision efficiency q ([0-9.]+).*/\1/p')
[[ -n $q ]] && grep -q "Timoshenko, as the game case below: \`q\` = $q" "$root/docs/bats.md" || fail "docs/bats.md: the Timoshenko R161's q at 70 cm is not the program's ($q)"
echo "claims: scenes, options of model.md section 10 and its planned extensions, sweep.md's batting study, bats.md's q checked"

echo "doc_commands: $((SECONDS - t_start)) s"
if ((fails)); then
  echo "FAILED: $fails check(s)"
  exit 1
fi
echo "all passed"
