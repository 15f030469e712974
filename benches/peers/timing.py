"""What the peer scripts time alike: a function's median in process, and one
`graphostatik check --verbose` with the time it reports for itself."""
import re
import statistics
import subprocess
import sys
import time


def median_ms(f, reps):
    """The median wall time of `reps` calls of `f`, in ms."""
    times = []
    for _ in range(reps):
        t = time.perf_counter()
        f()
        times.append((time.perf_counter() - t) * 1e3)
    return statistics.median(times)


def timed_check(exe, path):
    """One `check --verbose` of `path`: (wall ms end to end, ms in process as it reports)."""
    t = time.perf_counter()
    out = subprocess.run([exe, "check", path, "--verbose"], capture_output=True, text=True)
    wall = (time.perf_counter() - t) * 1e3
    if out.returncode != 0:
        sys.exit(f"graphostatik check {path} failed ({out.returncode}): {out.stderr.strip()[:300]}")
    m = re.search(r"([0-9.]+) ms", out.stderr)
    if not m:
        sys.exit(f"no time in the verbose line: {out.stderr.strip()[:300]}")
    return wall, float(m.group(1))
