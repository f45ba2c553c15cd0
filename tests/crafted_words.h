/* Crafted saved files with extra translation words: a valid file of
   hdt_save with more words appended to its table (ids beyond every id its
   faces and vertices use), the header's count and the checksum rewritten,
   as a hostile file would be. Shared by tests/test_save.c and
   bench/load_bench.c; needs only hdt.h and the C library. */
#ifndef HDT_CRAFTED_WORDS_H
#define HDT_CRAFTED_WORDS_H

#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "hdt.h"

/* Letters of many words, end to end, and where each ends. */
typedef struct crafted_words_t {
  int32_t *letters;
  size_t *ends; /* word i is letters[ends[i - 1] .. ends[i]) (ends[-1] = 0) */
  size_t count, letter_count, capacity, letter_capacity;
} crafted_words_t;

static inline void crafted_words_add(crafted_words_t *w, const int32_t *letters, size_t n) {
  if (w->count == w->capacity) {
    w->capacity = w->capacity ? 2 * w->capacity : 64;
    w->ends = (size_t *)realloc(w->ends, w->capacity * sizeof *w->ends);
  }
  while (w->letter_count + n > w->letter_capacity) {
    w->letter_capacity = w->letter_capacity ? 2 * w->letter_capacity : 4096;
    w->letters = (int32_t *)realloc(w->letters, w->letter_capacity * sizeof *w->letters);
  }
  if (!w->ends || !w->letters) abort();
  memcpy(w->letters + w->letter_count, letters, n * sizeof *letters);
  w->letter_count += n;
  w->ends[w->count++] = w->letter_count;
}

static inline void crafted_words_free(crafted_words_t *w) {
  free(w->letters);
  free(w->ends);
  memset(w, 0, sizeof *w);
}

static inline uint32_t crafted_crc32(const unsigned char *p, size_t n) {
  static uint32_t table[256];
  if (table[1] == 0)
    for (uint32_t b = 0; b < 256; ++b) {
      uint32_t c = b;
      for (int k = 0; k < 8; ++k) c = c & 1 ? 0xEDB88320u ^ (c >> 1) : c >> 1;
      table[b] = c;
    }
  uint32_t c = 0xFFFFFFFFu;
  for (size_t i = 0; i < n; ++i) c = (c >> 8) ^ table[(c ^ p[i]) & 0xFF];
  return c ^ 0xFFFFFFFFu;
}

static inline uint32_t crafted_get32(const unsigned char *p) {
  return (uint32_t)p[0] | (uint32_t)p[1] << 8 | (uint32_t)p[2] << 16 | (uint32_t)p[3] << 24;
}
static inline void crafted_put32(unsigned char *p, uint32_t v) {
  for (int i = 0; i < 4; ++i) p[i] = (unsigned char)(v >> 8 * i);
}

/* The saved file `file` (n bytes) with `extra` appended to its words;
   malloc'ed, *out_n its size. The words are written as given (letters as
   u16), canonical or not: the loader is the one to judge them. */
static inline unsigned char *crafted_file(const unsigned char *file, size_t n, const crafted_words_t *extra,
                                          size_t *out_n) {
  const size_t header = 44;
  size_t at = header;
  const uint32_t words = crafted_get32(file + 16);
  for (uint32_t i = 0; i < words; ++i) at += 2 + 2 * ((size_t)file[at] | (size_t)file[at + 1] << 8);
  const size_t added = 2 * extra->count + 2 * extra->letter_count;
  unsigned char *out = (unsigned char *)malloc(n + added);
  if (!out) abort();
  memcpy(out, file, at);
  unsigned char *p = out + at;
  for (size_t i = 0, start = 0; i < extra->count; start = extra->ends[i++]) {
    const size_t len = extra->ends[i] - start;
    *p++ = (unsigned char)len, *p++ = (unsigned char)(len >> 8);
    for (size_t k = start; k < extra->ends[i]; ++k)
      *p++ = (unsigned char)extra->letters[k], *p++ = (unsigned char)(extra->letters[k] >> 8);
  }
  memcpy(p, file + at, n - at);
  crafted_put32(out + 16, words + (uint32_t)extra->count);
  *out_n = n + added;
  crafted_put32(out + *out_n - 4, crafted_crc32(out, *out_n - 4));
  return out;
}

