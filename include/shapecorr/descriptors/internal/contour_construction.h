// Copyright (c) 2026 ShapeCorr contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Internal: the fast contour construction shared by the Spin Contour (chapter 3) and the Geodesic
// Spin Contour (chapter 4). Both sample a row coordinate t that is linear inside every triangle
// (the height along the axis; the geodesic distance) on the lines t = 0, 1, ..., R-1, and take on
// each line the alpha range of every connected piece of the level set (the distance to the axis;
// the average geodesic distance). The union of the ranges per row gives the contour's end points,
// and the closing samples on the column grid complete it (ALGORITHMS.md, chapters 3 and 4).
#ifndef SHAPECORR_DESCRIPTORS_INTERNAL_CONTOUR_CONSTRUCTION_H
#define SHAPECORR_DESCRIPTORS_INTERNAL_CONTOUR_CONSTRUCTION_H

#include <shapecorr/descriptors/Spin_contour.h>
#include <shapecorr/internal/indexed_mesh.h>

#include <Eigen/Core>
#if defined(__SSE2__)
#include <emmintrin.h>
#endif

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <unordered_map>
#include <utility>
#include <vector>

namespace shapecorr {
namespace internal {

/// A face's corners, neighbours (across edge corner k -> k+1; -1 on boundaries and non-manifold
/// edges) and the index of that edge in the neighbour, in one aligned record (the contour walk
/// reads all three for every face it visits).
struct alignas(32) Face_link {
  int v[3];
  int nb[3];
  std::int8_t edge[3];
};

inline std::vector<Face_link> build_face_links(const Triangle_arrays& a) {
  const std::size_t m = a.number_of_faces();
  std::vector<Face_link> links(m);
  for(std::size_t f = 0; f < m; ++f)
    for(std::size_t k = 0; k < 3; ++k) {
      links[f].v[k] = a.F(static_cast<Eigen::Index>(f), static_cast<Eigen::Index>(k));
      links[f].nb[k] = -1;
      links[f].edge[k] = -1;
    }
  std::unordered_map<std::uint64_t, std::pair<int, int>> open_edges; // edge key -> (face, k), or (-2, .) when used 3+ times
  open_edges.reserve(3 * m);
  for(std::size_t f = 0; f < m; ++f)
    for(int k = 0; k < 3; ++k) {
      const std::uint64_t u = static_cast<std::uint32_t>(links[f].v[k]), v = static_cast<std::uint32_t>(links[f].v[(k + 1) % 3]);
      const std::uint64_t key = std::min(u, v) << 32 | std::max(u, v);
      auto it = open_edges.find(key);
      if(it == open_edges.end()) {
        open_edges.emplace(key, std::make_pair(static_cast<int>(f), k));
      } else if(it->second.first >= 0 && links[static_cast<std::size_t>(it->second.first)].nb[it->second.second] < 0) {
        links[static_cast<std::size_t>(it->second.first)].nb[it->second.second] = static_cast<int>(f);
        links[f].nb[k] = it->second.first;
      } else if(it->second.first >= 0) { // a third face on this edge: no neighbours across it at all
        const int f0 = it->second.first, k0 = it->second.second;
        const int f1 = links[static_cast<std::size_t>(f0)].nb[k0];
        links[static_cast<std::size_t>(f0)].nb[k0] = -1;
        if(f1 >= 0)
          for(int& nb : links[static_cast<std::size_t>(f1)].nb)
            if(nb == f0) nb = -1;
        it->second.first = -2;
      }
    }
  for(std::size_t f = 0; f < m; ++f)
    for(int k = 0; k < 3; ++k) {
      const int nb = links[f].nb[k];
      if(nb < 0) continue;
      for(int k2 = 0; k2 < 3; ++k2)
        if(links[static_cast<std::size_t>(nb)].nb[k2] == static_cast<int>(f)) links[f].edge[k] = static_cast<std::int8_t>(k2);
    }
  return links;
}

/// The contour walk's half-edge records: half-edge h = 4 f + k is edge k of face f (corner k to
/// k + 1; slot 3 of each face is unused, so that h >> 2 is the face). A walk crossing face f
/// through its edge k leaves through the next half-edge (corner k + 1 to k + 2) or the previous
/// one (k + 2 to k); the record holds the corner opposite the edge, which decides, and the twins
/// of both candidates in their faces (-1 on a boundary), so that a step reads one record and the
/// opposite corner's vertex record.
struct alignas(16) Half_edge_link {
  std::int32_t opposite;
  std::int32_t next_twin; // the twin of the next half-edge
  std::int32_t twins_xor; // next_twin ^ the twin of the previous half-edge (a step picks one by a mask)
  std::int32_t flips;     // bit 0 (1): the next (previous) twin runs the same way (faces oriented inconsistently)
};

// p when the mask m is all ones, q when it is zero (without a branch: the walk's choices are
// unpredictable).
template <typename T>
inline const T* pick(std::uintptr_t m, const T* p, const T* q) {
  return reinterpret_cast<const T*>((reinterpret_cast<std::uintptr_t>(p) & m) | (reinterpret_cast<std::uintptr_t>(q) & ~m));
}

// The twin of half-edge k of face f in its face (-1 when none) and whether it runs the same way.
inline std::int32_t twin_half_edge(const std::vector<Face_link>& links, std::size_t f, int k, bool& same_way) {
  const int nb = links[f].nb[k];
  same_way = false;
  if(nb < 0 || links[f].edge[k] < 0) return -1;
  const int e = links[f].edge[k];
  same_way = links[static_cast<std::size_t>(nb)].v[e] == links[f].v[k];
  return 4 * nb + e;
}

inline std::vector<Half_edge_link> build_half_edge_links(const std::vector<Face_link>& links) {
  std::vector<Half_edge_link> he(4 * links.size(), Half_edge_link{-1, -1, -1, 0});
  for(std::size_t f = 0; f < links.size(); ++f)
    for(int k = 0; k < 3; ++k) {
      Half_edge_link& h = he[4 * f + static_cast<std::size_t>(k)];
      const int k1 = (k + 1) % 3, k2 = (k + 2) % 3;
      bool same_next, same_prev;
      h.opposite = links[f].v[k2];
      h.next_twin = twin_half_edge(links, f, k1, same_next);
      h.twins_xor = h.next_twin ^ twin_half_edge(links, f, k2, same_prev);
      h.flips = (same_next ? 1 : 0) | (same_prev ? 2 : 0);
    }
  return he;
}

/// Whether the faces make a closed connected 2-manifold of genus 0 (a topological sphere): every
/// edge in exactly two faces, every vertex in at least one face and its faces one fan around it,
/// one component, V - E + F = 2.
inline bool is_topological_sphere(const std::vector<Face_link>& links, std::size_t vertices) {
  const std::size_t m = links.size();
  if(m == 0) return false;
  std::vector<std::uint32_t> incident(vertices, 0u);
  for(const Face_link& f : links)
    for(int k = 0; k < 3; ++k) {
      if(f.nb[k] < 0 || f.edge[k] < 0 || f.v[k] < 0 || static_cast<std::size_t>(f.v[k]) >= vertices) return false;
      ++incident[static_cast<std::size_t>(f.v[k])];
    }
  for(std::uint32_t c : incident)
    if(c == 0) return false;
  // the faces around each vertex, walked from one of them across its edges at the vertex: one
  // cycle through all of them
  std::vector<char> fan_done(vertices, 0);
  for(std::size_t f0 = 0; f0 < m; ++f0)
    for(int k0 = 0; k0 < 3; ++k0) {
      const int v = links[f0].v[k0];
      if(fan_done[static_cast<std::size_t>(v)]) continue;
      fan_done[static_cast<std::size_t>(v)] = 1;
      std::size_t f = f0, count = 0;
      int e = (k0 + 2) % 3; // leave through the edge from corner k0 + 2 to corner k0
      do {
        const int in = links[f].edge[e];
        const std::size_t g = static_cast<std::size_t>(links[f].nb[e]);
        int kg = -1;
        for(int j = 0; j < 3; ++j)
          if(links[g].v[j] == v) kg = j;
        if(kg < 0) return false;
        const int a = (kg + 2) % 3, b = kg; // g's two edges at v: leave through the other one
        e = in == a ? b : (in == b ? a : -1);
        if(e < 0 || ++count > incident[static_cast<std::size_t>(v)]) return false;
        f = g;
      } while(f != f0);
      if(count != incident[static_cast<std::size_t>(v)]) return false;
    }
  // one component (faces joined across edges)
  std::vector<char> seen(m, 0);
  std::vector<std::size_t> stack{0};
  seen[0] = 1;
  std::size_t reached = 1;
  while(!stack.empty()) {
    const std::size_t f = stack.back();
    stack.pop_back();
    for(int k = 0; k < 3; ++k) {
      const std::size_t g = static_cast<std::size_t>(links[f].nb[k]);
      if(!seen[g]) {
        seen[g] = 1;
        ++reached;
        stack.push_back(g);
      }
    }
  }
  if(reached != m || m % 2 != 0) return false;
  const long chi = static_cast<long>(vertices) - static_cast<long>(3 * m / 2) + static_cast<long>(m);
  return chi == 2;
}

/// Every vertex's neighbours with a face on the edge to each: kWidth slots per vertex (padded with
/// the vertex itself), the rest of a larger star in an overflow list.
struct Vertex_stars {
  static constexpr int kWidth = 8;
  std::vector<std::int32_t> nb, face;     // kWidth per vertex
  std::vector<std::uint32_t> more_begin;  // per vertex (and one past): its neighbours beyond kWidth
  std::vector<std::int32_t> more_nb, more_face;
};

inline Vertex_stars build_vertex_stars(const std::vector<Face_link>& links, std::size_t vertices) {
  std::vector<std::vector<std::pair<std::int32_t, std::int32_t>>> star(vertices);
  for(std::size_t f = 0; f < links.size(); ++f)
    for(int k = 0; k < 3; ++k) {
      const int u = links[f].v[k], v = links[f].v[(k + 1) % 3];
      for(const auto& e : {std::make_pair(u, v), std::make_pair(v, u)}) {
        auto& s = star[static_cast<std::size_t>(e.first)];
        if(std::find_if(s.begin(), s.end(), [&](const std::pair<std::int32_t, std::int32_t>& x) { return x.first == e.second; }) == s.end())
          s.emplace_back(e.second, static_cast<std::int32_t>(f));
      }
    }
  Vertex_stars st;
  const std::size_t W = Vertex_stars::kWidth;
  st.nb.resize(W * vertices);
  st.face.assign(W * vertices, 0);
  st.more_begin.assign(vertices + 1, 0u);
  for(std::size_t v = 0; v < vertices; ++v) {
    for(std::size_t k = 0; k < W; ++k) {
      st.nb[W * v + k] = k < star[v].size() ? star[v][k].first : static_cast<std::int32_t>(v);
      if(k < star[v].size()) st.face[W * v + k] = star[v][k].second;
    }
    for(std::size_t k = W; k < star[v].size(); ++k) {
      st.more_nb.push_back(star[v][k].first);
      st.more_face.push_back(star[v][k].second);
    }
    st.more_begin[v + 1] = static_cast<std::uint32_t>(st.more_nb.size());
  }
  return st;
}

// Counting sort of (row, value) pairs by row: out holds the values grouped by row, row r in
// [count[r], count[r + 1]).
template <typename Value>
void group_by_row(const std::pair<std::uint32_t, Value>* in, std::size_t n, std::size_t rows, std::vector<std::uint32_t>& count,
                  std::vector<std::uint32_t>& next, std::vector<Value>& out) {
  // Even and odd entries are counted and placed with separate counters: consecutive entries
  // mostly share a row, and one counter would make every increment wait for the previous one.
  count.assign(2 * rows + 1, 0u);
  std::uint32_t* c0 = count.data() + 1;
  std::uint32_t* c1 = c0 + rows;
  std::size_t i = 0;
  for(; i + 1 < n; i += 2) {
    ++c0[in[i].first];
    ++c1[in[i + 1].first];
  }
  if(i < n) ++c0[in[i].first];
  // row r: the even entries from next[r], the odd ones from next[rows + r]
  next.resize(2 * rows);
  std::uint32_t start = 0;
  for(std::size_t r = 0; r < rows; ++r) {
    const std::uint32_t e = c0[r], o = c1[r];
    next[r] = start;
    next[rows + r] = start + e;
    count[r] = start;
    start += e + o;
  }
  count[rows] = start;
  count.resize(rows + 1);
  out.resize(n);
  std::uint32_t* n0 = next.data();
  std::uint32_t* n1 = n0 + rows;
  for(i = 0; i + 1 < n; i += 2) {
    out[n0[in[i].first]++] = in[i].second;
    out[n1[in[i + 1].first]++] = in[i + 1].second;
  }
  if(i < n) out[n0[in[i].first]++] = in[i].second;
}

/// Scratch space of one thread's contour constructions; `Vertex` is the section policy's
/// per-vertex record (its row coordinate `t` and the data alpha is interpolated from).
template <typename Vertex>
struct Contour_workspace {
  std::vector<Vertex> vx;
  std::vector<std::array<int, 2>> rows;                    // per vertex: floor(t), ceil(t) (clamped to [-1, R])
  std::vector<std::pair<std::uint32_t, std::pair<double, double>>> entries; // (row, alpha interval)
  std::vector<std::pair<std::uint32_t, std::uint32_t>> face_rows; // (row, face) of every face a row line crosses
  std::vector<std::uint32_t> bucket;                       // faces grouped by row
  std::vector<std::uint32_t> stamp;                        // per face, twice (even, odd rows; each after a boundary slot): the row walk that visited it last
  std::uint32_t epoch = 0;
  std::vector<std::uint32_t> stack, stack2; // faces for the general code, of the two rows walked together
  std::vector<std::uint32_t> count, next;
  std::vector<std::pair<double, double>> sorted;           // intervals grouped by row
  std::vector<std::vector<std::pair<double, double>>> merged;
  std::vector<float> row;
  std::vector<std::size_t> row_end;

