#!/usr/bin/env bash
# ASCII line-by-line plotter: lines per second to /dev/null and peak memory,
# beside the same plotter in Python (ascii_lines.py), in one run.
#
#   bench/ascii_bench.sh [STEPS] [PEER_STEPS]    (defaults 1e7 and 1e6)
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/setup --bench >/dev/null  # the peers' packages, and a current build
STEPS=${1:-10000000}
PEER_STEPS=${2:-1000000}
VIBRA=${VIBRA:-build/vibra}
PEERS=${PEERS:-bench/peers}
mem=$(mktemp)
trap 'rm -f "$mem"' EXIT

# run NAME LINES COMMAND...: lines/s and peak memory of the whole process.
run() {
  local name=$1 lines=$2; shift 2
  local start end
  start=$(date +%s.%N)
  /usr/bin/time -f %M -o "$mem" "$@" >/dev/null 2>/dev/null
  end=$(date +%s.%N)
  LAST=$(echo "$lines / ($end - $start)" | bc -l)
  printf "%-52s %12d lines %12.0f lines/s %8d KiB peak\n" "$name" "$lines" "$LAST" "$(tail -1 "$mem")"
}

SCENE=(--set Theta=40 --set alpha=0.8 --set "dt=2*pi/60" --set scheme=centered --width 60)
run "vibra ascii pendulum (1/100 of the steps)" $((STEPS / 100)) "$VIBRA" ascii pendulum "${SCENE[@]}" --set "T=$((STEPS / 100 - 1))*2*pi/60"
run "vibra ascii pendulum" "$STEPS" "$VIBRA" ascii pendulum "${SCENE[@]}" --set "T=$((STEPS - 1))*2*pi/60"
ours=$LAST
run "Python ascii_lines.py" "$PEER_STEPS" /usr/bin/python3 "$PEERS/ascii_lines.py" --steps "$PEER_STEPS" --width 60
printf "  -> vibra / Python = %.0fx lines/s (target 50x); memory is flat if the two vibra rows match\n" "$(echo "$ours / $LAST" | bc -l)"
