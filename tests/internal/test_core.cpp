// Internal tests of the C++ core (Check, compiled as C++).
#include <algorithm>
#include <array>
#include <cfloat>
#include <cmath>
#include <cstdio>
#include <limits>
#include <random>

#include "exact/field.hpp"
#include "exact/multiprecision.hpp"
#include "exact/unit_disk.hpp"
#include "group/canonical.hpp"
#include "group/centre_index.hpp"
#include "group/dehn.hpp"
#include "group/exact_lorentz.hpp"
#include "group/generators.hpp"
#include "group/moebius_centre.hpp"
#include "group/neighbours.hpp"
#include "group/translation_table.hpp"
#include "group/word_matrix.hpp"
#include "surface/polygon.hpp"
#include "surface/systole.hpp"

// Last: check.h defines a macro named fail that breaks <iostream>.
#include <check.h>

#include "run_suite.hpp"

using namespace hdt;
using group::Letter;
using group::Presentation;
using group::Word;

namespace {

template <class T>
T distance_to_identity(const group::Moebius<T> &m) {
  using std::abs;
  // +I or -I: the SU(1,1) sign is free.
  const T plus = abs(m.a.re - T(1)) + abs(m.a.im) + abs(m.b.re) + abs(m.b.im);
  const T minus = abs(m.a.re + T(1)) + abs(m.a.im) + abs(m.b.re) + abs(m.b.im);
  return plus < minus ? plus : minus;
}

double matrix_gap(const group::Moebius<double> &x, const group::Moebius<double> &y) {
  const double plus = std::abs(x.a.re - y.a.re) + std::abs(x.a.im - y.a.im) + std::abs(x.b.re - y.b.re) +
                      std::abs(x.b.im - y.b.im);
  const double minus = std::abs(x.a.re + y.a.re) + std::abs(x.a.im + y.a.im) + std::abs(x.b.re + y.b.re) +
                       std::abs(x.b.im + y.b.im);
  return std::min(plus, minus) / (1.0 + std::abs(x.a.re));
}

Word random_word(std::mt19937 &rng, int letters, int max_length) {
  std::uniform_int_distribution<int> len(0, max_length), letter(0, letters - 1);
  Word w(len(rng));
  for (Letter &k : w) k = letter(rng);
  return w;
}

}  // namespace

// The closed forms of N (neighbour_word, neighbour_id) against the sorted
// enumeration, which also yields canonical words (checked above); and
// every other word of length <= 2g is no id: a run spelled the long way, a
// non-run, a letter out of range.
START_TEST(neighbour_closed_forms_match_enumeration) {
  for (int g = 2; g <= 12; ++g) {
    const Presentation p(g);
    const std::vector<Word> all = group::neighbour_words(p);
    ck_assert_uint_eq(all.size(), group::neighbour_count(p));
    for (std::size_t id = 0; id < all.size(); ++id) {
      ck_assert_msg(group::neighbour_word(p, id) == all[id], "g=%d id %zu", g, id);
      ck_assert_int_eq(group::neighbour_id(p, all[id]), int64_t(id));
    }
    const int h = p.half_relator(), n = p.letter_count();
    int canonical_half_runs = 0;
    for (Letter y = 0; y < n; ++y)
      for (int s : {p.relator_step(), p.inverse_relator_step()}) {
        Word w(h);
        for (int i = 0; i < h; ++i) w[i] = Letter((y + int64_t(i) * s) % n);
        const int64_t id = group::neighbour_id(p, w);
        if (id >= 0) ++canonical_half_runs, ck_assert(all[std::size_t(id)] == w);
        else ck_assert(std::find(all.begin(), all.end(), w) == all.end());
      }
    ck_assert_int_eq(canonical_half_runs, n);
    ck_assert_int_eq(group::neighbour_id(p, Word{0, 1}), -1);
    ck_assert_int_eq(group::neighbour_id(p, Word{0, Letter(n)}), -1);
    ck_assert_int_eq(group::neighbour_id(p, p.relator()), -1);
  }
  // Large genus: the round trip on a sample, without the enumeration.
  const Presentation p(1024);
  for (std::size_t id = 0; id < group::neighbour_count(p); id += 9973) {
    const Word w = group::neighbour_word(p, id);
    ck_assert_int_eq(group::neighbour_id(p, w), int64_t(id));
  }
}
END_TEST

