#!/usr/bin/env python3
"""xcable against the peer reference solutions of bench/peer -> comparison.md.

Runs xcable (scheme 'rod', default numerics) on the twelve scenes of
peer_common.cases() at 121, 241, 481 and 961 nodes and compares it with the
lumped-mass reference at its finest N (data/<case>.tsv, N = 6400) and, where
it is meaningful (before the recoil reaches the fixed end), with MoorDyn
(data/moordyn_<case>.tsv, N = 800). The reference's own uncertainty is the
difference between its two finest N (N = 3200 and 6400): from runs/ when
that directory is there (more digits), else from summary.md.

  python3 compare.py                    # all runs, then comparison.md
  python3 compare.py --reuse            # keep complete runs whose namelist is unchanged
  python3 compare.py --only fast_180kN slack_5kN_slow --nodes 121 241

Needs Python 3, numpy and h5py (not scipy). Not part of make test. The
executable: --exe, else /tmp/xcable_peer, else /tmp/peerbuild/bin/xcable
(a private copy; see the header of comparison.md). Scratch runs go to
--work (default /tmp/peer_runs).
"""

import argparse
import datetime
import hashlib
import json
import math
import os
import re
import subprocess
import sys
import time

import h5py
import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
sys.dont_write_bytecode = True  # no __pycache__ in the source tree
sys.path.insert(0, HERE)
import peer_common as pc  # noqa: E402

DATA = os.path.join(HERE, "data")
RUNS = os.path.join(HERE, "runs")
SUMMARY = os.path.join(HERE, "summary.md")
NODES = (121, 241, 481, 961)
TIMES = (0.5, 1.0, 1.5, 2.0)
FIELDS = "x z u v tension"
EXE_CANDIDATES = ("/tmp/xcable_peer", "/tmp/peerbuild/bin/xcable")


# ====================================================================== utils
def fmt(v, spec="%.4g", none="-"):
    if v is None or (isinstance(v, float) and not math.isfinite(v)):
        return none
    return spec % v


def table(head, body):
    out = ["| " + " | ".join(head) + " |",
           "|" + "|".join("---" for _ in head) + "|"]
    out += ["| " + " | ".join(str(c) for c in r) + " |" for r in body]
    return "\n".join(out) + "\n"


def attr_str(v):
    if isinstance(v, bytes):
        return v.decode()
    if isinstance(v, np.ndarray) and v.dtype.kind == "S":
        return b"".join(v.tolist()).decode()
    return str(v)


def sha256(path):
    h = hashlib.sha256()
    with open(path, "rb") as f:
        for block in iter(lambda: f.read(1 << 20), b""):
            h.update(block)
    return h.hexdigest()


def loadavg():
    try:
        return "%.2f %.2f %.2f" % os.getloadavg()
    except OSError:
        return "?"


# ============================================================ namelist parse
_TOKEN = re.compile(r"'(?:[^']|'')*'|\"[^\"]*\"|&\w+|/|=|,|[^\s,=/'\"]+")


def parse_namelist(text):
    """{group: {variable: value or [values]}} of a (resolved) namelist text."""
    groups = {}
    toks = _TOKEN.findall(text)  # resolved namelists carry no comments
    i = 0
    while i < len(toks):
        if not toks[i].startswith("&"):
            i += 1
            continue
        name = toks[i][1:].lower()
        body = []
        i += 1
        while i < len(toks) and toks[i] != "/":
            if toks[i] != ",":
                body.append(toks[i])
            i += 1
        grp = {}
        key = None
        k = 0
        while k < len(body):
            if k + 1 < len(body) and body[k + 1] == "=":
                key = body[k].lower()
                grp[key] = []
                k += 2
                continue
            if key is not None:
                grp[key].append(_value(body[k]))
            k += 1
        groups[name] = {kk: (vv[0] if len(vv) == 1 else vv) for kk, vv in grp.items()}
        i += 1
    return groups


def _value(tok):
    if tok[:1] in "'\"":
        return tok[1:-1].replace("''", "'")
    low = tok.lower()
    if low in (".true.", "t", ".t."):
        return True
    if low in (".false.", "f", ".f."):
        return False
    try:
        return float(low.replace("d", "e"))
    except ValueError:
        return tok


# ============================================================ summary.md
def summary_tables(path=SUMMARY):
    """[(heading, header cells, rows)] of every markdown table in summary.md."""
    out = []
    if not os.path.exists(path):
        return out
    heading = ""
    lines = open(path).read().splitlines()
    i = 0
    while i < len(lines):
        ln = lines[i]
        if ln.startswith("#"):
            heading = ln.lstrip("#").strip()
        if ln.startswith("|") and i + 1 < len(lines) and lines[i + 1].startswith("|---"):
            head = [c.strip() for c in ln.strip("|").split("|")]
            rows = []
            i += 2
            while i < len(lines) and lines[i].startswith("|"):
                rows.append([c.strip() for c in lines[i].strip("|").split("|")])
                i += 1
            out.append((heading, head, rows))
            continue
        i += 1
    return out


def find_table(tables, heading_start, first_head=None):
    for h, head, rows in tables:
        if h.startswith(heading_start) and (first_head is None or head[0] == first_head):
            return head, rows
    return None, []


_PAREN = re.compile(r"\(([^)]*)\)")


def paren_float(cell):
    m = _PAREN.search(cell)
    if not m:
        return None
    try:
        return float(m.group(1))
    except ValueError:
        return None


