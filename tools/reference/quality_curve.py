#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""The frame's shadow error against the number of shadowed lights, beside its GPU time.

For each light count, camera (overview: the whole hall; street: eye height among the lights)
and motion (moving: every light moves; static: the same lights with the animation stopped), runs
`shadowgraph-reference --whole-frame` on the stress scene (half point, half spot lights) with
the engine's default settings, and reads its JSON: misclassified lit pixels, MAE, the GPU frame
of the frames before the measured one, whether pairs were sampled. Writes quality_curve.csv and,
when gnuplot is installed (apt-get install gnuplot-nox), quality_curve.png (error) and
quality_curve_time.png (GPU frame) into --out; prints progress per run and a Markdown table.
Python's standard library only.

  python3 tools/reference/quality_curve.py --out curve-lavapipe
  python3 tools/reference/quality_curve.py --counts 1,16,256,1024,4096,16384,100000 --width 1920 \\
      --height 1080 --pairs-per-pixel 16 --out curve-gpu
  python3 tools/reference/quality_curve.py --from-csv curve-gpu/quality_curve.csv --out curve-gpu
"""
import argparse
import csv
import json
import os
import subprocess
import sys
import tempfile
import time

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
sys.path.insert(0, os.path.join(ROOT, "tools"))
from line_plot import gnuplot_found, line_plot  # noqa: E402  (tools/line_plot.py)
COLUMNS = ("device", "width", "height", "triangles", "camera", "motion", "lights", "frames", "misclassified",
           "mae", "lit_pixels", "sampled_fraction", "gpu_frame_ms", "lights_without_map", "trace_seconds")


def parse_args():
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("--reference", default=os.path.join(ROOT, "build", "tools", "reference", "shadowgraph-reference"))
    p.add_argument("--counts", default="1,16,256,1024", help="shadowed light counts, comma-separated")
    p.add_argument("--cameras", default="overview,street", help="overview and/or street")
    p.add_argument("--motion", default="static,moving", help="static and/or moving")
    p.add_argument("--width", type=int, default=320)
    p.add_argument("--height", type=int, default=180)
    p.add_argument("--triangles", type=int, default=20000, help="the stress scene's triangles")
    p.add_argument("--frames", type=int, default=30,
                   help="frames rendered before the measured one is probed (moving: maps may lag)")
    p.add_argument("--pairs-per-pixel", type=int, default=64, help="the probe's room; more pairs are sampled")
    p.add_argument("--soft-samples", type=int, default=16, help="rays a pair of a PCSS light's soft reference")
    p.add_argument("--reference-args", default="", help="more options, e.g. '--shadow-memory 16'")
    p.add_argument("--timeout", type=float, default=3600.0, help="seconds per run")
    p.add_argument("--out", default="quality-curve", help="folder for the CSV and the plots")
    p.add_argument("--from-csv", help="run nothing: plot and tabulate an earlier quality_curve.csv")
    args = p.parse_args()
    args.counts = [int(c) for c in args.counts.split(",") if c]
    args.cameras = [c for c in args.cameras.split(",") if c]
    args.motion = [m for m in args.motion.split(",") if m]
    for m in args.motion:
        if m not in ("static", "moving"):
            p.error(f"--motion: unknown '{m}' (static, moving)")
    return args


def run_once(args, count, camera, motion, json_path):
    points = count // 2
    command = [args.reference, "--whole-frame", "--scene", "stress", "--camera", camera,
               "--scene-triangles", str(args.triangles), "--point-lights", str(points),
               "--spot-lights", str(count - points), "--width", str(args.width), "--height", str(args.height),
               "--frames", str(args.frames), "--pairs-per-pixel", str(args.pairs_per_pixel),
               "--soft-samples", str(args.soft_samples), "--json", json_path]
    # The same scene both ways (the stress scene lays out moving lights apart from still ones):
    # static stops the animation instead.
    command += ["--moving-lights", "1"] + ([] if motion == "moving" else ["--animate", "off"])
    command += args.reference_args.split()
    result = subprocess.run(command, capture_output=True, text=True, timeout=args.timeout)
    if result.returncode != 0:
        raise RuntimeError(f"exit {result.returncode}: {(result.stderr or result.stdout).strip()[-400:]}")
    with open(json_path) as f:
        report = json.load(f)
    frame = report["frame"]
    return {"device": report["device"], "width": report["width"], "height": report["height"],
            "triangles": args.triangles, "camera": camera, "motion": motion, "lights": count,
            "frames": report["frames"], "misclassified": frame["misclassified"], "mae": frame["mae"],
            "lit_pixels": frame["lit_pixels"], "sampled_fraction": frame["sampled_fraction"],
            "gpu_frame_ms": report["gpu_frame_ms"], "lights_without_map": report["lights_without_map"],
            "trace_seconds": report["trace_seconds"]}


def plot(out_dir, rows):
    if not gnuplot_found("quality_curve"):
        return
    first = rows[0]
    keys = sorted({(r["camera"], r["motion"]) for r in rows})
    for column, name, label, scale in (("misclassified", "quality_curve.png", "misclassified lit pixels (%)", 100.0),
                                       ("mae", "quality_curve_mae.png", "MAE over lit pixels", 1.0),
                                       ("gpu_frame_ms", "quality_curve_time.png", "GPU frame (ms)", 1.0)):
        series = [(f"{camera}, {motion}",
                   sorted((r["lights"], r[column] * scale) for r in rows if r["camera"] == camera and
                          r["motion"] == motion))
                  for camera, motion in keys]
        line_plot(os.path.join(out_dir, name),
                  f"{label}: {first['device']}, {first['width']}x{first['height']}, {first['triangles']} triangles",
                  "shadowed lights", label, series)
        print(f"quality_curve: wrote {os.path.join(out_dir, name)}")


def write_csv(path, rows):
    with open(path, "w", newline="") as f:
        writer = csv.DictWriter(f, fieldnames=COLUMNS)
        writer.writeheader()
        writer.writerows(rows)


def read_csv(path):
    numbers = {"width": int, "height": int, "triangles": int, "lights": int, "frames": int, "misclassified": float,
               "mae": float, "lit_pixels": int, "sampled_fraction": float, "gpu_frame_ms": float,
               "lights_without_map": int, "trace_seconds": float}
    with open(path) as f:
        return [{k: numbers[k](v) if k in numbers else v for k, v in row.items()} for row in csv.DictReader(f)]


def table(rows):
    print("\n| camera | motion | lights | misclassified | MAE | lit pixels | sampled | GPU frame (ms) | lights without a map |")
    print("|---|---|---:|---:|---:|---:|---:|---:|---:|")
    for r in sorted(rows, key=lambda r: (r["camera"], r["motion"], r["lights"])):
        sampled = f"{100 * r['sampled_fraction']:.0f}%" if r["sampled_fraction"] < 1 else "all"
        print(f"| {r['camera']} | {r['motion']} | {r['lights']:,} | {100 * r['misclassified']:.2f}% | {r['mae']:.4f} | "
              f"{r['lit_pixels']:,} | {sampled} | {r['gpu_frame_ms']:.2f} | {r['lights_without_map']:,} |")


def main():
    args = parse_args()
    os.makedirs(args.out, exist_ok=True)
    if args.from_csv:
        rows = read_csv(args.from_csv)
    else:
        if not os.access(args.reference, os.X_OK):
            sys.exit(f"quality_curve: no reference tool at {args.reference} (build it, or pass --reference)")
        rows = []
        runs = [(c, cam, m) for cam in args.cameras for m in args.motion for c in args.counts]
        with tempfile.TemporaryDirectory() as scratch:
            for i, (count, camera, motion) in enumerate(runs, 1):
                start = time.monotonic()
                row = run_once(args, count, camera, motion, os.path.join(scratch, "frame.json"))
                rows.append(row)
                print(f"quality_curve: {i}/{len(runs)} {camera} {motion} {count} lights: misclassified "
                      f"{100 * row['misclassified']:.2f}%, MAE {row['mae']:.4f}, GPU frame {row['gpu_frame_ms']:.2f} ms "
                      f"({time.monotonic() - start:.0f} s)", flush=True)
                write_csv(os.path.join(args.out, "quality_curve.csv"), rows)  # a run cut short keeps its rows
    table(rows)
    plot(args.out, rows)


if __name__ == "__main__":
    main()
