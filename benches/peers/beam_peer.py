#!/usr/bin/env python3
"""The beam peer: the same simply supported beams through `graphostatik check` and numpy.

For every size the script writes a beam scene (supports at 0 and 8 m, n point loads of 100 to
160 kg spread over the span, the reactions, the moment area and the shear diagram asked for:
the beams of `cargo bench --bench check`), then measures in one run, median of several:

- numpy: from the parsed scene, the loads' places and sizes as arrays, the reactions by
  moments, the shear right of every load and the moment at every load by two prefix sums
  (`cumsum`), and the largest moment, in process: the import and the JSON parse are not
  counted, the arrays, the reactions and the sums are;
- graphostatik in process: the time `graphostatik check --verbose` reports for the scene
  (read, validation, the funicular polygon with its closing line, the moment area and the
  shear diagram, every check of every section against its closed form, the table);
- graphostatik end to end: the whole command, process start and exit included;
- the command's peak resident memory (GNU time's `%M`, where /usr/bin/time is installed)
  against the scene's text: the whole process, its code and the heap in huge pages included.

Before timing, numpy's reactions and largest moment are compared with the check's own
(`check --json`: the worst row of "reaction A", "reaction B" and "largest |M|"), the largest
relative difference in the last column.

Run from the repository root after `cargo build --release`:

    python3 benches/peers/beam_peer.py [--sizes 1000,100000,1000000] [--reps 5] [--exe PATH]

Needs numpy (`pip install numpy`). Prints a Markdown table.
"""
import argparse
import json
import os
import statistics
import subprocess
import sys
import tempfile

import numpy as np
from timing import median_ms, timed_check

EXE = os.path.join("target", "release", "graphostatik")
SPAN = 8.0


def beam(n):
    """n point loads on a beam on two supports (as `benches/check.rs` writes them)."""
    loads = [{"x_m": 0.1 + 7.8 * (i + 0.5) / n, "kg": 100 + 10 * (i % 7)} for i in range(n)]
    return {
        "procedure": "beam",
        "title": "many loads",
        "beam": {"supports_m": [0, SPAN]},
        "point_loads": loads,
        "outputs": ["reactions", "moment_area", "shear_diagram"],
    }


def numpy_beam(scene):
    """Reactions, shear right of every load, moment at every load; returns (A, B, max |M|)."""
    loads = scene["point_loads"]
    x = np.fromiter((p["x_m"] for p in loads), float, len(loads))
    p = np.fromiter((p["kg"] for p in loads), float, len(loads))
    order = np.argsort(x, kind="stable")
    x, p = x[order], p[order]
    b = np.dot(p, x) / SPAN
    a = p.sum() - b
    shear = a - np.cumsum(p)  # right of each load
    left = np.concatenate([[a], shear[:-1]])  # from the last load (or support A) to this one
    moment = np.cumsum(left * np.diff(x, prepend=0.0))
    return a, b, np.max(np.abs(moment))


def peak_mb(path):
    """The command's peak resident memory in MB, through GNU time (an untimed run of its own:
    a child started from Python would count Python's pages from before its exec), or None."""
    gnu_time = "/usr/bin/time"
    if not os.access(gnu_time, os.X_OK):
        return None
    out = subprocess.run([gnu_time, "-f", "%M", EXE, "check", path], capture_output=True, text=True)
    last = out.stderr.strip().splitlines()[-1:]
    return int(last[0]) / 1024.0 if out.returncode == 0 and last and last[0].isdigit() else None


def checked_values(path):
    """The check's own reactions and largest moment (`check --json`), an untimed run."""
    out = subprocess.run([EXE, "check", path, "--json"], capture_output=True, text=True)
    report = json.loads(out.stdout)
    rows = report if isinstance(report, list) else [k["worst"] for k in report["kinds"]]
    value = {}
    for r in rows:
        for key, name in (("A", "reaction A"), ("B", "reaction B"), ("M", "largest |M|")):
            if r["quantity"].startswith(name):
                value[key] = r["constructed"]
    if len(value) != 3:
        sys.exit(f"{path}: the check's table lacks a reaction or the largest moment")
    return value["A"], value["B"], value["M"]


def main():
    global EXE
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--sizes", default="1000,100000,1000000", help="point loads, comma-separated")
    ap.add_argument("--reps", type=int, default=5)
    ap.add_argument("--exe", default=EXE, help="the graphostatik binary (another build to compare)")
    args = ap.parse_args()
    EXE = args.exe
    print("| loads | scene text | numpy, in process | graphostatik check, in process | check / numpy | check, end to end | peak memory | peak / text | check against numpy |")
    print("|---:|---:|---:|---:|---:|---:|---:|---:|---:|")
    with tempfile.TemporaryDirectory() as tmp:
        for n in (int(x) for x in args.sizes.split(",")):
            scene = beam(n)
            path = os.path.join(tmp, f"beam_{n}.json")
            with open(path, "w") as f:
                json.dump(scene, f)
            text_mb = os.path.getsize(path) / 2**20
            ours, theirs = checked_values(path), numpy_beam(scene)
            off = max(abs(o - t) / abs(t) for o, t in zip(ours, theirs))
            t_np = median_ms(lambda: numpy_beam(scene), args.reps)
            runs = [timed_check(EXE, path) for _ in range(args.reps)]
            t_e2e = statistics.median(r[0] for r in runs)
            t_in = statistics.median(r[1] for r in runs)
            peak = peak_mb(path)
            memory = f"{peak:.1f} MB | {peak / text_mb:.0f}x" if peak else "- | -"
            print(
                f"| {n:,} | {text_mb:.1f} MB | {t_np:.2f} ms | {t_in:.2f} ms | {t_in / t_np:.1f}x "
                f"| {t_e2e:.2f} ms | {memory} | {off:.0e} |",
                flush=True,
            )


if __name__ == "__main__":
    main()
