#!/usr/bin/env bash
# A storyboard against x264 alone on the same frames: the example lecture
# (cards, a paced pendulum, a three-scheme comparison) rendered as MP4, then
# its frames, decoded to raw YUV in memory, encoded by the ffmpeg CLI with
# vibra's x264 settings. The two alternate, REPEAT=5 rounds, so that a busy
# moment slows both alike; prints frames/s of both (medians) and the ratio.
#
#   bench/lecture_bench.sh [STORYBOARD] [WxH]   (default examples/damped_pendulum_lecture.toml, 1280x720)
set -euo pipefail
cd "$(dirname "$0")/.."
STORY=${1:-examples/damped_pendulum_lecture.toml}
DIMS=${2:-1280x720}
VIBRA=${VIBRA:-build/vibra}
REPEAT=${REPEAT:-5}
WORK=$(mktemp -d /dev/shm/vibra_lecture_bench.XXXXXX 2>/dev/null || mktemp -d)
trap 'rm -rf "$WORK"' EXIT
X264=(-c:v libx264 -preset veryfast -x264-params bframes=0:me=dia:subme=1:8x8dct=0 -crf 23 -g 150 -profile:v high -threads 2)

source bench/wall_time.sh  # seconds, median

ours_run() { "$VIBRA" lecture "$STORY" --size "$DIMS" -q -o "$WORK/lecture.mp4"; }
ours_run >/dev/null 2>&1 || { "$VIBRA" lecture "$STORY" --size "$DIMS" -q -o "$WORK/lecture.mp4"; exit 1; }
ffmpeg -v error -i "$WORK/lecture.mp4" -map 0:v:0 -f rawvideo -pix_fmt yuv420p -y "$WORK/raw.yuv"
w=${DIMS%x*} h=${DIMS#*x}
frames=$(( $(stat -c %s "$WORK/raw.yuv") / (w * h * 3 / 2) ))
fps=$(ffprobe -v error -select_streams v:0 -show_entries stream=r_frame_rate -of csv=p=0 "$WORK/lecture.mp4")
theirs_run() {
  ffmpeg -v error -f rawvideo -pix_fmt yuv420p -s "$DIMS" -r "$fps" -i "$WORK/raw.yuv" "${X264[@]}" -f mp4 -y "$WORK/ceiling.mp4"
}
ours_all="" theirs_all=""
for ((i = 0; i < REPEAT; ++i)); do
  ours_all+="$(seconds ours_run) "
  theirs_all+="$(seconds theirs_run) "
done
ours=$(echo "$ours_all" | median) theirs=$(echo "$theirs_all" | median)
printf "%-48s %8.1f frames/s %8.2f s (%d frames, median of %d)\n" "vibra lecture $(basename "$STORY") $DIMS" \
  "$(echo "$frames / $ours" | bc -l)" "$ours" "$frames" "$REPEAT"
printf "%-48s %8.1f frames/s %8.2f s\n" "ffmpeg CLI x264 encoder only, same frames" "$(echo "$frames / $theirs" | bc -l)" "$theirs"
printf "  -> the lecture reaches %.0f%% of the encoder alone\n" "$(echo "100 * $theirs / $ours" | bc -l)"
