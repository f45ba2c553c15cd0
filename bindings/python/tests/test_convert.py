"""The two-call pattern of hdt._convert.call_word, against a fake C function."""

import pytest

import hdt
from hdt._convert import call_word

WORD = (3, 1, 4)


def fake_word_function(word, lie_by=0):
    """A stand-in for hdt_neighbour_word: (function, capacities it was called with)."""
    capacities = []

    def function(out, capacity, out_length):
        capacities.append(capacity)
        out_length._obj.value = len(word) + lie_by * len(capacities)
        if capacity == 0:
            return hdt.Status.OK
        if capacity < out_length._obj.value:
            return hdt.Status.EBUFS
        out[: len(word)] = word
        return hdt.Status.OK

    function.__name__ = "fake"
    return function, capacities


@pytest.mark.parametrize("guess, calls", [(0, [0, 3]), (2, [2, 3]), (3, [3]), (10, [10])])
def test_call_word_asks_again_only_when_the_guess_is_short(guess, calls):
    function, capacities = fake_word_function(WORD)
    assert call_word(function, capacity=guess) == WORD
    assert capacities == calls


def test_the_empty_word_takes_one_call():
    function, capacities = fake_word_function(())
    assert call_word(function) == ()
    assert capacities == [0]


def test_a_length_that_keeps_growing_is_an_internal_error():
    function, _ = fake_word_function(WORD, lie_by=1)
    with pytest.raises(hdt.InternalError, match="fake: the word's length changed between calls"):
        call_word(function)
