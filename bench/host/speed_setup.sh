# Sourced by the host speed benchmarks (bench/host/*_speed.sh) after
# scripts/help.sh; brings in scripts/common.sh and gives them
#
#   speed_setup [ROW...] -- "$@"
#
# which reads --runs N (the script's default stays), --shared DIR, --minrt
# PATH and the script's own option rows (script_options), checks that minrt
# is built, makes the scratch folder $work and prints the CPU line. Sets
# root, shared (default ../shared) and minrt (default build/release/host/minrt).
. "$(dirname "$0")/../../scripts/common.sh"
speed_setup() {
  root=$(cd "$(dirname "$0")/../.." && pwd)
  shared=$root/../shared
  minrt=$root/build/release/host/minrt
  script_options "--runs runs" "--shared shared" "--minrt minrt" "$@"
  script_needs_built "$minrt"
  script_scratch
  echo "cpu: $(sed -n 's/^model name[[:space:]]*: //p' /proc/cpuinfo | head -1), $(nproc) cores," \
       "load $(cut -d' ' -f1 /proc/loadavg)"
}
