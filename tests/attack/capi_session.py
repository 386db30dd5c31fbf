"""A host program driving libchute_coupling.so (ctypes) with hostile calls, checking the
promises of structural/coupling/chute_coupling.h: every call returns a documented status, a
refused call changes nothing (time, state), a refused advance leaves the handle usable (a normal
advance afterwards succeeds), no call blocks.
   capi_session.py LIB CASE OP [OP ...]
OPs: advance:DT (DT a Python float literal, e.g. 5e-324, 1e300, nan), pressures:KIND (face
pressures all KIND: nan, inf, 1e308, -1e308, 0, huge), forces:KIND, vpressures:KIND,
save, restore, getters, null:NAME (a NULL output pointer to getter NAME), nullhandle.
Exit 0 when every promise held; 1 with one line "chute: capi: ..." when one was broken."""
import ctypes
import math
import sys

OK, INPUT, SOLVER, STATE, INTERNAL = 0, 1, 2, 3, 4
lib = ctypes.CDLL(sys.argv[1])
lib.chute_coupling_last_error.restype = ctypes.c_char_p
lib.chute_coupling_advance.argtypes = [ctypes.c_void_p, ctypes.c_double,
                                       ctypes.POINTER(ctypes.c_double)]
for name in ["time", "end_time", "preferred_time_step"]:
    getattr(lib, "chute_coupling_" + name).argtypes = [ctypes.c_void_p,
                                                       ctypes.POINTER(ctypes.c_double)]
GETTERS = ["reference_coordinates", "current_coordinates", "displacements", "velocities",
           "accelerations", "face_normals", "face_areas"]
for name in GETTERS + ["set_face_pressures", "set_vertex_pressures", "set_vertex_forces"]:
    getattr(lib, "chute_coupling_" + name).argtypes = [ctypes.c_void_p, ctypes.c_void_p]


def broken(why):
    print("chute: capi: broken promise: " + why, file=sys.stderr)
    sys.exit(1)


handle = ctypes.c_void_p()
rc = lib.chute_coupling_create(sys.argv[2].encode(), None, 0, ctypes.byref(handle))
if rc != OK:
    print("chute: create: " + lib.chute_coupling_last_error(None).decode(errors="replace")
          .splitlines()[0], file=sys.stderr)
    sys.exit(2)
nv, nf = ctypes.c_int(), ctypes.c_int()
lib.chute_coupling_num_vertices(handle, ctypes.byref(nv))
lib.chute_coupling_num_faces(handle, ctypes.byref(nf))
nv, nf = nv.value, nf.value


def now():
    t = ctypes.c_double()
    if lib.chute_coupling_time(handle, ctypes.byref(t)) != OK:
        broken("time() failed")
    return t.value


def state():
    buf = (ctypes.c_double * (3 * nv))()
    if lib.chute_coupling_current_coordinates(handle, buf) != OK:
        broken("current_coordinates() failed")
    return list(buf)


def number(kind):
    return {"huge": 1e300}.get(kind) or float(kind)


def expect_refused_unchanged(what, rc, before):
    if rc not in (INPUT, SOLVER, STATE):
        broken("%s returned %d, not a documented refusal" % (what, rc))
    if not lib.chute_coupling_last_error(handle):
        broken("%s: no error message" % what)
    after = (now(), state())
    if after[0] != before[0] or any(a != b and not (math.isnan(a) and math.isnan(b))
                                    for a, b in zip(after[1], before[1])):
        broken("%s was refused (%d) but changed the state" % (what, rc))


dtp = ctypes.c_double()
lib.chute_coupling_preferred_time_step(handle, ctypes.byref(dtp))
saved = False
for op in sys.argv[3:]:
    name, _, arg = op.partition(":")
    before = (now(), state())
    if name == "advance":
        dt = float(arg)
        taken = ctypes.c_double()
        rc = lib.chute_coupling_advance(handle, dt, ctypes.byref(taken))
        if rc == OK:
            if not (dt > 0 and math.isfinite(dt)):
                broken("advance(%r) returned OK" % dt)
            if now() <= before[0]:
                broken("advance(%r) returned OK without moving time" % dt)
        else:
            expect_refused_unchanged("advance(%r)" % dt, rc, before)
            # The handle stays usable: a normal step afterwards succeeds.
            if lib.chute_coupling_advance(handle, dtp.value, None) != OK:
                broken("after a refused advance(%r) a normal advance fails: %s" % (
                    dt, lib.chute_coupling_last_error(handle).decode(errors="replace")))
    elif name in ("pressures", "vpressures", "forces"):
        n = {"pressures": nf, "vpressures": nv, "forces": 3 * nv}[name]
        fn = {"pressures": "set_face_pressures", "vpressures": "set_vertex_pressures",
              "forces": "set_vertex_forces"}[name]
        values = (ctypes.c_double * max(n, 1))(*([number(arg)] * n))
        rc = getattr(lib, "chute_coupling_" + fn)(handle, values)
        finite = math.isfinite(number(arg))
        if rc == OK and not finite:
            broken("%s(%s) accepted" % (fn, arg))
        if rc != OK:
            expect_refused_unchanged("%s(%s)" % (fn, arg), rc, before)
        # Whatever was accepted, advancing never crashes or blocks; it may fail cleanly.
        rc = lib.chute_coupling_advance(handle, dtp.value, None)
        if rc not in (OK, SOLVER):
            broken("advance after %s(%s) returned %d" % (fn, arg, rc))
        if rc == SOLVER:
            expect_refused_unchanged("advance after %s(%s)" % (fn, arg), rc, before)
            zero = (ctypes.c_double * max(3 * nv, nf, 1))()
            getattr(lib, "chute_coupling_" + fn)(handle, zero)
    elif name == "save":
        if lib.chute_coupling_save_checkpoint(handle) != OK:
            broken("save_checkpoint failed")
        saved = True
    elif name == "restore":
        rc = lib.chute_coupling_restore_checkpoint(handle)
        if saved and rc != OK:
            broken("restore after save failed")
        if not saved:
            expect_refused_unchanged("restore without save", rc, before)
    elif name == "getters":
        for g in GETTERS:
            buf = (ctypes.c_double * (3 * max(nv, nf)))()
            if getattr(lib, "chute_coupling_" + g)(handle, buf) != OK:
                broken(g + " failed")
    elif name == "null":
        rc = getattr(lib, "chute_coupling_" + arg)(handle, None)
        if rc != INPUT:
            broken("%s(NULL) returned %d, not CHUTE_ERROR_INPUT" % (arg, rc))
    elif name == "nullhandle":
        t = ctypes.c_double()
        for g in ["time", "end_time", "preferred_time_step"]:
            if getattr(lib, "chute_coupling_" + g)(None, ctypes.byref(t)) == OK:
                broken(g + "(NULL handle) returned OK")
        if lib.chute_coupling_advance(None, 1e-3, None) == OK:
            broken("advance(NULL handle) returned OK")
    else:
        print("capi_session.py: unknown op " + op, file=sys.stderr)
        sys.exit(3)
lib.chute_coupling_destroy(handle)
sys.exit(0)
