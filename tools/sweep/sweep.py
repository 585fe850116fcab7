#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""GPU frame time against the number of lights, optimized and naive, in one run.

For each light type (point, spot, mixed), light count and mode (optimized: the sandbox's
defaults; naive: --naive), renders the stress scene headless with every light moving (so every
shadow map is redrawn every frame) from each of --cameras (overview: the whole hall; street:
eye height among the lights) and reads its --stats: times, the raster used, the light-list pairs
dropped and held, the shadow time budget in use and what it did (the budget that bound most, lights
demoted and views deferred by time, the tiers it lowered), the lights a pixel filters
(--filtered-shadows), how many frames the due maps lagged at most and how many lights changed tier
(medians over the run's frames). Writes sweep.csv and, when gnuplot is
installed (apt-get install gnuplot-nox), sweep.png (GPU frame) and sweep_lighting.png (the
lighting passes alone) into --out; prints progress per run and a summary table. Python's
standard library only.

  python3 tools/sweep/sweep.py --out sweep-lavapipe
  python3 tools/sweep/sweep.py --counts 1,4,16,64,256,1024,4096 --width 1920 --height 1080 --out sweep-gpu
  python3 tools/sweep/sweep.py --types mixed --cameras overview,street --modes optimized --out sweep-near
  python3 tools/sweep/sweep.py --shadow-budget-ms 0 --out sweep-unbudgeted   # no time budget on a GPU
"""
import argparse
import csv
import json
import os
import subprocess
import sys
import tempfile
import time

sys.path.insert(0, os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
from line_plot import gnuplot_found, line_plot  # noqa: E402  (tools/line_plot.py)

LIGHTING_PASSES = ("forward", "g-buffer", "light tiles", "lighting", "tone map")


def parse_args():
    root = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("--sandbox", default=os.path.join(root, "build", "sandbox", "shadowgraph-sandbox"))
    p.add_argument("--counts", default="1,4,16,64,256,1024", help="light counts, comma-separated")
    p.add_argument("--types", default="point,spot,mixed", help="point, spot and/or mixed (half each)")
    p.add_argument("--modes", default="optimized,naive", help="optimized and/or naive")
    p.add_argument("--width", type=int, default=1280)
    p.add_argument("--height", type=int, default=720)
    p.add_argument("--frames", type=int, default=8, help="frames per run (the first two are not timed)")
    p.add_argument("--triangles", type=int, default=20000, help="the stress scene's triangles")
    p.add_argument("--moving", type=float, default=1.0, help="fraction of lights that move each frame")
    p.add_argument("--light-spread", type=float, default=1.0,
                   help="the lights' square as a fraction of the hall's side (0.5: a quarter of the floor, "
                        "in front of the street camera: dense lights)")
    p.add_argument("--cameras", default="overview",
                   help="the stress scene's cameras, comma-separated: overview (the whole hall from above), "
                        "street (eye height among the lights)")
    p.add_argument("--max-frame-ms", type=float, default=4000.0,
                   help="once a type and mode takes longer per frame, its larger counts are skipped")
    p.add_argument("--timeout", type=float, default=600.0, help="seconds per run")
    p.add_argument("--out", default="sweep", help="folder for sweep.csv and sweep.png")
    p.add_argument("--shadow-budget-ms", type=float,
                   help="the sandbox's --shadow-budget-ms (default: the sandbox's, 6 on GPUs, none on CPU devices; "
                        "0: none); --naive runs have none")
    p.add_argument("--sandbox-args", default="", help="more sandbox options, e.g. '--device NVIDIA'")
    p.add_argument("--from-csv", help="render nothing: plot and summarize an earlier sweep.csv (e.g. one "
                   "made on a machine without gnuplot)")
    args = p.parse_args()
    try:
        args.counts = [int(c) for c in args.counts.split(",")]
    except ValueError:
        p.error("--counts takes whole numbers separated by commas")
    args.types = args.types.split(",")
    args.modes = args.modes.split(",")
    args.cameras = args.cameras.split(",")
    if any(c not in ("overview", "street") for c in args.cameras):
        p.error("--cameras takes overview, street")
    if any(t not in ("point", "spot", "mixed") for t in args.types):
        p.error("--types takes point, spot, mixed")
    if any(m not in ("optimized", "naive") for m in args.modes):
        p.error("--modes takes optimized, naive")
    if not args.from_csv and not os.access(args.sandbox, os.X_OK):
        p.error(f"no sandbox binary at {args.sandbox}: build first (bash tools/bootstrap.sh test)")
    return args


def light_options(light_type, count):
    points = count if light_type == "point" else (0 if light_type == "spot" else count // 2)
    return ["--point-lights", str(points), "--spot-lights", str(count - points)]


def run_once(args, light_type, count, mode, camera, stats_path):
    command = [args.sandbox, "--headless", "--scene", "stress", "--camera", camera, "--width", str(args.width), "--height",
               str(args.height), "--frames", str(args.frames), "--scene-triangles", str(args.triangles),
               "--moving-lights", str(args.moving), "--light-spread", str(args.light_spread), "--stats", stats_path,
               "--screenshot", ""]
    command += light_options(light_type, count) + (["--naive"] if mode == "naive" else [])
    if args.shadow_budget_ms is not None:
        command += ["--shadow-budget-ms", str(args.shadow_budget_ms)]
    command += args.sandbox_args.split()
    result = subprocess.run(command, capture_output=True, text=True, timeout=args.timeout)
    if result.returncode != 0:
        raise RuntimeError(f"exit {result.returncode}: {result.stderr.strip()[-400:]}")
    with open(stats_path) as f:
        return json.load(f)


def median(summary):
    return summary["median"] if summary else None


def row_of(stats, light_type, count, mode, camera):
    passes = stats["passes"]
    shadow = sum(p["gpu_ms"]["median"] for p in passes if p["name"].startswith("shadow"))
    lighting = sum(p["gpu_ms"]["median"] for p in passes if p["name"].startswith(LIGHTING_PASSES))
    budget = stats.get("shadow_budget", {})
    return {"device": stats["device"], "type": light_type, "lights": count, "mode": mode, "camera": camera,
            "light_spread": stats.get("settings", {}).get("light-spread", ""),
            "lighting_path": stats.get("lighting", ""), "raster": stats["shadows"].get("raster") or "",
            "dropped_light_pairs": stats.get("dropped_light_pairs", ""),
            "light_list_pairs": median(stats.get("light_list_pairs")), "gpu_frame_ms": median(stats["gpu_frame_ms"]),
            "filtered_shadows": stats.get("filtered_shadows", ""),
            "map_lag_max": median(stats["shadows"].get("map_lag_frames", {}).get("max")),
            "lights_changed_tier": median(stats["shadows"].get("lights_changed_tier")),
            "wall_frame_ms": median(stats.get("wall_frame_ms")), "cpu_frame_ms": median(stats["cpu_frame_ms"]),
            "shadow_ms": round(shadow, 4), "lighting_ms": round(lighting, 4),
            "shadow_budget_ms": budget.get("budget_ms") or "", "budget_bound": budget.get("bound", ""),
            "lowered_tiers": budget.get("lowered_tiers", ""),
            "lights_demoted_by_time": median(budget.get("lights_demoted_by_time")),
            "views_deferred_by_time": median(budget.get("views_deferred_by_time")),
            "triangles": stats["scene"]["triangles"], "width": stats["resolution"]["width"],
            "height": stats["resolution"]["height"]}


def plot(out_dir, rows, args):
    if not gnuplot_found("sweep"):
        return
    # The whole GPU frame, and the lighting alone (the shadow passes are the same work in both
    # modes but for the naive six passes per cube and unculled casters).
    first = rows[0]
    for column, name, label in (("gpu_frame_ms", "sweep.png", "GPU frame"),
                                ("lighting_ms", "sweep_lighting.png", "lighting passes")):
        series = [(f"{light_type}, {camera}, {mode}",
                   [(r["lights"], r[column]) for r in rows if r["type"] == light_type and r["mode"] == mode and
                    r.get("camera", "overview") == camera and r[column]])
                  for light_type in args.types for camera in args.cameras for mode in args.modes]
        line_plot(os.path.join(out_dir, name),
                  f"{label} against shadowed lights: {first['device']}, {first['width']}x{first['height']}, "
                  f"{first['triangles']} triangles, every light moving",
                  "lights (each with a shadow)", f"{label} (ms)", series, logscale="xy", size=(1100, 700))
        print(f"sweep: wrote {os.path.join(out_dir, name)}")


def read_csv(path):
    numbers = {"lights": int, "triangles": int, "dropped_light_pairs": int, "width": int, "height": int, "gpu_frame_ms": float, "wall_frame_ms": float,
               "cpu_frame_ms": float, "shadow_ms": float, "lighting_ms": float, "shadow_budget_ms": float,
               "lowered_tiers": float, "lights_demoted_by_time": float, "views_deferred_by_time": float,
               "light_list_pairs": float, "filtered_shadows": int, "map_lag_max": float,
               "lights_changed_tier": float}
    with open(path) as f:
        return [{k: (numbers[k](v) if k in numbers and v != "" else v) for k, v in row.items()}
                for row in csv.DictReader(f)]


def summarize(rows, args):
    print(f"\nGPU frame ms on {rows[0]['device']}, {rows[0]['width']}x{rows[0]['height']}:")
    print(f"{'type':6} {'camera':8} {'lights':>7} {'optimized':>10} {'naive':>10} {'naive/opt':>10}")
    by_key = {(r["type"], r.get("camera", "overview"), r["lights"], r["mode"]): r["gpu_frame_ms"] for r in rows}
    for light_type in args.types:
        for camera in args.cameras:
            for count in args.counts:
                opt = by_key.get((light_type, camera, count, "optimized"))
                naive = by_key.get((light_type, camera, count, "naive"))
                if opt is None and naive is None:
                    continue
                ratio = f"{naive / opt:10.1f}" if opt and naive else f"{'-':>10}"
                show = lambda v: f"{v:10.2f}" if v is not None else f"{'-':>10}"
                print(f"{light_type:6} {camera:8} {count:7} {show(opt)} {show(naive)} {ratio}")


def main():
    args = parse_args()
    os.makedirs(args.out, exist_ok=True)
    if args.from_csv:
        rows = read_csv(args.from_csv)
        args.counts = sorted({r["lights"] for r in rows})
        args.types = [t for t in ("point", "spot", "mixed") if any(r["type"] == t for r in rows)]
        args.modes = [m for m in ("optimized", "naive") if any(r["mode"] == m for r in rows)]
        args.cameras = [c for c in ("overview", "street") if any(r.get("camera", "overview") == c for r in rows)]
        plot(args.out, rows, args)
        summarize(rows, args)
        return
    runs = [(t, c, n, m) for t in args.types for c in args.cameras for m in args.modes for n in args.counts]
    rows, too_slow = [], set()
    started = time.monotonic()
    with tempfile.TemporaryDirectory() as scratch:
        for index, (light_type, camera, count, mode) in enumerate(runs, 1):
            label = f"[{index}/{len(runs)}] {light_type:5} {camera:8} {count:6} lights, {mode:9}"
            if (light_type, camera, mode) in too_slow:
                print(f"{label}: skipped (a smaller count already took over {args.max_frame_ms:.0f} ms a frame)")
                continue
            try:
                stats = run_once(args, light_type, count, mode, camera, os.path.join(scratch, "stats.json"))
            except (RuntimeError, subprocess.TimeoutExpired) as error:
                print(f"{label}: failed: {error}")
                too_slow.add((light_type, camera, mode))
                continue
            row = row_of(stats, light_type, count, mode, camera)
            rows.append(row)
            print(f"{label}: GPU {row['gpu_frame_ms']:9.2f} ms (shadows {row['shadow_ms']:8.2f}, lighting "
                  f"{row['lighting_ms']:8.2f}), wall {row['wall_frame_ms'] or 0:9.2f} ms, {row['raster'] or '-'} "
                  f"raster, {row['dropped_light_pairs']} pairs dropped, budget {row['shadow_budget_ms'] or '-'} ms bound "
                  f"{row['budget_bound'] or '-'} ({row['lights_demoted_by_time'] or 0:.0f} lights demoted, "
                  f"{row['views_deferred_by_time'] or 0:.0f} views deferred)  [{time.monotonic() - started:.0f} s]",
                  flush=True)
            if row["gpu_frame_ms"] and row["gpu_frame_ms"] > args.max_frame_ms:
                too_slow.add((light_type, camera, mode))
    if not rows:
        sys.exit("sweep: no run succeeded")
    with open(os.path.join(args.out, "sweep.csv"), "w", newline="") as f:
        writer = csv.DictWriter(f, fieldnames=list(rows[0].keys()))
        writer.writeheader()
        writer.writerows(rows)
    print(f"sweep: wrote {os.path.join(args.out, 'sweep.csv')}")
    plot(args.out, rows, args)

    summarize(rows, args)


if __name__ == "__main__":
    main()