// The multiprecision generator sets fold the angles onto [0, pi/2] (a sign
// per quadrant): each generator agrees with the direct formula.
START_TEST(folded_generator_sets_match_the_formula) {
  using T = exact::mp_real<40>;
  for (int g : {2, 3, 5, 32}) {
    const Presentation p(g);
    const group::GeneratorSet<T> set(p);
    const T A = group::half_trace<T>(g);
    for (Letter k = 0; k < p.letter_count(); ++k) {
      const group::Moebius<T> direct = group::generator<T>(p, k), folded = set.moebius(k);
      const T gap = abs(direct.a.re - folded.a.re) + abs(direct.a.im - folded.a.im) + abs(direct.b.re - folded.b.re) +
                    abs(direct.b.im - folded.b.im);
      ck_assert_msg(gap < T(1e-36) * A, "g=%d letter %d", g, k);
    }
  }
}
END_TEST

START_TEST(relation_is_identity_in_mpfr) {
  using T = exact::mp_real<100>;
  for (int g = 2; g <= 32; ++g) {
    const Presentation p(g);
    const group::GeneratorSet<T> gens(p);
    const T gap = distance_to_identity(gens.moebius(p.relator()));
    ck_assert_msg(gap < T("1e-60"), "genus %d: relator is %g from the identity", g, gap.convert_to<double>());
    // The Lorentz product is exactly the identity matrix too.
    const auto L = gens.lorentz(p.relator());
    T worst = 0;
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) worst = std::max(worst, T(abs(L.m[i][j] - T(i == j ? 1 : 0))));
    ck_assert_msg(worst < T("1e-55"), "genus %d: Lorentz relator off by %g", g, worst.convert_to<double>());
  }
}
END_TEST

// zeta^k (its one-coefficient form when n is a power of two) equals k
// products by zeta, and sin(2 pi k/n) (without the product by 1/i) satisfies
// sin^2 + cos^2 = 1 and sin(2 pi k/n) = cos(2 pi (k - n/4)/n), exactly, for
// n = 8g at a power-of-two genus and at others.
START_TEST(cyclotomic_powers_and_sines_are_exact) {
  for (int n : {16, 24, 40, 64, 96}) {
    const exact::CyclotomicField K(n);
    const exact::Cyclotomic zeta = K.zeta_power(1), one = K.integer(1);
    exact::Cyclotomic power = one;
    for (long k = 0; k < 2L * n; ++k) {
      const auto same = [&](const exact::Cyclotomic &a, const exact::Cyclotomic &b) { return K.sub(a, b).is_zero(); };
      ck_assert_msg(same(K.zeta_power(k), power), "n=%d zeta^%ld", n, k);
      ck_assert_msg(same(K.zeta_power(k - 3L * n), power), "n=%d zeta^(%ld - 3n)", n, k);
      const exact::Cyclotomic c = K.cos_2pi(k), s = K.sin_2pi(k);
      ck_assert_msg(same(K.add(K.mul(c, c), K.mul(s, s)), one), "n=%d k=%ld: sin^2 + cos^2", n, k);
      ck_assert_msg(same(s, K.cos_2pi(k - n / 4)), "n=%d k=%ld: sin", n, k);
      power = K.mul(power, zeta);
    }
  }
}
END_TEST