  void resize(std::size_t vertices) {
    vx.resize(vertices);
    rows.resize(vertices);
  }
  /// Sets the floor/ceil rows of vertex i from its row coordinate t (by integer conversion:
  /// std::floor is a library call without SSE4.1).
  void set_rows(std::size_t i, double t_i, std::size_t R) {
    const double c = std::min(static_cast<double>(R), std::max(-1.0, t_i));
    const int t = static_cast<int>(c);
    const int fl = t - (static_cast<double>(t) > c ? 1 : 0);
    rows[i] = {{fl, fl + (static_cast<double>(fl) < c ? 1 : 0)}};
  }
};

/// x converted to long within [lo, hi]: NaN and values below lo give lo, values above hi give hi
/// (a plain conversion of an infinite or out-of-range double is undefined behaviour).
inline long clamped_to_long(double x, long lo, long hi) {
  if(!(x >= static_cast<double>(lo))) return lo;
  if(!(x <= static_cast<double>(hi))) return hi;
  return static_cast<long>(x);
}

/// The walk's seeds by descent, for a row coordinate t given at the vertices of `ball` ((vertex,
/// distance) pairs; records in `ws.vx`, and rounded to float in `tf`; every other vertex at t =
/// `outside`, above every row) on a topological sphere: a seed (r, f) for every vertex x and row r strictly between t at
/// a strictly lower neighbour p of x (the highest, in float, to have few seeds) and t at x, f a
/// face on the edge x p; grouped by row into `ws.bucket` / `ws.count` as by seed_rows_by_faces.
/// They meet every piece of every row's level set when
///  (a) exactly one ball vertex has no strictly lower neighbour,
///  (b) no vertex lies on a row line and every ball vertex has t < outside,
///  (c) every vertex with t <= R - 1 has all its neighbours in the ball.
/// Proof: the set A_r where t <= r is connected by (a) (from any point of it, down inside its
/// face to a corner, then along the strictly descending edges to the one minimum). On a sphere
/// each component U of the complement of a connected A_r has a connected boundary
/// (unicoherence), so by (b) a single piece C of the level set. An edge crossing C has its upper
/// end u in the ball by (c); the descending path from u stays in the ball and ends at the
/// minimum below r, so it leaves U, through C, by an edge x p with t(p) < r < t(x): a seed of C.
/// (A neighbour lower in float is lower in double; rows come from the doubles.)
/// Returns false, and seeds nothing, when a condition fails: the caller uses seed_rows_by_faces.
template <typename V>
bool seed_rows_by_descent(const Vertex_stars& stars, const float* tf, const std::vector<std::pair<std::size_t, double>>& ball, std::size_t R, double outside,
                          Contour_workspace<V>& ws) {
  constexpr std::size_t W = Vertex_stars::kWidth;
  const V* vx = ws.vx.data();
  const double top = outside, last = static_cast<double>(R) - 1.0;
  const float top_f = static_cast<float>(outside), none = -std::numeric_limits<float>::infinity();
  const int last_row = static_cast<int>(R) - 1;
  std::size_t n_seeds = 0, minima = 0;
  unsigned bad = 0; // a vertex on a row line, at or above the outside value, or NaN
  float t_next_to_disc = none;
  constexpr std::size_t kCandidates = 2;
  if(ws.face_rows.size() < kCandidates * ball.size() + kCandidates) ws.face_rows.resize(kCandidates * ball.size() + 64);
  // floor of x in [-1, outside] by integer conversion (std::floor is a library call without SSE4.1)
  auto floor_of = [](double x) {
    const int i = static_cast<int>(x);
    return i - (static_cast<double>(i) > x ? 1 : 0);
  };
  for(const auto& b : ball) {
    const std::size_t v = b.first;
    const std::int32_t* nb = stars.nb.data() + W * v;
    float best, highest;
    int k_best;
#if defined(__SSE2__)
    { // four neighbours per register, without branches (their outcomes are random)
      static_assert(W == 8, "two quadruples of neighbours");
      const __m128 t = _mm_set1_ps(tf[v]), lowest = _mm_set1_ps(none);
      const __m128 n0 = _mm_setr_ps(tf[nb[0]], tf[nb[1]], tf[nb[2]], tf[nb[3]]);
      const __m128 n1 = _mm_setr_ps(tf[nb[4]], tf[nb[5]], tf[nb[6]], tf[nb[7]]);
      const __m128 below0 = _mm_cmplt_ps(n0, t), below1 = _mm_cmplt_ps(n1, t);
      const __m128 c0 = _mm_or_ps(_mm_and_ps(below0, n0), _mm_andnot_ps(below0, lowest));
      const __m128 c1 = _mm_or_ps(_mm_and_ps(below1, n1), _mm_andnot_ps(below1, lowest));
      __m128 m = _mm_max_ps(c0, c1), h = _mm_max_ps(n0, n1);
      m = _mm_max_ps(m, _mm_shuffle_ps(m, m, _MM_SHUFFLE(2, 3, 0, 1)));
      m = _mm_max_ps(m, _mm_shuffle_ps(m, m, _MM_SHUFFLE(1, 0, 3, 2))); // every lane: the largest
      h = _mm_max_ps(h, _mm_movehl_ps(h, h));
      h = _mm_max_ss(h, _mm_shuffle_ps(h, h, _MM_SHUFFLE(1, 1, 1, 1)));
      best = _mm_cvtss_f32(m);
      highest = _mm_cvtss_f32(h);
      const int hit = _mm_movemask_ps(_mm_cmpeq_ps(c0, m)) | (_mm_movemask_ps(_mm_cmpeq_ps(c1, m)) << 4);
      k_best = __builtin_ctz(static_cast<unsigned>(hit) | 0x100u) & 7;
    }
#else
    best = none;
    highest = none;
    k_best = 0;
    for(std::size_t k = 0; k < W; ++k) {
      const float tn = tf[nb[k]];
      highest = std::max(highest, tn);
      const float c = tn < tf[v] ? tn : none;
      k_best = c > best ? static_cast<int>(k) : k_best;
      best = std::max(best, c);
    }
#endif
    std::int32_t face = stars.face[W * v + static_cast<std::size_t>(k_best)], p = nb[k_best];
    if(stars.more_begin[v + 1] != stars.more_begin[v]) // rare: more than W neighbours
      for(std::uint32_t j = stars.more_begin[v]; j < stars.more_begin[v + 1]; ++j) {
        const float tn = tf[stars.more_nb[j]];
        highest = std::max(highest, tn);
        if(tn < tf[v] && tn > best) {
          best = tn;
          face = stars.more_face[j];
          p = stars.more_nb[j];
        }
      }
    const double tv = vx[v].t, tp = vx[static_cast<std::size_t>(p)].t;
    const unsigned has_lower = best > none ? 1u : 0u;
    const int fl = floor_of(std::max(-1.0, std::min(tv, top)));
    minima += 1u - has_lower;
    // (b), (c), without branches (the largest t next to a disc vertex is checked after the loop)
    bad |= static_cast<unsigned>(!(tv < top));
    t_next_to_disc = std::max(t_next_to_disc, tv <= last ? highest : none);
    bad |= static_cast<unsigned>(static_cast<double>(fl) == tv) & static_cast<unsigned>(static_cast<unsigned>(fl) <= static_cast<unsigned>(last_row));
    // rows r with t(p) < r < t(x): from floor(t(p)) + 1 to floor(t(x)) (neither is a row: (b))
    const int lo = std::max(0, floor_of(std::max(-1.0, std::min(tp, top))) + 1);
    const int hi = std::min(last_row, fl);
    const int count = has_lower ? std::max(0, hi - lo + 1) : 0;
    auto* o = ws.face_rows.data() + n_seeds;
    o[0] = {static_cast<std::uint32_t>(lo), static_cast<std::uint32_t>(face)};
    o[1] = {static_cast<std::uint32_t>(lo + 1), static_cast<std::uint32_t>(face)};
    if(count > static_cast<int>(kCandidates)) { // an edge across more than two rows
      if(ws.face_rows.size() < n_seeds + static_cast<std::size_t>(count) + (ball.size() + 1) * kCandidates) {
        ws.face_rows.resize(2 * (n_seeds + static_cast<std::size_t>(count) + (ball.size() + 1) * kCandidates));
        o = ws.face_rows.data() + n_seeds;
      }
      for(int r = lo + static_cast<int>(kCandidates); r <= hi; ++r) o[r - lo] = {static_cast<std::uint32_t>(r), static_cast<std::uint32_t>(face)};
    }
    n_seeds += static_cast<std::size_t>(count);
  }
  if(bad || t_next_to_disc >= top_f || minima != 1) return false;
  group_by_row(ws.face_rows.data(), n_seeds, R, ws.count, ws.next, ws.bucket);
  return true;
}

// The section of a face (corner records w) with the line t as an alpha range [l, u]; 0 when
// empty, else the bit mask of the edges (corner k to k+1) through which the section leaves the face.
template <typename S>
int level_line_section(const S& s, const typename S::Vertex* const* w, double t, double& l, double& u) {
  typedef typename S::Point P;
  const double d[3] = {w[0]->t - t, w[1]->t - t, w[2]->t - t};
  if(d[0] != 0 && d[1] != 0 && d[2] != 0) {
    // The common case: one vertex alone on its side; the section joins its two edges.
    const bool p0 = d[0] > 0, p1 = d[1] > 0, p2 = d[2] > 0;
    if(p0 == p1 && p1 == p2) return 0;
    const int k = (p0 == p1) ? 2 : (p0 == p2 ? 1 : 0);
    const int a = (k + 1) % 3, b = (k + 2) % 3;
    s.segment(S::cross(*w[k], *w[a], d[k], d[a]), S::cross(*w[k], *w[b], d[k], d[b]), l, u);
    return (1 << k) | (1 << b); // edges (k, k+1) and (k+2, k)
  }
  P pts[6];
  int np = 0;
  for(int k = 0; k < 3; ++k) {
    const int k2 = (k + 1) % 3;
    if(d[k] == 0) pts[np++] = S::at(*w[k]);
    if((d[k] < 0 && d[k2] > 0) || (d[k] > 0 && d[k2] < 0)) pts[np++] = S::cross(*w[k], *w[k2], d[k], d[k2]);
  }
  if(np == 0) return 0;
  s.polygon(pts, np, np == 3 && d[0] == 0 && d[1] == 0 && d[2] == 0, l, u);
  int edges = 0; // corners on the line: leave through every edge the line meets
  for(int k = 0; k < 3; ++k)
    if(d[k] * d[(k + 1) % 3] <= 0) edges |= 1 << k;
  return edges;
}

// The point of the line t on the edge from corner record i to j (i when both lie on it).
template <typename S>
typename S::Point level_line_point(const typename S::Vertex& i, const typename S::Vertex& j, double t) {
  const double si = i.t - t, sj = j.t - t;
  if(si == 0) return S::at(i);
  if(sj == 0) return S::at(j);
  return S::cross(i, j, si, sj);
}

// The contour from the pieces' intervals in `ws.entries` (rows 0..R-1): the union per row, the
// end points and the closing samples (see build_level_set_contour).
template <typename S, typename V>
void finish_level_set_contour(const S& s, std::size_t R, std::size_t cols, double alpha_scale, Contour_workspace<V>& ws, Spin_contour& out) {
  ws.merged.resize(R);
  // 3. Group the intervals by row, sort each row by its lower ends, union.
  group_by_row(ws.entries.data(), ws.entries.size(), R, ws.count, ws.next, ws.sorted);
  for(std::size_t r = 0; r < R; ++r) {
    auto first = ws.sorted.begin() + ws.count[r], last = ws.sorted.begin() + ws.count[r + 1];
    auto& merged = ws.merged[r];
    merged.clear();
    std::sort(first, last, [](const std::pair<double, double>& a, const std::pair<double, double>& b) { return a.first < b.first; });
    for(auto it = first; it != last; ++it) {
      const auto& iv = *it;
      if(!merged.empty() && iv.first <= merged.back().second + s.merge_eps) merged.back().second = std::max(merged.back().second, iv.second);
      else merged.push_back(iv);
    }
    for(auto& iv : merged) iv = {s.finish(iv.first), s.finish(iv.second)};
  }
  // 4. End points, and the closing samples of I_r \ I_{r-1} and I_r \ I_{r+1} on the column grid,
  //    pushed in increasing order (the sort below then finds them in place). A row's samples
  //    increase, so the intervals of the rows above and below that may contain them are found
  //    by two cursors instead of binary searches.
  const double dc = alpha_scale / static_cast<double>(cols);
  static const std::vector<std::pair<double, double>> none;
  ws.row.clear(); // all rows' points, row r in [row_end[r], row_end[r + 1])
  ws.row_end.assign(1, 0);
  for(std::size_t r = 0; r < R; ++r) {
    const auto& above = r > 0 ? ws.merged[r - 1] : none;
    const auto& below = r + 1 < R ? ws.merged[r + 1] : none;
    std::size_t ia = 0, ib = 0;
    auto contains = [](const std::vector<std::pair<double, double>>& iv, std::size_t& i, double a) {
      while(i < iv.size() && iv[i].second < a) ++i;
      return i < iv.size() && iv[i].first <= a;
    };
    for(const auto& seg : ws.merged[r]) {
      ws.row.push_back(static_cast<float>(seg.first / alpha_scale));
      // column range of the segment, clamped before the integer conversion (an infinite or NaN
      // quotient, dc = 0 on a flat neighbourhood, gives an empty range instead of undefined behaviour)
      const long c0 = clamped_to_long(std::ceil(seg.first / dc - 0.5), 0, static_cast<long>(cols));
      const long c1 = clamped_to_long(std::floor(seg.second / dc - 0.5), -1, static_cast<long>(cols) - 1);
      for(long k = c0; k <= c1; ++k) {
        const double a = (static_cast<double>(k) + 0.5) * dc;
        const bool in_above = contains(above, ia, a), in_below = contains(below, ib, a);
        if(!in_above || !in_below) ws.row.push_back(static_cast<float>(a / alpha_scale));
      }
      if(seg.second > seg.first) ws.row.push_back(static_cast<float>(seg.second / alpha_scale));
    }
    std::sort(ws.row.begin() + static_cast<std::ptrdiff_t>(ws.row_end.back()), ws.row.end());
    ws.row.erase(std::unique(ws.row.begin() + static_cast<std::ptrdiff_t>(ws.row_end.back()), ws.row.end()), ws.row.end());
    ws.row_end.push_back(ws.row.size());
  }
  // one allocation for the contour's points
  out.reserve(ws.row.size());
  for(std::size_t r = 0; r < R; ++r) out.append_row(r, ws.row.begin() + static_cast<std::ptrdiff_t>(ws.row_end[r]), ws.row.begin() + static_cast<std::ptrdiff_t>(ws.row_end[r + 1]));
}

// The walk's seeds from the faces (the general way): every face a row line crosses, under that
// row (most faces cross none to three); `ws.bucket` gets them grouped by row, row r in
// [ws.count[r], ws.count[r + 1]). Rows per vertex from `ws.set_rows`; `F` holds the faces'
// corners, 3 per face (this pass reads the compact copy). Branch-free unless a face spans more
// than kCandidates rows: that many candidate entries are written and the end advances by the
// count (a loop over the rows, whose trip count varies, mispredicted about once per face with
// long edges).
template <typename V, typename FaceVisitor>
void seed_rows_by_faces(const int* F, std::size_t R, FaceVisitor&& for_each_face, Contour_workspace<V>& ws) {
  std::size_t n_rows = 0;
  const int last_row = static_cast<int>(R) - 1;
  constexpr int kCandidates = 6; // (three pairs of rows below)
  for_each_face([&](std::size_t f) {
    const auto& a0 = ws.rows[static_cast<std::size_t>(F[3 * f])];
    const auto& a1 = ws.rows[static_cast<std::size_t>(F[3 * f + 1])];
    const auto& a2 = ws.rows[static_cast<std::size_t>(F[3 * f + 2])];
    // rows r with min t <= r <= max t: from the smallest ceil to the largest floor
    const int lo = std::max(0, std::min({a0[1], a1[1], a2[1]}));
    const int hi = std::min(last_row, std::max({a0[0], a1[0], a2[0]}));
    const int count = std::max(0, hi - lo + 1);
    if(ws.face_rows.size() < n_rows + static_cast<std::size_t>(count) + kCandidates) ws.face_rows.resize(2 * (n_rows + static_cast<std::size_t>(count)) + 64);
    auto* o = ws.face_rows.data() + n_rows;
#if defined(__SSE2__)
    { // the candidates as three 16-byte stores of (row, face) pairs
      static_assert(sizeof(*o) == 8, "(row, face) pairs of two 32-bit values");
      const __m128i base = _mm_add_epi32(_mm_setr_epi32(lo, static_cast<int>(f), lo, static_cast<int>(f)), _mm_setr_epi32(0, 0, 1, 0));
      const __m128i two = _mm_setr_epi32(2, 0, 2, 0);
      __m128i* q = reinterpret_cast<__m128i*>(o);
      _mm_storeu_si128(q, base);
      _mm_storeu_si128(q + 1, _mm_add_epi32(base, two));
      _mm_storeu_si128(q + 2, _mm_add_epi32(base, _mm_add_epi32(two, two)));
    }
#else
    for(int j = 0; j < kCandidates; ++j) o[j] = {static_cast<std::uint32_t>(lo + j), static_cast<std::uint32_t>(f)};
#endif
    for(int r = lo + kCandidates; r <= hi; ++r) o[r - lo] = {static_cast<std::uint32_t>(r), static_cast<std::uint32_t>(f)};
    n_rows += static_cast<std::size_t>(count);
  });
  group_by_row(ws.face_rows.data(), n_rows, R, ws.count, ws.next, ws.bucket);
}

/// Walks the level sets t = r of the rows r = 0..R-1 (vertex records in `ws.vx`) from the seeds in
/// `ws.bucket` / `ws.count` (by `seed_rows_by_faces` or `seed_rows_by_descent`: any set of faces
/// that meets every connected piece of every row's level set, grouped by row), and records the
/// alpha interval of each connected piece in `ws.entries`.
///
/// Along a connected curve alpha takes every value between its extremes, so a piece contributes
/// one interval [min, max] and the union of a row needs no sorting of per-face intervals. In the
/// common case (no corner on the line) a face has exactly two crossing edges, so a piece is
/// walked as two *chains* out of its seed face, each carrying the crossing on its shared edge:
/// one interpolation per face. Faces with a corner on the line go through the general code
/// (`open`). Rows are walked two at a time, each with its own face stamps (a face may meet both),
/// so that four chains run interleaved and their dependent loads overlap.
///
/// The section policy `S` gives the per-vertex record `S::Vertex`, the point type on a level line
/// `S::Point`, `S::cross(a, b, sa, sb)` (the point where t crosses the level on the edge a b, sa
/// and sb the offsets of a.t and b.t from it, of opposite signs), `S::at(a)`, `s.segment(p, q, l,
/// u)` (the alpha range, possibly in squared units, of a segment of a level line),
/// `s.polygon(points, n, in_plane, l, u)` (the same for a face with corners on the line: n
/// points, or the whole triangle when `in_plane`), `s.keep(l, u)` (clips a piece's range; false
/// drops it), `s.finish(x)` (from the range's units to alpha) and `s.merge_eps`.
template <typename S>
class Level_set_walker {
public:
  typedef typename S::Vertex V;
  typedef typename S::Point P;

