#!/usr/bin/python3
"""Video peer: matplotlib.animation.FuncAnimation saved through FFMpegWriter
(frames piped to the ffmpeg program), the documented matplotlib way.

  funcanim_video.py --frames 300 --size 720p|1080p --codec mp4|webm [--mode reuse|redraw] --out NAME

mp4 : FFMpegWriter(fps=25) with matplotlib's default codec h264, which
      ffmpeg runs as libx264 with its defaults (preset medium, crf 23);
      matplotlib adds -pix_fmt yuv420p.
webm: FFMpegWriter(fps=25, codec="libvpx-vp9", extra_args=["-pix_fmt", "yuv420p"]),
      libvpx-vp9's defaults otherwise.
Writes NAME.mp4 or NAME.webm; prints the save's frames/s on stderr.
"""
import os
import sys
import time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import pendulum_scene as scene  # noqa: E402


def main():
    parser = scene.diagram_arguments("movie")
    parser.add_argument("--codec", choices=["mp4", "webm"], default="mp4")
    args = parser.parse_args()
    fig, draw = scene.diagram_run(args)
    from matplotlib.animation import FFMpegWriter, FuncAnimation

    animation = FuncAnimation(fig, draw, frames=args.frames,
                              init_func=lambda: [], blit=False, repeat=False, cache_frame_data=False)
    if args.codec == "mp4":
        writer, name = FFMpegWriter(fps=25), args.out + ".mp4"
    else:
        writer = FFMpegWriter(fps=25, codec="libvpx-vp9", extra_args=["-pix_fmt", "yuv420p"])
        name = args.out + ".webm"
    start = time.perf_counter()
    animation.save(name, writer=writer, dpi=100)
    took = time.perf_counter() - start
    print("funcanim_video: %d frames in %.3f s, %.1f frames/s" % (args.frames, took, args.frames / took),
          file=sys.stderr)


if __name__ == "__main__":
    main()