START_TEST(relation_is_exact_in_the_field) {
  // The exact Lorentz matrices M_k of the generators (each sin(pi/4g)^2 times
  // the Lorentz matrix) multiply along the relator to sin(pi/4g)^(8g) I, with
  // every entry compared exactly (zero test in K_g, no rounding).
  for (int g = 2; g <= 8; ++g) {
    const Presentation p(g);
    const exact::Field &F = exact::field_of_genus(g);
    const exact::CyclotomicField &K = F.cyclotomic();
    const group::ExactLorentz L = group::exact_lorentz(F, p.relator());
    ck_assert_int_eq(L.letters, 4 * g);
    const exact::Cyclotomic s = K.sin_2pi(1), s2 = K.mul(s, s);
    exact::Cyclotomic scale = K.integer(1);
    for (int i = 0; i < L.letters; ++i) scale = K.mul(scale, s2);
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) {
        const exact::FieldElement expected = i == j ? F.from_cyclotomic(scale) : F.zero();
        ck_assert_msg(F.sign(F.sub(L.m[i][j], expected)) == exact::Sign::zero, "genus %d: entry (%d, %d) is not exact",
                      g, i, j);
      }
    // A proper prefix is not a multiple of the identity.
    const Word relator = p.relator();
    const group::ExactLorentz half = group::exact_lorentz(F, Word(relator.begin(), relator.begin() + 2 * g));
    ck_assert(F.sign(half.m[0][1]) != exact::Sign::zero || F.sign(half.m[0][2]) != exact::Sign::zero ||
              F.sign(half.m[1][2]) != exact::Sign::zero);
    // The exact generator agrees with the double one after the scale.
    const group::ExactLorentz G = group::exact_generator(F, 3 % p.letter_count());
    const auto D = group::Lorentz<double>::from_moebius(group::generator<double>(p, 3 % p.letter_count()));
    const double s2d = F.approximate(F.from_cyclotomic(s2));
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j)
        ck_assert_double_eq_tol(F.approximate(G.m[i][j]) / s2d, D.m[i][j], 1e-12 * D.m[0][0]);
  }
}
END_TEST

START_TEST(relation_in_plain_double_within_its_error_bound) {
  for (int g = 2; g <= 32; ++g) {
    const Presentation p(g);
    const group::GeneratorSet<double> gens(p);
    const double gap = distance_to_identity(gens.moebius(p.relator()));
    // The plain product loses about 2^word_precision_bits ulps at worst.
    const double bound = std::ldexp(DBL_EPSILON, int(group::word_precision_bits(p, p.relator().size())));
    ck_assert_msg(gap < bound, "genus %d: gap %g above bound %g", g, gap, bound);
    // The accurate path rounds once: the identity to the last bit.
    ck_assert_double_lt(distance_to_identity(group::accurate_moebius(p, p.relator())), 1e-15);
  }
}
END_TEST

// The test's own inverse map of the hyperboloid to the disk,
// (t, u, v) -> (u, v) / (1 + t), and inverse of a Lorentz matrix, J L^T J
// with J = diag(1, -1, -1): the library needs neither.
template <class T>
group::Complex<T> to_disk(const group::HyperboloidPoint<T> &p) {
  const T s = T(1) / (T(1) + p.t);
  return {p.u * s, p.v * s};
}

template <class T>
group::Lorentz<T> lorentz_inverse(const group::Lorentz<T> &L) {
  group::Lorentz<T> r;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) r.m[i][j] = ((i == 0) == (j == 0) ? T(1) : T(-1)) * L.m[j][i];
  return r;
}

START_TEST(lorentz_matches_moebius) {
  std::mt19937 rng(7);
  for (int g : {2, 3, 7}) {
    const Presentation p(g);
    const group::GeneratorSet<double> gens(p);
    for (int trial = 0; trial < 200; ++trial) {
      const Word w = random_word(rng, p.letter_count(), 4);
      const auto m = gens.moebius(w);
      const auto L = gens.lorentz(w);
      const group::Complex<double> z{0.3 - 0.001 * trial, 0.2};
      const auto image = to_disk(L.apply(group::to_hyperboloid(z)));
      const auto direct = m.apply(z);
      ck_assert_double_eq_tol(image.re, direct.re, 1e-9);
      ck_assert_double_eq_tol(image.im, direct.im, 1e-9);
      ck_assert_double_eq_tol(m.determinant(), 1.0, 1e-9 * (1 + m.a.re * m.a.re));
      // The two translation lengths agree.
      ck_assert_double_eq_tol(m.translation_length(), L.translation_length(), 1e-7);
      // L^{-1} L = I, up to rounding that grows with the entries' size (on the
      // accurately rounded matrix: the plain product drifts off the group).
      const auto La = group::accurate_lorentz(p, w);
      const auto I = lorentz_inverse(La) * La;
      const double tol = 1e-14 * La.m[0][0] * La.m[0][0];
      for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) ck_assert_double_eq_tol(I.m[i][j], (i == j ? 1.0 : 0.0), tol);
    }
  }
}
END_TEST

