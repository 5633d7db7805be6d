#!/usr/bin/env python3
"""Loads vibra's lecture pages in headless Chromium and checks they work.

Drives Chromium through its DevTools protocol over --remote-debugging-pipe
(standard library only). Renders a small pendulum page into a directory
whose name has a space and non-ASCII letters, then checks: the video loads
(readyState, duration = frames / fps; which source played is reported)
from the page's folder PAGE_files/, ArrowRight while paused advances
currentTime by 1 / fps and shows that frame, clicking or dragging in a
plot seeks there, the speed selector sets
the rate, the plots' cursor moves while playing, the wheel zooms all
time axes together and a double-click resets them; a figure page's legend
hides a curve; a frames-player page steps with the same keys; no console
errors; nothing fetched but file: and data: URLs. Saves a screenshot.

Usage: check_lecture_page.py VIBRA [--screenshot FILE.png] [--keep DIR]
Exit 77 (skipped) only when Chromium is not installed, and then only on a
developer's machine: with CI=true a missing Chromium fails the test.
"""
import base64
import csv
import fcntl
import json
import os
import shutil
import subprocess
import sys
import tempfile
import threading
import time
from pathlib import Path
from urllib.parse import unquote

SKIP = 77
failures = []


def check(ok, what):
    print(("ok    " if ok else "FAIL  ") + what, flush=True)
    if not ok:
        failures.append(what)


