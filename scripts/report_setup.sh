# Sourced by the format reports (scripts/FORMAT_report.sh) after help.sh and
# common.sh, with $report set to the format's folder name (cs418, eastray)
# and $what to what ../shared holds of it ("CS418 tests"): reads their
# options (--shared DIR, --out DIR or --write-docs for docs/$report/),
# checks the build and the scenes, and sets root, shared, out, bin (minrt's
# and image-compare's folder), dir (the format's scenes) and a scratch $work.
root=$(cd "$(dirname "$0")/.." && pwd)
shared=$root/../shared
out=$root/build/reports/$report
script_options "--shared shared" "--out out" "--write-docs out=$root/docs/$report" -- "$@"
bin=$root/build/release/host
script_needs_built "$bin/minrt" "$bin/image-compare"
dir=$shared/formats/$report
[ -d "$dir" ] || { echo "${0##*/}: error: no $what in $dir" >&2; exit 1; }
mkdir -p "$out"
script_scratch