START_TEST(dehn_output_is_reduced_and_equal) {
  std::mt19937 rng(11);
  for (int g = 2; g <= 6; ++g) {
    const Presentation p(g);
    for (int trial = 0; trial < 500; ++trial) {
      const Word w = random_word(rng, p.letter_count(), 30);
      const Word r = group::dehn_reduce(p, w);
      ck_assert(group::is_dehn_reduced(p, r));
      ck_assert_uint_le(r.size(), w.size());
      ck_assert_double_lt(matrix_gap(group::accurate_moebius(p, w), group::accurate_moebius(p, r)), 1e-9);
    }
    // Every rotation of the relator and of its inverse vanishes.
    const Word rel = p.relator();
    for (int k = 0; k < p.letter_count(); ++k) {
      Word rot(rel.begin() + k, rel.end());
      rot.insert(rot.end(), rel.begin(), rel.begin() + k);
      ck_assert(group::dehn_reduce(p, rot).empty());
      ck_assert(group::dehn_reduce(p, p.inverse(rot)).empty());
    }
  }
}
END_TEST

START_TEST(dehn_is_not_geodesic_but_canonical_is) {
  // A chain of two half relators: Dehn-reduced, yet two letters too long.
  const Presentation p(2);
  const Word chain{0, 5, 2, 7, 5, 2, 7, 4};
  ck_assert(group::is_dehn_reduced(p, chain));
  const Word c = group::canonical_word(p, chain);
  ck_assert_uint_eq(c.size(), 6);
  ck_assert_double_lt(matrix_gap(group::accurate_moebius(p, chain), group::accurate_moebius(p, c)), 1e-12);
}
END_TEST

START_TEST(neighbour_ids_are_fixed_and_tables_agree) {
  for (int g = 2; g <= 5; ++g) {
    const Presentation p(g);
    group::TranslationTable table(p), other(p);
    ck_assert_uint_eq(table.neighbour_count(), group::neighbour_count(p));
    ck_assert(table.word(0).empty());
    for (std::size_t id = 0; id < table.neighbour_count(); ++id) {
      ck_assert(table.word(id) == group::neighbour_word(p, id));
      ck_assert(group::canonical_word(p, table.word(id)) == table.word(id));
    }
    // Composition agrees with matrices, is cached, and gives the same ids in
    // two tables that meet the new elements in the same order.
    std::mt19937 rng(g);
    std::uniform_int_distribution<int> pick(0, int(table.neighbour_count()) - 1);
    for (int trial = 0; trial < 300; ++trial) {
      const int a = pick(rng), b = pick(rng);
      const auto ab = table.compose(a, b);
      ck_assert_int_eq(ab, table.compose(a, b));
      ck_assert_int_eq(ab, other.compose(a, b));
      ck_assert_double_lt(matrix_gap(table.moebius(ab), table.moebius(a) * table.moebius(b)), 1e-9);
      ck_assert_int_eq(table.compose(ab, table.inverse(b)), a);
    }
  }
}
END_TEST

// Products and inverses named through the centre index (most of them, once
// the factors' matrices are known) are the elements of the concatenated
// words, checked against canonical_word; products of products reach
// elements outside N. A centre away from every element finds nothing.
START_TEST(products_named_by_centre_are_canonical) {
  for (int g : {2, 3, 4, 8}) {
    const Presentation p(g);
    group::TranslationTable table(p);
    std::mt19937 rng(100 + g);
    std::vector<group::TranslationId> pool;
    for (std::size_t id = 0; id < table.neighbour_count(); ++id) pool.push_back(group::TranslationId(id));
    for (int trial = 0; trial < 1500; ++trial) {
      std::uniform_int_distribution<std::size_t> pick(0, pool.size() - 1);
      const auto a = pool[pick(rng)], b = pool[pick(rng)];
      const auto ab = table.compose(a, b);
      Word w = table.word(a);
      w.insert(w.end(), table.word(b).begin(), table.word(b).end());
      ck_assert_msg(table.word(ab) == group::canonical_word(p, w), "g=%d: product %d * %d misnamed", g, a, b);
      const auto inv = table.inverse(ab);
      ck_assert_msg(table.word(inv) == group::canonical_word(p, p.inverse(table.word(ab))), "g=%d: inverse misnamed", g);
      if (trial % 50 == 0 && table.word(ab).size() <= std::size_t(3 * g)) pool.push_back(ab);
    }
    group::CentreIndex index(p);
    for (std::size_t id = 0; id < table.neighbour_count(); ++id) {
      const auto &L = table.lorentz(group::TranslationId(id));
      index.add(int32_t(id), L.m[1][0], L.m[2][0], 0);
    }
    const double K = 16 * index.max_error();
    for (std::size_t id = 0; id < table.neighbour_count(); ++id) {
      const auto &L = table.lorentz(group::TranslationId(id));
      const double e = index.max_error();
      ck_assert_int_eq(index.find(L.m[1][0] + e / 2, L.m[2][0] - e / 2, e), int32_t(id));
      // Half way to the nearest other centre (>= K away) is nobody's.
      ck_assert_int_eq(index.find(L.m[1][0] + K / 2, L.m[2][0], e), -1);
      ck_assert_int_eq(index.find(L.m[1][0], L.m[2][0] - K / 2, e), -1);
    }
  }
}
END_TEST

