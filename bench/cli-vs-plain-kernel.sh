#!/usr/bin/env bash
# The comparison picture of bench/compare-flam3.sh (the three-map Sierpinski, coloured by map,
# 1024 x 1024) rendered end to end by `attractor-cli render` on 1 and 2 threads, set against
# the plain chaos-game kernel of `attractor-bench --quick` (one colour, 4-byte counts) and the
# engine's own lines, alternating in ROUNDS rounds: on a shared host whose rates swing by 2x
# within minutes, only figures of the same round compare. Prints one line a round.
# Usage: bench/cli-vs-plain-kernel.sh [ROUNDS (default 5)] [SAMPLES (default 1e9)]
set -euo pipefail
cd "$(dirname "$0")/.."
ROUNDS=${1:-5}
SAMPLES=${2:-1e9}
BIN=${AWB_BIN:-build/bin}
[ -x "$BIN/attractor-cli" ] && [ -x "$BIN/attractor-bench" ] || bash scripts/setup.sh >/dev/null
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
# The rate (Mpoints/s) of the bench line matching both patterns.
rate() {
  grep -F "$1" | grep -F "threads $2" |
    awk '{ for (i = 2; i <= NF; i++) if ($i == "Mpoints/s") { print $(i - 1); exit } }'
}
cli() {
  local t0 t1
  t0=$(date +%s.%N)
  "$BIN/attractor-cli" render bench/sierpinski-plane.awb --samples "$SAMPLES" --threads "$1" \
    --size 1040x1058 --out "$tmp/picture.png" >/dev/null
  t1=$(date +%s.%N)
  awk -v s="$SAMPLES" -v a="$t0" -v b="$t1" 'BEGIN { printf "%.1f", s / (b - a) / 1e6 }'
}
echo "cli-vs-plain-kernel: Sierpinski coloured by map, $SAMPLES samples, Mpoints/s"
for r in $(seq 1 "$ROUNDS"); do
  bench=$("$BIN/attractor-bench" --quick)
  p1=$(rate "plain kernel   chaos" 1 <<<"$bench"); p2=$(rate "plain kernel   chaos" 2 <<<"$bench")
  o1=$(rate "chaos game     Sierpinski in the plane" 1 <<<"$bench")
  o2=$(rate "chaos game     Sierpinski in the plane" 2 <<<"$bench")
  e1=$(rate "colour by map" 1 <<<"$bench"); e2=$(rate "colour by map" 2 <<<"$bench")
  c1=$(cli 1); c2=$(cli 2)
  awk -v r="$r" -v p1="$p1" -v p2="$p2" -v o1="$o1" -v o2="$o2" -v e1="$e1" -v e2="$e2" \
      -v c1="$c1" -v c2="$c2" 'BEGIN {
    printf "round %d: plain kernel %.0f | %.0f   engine one colour %.0f | %.0f   engine coloured %.0f | %.0f   cli coloured %.0f | %.0f (1 | 2 threads)   cli/plain %.2f   cli 2/1 threads %.2fx\n",
           r, p1, p2, o1, o2, e1, e2, c1, c2, c1 / p1, c2 / c1 }'
done
