#!/usr/bin/env bash
# Soak test of the viewer (not part of CI): `throng view` under Xvfb with the validation layer,
# the coverage LOD and the motion cache on, replaying an input script in a loop for SECONDS
# (default 600): respawns (random and circle scenes, changing sizes), the LOD and the cache
# switched off and on again (`lod`, `cache`), window resizes, camera orbits, pans, zooms,
# flights and presets, pause and vsync toggles. It samples the viewer's resident memory (VmRSS)
# every 5 s and reports its growth after warm-up: the largest VmRSS of the last minute against
# the largest of the minute after warm-up (the first fifth of the run), so both windows hold
# whole script cycles (shorter runs: windows of a quarter of the run). Exits 1 when the growth
# exceeds 5% or the validation layer printed any message (or the viewer failed).
#   scripts/soak.sh [SECONDS]      THRONG_BIN=path/to/throng to use another build
set -euo pipefail
cd "$(dirname "$0")/.."

seconds=${1:-600}
[[ "$seconds" =~ ^[1-9][0-9]*$ ]] && [ "$seconds" -ge 30 ] || {
  echo "usage: scripts/soak.sh [SECONDS >= 30]" >&2
  exit 2
}
throng=$(realpath "${THRONG_BIN:-build/bin/throng}")
[ -x "$throng" ] || { echo "error: $throng not found: build it first (scripts/build.sh)" >&2; exit 2; }
command -v Xvfb > /dev/null || { echo "error: Xvfb not found (scripts/install_deps.sh)" >&2; exit 2; }
readonly kSampleSeconds=5 kMaxGrowthPercent=5

work=$(mktemp -d /tmp/throng-soak-XXXXXX)
xvfb_pid=""
viewer_pid=""
cleanup() {
  [ -n "$viewer_pid" ] && kill "$viewer_pid" 2> /dev/null || true
  [ -n "$xvfb_pid" ] && kill "$xvfb_pid" 2> /dev/null || true
  wait 2> /dev/null || true
  rm -rf "$work"
}
trap cleanup EXIT

# A private X server on a free display number.
for n in $(seq 150 199); do
  [ -e "/tmp/.X11-unix/X$n" ] || [ -e "/tmp/.X$n-lock" ] && continue
  Xvfb ":$n" -screen 0 1600x1200x24 -nolisten tcp > /dev/null 2>&1 &
  xvfb_pid=$!
  for _ in $(seq 50); do
    [ -e "/tmp/.X11-unix/X$n" ] && break
    sleep 0.1
  done
  if kill -0 "$xvfb_pid" 2> /dev/null && [ -e "/tmp/.X11-unix/X$n" ]; then
    export DISPLAY=":$n"
    break
  fi
  xvfb_pid=""
done
[ -n "$xvfb_pid" ] || { echo "error: could not start Xvfb on any display :150..:199" >&2; exit 1; }
export XDG_RUNTIME_DIR=$work LP_NUM_THREADS=${LP_NUM_THREADS:-2}

