#!/usr/bin/python3
"""PNG-sequence peer: matplotlib (Agg) saves one PNG per frame with savefig,
tmp_0000.png, tmp_0001.png, ... in --out, the book's way of making frames.

  png_frames.py --frames 300 --size 720p|1080p [--mode reuse|redraw] --out DIR

--mode reuse (default) moves artists made once; --mode redraw clears and
redraws the axes every frame. Prints the loop's frames/s on stderr.
"""
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import pendulum_scene as scene  # noqa: E402


def main():
    args = scene.diagram_arguments("frames").parse_args()
    fig, draw = scene.diagram_run(args)
    scene.save_png_frames(fig, draw, args.frames, args.out, "png_frames")

if __name__ == "__main__":
    main()
