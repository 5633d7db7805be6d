"""vibra.ascii_lines: the classic line-by-line ASCII plot of a run."""

from ._native import native
from ._keys import assignments


def ascii_lines(model, *, width=68, symbols="*o+x@", ymin=None, ymax=None, exact=False,
                counter="", columns=(), legend=False, **keys):
    """Yields the lines `vibra ascii MODEL` prints (without newlines): a legend
    with columns or legend=True, then one line per time step with its
    counter (period, time or none). Keys of the model as keywords (T="inf"
    runs until you stop iterating). columns=("theta", "S") picks the series."""
    if isinstance(columns, str):
        columns = columns.split(",")
    return native("AsciiLines", shown="ascii_lines")(model, assignments(keys), width, symbols,
                             None if ymin is None else float(ymin), None if ymax is None else float(ymax),
                             exact, counter, list(columns), legend)
