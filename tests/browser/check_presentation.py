#!/usr/bin/env python3
"""Drives vibra's presentation page (vibra lecture --present) in headless Chromium with key events.

From file:// with the network emulated off, on a storyboard of four shots
(a card that holds, a scene that goes on by itself, a scene that plays 1 s
once and loops the rest, a card that loops), checks: the first shot starts
on entering; a shot holds, goes on or loops as its storyboard says; → ↓
Space PageDown go on and ← ↑ PageUp go back, Home and End, a number and
Enter jumps; B blacks the screen, P pauses; the progress line; the address
keeps the slide (#N) and a reload stays there; S opens the speaker view,
which follows the main window (title, notes, next shot's first frame, the
shot's simulated time) and whose keys drive it; no console errors and
nothing fetched but file: URLs.

Usage: check_presentation.py VIBRA [--screenshots DIR] [--example STORYBOARD]
--example renders that storyboard instead (at its own size) and saves the
screenshots docs/lecture.md shows: slide 2 and the speaker view.
Exit 77 (skipped) only when Chromium is not installed, and then only on a
developer's machine: with CI=true a missing Chromium fails the test.
"""
import shutil
import sys
import tempfile
import time
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))
from check_lecture_page import Chromium, check, check_no_problems, find_chromium, run, verdict  # noqa: E402

# The storyboard the C++ tests use too (tests/scenes/lecture/lecture_present_test.cpp): 10 fps, shots of 1, 2, 3 and 0.5 s;
# a card that holds, a scene that goes on by itself, one that plays 1 s once and loops the rest, a card that loops.
STORY = Path(__file__).resolve().parent / "present_story.toml"

KEYS = {"ArrowRight": 39, "ArrowLeft": 37, "ArrowDown": 40, "ArrowUp": 38, "PageDown": 34, "PageUp": 33,
        "Home": 36, "End": 35, "Enter": 13, " ": 32}


def press(browser, key):
    code = {" ": "Space"}.get(key, key if len(key) > 1 else ("Key" + key.upper() if key.isalpha() else "Digit" + key))
    keycode = KEYS.get(key, ord(key.upper()) if len(key) == 1 else 0)
    for kind in ("keyDown", "keyUp"):
        params = {"type": kind, "key": key, "code": code, "windowsVirtualKeyCode": keycode}
        if kind == "keyDown" and len(key) == 1:
            params["text"] = key
        browser.send("Input.dispatchKeyEvent", params)


def load_url(browser, url):
    """Loads `url` (a file: URL with an address such as #3) and waits for its load event."""
    with browser.lock:
        browser.events = [e for e in browser.events if e.get("method") != "Page.loadEventFired"]
    browser.send("Page.navigate", {"url": url})
    browser.wait_event("Page.loadEventFired")


def slide(browser):
    return browser.js("vibraPresent.current")


def moves_to(browser, key, index, what):
    """Presses `key` and checks the page is on slide `index` (0-based) with the address #index+1."""
    press(browser, key)
    ok = browser.wait_for(f"vibraPresent.current === {index} && location.hash === '#{index + 1}'", 3)
    check(ok, f"{what}: slide {index + 1}, address #{index + 1} (on slide {slide(browser) + 1},"
              f" {browser.js('location.hash')})")


def playing(browser, index):
    return browser.wait_for(f"(v => !v.paused && v.currentTime > 0)(vibraPresent.videos[{index}])", 4)


def check_endings(browser):
    check(browser.wait_for("vibraPresent.current === 0", 5) and browser.js("location.hash") == "#1",
          "the page opens on slide 1, the address #1")
    check(playing(browser, 0), "the first shot starts on entering")
    check(browser.wait_for("vibraPresent.videos[0].ended", 5), "the card plays to its end")
    time.sleep(0.6)
    check(slide(browser) == 0 and browser.js("vibraPresent.videos[0].ended"),
          "a card holds its last frame: still slide 1")
    moves_to(browser, "ArrowRight", 1, "ArrowRight goes on")
    check(playing(browser, 1), "the next shot starts on entering")
    check(browser.wait_for("vibraPresent.current === 2 && location.hash === '#3'", 5),
          "then = \"next\": the shot goes on to slide 3 by itself, the address follows")
    browser.wait_for("vibraPresent.videos[2].currentTime > 0.2", 3)  # past the entry's own seek to 0
    browser.js("window.seeks = []; vibraPresent.videos[2].addEventListener('seeked', e => seeks.push(e.target.currentTime)); 0")
    check(browser.wait_for("vibraPresent.loops >= 2", 8), "intro + loop: the shot loops on")
    seeks = browser.js("seeks")
    check(seeks and all(abs(s - 1.0) < 0.06 for s in seeks) and slide(browser) == 2,
          f"each loop starts after the 1 s intro, on slide 3: seeks to {seeks}")
    check(playing(browser, 2), "the loop keeps playing")


