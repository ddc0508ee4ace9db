#!/usr/bin/env bash
# Frames in parallel vs tiles in parallel for `grcis animate`, measured as paired runs: each round
# runs both modes back to back (alternating which goes first), so a machine whose load changes
# (a shared CI box) disturbs both alike. Prints each run's frames/s (from the summary line, which
# excludes start-up and script compilation) and the median of the per-round ratios.
#
#   bench/animate-parallel.sh [SIZE] [SPP] [FRAMES] [ROUNDS]     e.g. 160x120 4 0-24 8
set -euo pipefail
cd "$(dirname "$0")/.."
size=${1:-160x120} spp=${2:-4} frames=${3:-0-24} rounds=${4:-8}
dotnet build src/GrCis.Cli -c Release -v q -nologo >/dev/null
dll=src/GrCis.Cli/bin/Release/net10.0/grcis.dll
out=$(mktemp -d "${TMPDIR:-/tmp}/grcis-bench.XXXXXX")
trap 'rm -rf "$out"' EXIT

ratios=()
for r in $(seq 1 "$rounds"); do
  order=(frames tiles); [ $((r % 2)) -eq 0 ] && order=(tiles frames)
  declare -A fps=()
  for m in "${order[@]}"; do
    rm -rf "$out/f"
    line=$(dotnet exec "$dll" animate scripts/Orbit.cs -o "$out/f/o###.png" --size "$size" --spp "$spp" \
             --frames "$frames" --parallel "$m" -q)
    fps[$m]=$(grep -o '[0-9.]* frames/s' <<<"$line" | cut -d' ' -f1)
  done
  ratio=$(awk -v a="${fps[frames]}" -v b="${fps[tiles]}" 'BEGIN { printf "%.3f", a / b }')
  ratios+=("$ratio")
  echo "round $r: frames ${fps[frames]} frames/s, tiles ${fps[tiles]} frames/s, ratio $ratio (load $(cut -d' ' -f1 /proc/loadavg 2>/dev/null || echo ?))"
  unset fps
done
printf '%s\n' "${ratios[@]}" | sort -n | awk -v s="$size" -v p="$spp" '{ a[NR] = $1 } END {
  m = (NR % 2) ? a[(NR + 1) / 2] : (a[NR / 2] + a[NR / 2 + 1]) / 2
  printf "%s spp %s: median frames/tiles ratio %.3f over %d rounds (> 1: frames in parallel is faster)\n", s, p, m, NR }'
