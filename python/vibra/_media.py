"""vibra.render and what it returns: a Video or an Image that shows itself
in a notebook cell and is path-like (open(video), os.fspath(video))."""

import base64
import html
import os
from pathlib import Path

from ._native import native, path_text
from ._keys import assignments, comparison_text, pacing_texts, size_text, value_text

# Videos up to this size are embedded in the notebook as a data URI; larger
# ones are linked by their path relative to the notebook's directory, so the
# notebook file stays small.
EMBED_LIMIT = 20 * 2**20

VIDEO_TYPES = {".mp4": "video/mp4", ".webm": "video/webm", ".mkv": "video/x-matroska", ".ogv": "video/ogg"}


class _Output(os.PathLike):
    def __init__(self, path):
        self.path = Path(path)

    def __fspath__(self):
        return os.fspath(self.path)

    @property
    def data(self):
        """The file's bytes."""
        return self.path.read_bytes()

    def _relative_url(self):
        return html.escape(os.path.relpath(self.path).replace(os.sep, "/"))

    def _data_uri(self, mime):
        return f"data:{mime};base64," + base64.b64encode(self.data).decode("ascii")

    def __repr__(self):
        return f"{type(self).__name__}({os.fspath(self.path)!r})"


class Video(_Output):
    """A rendered video file. In a notebook it plays in the cell: embedded up
    to EMBED_LIMIT bytes, linked by its relative path beyond."""

    def _repr_html_(self):
        suffix = self.path.suffix.lower()
        embed = self.path.stat().st_size <= EMBED_LIMIT
        if suffix == ".gif":
            src = self._data_uri("image/gif") if embed else self._relative_url()
            return f'<img src="{src}" alt="{html.escape(self.path.name)}">'
        mime = VIDEO_TYPES.get(suffix, "video/mp4")
        src = self._data_uri(mime) if embed else self._relative_url()
        return (f'<video controls loop style="max-width: 100%"><source src="{src}" type="{mime}">'
                f'<a href="{self._relative_url()}">{html.escape(self.path.name)}</a></video>')

    def _repr_mimebundle_(self, include=None, exclude=None):
        return {"text/html": self._repr_html_(), "text/plain": repr(self)}


class Image(_Output):
    """A still (PNG, SVG or PDF) that shows itself in a notebook."""

    def _repr_mimebundle_(self, include=None, exclude=None):
        suffix = self.path.suffix.lower()
        bundle = {"text/plain": repr(self)}
        if suffix == ".png":
            bundle["image/png"] = base64.b64encode(self.data).decode("ascii")
        elif suffix == ".svg":
            bundle["image/svg+xml"] = self.data.decode("utf-8")
        else:
            bundle["text/html"] = self._repr_html_()
        return bundle

    def _repr_html_(self):
        suffix = self.path.suffix.lower()
        if suffix == ".png":
            return f'<img src="{self._data_uri("image/png")}" alt="{html.escape(self.path.name)}">'
        return f'<a href="{self._relative_url()}">{html.escape(self.path.name)}</a>'


