# scripts/mutants --sample N: generated mutants, sampled across the source folders, scored per folder.
"""Runs a sample of generated mutants (scripts/mutant_sites.py) in the
mutants' copy of the tree and prints the mutation score per folder with the
survivors as diffs (docs/contributing.md, "Mutants").

Each mutant is one edit of one .cpp file (with --headers, .hpp too: each
rebuilds every file that includes it). vibra and vibra_tests are rebuilt in
the copy's mutant build (-O1, no Python module, through ccache: ninja
compiles the one object and relinks). Then the tests most likely to kill it
run first (scripts/mutant_targets.py: the test files named after the
mutated file, including its header, or in the mirrored test folder), and
only when they all pass, the rest of the fast suite; each as one process
that Catch2's --abort ends at the first failure, both within a time limit
of a few times the unmutated suite's. KILLED: a test failed (the verdict
names it, and whether it was a targeted one) or the time ran out;
SURVIVED: the whole fast suite passed; INVALID: it does not compile (not
scored; another site of its folder is drawn instead). The file is restored
after each mutant whatever happens, also on Ctrl-C or SIGTERM.

Equivalent mutants (no program can tell them from the original) are triaged
once into scripts/mutants-equivalent.txt, one stable id a line with the
reason, and never drawn again.
"""
import difflib
import hashlib
import json
import os
import re
import signal
import subprocess
import sys
import time
from collections import defaultdict
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))
import mutant_sites  # noqa: E402
import mutant_targets  # noqa: E402
from mutant_ledger import Ledger  # noqa: E402

SOURCE_FOLDERS = ["src/core", "src/cli", "src/jobs", "render", "scenes"]  # scored separately
EQUIVALENTS = Path(__file__).resolve().parent / "mutants-equivalent.txt"


def folder_of(path):
    return next(f for f in SOURCE_FOLDERS if path.startswith(f + "/"))


def load_equivalents(path=EQUIVALENTS):
    """The triaged ids: one a line, the reason after them; # starts a comment line."""
    if not path.exists():
        return set()
    lines = (line.split()[0] for line in path.read_text().splitlines() if line.strip() and not line.startswith("#"))
    return set(lines)


def all_sites(tree, headers, equivalents):
    """Every site of every source file, by folder, the triaged equivalents left out."""
    by_folder = defaultdict(list)
    suffixes = (".cpp", ".hpp") if headers else (".cpp",)
    for folder in SOURCE_FOLDERS:
        for path in sorted((tree / folder).rglob("*")):
            if path.suffix in suffixes:
                rel = str(path.relative_to(tree))
                by_folder[folder] += [s for s in mutant_sites.sites(rel, path.read_text()) if s.id not in equivalents]
    return by_folder


def draw_key(seed, site):
    """A site's place in the draw, from the seed and its own id alone: triaging an
    equivalent or editing another line leaves the other sites' order as it was,
    so a resumed run draws the sites it drew before."""
    return hashlib.sha256(f"{seed}:{getattr(site, 'id', site)}".encode()).hexdigest()


def draw_order(by_folder, seed):
    """Sites in the order they are tried: each folder's shuffled, the folders taken in turn."""
    queues = {f: sorted(sites, key=lambda s: draw_key(seed, s)) for f, sites in sorted(by_folder.items())}
    longest = max((len(q) for q in queues.values()), default=0)
    for i in range(longest):
        for folder, queue in queues.items():
            if i < len(queue):
                yield folder, queue[i]


def diff_of(site, original, mutated):
    line = site.line
    before, after = original.split("\n")[line - 1], mutated.split("\n")[line - 1]
    return "".join(difflib.unified_diff([before + "\n"], [after + "\n"], f"a/{site.file}", f"b/{site.file}",
                                        lineterm="\n", n=0)).replace("@@ -1 +1 @@", f"@@ line {line} @@")


def run_suite(suite, spec, timeout, log, extra=()):
    """'KILLED' or 'SURVIVED', and the failing test's name where Catch2 printed it."""
    with open(log, "w") as out:
        try:
            # From the suite's folder, as ctest runs it; -# tags each case with its file, [#name_test].
            rc = subprocess.run([str(suite), "-#", "--abort", *extra, spec], stdout=out, stderr=subprocess.STDOUT,
                                cwd=Path(suite).parent, timeout=timeout).returncode
        except subprocess.TimeoutExpired:
            return "KILLED", f"timed out after {timeout:.0f} s"
    if rc == 0:
        return "SURVIVED", ""
    # Catch2 prints a failure under a rule of dashes: the test case's name.
    failed = re.search(r"^-{20,}\n(.+)$", Path(log).read_text(errors="replace"), re.M)
    return "KILLED", f"by {failed.group(1)[:100]}" if failed else f"exit {rc}"


