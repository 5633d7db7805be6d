"""The compiled module vibra._vibra, each function wrapped so that a wrong
argument type is one line naming the argument, never pybind11's list of
C++ signatures."""

import numbers
import os

from . import _vibra

# What each kind pybind11 names takes, as a message says it.
_KIND_WORDS = {"str": "a string", "int": "a whole number", "float": "a number", "bool": "True or False"}


def _fits(value, kind):
    """Whether pybind11 takes `value` for a parameter it describes as `kind`."""
    if kind.startswith("Optional["):
        return value is None or _fits(value, kind[len("Optional["):-1])
    if kind == "str":
        return isinstance(value, str)
    if kind == "bool":
        return isinstance(value, bool)
    if kind == "int":
        return isinstance(value, numbers.Integral) and -2**63 <= value < 2**63
    if kind == "float":
        return isinstance(value, numbers.Real)
    if kind.startswith(("List[", "Tuple[")):
        return isinstance(value, (list, tuple))
    return True  # a kind not judged here


def _parameters(message):
    """[(name, kind), ...] from the first signature pybind11's message lists."""
    start = message.find("(", message.find("1. "))
    end = message.find(")\n", start)
    end = message.find(") ->", start) if message.find(") ->", start) >= 0 else end
    if start < 0 or end < 0:
        return []
    parameters, depth, piece = [], 0, ""
    for c in message[start + 1:end] + ",":
        depth += (c == "[") - (c == "]")
        if c == "," and depth == 0:
            name, _, kind = piece.strip().partition(": ")
            parameters.append((name, kind.partition(" = ")[0]))
            piece = ""
        else:
            piece += c
    return parameters


def _wanted(kind):
    """What a parameter of `kind` takes, in words."""
    if kind.startswith("Optional["):
        return _wanted(kind[len("Optional["):-1]) + " or None"
    return _KIND_WORDS.get(kind, "a list" if kind.startswith(("List[", "Tuple[")) else kind)


def _shown(value):
    text = repr(value)
    return text if len(text) <= 40 else text[:37] + "..."


def _one_line(function, args, aliases, message):
    parameters = [p for p in _parameters(message) if p[0] != "self"]
    for (name, kind), value in zip(parameters, args):
        if _fits(value, kind):
            continue
        name = aliases.get(name, name)
        if isinstance(value, numbers.Integral) and "int" in kind:
            return f"vibra.{function}: {name}={_shown(value)} is out of range for a whole number"
        return f"vibra.{function}: {name}={_shown(value)} must be {_wanted(kind)}, not {type(value).__name__}"
    return f"vibra.{function}: an argument has a type it does not take (see help(vibra.{function}))"


def path_text(function, name, value):
    """A path argument as text, or a one-line TypeError naming it."""
    if isinstance(value, (str, os.PathLike)):
        return os.fspath(value)
    raise TypeError(f"vibra.{function}: {name}={_shown(value)} must be a path (a string), not {type(value).__name__}")


def native(function, owner=_vibra, shown=None, **aliases):
    """_vibra.FUNCTION (or a method of `owner`), its TypeErrors one line,
    said of vibra.SHOWN; `aliases` maps the module's parameter names to the
    names the caller knows (output="out")."""
    compiled = getattr(owner, function)
    shown = shown or function

    def call(*args):
        try:
            return compiled(*args)
        except TypeError as error:
            if "incompatible" not in str(error) or "arguments" not in str(error):
                raise
            raise TypeError(_one_line(shown, args, aliases, str(error))) from None
    return call
