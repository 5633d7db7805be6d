#!/usr/bin/python3
"""ASCII peer: the line-by-line text plotter in pure Python, one line per
time step written to stdout as soon as it is made: the angle's symbol on a
--width column axis, the zero line marked |, the time at the end of the line
(the book's terminal plotter, without its pause between lines).

  ascii_lines.py --steps 1000000 [--width 60]

Solves the pendulum first (the centered scheme, pendulum_scene.py), then
prints. Prints lines/s on stderr.
"""
import argparse
import os
import sys
import time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import pendulum_scene as scene  # noqa: E402


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--steps", type=int, default=100000)
    parser.add_argument("--width", type=int, default=60)
    args = parser.parse_args()
    u, t = scene.solve(max(args.steps - 1, 1))
    top = 1.2 * abs(u).max()
    bottom = -top
    columns = args.width
    scale = (columns - 1) / (top - bottom)
    zero = int(round(-bottom * scale))
    out = sys.stdout
    start = time.perf_counter()
    for n in range(len(u)):
        line = [" "] * columns
        line[zero] = "|"
        column = int(round((u[n] - bottom) * scale))
        if 0 <= column < columns:
            line[column] = "*"
        out.write("".join(line) + " %.2f\n" % t[n])
    out.flush()
    took = time.perf_counter() - start
    print("ascii_lines: %d lines in %.3f s, %.0f lines/s" % (len(u), took, len(u) / took), file=sys.stderr)


if __name__ == "__main__":
    main()
