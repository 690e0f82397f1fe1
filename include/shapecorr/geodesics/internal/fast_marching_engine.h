// Copyright (c) 2026 ShapeCorr contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Internal: fast marching on triangle meshes (Kimmel & Sethian 1998) with the virtual-source
// triangle update (the front from two known vertices is continued as a straight ray from the
// unfolded point source, which is exact on developable patches), falling back to edge (Dijkstra)
// updates where the ray does not cross the triangle. The march can stop at a radius: its cost is
// then proportional to the geodesic ball, not to the mesh.
#ifndef SHAPECORR_GEODESICS_INTERNAL_FAST_MARCHING_ENGINE_H
#define SHAPECORR_GEODESICS_INTERNAL_FAST_MARCHING_ENGINE_H

#include <shapecorr/exceptions.h>
#include <shapecorr/internal/intrinsic_triangulation.h>

#include <Eigen/Core>

#include <cmath>
#include <cstdint>
#include <limits>
#include <type_traits>
#include <utility>
#include <vector>

namespace shapecorr {
namespace internal {

class Fast_marching_engine {
public:
  struct Heap_entry {
    double key;
    int v;
  };
  /// State of one vertex in a query: its tentative distance and its slot in the heap
  /// (`far` = not reached yet, `done` = accepted).
  struct Vertex_state {
    double dist;
    int slot;
  };
  static constexpr int far = -1, done = -2;
  /// Per-query scratch state; reusable across queries (reset costs what the last query touched).
  /// Cache-line aligned: the workspaces of concurrent threads sit side by side in a vector, and the
  /// heap's size changes at every step (false sharing made two threads slower than one).
  struct alignas(64) Workspace {
    std::vector<Vertex_state> state;
    std::vector<int> touched;     // vertices whose state the last query changed
    std::vector<Heap_entry> heap; // indexed 4-ary min-heap of (dist, vertex), keys stored inline
  };

  /// One possible update when vertex v is accepted: target t of a face (v, o, t), with the
  /// unfolding of t over the edge v-o (v at (0,0), o at (c,0), t at (cx, cy), cy > 0).
  struct Update {
    int t, o;
    double l_vt, c, inv2c, cx, cy;
  };

  explicit Fast_marching_engine(const Triangle_arrays& a) : m_n(a.number_of_vertices()) {
    if(m_n == 0 || a.number_of_faces() == 0)
      throw Invalid_input(Mesh_defect::empty_mesh, "fast marching: the mesh has no vertex or no face");
    if(!a.V.allFinite())
      throw Invalid_input(Mesh_defect::non_finite_coordinate, "fast marching: the mesh has NaN or infinite coordinates");
    const std::size_t m = a.number_of_faces();
    m_faces.resize(m);
    m_len.resize(m);
    std::vector<int> deg(m_n + 1, 0);
    for(std::size_t f = 0; f < m; ++f) {
      for(int k = 0; k < 3; ++k) {
        m_faces[f][static_cast<std::size_t>(k)] = a.F(static_cast<Eigen::Index>(f), k);
        ++deg[static_cast<std::size_t>(a.F(static_cast<Eigen::Index>(f), k)) + 1];
      }
      for(int k = 0; k < 3; ++k) // length of the edge opposite corner k
        m_len[f][static_cast<std::size_t>(k)] =
            (a.point(static_cast<std::size_t>(m_faces[f][static_cast<std::size_t>((k + 1) % 3)])) -
             a.point(static_cast<std::size_t>(m_faces[f][static_cast<std::size_t>((k + 2) % 3)]))).norm();
    }
    // per vertex, the updates it triggers when accepted (two per incident face), pre-oriented
    m_offset.assign(m_n + 1, 0);
    for(std::size_t v = 0; v < m_n; ++v) m_offset[v + 1] = m_offset[v] + 2 * deg[v + 1];
    m_updates.resize(static_cast<std::size_t>(m_offset[m_n]));
    std::vector<int> fill(m_offset.begin(), m_offset.end() - 1);
    for(std::size_t f = 0; f < m; ++f)
      for(int k = 0; k < 3; ++k) {
        const int v = m_faces[f][static_cast<std::size_t>(k)];
        for(int s = 1; s <= 2; ++s) {
          const int tc = (k + s) % 3, oc = (k + 3 - s) % 3;
          Update u;
          u.t = m_faces[f][static_cast<std::size_t>(tc)];
          u.o = m_faces[f][static_cast<std::size_t>(oc)];
          u.l_vt = m_len[f][static_cast<std::size_t>(oc)];
          u.c = m_len[f][static_cast<std::size_t>(tc)];
          u.inv2c = u.c > 0 ? 1.0 / (2 * u.c) : 0.0;
          const auto apex = unfold_apex(u.c, u.l_vt, m_len[f][static_cast<std::size_t>(k)]);
          u.cx = apex.first;
          u.cy = apex.second; // cy = 0 (degenerate face): no triangle update
          m_updates[static_cast<std::size_t>(fill[static_cast<std::size_t>(v)]++)] = u;
        }
      }
  }

  std::size_t number_of_vertices() const { return m_n; }

  void prepare(Workspace& w) const {
    if(w.state.size() != m_n) {
      w.state.assign(m_n, Vertex_state{std::numeric_limits<double>::infinity(), far});
      w.touched.clear();
      w.heap.clear();
    }
  }