# ============================================================ references
class Reference:
    """The peer data of one case: lumped N=6400 (data/), bands, MoorDyn."""

    def __init__(self, case, tables, manifest):
        self.case = case
        self.ts, self.tb, self.te, self.sample = pc.cases()[case]
        self.paper = not case.startswith("slack")
        self.lumped = pc.read_tsv(os.path.join(DATA, case + ".tsv"))
        md = os.path.join(DATA, "moordyn_" + case + ".tsv")
        self.moordyn = pc.read_tsv(md) if os.path.exists(md) else None
        self.man = manifest.get(case + ".tsv", {})
        self.man_md = manifest.get("moordyn_" + case + ".tsv", {})
        self.tables = tables

    # ---- runs/ (optional, not committed)
    @staticmethod
    def run_info(tag):
        js = os.path.join(RUNS, tag + ".json")
        ts = os.path.join(RUNS, tag + ".tsv")
        if not (os.path.exists(js) and os.path.exists(ts)):
            return None, None
        return json.load(open(js)), pc.read_tsv(ts)

    # ---- paper runs
    def window_mean(self, rows, t0, t1):
        t = rows["t"]
        sel = (t >= t0 - 1e-9) & (t <= t1 + 1e-9)
        return float(np.mean(rows["end_speed"][sel]))

    def plateau_window(self):
        return self.tb + 0.005, self.te

    def plateau(self):
        """(N=6400 value, band |6400 - 3200|, source of the band)."""
        t0, t1 = self.plateau_window()
        v6400 = self.window_mean(self.lumped, t0, t1)
        _, r3200 = self.run_info("lumped_%s_N3200" % self.case)
        if r3200 is not None:
            return v6400, abs(v6400 - self.window_mean(r3200, t0, t1)), "runs/"
        head, rows = find_table(self.tables, "Paper runs: plateau")
        vals = {r[1]: float(r[2].split()[0]) for r in rows if r[0] == self.case}
        if "3200" in vals and "6400" in vals:
            return v6400, max(abs(vals["6400"] - vals["3200"]), 5e-4), "summary.md (3 decimals)"
        return v6400, None, "-"

    def drop_time(self):
        """(t_1% at N=6400, band |6400 - 3200|, source)."""
        i64, _ = self.run_info("lumped_%s_N6400" % self.case)
        i32, _ = self.run_info("lumped_%s_N3200" % self.case)
        if i64 and i32 and i64.get("t_drop_1pct") and i32.get("t_drop_1pct"):
            return i64["t_drop_1pct"], abs(i64["t_drop_1pct"] - i32["t_drop_1pct"]), "runs/"
        head, rows = find_table(self.tables, "Paper runs: plateau")
        vals = {r[1]: float(r[5]) for r in rows if r[0] == self.case}
        if "3200" in vals and "6400" in vals:
            return vals["6400"], max(abs(vals["6400"] - vals["3200"]), 5e-6), "summary.md (5 decimals)"
        if i64 and i64.get("t_drop_1pct"):
            return i64["t_drop_1pct"], None, "runs/"
        return self.tsv_drop_time(self.lumped), None, "data/ (samples)"

    @staticmethod
    def tsv_drop_time(rows):
        ta = rows["tension_a"]
        t = rows["t"]
        lim = 0.99 * ta[0]
        k = np.nonzero(ta < lim)[0]
        if len(k) == 0 or k[0] == 0:
            return None
        k = k[0]
        return float(t[k - 1] + (t[k] - t[k - 1]) * (lim - ta[k - 1]) / (ta[k] - ta[k - 1]))

    def theory_plateau(self):
        head, rows = find_table(self.tables, "Static catenary")
        for r in rows:
            if abs(float(r[0]) * 1000 - self.ts) < 1e-6:
                return float(r[-1])
        return None

    def quad_span(self):
        head, rows = find_table(self.tables, "Static catenary")
        for r in rows:
            if abs(float(r[0]) * 1000 - self.ts) < 1e-6:
                return float(r[3])
        return None

    def moordyn_paper(self):
        """MoorDyn in summary.md's window: dict with window, N=800 / 400
        values, and lumped.py with MoorDyn's table and with the tanh law at
        N = 400 (the effect of MoorDyn's law on the same chain)."""
        head, rows = find_table(self.tables, "MoorDyn against", "case")
        for r in rows:
            if r[0] != self.case:
                continue

            def split(cell):
                p = [x.strip() for x in cell.split("/")]
                return float(p[0]), float(p[1])
            w0, w1 = (float(x) for x in r[6].split("-"))
            out = {"window": (w0, w1)}
            out["md400"], out["md800"] = split(r[1]), split(r[2])
            out["table400"], out["tanh400"] = split(r[3]), split(r[5])
            if self.moordyn is not None:
                out["md800_data"] = self.window_mean(self.moordyn, w0, w1)
            i8, _ = self.run_info("moordyn_%s_N800" % self.case)
            i4, _ = self.run_info("moordyn_%s_N400" % self.case)
            if i8 and i4:
                out["md_t_full"] = (i4["t_drop_1pct"], i8["t_drop_1pct"])
            out["lumped6400"] = self.window_mean(self.lumped, w0, w1)
            return out
        return None

    # ---- slack releases
    def at(self, rows, t):
        k = int(np.argmin(np.abs(rows["t"] - t)))
        if abs(rows["t"][k] - t) > 1e-7:
            return None
        return float(rows["end_x"][k]), float(rows["end_z"][k])

    def slack_bands(self):
        """{t: (|dr| 3200->6400, spread)} from summary.md."""
        out = {}
        head, rows = find_table(self.tables, self.case)
        row = [r for r in rows if r[0] == "6400"]
        head2, rows2 = find_table(self.tables, "Slack releases: reference end position")
        row2 = [r for r in rows2 if r[0] == self.case]
        for j, t in enumerate(TIMES):
            b = paren_float(row[0][1 + j]) if row else None
            s = paren_float(row2[0][1 + j]) if row2 else None
            out[t] = (b, s)
        return out

    def slack_front(self):
        """t_1% at end a of the reference (N = 6400) and its source."""
        i64, _ = self.run_info("lumped_%s_N6400" % self.case)
        if i64 and i64.get("t_drop_1pct"):
            return i64["t_drop_1pct"], "runs/ (every step)"
        return self.tsv_drop_time(self.lumped), "data/ (10 ms samples)"


def read_manifest():
    path = os.path.join(DATA, "manifest.tsv")
    out = {}
    with open(path) as f:
        head = f.readline().rstrip("\n").split("\t")
        for ln in f:
            c = ln.rstrip("\n").split("\t")
            out[c[0]] = dict(zip(head, c))
    return out


# ============================================================ xcable runs
def scene_namelist(case, nodes, h5name):
    ts, tb, te, sample = pc.cases()[case]
    p = ", ".join(repr(float(v)) for v in pc.P)
    return "\n".join([
        "! generated by bench/peer/compare.py: %s at %d nodes, the scene of" % (case, nodes),
        "! bench/peer/peer_common.py (every scene value set explicitly);",
        "! numerics: xcable's defaults (scheme 'rod') except nodes and t_end.",
        "&cable    length = %r, diameter = %r, density = %r, young = %r," % (
            pc.LENGTH, pc.DIAMETER, pc.DENSITY, pc.YOUNG),
        "          gravity = %r, area = %r, bending_stiffness = %r /" % (
            pc.GRAVITY, pc.AREA, pc.EI),
        "&material law = 'tanh', p = %s, compression = 'law' /" % p,
        "&static   tension = %r /" % float(ts),
        "&end_a    kind = 'fixed', x = 0.0, z = 0.0 /",
        "&end_b    kind = 'fixed' /",
        "&rupture  enabled = .true., s_break = %r, t_break = %r, time = 0.0 /" % (pc.LENGTH, tb),
        "&numerics nodes = %d, t_end = %r /" % (nodes, te),
        "&output   file = '%s', interval = %r, fields = '%s', energy = .true., quiet = .true. /" % (
            h5name, sample, FIELDS),
        ""])


def run_xcable(exe, work, stem, text, reuse):
    """Write stem.nml, run it (unless reused); returns (process wall s, rc, stderr)."""
    nml = os.path.join(work, stem + ".nml")
    h5 = os.path.join(work, stem + ".h5")
    meta = os.path.join(work, stem + ".run.json")
    if reuse and os.path.exists(nml) and os.path.exists(h5) and os.path.exists(meta):
        if open(nml).read() == text:
            m = json.load(open(meta))
            if m.get("exe_sha256") == EXE_SHA:
                REUSED.append((m.get("when"), m.get("load")))
                return m["wall"], m["rc"], m["stderr"], True
    with open(nml, "w") as f:
        f.write(text)
    if os.path.exists(h5):
        os.remove(h5)
    load = os.getloadavg()[0] if hasattr(os, "getloadavg") else None
    t0 = time.perf_counter()
    pr = subprocess.run([exe, stem + ".nml"], cwd=work, capture_output=True, text=True)
    wall = time.perf_counter() - t0
    with open(meta, "w") as f:
        json.dump({"wall": wall, "rc": pr.returncode, "stderr": pr.stderr[-4000:],
                   "exe_sha256": EXE_SHA, "load": load,
                   "when": datetime.datetime.now(datetime.timezone.utc).strftime("%Y-%m-%d %H:%M")}, f)
    return wall, pr.returncode, pr.stderr[-4000:], False