  Level_set_walker(const std::vector<Face_link>& links, const std::vector<Half_edge_link>& half_edges, const S& s, Contour_workspace<V>& ws)
    : m_links(links), m_he(half_edges.data()), m_vx(ws.vx.data()), m_faces(links.size()), m_s(s), m_ws(ws) {
    ws.entries.clear();
  }

  /// Walks every row of [0, R).
  void walk(std::size_t R) {
    if(m_ws.stamp.size() != 2 * (m_faces + 1) || m_ws.epoch > 0xFFFFFFFFu - R) {
      m_ws.stamp.assign(2 * (m_faces + 1), 0);
      m_ws.epoch = 0;
    }
    for(std::size_t r0 = 0; r0 < R; r0 += 2) walk_row_pair(r0, r0 + 1 < R ? 2 : 1);
  }

private:
  // One row's walk: its line, its stamps and the seeds still to try.
  struct Row {
    double t;
    std::uint32_t r;      // the row
    std::uint32_t key;    // the stamp of faces this row's walk visited
    std::uint32_t* stamp; // per face; stamp[-1]: beyond a boundary
    std::vector<std::uint32_t>* stack; // faces with a corner on the line, for the general code
    std::uint32_t next, end; // the row's seeds still to try: bucket[next, end)
    double lmin, umax;       // the range of the current piece
  };
  // A chain follows the section from face to face. Its state is the half-edge h by which it
  // enters a face, with the records of h's origin x and target y (on opposite sides of the
  // line). The opposite corner w lies on x's side (the section leaves through y -> w, the next
  // half-edge) or on y's (through w -> x, the previous one).
  struct Chain {
    std::int32_t h;
    const V* x;
    const V* y;
    int x_above; // x lies above the line (consistent orientations keep it there)
    P pt, first;
    double lo, hi; // the range of the points it passed (empty until it moves)
  };

