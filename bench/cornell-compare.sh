#!/usr/bin/env bash
# Our path tracer against Blender Cycles on the Cornell boxes of the shared benchmark folder
# (bench/cornell there: specification, cycles_cornell.py, pfm_error.py), on one machine, same
# thread count, alternating the two renderers. Prints a TSV:
#   variant  renderer  spp  render_s  rmse  rmse_le1  mean_lum
# render_s: Cycles' own render-call time (CORNELL_RENDER_SECONDS); ours: the render time grcis
# prints (scene set-up excluded, like Cycles' figure). rmse: all pixels and channels against the
# reference; rmse_le1: only pixels whose reference is <= 1 (pfm_error.py --exclude-above 1).
# The reference is Cycles at REF_SPP with seed 1000 (test renders use seed 0), rendered once and kept
# in OUTDIR. Settings through the environment (defaults in brackets):
#   THREADS [2]  SPP ["16 64 256"]  REF_SPP [8192, the reference issue 26 names]  VARIANTS ["diffuse spheres"]
#   OUTDIR [bench/results/cornell-work]  CORNELL_DIR [../shared/bench/cornell beside the repository]
#   OURS_EXTRA_SPP [1024] (one more of ours, for its converged mean; empty: none)
#   REPEAT [1] (renders per renderer and sample count, alternating; render_s is their median, all in times)
# SPP values are squares (an n×n grid per pixel; grcis rounds others up). Tables from the TSV:
#   python3 bench/cornell-table.py results.tsv
set -euo pipefail

THREADS=${THREADS:-2}
SPP=${SPP:-"16 64 256"}
REF_SPP=${REF_SPP:-8192}
VARIANTS=${VARIANTS:-"diffuse spheres"}
OURS_EXTRA_SPP=${OURS_EXTRA_SPP-1024}
REPEAT=${REPEAT:-1}
here=$(cd "$(dirname "$0")" && pwd)
repo=$(dirname "$here")
OUTDIR=${OUTDIR:-$repo/bench/results/cornell-work}
cornell=${CORNELL_DIR:-}
if [[ -z "$cornell" ]]; then
  for d in "$repo/../shared/bench/cornell" "$repo/../../shared/bench/cornell"; do
    if [[ -f "$d/cycles_cornell.py" ]]; then cornell=$(cd "$d" && pwd); break; fi
  done
fi
[[ -n "$cornell" && -f "$cornell/cycles_cornell.py" ]] || { echo "cornell-compare: set CORNELL_DIR to the folder with cycles_cornell.py" >&2; exit 2; }
command -v blender >/dev/null 2>&1 || { echo "cornell-compare: needs Blender (Debian package blender)" >&2; exit 2; }
mkdir -p "$OUTDIR"

# MSBuild reads environment variables as properties: OUTDIR would become its OutDir.
env -u OUTDIR dotnet build "$repo/src/GrCis.Cli" -c Release -v q -nologo >/dev/null
grcis=(dotnet "$repo/src/GrCis.Cli/bin/Release/net10.0/grcis.dll")

cycles() {  # variant spp seed out.pfm -> prints render seconds
  local log="${4%.pfm}.log"
  blender -b --factory-startup -t "$THREADS" --python "$cornell/cycles_cornell.py" -- \
    --variant "cornell-$1" --spp "$2" --threads "$THREADS" --seed "$3" --out "$4" > "$log" 2>&1 ||
    { echo "cornell-compare: Cycles failed, see $log" >&2; exit 1; }
  sed -n 's/^CORNELL_RENDER_SECONDS //p' "$log"
}

ours() {  # variant spp out.pfm -> prints render seconds
  "${grcis[@]}" render "$repo/scripts/CornellBox.cs" --param "variant=$1" --algorithm path --size 256x256 \
    --spp "$2" --threads "$THREADS" --seed 0 -o "$3" -q | sed -n 's/.*, \([0-9.]*\) s, .*/\1/p'
}

errors() {  # ref test -> "rmse rmse_le1 mean_lum"
  local all le1
  all=$(python3 "$cornell/pfm_error.py" "$1" "$2" --tsv)
  le1=$(python3 "$cornell/pfm_error.py" "$1" "$2" --tsv --exclude-above 1)
  echo "$(echo "$all" | cut -f1) $(echo "$le1" | cut -f1) $(echo "$all" | cut -f4)"
}

median() {  # numbers... -> their median (the lower middle one of an even count)
  printf '%s\n' "$@" | sort -g | sed -n "$(( ($# + 1) / 2 ))p"
}

printf 'variant\trenderer\tspp\trender_s\trmse\trmse_le1\tmean_lum\ttimes\n'
for v in $VARIANTS; do
  ref="$OUTDIR/$v-ref-$REF_SPP.pfm"
  if [[ ! -f "$ref" ]]; then
    echo "cornell-compare: rendering the Cycles reference $v at $REF_SPP spp (seed 1000)" >&2
    cycles "$v" "$REF_SPP" 1000 "$ref" >/dev/null
  fi
  printf '%s\treference\t%s\t-\t-\t-\t%s\t-\n' "$v" "$REF_SPP" "$(python3 "$cornell/pfm_error.py" "$ref" "$ref" --tsv | cut -f3)"
  for s in $SPP; do
    # Both are seeded, so the repeats give the same image; only their times differ.
    tc=(); to=()
    for ((r = 0; r < REPEAT; r++)); do
      tc+=("$(cycles "$v" "$s" 0 "$OUTDIR/$v-cycles-$s.pfm")")
      to+=("$(ours "$v" "$s" "$OUTDIR/$v-ours-$s.pfm")")
    done
    read -r e1 e2 m <<< "$(errors "$ref" "$OUTDIR/$v-cycles-$s.pfm")"
    printf '%s\tcycles\t%s\t%s\t%s\t%s\t%s\t%s\n' "$v" "$s" "$(median "${tc[@]}")" "$e1" "$e2" "$m" "${tc[*]}"
    read -r e1 e2 m <<< "$(errors "$ref" "$OUTDIR/$v-ours-$s.pfm")"
    printf '%s\tours\t%s\t%s\t%s\t%s\t%s\t%s\n' "$v" "$s" "$(median "${to[@]}")" "$e1" "$e2" "$m" "${to[*]}"
  done
  if [[ -n "$OURS_EXTRA_SPP" ]]; then
    t=$(ours "$v" "$OURS_EXTRA_SPP" "$OUTDIR/$v-ours-$OURS_EXTRA_SPP.pfm")
    read -r e1 e2 m <<< "$(errors "$ref" "$OUTDIR/$v-ours-$OURS_EXTRA_SPP.pfm")"
    printf '%s\tours\t%s\t%s\t%s\t%s\t%s\t%s\n' "$v" "$OURS_EXTRA_SPP" "$t" "$e1" "$e2" "$m" "$t"
  fi
done
