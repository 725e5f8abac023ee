# Sourced by the bench/ and scripts/ commands right after help.sh: what they
# share past --help. POSIX sh.

# Their options, from one table, so that each script lists an option once:
#
#   script_options "--runs runs" "--large large=1" -- "$@"
#
# A row is an option and the variable it sets: to the word after it, or
# with "=VALUE" to VALUE (a flag). An argument no row names, or an option
# without its value, is a one-line error naming the script, status 2.
script_options() {
  _so_rows=
  while [ $# -gt 0 ] && [ "$1" != -- ]; do
    _so_rows="$_so_rows$1
"
    shift
  done
  [ $# -gt 0 ] && shift
  while [ $# -gt 0 ]; do
    _so_set=$(printf '%s' "$_so_rows" | while read -r _so_opt _so_var; do
      if [ "$_so_opt" = "$1" ]; then echo "$_so_var"; break; fi
    done)
    case $_so_set in
      "") script_usage_error "unknown argument '$1'" ;;
      *=*) eval "${_so_set%%=*}=\${_so_set#*=}"; shift ;;
      *)
        [ $# -ge 2 ] || script_usage_error "$1 needs a value"
        eval "$_so_set=\$2"
        shift 2
        ;;
    esac
  done
}

# NAME: error: MESSAGE (see --help), status 2.
script_usage_error() {
  echo "${0##*/}: error: $1 (see --help)" >&2
  exit 2
}

# The programs a script runs, each an executable of the build; else a
# one-line error naming it, status 1.
script_needs_built() {
  for _snb in "$@"; do
    [ -x "$_snb" ] || { echo "${0##*/}: error: $_snb not built (run scripts/test.sh first)" >&2; exit 1; }
  done
}

# A scratch folder in $work, removed when the script exits.
script_scratch() {
  work=$(mktemp -d)
  trap 'rm -rf "$work"' EXIT
}
