#!/usr/bin/env python3
"""Issue 24, the physical limit: each integrator's floating-point work and data per link and step against
this machine's peak and bandwidth. Driven by bench/physical_limit.sh (which builds the two helpers); see
docs/performance.md, "The physical limit (issue 24)". Not a test: it prints figures, it judges nothing.

Method:
- wall time per step: whole cable_sim processes, a long run less a near-zero one (start-up, statics and
  CSV taken out), median of `--repeats` interleaved pairs;
- floating-point operations per step: this VM exposes no hardware counters (perf lists no cycles,
  instructions or fp_ret_sse_avx_ops), so they are counted from the instructions executed:
  valgrind's callgrind counts every instruction's executions inside CableSimulator::step()
  (--toggle-collect), objdump names each instruction, and each arithmetic instruction counts its lanes
  (1 for sd, 2 for xmm pd, 4 for ymm pd), a fused multiply-add twice, as the Zen counter
  fp_ret_sse_avx_ops.all does. Counted: add, sub, mul, div, sqrt, FMA, hadd/addsub (double and single,
  libm's included); not counted: compares, min/max, conversions, and/xor used for abs and negation.
  Two runs of different lengths, subtracted: per step, start-up excluded. Valgrind runs the same
  AVX2/FMA copies of the hot loops (hot_path.h) as the processor does (both lack AVX-512);
- data per link: bench/src/link_bytes.cpp (the heap a simulator holds, n = 1000 less n = 100; the
  semi-implicit's, whose dense matrices grow as n^2, at n = 100 over 100);
- traffic past L2: callgrind's cache simulation with this core's L1d (32 KiB, 8-way) and L2 (512 KiB,
  8-way) as the last level: misses x 64 B (a model: no prefetcher, no L3 victim behaviour);
- time by function (n = 1000; the semi-implicit at 100): perf's software clock (cpu-clock, 4 kHz), the
  shares taken over the functions the step runs, against each one's counted instructions and flops.
"""
import argparse
import os
import re
import statistics
import subprocess
import sys
import tempfile
import time

HERE = os.path.dirname(os.path.abspath(__file__))
REPO = os.path.dirname(HERE)

# (label, preset, integrator, dt [s], links, timed duration [s], counted steps)
CASES = [
    ("rk4", "armoured_umbilical", "rk4", 5e-5, 100, 0.5, 20),
    ("rk4", "armoured_umbilical", "rk4", 5e-5, 1000, 0.5, 20),
    ("implicit", "armoured_umbilical", "implicit", 0.025, 100, 150.0, 20),
    ("implicit", "armoured_umbilical", "implicit", 0.025, 1000, 25.0, 20),
    ("semi_implicit", "armoured_umbilical", "semi_implicit", 0.01, 100, 1.0, 6),
]

ARITH = re.compile(r"^v?(add|sub|mul|div|sqrt|addsub|hadd|hsub)(sd|ss|pd|ps)$")
FMA = re.compile(r"^v?f(n?)m(add|sub|addsub|subadd)(132|213|231)(sd|ss|pd|ps)$")
X87 = re.compile(r"^f(add|sub|subr|mul|div|divr|sqrt)p?$|^fi(add|sub|mul|div)")


def lanes(suffix, operands):
    if suffix in ("sd", "ss"):
        return 1
    wide = "%ymm" in operands
    if suffix == "pd":
        return 4 if wide else 2
    return 8 if wide else 4


def classify(mnemonic, operands):
    """(flops, kind, operation) of one instruction; kind 'scalar' or 'packed' (None: not arithmetic),
    operation 'fma', 'div', 'sqrt' or 'other'."""
    m = FMA.match(mnemonic)
    if m:
        n = lanes(m.group(4), operands)
        return 2 * n, ("scalar" if n == 1 else "packed"), "fma"
    m = ARITH.match(mnemonic)
    if m:
        n = lanes(m.group(2), operands)
        return n, ("scalar" if n == 1 else "packed"), m.group(1) if m.group(1) in ("div", "sqrt") else "other"
    if X87.match(mnemonic):
        return 1, "scalar", "div" if mnemonic.startswith(("fdiv", "fidiv")) else "sqrt" if mnemonic == "fsqrt" else "other"
    return 0, None, "other"


_disassembly = {}


