"""Words in the group Gamma_g of M_g, and its neighbour set N.

A word is any iterable of ints, the letters 0..4g-1: letter k is the
generator g_k, the translation that maps side s_{k+2g} of F_g onto side s_k,
and g_{k+2g} is the inverse of g_k. The word [k1, ..., km] is the product
g_k1 g_k2 ... g_km (applied to a point, g_km acts first); the empty word is
the identity.

Every function raises :class:`hdt.InvalidArgument` (a ValueError) for
genus < 2 or a letter outside 0..4g-1, :class:`hdt.NotSupported` for a genus
above HDT_GENUS_MAX, and TypeError when the word is not an iterable of ints.
"""

from __future__ import annotations

from typing import List, Tuple

from ._arrays import Matrix, Point, Word, WordLike
from ._convert import c_coordinate, c_genus, c_id, c_word, call_doubles, call_point, call_size, call_word
from ._lib import lib


def reduce_word(genus: int, word: WordLike) -> Word:
    """The canonical word of the element, as a tuple of ints.

    The canonical word is the shortlex-least geodesic word (fewest letters;
    among those, lexicographically least). Two words of the same element give
    the same canonical word; the identity gives (). Raises
    :class:`hdt.NotSupported` when the reduced word has more than 2048
    letters and needs a precision that grows with its length (see hdt.h).
    """
    letters, length = c_word(word)
    # A canonical word is never longer than the word, so one call mostly does.
    return call_word(lib.hdt_word_reduce, c_genus(genus), letters, length, capacity=length)


def word_matrix(genus: int, word: WordLike) -> Matrix:
    """The SU(1,1) matrix [[a, b], [conj b, conj a]] of the word as the pair
    (a, b) of complex numbers, in double precision.

    The word is shortened with Dehn's algorithm first, which keeps the matrix
    (any word of the identity gives exactly (1, 0)); the product is computed
    in multiprecision and rounded once. A matrix and its negative are the
    same element. Raises :class:`hdt.OutOfDomain` when an entry exceeds the
    double range (g_0^n at genus 2 from n = 465).
    """
    letters, length = c_word(word)
    re_a, im_a, re_b, im_b = call_doubles(lib.hdt_word_matrix, 4, c_genus(genus), letters, length)
    return complex(re_a, im_a), complex(re_b, im_b)


def word_lorentz(genus: int, word: WordLike) -> Tuple[Tuple[float, ...], ...]:
    """The 3x3 Lorentz matrix of the word acting on the hyperboloid
    t^2 - u^2 - v^2 = 1, as a tuple of three rows (t, u, v).

    A disk point z = x + iy is the hyperboloid point
    ((1 + |z|^2), 2x, 2y) / (1 - |z|^2). Dehn's algorithm first, as in
    :func:`word_matrix`. Raises :class:`hdt.OutOfDomain` when an entry
    exceeds the double range (g_0^n at genus 2 from n = 233).
    """
    letters, length = c_word(word)
    m = call_doubles(lib.hdt_word_lorentz, 9, c_genus(genus), letters, length)
    return tuple(tuple(m[row : row + 3]) for row in (0, 3, 6))


def word_apply(genus: int, word: WordLike, x: float, y: float) -> Point:
    """The image (x', y') of the disk point (x, y) under the word's element.

    A word of the identity returns (x, y) unchanged. Raises
    :class:`hdt.OutOfDomain` (a ValueError) when (x, y) is not a finite point
    of the open unit disk, or when the image, rounded to double, is not in it
    (images within 2^-100 of the circle may be refused without being
    computed); TypeError when x or y is not a real number.
    """
    letters, length = c_word(word)
    x, y = c_coordinate(x, "x"), c_coordinate(y, "y")
    return call_point(lib.hdt_word_apply, c_genus(genus), letters, length, x, y)


def neighbour_count(genus: int) -> int:
    """The size (4g-1)^2 of N = {h in Gamma_g : h(F_g) meets F_g}, identity
    included."""
    return call_size(lib.hdt_neighbour_count, c_genus(genus))


def neighbour_word(genus: int, id: int) -> Word:
    """The canonical word (a tuple of ints) of the element of N with
    translation id `id`.

    The ids 0..neighbour_count(genus)-1 are fixed for each genus: id 0 is the
    identity, the others follow in shortlex order of their canonical words.
    Raises :class:`hdt.InvalidArgument` when id is not in that range.
    """
    return call_word(lib.hdt_neighbour_word, c_genus(genus), c_id(id))


def neighbour_words(genus: int) -> List[Word]:
    """The canonical words of N as a list indexed by translation id
    (see :func:`neighbour_word`)."""
    return [neighbour_word(genus, i) for i in range(neighbour_count(genus))]