  // Rows r0 and r0 + 1 (`nr` = 2), or r0 alone (1): pieces of both rows with two chains each,
  // stepped together while both rows have pieces; then the rest of each row.
  void walk_row_pair(std::size_t r0, std::size_t nr) {
    Row rows[2];
    for(std::size_t j = 0; j < nr; ++j) {
      Row& w = rows[j];
      w.t = static_cast<double>(r0 + j);
      w.r = static_cast<std::uint32_t>(r0 + j);
      w.key = ++m_ws.epoch;
      w.stamp = m_ws.stamp.data() + 1 + j * (m_faces + 1);
      w.stamp[-1] = w.key;
      w.stack = j == 0 ? &m_ws.stack : &m_ws.stack2;
      w.stack->clear();
      w.next = m_ws.count[r0 + j];
      w.end = m_ws.count[r0 + j + 1];
    }
    Chain a[3], b[3];
    bool more_a = next_piece(rows[0], a), more_b = nr == 2 && next_piece(rows[1], b);
    while(more_a && more_b) {
      // four chains interleaved; the two of a closed piece meet half-way
      Chain a0 = a[0], a1 = a[1], b0 = b[0], b1 = b[1]; // (local copies: kept in registers)
      bool ga0 = true, ga1 = true, gb0 = true, gb1 = true;
      while(ga0 && ga1 && gb0 && gb1) {
        ga0 = step(rows[0], a0);
        ga1 = step(rows[0], a1);
        gb0 = step(rows[1], b0);
        gb1 = step(rows[1], b1);
      }
      if(!ga0 || !ga1) { // piece a is done or nearly: finish it, go on with b
        drain(rows[0], a0, a1, ga0, ga1, a);
        if(!gb0 || !gb1) { // b as well
          drain(rows[1], b0, b1, gb0, gb1, b);
          more_b = next_piece(rows[1], b);
        } else { // b continues: its chains resume with the next piece of a
          b[0] = b0;
          b[1] = b1;
        }
        more_a = next_piece(rows[0], a);
      } else { // piece b is done or nearly
        drain(rows[1], b0, b1, gb0, gb1, b);
        a[0] = a0;
        a[1] = a1;
        more_b = next_piece(rows[1], b);
      }
    }
    walk_rest_of_row(rows[0], a, more_a);
    if(nr == 2) walk_rest_of_row(rows[1], b, more_b);
  }