// The table's matrices (one Moebius product, accurate_matrices) agree with
// the separately computed Lorentz and Moebius products to 2^-60 of L_00.
START_TEST(table_matrices_match_word_products) {
  for (int g : {2, 3, 5, 16}) {
    const Presentation p(g);
    group::TranslationTable table(p);
    const std::size_t step = g == 16 ? 97 : 1;
    for (std::size_t id = 0; id < table.neighbour_count(); id += step) {
      const auto t = group::TranslationId(id);
      const auto L = group::accurate_lorentz(p, table.word(t));
      const auto M = group::accurate_moebius(p, table.word(t));
      const double tol = 0x1p-60 * L.m[0][0];
      for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j)
          ck_assert_msg(std::abs(table.lorentz(t).m[i][j] - L.m[i][j]) <= tol, "g=%d id %zu L[%d][%d]", g, id, i, j);
      ck_assert(std::abs(table.moebius(t).a.re - M.a.re) <= tol && std::abs(table.moebius(t).a.im - M.a.im) <= tol);
      ck_assert(std::abs(table.moebius(t).b.re - M.b.re) <= tol && std::abs(table.moebius(t).b.im - M.b.im) <= tol);
    }
  }
}
END_TEST

// The centres that name products and inverses (moebius_centre.hpp), from
// the table's double Moebius matrices, are within their error bounds of the
// centres of the concatenated words' products at 2660 bits (the words of
// two elements of N at genus 32 lose at most 128 log2(2A) < 700 bits, a run
// at genus 128 2,138), and stay below a quarter of the index's K/16 (0.53
// against 5.1 at genus 32), so that the index can name these products.
START_TEST(moebius_centres_within_their_bounds) {
  using R = exact::mp_real<800>;
  auto exact_centre = [](const Presentation &p, const Word &w, R *p1, R *p2) {
    const group::Moebius<R> m = group::shared_generators<R>(p).moebius(w);
    const group::Complex<R> ab = m.a * m.b;
    *p1 = R(2) * ab.re, *p2 = R(2) * ab.im;
  };
  auto within = [](double p1, double p2, double error, const R &e1, const R &e2) {
    return abs(R(p1) - e1) <= R(error) && abs(R(p2) - e2) <= R(error);
  };
  for (int g : {2, 3, 8, 32, 128}) {
    const Presentation p(g);
    group::TranslationTable table(p);
    const group::CentreIndex index(p);
    std::mt19937 rng(300 + g);
    std::uniform_int_distribution<std::size_t> pick(1, table.neighbour_count() - 1);
    double worst = 0;  // the largest bound met, against K/16
    for (int trial = 0; trial < (g == 128 ? 40 : 200); ++trial) {
      const auto a = group::TranslationId(pick(rng)), b = group::TranslationId(pick(rng));
      double p1, p2, error;
      R e1, e2;
      group::centre_of(table.moebius(a), false, &p1, &p2, &error);
      exact_centre(p, table.word(a), &e1, &e2);
      ck_assert_msg(within(p1, p2, error, e1, e2), "g=%d: centre of id %d", g, a);
      worst = std::max(worst, error);
      group::centre_of(table.moebius(a), true, &p1, &p2, &error);
      exact_centre(p, p.inverse(table.word(a)), &e1, &e2);
      ck_assert_msg(within(p1, p2, error, e1, e2), "g=%d: centre of id %d^-1", g, a);
      if (g == 128) continue;  // products of two runs: beyond 2660 bits' certain reach
      group::product_centre_of(table.moebius(a), table.moebius(b), &p1, &p2, &error);
      Word w = table.word(a);
      w.insert(w.end(), table.word(b).begin(), table.word(b).end());
      exact_centre(p, w, &e1, &e2);
      ck_assert_msg(within(p1, p2, error, e1, e2), "g=%d: centre of %d * %d", g, a, b);
      worst = std::max(worst, error);
    }
    ck_assert_msg(worst < index.max_error() / 4, "g=%d: bound %g against K/16 = %g", g, worst, index.max_error());
  }
}
END_TEST

