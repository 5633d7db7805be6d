#!/usr/bin/env python3
"""Drives vibra's live page (`vibra render SCENE -o PAGE.html --live`) in headless Chromium.

Writes a 960x540 pendulum page of a 10-period run into a directory whose name
has a space and non-ASCII letters, opens it from file:// with the network off
and checks: it starts
with nothing fetched but file: and data: URLs; moving a slider, choosing in a
select and typing in a number box re-solves in the page, whose rows equal the
native `vibra solve` rows to 1e-12; a
share link restores a state; "Render this" shows the command, which run
natively draws the still the page shows (PSNR at least 30 dB, and no part of
the frame, body, arrow or label, more than a pixel off: for the pendulum and
every other built-in scene, a spring comparing two dt with its plot panels
and legend among them, and a user's scene file); a bad value typed in a number box is
refused with the CLI's one-line reason; frames per second while playing and
the latency of a moved control. Prints the figures; saves a screenshot.

Usage: check_live_page.py VIBRA [--screenshot FILE.png]
Exit 77 (skipped) when Chromium is missing on a developer's machine, or when
vibra was built without the browser build (then `--live` says so).
"""
import base64
import math
import os
import shlex
import subprocess
import sys
import tempfile
import time
import zlib
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))
from check_lecture_page import Chromium, check, check_no_problems, find_chromium, verdict  # noqa: E402

SKIP = 77
SIZE = (960, 540)
BASE = ["--size", "960x540", "--set", "periods=10"]


