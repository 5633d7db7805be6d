"""The chapter's experiments, as `vibra analyze` runs them: each returns a
Table of named numpy columns (a tuple of Tables for orbit(long=True)) and,
with out="figure.png" (.svg, .pdf), also draws the command's figure."""

import html

import numpy as np

from ._native import native
from ._keys import assignments, comma_list, size_text, value_text


class Table:
    """An experiment's table: `heading` says what it holds; each column is a
    numpy array, as an attribute or by name (`table["dt"]`); `conclusion` is
    the sentence the command prints under it ("" for none), e.g. whether
    convergence rates have settled. Shows itself as an HTML table in a
    notebook."""

    def __init__(self, heading, columns, conclusion=""):
        self.heading = heading
        self.conclusion = conclusion
        self._columns = dict(columns)

    @property
    def columns(self):
        return tuple(self._columns)

    def __len__(self):
        return len(next(iter(self._columns.values()), ()))

    def __getitem__(self, name):
        try:
            return self._columns[name]
        except KeyError:
            raise KeyError(f"no column {name!r}: choose from {', '.join(self._columns)}") from None

    def __getattr__(self, name):
        columns = self.__dict__.get("_columns", {})
        if name in columns:
            return columns[name]
        raise AttributeError(f"Table has no attribute or column {name!r} (columns: {', '.join(columns)})")

    def __dir__(self):
        return sorted(set(super().__dir__()) | set(self._columns))

    @staticmethod
    def _cell(value):
        if isinstance(value, (float, np.floating)):
            return "" if np.isnan(value) else f"{value:.4g}"
        return str(value)

    def _rows(self):
        return [[self._cell(column[i]) for column in self._columns.values()] for i in range(len(self))]

    def __repr__(self):
        rows = [list(self._columns)] + self._rows()
        widths = [max(len(row[c]) for row in rows) for c in range(len(rows[0]))]
        lines = ["  ".join(cell.rjust(width) for cell, width in zip(row, widths)).rstrip() for row in rows]
        return "\n".join([self.heading] + lines + ([self.conclusion] if self.conclusion else []))

    def _repr_html_(self):
        head = "".join(f"<th>{html.escape(name)}</th>" for name in self._columns)
        # Numbers align right, words left, as the command line prints them.
        align = ["left" if column.dtype.kind == "U" else "right" for column in self._columns.values()]
        body = "".join("<tr>" + "".join(f'<td style="text-align: {a}">{html.escape(cell)}</td>'
                                        for a, cell in zip(align, row)) + "</tr>"
                       for row in self._rows())
        return (f"<table><caption style=\"caption-side: top\">{html.escape(self.heading)}</caption>"
                f"<thead><tr>{head}</tr></thead><tbody>{body}</tbody></table>"
                + (f"<p>{html.escape(self.conclusion)}</p>" if self.conclusion else ""))


def _tables(result):
    tables = tuple(Table(heading, columns, conclusion) for heading, columns, conclusion in result)
    return tables[0] if len(tables) == 1 else tables


def _figure(out):
    return "" if out is None else str(out)


def convergence(model="undamped", *, levels=None, out=None, size="1280x720", **keys):
    """Errors E and rates r for dt halved `levels - 1` times (default: until
    the last two rates agree, which `conclusion` says), against the exact
    solution (undamped, or two-body's circular orbit). Model keys as keywords;
    dt (or steps_per_period) is the first level's."""
    return _tables(native("convergence")(model, assignments(keys), levels, _figure(out), size_text(size)))


def energy(*, schemes=None, T=None, dt=None, out=None, size="1280x720"):
    """The chapter's energy-error table: max |e_E|/E(0) per scheme, T and dt
    for u'' + (2 pi)^2 u = 0. Lists as Python lists or "a,b" strings."""
    return _tables(native("energy")(comma_list("schemes", schemes), comma_list("T", T), comma_list("dt", dt),
                                 _figure(out), size_text(size)))


def empirical(model="undamped", *, dt=None, mesh_extrema=False, out=None, size="1280x720", **keys):
    """Local periods, angular frequencies and amplitudes from the extrema of
    the main quantity, one run per dt (default: the model's dt)."""
    return _tables(native("empirical")(model, assignments(keys), comma_list("dt", dt), mesh_extrema,
                                    _figure(out), size_text(size)))


def frequency(*, w=None, steps_per_period=None, out=None, size="1280x720"):
    """The centered scheme's numerical frequency (1.18) and its series (1.19)."""
    return _tables(native("frequency")(None if w is None else value_text("w", w),
                                    comma_list("steps_per_period", steps_per_period), _figure(out), size_text(size)))


def amplitude(*, schemes=None, dt=None, periods=None, out=None, size="1280x720"):
    """Amplitude errors of first-order-system solvers on the undamped
    oscillator (Exercise 1.13)."""
    return _tables(native("amplitude")(comma_list("schemes", schemes), None if dt is None else value_text("dt", dt),
                                    None if periods is None else value_text("periods", periods),
                                    _figure(out), size_text(size)))


def orbit(*, scheme=None, steps_per_orbit=None, orbits=None, long=False, out=None, size="1280x720"):
    """Position error and CPU time of two-body's circular orbit (Exercise 1.28).
    long=True adds PEFRL over 100000 orbits with the fitted error growth: a
    second Table (then a tuple of two is returned)."""
    return _tables(native("orbit")(scheme, comma_list("steps_per_orbit", steps_per_orbit), orbits, long,
                                _figure(out), size_text(size)))
