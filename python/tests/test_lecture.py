"""vibra.lecture: a storyboard's shots in one Video with chapters and
subtitles; vibra.render's slow= and pause= pace a render as the flags do."""

import json
import os
import subprocess

import pytest

import vibra

STORY = """title = "Springs"
size = "320x180"
fps = 10
[[shot]]
card = "Springs"
seconds = 1
[[shot]]
scene = "spring"
set = { T = 2, dt = 0.05 }
seconds = 3.1
pause = [{ at = 1, seconds = 1 }]
notes = ["0.5-1.5: held here", "1.02-1.08: between frames"]
"""


def probe(path, entries):
    out = subprocess.run(["ffprobe", "-v", "error", "-count_frames", "-show_entries", entries, "-of", "json",
                          os.fspath(path)], capture_output=True, text=True, check=True).stdout
    return json.loads(out)


def test_a_lecture_is_a_video_with_chapters_and_subtitles(in_tmp):
    (in_tmp / "story.toml").write_text(STORY)
    video = vibra.lecture("story.toml", output="talk.mp4")
    assert isinstance(video, vibra.Video) and os.fspath(video) == "talk.mp4"
    info = probe(video, "chapter=start_time,end_time:chapter_tags=title:stream=codec_name,nb_read_frames")
    assert [c["tags"]["title"] for c in info["chapters"]] == ["Springs", "spring"]
    # A shot of S seconds is round(10 S) frames: 10 and 31.
    assert [float(c["end_time"]) for c in info["chapters"]] == [1.0, 4.1]
    assert [s["codec_name"] for s in info["streams"]][:2] == ["h264", "mov_text"]
    assert int(info["streams"][0]["nb_read_frames"]) == 41
    # A note a frame shows is drawn, not a subtitle; one between frames is a subtitle.
    subtitles = (in_tmp / "talk.vtt").read_text()
    assert "held here" not in subtitles
    assert "00:00:03.020 --> 00:00:04.100\nbetween frames" in subtitles
    one = vibra.lecture("story.toml", output="two.webm", shot=2)
    assert int(probe(one, "stream=nb_read_frames")["streams"][0]["nb_read_frames"]) == 31


def test_a_presentation_and_a_folder_of_shots(in_tmp):
    (in_tmp / "story.toml").write_text(STORY)
    page = vibra.lecture("story.toml", output="talk.html", present=True, shots_dir="shots")
    assert os.fspath(page) == "talk.html" and "present" in (in_tmp / "talk.html").read_text().lower()
    shots = sorted(p.name for p in (in_tmp / "shots").iterdir())
    assert [n for n in shots if n.endswith(".mp4")] == ["01-springs.mp4", "02-spring.mp4"]
    assert "index.md" in shots and "beamer.tex" in shots
    # Each shot's own video holds its own frames: 10 and 31.
    frames = [int(probe(in_tmp / "shots" / n, "stream=nb_read_frames")["streams"][0]["nb_read_frames"])
              for n in ("01-springs.mp4", "02-spring.mp4")]
    assert frames == [10, 31]
    with pytest.raises(ValueError, match="--present makes a page of slides"):
        vibra.lecture("story.toml", output="talk.mp4", present=True)
    with pytest.raises(TypeError):
        vibra.lecture("story.toml", output="talk.html", shots_dir=3)


def test_a_bad_storyboard_raises_with_the_shot_and_key(in_tmp):
    (in_tmp / "story.toml").write_text(STORY.replace("seconds = 3.1", "secnds = 3.1"))
    with pytest.raises(ValueError, match=r"shot 2, secnds: unknown key 'secnds'"):
        vibra.lecture("story.toml", output="talk.mp4")
    assert not (in_tmp / "talk.mp4").exists() and not (in_tmp / "talk.vtt").exists()


def test_slow_and_pause_pace_a_render(in_tmp):
    # T = 4 at speed 1 and 10 fps: 41 frames; 1-2 four times slower adds 30, the pause 10.
    video = vibra.render("spring", out="paced.mp4", T=4, dt=0.05, speed=1, fps=10, size=(320, 180),
                         slow=(1, 2, 4), pause=["3:1"])
    assert int(probe(video, "stream=nb_read_frames")["streams"][0]["nb_read_frames"]) == 81
    with pytest.raises(ValueError, match="overlaps"):
        vibra.render("spring", out="bad.mp4", slow=["2-4:4", "3-5:2"])
    with pytest.raises(ValueError, match="is not"):
        vibra.render("spring", out="bad.mp4", pause=(1, 2, 3))


SPOKEN = """size = "320x180"
fps = 10
[[shot]]
card = "Springs"
say = "A spring swings."
"""


def test_a_narrated_lecture_speaks_unless_muted(in_tmp):
    (in_tmp / "story.toml").write_text(SPOKEN)
    spoken = probe(vibra.lecture("story.toml", output="spoken.mp4"), "stream=codec_type,codec_name:chapter=end_time")
    muted = probe(vibra.lecture("story.toml", output="muted.mp4", mute=True), "stream=codec_type,codec_name:chapter=end_time")
    assert [s["codec_name"] for s in spoken["streams"] if s["codec_type"] == "audio"] == ["aac"]
    assert [s for s in muted["streams"] if s["codec_type"] == "audio"] == []
    assert spoken["chapters"] == muted["chapters"]  # the card lasts its speech either way
    assert float(spoken["chapters"][0]["end_time"]) > 1  # 0.25 s, the words, a 0.75 s tail
