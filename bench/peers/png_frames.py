#!/usr/bin/python3
"""PNG-sequence peer: matplotlib (Agg) saves one PNG per frame with savefig,
tmp_0000.png, tmp_0001.png, ... in --out, the book's way of making frames.

  png_frames.py --frames 300 --size 720p|1080p [--mode reuse|redraw] --out DIR

--mode reuse (default) moves artists made once; --mode redraw clears and
redraws the axes every frame. Prints the loop's frames/s on stderr.
"""
import os
import sys
import time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import pendulum_scene as scene  # noqa: E402


def main():
    args = scene.diagram_arguments("frames").parse_args()
    fig, draw = scene.diagram_run(args)
    os.makedirs(args.out, exist_ok=True)
    start = time.perf_counter()
    for i in range(args.frames):
        draw(i)
        fig.savefig(os.path.join(args.out, "tmp_%04d.png" % i), dpi=100)
    took = time.perf_counter() - start
    print("png_frames: %d frames in %.3f s, %.1f frames/s" % (args.frames, took, args.frames / took), file=sys.stderr)


if __name__ == "__main__":
    main()
