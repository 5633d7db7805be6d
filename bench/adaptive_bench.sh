#!/usr/bin/env bash
# Adaptive Dormand-Prince 5(4) on a long pendulum, to CSV: vibra's dopri5
# beside SciPy's solve_ivp(method="RK45") (bench/peers/solve_ivp_pendulum.py),
# the same pair at the same tolerances, as whole processes (start-up
# included), fastest of 3 runs by wall and by CPU time (user + sys).
#
#   bench/adaptive_bench.sh [PERIODS] [RTOL]    (defaults 1000 and 1e-8)
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/setup --bench >/dev/null  # the peers' packages, and a current build
PERIODS=${1:-1000}
RTOL=${2:-1e-8}
ATOL=1e-9
VIBRA=${VIBRA:-build/vibra}
PEERS=${PEERS:-bench/peers}
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT

# fastest NAME COMMAND...: the best wall and CPU (user + sys) seconds of 3
# runs of the whole process, in WALL and CPU.
fastest() {
  local name=$1 wall=1e9 cpu=1e9 times; shift
  for _ in 1 2 3; do
    /usr/bin/time -f "%e %U %S" -o "$out/time" "$@" 2>/dev/null
    read -r times < <(awk '{print $1, $2 + $3}' "$out/time")
    wall=$(echo "$times" | awk -v best="$wall" '{print ($1 < best) ? $1 : best}')
    cpu=$(echo "$times" | awk -v best="$cpu" '{print ($2 < best) ? $2 : best}')
  done
  WALL=$wall CPU=$cpu
  printf "%-8s %8.3f s wall %8.3f s CPU %10d rows\n" "$name" "$wall" "$cpu" "$(($(wc -l <"$out/$name.csv") - 1))"
}

fastest vibra "$VIBRA" solve pendulum --set alpha=0 --set scheme=dopri5 --set rtol="$RTOL" --set atol="$ATOL" \
  --set periods="$PERIODS" -q -o "$out/vibra.csv"
our_wall=$WALL our_cpu=$CPU
fastest scipy /usr/bin/python3 "$PEERS/solve_ivp_pendulum.py" --periods "$PERIODS" --rtol "$RTOL" --atol "$ATOL" \
  --out "$out/scipy.csv"
printf "  -> %s periods at rtol %s: vibra dopri5 is %.0fx faster in wall time, %.0fx in CPU time than solve_ivp RK45\n" \
  "$PERIODS" "$RTOL" "$(echo "$WALL / $our_wall" | bc -l)" "$(echo "$CPU / $our_cpu" | bc -l)"
# The two runs take about the same steps and land on the same angle.
printf "  last rows: vibra %s\n             scipy %s\n" "$(tail -1 "$out/vibra.csv")" "$(tail -1 "$out/scipy.csv")"
