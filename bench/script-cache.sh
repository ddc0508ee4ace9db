#!/usr/bin/env bash
# Whole-process time of `grcis render scripts/FiveBalls.cs -s 160x120`: the first run (compiled-script cache
# emptied before each run), a second run of the unchanged script (cached), --no-cache, and the built-in
# Five balls for scale. Each build given is measured with hyperfine (Debian package `hyperfine`), the cases of
# all builds interleaved in one hyperfine call per case so a changing load disturbs them alike; prints the
# median wall time and the mean user+system CPU time of each.
#
#   bench/script-cache.sh [RUNS] [LABEL=path/to/grcis.dll ...]
#
# Without builds: the Release build (built here) and, when present, the ReadyToRun publish
# (dotnet publish src/GrCis.Cli -p:PublishProfile=ReadyToRun). A build without the cache (an older commit)
# runs its "cached" and "no-cache" cases as plain renders (its --no-cache is not passed).
set -euo pipefail
cd "$(dirname "$0")/.."
runs=${1:-10}
shift || true
builds=("$@")
if [ ${#builds[@]} -eq 0 ]; then
  dotnet build src/GrCis.Cli -c Release -v q -nologo >/dev/null
  builds=("jit=src/GrCis.Cli/bin/Release/net10.0/grcis.dll")
  [ -f src/GrCis.Cli/bin/publish/grcis.dll ] && builds+=("r2r=src/GrCis.Cli/bin/publish/grcis.dll")
fi
command -v hyperfine >/dev/null || { echo "hyperfine is needed (apt-get install hyperfine)" >&2; exit 2; }
out=$(mktemp -d "${TMPDIR:-/tmp}/grcis-bench.XXXXXX")
trap 'rm -rf "$out"' EXIT
script=$PWD/scripts/FiveBalls.cs
size=160x120

has_cache() { dotnet exec "$1" render --help | grep -q -- --no-cache; }

for case in first cached no-cache built-in; do
  args=()
  for b in "${builds[@]}"; do
    label=${b%%=*} dll=$(realpath "${b#*=}") cache="$out/cache-$label"
    render="dotnet exec $dll render"
    opts="-s $size -o $out/$label.png -q"
    case $case in
      first) args+=(--prepare "rm -rf $cache" -n "$label first" "env GRCIS_CACHE_DIR=$cache $render $script $opts") ;;
      cached)
        env GRCIS_CACHE_DIR="$cache" dotnet exec "$dll" render "$script" $opts >/dev/null
        args+=(--prepare true -n "$label cached" "env GRCIS_CACHE_DIR=$cache $render $script $opts") ;;
      no-cache)
        flag=""; has_cache "$dll" && flag="--no-cache"
        args+=(--prepare true -n "$label no-cache" "env GRCIS_CACHE_DIR=$cache $render $script $opts $flag") ;;
      built-in) args+=(--prepare true -n "$label built-in" "$render 'Five balls' $opts") ;;
    esac
  done
  hyperfine -N --warmup 1 --runs "$runs" --style none --export-json "$out/$case.json" "${args[@]}" >/dev/null
  python3 - "$out/$case.json" <<'PY'
import json, sys
for r in json.load(open(sys.argv[1]))["results"]:
    print(f"{r['command']:<22} median {r['median']:.3f} s   (min {r['min']:.3f}, max {r['max']:.3f}; CPU {r['user'] + r['system']:.3f} s)")
PY
done
echo "load average after: $(cut -d' ' -f1-3 /proc/loadavg 2>/dev/null || echo ?)"
