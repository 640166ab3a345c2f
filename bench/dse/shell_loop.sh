#!/usr/bin/env bash
# The baseline for `swarmcheck dse`'s throughput: what a user does without it, one
# `swarmcheck run` per run from a shell loop, each with its own scenario file. The runs are
# exactly those of a DSE configuration beside this script, so the two rates compare the same work:
#
#   big     200 runs = loop-40.dse.json on lattice-64.json: 100 robots on 64^2, stochastic,
#           abstract, max_steps 4000; ertu_perc 0.01, max_ph x a1 (4 x 10), seeds 1..5
#   thesis  200 runs = thesis-200.dse.json on scenarios/thesis/dse/base.json: the thesis set-up
#           (map 10, 4 robots, rule thesis, abstract, 199 steps), ertu_perc 0.001 .. 0.200
#
#   bench/dse/shell_loop.sh big|thesis [BINARY] [PARALLEL]    (from the repository root)
#     BINARY    default build/bin/swarmcheck;  PARALLEL  processes at once (xargs -P), default 1
# Prints wall seconds, runs/s and the CPU seconds of all the processes.
set -euo pipefail
which=${1:?usage: shell_loop.sh big|thesis [BINARY] [PARALLEL]}
bin=$(realpath "${2:-build/bin/swarmcheck}")
parallel=${3:-1}
here=$(cd "$(dirname "$0")" && pwd)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

case "$which" in
  big)
    robots=""   # lattice-64.json's: a 10 x 10 lattice, cell (3 + 6 i, 3 + 6 j)
    for i in $(seq 0 9); do
      for j in $(seq 0 9); do robots+="${robots:+,}[$((3 + 6 * i)).5, $((3 + 6 * j)).5]"; done
    done
    robots="[$robots]"
    n=0
    for max_ph in 0.5 1 1.5 2; do
      for a1 in 0.25 0.5 0.75 1 1.25 1.5 1.75 2 2.25 2.5; do
        for seed in 1 2 3 4 5; do
          cat >"$work/p$n.json" <<EOF
{"map_size": 64, "robots": $robots, "rule": "stochastic", "mode": "abstract", "seed": $seed, "max_steps": 4000,
 "params": {"ertu": 0.01, "max_ph": $max_ph, "a1": $a1}}
EOF
          n=$((n + 1))
        done
      done
    done ;;
  thesis)
    base="$here/../../scenarios/thesis/dse/base.json"
    n=0
    for ertu in $(seq 0.001 0.001 0.200); do
      sed "s/\"ertu\": [0-9.]*/\"ertu\": $ertu/" "$base" >"$work/p$n.json"
      n=$((n + 1))
    done ;;
  *) echo "shell_loop.sh: expected big or thesis, got $which" >&2; exit 2 ;;
esac

runs=$(ls "$work"/*.json | wc -l)
start=$(date +%s.%N)
cpu_before=$(awk '{print $14 + $15 + $16 + $17}' /proc/$$/stat)
ls "$work"/*.json | xargs -P "$parallel" -I{} sh -c "'$bin' run {} --json > {}.out"
end=$(date +%s.%N)
ticks=$(getconf CLK_TCK)
cpu=$(awk -v t="$ticks" -v b="$cpu_before" '{printf "%.2f", ($14 + $15 + $16 + $17 - b) / t}' /proc/$$/stat)
echo "$runs runs of swarmcheck run from a shell loop ($parallel at a time): $(echo "$end - $start" | bc) s wall," \
     "$(echo "scale=1; $runs / ($end - $start)" | bc) runs/s, $cpu CPU s"
