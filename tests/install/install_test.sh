# `cmake --install BUILD --prefix P`: the binary runs from P and says its version, each command has a man page that
# man reads without a warning and that lists the command's options, the completions, docs and examples are there.
#   install_test.sh BUILD VERSION
set -uo pipefail
BUILD=$1 version=$2
source "$(dirname "$0")/installed_prefix.sh"
command -v man >/dev/null || missing "man is not installed: install the Debian packages man-db and groff-base (scripts/setup does)"

vibra=$PREFIX/bin/vibra
[ -x "$vibra" ] || fail "cmake --install put no executable at bin/vibra"
said=$("$vibra" --version) || fail "the installed vibra --version failed"
[[ $said =~ ^vibra\ ${version//./\\.}\ \(git\ [0-9A-Za-z._+-]+\)$ ]] || fail "vibra --version said '$said'"

# The commands as --help lists them; each but help has its page, and the page has the options of its --help.
commands=$("$vibra" --help | sed -n '/^Subcommands:/,/^$/p' | awk 'NR > 1 && NF { print $1 }' | grep -vx help)
[ "$(wc -w <<<"$commands")" -ge 7 ] || fail "vibra --help lists only: $commands"
man1=$PREFIX/share/man/man1
for page in vibra $(printf 'vibra-%s ' $commands); do
  [ -s "$man1/$page.1" ] || fail "no man page share/man/man1/$page.1"
  warnings=$(MANWIDTH=80 man --warnings -l "$man1/$page.1" 2>&1 >/dev/null)
  [ -z "$warnings" ] || fail "man warns on $page.1: $warnings"
done
for command in $commands; do
  text=$(MANWIDTH=200 man -l "$man1/vibra-$command.1" 2>/dev/null)
  for option in $("$vibra" "$command" --help | grep -oE '^  (-[a-zA-Z],)?--[A-Za-z][A-Za-z-]*' | grep -oE -- '--[A-Za-z-]+'); do
    grep -qe "$option" <<<"$text" || fail "man vibra-$command does not show $option, which vibra $command --help lists"
  done
done
[ "$(MANPATH=$PREFIX/share/man man -w vibra-render)" = "$man1/vibra-render.1" ] || fail "man -w does not find vibra-render under the prefix"
MANWIDTH=80 man -l "$man1/vibra.1" | grep -q "vibra help COMMAND" || fail "man vibra shows no synopsis of vibra help"

for file in share/bash-completion/completions/vibra share/zsh/vendor-completions/_vibra \
            share/fish/vendor_completions.d/vibra.fish share/doc/vibra/README.md share/doc/vibra/docs/install.md \
            share/doc/vibra/examples/damped_pendulum_lecture.toml share/doc/vibra/media/lecture_page.png; do
  [ -s "$PREFIX/$file" ] || fail "cmake --install put no $file"
done
echo "ok: vibra, $(ls "$man1" | wc -l) man pages, completions, docs and examples installed under a fresh prefix"
