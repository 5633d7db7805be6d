# Shared by the scale-out tests: a small render, its one-pass reference, and
# the comparison of decoded frames, and what a missing tool means. Source it
# after setting VIBRA; set WORK (a fresh mktemp -d) before check_same_frames.
RENDER_ARGS=(--set periods=1 --size 320x180 --fps 10 --quality lossless)

# fail and missing: what a failed check and a missing tool mean.
source "$(dirname "${BASH_SOURCE[0]}")/../test_requirements.sh"

# Per-frame MD5s of the decoded pictures with their timestamps (ffmpeg's framemd5).
frame_hashes() { ffmpeg -v error -i "$1" -f framemd5 - | grep -v '^#'; }

# The joined video must decode to the one-pass render's frames, timestamps and all.
check_same_frames() {
  local joined=$1 reference=$2
  [ -s "$joined" ] || fail "$joined was not written"
  frame_hashes "$reference" >"$WORK/reference.md5" || fail "cannot decode $reference"
  frame_hashes "$joined" >"$WORK/joined.md5" || fail "cannot decode $joined"
  local frames; frames=$(wc -l <"$WORK/reference.md5")
  [ "$frames" -gt 10 ] || fail "the reference has only $frames frames"
  diff -q "$WORK/reference.md5" "$WORK/joined.md5" >/dev/null ||
    fail "$joined does not decode to the one-pass render's frames: $(diff "$WORK/reference.md5" "$WORK/joined.md5" | head -4)"
  echo "ok: $joined decodes to the one-pass render's $frames frames"
}
