#!/usr/bin/python3
"""PNG-sequence peer for the spring-dashpot scene (Fig 1.18): matplotlib
(Agg) draws the wall, the spring's zigzag, the dashpot, the body on wheels
over the floor, u marked from equilibrium and the arrows of the spring
force -ku, the damper force -bu' and F(t), each labelled, and saves one PNG
per frame with savefig, tmp_0000.png, tmp_0001.png, ... in --out.

  spring_dashpot_frames.py --frames 300 --size 720p|1080p [--mode reuse|redraw] --out DIR

Model (vibra's built-in scene spring_dashpot): m u'' + b u' + k u = F(t),
m = 1, k = 1, b = 0.15, F(t) = 0.3 cos(1.2 t), u(0) = 1, u'(0) = 0, solved
by the book's centered scheme for linear damping as a Python loop, dt = 2 pi/60,
one frame per step. --mode reuse (default) moves artists made once (the fast
matplotlib way); redraw clears and redraws the axes every frame. Prints the
loop's frames/s on stderr.
"""
import math
import os
import sys

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import pendulum_scene as scene  # noqa: E402

M, K, B, DT = 1.0, 1.0, 0.15, 2 * math.pi / 60
I, V = 1.0, 0.0


def F(t):
    return 0.3 * math.cos(1.2 * t)


def solve(steps, dt=DT):
    """u^0..u^steps by the centered scheme with linear damping, and t."""
    u = np.zeros(steps + 1)
    t = np.arange(steps + 1) * dt
    u[0] = I
    if steps > 0:
        u[1] = u[0] + dt * V + dt * dt / (2 * M) * (F(t[0]) - B * V - K * u[0])
    for n in range(1, steps):
        u[n + 1] = (2 * M * u[n] - (M - B * dt / 2) * u[n - 1] + dt * dt * (F(t[n]) - K * u[n])) / (M + B * dt / 2)
    return u, t


def frames(count):
    """u, t and the forces -ku, -bu', F for `count` frames, one per step."""
    u, t = solve(max(count, 2))
    v = np.empty_like(u)
    v[0] = V
    v[1:-1] = (u[2:] - u[:-2]) / (2 * DT)
    v[-1] = (u[-1] - u[-2]) / DT
    forces = np.stack([-K * u, -B * v, 0.3 * np.cos(1.2 * t)], axis=1)
    return u[:count], t[:count], forces[:count]