class XRun:
    """Measured quantities of one xcable run."""

    def __init__(self, case, nodes, h5path, wall, rc, stderr):
        self.case, self.nodes, self.wall, self.rc = case, nodes, wall, rc
        self.stderr = stderr.strip()
        self.ok = False
        self.status = "no file"
        if not os.path.exists(h5path):
            return
        with h5py.File(h5path, "r") as f:
            a = f.attrs
            self.status = attr_str(a.get("status", b"?"))
            self.reason = attr_str(a.get("failure_reason", b""))
            self.warnings = attr_str(a.get("warnings", b""))
            self.namelist = parse_namelist(attr_str(a.get("namelist", b"")))
            self.code_version = attr_str(a.get("code_version", b"?"))
            s = f["summary"].attrs if "summary" in f else {}
            self.summary = {k: (s[k].item() if hasattr(s[k], "item") else s[k]) for k in s}
            st = f["static"].attrs
            self.span = float(st["span"])
            self.static_tension_a = float(st.get("tension_a", np.nan))
            self.t = f["time"][:]
            self.x = f["x"][:, -1]
            self.z = f["z"][:, -1]
            self.speed = np.hypot(f["u"][:, -1], f["v"][:, -1])
            self.x0 = f["x"][0, 0], f["z"][0, 0]
            self.e_bend0 = float(f["history/energy/bending"][0]) if "history/energy/bending" in f else None
            self.e_strain0 = float(f["history/energy/strain"][0]) if "history/energy/strain" in f else None
            h = f["history"]
            self.h_t = h["time"][:]
            self.h_ta = h["end_a/tension"][:] if "end_a" in h else None
        self.ok = self.status == "complete"
        self.t_reached = float(self.summary.get("time_reached", self.t[-1] if len(self.t) else 0))

    def get(self, key, default=None):
        return self.summary.get(key, default)

    def snap_index(self, t):
        if not len(self.t):
            return None
        k = int(np.argmin(np.abs(self.t - t)))
        return k if abs(self.t[k] - t) <= 1e-7 else None

    def pos(self, t):
        k = self.snap_index(t)
        return None if k is None else (float(self.x[k]), float(self.z[k]))

    def mean_speed(self, times):
        ks = [self.snap_index(t) for t in times]
        if any(k is None for k in ks):
            return None
        return float(np.mean(self.speed[ks]))

    def drop_time(self):
        v = self.get("end_a_front_arrival_time", self.get("front_arrival_time"))
        return v if v is not None and v >= 0 else None


# ============================================================ main
EXE_SHA = ""
REUSED = []  # (time, load average) of the runs reused from an earlier call


def main():
    global EXE_SHA, RUNS
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--exe", help="xcable executable (default: %s)" % " or ".join(EXE_CANDIDATES))
    ap.add_argument("--work", default="/tmp/peer_runs", help="scratch directory for the runs")
    ap.add_argument("--nodes", type=int, nargs="+", default=list(NODES))
    ap.add_argument("--only", nargs="+", help="cases to run (default: all twelve)")
    ap.add_argument("--reuse", action="store_true",
                    help="reuse complete runs in --work whose namelist and executable are unchanged")
    ap.add_argument("--out", default=os.path.join(HERE, "comparison.md"))
    ap.add_argument("--ignore-runs", action="store_true",
                    help="do not read runs/ (bands from summary.md only, as in a fresh clone)")
    args = ap.parse_args()
    if args.ignore_runs:
        RUNS = os.path.join(HERE, "no such directory")

    exe = args.exe or next((e for e in EXE_CANDIDATES if os.access(e, os.X_OK)), None)
    if not exe or not os.access(exe, os.X_OK):
        sys.exit("compare.py: no xcable executable: cp /work/main/bin/xcable /tmp/xcable_peer, "
                 "or build a private copy into /tmp/peerbuild (see comparison.md), or pass --exe")
    exe = os.path.abspath(exe)
    EXE_SHA = sha256(exe)
    os.makedirs(args.work, exist_ok=True)
    cases = pc.cases()
    names = args.only or list(cases)
    for c in names:
        if c not in cases:
            sys.exit("compare.py: unknown case %s; known: %s" % (c, " ".join(cases)))
    nodes = sorted(args.nodes)
    load_start = loadavg()
    started = datetime.datetime.now(datetime.timezone.utc)

    # ---- xcable's defaults: one run of an empty scene, its resolved namelist
    dtext = "&output file = 'defaults.h5', quiet = .true., fields = 'x' /\n"
    w, rc, err, _ = run_xcable(exe, args.work, "defaults", dtext, args.reuse)
    if rc != 0:
        sys.exit("compare.py: the default run failed: " + err)
    with h5py.File(os.path.join(args.work, "defaults.h5"), "r") as f:
        defaults = parse_namelist(attr_str(f.attrs["namelist"]))
        code_version = attr_str(f.attrs.get("code_version", b"?"))
        compiler = attr_str(f.attrs.get("compiler_version", b"?"))

    # ---- runs
    runs = {}
    for c in names:
        for n in nodes:
            stem = "%s_n%d" % (c, n)
            text = scene_namelist(c, n, stem + ".h5")
            wall, rc, err, reused = run_xcable(exe, args.work, stem, text, args.reuse)
            r = XRun(c, n, os.path.join(args.work, stem + ".h5"), wall, rc, err)
            runs[c, n] = r
            print("%-18s %4d nodes: %s, rc %d, %.1f s%s" % (c, n, r.status, rc, wall,
                                                         " (reused)" if reused else ""),
                  file=sys.stderr, flush=True)

    # ---- statics with EI -> 0 (the smallest EI xcable accepts), finest grid:
    # separates the effect of bending in xcable's static state from the rest
    statics0 = {}
    for c in names:
        ts = cases[c][0]
        if ts in statics0:
            continue
        stem = "statics_ei0_%gkN_n%d" % (ts / 1000, nodes[-1])
        text = scene_namelist(c, nodes[-1], stem + ".h5")
        text = re.sub(r"bending_stiffness = [^ /]+", "bending_stiffness = 1e-6", text)
        text = re.sub(r"t_end = [^ /]+", "t_end = %r" % cases[c][3], text)
        text = text.replace("! numerics:", "! statics check with EI = 1e-6 N m^2 (one sample of dynamics); numerics:")
        wall, rc, err, _ = run_xcable(exe, args.work, stem, text, args.reuse)
        r = XRun(c, nodes[-1], os.path.join(args.work, stem + ".h5"), wall, rc, err)
        statics0[ts] = r.span if hasattr(r, "span") else None

    tables = summary_tables()
    manifest = read_manifest()
    refs = {c: Reference(c, tables, manifest) for c in names}
    md = build_report(args, exe, code_version, compiler, defaults, runs, refs, names, nodes,
                      load_start, started, statics0)
    with open(args.out, "w") as f:
        f.write(md)
    print("wrote " + args.out, file=sys.stderr)


