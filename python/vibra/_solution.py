"""vibra.solve and vibra.stream: a model's trajectory as numpy arrays that
view the memory the C++ solver filled (no copy)."""

import numpy as np

from . import _vibra
from ._native import native
from ._keys import assignments


class Solution:
    """A run's table of samples: `.t` and every column as an attribute or by
    name (`run["theta"]`), `np.asarray(run)` the (steps, columns) table.
    The arrays view one column-major buffer owned by C++; `.info` holds the
    model, scheme, dt, T, steps and small-oscillation period."""

    def __init__(self, columns, table, info):
        self.columns = tuple(columns)
        self.info = info
        self._table = table

    def __array__(self, dtype=None, copy=None):
        if dtype is None or np.dtype(dtype) == self._table.dtype:
            return self._table
        return self._table.astype(dtype)

    def __len__(self):
        return self._table.shape[0]

    def __getitem__(self, name):
        try:
            return self._table[:, self.columns.index(name)]
        except ValueError:
            raise KeyError(f"no column {name!r}: choose from {', '.join(self.columns)}") from None

    def __getattr__(self, name):
        columns = self.__dict__.get("columns", ())
        if name in columns:
            return self._table[:, columns.index(name)]
        raise AttributeError(f"{type(self).__name__} has no attribute or column {name!r} "
                             f"(columns: {', '.join(columns)})")

    def __dir__(self):
        return sorted(set(super().__dir__()) | set(self.columns))

    def __repr__(self):
        return (f"<vibra.Solution {self.info['model']} ({self.info['scheme']}, dt={self.info['dt']:.6g}): "
                f"{len(self)} rows of {', '.join(self.columns)}>")


def solve(model, *, every=1, **keys):
    """Solves `model` ("undamped", "vibration", "pendulum", ...) with its keys
    as keywords, as `vibra solve MODEL --set KEY=VALUE` does: numbers or
    strings (Theta=40, Theta="0.7rad", s="sin(u)", scheme="rk4", T=20).
    Keeps every `every`-th step and the last. Returns a Solution."""
    columns, table, info = native("solve")(model, assignments(keys), every)
    return Solution(columns, table, info)


def stream(model, *, chunk=65536, every=1, **keys):
    """Like solve, for runs of any length (T=inf too): yields Solutions of up
    to `chunk` rows in turn, in constant memory. Ctrl-C (a notebook's stop
    button) interrupts it between two looks at the signal, 65536 steps apart."""
    run = native("Stream", shown="stream")(model, assignments(keys), every)
    columns, info = run.columns, run.info
    next_chunk = native("next_chunk", run, "stream", rows="chunk")
    while (table := next_chunk(chunk)) is not None:
        yield Solution(columns, table, info)


def models():
    """The models: name, summary, columns and keys (name, default, unit, meaning)."""
    return _vibra.models()