def check_moves(browser):
    moves_to(browser, "ArrowLeft", 1, "ArrowLeft goes back")
    moves_to(browser, "PageUp", 0, "PageUp (a clicker's back) goes back")
    moves_to(browser, "PageDown", 1, "PageDown (a clicker's next) goes on")
    moves_to(browser, "ArrowUp", 0, "ArrowUp goes back")
    moves_to(browser, "End", 3, "End goes to the last slide")
    moves_to(browser, "Home", 0, "Home goes to the first")
    moves_to(browser, "ArrowDown", 1, "ArrowDown goes on")
    moves_to(browser, " ", 2, "Space goes on")
    press(browser, "4")
    check(browser.js("document.getElementById('status').textContent") == "go to 4", "a number typed is shown")
    moves_to(browser, "Enter", 3, "4 then Enter jumps to slide 4")
    check(browser.js("document.getElementById('progress-bar').style.width") == "100%", "the progress line is full on the last")
    check(browser.js("vibraPresent.videos[3].loop") and playing(browser, 3), "then = \"loop\": the card loops whole")
    press(browser, "9")
    press(browser, "Enter")
    time.sleep(0.2)
    check(slide(browser) == 3, "9 then Enter (no slide 9) stays")
    moves_to(browser, "PageDown", 3, "PageDown on the last slide stays")
    press(browser, "3")
    moves_to(browser, "Enter", 2, "3 then Enter jumps back to slide 3")
    check(browser.js("document.getElementById('progress-bar').style.width") == "75%", "the progress line: 3 of 4")
    press(browser, "b")
    check(browser.js("!document.getElementById('black').hidden"), "B blacks the screen")
    press(browser, "b")
    check(browser.js("document.getElementById('black').hidden"), "B again shows the slide")
    press(browser, "p")
    check(browser.wait_for("vibraPresent.videos[2].paused", 2), "P pauses")
    press(browser, "p")
    check(playing(browser, 2), "P again plays on")


def check_reload(browser, page):
    browser.send("Page.navigate", {"url": "about:blank"})
    time.sleep(0.3)
    load_url(browser, page.resolve().as_uri() + "#3")
    check(browser.wait_for("vibraPresent.current === 2", 5) and playing(browser, 2),
          "a reload at #3 stays on slide 3 and plays it")


def speaker_session(browser):
    for _ in range(50):
        for t in browser.send("Target.getTargets", session=False)["targetInfos"]:
            if t["type"] == "page" and t["url"].endswith("#speaker"):
                return browser.send("Target.attachToTarget", {"targetId": t["targetId"], "flatten": True},
                                    session=False)["sessionId"]
        time.sleep(0.1)
    return None


def in_session(browser, session, action):
    saved, browser.session = browser.session, session
    try:
        return action()
    finally:
        browser.session = saved