# ============================================================ report
def conventions(defaults, runs):
    """Sentences: each convention of peer_common against xcable's default and
    the value set in the generated namelists (read back from a result file)."""
    d = defaults
    any_run = next((r for r in runs.values() if r.ok), None)
    res = any_run.namelist if any_run else {}

    def dv(g, k):
        return d.get(g, {}).get(k)

    def rv(g, k):
        return res.get(g, {}).get(k)

    def same(a, b, rel=1e-12):
        if isinstance(a, (list, tuple)) or isinstance(b, (list, tuple)):
            return (len(a) == len(b)) and all(same(x, y, rel) for x, y in zip(a, b))
        if isinstance(a, float) and isinstance(b, float):
            return abs(a - b) <= rel * max(abs(a), abs(b), 1e-300)
        return a == b

    def word(a, b):
        return "the same" if same(a, b) else "**different**"

    out = []
    rows = (("cable", "length", pc.LENGTH, "m", "unstretched length L"),
            ("cable", "diameter", pc.DIAMETER, "m", "diameter d"),
            ("cable", "density", pc.DENSITY, "kg/m^3", "density"),
            ("cable", "area", pc.AREA, "m^2", "area pi d^2/4 (mass per length m = rho A = %.6f kg/m)" % pc.MASS),
            ("cable", "gravity", pc.GRAVITY, "m/s^2", "gravity g"),
            ("cable", "young", pc.YOUNG, "Pa", "Young's modulus (used for EI only)"),
            ("cable", "bending_stiffness", pc.EI, "N m^2", "bending stiffness EI = E pi d^4/64"))
    for g, k, v, unit, what in rows:
        out.append("- **%s** (`&%s %s`): peer_common %r %s; xcable's default %r (as resolved "
                   "in a run with no input), %s; set explicitly to %r (read back from the result "
                   "file: %r)." % (what, g, k, v, unit, dv(g, k), word(float(dv(g, k) or 0), v), v,
                                   rv(g, k)))
    p_def = dv("material", "p")
    out.append("- **Law**: peer_common's `TanhLaw` T = p1 tanh(p2 eps + p3) + p4 + p5 eps with p = %s; "
               "xcable's default law %r with p = %s, %s; set explicitly (`law = 'tanh'`, the same p)."
               % (", ".join("%g" % v for v in pc.P), dv("material", "law"),
                  ", ".join("%g" % v for v in (p_def or [])), word([float(x) for x in p_def or []],
                                                              [float(x) for x in pc.P])))
    out.append("- **Compressive branch**: the reference uses the same formula for eps < 0 "
               "(`TanhLaw`, 'the same formula in compression', f(0) = -42 N); xcable's "
               "`compression = 'law'` is 'the law continued below zero strain' (the tanh "
               "formula itself, `material/law.f90`; 'none' would be the tension-only cut that "
               "MoorDyn has). xcable's default is %r, %s; set explicitly to 'law'."
               % (dv("material", "compression"),
                  "the same" if dv("material", "compression") == "law" else "**different**"))
    out.append("- **strain_max** (xcable only): xcable refuses static states above strain %r; "
               "the largest static strain here is 0.2278 (315 kN), so it does not bind; the "
               "dynamics are not limited by it (nor is the reference)." % dv("material", "strain_max"))
    out.append("- **Static tension**: the reference's static state has the end tension T_s at both "
               "ends, H = sqrt(T_s^2 - (w0 L/2)^2), the force holding end b F_s = (H, w0 L/2), both "
               "ends at one height (`discrete_catenary`); xcable's `&static tension` is 'the end "
               "tension T_s of the paper's symmetric catenary (ends at one height, span from the "
               "tension)', the span adjusted until the support force at end b has magnitude T_s. "
               "Default %r N; set to each case's T_s. The spans below check that the two static "
               "states are the same catenary." % dv("static", "tension"))
    out.append("- **Bending in the static state** (not settable): the reference leaves bending "
               "out of its initial state (its pinned ends then carry the catenary's curvature, a "
               "boundary layer of length sqrt(EI/T_s) = 0.1-0.2 m that relaxes at once, initial "
               "bending energy below 0.5 J); xcable's rod statics solve the full equilibrium with "
               "EI and zero moment at the pinned ends (static curvature 0 at the end nodes). The "
               "static table gives both initial bending energies and xcable's span with EI -> 0, "
               "which isolates this difference.")
    out.append("- **Ends**: the reference pins end a at (0, 0) (no moment) and releases end b from "
               "(span, 0); xcable's defaults are end_a %r and end_b %r at z = 0, with the fixed end "
               "at the origin and no end moment (a 'fixed' end holds the position only); set "
               "explicitly (`&end_a kind = 'fixed', x = 0, z = 0`, `&end_b kind = 'fixed'`). Both use "
               "x horizontal and z up."
               % (dv("end_a", "kind"), dv("end_b", "kind")))
    out.append("- **Release**: the reference ramps the static end force as F_s cos^2(pi t / (2 "
               "t_break)) from t = 0 and then 0 (`ramp`); xcable's break at end b replaces the "
               "support by the force that held it, ramped by cos^2(pi (t - time)/(2 t_break)) "
               "(`smooth_ramp`, eqs. 31-32). xcable's defaults: enabled %r, s_break %r (resolved: L, end b), "
               "time %r, t_break %r s; set explicitly to s_break = L, time = 0 and each case's "
               "t_break (the default 0.05 s is the slow ramp only)."
               % (dv("rupture", "enabled"), dv("rupture", "s_break"), dv("rupture", "time"),
                  dv("rupture", "t_break")))
    extra = sorted("&%s %s" % (g, k) for g, grp in d.items() for k in grp
                   if re.search(r"damp|drag|fluid|current|added|water", k))
    dissipated = max((abs(r.get("dissipated", 0) or 0) for r in runs.values() if r.ok), default=0)
    out.append("- **No fluid, no damping**: the reference has neither; xcable's inputs with such a "
               "name: %s; theta = %r (0.5: no numerical dissipation); the largest `/summary "
               "dissipated` over the runs is %.3g J."
               % (", ".join("`%s` = %r" % (e, d[e.split()[0][1:]][e.split()[1]]) for e in extra)
                  if extra else "none in this executable's schema", dv("numerics", "theta"), dissipated))
    out.append("- **Discretisation** (left at xcable's defaults, as asked): scheme %r, mass_matrix "
               "%r, courant %r (dt = ds / c with c the largest axial wave speed of the static "
               "state), theta %r, newton_tol %r. xcable's N counts nodes (N - 1 cells); the "
               "reference's N counts segments (N + 1 nodes), Courant 0.5 on the largest wave speed "
               "of the whole law (1110 m/s)."
               % (dv("numerics", "scheme"), dv("numerics", "mass_matrix"), dv("numerics", "courant"),
                  dv("numerics", "theta"), dv("numerics", "newton_tol")))
    out.append("- **t_end and sampling**: t_end is each case's (`peer_common.cases()`), the default "
               "%r s is not used; snapshots every 1 ms (paper runs) or 10 ms (slack releases), the "
               "reference's sample interval, so both codes are read at the same times."
               % dv("numerics", "t_end"))
    out.append("- **Released-end speed**: the reference's `end_speed` is |velocity| of the end-b "
               "node; xcable's is hypot(u, v) at its last node in the snapshots (u tangential, v "
               "normal). The plateau is the mean over the reference's samples from t_break + 5 ms "
               "to t_end, as in `report.py`.")
    out.append("- **1 % drop at the fixed end**: the reference's `tension_a` is the support force "
               "projected on the first segment, and the drop is detected every step with linear "
               "interpolation; xcable's `/summary end_a_front_arrival_time` is the same test on its "
               "end tension (the law at the strain extrapolated from the three end cells), every "
               "step, linear interpolation. Both are relative to their own t = 0 value.")
    out.append("- **Energy drift**: both are max |ledger(t) - ledger(0)| / E_strain(0), ledger = "
               "strain + kinetic + bending + gravity - work of the end force, strain energy W(eps) = "
               "integral of f from 0, gravity energy zero at the height of the supports; xcable "
               "checks every step, the reference every sample.")
    return "\n".join(out) + "\n"


def verdict(d, band):
    if d is None or band is None:
        return "-"
    if d <= band:
        return "inside"
    return "outside (x%.3g)" % (d / band) if band > 0 else "outside"


