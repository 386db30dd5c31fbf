#!/usr/bin/env python3
"""The long attack run: the short corpus (tests/attack/inputs.py) plus generated and mutated
inputs on every input surface of `chute`, each run against the real binary with a time and a
memory limit and classified (tests/attack/harness.py). Writes the table of inputs per class and
outcomes, and every bad outcome, to --report (markdown).

   bench/attack/attack.py --chute build/bin/chute [--per-class 1.0] [--seed 20]
                          [--work /tmp/chute_attack] [--report bench/attack/results.md]

--per-class scales the number of generated inputs (1.0: about 1,300 inputs in all). With a
sanitizer build (bench/attack/README.md) ASan's RSS limit replaces RLIMIT_AS.
"""
import argparse
import concurrent.futures
import os
import random
import re
import shutil
import sys
import time
import tomllib

HERE = os.path.dirname(os.path.abspath(__file__))
SOURCE = os.path.dirname(os.path.dirname(HERE))
sys.path.insert(0, os.path.join(SOURCE, "tests", "attack"))
import harness  # noqa: E402
import inputs  # noqa: E402
from inputs import ANY_CLEAN, ERROR, OK, Input  # noqa: E402

HOSTILE_NUMBERS = ["0", "-1", "1e308", "-1e308", "5e-324", "nan", "inf", "-inf", "1e9",
                   "2147483648", "9223372036854775808", "1e-300", "\"x\"", "[]", "{}", "true",
                   "-0.0", "1e100", "99999999999999999999"]
HOSTILE_ARGS = ["", "-1", "0", "nan", "inf", "1e308", "5e-324", "abc", "x" * 5000, "\u00e9",
                "/dev/zero", "--", "-", "1e9", "100000000", "20000x20000", "0x0", "8x8",
                "8192x8192", "4096x4096", "t"]
NUMBER = re.compile(rb"(?<![A-Za-z_.])-?\d+(\.\d+)?([eE][-+]?\d+)?")


def mutate_bytes(rng, data, text=True):
    """One random edit of a file: bytes changed, a line deleted, duplicated or swapped, a number
    replaced by a hostile one, a cut, brackets inserted."""
    data = bytearray(data)
    kind = rng.choice(["flip", "delete", "duplicate", "swap", "number", "truncate", "brackets"]
                      if text else ["flip", "truncate", "number", "flip"])
    if not data:
        return bytes(data), "empty"
    if kind == "flip":
        for _ in range(rng.randint(1, 8)):
            data[rng.randrange(len(data))] = rng.randrange(256)
    elif kind == "truncate":
        data = data[: rng.randrange(len(data))]
    elif kind in ("delete", "duplicate", "swap"):
        lines = bytes(data).split(b"\n")
        i, j = rng.randrange(len(lines)), rng.randrange(len(lines))
        if kind == "delete":
            del lines[i]
        elif kind == "duplicate":
            lines.insert(i, lines[i])
        else:
            lines[i], lines[j] = lines[j], lines[i]
        data = bytearray(b"\n".join(lines))
    elif kind == "number":
        matches = list(NUMBER.finditer(bytes(data)))
        if matches:
            m = rng.choice(matches)
            data[m.start():m.end()] = rng.choice(HOSTILE_NUMBERS).encode()
    elif kind == "brackets":
        at = rng.randrange(len(data))
        data[at:at] = b"[" * rng.choice([2, 70, 10000])
    return bytes(data), kind


