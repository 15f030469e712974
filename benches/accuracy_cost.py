#!/usr/bin/env python3
"""What accuracy costs a user: `check`, `check --reference` and one `drafting` drawing per scene.

For every bundled scene, in one run: `graphostatik check --verbose` (its in-process time, the
median of five), `check --reference` (the double-double replay beside the f64 construction,
median of five) and `drafting --runs 20 --jobs 1` (the whole command, median of three,
divided by its 20 drawings), each against the plain check. Scenes whose check takes under
`--min-ms` are left out of the summary: their time is the process's fixed cost and noise.

Run from the repository root after `cargo build --release`:

    python3 benches/accuracy_cost.py [--min-ms 1.5] [--exe target/release/graphostatik]

Prints a Markdown table.
"""
import argparse
import glob
import os
import re
import statistics
import subprocess
import time


def in_process_ms(exe, args):
    out = subprocess.run([exe, *args, "--verbose"], capture_output=True, text=True)
    found = re.findall(r"([0-9.]+) ms", out.stderr)
    return float(found[-1]) if found else None


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--exe", default=os.path.join("target", "release", "graphostatik"))
    ap.add_argument("--min-ms", type=float, default=1.5)
    args = ap.parse_args()
    print("| scene | `check` | `check --reference` | ratio | one drafting drawing | in checks |")
    print("|---|---:|---:|---:|---:|---:|")
    ratios, drawings = [], []
    for path in sorted(glob.glob(os.path.join("scenes", "*.json"))):
        check = [in_process_ms(args.exe, ["check", path]) for _ in range(5)]
        ref = [in_process_ms(args.exe, ["check", path, "--reference"]) for _ in range(5)]
        if None in check or None in ref:
            continue
        runs = []
        for _ in range(3):
            t = time.perf_counter()
            subprocess.run([args.exe, "drafting", path, "--runs", "20", "--jobs", "1"],
                           capture_output=True)
            runs.append((time.perf_counter() - t) * 1e3 / 20)
        c, r, d = statistics.median(check), statistics.median(ref), statistics.median(runs)
        if c < args.min_ms:
            continue
        ratios.append(r / c)
        drawings.append(d / c)
        name = os.path.basename(path)[:-5]
        print(f"| {name} | {c:.2f} ms | {r:.2f} ms | {r / c:.2f}x | {d:.2f} ms | {d / c:.1f} |",
              flush=True)
    if ratios:
        print(f"\nreference / check: median {statistics.median(ratios):.2f}x "
              f"({min(ratios):.2f} to {max(ratios):.2f}); one drawing: median "
              f"{statistics.median(drawings):.1f} checks ({min(drawings):.1f} to {max(drawings):.1f})")


if __name__ == "__main__":
    main()
