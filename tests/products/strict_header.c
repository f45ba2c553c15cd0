/* Compiled (not run) by check_header.sh as strict C99 and as C++17: hdt.h
   must stand alone, survive a second inclusion, and declare usable
   prototypes. */
#include "hdt.h"

typedef char status_values_are_pinned[(HDT_OK == 0 && HDT_EBUFS == -6 && HDT_EINTERNAL == -99) ? 1 : -1];
typedef char limits_are_positive[(HDT_GENUS_MAX >= 2 && HDT_WORD_MAX_LENGTH > 0) ? 1 : -1];

#ifdef __cplusplus
static_assert(noexcept(hdt_systole(2)), "C++ callers see that no function throws");
static_assert(noexcept(hdt_word_reduce(2, nullptr, 0, nullptr, 0, nullptr)), "");
#endif

int strict_header_probe(void);

int strict_header_probe(void) {
  const int32_t word[2] = {0, 5};
  int32_t out[8];
  double x = 0, y = 0, m4[4], m9[9];
  size_t n = 0;
  hdt_status s = HDT_OK;
  s = hdt_polygon_vertex(2, 0, &x, &y);
  s = hdt_polygon_side_midpoint(2, 0, &x, &y);
  s = hdt_word_reduce(2, word, 2, out, 8, &n);
  s = hdt_word_matrix(2, word, 2, m4);
  s = hdt_word_lorentz(2, word, 2, m9);
  s = hdt_word_apply(2, word, 2, x, y, &x, &y);
  s = hdt_neighbour_count(2, &n);
  s = hdt_neighbour_word(2, 1, out, 8, &n);
  return (int)s + (int)hdt_status_string(s)[0] + (int)hdt_last_error_message()[0] + hdt_version() + hdt_abi_version() +
         (int)hdt_version_string()[0] + (hdt_systole(2) > 3.0);
}
