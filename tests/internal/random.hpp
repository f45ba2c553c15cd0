// The internal suites' random numbers: splitmix64 (Steele, Lea, Flood),
// a fixed sequence per seed.
#pragma once

#include <cstdint>

inline uint64_t splitmix(uint64_t *state) {
  uint64_t z = (*state += 0x9e3779b97f4a7c15ULL);
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
  return z ^ (z >> 31);
}

// Uniform in [0, 1), 53 random bits.
inline double uniform01(uint64_t *state) { return double(splitmix(state) >> 11) * 0x1p-53; }
