"""vibra.render: videos and stills that decode, show themselves in a
notebook (embedded or linked) and are path-like."""

import base64
import json
import os
import signal
import subprocess
import threading

import pytest

import vibra
from vibra import _media


def probe(path):
    out = subprocess.run(["ffprobe", "-v", "error", "-count_frames", "-show_streams", "-of", "json", os.fspath(path)],
                         capture_output=True, text=True, check=True).stdout
    return json.loads(out)["streams"][0]


def test_a_video_decodes_and_plays_inline(in_tmp):
    video = vibra.render(T=1, speed=1, fps=10, size=(320, 180), Theta=40)
    assert isinstance(video, vibra.Video)
    assert os.fspath(video) == "pendulum.mp4" and (in_tmp / "pendulum.mp4").is_file()
    stream = probe(video)
    assert (stream["codec_name"], stream["width"], stream["height"]) == ("h264", 320, 180)
    # The scene's dt is 2 pi/120, so T = 1 ends at 19 steps, t = 0.9948; at 10 fps and speed 1 the frames
    # are t = 0, 0.1, ..., 0.9: exactly 10 (a frame at t = 1 would lie past the run).
    assert int(stream["nb_read_frames"]) == 10
    html = video._repr_mimebundle_()["text/html"]
    assert html.startswith("<video") and "data:video/mp4;base64," in html
    embedded = html.split("base64,", 1)[1].split('"', 1)[0]
    assert base64.b64decode(embedded) == (in_tmp / "pendulum.mp4").read_bytes()
    with open(video, "rb") as f:  # path-like
        assert f.read(12)[4:8] == b"ftyp"


def test_a_large_video_is_linked_not_embedded(in_tmp, monkeypatch):
    (in_tmp / "clips").mkdir()
    video = vibra.render(out=in_tmp / "clips" / "big.webm", T=0.5, fps=10, size="320x180")
    assert probe(video)["codec_name"] == "vp9"
    monkeypatch.setattr(_media, "EMBED_LIMIT", 0)
    html = video._repr_html_()
    assert "base64" not in html and 'src="clips/big.webm"' in html and 'type="video/webm"' in html


def test_a_still_is_an_image(in_tmp):
    image = vibra.render(at=0.5, size=(400, 300), layout="fbd", out="still.png")
    assert isinstance(image, vibra.Image)
    stream = probe(image)
    assert (stream["codec_name"], stream["width"], stream["height"]) == ("png", 400, 300)
    bundle = image._repr_mimebundle_()
    assert base64.b64decode(bundle["image/png"]) == (in_tmp / "still.png").read_bytes()
    svg = vibra.render(at=0.5, out="still.svg", size="400x300")
    assert svg._repr_mimebundle_()["image/svg+xml"].lstrip().startswith("<?xml")


def test_a_scene_named_with_a_hyphen_or_an_underscore_is_one_scene(in_tmp):
    # The one spelling rule (docs/install.md): spring-dashpot is the preset spring_dashpot.
    vibra.render("spring_dashpot", at=1, size=(160, 90), out="listed.png")
    vibra.render("spring-dashpot", at=1, size=(160, 90), out="hyphen.png")
    assert (in_tmp / "listed.png").read_bytes() == (in_tmp / "hyphen.png").read_bytes()


def test_a_transparent_still_has_alpha_where_nothing_is_drawn(in_tmp):
    image = vibra.render(at=0.5, size=(320, 180), layout="fbd", out="overlay.png", transparent=True)
    assert probe(image)["pix_fmt"] == "rgba"
    rgba = subprocess.run(["ffmpeg", "-v", "error", "-i", os.fspath(image), "-f", "rawvideo", "-pix_fmt", "rgba", "-"],
                          capture_output=True, check=True).stdout
    alpha = rgba[3::4]
    assert len(alpha) == 320 * 180 and alpha[0] == 0  # the corner: no background
    assert max(alpha) == 255  # the drawing is opaque
    with pytest.raises(OSError, match="cannot be transparent"):
        vibra.render(out="overlay.mp4", transparent=True, T=0.5)


def test_default_still_name_and_scene_keys(in_tmp):
    image = vibra.render("pendulum_book", at=0, size=(200, 150))
    assert os.fspath(image) == "pendulum_book.png" and (in_tmp / "pendulum_book.png").is_file()


def test_bad_input_raises_value_error_and_leaves_nothing(in_tmp, cli):
    with pytest.raises(ValueError) as error:
        vibra.render(layot="fbd", T=1)
    assert "layot" in str(error.value) and "layout" in str(error.value)
    with pytest.raises(ValueError, match="size"):
        vibra.render(size=(320,), T=1)
    with pytest.raises(ValueError, match="one picture"):
        vibra.render(out="x.svg", T=1)
    assert list(in_tmp.iterdir()) == []


def test_ctrl_c_stops_a_render_and_keeps_no_partial_file(in_tmp):
    timer = threading.Timer(0.5, lambda: os.kill(os.getpid(), signal.SIGINT))
    timer.start()
    try:
        with pytest.raises(KeyboardInterrupt):
            vibra.render(T=2000, size=(320, 180), fps=10, quality="draft")
    finally:
        timer.cancel()
    assert not (in_tmp / "pendulum.mp4").exists()
    assert signal.getsignal(signal.SIGINT) is signal.default_int_handler  # Python's handler is back


def test_compare_draws_the_runs_together_from_a_dict_or_a_string(in_tmp):
    runs = {"scheme": ["forward-euler", "rk4"]}
    video = vibra.render("spring", compare=runs, periods=1, size=(320, 180), fps=10)
    alone = vibra.render("spring", out="alone.mp4", periods=1, size=(320, 180), fps=10)
    assert int(probe(video)["nb_read_frames"]) == int(probe(alone)["nb_read_frames"])
    still = vibra.render("undamped", out="grid.png", at=0.5, layout="grid", compare="dt=0.05,0.025", periods=2)
    assert isinstance(still, vibra.Image) and (in_tmp / "grid.png").is_file()
    with pytest.raises(ValueError, match="one key with its values"):
        vibra.render("spring", compare={"scheme": ["rk4"], "dt": [0.1]})
    with pytest.raises(ValueError, match="given twice"):
        vibra.render("spring", compare="scheme=rk4,rk4")
