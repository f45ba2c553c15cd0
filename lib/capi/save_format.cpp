// The saved-triangulation format, versions 1 (M_g) and 2 (a surface given
// by a polygon). Layout (all integers little-endian, doubles as their
// IEEE-754 bits; docs/format.md):
//
//   offset  size  field
//        0     8  magic 89 'H' 'D' 'T' 0D 0A 1A 0A
//        8     4  format version (1: M_g, 2: a polygon surface)
//       12     4  genus
//       16     4  W, the translation words beyond N
//       20     4  V, the vertex ids (live and removed)
//       24     4  F, the faces
//       28     4  the face the next walk starts from
//       32     4  the vertex last touched (FFFFFFFF: none)
//       36     8  the walk's random state
//       44        version 2 only: u32 T, then the polygon's text, T bytes
//                 W words: u16 length, then u16 letters (version 1: the
//                   canonical words of the ids from |N| on; version 2: the
//                   words in the pairings of ids 1 .. W)
//                 V vertices, 25 bytes: f64 x, f64 y, i32 home, u32 face
//                   (FFFFFFFF: removed), u8 flags (bit 0: dummy)
//                 F faces, 48 bytes: u32 v[3], i32 t[3], u32 n[3], i32 nt[3]
//      end-4     4  CRC-32 (ISO-HDLC, as zlib's crc32) of every byte before it
#include "capi/save_format.hpp"

#include <cstdint>
#include <cstdio>
#include <cstring>
#include <string>
#include <utility>
#include <vector>

#if defined(__linux__)
#include <sys/mman.h>
#endif

#include <zlib.h>

#include "capi/guard.hpp"
#include "capi/handle.hpp"
#include "domain/field_lock.hpp"
#include "domain/fundamental_polygon.hpp"
#include "domain/polygon_text.hpp"
#include "group/canonical.hpp"

namespace hdt::capi {

namespace {

using mesh::Face;
using mesh::kNone;
using mesh::Snapshot;
using mesh::SnapshotError;
using mesh::Triangulation;
using mesh::Vertex;

constexpr unsigned char kMagic[8] = {0x89, 'H', 'D', 'T', 0x0D, 0x0A, 0x1A, 0x0A};
constexpr uint32_t kVersion = 1, kPolygonVersion = 2;
constexpr std::size_t kHeader = 44, kVertexBytes = 25, kFaceBytes = 48, kChecksum = 4;

// CRC-32 (ISO-HDLC: reflected, polynomial 0xEDB88320) of n bytes: zlib's
// crc32, which is that CRC, in its size_t form (crc32_z, zlib >= 1.2.9) so
// that a file past 4 GiB needs no loop here. tests/test_save.c checks it
// against a bit-by-bit CRC of its own.
uint32_t checksum(const unsigned char *p, std::size_t n) { return uint32_t(crc32_z(0, p, n)); }

class Writer {
 public:
  explicit Writer(unsigned char *out) : p_(out) {}
  void bytes(const void *b, std::size_t n) { std::memcpy(p_, b, n), p_ += n; }
  void u8(uint8_t v) { *p_++ = v; }
  void u16(uint16_t v) { u8(uint8_t(v)), u8(uint8_t(v >> 8)); }
  void u32(uint32_t v) {
    for (int i = 0; i < 4; ++i) u8(uint8_t(v >> 8 * i));
  }
  void u64(uint64_t v) {
    for (int i = 0; i < 8; ++i) u8(uint8_t(v >> 8 * i));
  }
  void f64(double d) {
    uint64_t v;
    std::memcpy(&v, &d, 8);
    u64(v);
  }
  unsigned char *at() const { return p_; }