def case_inputs(ctx, rng, n):
    """Mutated shipped cases (their meshes beside them), run a few steps."""
    out, d = [], ctx.path("cases")
    os.makedirs(d, exist_ok=True)
    sources = sorted(os.path.join(SOURCE, "cases", f) for f in os.listdir(os.path.join(SOURCE,
                                                                                       "cases")))
    sources.append(os.path.join(SOURCE, "mesh", "examples", "flat_canopy.toml"))
    for s in sources:
        if s.endswith(".msh"):
            link = os.path.join(d, os.path.basename(s))
            if not os.path.lexists(link):
                os.symlink(s, link)
    shutil.copy(os.path.join(SOURCE, "mesh", "examples", "flat_canopy.msh"), d)
    tomls = [s for s in sources if s.endswith(".toml")]
    for k in range(n):
        src = rng.choice(tomls)
        raw = open(src, "rb").read()
        data, kind = mutate_bytes(rng, raw)
        name = "%s_%d.toml" % (os.path.basename(src)[:-5], k)
        path = ctx.write(os.path.join("cases", name), data)
        extra = []
        spec = tomllib.loads(raw.decode())
        solver = spec.get("solver", {})
        if solver.get("type", "dynamic") == "dynamic" and "dt" in solver:
            # A few steps: an implicit case's dt is its step; an explicit case's dt only caps
            # the stable step, often a hundred times shorter (3 dt of the packed slider C-9 were
            # 600 steps with its contact: 7 s in Release, past the sanitizer build's limit), so
            # an explicit case runs 3 dt / 100 with dt / 100 as its cap.
            explicit = solver.get("integrator") == "central_difference"
            scale = 0.01 if explicit else 1.0  # dt scaled with t_end: a step still fits
            extra = ["--set", "solver.t_end=%r" % (3 * solver["dt"] * scale)]
            if explicit:
                extra += ["--set", "solver.dt=%r" % (solver["dt"] * scale)]
        out.append(Input("case TOML", "%s %s" % (name, kind), inputs.run_case(ctx, path, *extra),
                         ANY_CLEAN, None, 90))
    return out


def scalar_paths(value, prefix=""):
    """Dotted paths of the scalars of a TOML document (array elements by index)."""
    if isinstance(value, dict):
        for k, v in value.items():
            yield from scalar_paths(v, prefix + k + ".")
    elif isinstance(value, list):
        for i, v in enumerate(value):
            yield from scalar_paths(v, prefix + str(i) + ".")
    else:
        yield prefix[:-1]


def set_inputs(ctx, rng, n):
    out = []
    cases = ["pulley.toml", "airbag.toml", "hencky.toml", "capstan_belt.toml", "bead_1.toml"]
    for k in range(n):
        case = ctx.case(rng.choice(cases))
        spec = tomllib.load(open(case, "rb"))
        paths = list(scalar_paths(spec))
        path = rng.choice(paths)
        parts = path.split(".")
        how = rng.choice(["value", "value", "index", "deeper", "typo", "prefix"])
        if how == "index":
            parts[rng.randrange(len(parts))] = rng.choice(["99999999999", "-1", "0", "1e3", ""])
        elif how == "deeper":
            parts += rng.choice([["0"], ["x"], ["0", "0"]])
        elif how == "typo" and parts[-1]:
            w = list(parts[-1])
            w[rng.randrange(len(w))] = rng.choice("xyz_.")
            parts[-1] = "".join(w)
        elif how == "prefix":
            parts = parts[: rng.randrange(1, len(parts) + 1)]
        value = rng.choice(HOSTILE_NUMBERS + ["[[[[1]]]]", "\"" + "x" * 3000 + "\"", "{a=1}",
                                              "bossak", "static", "1", "0.5"])
        extra = []
        solver = spec.get("solver", {})
        if solver.get("type", "dynamic") == "dynamic" and "dt" in solver:
            # A few steps: an implicit case's dt is its step; an explicit case's dt only caps
            # the stable step, often a hundred times shorter (3 dt of the packed slider C-9 were
            # 600 steps with its contact: 7 s in Release, past the sanitizer build's limit), so
            # an explicit case runs 3 dt / 100 with dt / 100 as its cap.
            explicit = solver.get("integrator") == "central_difference"
            scale = 0.01 if explicit else 1.0  # dt scaled with t_end: a step still fits
            extra = ["--set", "solver.t_end=%r" % (3 * solver["dt"] * scale)]
            if explicit:
                extra += ["--set", "solver.dt=%r" % (solver["dt"] * scale)]
        assignment = ".".join(parts) + "=" + value
        out.append(Input("--set", assignment[:60], inputs.run_case(ctx, case, *extra, "--set",
                                                                   assignment),
                         ANY_CLEAN, None, 90))
    return out


