"""Words in Gamma_g and the neighbour set N, against the C semantics."""

import math
import random

import pytest

import hdt

GENERA = (2, 3, 4)


def relator(genus):
    """prod_{j=0}^{4g-1} g_{j(2g+1) mod 4g}, the relation of Gamma_g."""
    return [j * (2 * genus + 1) % (4 * genus) for j in range(4 * genus)]


def inverse(genus, word):
    return [(k + 2 * genus) % (4 * genus) for k in reversed(word)]


def random_words(genus, count=25, longest=14, seed=1):
    generator = random.Random(seed * 1000 + genus)
    return [[generator.randrange(4 * genus) for _ in range(generator.randrange(longest + 1))] for _ in range(count)]


def same_element(m, n, tolerance=1e-9):
    """Whether the SU(1,1) pairs (a, b) m and n agree up to sign."""
    scale = max(1.0, abs(m[0]))
    return any(abs(m[0] - s * n[0]) <= tolerance * scale and abs(m[1] - s * n[1]) <= tolerance * scale
               for s in (1, -1))


def to_hyperboloid(x, y):
    r2 = x * x + y * y
    return ((1 + r2) / (1 - r2), 2 * x / (1 - r2), 2 * y / (1 - r2))


# ---- reduce_word ----

@pytest.mark.parametrize("genus", (2, 3, 4, 5))
def test_the_relator_and_its_inverse_reduce_to_the_identity(genus):
    assert hdt.reduce_word(genus, relator(genus)) == ()
    assert hdt.reduce_word(genus, inverse(genus, relator(genus))) == ()
    rotated = relator(genus)[3:] + relator(genus)[:3]
    assert hdt.reduce_word(genus, rotated) == ()


@pytest.mark.parametrize("genus", GENERA)
def test_reduce_word_is_idempotent_and_keeps_the_element(genus):
    for word in random_words(genus):
        reduced = hdt.reduce_word(genus, word)
        assert isinstance(reduced, tuple) and all(isinstance(k, int) for k in reduced)
        assert len(reduced) <= len(word)
        assert hdt.reduce_word(genus, reduced) == reduced
        assert same_element(hdt.word_matrix(genus, word), hdt.word_matrix(genus, reduced))


@pytest.mark.parametrize("genus", GENERA)
def test_a_word_times_its_inverse_reduces_to_the_identity(genus):
    for word in random_words(genus, count=10):
        assert hdt.reduce_word(genus, word + inverse(genus, word)) == ()


def test_reduce_word_takes_any_iterable_of_ints():
    expected = hdt.reduce_word(2, [0, 1, 2])
    assert hdt.reduce_word(2, (0, 1, 2)) == expected
    assert hdt.reduce_word(2, range(3)) == expected
    assert hdt.reduce_word(2, (k for k in [0, 1, 2])) == expected
    assert hdt.reduce_word(2, []) == ()


def test_a_long_canonical_word_comes_back_whole():
    word = [0, 1, 2, 3] * 3  # already canonical: 12 letters
    assert hdt.reduce_word(2, word) == tuple(word)


# ---- word_matrix, word_lorentz, word_apply ----

def test_the_empty_word_is_the_identity():
    assert hdt.word_matrix(2, []) == (1, 0)
    assert hdt.word_lorentz(2, []) == ((1, 0, 0), (0, 1, 0), (0, 0, 1))
    assert hdt.word_apply(2, [], 0.25, -0.5) == (0.25, -0.5)


@pytest.mark.parametrize("genus", GENERA)
def test_generator_matrices_follow_the_design(genus):
    big_a = 1 / math.tan(math.pi / (4 * genus))
    for k in range(4 * genus):
        a, b = hdt.word_matrix(genus, [k])
        assert a == pytest.approx(big_a, rel=1e-14)
        assert abs(b) == pytest.approx(math.sqrt(big_a**2 - 1), rel=1e-14)
        assert abs(a) ** 2 - abs(b) ** 2 == pytest.approx(1, rel=1e-12)


@pytest.mark.parametrize("genus", GENERA)
def test_generator_k_maps_side_midpoint_k_plus_2g_to_k(genus):
    for k in range(4 * genus):
        x, y = hdt.polygon_side_midpoint(genus, k + 2 * genus)
        assert hdt.word_apply(genus, [k], x, y) == pytest.approx(hdt.polygon_side_midpoint(genus, k), abs=1e-14)


def test_a_word_acts_from_its_last_letter():
    z = (0.1, 0.2)
    inner = hdt.word_apply(2, [5], *z)
    assert hdt.word_apply(2, [3, 5], *z) == pytest.approx(hdt.word_apply(2, [3], *inner), abs=1e-14)


@pytest.mark.parametrize("genus", GENERA)
def test_lorentz_matrix_acts_like_the_moebius_map(genus):
    z = (0.3, -0.1)
    for word in random_words(genus, count=8, longest=4):
        m = hdt.word_lorentz(genus, word)
        p = to_hyperboloid(*z)
        image = tuple(sum(m[i][j] * p[j] for j in range(3)) for i in range(3))
        assert image == pytest.approx(to_hyperboloid(*hdt.word_apply(genus, word, *z)), rel=1e-9)


@pytest.mark.parametrize("genus", GENERA)
def test_words_of_the_identity_give_it_exactly(genus):
    for word in (relator(genus), inverse(genus, relator(genus)), [1, 1 + 2 * genus]):
        assert hdt.word_matrix(genus, word) == (1, 0)
        assert hdt.word_lorentz(genus, word) == ((1, 0, 0), (0, 1, 0), (0, 0, 1))
        assert hdt.word_apply(genus, word, 0.0, 0.14) == (0.0, 0.14)