  // The remaining pieces of one row, their two chains interleaved.
  void walk_rest_of_row(Row& w, Chain* ch, bool more) {
    for(; more; more = next_piece(w, ch)) {
      Chain c0 = ch[0], c1 = ch[1];
      bool g0 = true, g1 = true;
      while(g0 && g1) {
        g0 = step(w, c0);
        g1 = step(w, c1);
      }
      drain(w, c0, c1, g0, g1, ch);
    }
  }

  // The next piece of row w whose seed face has two chains out of it (the common case), started
  // in ch; pieces of the general kind met on the way are walked on the spot. False: no more.
  bool next_piece(Row& w, Chain* ch) {
    while(w.next < w.end) {
      const std::uint32_t f0 = m_ws.bucket[w.next++];
      if(w.stamp[f0] == w.key) continue;
      w.stamp[f0] = w.key;
      w.lmin = std::numeric_limits<double>::infinity();
      w.umax = -std::numeric_limits<double>::infinity();
      int n = 0;
      open(w, f0, ch, n);
      if(n == 2 && w.stack->empty()) return true;
      finish_piece(w, ch, n);
    }
    return false;
  }

  // The two chains of a piece, one of them stopped or both: the rest one at a time, then the
  // rest of the piece.
  void drain(Row& w, Chain& c0, Chain& c1, bool g0, bool g1, Chain* ch) {
    while(g0) g0 = step(w, c0);
    while(g1) g1 = step(w, c1);
    close(w, c0);
    close(w, c1);
    finish_piece(w, ch, 0);
  }

