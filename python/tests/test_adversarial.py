"""The Python API under hostile arguments (issues 27 and 30): wrong types,
None, negative and huge sizes, NaN and infinities. Each must raise a Python
exception (ValueError for a bad value, TypeError for a wrong type, OSError
for an unusable path) with a
one-line message, never crash the interpreter, and leave no file behind."""

import _thread
import math
import os
import signal
import subprocess
import sys
import threading
import time

import pytest

import vibra

BAD_VALUES = [
    # (call, exception, part of the message)
    (lambda: vibra.solve("undamped", dt=float("nan")), ValueError, "dt"),
    (lambda: vibra.solve("undamped", dt=float("inf")), ValueError, "dt"),
    (lambda: vibra.solve("undamped", dt=-0.1), ValueError, "dt"),
    (lambda: vibra.solve("undamped", dt=1e308), ValueError, "dt"),
    (lambda: vibra.solve("undamped", T=1e308), ValueError, "T"),
    (lambda: vibra.solve("undamped", I=1e308), ValueError, "I=1e+308 must be a number"),
    (lambda: vibra.solve("undamped", I=None), ValueError, "I=None is not a number"),
    (lambda: vibra.solve("undamped", I=[1, 2]), ValueError, "is not a number or a string"),
    (lambda: vibra.solve("undamped", I="30abc"), ValueError, "write a decimal number"),
    (lambda: vibra.solve("undamped", I="0x10"), ValueError, "write a decimal number"),
    (lambda: vibra.solve("undamped", every=0), ValueError, "every=0"),
    (lambda: vibra.solve("undamped", every=-3), ValueError, "every=-3"),
    (lambda: vibra.solve("undamped", every=None), TypeError, ""),
    (lambda: vibra.solve(None), TypeError, ""),
    (lambda: vibra.solve(42), TypeError, ""),
    (lambda: vibra.solve("undamped", T="inf"), ValueError, "vibra.stream"),
    (lambda: next(vibra.stream("undamped", chunk=0)), ValueError, "chunk=0"),
    (lambda: next(vibra.stream("undamped", chunk=-1)), ValueError, "chunk=-1"),
    (lambda: next(vibra.stream("undamped", T="inf", chunk=2**62)), ValueError, "chunk=4611686018427387904"),
    (lambda: next(vibra.stream("undamped", T="inf", chunk=2**100)), TypeError, ""),
    (lambda: next(vibra.stream("undamped", chunk="many")), TypeError, ""),
    (lambda: next(vibra.stream("undamped", chunk=None)), TypeError, ""),
    (lambda: vibra.render(size=(-64, 36), out="x.mp4"), ValueError, "size"),
    (lambda: vibra.render(size=(0, 0), out="x.mp4"), ValueError, "size"),
    (lambda: vibra.render(size=(10**12, 36), out="x.mp4"), ValueError, "size"),
    (lambda: vibra.render(size="huge", out="x.mp4"), ValueError, "size"),
    (lambda: vibra.render(size=None, fps=-1, out="x.mp4"), ValueError, "fps"),
    (lambda: vibra.render(fps=math.nan, out="x.mp4"), ValueError, "fps"),
    (lambda: vibra.render(at=math.inf, out="x.png"), ValueError, "--at"),
    (lambda: vibra.render(at=-1e300, out="x.png"), ValueError, "--at"),
    (lambda: vibra.render(at="soon", out="x.png"), ValueError, ""),
    (lambda: vibra.render(threads=-5, size=(64, 36), out="x.mp4"), ValueError, "--threads"),
    (lambda: vibra.render(crf=1000, size=(64, 36), out="x.mp4"), ValueError, "--crf"),
    (lambda: vibra.render(window="1e-300x", out="x.mp4"), ValueError, "window"),
    (lambda: vibra.render(scene=None), TypeError, ""),
    (lambda: vibra.render(out=""), OSError, "the output path is empty"),  # paths: OSError, as open() raises
    # Adaptive runs doubles cannot advance (docs/schemes.md): refused, not a hang.
    (lambda: vibra.solve("undamped", scheme="dopri5", rtol=1e-15), ValueError, "rtol=1e-15 is out of range"),
    (lambda: vibra.solve("vibration", scheme="dopri5", s="-u^3", dt=0.01, T=3), ValueError,
     "dopri5: the step size fell below what doubles resolve at t = 1.85"),
    (lambda: next(vibra.stream("vibration", scheme="rkf45", s="-u^3", dt=0.01, T=3)), ValueError,
     "rkf45: the step size fell below what doubles resolve"),
    (lambda: vibra.solve("vibration", scheme="rkf45", F="sqrt(0.5-t)", T=1), ValueError,
     "the error estimate is not finite for any step size at t = 0.5"),
]


@pytest.mark.parametrize("call, exception, message", BAD_VALUES, ids=range(len(BAD_VALUES)))
def test_bad_argument_raises(call, exception, message, tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)
    with pytest.raises(exception) as error:
        call()
    assert message in str(error.value)
    assert "\n" not in str(error.value)  # TypeErrors too: never pybind11's list of signatures
    assert list(tmp_path.iterdir()) == []  # nothing written


@pytest.mark.parametrize("scheme", ["dopri5", "rkf45"])
@pytest.mark.parametrize("keys, T", [(dict(model="undamped", atol=1e-300, dt=0.001, T=0.01), 0.01),
                                     (dict(model="vibration", F="1e200*t", dt=0.5, T=10), 10),
                                     (dict(model="undamped", dt=0.1), 10)])