def check_speaker(browser, screenshots):
    press(browser, "s")
    session = speaker_session(browser)
    check(session is not None, "S opens the speaker view, a second window (#speaker)")
    if session is None:
        return
    speaker = lambda expression, timeout=4: in_session(browser, session, lambda: browser.wait_for(expression, timeout))
    title = "document.getElementById('speaker-title').textContent"
    check(speaker(f"{title} === '3 / 4  spring'"), "the speaker view shows the current slide")
    check(speaker("document.getElementById('speaker-next-still').src.endsWith('04-the-end.png')"),
          "and the next shot's first frame")
    check(speaker("/^0:0[0-9]$/.test(document.getElementById('speaker-elapsed').textContent)"), "and the elapsed time")
    check(speaker("/^t = [0-9]+\\.[0-9]{2}$/.test(document.getElementById('speaker-time').textContent)"),
          "and the shot's simulated time")
    # Paused, the speaker's clock is the simulated time of the frame on screen: slide 3 shows T = 2 over
    # 30 frames, so frame k shows t = 2 k / 29 (the frame as the browser presented it, seen by the test).
    browser.js("(v => { const on = (now, m) => { window.lastFrame = Math.round(m.mediaTime * 10);"
               " v.requestVideoFrameCallback(on); }; v.requestVideoFrameCallback(on); })(vibraPresent.videos[2]); 0")
    browser.wait_for("window.lastFrame > 0", 3)
    press(browser, "p")
    time.sleep(0.5)
    k = browser.js("window.lastFrame")
    expected = f"t = {2 * k / 29:.2f}"
    check(speaker(f"document.getElementById('speaker-time').textContent === '{expected}'"
                  " && document.getElementById('speaker-state').textContent === 'paused'"),
          f"paused at frame {k}, the speaker view shows its simulated time, {expected}, and 'paused'")
    press(browser, "p")
    press(browser, "ArrowLeft")
    check(speaker(f"{title} === '2 / 4  spring' && document.getElementById('speaker-notes').textContent"
                  " === 't = 0.5 to 1.5: halfway'", 1.2),
          "it follows the main window back to slide 2, with that shot's notes")
    if screenshots:
        in_session(browser, session, lambda: browser.screenshot(screenshots / "speaker_view.png"))
    in_session(browser, session, lambda: press(browser, "Home"))
    check(browser.wait_for("vibraPresent.current === 0", 3), "the speaker's Home moves the main window to slide 1")
    check(speaker(f"{title} === '1 / 4  Springs'"), "and the speaker view follows")


def main():
    args = sys.argv[1:]
    if not args:
        print(__doc__)
        return 2
    vibra = args[0]
    screenshots = Path(args[args.index("--screenshots") + 1]) if "--screenshots" in args else None
    example = Path(args[args.index("--example") + 1]).resolve() if "--example" in args else None
    chromium, missing = find_chromium("the presentation was not checked in a browser")
    if not chromium:
        return missing
    work = Path(tempfile.mkdtemp(prefix="vibra_present_"))
    try:
        page = work / "talk ø.html"  # links must survive spaces and non-ASCII names
        story = example or STORY
        run([vibra, "lecture", str(story), "--present", "-q", "-o", str(page)])
        browser = Chromium(chromium, str(work / "profile"))
        try:
            browser.open_tab(1280, 720)
            browser.send("Network.emulateNetworkConditions",
                         {"offline": True, "latency": 0, "downloadThroughput": -1, "uploadThroughput": -1})
            if example:
                take_example_screenshots(browser, page, screenshots or work)
            else:
                browser.load(page)
                check_endings(browser)
                check_moves(browser)
                check_reload(browser, page)
                check_speaker(browser, screenshots)
            errors, fetched = browser.problems()
        finally:
            browser.close()
        check_no_problems(errors, fetched)
    finally:
        shutil.rmtree(work, ignore_errors=True)
    return verdict("all presentation checks passed")


def take_example_screenshots(browser, page, folder):
    """The example lecture: slide 2 held at its pause, and the speaker view beside it."""
    load_url(browser, page.resolve().as_uri() + "#2")
    check(browser.wait_for("vibraPresent.current === 1 && vibraPresent.videos[1].currentTime > 4.2", 10), "slide 2 plays")
    press(browser, "p")
    browser.screenshot(folder / "lecture_present.png")
    press(browser, "s")
    session = speaker_session(browser)
    check(session is not None, "the speaker view opens")
    if session:
        in_session(browser, session, lambda: browser.send("Emulation.setDeviceMetricsOverride",
                                                          {"width": 1000, "height": 640, "deviceScaleFactor": 1,
                                                           "mobile": False}))
        in_session(browser, session, lambda: browser.wait_for(
            "document.getElementById('speaker-title').textContent.startsWith('2 / 4')", 5))
        time.sleep(0.5)
        in_session(browser, session, lambda: browser.screenshot(folder / "lecture_speaker.png"))
    print("      screenshots in " + str(folder))


if __name__ == "__main__":
    sys.exit(main())
