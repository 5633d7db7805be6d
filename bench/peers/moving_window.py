#!/usr/bin/python3
"""Moving-window peer: the pendulum's angle u(t) drawn up to the current step
in a window of --window periods that scrolls with time, one PNG per frame
(the book's moving plot window, in matplotlib): the line's data and the
x limits change each frame; axes, ticks and the title are redrawn by savefig.

  moving_window.py --frames 300 --size 720p|1080p --window 4 [--stride 1] --out DIR

Frame i shows the steps up to i*stride + 1. Prints frames/s on stderr.
"""
import argparse
import math
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import pendulum_scene as scene  # noqa: E402


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--frames", type=int, default=300)
    parser.add_argument("--size", choices=scene.SIZES, default="720p")
    parser.add_argument("--window", type=float, default=4.0, help="window width in periods (2 pi)")
    parser.add_argument("--stride", type=int, default=1, help="time steps per frame")
    parser.add_argument("--out", default="frames_window")
    args = parser.parse_args()
    width, height = scene.SIZES[args.size]
    u, t = scene.solve(args.frames * args.stride + 1)
    fig, ax = scene.figure(width, height)
    ax.set_position([0.08, 0.1, 0.88, 0.82])
    ax.set_axis_on()
    limit = 1.2 * abs(u).max()
    ax.set_ylim(-limit, limit)
    ax.set_xlabel("t")
    ax.set_ylabel("u")
    (line,) = ax.plot([], [], "r-")
    window = args.window * 2 * math.pi

    def draw(i):
        n = i * args.stride + 1
        left = max(0.0, t[n] - window)
        first = int(left / scene.DT)
        line.set_data(t[first:n + 1], u[first:n + 1])
        ax.set_xlim(left, max(window, t[n]))
        ax.set_title("t=%6.3f" % t[n])

    scene.save_png_frames(fig, draw, args.frames, args.out, "moving_window")

if __name__ == "__main__":
    main()
