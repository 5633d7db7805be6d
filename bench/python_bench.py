"""vibra from Python, in one run:
  - vibra.solve of 1e7 pendulum steps against `vibra solve` writing its CSV
    to /dev/null (target: vibra.solve within 1.2x of the command line's time);
  - the peak memory vibra.solve adds against the bytes of the arrays it
    returns (target: no more than 10% above), measured in a fresh process;
  - a pure-Python loop of the same scheme (centered, quadratic drag, the same
    five columns) beside them, on fewer steps, checked against vibra.solve.

    PYTHONPATH=build/python /usr/bin/python3 bench/python_bench.py [--steps N] [--peer-steps N] [--repeat R]
"""

import argparse
import json
import math
import os
import subprocess
import sys
import time

import numpy as np

import vibra

DT = "2*pi/60"
KEYS = dict(scheme="centered", Theta=40, alpha=0.8, dt=DT)


def settings(steps):
    return dict(KEYS, T=f"{steps}*{DT}")


def best_of(repeat, work):
    times = []
    for _ in range(repeat):
        start = time.perf_counter()
        work()
        times.append(time.perf_counter() - start)
    return min(times)


def cli_seconds(exe, steps, repeat):
    args = [exe, "solve", "pendulum"] + [a for k, v in settings(steps).items() for a in ("--set", f"{k}={v}")]
    with open(os.devnull, "wb") as null:
        return best_of(repeat, lambda: subprocess.run(args, stdout=null, check=True))


MEMORY_PROBE = """
import json, os, resource, sys, time
import numpy as np, vibra
keys = json.loads(sys.argv[1])
def rss():
    with open("/proc/self/statm") as f:
        return int(f.read().split()[1]) * os.sysconf("SC_PAGE_SIZE")
before = rss()
run = vibra.solve("pendulum", **keys)
peak = resource.getrusage(resource.RUSAGE_SELF).ru_maxrss * 1024
print(json.dumps({"before": before, "peak": peak, "nbytes": np.asarray(run).nbytes}))
"""


def memory(steps):
    out = subprocess.run([sys.executable, "-c", MEMORY_PROBE, json.dumps(settings(steps))],
                         capture_output=True, text=True, check=True).stdout
    return json.loads(out)


def python_loop(steps, Theta, alpha, dt):
    """The centered scheme for theta'' = -sin(theta) - alpha |theta'| theta'
    (quadratic drag by the geometric mean, first step from the Taylor series),
    and the columns t, theta, omega, S, D, exactly as vibra computes them."""
    t, theta, omega, S, D = ([0.0] * (steps + 1) for _ in range(5))
    dt2, half_inverse_dt = dt * dt, 0.5 / dt
    cur, v0 = Theta, 0.0
    nxt = cur + dt * v0 + 0.5 * dt * dt * (-math.sin(cur) - alpha * abs(v0) * v0)
    prev = nxt - 2 * dt * v0
    for n in range(steps + 1):
        w = (nxt - prev) * half_inverse_dt
        t[n], theta[n], omega[n] = n * dt, cur, w
        S[n] = w * w + math.cos(cur)
        D[n] = -alpha * abs(w) * w
        prev, cur = cur, nxt
        jump = alpha * abs(cur - prev)
        nxt = (2 * cur - prev + jump * cur + dt2 * -math.sin(cur)) / (1 + jump)
    return t, theta, omega, S, D


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--steps", type=int, default=10_000_000)
    parser.add_argument("--peer-steps", type=int, default=1_000_000)
    parser.add_argument("--repeat", type=int, default=3)
    parser.add_argument("--vibra", default=os.environ.get("VIBRA", "build/vibra"))
    o = parser.parse_args()

    steps = o.steps
    ours = best_of(o.repeat, lambda: vibra.solve("pendulum", **settings(steps)))
    cli = cli_seconds(o.vibra, steps, o.repeat)
    print(f"{'vibra.solve pendulum (5 columns into numpy)':<48} {steps:>10} steps {ours:8.3f} s {steps / ours / 1e6:8.1f} M steps/s")
    print(f"{'vibra solve pendulum > /dev/null (CSV)':<48} {steps:>10} steps {cli:8.3f} s {steps / cli / 1e6:8.1f} M steps/s")
    print(f"  -> vibra.solve / command line = {ours / cli:.2f}x the time (target <= 1.2x)")

    m = memory(steps)
    added = m["peak"] - m["before"]
    print(f"{'peak memory added by vibra.solve':<48} {added / 2**20:10.1f} MiB for arrays of {m['nbytes'] / 2**20:.1f} MiB"
          f" -> {added / m['nbytes'] - 1:+.1%} (target <= +10%)")

    dt = 2 * math.pi / 60
    start = time.perf_counter()
    columns = python_loop(o.peer_steps, math.radians(40), 0.8, dt)
    peer = time.perf_counter() - start
    reference = vibra.solve("pendulum", **settings(o.peer_steps))
    difference = max(float(np.max(np.abs(np.asarray(c) - reference[name])))
                     for c, name in zip(columns, reference.columns))
    print(f"{'pure-Python loop, same scheme and columns':<48} {o.peer_steps:>10} steps {peer:8.3f} s "
          f"{o.peer_steps / peer / 1e6:8.2f} M steps/s (max difference from vibra.solve {difference:.1e})")
    print(f"  -> vibra.solve / Python loop = {(steps / ours) / (o.peer_steps / peer):.0f}x steps/s")


if __name__ == "__main__":
    main()
