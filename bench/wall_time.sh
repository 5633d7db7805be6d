# Sourced by the bench scripts: wall times of whole runs, alone or in alternating pairs, as medians with their range. Needs WORK (a scratch folder).
#
# A single run on a shared machine swings by 15% or more, and a busy moment
# slows whatever runs in it: so two commands are timed in turn, A B A B ...
# (REPEAT rounds, default 5), and each ratio is taken pair by pair before its
# median is quoted, with the smallest and largest beside it.

seconds() {  # seconds COMMAND...: wall time of one run; a program's peak memory (KiB) goes to $WORK/peak, the largest so far
  local start end
  start=$(date +%s.%N)
  if declare -F "$1" >/dev/null; then  # a shell function: timed as it is (its programs' memory is not seen)
    "$@" >/dev/null 2>"$WORK/err" || { echo "$1: FAILED" >&2; cat "$WORK/err" >&2; exit 1; }
  else
    /usr/bin/time -f %M -o "$WORK/mem" "$@" >/dev/null 2>"$WORK/err" || { echo "$1: FAILED" >&2; cat "$WORK/err" >&2; exit 1; }
    local kib; kib=$(tail -1 "$WORK/mem")
    [ -s "$WORK/peak" ] && [ "$(cat "$WORK/peak")" -ge "$kib" ] || echo "$kib" >"$WORK/peak"
  fi
  end=$(date +%s.%N)
  echo "$end - $start" | bc -l
}
median() { tr ' ' '\n' | grep . | sort -g | awk '{a[NR] = $1} END {print a[int((NR + 1) / 2)]}'; }
smallest() { tr ' ' '\n' | grep . | sort -g | head -1; }
largest() { tr ' ' '\n' | grep . | sort -g | tail -1; }

# alone LABEL FRAMES COMMAND...: REPEAT runs; prints frames/s as median (min-max), the median time and
# (for a program, not a function) the peak memory.
# Sets MEDIAN_FPS and PEAK_KIB.
alone() {
  local label=$1 frames=$2; shift 2
  local times="" rates=""
  rm -f "$WORK/peak"
  for ((i = 0; i < ${REPEAT:-5}; ++i)); do
    local t; t=$(seconds "$@")
    times+="$t " rates+="$(echo "$frames / $t" | bc -l) "
  done
  MEDIAN_FPS=$(echo "$rates" | median) PEAK_KIB=$(cat "$WORK/peak" 2>/dev/null || echo 0)
  local peak=""  # a shell function's programs are not measured: no figure rather than 0
  [ "$PEAK_KIB" -gt 0 ] && peak=$(printf " %8d KiB peak" "$PEAK_KIB")
  printf "%-52s %8.1f frames/s (%.1f-%.1f) %7.2f s%s\n" "$label" "$MEDIAN_FPS" "$(echo "$rates" | smallest)" \
    "$(echo "$rates" | largest)" "$(echo "$times" | median)" "$peak"
}

# pair FRAMES LABEL_A FUNCTION_A LABEL_B FUNCTION_B: A and B in turn, REPEAT rounds. Prints each one's
# frames/s as median (min-max), then A's speed over B's, pair by pair: median (min-max).
# Sets PAIR_RATIO (that median), FPS_A and FPS_B.
pair() {
  local frames=$1 label_a=$2 run_a=$3 label_b=$4 run_b=$5
  local rates_a="" rates_b="" ratios=""
  for ((i = 0; i < ${REPEAT:-5}; ++i)); do
    local a b
    a=$(seconds "$run_a")
    b=$(seconds "$run_b")
    rates_a+="$(echo "$frames / $a" | bc -l) " rates_b+="$(echo "$frames / $b" | bc -l) " ratios+="$(echo "$b / $a" | bc -l) "
  done
  FPS_A=$(echo "$rates_a" | median) FPS_B=$(echo "$rates_b" | median) PAIR_RATIO=$(echo "$ratios" | median)
  printf "%-52s %8.1f frames/s (%.1f-%.1f)\n" "$label_a" "$FPS_A" "$(echo "$rates_a" | smallest)" "$(echo "$rates_a" | largest)"
  printf "%-52s %8.1f frames/s (%.1f-%.1f)\n" "$label_b" "$FPS_B" "$(echo "$rates_b" | smallest)" "$(echo "$rates_b" | largest)"
  printf "  -> %s: %.2fx (%.2f-%.2f), median of %d alternating pairs\n" "${PAIR_SAYS:-first / second}" "$PAIR_RATIO" \
    "$(echo "$ratios" | smallest)" "$(echo "$ratios" | largest)" "${REPEAT:-5}"
}
