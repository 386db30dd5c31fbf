"""Hostile inputs for every input surface of `chute`, written into a work directory.

corpus(ctx) is the short, fixed list run by ctest (tests/attack/corpus.py); bench/attack/attack.py
adds generated and mutated inputs built from the same seeds. Each input is
Input(cls, name, cmd, expect, marker, timeout): its class (a row of the table), a name, the
command line, the set of outcome classes it may end in (harness.py), a marker file whose existence
means a command ran, and a time limit.
"""

import os
import shutil
import struct
import subprocess
import sys
from collections import namedtuple

import cbor
import mshedit

HERE = os.path.dirname(os.path.abspath(__file__))

Input = namedtuple("Input", "cls name cmd expect marker timeout")
ERROR = {"error"}
OK = {"success"}
# A valid but extreme input may run (0), stop early (3) or be refused (2): never crash or hang.
ANY_CLEAN = {"success", "error", "failed"}


class Context:
    """Paths and seeds shared by the generators."""

    def __init__(self, chute, source, work):
        self.chute, self.source, self.work = chute, source, work
        self.marker = os.path.join(work, "MARKER")
        self.seeds = {}  # .msh seeds by format: "41a", "41b", "22a", "22b"
        self.lib = os.path.join(os.path.dirname(os.path.dirname(chute)), "structural",
                                "libchute_coupling.so")

    def path(self, *parts):
        return os.path.join(self.work, *parts)

    def write(self, name, data):
        p = self.path(name)
        os.makedirs(os.path.dirname(p), exist_ok=True)
        with open(p, "wb") as f:
            f.write(data if isinstance(data, bytes) else data.encode())
        return p

    def case(self, name):
        return os.path.join(self.source, "cases", name)


def mesh_case_text(ctx, mesh_file):
    """The example case over `mesh_file`, two steps long."""
    with open(os.path.join(ctx.source, "mesh", "examples", "flat_canopy.toml")) as f:
        text = f.read()
    text = text.replace('file = "flat_canopy.msh"', 'file = "%s"' % mesh_file)
    return text.replace("t_end = 0.05", "t_end = 0.002")


def setup(ctx):
    """Seeds: the example mesh in four formats (gmsh converts it), a short run for `plot`, and
    a geo script that would create the marker file."""
    os.makedirs(ctx.work, exist_ok=True)
    example = os.path.join(ctx.source, "mesh", "examples", "flat_canopy.msh")
    shutil.copy(example, ctx.path("seed_41a.msh"))
    ctx.seeds["41a"] = ctx.path("seed_41a.msh")
    if shutil.which("gmsh"):
        for key, fmt, binary in [("41b", "msh41", True), ("22a", "msh22", False),
                                 ("22b", "msh22", True)]:
            out = ctx.path("seed_%s.msh" % key)
            cmd = ["gmsh", example, "-save", "-format", fmt, "-o", out] + (["-bin"] if binary else [])
            if subprocess.run(cmd, capture_output=True).returncode == 0 and os.path.exists(out):
                ctx.seeds[key] = out
    for key, seed in ctx.seeds.items():
        ctx.write("case_%s.toml" % key, mesh_case_text(ctx, seed))
    run_dir = ctx.path("run")
    subprocess.run([ctx.chute, "run", ctx.case("pulley.toml"), "--out", run_dir, "--quiet",
                    "--set", "solver.t_end=0.1"], check=True, capture_output=True)
    with open(os.path.join(run_dir, "probes.csv")) as f:
        ctx.probes = f.read()
    ctx.columns = ctx.probes.splitlines()[0].split(",")[1]
    # A run with a checkpoint (bead_5: a sliding group, so term histories are in it), kept as
    # the pristine output directory every restart input starts from.
    ctx.ckpt_run = ctx.path("ckpt_run")
    subprocess.run([ctx.chute, "run", ctx.case("bead_5.toml"), "--out", ctx.ckpt_run, "--quiet",
                    "--checkpoint-every", "20", "--set", "solver.t_end=0.2"], check=True,
                   capture_output=True)
    with open(os.path.join(ctx.ckpt_run, "checkpoint.cbor"), "rb") as f:
        ctx.checkpoint = f.read()
    with open(os.path.join(ctx.source, "mesh", "examples", "flat_canopy.geo")) as f:
        geo = f.read()
    ctx.evil_geo = ctx.write("evil.geo", 'System "touch %s";\n%s' % (ctx.marker, geo))
    ctx.write("case_geo.toml", mesh_case_text(ctx, ctx.evil_geo))
    setup_mesh_damage(ctx)
    setup_viewers(ctx)
    os.mkfifo(ctx.path("fifo.msh")) if not os.path.exists(ctx.path("fifo.msh")) else None
    for name in ["fifo.toml", "fifo.geo", "fifo.csv"]:
        if not os.path.exists(ctx.path(name)):
            os.mkfifo(ctx.path(name))
    for name in ["zero.msh", "zero.toml", "zero.csv"]:
        if not os.path.lexists(ctx.path(name)):
            os.symlink("/dev/zero", ctx.path(name))
    os.makedirs(ctx.path("dir.msh"), exist_ok=True)
    os.makedirs(ctx.path("dir.toml"), exist_ok=True)