START_TEST(side_pairing_maps_paired_sides) {
  // g_k maps side s_j onto s_k, j = k^-1 (the letter of g_k^-1, as the
  // presentation pairs sides): midpoint to midpoint, and the
  // endpoints v_{k+2g-1}, v_{k+2g} to v_k, v_{k-1}.
  using T = exact::mp_real<50>;
  for (int g = 2; g <= 6; ++g) {
    const Presentation p(g);
    const group::GeneratorSet<T> gens(p);
    for (int k = 0; k < p.letter_count(); ++k) {
      const int j = p.inverse(k);
      ck_assert_int_eq(j, (k + 2 * g) % (4 * g));
      auto gap = [&](group::Complex<T> from, group::Complex<T> to) {
        const auto image = gens.moebius(k).apply(from);
        return T(abs(image.re - to.re) + abs(image.im - to.im));
      };
      ck_assert(gap(surface::polygon_side_midpoint<T>(g, j), surface::polygon_side_midpoint<T>(g, k)) < T("1e-40"));
      ck_assert(gap(surface::polygon_vertex<T>(g, j - 1), surface::polygon_vertex<T>(g, k)) < T("1e-40"));
      ck_assert(gap(surface::polygon_vertex<T>(g, j), surface::polygon_vertex<T>(g, k - 1)) < T("1e-40"));
    }
  }
}
END_TEST

START_TEST(systole_formula_in_mpfr) {
  using T = exact::mp_real<50>;
  // g = 2: 2 arccosh(1 + sqrt 2).
  const T expected = T(2) * acosh(T(1) + sqrt(T(2)));
  ck_assert(abs(surface::systole<T>(2) - expected) < T("1e-45"));
  ck_assert(std::isnan(surface::systole_or_nan(1)));
}
END_TEST

START_TEST(unit_disk_test_is_exact) {
  ck_assert(exact::inside_unit_disk(0.0, 0.0));
  ck_assert(exact::inside_unit_disk(std::nextafter(1.0, 0.0), 0.0));
  ck_assert(!exact::inside_unit_disk(1.0, 0.0));
  ck_assert(!exact::inside_unit_disk(0.0, -1.0));
  // 0.6 and 0.8 are not exact in binary: as doubles, 0.6^2 + 0.8^2 exceeds 1
  // by 4.4e-17, which the floating-point sum (exactly 1.0) cannot see.
  ck_assert(!exact::inside_unit_disk(0.6, 0.8));
  // Reference values from exact rational arithmetic (Python's fractions):
  ck_assert(exact::inside_unit_disk(0.6, std::nextafter(0.8, 0.0)));
  // d = sqrt(0.5) rounded up: 2 d^2 > 1 although d*d + d*d rounds to 1.
  const double d = std::sqrt(0.5);
  ck_assert(!exact::inside_unit_disk(d, d));
  ck_assert(exact::inside_unit_disk(std::nextafter(d, 0.0), d));
}
END_TEST

// The matrices of translations (a cached product of the word shifted to
// start with letter 0, on the rung its error bound along the product
// certifies, then turned) within their stated bounds of a direct
// letter-by-letter product at 2126 bits: for the Lorentz matrices in 133-bit
// MPFR 2^-d |L_ij| + 2^-(d + 4) L_00, in double 2^-53 |L_ij| + 2^-66 L_00.
// Every element of N at small genus, random words (not runs) too, and at
// genus 128 the relator runs of 2g letters, which used to take the top rung
// (the direct product of 256 letters loses at most 2138 bits of 8503).
double worst_split_error = 0;  // the largest moebius_error met, printed

