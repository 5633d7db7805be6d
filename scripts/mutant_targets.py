# The tests a sampled mutant runs first: the test files most likely to kill a mutant of a given source file.
"""Maps a mutated source file to the test files most likely to kill it, so
that scripts/mutants --sample runs those first and stops at the first
failure; only a mutant that survives them runs the rest of the fast suite.

A test file is a target of a source file when, in this order:
  1. it is named after it (shapes.cpp: shapes_test.cpp),
  2. it includes the source's own header (shapes.hpp) by name,
  3. a test case's name there names the source's subject: the file's name
     without the words that say its kind (bounces_experiment.cpp: "bounces",
     bumpy_road_diagram.cpp: "bumpy road" or "bumpy_road"), five letters at least,
  4. it sits in the test folder that mirrors the source's folder
     (render/draw/elements/ -> tests/render/draw/elements/, or the
     nearest mirrored parent that exists; src/jobs is tested in tests/cli).
Catch2 selects a test file's cases by the tag [#FILENAME] that -# gives
every test case (the file's name without .cpp).
"""
import re
from pathlib import Path

# Where each source folder's tests live (policy as a table).
TEST_FOLDER_OF = {"src/core": "tests/core", "src/cli": "tests/cli", "src/jobs": "tests/cli",
                  "render": "tests/render", "scenes": "tests/scenes"}
INCLUDE = re.compile(r'^\s*#\s*include\s+"([^"]+)"', re.M)
TEST_CASE_NAME = re.compile(r'TEST_CASE\(\s*"((?:[^"\\]|\\.)*)"')
# Words of a source file's name that say what kind of thing it is, not what it is about.
KIND_WORDS = {"experiment", "experiments", "diagram", "diagrams", "panel", "panels", "command", "job", "scene",
              "figure", "analysis", "analyze"}


def mirrored_folder(tree, source):
    """The test folder mirroring the source's, or its nearest existing parent."""
    for root, tests in TEST_FOLDER_OF.items():
        if source.startswith(root + "/"):
            rest = Path(source[len(root) + 1:]).parent
            candidates = [Path(tests) / rest, *(Path(tests) / p for p in rest.parents)]
            return next((c for c in candidates if (tree / c).is_dir()), None)
    return None


def subject(source):
    """The words a test uses for what a source file is about (see KIND_WORDS), or None when too short to mean it."""
    words = [w for w in Path(source).stem.split("_") if w not in KIND_WORDS]
    text = " ".join(words)
    return text if len(text) >= 5 else None


def names_subject(test_file, about):
    """Whether a test case of the file names `about` (with spaces or underscores), in any case."""
    names = " | ".join(TEST_CASE_NAME.findall(test_file.read_text())).lower()
    return about in names or about.replace(" ", "_") in names


def test_files(tree):
    """Every Catch2 test file of the tree, relative to it, sorted."""
    return sorted(str(p.relative_to(tree)) for p in (tree / "tests").rglob("*_test.cpp"))


def targets(tree, source, files=None):
    """The test files (relative paths) that should catch a mutant of `source`, most likely first."""
    tree = Path(tree)
    files = test_files(tree) if files is None else files
    stem = Path(source).stem
    named = [f for f in files if Path(f).stem == stem + "_test"]
    header = Path(source).with_suffix(".hpp").name
    including = [f for f in files if any(Path(i).name == header for i in INCLUDE.findall((tree / f).read_text()))]
    folder = mirrored_folder(tree, source)
    mirrored = [f for f in files if folder is not None and Path(f).parent == folder]
    about = subject(source)
    naming = [] if about is None else [f for f in files if names_subject(tree / f, about)]
    ordered = []
    for f in named + including + naming + mirrored:
        if f not in ordered:
            ordered.append(f)
    return ordered


def tag_of(test_file):
    return f"[#{Path(test_file).stem}]"


def targeted_spec(spec, files):
    """A Catch2 spec for the target files' cases that `spec` selects (one OR-term per file)."""
    return ",".join(f"{tag_of(f)} {spec}" for f in files)


def rest_spec(spec, files):
    """A Catch2 spec for the cases of `spec` in every other file."""
    return " ".join([spec, *(f"~{tag_of(f)}" for f in files)])
