# scripts/coverage's report: lines and branches per source folder from an lcov tracefile, and the files below the bar.
"""Reads an lcov tracefile (lcov --capture --rc branch_coverage=1) and prints,
per source folder, the lines and branches the suite ran, then every
production file under the line bar (85%).

    coverage_summary.py TRACEFILE ROOT [--bar 85]
"""
import argparse
import sys
from collections import defaultdict
from pathlib import Path

# Folders scored separately, most specific first (a file counts in the first that holds it).
FOLDERS = ["src/core/schemes", "src/core/models", "src/core/analysis", "src/core", "src/cli", "src/jobs",
           "render/draw", "render/encode", "render/labels", "render/output", "render/plot", "render/typeset",
           "render", "scenes/diagrams", "scenes/panels", "scenes/figures", "scenes/lecture", "scenes"]
COUNTERS = {"LF": "lines", "LH": "lines_hit", "BRF": "branches", "BRH": "branches_hit"}


def read_tracefile(text, root):
    """{relative path: {lines, lines_hit, branches, branches_hit}} for files under root's source folders.

    lcov 1.16's capture may write a file once per object that compiled it,
    with its DA and BRDA records but no LF/LH/BRF/BRH sums: the records are
    merged per file (a line is run when any object ran it); the sums are
    used only for a file that has no records."""
    sums, lines, branches, current = {}, defaultdict(dict), defaultdict(dict), None
    root = str(Path(root).resolve()) + "/"
    for line in text.splitlines():
        key, _, value = line.partition(":")
        if key == "SF":
            path = str(Path(value).resolve())
            rel = path[len(root):] if path.startswith(root) else None
            current = rel if rel and folder_of(rel) else None
            if current:
                sums.setdefault(current, defaultdict(int))
        elif current is None:
            continue
        elif key == "DA":
            number, count = value.split(",")[:2]
            lines[current][number] = lines[current].get(number, False) or int(count) > 0
        elif key == "BRDA":
            *where, taken = value.split(",")
            branches[current][tuple(where)] = branches[current].get(tuple(where), False) or taken not in ("-", "0")
        elif key in COUNTERS:
            sums[current][COUNTERS[key]] += int(value)
        elif key == "end_of_record":
            current = None
    for rel in sums:
        if lines[rel]:
            sums[rel].update(lines=len(lines[rel]), lines_hit=sum(lines[rel].values()),
                             branches=len(branches[rel]), branches_hit=sum(branches[rel].values()))
    return sums


def folder_of(rel):
    return next((f for f in FOLDERS if rel.startswith(f + "/")), None)


def percent(hit, total):
    return f"{100 * hit / total:5.1f}%" if total else "    -"


def report(files, bar):
    """The table per folder, then the files under the bar; returns the lines printed."""
    by_folder = defaultdict(lambda: defaultdict(int))
    for rel, counts in files.items():
        for key, value in counts.items():
            by_folder[folder_of(rel)][key] += value
    out = [f"{'folder':20} {'lines':>17} {'branches':>19}"]
    for folder in FOLDERS:
        c = by_folder.get(folder)
        if c:
            out.append(f"{folder + '/':20} {c['lines_hit']:6}/{c['lines']:<6} {percent(c['lines_hit'], c['lines'])}"
                       f" {c['branches_hit']:7}/{c['branches']:<7} {percent(c['branches_hit'], c['branches'])}")
    under = sorted((100 * c["lines_hit"] / c["lines"], rel) for rel, c in files.items()
                   if c["lines"] and 100 * c["lines_hit"] / c["lines"] < bar)
    out.append(f"\n{len(under)} of {len(files)} files under {bar:g}% of lines:" if under else
               f"\nevery one of {len(files)} files at {bar:g}% of lines or more")
    out += [f"  {p:5.1f}%  {rel}" for p, rel in under]
    return out


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("tracefile")
    parser.add_argument("root")
    parser.add_argument("--bar", type=float, default=85)
    args = parser.parse_args()
    try:
        text = Path(args.tracefile).read_text()
    except OSError as e:
        sys.exit(f"coverage: cannot read the tracefile {args.tracefile} ({e.strerror}): run scripts/coverage")
    files = read_tracefile(text, args.root)
    if not files:
        sys.exit(f"coverage: {args.tracefile} holds no file of {', '.join(FOLDERS[:1])}...: was the build instrumented?")
    print("\n".join(report(files, args.bar)))
    return 0


if __name__ == "__main__":
    sys.exit(main())