def gmsh_convert(src, dst, version, binary):
    """src saved by the gmsh command as format 2.2 or 4.1, ASCII or binary; False if it fails."""
    if not shutil.which("gmsh"):
        return False
    cmd = ["gmsh", src, "-save", "-format", "msh22" if version == "22" else "msh41", "-o", dst]
    if binary:
        cmd.append("-bin")
    return subprocess.run(cmd, capture_output=True).returncode == 0 and os.path.exists(dst)


def setup_mesh_damage(ctx):
    """The meshes damaged by mshedit: the example (triangles, lines) and a generated parachute
    (a quadrangle slider, a start view), each as ASCII 2.2 and 4.1, with their cases."""
    gen, case = ctx.path("gen_seed.msh"), ctx.path("gen_seed.toml")
    subprocess.run([ctx.chute, "mesh", "parachute", "--gores", "8", "--diameter", "2",
                    "--line-length", "2", "--element-size", "0.5", "--slider", "0.3", "--start",
                    "folded", "--line-elements", "3", "--out", gen, "--case", case, "--quiet"],
                   check=True, capture_output=True)
    ctx.damage_seeds = {}
    for name, msh41 in [("flat", ctx.seeds["41a"]), ("chute", gen)]:
        texts = {"41": open(msh41).read()}
        msh22 = ctx.path("damage_seed_%s_22.msh" % name)
        if gmsh_convert(msh41, msh22, "22", False):
            texts["22"] = open(msh22).read()
        ctx.damage_seeds[name] = texts
    ctx.gen_case = case


MESH_DAMAGE = "msh elements and groups"


def damaged_mesh_input(ctx, seed, version, binary, kind, rng, tag):
    """`chute run` over the seed mesh with one damage of `kind` (mshedit), in format version
    (ASCII, or binary as gmsh saves the damaged ASCII file): it must be refused (exit 2, one line,
    nothing written). None when the seed has nothing to damage that way, or gmsh's binary save
    does not keep the damage (it merges 2.2 groups of one name; it writes no views)."""
    text = ctx.damage_seeds[seed].get(version)
    if text is None:
        return None
    if binary and (kind == "view_missing_node" or (kind == "group_name" and version == "22")):
        return None
    r = mshedit.damage(text, kind, rng)
    if r is None:
        return None
    damaged, what = r
    name = "%s_%s%s_%s_%s" % (seed, version, "b" if binary else "a", kind, tag)
    path = ctx.write("dmg_%s.msh" % name, damaged)
    if binary:
        out = ctx.path("dmg_%s_bin.msh" % name)
        if not gmsh_convert(path, out, version, True):
            return None
        path = out
    if seed == "flat":
        cmd = run_case(ctx, ctx.write("dmg_%s.toml" % name, mesh_case_text(ctx, path)))
    else:
        cmd = run_case(ctx, ctx.gen_case, "--set", 'mesh.file="%s"' % path)
    return Input(MESH_DAMAGE, "%s: %s" % (name, what)[:70], cmd, ERROR, None, 30)


VIEWERS = "render and plot files"


def vtu_text(connectivity="0 1 1 2", offsets="2 4", types="3 3", kinds="1 1",
             points="0 0 0 1 0 0 1 1 0"):
    """A small ASCII frame of three points and two lines, to damage."""
    n_points = len(points.split()) // 3
    n_cells = len(types.split())
    return ('<?xml version="1.0"?>\n<VTKFile type="UnstructuredGrid" version="1.0" '
            'byte_order="LittleEndian" header_type="UInt64">\n<UnstructuredGrid>'
            '<Piece NumberOfPoints="%d" NumberOfCells="%d">\n<Points><DataArray type="Float64" '
            'NumberOfComponents="3" format="ascii">%s</DataArray></Points>\n<Cells><DataArray '
            'type="Int64" Name="connectivity" format="ascii">%s</DataArray><DataArray type="Int64" '
            'Name="offsets" format="ascii">%s</DataArray><DataArray type="UInt8" Name="types" '
            'format="ascii">%s</DataArray></Cells>\n<CellData><DataArray type="Int32" Name="kind" '
            'format="ascii">%s</DataArray><DataArray type="Float64" Name="axial_force" '
            'format="ascii">%s</DataArray><DataArray type="Float64" Name="principal_stress" '
            'NumberOfComponents="2" format="ascii">%s</DataArray></CellData>\n</Piece>'
            '</UnstructuredGrid></VTKFile>\n' % (
                n_points, n_cells, points, connectivity, offsets, types, kinds,
                " ".join(["1"] * n_cells), " ".join(["0 0"] * n_cells)))


def pvd_text(files, times=None):
    times = times or [str(k) for k in range(len(files))]
    return ('<?xml version="1.0"?>\n<VTKFile type="Collection" version="0.1"><Collection>\n' +
            "".join('<DataSet timestep="%s" file="%s"/>\n' % (t, f) for t, f in zip(times, files))
            + "</Collection></VTKFile>\n")


