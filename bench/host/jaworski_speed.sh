#!/usr/bin/env bash
# Speed of minrt against Michał Jaworski's original program (JaworWr/Ray-tracer,
# built by hand outside this repository: pass its binary) on its speed scene:
# 640x480, 20 spheres, a mirror floor, 2 lights, ray depth 4
# (bench/host/make_jaworski_scene.py).
#   bench/host/jaworski_speed.sh [--runs N] [--minrt BINARY] [--fifo|--nice] ORIGINAL_BINARY [ORIGINAL RTS OPTIONS...]
# e.g. bench/host/jaworski_speed.sh /work/ext/jaworski/ray-tracer +RTS -N -RTS
# Checks first that both write the same BMP, byte for byte; then runs minrt on
# one thread, minrt on every core and the original in turn, N times each,
# and prints the medians of the wall and CPU times (user + system of the
# process, to the microsecond), the ratios to the original and what every
# core gives over one thread. --minrt: the minrt to measure (default
# build/release/host/minrt). The load average is printed before and after
# the runs, and the CPU time that other processes took while minrt ran, as
# a share of one core: the cores' gain is a wall-time figure and means
# something only when that share is near 0 (an idle machine); a process
# that keeps a core half busy takes a quarter of the two-thread run's
# cores and little of the one-thread run's. --fifo runs minrt (not the
# original) at real-time priority (SCHED_FIFO 10, which needs root or
# CAP_SYS_NICE), ahead of every ordinary process: the figures of an idle
# machine on a busy one, as far as the other processes' use of the caches
# and of the host allows. --nice keeps minrt at the ordinary policy
# (SCHED_OTHER, with the kernel's ordinary placement of its threads) in a
# session of its own whose scheduling group (/proc/self/autogroup) is at
# nice -20 (root or CAP_SYS_NICE), ahead of the other sessions' processes;
# the original runs in another session at nice 0.
. "$(dirname "$0")/../../scripts/help.sh"
set -euo pipefail
root=$(cd "$(dirname "$0")/../.." && pwd)
runs=7
minrt=$root/build/release/host/minrt
mode=ordinary
usage() { echo "usage: $0 [--runs N] [--minrt BINARY] [--fifo|--nice] ORIGINAL_BINARY [ORIGINAL OPTIONS...]" >&2; exit 2; }
while (($#)); do
  case $1 in
    --runs) [[ $# -ge 2 ]] || usage; runs=$2; shift 2 ;;
    --fifo) mode=fifo; shift ;;
    --nice) mode=nice; shift ;;
    --minrt) [[ $# -ge 2 ]] || usage; minrt=$2; shift 2 ;;
    *) break ;;
  esac
done
(($# >= 1)) || usage
original=$1
shift
original_opts=("$@")
[[ -x $minrt ]] || { echo "not built: $minrt (scripts/setup.sh builds it)" >&2; exit 1; }
[[ -x $original ]] || { echo "not an executable: $original" >&2; exit 1; }

work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
python3 "$root/bench/host/make_jaworski_scene.py" >"$work/scene.txt"

# Same bytes first (the original prints its errors on stdout and exits 0,
# so a missing file is the sign of trouble).
"$original" "${original_opts[@]}" -o "$work/original.bmp" "$work/scene.txt" >"$work/original.log"
[[ -s $work/original.bmp ]] || { echo "the original wrote no image:" >&2; cat "$work/original.log" >&2; exit 1; }
"$minrt" -q --threads 1 -o "$work/minrt.bmp" "$work/scene.txt"
if ! cmp -s "$work/original.bmp" "$work/minrt.bmp"; then
  echo "the BMPs differ: $(cmp "$work/original.bmp" "$work/minrt.bmp" | head -1)" >&2
  exit 1
fi
echo "same BMP: sha256 $(sha256sum "$work/minrt.bmp" | cut -c1-16)... ($(stat -c %s "$work/minrt.bmp") bytes)"

# The runs, interleaved: each program's wall time from its start to its
# end as the parent sees it, its CPU time from its own rusage.
python3 - "$runs" "$mode" "$minrt" "$work" "$original" "${original_opts[@]}" <<'PY'
import os, resource, statistics, subprocess, sys, time

runs, mode, minrt, work, original = int(sys.argv[1]), sys.argv[2], sys.argv[3], sys.argv[4], sys.argv[5]
original_opts = sys.argv[6:]
scene = os.path.join(work, "scene.txt")
programs = {
    "one": ("minrt, 1 thread", [minrt, "-q", "--threads", "1", "-o", os.path.join(work, "a.bmp"), scene], True),
    "all": (f"minrt, {os.cpu_count()} threads", [minrt, "-q", "-o", os.path.join(work, "b.bmp"), scene], True),
    "theirs": ("original " + " ".join(original_opts), [original] + original_opts + ["-o", os.path.join(work, "c.bmp"), scene], False),
}

def ordinary():
    os.sched_setscheduler(0, os.SCHED_OTHER, os.sched_param(0))

# How the original starts when minrt is given a head start: back at the
# ordinary policy (--fifo) or in a session, and so a group, of its own.
unboosted = {"ordinary": None, "fifo": ordinary, "nice": os.setsid}[mode]

TICK = os.sysconf("SC_CLK_TCK")

def busy_seconds():
    # Every core's time in user, nice, system, irq and softirq (not idle,
    # iowait or steal), in seconds, from /proc/stat's first line.
    user, nice, system, _idle, _iowait, irq, softirq = map(int, open("/proc/stat").readline().split()[1:8])
    return (user + nice + system + irq + softirq) / TICK

def own_cpu():
    u = resource.getrusage(resource.RUSAGE_SELF)
    return u.ru_utime + u.ru_stime

def measure(args, boosted):
    busy, runner = busy_seconds(), own_cpu()
    start = time.perf_counter()
    child = subprocess.Popen(args, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL,
                             preexec_fn=None if boosted else unboosted)
    _, status, usage = os.wait4(child.pid, 0)
    wall = time.perf_counter() - start
    if status != 0:
        sys.exit(f"{args[0]} failed (status {status})")
    cpu = usage.ru_utime + usage.ru_stime
    # What the other processes used meanwhile: every core's busy time less
    # the program's and this runner's (to the clock tick: the sum over the
    # runs is the figure).
    others = busy_seconds() - busy - cpu - (own_cpu() - runner)
    return wall, cpu, others

if mode == "fifo":
    # This runner too, so that it sees minrt's end at once; the original
    # runs at the ordinary priority.
    try:
        os.sched_setscheduler(0, os.SCHED_FIFO, os.sched_param(10))
    except PermissionError as e:
        sys.exit(f"--fifo: cannot run at real-time priority ({e})")
elif mode == "nice":
    # A new session gets a scheduling group of its own: only this runner
    # and the minrt runs are in it, not the caller's session.
    try:
        os.setsid()
        with open("/proc/self/autogroup", "w") as group:
            group.write("-20")
    except OSError as e:
        sys.exit(f"--nice: cannot give this run's session nice -20 ({e})")
load_before = open("/proc/loadavg").read().split()[:3]
wall = {k: [] for k in programs}
cpu = {k: [] for k in programs}
others = {k: 0.0 for k in programs}
for _ in range(runs):
    for name, (_, args, boosted) in programs.items():
        w, c, o = measure(args, boosted)
        wall[name].append(w)
        cpu[name].append(c)
        others[name] += o
load_after = open("/proc/loadavg").read().split()[:3]
model = next((l.split(":", 1)[1].strip() for l in open("/proc/cpuinfo") if l.startswith("model name")), "?")
print(f"cpu: {model}, {os.cpu_count()} cores; load average {' '.join(load_before)} before the runs, "
      f"{' '.join(load_after)} after"
      f"{ {'ordinary': '', 'fifo': '; minrt at SCHED_FIFO', 'nice': '; minrt in a session at nice -20'}[mode]}")
print(f"640x480, 20 spheres, 2 lights, ray depth 4; medians of {runs} interleaved runs (seconds)")
print(f"  {'program':26s} {'wall':>8s} {'cpu':>8s}   wall times (ms)")
med = {k: (statistics.median(wall[k]), statistics.median(cpu[k])) for k in programs}
for name, (label, _, _) in programs.items():
    times = " ".join(f"{w * 1000:.1f}" for w in wall[name])
    print(f"  {label:26s} {med[name][0]:8.4f} {med[name][1]:8.4f}   [{times}]")
(ow, oc), (aw, ac), (tw, tc) = med["one"], med["all"], med["theirs"]
print(f"  ratio, wall: original / minrt 1 thread {tw / ow:.1f}x, / minrt all cores {tw / aw:.1f}x")
print(f"  ratio, cpu:  original / minrt 1 thread {tc / oc:.1f}x")
print(f"  all cores / 1 thread, wall: {ow / aw:.2f}x (all cores use {ac / oc:.2f}x the cpu)")
share = {k: max(0.0, others[k]) / sum(wall[k]) for k in ("one", "all")}
print(f"  other processes' cpu while minrt ran: {share['one']:.2f} of a core (1 thread), "
      f"{share['all']:.2f} ({os.cpu_count()} threads)")
PY