def durations(log):
    """Each test case's seconds, from a run with --durations yes."""
    found = re.findall(r"^(\d+\.\d+) s: (.+)$", Path(log).read_text(errors="replace"), re.M)
    return {name: float(seconds) for seconds, name in found}


def targeted_timeout(suite, spec, timeout, seconds_of):
    """Five times what the targeted cases took unmutated (at least a minute), so that a
    mutant that loops in them costs minutes, not the whole suite's limit."""
    if not seconds_of:
        return timeout
    names = subprocess.run([str(suite), "-#", "--list-test-names-only", spec], capture_output=True, text=True,
                           cwd=Path(suite).parent).stdout.splitlines()
    return min(timeout, max(60.0, 5 * sum(seconds_of.get(n, 0.0) for n in names)))


def run_targeted_first(suite, spec, targets, timeout, log_stem, seconds_of=None):
    """The target files' tests first; the rest of the suite only if they all pass.
    The verdict is the whole suite's; a kill says which part found it."""
    deadline = time.time() + timeout
    if targets:
        targeted = mutant_targets.targeted_spec(spec, targets)
        outcome, detail = run_suite(suite, targeted, targeted_timeout(suite, targeted, timeout, seconds_of),
                                    f"{log_stem}-targeted.log")
        if outcome == "KILLED":
            return outcome, f"{detail} [targeted]"
    rest = mutant_targets.rest_spec(spec, targets)
    outcome, detail = run_suite(suite, rest, max(1.0, deadline - time.time()), f"{log_stem}-rest.log")
    return outcome, f"{detail} [rest of the suite]" if outcome == "KILLED" else detail


def restore_on_signals():
    """SIGTERM and SIGHUP end the run through the finally blocks, as Ctrl-C does."""
    def stop(signum, _frame):
        raise SystemExit(f"mutants: stopped by signal {signum}; the copy's sources restored")
    for s in (signal.SIGTERM, signal.SIGHUP):
        signal.signal(s, stop)


def try_site(site, tree, build_ok, suite, spec, baseline, logs):
    """Plants one site, builds, runs its targeted tests then the rest; restores the file whatever happens."""
    path = tree / site.file
    original = path.read_text()
    mutated = site.apply(original)
    name = site.id.replace("/", "_").replace(":", "_")
    try:
        path.write_text(mutated)
        if not build_ok(logs / f"{name}-build.log"):
            return "INVALID", "does not compile", ""
        targets = mutant_targets.targets(tree, site.file)
        timeout, seconds_of = baseline
        outcome, detail = run_targeted_first(suite, spec, targets, timeout, logs / f"{name}-tests", seconds_of)
        return outcome, detail, diff_of(site, original, mutated)
    finally:
        path.write_text(original)


def print_scores(results):
    by_folder = defaultdict(lambda: [0, 0])
    for folder, site, outcome, _, _ in results:
        if outcome != "INVALID":
            by_folder[folder][0] += outcome == "KILLED"
            by_folder[folder][1] += 1
    print("\nfolder        killed / scored   score")
    for folder in SOURCE_FOLDERS:
        killed, scored = by_folder.get(folder, (0, 0))
        score = f"{100 * killed / scored:5.1f}%" if scored else "    -"
        print(f"{folder:12} {killed:7} / {scored:<8} {score}")
    killed = sum(k for k, _ in by_folder.values())
    scored = sum(n for _, n in by_folder.values())
    print(f"{'all':12} {killed:7} / {scored:<8} {100 * killed / max(scored, 1):5.1f}%")
    return killed, scored


# Tests that cannot pass at the lowest priority: each lowers some threads'
# priority below the run's own, and at niceness 19 there is no room below.
NEEDS_ROOM_BELOW = ["the encoder's threads give way to the drawing thread*"]


def suite_spec(spec, niceness):
    """The spec a run at this niceness can pass: at 19 without the tests that need room below it."""
    if niceness < 19:
        return spec
    return " ".join([spec, *(f'~"{name}"' for name in NEEDS_ROOM_BELOW)])


