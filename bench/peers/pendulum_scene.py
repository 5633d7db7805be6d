"""The scene every peer draws, and the solver every peer runs.

Model, scaled (docs/models.md): theta'' + alpha |theta'| theta' + sin(theta) = 0,
theta(0) = 40 degrees, theta'(0) = 0, alpha = 0.8, dt = 2 pi/60, one frame per
step. This is the scene bench/render_bench.sh asks vibra for.

Solver: the book's centered scheme with quadratic damping by the geometric
mean, (1.82) and its first step (1.84), as a Python loop over numpy arrays
with s(u) and F(t) called as Python functions, the way the book's solver is
written. omega is the centered difference of theta (1.12).

Picture: white canvas, a thick ceiling line, a dashed vertical from the
pivot, the wire, a filled bob, the angle arc with its label, and the forces
mg, S and D as arrows from the bob (forces in units of m g), each labelled.
Coordinates are in units of the canvas height.
"""
import argparse
import math
import os
import sys
import time

import numpy as np

THETA = math.radians(40.0)
ALPHA = 0.8
DT = 2 * math.pi / 60
SIZES = {"720p": (1280, 720), "1080p": (1920, 1080)}


def solve(steps, I=THETA, V=0.0, b=ALPHA, dt=DT):
    """u^0..u^steps and t by the centered scheme (m = 1, s = sin, F = 0)."""
    m = 1.0

    def s(u):
        return math.sin(u)

    def F(t):
        return 0.0

    u = np.zeros(steps + 1)
    t = np.arange(steps + 1) * dt
    u[0] = I
    if steps > 0:
        u[1] = u[0] + dt * V + dt * dt / (2 * m) * (-b * V * abs(V) - s(u[0]) + F(t[0]))
    for n in range(1, steps):
        jump = b * abs(u[n] - u[n - 1])
        u[n + 1] = (2 * m * u[n] - m * u[n - 1] + jump * u[n] + dt * dt * (F(t[n]) - s(u[n]))) / (m + jump)
    return u, t


def wire_and_drag(theta, dt=DT, alpha=ALPHA):
    """omega, S = omega^2 + cos(theta) and D = -alpha |omega| omega."""
    omega = np.empty_like(theta)
    omega[0] = 0.0
    if len(theta) > 2:
        omega[1:-1] = (theta[2:] - theta[:-2]) / (2 * dt)
    if len(theta) > 1:
        omega[-1] = (theta[-1] - theta[-2]) / dt
    return omega, omega**2 + np.cos(theta), -alpha * np.abs(omega) * omega


def frames(count):
    """theta, S and D for `count` frames, one per time step."""
    theta, _ = solve(max(count, 2))
    _, S, D = wire_and_drag(theta)
    return theta[:count], S[:count], D[:count]