def msh_inputs(ctx, rng, n):
    out = []
    seeds = sorted(ctx.seeds.items())
    for k in range(n):
        key, seed = seeds[k % len(seeds)]
        data = open(seed, "rb").read()
        if rng.random() < 0.25:
            section = rng.choice([b"$Nodes", b"$Elements"])
            value = rng.choice([0, 1, 2 ** 31, 2 ** 63 - 1, 10 ** 9, 376, 378, 776, 778])
            data = inputs.replace_count(data, section, value=value, fmt=key)
            kind = "%s count %d" % (section.decode(), value)
        else:
            data, kind = mutate_bytes(rng, data, text=not key.endswith("b"))
        out.append(inputs.mesh_run(ctx, "%s_%d %s" % (key, k, kind), data, ANY_CLEAN))
    return out


def geo_inputs(ctx, rng):
    """Scripts through `mesh geo` (bounded) and through a case (never run)."""
    c, out = ctx.chute, []
    G = ".geo (case, C API, mesh geo)"
    square = ("Point(1)={0,0,0};Point(2)={1,0,0};Point(3)={1,1,0};Point(4)={0,1,0};"
              "Line(1)={1,2};Line(2)={2,3};Line(3)={3,4};Line(4)={4,1};Curve Loop(1)={1,2,3,4};"
              "Plane Surface(1)={1};Physical Surface(\"s\")={1};\n")
    scripts = {
        "while loop": "i = 0;\nFor j In {1:1e15}\n  i += j;\nEndFor\n",
        "include /dev/zero": 'Include "/dev/zero";\n',
        "merge fifo": 'Merge "%s";\n' % ctx.path("fifo.msh"),
        "huge list": "x[] = {1:1e10};\n",
        "exit without mesh": "Exit;\n",
        "error call": 'Error("stop");\n' + square,
        "no physical groups": square.replace('Physical Surface("s")={1};', ""),
        "tiny size": "Mesh.CharacteristicLengthMax = 1e-6;\n" + square,
        "format 1.0": "Mesh.MshFileVersion = 1.0;\n" + square,
        "3-D tetrahedra": square + "Extrude{0,0,1}{Surface{1};}\nPhysical Volume(\"v\")={1};\n",
        "second order": "Mesh.ElementOrder = 2;\n" + square,
        "valid square": square,
        "recursion": 'Macro M\n Call M;\nReturn\nCall M;\n',
    }
    for name, text in scripts.items():
        p = ctx.write("geo_%s.geo" % name.replace(" ", "_"), text)
        expect = OK if name in ("valid square",) else ANY_CLEAN
        out.append(Input(G, "mesh geo " + name, [c, "mesh", "geo", p, "--out",
                                                 ctx.path("geo_out.msh"), "--timeout", "3",
                                                 "--max-memory", "1024"], expect, None, 30))
        # The same script named by a case, with a command that must never run.
        evil = ctx.write("geo_evil_%s.geo" % name.replace(" ", "_"),
                         'System "touch %s";\n%s' % (ctx.marker, text))
        case = ctx.write("geo_case_%s.toml" % name.replace(" ", "_"),
                         inputs.mesh_case_text(ctx, evil))
        out.append(Input(G, "case over " + name, inputs.run_case(ctx, case), ERROR, ctx.marker,
                         20))
    return out


