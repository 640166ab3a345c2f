#!/usr/bin/env python3
"""Writes a scenario of N robots on distinct cells of an M x M map (no obstacles), chosen by a
seeded shuffle, to standard output: the swarm the README's speed figures run.
    python3 scenarios/examples/generate_swarm.py 10000 256 > swarm.json
    swarmcheck run swarm.json --body intocps --steps 100
"""
import json
import random
import sys


def main():
    if len(sys.argv) != 3:
        sys.exit("usage: generate_swarm.py ROBOTS MAP_SIZE")
    robots, size = int(sys.argv[1]), int(sys.argv[2])
    if not (1 <= robots <= size * size):
        sys.exit(f"generate_swarm.py: expected 1 <= ROBOTS <= MAP_SIZE^2 = {size * size}, got {robots}")
    cells = random.Random(1).sample(range(size * size), robots)
    scenario = {"map_size": size, "robots": [[c // size + 0.5, c % size + 0.5] for c in cells]}
    json.dump(scenario, sys.stdout, separators=(",", ":"))
    sys.stdout.write("\n")


if __name__ == "__main__":
    main()
