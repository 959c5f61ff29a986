#!/usr/bin/env bash
# Window smoke test: runs the real game under a virtual display, fires a scripted shot and checks the screenshot
# is a real 1280x720 frame. Usage: play_smoke.sh ABALIKE OUT_DIR [play arguments...]
# ABALIKE_SMOKE_FRAMES sets how many frames it plays (default 240). The display is xvfb.sh's, beside this script.
set -euo pipefail
abalike="$1"
out="$2"
shift 2
mkdir -p "$out"
png="$out/frame-$$.png"
rm -f "$png"
"$(dirname "$0")/xvfb.sh" 1280x720 "$abalike" play "$@" --frames "${ABALIKE_SMOKE_FRAMES:-240}" --screenshot "$png" --size 1280x720
[[ -s "$png" ]] || { echo "no screenshot written"; exit 1; }
# PNG signature, then IHDR width and height as big-endian 32-bit numbers at bytes 16..23.
signature=$(od -An -tx1 -N8 "$png" | tr -d ' \n')
[[ "$signature" == "89504e470d0a1a0a" ]] || { echo "not a PNG: $signature"; exit 1; }
size=$(od -An -tu1 -j16 -N8 "$png" | tr -s ' ' | sed 's/^ //')
read -r w1 w2 w3 w4 h1 h2 h3 h4 <<<"$size"
width=$(((w1 << 24) | (w2 << 16) | (w3 << 8) | w4))
height=$(((h1 << 24) | (h2 << 16) | (h3 << 8) | h4))
[[ $width -eq 1280 && $height -eq 720 ]] || { echo "screenshot is ${width}x${height}, expected 1280x720"; exit 1; }
# A drawn frame (sky, ground, bodies, text) compresses to tens of kB; a blank one to almost nothing.
bytes=$(stat -c %s "$png")
[[ $bytes -gt 30000 ]] || { echo "screenshot is only $bytes bytes: nothing drawn?"; exit 1; }
echo "ok: ${width}x${height}, $bytes bytes"