def test_results_beyond_double_are_out_of_domain():
    a, b = hdt.word_matrix(2, [0] * 400)  # cosh and sinh of 400 acosh(cot(pi/8)): 1.7e265
    assert math.isfinite(a.real) and math.isfinite(b.real) and a.real > 1e265
    with pytest.raises(hdt.OutOfDomain, match="hdt_word_matrix: the matrix entries exceed the double range"):
        hdt.word_matrix(2, [0] * 470)
    with pytest.raises(hdt.OutOfDomain, match="hdt_word_lorentz: the matrix entries exceed the double range"):
        hdt.word_lorentz(2, [0] * 400)
    with pytest.raises(hdt.OutOfDomain, match="hdt_word_apply: the image"):
        hdt.word_apply(2, [0] * 100, 0.1, 0.2)


def test_word_apply_accepts_ints_and_floats():
    assert hdt.word_apply(2, [0], 0, 0) == hdt.word_apply(2, [0], 0.0, 0.0)


# ---- the neighbour set N ----

@pytest.mark.parametrize("genus", (2, 3, 4, 5, 6))
def test_the_neighbour_count_is_4g_minus_1_squared(genus):
    assert hdt.neighbour_count(genus) == (4 * genus - 1) ** 2
    assert len(hdt.neighbour_words(genus)) == (4 * genus - 1) ** 2


@pytest.mark.parametrize("genus", GENERA)
def test_neighbour_words_are_canonical_in_shortlex_order(genus):
    words = hdt.neighbour_words(genus)
    assert words[0] == ()
    assert words == sorted(words, key=lambda w: (len(w), w))
    assert len(set(words)) == len(words)
    assert max(map(len, words)) == 2 * genus
    for i, word in enumerate(words):
        assert hdt.neighbour_word(genus, i) == word
        assert hdt.reduce_word(genus, word) == word


# ---- bad input ----

def test_a_letter_out_of_range_is_an_invalid_argument():
    with pytest.raises(hdt.InvalidArgument, match=r"hdt_word_reduce: letter 8 at position 1 is outside 0\.\.7"):
        hdt.reduce_word(2, [0, 8])
    with pytest.raises(ValueError, match=r"letter -1 at position 0 is outside 0\.\.7"):
        hdt.word_matrix(2, [-1])
    with pytest.raises(hdt.InvalidArgument, match="letter 1099511627776 at position 2"):
        hdt.word_lorentz(2, [0, 1, 2**40])


@pytest.mark.parametrize("function, arguments", [
    (hdt.reduce_word, ()), (hdt.word_matrix, ()), (hdt.word_lorentz, ()), (hdt.word_apply, (0.0, 0.0)),
])
def test_every_word_function_checks_genus_and_word(function, arguments):
    with pytest.raises(hdt.InvalidArgument, match="genus must be at least 2, got 1") as caught:
        function(1, [0], *arguments)
    assert isinstance(caught.value, ValueError)
    with pytest.raises(hdt.NotSupported, match="exceeds HDT_GENUS_MAX"):
        function(2000, [0], *arguments)
    with pytest.raises(hdt.InvalidArgument, match="letter 9 at position 0"):
        function(2, [9], *arguments)
    with pytest.raises(TypeError, match="word must be an iterable of ints, not int"):
        function(2, 5, *arguments)
    with pytest.raises(TypeError, match="letter at position 1 must be an int, not float"):
        function(2, [0, 1.0], *arguments)
    with pytest.raises(TypeError, match="letter at position 0 must be an int, not str"):
        function(2, "01", *arguments)


@pytest.mark.parametrize("x, y, text", [
    (math.nan, 0.0, "is not finite"),
    (0.0, math.inf, "is not finite"),
    (1.0, 0.0, "not inside the open unit disk"),
    (0.6, 0.8, "not inside the open unit disk"),
    (-2.0, 0.5, "not inside the open unit disk"),
    (10**400, 0, "is not finite"),
], ids=["nan", "inf", "on the circle", "rounds onto the circle", "outside", "huge int"])
def test_word_apply_outside_the_open_disk_is_out_of_domain(x, y, text):
    with pytest.raises(hdt.OutOfDomain, match=text) as caught:
        hdt.word_apply(2, [0], x, y)
    assert isinstance(caught.value, ValueError)
    assert caught.value.status == hdt.Status.EDOMAIN
    assert caught.value.message.startswith("hdt_word_apply: ")


def test_word_apply_wants_real_coordinates():
    with pytest.raises(TypeError, match="x must be a real number, not str"):
        hdt.word_apply(2, [0], "0.5", 0.0)
    with pytest.raises(TypeError, match="y must be a real number, not complex"):
        hdt.word_apply(2, [0], 0.0, 0.5j)


def test_a_neighbour_id_not_in_n_is_an_invalid_argument():
    with pytest.raises(hdt.InvalidArgument, match=r"translation id 49 is not in N \(\|N\| = 49\)"):
        hdt.neighbour_word(2, 49)
    with pytest.raises(hdt.InvalidArgument, match="translation id -1 is not in N"):
        hdt.neighbour_word(2, -1)
    with pytest.raises(hdt.InvalidArgument, match="is not in N"):
        hdt.neighbour_word(2, 2**70)
    with pytest.raises(TypeError, match="id must be an int"):
        hdt.neighbour_word(2, 1.5)


def test_neighbour_functions_check_the_genus():
    for function in (hdt.neighbour_count, hdt.neighbour_words):
        with pytest.raises(hdt.InvalidArgument, match="genus must be at least 2"):
            function(1)
    with pytest.raises(hdt.NotSupported, match="exceeds HDT_GENUS_MAX"):
        hdt.neighbour_word(2000, 0)