template <class R>
void check_translation_matrices(const Presentation &p, const Word &w) {
  using Mid = exact::mp_real<40>;
  const group::GeneratorSet<R> &set = group::shared_generators<R>(p);
  const group::Lorentz<R> L = group::Lorentz<R>::from_moebius(set.moebius(w));
  const group::Lorentz<Mid> M = group::accurate_lorentz_as<Mid>(p, w);
  group::Moebius<double> md, low;
  group::Lorentz<double> ld;
  double split_error = 1;
  group::accurate_matrices(p, w, &md, &ld, &low, &split_error);
  const int d = std::numeric_limits<Mid>::digits;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) {
      const R exact = L.m[i][j], size = abs(exact), big = L.m[0][0];
      ck_assert_msg(abs(R(M.m[i][j]) - exact) <= ldexp(size, -d) + ldexp(big, -d - 4) + ldexp(big, -2 * d),"g=%d MPFR, length %zu",
                    p.genus(), w.size());
      ck_assert_msg(abs(R(ld.m[i][j]) - exact) <= ldexp(size, -53) + ldexp(big, -66) + ldexp(big, -118),"g=%d double, length %zu",
                    p.genus(), w.size());
    }
  const group::Moebius<R> m = set.moebius(w);
  const R scale = sqrt(norm2(m.a)) + sqrt(norm2(m.b));
  const R gap = abs(R(md.a.re) - m.a.re) + abs(R(md.a.im) - m.a.im) + abs(R(md.b.re) - m.b.re) +
                abs(R(md.b.im) - m.b.im);
  ck_assert_msg(gap <= ldexp(scale, -51), "g=%d Moebius, length %zu", p.genus(), w.size());
  // The split form: each part within split_error (|a| + |b|) + 2^-106 |.|.
  ck_assert_double_le(split_error, 0x1p-72);
  const std::array<std::array<double, 2>, 4> parts = {
      {{md.a.re, low.a.re}, {md.a.im, low.a.im}, {md.b.re, low.b.re}, {md.b.im, low.b.im}}};
  const std::array<R, 4> exact_parts = {m.a.re, m.a.im, m.b.re, m.b.im};
  for (int i = 0; i < 4; ++i) {
    const R off = abs(R(parts[i][0]) + R(parts[i][1]) - exact_parts[i]);
    ck_assert_msg(off <= R(split_error) * scale + ldexp(abs(exact_parts[i]), -106) * R(1.0001),
                  "g=%d split Moebius, length %zu", p.genus(), w.size());
  }
  worst_split_error = std::max(worst_split_error, split_error);
}

START_TEST(translation_matrices_match_direct_products) {
  std::mt19937 rng(16);
  for (int g : {2, 3, 5, 32}) {
    const Presentation p(g);
    std::vector<Word> words;
    if (g < 32) words = group::neighbour_words(p);
    for (int i = 0; i < 200; ++i) words.push_back(random_word(rng, p.letter_count(), 2 * g));
    for (const Word &w : words) check_translation_matrices<exact::mp_real<640>>(p, w);
  }
  const Presentation p(128);
  const int n = p.letter_count();
  for (int first : {0, 1, 77, 255, 300, 511})
    for (int step : {p.relator_step(), p.inverse_relator_step()}) {
      Word run(std::size_t(p.half_relator()));
      for (std::size_t i = 0; i < run.size(); ++i) run[i] = Letter((first + int(i) * step) % n);
      check_translation_matrices<exact::mp_real<2560>>(p, run);
    }
  std::printf("translation matrices: largest split Moebius error bound 2^%.1f (|a| + |b|)\n",
              std::log2(worst_split_error));
}
END_TEST

// An element of N at length 2g spelled the long way round (the inverse of
// the rest of its relator) is found without canonicalising: the same id.
START_TEST(half_relators_spelled_the_other_way_are_found) {
  for (int g : {2, 3, 7}) {
    const Presentation p(g);
    group::TranslationTable table(p);
    const int n = p.letter_count();
    for (std::size_t id = table.neighbour_count() - std::size_t(n); id < table.neighbour_count(); ++id) {
      const Word &w = group::neighbour_word(p, id);
      ck_assert_uint_eq(w.size(), std::size_t(2 * g));
      const int step = (w[1] - w[0] + n) % n;
      Word other(w.size());
      for (std::size_t j = 1; j <= w.size(); ++j) other[w.size() - j] = p.inverse(Letter((w.back() + int(j) * step) % n));
      ck_assert(other != w);
      ck_assert_int_eq(table.intern(other), group::TranslationId(id));
      ck_assert(group::canonical_word(p, other) == w);  // the independent way
    }
  }
}
END_TEST

