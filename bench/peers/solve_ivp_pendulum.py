#!/usr/bin/python3
"""Adaptive-solver peer: SciPy's solve_ivp(method="RK45"), the Dormand-Prince
5(4) pair that vibra's dopri5 implements, on the scaled pendulum without drag
theta'' = -sin(theta), theta(0) = 70 degrees, omega(0) = 0, writing every
accepted step as CSV with the columns of `vibra solve pendulum`:
t, theta, omega, S = omega^2 + cos(theta), D = 0.

  solve_ivp_pendulum.py --periods 1000 --rtol 1e-8 --atol 1e-9 --out FILE.csv

vibra's counterpart:
  vibra solve pendulum --set alpha=0 --set scheme=dopri5 --set rtol=1e-8 \\
      --set atol=1e-9 --set periods=1000 -o FILE.csv
Prints the step count and the last angle on stderr (so a run can be checked).
"""
import argparse
import math
import sys

import numpy as np
from scipy.integrate import solve_ivp


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--periods", type=float, default=1000)
    parser.add_argument("--rtol", type=float, default=1e-8)
    parser.add_argument("--atol", type=float, default=1e-9)
    parser.add_argument("--out", required=True)
    args = parser.parse_args()

    def rhs(_t, y):
        return [y[1], -math.sin(y[0])]

    T = 2 * math.pi * args.periods  # the small-oscillation period is 2 pi
    solution = solve_ivp(rhs, (0, T), [math.radians(70), 0.0], method="RK45", rtol=args.rtol, atol=args.atol)
    theta, omega = solution.y
    table = np.column_stack([solution.t, theta, omega, omega * omega + np.cos(theta), np.zeros_like(theta)])
    with open(args.out, "w") as out:
        out.write("t,theta,omega,S,D\n")
        np.savetxt(out, table, fmt="%.17g", delimiter=",")
    print("solve_ivp_pendulum: %d steps, theta(T) = %.9f" % (len(solution.t) - 1, theta[-1]), file=sys.stderr)


if __name__ == "__main__":
    main()
