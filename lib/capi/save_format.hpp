// The saved-triangulation format, version 1 (docs/format.md): bytes from a
// triangulation and a checked snapshot from bytes.
#pragma once

#include <cstddef>
#include <cstdint>

#include "mesh/triangulation.hpp"

namespace hdt::capi {

// The size of t's saved form, in bytes.
std::size_t saved_size(const mesh::Triangulation &t);
// Writes t's saved form, saved_size(t) bytes, to out.
void write_saved(const mesh::Triangulation &t, unsigned char *out);
// The triangulation saved in bytes[0 .. size): every field checked, then
// the whole validated (Triangulation::restore). Throws ApiError(HDT_EINVAL)
// with a message that names the byte offset at fault; bad_alloc when
// memory runs out (allocations: a small multiple of size, plus the genus's
// surface, built for any file that passes the checks needing none).
mesh::Triangulation read_saved(const unsigned char *bytes, std::size_t size);

}  // namespace hdt::capi
