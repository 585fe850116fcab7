#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""The five shadow algorithms' error beside their cost, and their error against the map size.

Runs shadowgraph-reference on each scene twice: once with every light at its own settings and
the GPU cost measured (SCENE.json), once per requested resolution tier without the cost
(SCENE_tiers.json). Prints the Markdown tables of docs/QUALITY.md and, when gnuplot is installed
(apt-get install gnuplot-nox), writes quality-frontier.png (error against cost per light) and
quality-tiers.png (misclassified pixels against the map size) into --out. Scenes whose files
are missing (the shared glTF assets) are skipped with a message. Python's standard library only.

  python3 tools/reference/quality.py --out quality-lavapipe
  python3 tools/reference/quality.py --from-json quality-lavapipe   # tables and plots again
"""
import argparse
import json
import os
import shutil
import subprocess
import sys

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
ALGORITHMS = ("hard", "pcf", "noise", "pcss", "pcss_noise")
TIERS = (32, 64, 128, 256, 512, 1024, 2048)
# Misclassified pixels (outside the edge band) a tier must keep under, as issue 15 asks.
THRESHOLD = 0.01
# A light that lights fewer pixels than this outside the edge band is left out of the tables:
# one wrong pixel of a few dozen would read as a large error.
MIN_PIXELS = 500


def scenes(assets):
    """(name, file that must exist or None, tool arguments) of each scene compared."""
    spot = os.path.join(assets, "ShadowsSpot", "shadows-spot.gltf")
    directional = os.path.join(assets, "ShadowsDirectional", "shadows-directional.gltf")
    return [
        ("default", None, ["--scene", "default"]),
        # A slice: 16 local lights and the sun over 50k triangles, seen from near the middle, where
        # a few of them light enough pixels to measure.
        ("stress", None, ["--scene", "stress", "--scene-triangles", "50000", "--point-lights", "8",
                          "--spot-lights", "8", "--camera", "0,8,16,0,0,0"]),
        # The light sits inside a marker cone of a transparent material, which casts no shadow.
        ("ShadowsSpot", spot, ["--scene", spot]),
        ("ShadowsDirectional", directional, ["--scene", directional]),
    ]


def parse_args():
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("--tool", default=os.path.join(ROOT, "build", "tools", "reference", "shadowgraph-reference"))
    p.add_argument("--assets", default=os.path.join(ROOT, "..", "shared", "assets"),
                   help="the shared glTF assets (ShadowsSpot, ShadowsDirectional)")
    p.add_argument("--width", type=int, default=640)
    p.add_argument("--height", type=int, default=360)
    p.add_argument("--cost-frames", type=int, default=20)
    p.add_argument("--soft-samples", type=int, default=64)
    p.add_argument("--out", default="quality", help="folder for the JSON files and the plots")
    p.add_argument("--tool-args", default="", help="more tool options, e.g. '--device NVIDIA'")
    p.add_argument("--from-json", help="run nothing: tables and plots from an earlier --out folder")
    args = p.parse_args()
    if not args.from_json and not os.access(args.tool, os.X_OK):
        p.error(f"no tool binary at {args.tool}: build first (bash tools/bootstrap.sh test)")
    return args


def run_tool(args, name, scene_args, extra, json_path):
    command = [args.tool, "--width", str(args.width), "--height", str(args.height), "--images", "",
               "--json", json_path] + scene_args + extra + args.tool_args.split()
    print(f"quality: {name}: {' '.join(command[1:])}", flush=True)
    result = subprocess.run(command, text=True, capture_output=True)
    if result.returncode != 0:
        sys.exit(f"quality: {name} failed ({result.returncode}):\n{result.stdout}{result.stderr}")


def measure(args):
    os.makedirs(args.out, exist_ok=True)
    for name, required, scene_args in scenes(args.assets):
        if required and not os.path.exists(required):
            print(f"quality: skipping {name}: {required} is missing")
            continue
        run_tool(args, name, scene_args,
                 ["--cost-frames", str(args.cost_frames), "--soft-samples", str(args.soft_samples)],
                 os.path.join(args.out, f"{name}.json"))
        # Misclassification is measured against the hard reference: few soft rays are enough. Each
        # map gets the size asked for however small its light is on screen.
        run_tool(args, name + " tiers", scene_args,
                 ["--cost-frames", "0", "--soft-samples", "16", "--resolutions", ",".join(map(str, TIERS)),
                  "--shadow-resolution", "requested"],
                 os.path.join(args.out, f"{name}_tiers.json"))


def load(folder):
    """{scene: (own run, tier run)} of the scenes measured in `folder`, in scenes() order."""
    out = {}
    for name, _, _ in scenes(""):
        own = os.path.join(folder, f"{name}.json")
        tiers = os.path.join(folder, f"{name}_tiers.json")
        if os.path.exists(own) and os.path.exists(tiers):
            with open(own) as a, open(tiers) as b:
                out[name] = (json.load(a), json.load(b))
    return out


def overall_mae(run):
    """Mean absolute error against the soft reference over every measured pixel."""
    pen, out = run["penumbra"], run["outside_penumbra"]
    pixels = pen["pixels"] + out["pixels"]
    return (pen["mae"] * pen["pixels"] + out["mae"] * out["pixels"]) / pixels if pixels else 0.0


def mean(values):
    return sum(values) / len(values) if values else 0.0


def measurable(light):
    return all(r["outside_band"] >= MIN_PIXELS for r in light["runs"])


def runs_of(report, algorithm):
    return [r for light in report["lights"] if measurable(light) for r in light["runs"]
            if r["algorithm"] == algorithm]


def cost_of(report, algorithm):
    return next((c for c in report["costs"] if c["algorithm"] == algorithm), None)


def summary_table(name, report):
    print(f"\n### {name}\n")
    kept = [f"{l['name']} ({l['type']})" for l in report["lights"] if measurable(l)]
    left_out = [f"{l['name']} ({l['type']})" for l in report["lights"] if not measurable(l)]
    print(f"{report['device']}, {report['width']}x{report['height']}; means over {len(kept)} lights: "
          f"{', '.join(kept)}" + (f"; left out, under {MIN_PIXELS} pixels outside the edge band: "
                                  f"{', '.join(left_out)}" if left_out else "") + ".\n")
    print("| algorithm | misclassified | penumbra MAE | outside-penumbra MAE | MAE (all) | acne | "
          "lighting ms per light | shadow maps ms (all lights) |")
    print("|---|---:|---:|---:|---:|---:|---:|---:|")
    for algorithm in ALGORITHMS:
        runs = runs_of(report, algorithm)
        if not runs:
            continue
        cost = cost_of(report, algorithm)
        print(f"| {algorithm} | {100 * mean([r['misclassified'] for r in runs]):.2f}% "
              f"| {mean([r['penumbra']['mae'] for r in runs]):.3f} "
              f"| {mean([r['outside_penumbra']['mae'] for r in runs]):.3f} "
              f"| {mean([overall_mae(r) for r in runs]):.3f} "
              f"| {100 * mean([r['acne'] for r in runs]):.2f}% "
              f"| {cost['lighting_ms_per_light']:.3f} | {cost['shadow_maps_ms']:.2f} |"
              if cost else f"| {algorithm} | - | - | - | - | - | - | - |")


def tier_runs(report, algorithm):
    """{light: {tier: run}} for the runs whose map got the tier asked for (a tier a light could not
    have, such as a cube's face beyond a quarter page, has no entry)."""
    out = {}
    for light in filter(measurable, report["lights"]):
        for r in light["runs"]:
            if r["algorithm"] == algorithm and r["resolution"] == r["requested_resolution"]:
                out.setdefault(light["name"], {})[r["requested_resolution"]] = r
    return out


def tier_tables(data):
    print("\n### Worst light's misclassified pixels against the map size\n")
    print("Per scene and algorithm, the largest misclassified fraction over the lights whose map got the "
          f"size asked for (lights measured on at least {MIN_PIXELS} pixels); '-': no light got it.\n")
    print("| scene | algorithm | " + " | ".join(str(t) for t in TIERS) + " | needs for <= 1% |")
    print("|---|---|" + "---:|" * len(TIERS) + "---|")
    for name, (_, tiers) in data.items():
        for algorithm in ALGORITHMS:
            lights = tier_runs(tiers, algorithm)
            cells, needed = [], None
            for t in TIERS:
                values = [by_tier[t]["misclassified"] for by_tier in lights.values() if t in by_tier]
                cells.append(f"{100 * max(values):.2f}%" if values else "-")
                if values and needed is None and max(values) <= THRESHOLD:
                    needed = t
            print(f"| {name} | {algorithm} | " + " | ".join(cells) + f" | {needed if needed else '> 2048'} |")


def plot(args, data):
    gnuplot = shutil.which("gnuplot")
    if not gnuplot:
        print("\nquality: gnuplot not found (apt-get install gnuplot-nox): no plots, the JSON has everything")
        return
    frontier = os.path.join(args.out, "quality-frontier.dat")
    with open(frontier, "w") as f:
        for name, (own, _) in data.items():
            f.write(f'"{name}"\n')
            for algorithm in ALGORITHMS:
                cost = cost_of(own, algorithm)
                runs = runs_of(own, algorithm)
                if cost and runs:
                    f.write(f"{max(cost['lighting_ms_per_light'], 1e-3):.4f} "
                            f"{mean([overall_mae(r) for r in runs]):.4f} {algorithm}\n")
            f.write("\n\n")
    tiers = os.path.join(args.out, "quality-tiers.dat")
    with open(tiers, "w") as f:
        for algorithm in ALGORITHMS:
            f.write(f'"{algorithm}"\n')
            for t in TIERS:
                values = [by_tier[t]["misclassified"] for _, (_, report) in data.items()
                          for by_tier in tier_runs(report, algorithm).values() if t in by_tier]
                if values:
                    f.write(f"{t} {100 * mean(values):.4f}\n")
            f.write("\n\n")
    device = next(iter(data.values()))[0]["device"]
    script = f"""
set terminal pngcairo size 1000,640 noenhanced
set output '{os.path.join(args.out, "quality-frontier.png")}'
set title 'Shadow error against cost, {device}, {args.width}x{args.height}'
set xlabel 'lighting GPU ms per shadowed light (over shadows off)'
set ylabel 'mean |visibility - soft reference| per pixel'
set logscale x
set key outside right
set grid
plot for [i=0:{len(data) - 1}] '{frontier}' index i using 1:2 with points pointsize 1.5 title columnheader(1), \\
     for [i=0:{len(data) - 1}] '{frontier}' index i using 1:2:3 with labels offset 1,0.6 font ',8' notitle
set output '{os.path.join(args.out, "quality-tiers.png")}'
set title 'Misclassified pixels (outside a 2-pixel edge band) against map size, mean over lights and scenes'
set xlabel 'shadow map (cube face) side, texels'
set ylabel 'misclassified, %'
set logscale x 2
set logscale y
set yrange [0.001:*]
plot for [i=0:{len(ALGORITHMS) - 1}] '{tiers}' index i using 1:($2 > 0.001 ? $2 : 0.001) with linespoints \\
     title columnheader(1)
"""
    subprocess.run([gnuplot], input=script, text=True, check=True)
    print(f"\nquality: wrote {args.out}/quality-frontier.png and quality-tiers.png")


def main():
    args = parse_args()
    if args.from_json:
        args.out = args.from_json
    else:
        measure(args)
    data = load(args.out)
    if not data:
        sys.exit(f"quality: no results in {args.out}")
    for name, (own, _) in data.items():
        summary_table(name, own)
    tier_tables(data)
    plot(args, data)


if __name__ == "__main__":
    main()
