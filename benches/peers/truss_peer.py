#!/usr/bin/env python3
"""The truss peer: the same Pratt girders through `graphostatik check` and through numpy/scipy.

For every size the script writes a truss scene (a Pratt girder of n panels, 2n joints, a load
at every inner bottom joint, a pin at the left and a roller at the right), then measures in
one run, median of several:

- numpy: the 2k x 2k joint equations of the parsed scene assembled as a scipy.sparse matrix
  and solved by scipy.sparse.linalg.spsolve (SuperLU), in process: the import and the JSON
  parse are not counted, the assembly and the solve are;
- graphostatik in process: the time `graphostatik check --verbose` reports for the scene
  (read, validation, determinacy, the recorded Cremona plan, the sparse solve, every check,
  the table: past 1,000 checks a row per kind with its count and worst, and every failure);
- graphostatik end to end: the whole command, process start and exit included;
- compas_ags (ETH's algebraic graphic statics) and anastruct (a 2D frame FEM), where they are
  installed and up to `--peer-max` joints: the girder built in each (compas_ags: the form
  diagram with the loads and reactions as leaf edges, the loads its independent edges;
  anastruct: truss elements, a hinge and a roller), solved, its member forces read, in
  process. Each one's forces are compared with numpy's (the largest difference over the
  largest force, in the last column) before it is timed.

Run from the repository root after `cargo build --release`:

    python3 benches/peers/truss_peer.py [--sizes 10,100,1000,10000,100000] [--reps 5] [--exe PATH]

Needs numpy and scipy (`pip install numpy scipy`); the peers `pip install compas_ags
anastruct`. Prints a Markdown table.
"""
import argparse
import json
import os
import statistics
import subprocess
import sys
import tempfile

import numpy as np
import scipy.sparse
import scipy.sparse.linalg
from timing import median_ms, timed_check

EXE = os.path.join("target", "release", "graphostatik")


def pratt(n, panel=2.0, height=2.0):
    """A Pratt girder of n panels as a scene (the layout of truss::generate::parallel_chord)."""
    joints = [{"name": f"B{i}", "at_m": [i * panel, 0.0]} for i in range(n + 1)]
    joints += [{"name": f"T{i}", "at_m": [i * panel, height]} for i in range(1, n)]
    members = []

    def add(a, b):
        members.append({"name": str(len(members) + 1), "joints": [a, b]})

    for i in range(n):
        add(f"B{i}", f"B{i + 1}")
    add("B0", "T1")
    add(f"B{n}", f"T{n - 1}")
    for i in range(1, n):
        add(f"B{i}", f"T{i}")
        if i + 1 < n:
            add(f"T{i}", f"T{i + 1}")
    for j in range(1, n - 1):
        if 2 * j + 1 < n:
            add(f"T{j}", f"B{j + 1}")
        else:
            add(f"B{j}", f"T{j + 1}")
    loads = [{"joint": f"B{i}", "kg": 1000.0 + (i % 7) * 100.0} for i in range(1, n)]
    return {
        "procedure": "truss",
        "title": f"Pratt girder, {n} panels",
        "joints": joints,
        "members": members,
        "supports": [
            {"joint": "B0", "kind": "pinned"},
            {"joint": f"B{n}", "kind": "roller", "direction_deg": 90},
        ],
        "load_cases": [{"name": "P", "loads": loads}],
    }


def numpy_solve(scene):
    """Assembles and solves the joint equations; returns the member forces."""
    index = {j["name"]: i for i, j in enumerate(scene["joints"])}
    xy = np.array([j["at_m"] for j in scene["joints"]], dtype=float)
    ends = np.array([[index[a], index[b]] for a, b in (m["joints"] for m in scene["members"])])
    k, s = len(xy), len(ends)
    d = xy[ends[:, 1]] - xy[ends[:, 0]]
    d /= np.hypot(d[:, 0], d[:, 1])[:, None]
    m = np.arange(s)
    rows = np.concatenate([2 * ends[:, 0], 2 * ends[:, 0] + 1, 2 * ends[:, 1], 2 * ends[:, 1] + 1])
    cols = np.concatenate([m, m, m, m])
    vals = np.concatenate([d[:, 0], d[:, 1], -d[:, 0], -d[:, 1]])
    a, b = index[scene["supports"][0]["joint"]], index[scene["supports"][1]["joint"]]
    rows = np.concatenate([rows, [2 * a, 2 * a + 1, 2 * b + 1]])
    cols = np.concatenate([cols, [s, s + 1, s + 2]])
    vals = np.concatenate([vals, [1.0, 1.0, 1.0]])
    mat = scipy.sparse.csc_matrix((vals, (rows, cols)), shape=(2 * k, s + 3))
    p = np.zeros(2 * k)
    for case in scene["load_cases"]:
        for load in case["loads"]:
            p[2 * index[load["joint"]] + 1] -= load["kg"]
    f = scipy.sparse.linalg.spsolve(mat, -p)
    return f[:s]


