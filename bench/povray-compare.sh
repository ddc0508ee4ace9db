#!/usr/bin/env bash
# Times POV-Ray 3.7 and grcis on the peer scenes (shared/bench/povray) at the same image size,
# samples per pixel and thread count, and prints ours / POV-Ray per scene.
#
#   bench/povray-compare.sh            # 2 threads (THREADS=1 bench/povray-compare.sh for one)
#   MODE=whole bench/povray-compare.sh # whole processes, alternated (ROUNDS=7; GRCIS=path/to/grcis;
#                                      # GRCIS_BASE=another/grcis adds a second build to each round, e.g. before a change;
#                                      # without GRCIS: the ReadyToRun publish, as grcis is published for speed;
#                                      # BUILD=plain: the plain Release build instead)
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

# The peer scenes: POVRAY_SCENES, else a folder found from the repository (its own bench/povray, or the shared
# bench/povray folder beside the repository or its parent); never a path of one machine.
scenes=${POVRAY_SCENES:-}
if [[ -z "$scenes" ]]; then
  for d in "$repo/bench/povray" "$repo/../shared/bench/povray" "$repo/../../shared/bench/povray"; do
    if [[ -f "$d/fiveballs.pov" ]]; then scenes=$(cd "$d" && pwd); break; fi
  done
fi
[[ -z "${POVRAY_SCENES:-}" || -f "$POVRAY_SCENES/fiveballs.pov" ]] || { echo "povray-compare: POVRAY_SCENES='$POVRAY_SCENES' has no fiveballs.pov" >&2; exit 2; }
[[ -n "$scenes" && -f "$scenes/fiveballs.pov" ]] || { echo "povray-compare: no peer scenes found (looked in bench/povray and ../shared/bench/povray of the repository); set POVRAY_SCENES to the folder with fiveballs.pov" >&2; exit 2; }

if ! command -v povray >/dev/null 2>&1; then
  echo "povray-compare: installing POV-Ray from Debian (apt-get install povray)" >&2
  as_root=""
  [[ $(id -u) -ne 0 ]] && as_root="sudo"
  $as_root apt-get update -qq
  DEBIAN_FRONTEND=noninteractive $as_root apt-get install -y -qq povray >/dev/null
fi

tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT

