"""vibra.plot: the same plot job as `vibra plot`, so the same bytes, the same refusals."""

import os
import struct

import pytest

import vibra


def png_size(path):
    with open(path, "rb") as f:
        header = f.read(24)
    assert header[:8] == b"\x89PNG\r\n\x1a\n"
    return struct.unpack(">II", header[16:24])


def test_a_figure_is_the_command_lines_byte_for_byte(in_tmp, cli):
    image = vibra.plot("undamped", "py.png", panels=["u", "exact"], periods=3, steps_per_period=12)
    assert isinstance(image, vibra.Image) and os.fspath(image) == "py.png"
    done = cli("plot", "undamped", "--panels", "u,exact", "--set", "periods=3", "--set", "steps_per_period=12",
               "-o", "cli.png", "-q")
    assert done.returncode == 0, done.stderr
    assert (in_tmp / "py.png").read_bytes() == (in_tmp / "cli.png").read_bytes()
    assert png_size("py.png") == (1280, 720)
    assert "image/png" in image._repr_mimebundle_()


def test_compare_size_and_mesh_marks_reach_the_job(in_tmp, cli):
    vibra.plot("undamped", "schemes.png", compare={"scheme": ["forward-euler", "rk4"]}, size=(640, 360), periods=2)
    done = cli("plot", "undamped", "--compare", "scheme=forward-euler,rk4", "--size", "640x360", "--set", "periods=2",
               "-o", "schemes_cli.png", "-q")
    assert done.returncode == 0, done.stderr
    assert png_size("schemes.png") == (640, 360)  # first: a size lost on the way is named as such
    assert (in_tmp / "schemes.png").read_bytes() == (in_tmp / "schemes_cli.png").read_bytes()
    marked = vibra.plot("undamped", "mesh.png", annotate="mesh", periods=1, steps_per_period=8)
    plain = vibra.plot("undamped", "plain.png", periods=1, steps_per_period=8)
    assert marked.data != plain.data


def test_a_page_is_returned_as_its_path(in_tmp):
    page = vibra.plot("pendulum", "swing.html", periods=2)
    assert not isinstance(page, vibra.Image) and os.fspath(page) == "swing.html"
    assert "<html" in (in_tmp / "swing.html").read_text().lower()


def test_bad_input_is_one_line_and_leaves_nothing(in_tmp):
    with pytest.raises(ValueError) as error:
        vibra.plot("undamped", "x.png", panels="u,speed")
    assert "speed" in str(error.value) and "\n" not in str(error.value)
    with pytest.raises(ValueError, match="--annotate"):
        vibra.plot("undamped", "x.html", annotate="mesh")
    with pytest.raises(ValueError, match="one key at a time|compare"):
        vibra.plot("undamped", "x.png", compare="bogus")
    with pytest.raises(TypeError, match="plot"):
        vibra.plot("undamped", "x.png", transparent="yes")
    assert list(in_tmp.iterdir()) == []
