# scripts/mutants' hand list stays true to the tree: each mutant's text occurs exactly once in its file, and its tests exist.
import importlib.machinery
import importlib.util
import unittest
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]


def hand_list():
    loader = importlib.machinery.SourceFileLoader("mutants", str(ROOT / "scripts" / "mutants"))
    module = importlib.util.module_from_spec(importlib.util.spec_from_loader("mutants", loader))
    loader.exec_module(module)
    return module.MUTANTS


class HandList(unittest.TestCase):
    def test_every_mutant_finds_its_text_once(self):
        # A mutant whose text moved is reported STALE by the script and tests nothing: caught here, when the code changes.
        for mutant in hand_list():
            with self.subTest(mutant=mutant.name):
                text = (ROOT / mutant.file).read_text()
                self.assertEqual(text.count(mutant.old), 1, f"{mutant.name}: its text in {mutant.file}")
                self.assertNotEqual(mutant.old, mutant.new)

    def test_names_are_unique(self):
        names = [m.name for m in hand_list()]
        self.assertEqual(len(names), len(set(names)))


if __name__ == "__main__":
    unittest.main()
