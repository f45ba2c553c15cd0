// The saved-triangulation format (docs/format.md): version 1 for M_g's
// triangulations, version 2 for a polygon surface's (the polygon's text
// stored exactly, the translations as words in its pairings); bytes from a
// triangulation and a checked triangulation from bytes.
#pragma once

#include <cstddef>
#include <cstdint>

#include <memory>

#include "hdt.h"
#include "mesh/polygon_triangulation.hpp"
#include "mesh/triangulation.hpp"

namespace hdt::capi {

// The size of t's saved form, in bytes.
std::size_t saved_size(const mesh::Triangulation &t);
std::size_t saved_size(const mesh::PolygonTriangulation &t);
// Writes t's saved form, saved_size(t) bytes, to out.
void write_saved(const mesh::Triangulation &t, unsigned char *out);
void write_saved(const mesh::PolygonTriangulation &t, unsigned char *out);
// The triangulation saved in bytes[0 .. size): every field checked, then
// the whole validated (Triangulation::restore). Throws ApiError(HDT_EINVAL)
// with a message that names the byte offset at fault; bad_alloc when
// memory runs out (allocations: a small multiple of size, plus the genus's
// surface, built for any file that passes the checks needing none).
std::unique_ptr<hdt_triangulation> read_saved(const unsigned char *bytes, std::size_t size);

}  // namespace hdt::capi
