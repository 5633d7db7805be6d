"""The Python API under hostile arguments (issues 27 and 30): wrong types,
None, negative and huge sizes, NaN and infinities. Each must raise a Python
exception (ValueError for a bad value, TypeError for a wrong type, OSError
for an unusable path) with a
one-line message, never crash the interpreter, and leave no file behind."""

import math

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
    if exception is ValueError:  # vibra's own messages; pybind11's TypeErrors list the signatures
        assert "\n" not in str(error.value)
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
