"""A small CBOR (RFC 8949) codec, enough to read and re-write chute's checkpoint files: unsigned
and negative integers, byte and text strings, arrays, maps, tags (kept), floats (half, single,
double; written as double), true/false/null. Python's standard library has no CBOR module and
the attack inputs must forge checkpoints whose checksum is right, so the fields are reached."""
import struct


class Tagged:
    def __init__(self, tag, value):
        self.tag, self.value = tag, value


def _head(major, n):
    if n < 24:
        return bytes([major << 5 | n])
    for info, fmt in ((24, ">B"), (25, ">H"), (26, ">I"), (27, ">Q")):
        if n < (1 << (8 * struct.calcsize(fmt))):
            return bytes([major << 5 | info]) + struct.pack(fmt, n)
    raise ValueError("integer too large for CBOR")


def dumps(v):
    if v is None:
        return b"\xf6"
    if v is True:
        return b"\xf5"
    if v is False:
        return b"\xf4"
    if isinstance(v, Tagged):
        return _head(6, v.tag) + dumps(v.value)
    if isinstance(v, int):
        return _head(0, v) if v >= 0 else _head(1, -1 - v)
    if isinstance(v, float):
        return b"\xfb" + struct.pack(">d", v)
    if isinstance(v, (bytes, bytearray)):
        return _head(2, len(v)) + bytes(v)
    if isinstance(v, str):
        b = v.encode("utf-8", "surrogatepass")
        return _head(3, len(b)) + b
    if isinstance(v, list):
        return _head(4, len(v)) + b"".join(dumps(x) for x in v)
    if isinstance(v, dict):
        return _head(5, len(v)) + b"".join(dumps(k) + dumps(x) for k, x in v.items())
    raise TypeError(type(v))


def loads(data):
    v, at = _read(memoryview(bytes(data)), 0)
    if at != len(data):
        raise ValueError("trailing bytes")
    return v


def _read(b, at):
    ib = b[at]
    major, info = ib >> 5, ib & 31
    at += 1
    if major == 7:
        if info == 20:
            return False, at
        if info == 21:
            return True, at
        if info in (22, 23):
            return None, at
        if info == 25:
            return _half(b[at:at + 2]), at + 2
        if info == 26:
            return struct.unpack(">f", b[at:at + 4])[0], at + 4
        if info == 27:
            return struct.unpack(">d", b[at:at + 8])[0], at + 8
        raise ValueError("unsupported simple value %d" % info)
    if info < 24:
        n = info
    elif info in (24, 25, 26, 27):
        size = 1 << (info - 24)
        n = int.from_bytes(b[at:at + size], "big")
        at += size
    else:
        raise ValueError("indefinite lengths are not used by chute")
    if major == 0:
        return n, at
    if major == 1:
        return -1 - n, at
    if major == 2:
        return bytes(b[at:at + n]), at + n
    if major == 3:
        return bytes(b[at:at + n]).decode("utf-8", "surrogatepass"), at + n
    if major == 4:
        out = []
        for _ in range(n):
            x, at = _read(b, at)
            out.append(x)
        return out, at
    if major == 5:
        out = {}
        for _ in range(n):
            k, at = _read(b, at)
            x, at = _read(b, at)
            out[k] = x
        return out, at
    x, at = _read(b, at)
    return Tagged(n, x), at


def _half(two):
    h = int.from_bytes(two, "big")
    sign, exp, frac = h >> 15, (h >> 10) & 31, h & 1023
    if exp == 0:
        val = frac * 2.0 ** -24
    elif exp == 31:
        val = float("inf") if frac == 0 else float("nan")
    else:
        val = (1 + frac / 1024.0) * 2.0 ** (exp - 15)
    return -val if sign else val


def fnv1a(data):
    """The checkpoint's checksum (app/CheckpointFile.cpp): 64-bit FNV-1a over the payload."""
    h = 1469598103934665603
    for byte in data:
        h = ((h ^ byte) * 1099511628211) & 0xFFFFFFFFFFFFFFFF
    return h
