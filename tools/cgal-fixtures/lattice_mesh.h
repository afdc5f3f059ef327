// Triangle meshes on an integer lattice, shared by ray_mesh.cpp and
// mesh_points.cpp: coordinates X 2^e with |X| < 2^53, all multiples of 24
// before an offset, so that the points k/24 of the way along an edge are
// lattice points too, and every such point is an exact input.
#pragma once

#include "ray.h"

namespace fixtures {

using Tri3 = std::array<int, 3>;

// A mesh on the lattice: integer points (times 2^e, plus an integer offset
// before scaling), triangles by index.
struct LatticeMesh {
  std::string name, what;
  int e = 0;
  std::vector<I3> pts;
  std::vector<Tri3> tris;

  P3 at(const I3& x) const { return lattice3(x, e); }
  std::vector<P3> vertices() const {
    std::vector<P3> v;
    for (const I3& p : pts) v.push_back(at(p));
    return v;
  }
  // Every edge (a < b) and how many triangles use it.
  std::map<std::pair<int, int>, int> edges() const {
    std::map<std::pair<int, int>, int> count;
    for (const Tri3& t : tris)
      for (int k = 0; k < 3; ++k) ++count[std::minmax(t[k], t[(k + 1) % 3])];
    return count;
  }
  I3 lo() const {
    I3 m = pts[0];
    for (const I3& p : pts)
      for (int k = 0; k < 3; ++k) m[k] = std::min(m[k], p[k]);
    return m;
  }
  I3 hi() const {
    I3 m = pts[0];
    for (const I3& p : pts)
      for (int k = 0; k < 3; ++k) m[k] = std::max(m[k], p[k]);
    return m;
  }
  I3 centre() const {
    I3 a = lo(), b = hi();
    return I3{(a[0] + b[0]) / 2, (a[1] + b[1]) / 2, (a[2] + b[2]) / 2};
  }
  I3 normal(int t) const {
    const Tri3& x = tris[t];
    return cross3(sub3(pts[x[1]], pts[x[0]]), sub3(pts[x[2]], pts[x[0]]));
  }
  void shift(const I3& off) {
    for (I3& p : pts) p = add3(p, off);
  }
};

// ---------------------------------------------------------------------------
// Meshes

inline void add_quad(std::vector<Tri3>& t, int a, int b, int c, int d) {
  t.push_back({a, b, c});
  t.push_back({a, c, d});
}

inline LatticeMesh octahedron(int64_t R, int e) {
  LatticeMesh m;
  m.e = e;
  m.pts = {{R, 0, 0}, {-R, 0, 0}, {0, R, 0}, {0, -R, 0}, {0, 0, R}, {0, 0, -R}};
  for (int sx : {0, 1})
    for (int sy : {2, 3})
      for (int sz : {4, 5}) m.tris.push_back({sx, sy, sz});
  return m;
}

inline LatticeMesh cube(int64_t R, int e) {
  LatticeMesh m;
  m.e = e;
  for (int i = 0; i < 8; ++i) m.pts.push_back({i & 1 ? R : -R, i & 2 ? R : -R, i & 4 ? R : -R});
  add_quad(m.tris, 0, 1, 3, 2);  // z = -R
  add_quad(m.tris, 4, 6, 7, 5);  // z = +R
  add_quad(m.tris, 0, 4, 5, 1);  // y = -R
  add_quad(m.tris, 2, 3, 7, 6);  // y = +R
  add_quad(m.tris, 0, 2, 6, 4);  // x = -R
  add_quad(m.tris, 1, 5, 7, 3);  // x = +R
  return m;
}

// The octahedron subdivided `levels` times (each triangle into four), every
// vertex pushed out to radius R (rounded to an integer, then times 24):
// closed, with shared edges and vertices of valence 4, 5 and 6.
inline LatticeMesh octasphere(int levels, int64_t R, int e) {
  std::vector<P3> dirs = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
  std::vector<Tri3> tris = octahedron(1, 0).tris;
  for (int l = 0; l < levels; ++l) {
    std::map<std::pair<int, int>, int> mid;
    auto midpoint = [&](int a, int b) {
      auto key = std::minmax(a, b);
      auto it = mid.find(key);
      if (it != mid.end()) return it->second;
      dirs.push_back(pnormalize(padd(dirs[a], dirs[b])));
      return mid[key] = int(dirs.size()) - 1;
    };
    std::vector<Tri3> next;
    for (const Tri3& t : tris) {
      int ab = midpoint(t[0], t[1]), bc = midpoint(t[1], t[2]), ca = midpoint(t[2], t[0]);
      next.push_back({t[0], ab, ca});
      next.push_back({ab, t[1], bc});
      next.push_back({ca, bc, t[2]});
      next.push_back({ab, bc, ca});
    }
    tris = next;
  }
  LatticeMesh m;
  m.e = e;
  for (const P3& d : dirs) {
    I3 p;
    for (int k = 0; k < 3; ++k) p[k] = 24 * int64_t(std::nearbyint(d[k] * double(R)));
    m.pts.push_back(p);
  }
  m.tris = tris;
  return m;
}

// An n x n height field: lattice points (24 S i, 24 S j, 24 h), h random in
// [-H, H], each square split along a diagonal chosen at random.
inline LatticeMesh height_field(Rng& r, int n, int64_t S, int64_t H, int e) {
  LatticeMesh m;
  m.e = e;
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i) m.pts.push_back({24 * S * i, 24 * S * j, 24 * r.range(-H, H)});
  auto id = [n](int i, int j) { return j * (n + 1) + i; };
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      if (r.chance(50))
        add_quad(m.tris, id(i, j), id(i + 1, j), id(i + 1, j + 1), id(i, j + 1));
      else
        add_quad(m.tris, id(i + 1, j), id(i + 1, j + 1), id(i, j + 1), id(i, j));
    }
  return m;
}

