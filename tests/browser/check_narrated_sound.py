#!/usr/bin/env python3
"""Plays a narrated lecture's MP4 and WebM in headless Chromium and checks it hears the speech.

Renders a small storyboard whose card speaks, and the same one --mute, then
serves them over HTTP on 127.0.0.1 (so the page and its media share an
origin: Web Audio reads nothing from a cross-origin file: video) and plays
each video through an AudioContext analyser: the narrated MP4 and WebM must
show signal (peak above 0.02), the muted one none. The page's own <video>
must not be muted; nor must the speaking slide of the same lecture given
--present, whose own video must play and speak. Drives Chromium as check_lecture_page.py does.

Usage: check_narrated_sound.py VIBRA
Exit 77 (skipped) only when Chromium is not installed and CI is not true.
"""
import functools
import http.server
import os
import shutil
import subprocess
import sys
import tempfile
import threading
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))
from check_lecture_page import SKIP, Chromium, check, failures  # noqa: E402

STORY = """title = "A spoken card"
size = "320x180"
fps = 10
[[shot]]
card = "Springs"
say = "A spring swings, and drag slows it down."
"""

# Plays `src` through an analyser for up to 3 s of its speech; the largest |sample| seen.
LISTEN = """(async () => {
  const v = document.createElement('video');
  v.src = %r;
  document.body.appendChild(v);
  await new Promise((ok, no) => { v.oncanplay = ok; v.onerror = () => no(new Error('cannot load ' + v.src)); });
  const ctx = new AudioContext();
  const analyser = ctx.createAnalyser();
  analyser.fftSize = 2048;
  ctx.createMediaElementSource(v).connect(analyser);
  analyser.connect(ctx.destination);
  await ctx.resume();
  await v.play();
  const samples = new Float32Array(analyser.fftSize);
  let peak = 0;
  const start = performance.now();
  while (performance.now() - start < 3000 && !v.ended) {
    analyser.getFloatTimeDomainData(samples);
    for (const x of samples) peak = Math.max(peak, Math.abs(x));
    await new Promise(r => setTimeout(r, 20));
  }
  v.pause();
  v.remove();
  await ctx.close();
  return peak;
})()"""


class QuietHandler(http.server.SimpleHTTPRequestHandler):
    def log_message(self, *args):
        pass


def serve(directory):
    handler = functools.partial(QuietHandler, directory=str(directory))
    server = http.server.ThreadingHTTPServer(("127.0.0.1", 0), handler)
    threading.Thread(target=server.serve_forever, daemon=True).start()
    return server


def main():
    if len(sys.argv) < 2:
        print(__doc__)
        return 2
    vibra = str(Path(sys.argv[1]).resolve())
    chromium = shutil.which("chromium") or shutil.which("chromium-browser")
    if not chromium:
        print("SKIPPED: chromium is not installed (scripts/setup installs it)")
        return 1 if os.environ.get("CI") == "true" else SKIP
    work = Path(tempfile.mkdtemp(prefix="vibra_sound_"))
    try:
        (work / "story.toml").write_text(STORY)
        for args in (["-o", "lecture.html"], ["--mute", "-o", "muted.mp4"], ["--present", "-o", "talk.html"]):
            subprocess.run([vibra, "lecture", "story.toml", "-q"] + args, cwd=work, check=True)
        server = serve(work)
        base = "http://127.0.0.1:%d/" % server.server_address[1]
        browser = Chromium(chromium, str(work / "profile"))
        try:
            browser.open_tab(800, 600)
            browser.send("Page.navigate", {"url": base + "lecture.html"})
            browser.wait_event("Page.loadEventFired")
            check(browser.js("document.getElementById('video').muted") is False, "the page's video is not muted")
            browser.send("Page.navigate", {"url": base + "talk.html#1"})
            browser.wait_event("Page.loadEventFired")
            playing = browser.js("""new Promise(done => {
              const v = document.querySelector('#slide-1 video');
              const t0 = performance.now();
              (function look() {
                if (v.currentTime > 0.3 || performance.now() - t0 > 5000) done([v.muted, v.paused, v.currentTime]);
                else setTimeout(look, 50);
              })();
            })""")
            check(playing[0] is False and playing[1] is False and playing[2] > 0.3,
                  "the speaking slide plays unmuted (muted, paused, time: %s)" % (playing,))
            for name, heard in (("lecture_files/lecture.mp4", True), ("lecture_files/lecture.webm", True),
                                ("muted.mp4", False), ("talk_files/01-springs.mp4", True)):
                peak = browser.js(LISTEN % (base + name))
                check(peak > 0.02 if heard else peak == 0,
                      "%s: the analyser's peak is %.4f (%s)" % (name, peak, "speech" if heard else "silence"))
        finally:
            browser.close()
            server.shutdown()
    finally:
        shutil.rmtree(work, ignore_errors=True)
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
