#!/usr/bin/zsh -f
# SPDX-License-Identifier: MIT
# zsh_complete.zsh FPATH_DIR WORDS...: prints, one a line, the words zsh's completion
# system offers at the end of the line WORDS (a trailing '' completes a new word), with the
# completion functions of FPATH_DIR first in $fpath. Runs an interactive zsh in a pseudo
# terminal (zsh/zpty), records every compadd and ends after the first completion.
zmodload zsh/zpty || exit 1
dir=$1
shift
zpty z zsh -f -i
zpty -w z "PROMPT=''; fpath=(${(q)dir} \$fpath); autoload -Uz compinit; compinit -u -D"
zpty -w z 'compadd() { local -a hits; builtin compadd -O hits "$@"; local h; for h in $hits; do print -r -- "H""IT:$h"; done; builtin compadd "$@"; }'
zpty -w z 'comppostfuncs=(finish); finish() { print -r -- "DO""NE:"; exit; }'
zpty -w z "bindkey '^I' complete-word"
zpty -w z "${(j: :)${(q)@}}"$'\t'
while zpty -r z line; do
  [[ $line == *DONE:* ]] && break
  [[ $line == *HIT:* ]] && print -r -- ${${line##*HIT:}%%$'\r'*}
done
