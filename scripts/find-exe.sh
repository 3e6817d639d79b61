# Sourced by the scripts that run beamimpact. find_beamimpact SCRIPT [PATH] prints the
# executable to use: PATH when given (it must be an executable file), else
# build/release/beamimpact, else the first build/*/beamimpact of this checkout; otherwise it
# fails (status 2) naming SCRIPT and how to build one.
find_beamimpact() {
  local name=$1 path=${2:-} root c
  root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
  if [[ -n $path ]]; then
    [[ -x $path && ! -d $path ]] || { echo "$name: $path is not an executable" >&2; return 2; }
    readlink -f "$path"
    return 0
  fi
  for c in "$root/build/release/beamimpact" "$root"/build/*/beamimpact; do
    if [[ -x $c ]]; then readlink -f "$c"; return 0; fi
  done
  echo "$name: no build/*/beamimpact; build one (cmake --preset release && cmake --build --preset release) or pass its path" >&2
  return 2
}
