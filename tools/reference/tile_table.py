#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""Shadow error by the tile each light got in the atlas, from shadowgraph-reference's JSON.

Groups every measured run by light type and the resolution the atlas gave it (not the one asked
for), and prints a Markdown row per group: lights measured, their mean misclassified and acne
fractions, and the same weighted by pixels (misclassified over the pixels outside the edge band,
acne over the lit ones). Lights with fewer than --min-pixels outside the band are left out, as in
docs/QUALITY.md. Python's standard library only.

  shadowgraph-reference --scene stress --point-lights 512 --spot-lights 512 --moving-lights 0 \\
      --width 1920 --height 1080 --algorithms hard --cost-frames 0 --soft-samples 1 --json far.json
  python3 tools/reference/tile_table.py far.json
"""
import argparse
import json
from collections import defaultdict


def main():
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("json", nargs="+", help="shadowgraph-reference --json files, tabled together")
    p.add_argument("--min-pixels", type=int, default=0,
                   help="leave out lights with fewer pixels outside the edge band (default 0: none)")
    args = p.parse_args()

    groups = defaultdict(list)  # (algorithm, type, tile) -> runs
    for path in args.json:
        with open(path) as f:
            report = json.load(f)
        for light in report["lights"]:
            for run in light["runs"]:
                if run["resolution"] == 0 or run["outside_band"] < max(args.min_pixels, 1):
                    continue
                groups[(run["algorithm"], light["type"], run["resolution"])].append(run)

    print("| algorithm | light | tile | lights | mean misclassified | mean acne | pixels outside the band "
          "| misclassified (pixels) | acne (of lit pixels) |")
    print("|---|---|---:|---:|---:|---:|---:|---:|---:|")
    for (algorithm, kind, tile), runs in sorted(groups.items()):
        outside = sum(r["outside_band"] for r in runs)
        wrong = sum(r["misclassified"] * r["outside_band"] for r in runs)
        # Reports written before the tool counted lit pixels have no "lit": no weighted acne then.
        lit = sum(r.get("lit", 0) for r in runs)
        acne = f"{100 * sum(r['acne'] * r['lit'] for r in runs) / lit:.2f}%" if lit else "-"
        print(f"| {algorithm} | {kind} | {tile} | {len(runs)} "
              f"| {100 * sum(r['misclassified'] for r in runs) / len(runs):.2f}% "
              f"| {100 * sum(r['acne'] for r in runs) / len(runs):.2f}% | {outside} "
              f"| {100 * wrong / outside:.2f}% | {acne} |")


if __name__ == "__main__":
    main()
