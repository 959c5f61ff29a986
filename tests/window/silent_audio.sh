#!/usr/bin/env bash
# Silent sound: plays a shot that breaks blocks (launch, impacts, breaks and the end of the level all ask for
# sounds) with no audio device, once with sound left on and once with ABALIKE_AUDIO=off. Both must exit 0 and
# print nothing from OpenAL or SFML's audio module on stderr. Usage: silent_audio.sh ABALIKE OUT_DIR LEVEL
# (each under a display of its own: xvfb.sh, beside this script).
set -euo pipefail
abalike="$1"
out="$2"
level="$3"
mkdir -p "$out"
for mode in default off; do
    err="$out/silent-audio-$mode-$$.err"
    if [[ $mode == off ]]; then
        env ABALIKE_AUDIO=off "$(dirname "$0")/xvfb.sh" 1280x720 "$abalike" play "$level" --shot 30,16 \
            --frames 400 --size 1280x720 2>"$err" >/dev/null
    else
        env -u ABALIKE_AUDIO -u ALSOFT_LOGLEVEL "$(dirname "$0")/xvfb.sh" 1280x720 "$abalike" play "$level" \
            --shot 30,16 --frames 400 --size 1280x720 2>"$err" >/dev/null
    fi
    if grep -qiE 'AL lib|ALSA|openal|alc|sound|audio' "$err"; then
        echo "audio messages on stderr with sound $mode:"
        head -20 "$err"
        exit 1
    fi
    lines=$(wc -l <"$err")
    [[ $lines -le 2 ]] || { echo "stderr has $lines lines with sound $mode:"; head -20 "$err"; exit 1; }
    rm -f "$err"
    echo "ok: sound $mode, quiet"
done