def series_dir(ctx, name, frames, pvd=None):
    """A run directory holding a .pvd over `frames` ({file name: bytes or None for a FIFO or
    a path to link to})."""
    d = ctx.path("series_" + name)
    shutil.rmtree(d, ignore_errors=True)
    os.makedirs(d)
    for fname, data in frames.items():
        p = os.path.join(d, fname)
        if data is None:
            os.mkfifo(p)
        elif isinstance(data, str) and data.startswith("->"):
            os.symlink(data[2:], p)
        else:
            with open(p, "wb") as f:
                f.write(data if isinstance(data, bytes) else data.encode())
    if pvd is not False:
        p = os.path.join(d, "s.pvd")
        if pvd is None:
            pvd = pvd_text(sorted(frames))
        if pvd == "FIFO":
            os.mkfifo(p)
        else:
            with open(p, "w") as f:
                f.write(pvd)
    return d


def setup_viewers(ctx):
    """A run with a VTU series for `chute render` (bead_5, one second)."""
    ctx.vtu_run = ctx.path("vtu_run")
    subprocess.run([ctx.chute, "run", ctx.case("bead_5.toml"), "--out", ctx.vtu_run, "--quiet",
                    "--set", "output.vtu.write=true", "--set", "solver.t_end=1"], check=True,
                   capture_output=True)
    ctx.frames = sorted(f for f in os.listdir(ctx.vtu_run) if f.endswith(".vtu"))


def render_input(ctx, name, run_dir, expect=ERROR, *extra):
    out = ctx.path("render_out", name)
    return Input(VIEWERS, name, [ctx.chute, "render", run_dir, "--out", out, "--quiet"] +
                 list(extra), expect, None, 60)


def run_case(ctx, case, *extra):
    """`chute run` into an output directory of its own (inputs may run in parallel)."""
    ctx.runs = getattr(ctx, "runs", 0) + 1
    return [ctx.chute, "run", case, "--quiet", "--out", ctx.path("out", str(ctx.runs))] + list(extra)


def mesh_run(ctx, name, data, expect=ERROR):
    """A case over a mesh file with these bytes."""
    msh = ctx.write("m_" + name + ".msh", data)
    case = ctx.write("m_" + name + ".toml", mesh_case_text(ctx, msh))
    return Input("msh 2.2/4.1 ASCII/binary", name, run_case(ctx, case), expect, ctx.marker, 30)


def replace_count(text, section, delta=None, value=None, fmt="22a"):
    """The node or element count of `section` changed (format 2.2: the line after the header;
    4.1: the second number of the header, a size_t in binary files)."""
    at = text.find(b"\n" + section + b"\n")
    if at < 0:
        return text
    start = at + len(section) + 2
    if fmt == "41b":
        n = struct.unpack_from("<Q", text, start + 8)[0]
        new = value if value is not None else n + delta
        return text[:start + 8] + struct.pack("<Q", new) + text[start + 16:]
    end = text.index(b"\n", start)
    parts = text[start:end].split(b" ")
    k = 1 if fmt.startswith("41") else 0
    n = int(parts[k])
    parts[k] = str(value if value is not None else n + delta).encode()
    return text[:start] + b" ".join(parts) + text[end:]


CHECKPOINT = "checkpoint (--restart)"
CAPI = "C API (ctypes host)"


def restart_input(ctx, name, data, expect=ERROR):
    """`chute run bead_5 --restart` with a checkpoint file of these bytes (or at this path, for
    FIFOs and the like), on a fresh copy of the run's output; a refusal must leave it as it was
    (restart_check.py)."""
    ctx.restarts = getattr(ctx, "restarts", 0) + 1
    if isinstance(data, str):
        path = data
    else:
        path = ctx.write(os.path.join("ckpt", "%d.cbor" % ctx.restarts), data)
    cmd = [sys.executable, os.path.join(HERE, "restart_check.py"), ctx.chute,
           ctx.case("bead_5.toml"), ctx.ckpt_run, ctx.path("ckpt_out", str(ctx.restarts)), path]
    return Input(CHECKPOINT, name, cmd, expect, None, 60)


def forged(ctx, edit):
    """The checkpoint with its payload decoded, edited by edit(payload) and re-encoded under a
    correct checksum: what reaches the field checks (a damaged file stops at the checksum)."""
    outer = cbor.loads(ctx.checkpoint)
    payload = cbor.loads(outer["payload"])
    payload = edit(payload) or payload
    outer["payload"] = cbor.dumps(payload)
    outer["checksum"] = cbor.fnv1a(outer["payload"])
    return cbor.dumps(outer)


def parachute_check(ctx, name, args, expect, work=None):
    """`chute mesh parachute ARGS` and, when it succeeds, two steps of the case it wrote
    (tests/attack/parachute_check.py): a generated case chute run refuses is a broken promise."""
    ctx.parachutes = getattr(ctx, "parachutes", 0) + 1
    work = work or ctx.path("pcheck", str(ctx.parachutes))
    cmd = [sys.executable, os.path.join(HERE, "parachute_check.py"), ctx.chute, work] + args
    return Input("mesh parachute arguments", name, cmd, expect, None, 120)