  // The rest of a piece, one chain at a time: the `n` chains started in ch, then the faces with a
  // corner on the line (the general code) and the chains out of them; then the piece's interval.
  void finish_piece(Row& w, Chain* ch, int n) {
    for(;;) {
      for(int i = 0; i < n; ++i) {
        while(step(w, ch[i])) {
        }
        close(w, ch[i]);
      }
      n = 0;
      if(w.stack->empty()) break;
      const std::uint32_t f = w.stack->back();
      w.stack->pop_back();
      open(w, f, ch, n);
    }
    if(w.lmin <= w.umax && m_s.keep(w.lmin, w.umax)) m_ws.entries.push_back({w.r, {w.lmin, w.umax}});
  }

  // The section of face f: its range joins the piece's, and the chains out of it are started in
  // ch (n of them; false: none).
  bool open(Row& w, std::uint32_t f, Chain* ch, int& n) {
    double l, u;
    const V* corner[3] = {corner_record(f, 0), corner_record(f, 1), corner_record(f, 2)};
    const int edges = level_line_section(m_s, corner, w.t, l, u);
    n = 0;
    if(!edges) return false;
    w.lmin = std::min(w.lmin, l);
    w.umax = std::max(w.umax, u);
    for(int k = 0; k < 3; ++k)
      if(edges >> k & 1 && start(w, f, k, level_line_point<S>(*corner_record(f, k), *corner_record(f, (k + 1) % 3), w.t), ch[n])) ++n;
    return n > 0;
  }

