/* The byte reader of the fuzz targets: a fuzz input is read front to back;
   bytes past its end read as 0 and mark the reader empty, so every input
   decodes to something and a short input ends early. */
#ifndef HDT_FUZZ_READER_H
#define HDT_FUZZ_READER_H

#include <stddef.h>
#include <stdint.h>
#include <string.h>

typedef struct reader {
  const uint8_t *p;
  size_t n;
  int empty; /* a read ran past the end */
} reader;

static inline uint8_t u8(reader *r) {
  if (r->n == 0) {
    r->empty = 1;
    return 0;
  }
  --r->n;
  return *r->p++;
}
static inline uint16_t u16(reader *r) {
  const uint16_t lo = u8(r);
  return (uint16_t)(lo | (u8(r) << 8));
}
static inline uint32_t u32(reader *r) {
  const uint32_t lo = u16(r);
  return lo | ((uint32_t)u16(r) << 16);
}
static inline uint64_t u64(reader *r) {
  const uint64_t lo = u32(r);
  return lo | ((uint64_t)u32(r) << 32);
}
static inline double f64(reader *r) {
  const uint64_t b = u64(r);
  double d;
  memcpy(&d, &b, sizeof d);
  return d;
}

#endif /* HDT_FUZZ_READER_H */