def csv_inputs(ctx, rng, n):
    out = []
    c = ctx.chute
    for k in range(n):
        data, kind = mutate_bytes(rng, ctx.probes.encode())
        d = ctx.path("csv_%d" % k)
        os.makedirs(d, exist_ok=True)
        with open(os.path.join(d, "probes.csv"), "wb") as f:
            f.write(data)
        cmd = [c, "plot", d, "--columns", ctx.columns, "--out", ctx.path("csv_%d.png" % k)]
        if k % 4 == 0:  # the mutated file as a reference curve of the good run
            cmd = [c, "plot", ctx.path("run"), "--columns", ctx.columns, "--reference",
                   os.path.join(d, "probes.csv"), "--out", ctx.path("csv_%d.png" % k)]
        out.append(Input("plot CSV", "csv %d %s" % (k, kind), cmd, ANY_CLEAN, None, 60))
    return out


def arg_inputs(ctx, rng, n):
    c, out = ctx.chute, []
    pulley = ctx.case("pulley.toml")
    verbs = {
        "run": ([pulley], ["--out", "--set", "--checkpoint-every", "--restart", "--quiet",
                           "--newton-log"]),
        "render": ([ctx.path("run")], ["--times", "--all", "--view", "--color", "--compare",
                                       "--size", "--out", "--quiet"]),
        "plot": ([ctx.path("run")], ["--columns", "--reference", "--title", "--size", "--out"]),
        "couple": ([ctx.case("canopy_coupled.toml")], ["--scheme", "--relaxation", "--omega",
                                                       "--tolerance", "--max-iterations",
                                                       "--window", "--t-end", "--surface"]),
        "mesh parachute": ([], ["--gores", "--diameter", "--line-length", "--element-size",
                                "--vent-diameter", "--line-elements", "--mesh-algorithm",
                                "--slider", "--slider-divisions", "--payload-mass",
                                "--payload-box", "--riser-length", "--riser-elements", "--start",
                                "--inflated-ratio", "--bundle-radius", "--slider-drop",
                                "--line-slack", "--out", "--case", "--config", "--t-end", "--dt",
                                "--max-elements", "--units", "--pressure", "--ramp-time"]),
        "mesh geo": ([os.path.join(SOURCE, "mesh", "examples", "flat_canopy.geo")],
                     ["--out", "--timeout", "--max-memory"]),
    }
    base = {"mesh parachute": ["--gores", "8", "--diameter", "2", "--line-length", "2",
                               "--element-size", "0.4", "--out", ctx.path("a.msh")],
            "run": ["--set", "solver.t_end=0.05", "--out", ctx.path("args_out")],
            "mesh geo": ["--out", ctx.path("args_geo.msh")],
            "couple": ["--t-end", "0.002"],
            "plot": ["--columns", ctx.columns, "--out", ctx.path("args.png")],
            "render": ["--out", ctx.path("args_render")]}
    for k in range(n):
        verb = rng.choice(sorted(verbs))
        positional, options = verbs[verb]
        args = list(positional) if rng.random() < 0.9 else []
        args += base.get(verb, [])
        for _ in range(rng.randint(1, 3)):
            opt = rng.choice(options)
            value = rng.choice(HOSTILE_ARGS + [ctx.path("fifo.csv"), ctx.path("dir.toml"),
                                               ctx.work])
            args += [opt, value]
        out.append(Input("arguments of every verb", ("%s %s" % (verb, " ".join(
            a[-12:] for a in args[-4:])))[:70], [c] + verb.split() + args, ANY_CLEAN, None, 120))
    return out


