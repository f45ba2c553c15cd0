// The abelianisation of translations: the class [gamma] in Z^{2g} of a
// translation id (hyperbolic band theory twists sections by characters of
// Gamma_g, which factor through it: bindings/python/hdt/fem.py).
#include <cstdint>
#include <limits>
#include <string>
#include <vector>

#include "capi/guard.hpp"
#include "capi/handle.hpp"
#include "dual/constructions.hpp"
#include "hdt.h"
#include "mesh/polygon_triangulation.hpp"
#include "mesh/triangulation.hpp"

using hdt::capi::ApiError;
using hdt::capi::guarded;

extern "C" {

HDT_API hdt_status hdt_translation_homology(const hdt_triangulation *t, int32_t id, int32_t *out, size_t capacity,
                                            size_t *count) HDT_NOEXCEPT {
  return guarded("hdt_translation_homology", [&] {
    return hdt::capi::visit(t, [&](const auto &tri) {
      if (!count) throw ApiError(HDT_EINVAL, "count must not be NULL");
      if (id < 0 || std::size_t(id) >= tri.table().size())
        throw ApiError(HDT_EINVAL, "unknown translation id " + std::to_string(id));
      const int g = tri.genus();
      const std::size_t n = 2 * std::size_t(g);
      if (capacity > 0 && !out) throw ApiError(HDT_EINVAL, "out is NULL but capacity is " + std::to_string(capacity));
      if (!hdt::capi::list_fits(n, capacity, count, "homology coordinates (2g)")) return HDT_OK;
      std::vector<int64_t> sum(n, 0);
      if constexpr (hdt::dual::kMg<std::decay_t<decltype(tri)>>) {
        // Letter k < 2g is g_k: +1 on coordinate k; letter k + 2g is g_k^-1:
        // -1 there. The relator prod_j g_{j(2g+1) mod 4g} holds each g_k
        // once and each g_k^-1 once (2g+1 is odd and prime to 4g), so it
        // counts 0: the count is a homomorphism on Gamma_g, the same for
        // every word of the element (tests/test_homology.c).
        for (const int32_t letter : tri.table().word(id)) {
          if (letter < g * 2)
            ++sum[std::size_t(letter)];
          else
            --sum[std::size_t(letter - 2 * g)];
        }
      } else {
        // A polygon surface: its word in the pairings, through the basis
        // of H_1 from its vertex cycles' relations (domain/homology.hpp).
        sum = tri.surface().homology().of(tri.surface().word(hdt::domain::ElementId(id)));
      }
      for (const int64_t c : sum)
        if (c < std::numeric_limits<int32_t>::min() || c > std::numeric_limits<int32_t>::max())
          throw std::logic_error("hdt_translation_homology: a coordinate beyond int32_t");
      for (std::size_t i = 0; i < n; ++i) out[i] = int32_t(sum[i]);
      return HDT_OK;
    });
  });
}

}  // extern "C"
