"""A minimal CBOR decoder (RFC 8949) for the .rigmesh documents that
nlohmann::json::to_cbor writes: ints, floats (16/32/64), strings, arrays,
maps, true/false/null, tags (the tag is dropped)."""
import struct


def loads(data: bytes):
    value, end = _item(data, 0)
    return value


def _length(data, pos, info):
    if info < 24:
        return info, pos
    if info == 24:
        return data[pos], pos + 1
    if info == 25:
        return struct.unpack_from(">H", data, pos)[0], pos + 2
    if info == 26:
        return struct.unpack_from(">I", data, pos)[0], pos + 4
    if info == 27:
        return struct.unpack_from(">Q", data, pos)[0], pos + 8
    raise ValueError("indefinite lengths not supported")


def _item(data, pos):
    head = data[pos]
    pos += 1
    major, info = head >> 5, head & 31
    if major == 7:
        if info == 20:
            return False, pos
        if info == 21:
            return True, pos
        if info in (22, 23):
            return None, pos
        if info == 25:
            return struct.unpack_from(">e", data, pos)[0], pos + 2
        if info == 26:
            return struct.unpack_from(">f", data, pos)[0], pos + 4
        if info == 27:
            return struct.unpack_from(">d", data, pos)[0], pos + 8
        raise ValueError("simple value %d" % info)
    n, pos = _length(data, pos, info)
    if major == 0:
        return n, pos
    if major == 1:
        return -1 - n, pos
    if major == 2:
        return bytes(data[pos:pos + n]), pos + n
    if major == 3:
        return data[pos:pos + n].decode("utf-8"), pos + n
    if major == 4:
        out = []
        for _ in range(n):
            v, pos = _item(data, pos)
            out.append(v)
        return out, pos
    if major == 5:
        out = {}
        for _ in range(n):
            k, pos = _item(data, pos)
            v, pos = _item(data, pos)
            out[k] = v
        return out, pos
    if major == 6:
        return _item(data, pos)
    raise ValueError("major %d" % major)