  // Starts a chain out of face p through its edge k_out, whose point on the line is pt; false
  // when the next face has a corner on the line (pushed for the general code).
  bool start(Row& w, std::uint32_t p, int k_out, P pt, Chain& c) {
    bool same_way;
    c.h = twin_half_edge(m_links, p, k_out, same_way);
    c.x = corner_record(p, k_out == 2 ? 0 : k_out + 1); // h's origin, unless same_way
    c.y = corner_record(p, k_out);
    if(same_way) std::swap(c.x, c.y);
    const double sx = c.x->t - w.t, sy = c.y->t - w.t;
    c.x_above = sx > 0 ? 1 : 0;
    c.pt = c.first = pt;
    c.lo = std::numeric_limits<double>::infinity();
    c.hi = -std::numeric_limits<double>::infinity();
    if(sx == 0 || sy == 0) { // the next face has a corner on the line: general code
      const std::int32_t nb = c.h >> 2;
      if(w.stamp[nb] != w.key) {
        w.stamp[nb] = w.key;
        w.stack->push_back(static_cast<std::uint32_t>(nb));
      }
      return false;
    }
    return true;
  }

  // One step of a chain into the face its half-edge h enters; false when it stops there (a face
  // visited already, a boundary, or a corner on the line, left to the general code).
  bool step(Row& w, Chain& c) const {
    const std::int32_t f = c.h >> 2; // -1 beyond a boundary, whose stamp is the key
    if(w.stamp[f] == w.key) return false;
    w.stamp[f] = w.key;
    const Half_edge_link& e = m_he[c.h];
    const V* o = &m_vx[static_cast<std::size_t>(e.opposite)];
    const double so = o->t - w.t;
    if(so == 0) { // a corner on the line: general code
      w.stack->push_back(static_cast<std::uint32_t>(f));
      return false;
    }
    const int via_prev = (so > 0 ? 1 : 0) ^ c.x_above;
    const std::uintptr_t mask = std::uintptr_t(0) - static_cast<std::uintptr_t>(via_prev);
    // the exit edge from its first corner a to its second b, as the face lists them: y -> o
    // (the next half-edge) or o -> x (the previous one)
    const V* a = pick(mask, o, c.y);
    const V* b = pick(mask, c.x, o);
    const double sa = a->t - w.t, sb = b->t - w.t;
    const P q = S::cross(*a, *b, sa, sb);
    if constexpr(S::linear) { // the range of a segment is that of its end points
      c.lo = std::min(c.lo, q);
      c.hi = std::max(c.hi, q);
    } else {
      double l, u;
      m_s.segment(c.pt, q, l, u);
      c.lo = std::min(c.lo, l);
      c.hi = std::max(c.hi, u);
    }
    // The twin runs b -> a (or a -> b when the faces disagree in orientation); b lies on x's
    // side, a on y's. Both twins were loaded with the record: the choice is a mask, not a load.
    c.h = e.next_twin ^ (e.twins_xor & -static_cast<std::int32_t>(via_prev));
    if((e.flips >> via_prev) & 1) { // rare: a face of the other orientation
      c.x = a;
      c.y = b;
      c.x_above ^= 1;
    } else {
      c.x = b;
      c.y = a;
    }
    if constexpr(!S::linear) c.pt = q; // (the linear policy needs the end points only)
    return true;
  }

