#!/usr/bin/python3
"""Solver peer: the book's centered scheme for the pendulum with quadratic
drag as a Python loop (pendulum_scene.solve), timed without the imports.

  solver_loop.py --steps 1000000

Prints steps/s and the last value on stderr (so a run can be checked).
"""
import argparse
import os
import sys
import time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import pendulum_scene as scene  # noqa: E402


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--steps", type=int, default=1000000)
    args = parser.parse_args()
    start = time.perf_counter()
    u, _ = scene.solve(args.steps)
    took = time.perf_counter() - start
    print("solver_loop: %d steps in %.3f s, %.0f steps/s (%.3f us/step), u[-1] = %.6e"
          % (args.steps, took, args.steps / took, 1e6 * took / args.steps, u[-1]), file=sys.stderr)


if __name__ == "__main__":
    main()
