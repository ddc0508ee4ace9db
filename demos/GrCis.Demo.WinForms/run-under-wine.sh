#!/usr/bin/env bash
# Publishes the demo for win-x64 (WinForms from the runtime pack), runs it under Wine on Xvfb,
# clicks Render and takes a screenshot. Needs: apt-get install wine xvfb xdotool imagemagick.
# Usage: demos/GrCis.Demo.WinForms/run-under-wine.sh [screenshot.png [demo arguments: -dir, -scene, -nodefault]]
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
out="${TMPDIR:-/tmp}/grcis-demo-win-x64"
shot="${1:-$PWD/grcis-demo-wine.png}"
[ $# -gt 0 ] && shift
display=":77"
export WINEPREFIX="${WINEPREFIX:-${TMPDIR:-/tmp}/grcis-wine-prefix}" WINEDEBUG=-all
# Without this the CLR dies under Wine 8 on the first render ("Internal CLR error (0x80131506)" in a finalizer).
export DOTNET_EnableWriteXorExecute=0

dotnet publish "$here" -c Release -p:WinFormsFromRuntimePack=true --self-contained -o "$out"

Xvfb "$display" -screen 0 1280x900x24 &
xvfb=$!
trap 'kill "$app" 2>/dev/null || true; wineserver -k 2>/dev/null || true; kill "$xvfb" 2>/dev/null || true' EXIT
sleep 2
export DISPLAY="$display"
[ -d "$WINEPREFIX" ] || wine wineboot --init
wine "$out/grcis-demo.exe" "$@" &
app=$!
sleep 20                      # first start of the runtime under Wine is slow
# No window manager on Xvfb: focus the window directly; Enter is the form's accept button (Render).
win="$(xdotool search --sync --name "GrCis ray tracing demo" | head -1)"
xdotool windowfocus --sync "$win" key --window "$win" Return
sleep 12
import -window root "$shot"
echo "screenshot: $shot"
