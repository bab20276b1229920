#!/usr/bin/env bash
# Renders the same three-map Sierpinski gasket (f_i(z) = z/2 + v_i/2, v = (0,0), (1,0),
# (0.5,1); bench/sierpinski-plane.awb), then a flame of three non-linear xforms (imported as a
# flame item), each at equal sample counts and threads with flam3-render
# (Debian flam3-utils, installed here if missing) and with `attractor-cli render`, both into a
# 1024 x 1024 raster, and prints both rates, their ratio and the peak memory of each.
# Usage: bench/compare-flam3.sh [SAMPLES (default 1e9)] [THREADS (default 1)] [RUNS (default 1)]
# With RUNS > 1 each comparison runs that many times, the two programs one after the other each
# time (a shared machine's speed drifts: the ratio of a pair is steadier than either time), and
# the median ratio is printed after the runs.
set -euo pipefail
cd "$(dirname "$0")/.."
SAMPLES=${1:-1000000000}
THREADS=${2:-1}
RUNS=${3:-1}
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
palette() { for i in $(seq 0 255); do echo "  <color index=\"$i\" rgb=\"$i 60 $((255 - i))\"/>"; done; }
head_of() {  # NAME CX CY SCALE
  echo "<flame name=\"$1\" size=\"$SIDE $SIDE\" center=\"$2 $3\" scale=\"$4\""
  echo "  quality=\"$QUALITY\" oversample=\"1\" filter=\"0\" supersample=\"1\" temporal_samples=\"1\""
  echo "  brightness=\"4\" gamma=\"2.2\" vibrancy=\"1\" background=\"1 1 1\" estimator_radius=\"0\">"
}
{
  head_of sierpinski 0.5 0.5 $SIDE
  # flam3 coefs are \"a d b e c f\": x' = a x + b y + c, y' = d x + e y + f.
  echo '  <xform weight="1" color="0" linear="1" coefs="0.5 0 0 0.5 0 0"/>'
  echo '  <xform weight="1" color="0.5" linear="1" coefs="0.5 0 0 0.5 0.5 0"/>'
  echo '  <xform weight="1" color="1" linear="1" coefs="0.5 0 0 0.5 0.25 0.5"/>'
  palette
  echo "</flame>"
} > "$tmp/sierpinski.flam3"
# Variation-heavy: every xform non-linear (spherical, julian with its power and branch, swirl,
# sinusoidal, a post map): the flame item's own chaos game (issue 45).
{
  head_of variations 0 0 $((SIDE / 4))
  echo '  <xform weight="1" color="0" linear="0.4" spherical="0.6" coefs="0.5 0 0 0.5 0 0"/>'
  echo '  <xform weight="1" color="0.5" julian="1" julian_power="3" julian_dist="1" coefs="0.5 0.1 -0.1 0.5 0.5 0"/>'
  echo '  <xform weight="1" color="1" swirl="0.5" sinusoidal="0.5" coefs="0.5 0 0 0.5 0.25 0.5" post="0.9 0.1 -0.1 0.9 0 0"/>'
  palette
  echo "</flame>"
} > "$tmp/variations.flam3"
build/bin/attractor-cli import "$tmp/variations.flam3" --out "$tmp/variations.awb" >/dev/null

now() { date +%s.%N; }
compare() {  # TITLE FLAME PROJECT SIZE
  local t0 t1 t2 run ratios=""
  for run in $(seq "$RUNS"); do
    t0=$(now)
    /usr/bin/time -f %M -o "$tmp/flam3.rss" env nthreads="$THREADS" ss=1 qs=1 isaac_seed=1 \
      out="$tmp/flam3.png" format=png verbose=0 flam3-render < "$2" >/dev/null 2>&1
    t1=$(now)
    # An IFS item's panel is the raster plus 16 px of margin and a 26 px caption; a flame item
    # writes its picture alone, with flam3's tone (filters, estimator, gamma), as flam3 does.
    /usr/bin/time -f %M -o "$tmp/awb.rss" build/bin/attractor-cli render "$3" \
      --samples "$SAMPLES" --threads "$THREADS" --size "$4" \
      --out "$tmp/awb.png" >/dev/null
    t2=$(now)
    ratios="$ratios $(awk -v a="$t0" -v b="$t1" -v c="$t2" 'BEGIN { printf "%.4f", (b - a) / (c - b) }')"
    awk -v title="$1" -v s="$SAMPLES" -v th="$THREADS" -v a="$t0" -v b="$t1" -v c="$t2" \
        -v rf="$(cat "$tmp/flam3.rss")" -v ra="$(cat "$tmp/awb.rss")" -v side=$SIDE \
        -v run="$run" -v runs="$RUNS" 'BEGIN {
      f = s / (b - a) / 1e6; w = s / (c - b) / 1e6;
      printf "compare-flam3: %s, %dx%d raster, %.3g samples, %d thread(s)", title, side, side, s, th;
      if (runs > 1) printf ", run %d of %d", run, runs;
      printf "\n";
      printf "  flam3-render          %8.2f s  %8.1f Msamples/s  peak RSS %6.1f MB\n", b - a, f, rf / 1024;
      printf "  attractor-cli render  %8.2f s  %8.1f Msamples/s  peak RSS %6.1f MB\n", c - b, w, ra / 1024;
      printf "  ratio (attractor-cli / flam3)  %.2fx\n", w / f;
    }'
  done
  if [ "$RUNS" -gt 1 ]; then
    echo "$ratios" | tr ' ' '\n' | grep . | sort -g | awk -v title="$1" '{ r[NR] = $1 }
      END { m = NR % 2 ? r[(NR + 1) / 2] : (r[NR / 2] + r[NR / 2 + 1]) / 2;
            printf "compare-flam3: %s: median ratio of %d runs %.2fx (%.2f-%.2fx)\n", title, NR, m, r[1], r[NR] }'
  fi
}
compare "Sierpinski, 3 linear maps" "$tmp/sierpinski.flam3" bench/sierpinski-plane.awb \
  $((SIDE + 16))x$((SIDE + 8 + 26))
compare "3 xforms of non-linear variations (a flame item)" "$tmp/variations.flam3" \
  "$tmp/variations.awb" ${SIDE}x${SIDE}
