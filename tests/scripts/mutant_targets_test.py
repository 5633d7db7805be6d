# Tests of scripts/mutant_targets.py and the targeted-first judging of scripts/mutants --sample: which tests run first, what a verdict names.
import os
import stat
import sys
import tempfile
import unittest
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parents[2] / "scripts"))
import mutant_sample  # noqa: E402
import mutant_targets  # noqa: E402


def make_tree(root, files):
    for rel, text in files.items():
        (root / rel).parent.mkdir(parents=True, exist_ok=True)
        (root / rel).write_text(text)
    return root


TREE = {
    "render/draw/elements/shapes.cpp": "",
    "tests/render/draw/annotations_test.cpp": '#include "render/draw/annotations.hpp"\n',
    "tests/render/draw/shapes_test.cpp": "",
    "tests/scenes/pendulum_test.cpp": '#include "render/draw/elements/shapes.hpp"\n',
    "tests/scenes/energy_bars_test.cpp": '// #include "shapes.hpp" in a comment counts not\n',
    "tests/cli/render_outputs_test.cpp": "",
    "tests/core/schemes_test.cpp": "",
}


class Targets(unittest.TestCase):
    def test_named_then_including_then_the_nearest_mirrored_folder(self):
        with tempfile.TemporaryDirectory() as d:
            tree = make_tree(Path(d), TREE)
            self.assertEqual(mutant_targets.targets(tree, "render/draw/elements/shapes.cpp"),
                             ["tests/render/draw/shapes_test.cpp", "tests/scenes/pendulum_test.cpp",
                              "tests/render/draw/annotations_test.cpp"])

    def test_the_jobs_are_tested_through_the_command_line(self):
        with tempfile.TemporaryDirectory() as d:
            tree = make_tree(Path(d), TREE)
            self.assertEqual(mutant_targets.targets(tree, "src/jobs/render_job.cpp"),
                             ["tests/cli/render_outputs_test.cpp"])

    def test_a_file_without_tests_of_its_own_has_none(self):
        with tempfile.TemporaryDirectory() as d:
            tree = make_tree(Path(d), {"tests/core/schemes_test.cpp": ""})
            self.assertEqual(mutant_targets.targets(tree, "web/app.cpp"), [])

    def test_then_the_files_whose_test_names_name_the_sources_subject(self):
        with tempfile.TemporaryDirectory() as d:
            tree = make_tree(Path(d), {
                "tests/cli/analyze_test.cpp": 'TEST_CASE("vibra analyze Bounces lists every impact")\n',
                "tests/scenes/diagrams_test.cpp": 'TEST_CASE("bumpy_road: the wheel")\nload_scene("bounces")\n',
                "tests/scenes/free_body_test.cpp": 'TEST_CASE("the bumpy road\'s arrows")\n',
                "tests/core/schemes_test.cpp": 'TEST_CASE("road and bumps")\n'})
            self.assertEqual(mutant_targets.targets(tree, "src/jobs/experiments/bounces_experiment.cpp"),
                             ["tests/cli/analyze_test.cpp"])
            self.assertEqual(mutant_targets.targets(tree, "scenes/diagrams/bumpy_road_diagram.cpp"),
                             ["tests/scenes/diagrams_test.cpp", "tests/scenes/free_body_test.cpp"])
            # A subject too short to mean anything (text.cpp: "text") adds nothing.
            self.assertIsNone(mutant_targets.subject("render/draw/text.cpp"))

    def test_the_specs_select_the_targets_and_then_everything_else(self):
        files = ["tests/render/draw/shapes_test.cpp", "tests/scenes/pendulum_test.cpp"]
        self.assertEqual(mutant_targets.targeted_spec("~[heavy]", files),
                         "[#shapes_test] ~[heavy],[#pendulum_test] ~[heavy]")
        self.assertEqual(mutant_targets.rest_spec("~[heavy]", files), "~[heavy] ~[#shapes_test] ~[#pendulum_test]")


FAKE_SUITE = """#!/usr/bin/env python3
# A stand-in for vibra_tests: records each spec; fails a spec naming the tag in FAIL_TAG.
import os, sys
spec = sys.argv[-1]
if "--list-test-names-only" in sys.argv:
    print("fast case\\nslow case")
    sys.exit(0)
with open(os.environ["SPECS_LOG"], "a") as out:
    out.write(spec + "\\n")
if os.environ["FAIL_TAG"] and os.environ["FAIL_TAG"] in spec and "~" + os.environ["FAIL_TAG"] not in spec:
    print("-" * 40 + "\\n" + os.environ["FAIL_TAG"] + " case fails\\n" + "-" * 40)
    sys.exit(1)
"""


