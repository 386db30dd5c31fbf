"""chute_coupling_create() from a host program (ctypes): exit 0 if the case loads, 2 with one line
"chute: create: <error>" for bad input (CHUTE_ERROR_INPUT), 1 otherwise. A crash inside the
library kills this process (the harness sees the signal).
   capi_create.py LIBCHUTE_COUPLING.so CASE.toml [OVERRIDE...]"""
import ctypes
import sys

lib = ctypes.CDLL(sys.argv[1])
lib.chute_coupling_last_error.restype = ctypes.c_char_p
handle = ctypes.c_void_p()
overrides = (ctypes.c_char_p * max(1, len(sys.argv) - 3))(*[a.encode() for a in sys.argv[3:]])
rc = lib.chute_coupling_create(sys.argv[2].encode(), overrides, len(sys.argv) - 3,
                               ctypes.byref(handle))
if rc == 0:
    lib.chute_coupling_destroy(handle)
    sys.exit(0)
message = lib.chute_coupling_last_error(None).decode("utf-8", "replace")
print("chute: create: " + message.splitlines()[0] if message else "chute: create: error %d" % rc,
      file=sys.stderr)
sys.exit(2 if rc == 1 else 1)