def baseline_timeout(spec, build_ok, suite, logs, key):
    """Builds and runs the unmutated copy (it must pass); the time limit per mutant and each case's seconds.
    Kept in baseline.json beside the logs for its key (the copy's tree and the spec):
    a resumed run of the same tree does not pay for the baseline again."""
    kept_path = logs.parent / "baseline.json"
    try:
        kept = json.loads(kept_path.read_text())
    except (OSError, ValueError):
        kept = {}
    if kept.get("key") == key and isinstance(kept.get("seconds"), (int, float)):
        suite_seconds, seconds_of, how = kept["seconds"], kept.get("cases", {}), "kept from a run of the same tree"
    else:
        start = time.time()
        if not build_ok(logs / "baseline-build.log"):
            sys.exit(f"mutants: the unmutated copy does not build: {logs / 'baseline-build.log'}")
        outcome, detail = run_suite(suite, spec, None, logs / "baseline-tests.log", ("--durations", "yes"))
        if outcome != "SURVIVED":
            sys.exit(f"mutants: the unmutated copy fails the fast suite ({detail}): {logs / 'baseline-tests.log'}")
        suite_seconds, seconds_of, how = time.time() - start, durations(logs / "baseline-tests.log"), "measured now"
        temporary = kept_path.with_suffix(".tmp")
        temporary.write_text(json.dumps({"key": key, "seconds": suite_seconds, "cases": seconds_of}) + "\n")
        os.replace(temporary, kept_path)
    timeout = max(60.0, 3 * suite_seconds)
    print(f"mutants: baseline built and passed '{spec}' in {suite_seconds:.0f} s ({how}); "
          f"{timeout:.0f} s per mutant at most")
    return timeout, seconds_of


def judge_sample(args, by_folder, ledger, judge):
    """Each drawn site's verdict, kept from the ledger or judged now (and recorded at once)."""
    results, scored, tried = [], 0, 0
    for folder, site in draw_order(by_folder, args.seed):
        if scored >= args.sample or tried >= 3 * args.sample:  # bounded: invalid mutants draw again, not forever
            break
        tried += 1
        t0 = time.time()
        entry = ledger.verdict(site.id, args.rejudge_survivors)
        kept = entry is not None
        if not kept:
            entry = ledger.record(site.id, folder, *judge(site), seconds=round(time.time() - t0, 1))
        scored += entry["outcome"] != "INVALID"
        results.append((folder, site, entry["outcome"], entry["detail"], entry["diff"]))
        when = "judged before" if kept else f"{time.time() - t0:.0f} s"
        print(f"  [{scored}/{args.sample}] {entry['outcome']:8} {site.id} ({when}) {entry['detail']}", flush=True)
    return results


def ledger_path(args, work):
    """Where the verdicts are kept: --ledger's file, else beside the copy."""
    return getattr(args, "ledger", None) or work / "sample-verdicts.jsonl"


def run_sample(args, tree, build_ok, suite, logs):
    """The --sample run; exit status 0 when no mutant survived."""
    restore_on_signals()
    equivalents = load_equivalents()
    by_folder = all_sites(tree, args.headers, equivalents)
    total = sum(len(s) for s in by_folder.values())
    ledger = Ledger(ledger_path(args, logs.parent), args.seed)
    print(f"mutants: {total} sites in {', '.join(SOURCE_FOLDERS)} ({len(equivalents)} triaged as equivalent); "
          f"sampling {args.sample} with seed {args.seed}; {len(ledger.judged)} judged before ({ledger.path})")
    revision, tree_hash = (subprocess.run(["git", "-C", str(tree), "rev-parse", "--short", rev], capture_output=True,
                                          text=True).stdout.strip() for rev in ("HEAD", "HEAD^{tree}"))
    spec = suite_spec(args.spec, os.nice(0))
    if spec != args.spec:
        print(f"mutants: at niceness 19, without the tests that need room below it: '{spec}'")
    baseline = None  # the baseline runs only when a mutant is to be judged

    def judge(site):
        nonlocal baseline
        baseline = baseline or baseline_timeout(spec, build_ok, suite, logs, f"{tree_hash} {spec}")
        return (*try_site(site, tree, build_ok, suite, spec, baseline, logs), revision)

    results = judge_sample(args, by_folder, ledger, judge)
    killed, scored = print_scores(results)
    survivors = [r for r in results if r[2] == "SURVIVED"]
    if survivors:
        print(f"\n{len(survivors)} survived (a test to add, or an id for {EQUIVALENTS.name} with the reason):")
        for _, site, _, _, diff in survivors:
            print(f"\n{site.id}\n{diff}", end="")
    if baseline:
        build_ok(logs / "restored-build.log")  # leave the copy built as the tree is
    return 0 if killed == scored else 1
