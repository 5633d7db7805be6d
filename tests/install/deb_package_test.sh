# `cpack -G DEB` makes a package that dpkg installs, whose vibra --version and man vibra work from /usr, and that
# dpkg removes leaving none of its files. Needs root and dpkg (CI runs as root); one run at a time per machine.
# Never leaves the package installed, even when a check fails or the run is interrupted, and refuses to start
# when a vibra package, or any file the package holds, is already there: those are not this test's to replace.
#   deb_package_test.sh BUILD VERSION
set -uo pipefail
build=$1 version=$2
source "$(dirname "$0")/../test_requirements.sh"
[ "$(id -u)" = 0 ] || missing "not root: the package test installs into /usr with dpkg (CI runs it as root)"
for tool in dpkg dpkg-deb dpkg-shlibdeps cpack man flock; do
  command -v $tool >/dev/null || missing "$tool is not installed: install dpkg-dev, cmake, man-db and util-linux (scripts/setup does)"
done

exec 9</var/lib/dpkg  # a lock on dpkg's folder: a second run of this test waits
flock -w 600 9 || fail "another run held /var/lib/dpkg for 10 minutes"
case $(dpkg-query -W -f='${db:Status-Abbrev}' vibra 2>/dev/null) in
  "" | "un ") ;;
  *) fail "a package named vibra is on this machine already: not this test's to replace; remove it (dpkg --purge vibra) and run again" ;;
esac

work=$(mktemp -d)
installed=false
cleanup() {
  if $installed && ! dpkg --purge vibra >"$work/purge.log" 2>&1; then
    echo "FAIL: could not remove the package: dpkg --purge vibra: $(tail -2 "$work/purge.log")" >&2
  fi
  rm -rf "$work"
}
trap cleanup EXIT
trap 'exit 130' INT TERM  # through cleanup

cpack -G DEB --config "$build/CPackConfig.cmake" -B "$work" >"$work/cpack.log" 2>&1 ||
  fail "cpack -G DEB failed: $(tail -3 "$work/cpack.log")"
deb=$work/vibra_${version}_$(dpkg --print-architecture).deb
[ -s "$deb" ] || fail "cpack made no $(basename "$deb"): $(ls "$work")"
# dpkg -i would silently replace a file that no package owns: refuse, as none of them is this test's.
dpkg-deb --fsys-tarfile "$deb" | tar -t | grep -v '/$' | sed 's|^\.||' >"$work/contents" || fail "cannot list $deb"
while read -r file; do
  [ ! -e "$file" ] || fail "$file exists and is no package's: the package would replace it; move it away and run again"
done <"$work/contents"
installed=true  # from here on: dpkg -i may stop half-way, and the package must still go
dpkg -i "$deb" >"$work/dpkg.log" 2>&1 || fail "dpkg -i failed: $(tail -3 "$work/dpkg.log")"
[ "$(dpkg-query -W -f='${db:Status-Abbrev}' vibra)" = "ii " ] || fail "dpkg does not list vibra as installed"

said=$(/usr/bin/vibra --version) || fail "/usr/bin/vibra --version failed"
[[ $said =~ ^vibra\ ${version//./\\.}\ \(git\ [0-9A-Za-z._+-]+\)$ ]] || fail "the packaged vibra --version said '$said'"
[ "$(man -w vibra)" = /usr/share/man/man1/vibra.1 ] || fail "man -w vibra finds $(man -w vibra 2>&1), not the package's page"
MANWIDTH=80 man vibra 2>/dev/null | grep -q "vibra help COMMAND" || fail "man vibra does not show the page"
MANWIDTH=80 man vibra-render 2>/dev/null | grep -q -- "--layout" || fail "man vibra-render does not show render's options"
dpkg -L vibra >"$work/files" || fail "dpkg -L vibra failed"
grep -qx /usr/share/bash-completion/completions/vibra "$work/files" || fail "the package has no bash completion"

dpkg -r vibra >"$work/remove.log" 2>&1 || fail "dpkg -r vibra failed: $(tail -3 "$work/remove.log")"
case $(dpkg-query -W -f='${db:Status-Abbrev}' vibra 2>/dev/null) in
  "" | "un ") installed=false ;;
  *) fail "after dpkg -r, dpkg lists vibra as $(dpkg-query -W -f='${db:Status-Abbrev}' vibra)" ;;
esac
while read -r file; do
  [ ! -e "$file" ] || fail "dpkg -r left $file behind"
done <"$work/contents"
echo "ok: $(basename "$deb") installed, ran vibra --version and man vibra, and was removed with all its files"
