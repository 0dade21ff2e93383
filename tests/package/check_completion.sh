#!/usr/bin/env bash
# The generated bash completion against the CLI itself: every subcommand `ceilplan --help` lists
# completes from its first letters, and after `ceilplan COMMAND -` every flag its --help lists is
# offered, with --config; a flag that takes one of a list completes its values.
#   check_completion.sh CEILPLAN COMPLETION_FILE
set -euo pipefail
ceilplan=$1
# shellcheck source=/dev/null
source "$2"
fail() { echo "check_completion: $*" >&2; exit 1; }
complete_words() {
  COMP_WORDS=(ceilplan "$@")
  COMP_CWORD=$#
  _ceilplan
  echo " ${COMPREPLY[*]} "
}

commands=$("$ceilplan" --help | sed -n '/^Subcommands:/,$p' | sed -nE 's/^  ([a-z][-a-z]*) .*/\1/p')
[[ $(wc -w <<<"$commands") -ge 10 ]] || fail "too few subcommands in ceilplan --help: $commands"
for command in $commands; do
  [[ $(complete_words "${command:0:3}") == *" $command "* ]] || fail "'ceilplan ${command:0:3}' does not offer $command"
  offered=$(complete_words "$command" -)
  for flag in $("$ceilplan" "$command" --help | grep -oE '^ +-[-a-z0-9]+(,-[-a-z0-9]+)*' | tr ',' '\n') --config; do
    [[ $offered == *" $flag "* ]] || fail "'ceilplan $command -' does not offer $flag"
  done
done
[[ $(complete_words tour --mode '') == " ceiling free both " ]] || fail "tour --mode: $(complete_words tour --mode '')"
[[ $(complete_words help t) == " tour " ]] || fail "help t: $(complete_words help t)"
echo "completion OK: $(wc -w <<<"$commands") subcommands"
