"""Model and scene keys given as Python keywords, turned into the KEY=VALUE
text the command line's --set takes."""

import numbers


def value_text(key, value):
    """`value` as --set would take it: numbers in full precision, strings
    (expressions, angles such as "0.7rad", formulas, choices) as they are."""
    if isinstance(value, str):
        return value
    if isinstance(value, bool) or not isinstance(value, numbers.Real):
        raise ValueError(f"{key}={value!r} is not a number or a string: "
                         f"write e.g. {key}=0.5 or {key}=\"2*pi/40\"")
    if isinstance(value, numbers.Integral):
        return str(int(value))
    return repr(float(value))


def assignments(keys):
    """["KEY=VALUE", ...] for a dict of keywords."""
    return [f"{key}={value_text(key, value)}" for key, value in keys.items()]


def comma_list(name, value):
    """A comma-separated option from a list/tuple of numbers or words, a single
    one, or a string as the command line takes it; None stays None."""
    if value is None or isinstance(value, str):
        return value
    if isinstance(value, (list, tuple)):
        return ",".join(value_text(name, item) for item in value)
    return value_text(name, value)


def comparison_text(compare):
    """--compare's KEY=V1,V2,... from "KEY=V1,V2", or a one-key dict such as
    {"scheme": ["forward-euler", "rk4"]} or {"dt": [0.1, 0.05]}."""
    if compare is None or isinstance(compare, str):
        return compare
    if isinstance(compare, dict) and len(compare) == 1:
        (key, values), = compare.items()
        return f"{key}={comma_list(key, values)}"
    raise ValueError(f"compare={compare!r} is not \"KEY=V1,V2\" or one key with its values: "
                     "write e.g. compare={\"scheme\": [\"forward-euler\", \"rk4\"]}")


def size_text(size):
    """(1280, 720) or "1280x720" as "1280x720"."""
    if isinstance(size, str):
        return size
    try:
        width, height = size
    except (TypeError, ValueError):
        raise ValueError(f"size={size!r} is not (width, height) or \"WxH\": write e.g. size=(1280, 720)") from None
    return f"{value_text('size', width)}x{value_text('size', height)}"


def pacing_texts(name, value):
    """slow= or pause= as the texts --slow and --pause take: "2-4:4" / "3:1",
    a tuple (2, 4, 4) / (3, 1), or a list of either; None gives none."""
    if value is None:
        return []
    items = value if isinstance(value, list) else [value]
    texts = []
    for item in items:
        if isinstance(item, str):
            texts.append(item)
        elif isinstance(item, tuple) and len(item) == (3 if name == "slow" else 2):
            numbers_ = [value_text(name, x) for x in item]
            texts.append(f"{numbers_[0]}-{numbers_[1]}:{numbers_[2]}" if name == "slow" else f"{numbers_[0]}:{numbers_[1]}")
        else:
            form = '"2-4:4" or (2, 4, 4)' if name == "slow" else '"3:1" or (3, 1)'
            raise ValueError(f"{name}={item!r} is not {form}: write e.g. {name}={form.split(' or ')[0]}")
    return texts
