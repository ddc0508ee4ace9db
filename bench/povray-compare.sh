#!/usr/bin/env bash
# Times POV-Ray 3.7 and grcis on the peer scenes (shared/bench/povray) at the same image size,
# samples per pixel and thread count, and prints ours / POV-Ray per scene.
#
#   bench/povray-compare.sh            # 2 threads (THREADS=1 bench/povray-compare.sh for one)
#
# Equivalence (see docs/performance.md): 640x480 (Two spheres also 1280x720); POV-Ray
# +A0.0 +AM1 +R4 = a 4x4 grid plus the centre (17 samples) vs our 16 spp; Declare=MTL=13 =
# GrCis MaxLevel 12; adc_bailout 0.05 = MinImportance 0.05; same thread count (+WT / --threads).
# Times: POV-Ray's own "Trace Time" (parsing and start-up excluded) vs our render time from
# `grcis bench` (scene set-up, BVH build and JIT warm-up excluded); POV-Ray's wall time is shown too.
# CPU: processor seconds of all threads (POV-Ray's whole process, ours during the render), which a
# loaded machine disturbs far less than wall time.
set -euo pipefail

THREADS=${THREADS:-2}
here=$(cd "$(dirname "$0")" && pwd)
repo=$(dirname "$here")

scenes=${POVRAY_SCENES:-}
if [[ -z "$scenes" ]]; then
  for d in "$repo/../shared/bench/povray" "$repo/../../shared/bench/povray" /work/shared/bench/povray; do
    if [[ -f "$d/fiveballs.pov" ]]; then scenes=$(cd "$d" && pwd); break; fi
  done
fi
[[ -n "$scenes" && -f "$scenes/fiveballs.pov" ]] || { echo "povray-compare: set POVRAY_SCENES to the folder with fiveballs.pov" >&2; exit 2; }

if ! command -v povray >/dev/null 2>&1; then
  echo "povray-compare: installing POV-Ray from Debian (apt-get install povray)" >&2
  as_root=""
  [[ $(id -u) -ne 0 ]] && as_root="sudo"
  $as_root apt-get update -qq
  DEBIAN_FRONTEND=noninteractive $as_root apt-get install -y -qq povray >/dev/null
fi

dotnet build "$repo/src/GrCis.Cli" -c Release -v q -nologo >/dev/null
grcis=(dotnet "$repo/src/GrCis.Cli/bin/Release/net10.0/grcis.dll")
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT

printf '%-12s %-9s %-8s %3s  %10s %10s %10s  %9s   %8s %8s  %s\n' scene size spp threads "POV trace" "POV wall" "ours" "ours/POV" "POV cpu" "our cpu" "cpu ratio"
# pov file | our bench case | width | height
for row in "fiveballs five-balls 640 480" "twospheres two-spheres 640 480" \
           "twospheres two-spheres-720p 1280 720" "sphereflake flake9 640 480"; do
  read -r pov ours w h <<<"$row"
  start=$(date +%s.%N)
  TIMEFORMAT='%U %S'
  { time (cd "$tmp" && povray "+I$scenes/$pov.pov" "+O$tmp/$pov.png" "+W$w" "+H$h" -D +A0.0 +AM1 +R4 -J "+WT$THREADS" \
     File_Gamma=2.2 +FN Declare=MTL=13 >"$tmp/$pov.log" 2>&1); } 2>"$tmp/$pov.time"
  end=$(date +%s.%N)
  wall=$(awk -v a="$start" -v b="$end" 'BEGIN { print b - a }')
  trace=$(sed -n 's/.*Trace Time:.*(\([0-9.]*\) seconds).*/\1/p' "$tmp/$pov.log" | tail -1)
  json=$("${grcis[@]}" bench --scene "$ours" --no-slow --json --threads "$THREADS" 2>/dev/null)
  mine=$(printf '%s' "$json" | sed -n 's/.*"seconds": \([0-9.eE+-]*\),*/\1/p' | head -1)
  mycpu=$(printf '%s' "$json" | sed -n 's/.*"cpuSeconds": \([0-9.eE+-]*\),*/\1/p' | head -1)
  povcpu=$(awk '{ print $1 + $2 }' "$tmp/$pov.time")
  ratio=$(awk -v a="$mine" -v b="$trace" 'BEGIN { print a / b }')
  cratio=$(awk -v a="$mycpu" -v b="$povcpu" 'BEGIN { print a / b }')
  printf '%-12s %-9s %-8s %3s  %9.2fs %9.2fs %9.2fs  %9.2f   %7.2fs %7.2fs  %.2f\n' "$pov" "${w}x$h" "17 vs 16" "$THREADS" "$trace" "$wall" "$mine" "$ratio" "$povcpu" "$mycpu" "$cratio"
done
