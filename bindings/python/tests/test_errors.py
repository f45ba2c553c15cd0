"""The exception hierarchy: one class per status code of include/hdt.h."""

import pytest

import hdt
from hdt._errors import error_for_status

CLASSES = [
    (hdt.Error, -1, ()),
    (hdt.InvalidArgument, -2, (ValueError,)),
    (hdt.OutOfDomain, -3, (ValueError,)),
    (hdt.AlreadyExists, -4, ()),
    (hdt.OutOfMemory, -5, (MemoryError,)),
    (hdt.BufferTooSmall, -6, ()),
    (hdt.NotSupported, -7, ()),
    (hdt.InternalError, -99, ()),
]


def test_status_values_are_those_of_the_header():
    assert {s.name: int(s) for s in hdt.Status} == {
        "OK": 0, "ERROR": -1, "EINVAL": -2, "EDOMAIN": -3, "EEXISTS": -4, "ENOMEM": -5, "EBUFS": -6,
        "ENOTSUP": -7, "EINTERNAL": -99}


@pytest.mark.parametrize("cls, status, bases", CLASSES)
def test_each_status_has_its_class(cls, status, bases):
    assert issubclass(cls, hdt.Error) and issubclass(cls, Exception)
    for base in bases:
        assert issubclass(cls, base)
    assert cls.status == status
    error = error_for_status(status)
    assert type(error) is cls
    assert error.status == status and error.status is hdt.Status(status)


def test_an_error_carries_the_library_message():
    with pytest.raises(hdt.Error) as caught:
        hdt.reduce_word(2, [0, 8])
    error = caught.value
    assert error.message == "hdt_word_reduce: letter 8 at position 1 is outside 0..7"
    assert str(error) == error.message
    assert error.status == hdt.Status.EINVAL


def test_an_unknown_status_is_a_plain_error():
    error = error_for_status(-1234)
    assert type(error) is hdt.Error
    assert error.status == -1234
    assert error.message


def test_errors_made_in_python_default_to_their_class_status():
    assert hdt.InvalidArgument("text").status == hdt.Status.EINVAL
    assert hdt.Error("text").status == hdt.Status.ERROR


def test_already_exists_can_carry_the_vertex():
    assert hdt.AlreadyExists("text").vertex is None
    with hdt.Triangulation(2) as t:
        v = t.insert(0.25, 0.125)
        with pytest.raises(hdt.AlreadyExists) as caught:
            t.insert(0.25, 0.125)
    assert caught.value.vertex == v


def test_a_closed_handle_is_an_invalid_argument_of_its_own_class():
    assert issubclass(hdt.HandleClosed, hdt.InvalidArgument) and issubclass(hdt.HandleClosed, ValueError)
    assert hdt.HandleClosed("text").status == hdt.Status.EINVAL
    assert type(error_for_status(hdt.Status.EINVAL)) is hdt.InvalidArgument  # never made from a status