/* splitmix64, for the words' letters. */
static inline uint64_t crafted_next(uint64_t *s) {
  uint64_t z = (*s += 0x9E3779B97F4A7C15ull);
  z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
  z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
  return z ^ (z >> 31);
}

static inline int crafted_same(const crafted_words_t *w, size_t i, const int32_t *a, size_t n) {
  const size_t start = i ? w->ends[i - 1] : 0;
  return w->ends[i] - start == n && memcmp(w->letters + start, a, n * sizeof *a) == 0;
}

/* Whether w is a run of letters with a constant step 2g +- 1 (mod 4g): a
   subword of the relator or its inverse. N's words are such runs (its
   tiles are those around F_g's corners, reached across consecutive sides
   of a corner); a word of two letters or more that is not one is outside N. */
static inline int crafted_is_run(int genus, const int32_t *w, size_t n) {
  if (n < 2) return 1;
  const int32_t m = 4 * genus, step = ((w[1] - w[0]) % m + m) % m;
  if (step != 2 * genus + 1 && step != 2 * genus - 1) return 0;
  for (size_t i = 2; i < n; ++i)
    if (((w[i] - w[i - 1]) % m + m) % m != step) return 0;
  return 1;
}

/* `count` distinct canonical words (hdt_word_reduce) of elements outside N
   (words that are not runs, crafted_is_run) and of length at most
   max_length: each reduced from a random freely reduced word of `length`
   letters, cut to max_length. The words a hostile file would hold: new,
   canonical, and as long as it likes. 0 when hdt_word_reduce fails. */
static inline int crafted_canonical_words(int genus, size_t count, size_t length, size_t max_length, uint64_t seed,
                                          crafted_words_t *out) {
  const int letters = 4 * genus;
  int32_t *w = (int32_t *)malloc((length + 1) * sizeof *w), *c = (int32_t *)malloc((length + 1) * sizeof *c);
  if (!w || !c) abort();
  uint64_t hash_seed = seed;
  /* Hashes of the words kept, open addressing, to keep them distinct. */
  const size_t slots = 4 * count + 16;
  size_t *slot = (size_t *)calloc(slots, sizeof *slot); /* index + 1; 0 empty */
  if (!slot) abort();
  int ok = 1;
  for (size_t tries = 0; out->count < count && tries < 20 * count + 100; ++tries) {
    for (size_t i = 0; i < length; ++i) {
      int32_t k;
      do k = (int32_t)(crafted_next(&hash_seed) % (uint64_t)letters);
      while (i > 0 && k == (w[i - 1] + 2 * genus) % letters);
      w[i] = k;
    }
    size_t n = 0;
    if (hdt_word_reduce(genus, w, length, c, length, &n) != HDT_OK) {
      ok = 0;
      break;
    }
    if (n > max_length) n = max_length; /* a prefix of a canonical word is canonical */
    if (crafted_is_run(genus, c, n)) continue;
    uint64_t h = 1469598103934665603ull;
    for (size_t i = 0; i < n; ++i) h = (h ^ (uint32_t)c[i]) * 1099511628211ull;
    size_t s = (size_t)(h % slots);
    int repeat = 0;
    for (; slot[s]; s = (s + 1) % slots)
      if (crafted_same(out, slot[s] - 1, c, n)) repeat = 1;
    if (repeat) continue;
    crafted_words_add(out, c, n);
    slot[s] = out->count;
  }
  free(slot);
  free(w);
  free(c);
  return ok && out->count == count;
}

/* g_0^n: canonical (each letter is the least one whose side line separates
   the rest's tile from F_g) and as far from O as n letters go. */
static inline void crafted_power(int genus, size_t n, crafted_words_t *out) {
  (void)genus;
  int32_t *w = (int32_t *)calloc(n ? n : 1, sizeof *w);
  if (!w) abort();
  crafted_words_add(out, w, n);
  free(w);
}

#endif
