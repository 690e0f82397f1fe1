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
#include <shapecorr/mesh/internal/indexed_mesh.h>

#include <cmath>
#include <cstdint>
#include <limits>
#include <queue>
#include <utility>
#include <vector>

namespace shapecorr {
namespace internal {

class Fast_marching_engine {
public:
  /// Per-query scratch state; reusable across queries (reset costs what the last query touched).
  struct Workspace {
    std::vector<double> dist;
    std::vector<std::uint32_t> stamp;  // == generation: dist valid; == generation with accepted flag
    std::vector<char> accepted;
    std::vector<int> touched;
    std::uint32_t generation = 0;
    std::vector<std::pair<double, int>> heap_storage;
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
    // unfolding of corner k over its opposite edge: A = corner k+1 at (0,0), B = corner k+2 at
    // (c,0), corner k at (cx, cy), cy > 0
    m_unfold.resize(m);
    for(std::size_t f = 0; f < m; ++f)
      for(int k = 0; k < 3; ++k) {
        const double c = m_len[f][static_cast<std::size_t>(k)];                 // |AB|
        const double b = m_len[f][static_cast<std::size_t>((k + 2) % 3)];       // |A C|: opposite corner k+2
        const double a = m_len[f][static_cast<std::size_t>((k + 1) % 3)];       // |B C|: opposite corner k+1
        const double cx = c > 0 ? (b * b + c * c - a * a) / (2 * c) : 0.0;
        const double cy2 = b * b - cx * cx;
        m_unfold[f][static_cast<std::size_t>(k)] = {c, cx, cy2 > 0 ? std::sqrt(cy2) : 0.0};
      }
    m_offset.assign(m_n + 1, 0);
    for(std::size_t v = 0; v < m_n; ++v) m_offset[v + 1] = m_offset[v] + deg[v + 1];
    m_incident.resize(static_cast<std::size_t>(m_offset[m_n]));
    std::vector<int> fill(m_offset.begin(), m_offset.end() - 1);
    for(std::size_t f = 0; f < m; ++f)
      for(int k = 0; k < 3; ++k)
        m_incident[static_cast<std::size_t>(fill[static_cast<std::size_t>(m_faces[f][static_cast<std::size_t>(k)])]++)] =
            static_cast<int>(3 * f) + k;
  }

  std::size_t number_of_vertices() const { return m_n; }

  void prepare(Workspace& w) const {
    if(w.dist.size() != m_n) {
      w.dist.assign(m_n, std::numeric_limits<double>::infinity());
      w.stamp.assign(m_n, 0);
      w.accepted.assign(m_n, 0);
      w.generation = 0;
    }
  }

