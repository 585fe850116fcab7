#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""The one-light frame ratio: the engine's wall time a frame against the plain forward renderer's
(shadowgraph-plain-forward) on the same scene, size and machine.

Each round runs, per scene, the plain renderer and then the sandbox (headless, the light's map at
its requested resolution, as the plain renderer draws it), so that both see the machine in the same
minutes; a shared or throttled machine moves both. The sandbox's figure is the median wall time of
its settled frames (--stats), the plain renderer's the median it prints. Prints each run as it
ends and a summary per scene: the medians over rounds, the ratio of the medians and the range of
the rounds' ratios. Writes one_light_ratio.csv into --out. Python's standard library only.

  python3 tools/plain-forward/one_light_ratio.py --rounds 5 --out ratio-lavapipe
  python3 tools/plain-forward/one_light_ratio.py --width 1920 --height 1080 --frames 200 --out ratio-gpu
  python3 tools/plain-forward/one_light_ratio.py --quick --out ratio-smoke   # a smoke test: its times mean nothing
"""
import argparse
import csv
import json
import os
import re
import statistics
import subprocess
import sys

SCENES = ("point-room", "spot-columns")
PLAIN_LINE = re.compile(r"wall ([0-9.]+) ms, GPU ([0-9.]+) ms a frame")


def run(command):
    """Runs `command`, returning its standard output; exits with its error output if it fails."""
    done = subprocess.run(command, capture_output=True, text=True)
    if done.returncode != 0:
        sys.stderr.write(done.stdout[-2000:] + done.stderr[-2000:])
        sys.exit(f"one_light_ratio: {' '.join(command)} failed with exit code {done.returncode}")
    return done.stdout


def plain_wall_ms(args, scene):
    command = [args.plain, "--scene", scene, "--width", str(args.width), "--height", str(args.height),
               "--frames", str(args.frames)] + (["--device", args.device] if args.device else [])
    found = PLAIN_LINE.search(run(command))
    if not found:
        sys.exit(f"one_light_ratio: {args.plain} printed no frame time")
    return float(found.group(1))


def engine_wall_ms(args, scene):
    stats_path = os.path.join(args.out, f"engine_{scene}.json")
    command = [args.sandbox, "--headless", "--scene", scene, "--shadow-resolution", "requested",
               "--width", str(args.width), "--height", str(args.height), "--frames", str(args.frames),
               "--stats", stats_path] + (["--device", args.device] if args.device else [])
    run(command)
    with open(stats_path) as f:
        settled = json.load(f)["settled"]
    if settled is None:
        sys.exit(f"one_light_ratio: the sandbox's {args.frames} frames of {scene} never settled; "
                 "ask for more --frames")
    return settled["wall_frame_ms"]["median"]


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--build", default="build", help="the build folder holding both programs (default: build)")
    parser.add_argument("--scenes", default=",".join(SCENES), help="comma-separated, of " + ", ".join(SCENES))
    parser.add_argument("--rounds", type=int, default=3, help="rounds of every scene (default: 3)")
    parser.add_argument("--frames", type=int, default=30, help="frames a run (default: 30)")
    parser.add_argument("--width", type=int, default=1280)
    parser.add_argument("--height", type=int, default=720)
    parser.add_argument("--device", help="the Vulkan device whose name contains this, for both programs")
    parser.add_argument("--quick", action="store_true", help="one round of 4 frames at 160x90: a smoke test")
    parser.add_argument("--out", default="one-light-ratio", help="folder for the CSV and the runs' stats")
    args = parser.parse_args()
    if args.quick:
        args.rounds, args.frames, args.width, args.height = 1, 4, 160, 90
    scenes = [s for s in args.scenes.split(",") if s]
    unknown = [s for s in scenes if s not in SCENES]
    if unknown or not scenes:
        parser.error(f"--scenes takes {', '.join(SCENES)}; not {', '.join(unknown) or 'none'}")
    if args.rounds < 1 or args.frames < 2:
        parser.error("--rounds must be at least 1 and --frames at least 2")
    args.plain = os.path.join(args.build, "tools", "plain-forward", "shadowgraph-plain-forward")
    args.sandbox = os.path.join(args.build, "sandbox", "shadowgraph-sandbox")
    for program in (args.plain, args.sandbox):
        if not os.access(program, os.X_OK):
            sys.exit(f"one_light_ratio: {program} not found; build the project first or give --build")
    os.makedirs(args.out, exist_ok=True)

    rows = []
    runs = args.rounds * len(scenes)
    for round_index in range(args.rounds):
        for scene in scenes:
            plain = plain_wall_ms(args, scene)
            engine = engine_wall_ms(args, scene)
            rows.append({"scene": scene, "round": round_index + 1, "engine_wall_ms": engine,
                         "plain_wall_ms": plain, "ratio": engine / plain})
            print(f"[{len(rows)}/{runs}] round {round_index + 1}, {scene}: engine {engine:.2f} ms, "
                  f"plain {plain:.2f} ms, ratio {engine / plain:.2f}", flush=True)

    csv_path = os.path.join(args.out, "one_light_ratio.csv")
    with open(csv_path, "w", newline="") as f:
        writer = csv.DictWriter(f, fieldnames=list(rows[0]))
        writer.writeheader()
        writer.writerows(rows)
    print(f"\n{args.width}x{args.height}, {args.frames} frames a run, {args.rounds} round(s); wall ms a frame")
    print("| scene | engine (median) | plain (median) | ratio of medians | rounds' ratios |")
    print("| --- | ---: | ---: | ---: | ---: |")
    for scene in scenes:
        mine = [r for r in rows if r["scene"] == scene]
        engine = statistics.median(r["engine_wall_ms"] for r in mine)
        plain = statistics.median(r["plain_wall_ms"] for r in mine)
        ratios = [r["ratio"] for r in mine]
        print(f"| {scene} | {engine:.2f} | {plain:.2f} | {engine / plain:.2f} | {min(ratios):.2f}-{max(ratios):.2f} |")
    print(f"\nwrote {csv_path}")


if __name__ == "__main__":
    main()
