#!/usr/bin/python3
"""Run seeds worked out independently of dvpr's C++, for the literals in the tests.

RunSeed(seed, robots, run) = MixSeed(MixSeed(seed, robots), run), where MixSeed(seed, key) is
one SplitMix64 step from state `seed`, then one more from state (its output XOR key)
(as sim/random_bits.h describes it). SplitMix64 is Steele, Lea and Flood's (2014), written here from
its published constants; the first check below is its widely quoted first output from state 0.

  run_seeds.py SEED ROBOTS... --runs R     prints "robots,run,seed" for every robots and run
"""
import argparse

MASK = (1 << 64) - 1


def splitmix64(state):
    """(new state, output) of one SplitMix64 step."""
    state = (state + 0x9E3779B97F4A7C15) & MASK
    z = state
    z = ((z ^ (z >> 30)) * 0xBF58476D1CE4E5B9) & MASK
    z = ((z ^ (z >> 27)) * 0x94D049BB133111EB) & MASK
    return state, z ^ (z >> 31)


def mix_seed(seed, key):
    _, first = splitmix64(seed)
    _, out = splitmix64(first ^ key)
    return out


def run_seed(seed, robots, run):
    return mix_seed(mix_seed(seed, robots), run)


assert splitmix64(0)[1] == 0xE220A8397B1DCDAF


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("seed", type=int)
    ap.add_argument("robots", type=int, nargs="+")
    ap.add_argument("--runs", type=int, required=True)
    a = ap.parse_args()
    for n in a.robots:
        for run in range(a.runs):
            print(f"{n},{run},{run_seed(a.seed, n, run)}")


if __name__ == "__main__":
    main()
