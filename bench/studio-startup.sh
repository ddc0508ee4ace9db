#!/bin/bash
# Time to the first answered /api/status of `grcis studio`, and the CPU seconds (user + system of grcis studio and
# its children) spent by then, for two builds alternated in each round (the machine may be loaded: compare medians).
# usage: bench/studio-startup.sh BEFORE_DIR AFTER_DIR [ROUNDS]   (each DIR holds a built grcis.dll)
set -eu
before=$1; after=$2; rounds=${3:-7}
once() {
  local dll=$1/grcis.dll tmp; tmp=$(mktemp -d)
  local start end pid ticks=0 url base tok
  start=$(date +%s.%N)
  dotnet exec "$dll" studio --no-open --port 0 --nodefault > "$tmp/url" 2> "$tmp/err" &
  pid=$!
  while ! [ -s "$tmp/url" ]; do sleep 0.02; done
  url=$(head -1 "$tmp/url"); base=${url%%/?token=*}; tok=${url##*token=}
  until curl -sf -H "X-GrCis-Token: $tok" "$base/api/status" > /dev/null; do sleep 0.02; done
  end=$(date +%s.%N)
  for p in $pid $(pgrep -P $pid || true); do read -r -a f < /proc/$p/stat; ticks=$((ticks + f[13] + f[14])); done
  kill -TERM $pid; wait $pid 2> /dev/null || true; rm -rf "$tmp"
  echo "$(echo "$end - $start" | bc) $(echo "scale=2; $ticks / $(getconf CLK_TCK)" | bc)"
}
for i in $(seq "$rounds"); do
  if (( i % 2 )); then b=$(once "$before"); a=$(once "$after"); else a=$(once "$after"); b=$(once "$before"); fi
  echo "round $i  before: $b  after: $a  (wall s, CPU s)"
done
