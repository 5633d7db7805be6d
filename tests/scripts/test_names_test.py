# Catch2 test names survive CMake and ctest: no semicolon (CMake cuts a list there, and ctest then runs a filter that matches nothing), each name once.
import re
import unittest
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]
# TEST_CASE( followed by one or more adjacent string literals.
NAME = re.compile(r'TEST_CASE\(\s*((?:"(?:[^"\\]|\\.)*"\s*)+)')
LITERAL = re.compile(r'"((?:[^"\\]|\\.)*)"')


def test_names():
    for source in sorted((ROOT / "tests").rglob("*.cpp")):
        for match in NAME.finditer(source.read_text(errors="replace")):
            yield source.relative_to(ROOT), "".join(LITERAL.findall(match.group(1)))


class TestNames(unittest.TestCase):
    def test_found(self):
        self.assertGreater(len(list(test_names())), 500)

    def test_no_semicolon(self):
        for source, name in test_names():
            with self.subTest(source=str(source), name=name):
                self.assertNotIn(";", name, "ctest would cut this name at the semicolon and match no test")

    def test_each_name_once(self):
        seen = {}
        for source, name in test_names():
            with self.subTest(name=name):
                self.assertNotIn(name, seen, f"in {source} and {seen.get(name)}")
            seen[name] = source


if __name__ == "__main__":
    unittest.main()
