"""vibra.explore: the live page of `vibra render SCENE -o PAGE.html --live`,
shown inline in a notebook cell, where its controls re-solve in the browser."""

import html
import os
from pathlib import Path

from ._keys import assignments, size_text
from ._native import native, path_text


class LivePage(os.PathLike):
    """A live page on disk (PAGE.html and PAGE_files/). In a notebook it
    shows inline, in a frame as large as the page's picture and controls."""

    def __init__(self, path, width, height):
        self.path = Path(path)
        self.width, self.height = width, height

    def __fspath__(self):
        return os.fspath(self.path)

    def __repr__(self):
        return f"LivePage({os.fspath(self.path)!r})"

    def _repr_html_(self):
        # By its path relative to the notebook's folder, as the notebook's server serves it
        # (the page loads its WebAssembly and fonts from PAGE_files/ beside it).
        src = html.escape(os.path.relpath(self.path).replace(os.sep, "/"))
        return (f'<iframe src="{src}" width="{self.width + 40}" height="{self.height + 420}" '
                f'style="border: 0; max-width: 100%" title="{html.escape(self.path.name)}"></iframe>')


def explore(scene="pendulum", out=None, *, size=None, quiet=True, **keys):
    """Writes the live page of a scene, as `vibra render SCENE -o PAGE.html
    --live` does (default out: SCENE_live.html, with SCENE_live_files/), and
    returns a LivePage that shows it inline in a notebook: a control for
    every key of the model (Theta, alpha, scheme...), play, pause, speed and
    a time scrubber, re-solved and drawn in the browser. SCENE is a built-in
    scene, a model or a scene file (its text goes into the page). Keywords are the
    model's keys (Theta=45, alpha=0.8), the page's starting state, or scene
    keys such as size=(960, 540). Raises ValueError with the CLI's reason for
    a bad key or value."""
    scene = path_text("explore", "scene", scene)
    settings = [("size", size_text(size))] if size is not None else []
    settings += [tuple(a.split("=", 1)) for a in assignments(keys)]
    out = path_text("explore", "out", out if out is not None else Path(scene).stem + "_live.html")
    native("live_page", shown="explore", output="out")(scene, settings, out, quiet)
    width, height = 1280, 720
    if size is not None:
        width, height = (int(v) for v in size_text(size).split("x"))
    return LivePage(out, width, height)