class Diagram:
    """The spring-dashpot picture in world units (the wall at x = 0, the body's
    left side at REST + u), its artists made once and moved each frame."""

    REST, BODY_W, BODY_H, WHEEL = 4.0, 2.2, 1.6, 0.3
    SPRING_Y, DASHPOT_Y, COILS, ZIG = 1.55, 0.8, 10, 0.22
    ARROW_UNIT = 1.6  # world units per unit of force

    def __init__(self, ax, width, height):
        self.ax = ax
        scale = height / 720.0 * 0.72  # points per 720p pixel at 100 dpi
        self.medium, self.thin = 2.5 * scale, 1.5 * scale
        self.font, self.small = 22 * scale, 15 * scale
        self.world_h = 5.2
        self.world_w = self.world_h * width / height
        self.build()

    def build(self):
        from matplotlib.collections import LineCollection
        from matplotlib.patches import Circle, Rectangle

        ax = self.ax
        ax.set_xlim(-0.8, self.world_w - 0.8)
        ax.set_ylim(-0.9, self.world_h - 0.9)
        ax.set_aspect("equal")
        ax.set_axis_off()
        floor_end = self.REST + self.BODY_W + 3.5
        ax.plot([-0.3, floor_end], [0, 0], "k-", lw=self.medium)
        ax.plot([0, 0], [0, 2.6], "k-", lw=self.medium)
        # Hatching as one LineCollection (a Line2D per stroke would slow matplotlib down).
        floor = [[(x, 0), (x - 0.14, -0.14)] for x in np.arange(-0.3, floor_end, 0.18)]
        wall = [[(0, y), (-0.14, y - 0.14)] for y in np.arange(0.05, 2.6, 0.18)]
        ax.add_collection(LineCollection(floor + wall, colors="k", linewidths=self.thin * 0.7))
        rest = self.REST + self.BODY_W
        ax.plot([rest, rest], [0, 2.0 * self.WHEEL + self.BODY_H + 0.9], "--", color="0.5", lw=self.thin)
        # The dashpot's cylinder, fixed to the wall.
        y, h = self.DASHPOT_Y, 0.2
        ax.plot([0, 1.3], [y, y], "k-", lw=self.thin)
        ax.plot([1.3, 1.3, 3.0], [y + h, y - h, y - h], "k-", lw=self.thin)
        ax.plot([1.3, 3.0], [y + h, y + h], "k-", lw=self.thin)
        (self.piston,) = ax.plot([], [], "k-", lw=self.medium)
        (self.rod,) = ax.plot([], [], "k-", lw=self.thin)
        (self.spring,) = ax.plot([], [], "-", color="0.1", lw=self.thin)
        self.body = Rectangle((0, 2 * self.WHEEL), self.BODY_W, self.BODY_H, facecolor="tab:blue", edgecolor="k",
                              lw=self.thin)
        ax.add_patch(self.body)
        self.wheels = [Circle((0, self.WHEEL), self.WHEEL, facecolor="white", edgecolor="k", lw=self.thin)
                       for _ in range(2)]
        for wheel in self.wheels:
            ax.add_patch(wheel)
        top = 2 * self.WHEEL + self.BODY_H + 0.45
        (self.dimension,) = ax.plot([], [], "k-", lw=self.thin)
        self.dimension_ends = ax.plot([], [], "k|", ms=8 * self.thin)[0]
        self.u_label = ax.text(0, top + 0.25, "$u$", fontsize=self.font, ha="center", va="center")
        self.dimension_y = top
        self.arrows, self.labels = [], []
        for name, colour in ((r"$-ku$", "tab:orange"), (r"$-bu'$", "tab:pink"), (r"$F(t)$", "tab:green")):
            self.arrows.append(ax.arrow(0, 0, 0.1, 0, width=0.05, head_width=0.2, head_length=0.15,
                                        length_includes_head=True, color=colour))
            self.labels.append(ax.text(0, 0, name, fontsize=self.font, color=colour, ha="center", va="center"))
        self.clock = ax.text(-0.6, self.world_h - 1.2, "", fontsize=self.font, ha="left", va="center")
        ax.text(-0.6, -0.7, "vibration · centered · m=1 · k=1 · b=0.15 · F=0.3*cos(1.2*t) · I=1 · V=0",
                fontsize=self.small, color="0.3", ha="left", va="center")

    def redraw(self, u, t, forces):
        self.ax.cla()
        self.build()
        return self.update(u, t, forces)

    def update(self, u, t, forces):
        left = self.REST + u
        right = left + self.BODY_W
        # The spring: straight leads at both ends, a zigzag of COILS coils between.
        lead = 0.3
        xs = np.linspace(lead, left - lead, 2 * self.COILS + 1)
        ys = np.full_like(xs, self.SPRING_Y)
        ys[1:-1:2] += self.ZIG
        ys[2:-1:2] -= self.ZIG
        self.spring.set_data(np.concatenate([[0], xs, [left]]), np.concatenate([[self.SPRING_Y], ys, [self.SPRING_Y]]))
        piston = left - 1.6
        y = self.DASHPOT_Y
        self.piston.set_data([piston, piston], [y - 0.16, y + 0.16])
        self.rod.set_data([piston, left], [y, y])
        self.body.set_x(left)
        for wheel, at in zip(self.wheels, (0.25, 0.75)):
            wheel.set_center((left + at * self.BODY_W, self.WHEEL))
        rest = self.REST + self.BODY_W
        self.dimension.set_data([rest, right], [self.dimension_y, self.dimension_y])
        self.dimension_ends.set_data([rest, right], [self.dimension_y, self.dimension_y])
        self.u_label.set_x(0.5 * (rest + right))
        centre = np.array([left + self.BODY_W / 2, 2 * self.WHEEL + self.BODY_H / 2])
        for i, (arrow, label, force) in enumerate(zip(self.arrows, self.labels, forces)):
            y = centre[1] + (0.45 - 0.45 * i)
            dx = self.ARROW_UNIT * force
            arrow.set_data(x=centre[0], y=y, dx=dx, dy=0.0)
            label.set_position((centre[0] + dx + math.copysign(0.55, dx if dx != 0 else 1.0), y))
        self.clock.set_text("$t$ = %.2f" % t)
        return [self.spring, self.piston, self.rod, self.body, *self.wheels, self.dimension, self.dimension_ends,
                self.u_label, *self.arrows, *self.labels, self.clock]


def main():
    args = scene.diagram_arguments("frames").parse_args()
    width, height = scene.SIZES[args.size]
    u, t, forces = frames(args.frames)
    fig, ax = scene.figure(width, height)
    diagram = Diagram(ax, width, height)
    draw = diagram.update if args.mode == "reuse" else diagram.redraw
    scene.save_png_frames(fig, lambda i: draw(u[i], t[i], forces[i]), args.frames, args.out, "spring_dashpot_frames")

if __name__ == "__main__":
    main()
