# bash completion for apprentice. Installed to
# share/bash-completion/completions/apprentice, where Debian's
# bash-completion loads it the first time you press Tab after "apprentice";
# or source it from ~/.bashrc.
#
# Subcommands and flags are read from apprentice's own --help, so they are
# always those of the installed program; values are completed where they
# have a known form (scenario files, knowledge stores, conditions).

_apprentice_help_words() {
  # $1: the program; $2: the subcommand or empty. Prints the flags, or with
  # no subcommand the subcommands too.
  local help
  help=$("$1" ${2:+"$2"} --help 2>/dev/null) || return
  printf '%s\n' "$help" | grep -oE '^ +(-[A-Za-z],)?--[A-Za-z0-9][A-Za-z0-9-]*' | sed -E 's/^ +//; s/^-[A-Za-z],//'
  if [[ -z $2 ]]; then
    printf '%s\n' "$help" | sed -n '/^Subcommands:/,$p' | grep -oE '^  [a-z][a-z0-9-]*' | sed 's/^ *//'
  fi
}

_apprentice() {
  local cur=${COMP_WORDS[COMP_CWORD]} prev=${COMP_WORDS[COMP_CWORD-1]}
  local program=${COMP_WORDS[0]} subcommand="" i
  for ((i = 1; i < COMP_CWORD; i++)); do
    if [[ ${COMP_WORDS[i]} != -* ]]; then
      case ${COMP_WORDS[i-1]} in
        --scenario|--knowledge|--goal|--out|--transcript|--knowledge-out|--knowledge-in|--conditions|--condition|\
        --generalization|--llm|--llm-model|--llm-api-key|--llm-timeout-ms|--llm-connect-timeout-ms|--llm-seed|\
        --depth|--max-nodes|--task|--domain|--household|--to|--from|\
        --object|--subtask|--corpus|--plot|--scenarios|--settings|--only|--host|--port|--token|--log-dir|--max-sessions|\
        --idle-seconds) continue ;;
      esac
      subcommand=${COMP_WORDS[i]}
      break
    fi
  done
  local conditions="instruction inst+search4 search4+llm inst+llm inst+search2+llm inst+search4+llm"
  case $prev in
    --scenarios)
      COMPREPLY=($(compgen -f -X '!*.yml' -- "$cur") $(compgen -f -X '!*.yaml' -- "$cur") $(compgen -d -- "$cur")); compopt -o filenames 2>/dev/null; return ;;
    --settings)
      # The benchmark's settings, a comma-separated list: complete the last name.
      local settings="a-alone a-alone+llm a-teacher a-teacher+llm b-alone b-alone+llm b-teacher" done_settings="" last_setting=$cur
      if [[ $cur == *,* ]]; then done_settings=${cur%,*},; last_setting=${cur##*,}; fi
      COMPREPLY=($(compgen -P "$done_settings" -W "$settings" -- "$last_setting")); compopt -o nospace 2>/dev/null; return ;;
    --scenario)
      COMPREPLY=($(compgen -f -X '!*.yaml' -- "$cur") $(compgen -f -X '!*.yml' -- "$cur") $(compgen -d -- "$cur")); compopt -o filenames 2>/dev/null; return ;;
    --knowledge|--knowledge-in)
      COMPREPLY=($(compgen -f -X '!*.sqlite' -- "$cur") $(compgen -d -- "$cur")); compopt -o filenames 2>/dev/null; return ;;
    --domain)
      COMPREPLY=($(compgen -f -X '!*.pddl' -- "$cur") $(compgen -d -- "$cur")); compopt -o filenames 2>/dev/null; return ;;
    --corpus)
      COMPREPLY=($(compgen -f -X '!*.jsonl' -- "$cur") $(compgen -d -- "$cur")); compopt -o filenames 2>/dev/null; return ;;
    --plot)
      COMPREPLY=($(compgen -f -X '!*.svg' -- "$cur") $(compgen -f -X '!*.png' -- "$cur") $(compgen -d -- "$cur")); compopt -o filenames 2>/dev/null; return ;;
    --out|--transcript|--knowledge-out|--log-dir)
      COMPREPLY=($(compgen -d -- "$cur")); compopt -o filenames 2>/dev/null; return ;;
    --generalization)
      COMPREPLY=($(compgen -W "full paper" -- "$cur")); return ;;
    --condition)
      COMPREPLY=($(compgen -W "$conditions" -- "$cur")); return ;;
    --conditions)
      # A comma-separated list: complete the last name.
      local done_part="" last=$cur
      if [[ $cur == *,* ]]; then done_part=${cur%,*},; last=${cur##*,}; fi
      COMPREPLY=($(compgen -P "$done_part" -W "$conditions" -- "$last")); compopt -o nospace 2>/dev/null; return ;;
    --llm)
      # The schemes of src/llm/factory.cc's list of backends.
      COMPREPLY=($(compgen -W "openai:http:// openai-chat:http:// llama:http:// replay: record: corpus:" -- "$cur")); compopt -o nospace 2>/dev/null
      return ;;
    --goal|--household|--llm-model|--llm-api-key|--llm-timeout-ms|--llm-connect-timeout-ms|--llm-seed|--depth|--max-nodes|--task|--object|--subtask|--host|--port|--token|--max-sessions|--idle-seconds)
      return ;;
  esac
  local words
  words=$(_apprentice_help_words "$program" "$subcommand")
  if [[ -z $subcommand && $cur != -* ]]; then
    words=$(printf '%s\n' "$words" | grep -v '^-')
  elif [[ $cur != -* && -n $subcommand ]]; then
    return
  fi
  COMPREPLY=($(compgen -W "$words" -- "$cur"))
}

complete -F _apprentice apprentice
