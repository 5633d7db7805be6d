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
