#!/usr/bin/env bash
# The installed tool against the ReadyToRun publish, whole processes: `grcis --version` (start-up), the built-in
# Five balls at 160x120, the script scripts/FiveBalls.cs at 160x120 cached (compiled in a run before) and compiled
# (--no-cache: Roslyn's start, where its ReadyToRun code counts most). The two builds run alternately, one run of
# each per hyperfine call, the order swapped every call (so a changing load disturbs them alike), each with a cache
# folder of its own; prints the median wall and CPU time of each, and installed / publish.
#
#   bench/installed-tool.sh [RUNS] [ARTIFACTS]
#
# installed: `dotnet tool install --tool-path <tmp> --add-source ARTIFACTS GrCis.Cli` (without ARTIFACTS, this
# machine's packages are packed first: `dotnet pack src/GrCis.Cli -c Release`, minutes); publish: `dotnet publish
# src/GrCis.Cli -p:PublishProfile=ReadyToRun` (src/GrCis.Cli/bin/publish/grcis). Needs hyperfine (apt-get install
# hyperfine) and python3.
set -euo pipefail
cd "$(dirname "$0")/.."
runs=${1:-15}
command -v hyperfine >/dev/null || { echo "hyperfine is needed (apt-get install hyperfine)" >&2; exit 2; }
out=$(mktemp -d "${TMPDIR:-/tmp}/grcis-installed.XXXXXX")
trap 'rm -rf "$out"' EXIT
artifacts=${2:-}
if [ -z "$artifacts" ]; then
  artifacts=$out/artifacts
  dotnet pack src/GrCis.Cli -c Release -o "$artifacts" -v q -nologo >/dev/null
fi
artifacts=$(realpath "$artifacts")
dotnet tool install --tool-path "$out/tools" --add-source "$artifacts" GrCis.Cli >/dev/null
dotnet publish src/GrCis.Cli -p:PublishProfile=ReadyToRun -v q -nologo >/dev/null
installed=$out/tools/grcis
publish=$PWD/src/GrCis.Cli/bin/publish/grcis
script=$PWD/scripts/FiveBalls.cs
echo "installed: $(find "$out/tools/.store" -name grcis.dll | sed "s|$out/tools/||")"

for case in version built-in script compile; do
  declare -A cmd=()
  for b in installed publish; do
    run="env GRCIS_CACHE_DIR=$out/cache-$b ${!b}"
    case $case in
      version) cmd[$b]="$run --version" ;;
      built-in) cmd[$b]="$run render FiveBalls -s 160x120 -o $out/$b.png -q" ;;
      script) cmd[$b]="$run render $script -s 160x120 -o $out/$b-script.png -q" ;;
      compile) cmd[$b]="$run render $script -s 160x120 -o $out/$b-script.png -q --no-cache" ;;
    esac
    ${cmd[$b]} >/dev/null # warm-up: the script compiled into its cache, the start-up profile recorded
  done
  # Alternating: one run of each per round, the order swapped every round.
  for ((i = 0; i < runs; i++)); do
    if ((i % 2 == 0)); then order=(installed publish); else order=(publish installed); fi
    hyperfine -N --runs 1 --style none --export-json "$out/$case-$i.json" \
      -n "${order[0]}" "${cmd[${order[0]}]}" -n "${order[1]}" "${cmd[${order[1]}]}" >/dev/null
  done
  python3 - "$case" "$out"/"$case"-*.json <<'PY'
import json, statistics, sys
runs = {}
for f in sys.argv[2:]:
    for x in json.load(open(f))["results"]:
        runs.setdefault(x["command"], []).append((x["times"][0], x["user"] + x["system"]))
med = {b: (statistics.median(t for t, _ in r), statistics.median(c for _, c in r)) for b, r in runs.items()}
for b in ("installed", "publish"):
    t = [w for w, _ in runs[b]]
    print(f"{sys.argv[1]:<9} {b:<10} median {med[b][0]:.3f} s (min {min(t):.3f}, max {max(t):.3f}; CPU {med[b][1]:.3f} s; {len(t)} runs)")
print(f"{sys.argv[1]:<9} installed / publish: {med['installed'][0] / med['publish'][0]:.2f} wall, {med['installed'][1] / med['publish'][1]:.2f} CPU")
PY
done
cmp "$out/installed.png" "$out/publish.png" && echo "images: identical"
echo "load average after: $(cut -d' ' -f1-3 /proc/loadavg 2>/dev/null || echo ?)"
