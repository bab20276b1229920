#!/usr/bin/env bash
# Renders the same three-map Sierpinski gasket (f_i(z) = z/2 + v_i/2, v = (0,0), (1,0),
# (0.5,1); bench/sierpinski-plane.awb) at equal sample counts and threads with flam3-render
# (Debian flam3-utils, installed here if missing) and with `attractor-cli render`, both into a
# 1024 x 1024 raster, and prints both rates, their ratio and the peak memory of each.
# Usage: bench/compare-flam3.sh [SAMPLES (default 1e9)] [THREADS (default 1)]
set -euo pipefail
cd "$(dirname "$0")/.."
SAMPLES=${1:-1000000000}
THREADS=${2:-1}
as_root() { if [ "$(id -u)" -eq 0 ]; then "$@"; else sudo "$@"; fi; }
if ! command -v flam3-render >/dev/null; then
  as_root apt-get install -y -q flam3-utils >/dev/null
fi
[ -x build/bin/attractor-cli ] || bash scripts/setup.sh >/dev/null
[ -x /usr/bin/time ] || as_root apt-get install -y -q time >/dev/null

tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
SIDE=1024
# flam3 draws quality x pixels samples.
QUALITY=$(awk -v s="$SAMPLES" -v p=$((SIDE * SIDE)) 'BEGIN { printf "%.6f", s / p }')
{
  echo "<flame name=\"sierpinski\" size=\"$SIDE $SIDE\" center=\"0.5 0.5\" scale=\"$SIDE\""
  echo "  quality=\"$QUALITY\" oversample=\"1\" filter=\"0\" supersample=\"1\" temporal_samples=\"1\""
  echo "  brightness=\"4\" gamma=\"2.2\" vibrancy=\"1\" background=\"1 1 1\" estimator_radius=\"0\">"
  # flam3 coefs are \"a d b e c f\": x' = a x + b y + c, y' = d x + e y + f.
  echo '  <xform weight="1" color="0" linear="1" coefs="0.5 0 0 0.5 0 0"/>'
  echo '  <xform weight="1" color="0.5" linear="1" coefs="0.5 0 0 0.5 0.5 0"/>'
  echo '  <xform weight="1" color="1" linear="1" coefs="0.5 0 0 0.5 0.25 0.5"/>'
  for i in $(seq 0 255); do
    echo "  <color index=\"$i\" rgb=\"$i 60 $((255 - i))\"/>"
  done
  echo "</flame>"
} > "$tmp/sierpinski.flam3"

now() { date +%s.%N; }
t0=$(now)
/usr/bin/time -f %M -o "$tmp/flam3.rss" env nthreads="$THREADS" ss=1 qs=1 isaac_seed=1 \
  out="$tmp/flam3.png" format=png verbose=0 flam3-render < "$tmp/sierpinski.flam3" >/dev/null 2>&1
t1=$(now)
# The CLI's panel is the raster plus 16 px of margin; 26 px caption below.
/usr/bin/time -f %M -o "$tmp/awb.rss" build/bin/attractor-cli render bench/sierpinski-plane.awb \
  --samples "$SAMPLES" --threads "$THREADS" --size $((SIDE + 16))x$((SIDE + 8 + 26)) \
  --out "$tmp/awb.png" >/dev/null
t2=$(now)
awk -v s="$SAMPLES" -v th="$THREADS" -v a="$t0" -v b="$t1" -v c="$t2" \
    -v rf="$(cat "$tmp/flam3.rss")" -v ra="$(cat "$tmp/awb.rss")" 'BEGIN {
  f = s / (b - a) / 1e6; w = s / (c - b) / 1e6;
  printf "compare-flam3: Sierpinski, 3 maps, %dx%d raster, %.3g samples, %d thread(s)\n", 1024, 1024, s, th;
  printf "  flam3-render          %8.2f s  %8.1f Msamples/s  peak RSS %6.1f MB\n", b - a, f, rf / 1024;
  printf "  attractor-cli render  %8.2f s  %8.1f Msamples/s  peak RSS %6.1f MB\n", c - b, w, ra / 1024;
  printf "  ratio (attractor-cli / flam3)  %.2fx\n", w / f;
}'
