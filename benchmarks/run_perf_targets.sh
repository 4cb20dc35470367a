#!/usr/bin/env bash
# The performance targets in one run (about 3-5 minutes on the GPU machine): the engine's CPU path and GPU-driven
# path at 1k/10k against the raw ceiling, 100k and 1M cubes turned on the GPU, 100k static models with one moving,
# one entity, the frame's Python at 1k, with GPU ms per pass (--gpu-passes) and the GPU memory the renderer
# holds in the JSON; then the same scenes and raw ceiling again with two frames in flight (each
# frame waits for the one before: --sync inflight / SYNC=inflight). Writes scenes-*.json, raw*.jsonl,
# frame-cost-*.json, targets.md/json and log.txt into the folder given (default: $OUT); where nvidia-smi is there,
# also clocks.csv: the GPU's SM and memory clocks, load and power every 100 ms while the run lasts (a captured
# frame timed slower than the measured ones can then be checked against the clocks).
# usage: bash benchmarks/run_perf_targets.sh [OUT_DIR] [PYTHON]
set -u
out="${1:-${OUT:-perf-out}}"
py="${2:-python3}"
mkdir -p "$out"
out="$(cd "$out" && pwd)"  # absolute: the runs below start from the repository root
cd "$(dirname "$0")/.."
common=(--frames 300 --warmup 30 --max-seconds 3 --size 1280x720)
timed=(--gpu-passes 20)  # then 20 frames more through the frame inspector's timer: GPU ms per pass, beside the fps
clocks=""
if command -v nvidia-smi > /dev/null; then
  nvidia-smi --query-gpu=timestamp,clocks.sm,clocks.mem,utilization.gpu,power.draw --format=csv -lms 100 \
      > "$out/clocks.csv" 2>&1 &
  clocks=$!
  trap 'kill "$clocks" 2> /dev/null' EXIT
fi
{
  "$py" benchmarks/bench_scenes.py "${common[@]}" --scenes scene1,cubes1k,cubes10k,static100k --rotate batch \
      "${timed[@]}" --json "$out/scenes-cpu.json"
  "$py" benchmarks/bench_scenes.py "${common[@]}" --scenes cubes1k,cubes10k --rotate angle \
      "${timed[@]}" --json "$out/scenes-angle.json"
  "$py" benchmarks/bench_scenes.py "${common[@]}" --scenes cubes1k,cubes10k,cubes100k,cubes1m --rotate gpu \
      "${timed[@]}" --json "$out/scenes-gpu.json"
  NS=1,1000,10000,100000 "$py" benchmarks/raw_ceiling.py both 1280 720 300 > "$out/raw.jsonl"
  inflight=("${common[@]}" --sync inflight)
  "$py" benchmarks/bench_scenes.py "${inflight[@]}" --scenes scene1,cubes1k,cubes10k,static100k --rotate batch \
      --json "$out/scenes-inflight-cpu.json"
  "$py" benchmarks/bench_scenes.py "${inflight[@]}" --scenes cubes1k,cubes10k,cubes100k,cubes1m --rotate gpu \
      --json "$out/scenes-inflight-gpu.json"
  SYNC=inflight NS=1,1000,10000,100000 "$py" benchmarks/raw_ceiling.py both 1280 720 300 > "$out/raw-inflight.jsonl"
  for api in opengl webgpu; do
    "$py" benchmarks/bench_frame_cost.py --backend "$api" --frames 1000 --json "$out/frame-cost-$api.json"
  done
  "$py" benchmarks/perf_targets.py "$out"
} 2>&1 | tee "$out/log.txt"
