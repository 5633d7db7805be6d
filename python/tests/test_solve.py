"""vibra.solve: numbers, memory views, every, keys as numbers or strings, errors."""

import math

import numpy as np
import pytest

import vibra


def test_centered_scheme_is_its_exact_discrete_solution():
    # u^n = I cos(w~ t_n), w~ = (2/dt) asin(w dt/2) (1.18), (1.20): the centered
    # scheme reproduces it to rounding.
    run = vibra.solve("undamped", I=0.7, w=2 * math.pi, dt=0.05, T=10)
    w_tilde = 2 / 0.05 * math.asin(2 * math.pi * 0.05 / 2)
    assert len(run) == 201
    np.testing.assert_allclose(run.t, 0.05 * np.arange(201), rtol=0, atol=1e-12)
    np.testing.assert_allclose(run.u, 0.7 * np.cos(w_tilde * run.t), rtol=0, atol=1e-12)


def test_matches_the_command_line_to_the_last_bit(cli):
    run = vibra.solve("pendulum", Theta=40, alpha=0.8, T=5)
    csv = cli("solve", "pendulum", "--set", "Theta=40", "--set", "alpha=0.8", "--set", "T=5").stdout.splitlines()
    assert csv[0].split(",") == list(run.columns)
    table = np.array([[float(x) for x in line.split(",")] for line in csv[1:]])
    assert np.array_equal(np.asarray(run), table)


def test_arrays_view_memory_filled_by_cpp():
    run = vibra.solve("pendulum", Theta=30)
    table = np.asarray(run)
    assert table.shape == (len(run), 5) and table.dtype == np.float64
    assert not table.flags.owndata
    assert not run.theta.flags.owndata and not run.t.flags.owndata
    assert np.shares_memory(run.theta, table) and np.shares_memory(run["theta"], table)
    assert run.theta.flags.c_contiguous  # a column is contiguous: the buffer is column-major
    assert run.columns == ("t", "theta", "omega", "S", "D")


def test_the_buffer_outlives_the_solution():
    theta = vibra.solve("pendulum", Theta=30).theta
    import gc
    gc.collect()
    assert theta[0] == pytest.approx(math.radians(30), abs=1e-15)
    assert theta.base is not None


def test_every_keeps_every_kth_step_and_the_last():
    full = vibra.solve("undamped", dt=0.1, T=1)
    sparse = vibra.solve("undamped", dt=0.1, T=1, every=4)
    expected = [0, 4, 8, 10]
    np.testing.assert_array_equal(sparse.t, full.t[expected])
    np.testing.assert_array_equal(np.asarray(sparse), np.asarray(full)[expected])


def test_keys_as_numbers_or_strings():
    in_degrees = vibra.solve("pendulum", Theta=40, T=2)
    in_radians = vibra.solve("pendulum", Theta=f"{math.radians(40)!r}rad", T=2)
    assert in_radians.theta[0] == pytest.approx(math.radians(40), rel=1e-15)
    np.testing.assert_allclose(in_radians.theta, in_degrees.theta, rtol=0, atol=1e-14)
    assert vibra.solve("pendulum", Theta="0.7rad", T=1).theta[0] == 0.7
    as_text = vibra.solve("undamped", dt="2*pi/400", T=1)
    assert as_text.info["dt"] == pytest.approx(2 * math.pi / 400, rel=1e-15)
    # A formula: s(u) = sin(u) is the undamped pendulum.
    formula = vibra.solve("vibration", s="sin(u)", I=0.5, dt=0.01, T=3, scheme="rk4")
    pendulum = vibra.solve("pendulum", Theta="0.5rad", alpha=0, dt=0.01, T=3, scheme="rk4")
    np.testing.assert_allclose(formula.u, pendulum.theta, rtol=0, atol=1e-12)


def test_a_hyphen_and_an_underscore_are_one_letter_in_names():
    # The one spelling rule (docs/install.md): model, key and scheme names alike.
    listed = vibra.solve("elastic-pendulum", steps_per_period=20, T=1, scheme="euler-cromer")
    other = vibra.solve("elastic_pendulum", **{"steps-per-period": 20}, T=1, scheme="euler_cromer")
    assert np.array_equal(np.asarray(listed), np.asarray(other))
    assert other.info["scheme"] == "euler-cromer"


def test_bad_input_raises_the_command_lines_message(cli):
    with pytest.raises(ValueError) as error:
        vibra.solve("pendulum", Thetaa=40)
    stderr = cli("solve", "pendulum", "--set", "Thetaa=40").stderr.strip()
    assert stderr == "vibra: error: " + str(error.value)
    assert "did you mean 'Theta'" in str(error.value)
    with pytest.raises(ValueError, match="unknown model 'pendulm'.*did you mean 'pendulum'"):
        vibra.solve("pendulm")
    with pytest.raises(ValueError, match="every=0 must be a whole number 1.."):
        vibra.solve("undamped", every=0)
    with pytest.raises(ValueError, match="vibra.stream"):
        vibra.solve("undamped", T="inf")
    with pytest.raises(ValueError, match="not a number or a string"):
        vibra.solve("undamped", I=[1])


def test_a_blow_up_raises_solution_error_with_step_and_time():
    with pytest.raises(vibra.SolutionError) as error:
        vibra.solve("undamped", scheme="forward-euler", dt=0.3, T=1e5, every=1000)
    assert "non-finite at step" in str(error.value)
    assert error.value.step > 0
    assert error.value.t == pytest.approx(error.value.step * 0.3, rel=1e-12)
    assert f"step {error.value.step} " in str(error.value)
    assert isinstance(error.value, RuntimeError)


def test_models_lists_keys_with_defaults():
    names = {m["name"]: m for m in vibra.models()}
    assert "pendulum" in names and names["undamped"]["columns"] == ["t", "u", "v"]
    assert {"name": "I", "default": "1", "unit": "length", "meaning": "initial displacement u(0)"} in names["undamped"]["keys"]