def summary_section(facts, runs, refs, names, nodes, statics0):
    """Key numbers, computed (no hand-written conclusions)."""
    finest = nodes[-1]
    prev = nodes[-2] if len(nodes) > 1 else finest
    out = ["## Key numbers (xcable at %d nodes)\n" % finest]
    items = []
    if facts["paper"]:
        rel = [abs(v - vr) / vr for _, v, vr, *_ in facts["paper"] if v is not None]
        inside_v = sum(1 for f in facts["paper"] if f[1] is not None and f[3] is not None
                       and abs(f[1] - f[2]) <= f[3])
        inside_t = sum(1 for f in facts["paper"] if f[4] is not None and f[6] is not None
                       and abs(f[4] - f[5]) <= f[6])
        dts = [abs(f[4] - f[5]) * 1e3 for f in facts["paper"] if f[4] is not None]
        items.append("Paper runs: plateau speed within %.1e relative of the reference (%s), "
                     "inside the reference's band in %d of %d cases; t_1%% within %.4f ms (%s), "
                     "inside the band in %d of %d. Reference bands: %s. xcable's own %d-%d "
                     "change: %s."
                     % (max(rel), ", ".join("%s %+.1e m/s" % (f[0], f[1] - f[2]) for f in facts["paper"]),
                        inside_v, len(facts["paper"]), max(dts),
                        ", ".join("%s %+.4f" % (f[0], (f[4] - f[5]) * 1e3) for f in facts["paper"]),
                        inside_t, len(facts["paper"]),
                        "; ".join("%s %s m/s, %s ms" % (f[0], fmt(f[3], "%.1e"),
                                                       fmt(None if f[6] is None else f[6] * 1e3, "%.1e"))
                                  for f in facts["paper"]),
                        prev, finest,
                        "; ".join("%s %+.1e m/s, %+.4f ms" % (f[0], f[7] or 0, (f[8] or 0) * 1e3)
                                  for f in facts["paper"])))
    if facts["md_paper"]:
        items.append("Paper runs against MoorDyn N = 800 (its window, before its t_valid), once "
                     "MoorDyn's own law effect is added back (residual): %s."
                     % "; ".join("%s %+.3f m/s (MoorDyn band %.3f), %+.3f ms (band %.3f)"
                                 % (c, rv or 0, bv, (rt or 0) * 1e3, bt * 1e3)
                                 for c, rv, bv, rt, bt in facts["md_paper"]))
    if facts["early"]:
        items.append("Slack releases, up to the reference's t_1%% (the front reaching the fixed "
                     "end): the released end agrees with the reference to %s m. The static spans "
                     "differ from the quadrature by %s; with EI = 1e-6 in xcable's statics by %s: "
                     "that part is the static effect of the bending the reference leaves out of its "
                     "static state."
                     % (", ".join("%s %.1e" % (c, d) for c, tf, d, _ in facts["early"] if d is not None),
                        ", ".join("%g kN %+.1e m" % (ts / 1000, runs[(c, finest)].span - refs[c].quad_span())
                                  for c, ts in _per_tension(names, refs) if (c, finest) in runs
                                  and hasattr(runs[(c, finest)], "span") and ts < 60000),
                        ", ".join("%+.1e m" % (statics0[ts] - refs[c].quad_span())
                                  for c, ts in _per_tension(names, refs) if statics0.get(ts) and ts < 60000)))
        items.append("Slack releases after that: xcable and the reference separate once the fixed "
                     "end has gone into compression (first sample with more than 1 cm between them: "
                     "%s s)." % ", ".join("%s %s" % (c, fmt(t1, "%.2f")) for c, _, _, t1 in facts["early"]))
    if facts["slack"]:
        for t in TIMES:
            rows = [f for f in facts["slack"] if abs(f[1] - t) < 1e-9 and f[2] is not None]
            if not rows:
                continue
            n_in = sum(1 for f in rows if f[3] is not None and f[2] <= f[3])
            n_sp = sum(1 for f in rows if f[4] is not None and f[2] <= f[4])
            items.append("End position at %.1f s: inside the reference's band in %d of %d cases, "
                         "inside its spread in %d of %d; distance, band, xcable %d-%d change (m): %s."
                         % (t, n_in, len(rows), n_sp, len(rows), prev, finest,
                            "; ".join("%s %.2g / %s / %s" % (f[0].replace("slack_", ""), f[2], fmt(f[3], "%.2g"),
                                                          fmt(f[5], "%.2g")) for f in rows)))
    if facts["md_slack"]:
        items.append("Slack releases against MoorDyn just before t_1%%: %s m (MoorDyn's band %s m; "
                     "xcable to lumped.py %s m)."
                     % (", ".join("%s %.2g" % (c, dm) for c, dl, dm, mb in facts["md_slack"] if dm is not None),
                        ", ".join(fmt(mb, "%.2g") for c, dl, dm, mb in facts["md_slack"]),
                        ", ".join(fmt(dl, "%.2g") for c, dl, dm, mb in facts["md_slack"])))
    ok = [r for r in runs.values() if r.ok]
    if ok:
        drift = max(r.get("energy_drift", 0) for r in ok)
        rd = [float(refs[c].man["ledger_drift_rel"]) for c in names if refs[c].man.get("ledger_drift_rel")]
        items.append("Energy ledger: xcable's drift is at most %.1e of the initial strain energy in "
                     "all %d runs (reference: %s at N = 6400)."
                     % (drift, len(ok), "%.1e to %.1e" % (min(rd), max(rd)) if rd else "-"))
        fin = [r for r in ok if r.nodes == finest]
        sl = [r.wall for r in fin if r.case.startswith("slack")]
        pa = [r.wall for r in fin if not r.case.startswith("slack")]
        rs = [float(refs[c].man["wall_s"]) for c in names if c.startswith("slack") and refs[c].man.get("wall_s")]
        rp = [float(refs[c].man["wall_s"]) for c in names if not c.startswith("slack") and refs[c].man.get("wall_s")]
        items.append("Wall time at %d nodes: %s%s (reference lumped.py at N = 6400, `manifest.tsv`: %s%s)."
                     % (finest, "slack releases %.0f-%.0f s" % (min(sl), max(sl)) if sl else "",
                        (", paper runs %.1f-%.1f s" % (min(pa), max(pa))) if pa else "",
                        "slack releases %.0f-%.0f s" % (min(rs), max(rs)) if rs else "",
                        (", paper runs %.1f-%.1f s" % (min(rp), max(rp))) if rp else ""))
    out.append("".join("- " + x + "\n" for x in items))
    return out


def _per_tension(names, refs):
    seen, out = set(), []
    for c in names:
        if refs[c].ts not in seen:
            seen.add(refs[c].ts)
            out.append((c, refs[c].ts))
    return out