# One cycle of the script (about 280 frames). It ends with the LOD and the cache on, as it starts.
cat > "$work/cycle.txt" << 'SCRIPT'
respawn 3000 random
drag 640 360 760 380 20
scroll 2
key W 20
key 3
resize 960 540
wait 30
drag 400 300 300 250 15 right
cache off
respawn 1500 circle
key 1
lod off
resize 1280 720
scroll -2
drag 600 200 500 260 10 middle
key 4
key SPACE
wait 10
key SPACE
key V
wait 20
key V
lod on
key SHIFT 5
key S 20
key 2
cache on
respawn 2500
resize 1024 768
key R
lod off
wait 20
lod on
wait 40
resize 1280 720
wait 30
SCRIPT
cycle_frames=$(awk '
  $1 == "wait" { f += $2 } $1 == "drag" { f += ($6 == "" ? 10 : $6) + 1 }
  $1 == "key" { f += ($3 == "" ? 1 : $3) + 1 }
  $1 ~ /^(scroll|resize|respawn|lod|cache|close)$/ { f += 1 }
  END { print f }' "$work/cycle.txt")

view() {  # FRAMES SCRIPT LOG: runs the viewer in the background, sets viewer_pid
  "$throng" view --validation --lod --cache --clock real --frames "$1" --input-script "$2" \
    > "$3" 2>&1 &
  viewer_pid=$!
}
script_of() {  # CYCLES OUT
  : > "$2"
  for _ in $(seq "$1"); do cat "$work/cycle.txt" >> "$2"; done
}

# Calibration: two cycles give the frame rate, so the soak's frame count lasts about SECONDS.
script_of 2 "$work/calibrate.txt"
start=$(date +%s.%N)
view $((2 * cycle_frames)) "$work/calibrate.txt" "$work/calibrate.log"
status=0
wait "$viewer_pid" || status=$?
viewer_pid=""
elapsed=$(awk -v a="$start" -v b="$(date +%s.%N)" 'BEGIN { printf "%.1f", b - a }')
if [ "$status" -ne 0 ]; then
  echo "soak: the calibration run failed (exit $status):" >&2
  tail -20 "$work/calibrate.log" >&2
  exit 1
fi
frames=$(awk -v s="$seconds" -v f=$((2 * cycle_frames)) -v e="$elapsed" 'BEGIN { printf "%d", s * f / e }')
cycles=$((frames / cycle_frames + 1))
script_of "$cycles" "$work/soak.txt"
echo "soak: ${cycle_frames} frames per script cycle, $((2 * cycle_frames)) in ${elapsed%.*} s;" \
  "running $frames frames (~${seconds} s, $cycles cycles) on $DISPLAY"

start=$(date +%s)
view "$frames" "$work/soak.txt" "$work/soak.log"
: > "$work/rss.txt"
while kill -0 "$viewer_pid" 2> /dev/null; do
  rss=$(awk '/^VmRSS:/ { print $2 }' "/proc/$viewer_pid/status" 2> /dev/null || true)
  [ -n "$rss" ] && echo "$(($(date +%s) - start)) $rss" >> "$work/rss.txt"
  sleep "$kSampleSeconds"
done
status=0
wait "$viewer_pid" || status=$?
viewer_pid=""
duration=$(($(date +%s) - start))

messages=$(grep -c '^vulkan validation:' "$work/soak.log" || true)
window=$((duration / 4 < 60 ? duration / 4 : 60))
warmup=$((duration / 5 > window ? duration / 5 : window))
read -r base final growth < <(awk -v warm="$warmup" -v win="$window" -v end="$duration" '
  { t[NR] = $1; r[NR] = $2 }
  END {
    for (i = 1; i <= NR; ++i) {
      if (t[i] >= warm && t[i] < warm + win && r[i] > base) base = r[i]
      if (t[i] >= end - win && r[i] > final) final = r[i]
    }
    printf "%d %d %.2f\n", base, final, (base > 0 ? 100 * (final - base) / base : 0)
  }' "$work/rss.txt")
mkdir -p build-soak && cp "$work/rss.txt" build-soak/rss.txt
echo "soak: $frames frames in $duration s, viewer exit $status"
echo "soak: largest VmRSS after warm-up ($warmup-$((warmup + window)) s) $((base / 1024)) MB," \
  "in the last $window s $((final / 1024)) MB: growth ${growth}% (limit ${kMaxGrowthPercent}%)"
echo "soak: validation messages: $messages; RSS samples (s, kB) in build-soak/rss.txt"
failed=0
if [ "$status" -ne 0 ] || [ "$messages" -ne 0 ]; then
  grep -m5 -E '^vulkan validation:|^error' "$work/soak.log" >&2 || tail -5 "$work/soak.log" >&2
  failed=1
fi
awk -v g="$growth" -v limit="$kMaxGrowthPercent" 'BEGIN { exit !(g > limit) }' && failed=1
[ "$failed" -eq 0 ] && echo "soak: passed" || echo "soak: FAILED"
exit "$failed"
