# Installs the build BUILD into a fresh prefix, removed at exit: source it with BUILD set; PREFIX is the prefix.
source "$(dirname "${BASH_SOURCE[0]}")/../test_requirements.sh"
command -v cmake >/dev/null || missing "cmake is not installed: install the Debian package cmake (scripts/setup does)"
PREFIX=$(mktemp -d)
trap 'rm -rf "$PREFIX"' EXIT
cmake --install "$BUILD" --prefix "$PREFIX" >"$PREFIX/.install.log" 2>&1 ||
  fail "cmake --install $BUILD --prefix $PREFIX failed: $(tail -3 "$PREFIX/.install.log")"
