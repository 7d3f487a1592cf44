#!/usr/bin/env python3
"""Time a command as a whole process, alone or in pairs with a baseline.

usage: scripts/time-pairs.py [-n RUNS] [--warmup W] [--timeout SECONDS] [--vs 'COMMAND_B'] -- COMMAND [ARG ...]

COMMAND (A) runs RUNS times (default 5) after W runs that are not counted (default 1).
With --vs, the baseline B (one string, split as a shell splits words) runs too, in turn
with A (A B A B ...), and the ratio A/B is taken pair by pair: this machine's speed
drifts by 10-20% from hour to hour, and a ratio of neighbouring runs keeps its meaning
where two separate timings do not. Each figure is printed as min, median and max; quote
the median. Wall seconds come from a monotonic clock around each run; user and system
seconds and the peak resident memory from the operating system's accounting of the
finished child (wait4; the peak reads at least this script's own, about 15 MiB, which the
child had before it started the command). The commands' output is discarded. --timeout bounds the whole
call: the running command is then killed and the finished runs are printed (exit 3).
"""
import argparse
import os
import shlex
import signal
import statistics
import subprocess
import sys
import time


def run(argv, deadline):
    """One run of argv: (wall, user, sys, peak MiB), or None if the deadline passed."""
    start = time.monotonic()
    try:
        child = subprocess.Popen(argv, stdin=subprocess.DEVNULL, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL,
                                 start_new_session=True)
    except OSError as e:
        sys.exit(f"time-pairs.py: cannot start {shlex.join(argv)}: {e.strerror}")
    while True:
        pid, status, usage = os.wait4(child.pid, os.WNOHANG)
        if pid:
            break
        if time.monotonic() > deadline:
            os.killpg(child.pid, signal.SIGKILL)
            os.wait4(child.pid, 0)
            return None
        time.sleep(0.002)
    wall = time.monotonic() - start
    code = os.waitstatus_to_exitcode(status)
    if code != 0:
        print(f"time-pairs.py: {shlex.join(argv)} exited with {code}", file=sys.stderr)
    return wall, usage.ru_utime, usage.ru_stime, usage.ru_maxrss / 1024.0


def spread(values):
    return f"{min(values):12.4f}{statistics.median(values):12.4f}{max(values):12.4f}"


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("-n", type=int, default=5, help="counted runs of each command")
    parser.add_argument("--warmup", type=int, default=1, help="runs of each command before the counted ones")
    parser.add_argument("--timeout", type=float, default=3600, help="a bound on the whole call, seconds")
    parser.add_argument("--vs", help="the baseline command B, one string")
    parser.add_argument("command", nargs=argparse.REMAINDER)
    a = parser.parse_args()
    command = a.command[1:] if a.command[:1] == ["--"] else a.command
    if not command or a.n < 1 or a.warmup < 0:
        parser.error("give a command after --, and -n of at least 1")
    commands = {"A": command}
    if a.vs:
        commands["B"] = shlex.split(a.vs)
    deadline = time.monotonic() + a.timeout
    runs = {name: [] for name in commands}
    finished = True
    for i in range(a.warmup + a.n):
        for name, argv in commands.items():
            r = run(argv, deadline)
            if r is None:
                finished = False
                break
            if i >= a.warmup:
                runs[name].append(r)
        if not finished:
            print("time-pairs.py: the time bound ended the runs", file=sys.stderr)
            break
    print(f"{'':16s}{'min':>12s}{'median':>12s}{'max':>12s}")
    labels = ("wall s", "user s", "sys s", "peak MiB")
    for name, rs in runs.items():
        if not rs:
            continue
        for k, label in enumerate(labels):
            print(f"{name + ' ' + label:16s}{spread([r[k] for r in rs])}")
        print(f"{name + ' cpu s':16s}{spread([r[1] + r[2] for r in rs])}")
    if a.vs:
        pairs = list(zip(runs["A"], runs["B"]))
        if pairs:
            for k, label in ((0, "wall"), (1, "user")):
                print(f"{'A/B ' + label:16s}{spread([x[k] / y[k] if y[k] > 0 else float('inf') for x, y in pairs])}")
            print(f"{'A/B cpu':16s}{spread([(x[1] + x[2]) / max(y[1] + y[2], 1e-9) for x, y in pairs])}")
    return 0 if finished else 3


if __name__ == "__main__":
    sys.exit(main())
