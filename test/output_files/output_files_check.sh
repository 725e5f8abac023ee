#!/usr/bin/env bash
# firmware-sim --profile-out/--folded-out and accuracy-report --out write
# through posix/output_file.hpp (make_report.py through safe_output.py): a FIFO or a symbolic link as the target is
# refused (status non-zero, one line, the target untouched); a regular file
# is replaced whole; no temporary file is left behind.
#   output_files_check.sh FIRMWARE_SIM TEST_ELF ACCURACY_REPORT SCENE
set -u
sim=$1 elf=$2 acc=$3 scene=$4
root=$(cd "$(dirname "$0")/../.." && pwd)
work=$(mktemp -d "${TMPDIR:-/tmp}/minrt-output-files.XXXXXX")
trap 'rm -rf "$work"' EXIT
fail=0
check() {  # check WHAT CONDITION...
  local what=$1
  shift
  if "$@"; then echo "ok: $what"; else echo "FAILED: $what"; fail=1; fi
}
no_temporaries() { ! ls "$work" | grep -q '\.partial\.'; }

# firmware-sim: a profile onto a FIFO, then onto a symbolic link.
mkfifo "$work/fifo"
"$sim" --profile-out "$work/fifo" "$elf" -- recur 15 >/dev/null 2>"$work/err"
status=$?
check "firmware-sim --profile-out FIFO: status $status" test "$status" -ne 0
check "firmware-sim --profile-out FIFO: says why" grep -q "refusing to replace $work/fifo: it is a FIFO" "$work/err"
check "firmware-sim --profile-out FIFO: still a FIFO" test -p "$work/fifo"
echo kept >"$work/target"
ln -s target "$work/link"
"$sim" --folded-out "$work/link" "$elf" -- recur 15 >/dev/null 2>"$work/err"
status=$?
check "firmware-sim --folded-out link: status $status" test "$status" -ne 0
check "firmware-sim --folded-out link: says why" grep -q "it is a symbolic link" "$work/err"
check "firmware-sim --folded-out link: link and its target untouched" \
  test -L "$work/link" -a "$(cat "$work/target")" = kept

# A regular file is replaced by the whole profile.
echo old >"$work/profile.cg"
"$sim" --profile-out "$work/profile.cg" --folded-out "$work/folded.txt" "$elf" -- recur 15 >/dev/null 2>"$work/err"
status=$?
check "firmware-sim profiles onto a regular file: status $status" test "$status" -eq 0
check "firmware-sim --profile-out: a callgrind file" grep -q '^events:' "$work/profile.cg"
check "firmware-sim --folded-out: recur's stacks" grep -q 'recur' "$work/folded.txt"
check "firmware-sim: no temporary file left" no_temporaries

# accuracy-report: an image whose name is taken by a FIFO is refused, the
# others are written whole.
stem=$(basename "$scene" .sld)
mkfifo "$work/$stem.double-libm.ppm"
"$acc" --size 8x8 --out "$work" "$scene" >/dev/null 2>"$work/err"
status=$?
check "accuracy-report onto a FIFO: status $status" test "$status" -ne 0
check "accuracy-report onto a FIFO: says why" grep -q "refusing to replace .*double-libm.ppm: it is a FIFO" "$work/err"
check "accuracy-report onto a FIFO: still a FIFO" test -p "$work/$stem.double-libm.ppm"
check "accuracy-report: the other images are complete P6 files" \
  test "$(head -c 2 "$work/$stem.float-portable.ppm")" = P6 -a "$(stat -c %s "$work/$stem.float-portable.ppm")" -eq $((11 + 8 * 8 * 3))
check "accuracy-report: no temporary file left" no_temporaries
# bench/accuracy/make_report.py writes its files (docs/accuracy.md, the
# figures, its run cache) through bench/accuracy/safe_output.py, the same rules.
PYTHONDONTWRITEBYTECODE=1 PYTHONPATH="$root/bench/accuracy" python3 - "$work" <<'PY' >"$work/py.out" 2>&1
import os, sys
from safe_output import OutputError, write_atomically
work = sys.argv[1]
fifo = os.path.join(work, "report.fifo")
os.mkfifo(fifo)
try:
    write_atomically(fifo, "x")
    sys.exit("FIFO not refused")
except OutputError as e:
    assert "it is a FIFO" in str(e), e
target = os.path.join(work, "accuracy.md")
with open(target, "w") as f:
    f.write("old")
write_atomically(target, "new report\n")
assert open(target).read() == "new report\n"
print("python ok")
PY
check "safe_output.py: FIFO refused, regular file replaced whole" grep -qx "python ok" "$work/py.out"
check "safe_output.py: no temporary file left" no_temporaries
exit $fail
