# Sourced by the bench scripts: the wall time of one run, and the median of several. Needs WORK (a scratch folder).
seconds() {  # seconds COMMAND...: wall time of one run
  local start end
  start=$(date +%s.%N)
  "$@" >/dev/null 2>"$WORK/err" || { echo "$1: FAILED" >&2; cat "$WORK/err" >&2; exit 1; }
  end=$(date +%s.%N)
  echo "$end - $start" | bc -l
}
median() { tr ' ' '\n' | grep . | sort -g | awk '{a[NR] = $1} END {print a[int((NR + 1) / 2)]}'; }