def render(scene="pendulum", out=None, at=None, *, size=None, fps=None, layout=None, speed=None,
           window=None, window_mode=None, compare=None, slow=None, pause=None, title=None, equation=False,
           notes=None, frame_per_step=False, frames_player=False, codec="", quality="medium", crf=-1, preset="",
           threads=0, transparent=False, quiet=True, **keys):
    """Renders a scene as `vibra render` does: a video (out="name.mp4", .webm,
    .mkv, .ogv or .gif; default SCENE.mp4), or with at=T one still (out=
    "name.png", .svg or .pdf; default SCENE.png). PNG frame patterns
    ("frames/tmp_%04d.png") and pages ("page.html", with their videos and
    CSV in page_files/) are written too and returned as a Path. Other keywords are scene keys (size=(1280, 720) or
    "1280x720", fps, layout="fbd", speed, window="8periods", ...) or keys of
    the scene's model (Theta=40, alpha=0.8, T=20). compare={"scheme": ["forward-euler",
    "rk4"]} (or "scheme=forward-euler,rk4") draws one run per value together, as
    --compare does. transparent=True draws no background (PNG with alpha, .webm
    VP9 with alpha, .mov ProRes 4444, SVG/PDF without the background rectangle).
    slow="2-4:4" (or (2, 4, 4), or a list of them) plays simulated times 2 to 4
    four times slower; pause="3:1" (or (3, 1), or a list) holds t = 3 for 1 s
    of video, as --slow and --pause do. title="The damped pendulum" puts a
    title across the top, equation=True the model's equation of motion beside
    or under it (and, comparing schemes, each scheme's update formula in the
    legend); notes=["2-4: drag takes energy out @theta"] adds callouts, as
    --title, --equation and --note do. Returns a Video or an Image.
    """
    scene = path_text("render", "scene", scene)
    settings = []
    for key, value in (("size", size), ("fps", fps), ("layout", layout), ("speed", speed),
                       ("window", window), ("window_mode", window_mode), ("compare", comparison_text(compare))):
        if value is not None:
            settings.append((key, size_text(value) if key == "size" else value_text(key, value)))
    if title is not None:
        settings.append(("title", str(title)))
    if equation:
        settings.append(("equation", "true"))
    if isinstance(notes, str):
        notes = [notes]
    for note in notes or []:
        settings.append(("notes", str(note)))
    settings += [("slow", text) for text in pacing_texts("slow", slow)]
    settings += [("pause", text) for text in pacing_texts("pause", pause)]
    settings += [tuple(a.split("=", 1)) for a in assignments(keys)]
    if out is None:
        out = Path(scene).stem + (".png" if at is not None else ".mp4")
    out = path_text("render", "out", out)
    native("render", output="out")(scene, settings, out, None if at is None else float(at), frame_per_step,
                                   frames_player, codec, quality, crf, preset, threads, transparent, quiet)
    suffix = Path(out).suffix.lower()
    if at is not None:
        return Image(out)
    if suffix in VIDEO_TYPES or suffix == ".gif":
        return Video(out)
    return Path(out)


def lecture(storyboard, output=None, *, shot=None, codec="", quality="medium", crf=-1, preset="", threads=0,
            force=False, quiet=True, mute=False, present=False, shots_dir=None):
    """Plays a storyboard's shots into one video as `vibra lecture` does:
    output="name.mp4" or .webm (default: the storyboard's name .mp4), with
    name.vtt (subtitles) beside it, a chapter per shot and a subtitle track;
    or "page.html" (a page with a chapter list; returned as a Path). shot=N
    renders shot N alone. Shots with say = "..." speak (AAC or Opus in the
    video); mute=True leaves the sound track out, as --mute. present=True
    with output="talk.html" makes the slides of --present; shots_dir="shots"
    writes every shot as its own MP4 and PNG with index.md and beamer.tex, as
    --shots-dir. Returns a Video, or the page's Path.
    """
    storyboard = path_text("lecture", "storyboard", storyboard)
    if output is None:
        output = Path(storyboard).stem + ".mp4"
    output = path_text("lecture", "output", output)
    shots_dir = "" if shots_dir is None else path_text("lecture", "shots_dir", shots_dir)
    native("lecture")(storyboard, output, shot, codec, quality, crf, preset, threads, force, quiet, bool(mute),
                      bool(present), shots_dir)
    if Path(output).suffix.lower() in VIDEO_TYPES:
        return Video(output)
    return Path(output)


def plot(model="pendulum", out=None, *, panels=None, compare=None, annotate=None, size=None, transparent=False,
         **keys):
    """Draws a model's run as `vibra plot` does: a figure (out="name.png",
    .svg or .pdf; default MODEL.png) of its panels, or out="name.html" a page
    of linked, zoomable plots (returned as a Path). panels="u,exact" (or a
    list) chooses the panels; compare={"scheme": ["forward-euler", "rk4"]}
    (or "scheme=forward-euler,rk4") draws one run per value together;
    annotate="mesh" marks every step; size=(1280, 720) or "1280x720";
    transparent=True draws no background. Other keywords are the model's
    keys (Theta=40, alpha=0.8, T=20). Returns an Image, or the page's Path.
    """
    model = path_text("plot", "model", model)
    if out is None:
        out = model + ".png"
    out = path_text("plot", "out", out)
    panels = ",".join(panels) if isinstance(panels, (list, tuple)) else (panels or "")
    native("plot", output="out")(model, assignments(keys), out, panels, "" if size is None else size_text(size),
                                 comparison_text(compare) or "", annotate or "", transparent)
    return Path(out) if Path(out).suffix.lower() == ".html" else Image(out)
