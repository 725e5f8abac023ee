# Sourced first by the bench/ and scripts/ commands: -h or --help
# prints the script's header comment (its usage) and exits 0, before
# anything is built or run. POSIX sh, as some of the scripts are.

# The sourcing script's header comment, without the comment marks.
script_usage() {
  sed -n '2,/^[^#]/{/^#/s/^# \{0,1\}//p;}' "$0"
}

case "${1:-}" in
  -h | --help)
    script_usage
    exit 0
    ;;
esac
