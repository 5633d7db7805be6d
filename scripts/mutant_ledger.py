# The judged mutants of scripts/mutants --sample, kept between runs so that a run interrupted or spread over sessions continues.
"""A ledger of judged sampled mutants, one JSON object a line, keyed by
seed and site id (scripts/mutant_sites.py), in the mutants' work folder.

A line is appended and flushed to disk as soon as a mutant is judged, so a
run stopped at any moment keeps every verdict it reached; a line cut short
by a kill is skipped when read. A resumed run takes each kept verdict as it
is and judges only the sites it has not seen. SURVIVED verdicts are
judged again with --rejudge-survivors (after a test was added for them):
the newest line for a site wins.
"""
import json
import os
from pathlib import Path

FIELDS = ("seed", "site", "folder", "outcome", "detail", "diff", "revision")


class Ledger:
    def __init__(self, path, seed):
        self.path, self.seed, self.judged = Path(path), seed, {}
        if self.path.exists():
            for line in self.path.read_text(errors="replace").splitlines():
                entry = parse(line)
                if entry and entry["seed"] == seed:
                    self.judged[entry["site"]] = entry

    def verdict(self, site_id, rejudge_survivors=False):
        """The kept verdict of a site, or None when it is still to be judged."""
        entry = self.judged.get(site_id)
        if entry is None or (rejudge_survivors and entry["outcome"] == "SURVIVED"):
            return None
        return entry

    def record(self, site_id, folder, outcome, detail, diff, revision, seconds=None):
        entry = dict(zip(FIELDS, (self.seed, site_id, folder, outcome, detail, diff, revision)))
        if seconds is not None:
            entry["seconds"] = seconds  # what judging it cost (docs/contributing.md: the time per mutant)
        self.path.parent.mkdir(parents=True, exist_ok=True)
        with open(self.path, "a+") as out:
            # A line left unfinished by a killed run must not swallow this one.
            out.seek(0, os.SEEK_END)
            if out.tell() > 0:
                out.seek(out.tell() - 1)
                if out.read(1) != "\n":
                    out.write("\n")
            out.write(json.dumps(entry) + "\n")
            out.flush()
            os.fsync(out.fileno())
        self.judged[site_id] = entry
        return entry


def parse(line):
    """One ledger line as a dict, or None when it is cut short or not a verdict."""
    try:
        entry = json.loads(line)
    except json.JSONDecodeError:
        return None
    if not isinstance(entry, dict) or any(field not in entry for field in FIELDS):
        return None
    return entry
