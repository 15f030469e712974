#!/usr/bin/env bash
# The before/after pictures of docs/img/ (README "Figures"): four bundled figures as
# d8a2127 drew them from its own scenes (before the sheet layout, the label placer and the
# crowd rule; today's scenes have fields it does not know) and as the working tree draws
# them, each pair side by side. Needs git, cargo and Python's Pillow.
# Run from the repository's root: bash docs/img/before_after.sh
set -euo pipefail
old=d8a2127
work=$(mktemp -d)
git worktree add -f "$work/old" "$old" >/dev/null
(cd "$work/old" && CARGO_TARGET_DIR="$work/target-old" cargo build -q --bin graphostatik)
cargo build -q --bin graphostatik
for s in kg_abb1043_crank_rocker kg_abb1056_otto_four_cylinders lh_j_locomotive_dynamics \
         lh_aufgabe5_crane_bridge; do
  "$work/target-old/debug/graphostatik" render "$work/old/scenes/$s.json" --out "$work/before" \
    --format png --dpi 90 -q 2>/dev/null
  target/debug/graphostatik render "scenes/$s.json" --out "$work/after" \
    --format png --dpi 90 -q 2>/dev/null
done
python3 - "$work" <<'PY'
import sys
from PIL import Image, ImageDraw
work = sys.argv[1]
# Which part of each sheet to show (fractions of width and height; a second box for the
# after side where the sheet's parts moved), and the width of a side.
views = {
    "kg_abb1043_crank_rocker": ((0.0, 0.205, 0.56, 0.8), (0.0, 0.2, 1.0, 0.68), 620),
    "kg_abb1056_otto_four_cylinders": ((0.0, 0.0, 1.0, 1.0), None, 620),
    "lh_j_locomotive_dynamics": ((0.55, 0.07, 1.0, 0.45), None, 520),
    # The crane bridge's numbered Bauplan, at 1 : 200 before and 1 : 100 after.
    "lh_aufgabe5_crane_bridge": ((0.0, 0.0145, 0.16, 0.044), (0.0, 0.031, 0.2, 0.131), 620),
}
for name, (box, after_box, side) in views.items():
    pair = []
    for when in ("before", "after"):
        x0, y0, x1, y1 = after_box if when == "after" and after_box else box
        im = Image.open(f"{work}/{when}/{name}.png").convert("L")
        w, h = im.size
        im = im.crop((int(x0 * w), int(y0 * h), int(x1 * w), int(y1 * h)))
        im = im.resize((side, max(1, round(im.size[1] * side / im.size[0]))), Image.LANCZOS)
        pair.append(im)
    height = max(p.size[1] for p in pair) + 24
    out = Image.new("L", (2 * side + 30, height), 255)
    d = ImageDraw.Draw(out)
    for k, (p, when) in enumerate(zip(pair, ("before", "after"))):
        out.paste(p, (k * (side + 30), 24))
        d.text((k * (side + 30) + 4, 4), when, fill=0)
    d.line([(side + 15, 0), (side + 15, height)], fill=160)
    out.save(f"docs/img/{name}.png", optimize=True)
    print(f"docs/img/{name}.png", out.size)
PY
git worktree remove --force "$work/old"
rm -rf "$work"