def disassemble(obj):
    """Address -> (mnemonic, operands) of every instruction of `obj` (file addresses, as callgrind's)."""
    if obj not in _disassembly:
        table = {}
        out = subprocess.run(["objdump", "-d", "--no-show-raw-insn", obj], capture_output=True, text=True).stdout
        for line in out.splitlines():
            m = re.match(r"^\s+([0-9a-f]+):\s+(\S+)\s*(.*)$", line)
            if m:
                table[int(m.group(1), 16)] = (m.group(2), m.group(3))
        _disassembly[obj] = table
    return _disassembly[obj]


def short_name(function):
    """A function's name without namespace, arguments or clone suffix, as callgrind and perf both give it."""
    name = function.replace("cable_dynamics::", "").replace("(anonymous namespace)::", "")
    return re.sub(r"\(.*|\s*\[clone.*|@.*", "", name).strip()


def count_callgrind(path):
    """Totals of one callgrind output (--dump-instr=yes --compress-strings=no --compress-pos=no)."""
    per_instruction = {}
    obj = function = None
    skip_next = False
    events = []
    summary = None
    with open(path) as f:
        for line in f:
            if skip_next:  # the inclusive cost of a call: not this function's own
                skip_next = False
                continue
            if line.startswith("ob="):
                obj = line[3:].strip()
            elif line.startswith("fn="):
                function = line[3:].strip()
            elif line.startswith("calls="):
                skip_next = True
            elif line.startswith("events:"):
                events = line.split()[1:]
            elif line.startswith("summary:"):
                summary = [int(v) for v in line.split()[1:]]
            elif line.startswith("0x"):
                fields = line.split()
                key = (obj, function, int(fields[0], 16))
                per_instruction[key] = per_instruction.get(key, 0) + int(fields[1])
    totals = dict(zip(events, summary))
    for key in ("flops_scalar", "flops_packed", "fp_instructions", "fma", "div", "sqrt", "unknown"):
        totals[key] = 0
    by_function = {}  # short name -> [instructions, flops]
    for (obj, function, address), count in per_instruction.items():
        instruction = disassemble(obj).get(address)
        if instruction is None:
            totals["unknown"] += count
            continue
        n, kind, operation = classify(*instruction)
        name = short_name(function)
        entry = by_function.setdefault(name, [0, 0])
        entry[0] += count
        if kind:
            totals["flops_" + kind] += n * count
            totals["fp_instructions"] += count
            if operation != "other":
                totals[operation] += count
            entry[1] += n * count
    return totals, by_function


def cable_sim_args(binary, preset, integrator, dt, links, duration, output):
    return [binary, "--config", os.path.join(REPO, "config", preset + ".yaml"), "--set", "cable.links=%d" % links,
            "--set", "simulation.integrator=" + integrator, "--set", "simulation.dt=%g" % dt,
            "--duration", "%g" % duration, "--sample", "%g" % duration, "--output", output]


def wall(args):
    t0 = time.perf_counter()
    run = subprocess.run(args, check=True, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, text=True)
    seconds = time.perf_counter() - t0
    if "needed substeps" in run.stderr:  # a retried step costs two or more: the time per step would not be one step's
        print("# warning: %s: %s" % (" ".join(args[-8:]), run.stderr.strip()), file=sys.stderr)
    return seconds


def step_seconds(binary, case, repeats, work):
    """Median over `repeats` of (long run - near-zero run) / steps, and the range."""
    _, preset, integrator, dt, links, duration, _ = case
    out = os.path.join(work, "o.csv")
    steps = round(duration / dt)
    per_step = []
    for _ in range(repeats):
        short = wall(cable_sim_args(binary, preset, integrator, dt, links, 2 * dt, out))
        full = wall(cable_sim_args(binary, preset, integrator, dt, links, duration, out))
        per_step.append((full - short) / (steps - 2))
    return statistics.median(per_step), min(per_step), max(per_step)