def fake_suite(folder):
    suite = Path(folder) / "vibra_tests"
    suite.write_text(FAKE_SUITE)
    suite.chmod(suite.stat().st_mode | stat.S_IEXEC)
    return suite


class TargetedFirst(unittest.TestCase):
    def judge(self, fail_tag, targets):
        with tempfile.TemporaryDirectory() as d:
            suite = fake_suite(d)
            os.environ.update(SPECS_LOG=str(Path(d) / "specs"), FAIL_TAG=fail_tag)
            verdict = mutant_sample.run_targeted_first(suite, "~[heavy]", targets, 60, str(Path(d) / "m"))
            return verdict, (Path(d) / "specs").read_text().splitlines()

    def test_the_targeted_tests_get_five_times_their_unmutated_seconds_within_the_suites_limit(self):
        with tempfile.TemporaryDirectory() as d:
            suite = fake_suite(d)
            seconds_of = {"fast case": 1.0, "slow case": 30.0, "elsewhere": 500.0}
            self.assertEqual(mutant_sample.targeted_timeout(suite, "[#x_test]", 1000, seconds_of), 155.0)
            self.assertEqual(mutant_sample.targeted_timeout(suite, "[#x_test]", 100, seconds_of), 100)
            self.assertEqual(mutant_sample.targeted_timeout(suite, "[#x_test]", 1000, {"fast case": 1.0}), 60.0)
            self.assertEqual(mutant_sample.targeted_timeout(suite, "[#x_test]", 1000, {}), 1000)

    def test_the_baselines_case_seconds_are_read_from_catch2s_durations(self):
        with tempfile.TemporaryDirectory() as d:
            log = Path(d) / "baseline.log"
            log.write_text("Filters: ~[heavy]\n0.250 s: a case: with a colon\n12.000 s: another\n=====\n")
            self.assertEqual(mutant_sample.durations(log), {"a case: with a colon": 0.25, "another": 12.0})

    def test_a_kill_by_a_targeted_test_runs_nothing_else_and_says_so(self):
        verdict, specs = self.judge("[#shapes_test]", ["tests/render/draw/shapes_test.cpp"])
        self.assertEqual(verdict, ("KILLED", "by [#shapes_test] case fails [targeted]"))
        self.assertEqual(specs, ["[#shapes_test] ~[heavy]"])

    def test_a_survivor_of_the_targets_runs_the_rest_of_the_suite(self):
        verdict, specs = self.judge("~[#shapes_test]", ["tests/render/draw/shapes_test.cpp"])
        self.assertEqual(verdict, ("KILLED", "by ~[#shapes_test] case fails [rest of the suite]"))
        self.assertEqual(specs, ["[#shapes_test] ~[heavy]", "~[heavy] ~[#shapes_test]"])

    def test_a_survivor_passed_the_whole_suite(self):
        verdict, specs = self.judge("", ["tests/render/draw/shapes_test.cpp"])
        self.assertEqual(verdict, ("SURVIVED", ""))
        self.assertEqual(len(specs), 2)

    def test_without_targets_the_whole_suite_runs_once(self):
        verdict, specs = self.judge("", [])
        self.assertEqual(specs, ["~[heavy]"])


class Baseline(unittest.TestCase):
    def test_the_tests_that_need_room_below_are_left_out_only_at_niceness_19(self):
        self.assertEqual(mutant_sample.suite_spec("~[heavy]", 10), "~[heavy]")
        self.assertEqual(mutant_sample.suite_spec("~[heavy]", 19),
                         "~[heavy] ~\"the encoder's threads give way to the drawing thread*\"")

    def test_a_baseline_is_kept_for_its_tree_and_measured_again_for_another(self):
        with tempfile.TemporaryDirectory() as d:
            logs = Path(d) / "logs"
            logs.mkdir()
            (logs.parent / "baseline.json").write_text('{"key": "tree1 ~[heavy]", "seconds": 100, "cases": {"a": 2}}\n')
            builds = []
            kept = mutant_sample.baseline_timeout("~[heavy]", builds.append, "/bin/true", logs, "tree1 ~[heavy]")
            self.assertEqual((kept, builds), ((300.0, {"a": 2}), []))
            with self.assertRaises(SystemExit):  # another tree: built again (this stand-in build fails)
                mutant_sample.baseline_timeout("~[heavy]", lambda log: builds.append(log), "/bin/true", logs,
                                               "tree2 ~[heavy]")
            self.assertEqual(len(builds), 1)


if __name__ == "__main__":
    unittest.main()
