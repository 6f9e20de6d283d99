#!/usr/bin/env python3
"""Floating-point work of full Newton per node-step, and the floor it implies (docs/measurements/data/speed_rounds.md).

    python3 bench/floor.py [BIN] [--nodes 241 961] [--work DIR]

Issue 16 estimated a floor for the cost of a node-step from the arithmetic a
step needs (about 900 flops for one residual, one substitution, and a
Jacobian with its factorisation every fifth step) at 130-200 ns, that is at
4.5-6.9 flops per ns. The rod keeps full Newton (a fresh Jacobian and its
factorisation at every iteration, about two iterations a step: docs/measurements/data/speed_rounds.md,
"Measured and not taken"), so its floor by the same reckoning is the
arithmetic full Newton does, at the same rate.

This program counts that arithmetic on the lean runs of bench/speed.py
(fast_180kN without gnuplot text and ledger, on 241 and 961 nodes):
callgrind collects instructions only inside the step's residual and Jacobian
(rod_problem_evaluate, with everything it calls), the factorisation
(band_factor) and the substitution (band_solve), with one count per
instruction address; the executable's disassembly gives each address's
mnemonic (libm's too). Scalar double additions, subtractions,
multiplications, divisions and square roots count one flop, their packed
forms one per lane, a fused multiply-add two; compares, moves, sign and
absolute-value masks count none. Prints a markdown table:
flops and instructions per node-step in each part, and the floor at 4.5-6.9
flops per ns. Needs valgrind and objdump.
"""
import argparse
import collections
import os
import re
import subprocess
import sys
import tempfile

import h5py

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
from speed import namelist  # noqa: E402

PARTS = [("residual and Jacobian", "__xcable_model_rod_MOD_rod_problem_evaluate"),
         ("factorisation", "__xcable_solver_banded_MOD_band_factor"),
         ("substitution", "__xcable_solver_banded_MOD_band_solve")]
FLOPS = {"addsd": 1, "subsd": 1, "mulsd": 1, "divsd": 1, "sqrtsd": 1,
         "addpd": 2, "subpd": 2, "mulpd": 2, "divpd": 2, "sqrtpd": 2}
# The rate: 900 flops in 130-200 ns.
RATE = (900 / 200, 900 / 130)


def flops_of(mnemonic, operands):
    """Flops of one instruction: SSE2 forms, their AVX forms (v...), and fused multiply-adds (libm's)."""
    lanes = 4 if "ymm" in operands else 2
    if mnemonic in FLOPS:
        return FLOPS[mnemonic]
    if mnemonic.startswith("v") and mnemonic[1:] in FLOPS:
        return 1 if mnemonic.endswith("sd") else lanes
    if re.match(r"vfn?m(add|sub)\d+(sd|pd)$", mnemonic):
        return 2 if mnemonic.endswith("sd") else 2*lanes
    return 0


def mnemonics(exe):
    """Address -> flops of every instruction of an executable or shared library."""
    out = subprocess.run(["objdump", "-d", "--no-show-raw-insn", exe], check=True, capture_output=True,
                         text=True).stdout
    table = {}
    for line in out.splitlines():
        m = re.match(r"\s*([0-9a-f]+):\s+(\S+)\s*(.*)", line)
        if m:
            table[int(m.group(1), 16)] = flops_of(m.group(2), m.group(3))
    return table


def count(exe, nml, work, function):
    """Instructions and flops executed inside `function` (with its callees, in the executable and in the
    shared libraries it calls, such as libm), and the instructions in the shared libraries."""
    out = os.path.join(work, "floor.%s.out" % function)
    subprocess.run(["valgrind", "--tool=callgrind", "--dump-instr=yes", "--toggle-collect=" + function,
                    "--callgrind-out-file=" + out, exe, nml], check=True, cwd=work,
                   stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    exe_name = os.path.realpath(exe)
    objects, tables, current, address, skip = {}, {}, None, 0, False
    instructions, flops, elsewhere = 0, 0, 0
    for line in open(out):
        line = line.rstrip("\n")
        if line.startswith(("ob=", "cob=")):
            m = re.match(r"c?ob=\((\d+)\)\s*(.*)", line)
            if m.group(2):
                objects[m.group(1)] = m.group(2)
            if line.startswith("ob="):
                current = objects[m.group(1)]
                if current not in tables:
                    tables[current] = mnemonics(current) if os.path.exists(current) else {}
            continue
        if line.startswith("calls="):
            skip = True  # the next cost line is a call's inclusive cost
            continue
        if not line or line[0] not in "+-*0123456789":
            continue
        fields = line.split()
        a = fields[0]
        if a.startswith("0x"):
            address = int(a, 16)
        elif a[0] in "+-":
            step = int(a[1:], 16) if a[1:].startswith("0x") else int(a[1:])
            address += step if a[0] == "+" else -step
        if skip:
            skip = False
            continue
        if len(fields) < 3 or current is None:
            continue
        ir = int(fields[2])
        instructions += ir
        flops += ir * tables[current].get(address, 0)
        if os.path.realpath(current) != exe_name:
            elsewhere += ir
    return instructions, flops, elsewhere


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("exe", nargs="?", default=os.path.join(os.path.dirname(HERE), "bin", "xcable"))
    ap.add_argument("--nodes", type=int, nargs="+", default=[241, 961])
    ap.add_argument("--work")
    a = ap.parse_args()
    work = a.work or tempfile.mkdtemp(prefix="xcable_floor_")
    os.makedirs(work, exist_ok=True)
    print("# Full Newton's arithmetic per node-step (lean fast_180kN, %s)\n" % a.exe)
    print("| nodes | steps | Newton iterations | part | instructions per node-step | flops per node-step | "
          "flops per instruction | in shared libraries (libm) |")
    print("|---:|---:|---:|---|---:|---:|---:|---:|")
    floors = []
    for nodes in a.nodes:
        nml = os.path.join(work, "lean_%d.nml" % nodes)
        h5 = os.path.join(work, "lean_%d.h5" % nodes)
        namelist(nodes, True, nml, h5)
        total_i, total_f = 0, 0
        rows = []
        for name, function in PARTS:
            ins, fl, elsewhere = count(a.exe, nml, work, function)
            rows.append((name, ins, fl, elsewhere))
            total_i += ins
            total_f += fl
        with h5py.File(h5, "r") as f:
            steps = int(f["summary"].attrs["steps"])
            iterations = int(f["summary"].attrs["newton_iterations"])
        ns = nodes * steps
        for name, ins, fl, elsewhere in rows + [("all three", total_i, total_f, sum(r[3] for r in rows))]:
            print("| %d | %d | %d | %s | %.0f | %.0f | %.2f | %.1f %% |" % (nodes, steps, iterations, name, ins / ns,
                                                                          fl / ns, fl / max(ins, 1),
                                                                          100.0 * elsewhere / max(ins, 1)))
        floors.append((nodes, total_f / ns))
    print()
    print("| nodes | flops per node-step (full Newton) | floor at %.1f-%.1f flops per ns | twice the floor |" % RATE)
    print("|---:|---:|---:|---:|")
    for nodes, f in floors:
        print("| %d | %.0f | %.0f-%.0f ns | %.0f-%.0f ns |" % (nodes, f, f / RATE[1], f / RATE[0], 2 * f / RATE[1],
                                                              2 * f / RATE[0]))


if __name__ == "__main__":
    main()
