#!/usr/bin/env python3
"""Lab 08: how long a key waits during a GL hemicube run (issue 19 item 7; docs/bench/radiosity.md
"Input during a GL run"). Not a CI test: timings on a shared machine.

For each round and each lab08-radiosity given (alternated, e.g. a build before and after a
change), opens a real window (--method gl, WB_LOG_KEYS=1), waits for its first run to end, then
presses `]` and `[` in turn (each remeshes, coarser and back to the default, and restarts the GL
solve) PRESSES times at random moments 0.15-0.7 s apart, so that most presses meet a GL run in
progress (the default run takes ~1 s; "runs stopped" counts those that did), and times each
press from just before `xdotool key` to the shell's "lab key" line on stderr. The first press,
with the lab idle after its first run, is the floor of what the script can see (xdotool's
start-up, the poll of the log). Prints the median, 90th percentile and maximum.
Needs an X display (DISPLAY, e.g. Xvfb 1280x800) with nothing else on it.
    lab08_key_latency.py ROUNDS PRESSES WINDOW_EXE [WINDOW_EXE...]
"""
import os
import random
import statistics
import subprocess
import sys
import tempfile
import time


def wait_for(path, text, timeout, start=0):
    end = time.monotonic() + timeout
    while time.monotonic() < end:
        with open(path, errors="replace") as f:
            f.seek(start)
            if text in f.read():
                return True
        time.sleep(0.001)
    return False


def count(path, text):
    with open(path, errors="replace") as f:
        return f.read().count(text)


def press_and_time(err, key):
    before = count(err, "lab key ")
    t0 = time.monotonic()
    subprocess.run(["xdotool", "key", key], check=True)
    end = t0 + 5
    while time.monotonic() < end:
        if count(err, "lab key ") > before:
            return time.monotonic() - t0
        time.sleep(0.001)
    return float("nan")


def window(exe, presses, rng):
    tmp = tempfile.mkdtemp()
    out, err = os.path.join(tmp, "out"), os.path.join(tmp, "err")
    env = dict(os.environ, WB_LOG_KEYS="1")
    with open(out, "w") as o, open(err, "w") as e:
        p = subprocess.Popen([exe, "--method", "gl"], stdout=o, stderr=e, env=env)
    try:
        if not wait_for(out, " run ", 60):
            raise SystemExit(f"{exe}: no end of the first run")
        wid = subprocess.run(["xdotool", "search", "--onlyvisible", "--pid", str(p.pid)],
                             capture_output=True, text=True).stdout.split()
        if wid:
            subprocess.run(["xdotool", "windowmove", wid[0], "0", "0"])
        subprocess.run(["xdotool", "mousemove", "400", "300"]) # focus follows the pointer
        time.sleep(0.3)
        idle = press_and_time(err, "bracketright") # the lab idle: the floor
        busy = []
        for i in range(presses):
            time.sleep(rng.uniform(0.15, 0.7))
            busy.append(press_and_time(err, "bracketleft" if i % 2 == 0 else "bracketright"))
        runs = [l for l in open(out) if "GL run" in l]
        return idle, busy, runs
    finally:
        p.kill()
        p.wait()


def main():
    rounds, presses, exes = int(sys.argv[1]), int(sys.argv[2]), sys.argv[3:]
    rng = random.Random(1)
    for r in range(rounds):
        for exe in exes:
            load = open("/proc/loadavg").read().split()[:3]
            idle, busy, runs = window(exe, presses, rng)
            busy.sort()
            print(f"round {r + 1} load {' '.join(load)} {exe}: idle {idle * 1000:.0f} ms; "
                  f"during a GL run median {statistics.median(busy) * 1000:.0f} ms, "
                  f"p90 {busy[int(0.9 * (len(busy) - 1))] * 1000:.0f} ms, "
                  f"max {busy[-1] * 1000:.0f} ms ({len(busy)} presses, "
                  f"{sum(1 for l in runs if 'stopped' in l)} runs stopped)", flush=True)


if __name__ == "__main__":
    main()