def parachute_inputs(ctx, rng, n):
    """`chute mesh parachute` over classes of values of every geometric option (tiny,
    subnormal, huge, near a bound, NaN, inf, negative, zero) on five kinds of parachute; a
    generated case must fly two steps (tests/attack/parachute_check.py)."""
    variants = {"plain": [], "slider": ["--slider", "0.3", "--start", "folded"],
                "box": ["--payload-mass", "1", "--payload-box", "0.2,0.2,0.2", "--riser-length",
                        "0.5"],
                "vent": ["--vent-diameter", "0.4", "--start", "inflated"],
                "point": ["--payload-mass", "1", "--riser-length", "0.5", "--slider", "0.3"]}
    near = {"--diameter": ["1e-6", "9.99e-7", "0.8", "3.999"],
            "--vent-diameter": ["1.999999999", "1.998", "1.9981", "0.002", "0.0019999"],
            "--line-length": ["1.000000001", "1.0000005", "1.01"],
            "--element-size": ["1", "1.0000001", "0.001"],
            "--slider": ["0.002", "0.0019", "1.5", "3", "100"],
            "--payload-mass": ["1e-6", "9e-7"],
            "--riser-length": ["0.1415", "0.1414", "0.002"],
            "--bundle-radius": ["0.999999", "0.002", "0.0019"],
            "--slider-drop": ["1.9999", "2", "5", "0.002"],
            "--line-slack": ["0.4999", "0.49"],
            "--inflated-ratio": ["0.63662", "0.6367", "0.99999999"],
            "--gores": ["3", "4", "1000", "1001"], "--line-elements": ["10000", "10001"],
            "--slider-divisions": ["999", "1000", "1001"], "--riser-elements": ["10001"],
            "--dt": ["2", "2.0000001", "1e-12"], "--t-end": ["0.002", "1e6"],
            "--pressure": ["-1", "1e6", "0", "1e5", "1e4", "1e-6", "1e-12"],
            "--ramp-time": ["1e6", "0"]}
    common = ["5e-324", "1e-300", "1e-12", "1e-9", "-1", "-0.0", "0", "1e6", "1e308", "nan",
              "inf", "-inf"]
    base = ["--gores", "8", "--diameter", "2", "--line-length", "2", "--element-size", "0.4",
            "--line-elements", "4"]
    combos = [(o, v) for o, vs in near.items() for v in common + vs]
    rng.shuffle(combos)
    out = []
    for k, (option, value) in enumerate(combos[:n]):
        vname = rng.choice(sorted(variants))
        args = base + variants[vname]
        if option in args:
            i = args.index(option)
            args = args[:i] + args[i + 2:]
        args = args + [option, value]
        out.append(inputs.parachute_check(ctx, "%s %s %s" % (vname, option, value), args,
                                          ANY_CLEAN))
    return out


def mesh_damage_inputs(ctx, rng, n):
    """Every kind of element or group damage (tests/attack/mshedit.py) at random places of both
    seeds in the four formats: each must be refused."""
    out = []
    tries = 0
    while len(out) < n and tries < 10 * n:
        tries += 1
        i = inputs.damaged_mesh_input(ctx, rng.choice(["flat", "chute"]), rng.choice(["22", "41"]),
                                      rng.random() < 0.5, rng.choice(inputs.mshedit.KINDS), rng,
                                      str(tries))
        if i:
            out.append(i)
    return out


def frame_inputs(ctx, rng, n):
    """A run's VTU series with one frame or the .pvd mutated (bytes changed, cut, numbers
    replaced): `chute render` draws it or refuses it, never crashes or hangs."""
    out = []
    for k in range(n):
        d = ctx.path("frames_%d" % k)
        shutil.rmtree(d, ignore_errors=True)
        shutil.copytree(ctx.vtu_run, d)
        pvd = [f for f in os.listdir(d) if f.endswith(".pvd")][0]
        target = pvd if rng.random() < 0.2 else rng.choice(ctx.frames)
        path = os.path.join(d, target)
        data, kind = mutate_bytes(rng, open(path, "rb").read(), text=target.endswith(".pvd"))
        with open(path, "wb") as f:
            f.write(data)
        out.append(inputs.render_input(ctx, "frames %d: %s %s" % (k, target[-12:], kind), d,
                                       ANY_CLEAN, "--size", "320x180"))
    return out


