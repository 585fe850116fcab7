#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""Sandbox builds compared on the same frames, interleaved: each round runs every scene with every
build in turn, so that all of them see the machine in the same minutes (hosts of one kind can
differ by half from call to call, and one host's speed moves from round to round). Reads each
run's --stats: the GPU and CPU frame medians of the settled frames (of the whole run where it
never settled, which the row says), the light lists' pairs and the passes asked for. Prints each
run as it ends and, per scene and build, the rounds' range. Writes compare_builds.csv into --out.
Python's standard library only.

  python3 tools/compare/compare_builds.py before=old/shadowgraph-sandbox after=build/sandbox/shadowgraph-sandbox
  python3 tools/compare/compare_builds.py a=A b=B --scenes far,eye --rounds 3 --passes "shadow copy,light tiles"
  python3 tools/compare/compare_builds.py a=A b=B --scenes default --args "--render-scale 0.5"
  python3 tools/compare/compare_builds.py a=A b=A --quick --out compare-smoke   # a smoke test: its times mean nothing
"""
import argparse
import csv
import json
import os
import shlex
import subprocess
import sys

# The frames the project's performance notes measure (README, docs/PERFORMANCE.md).
HUNDRED_THOUSAND = ["--scene", "stress", "--width", "1920", "--height", "1080", "--point-lights", "50000",
                    "--spot-lights", "50000", "--moving-lights", "0.05", "--frames", "300"]
SCENES = {
    "far": HUNDRED_THOUSAND,
    "eye": HUNDRED_THOUSAND + ["--camera", "street"],
    "k1": ["--scene", "stress", "--width", "1920", "--height", "1080", "--point-lights", "512",
           "--spot-lights", "512", "--frames", "200", "--camera", "street"],
    "default": ["--scene", "default", "--width", "1280", "--height", "720", "--frames", "40",
                "--pipeline-builds", "in-frame"],
}
QUICK = ["--scene", "default", "--width", "160", "--height", "90", "--frames", "4"]


def parse_build(text):
    name, sep, path = text.partition("=")
    if not sep or not name or not path:
        raise argparse.ArgumentTypeError(f"a build is NAME=PATH to a sandbox binary, not '{text}'")
    if not os.access(path, os.X_OK):
        raise argparse.ArgumentTypeError(f"{path} is not an executable file")
    return name, path


def frame_figures(stats, passes):
    """The run's GPU and CPU frame medians, its list pairs and the passes matching `passes`."""
    settled = stats.get("settled")
    source = settled or stats
    row = {
        "settled": settled is not None,
        "gpu_ms": source["gpu_frame_ms"]["median"] if source.get("gpu_frame_ms") else None,
        "cpu_ms": source["cpu_frame_ms"]["median"],
        "light_list_pairs": (stats.get("light_list_pairs") or {}).get("median"),
    }
    for wanted in passes:
        times = [p["gpu_ms"]["median"] for p in source.get("passes") or stats.get("passes") or []
                 if wanted in p["name"] and p.get("gpu_ms")]
        row[wanted] = sum(times) if times else None
    return row


def text(value, digits=3):
    return "-" if value is None else f"{value:.{digits}f}"


def span(values, digits=3):
    values = [v for v in values if v is not None]
    if not values:
        return "-"
    low, high = min(values), max(values)
    return text(low, digits) if low == high else f"{text(low, digits)}-{text(high, digits)}"


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("builds", nargs="+", type=parse_build, metavar="NAME=PATH",
                        help="the sandbox binaries, named as the rows show them")
    parser.add_argument("--scenes", default="far,eye,k1",
                        help="comma-separated, of " + ", ".join(SCENES) + " (default: far,eye,k1)")
    parser.add_argument("--rounds", type=int, default=2, help="rounds of every scene and build (default: 2)")
    parser.add_argument("--args", default="", help="more sandbox options for every run, as one string")
    parser.add_argument("--passes", default="", help="comma-separated pass names (or parts of them) to report")
    parser.add_argument("--quick", action="store_true", help="one round of `default` at 160x90, 4 frames")
    parser.add_argument("--out", default="compare-builds", help="folder for the CSV and the runs' stats")
    args = parser.parse_args()
    names = [name for name, _ in args.builds]
    if len(set(names)) != len(names):
        parser.error("each build needs a name of its own")
    if args.quick:
        scenes, rounds = {"quick": QUICK}, 1
    else:
        names_asked = [s for s in args.scenes.split(",") if s]
        unknown = [s for s in names_asked if s not in SCENES]
        if unknown or not names_asked or args.rounds < 1:
            parser.error(f"--scenes takes {', '.join(SCENES)} (not {', '.join(unknown) or 'none'}); "
                         "--rounds at least 1")
        scenes, rounds = {s: SCENES[s] for s in names_asked}, args.rounds
    passes = [p.strip() for p in args.passes.split(",") if p.strip()]
    extra = shlex.split(args.args)
    os.makedirs(args.out, exist_ok=True)

    rows = []
    for round_index in range(1, rounds + 1):
        for scene, scene_args in scenes.items():
            for name, path in args.builds:
                stats_path = os.path.join(args.out, f"{scene}_{name}_{round_index}.json")
                command = [path, "--headless", *scene_args, *extra, "--stats", stats_path]
                done = subprocess.run(command, capture_output=True, text=True)
                if done.returncode != 0:
                    sys.stderr.write(done.stdout[-2000:] + done.stderr[-2000:])
                    sys.exit(f"compare_builds: {shlex.join(command)} failed with exit code {done.returncode}")
                with open(stats_path) as f:
                    row = {"scene": scene, "build": name, "round": round_index,
                           **frame_figures(json.load(f), passes)}
                rows.append(row)
                figures = " ".join(f"{p} {text(row[p])}" for p in passes)
                print(f"round {round_index} {scene} {name}: GPU {text(row['gpu_ms'])} ms, CPU "
                      f"{text(row['cpu_ms'], 2)} ms{'' if row['settled'] else ' (never settled)'}"
                      f"{', ' + figures if figures else ''}", flush=True)

    print(f"\n{rounds} round(s); settled medians, ms, the rounds' range")
    print("| scene | build | GPU frame | CPU frame | list pairs |" + "".join(f" {p} |" for p in passes))
    print("| --- | --- | ---: | ---: | ---: |" + " ---: |" * len(passes))
    for scene in scenes:
        for name in names:
            mine = [r for r in rows if r["scene"] == scene and r["build"] == name]
            cells = [span([r["gpu_ms"] for r in mine]), span([r["cpu_ms"] for r in mine], 2),
                     span([r["light_list_pairs"] for r in mine], 0)] + [span([r[p] for r in mine]) for p in passes]
            print(f"| {scene} | {name} | " + " | ".join(cells) + " |")

    csv_path = os.path.join(args.out, "compare_builds.csv")
    with open(csv_path, "w", newline="") as f:
        writer = csv.DictWriter(f, fieldnames=["scene", "build", "round", "settled", "gpu_ms", "cpu_ms",
                                               "light_list_pairs", *passes])
        writer.writeheader()
        writer.writerows(rows)
    print(f"wrote {csv_path}")


if __name__ == "__main__":
    main()
