"""vibra.ascii_lines: the same lines as `vibra ascii`."""

import itertools

import pytest

import vibra


def test_lines_are_the_command_lines(cli):
    lines = list(vibra.ascii_lines("undamped", exact=True, width=60, symbols="+o", scheme="euler-cromer", T=3))
    printed = cli("ascii", "undamped", "--exact", "--width", "60", "--symbols", "+o",
                  "--set", "scheme=euler-cromer", "--set", "T=3").stdout.splitlines()
    assert lines == printed
    assert len(lines) == 3 * 40 + 1  # the book's plotter: no legend line
    with_legend = list(vibra.ascii_lines("undamped", exact=True, legend=True, symbols="+o", T=3))
    assert with_legend[0] == "+ u   o exact" and len(with_legend) == 1 + 3 * 40 + 1


def test_columns_and_counter(cli):
    lines = list(vibra.ascii_lines("pendulum", columns=("theta", "S"), counter="time", T=1, Theta=50))
    printed = cli("ascii", "pendulum", "--columns", "theta,S", "--counter", "time",
                  "--set", "T=1", "--set", "Theta=50").stdout.splitlines()
    assert lines == printed


def test_an_endless_run_yields_lines_on_demand():
    lines = list(itertools.islice(vibra.ascii_lines("undamped", T="inf", width=20, counter="none"), 1000))
    assert len(lines) == 1000 and all(len(line) == 21 for line in lines)


def test_bad_options_raise_value_error():
    with pytest.raises(ValueError, match="no column 'x'"):
        vibra.ascii_lines("undamped", columns="x")
    with pytest.raises(ValueError, match="give both --ymin and --ymax"):
        vibra.ascii_lines("undamped", ymin=-1)
