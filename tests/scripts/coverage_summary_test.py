# Tests of scripts/coverage_summary.py: an lcov tracefile summed per source folder, and the files under the bar listed.
import sys
import unittest
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parents[2] / "scripts"))
import coverage_summary  # noqa: E402

ROOT = "/repo"
TRACEFILE = """TN:
SF:/repo/src/core/schemes/pefrl.hpp
LF:10
LH:9
BRF:4
BRH:2
end_of_record
SF:/repo/src/core/time_mesh.cpp
LF:30
LH:15
BRF:10
BRH:5
end_of_record
SF:/repo/src/core/csv_writer.cpp
LF:10
LH:10
end_of_record
SF:/usr/include/c++/12/bits/stl_vector.h
LF:100
LH:1
end_of_record
SF:/repo/tests/main.cpp
LF:5
LH:5
end_of_record
"""


class Summary(unittest.TestCase):
    def test_files_of_the_source_folders_only(self):
        files = coverage_summary.read_tracefile(TRACEFILE, ROOT)
        self.assertEqual(sorted(files), ["src/core/csv_writer.cpp", "src/core/schemes/pefrl.hpp", "src/core/time_mesh.cpp"])
        self.assertEqual(files["src/core/time_mesh.cpp"]["lines_hit"], 15)

    def test_each_file_counts_in_its_most_specific_folder(self):
        lines = coverage_summary.report(coverage_summary.read_tracefile(TRACEFILE, ROOT), 85)
        rows = [line.split() for line in lines]
        self.assertIn(["src/core/schemes/", "9/10", "90.0%", "2/4", "50.0%"], rows)
        self.assertIn(["src/core/", "25/40", "62.5%", "5/10", "50.0%"], rows)

    def test_files_under_the_bar_are_named_lowest_first(self):
        lines = coverage_summary.report(coverage_summary.read_tracefile(TRACEFILE, ROOT), 85)
        self.assertEqual(lines[-2:], ["\n1 of 3 files under 85% of lines:", "   50.0%  src/core/time_mesh.cpp"])

    def test_records_of_one_file_from_two_objects_merge_without_sums(self):
        # lcov 1.16 writes a file once per object that compiled it, DA and BRDA only: a line run by either counts once.
        twice = """TN:
SF:/repo/src/core/a.cpp
DA:1,0
DA:2,3
BRDA:2,0,0,-
BRDA:2,0,1,1
end_of_record
TN:
SF:/repo/src/core/a.cpp
DA:1,4
DA:2,0
DA:5,0
BRDA:2,0,0,0
BRDA:2,0,1,0
end_of_record
"""
        counts = coverage_summary.read_tracefile(twice, ROOT)["src/core/a.cpp"]
        self.assertEqual((counts["lines"], counts["lines_hit"]), (3, 2))
        self.assertEqual((counts["branches"], counts["branches_hit"]), (2, 1))


if __name__ == "__main__":
    unittest.main()