// A lattice point at a random vertex, k/24 of the way along a random edge,
// or a random lattice point of a random face ((a v0 + b v1 + c v2) / 24).
inline I3 vertex_point(Rng& r, const LatticeMesh& m) { return m.pts[r.next() % m.pts.size()]; }

inline I3 edge_point(Rng& r, const LatticeMesh& m) {
  const Tri3& t = m.tris[r.next() % m.tris.size()];
  int k = int(r.next() % 3);
  const I3 &a = m.pts[t[k]], &b = m.pts[t[(k + 1) % 3]];
  int64_t w = r.chance(40) ? 12 : r.range(1, 23);
  I3 step = sub3(b, a);
  for (int64_t& c : step) {
    if (c % 24 != 0) die("ray_mesh: an edge not a multiple of 24");
    c /= 24;
  }
  return add3(a, mul3(step, w));
}

inline I3 face_point(Rng& r, const LatticeMesh& m, int t, bool inside) {
  int64_t w1, w2;
  if (inside) {
    int64_t w0 = r.range(1, 22);
    w1 = r.range(1, 23 - w0), w2 = 24 - w0 - w1;
  } else {
    w1 = r.range(-30, 40), w2 = r.range(-30, 40);
  }
  // v0 + (w1 (v1 - v0) + w2 (v2 - v0)) / 24: the edges are multiples of 24
  // (an offset moves both ends).
  const Tri3& x = m.tris[t];
  I3 U = sub3(m.pts[x[1]], m.pts[x[0]]), V = sub3(m.pts[x[2]], m.pts[x[0]]);
  for (int64_t& c : U) c /= 24;
  for (int64_t& c : V) c /= 24;
  return add3(m.pts[x[0]], add3(mul3(U, w1), mul3(V, w2)));
}

// Calls make(r) until `n` queries are written (make returns how many it
// wrote), or dies: the generators of ray_mesh.cpp and mesh_points.cpp.
template <class File, class F>
void repeat(File& f, Rng& r, int n, F make) {
  int made = 0;
  for (int tries = 0; made < n; ++tries) {
    if (tries > 50 * n) die("mesh %s: a section keeps failing", f.mesh().name.c_str());
    made += make(r);
  }
}

}  // namespace fixtures