def capi_input(ctx, name, ops, case=None, expect=OK):
    cmd = [sys.executable, os.path.join(HERE, "capi_session.py"), ctx.lib,
           case or ctx.case("canopy_coupled.toml")] + ops
    return Input(CAPI, name, cmd, expect, None, 120)


def corpus(ctx):
    c, out = ctx.chute, []
    add = out.append
    deep = "a = " + "[" * 6000 + "]" * 6000 + "\n"
    deep_tables = "a = " + "{b = " * 6000 + "1" + "}" * 6000 + "\n"

    # ---- case TOML
    T = "case TOML"
    add(Input(T, "valid pulley", run_case(ctx, ctx.case("pulley.toml"), "--set",
                                          "solver.t_end=0.05"), OK, None, 60))
    for name, text in [("6000 nested arrays", deep), ("6000 nested inline tables", deep_tables),
                       ("empty", ""), ("unterminated string", 'name = "abc\n'),
                       ("binary junk", bytes(range(256)) * 4), ("dt nan",
                                                                open(ctx.case("pulley.toml")).read().replace("dt = 1.0e-2", "dt = nan"))]:
        add(Input(T, name, run_case(ctx, ctx.write("t_%d.toml" % len(out), text)), ERROR, None, 20))
    for name in ["fifo.toml", "zero.toml", "dir.toml", "missing.toml"]:
        add(Input(T, name, run_case(ctx, ctx.path(name)), ERROR, None, 10))

    # ---- --set
    S = "--set"
    pulley = ctx.case("pulley.toml")
    for s in ["solver.dt=5e-324", "solver.dt=1e308", "solver.dt_min=1e-300", "solver.dt=nan",
              "solver.dt=inf", "solver.dt=-1", "membranes.0.divisions.0.0=4", "=", "solver..dt=1",
              "solver.dt", "solver.dt=", "nodes.99999999999.x=1", "solver.d\u03c4=1",
              "solver.dt=" + "[" * 6000 + "]" * 6000, "a." * 5000 + "b=1",
              "solver.t_end=1e300"]:
        add(Input(S, s[:40], run_case(ctx, pulley, "--set", s), ERROR, None, 20))
    # A reference whose geometry fails only when the run starts (found by the long run).
    add(Input(S, "nodes.bead.2=5e-324 (bead on the rope line)",
              run_case(ctx, ctx.case("bead_1.toml"), "--set", "nodes.bead.2=5e-324"), ERROR,
              None, 20))
    # A hopeless static solve fails in about a second (found by the long run under ASan: 37 s).
    add(Input(S, "hencky loads.pressure.0.pressure=2147483648",
              run_case(ctx, ctx.case("hencky.toml"), "--set",
                       "loads.pressure.0.pressure=2147483648"), {"failed"}, None, 20))
    add(Input(S, "membranes.0.divisions.0=4", run_case(ctx, ctx.case("airbag.toml"), "--set",
              "membranes.0.divisions.0=4", "--set", "solver.t_end=2.5e-4"), OK, None, 60))

    # ---- .msh
    for key, seed in sorted(ctx.seeds.items()):
        data = open(seed, "rb").read()
        add(mesh_run(ctx, key + " valid", data, OK))
        for section in [b"$Nodes", b"$Elements"]:
            for delta in [-1, 1]:
                add(mesh_run(ctx, "%s %s %+d" % (key, section.decode(), delta),
                             replace_count(data, section, delta, fmt=key)))
        add(mesh_run(ctx, key + " truncated", data[: len(data) // 2]))
    a = open(ctx.seeds["41a"], "rb").read()
    view = b"$NodeData\n1\n\"u0\"\n1\n0\n3\n0\n3\n1000000000\n1 0 0 0\n$EndNodeData\n"
    add(mesh_run(ctx, "41a NodeData count 1e9", a + view))
    for bad in [b"nan", b"inf", b"1e308"]:
        lines = a.split(b"\n")
        i = lines.index(b"$Nodes") + 3  # first block's first coordinate line
        while len(lines[i].split()) != 3:
            i += 1
        lines[i] = bad + b" 0 0"
        add(mesh_run(ctx, "41a coordinate " + bad.decode(), b"\n".join(lines)))
    for name in ["fifo.msh", "zero.msh", "dir.msh"]:
        case = ctx.write("m_%s.toml" % name, mesh_case_text(ctx, ctx.path(name)))
        add(Input("msh 2.2/4.1 ASCII/binary", name, run_case(ctx, case), ERROR, None, 10))
    add(mesh_run(ctx, "empty", b""))
    unv = ctx.write("mesh.unv", "    -1\n  2411\n")
    case = ctx.write("m_unv.toml", mesh_case_text(ctx, unv))
    add(Input("msh 2.2/4.1 ASCII/binary", ".unv", run_case(ctx, case), ERROR, None, 10))

    # ---- every element and group checked on import: each damage in each format (mshedit)
    import random
    rng = random.Random(0)
    for k, kind in enumerate(mshedit.KINDS):
        for version in ["22", "41"]:
            for binary in [False, True]:
                seeds = ["chute", "flat"] if (k + (version == "41")) % 2 else ["flat", "chute"]
                for seed in seeds:  # the first seed that has something to damage this way
                    i = damaged_mesh_input(ctx, seed, version, binary, kind, rng, "c")
                    if i:
                        add(i)
                        break
    add(Input(MESH_DAMAGE, "mesh.scale=1e102 (coordinates past 1e100)",
              run_case(ctx, ctx.path("case_41a.toml"), "--set", "mesh.scale=1e102"), ERROR, None,
              20))
    # A point mass on a node no element uses: its own block of the matrix (it was outside the
    # sparsity pattern: exit 1).
    free = ctx.write("free_mass.toml", open(ctx.case("pulley.toml")).read().replace(
        "[nodes]", "[nodes]\nball = [9.0, 9.0, 9.0]", 1) +
        "\n[[point_masses]]\nnode = \"ball\"\nmass = 1.0\n")
    add(Input(T, "a point mass on a node no element uses", run_case(ctx, free, "--set",
                                                                    "solver.t_end=0.05"), OK,
              None, 60))

    # ---- .geo: never run by a case or the coupling library; bounded through `mesh geo`
    G = ".geo (case, C API, mesh geo)"
    add(Input(G, "case names a .geo with System", run_case(ctx, ctx.path("case_geo.toml")),
              ERROR, ctx.marker, 20))
    add(Input(G, "--set mesh.file=.geo", run_case(ctx, ctx.path("case_41a.toml"), "--set",
              'mesh.file="%s"' % ctx.evil_geo), ERROR, ctx.marker, 20))
    add(Input(G, "couple over a .geo case", [c, "couple", ctx.path("case_geo.toml")], ERROR,
              ctx.marker, 20))
    add(Input(G, "C API create over a .geo case", [sys.executable, os.path.join(
        os.path.dirname(os.path.abspath(__file__)), "capi_create.py"), ctx.lib,
        ctx.path("case_geo.toml")], ERROR, ctx.marker, 20))
    geo = os.path.join(ctx.source, "mesh", "examples", "flat_canopy.geo")
    add(Input(G, "mesh geo valid", [c, "mesh", "geo", geo, "--out", ctx.path("g.msh")], OK,
              None, 60))
    loop = ctx.write("loop.geo", "For i In {1:1e15}\n  x = i;\nEndFor\n")
    add(Input(G, "mesh geo endless loop", [c, "mesh", "geo", loop, "--out", ctx.path("g2.msh"),
                                           "--timeout", "1"], ERROR, None, 20))
    bomb = ctx.write("bomb.geo", "Mesh.CharacteristicLengthMax = 1e-5;\nPoint(1)={0,0,0};"
                     "Point(2)={1,0,0};Point(3)={1,1,0};Point(4)={0,1,0};Line(1)={1,2};"
                     "Line(2)={2,3};Line(3)={3,4};Line(4)={4,1};Curve Loop(1)={1,2,3,4};"
                     "Plane Surface(1)={1};Physical Surface(\"s\")={1};\n")
    add(Input(G, "mesh geo 1e10-element bomb", [c, "mesh", "geo", bomb, "--out",
              ctx.path("g3.msh"), "--timeout", "2", "--max-memory", "1024"], ERROR, None, 30))
    syntax = ctx.write("syntax.geo", "Point(1) = {0,0,0;\n")
    add(Input(G, "mesh geo syntax error", [c, "mesh", "geo", syntax, "--out", ctx.path("g4.msh")],
              ERROR, None, 20))
    for name in ["fifo.geo", "missing.geo"]:
        add(Input(G, "mesh geo " + name, [c, "mesh", "geo", ctx.path(name), "--out",
                                          ctx.path("g5.msh")], ERROR, None, 10))
    add(Input(G, "mesh geo --out is the script", [c, "mesh", "geo", syntax, "--out", syntax],
              ERROR, None, 10))


    # ---- checkpoints (--restart)
    good = ctx.checkpoint
    add(restart_input(ctx, "the run's own checkpoint", good, OK))
    add(restart_input(ctx, "re-encoded unchanged (codec check)", forged(ctx, lambda p: None), OK))
    for name, path in [("fifo", ctx.path("fifo.msh")), ("dev zero", "/dev/zero"),
                       ("directory", ctx.path("dir.toml")), ("missing", ctx.path("none.cbor"))]:
        add(restart_input(ctx, "checkpoint is a " + name, path))
    add(restart_input(ctx, "empty", b""))
    add(restart_input(ctx, "truncated", good[: len(good) // 2]))
    add(restart_input(ctx, "nested 400000 deep", b"\x81" * 400000 + b"\x00"))
    deep = b"\x81" * 400000 + b"\x00"
    add(restart_input(ctx, "payload nested 400000 deep, checksum right", cbor.dumps(
        {"format": cbor.loads(good)["format"], "payload": deep, "checksum": cbor.fnv1a(deep)})))
    add(restart_input(ctx, "format 2 (before every key was in it)",
                      cbor.dumps(dict(cbor.loads(good), format=2))))
    add(restart_input(ctx, "format 3 (before the stress resultants and flow histories)",
                      cbor.dumps(dict(cbor.loads(good), format=3))))
    add(restart_input(ctx, "format 5", cbor.dumps(dict(cbor.loads(good), format=5))))

    def setter(key, value):
        def edit(p):
            p[key] = value
        return edit

    for name, edit in [("x with a NaN", lambda p: p["x"].__setitem__(0, float("nan"))),
                       ("x one short", lambda p: p["x"].pop()),
                       ("x empty", setter("x", [])),
                       ("t = inf", setter("t", float("inf"))),
                       ("t = -1", setter("t", -1.0)),
                       ("dt = 0", setter("dt", 0.0)),
                       ("counters 2^63", setter("counters", [2 ** 63 - 1] * 5)),
                       # One counter at a time: each alone once passed the reader and overflowed
                       # as the run counted on (a negative step count, no step limit).
                       ("steps 2^63 - 1 alone", lambda p: p["counters"].__setitem__(0, 2 ** 63 - 1)),
                       ("event retries 2^63 - 1 alone",
                        lambda p: p["counters"].__setitem__(2, 2 ** 63 - 1)),
                       ("newton iterations 2^63 - 1 alone",
                        lambda p: p["counters"].__setitem__(3, 2 ** 63 - 1)),
                       # An output clock not of the checkpoint's time: no more rows were written
                       # and the run "completed".
                       ("probe clock 2^63 - 1", lambda p: p["output"].__setitem__(
                           "probe_clock", 2 ** 63 - 1)),
                       ("probe clock 10^6", lambda p: p["output"].__setitem__("probe_clock", 10 ** 6)),
                       ("probe clock 0", lambda p: p["output"].__setitem__("probe_clock", 0)),
                       ("terms emptied", setter("terms", [])),
                       ("a term's ints out of range", lambda p: p["terms"][0].__setitem__(
                           "ints", [2 ** 31 + 7] * len(p["terms"][0]["ints"]))),
                       ("a term's reals NaN", lambda p: p["terms"][0].__setitem__(
                           "reals", [float("nan")] * len(p["terms"][0]["reals"]))),
                       ("model hash changed", setter("model_hash", 1)),
                       ("solver dt changed", lambda p: p["settings"].__setitem__(
                           "solver.dt", "0.001")),
                       ("gravity changed", lambda p: p["settings"].__setitem__(
                           "loads.gravity", "[0.0, 0.0, -1.0]")),
                       ("probe rows 1e15", lambda p: p["output"].__setitem__("probe_rows",
                                                                             10 ** 15)),
                       ("x is a string", setter("x", "x")),
                       # Finite but absurd (found by the long run under ASan): it overflowed in
                       # the first step, after the output directory had been touched.
                       ("a v entry 1e308", lambda p: p["v"].__setitem__(17, 1e308)),
                       ("key deleted", lambda p: p.pop("v"))]:
        add(restart_input(ctx, "forged: " + name, forged(ctx, edit)))

    # ---- the C API, from a host program
    add(capi_input(ctx, "windows that cannot move time or never end",
                   ["advance:5e-324", "advance:1e-20", "advance:1e300", "advance:nan",
                    "advance:inf", "advance:-1", "advance:0", "advance:-0.0"]))
    add(capi_input(ctx, "non-finite and absurd loads",
                   ["pressures:nan", "pressures:inf", "vpressures:-inf", "forces:nan",
                    "pressures:1e308", "forces:-1e308"]))
    add(capi_input(ctx, "checkpoint order, NULL pointers and handles",
                   ["restore", "save", "advance:0.002", "restore", "getters",
                    "null:velocities", "null:face_areas", "null:set_face_pressures",
                    "nullhandle"]))

    # ---- CSV inputs of plot
    P = "plot CSV"
    run_dir = ctx.path("run")
    # Each input its own image: inputs run two at a time, and two plots of one --out raced (each
    # checks its image after writing it; the other's truncation read as "the image could not be
    # written", exit 3; chute now writes images whole and renames them into place).
    def plot_to(name):
        return [c, "plot", "--columns", ctx.columns, "--out",
                ctx.path("p_%s.png" % name.replace(" ", "_"))]

    add(Input(P, "valid", plot_to("valid") + [run_dir], OK, None, 60))
    lines = ctx.probes.splitlines()
    sub = "\n".join([lines[0]] + [",".join(["4.9406564584124654e-324"] + r.split(",")[1:])
                                  if k == 0 else r for k, r in enumerate(lines[1:])]) + "\n"
    for name, text, expect in [("subnormal numbers", sub, OK), ("empty", "", ERROR),
                               ("junk", "t,x\n1,abc\n", ERROR),
                               ("more values than columns", lines[0] + "\n1,2,3,4,5,6,7,8,9\n",
                                ERROR),
                               ("huge number", lines[0] + "\n" + ",".join(["1e999"] * len(lines[0].split(","))) + "\n", ERROR)]:
        d = ctx.path("plot_" + name.replace(" ", "_"))
        os.makedirs(d, exist_ok=True)
        with open(os.path.join(d, "probes.csv"), "w") as f:
            f.write(text)
        add(Input(P, name, plot_to(name) + [d], expect, None, 60))
    d = ctx.path("plot_summary_fifo")
    os.makedirs(d, exist_ok=True)
    shutil.copy(os.path.join(run_dir, "probes.csv"), d)
    if not os.path.lexists(os.path.join(d, "summary.json")):
        os.mkfifo(os.path.join(d, "summary.json"))
    add(Input(P, "summary.json is a fifo", plot_to("summary fifo") + [d], ERROR, None, 10))
    for name, target in [("fifo", ctx.path("fifo.csv")), ("dev zero", "/dev/zero"),
                         ("directory", ctx.path("dir.toml"))]:
        d = ctx.path("plot_" + name.replace(" ", "_"))
        os.makedirs(d, exist_ok=True)
        link = os.path.join(d, "probes.csv")
        if not os.path.lexists(link):
            os.symlink(target, link)
        add(Input(P, "probes.csv is a " + name, plot_to("csv " + name) + [d], ERROR, None, 10))
        add(Input(P, "--reference is a " + name,
                  plot_to("reference " + name) + [run_dir, "--reference", target], ERROR, None,
                  10))

    # ---- the files `chute render` and `chute plot` open: frames checked before drawing, no
    # blocking on FIFOs, the output never a FIFO or a link, images within the memory budget
    V = VIEWERS
    good = vtu_text()
    add(render_input(ctx, "a valid hand-written frame", series_dir(ctx, "good", {"a.vtu": good}),
                     OK))
    for name, frame in [("a point index out of range", vtu_text(connectivity="0 1 1 7")),
                        ("a negative point index", vtu_text(connectivity="0 1 -1 2")),
                        ("a point index of 2^40", vtu_text(connectivity="0 1 1 1099511627776")),
                        ("an unknown cell type", vtu_text(types="3 99")),
                        ("a polyhedron cell", vtu_text(types="3 42")),
                        ("a hexahedron of two points", vtu_text(types="3 12")),
                        ("a quadrangle of two points", vtu_text(types="3 9")),
                        ("offsets past the end", vtu_text(offsets="2 40")),
                        ("offsets backwards", vtu_text(offsets="4 2")),
                        ("a kind out of range", vtu_text(kinds="1 99")),
                        ("a NaN point", vtu_text(points="0 0 0 nan 0 0 1 1 0")),
                        ("no points", vtu_text(points="", connectivity="", offsets="", types="",
                                               kinds="")),
                        ("not XML", "junk\x00\xff" * 100)]:
        add(render_input(ctx, "frame: " + name, series_dir(ctx, name.replace(" ", "_"),
                                                           {"a.vtu": frame})))
    for name, target in [("a FIFO", None), ("/dev/zero", "->/dev/zero"),
                         ("a directory", "->" + ctx.path("dir.toml"))]:
        add(render_input(ctx, "frame is " + name, series_dir(ctx, "frame_" + name[-4:],
                                                             {"a.vtu": target})))
    add(render_input(ctx, "the .pvd is a FIFO", series_dir(ctx, "pvd_fifo", {"a.vtu": good},
                                                            "FIFO")))
    add(render_input(ctx, "a .pvd time that is NaN", series_dir(
        ctx, "pvd_nan", {"a.vtu": good}, pvd_text(["a.vtu"], ["nan"]))))
    add(render_input(ctx, "a .pvd naming no file", series_dir(
        ctx, "pvd_missing", {"a.vtu": good}, pvd_text(["nowhere.vtu"]))))
    # The snapshot's own file is a FIFO (or a link) before the render writes it.
    d = series_dir(ctx, "png_fifo", {"a.vtu": good})
    os.makedirs(os.path.join(d, "snap"))
    os.mkfifo(os.path.join(d, "snap", "s_iso_t0.000000.png"))
    add(Input(V, "the snapshot file is a FIFO", [c, "render", d, "--out", os.path.join(d, "snap"),
                                                 "--quiet"], ERROR, None, 30))
    run_dir_v = ctx.vtu_run
    add(Input(V, "render 8192x8192 (beyond the memory budget)",
              [c, "render", run_dir_v, "--size", "8192x8192", "--out",
               ctx.path("render_out", "big")], ERROR, None, 30))
    plot_v = [c, "plot", ctx.path("run"), "--out", ctx.path("pv.png")]
    add(Input(V, "plot --columns t", plot_v + ["--columns", "t"], ERROR, None, 30))
    add(Input(V, "plot --columns %s,t" % ctx.columns, plot_v + ["--columns", ctx.columns + ",t"],
              ERROR, None, 30))
    add(Input(V, "plot --size 8192x8192", plot_v + ["--columns", ctx.columns, "--size",
                                                    "8192x8192"], ERROR, None, 30))
    os.mkfifo(ctx.path("plot_fifo.png"))
    os.symlink(ctx.path("plot_target.png"), ctx.path("plot_link.png"))
    for name in ["plot_fifo.png", "plot_link.png"]:
        add(Input(V, "plot --out " + name, [c, "plot", ctx.path("run"), "--columns", ctx.columns,
                                            "--out", ctx.path(name)], ERROR, None, 20))

    # ---- arguments of every verb
    A = "arguments of every verb"
    mp = [c, "mesh", "parachute", "--gores", "8", "--diameter", "2", "--line-length", "2",
          "--element-size", "0.4", "--out", ctx.path("p.msh"), "--quiet"]

    def opt(args, name):
        """mp with `name` set to args (replacing its value if present)."""
        cmd = list(mp)
        if name in cmd:
            i = cmd.index(name)
            del cmd[i:i + 2]
        return cmd + [name] + args

    add(Input(A, "mesh parachute valid", mp, OK, None, 60))
    # Generation refuses what would give a case `chute run` refuses, and never aborts.
    for name, args in [("--vent-diameter 1.999999999 (gmsh threw in OpenMP: abort)",
                        ["--vent-diameter", "1.999999999"]),
                       ("--dt 3 --t-end 2", ["--dt", "3", "--t-end", "2", "--case",
                                             ctx.path("pc.toml")]),
                       ("--slider-divisions 1000 with --case",
                        ["--slider", "0.3", "--slider-divisions", "1000", "--case",
                         ctx.path("pc.toml")]),
                       ("--out without .msh", ["--out", ctx.path("p.mesh")]),
                       # A case whose explicit step would take more than 1e9 steps (a payload of
                       # 1e-6 on the confluence): refused at generation, nothing written.
                       ("--payload-mass 1e-6 on a box with --case",
                        ["--payload-mass", "1e-6", "--payload-box", "0.2,0.2,0.2",
                         "--riser-length", "0.5", "--line-elements", "4", "--case",
                         ctx.path("pm.toml")])]:
        # mp with every option of args replaced by args' own (options and their values): the
        # option named once, so the input tests what it is named for (it once repeated the
        # name and stopped at the argument parser).
        cmd = list(mp)
        for option in [x for x in args if x.startswith("--")]:
            if option in cmd:
                i = cmd.index(option)
                del cmd[i:i + 2]
        cmd = cmd + args if args[0] != "--out" else mp[:mp.index("--out")] + args + ["--quiet"]
        add(Input(A, "mesh parachute " + name, cmd, ERROR, None, 30))
    # Paths written into the generated case: quotes, backslashes, newlines, tabs, spaces,
    # non-ASCII are escaped; a path that is not UTF-8 cannot be named in TOML (refused).
    for k, name in enumerate(['q"uote', "back\\slash", "new\nline", "tab\tstop", "sp ace #x",
                              "\u00e9t\u00e9", "dollar$HOME"]):
        d = ctx.path("pcheck_%d" % k)
        add(parachute_check(ctx, "mesh parachute --out/--case named " + repr(name),
                            ["--gores", "8", "--diameter", "2", "--line-length", "2",
                             "--element-size", "0.5", "--out", os.path.join(d, name + ".msh"),
                             "--case", os.path.join(d, name + ".toml")], OK, d))
    for name, args in [("--gores", ["1000000"]), ("--gores", ["abc"]), ("--gores", ["-3"]),
                       ("--line-elements", ["1000000000"]), ("--element-size", ["1e-9"]),
                       ("--mesh-algorithm", ["8"]), ("--mesh-algorithm", ["2"]),
                       ("--diameter", ["nan"]), ("--diameter", ["inf"]), ("--diameter", ["1e308"]),
                       ("--slider-divisions", ["1000000"]), ("--riser-elements", ["1e9"]),
                       ("--case", [ctx.path("p.msh")]), ("--config", ["/dev/zero"]),
                       ("--config", [ctx.write("deep.toml", deep)]),
                       ("--max-elements", ["1e300"]), ("--payload-box", ["1,2"])]:
        add(Input(A, "mesh parachute %s %s" % (name, args[0][-20:]), opt(args, name), ERROR,
                  None, 30))
    for args in [[], ["nonsense"], ["run"], ["run", pulley, "--checkpoint-every", "-1"],
                 ["run", pulley, "--checkpoint-every", "1" * 30], ["run", pulley, "--bogus"],
                 ["render", ctx.path("nowhere")], ["render", run_dir, "--size", "99999x5"],
                 ["render", run_dir, "--size", "-5x10"], ["plot", run_dir],
                 ["plot", run_dir, "--columns", ctx.columns, "--size", "20000x20000"],
                 ["plot", run_dir, "--columns", ctx.columns, "--size", "0x0"],
                 ["plot", run_dir, "--columns", ctx.columns, "--out", ctx.work],
                 ["plot", run_dir, "--columns", ctx.columns, "--out", "/nonexistent/p.png"],
                 ["plot", run_dir, "--columns", "no_such_column", "--out", ctx.path("q.png")],
                 ["couple", ctx.path("missing.toml")], ["mesh"], ["mesh", "parachute"],
                 ["couple", ctx.case("canopy_coupled.toml"), "--t-end", "0.002", "--omega", "nan"],
                 ["mesh", "geo"], ["mesh", "geo", syntax, "--out", ctx.path("x.msh"),
                                   "--timeout", "-1"],
                 ["mesh", "geo", geo, "--out", ctx.path("x.txt")]]:
        add(Input(A, " ".join(["chute"] + [a[-30:] for a in args])[:70], [c] + args, ERROR, None,
                  30))
    return out