def png_pixels(data):
    """Width, height and RGBA rows of an 8-bit RGB or RGBA, non-interlaced PNG."""
    assert data[:8] == b"\x89PNG\r\n\x1a\n"
    i, idat, width, height, kind = 8, b"", 0, 0, 6
    while i < len(data):
        n = int.from_bytes(data[i:i + 4], "big")
        tag, body = data[i + 4:i + 8], data[i + 8:i + 8 + n]
        if tag == b"IHDR":
            width, height, kind = int.from_bytes(body[:4], "big"), int.from_bytes(body[4:8], "big"), body[9]
        elif tag == b"IDAT":
            idat += body
        i += 12 + n
    channels = 4 if kind == 6 else 3
    raw, stride, rows, previous = zlib.decompress(idat), width * channels, [], bytearray(width * channels)
    for y in range(height):
        line = raw[y * (stride + 1):(y + 1) * (stride + 1)]
        f, row = line[0], bytearray(line[1:])
        for x in range(stride):
            a = row[x - channels] if x >= channels else 0
            b = previous[x]
            c = previous[x - channels] if x >= channels else 0
            if f == 1:
                row[x] = (row[x] + a) & 255
            elif f == 2:
                row[x] = (row[x] + b) & 255
            elif f == 3:
                row[x] = (row[x] + (a + b) // 2) & 255
            elif f == 4:
                p = a + b - c
                pa, pb, pc = abs(p - a), abs(p - b), abs(p - c)
                row[x] = (row[x] + (a if pa <= pb and pa <= pc else b if pb <= pc else c)) & 255
        rows.append(row if channels == 4 else bytearray(v for k in range(width) for v in (*row[3 * k:3 * k + 3], 255)))
        previous = row
    return width, height, rows


def psnr(a, b):
    """PSNR in dB of two pictures' RGB (alpha ignored: the page's canvas is on white)."""
    total, count = 0, 0
    for ra, rb in zip(a[2], b[2]):
        for x in range(0, len(ra), 4):
            for k in range(3):
                d = ra[x + k] - rb[x + k]
                total += d * d
            count += 3
    return float("inf") if total == 0 else 10 * math.log10(255 * 255 * count / total)


def colour_centre(picture, colour, box, tolerance=30):
    """The centre of the pixels within `tolerance` of `colour` (RGB) inside box (x0, y0, x1, y1), or None."""
    sx = sy = n = 0
    x0, y0, x1, y1 = box
    for y in range(y0, y1):
        row = picture[2][y]
        for x in range(x0, x1):
            if all(abs(row[4 * x + k] - colour[k]) <= tolerance for k in range(3)):
                sx, sy, n = sx + x, sy + y, n + 1
    return (sx / n, sy / n) if n else None


# The diagram's bodies and arrows by colour, each with its label (the
# free-body diagram's part of the 960x540 frame, above the legend).
DIAGRAM = (0, 40, 440, 470)
BODIES = {"the bob": (0, 115, 179), "the wire force S and its label": (0, 158, 115),
          "gravity mg and its label": (213, 94, 0)}


def native(vibra, args, cwd):
    return subprocess.run([vibra] + args, capture_output=True, text=True, cwd=cwd)


def native_rows(vibra, settings, cwd):
    out = native(vibra, ["solve", "pendulum"] + [w for s in settings for w in ("--set", s)], cwd).stdout
    lines = out.strip().split("\n")
    return [[float(v) for v in line.split(",")] for line in lines[1:]]


def page_rows(browser):
    """The rows of the page's model keys as they stand, solved by the page's own WebAssembly core."""
    return browser.js("""(() => {
      const p = vibraLivePage, core = p.core;
      const lines = p.keys.filter(k => p.values[k.name]).map(k => `${k.name}=${p.values[k.name]}`);
      if (core.ccall('vibra_solve', 'number', ['string', 'string'], ['pendulum', lines.join('\\n')]) !== 0) return null;
      const width = core.UTF8ToString(core._vibra_columns()).split(',').length, n = core._vibra_row_count();
      const at = core._vibra_rows() >> 3, flat = core.HEAPF64.subarray(at, at + n * width), rows = [];
      for (let i = 0; i < n; i++) rows.push(Array.from(flat.subarray(i * width, (i + 1) * width)));
      return rows; })()""")


def page_settings(browser):
    return browser.js("vibraLivePage.keys.filter(k => vibraLivePage.values[k.name])"
                      ".map(k => `${k.name}=${vibraLivePage.values[k.name]}`)")


def largest_difference(a, b):
    if a is None or len(a) != len(b):
        return float("inf")
    return max((abs(x - y) / max(1, abs(y)) for ra, rb in zip(a, b) for x, y in zip(ra, rb)), default=0)


def move(browser, selector, value):
    """Sets a control's value as a user would, then fires its events; the page's latency of that change."""
    browser.js(f"""(() => {{ const e = document.querySelector({selector!r}); e.focus(); e.value = {value!r};
                   e.dispatchEvent(new Event('input')); e.dispatchEvent(new Event('change')); }})()""")
    return browser.js("vibraLivePage.lastLatency")


def check_controls(browser, vibra, work):
    latencies = []
    for what, selector, value in [("a slider", "input[type=range][data-key=Theta]", "45"),
                                  ("a select", "select[data-key=scheme]", "euler-cromer"),
                                  ("a number box", "input[type=number][data-key=alpha]", "0.8")]:
        latencies.append(move(browser, selector, value))
        settings = page_settings(browser)
        worst = largest_difference(page_rows(browser), native_rows(vibra, settings, work))
        check(worst <= 1e-12, f"{what} re-solves: the page's rows equal `vibra solve pendulum` ({worst:.1e}) for "
                              + " ".join(settings))
    return latencies


def page_frame(browser):
    data = browser.js("document.getElementById('frame').toDataURL('image/png')")
    return png_pixels(base64.b64decode(data.split(",", 1)[1]))


def shifted_blocks(frame, still, size=24):
    """The size x size blocks of the frame under 30 dB against the still, with the best PSNR any shift
    of at most a pixel gives each: (x, y, dB, best dB). A label or a body more than a pixel off leaves
    a block far below 20 dB even shifted (the pendulum's S placed 5 px off: 13.8 dB), while glyphs
    antialiased otherwise and a hatch a pixel apart stay above 24 dB."""
    width, height = len(frame[2][0]) // 4, len(frame[2])

    def block_db(x, y, dx, dy):
        total = 0
        for row in range(y, y + size):
            a, b = frame[2][row], still[2][row + dy]
            for col in range(4 * x, 4 * (x + size), 4):
                for k in range(3):
                    d = a[col + k] - b[col + 4 * dx + k]
                    total += d * d
        return float("inf") if total == 0 else 10 * math.log10(255 * 255 * 3 * size * size / total)

    found = []
    for y in range(1, height - size, size):
        for x in range(1, width - size, size):
            db = block_db(x, y, 0, 0)
            if db < 30:
                found.append((x, y, db, max(block_db(x, y, dx, dy) for dx in (-1, 0, 1) for dy in (-1, 0, 1))))
    return found


def check_picture(what, frame, still):
    """The page's frame against the native still: at least 30 dB, and nothing drawn more than a pixel off."""
    db = psnr(frame, still)
    check(db >= 30, f"{what}: the page's frame against the native still: {db:.1f} dB (at least 30)")
    off = [b for b in shifted_blocks(frame, still) if b[3] < 20]
    check(not off, f"{what}: every part of the frame (bodies, arrows, labels, legend, panels) within a pixel of "
                   "the still's" + "".join(f"; block at {x},{y}: {a:.1f} dB, {b:.1f} dB shifted" for x, y, a, b in off))
    return db


def native_still(browser, vibra, work, scene):
    """"Render this" clicked, its command run natively: the still it writes."""
    browser.js("document.getElementById('render_this').click()")
    command = browser.js("document.getElementById('command').textContent")
    words = shlex.split(command)
    r = native(vibra, words[1:], work)
    check(r.returncode == 0, f"{scene}: \"Render this\" runs natively: {command}" + ("" if r.returncode == 0 else ": " + r.stderr.strip()))
    return command, png_pixels((work / f"{scene}.png").read_bytes())


def check_still(browser, vibra, work):
    """The page's frame at t = 3 against `vibra render ... --at 3`, run as "Render this" shows it."""
    browser.js("(() => { const e = document.getElementById('time'); e.value = '3'; e.dispatchEvent(new Event('input')); })()")
    check(browser.wait_for("vibraLivePage.settled", 10), "the frame at rest is drawn as the still (its label chain)")
    command, still = native_still(browser, vibra, work, "pendulum")
    words = shlex.split(command)
    check(words[:3] == ["vibra", "render", "pendulum"] and "--at" in words and "Theta=50" in command,
          "\"Render this\" shows the vibra render command: " + command)
    frame = page_frame(browser)
    if os.environ.get("VIBRA_LIVE_KEEP"):
        keep = Path(os.environ["VIBRA_LIVE_KEEP"])
        (keep / "native.png").write_bytes((work / "pendulum.png").read_bytes())
        data = browser.js("document.getElementById('frame').toDataURL('image/png')")
        (keep / "page.png").write_bytes(base64.b64decode(data.split(",", 1)[1]))
    db = check_picture("the pendulum", frame, still)
    for name, colour in BODIES.items():
        a, b = colour_centre(frame, colour, DIAGRAM), colour_centre(still, colour, DIAGRAM)
        off = math.hypot(a[0] - b[0], a[1] - b[1]) if a and b else float("inf")
        check(off <= 1, f"{name}: where the native still draws it, within {off:.2f} px (at most 1)")
    return frame, still, db


# Every other built-in scene, each a page of its own at a time a share link gives: among them plot
# panels and a legend of compared runs, the bumpy road's hatched ground, subscripts (the bouncing ball's
# C_R, the RLC circuit's symbols) and a superscript (the orbit's panel's x10^-8).
OTHER_SCENES = [
    ("spring", ["--set", "compare=dt=0.3,0.15"], 4.5),
    ("bumpy_road", [], 2.5),
    ("rlc", [], 6),
    ("orbit", [], 5),
    ("bouncing_ball", [], 2),
    ("elastic_pendulum", [], 4),
    ("sliding_box", [], 3),
    ("washing_machine", [], 8),
    ("spring_dashpot", [], 3),
    ("pendulum_book", [], 4),
]


# A user's scene file: its text goes into the page, which sets it up with the same keys.
SCENE_FILE = """# A damped pendulum of the user's own
model = "pendulum"
Theta = 70
alpha = 0.3
periods = 4
"""


def check_scene_file(browser, vibra, work):
    """`vibra render swing.toml --live`: the page re-solves the file's scene and draws its still."""
    (work / "swing.toml").write_text(SCENE_FILE)
    page = work / "swing.html"
    r = native(vibra, ["render", "swing.toml", "--size", "960x540", "-o", str(page), "--live"], work)
    check(r.returncode == 0, "a scene file: vibra render swing.toml --live writes its page" + ("" if r.returncode == 0 else ": " + r.stderr))
    browser.send("Page.navigate", {"url": page.resolve().as_uri() + "#t=2"})
    ready = browser.wait_for("document.body.dataset.ready === 'true' && vibraLivePage.settled", 60)
    check(ready and browser.js("vibraLivePage.values.Theta") == "70", "a scene file: its page starts from the file's keys (Theta 70)")
    move(browser, "input[type=number][data-key=alpha]", "0.6")
    settings = page_settings(browser)
    worst = largest_difference(page_rows(browser), native_rows(vibra, settings, work))
    check(worst <= 1e-12 and "Theta=70" in settings, f"a scene file: a number box re-solves the file's scene to the rows of "
                                                     f"`vibra solve pendulum` ({worst:.1e})")
    browser.js("(() => { const e = document.getElementById('time'); e.value = '2'; e.dispatchEvent(new Event('input')); })()")
    check(browser.wait_for("vibraLivePage.settled", 10), "a scene file: the frame at rest")
    command, still = native_still(browser, vibra, work, "swing")
    check(shlex.split(command)[:3] == ["vibra", "render", "swing.toml"], f"a scene file: \"Render this\" names it: {command}")
    check_picture("a scene file", page_frame(browser), still)


def check_other_scenes(browser, vibra, work):
    for scene, args, t in OTHER_SCENES:
        page = work / f"{scene}.html"
        r = native(vibra, ["render", scene, "--size", "960x540"] + args + ["-o", str(page), "--live"], work)
        check(r.returncode == 0, f"{scene}: vibra render --live writes its page" + ("" if r.returncode == 0 else ": " + r.stderr))
        browser.send("Page.navigate", {"url": page.resolve().as_uri() + f"#t={t}"})
        ready = browser.wait_for("document.body.dataset.ready === 'true' && vibraLivePage.settled", 60)
        check(ready, f"{scene}: the page starts and its frame at t = {t} rests")
        _, still = native_still(browser, vibra, work, scene)
        frame = page_frame(browser)
        if os.environ.get("VIBRA_LIVE_KEEP"):
            keep = Path(os.environ["VIBRA_LIVE_KEEP"])
            (keep / f"{scene}_native.png").write_bytes((work / f"{scene}.png").read_bytes())
            data = browser.js("document.getElementById('frame').toDataURL('image/png')")
            (keep / f"{scene}_page.png").write_bytes(base64.b64decode(data.split(",", 1)[1]))
        check_picture(scene, frame, still)
        if "compare=dt=0.3,0.15" in args:
            check_comparison_control(browser, vibra, work)


def check_comparison_control(browser, vibra, work):
    """The comparison's values have a control: typed in, the runs are solved again and drawn as the CLI
    draws them; a bad one is refused with the CLI's reason."""
    move(browser, "input[data-key=compare]", "dt=0.3,0.1")
    settings = page_settings(browser)
    check("compare=dt=0.3,0.1" in settings, f"the comparison's values have a control: {' '.join(settings)}")
    browser.js("(() => { const e = document.getElementById('time'); e.value = '4.5'; e.dispatchEvent(new Event('input')); })()")
    check(browser.wait_for("vibraLivePage.settled", 10), "the comparison: the frame at rest")
    command, still = native_still(browser, vibra, work, "spring")
    check("compare=dt=0.3,0.1" in command, f"the comparison: \"Render this\" compares the values typed: {command}")
    check_picture("the comparison with the values typed", page_frame(browser), still)
    move(browser, "input[data-key=compare]", "dt=0.3,-1")
    shown = browser.js("document.getElementById('refusal').textContent")
    cli = native(vibra, ["render", "spring", "--set", "compare=dt=0.3,-1", "--at", "0", "-o", "refused.png"], work)
    check(cli.returncode == 2 and shown == cli.stderr.strip().removeprefix("vibra: error: "),
          f"the comparison: a bad value is refused with the CLI's reason: '{shown}'")


def check_share(browser, page):
    """A share link restores the keys and the time."""
    browser.send("Page.navigate", {"url": page.resolve().as_uri() + "#Theta=60&alpha=0.4&t=3"})
    browser.wait_for("document.body.dataset.ready === 'true'", 30)
    state = browser.js("[vibraLivePage.values.Theta, vibraLivePage.values.alpha, vibraLivePage.t,"
                       " document.querySelector('input[type=number][data-key=Theta]').value]")
    check(state == ["60", "0.4", 3, "60"], f"the share link #Theta=60&alpha=0.4&t=3 restores the state: {state}")


def check_refusal(browser, vibra, work):
    """A bad value typed in a number box: refused with the CLI's reason, the last good run kept."""
    before = browser.js("vibraLivePage.values.alpha")
    move(browser, "input[type=number][data-key=alpha]", "-1")
    shown = browser.js("[document.getElementById('refusal').hidden, document.getElementById('refusal').textContent,"
                       " document.querySelector('input[type=number][data-key=alpha]').getAttribute('aria-invalid'),"
                       " vibraLivePage.values.alpha]")
    cli = native(vibra, ["render", "pendulum", "--set", "alpha=-1", "--at", "0", "-o", "refused.png"], work)
    reason = cli.stderr.strip().removeprefix("vibra: error: ")
    check(cli.returncode == 2 and not shown[0] and shown[1] == reason,
          f"a bad value is refused with the CLI's one-line reason: '{shown[1]}'")
    check(shown[2] == "true" and shown[3] == before, "the box is marked invalid and the last good value stays")


def check_speed(browser):
    """Frames drawn per second while playing at speed 2 (60 frames of the clock a second asked), and draw times."""
    browser.js("vibraLivePage.drawTimes = []; document.getElementById('speed').value = '2';"
               " document.getElementById('time').value = '0'; document.getElementById('time').dispatchEvent(new Event('input'));"
               " vibraLivePage.drawTimes = []; document.getElementById('play').click()")
    started = time.time()
    time.sleep(3)
    drawn = browser.js("vibraLivePage.drawTimes.length")
    elapsed = time.time() - started
    times = sorted(browser.js("vibraLivePage.drawTimes"))
    browser.js("document.getElementById('pause').click()")
    fps = drawn / elapsed
    median = times[len(times) // 2] if times else float("inf")
    check(fps >= 30, f"{fps:.0f} frames drawn per second while playing at 960x540 (at least 30); "
                     f"a frame's draw: median {median:.1f} ms, slowest {times[-1] if times else 0:.1f} ms")
    return fps, median


def main():
    args = sys.argv[1:]
    vibra = str(Path(args[0]).resolve())
    screenshot = Path(args[args.index("--screenshot") + 1]) if "--screenshot" in args else None
    chromium, missing = find_chromium("the live page was not checked in a browser")
    if not chromium:
        return missing
    with tempfile.TemporaryDirectory() as tmp:
        work = Path(tmp) / "live page ü"
        work.mkdir()
        page = work / "explore.html"
        r = native(vibra, ["render", "pendulum"] + BASE + ["-o", str(page), "--live"], work)
        if r.returncode != 0 and "browser build" in r.stderr:
            print("SKIPPED: " + r.stderr.strip())
            return SKIP
        check(r.returncode == 0, "vibra render --live writes the page" + ("" if r.returncode == 0 else ": " + r.stderr))
        browser = Chromium(chromium, str(Path(tmp) / "profile"))
        try:
            browser.open_tab(1280, 1100)
            # The network off: the page needs nothing but its files.
            browser.send("Network.emulateNetworkConditions",
                         {"offline": True, "latency": 0, "downloadThroughput": -1, "uploadThroughput": -1})
            browser.load(page)
            check(browser.wait_for("document.body.dataset.ready === 'true'", 60), "the page starts from file:// with the network off")
            kinds = browser.js("[...new Set([...document.querySelectorAll('[data-key]')].map(e => e.dataset.kind))].sort()")
            check(kinds == ["number", "range", "select", "text"] or kinds == ["number", "range", "select"],
                  f"the keys have sliders, number boxes and selects: {kinds}")
            # The pendulum's L has no default (the wire's length is derived): its box says 'unset', not blank.
            unset = browser.js("(() => { const e = document.querySelector('input[type=number][data-key=L]');"
                               " return [e.value, e.placeholder]; })()")
            check(unset == ["", "unset"], f"a key with no value says 'unset' in its box: value and placeholder {unset}")
            latencies = check_controls(browser, vibra, work)
            check(max(latencies) <= 100, f"a new picture {max(latencies):.0f} ms at most after a control moves "
                                         f"at t = 0 (10 periods; {', '.join(f'{x:.0f}' for x in latencies)} ms)")
            # At t = 28.1 the frame is the 89th of its label chain: drawn at once, its chain only when it rests.
            browser.js("(() => { const e = document.getElementById('time'); e.value = '28.1';"
                       " e.dispatchEvent(new Event('input')); })()")
            late = move(browser, "input[type=range][data-key=Theta]", "50")
            check(late <= 100, f"a new picture {late:.0f} ms after a control moves at the end of a label chain "
                               "(t = 28.1; at most 100)")
            check_still(browser, vibra, work)
            check_refusal(browser, vibra, work)
            check_share(browser, page)
            if screenshot:
                browser.screenshot(screenshot)
                print("      screenshot: " + str(screenshot))
            check_speed(browser)
            check_other_scenes(browser, vibra, work)
            check_scene_file(browser, vibra, work)
            check_no_problems(*browser.problems())
        finally:
            browser.close()
    return verdict("the live page re-solves, draws and refuses as the CLI does")


if __name__ == "__main__":
    sys.exit(main())
