"""Saving and loading: to_bytes/from_bytes, save/load with paths and file
objects, pickling and copies, all through libhdt's format (hdt_save)."""

import copy
import io
import pickle
import struct
import zlib

import pytest

import hdt
from sample_points import as_list, random_points

HEADER, VERTEX_BYTES = 44, 25








def state(t):
    """Everything the faces and vertices lists show, as plain lists."""
    faces, vertices = t.faces(), t.vertices()
    return (t.genus, t.vertex_id_bound, as_list(faces.vertices), as_list(faces.translations),
            as_list(vertices.ids), as_list(vertices.points), as_list(vertices.dummy))


def built(genus=2, count=200, seed=1, remove_every=4, dummies=False):
    t = hdt.Triangulation(genus)
    points = random_points(count, seed)
    ids = [int(i) for i in t.insert_many(points)]
    for vertex in ids[::remove_every] if remove_every else []:
        try:
            t.remove(vertex)
        except hdt.NotSupported:
            pass
    if not dummies:
        t.remove_dummies()
    return t, points, ids


@pytest.mark.parametrize("genus,dummies", [(2, False), (2, True), (3, False)])
def test_bytes_round_trip_keeps_ids_faces_and_later_behaviour(genus, dummies, arrays):
    t, points, _ = built(genus, dummies=dummies)
    data = t.to_bytes()
    assert isinstance(data, bytes)
    u = hdt.Triangulation.from_bytes(data)
    assert u.to_bytes() == data
    assert state(u) == state(t)
    # validate() may give translation ids to elements it meets: both, to keep them in step.
    u.validate()
    t.validate()
    more = random_points(50, seed=99, radius=0.8)
    assert as_list(t.insert_many(more)) == as_list(u.insert_many(more))
    assert state(u) == state(t)


def test_points_are_stored_bit_for_bit_where_the_format_says():
    t, points, ids = built(2, count=50, remove_every=0, dummies=True)
    data = t.to_bytes()
    assert zlib.crc32(data[:-4]) == struct.unpack("<I", data[-4:])[0]
    words, vertices = struct.unpack_from("<II", data, 16)
    at = HEADER
    for _ in range(words):
        at += 2 + 2 * struct.unpack_from("<H", data, at)[0]
    assert vertices == t.vertex_id_bound
    for (x, y), vertex in zip(points, ids):
        assert struct.unpack_from("<dd", data, at + VERTEX_BYTES * int(vertex)) == (x, y)


def test_save_and_load_with_paths_and_file_objects(tmp_path):
    t, _, _ = built(2)
    path = tmp_path / "bolza.hdtri"
    t.save(path)
    assert hdt.Triangulation.load(path).to_bytes() == t.to_bytes()
    assert hdt.Triangulation.load(str(path)).to_bytes() == t.to_bytes()
    buffer = io.BytesIO()
    t.save(buffer)
    buffer.seek(0)
    assert state(hdt.Triangulation.load(buffer)) == state(t)


@pytest.mark.parametrize("operation", [copy.copy, copy.deepcopy, lambda t: pickle.loads(pickle.dumps(t))],
                         ids=["copy", "deepcopy", "pickle"])
def test_copies_and_pickles_are_independent_equals(operation):
    t, _, _ = built(3, count=80)
    u = operation(t)
    assert u is not t and state(u) == state(t)
    u.insert(0.01, 0.02)
    assert len(u) == len(t) + 1
    t.validate()


def test_damaged_bytes_raise_invalid_argument_naming_the_byte():
    data = hdt.Triangulation(2).to_bytes()
    with pytest.raises(hdt.InvalidArgument, match="byte"):
        hdt.Triangulation.from_bytes(data[:-1])
    damaged = bytearray(data)
    damaged[100] ^= 1
    with pytest.raises(hdt.InvalidArgument, match=r"byte \d+: the checksum"):
        hdt.Triangulation.from_bytes(damaged)
    with pytest.raises(hdt.InvalidArgument, match="byte 0:"):
        hdt.Triangulation.from_bytes(b"not a triangulation, but long enough to have a header of 48 bytes")
    with pytest.raises(ValueError):
        hdt.Triangulation.from_bytes(b"")
    with pytest.raises(TypeError):
        hdt.Triangulation.from_bytes("text")


def test_a_closed_triangulation_cannot_be_saved():
    t = hdt.Triangulation(2)
    t.close()
    with pytest.raises(hdt.HandleClosed):
        t.to_bytes()
    with pytest.raises(hdt.HandleClosed):
        pickle.dumps(t)
