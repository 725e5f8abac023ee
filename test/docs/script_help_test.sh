#!/usr/bin/env bash
# Every command of bench/ and scripts/ answers -h and --help with its usage (the header
# comment, which names the command as it is typed) and exit status 0, at
# once: nothing built, nothing run. A script that ignored the flag would
# start a long run and hit the timeout, or print something else.
set -uo pipefail
root=${1:?usage: script_help_test.sh REPO_ROOT}
cd "$root" || exit 2
fail=0 n=0
for script in bench/*/*.sh scripts/*.sh; do
  [[ -x $script ]] || continue  # sourced helpers: bench/firmware/common.sh, scripts/help.sh
  for flag in -h --help; do
    n=$((n + 1))
    out=$(timeout 20 "$script" "$flag" 2>&1)
    status=$?
    if ((status != 0)); then
      echo "FAIL $script $flag: exit $status: $(head -1 <<<"$out")"; fail=1
    elif ! grep -qF "$script" <<<"$out"; then
      echo "FAIL $script $flag: the usage does not name $script: $(head -1 <<<"$out")"; fail=1
    fi
  done
done
((n > 0)) || { echo "FAIL: no scripts found under $root/bench or $root/scripts"; exit 1; }
echo "$n help requests checked"
exit $fail