 private:
  unsigned char *p_;
};

// Asks for transparent huge pages (2 MB) under the records' storage before
// it is first written, where the system has them (Linux with THP in
// "madvise" mode, as here). The 120 MB of a 10^6-vertex file's records are
// fresh memory: in 4 KB pages their first touch takes a page fault per
// 4 KB, a large part of a load (docs/format.md), and
// validate() reads them in random order, where 2 MB pages spare most TLB
// misses. Only a hint: nothing changes where it is refused or unknown.
void advise_huge_pages(const void *p, std::size_t bytes) {
#if defined(__linux__) && defined(MADV_HUGEPAGE)
  constexpr std::uintptr_t huge = std::uintptr_t(1) << 21;
  const std::uintptr_t begin = (reinterpret_cast<std::uintptr_t>(p) + huge - 1) & ~(huge - 1);
  const std::uintptr_t end = (reinterpret_cast<std::uintptr_t>(p) + bytes) & ~(huge - 1);
  if (end > begin) madvise(reinterpret_cast<void *>(begin), end - begin, MADV_HUGEPAGE);
#else
  (void)p, (void)bytes;
#endif
}

[[noreturn]] void bad(std::size_t offset, const std::string &what) {
  throw ApiError(HDT_EINVAL, "byte " + std::to_string(offset) + ": " + what);
}

// Reads within [begin, end); every read is bounds-checked and names its offset.
class Reader {
 public:
  Reader(const unsigned char *b, std::size_t size) : b_(b), size_(size) {}
  std::size_t offset() const { return at_; }
  std::size_t left() const { return size_ - at_; }
  void need(std::size_t n, const char *what) const {
    if (n > left())
      bad(at_, std::string("the file ends inside ") + what + " (" + std::to_string(left()) + " bytes left, " +
                   std::to_string(n) + " needed): it is truncated");
  }
  uint8_t u8() { return b_[at_++]; }
  uint16_t u16() {
    const uint16_t v = uint16_t(b_[at_] | b_[at_ + 1] << 8);
    at_ += 2;
    return v;
  }
  // Spelled out byte by byte: GCC and Clang make one load of it on a
  // little-endian machine (the loop they did not; reading was a tenth of a
  // load).
  uint32_t u32() {
    const unsigned char *b = b_ + at_;
    at_ += 4;
    return uint32_t(b[0]) | uint32_t(b[1]) << 8 | uint32_t(b[2]) << 16 | uint32_t(b[3]) << 24;
  }
  uint64_t u64() {
    const uint64_t lo = u32();
    return lo | uint64_t(u32()) << 32;
  }
  double f64() {
    const uint64_t v = u64();
    double d;
    std::memcpy(&d, &v, 8);
    return d;
  }

