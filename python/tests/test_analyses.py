"""The experiments: the command line's tables as named numpy columns, the
book's numbers, figures on request, an HTML repr."""

import csv
import io
import math
import subprocess

import numpy as np
import pytest

import vibra


def cli_table(cli, *args):
    result = cli("analyze", *args, "--csv")
    assert result.returncode == 0, result.stderr
    rows = list(csv.reader(io.StringIO(result.stdout)))
    return rows[0], rows[1:]


def same_as_cli(table, header, rows):
    assert list(table.columns) == header and len(table) == len(rows)
    for c, name in enumerate(header):
        column = table[name]
        for value, text in zip(column, (row[c] for row in rows)):
            if column.dtype.kind == "f":
                assert (math.isnan(value) and text == "") or value == float(text)
            else:
                assert str(value) == text


def test_frequency_is_formula_1_18(cli):
    table = vibra.frequency(w=2, steps_per_period=[40, 10])
    dt = 2 * math.pi / (2 * np.array([40, 10]))
    np.testing.assert_allclose(table.w_tilde[:2], 2 / dt * np.arcsin(2 * dt / 2), rtol=1e-15)
    assert table.dt[-1] == 1.0 and table.w_tilde[-1] == pytest.approx(math.pi)  # the stability limit
    same_as_cli(table, *cli_table(cli, "frequency", "--w", "2", "--steps-per-period", "40,10"))


def test_convergence_rates_are_the_schemes_orders():
    table = vibra.convergence("undamped", scheme="rk4", T=4, levels=4)
    assert table.columns == ("i", "dt", "E", "r")
    assert table.i.dtype == np.int64 and list(table.i) == [0, 1, 2, 3]
    assert math.isnan(table.r[0])
    np.testing.assert_allclose(table.r[1:], 4, atol=0.05)
    centered = vibra.convergence("undamped", levels=3)
    np.testing.assert_allclose(centered.r[1:], 2, atol=0.05)


def test_convergence_by_default_halves_dt_until_the_rates_settle(cli):
    table = vibra.convergence("undamped", scheme="forward-euler")
    assert abs(table.r[-1] - table.r[-2]) <= 0.05 and abs(table.r[-1] - 1) < 0.1
    assert table.conclusion.startswith("The rates have settled")
    assert table.conclusion in cli("analyze", "convergence", "undamped", "--set", "scheme=forward-euler").stdout
    assert "have NOT settled" in vibra.convergence("undamped", scheme="forward-euler", levels=3).conclusion


def test_energy_table_is_the_command_lines(cli):
    table = vibra.energy(schemes=["rk4", "euler-cromer"], T=10, dt=[0.05, 0.025])
    assert table.scheme.dtype.kind == "U" and list(table.scheme) == ["rk4", "rk4", "euler-cromer", "euler-cromer"]
    same_as_cli(table, *cli_table(cli, "energy", "--schemes", "rk4,euler-cromer", "--T", "10", "--dt", "0.05,0.025"))


def test_empirical_and_amplitude_match_the_command_line(cli):
    same_as_cli(vibra.empirical("undamped", dt=[0.1, 0.05], periods=4),
                *cli_table(cli, "empirical", "undamped", "--dt", "0.1,0.05", "--set", "periods=4"))
    same_as_cli(vibra.amplitude(schemes="rk2,rk4", periods=3),
                *cli_table(cli, "amplitude", "--schemes", "rk2,rk4", "--periods", "3"))


def test_empirical_period_of_the_centered_scheme_is_2pi_over_w_tilde():
    table = vibra.empirical("undamped", dt=0.05, periods=6)
    w_tilde = 2 / 0.05 * math.asin(2 * math.pi * 0.05 / 2)
    np.testing.assert_allclose(table.angular_frequency, w_tilde, rtol=1e-10)


def test_orbit_table(cli):
    table = vibra.orbit(scheme="rk4", steps_per_orbit=[100, 200], orbits=5)
    header, rows = cli_table(cli, "orbit", "--scheme", "rk4", "--steps-per-orbit", "100,200", "--orbits", "5")
    assert list(table.columns) == header
    np.testing.assert_array_equal(table.max_error, [float(r[4]) for r in rows])  # cpu_s differs run to run
    assert table.max_error[1] < table.max_error[0] / 10  # 4th order: 16 times smaller


def test_figure_html_and_errors(in_tmp):
    table = vibra.frequency(out="frequency.png", size=(640, 360))
    probe = subprocess.run(["ffprobe", "-v", "error", "-show_entries", "stream=width,height", "-of", "csv=p=0",
                            "frequency.png"], capture_output=True, text=True, check=True)
    assert probe.stdout.strip() == "640,360"
    html = table._repr_html_()
    assert html.startswith("<table>") and "<th>w_tilde</th>" in html and "(1.18)" in html
    assert "w_tilde" in repr(table)
    with pytest.raises(ValueError, match="--steps-per-period"):
        vibra.frequency(steps_per_period=[2])
    with pytest.raises(ValueError, match="not a valid scheme"):
        vibra.energy(schemes="rk5")
    with pytest.raises(OSError, match="end the file name in .png, .svg or .pdf"):
        vibra.frequency(out="figure.gif")
    assert not (in_tmp / "figure.gif").exists()
