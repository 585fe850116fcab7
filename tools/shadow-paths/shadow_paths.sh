#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# Shadow work of the many-lights stress scenes on every shadow path, one binary, one run:
# per-light passes (the old way, the baseline), batched views with the raster hardware, and
# batched views rasterized in compute, with and without static layers. Prints one summary line per run (GPU frame, shadow work =
# the shadow passes' GPU time, CPU frame and its phases, views drawn and kept, memory) and keeps
# each run's --stats JSON and log in the output folder.
#
#   tools/shadow-paths/shadow_paths.sh [SANDBOX] [OUT_DIR]
#
# Defaults: build/sandbox/shadowgraph-sandbox and shadow-paths-out/. Run it on the device whose
# numbers you want; at 1920x1080 it takes a minute on an H200.
set -u
sandbox=${1:-build/sandbox/shadowgraph-sandbox}
out=${2:-shadow-paths-out}
mkdir -p "$out"
[ -x "$sandbox" ] || { echo "no sandbox at $sandbox (build it first)" >&2; exit 1; }

run() {  # name, then sandbox options
  local name=$1; shift
  echo "== $name: $*"
  if ! timeout 300 "$sandbox" --headless --width 1920 --height 1080 --screenshot "" \
      --stats "$out/$name.json" "$@" > "$out/$name.log" 2>&1; then
    echo "   failed (exit $?), see $out/$name.log"; return
  fi
  grep -E "CPU frame by phase|shadow atlas budget|validation errors" "$out/$name.log" | sed 's/^/   /'
  python3 - "$out/$name.json" <<'PY'
import json, sys
d = json.load(open(sys.argv[1]))
shadow = sum(p['gpu_ms']['median'] for p in d['passes'] if p['name'].startswith('shadow '))
s = d['shadows']
print('   GPU frame %.2f ms, shadow work %.2f ms, CPU frame %.2f ms, views drawn %.0f (moving casters only %.0f) '
      'kept %.0f, atlas %.0f MiB (tiles %.1f MiB), caster draws %d' % (
          d['gpu_frame_ms']['median'], shadow, d['cpu_frame_ms']['median'], s['views_rendered']['median'],
          s['views_moving_only']['median'], s['views_cached']['median'], d['shadow_map_bytes'] / 2**20,
          s['used_bytes'] / 2**20, s['caster_draws']))
PY
}

all_moving="--scene stress --point-lights 512 --spot-lights 512 --moving-lights 1"
run 1024_compute $all_moving --frames 20 --shadow-raster compute
run 1024_compute_no_layers $all_moving --frames 20 --shadow-raster compute --shadow-layers off
run 1024_hardware $all_moving --frames 20 --shadow-raster hardware
run 1024_per_light $all_moving --frames 12 --shadow-views per-light
run 1024_per_light_six $all_moving --frames 8 --shadow-views per-light --cube-shadows six
few_moving="--scene stress --point-lights 2048 --spot-lights 2048 --moving-lights 0.05"
run 4096_compute $few_moving --frames 40 --shadow-raster compute
run 4096_compute_no_layers $few_moving --frames 40 --shadow-raster compute --shadow-layers off
run 4096_hardware $few_moving --frames 30 --shadow-raster hardware
run 4096_per_light $few_moving --frames 20 --shadow-views per-light
run 4096_no_cache $few_moving --frames 10 --shadow-cache off --shadow-updates 0 --shadow-raster compute
run 100k --scene stress --scene-triangles 20000 --point-lights 50000 --spot-lights 50000 \
  --moving-lights 0.05 --frames 4
