"""vibra.explore: the live page written as `vibra render --live` writes it, shown inline in a notebook."""

import json
import os
import re

import pytest

import vibra


def test_explore_writes_the_live_page_and_shows_it_in_a_frame(in_tmp):
    page = vibra.explore("pendulum", size=(640, 360), Theta=45, alpha=0.8)
    assert os.fspath(page) == "pendulum_live.html"
    files = in_tmp / "pendulum_live_files"
    for name in ("vibra_live.js", "replay.js", "live.js", "DejaVuSans.ttf"):
        assert (files / name).stat().st_size > 1000, name
    text = (in_tmp / "pendulum_live.html").read_text()
    config = json.loads(re.search(r'<script id="config" type="application/json">(.*?)</script>', text).group(1))
    assert config["scene"] == "pendulum" and config["model"] == "pendulum"
    assert config["base"] == ["size=640x360", "Theta=45", "alpha=0.8"]
    assert config["initial"]["Theta"] == "45"
    frame = page._repr_html_()
    assert 'src="pendulum_live.html"' in frame and 'width="680"' in frame


def test_explore_refuses_a_bad_value_with_the_cli_reason_and_writes_nothing(in_tmp):
    with pytest.raises(ValueError, match="the drag coefficient alpha must be >= 0"):
        vibra.explore(alpha=-1)
    with pytest.raises(ValueError, match="give -o PAGE.html"):
        vibra.explore(out="page.mp4")
    assert list(in_tmp.iterdir()) == []


def test_explore_takes_a_scene_file_into_the_page_and_refuses_one_that_reads_a_road_file(in_tmp):
    (in_tmp / "swing.toml").write_text('model = "pendulum"\nTheta = 70\nperiods = 4\n')
    page = vibra.explore("swing.toml", alpha=0.5)
    assert os.fspath(page) == "swing_live.html"
    text = (in_tmp / "swing_live.html").read_text()
    config = json.loads(re.search(r'<script id="config" type="application/json">(.*?)</script>', text).group(1))
    assert config["sceneText"] == 'model = "pendulum"\nTheta = 70\nperiods = 4\n'
    assert config["name"] == "swing" and config["initial"]["Theta"] == "70" and config["base"] == ["alpha=0.5"]
    (in_tmp / "road.txt").write_text("0\n0.01\n" * 100)
    (in_tmp / "road.toml").write_text('model = "bumpy-road"\nroad = "road.txt"\ndx = 0.5\nT = 2\n')
    with pytest.raises(ValueError, match=r"--live cannot take 'road.txt', the road profile \(--set road\), into the page"):
        vibra.explore("road.toml")
    assert not (in_tmp / "road_live.html").exists() and not (in_tmp / "road_live_files").exists()