def test_adaptive_run_reaches_its_end(scheme, keys, T):
    """Once every step had h = 0 (41 rows at t = 0), and a run was cut at the
    mesh's row count: an adaptive run's rows advance and end at T."""
    keys = dict(keys)
    run = vibra.solve(keys.pop("model"), scheme=scheme, **keys)
    assert all(b > a for a, b in zip(run.t, run.t[1:]))
    assert run.t[-1] == pytest.approx(T, rel=1e-12)
    assert len(run) < 5000


# Wrong argument types (issue 42): one line naming the argument, never
# pybind11's list of C++ signatures.
WRONG_TYPES = [
    # (call, the argument as the message names it)
    (lambda: vibra.render(scene=None), "scene=None must be a path"),
    (lambda: vibra.render(out=5), "out=5 must be a path"),
    (lambda: vibra.render(crf="high", out="x.mp4"), "crf='high' must be a whole number, not str"),
    (lambda: vibra.render(threads=1.5, out="x.mp4"), "threads=1.5 must be a whole number, not float"),
    (lambda: vibra.render(quiet="yes", out="x.mp4"), "quiet='yes' must be True or False"),
    (lambda: vibra.render(codec=None, out="x.mp4"), "codec=None must be a string"),
    (lambda: vibra.lecture(None), "storyboard=None must be a path"),
    (lambda: vibra.lecture("talk.toml", shot="2"), "shot='2' must be a whole number or None"),
    (lambda: vibra.lecture("talk.toml", force="yes"), "force='yes' must be True or False"),
    (lambda: vibra.solve(None), "vibra.solve: model=None must be a string"),
    (lambda: vibra.solve("undamped", every=None), "every=None must be a whole number"),
    (lambda: next(vibra.stream("undamped", chunk="many")), "vibra.stream: chunk='many' must be a whole number"),
    (lambda: next(vibra.stream("undamped", T="inf", chunk=2**100)), "is out of range for a whole number"),
    (lambda: vibra.ascii_lines("undamped", width="wide"), "vibra.ascii_lines: width='wide' must be a whole number"),
    (lambda: vibra.convergence("undamped", levels="3"), "levels='3' must be a whole number or None"),
]


@pytest.mark.parametrize("call, message", WRONG_TYPES, ids=range(len(WRONG_TYPES)))
def test_wrong_type_is_one_line_naming_the_argument(call, message, in_tmp):
    with pytest.raises(TypeError) as error:
        call()
    assert message in str(error.value)
    assert "\n" not in str(error.value) and "incompatible" not in str(error.value)
    assert list(in_tmp.iterdir()) == []


LONG_WORK = [
    # (what, the call, its final paths)
    ("video", lambda: vibra.render(T=2000, size=(320, 180), fps=10, quality="draft", out="r.mp4"), ["r.mp4"]),
    ("page", lambda: vibra.render(T=3000, size=(320, 180), fps=10, out="r.html"), ["r.html", "r_files"]),
    ("lecture", lambda: vibra.lecture("talk.toml", "talk.mp4"), ["talk.mp4", "talk.vtt"]),
]
STOPS = {
    # A signal Python alone sees (a notebook's stop button, IDLE): once
    # noticed only when the whole output was written, and left on disk.
    "interrupt_main": _thread.interrupt_main,
    "SIGINT": lambda: os.kill(os.getpid(), signal.SIGINT),
}


@pytest.mark.parametrize("stop", STOPS, ids=list(STOPS))
@pytest.mark.parametrize("what, call, outputs", LONG_WORK, ids=[w[0] for w in LONG_WORK])
def test_ctrl_c_stops_within_a_second_and_leaves_nothing(what, call, outputs, stop, in_tmp):
    (in_tmp / "talk.toml").write_text('size = "320x180"\nfps = 10\n[[shot]]\ncard = "A"\nseconds = 200\n'
                                      '[[shot]]\nscene = "pendulum"\nseconds = 200\n')
    sent = []
    timer = threading.Timer(1.0, lambda: (sent.append(time.monotonic()), STOPS[stop]()))
    timer.start()
    try:
        with pytest.raises(KeyboardInterrupt):
            call()
        stopped = time.monotonic()
    finally:
        timer.cancel()
    assert sent and stopped - sent[0] < 3.0  # a bound for a hang, on a loaded machine: the promise is under a second
    assert sorted(p.name for p in in_tmp.iterdir()) == ["talk.toml"]  # nothing at the final paths, no temporary
    assert not any((in_tmp / name).exists() for name in outputs)
    assert signal.getsignal(signal.SIGINT) is signal.default_int_handler


def test_out_of_memory_is_one_line_memory_error(tmp_path):
    """std::bad_alloc once reached Python as its bare name."""
    program = ("import resource, vibra\n"
               "resource.setrlimit(resource.RLIMIT_AS, (1 << 30, 1 << 30))\n"
               "try:\n"
               "    vibra.solve('undamped', T=1e7, dt=1e-3)\n"
               "except MemoryError as error:\n"
               "    print(error)\n")
    run = subprocess.run([sys.executable, "-c", program], capture_output=True, text=True, cwd=tmp_path, timeout=60)
    assert run.returncode == 0, run.stderr
    assert run.stdout.startswith("out of memory: this call needs more memory than this machine gives it")
    assert run.stdout.count("\n") == 1 and "bad_alloc" not in run.stdout