if [[ "${MODE:-render}" == whole ]]; then
  # Whole processes, as a user runs them: `grcis render <scene>` (start-up, scene set-up, JIT, render, PNG) against
  # `povray` (start-up, parsing, trace, PNG). The two programs alternate, ROUNDS times per scene, so load that
  # comes and goes hits both alike; medians are printed. Wall s is what the ratio is about; CPU s (user + sys of
  # the process) is steadier on a shared machine. The trace and render columns are the programs' own reports of
  # the same runs (POV-Ray's "Trace Time", grcis's render time).
  ROUNDS=${ROUNDS:-7}
  if [[ -n "${GRCIS:-}" ]]; then
    grcis_bin=$GRCIS
  elif [[ "${BUILD:-r2r}" == plain ]]; then
    grcis_bin=$repo/src/GrCis.Cli/bin/Release/net10.0/grcis
    dotnet build "$repo/src/GrCis.Cli" -c Release -v q -nologo >/dev/null
  else
    # The ReadyToRun publish (src/GrCis.Cli/Properties/PublishProfiles/ReadyToRun.pubxml): grcis as README says to
    # publish it for the fastest start.
    grcis_bin=$repo/src/GrCis.Cli/bin/publish/grcis
    dotnet publish "$repo/src/GrCis.Cli" -p:PublishProfile=ReadyToRun -v q -nologo >/dev/null
  fi
  # A program, not a folder (a folder passes -x): GRCIS and GRCIS_BASE name the grcis executable itself.
  need_program() {
    [[ -f "$2" && -x "$2" ]] || { echo "povray-compare: no grcis program at $1=$2 (name the executable, e.g. <publish folder>/grcis)" >&2; exit 2; }
  }
  need_program GRCIS "$grcis_bin"
  base_bin=${GRCIS_BASE:-}
  [[ -z "$base_bin" ]] || need_program GRCIS_BASE "$base_bin"
  median() { sort -g | awk '{ v[NR] = $1 } END { if (NR % 2) print v[(NR + 1) / 2]; else print (v[NR / 2] + v[NR / 2 + 1]) / 2 }'; }
  # Runs "$@" and appends "wall cpu" to the file $1 ($2... is the command); its output goes to $tmp/out.
  timed() {
    local file=$1; shift
    local t0 t1
    t0=$(date +%s.%N)
    if ! /usr/bin/time -f '%U %S' -o "$tmp/cpu" "$@" >"$tmp/out" 2>&1; then
      echo "povray-compare: '$*' failed:" >&2
      cat "$tmp/out" >&2
      exit 1
    fi
    t1=$(date +%s.%N)
    awk -v a="$t0" -v b="$t1" -v c="$(awk '{ print $1 + $2 }' "$tmp/cpu")" 'BEGIN { print b - a, c }' >>"$file"
  }
  printf '%-12s %-9s %-8s %3s %2s  %9s %9s %9s  %8s %8s %9s  %9s %9s' scene size spp threads n "POV wall" "our wall" "ours/POV" \
    "POV cpu" "our cpu" "cpu ratio" "POV trace" "our render"
  [[ -n "$base_bin" ]] && printf '  %9s %9s %9s %10s' "base wall" "base/POV" "base cpu" "base rend"
  printf '\n'
  # pov file | our scene | width | height
  for row in "fiveballs fiveballs 640 480" "twospheres twospheres 640 480" "twospheres twospheres 1280 720"; do
    read -r pov ours w h <<<"$row"
    rm -f "$tmp/pov" "$tmp/ours" "$tmp/povtrace" "$tmp/ourrender" "$tmp/base" "$tmp/baserender"
    for ((r = 0; r < ROUNDS; r++)); do
      (cd "$tmp" && timed "$tmp/pov" povray "+I$scenes/$pov.pov" "+O$tmp/$pov.png" "+W$w" "+H$h" -D +A0.0 +AM1 +R4 -J \
        "+WT$THREADS" File_Gamma=2.2 +FN Declare=MTL=13)
      sed -n 's/.*Trace Time:.*(\([0-9.]*\) seconds).*/\1/p' "$tmp/out" | tail -1 >>"$tmp/povtrace"
      timed "$tmp/ours" "$grcis_bin" render "$ours" --size "${w}x$h" --spp 16 --threads "$THREADS" -o "$tmp/$ours.png"
      # "wrote FILE: 640x480, spp 16, seed 0, 0.38 s, ..." : the render's own time
      sed -n 's/^wrote .*, \([0-9.]*\) s, .*/\1/p' "$tmp/out" | tail -1 >>"$tmp/ourrender"
      if [[ -n "$base_bin" ]]; then
        timed "$tmp/base" "$base_bin" render "$ours" --size "${w}x$h" --spp 16 --threads "$THREADS" -o "$tmp/$ours-base.png"
        sed -n 's/^wrote .*, \([0-9.]*\) s, .*/\1/p' "$tmp/out" | tail -1 >>"$tmp/baserender"
      fi
    done
    pw=$(cut -d' ' -f1 "$tmp/pov" | median); pc=$(cut -d' ' -f2 "$tmp/pov" | median)
    ow=$(cut -d' ' -f1 "$tmp/ours" | median); oc=$(cut -d' ' -f2 "$tmp/ours" | median)
    pt=$(median <"$tmp/povtrace"); orr=$(median <"$tmp/ourrender")
    printf '%-12s %-9s %-8s %3s %2s  %8.2fs %8.2fs %9.2f  %7.2fs %7.2fs %9.2f  %8.2fs %8.2fs' "$pov" "${w}x$h" "17 vs 16" \
      "$THREADS" "$ROUNDS" "$pw" "$ow" "$(awk -v a="$ow" -v b="$pw" 'BEGIN { print a / b }')" "$pc" "$oc" \
      "$(awk -v a="$oc" -v b="$pc" 'BEGIN { print a / b }')" "$pt" "$orr"
    if [[ -n "$base_bin" ]]; then
      bw=$(cut -d' ' -f1 "$tmp/base" | median); bc=$(cut -d' ' -f2 "$tmp/base" | median); br=$(median <"$tmp/baserender")
      printf '  %8.2fs %9.2f %8.2fs %9.2fs' "$bw" "$(awk -v a="$bw" -v b="$pw" 'BEGIN { print a / b }')" "$bc" "$br"
    fi
    printf '\n'
  done
  exit 0
fi

dotnet build "$repo/src/GrCis.Cli" -c Release -v q -nologo >/dev/null
grcis=(dotnet "$repo/src/GrCis.Cli/bin/Release/net10.0/grcis.dll")

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