def time_shares(binary, case, work):
    """Share of the wall time by function (perf's software clock: the VM has no hardware counters), over
    the long run, start-up included (its own functions, the statics', drop out when the shares are taken
    over the step's functions only). None without perf."""
    _, preset, integrator, dt, links, duration, _ = case
    data = os.path.join(work, "perf.data")
    try:
        subprocess.run(["perf", "record", "-q", "-e", "cpu-clock", "-F", "4000", "-o", data] +
                       cable_sim_args(binary, preset, integrator, dt, links, duration, os.path.join(work, "o.csv")),
                       check=True, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
        report = subprocess.run(["perf", "report", "-i", data, "--sort", "symbol", "--stdio"], check=True,
                                capture_output=True, text=True).stdout
    except (OSError, subprocess.CalledProcessError):
        return None
    shares = {}
    for line in report.splitlines():
        m = re.match(r"^\s+([0-9.]+)%\s+\[\.\]\s+(.*?)\s*(-\s+-\s*)?$", line)
        if m:
            name = short_name(m.group(2))
            shares[name] = shares.get(name, 0.0) + float(m.group(1)) / 100.0
    return shares


def counted(binary, case, work):
    """Callgrind totals per step, from runs of 2 and 2 + `steps` steps."""
    _, preset, integrator, dt, links, _, steps = case
    results = []
    for k in (2, 2 + steps):
        cg = os.path.join(work, "cg.out")
        args = ["valgrind", "--tool=callgrind", "--callgrind-out-file=" + cg, "--dump-instr=yes", "--dump-line=no",
                "--compress-strings=no", "--compress-pos=no", "--collect-atstart=no",
                "--toggle-collect=cable_dynamics::CableSimulator::step()", "--cache-sim=yes",
                "--D1=32768,8,64", "--LL=524288,8,64"]
        subprocess.run(args + cable_sim_args(binary, preset, integrator, dt, links, k * dt,
                                             os.path.join(work, "o.csv")),
                       check=True, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
        results.append(count_callgrind(cg))
    (short, short_functions), (full, full_functions) = results
    functions = {name: [(v - short_functions.get(name, [0, 0])[i]) / steps for i, v in enumerate(values)]
                 for name, values in full_functions.items()}
    return {key: (full[key] - short[key]) / steps for key in full}, functions


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--cable-sim", required=True)
    parser.add_argument("--machine", required=True, help="machine_peak's output (key value lines)")
    parser.add_argument("--link-bytes", required=True, help="the link_bytes binary")
    parser.add_argument("--repeats", type=int, default=3)
    options = parser.parse_args()
    machine = {}
    with open(options.machine) as f:
        for line in f:
            key, value = line.split()
            machine[key] = float(value)
    peak = machine["peak_avx2_fma_gflops"]
    peak_scalar = machine["peak_scalar_fma_gflops"]
    l3_bw = machine["triad_gbs_6144kib"]
    mem_bw = machine["triad_gbs_393216kib"]
    ghz = machine["clock_ghz"]

    # Data per link: the heap of a simulator at 1000 links less at 100, over 900 (the fixed part drops out);
    # the semi-implicit's dense matrices grow as n^2: its heap at 100 links over 100.
    heap, held_at = {}, {}
    for integrator in ("rk4", "implicit", "semi_implicit"):
        for n in ((100, 1000) if integrator != "semi_implicit" else (100,)):
            out = subprocess.run([options.link_bytes, os.path.join(REPO, "config", "armoured_umbilical.yaml"),
                                  str(n), "--set", "simulation.integrator=" + integrator, "--set",
                                  "simulation.dt=%g" % {"rk4": 5e-5, "implicit": 0.025, "semi_implicit": 0.01}[integrator]],
                                 capture_output=True, text=True, check=True).stdout
            values = dict(line.split() for line in out.splitlines())
            held_at[(integrator, n)] = float(values["heap_bytes"])
        heap[integrator] = ((held_at[(integrator, 1000)] - held_at[(integrator, 100)]) / 900
                            if integrator != "semi_implicit" else held_at[(integrator, 100)] / 100)
    print("# per-link structures [B]: " + ", ".join("%s %s" % kv for kv in values.items() if kv[0] != "heap_bytes"))
    print("# data per link [B]: " + ", ".join("%s %.0f" % kv for kv in heap.items()) + " (semi-implicit: its heap at n = 100 over 100)")

    # Table 1: the work and how fast it runs; table 2: the data and the bandwidth it asks for.
    work_header = ("integrator", "n", "us/step", "ns/link/step", "flop/link/step", "in packed instr.", "FMA/link",
                   "div / sqrt instr./link", "instr/link", "instr/cycle", "flop/FP instr", "GFLOP/s", "of AVX2 peak",
                   "of scalar peak", "ns/link/step at AVX2 peak")
    data_header = ("integrator", "n", "B/link held", "heap at n", "B/link/step past L2", "GB/s past L2",
                   "of L3 triad", "of memory triad", "ns/link/step at L3 triad")
    work_rows, data_rows = [], []
    where_header = ("integrator", "n", "function", "of the time", "of the instr.", "of the flops", "instr/cycle",
                    "GFLOP/s")
    where_rows = []
    with tempfile.TemporaryDirectory() as work:
        for case in CASES:
            label, _, _, dt, n, _, _ = case
            seconds, low, high = step_seconds(options.cable_sim, case, options.repeats, work)
            c, functions = counted(options.cable_sim, case, work)
            flops = c["flops_scalar"] + c["flops_packed"]
            past_l2 = 64.0 * (c["DLmr"] + c["DLmw"])  # bytes a step moves between L2 and beyond
            gflops = flops / seconds * 1e-9
            cycles = seconds * ghz * 1e9
            work_rows.append((label, n, "%.1f (%.1f-%.1f)" % (seconds * 1e6, low * 1e6, high * 1e6),
                              "%.0f" % (seconds * 1e9 / n), "%.0f" % (flops / n),
                              "%.0f %%" % (100.0 * c["flops_packed"] / flops), "%.0f" % (c["fma"] / n),
                              "%.1f / %.1f" % (c["div"] / n, c["sqrt"] / n), "%.0f" % (c["Ir"] / n),
                              "%.2f" % (c["Ir"] / cycles), "%.2f" % (flops / c["fp_instructions"]), "%.2f" % gflops,
                              "%.1f %%" % (100.0 * gflops / peak), "%.0f %%" % (100.0 * gflops / peak_scalar),
                              "%.0f" % (flops / n / peak)))
            held = held_at[(label, n)]
            data_rows.append((label, n, "%.0f" % heap[label],
                              ("%.2f MiB" % (held / 2**20)) + (" (in L2)" if held < 512 * 1024 else " (past L2)"),
                              "%.0f" % (past_l2 / n), "%.2f" % (past_l2 / seconds * 1e-9),
                              "%.1f %%" % (100.0 * past_l2 / seconds * 1e-9 / l3_bw),
                              "%.1f %%" % (100.0 * past_l2 / seconds * 1e-9 / mem_bw),
                              "%.0f" % (past_l2 / n / l3_bw)))
            print("# %s n=%d: %s" % (label, n, ", ".join("%s %.4g" % kv for kv in sorted(c.items()))),
                  file=sys.stderr, flush=True)
            shares = time_shares(options.cable_sim, case, work) if n >= 1000 or label == "semi_implicit" else None
            if shares:
                in_step = sum(v for name, v in shares.items() if name in functions)
                ranked = sorted((name for name in functions if name in shares), key=lambda name: -shares[name])
                for name in ranked[:6]:
                    share = shares[name] / in_step
                    fn_seconds = share * seconds
                    where_rows.append((label, n, name, "%.0f %%" % (100.0 * share),
                                       "%.0f %%" % (100.0 * functions[name][0] / c["Ir"]),
                                       "%.0f %%" % (100.0 * functions[name][1] / flops),
                                       "%.2f" % (functions[name][0] / (fn_seconds * ghz * 1e9)),
                                       "%.2f" % (functions[name][1] / fn_seconds * 1e-9)))
            top = sorted(functions.items(), key=lambda kv: -kv[1][0])[:10]
            print("#   where (share of the step's instructions, of its flops): " + "; ".join(
                "%s %.0f %%, %.0f %%" % (name, 100.0 * v[0] / c["Ir"], 100.0 * v[1] / flops) for name, v in top),
                file=sys.stderr, flush=True)
    print("# machine: %.2f GHz (measured), AVX2 FMA peak %.1f GFLOP/s (%.1f flop/cycle), scalar FMA peak %.1f GFLOP/s, "
          "triad %.1f GB/s (L2) / %.1f GB/s (L3) / %.1f GB/s (memory), latencies FMA %.1f, div %.1f, sqrt+add %.1f cycles"
          % (ghz, peak, machine["peak_avx2_flop_per_cycle"], peak_scalar, machine["triad_gbs_96kib"], l3_bw, mem_bw,
             machine["latency_fma_cycles"], machine["latency_div_cycles"], machine["latency_sqrt_plus_add_cycles"]))
    for header, rows in ((work_header, work_rows), (data_header, data_rows), (where_header, where_rows)):
        print()
        print("| " + " | ".join(header) + " |")
        print("|" + "---|" * len(header))
        for row in rows:
            print("| " + " | ".join(str(v) for v in row) + " |")


if __name__ == "__main__":
    main()
