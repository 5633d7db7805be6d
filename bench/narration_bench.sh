#!/usr/bin/env bash
# What narration costs a lecture: the narrated example (flite speech, AAC)
# against its silent twin, the same storyboard with the narration keys taken
# out and every shot given the seconds its speech gave it, so both draw and
# encode the same frames. The two alternate, REPEAT=5 rounds; prints both
# medians and narration's share of the narrated render.
#
#   bench/narration_bench.sh [STORYBOARD] [WxH]   (default examples/damped_pendulum_narrated.toml, 1280x720)
set -euo pipefail
cd "$(dirname "$0")/.."
STORY=${1:-examples/damped_pendulum_narrated.toml}
DIMS=${2:-1280x720}
VIBRA=${VIBRA:-build/vibra}
REPEAT=${REPEAT:-5}
WORK=$(mktemp -d /dev/shm/vibra_narration_bench.XXXXXX 2>/dev/null || mktemp -d)
trap 'rm -rf "$WORK"' EXIT

source bench/wall_time.sh  # seconds, median

"$VIBRA" lecture "$STORY" --size "$DIMS" -q -o "$WORK/spoken.mp4"
ffprobe -v error -show_entries chapter=start_time,end_time -of csv=p=0 "$WORK/spoken.mp4" >"$WORK/chapters.csv"
# The silent twin: no say, voice, audio or fit; notes as plain strings; each shot its chapter's length.
python3 - "$STORY" "$WORK/chapters.csv" >"$WORK/silent.toml" <<'PY'
import json, sys, tomllib
story = tomllib.load(open(sys.argv[1], "rb"))
lengths = [float(b) - float(a) for a, b in (line.split(",") for line in open(sys.argv[2]) if line.strip())]
def value(v):
    if isinstance(v, dict): return "{ " + ", ".join(f"{k} = {value(x)}" for k, x in v.items()) + " }"
    if isinstance(v, list): return "[" + ", ".join(value(x) for x in v) + "]"
    if isinstance(v, bool): return "true" if v else "false"
    return json.dumps(v)
for key in ("title", "size", "fps"):
    if key in story: print(f"{key} = {value(story[key])}")
for shot, seconds in zip(story["shot"], lengths):
    print("[[shot]]")
    for key in ("say", "voice", "audio", "fit"): shot.pop(key, None)
    if "notes" in shot:
        shot["notes"] = [n if isinstance(n, str) else f"{n['at']}: {n['text']}" for n in shot["notes"]]
    shot["seconds"] = round(seconds, 6)
    for k, v in shot.items(): print(f"{k} = {value(v)}")
PY
spoken_run() { "$VIBRA" lecture "$STORY" --size "$DIMS" -q -o "$WORK/spoken.mp4" --force; }
silent_run() { "$VIBRA" lecture "$WORK/silent.toml" --size "$DIMS" -q -o "$WORK/silent.mp4" --force; }
silent_run
spoken_all="" silent_all=""
for ((i = 0; i < REPEAT; ++i)); do
  spoken_all+="$(seconds spoken_run) "
  silent_all+="$(seconds silent_run) "
done
spoken=$(echo "$spoken_all" | median) silent=$(echo "$silent_all" | median)
frames=$(ffprobe -v error -count_packets -select_streams v:0 -show_entries stream=nb_read_packets -of csv=p=0 "$WORK/spoken.mp4")
printf "%-52s %8.2f s (%d frames, median of %d)\n" "vibra lecture $(basename "$STORY") $DIMS, narrated" "$spoken" "$frames" "$REPEAT"
printf "%-52s %8.2f s\n" "the same shots and lengths, silent" "$silent"
printf "  -> narration adds %.1f%% to the render\n" "$(echo "100 * ($spoken - $silent) / $silent" | bc -l)"