class Chromium:
    """A headless Chromium spoken to over the DevTools pipe (fds 3 and 4)."""

    def __init__(self, exe, profile):
        to_child_r, self.to_child = os.pipe()
        self.from_child, from_child_w = os.pipe()
        a = fcntl.fcntl(to_child_r, fcntl.F_DUPFD, 10)
        b = fcntl.fcntl(from_child_w, fcntl.F_DUPFD, 10)

        def plumb():
            os.dup2(a, 3)
            os.dup2(b, 4)

        flags = ["--headless", "--no-sandbox", "--disable-gpu", "--disable-quic", "--no-first-run",
                 "--disable-background-networking", "--disable-component-update", "--disable-sync",
                 "--disable-default-apps", "--mute-audio", "--autoplay-policy=no-user-gesture-required",
                 "--remote-debugging-pipe", "--user-data-dir=" + profile, "about:blank"]
        self.proc = subprocess.Popen([exe] + flags, preexec_fn=plumb, pass_fds=(3, 4),
                                     stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
        for fd in (to_child_r, from_child_w, a, b):
            os.close(fd)
        self.next_id = 0
        self.replies = {}
        self.events = []
        self.lock = threading.Condition()
        threading.Thread(target=self._read, daemon=True).start()
        self.session = None

    def _read(self):
        buffer = b""
        while True:
            chunk = os.read(self.from_child, 1 << 16)
            if not chunk:
                return
            buffer += chunk
            while b"\0" in buffer:
                message, buffer = buffer.split(b"\0", 1)
                m = json.loads(message)
                with self.lock:
                    if "id" in m:
                        self.replies[m["id"]] = m
                    else:
                        self.events.append(m)
                    self.lock.notify_all()

    def send(self, method, params=None, session=True, timeout=30):
        with self.lock:
            self.next_id += 1
            i = self.next_id
        message = {"id": i, "method": method, "params": params or {}}
        if session and self.session:
            message["sessionId"] = self.session
        os.write(self.to_child, json.dumps(message).encode() + b"\0")
        deadline = time.time() + timeout
        with self.lock:
            while i not in self.replies:
                if not self.lock.wait(max(0.01, deadline - time.time())) and time.time() > deadline:
                    raise TimeoutError(method)
            reply = self.replies.pop(i)
        if "error" in reply:
            raise RuntimeError(method + ": " + json.dumps(reply["error"]))
        return reply.get("result", {})

    def wait_event(self, method, timeout=30):
        deadline = time.time() + timeout
        with self.lock:
            while True:
                for e in self.events:
                    if e.get("method") == method:
                        self.events.remove(e)
                        return e
                if time.time() > deadline:
                    raise TimeoutError(method)
                self.lock.wait(0.1)

    def open_tab(self, width, height):
        target = self.send("Target.createTarget", {"url": "about:blank"}, session=False)["targetId"]
        self.session = self.send("Target.attachToTarget", {"targetId": target, "flatten": True}, session=False)["sessionId"]
        for domain in ("Runtime", "Log", "Network", "Page"):
            self.send(domain + ".enable")
        self.send("Emulation.setDeviceMetricsOverride",
                  {"width": width, "height": height, "deviceScaleFactor": 1, "mobile": False})

    def load(self, path):
        with self.lock:
            self.events = [e for e in self.events if e.get("method") != "Page.loadEventFired"]
        self.send("Page.navigate", {"url": Path(path).resolve().as_uri()})
        self.wait_event("Page.loadEventFired")

    def js(self, expression):
        r = self.send("Runtime.evaluate", {"expression": expression, "returnByValue": True, "awaitPromise": True})
        if "exceptionDetails" in r:
            raise RuntimeError("page script failed: " + json.dumps(r["exceptionDetails"])[:400])
        return r["result"].get("value")

    def wait_for(self, expression, timeout=10):
        """Whether `expression` turns true within `timeout` seconds. A script
        error (an element not there yet, in a window still loading) counts as
        not yet; when the last try still failed, its error is raised."""
        deadline = time.time() + timeout
        error = None
        while time.time() < deadline:
            try:
                if self.js(expression):
                    return True
                error = None
            except RuntimeError as failed:
                error = failed
            time.sleep(0.05)
        if error:
            raise error
        return False

    def key(self, key, code, keycode):
        for kind in ("rawKeyDown", "keyUp"):
            params = {"type": kind, "key": key, "code": code, "windowsVirtualKeyCode": keycode}
            if key == " " and kind == "rawKeyDown":
                self.send("Input.dispatchKeyEvent", params)
                params = {"type": "char", "text": " ", "key": " ", "code": code, "windowsVirtualKeyCode": 32}
            self.send("Input.dispatchKeyEvent", params)

    def click(self, x, y, count=1, modifiers=0):
        for c in range(1, count + 1):
            for kind in ("mousePressed", "mouseReleased"):
                self.send("Input.dispatchMouseEvent", {"type": kind, "x": x, "y": y, "button": "left",
                                                       "clickCount": c, "modifiers": modifiers})

    def wheel(self, x, y, delta_y):
        self.send("Input.dispatchMouseEvent", {"type": "mouseWheel", "x": x, "y": y, "deltaX": 0, "deltaY": delta_y})

    def screenshot(self, path):
        data = self.send("Page.captureScreenshot", {"format": "png", "captureBeyondViewport": False})["data"]
        Path(path).write_bytes(base64.b64decode(data))

    def problems(self):
        """Console errors, uncaught exceptions and network fetches, from the events so far."""
        errors, fetched = [], []
        with self.lock:
            for e in self.events:
                m, p = e.get("method"), e.get("params", {})
                if m == "Runtime.consoleAPICalled" and p.get("type") in ("error", "assert"):
                    errors.append(" ".join(str(a.get("value", a.get("description", ""))) for a in p.get("args", [])))
                elif m == "Runtime.exceptionThrown":
                    errors.append(json.dumps(p.get("exceptionDetails", {}))[:300])
                elif m == "Log.entryAdded" and p.get("entry", {}).get("level") == "error":
                    errors.append(p["entry"].get("text", ""))
                elif m == "Network.requestWillBeSent":
                    fetched.append(p["request"]["url"])
        return errors, fetched

    def close(self):
        try:
            self.send("Browser.close", session=False, timeout=5)
        except Exception:
            pass
        try:
            self.proc.wait(5)
        except subprocess.TimeoutExpired:
            self.proc.kill()
            self.proc.wait()


def run(command):
    r = subprocess.run(command, capture_output=True, text=True)
    if r.returncode != 0:
        print("vibra failed:", " ".join(command), "\n", r.stderr, file=sys.stderr)
        sys.exit(1)


def plot_point(browser, panel, fx, fy):
    """Page coordinates of the point at fractions (fx, fy) of a panel's plot area, in whole pixels (as a
    mouse event's clientX is), so that the time under it can be computed exactly."""
    r = browser.js(f"(() => {{ const b = vibraPage.panels[{panel}].u.over.getBoundingClientRect();"
                   f" return [b.left + {fx} * b.width, b.top + {fy} * b.height]; }})()")
    return round(r[0]), round(r[1])


def check_lecture(browser, page, T, fps, frames, screenshot):
    browser.load(page)
    check(browser.wait_for("document.getElementById('video').readyState >= 2", 20),
          "the video loads (readyState >= HAVE_CURRENT_DATA)")
    source = browser.js("document.getElementById('video').currentSrc")
    h264 = browser.js("document.getElementById('video').canPlayType('video/mp4; codecs=avc1.4d401e')")
    print(f"      the source that plays: {source.rsplit('/', 1)[-1]} (this Chromium's H.264 support: '{h264 or 'none'}')")
    check(unquote(source).endswith(f"/{page.stem}_files/{page.stem}" + source[source.rfind("."):]),
          "the video comes from the page's own folder, PAGE_files/")
    # Without H.264 (a Chromium built without proprietary codecs) the WebM must be the one that plays.
    check(source.endswith(".mp4") if h264 else source.endswith(".webm"),
          "the browser plays the first source it can: " + ("MP4" if h264 else "WebM, as it has no H.264"))
    duration = browser.js("document.getElementById('video').duration")
    check(abs(duration - frames / fps) < 1e-3, f"duration {duration:.6f} s = {frames} frames / {fps} fps")
    # The WebM source, on its own, plays too (what Chromium without H.264 would show).
    browser.js("(() => { const v = document.createElement('video'); v.id = 'webm-alone'; v.muted = true;"
               " v.src = document.querySelector('source[type=\"video/webm\"]').src; document.body.append(v); })()")
    webm_ok = browser.wait_for("document.getElementById('webm-alone').readyState >= 2", 20)
    webm_duration = browser.js("document.getElementById('webm-alone').duration")
    check(webm_ok and abs(webm_duration - frames / fps) < 1e-3, f"the WebM alone plays, {webm_duration:.6f} s long")
    browser.js("document.getElementById('webm-alone').remove()")

    now = lambda: browser.js("document.getElementById('video').currentTime")
    settle = lambda: browser.wait_for("!document.getElementById('video').seeking", 5)
    check(browser.js("document.getElementById('video').paused") and now() == 0, "the page opens paused at the start")

    def presented_after(action):
        """The index of the frame the video shows after `action` (requestVideoFrameCallback)."""
        browser.js("window.presented = new Promise(done => document.getElementById('video')"
                   f".requestVideoFrameCallback((now, m) => done(Math.round(m.mediaTime * {fps})))); 0")
        action()
        settle()
        return browser.js("window.presented")

    arrow = lambda: browser.key("ArrowRight", "ArrowRight", 39)
    shown = [presented_after(arrow), presented_after(arrow)]
    t2 = now()
    shown.append(presented_after(lambda: browser.key("ArrowLeft", "ArrowLeft", 37)))
    t1 = now()
    # The page aims 10 us into a frame; the steps themselves are 1/fps exactly.
    check(abs(t1 - 1 / fps) < 2e-5 and abs(t2 - t1 - 1 / fps) < 2e-6,
          f"ArrowRight while paused steps 1/fps, ArrowLeft back: currentTime {t2:.6f}, then {t1:.6f}")
    check(shown == [1, 2, 1], f"the video shows the frames stepped to: {shown}")
    shown = presented_after(lambda: browser.key("End", "End", 35))
    check(abs(now() - (frames - 1) / fps) < 2e-5 and shown == frames - 1, f"End goes to the last frame ({shown})")
    browser.key("Home", "Home", 36)
    settle()
    check(now() == 0, "Home goes to the start")

    def frame_under(panel, x):
        """The frame nearest the simulated time under page coordinate x in a panel: frames are evenly spaced
        over [0, T], so frame k shows t = k T / (frames - 1)."""
        t = browser.js(f"(() => {{ const u = vibraPage.panels[{panel}].u;"
                       f" return u.posToVal({x} - u.over.getBoundingClientRect().left, 'x'); }})()")
        return min(frames - 1, max(0, round(t / (T / (frames - 1)))))

    def check_seek(shown, frame, what):
        """The video is at frame `frame` (the page aims 10 us into it) and shows that frame."""
        check(abs(now() - (frame / fps + 1e-5)) < 2e-5 and shown == frame,
              f"{what} seeks to frame {frame}: currentTime {now():.6f}, showing frame {shown}")

    # Clicking about 3/4 along a plot (the whole run shown), 0.7 of the way from frame 22's time to frame
    # 23's, seeks to the nearest frame under the pointer, exactly: 23, not 22.
    interval = T / (frames - 1)
    x = browser.js(f"(() => {{ const u = vibraPage.panels[1].u;"
                   f" return u.valToPos({22.7 * interval}, 'x') + u.over.getBoundingClientRect().left; }})()")
    x, y = round(x), plot_point(browser, 1, 0.75, 0.5)[1]
    frame = frame_under(1, x)
    check(frame == 23, f"the pointer at x = {x} is nearest frame 23: {frame}")
    check_seek(presented_after(lambda: browser.click(x, y)), frame, "a click about 3/4 along a plot")

    # Dragging from 1/4 to 1/2 of a plot scrubs the video along to t = T/2.
    x0, y0 = plot_point(browser, 2, 0.25, 0.5)
    x1, _ = plot_point(browser, 2, 0.5, 0.5)
    frame = frame_under(2, x1)

    browser.send("Input.dispatchMouseEvent", {"type": "mousePressed", "x": x0, "y": y0, "button": "left", "clickCount": 1})
    for k in range(1, 6):
        browser.send("Input.dispatchMouseEvent", {"type": "mouseMoved", "x": x0 + (x1 - x0) * k / 5, "y": y0,
                                                  "button": "left", "buttons": 1})
    browser.send("Input.dispatchMouseEvent", {"type": "mouseReleased", "x": x1, "y": y0, "button": "left", "clickCount": 1})
    settle()
    check(abs(now() - (frame / fps + 1e-5)) < 2e-5,
          f"a drag to 1/2 of a plot seeks to frame {frame} under the pointer: currentTime {now():.6f}")

    browser.js("(() => { const s = document.getElementById('speed'); s.value = '2';"
               " s.dispatchEvent(new Event('change')); })()")
    check(browser.js("document.getElementById('video').playbackRate") == 2, "the speed selector sets 2x")
    browser.js("(() => { const s = document.getElementById('speed'); s.value = '1';"
               " s.dispatchEvent(new Event('change')); })()")

    cursor = lambda: browser.js("vibraPage.panels[0].playhead.style.transform")
    browser.key("Home", "Home", 36)
    settle()
    before = cursor()
    browser.key(" ", "Space", 32)
    browser.wait_for("document.getElementById('video').currentTime > 0.3", 5)
    playing = not browser.js("document.getElementById('video').paused")
    after = cursor()
    check(playing and now() > 0.3, f"Space plays (currentTime {now():.3f} s)")
    check(before != after, f"the cursor follows the video: {before} -> {after}")
    browser.key(" ", "Space", 32)
    check(browser.wait_for("document.getElementById('video').paused", 2), "Space pauses")

    # Wheel zoom narrows every panel's time axis alike; a double-click resets.
    scales = "vibraPage.panels.map(p => [p.u.scales.x.min, p.u.scales.x.max])"
    x, y = plot_point(browser, 0, 0.5, 0.5)
    browser.wheel(x, y, -600)
    browser.wait_for("vibraPage.view[1] - vibraPage.view[0] < " + str(0.9 * T), 3)
    zoomed = browser.js(scales)
    linked = all(abs(s[0] - zoomed[0][0]) < 1e-9 and abs(s[1] - zoomed[0][1]) < 1e-9 for s in zoomed)
    check(zoomed[0][1] - zoomed[0][0] < 0.9 * T and linked, f"the wheel zooms all {len(zoomed)} time axes together: {zoomed[0]}")
    browser.screenshot(screenshot.with_name(screenshot.stem + "_zoomed.png"))
    browser.click(x, y, count=2)
    browser.wait_for("vibraPage.view[1] - vibraPage.view[0] > " + str(0.999 * T), 3)
    reset = browser.js(scales)
    check(all(abs(s[1] - s[0] - T) < 1e-9 * T for s in reset), "a double-click shows the whole run again")
    browser.key("Home", "Home", 36)
    settle()
    browser.key("ArrowRight", "ArrowRight", 39)  # a cursor to see in the screenshot
    settle()
    browser.screenshot(screenshot)
    print("      screenshot: " + str(screenshot))


def check_figure(browser, page):
    browser.load(page)
    entries = browser.js("[...document.querySelectorAll('#legend label')].map(l => l.dataset.key)")
    check(entries == ["undamped", "exact"], f"a figure's legend lists its curves: {entries}")
    browser.js("document.querySelector('#legend label[data-key=exact]').click()")
    check(browser.js("vibraPage.panels[0].u.series[2].show") is False, "the legend hides the exact solution")


def check_frames_player(browser, page, fps):
    browser.load(page)
    check(browser.wait_for("document.getElementById('frames').complete && document.getElementById('frames').naturalWidth > 0", 5),
          "the frames player shows frame 0")
    browser.key("ArrowRight", "ArrowRight", 39)
    src = browser.js("document.getElementById('frames').src")
    check(src.endswith("player_files/frame_0001.png") and abs(browser.js("vibraPage.media.time") - 1 / fps) < 1e-9,
          "ArrowRight steps the frames player one frame: " + src.rsplit("/", 1)[-1])


def check_no_problems(errors, fetched):
    """No console errors, and nothing fetched but file: and data: URLs (the page needs no network)."""
    check(not errors, "no console errors" + ("" if not errors else ": " + " | ".join(errors)))
    remote = [u for u in fetched if not u.startswith(("file:", "data:", "blob:"))]
    check(not remote, f"nothing fetched from the network ({len(fetched)} requests, all file: or data:)"
          + ("" if not remote else ": " + ", ".join(remote)))


def verdict(passed):
    """The exit status: 1 when a check failed (saying how many), else 0 (saying `passed`)."""
    if failures:
        print(f"{len(failures)} check(s) failed")
        return 1
    print(passed)
    return 0


def find_chromium(unchecked):
    """Chromium's path and 0, or None and the exit code to return: SKIP on a developer's machine, 1 with CI=true
    (scripts/setup installs Chromium there). `unchecked` says what then goes unchecked."""
    chromium = shutil.which("chromium") or shutil.which("chromium-browser")
    if chromium:
        return chromium, 0
    if os.environ.get("CI") == "true":
        print("FAIL: chromium is not installed: install the Debian package chromium (scripts/setup does);"
              " CI=true, so the browser test must run, not skip")
        return None, 1
    print("SKIPPED: chromium is not installed (scripts/setup installs it); " + unchecked)
    return None, SKIP


def main():
    args = sys.argv[1:]
    if not args:
        print(__doc__)
        return 2
    vibra = args[0]
    screenshot = Path(args[args.index("--screenshot") + 1]) if "--screenshot" in args else None
    chromium, missing = find_chromium("the page was not checked in a browser")
    if not chromium:
        return missing
    work = Path(tempfile.mkdtemp(prefix="vibra_page_"))
    keep = "--keep" in args
    try:
        directory = work / "lecture page ø"  # links must survive spaces and non-ASCII names
        directory.mkdir()
        page = directory / "Pendel ø.html"
        fps, frames = 30, 31  # periods=0.5: T = pi, speed = a period in 2 s, so 31 frames
        run([vibra, "render", "--size", "480x270", "--set", "periods=0.5", "--every", "2", "-q", "-o", str(page)])
        rows = list(csv.reader(open(page.parent / (page.stem + "_files") / (page.stem + ".csv"))))
        T = float(rows[-1][0])
        run([vibra, "plot", "undamped", "--panels", "u,exact", "--set", "periods=3", "-o", str(directory / "figure.html")])
        run([vibra, "render", "--size", "320x180", "--set", "periods=0.5", "--frames-player", "-q",
             "-o", str(directory / "player.html")])
        screenshot = screenshot or work / "lecture_page.png"

        browser = Chromium(chromium, str(work / "profile"))
        try:
            browser.open_tab(1400, 1250)
            check_lecture(browser, page, T, fps, frames, screenshot)
            check_figure(browser, directory / "figure.html")
            check_frames_player(browser, directory / "player.html", fps)
            errors, fetched = browser.problems()
        finally:
            browser.close()
        check_no_problems(errors, fetched)
    finally:
        if keep:
            print("kept " + str(work))
        else:
            shutil.rmtree(work, ignore_errors=True)
    return verdict("all browser checks passed")


if __name__ == "__main__":
    sys.exit(main())
