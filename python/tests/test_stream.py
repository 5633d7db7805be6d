"""vibra.stream: chunks of a run of any length, in constant memory, and
interruption by Ctrl-C (SIGINT) in the middle of C++ work."""

import os
import signal
import threading

import numpy as np
import pytest

import vibra


def test_chunks_join_into_the_whole_run():
    whole = vibra.solve("pendulum", Theta=60, T=30, every=3)
    chunks = list(vibra.stream("pendulum", Theta=60, T=30, every=3, chunk=100))
    assert [len(c) for c in chunks[:-1]] == [100] * (len(chunks) - 1)
    assert 0 < len(chunks[-1]) <= 100
    assert np.array_equal(np.concatenate([np.asarray(c) for c in chunks]), np.asarray(whole))
    assert all(not np.asarray(c).flags.owndata for c in chunks)
    assert chunks[0].columns == whole.columns


def test_an_endless_run_streams_until_the_consumer_stops():
    seen = 0
    last_t = -1.0
    for n, chunk in enumerate(vibra.stream("undamped", T="inf", chunk=1000)):
        assert len(chunk) == 1000 and chunk.t[0] > last_t
        last_t = chunk.t[-1]
        seen += 1
        if n == 49:
            break
    assert seen == 50
    assert last_t == pytest.approx(50 * 1000 / 40 - 1 / 40)  # 40 steps per period of 1


def sigint_after(seconds):
    timer = threading.Timer(seconds, lambda: os.kill(os.getpid(), signal.SIGINT))
    timer.start()
    return timer


def test_ctrl_c_interrupts_an_endless_stream_inside_a_chunk():
    # One chunk of 1e4 rows keeping every 1e6-th step is 1e10 steps: far longer
    # than the test, so only the signal can end it.
    timer = sigint_after(0.3)
    try:
        with pytest.raises(KeyboardInterrupt):
            for _ in vibra.stream("undamped", T="inf", every=1_000_000, chunk=10_000):
                pass
    finally:
        timer.cancel()


def test_ctrl_c_interrupts_solve():
    timer = sigint_after(0.3)
    try:
        with pytest.raises(KeyboardInterrupt):
            vibra.solve("undamped", T=1e9, every=1_000_000)
    finally:
        timer.cancel()


def test_a_blow_up_in_a_later_chunk_raises_solution_error():
    chunks = vibra.stream("undamped", scheme="forward-euler", dt=0.3, T=1e5, chunk=100)
    first = next(chunks)
    assert len(first) == 100
    with pytest.raises(vibra.SolutionError) as error:
        for _ in chunks:
            pass
    assert error.value.step > 100 and error.value.t == pytest.approx(0.3 * error.value.step)


def test_bad_chunk_size():
    with pytest.raises(ValueError, match="chunk=0 must be a whole number 1..16777216"):
        next(vibra.stream("undamped", chunk=0))
    # Once a segfault: rows * columns * 8 bytes overflowed to a small buffer.
    with pytest.raises(ValueError, match="chunk=4611686018427387904 must be a whole number"):
        next(vibra.stream("undamped", T="inf", chunk=2**62))
    with pytest.raises(ValueError, match="chunk=-5 must be"):
        next(vibra.stream("undamped", chunk=-5))