 private:
  const unsigned char *b_;
  std::size_t size_, at_ = 0;
};

// Where the item a SnapshotError names is stored.
std::size_t offset_of(const SnapshotError &e, const std::vector<std::size_t> &word_at, std::size_t words_at,
                      std::size_t vertices_at, std::size_t faces_at, const std::string &what) {
  switch (e.part) {
    case SnapshotError::kGenus: return 12;
    case SnapshotError::kCounts: return 24;
    case SnapshotError::kWord: return e.index < word_at.size() ? word_at[e.index] : words_at;
    case SnapshotError::kVertex: return vertices_at + kVertexBytes * e.index;
    case SnapshotError::kFace: return faces_at + kFaceBytes * e.index;
    case SnapshotError::kState: return 28;
    case SnapshotError::kStructure: break;
  }
  // validate()'s messages name the first broken face or vertex.
  for (const char *name : {"face ", "vertex "}) {
    const std::size_t k = what.find(std::string(": ") + name);
    if (k == std::string::npos) continue;
    const std::size_t digits = k + 2 + std::strlen(name);
    std::size_t i = digits;
    unsigned long long n = 0;
    while (i < what.size() && what[i] >= '0' && what[i] <= '9' && n < (1ull << 40)) n = 10 * n + unsigned(what[i++] - '0');
    if (i == digits) continue;
    return name[0] == 'f' ? faces_at + kFaceBytes * n : vertices_at + kVertexBytes * n;
  }
  return faces_at;
}

}  // namespace

std::size_t saved_size(const Triangulation &t) {
  const group::TranslationTable &T = t.table();
  std::size_t n = kHeader + kChecksum;
  for (std::size_t id = T.neighbour_count(); id < T.size(); ++id) {
    const std::size_t letters = T.word(group::TranslationId(id)).size();
    // Never write a file that hdt_load would refuse.
    if (letters > mesh::max_saved_word_length(t.genus()))
      throw ApiError(HDT_ENOTSUP, "translation id " + std::to_string(id) + " has a word of " + std::to_string(letters) +
                                      " letters, more than the format holds (" +
                                      std::to_string(mesh::max_saved_word_length(t.genus())) + ")");
    // Nor a word whose check the loader leaves open (group::check_canonical:
    // its element far beyond every element a point of the disk gives).
    if (group::check_canonical(T.presentation(), T.word(group::TranslationId(id)).data(), letters) !=
        group::CanonicalCheck::kCanonical)
      throw ApiError(HDT_ENOTSUP, "translation id " + std::to_string(id) +
                                      "'s element lies too far from O for the format to certify its word");
    n += 2 + 2 * letters;
  }
  return n + kVertexBytes * t.vertices().size() + kFaceBytes * t.faces().size();
}

namespace {

// Whether two polygon texts are equal but for the ball MID+/-RAD of a
// field line (its fourth token).
bool same_but_the_ball(const std::string &a, const std::string &b) {
  const auto tail = [](const std::string &t) {
    const std::size_t line = t.find('\n'), ball = t.rfind(' ', line);
    return t.compare(0, 6, "field ") == 0 && line != std::string::npos && ball != std::string::npos
               ? std::make_pair(t.substr(0, ball), t.substr(line))
               : std::make_pair(std::string(), t);
  };
  return tail(a) == tail(b);
}

// The polygon's text as version 2 stores it: what hdt_surface_polygon_text
// gives, which reads back as the same surface.
std::string polygon_text_of(const mesh::PolygonTriangulation &t) {
  return domain::polygon_text(t.surface().polygon().text());
}

// The file of snapshot s: version 1, or 2 with the polygon's text.
void write_file(const Snapshot &s, uint32_t version, const std::string *text, unsigned char *out) {
  Writer w(out);
  w.bytes(kMagic, 8);
  w.u32(version);
  w.u32(uint32_t(s.genus));
  w.u32(uint32_t(s.extra_words.size()));
  w.u32(uint32_t(s.vertices.size()));
  w.u32(uint32_t(s.faces.size()));
  w.u32(s.last_face);
  w.u32(s.last_vertex);
  w.u64(s.rng);
  if (text) {
    w.u32(uint32_t(text->size()));
    w.bytes(text->data(), text->size());
  }
  for (const group::Word &word : s.extra_words) {
    w.u16(uint16_t(word.size()));
    for (group::Letter l : word) w.u16(uint16_t(l));
  }
  for (std::size_t v = 0; v < s.vertices.size(); ++v) {
    const Vertex &u = s.vertices[v];
    w.f64(u.x), w.f64(u.y), w.u32(uint32_t(u.home)), w.u32(u.face), w.u8(s.dummy[v] ? 1 : 0);
  }
  for (const Face &f : s.faces) {
    for (int i = 0; i < 3; ++i) w.u32(f.v[i]);
    for (int i = 0; i < 3; ++i) w.u32(uint32_t(f.t[i]));
    for (int i = 0; i < 3; ++i) w.u32(f.n[i]);
    for (int i = 0; i < 3; ++i) w.u32(uint32_t(f.nt[i]));
  }
  w.u32(checksum(out, std::size_t(w.at() - out)));
}

}  // namespace

void write_saved(const Triangulation &t, unsigned char *out) { write_file(t.snapshot(), kVersion, nullptr, out); }

std::size_t saved_size(const mesh::PolygonTriangulation &t) {
  std::size_t n = kHeader + 4 + polygon_text_of(t).size() + kChecksum;
  for (std::size_t id = 1; id < t.table().size(); ++id) {
    const std::size_t letters = t.surface().word(domain::ElementId(id)).size();
    if (letters > mesh::max_saved_word_length(t.genus()))
      throw ApiError(HDT_ENOTSUP, "translation id " + std::to_string(id) + " has a word of " + std::to_string(letters) +
                                      " letters, more than the format holds (" +
                                      std::to_string(mesh::max_saved_word_length(t.genus())) + ")");
    n += 2 + 2 * letters;
  }
  return n + kVertexBytes * t.vertices().size() + kFaceBytes * t.faces().size();
}

void write_saved(const mesh::PolygonTriangulation &t, unsigned char *out) {
  const std::string text = polygon_text_of(t);
  write_file(t.snapshot(), kPolygonVersion, &text, out);
}

std::unique_ptr<hdt_triangulation> read_saved(const unsigned char *bytes, std::size_t size) {
  if (size < kHeader + kChecksum)
    bad(size, "the file is " + std::to_string(size) + " bytes, shorter than the " + std::to_string(kHeader + kChecksum) +
                  " of a header and checksum: it is truncated or not a saved triangulation");
  if (std::memcmp(bytes, kMagic, 8) != 0) bad(0, "not a saved libhdt triangulation (the first 8 bytes are not its signature)");
  Reader r(bytes, size - kChecksum);
  r.u64();
  const uint32_t version = r.u32();
  if (version != kVersion && version != kPolygonVersion)
    bad(8, "format version " + std::to_string(version) + "; this libhdt reads versions 1 (M_g) and 2 (a surface "
           "given by a polygon)");
  const bool polygon = version == kPolygonVersion;
  const uint32_t genus = r.u32();
  // Only a genus hdt_create accepts can have been saved (a polygon's is
  // checked against its text below).
  if (genus < 2 || (!polygon && genus > HDT_CREATE_GENUS_MAX))
    bad(12, "genus " + std::to_string(genus) + " is not in 2.." + std::to_string(HDT_CREATE_GENUS_MAX));
  const uint32_t W = r.u32(), V = r.u32(), F = r.u32();
  Snapshot s;
  s.genus = int(genus);
  s.last_face = r.u32();
  s.last_vertex = r.u32();
  s.rng = r.u64();
  // Every count is bounded by the bytes it needs before anything is
  // allocated: a hostile header cannot ask for more memory than the file's
  // size justifies.
  uint32_t T = 0;  // the polygon's text, version 2
  if (polygon) {
    r.need(4, "the polygon's length");
    T = r.u32();
  }
  const uint64_t least = uint64_t(kHeader) + (polygon ? 4 + uint64_t(T) : 0) + 2 * uint64_t(W) +
                         kVertexBytes * uint64_t(V) + kFaceBytes * uint64_t(F) + kChecksum;
  if (least > size)
    bad(16, "the header's counts (" + std::to_string(W) + " words, " + std::to_string(V) + " vertices, " + std::to_string(F) +
                " faces) need at least " + std::to_string(least) + " bytes; the file has " + std::to_string(size) +
                ": it is truncated or corrupted");
  const uint32_t stored = uint32_t(bytes[size - 4]) | uint32_t(bytes[size - 3]) << 8 | uint32_t(bytes[size - 2]) << 16 |
                          uint32_t(bytes[size - 1]) << 24;
  const uint32_t computed = checksum(bytes, size - kChecksum);
  if (stored != computed) {
    char text[160];
    std::snprintf(text, sizeof text,
                  "the checksum is %08x, the bytes before it give %08x: the file is corrupted or truncated", stored,
                  computed);
    bad(size - kChecksum, text);
  }

  // Version 2: the polygon, read and checked exactly as
  // hdt_surface_from_polygon does (its messages name the token at fault).
  std::unique_ptr<domain::FundamentalPolygon> P;
  std::unique_ptr<domain::FieldLock> lock;
  if (polygon) {
    const std::string text(reinterpret_cast<const char *>(bytes) + r.offset(), T);
    const std::size_t text_at = r.offset();
    for (uint32_t k = 0; k < T; ++k) r.u8();
    lock = std::make_unique<domain::FieldLock>(domain::names_field(text));
    try {
      P = std::make_unique<domain::FundamentalPolygon>(domain::parse_polygon_text(text));
    } catch (const std::bad_alloc &) {
      throw;
    } catch (const std::exception &e) {  // the checks' ParseError above all
      bad(text_at, std::string("the polygon: ") + e.what());
    }
    // Only the form hdt_save writes: saving the loaded triangulation must
    // give the same bytes (an equal polygon written otherwise would not),
    // but for the field line's ball, which e-antic narrows as it refines
    // the embedding it shares.
    if (!same_but_the_ball(domain::polygon_text(P->text()), text))
      bad(text_at, "the polygon's text is not in the form hdt_save writes (hdt_surface_polygon_text's)");
    if (P->genus() != int(genus))
      bad(12, "genus " + std::to_string(genus) + ", but the polygon's surface has genus " + std::to_string(P->genus()));
  }
  const std::size_t words_at = r.offset();
  std::vector<std::size_t> word_at;
  word_at.reserve(W);
  s.extra_words.resize(W);
  for (uint32_t i = 0; i < W; ++i) {
    word_at.push_back(r.offset());
    r.need(2, "a word's length");
    const uint16_t n = r.u16();
    r.need(2 * std::size_t(n), "a word");
    group::Word &word = s.extra_words[i];
    word.resize(n);
    for (uint16_t k = 0; k < n; ++k) word[k] = r.u16();
  }
  const std::size_t vertices_at = r.offset();
  r.need(kVertexBytes * std::size_t(V), "the vertices");
  // Reserved and appended, not resized: resize() zeroed the 120 MB of a
  // 10^6-vertex file's records first, a second pass over fresh pages.
  s.vertices.reserve(V);
  advise_huge_pages(s.vertices.data(), V * sizeof(Vertex));
  s.dummy.resize(V);
  for (uint32_t v = 0; v < V; ++v) {
    Vertex u;
    u.x = r.f64(), u.y = r.f64();
    u.home = int32_t(r.u32());
    u.face = r.u32();
    const uint8_t flags = r.u8();
    if (flags > 1) bad(r.offset() - 1, "vertex " + std::to_string(v) + " has unknown flags " + std::to_string(flags));
    s.vertices.push_back(u);
    s.dummy[v] = flags == 1;
  }
  const std::size_t faces_at = r.offset();
  r.need(kFaceBytes * std::size_t(F), "the faces");
  s.faces.reserve(F);
  advise_huge_pages(s.faces.data(), F * sizeof(Face));
  for (uint32_t k = 0; k < F; ++k) {
    Face f;
    for (int i = 0; i < 3; ++i) f.v[i] = r.u32();
    for (int i = 0; i < 3; ++i) f.t[i] = int32_t(r.u32());
    for (int i = 0; i < 3; ++i) f.n[i] = r.u32();
    for (int i = 0; i < 3; ++i) f.nt[i] = int32_t(r.u32());
    s.faces.push_back(f);
  }
  if (r.left() != 0) bad(r.offset(), std::to_string(r.left()) + " bytes after the last face, before the checksum");
  try {
    if (!polygon) return std::make_unique<hdt_triangulation>(Triangulation::restore(std::move(s)));
    const bool in_field = bool(P->field());
    return std::make_unique<hdt_triangulation>(
        mesh::PolygonTriangulation::restore([&] { return std::make_unique<mesh::PolygonGeometry>(*P); }, std::move(s)),
        in_field);
  } catch (const SnapshotError &e) {
    bad(offset_of(e, word_at, words_at, vertices_at, faces_at, e.what()), e.what());
  }
}

}  // namespace hdt::capi