def figure(width, height, dpi=100):
    """A matplotlib (Agg) figure of exactly width x height pixels, one axes filling it."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    fig = plt.figure(figsize=(width / dpi, height / dpi), dpi=dpi, facecolor="white")
    ax = fig.add_axes([0, 0, 1, 1])
    return fig, ax


class Diagram:
    """The free-body diagram, its artists made once and moved each frame
    (set_data, set_center, set_position: the idiomatic fast matplotlib way).
    `redraw` clears the axes and makes every artist again instead, as a
    drawing program that erases and redraws each frame does."""

    def __init__(self, ax, width, height):
        self.ax = ax
        self.aspect = width / height
        self.pivot = np.array([self.aspect / 2, 0.85])
        self.wire_length = 0.45
        self.bob_radius = 0.05
        self.arc_radius = self.wire_length / 4
        self.force_unit = 0.25
        scale = height / 720.0 * 0.72  # points per 720p pixel at 100 dpi
        self.thick, self.medium, self.thin = 6 * scale, 3 * scale, 1.5 * scale
        self.font = 22 * scale
        self.build()

    def build(self):
        from matplotlib.patches import Arc, Circle

        ax, P = self.ax, self.pivot
        ax.set_xlim(0, self.aspect)
        ax.set_ylim(0, 1)
        ax.set_aspect("equal")
        ax.set_axis_off()
        ax.plot([P[0] - 0.3, P[0] + 0.3], [P[1], P[1]], "k-", lw=self.thick, solid_capstyle="butt")
        ax.plot([P[0], P[0]], [P[1], P[1] - 0.6 * self.wire_length], "k--", lw=self.thin)
        (self.wire,) = ax.plot([], [], "-", color="0.2", lw=self.medium)
        self.arc = Arc(P, 2 * self.arc_radius, 2 * self.arc_radius, theta1=-90, theta2=-90, color="k", lw=self.thin)
        ax.add_patch(self.arc)
        self.theta_label = ax.text(0, 0, r"$\theta$", fontsize=self.font, ha="center", va="center")
        self.bob = Circle((0, 0), self.bob_radius, facecolor="tab:blue", edgecolor="k", lw=self.thin)
        ax.add_patch(self.bob)
        self.arrows, self.labels = [], []
        for name, colour in (("mg", "tab:red"), ("S", "tab:green"), ("D", "tab:purple")):
            self.arrows.append(ax.arrow(0, 0, 0, -0.1, width=0.006, head_width=0.025, head_length=0.035,
                                        length_includes_head=True, color=colour))
            self.labels.append(ax.text(0, 0, name, fontsize=self.font, ha="center", va="center"))

    def redraw(self, theta, S, D):
        self.ax.cla()
        self.build()
        return self.update(theta, S, D)

    def update(self, theta, S, D):
        P = self.pivot
        down_wire = np.array([math.sin(theta), -math.cos(theta)])
        bob = P + self.wire_length * down_wire
        across = np.array([down_wire[1], -down_wire[0]])
        forces = (np.array([0.0, -self.force_unit]), -self.force_unit * S * down_wire, -self.force_unit * D * across)
        self.wire.set_data([P[0], bob[0]], [P[1], bob[1]])
        degrees = math.degrees(theta)
        self.arc.theta1, self.arc.theta2 = min(-90, -90 + degrees), max(-90, -90 + degrees)
        self.arc.stale = True
        middle = math.radians(-90 + degrees / 2)
        self.theta_label.set_position(P + (self.arc_radius + 0.035) * np.array([math.cos(middle), math.sin(middle)]))
        self.bob.set_center(bob)
        for arrow, label, force in zip(self.arrows, self.labels, forces):
            arrow.set_data(x=bob[0], y=bob[1], dx=force[0], dy=force[1])
            length = math.hypot(force[0], force[1])
            offset = force / length * 0.03 if length > 1e-12 else np.array([0.03, 0.0])
            label.set_position(bob + force + offset)
        return [self.wire, self.arc, self.theta_label, self.bob, *self.arrows, *self.labels]


def diagram_arguments(default_out):
    """The options the diagram peers share: --frames, --size, --mode, --out."""
    parser = argparse.ArgumentParser()
    parser.add_argument("--frames", type=int, default=300)
    parser.add_argument("--size", choices=SIZES, default="720p")
    parser.add_argument("--mode", choices=["reuse", "redraw"], default="reuse")
    parser.add_argument("--out", default=default_out)
    return parser


def diagram_run(args):
    """The figure and `draw(i)`, which puts frame i on it, for parsed diagram_arguments."""
    width, height = SIZES[args.size]
    theta, S, D = frames(args.frames)
    fig, ax = figure(width, height)
    diagram = Diagram(ax, width, height)
    draw = diagram.update if args.mode == "reuse" else diagram.redraw
    return fig, lambda i: draw(theta[i], S[i], D[i])


def save_png_frames(fig, draw, frames, out, name):
    """draw(i) then savefig to out/tmp_%04d.png for each frame; the loop's
    frames/s on stderr, prefixed by `name`."""
    os.makedirs(out, exist_ok=True)
    start = time.perf_counter()
    for i in range(frames):
        draw(i)
        fig.savefig(os.path.join(out, "tmp_%04d.png" % i), dpi=100)
    took = time.perf_counter() - start
    print("%s: %d frames in %.3f s, %.1f frames/s" % (name, frames, took, frames / took), file=sys.stderr)