def big_csv_input(ctx):
    """A 900 MiB probes.csv (3 million rows, under the 1 GiB limit): plotted within the memory
    limit (it ran out of 4 GiB when held whole)."""
    d = ctx.path("big_csv")
    os.makedirs(d, exist_ok=True)
    columns = ["c%d.x" % k for k in range(15)]
    with open(os.path.join(d, "probes.csv"), "w") as f:
        f.write("t," + ",".join(columns) + "\n")
        tail = "," + ",".join(["0.12345678901234567"] * 14) + "\n"
        row = 0
        while f.tell() < 900 * 2 ** 20:
            f.write("".join("%r,%r%s" % (i * 1e-5, (i % 977) * 1e-3, tail)
                            for i in range(row, row + 20000)))
            row += 20000
    return Input("plot CSV", "a 900 MiB probes.csv", [ctx.chute, "plot", d, "--columns",
                                                      "c0.x,c7.x", "--out",
                                                      ctx.path("big_csv.png")], OK, None, 120)


HOSTILE_VALUES = [float("nan"), float("inf"), float("-inf"), -1, 0, 1e308, -1e308, 5e-324, -0.0,
                  2 ** 63 - 1, 2 ** 64 - 1, -2 ** 63, 2 ** 31, "x", "", [], {}, None, True,
                  b"\x00" * 9, 1.5, [float("nan")] * 3, [[[[[]]]]]]


def leaves(v, path=()):
    """Every position in a decoded payload: (path, value)."""
    yield path, v
    if isinstance(v, dict):
        for k, x in v.items():
            yield from leaves(x, path + (k,))
    elif isinstance(v, list):
        for i, x in enumerate(v):
            yield from leaves(x, path + (i,))


