# What a failed check and a missing tool mean to the shell tests (tests/scale_out, tests/install): source it.

fail() { echo "FAIL: $*" >&2; exit 1; }

# A missing requirement: skipped (exit 77) on a developer's machine, but a
# failure in CI (CI=true), where scripts/setup has installed everything.
missing() {
  if [ "${CI:-}" = true ]; then echo "FAIL: $* (CI=true: this test must run, not skip)" >&2; exit 1; fi
  echo "SKIP: $*"
  exit 77
}