  /// March from `sources` (distance 0) until every vertex closer than `radius` is accepted.
  /// `visit(v, d)` is called once per accepted vertex, in increasing distance order.
  template <typename Visit>
  void march(const std::vector<std::size_t>& sources, double radius, Workspace& w, Visit&& visit) const {
    prepare(w);
    // reset what the previous query touched
    for(int v : w.touched) {
      w.dist[static_cast<std::size_t>(v)] = std::numeric_limits<double>::infinity();
      w.accepted[static_cast<std::size_t>(v)] = 0;
    }
    w.touched.clear();
    typedef std::pair<double, int> Item;
    std::priority_queue<Item, std::vector<Item>, std::greater<Item>> heap(std::greater<Item>(), std::move(w.heap_storage));
    for(std::size_t s : sources) {
      if(s >= m_n)
        throw Invalid_input(Mesh_defect::invalid_argument, "source vertex " + std::to_string(s) + " out of range (mesh has " +
                                                               std::to_string(m_n) + " vertices)");
      if(w.dist[s] != 0.0) { w.dist[s] = 0.0; w.touched.push_back(static_cast<int>(s)); }
      heap.emplace(0.0, static_cast<int>(s));
    }
    while(!heap.empty()) {
      const Item top = heap.top();
      heap.pop();
      const std::size_t v = static_cast<std::size_t>(top.second);
      if(w.accepted[v] || top.first > w.dist[v]) continue;
      if(top.first > radius) break;
      w.accepted[v] = 1;
      visit(v, top.first);
      for(int k = m_offset[v]; k < m_offset[v + 1]; ++k) {
        const int c = m_incident[static_cast<std::size_t>(k)];
        const std::size_t f = static_cast<std::size_t>(c / 3);
        const int corner = c % 3;
        for(int s = 1; s <= 2; ++s) { // update the two other corners of the face
          const int tc = (corner + s) % 3, oc = (corner + 3 - s) % 3;
          const std::size_t t = static_cast<std::size_t>(m_faces[f][static_cast<std::size_t>(tc)]);
          if(w.accepted[t]) continue;
          const std::size_t o = static_cast<std::size_t>(m_faces[f][static_cast<std::size_t>(oc)]);
          double d = w.dist[v] + m_len[f][static_cast<std::size_t>(oc)]; // edge v-t is opposite corner oc
          if(w.accepted[o]) {
            // unfolding of t over edge (t+1, t+2); v is corner t+1 when s == 2, corner t+2 when s == 1
            const auto& u = m_unfold[f][static_cast<std::size_t>(tc)];
            const bool v_is_A = (s == 2);
            const double dA = v_is_A ? w.dist[v] : w.dist[o], dB = v_is_A ? w.dist[o] : w.dist[v];
            d = std::min(d, unfolded_update(dA, dB, u[0], u[1], u[2], std::min(d, w.dist[o] + m_len[f][static_cast<std::size_t>(corner)])));
          }
          if(d < w.dist[t]) {
            if(std::isinf(w.dist[t])) w.touched.push_back(static_cast<int>(t));
            w.dist[t] = d;
            heap.emplace(d, static_cast<int>(t));
          }
        }
      }
    }
    // keep the heap's buffer for the next query
    while(!heap.empty()) heap.pop();
    w.heap_storage.clear();
  }

  /// Virtual-source update with C unfolded at (cx, cy) over A = (0,0), B = (c,0); returns
  /// `fallback` where the ray from the virtual source misses the segment AB.
  static double unfolded_update(double dA, double dB, double c, double cx, double cy, double fallback) {
    if(!(c > 0) || !(cy > 0)) return fallback;
    const double sx = (dA * dA - dB * dB + c * c) / (2 * c);
    const double sy2 = dA * dA - sx * sx;
    if(sy2 < 0) return fallback;
    const double sy = -std::sqrt(sy2);
    // the ray from the virtual source S = (sx, sy) to C must cross the segment AB (y = 0)
    const double x = sx + (cx - sx) * (-sy / (cy - sy));
    if(x < 0 || x > c) return fallback;
    const double dx = cx - sx, dy = cy - sy;
    return std::min(fallback, std::sqrt(dx * dx + dy * dy));
  }

  /// Distance at C from A, B with distances dA, dB; c = |AB|, b = |AC|, a = |BC|.
  static double triangle_update(double dA, double dB, double c, double b, double a) {
    const double edge = std::min(dA + b, dB + a);
    if(!(c > 0)) return edge;
    const double cx = (b * b + c * c - a * a) / (2 * c);
    const double cy2 = b * b - cx * cx;
    if(!(cy2 > 0)) return edge;
    const double cy = std::sqrt(cy2);
    const double sx = (dA * dA - dB * dB + c * c) / (2 * c);
    const double sy2 = dA * dA - sx * sx;
    if(sy2 < 0) return edge;
    const double sy = -std::sqrt(sy2);
    // the ray from the virtual source S to C must cross the segment AB
    const double t = -sy / (cy - sy);
    const double x = sx + t * (cx - sx);
    if(x < 0 || x > c) return edge;
    return std::min(edge, std::hypot(cx - sx, cy - sy));
  }

private:
  std::size_t m_n;
  std::vector<std::array<int, 3>> m_faces;
  std::vector<std::array<double, 3>> m_len;                  // length of the edge opposite each corner
  std::vector<std::array<std::array<double, 3>, 3>> m_unfold;  // per corner: c, cx, cy (see constructor)
  std::vector<int> m_offset;
  std::vector<int> m_incident;  // corner ids 3f+k around each vertex
};

} // namespace internal
} // namespace shapecorr

#endif