// A non-zero element of tiny absolute value needs more precision than a
// fixed top rung: cos(2 pi / n) minus its dyadic approximation to `chunks`
// times 53 bits, both as exact field elements. The sign is that of the
// residual computed independently with MPFR at 60 (chunks + 20) bits.
// 180 chunks (9,500 bits) threw before the 34k- and 136k-bit rungs; 3,000
// (159,000 bits) threw before the run-time precision past them.
static void check_tiny_residual(int chunks) {
  const exact::Field &F = exact::field_of_genus(2);
  const exact::CyclotomicField &K = F.cyclotomic();
  mpfr_t c, d;
  mpfr_inits2(mpfr_prec_t(60 * (chunks + 20)), c, d, (mpfr_ptr)0);  // a chunk takes up to 55 bits
  mpfr_const_pi(c, MPFR_RNDN);
  mpfr_mul_ui(c, c, 2, MPFR_RNDN);
  mpfr_div_ui(c, c, (unsigned long)K.order(), MPFR_RNDN);
  mpfr_cos(c, c, MPFR_RNDN);  // the residual stays far above its error
  exact::Cyclotomic approximation = K.zero();
  for (int chunk = 0; chunk < chunks; ++chunk) {
    long e = 0;  // c = part 2^e: scaled, so that no chunk underflows a double
    const double part = mpfr_get_d_2exp(&e, c, MPFR_RNDN);
    approximation = K.add(approximation, K.mul_2exp(K.from_double(part), int(e)));
    mpfr_set_d(d, part, MPFR_RNDN);
    mpfr_mul_2si(d, d, e, MPFR_RNDN);
    mpfr_sub(c, c, d, MPFR_RNDN);  // exact: the leading bits cancel
  }
  const int expected = mpfr_sgn(c);
  ck_assert_msg(expected != 0 && mpfr_get_exp(c) < -50 * chunks, "residual exponent %ld", (long)mpfr_get_exp(c));
  const exact::FieldElement residual = F.from_cyclotomic(K.sub(K.cos_2pi(1), approximation));
  ck_assert_int_eq(exact::to_int(F.sign(residual)), expected);
  ck_assert_int_eq(exact::to_int(F.sign(F.neg(residual))), -expected);
  mpfr_clears(c, d, (mpfr_ptr)0);
}

START_TEST(sign_of_a_tiny_nonzero_element) { check_tiny_residual(180); }
END_TEST

START_TEST(sign_past_every_fixed_rung) { check_tiny_residual(3000); }
END_TEST

int main(void) {
  return run_suite("core", 300, [](TCase *tc) {
    tcase_add_test(tc, folded_generator_sets_match_the_formula);
    tcase_add_test(tc, relation_is_identity_in_mpfr);
    tcase_add_test(tc, cyclotomic_powers_and_sines_are_exact);
    tcase_add_test(tc, relation_is_exact_in_the_field);
    tcase_add_test(tc, relation_in_plain_double_within_its_error_bound);
    tcase_add_test(tc, lorentz_matches_moebius);
    tcase_add_test(tc, dehn_output_is_reduced_and_equal);
    tcase_add_test(tc, dehn_is_not_geodesic_but_canonical_is);
    tcase_add_test(tc, neighbour_ids_are_fixed_and_tables_agree);
    tcase_add_test(tc, neighbour_closed_forms_match_enumeration);
    tcase_add_test(tc, products_named_by_centre_are_canonical);
    tcase_add_test(tc, table_matrices_match_word_products);
    tcase_add_test(tc, moebius_centres_within_their_bounds);
    tcase_add_test(tc, side_pairing_maps_paired_sides);
    tcase_add_test(tc, systole_formula_in_mpfr);
    tcase_add_test(tc, unit_disk_test_is_exact);
    tcase_add_test(tc, translation_matrices_match_direct_products);
    tcase_add_test(tc, half_relators_spelled_the_other_way_are_found);
    tcase_add_test(tc, sign_of_a_tiny_nonzero_element);
    tcase_add_test(tc, sign_past_every_fixed_rung);
  });
}
