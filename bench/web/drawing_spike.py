#!/usr/bin/env python3
"""The browser drawing spike: figures for docs/performance.md and the choice in docs/architecture.md.

Renders the pendulum's free-body diagram at 960x540 as an SVG still (the
scene code's own paths, strokes, fills and glyph outlines), then in headless
Chromium, with the WebAssembly core (build/web/vibra_core.js):
  - the latency of a re-solve of a 10-period run (601 rows, and 20001 rows);
  - option A: those paths handed to the 2D canvas as Path2D, ms per frame
    and requestAnimationFrame frames/s;
  - option B's floor: a 960x540 frame of pixels from wasm memory put on the
    canvas per frame, before any rasterizing.
Prints the figures as JSON. Usage: bench/web/drawing_spike.py [BUILD] [--screenshot FILE.png]
"""
import json
import shutil
import subprocess
import sys
import tempfile
from pathlib import Path

HERE = Path(__file__).resolve().parent
sys.path.insert(0, str(HERE.parent.parent / "tests" / "browser"))
from check_lecture_page import Chromium, find_chromium  # noqa: E402

PAGE = """<!doctype html><meta charset="utf-8"><title>vibra drawing spike</title>
<body style="margin:0;overflow:hidden"><canvas id="frame" width="960" height="540"></canvas>
<script src="vibra_core.js"></script><script src="drawing_spike.js"></script>
<script>const stillSvg = %s;</script></body>
"""


def main():
    args = sys.argv[1:]
    screenshot = None
    if "--screenshot" in args:
        screenshot = args[args.index("--screenshot") + 1]
        del args[args.index("--screenshot"):args.index("--screenshot") + 2]
    build = Path(args[0] if args else "build").resolve()
    chromium, code = find_chromium("no figures measured")
    if not chromium:
        sys.exit(code)
    with tempfile.TemporaryDirectory() as work:
        work = Path(work)
        subprocess.run([str(build / "vibra"), "render", "pendulum", "--layout", "fbd", "--at", "3", "--size", "960x540",
                        "-q", "-o", str(work / "fbd.svg")], check=True)
        shutil.copy(build / "web" / "vibra_core.js", work)
        shutil.copy(HERE / "drawing_spike.js", work)
        (work / "spike.html").write_text(PAGE % json.dumps((work / "fbd.svg").read_text()))
        browser = Chromium(chromium, str(work / "profile"))
        try:
            browser.open_tab(960, 540)
            browser.load(work / "spike.html")
            figures = browser.js("measureSpike(stillSvg)")
            if screenshot:
                browser.screenshot(screenshot)
        finally:
            browser.close()
    print(json.dumps(figures, indent=1))


if __name__ == "__main__":
    main()
