# Tests of scripts/mutant_sites.py and the sampling of scripts/mutant_sample.py: which edits are generated, and their stable ids.
import sys
import tempfile
import unittest
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parents[2] / "scripts"))
import mutant_sample  # noqa: E402
import mutant_sites  # noqa: E402

SOURCE = '''// A comment with a + b and 3 < 4.
#include <vector>
#define TWICE(x) (2 * x)
/* block: a - b */
double f(double a, double b) {
  std::vector<int> v;
  const double* p = &a;
  for (auto&& x : v) x;
  const char* s = "a + b < 3";
  if (a < b) return a * 2.5;
  total += scale(a, b);
  return -a + b;
}
'''


def edits(text, operator=None):
    return {(s.operator, s.old, s.new) for s in mutant_sites.sites("x.cpp", text)
            if operator is None or s.operator == operator}


class Sites(unittest.TestCase):
    def test_comments_strings_and_directives_are_never_mutated(self):
        for site in mutant_sites.sites("x.cpp", SOURCE):
            line = SOURCE.split("\n")[site.line - 1]
            self.assertFalse(line.startswith(("//", "#", "/*")), site.id)
            self.assertNotIn('"', site.old, site.id)

    def test_operators_swap_but_template_brackets_stay(self):
        ops = edits(SOURCE, "operator")
        self.assertIn(("operator", "<", "<="), ops)  # a < b, spaced
        self.assertIn(("operator", "*", "/"), ops)
        self.assertIn(("operator", "+", "-"), ops)
        self.assertIn(("operator", "+=", "-="), ops)
        # std::vector<int> and the #include's <vector> give no site: one '<' only;
        # neither do the pointer type and the forwarding reference.
        self.assertEqual(sum(1 for s in mutant_sites.sites("x.cpp", SOURCE) if s.old == "<"), 1)
        self.assertEqual(sum(1 for s in mutant_sites.sites("x.cpp", SOURCE) if s.old in ("*", "&&")), 1)  # a * 2.5

    def test_constants_change_by_one_and_double(self):
        self.assertEqual(edits("x = 2.5;", "constant"), {("constant", "2.5", "3.5"), ("constant", "2.5", "1.5"),
                                                         ("constant", "2.5", "5.0")})
        self.assertEqual(edits("x = 0;", "constant"), {("constant", "0", "1")})
        self.assertEqual(edits("x = 3'600;", "constant"), {("constant", "3'600", "3601"), ("constant", "3'600", "3599"),
                                                          ("constant", "3'600", "7200")})
        self.assertEqual(edits("x = 0x1fULL;", "constant"), set())  # hexadecimal: left alone
        self.assertEqual(edits("x = 3u;", "constant"), {("constant", "3u", "4u"), ("constant", "3u", "2u"),
                                                        ("constant", "3u", "6u")})

    def test_arguments_swap_statements_drop_conditions_negate_signs_flip(self):
        self.assertIn(("swap-arguments", "a, b", "b, a"), edits(SOURCE, "swap-arguments"))
        self.assertIn(("drop-statement", "total += scale(a, b);", ";"), edits(SOURCE, "drop-statement"))
        self.assertIn(("negate-condition", "(a < b)", "(!(a < b))"), edits(SOURCE, "negate-condition"))
        self.assertEqual(edits(SOURCE, "sign"), {("sign", "-", "")})  # -a, not the binary minus
        self.assertEqual(edits("ok = true;", "boolean"), {("boolean", "true", "false")})

    def test_apply_makes_exactly_the_one_edit(self):
        site = next(s for s in mutant_sites.sites("x.cpp", SOURCE) if s.operator == "sign")
        self.assertEqual(site.apply(SOURCE), SOURCE.replace("return -a + b;", "return a + b;"))

    def test_ids_are_unique_and_survive_edits_elsewhere(self):
        ids = [s.id for s in mutant_sites.sites("x.cpp", SOURCE)]
        self.assertEqual(len(ids), len(set(ids)))
        moved = SOURCE.replace("double f(", "int g() { return 7; }\ndouble f(")
        moved_ids = {s.id for s in mutant_sites.sites("x.cpp", moved)}
        self.assertTrue(set(ids) <= moved_ids)
        self.assertEqual(len(moved_ids - set(ids)), len(mutant_sites.sites("x.cpp", "int g() { return 7; }")))


class Sampling(unittest.TestCase):
    def test_draws_take_the_folders_in_turn_and_repeat_for_a_seed(self):
        by_folder = {"render": list(range(10)), "scenes": list(range(100, 103)), "src/cli": [200]}
        order = list(mutant_sample.draw_order(by_folder, 7))
        self.assertEqual([f for f, _ in order[:3]], ["render", "scenes", "src/cli"])
        self.assertEqual(sorted(s for _, s in order), sorted(sum(by_folder.values(), [])))
        self.assertEqual(order, list(mutant_sample.draw_order(by_folder, 7)))
        self.assertNotEqual(order, list(mutant_sample.draw_order(by_folder, 8)))

    def test_triaged_equivalents_are_read_by_id(self):
        with tempfile.TemporaryDirectory() as d:
            path = Path(d) / "equivalent.txt"
            path.write_text("# id  reason\nsrc/core/a.cpp:0123456789:constant:1->2:0  a bound never reached\n\n")
            self.assertEqual(mutant_sample.load_equivalents(path), {"src/core/a.cpp:0123456789:constant:1->2:0"})

    def test_every_source_file_is_scored_in_its_folder(self):
        self.assertEqual(mutant_sample.folder_of("src/core/models/rlc.cpp"), "src/core")
        self.assertEqual(mutant_sample.folder_of("render/plot/axis.cpp"), "render")


if __name__ == "__main__":
    unittest.main()
