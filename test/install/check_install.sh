#!/bin/sh
# Installs BUILD into PREFIX (emptied first) and checks the tree: the user
# tools, the firmware images, a man page per tool that `man -l` renders, and
# an installed host-send that runs the installed firmware-sim and firmware.
# Usage: check_install.sh BUILD PREFIX SHARED
set -eu
build=$1 prefix=$2 shared=$3
fail() { echo "check_install: $*" >&2; exit 1; }

rm -rf "$prefix"
cmake --install "$build" --prefix "$prefix" >/dev/null || fail "cmake --install failed"

tools="minrt host-send firmware-sim image-compare"
for t in $tools; do
  [ -x "$prefix/bin/$t" ] || fail "missing bin/$t"
done
for f in minrt-rv32imf.elf minrt-rv32imf-program.bin; do
  [ -s "$prefix/share/minrt/firmware/$f" ] || fail "missing share/minrt/firmware/$f"
done
for t in $tools; do
  page=$prefix/share/man/man1/$t.1
  [ -s "$page" ] || fail "missing share/man/man1/$t.1"
  text=$(MANWIDTH=80 man -l "$page" 2>&1) || fail "man -l $page failed: $text"
  # The page has the sections help2man writes and the tool's own options.
  printf '%s\n' "$text" | grep -q '^NAME' || fail "$t.1: no NAME section"
  printf '%s\n' "$text" | grep -q '^SYNOPSIS' || fail "$t.1: no SYNOPSIS"
  printf '%s\n' "$text" | grep -q '^DESCRIPTION' || fail "$t.1: no DESCRIPTION"
  printf '%s\n' "$text" | grep -q -- '--help' || fail "$t.1: no --help option"
  printf '%s\n' "$text" | grep -q '^ *'"$t"' ' || fail "$t.1: the tool's name is not in the page"
done

# An installed host-send runs the firmware-sim beside it and the firmware in
# share/minrt/firmware: a wrapper in place of the installed simulator leaves
# a mark when it is started.
scene=$shared/scenes/ball.sld
if [ -f "$scene" ]; then
  mark=$prefix/simulator-started
  mv "$prefix/bin/firmware-sim" "$prefix/bin/firmware-sim.real"
  cat > "$prefix/bin/firmware-sim" <<WRAP
#!/bin/sh
printf '%s\n' "\$*" > "$mark"
exec "$prefix/bin/firmware-sim.real" "\$@"
WRAP
  chmod +x "$prefix/bin/firmware-sim"
  out=$prefix/ball.ppm
  env -u MINRT_FIRMWARE_SIM -u MINRT_FIRMWARE_ELF \
    "$prefix/bin/host-send" --sim --size 16x16 -q "$scene" -o "$out" || fail "installed host-send --sim failed"
  [ -s "$out" ] || fail "installed host-send wrote no image"
  [ -f "$mark" ] || fail "installed host-send did not run the installed firmware-sim"
  grep -q "/bin/../share/minrt/firmware/minrt-rv32imf.elf" "$mark" ||
    fail "installed host-send did not run the installed firmware: $(cat "$mark")"
  mv "$prefix/bin/firmware-sim.real" "$prefix/bin/firmware-sim"
  rm -f "$mark" "$out"
else
  echo "check_install: $scene missing: installed host-send not run" >&2
fi
echo "check_install: $prefix: $(find "$prefix" -type f | wc -l) files, man pages render"
