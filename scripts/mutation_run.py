#!/usr/bin/env python3
"""Feeds mechanist mutated inputs and counts how it ends: every run must exit with 0, 1 or 2.

Usage: scripts/mutation_run.py [--step N] [--json N] [--seed S] [--jobs J] [--mechanist PATH]
                               [--keep DIR]

Mutates STEP files of ../shared/data (AS1 and the smaller real exports) and the examples'
assembly files and meshes the way damaged files look: bytes flipped, ranges deleted or
duplicated, truncation, numbers replaced by nan, 1e308 or -1, STEP entity lines deleted. Each
mutant goes through `mechanist validate` and `mechanist analyze` (with `--read-timeout 20`, and
a 60 s bound on the whole run). Prints the
exit codes counted and every run that ended otherwise (a signal, a time-out, exit 3); with
--keep, those inputs are kept in DIR. Exit status 1 when any run ended otherwise.
"""
import argparse
import collections
import concurrent.futures
import os
import random
import re
import shutil
import subprocess
import sys
import tempfile

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
SHARED = os.path.join(os.path.dirname(ROOT), "shared", "data")
STEP_SOURCES = [
    "step/as1_pe_203.stp",
    "real/revolute_pin_solidedge_chrono/assembly.stp",
    "real/hinge_clamshell_build123d/clamshell_full.step",
    "real/cycloid_7pin_6lobe_onshape/Full Assembly.step",
    "real/spur_pair_20T_40T_solidworks/ISO standard Spur Gear Drive (2-1 ratio).STEP",
]
NUMBER = re.compile(rb"-?\d+\.?\d*(?:[eE][-+]?\d+)?")


def mutate(data, rng, step):
    kind = rng.choice(["flip", "delete", "duplicate", "truncate", "number"] +
                      (["entity", "entity"] if step else []))
    if kind == "flip":
        data = bytearray(data)
        for _ in range(rng.randint(1, 8)):
            data[rng.randrange(len(data))] = rng.randrange(256)
        return bytes(data), kind
    if kind in ("delete", "duplicate"):
        a = rng.randrange(len(data))
        b = min(len(data), a + rng.randint(1, 400))
        return (data[:a] + data[b:] if kind == "delete" else data[:b] + data[a:b] + data[b:]), kind
    if kind == "truncate":
        return data[:rng.randrange(len(data))], kind
    if kind == "number":
        spots = [m.span() for m in NUMBER.finditer(data[:200000])]
        if not spots:
            return data, kind
        a, b = rng.choice(spots)
        return data[:a] + rng.choice([b"nan", b"1e308", b"-1", b"0", b"-1e308", b"inf"]) + data[b:], kind
    lines = data.split(b"\n")
    entities = [i for i, l in enumerate(lines) if l.startswith(b"#")]
    for i in rng.sample(entities, min(len(entities), rng.randint(1, 4))):
        lines[i] = b""
    return b"\n".join(lines), kind


def run(mechanist, path):
    results = []
    for command in (["validate"], ["analyze"]):
        try:
            r = subprocess.run([mechanist, "--read-timeout", "20"] + command + [path],
                               stdout=subprocess.DEVNULL,
                               stderr=subprocess.PIPE, timeout=60)
            results.append((command[0], r.returncode, r.stderr[-300:].decode(errors="replace")))
        except subprocess.TimeoutExpired:
            results.append((command[0], "timeout", ""))
    return results


def make_mutant(rng, family, folder, examples):
    """Writes one mutant into its own folder; returns the file to run and the file mutated."""
    os.makedirs(folder)
    if family == "step":
        source = os.path.join(SHARED, rng.choice(STEP_SOURCES))
        data, kind = mutate(open(source, "rb").read(), rng, True)
        path = os.path.join(folder, "mutant.stp")
        open(path, "wb").write(data)
        return path, path, kind
    target = os.path.join(folder, "example")
    shutil.copytree(os.path.join(ROOT, "examples", rng.choice(examples)), target)
    files = sorted(os.path.join(dp, f) for dp, _, fs in os.walk(target) for f in fs
                   if f.endswith((".json", ".stl", ".obj", ".ply", ".off")))
    victim = rng.choice(files)
    data, kind = mutate(open(victim, "rb").read(), rng, False)
    open(victim, "wb").write(data)
    return os.path.join(target, "assembly.json"), victim, kind


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--step", type=int, default=1000)
    parser.add_argument("--json", type=int, default=1000)
    parser.add_argument("--seed", type=int, default=1)
    parser.add_argument("--jobs", type=int, default=1, help="mutants run at once")
    parser.add_argument("--mechanist", default=os.path.join(ROOT, "build", "cli", "mechanist"))
    parser.add_argument("--keep")
    args = parser.parse_args()
    rng = random.Random(args.seed)
    work = tempfile.mkdtemp(prefix="mechanist_mutants_")
    examples = sorted(d for d in os.listdir(os.path.join(ROOT, "examples")))
    plan = [("step", k) for k in range(args.step)] + [("json", k) for k in range(args.json)]
    # The mutants are made in order (a seed gives the same mutants whatever --jobs is), then run.
    mutants = [(family, k) + make_mutant(rng, family, os.path.join(work, str(n)), examples)
               for n, (family, k) in enumerate(plan)]
    counts = collections.Counter()
    bad = []
    with concurrent.futures.ThreadPoolExecutor(max_workers=args.jobs) as pool:
        runs = pool.map(lambda m: run(args.mechanist, m[2]), mutants)
        for n, ((family, k, path, victim, kind), results) in enumerate(zip(mutants, runs)):
            for command, code, err in results:
                counts[(family, command, code)] += 1
                if code not in (0, 1, 2):
                    bad.append((family, k, kind, command, code, err))
                    if args.keep:
                        os.makedirs(args.keep, exist_ok=True)
                        keep = os.path.join(args.keep, "%s_%d%s" % (family, k, os.path.splitext(victim)[1]))
                        shutil.copy(victim, keep)
            if sys.stderr.isatty():
                sys.stderr.write("\r%d/%d" % (n + 1, len(plan)))
    if sys.stderr.isatty():
        sys.stderr.write("\n")
    shutil.rmtree(work, ignore_errors=True)
    for key in sorted(counts, key=str):
        print("%s %s exit %s: %d" % (key[0], key[1], key[2], counts[key]))
    for b in bad:
        print("BAD %s #%d (%s) %s: %s %s" % b)
    print("%d runs, %d ended otherwise than 0, 1 or 2" % (sum(counts.values()), len(bad)))
    return 1 if bad else 0


if __name__ == "__main__":
    sys.exit(main())
