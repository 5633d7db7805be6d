#!/usr/bin/env bash
# GNU parallel renders three segments on this machine's cores and vibra concat
# joins them: the result decodes to exactly the one-pass render's frames. A
# second run with --skip-existing renders nothing.
#   tests/scale_out/parallel_segments_test.sh path/to/vibra
set -euo pipefail
VIBRA=$(realpath "$1")
source "$(dirname "$0")/common.sh"
command -v parallel >/dev/null || missing "GNU parallel is not installed: install the Debian package parallel (scripts/setup does)"
WORK=$(mktemp -d "${TMPDIR:-/tmp}/vibra_parallel.XXXXXX")
trap 'rm -rf "$WORK"' EXIT

"$VIBRA" render "${RENDER_ARGS[@]}" -q -o "$WORK/whole.mp4"
mkdir "$WORK/parts"
parallel --halt now,fail=1 -j2 "$VIBRA" render "${RENDER_ARGS[@]}" -q --segment {}/3 -o "$WORK/parts/lecture.mp4" ::: 0 1 2
[ "$(ls "$WORK/parts" | wc -l)" -eq 3 ] || fail "expected three segment files, got: $(ls "$WORK/parts")"
"$VIBRA" concat -q "$WORK"/parts/lecture.seg-*-of-3.mp4 -o "$WORK/lecture.mp4"
check_same_frames "$WORK/lecture.mp4" "$WORK/whole.mp4"

# A rerun (a requeued task) finds each segment complete and renders nothing.
before=$(stat -c %Y.%i "$WORK"/parts/*)
messages=$(parallel -j2 "$VIBRA" render "${RENDER_ARGS[@]}" --skip-existing --segment {}/3 -o "$WORK/parts/lecture.mp4" \
           ::: 0 1 2 2>&1)
[ "$(grep -c 'is already complete: skipped' <<<"$messages")" -eq 3 ] || fail "--skip-existing rendered again: $messages"
[ "$(stat -c %Y.%i "$WORK"/parts/*)" = "$before" ] || fail "--skip-existing rewrote a segment"
echo "ok: --skip-existing skipped the three complete segments"
