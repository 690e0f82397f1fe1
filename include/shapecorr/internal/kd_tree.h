// Copyright (c) 2026 ShapeCorr contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Internal: a static kd-tree over points of fixed dimension D (built once in O(m log m)):
// nearest-neighbour queries and radius queries. Used for contour distances, neighbourhoods of
// oriented points and closest-point ground truth.
#ifndef SHAPECORR_INTERNAL_KD_TREE_H
#define SHAPECORR_INTERNAL_KD_TREE_H

#include <algorithm>
#include <array>
#include <cstdint>
#include <limits>
#include <numeric>
#include <utility>
#include <vector>

namespace shapecorr {
namespace internal {

template <int D>
class Kd_tree {
public:
  typedef std::array<double, D> Point;

  Kd_tree() = default;
  explicit Kd_tree(std::vector<Point> points) : m_points(std::move(points)) {
    m_order.resize(m_points.size());
    std::iota(m_order.begin(), m_order.end(), 0u);
    m_nodes.reserve(2 * m_points.size() / leaf_size + 2);
    if(!m_points.empty()) build(0, static_cast<std::uint32_t>(m_points.size()));
  }

  std::size_t size() const { return m_points.size(); }
  const Point& point(std::size_t i) const { return m_points[i]; }

  /// Index of the nearest point to q (ties: any) and its squared distance; size() must be > 0.
  std::pair<std::size_t, double> nearest(const Point& q) const {
    std::pair<std::size_t, double> best(0, std::numeric_limits<double>::infinity());
    nearest_rec(0, q, best);
    return best;
  }

  /// The k nearest points to q, nearest first, as (index, squared distance) (fewer when size() < k).
  std::vector<std::pair<std::size_t, double>> k_nearest(const Point& q, std::size_t k) const {
    std::vector<std::pair<std::size_t, double>> heap; // max-heap on the distance, at most k entries
    if(k == 0 || m_points.empty()) return heap;
    heap.reserve(k + 1);
    k_nearest_rec(0, q, k, heap);
    std::sort_heap(heap.begin(), heap.end(), farther);
    return heap;
  }

  /// Calls fn(index, squared distance) for every point within distance r of q.
  template <typename Fn>
  void for_each_within(const Point& q, double r, Fn&& fn) const {
    if(m_points.empty()) return;
    radius_rec(0, q, r * r, fn);
  }

private:
  static constexpr std::uint32_t leaf_size = 8;
  struct Node {
    std::uint32_t begin, end;     // range of m_order
    std::uint32_t left = 0, right = 0; // children (0 = leaf)
    int axis = -1;
    double split = 0;
    Point lo{}, hi{};             // bounding box
  };

  std::uint32_t build(std::uint32_t b, std::uint32_t e) {
    const std::uint32_t id = static_cast<std::uint32_t>(m_nodes.size());
    m_nodes.push_back(Node{b, e});
    Point lo, hi;
    lo.fill(std::numeric_limits<double>::infinity());
    hi.fill(-std::numeric_limits<double>::infinity());
    for(std::uint32_t i = b; i < e; ++i)
      for(int d = 0; d < D; ++d) {
        lo[d] = std::min(lo[d], m_points[m_order[i]][d]);
        hi[d] = std::max(hi[d], m_points[m_order[i]][d]);
      }
    m_nodes[id].lo = lo;
    m_nodes[id].hi = hi;
    if(e - b <= leaf_size) return id;
    int axis = 0;
    for(int d = 1; d < D; ++d)
      if(hi[d] - lo[d] > hi[axis] - lo[axis]) axis = d;
    if(!(hi[axis] > lo[axis])) return id; // all points equal: a leaf however many
    const std::uint32_t mid = b + (e - b) / 2;
    std::nth_element(m_order.begin() + b, m_order.begin() + mid, m_order.begin() + e,
                     [&](std::uint32_t i, std::uint32_t j) { return m_points[i][axis] < m_points[j][axis]; });
    m_nodes[id].axis = axis;
    m_nodes[id].split = m_points[m_order[mid]][axis];
    const std::uint32_t l = build(b, mid);
    const std::uint32_t r = build(mid, e);
    m_nodes[id].left = l;
    m_nodes[id].right = r;
    return id;
  }

  static double box_distance2(const Node& nd, const Point& q) {
    double s = 0;
    for(int d = 0; d < D; ++d) {
      const double t = q[d] < nd.lo[d] ? nd.lo[d] - q[d] : (q[d] > nd.hi[d] ? q[d] - nd.hi[d] : 0.0);
      s += t * t;
    }
    return s;
  }
  static double distance2(const Point& a, const Point& b) {
    double s = 0;
    for(int d = 0; d < D; ++d) s += (a[d] - b[d]) * (a[d] - b[d]);
    return s;
  }

  void nearest_rec(std::uint32_t id, const Point& q, std::pair<std::size_t, double>& best) const {
    const Node& nd = m_nodes[id];
    if(box_distance2(nd, q) >= best.second) return;
    if(nd.axis < 0) {
      for(std::uint32_t i = nd.begin; i < nd.end; ++i) {
        const double d2 = distance2(m_points[m_order[i]], q);
        if(d2 < best.second) best = {m_order[i], d2};
      }
      return;
    }
    const bool left_first = q[nd.axis] < nd.split;
    nearest_rec(left_first ? nd.left : nd.right, q, best);
    nearest_rec(left_first ? nd.right : nd.left, q, best);
  }

  static bool farther(const std::pair<std::size_t, double>& a, const std::pair<std::size_t, double>& b) { return a.second < b.second; }

  void k_nearest_rec(std::uint32_t id, const Point& q, std::size_t k, std::vector<std::pair<std::size_t, double>>& heap) const {
    const Node& nd = m_nodes[id];
    if(heap.size() == k && box_distance2(nd, q) >= heap.front().second) return;
    if(nd.axis < 0) {
      for(std::uint32_t i = nd.begin; i < nd.end; ++i) {
        const double d2 = distance2(m_points[m_order[i]], q);
        if(heap.size() < k) {
          heap.emplace_back(m_order[i], d2);
          std::push_heap(heap.begin(), heap.end(), farther);
        } else if(d2 < heap.front().second) {
          std::pop_heap(heap.begin(), heap.end(), farther);
          heap.back() = {m_order[i], d2};
          std::push_heap(heap.begin(), heap.end(), farther);
        }
      }
      return;
    }
    const bool left_first = q[nd.axis] < nd.split;
    k_nearest_rec(left_first ? nd.left : nd.right, q, k, heap);
    k_nearest_rec(left_first ? nd.right : nd.left, q, k, heap);
  }

  template <typename Fn>
  void radius_rec(std::uint32_t id, const Point& q, double r2, Fn& fn) const {
    const Node& nd = m_nodes[id];
    if(box_distance2(nd, q) > r2) return;
    if(nd.axis < 0) {
      for(std::uint32_t i = nd.begin; i < nd.end; ++i) {
        const double d2 = distance2(m_points[m_order[i]], q);
        if(d2 <= r2) fn(static_cast<std::size_t>(m_order[i]), d2);
      }
      return;
    }
    radius_rec(nd.left, q, r2, fn);
    radius_rec(nd.right, q, r2, fn);
  }

  std::vector<Point> m_points;
  std::vector<std::uint32_t> m_order;
  std::vector<Node> m_nodes;
};

} // namespace internal
} // namespace shapecorr

#endif
