# The installed completion script of SHELL completes a scene name (and a model's, a scheme's, a command's):
# bash through `complete -p vibra` and the function it names (COMP_LINE and COMP_POINT set as bash sets them),
# zsh through the tables its script defines (its _vibra needs zsh's completion system),
# fish through `complete -C`.
#   completion_test.sh BUILD SHELL
set -uo pipefail
BUILD=$1 shell=$2
command -v "$shell" >/dev/null || missing "$shell is not installed: install the Debian package $shell (scripts/setup does)"
source "$(dirname "$0")/installed_prefix.sh"

# "COMMAND LINE|EXPECTED": what completing the line (the cursor at its end) must offer among its candidates.
cases=("vibra render spring_d|spring_dashpot" "vibra solve elastic|elastic-pendulum"
       "vibra solve undamped --set scheme=euler|euler-cromer-half" "vibra analyze fd|fd-accuracy" "vibra ren|render"
       "vibra help lec|lecture" "vibra render --layout |fbd+plot")

bash_offers() {  # LINE: what the function that `complete -p vibra` names puts in COMPREPLY
  bash --norc --noprofile -c '
    source "$1" || exit 1
    spec=$(complete -p vibra) || exit 1
    [[ $spec =~ ^complete\ -F\ ([_a-z]+)\ vibra$ ]] || { echo "complete -p vibra says: $spec" >&2; exit 1; }
    COMP_LINE=$2 COMP_POINT=${#2}
    "${BASH_REMATCH[1]}"
    printf "%s\n" "${COMPREPLY[@]}"' _ "$PREFIX/share/bash-completion/completions/vibra" "$1"
}

fish_offers() { fish --no-config -c "source '$PREFIX/share/fish/vendor_completions.d/vibra.fish'; complete -C '$1'" | cut -f1; }

zsh_offers() {  # the script's own tables: the words of the kind a command's first argument takes
  zsh -n "$PREFIX/share/zsh/vendor-completions/_vibra" || fail "zsh -n: the zsh completion does not parse"
  zsh -f -c "source <(sed '\$d' '$PREFIX/share/zsh/vendor-completions/_vibra')
    local words=(\${=1}); _vibra_command \"\${words[2]}\"; _vibra_words \$positional; print -l -- \$reply" _ "$1"
}

for case in "${cases[@]}"; do
  line=${case%|*} expected=${case#*|}
  [ "$shell" = zsh ] && case $line in "vibra render spring_d" | "vibra solve elastic") ;; *) continue ;; esac
  offered=$("${shell}_offers" "$line") || fail "$shell completion failed on '$line'"
  # bash completes a KEY=VALUE after its '=', fish and zsh the whole word.
  awk -v want="$expected" '{ sub(/^[a-z_]+=/, "") } $0 == want { found = 1 } END { exit !found }' <<<"$offered" || fail "$shell: completing '$line' offers no $expected, only: $(tr '\n' ' ' <<<"$offered")"
done
echo "ok: the installed $shell completion completes scene, model, scheme, experiment and command names"