def compas_ags_solve(scene):
    """The girder as compas_ags's form diagram (loads and reactions as vertical leaf edges,
    the loads independent), its force densities and force diagram updated; member forces
    in member order."""
    from compas_ags.ags import graphstatics
    from compas_ags.diagrams import ForceDiagram, FormDiagram, FormGraph

    xy = {j["name"]: j["at_m"] for j in scene["joints"]}
    lines = [([*xy[a], 0.0], [*xy[b], 0.0]) for a, b in (m["joints"] for m in scene["members"])]
    members = len(lines)
    loads = {}
    for case in scene["load_cases"]:
        for load in case["loads"]:
            loads[load["joint"]] = loads.get(load["joint"], 0.0) + load["kg"]
    # A vertical leaf edge below each loaded joint (its load) and each support (its reaction).
    leaves = []
    for name, kg in [*loads.items(), *((s["joint"], None) for s in scene["supports"])]:
        x, y = xy[name]
        lines.append(([x, y, 0.0], [x, y - 1.0, 0.0]))
        leaves.append((kg, len(lines) - 1))
    form = FormDiagram.from_graph(FormGraph.from_lines(lines))
    at = {}
    for u, v in form.edges():
        a = tuple(round(c, 9) for c in form.vertex_coordinates(u)[:2])
        b = tuple(round(c, 9) for c in form.vertex_coordinates(v)[:2])
        at[a, b] = at[b, a] = (u, v)

    def edge(i):
        a, b = lines[i]
        return at[tuple(round(c, 9) for c in a[:2]), tuple(round(c, 9) for c in b[:2])]

    for kg, i in leaves:
        if kg is not None:
            form.edge_attribute(edge(i), "is_ind", True)
            form.edge_attribute(edge(i), "q", kg)
    tips = [v for v in form.vertices() if form.vertex_degree(v) == 1]
    form.vertices_attribute("is_fixed", True, keys=tips)
    force = ForceDiagram.from_formdiagram(form)
    graphstatics.form_update_q_from_qind(form)
    graphstatics.force_update_from_form(force, form)
    return np.array([form.edge_attribute(edge(i), "f") for i in range(members)])


def anastruct_solve(scene):
    """The girder as anastruct truss elements on a hinge and a roller, solved; member forces
    in member order."""
    from anastruct import SystemElements

    xy = {j["name"]: j["at_m"] for j in scene["joints"]}
    ss = SystemElements(mesh=1)
    for a, b in (m["joints"] for m in scene["members"]):
        ss.add_truss_element(location=[xy[a], xy[b]], EA=1e9)
    pin, roller = scene["supports"]
    ss.add_support_hinged(node_id=ss.find_node_id(xy[pin["joint"]]))
    ss.add_support_roll(node_id=ss.find_node_id(xy[roller["joint"]]), direction="x")
    for case in scene["load_cases"]:
        for load in case["loads"]:
            ss.point_load(node_id=ss.find_node_id(xy[load["joint"]]), Fy=-load["kg"])
    ss.solve()
    return np.array(
        [r["Nmax"] if abs(r["Nmax"]) > abs(r["Nmin"]) else r["Nmin"] for r in ss.get_element_results()]
    )


def peers():
    """The peers installed, by name."""
    found = {}
    for name, solve in (("compas_ags", compas_ags_solve), ("anastruct", anastruct_solve)):
        try:
            __import__(name)
            found[name] = solve
        except ImportError:
            print(f"({name} is not installed: its column is left out)", file=sys.stderr)
    return found


def members_checked(path):
    """Member-force checks `check --json` reports (a row each, or past 1,000 checks the count
    of their kind in the summary); an untimed run of its own."""
    out = subprocess.run([EXE, "check", path, "--json"], capture_output=True, text=True)
    report = json.loads(out.stdout)
    if isinstance(report, list):
        return sum(1 for r in report if r["quantity"].startswith("member force"))
    return sum(k["checks"] for k in report["kinds"] if k["quantity"].startswith("member force"))


def main():
    global EXE
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--sizes", default="10,100,1000,10000,100000", help="joints, comma-separated")
    ap.add_argument("--reps", type=int, default=5)
    ap.add_argument("--exe", default=EXE, help="the graphostatik binary (another build to compare)")
    ap.add_argument("--peer-max", type=int, default=1000, help="most joints the peers are run on")
    args = ap.parse_args()
    EXE = args.exe
    import warnings

    warnings.filterwarnings("ignore")  # anastruct's polyfit of moments a truss has none of
    others = peers()
    head = "".join(f" {name}, in process | ratio |" for name in others)
    print("| joints | members | numpy + scipy spsolve, in process | graphostatik check, in process | ratio | graphostatik check, end to end | ratio |" + head + " members checked | peers' forces against numpy's |")
    print("|---:|---:|---:|---:|---:|---:|---:|" + "---:|---:|" * len(others) + "---:|---:|")
    with tempfile.TemporaryDirectory() as tmp:
        for joints in (int(x) for x in args.sizes.split(",")):
            n = max(joints // 2, 2)
            scene = pratt(n)
            path = os.path.join(tmp, f"pratt_{n}.json")
            with open(path, "w") as f:
                json.dump(scene, f)
            f_np = numpy_solve(scene)
            t_np = median_ms(lambda: numpy_solve(scene), args.reps)
            runs = [timed_check(EXE, path) for _ in range(args.reps)]
            t_e2e = statistics.median(r[0] for r in runs)
            t_in = statistics.median(r[1] for r in runs)
            checked = members_checked(path)
            k = len(scene["joints"])
            s = len(scene["members"])
            assert np.all(np.isfinite(f_np))
            cells, agree = "", []
            for name, solve in others.items():
                if k > args.peer_max:
                    cells += " - | - |"
                    continue
                off = np.max(np.abs(solve(scene) - f_np)) / np.max(np.abs(f_np))
                agree.append(f"{name} {off:.0e}")
                t = median_ms(lambda: solve(scene), args.reps if k <= 100 else 1)
                cells += f" {t:.2f} ms | {t / t_in:.1f}x |"
            print(
                f"| {k:,} | {s:,} | {t_np:.2f} ms | {t_in:.2f} ms | {t_np / t_in:.1f}x "
                f"| {t_e2e:.2f} ms | {t_np / t_e2e:.1f}x |{cells} {checked:,} | {', '.join(agree) or '-'} |",
                flush=True,
            )


if __name__ == "__main__":
    main()