  // A stopped chain's range joins its piece's.
  static void close(Row& w, const Chain& c) {
    w.lmin = std::min(w.lmin, c.lo);
    w.umax = std::max(w.umax, c.hi);
    if constexpr(S::linear) { // the first point, left out of the steps
      if(c.lo <= c.hi) { // it moved
        w.lmin = std::min(w.lmin, c.first);
        w.umax = std::max(w.umax, c.first);
      }
    }
  }

  const V* corner_record(std::uint32_t f, int k) const { return &m_vx[static_cast<std::size_t>(m_links[f].v[k])]; }

  const std::vector<Face_link>& m_links;
  const Half_edge_link* m_he;
  const V* m_vx;
  std::size_t m_faces;
  const S& m_s;
  Contour_workspace<V>& m_ws;
};

/// The contour of the level sets t = 0..R-1 (vertex records in `ws.vx`) from the walk's seeds in
/// `ws.bucket` / `ws.count` (see `Level_set_walker`). Alpha is sampled on `cols` columns over
/// [0, alpha_scale] for the closing samples and stored divided by `alpha_scale`; `out` must have
/// R rows.
template <typename S>
void walk_level_sets(const std::vector<Face_link>& links, const std::vector<Half_edge_link>& half_edges, const S& s, std::size_t R, std::size_t cols, double alpha_scale,
                     Contour_workspace<typename S::Vertex>& ws, Spin_contour& out) {
  Level_set_walker<S>(links, half_edges, s, ws).walk(R);
  finish_level_set_contour(s, R, cols, alpha_scale, ws, out);
}

/// The contour of the level sets t = 0..R-1 over the faces `for_each_face(fn)` visits (vertex
/// records in `ws.vx`, rows set with `ws.set_rows`): seeds from every face, then the walk (see
/// seed_rows_by_faces and walk_level_sets).
template <typename S, typename FaceVisitor>
void build_level_set_contour(const std::vector<Face_link>& links, const std::vector<Half_edge_link>& half_edges, const int* F, const S& s, std::size_t R, std::size_t cols, double alpha_scale,
                             FaceVisitor&& for_each_face, Contour_workspace<typename S::Vertex>& ws, Spin_contour& out) {
  seed_rows_by_faces(F, R, std::forward<FaceVisitor>(for_each_face), ws);
  walk_level_sets(links, half_edges, s, R, cols, alpha_scale, ws, out);
}

} // namespace internal
} // namespace shapecorr

#endif
