// The neighbour set N of a fundamental polygon P: the group elements h with
// h(P) meeting P, the identity included, each with a word in the pairings.
//
// Why the vertex walks find all of them. The pairings satisfy the hypotheses
// of Poincare's polygon theorem (FundamentalPolygon checks them: convexity,
// paired sides of equal length, each vertex cycle's angles summing to 2 pi
// with the pairings composing to the identity), so the copies h(P) tile the
// disk edge to edge, with no overlap and h(P) = P only for h = 1. Two convex
// tiles of such a tiling meet in a common side, a common vertex or not at
// all; a tile sharing a side with P also shares that side's two vertices.
// So N is the set of tiles around the vertices of P.
//
// The tiles around v_k, in order. The tile across side k is g_k(P); g_k sends
// v_{j+1} (j = paired(k)) to v_k, so its corner at v_k is the image of
// P's corner v_{j+1}, between the images of sides j (shared with P) and
// j + 1. The next tile is across that image of side j + 1: g_k g_{j+1}(P),
// and so on along the vertex cycle v -> paired(v) + 1, until the walk is back
// at side k, the product around the cycle being the identity (P again).
#pragma once

#include <vector>

#include "domain/fundamental_polygon.hpp"
#include "domain/word.hpp"

namespace hdt::domain {

// The tiles around v_k: the prefix products of the walk, the last one P.
std::vector<Word> tiles_around_vertex(const FundamentalPolygon &P, int k);

// N, each element once (exact Element equality), the identity first.
std::vector<Word> neighbours(const FundamentalPolygon &P);

}  // namespace hdt::domain
