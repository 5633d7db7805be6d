# Tests of scripts/mutant_ledger.py and the resumed --sample run: verdicts kept per seed and site, a stopped run continues where it stopped.
import argparse
import sys
import tempfile
import unittest
from collections import namedtuple
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parents[2] / "scripts"))
import mutant_sample  # noqa: E402
from mutant_ledger import Ledger  # noqa: E402

Site = namedtuple("Site", "id")


def sample_args(n, rejudge=False):
    return argparse.Namespace(sample=n, seed=3, rejudge_survivors=rejudge)


class Stop(Exception):
    pass


class Judge:
    """Judges a site KILLED, or SURVIVED when its id ends in 's'; stops after `limit` calls, as Ctrl-C would."""
    def __init__(self, limit=None):
        self.calls, self.limit = [], limit

    def __call__(self, site):
        if self.limit is not None and len(self.calls) == self.limit:
            raise Stop()
        self.calls.append(site.id)
        return ("SURVIVED" if site.id.endswith("s") else "KILLED", "detail", "diff", "abc1234")


class Verdicts(unittest.TestCase):
    def test_a_verdict_is_kept_per_seed_and_site(self):
        with tempfile.TemporaryDirectory() as d:
            path = Path(d) / "verdicts.jsonl"
            Ledger(path, 1).record("a.cpp:1:op:0", "src/core", "KILLED", "by x", "-a\n+b\n", "abc")
            self.assertEqual(Ledger(path, 1).verdict("a.cpp:1:op:0")["outcome"], "KILLED")
            self.assertIsNone(Ledger(path, 2).verdict("a.cpp:1:op:0"))
            self.assertIsNone(Ledger(path, 1).verdict("b.cpp:1:op:0"))

    def test_a_line_cut_short_is_skipped_and_swallows_nothing(self):
        with tempfile.TemporaryDirectory() as d:
            path = Path(d) / "verdicts.jsonl"
            Ledger(path, 1).record("first", "render", "KILLED", "", "", "abc")
            with open(path, "a") as out:
                out.write('{"seed": 1, "site": "cut", "fol')  # a run killed in the middle of a write
            Ledger(path, 1).record("after", "render", "SURVIVED", "", "", "abc")
            ledger = Ledger(path, 1)
            self.assertEqual(sorted(ledger.judged), ["after", "first"])

    def test_survivors_are_judged_again_only_when_asked_and_the_newest_wins(self):
        with tempfile.TemporaryDirectory() as d:
            path = Path(d) / "verdicts.jsonl"
            Ledger(path, 1).record("s", "scenes", "SURVIVED", "", "", "abc")
            Ledger(path, 1).record("k", "scenes", "KILLED", "", "", "abc")
            self.assertEqual(Ledger(path, 1).verdict("s")["outcome"], "SURVIVED")
            self.assertIsNone(Ledger(path, 1).verdict("s", rejudge_survivors=True))
            self.assertEqual(Ledger(path, 1).verdict("k", rejudge_survivors=True)["outcome"], "KILLED")
            Ledger(path, 1).record("s", "scenes", "KILLED", "by a new test", "", "def")
            self.assertEqual(Ledger(path, 1).verdict("s")["detail"], "by a new test")


    def test_the_ledger_is_the_one_given_else_beside_the_copy(self):
        given = argparse.Namespace(ledger=Path("/repo/scripts/mutants-verdicts.jsonl"))
        self.assertEqual(mutant_sample.ledger_path(given, Path("/tmp/copy")), given.ledger)
        for none_given in (argparse.Namespace(ledger=None), sample_args(1)):
            self.assertEqual(mutant_sample.ledger_path(none_given, Path("/tmp/copy")),
                             Path("/tmp/copy/sample-verdicts.jsonl"))


class ResumedRun(unittest.TestCase):
    BY_FOLDER = {"render": [Site(f"r{i}") for i in range(6)] + [Site("rs")],
                 "scenes": [Site(f"c{i}") for i in range(6)] + [Site("cs")]}

    def test_a_stopped_run_continues_with_the_sites_it_had_not_judged(self):
        with tempfile.TemporaryDirectory() as d:
            path = Path(d) / "verdicts.jsonl"
            first = Judge(limit=5)
            with self.assertRaises(Stop):
                mutant_sample.judge_sample(sample_args(10), self.BY_FOLDER, Ledger(path, 3), first)
            second = Judge()
            resumed = mutant_sample.judge_sample(sample_args(10), self.BY_FOLDER, Ledger(path, 3), second)
            self.assertEqual(len(second.calls), 5)
            self.assertFalse(set(first.calls) & set(second.calls))
            uninterrupted = Judge()
            with tempfile.TemporaryDirectory() as e:
                whole = mutant_sample.judge_sample(sample_args(10), self.BY_FOLDER, Ledger(Path(e) / "v", 3),
                                                   uninterrupted)
            self.assertEqual(first.calls + second.calls, uninterrupted.calls)
            self.assertEqual([(f, s.id, o) for f, s, o, _, _ in resumed], [(f, s.id, o) for f, s, o, _, _ in whole])

    def test_rejudging_runs_the_survivors_alone(self):
        with tempfile.TemporaryDirectory() as d:
            path = Path(d) / "verdicts.jsonl"
            everything = sorted(s.id for sites in self.BY_FOLDER.values() for s in sites)
            mutant_sample.judge_sample(sample_args(14), self.BY_FOLDER, Ledger(path, 3), Judge())
            again = Judge()
            mutant_sample.judge_sample(sample_args(14, rejudge=True), self.BY_FOLDER, Ledger(path, 3), again)
            self.assertEqual(sorted(again.calls), ["cs", "rs"])
            self.assertEqual(len(everything), 14)

    def test_triaging_a_site_leaves_the_others_in_their_order(self):
        order = [s.id for _, s in mutant_sample.draw_order(self.BY_FOLDER, 3)]
        triaged = {f: [s for s in sites if s.id != "r2"] for f, sites in self.BY_FOLDER.items()}
        render_after = [s.id for f, s in mutant_sample.draw_order(triaged, 3) if f == "render"]
        self.assertEqual(render_after, [i for i in order if i.startswith("r") and i != "r2"])


if __name__ == "__main__":
    unittest.main()