  /// March from `sources` (distance 0) until the front passes `radius`.
  /// `visit(v, d)` is called once per accepted vertex, in the order of acceptance: increasing
  /// distances except where a triangle update gives a vertex a distance below that of the vertex
  /// accepted before it (a virtual source can lie nearer to it than to that vertex; 18 to 30
  /// inversions per 1000 vertices on TOSCA meshes). For the same reason a vertex with a distance
  /// just below `radius` can be left out, when only a vertex beyond `radius` would have lowered
  /// it to there. If `visit` returns a `bool`, `false` stops the march there.
  template <typename Visit>
  void march(const std::vector<std::size_t>& sources, double radius, Workspace& w, Visit&& visit) const {
    prepare(w);
    Vertex_state* state = w.state.data();
    // reset what the previous query touched
    for(int v : w.touched) state[v] = Vertex_state{std::numeric_limits<double>::infinity(), far};
    w.touched.clear();
    w.heap.clear();
    for(std::size_t s : sources) {
      if(s >= m_n)
        throw Invalid_argument("source vertex " + std::to_string(s) + " out of range (mesh has " +
                                                               std::to_string(m_n) + " vertices)");
      if(state[s].slot == far) {
        w.touched.push_back(static_cast<int>(s));
        state[s].dist = 0.0;
        push(w, static_cast<int>(s), 0.0);
      }
    }
    while(!w.heap.empty()) {
      const std::size_t v = static_cast<std::size_t>(w.heap.front().v);
      const double dv = w.heap.front().key;
      if(dv > radius) break;
      pop(w);
      state[v].slot = done;
      if constexpr(std::is_same<decltype(visit(v, dv)), bool>::value) {
        if(!visit(v, dv)) break;
      } else {
        visit(v, dv);
      }
      const Update* end = m_updates.data() + m_offset[v + 1];
      for(const Update* u = m_updates.data() + m_offset[v]; u != end; ++u) {
        Vertex_state& st = state[u->t];
        if(st.slot == done) continue;
        double d = dv + u->l_vt;
        // (the edge update from o was applied when o was accepted)
        const Vertex_state& so = state[u->o];
        if(so.slot == done) d = unfolded_update(dv, so.dist, u->c, u->inv2c, u->cx, u->cy, d);
        if(d < st.dist) {
          st.dist = d;
          if(st.slot == far) {
            w.touched.push_back(u->t);
            push(w, u->t, d);
          } else {
            sift_up(w, static_cast<std::size_t>(st.slot), u->t, d);
          }
        }
      }
    }
  }

  /// Virtual-source update with C unfolded at (cx, cy) over A = (0,0), B = (c,0) (`inv2c` = 1/(2c));
  /// returns `fallback` where the ray from the virtual source misses the segment AB.
  static double unfolded_update(double dA, double dB, double c, double inv2c, double cx, double cy, double fallback) {
    if(!(cy > 0)) return fallback;
    const double sx = (dA * dA - dB * dB + c * c) * inv2c;
    const double sy2 = dA * dA - sx * sx;
    if(sy2 < 0) return fallback;
    const double sy = -std::sqrt(sy2);
    // the ray from the virtual source S = (sx, sy) to C crosses the segment AB iff A and B lie on
    // either side of the line SC (cross products of opposite signs; no division)
    const double dx = cx - sx, dy = cy - sy;
    const double side_a = dx * (-sy) - dy * (-sx);
    const double side_b = dx * (-sy) - dy * (c - sx);
    if(side_a < 0 || side_b > 0) return fallback;
    return std::min(fallback, std::sqrt(dx * dx + dy * dy));
  }

private:
  // indexed 4-ary min-heap of (key, vertex) entries
  static void place(Workspace& w, std::size_t i, const Heap_entry& e) {
    w.heap[i] = e;
    w.state[static_cast<std::size_t>(e.v)].slot = static_cast<int>(i);
  }
  // moves vertex v, whose key decreased to `key`, up from slot i
  static void sift_up(Workspace& w, std::size_t i, int v, double key) {
    while(i > 0) {
      const std::size_t parent = (i - 1) / 4;
      if(!(key < w.heap[parent].key)) break;
      place(w, i, w.heap[parent]);
      i = parent;
    }
    place(w, i, Heap_entry{key, v});
  }
  static void push(Workspace& w, int v, double key) {
    w.heap.push_back(Heap_entry{key, v});
    sift_up(w, w.heap.size() - 1, v, key);
  }
  static void pop(Workspace& w) {
    const Heap_entry last = w.heap.back();
    w.heap.pop_back();
    const std::size_t n = w.heap.size();
    if(n == 0) return;
    std::size_t i = 0;
    for(;;) {
      const std::size_t first = 4 * i + 1;
      if(first >= n) break;
      std::size_t best = first;
      double bk = w.heap[first].key;
      const std::size_t end = std::min(first + 4, n);
      for(std::size_t c = first + 1; c < end; ++c)
        if(w.heap[c].key < bk) { bk = w.heap[c].key; best = c; }
      if(!(bk < last.key)) break;
      place(w, i, w.heap[best]);
      i = best;
    }
    place(w, i, last);
  }

  std::size_t m_n;
  std::vector<std::array<int, 3>> m_faces;
  std::vector<std::array<double, 3>> m_len;  // length of the edge opposite each corner
  std::vector<int> m_offset;                 // CSR offsets into m_updates per vertex
  std::vector<Update> m_updates;
};

} // namespace internal
} // namespace shapecorr

#endif