def checkpoint_inputs(ctx, rng, n):
    """The run's checkpoint damaged (bytes changed: the checksum must refuse it) or forged (a
    field of the payload replaced, deleted, shortened or lengthened under a correct checksum:
    the field checks must refuse it or the restart must run cleanly)."""
    out = []
    for k in range(n):
        if k % 3 == 0:
            data, kind = mutate_bytes(rng, ctx.checkpoint, text=False)
            out.append(inputs.restart_input(ctx, "damaged %d %s" % (k, kind), data, ANY_CLEAN))
            continue
        how = []

        def edit(p):
            spots = [(path, v) for path, v in leaves(p) if path]
            path, value = rng.choice(spots)
            parent = p
            for key in path[:-1]:
                parent = parent[key]
            what = rng.choice(["value", "value", "value", "delete", "shorten", "lengthen"])
            if what == "delete" or (what in ("shorten", "lengthen") and not isinstance(value, list)):
                if isinstance(parent, dict):
                    del parent[path[-1]]
                else:
                    parent.pop(path[-1])
                what = "delete"
            elif what == "shorten":
                del value[len(value) // 2:]
            elif what == "lengthen":
                value.extend(value[:1] * rng.choice([1, 7, 100000]) or [0.0])
            else:
                parent[path[-1]] = rng.choice(HOSTILE_VALUES)
            how.append("%s %s" % (what, ".".join(map(str, path))))

        data = inputs.forged(ctx, edit)
        out.append(inputs.restart_input(ctx, ("forged %d %s" % (k, how[0]))[:70], data,
                                        ANY_CLEAN))
    return out


def capi_inputs(ctx, rng, n):
    """Host sessions of random calls with hostile arguments (capi_session.py checks the
    promises of chute_coupling.h after every call)."""
    dts = ["5e-324", "1e-20", "1e-300", "1e300", "nan", "inf", "-inf", "-1", "0", "-0.0", "1e9",
           "0.0005", "0.0005", "0.002"]
    kinds = ["nan", "inf", "-inf", "1e308", "-1e308", "0", "1", "huge", "5e-324", "-3"]
    getters = ["reference_coordinates", "current_coordinates", "displacements", "velocities",
               "accelerations", "face_normals", "face_areas"]
    out = []
    for k in range(n):
        ops = []
        for _ in range(rng.randint(2, 8)):
            what = rng.choice(["advance", "advance", "pressures", "vpressures", "forces", "save",
                               "restore", "getters", "null", "nullhandle"])
            if what == "advance":
                ops.append("advance:" + rng.choice(dts))
            elif what in ("pressures", "vpressures", "forces"):
                ops.append(what + ":" + rng.choice(kinds))
            elif what == "null":
                ops.append("null:" + rng.choice(getters))
            else:
                ops.append(what)
        out.append(inputs.capi_input(ctx, ("session %d %s" % (k, " ".join(ops)))[:70], ops))
    return out


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--chute", default=os.path.join(SOURCE, "build", "bin", "chute"))
    ap.add_argument("--work", default="/tmp/chute_attack")
    ap.add_argument("--report", default=os.path.join(HERE, "results.md"))
    ap.add_argument("--per-class", type=float, default=1.0)
    ap.add_argument("--seed", type=int, default=20)
    ap.add_argument("--jobs", type=int, default=2)
    ap.add_argument("--mem-mb", type=int, default=4096)
    ap.add_argument("--no-big-csv", dest="big_csv", action="store_false",
                    help="leave out the 900 MiB probes.csv (about 1 GB of disk, a minute)")
    a = ap.parse_args()
    rng = random.Random(a.seed)
    ctx = inputs.Context(os.path.abspath(a.chute), SOURCE, harness.fresh_dir(a.work))
    inputs.setup(ctx)
    asan = harness.sanitized(ctx.chute)
    s = a.per_class
    todo = (inputs.corpus(ctx) + case_inputs(ctx, rng, int(300 * s)) +
            set_inputs(ctx, rng, int(200 * s)) + msh_inputs(ctx, rng, int(300 * s)) +
            geo_inputs(ctx, rng) + csv_inputs(ctx, rng, int(100 * s)) +
            arg_inputs(ctx, rng, int(200 * s)) + checkpoint_inputs(ctx, rng, int(150 * s)) +
            capi_inputs(ctx, rng, int(60 * s)) + parachute_inputs(ctx, rng, int(250 * s)) +
            mesh_damage_inputs(ctx, rng, int(150 * s)) + frame_inputs(ctx, rng, int(300 * s)) +
            ([big_csv_input(ctx)] if a.big_csv else []))
    print("%d inputs, %s build" % (len(todo), "ASan/UBSan" if asan else "plain"), flush=True)
    start = time.time()
    table = harness.Table()

    def one(i):
        return harness.run(i.cmd, ctx.work, i.expect, i.timeout, a.mem_mb, asan, i.marker)

    # Inputs that watch the marker file run alone, the others --jobs at a time.
    free = [i for i in todo if not i.marker]
    with concurrent.futures.ThreadPoolExecutor(max_workers=a.jobs) as pool:
        results = dict(zip(map(id, free), pool.map(one, free)))
    for k, inp in enumerate(todo):
        o = results.get(id(inp)) or one(inp)
        table.add(inp.cls, inp.name, o)
        if o.cls in harness.BAD:
            print("%-8s %-50s %s" % (o.cls, inp.name[:50], o.why), flush=True)
    minutes = (time.time() - start) / 60
    with open(a.report, "w") as f:
        f.write("# Attack run: %d inputs, %s build, seed %d, %.1f min\n\n" % (
            len(todo), "ASan/UBSan" if asan else "Release (no sanitizers)", a.seed, minutes))
        f.write("Generated by `bench/attack/attack.py --per-class %g --seed %d`; limits per "
                "input: wall time 10-120 s (x3 under sanitizers), %s.\n\n" % (
                    s, a.seed, "ASan hard RSS limit %d MiB" % a.mem_mb if asan else
                    "RLIMIT_AS %d MiB" % a.mem_mb))
        f.write(table.markdown() + "\n\n")
        if table.bad:
            f.write("## Bad outcomes\n\n")
            for row in table.bad:
                f.write("- %s: `%s`: %s (%s) %s\n" % row)
    print(table.markdown())
    return 1 if table.failures() else 0


if __name__ == "__main__":
    sys.exit(main())