def build_report(args, exe, code_version, compiler, defaults, runs, refs, names, nodes,
                 load_start, started, statics0):
    finest = nodes[-1]
    L = []
    L.append("# xcable against the peer reference solutions\n")
    L.append("Generated by `bench/peer/compare.py` (%s UTC). Do not edit: rerun "
             "`python3 compare.py` in `bench/peer/`.\n"
             % started.strftime("%Y-%m-%d %H:%M"))
    L.append("xcable: `%s` (sha256 %s...), code_version %s, %s. "
             "It is a private copy of `/work/main/bin/xcable` (`cp /work/main/bin/xcable "
             "/tmp/xcable_peer`) or, where that does not exist, a private release build "
             "(`rsync -a --exclude build --exclude .git /work/main/ /tmp/peerbuild/ && cd "
             "/tmp/peerbuild && rm -rf build && fpm install --profile release --prefix .`). "
             "Scratch runs (namelists, HDF5) in `%s`. Load average at the start %s, at the end %s "
             "(2-core machine, shared): wall times are indicative.\n"
             % (exe, EXE_SHA[:16], code_version, compiler, args.work, load_start, loadavg()))
    if REUSED:
        when = sorted(w for w, _ in REUSED if w)
        loads = [x for _, x in REUSED if x is not None]
        L.append("%d of the runs were reused from an earlier call (%s); their wall times are "
                 "from that call%s.\n" % (len(REUSED), "%s to %s UTC" % (when[0], when[-1]) if when
                                           else "time not recorded",
                                           ", 1-min load average %.1f-%.1f" % (min(loads), max(loads))
                                           if loads else ""))
    L.append("What is compared: xcable (scheme 'rod', default numerics) at %s nodes against "
             "`lumped.py` at its finest N (N = 6400 segments, `data/<case>.tsv`), and MoorDyn "
             "(N = 800, `data/moordyn_<case>.tsv`) only before the recoil reaches the fixed end. "
             "'band' is the reference's own uncertainty: the difference between its two finest N "
             "(3200 and 6400), from `runs/` where that directory exists, else from `summary.md`. "
             "'inside' means |xcable - reference| <= band; 'outside (xk)' gives the ratio. Each "
             "case's 'xcable %d-%d' is xcable's own change between its two finest grids, its own "
             "resolution.\n" % (", ".join(str(n) for n in nodes), nodes[-2] if len(nodes) > 1 else finest,
                                finest))

    L.append("## Conventions checked\n")
    L.append("peer_common.py against xcable's defaults (the resolved namelist of a run with an "
             "empty scene) and against the generated namelists (read back from the result files). "
             "Every scene value is written explicitly into the namelists, whether it differs or "
             "not.\n")
    L.append(conventions(defaults, runs))

    findings = []
    facts = {"paper": [], "slack": [], "early": [], "md_paper": [], "md_slack": []}
    compact_paper = []
    prev_n = None

    # ---------------------------------------------------------------- statics
    L.append("\n## Static state\n")
    L.append("Span (m) of xcable's static state against the continuum catenary (quadrature, "
             "`summary.md`) and the lumped chain at N = 6400 (`manifest.tsv`); xcable's initial "
             "bending energy against the reference's (`E_bending` at t = 0). A span equal to "
             "the continuum's to the discretisation error confirms the same mass, law and static "
             "tension.\n")
    body = []
    seen = set()
    for c in names:
        ref = refs[c]
        if ref.ts in seen:
            continue
        seen.add(ref.ts)
        row = ["%g kN" % (ref.ts / 1000), fmt(ref.quad_span(), "%.6f"),
               fmt(float(ref.man["span"]) if ref.man.get("span") else None, "%.6f")]
        for n in nodes:
            r = runs.get((c, n))
            if r and hasattr(r, "span"):
                q = ref.quad_span()
                row.append("%.6f (%+.1e)" % (r.span, r.span - q) if q else "%.6f" % r.span)
            else:
                row.append("-")
        s0, q = statics0.get(ref.ts), ref.quad_span()
        row.append("%.6f (%+.1e)" % (s0, s0 - q) if s0 is not None and q else "-")
        rf = runs.get((c, finest))
        row.append("%.3g / %.3g" % (rf.e_bend0, float(ref.lumped["E_bending"][0]))
                   if rf is not None and getattr(rf, "e_bend0", None) is not None else "-")
        body.append(row)
    L.append(table(["T_s", "span quadrature", "span lumped 6400"]
                   + ["xcable %d (- quad)" % n for n in nodes]
                   + ["xcable %d, EI = 1e-6 (- quad)" % finest,
                      "E_bending(0) J xcable %d / lumped" % finest], body))
    L.append("The quadrature and the reference's chain leave bending out of the static state, "
             "xcable's statics include it (see the conventions): the column with EI = 1e-6 N m^2 "
             "(the smallest xcable accepts; a statics check only, not used below) shows how much "
             "of xcable's span difference is that static effect of EI. At 6 decimals the "
             "quadrature span itself is rounded to 5e-7 m.\n")

    # ---------------------------------------------------------------- paper runs
    paper = [c for c in names if refs[c].paper]
    if paper:
        L.append("\n## Paper runs: plateau speed and 1 % drop at the fixed end\n")
        L.append("Plateau: mean speed of the released end over the reference's samples (1 ms) from "
                 "t_break + 5 ms to t_end. t_1%: first time the tension at the fixed end is 1 % "
                 "below its static value. Reference: lumped.py N = 6400; band: |N=6400 - N=3200|.\n")
        for c in paper:
            ref = refs[c]
            v_ref, v_band, v_src = ref.plateau()
            t_ref, t_band, t_src = ref.drop_time()
            t0, t1 = ref.plateau_window()
            times = ref.lumped["t"][(ref.lumped["t"] >= t0 - 1e-9) & (ref.lumped["t"] <= t1 + 1e-9)]
            L.append("\n### %s (T_s = %g kN, t_break = %g s, t_end = %g s)\n"
                     % (c, ref.ts / 1000, ref.tb, ref.te))
            L.append("Reference: plateau %.4f m/s (band %s, from %s; theory %s m/s), t_1%% %.5f s "
                     "(band %s s, from %s); ledger drift %s of E_strain(0); wall %s s.\n"
                     % (v_ref, fmt(v_band, "%.2g"), v_src, fmt(ref.theory_plateau(), "%.4f"),
                        t_ref, fmt(t_band, "%.2g"), t_src, ref.man.get("ledger_drift_rel", "-"),
                        ref.man.get("wall_s", "-")))
            body = []
            prev_v = prev_t = None
            for n in nodes:
                r = runs.get((c, n))
                if r is None or not hasattr(r, "t"):
                    body.append([n, "no result"] + [""] * 12)
                    prev_v = prev_t = None
                    continue
                v = r.mean_speed(times)
                td = r.drop_time()
                dv_ = None if v is None else abs(v - v_ref)
                dt_ = None if td is None else abs(td - t_ref)
                own_v = None if v is None or prev_v is None else v - prev_v
                own_t = None if td is None or prev_t is None else td - prev_t
                body.append([n, fmt(v, "%.4f"), fmt(None if v is None else v - v_ref, "%+.2e"),
                             fmt(v_band, "%.1e"), verdict(dv_, v_band), fmt(own_v, "%+.1e"),
                             fmt(td, "%.5f"), fmt(None if td is None else (td - t_ref) * 1e3, "%+.4f"),
                             fmt(None if t_band is None else t_band * 1e3, "%.2g"),
                             verdict(dt_, t_band), fmt(None if own_t is None else own_t * 1e3, "%+.4f"),
                             fmt(r.get("energy_drift"), "%.1e"),
                             "%.2f" % r.wall, r.status])
                if n == finest:
                    facts["paper"].append((c, v, v_ref, v_band, td, t_ref, t_band, own_v, own_t))
                    compact_paper.append([c, fmt(v, "%.4f"), "%.4f" % v_ref,
                                          fmt(None if v is None else v - v_ref, "%+.1e"),
                                          fmt(v_band, "%.1e"), verdict(dv_, v_band), fmt(own_v, "%+.1e"),
                                          fmt(td, "%.5f"), "%.5f" % t_ref,
                                          fmt(None if td is None else (td - t_ref) * 1e3, "%+.4f"),
                                          fmt(None if t_band is None else t_band * 1e3, "%.2g"),
                                          verdict(dt_, t_band),
                                          fmt(None if own_t is None else own_t * 1e3, "%+.4f")])
                    if dv_ is not None and v_band is not None and dv_ > v_band:
                        findings.append((c, "plateau speed", "%.4f vs %.4f m/s: %+.2e m/s (band %.1e; "
                                         "xcable %d-%d change %s)" % (v, v_ref, v - v_ref, v_band,
                                                                       prev_n, n, fmt(own_v, "%+.1e"))))
                    if dt_ is not None and t_band is not None and dt_ > t_band:
                        findings.append((c, "t_1%", "%.5f vs %.5f s: %+.4f ms (band %.2g ms; xcable "
                                         "%d-%d change %s ms)" % (td, t_ref, (td - t_ref) * 1e3,
                                                                  t_band * 1e3, prev_n, n,
                                                                  fmt(None if own_t is None else own_t * 1e3,
                                                                      "%+.4f"))))
                prev_v, prev_t, prev_n = v, td, n
            L.append(table(["nodes", "plateau m/s", "- ref", "band", "vs band", "change from previous",
                            "t_1% s", "- ref ms", "band ms", "vs band", "change from previous ms",
                            "energy drift", "wall s", "status"], body))
        L.append("\n### Paper runs at %d nodes, all cases\n" % finest)
        L.append(table(["case", "plateau xcable", "ref", "- ref", "band", "vs band",
                        "xcable %d-%d" % (nodes[-2] if len(nodes) > 1 else finest, finest),
                        "t_1% xcable s", "ref s", "- ref ms", "band ms", "vs band",
                        "xcable %d-%d ms" % (nodes[-2] if len(nodes) > 1 else finest, finest)],
                       compact_paper))

        # ---- MoorDyn
        L.append("\n## Paper runs against MoorDyn (before the recoil reaches the fixed end)\n")
        L.append("MoorDyn N = 800 (`data/moordyn_<case>.tsv`; its N = 400 from `summary.md`) in "
                 "summary.md's window, which ends before MoorDyn's t_valid; its t_1% is detected "
                 "every step (from `runs/` where present, else `summary.md` to 5 decimals). MoorDyn's law is a 30-point table with no "
                 "compression, which is not the reference's scene: 'law effect' is what that law "
                 "changes on the same chain (lumped.py with MoorDyn's table minus lumped.py with "
                 "the tanh law, both N = 400, `summary.md`), so xcable - MoorDyn should be near minus "
                 "the law effect: 'residual' = (xcable - MoorDyn) + law effect, to be read against "
                 "MoorDyn's band |N=800 - N=400| (the law effect is itself an N = 400 figure).\n")
        body = []
        for c in paper:
            ref = refs[c]
            m = ref.moordyn_paper()
            if m is None:
                continue
            w0, w1 = m["window"]
            times = ref.lumped["t"][(ref.lumped["t"] >= w0 - 1e-9) & (ref.lumped["t"] <= w1 + 1e-9)]
            md800 = m.get("md800_data", m["md800"][0])
            r = runs.get((c, finest))
            v = r.mean_speed(times) if r is not None and hasattr(r, "t") else None
            td = r.drop_time() if r is not None and hasattr(r, "t") else None
            t4, t8 = m.get("md_t_full", (m["md400"][1], m["md800"][1]))
            law_v = m["table400"][0] - m["tanh400"][0]
            law_t = m["table400"][1] - m["tanh400"][1]
            facts["md_paper"].append((c, None if v is None else v - md800 + law_v,
                                      abs(m["md800"][0] - m["md400"][0]),
                                      None if td is None else td - t8 + law_t, abs(t8 - t4)))
            body.append([c, "%.3f-%.3f" % (w0, w1), fmt(v, "%.3f"), "%.3f" % m["lumped6400"],
                         "%.3f" % md800, fmt(None if v is None else v - md800, "%+.3f"),
                         "%.3f" % abs(m["md800"][0] - m["md400"][0]), "%+.3f" % law_v,
                         fmt(None if v is None else v - md800 + law_v, "%+.3f"),
                         fmt(td, "%.5f"), "%.5f" % t8,
                         fmt(None if td is None else (td - t8) * 1e3, "%+.3f"),
                         "%.3f" % (abs(t8 - t4) * 1e3), "%+.2f" % (law_t * 1e3),
                         fmt(None if td is None else (td - t8 + law_t) * 1e3, "%+.3f")])
        L.append(table(["case", "window s", "xcable %d m/s" % finest, "lumped 6400", "MoorDyn 800",
                        "xcable - MoorDyn", "MoorDyn band", "law effect", "residual",
                        "xcable t_1% s", "MoorDyn t_1% s", "xcable - MoorDyn ms", "MoorDyn band ms",
                        "law effect ms", "residual ms"], body))

    # ---------------------------------------------------------------- slack releases
    slack = [c for c in names if not refs[c].paper]
    if slack:
        L.append("\n## Slack releases: released-end position\n")
        L.append("x, z (m) of the released end; dist = distance to the reference (lumped.py, "
                 "N = 6400, `data/<case>.tsv`). band = |dr| between the reference's N = 3200 and "
                 "6400 (`summary.md`); spread (`summary.md`, README) = the largest distance between "
                 "its N = 1600, 3200, 6400 and N = 1600 at Courant 0.25, the README's measure of "
                 "how far the buckling phase is from converged. The verdict is against the band.\n")
        compact = []
        for c in slack:
            ref = refs[c]
            bands = ref.slack_bands()
            L.append("\n### %s (T_s = %g kN, t_break = %g s)\n" % (c, ref.ts / 1000, ref.tb))
            body = []
            row = ["ref N=6400"]
            for t in TIMES:
                p = ref.at(ref.lumped, t)
                row.append(fmt(p and p[0], "%.4f") + ", " + fmt(p and p[1], "%.4f"))
            body.append(row + ["%s" % ref.man.get("ledger_drift_rel", "-"), ref.man.get("wall_s", "-"), ""])
            body.append(["ref band / spread"] + ["%s / %s" % (fmt(bands[t][0], "%.2g"), fmt(bands[t][1], "%.2g"))
                                                 for t in TIMES] + ["", "", ""])
            for n in nodes:
                r = runs.get((c, n))
                if r is None or not hasattr(r, "t"):
                    body.append([n] + ["no result"] * 4 + ["", "", ""])
                    continue
                row = [n]
                for t in TIMES:
                    p, q = r.pos(t), ref.at(ref.lumped, t)
                    if p is None or q is None:
                        row.append("- (reached %.3f s)" % r.t_reached if not r.ok else "-")
                        continue
                    d = math.hypot(p[0] - q[0], p[1] - q[1])
                    row.append("%.4f, %.4f; %.2g %s" % (p[0], p[1], d,
                                                          "in" if bands[t][0] is not None and d <= bands[t][0] else
                                                          ("out" if bands[t][0] is not None else "")))
                body.append(row + [fmt(r.get("energy_drift"), "%.1e"), "%.2f" % r.wall, r.status])
            L.append(table(["nodes"] + ["%.1f s: x, z; dist" % t for t in TIMES]
                           + ["energy drift", "wall s", "status"], body))
            # compact summary at the finest grid, with xcable's own change
            rf, rp = runs.get((c, finest)), runs.get((c, nodes[-2])) if len(nodes) > 1 else None
            for t in TIMES:
                q = ref.at(ref.lumped, t)
                p = rf.pos(t) if rf is not None and hasattr(rf, "t") else None
                pp = rp.pos(t) if rp is not None and hasattr(rp, "t") else None
                d = None if p is None or q is None else math.hypot(p[0] - q[0], p[1] - q[1])
                own = None if p is None or pp is None else math.hypot(p[0] - pp[0], p[1] - pp[1])
                b, s = bands[t]
                facts["slack"].append((c, t, d, b, s, own))
                compact.append([c, "%.1f" % t, fmt(d, "%.2g"), fmt(b, "%.2g"), verdict(d, b),
                                fmt(s, "%.2g"), "inside" if d is not None and s is not None and d <= s else
                                ("outside" if d is not None and s is not None else "-"), fmt(own, "%.2g")])
                if d is not None and b is not None and d > b:
                    findings.append((c, "end position at %.1f s" % t,
                                     "dist = %.3g m (x %+.4f, z %+.4f), band %.2g m, spread %s m, xcable %d-%d change %s m"
                                     % (d, p[0] - q[0], p[1] - q[1], b, fmt(s, "%.2g"), nodes[-2], finest,
                                        fmt(own, "%.2g"))))
        L.append("\n### Slack releases at %d nodes, all cases\n" % finest)
        L.append(table(["case", "t s", "dist m", "band m", "vs band", "spread m", "vs spread",
                        "xcable %d-%d m" % (nodes[-2] if len(nodes) > 1 else finest, finest)], compact))

        # ---- when the difference appears
        L.append("\n### When the difference appears (xcable at %d nodes)\n" % finest)
        L.append("dist at every 10 ms sample: its value up to the reference's t_1% (the unloading "
                 "front reaching the fixed end, after which the fixed end goes into compression and "
                 "buckles), and the first samples where it exceeds 1 mm and 1 cm.\n")
        body = []
        for c in slack:
            ref = refs[c]
            r = runs.get((c, finest))
            if r is None or not hasattr(r, "t"):
                continue
            tf, _ = ref.slack_front()
            ts_, ds_ = [], []
            for k, t in enumerate(ref.lumped["t"]):
                p = r.pos(float(t))
                if p is None:
                    continue
                ts_.append(float(t))
                ds_.append(math.hypot(p[0] - ref.lumped["end_x"][k], p[1] - ref.lumped["end_z"][k]))
            ts_, ds_ = np.array(ts_), np.array(ds_)

            def first(lim):
                k = np.nonzero(ds_ > lim)[0]
                return "%.2f" % ts_[k[0]] if len(k) else "-"
            before = ds_[ts_ <= (tf if tf else 0) + 1e-9]
            k1 = np.nonzero(ds_ > 1e-2)[0]
            facts["early"].append((c, tf, float(before.max()) if len(before) else None,
                                   float(ts_[k1[0]]) if len(k1) else None))
            body.append([c, fmt(tf, "%.3f"), fmt(before.max() if len(before) else None, "%.2g"),
                         first(1e-3), first(1e-2), fmt(float(ds_[np.argmin(abs(ts_ - 0.5))]), "%.2g"),
                         fmt(float(ds_.max()), "%.2g")])
        L.append(table(["case", "ref t_1% s", "max dist up to t_1% m", "first dist > 1 mm s",
                        "first dist > 1 cm s", "dist at 0.5 s m", "max dist to 2 s m"], body))

        # ---- MoorDyn, slack: before the front reaches the fixed end
        L.append("\n## Slack releases against MoorDyn (before the recoil reaches the fixed end)\n")
        L.append("The unloading front reaches the fixed end (t_1%%, the reference's N = 6400 run) "
                 "well before 0.5 s in every slack release, and from there on MoorDyn has no "
                 "compression, so it is not a reference at 0.5-2.0 s (README: 0.2-1.7 m off the "
                 "tanh law already at 0.5 s). It is compared here at the last 10 ms sample before "
                 "the reference's t_1%%, where the whole cable is still in tension. Bands: "
                 "|N=6400 - N=3200| (lumped) and |N=800 - N=400| (MoorDyn) from `runs/` where "
                 "present. xcable at %d nodes.\n" % finest)
        body = []
        for c in slack:
            ref = refs[c]
            tf, tf_src = ref.slack_front()
            r = runs.get((c, finest))
            xt = r.drop_time() if r is not None and hasattr(r, "t") else None
            if tf is None:
                continue
            tc = math.floor(tf / ref.sample + 1e-9) * ref.sample
            if abs(tc - tf) < 1e-9:
                tc -= ref.sample
            tc = round(tc, 6)
            q = ref.at(ref.lumped, tc)
            mdp = ref.at(ref.moordyn, tc) if ref.moordyn is not None else None
            p = r.pos(tc) if r is not None and hasattr(r, "t") else None
            _, r32 = ref.run_info("lumped_%s_N3200" % c)
            _, m4 = ref.run_info("moordyn_%s_N400" % c)
            lb = mb = None
            if r32 is not None and q is not None:
                q2 = ref.at(r32, tc)
                lb = math.hypot(q[0] - q2[0], q[1] - q2[1]) if q2 else None
            if m4 is not None and mdp is not None:
                m2 = ref.at(m4, tc)
                mb = math.hypot(mdp[0] - m2[0], mdp[1] - m2[1]) if m2 else None
            dl = None if p is None or q is None else math.hypot(p[0] - q[0], p[1] - q[1])
            dm = None if p is None or mdp is None else math.hypot(p[0] - mdp[0], p[1] - mdp[1])
            facts["md_slack"].append((c, dl, dm, mb))
            body.append([c, fmt(tf, "%.4f"), fmt(xt, "%.4f"), "%.2f" % tc,
                         "%.4f, %.4f" % p if p else "-", "%.4f, %.4f" % q if q else "-",
                         fmt(dl, "%.2g"), "<1e-6" if lb == 0 else fmt(lb, "%.2g"),
                         "%.4f, %.4f" % mdp if mdp else "-", fmt(dm, "%.2g"),
                         "<1e-6" if mb == 0 else fmt(mb, "%.2g")])
        L.append(table(["case", "t_1% ref s", "t_1% xcable s", "t s", "xcable x, z", "lumped x, z",
                        "dist lumped", "lumped band", "MoorDyn x, z", "dist MoorDyn", "MoorDyn band"],
                       body))

    # ---------------------------------------------------------------- cost
    L.append("\n## xcable runs: cost and energy ledger\n")
    L.append("wall: the whole process (statics, dynamics, HDF5), measured around the call; "
             "dynamics: `/summary wall_time`. energy drift: `/summary energy_drift` (max ledger "
             "change / initial strain energy); reference: `manifest.tsv` ledger_drift_rel of the "
             "N = 6400 run and its wall time (lumped.py, numpy, same machine).\n")
    body = []
    for c in names:
        ref = refs[c]
        for n in nodes:
            r = runs.get((c, n))
            if r is None or not hasattr(r, "summary"):
                body.append([c, n, "-", "-", "-", "-", "-", "-", "-", r.status if r else "-", ""])
                continue
            warn = r.warnings.replace("\n", "; ").replace("|", "/")
            body.append([c, n, r.get("steps", "-"), fmt(r.get("dt_used"), "%.3g"),
                         r.get("rejected_steps", "-"), "%.2f" % r.wall, fmt(r.get("wall_time"), "%.2f"),
                         fmt(r.get("energy_drift"), "%.2e"), ref.man.get("ledger_drift_rel", "-"),
                         r.status + ("" if r.ok else ": " + r.reason), warn or "-"])
    L.append(table(["case", "nodes", "steps", "dt s", "rejected", "wall s", "dynamics s",
                    "energy drift", "ref drift (6400)", "status", "warnings"], body))
    tot = sum(r.wall for r in runs.values())
    L.append("\nTotal xcable wall time: %.0f s for %d runs.\n" % (tot, len(runs)))

    # ---------------------------------------------------------------- findings
    L.append("\n## Differences beyond the reference's band (xcable at %d nodes)\n" % finest)
    if not findings:
        L.append("None: every compared quantity is inside the reference's band.\n")
    else:
        L.append("Listed as computed; nothing was tuned. 'xcable %d-%d change' is xcable's own "
                 "resolution at that point: where it is as large as the difference, a finer xcable "
                 "grid would be needed to tell whether the two codes disagree.\n\n"
                 % (nodes[-2] if len(nodes) > 1 else finest, finest))
        L.append("".join("- %s, %s: %s\n" % (c, what, txt) for c, what, txt in findings))
    L[4:4] = summary_section(facts, runs, refs, names, nodes, statics0)
    failed = [r for r in runs.values() if not r.ok]
    if failed:
        L.append("\nRuns that did not complete:\n\n")
        for r in failed:
            L.append("- %s at %d nodes: %s %s (rc %d)\n" % (r.case, r.nodes, r.status,
                                                          getattr(r, "reason", ""), r.rc))
    return "\n".join(x.rstrip("\n") + "\n" for x in L)


if __name__ == "__main__":
    main()
