#!/usr/bin/env python3
"""Writes a particle-life rules file (the web app's JSON schema) from a seed, with the same
splitmix32 generator as src/sim/life/life_rules.cpp, so that presets in assets/rules/ are
exactly what `generateRules` makes for their seed (tests/sim/life/life_rules_test.cpp checks).

  scripts/make_life_rules.py --seed 2 --species 8 --count 65536 --size 1024 576 > assets/rules/x.json
"""
import argparse
import json
import struct


def f32(x):
    return struct.unpack("<f", struct.pack("<f", x))[0]


def splitmix32(seed):
    state = seed & 0xFFFFFFFF

    def nxt():
        nonlocal state
        state = (state + 0x9E3779B9) & 0xFFFFFFFF
        t = state ^ (state >> 16)
        t = (t * 0x21F0AAAD) & 0xFFFFFFFF
        t ^= t >> 15
        t = (t * 0x735A2D97) & 0xFFFFFFFF
        t ^= t >> 15
        return t / 4294967296.0

    return nxt


def generate(a):
    rng = splitmix32(a.seed)
    keys = ("strength", "collisionStrength", "radius", "collisionRadius")
    species, table = [], []
    for _ in range(a.species):
        color = [f32((0.25 + 0.75 * rng()) ** 2.2) for _ in range(3)] + [1.0]
        row = []
        for _ in range(a.species):
            strength = 100.0 * (0.25 + 0.75 * rng())
            strength *= 1.0 if rng() < 0.5 else -1.0
            collision = (5.0 + 15.0 * rng()) * abs(strength)
            radius = 2.0 + rng() * 30.0
            collision_radius = rng() * 0.5 * radius
            row.append([strength, collision, radius, collision_radius])
        table.append(row)
        species.append({"color": color, "forces": None, "spawnWeight": f32(rng())})
    if a.symmetric:  # in double, as the app's symmetrizeForces
        for i in range(a.species):
            for j in range(i + 1, a.species):
                for k in range(4):
                    table[i][j][k] = table[j][i][k] = (table[i][j][k] + table[j][i][k]) / 2.0
    for i, s in enumerate(species):
        s["forces"] = [{key: f32(v) for key, v in zip(keys, f)} for f in table[i]]
    return {"particleCount": a.count, "species": species, "simulationSize": a.size,
            "friction": a.friction, "centralForce": a.central, "symmetricForces": a.symmetric,
            "loopingBorders": a.looping, "seed": a.seed}


def main():
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("--seed", type=int, required=True)
    p.add_argument("--species", type=int, default=8)
    p.add_argument("--count", type=int, default=65536)
    p.add_argument("--size", type=float, nargs=2, default=[1024.0, 576.0])
    p.add_argument("--friction", type=float, default=10.0)
    p.add_argument("--central", type=float, default=0.0)
    p.add_argument("--symmetric", action="store_true")
    p.add_argument("--looping", action="store_true")
    print(json.dumps(generate(p.parse_args()), indent=2))


if __name__ == "__main__":
    main()
