// ray_mesh: one triangle mesh per file (ray_mesh-<name>.txt) with closest-hit
// (r) and shadow-segment (s) queries against it, answered exactly (`docs/fixture-format.md`'s
// ray_mesh rule: closed triangles; a ray in a triangle's plane enters it).
//
// Every mesh is built on an integer lattice (coordinates X 2^e, |X| < 2^53, all
// multiples of 24 before an offset, so that the points k/24 of the way along an
// edge are lattice points too), so rays exactly through shared edges and
// vertices, and rays exactly in a face's plane, are exact inputs. Each query's
// answer comes from GMP rationals, per triangle: the parameters [t_in, t_out]
// where the line meets the closed triangle (a point for a crossing; in the
// plane, the span between the edges' bounds), checked triangle by triangle
// against Epeck's do_intersect(Ray_3 or Segment_3, Triangle_3), and each hit's
// entry against the rational kernel's constructed intersection (a point or a
// segment). The first t is the least entry over the triangles; the tri list
// every triangle whose span holds it.

#include "lattice_mesh.h"
#include "ray.h"

#include <CGAL/intersections.h>

namespace fixtures {
namespace {

// ---------------------------------------------------------------------------
// Exact answers

struct Span {
  bool hit = false;
  Q lo, hi;  // the line's parameters on the closed triangle
};

// The parameters where the line o + t d lies on the closed triangle v (no
// hit for a degenerate triangle: the crate's meshes leave those out). Off
// the plane: the crossing t = n.(v0 - o) / n.d, inside when n.(E_i x (x -
// v_j)) >= 0 for each edge v_j -> v_m; in the plane: A_i + t B_i >= 0 with
// A_i = n.(E_i x (o - v_j)), B_i = n.(E_i x d).
Span line_span(const QV& o, const QV& d, const std::array<QV, 3>& v) {
  Span s;
  QV n = qcross(qsub(v[1], v[0]), qsub(v[2], v[0]));
  if (qzero(n)) return s;
  Q den = qdot(d, n), off = qdot(qsub(v[0], o), n);
  if (sgn(den) != 0) {
    Q t = off / den;
    QV x = qadd(o, qmul(d, t));
    for (int i = 0; i < 3; ++i) {
      const QV &a = v[(i + 1) % 3], &b = v[(i + 2) % 3];
      if (sgn(qdot(n, qcross(qsub(b, a), qsub(x, a)))) < 0) return s;
    }
    s.hit = true;
    s.lo = s.hi = t;
    return s;
  }
  if (sgn(off) != 0) return s;
  bool has_lo = false, has_hi = false;
  for (int i = 0; i < 3; ++i) {
    const QV &a = v[(i + 1) % 3], &b = v[(i + 2) % 3];
    QV E = qsub(b, a);
    Q A = qdot(n, qcross(E, qsub(o, a))), B = qdot(n, qcross(E, d));
    if (sgn(B) == 0) {
      if (sgn(A) < 0) return s;
      continue;
    }
    Q bound = -A / B;
    if (sgn(B) > 0) {
      if (!has_lo || bound > s.lo) s.lo = bound, has_lo = true;
    } else if (!has_hi || bound < s.hi) {
      s.hi = bound, has_hi = true;
    }
  }
  if (!has_lo || !has_hi) die("ray_mesh: a coplanar line without both bounds");
  s.hit = s.lo <= s.hi;
  return s;
}

struct Exact {
  std::vector<QV> v;
  std::vector<Tri3> tris;
  std::vector<Epeck::Triangle_3> ep;
  std::vector<RatK::Triangle_3> rat;
};

Exact exact_mesh(const std::vector<P3>& verts, const std::vector<Tri3>& tris) {
  Exact x;
  for (const P3& p : verts) x.v.push_back(QV{Q(p[0]), Q(p[1]), Q(p[2])});
  x.tris = tris;
  auto ep = [&](int i) { return Epeck::Point_3(verts[i][0], verts[i][1], verts[i][2]); };
  auto rp = [&](int i) { return RatK::Point_3(Rq(verts[i][0]), Rq(verts[i][1]), Rq(verts[i][2])); };
  for (const Tri3& t : tris) {
    x.ep.push_back(Epeck::Triangle_3(ep(t[0]), ep(t[1]), ep(t[2])));
    x.rat.push_back(RatK::Triangle_3(rp(t[0]), rp(t[1]), rp(t[2])));
  }
  return x;
}

std::array<QV, 3> tri_q(const Exact& m, int t) { return {m.v[m.tris[t][0]], m.v[m.tris[t][1]], m.v[m.tris[t][2]]}; }

struct RayAnswer {
  bool hit = false;
  Q t;
  std::vector<int> on;
  bool coplanar = false;  // some listed triangle holds the ray in its plane
};

RayAnswer ray_answer(const Exact& m, const P3& o, const P3& d) {
  QV qo{Q(o[0]), Q(o[1]), Q(o[2])}, qd{Q(d[0]), Q(d[1]), Q(d[2])};
  Epeck::Ray_3 ray(Epeck::Point_3(o[0], o[1], o[2]), Epeck::Vector_3(d[0], d[1], d[2]));
  RatK::Point_3 ro(Rq(o[0]), Rq(o[1]), Rq(o[2]));
  RatK::Vector_3 rd(Rq(d[0]), Rq(d[1]), Rq(d[2]));
  RatK::Ray_3 rray(ro, rd);
  std::vector<Span> spans(m.tris.size());
  RayAnswer a;
  for (size_t t = 0; t < m.tris.size(); ++t) {
    Span s = line_span(qo, qd, tri_q(m, int(t)));
    bool forward = s.hit && sgn(s.hi) >= 0;
    if (CGAL::do_intersect(ray, m.ep[t]) != forward) die("ray_mesh: do_intersect(Ray_3, Triangle_3) disagrees");
    if (!forward) {
      s.hit = false;
      spans[t] = s;
      continue;
    }
    if (sgn(s.lo) < 0) s.lo = 0;
    // The entry from the rational kernel's intersection: a point, or the
    // segment's end nearer the origin.
    auto x = CGAL::intersection(rray, m.rat[t]);
    if (!x) die("ray_mesh: no intersection where do_intersect holds");
    auto tof = [&](const RatK::Point_3& p) { return to_q(((p - ro) * rd) / (rd * rd)); };
    Q entry;
    if (const RatK::Point_3* p = boost::get<RatK::Point_3>(&*x)) {
      entry = tof(*p);
    } else if (const RatK::Segment_3* g = boost::get<RatK::Segment_3>(&*x)) {
      entry = std::min(tof(g->source()), tof(g->target()));
    } else {
      die("ray_mesh: an intersection that is neither a point nor a segment");
    }
    if (entry != s.lo) die("ray_mesh: CGAL's intersection enters at another t");
    spans[t] = s;
    if (!a.hit || s.lo < a.t) a.t = s.lo;
    a.hit = true;
  }
  if (!a.hit) return a;
  for (size_t t = 0; t < m.tris.size(); ++t) {
    const Span& s = spans[t];
    if (s.hit && s.lo <= a.t && a.t <= s.hi) {
      a.on.push_back(int(t));
      QV n = qcross(qsub(tri_q(m, int(t))[1], tri_q(m, int(t))[0]), qsub(tri_q(m, int(t))[2], tri_q(m, int(t))[0]));
      if (sgn(qdot(n, qd)) == 0) a.coplanar = true;
    }
  }
  return a;
}

bool segment_blocked(const Exact& m, const P3& p, const P3& q) {
  QV qp{Q(p[0]), Q(p[1]), Q(p[2])}, qq{Q(q[0]), Q(q[1]), Q(q[2])};
  QV d = qsub(qq, qp);
  Epeck::Segment_3 seg(Epeck::Point_3(p[0], p[1], p[2]), Epeck::Point_3(q[0], q[1], q[2]));
  bool blocked = false;
  for (size_t t = 0; t < m.tris.size(); ++t) {
    Span s = line_span(qp, d, tri_q(m, int(t)));
    bool meets = s.hit && s.lo <= 1 && sgn(s.hi) >= 0;
    if (CGAL::do_intersect(seg, m.ep[t]) != meets) die("ray_mesh: do_intersect(Segment_3, Triangle_3) disagrees");
    blocked |= meets;
  }
  return blocked;
}

// Whether the point lies on some triangle (the segment's ends must not).
bool on_mesh(const Exact& m, const P3& p) {
  Epeck::Point_3 x(p[0], p[1], p[2]);
  for (const auto& t : m.ep)
    if (t.has_on(x)) return true;
  return false;
}

// ---------------------------------------------------------------------------
// Output

// One ray_mesh file: the mesh, then sections of queries. Each section states
// what it must contain: 'h' a hit, 'm' a miss, '2' a hit on a point shared by
// two or more triangles, 'c' a hit of a ray in a listed triangle's plane, 'b'
// a blocked segment, 'f' a free one.
class MeshFile {
 public:
  MeshFile(const LatticeMesh& mesh) : mesh_(mesh), verts_(mesh.vertices()), exact_(exact_mesh(verts_, mesh.tris)) {
    out_ += "# ray_mesh fixtures, mesh \"" + mesh.name + "\": " + mesh.what + "\n";
    out_ += "# v x y z; f i j k (indices from 0); r ox oy oz dx dy dz hit [t tri...]: the exact first\n";
    out_ += "# t >= 0 on the closed triangles (a ray in a triangle's plane enters it), rounded to\n";
    out_ += "# nearest, and every triangle containing that point; s px py pz qx qy qz blocked: the\n";
    out_ += "# closed segment meets a triangle. GMP rationals per triangle, checked against Epeck's\n";
    out_ += "# do_intersect and the rational kernel's intersection. Generated by\n";
    out_ += "# tools/cgal-fixtures/generate.cpp; do not edit, rerun tools/cgal-fixtures/regenerate.sh.\n";
    for (const P3& p : verts_) out_ += "v " + format_coord(p[0]) + " " + format_coord(p[1]) + " " + format_coord(p[2]) + "\n";
    for (const Tri3& t : mesh.tris)
      out_ += "f " + std::to_string(t[0]) + " " + std::to_string(t[1]) + " " + std::to_string(t[2]) + "\n";
  }

  const LatticeMesh& mesh() const { return mesh_; }
  const Exact& exact() const { return exact_; }

  Rng section(const std::string& name, const std::string& what, const char* must) {
    end_section();
    section_ = name;
    must_ = must;
    out_ += "\n# section " + name + ": " + what + "\n";
    return Rng(fnv1a("ray_mesh/" + mesh_.name + "/" + name));
  }

  // Writes the ray's line; false (nothing written) when its t is not a
  // normal double or zero.
  bool ray(const P3& o, const P3& d) {
    if (d == P3{0, 0, 0}) return false;
    RayAnswer a = ray_answer(exact_, o, d);
    std::string line = "r " + coords(o) + " " + coords(d);
    if (!a.hit) {
      line += " 0";
      ++stats_['m'];
    } else {
      bool ok = true;
      double t = nearest_rational(a.t, ok);
      if (!ok) return false;
      line += " 1 " + format_coord(t);
      for (int i : a.on) line += " " + std::to_string(i);
      ++stats_['h'];
      if (a.on.size() >= 2) ++stats_['2'];
      if (a.coplanar) ++stats_['c'];
    }
    out_ += line + "\n";
    ++n_;
    return true;
  }

  // Writes the segment's line; false when an end lies on the mesh.
  bool segment(const P3& p, const P3& q) {
    if (on_mesh(exact_, p) || on_mesh(exact_, q)) return false;
    bool b = segment_blocked(exact_, p, q);
    out_ += "s " + coords(p) + " " + coords(q) + (b ? " 1" : " 0") + "\n";
    ++stats_[b ? 'b' : 'f'];
    ++n_;
    return true;
  }

  void finish(const std::string& outdir) {
    end_section();
    std::string path = outdir + "/ray_mesh-" + mesh_.name + ".txt";
    write_file(path, out_);
    std::fprintf(stderr, "%-12s %5d queries %8zu bytes  %s\n", "ray_mesh", total_, out_.size(), path.c_str());
  }

 private:
  static std::string coords(const P3& p) {
    return format_coord(p[0]) + " " + format_coord(p[1]) + " " + format_coord(p[2]);
  }

  void end_section() {
    if (section_.empty()) return;
    for (const char* c = must_; *c; ++c)
      if (stats_[*c] == 0) die("ray_mesh-%s/%s: no query of class %c", mesh_.name.c_str(), section_.c_str(), *c);
    std::fprintf(stderr, "ray_mesh-%-12s %-14s %4d queries (hit %d, shared %d, coplanar %d, miss %d; blocked %d, free %d)\n",
                 mesh_.name.c_str(), section_.c_str(), n_, stats_['h'], stats_['2'], stats_['c'], stats_['m'],
                 stats_['b'], stats_['f']);
    total_ += n_;
    n_ = 0;
    stats_.clear();
    section_.clear();
  }

  LatticeMesh mesh_;
  std::vector<P3> verts_;
  Exact exact_;
  std::string out_, section_;
  const char* must_ = "";
  std::map<char, int> stats_;
  int n_ = 0, total_ = 0;
};

// ---------------------------------------------------------------------------
// Query constructions. X is a lattice point (integers); rays o = X - S D,
// d = D 2^k, with D an integer direction, are exact.

// A direction from `from` towards `to` (integers), plus a random integer
// jitter of up to 2^j, never zero.
I3 towards(Rng& r, const I3& from, const I3& to, int j) {
  I3 D;
  do D = add3(sub3(to, from), bits3(r, j));
  while (zero3(D));
  return D;
}

// Bits of a direction about as long as the mesh is wide.
int mesh_bits(const LatticeMesh& m) {
  I3 ext = sub3(m.hi(), m.lo());
  int64_t w = std::max({ext[0], ext[1], ext[2], int64_t(1)});
  return std::max(1, 62 - __builtin_clzll(uint64_t(w)));
}

// A ray exactly through X from a random point around the mesh (distance
// about 2^spread lattice units beyond the box), d = D 2^k.
int ray_through(MeshFile& f, Rng& r, const I3& X, int spread) {
  const LatticeMesh& m = f.mesh();
  I3 from = add3(m.centre(), bits3(r, spread));
  I3 D = towards(r, from, X, 3);
  int64_t S = r.range(1, 4);
  P3 o = m.at(sub3(X, mul3(D, S)));
  P3 d = lattice3(D, m.e + int(r.range(-4, 4)));
  return f.ray(o, d) ? 1 : 0;
}

// The same through X moved by 1 or 2 ulps in one coordinate: o = x - step
// computed in f64 and kept only if exact.
int ray_near(MeshFile& f, Rng& r, const I3& X) {
  const LatticeMesh& m = f.mesh();
  P3 x = m.at(X);
  double& c = x[r.next() % 3];
  c = step_ulps(c, int(r.range(1, 2)) * r.sign());
  // An origin about a mesh width from x, so that o = x - step keeps x's
  // last bits (checked).
  I3 D = nonzero_bits3(r, mesh_bits(m));
  P3 step = lattice3(D, m.e);
  P3 o = psub(x, step);
  for (int i = 0; i < 3; ++i)
    if (Q(o[i]) != Q(x[i]) - Q(step[i])) return 0;
  return f.ray(o, lattice3(D, m.e + int(r.range(-4, 4)))) ? 1 : 0;
}

// A ray in the plane of face t: from a lattice point of the plane (inside
// the face, or anywhere), along a lattice direction of the plane.
int ray_coplanar(MeshFile& f, Rng& r, int t, bool inside) {
  const LatticeMesh& m = f.mesh();
  const Tri3& x = m.tris[t];
  I3 U = sub3(m.pts[x[1]], m.pts[x[0]]), V = sub3(m.pts[x[2]], m.pts[x[0]]);
  for (int64_t& c : U) c /= 24;
  for (int64_t& c : V) c /= 24;
  I3 O = face_point(r, m, t, inside), D;
  do D = add3(mul3(U, r.range(-6, 6)), mul3(V, r.range(-6, 6)));
  while (zero3(D));
  if (!inside && r.chance(60)) {
    // Aimed back through a point of the face (entering through an edge).
    I3 T = face_point(r, m, t, true);
    D = sub3(T, O);
    if (zero3(D)) return 0;
  }
  return f.ray(m.at(O), lattice3(D, m.e + int(r.range(-4, 4)))) ? 1 : 0;
}

// Nearly parallel to face t: the coplanar ray with its origin moved 1 ulp
// off the plane, or its direction tilted by a tiny multiple of the normal.
int ray_nearly_parallel(MeshFile& f, Rng& r, int t) {
  const LatticeMesh& m = f.mesh();
  const Tri3& x = m.tris[t];
  I3 U = sub3(m.pts[x[1]], m.pts[x[0]]), V = sub3(m.pts[x[2]], m.pts[x[0]]);
  I3 O = face_point(r, m, t, false), T = face_point(r, m, t, true);
  I3 D = sub3(T, O);
  if (zero3(D)) return 0;
  P3 o = m.at(O), d = lattice3(D, m.e);
  if (r.chance(50)) {
    double& c = o[r.next() % 3];
    c = step_ulps(c, r.sign());
  } else {
    I3 N = cross3(U, V);
    int64_t g = std::max({std::llabs(N[0]), std::llabs(N[1]), std::llabs(N[2])});
    int sh = 63 - __builtin_clzll(uint64_t(g));
    P3 tilt = lattice3(N, m.e - sh - int(r.range(20, 40)));
    for (int k = 0; k < 3; ++k) {
      double y = d[k] + tilt[k];
      if (Q(y) != Q(d[k]) + Q(tilt[k])) return 0;
      d[k] = y;
    }
  }
  return f.ray(o, d) ? 1 : 0;
}

// A segment through X: p = X - S D, q = X + S' D (both off the mesh), or
// ending short of X (q = X - D / 2^k), or X moved by an ulp.
int segment_through(MeshFile& f, Rng& r, const I3& X, int spread, int mode) {
  const LatticeMesh& m = f.mesh();
  I3 from = add3(m.centre(), bits3(r, spread));
  I3 D = towards(r, from, X, 3);
  P3 p = m.at(sub3(X, mul3(D, r.range(1, 3)))), q;
  switch (mode) {
    case 0: q = m.at(add3(X, mul3(D, r.range(1, 3)))); break;
    case 1: {
      // Just short of X: q = X - D 2^-k, exact or skipped.
      P3 x = m.at(X), step = lattice3(D, m.e - int(r.range(20, 52)));
      q = psub(x, step);
      for (int i = 0; i < 3; ++i)
        if (Q(q[i]) != Q(x[i]) - Q(step[i])) return 0;
      break;
    }
    default: {
      q = m.at(X);
      double& c = q[r.next() % 3];
      c = step_ulps(c, r.sign());
    }
  }
  return f.segment(p, q) ? 1 : 0;
}

// A segment in the plane of face t, between two lattice points of the plane.
int segment_coplanar(MeshFile& f, Rng& r, int t) {
  const LatticeMesh& m = f.mesh();
  I3 a = face_point(r, m, t, false), b = face_point(r, m, t, false);
  if (a == b) return 0;
  return f.segment(m.at(a), m.at(b)) ? 1 : 0;
}

// A random ray from around the mesh towards a random point of its box.
int ray_random(MeshFile& f, Rng& r, int spread) {
  const LatticeMesh& m = f.mesh();
  I3 lo = m.lo(), hi = m.hi(), T;
  for (int k = 0; k < 3; ++k) T[k] = r.range(lo[k], hi[k]);
  I3 from = add3(m.centre(), bits3(r, spread));
  if (from == T) return 0;
  return f.ray(m.at(from), lattice3(sub3(T, from), m.e)) ? 1 : 0;
}

// The common sections: rays through vertices and edge points exactly and
// 1-2 ulps off, through faces, random, from the mesh's points (t = 0), and
// segments; `closed` adds rays from inside, `coplanar` rays in face planes.
void common_sections(MeshFile& f, int spread, bool closed, bool coplanar, int n) {
  const LatticeMesh& m = f.mesh();
  Rng r = f.section("vertices", "rays exactly through a vertex, from around the mesh", "h2");
  repeat(f, r, n, [&](Rng& r) { return ray_through(f, r, vertex_point(r, m), spread); });
  r = f.section("edges", "rays exactly through a point k/24 along an edge (the midpoint 40% of the time)", "h2");
  repeat(f, r, n, [&](Rng& r) { return ray_through(f, r, edge_point(r, m), spread); });
  r = f.section("near-vertices", "the vertex rays through the vertex moved by 1-2 ulps in one coordinate", "h");
  repeat(f, r, n / 2, [&](Rng& r) { return ray_near(f, r, vertex_point(r, m)); });
  r = f.section("near-edges", "the edge rays through the edge point moved by 1-2 ulps in one coordinate", "h");
  repeat(f, r, n / 2, [&](Rng& r) { return ray_near(f, r, edge_point(r, m)); });
  r = f.section("faces", "rays through lattice points inside faces, and random rays at the mesh's box", "h");
  repeat(f, r, n / 2, [&](Rng& r) {
    return ray_through(f, r, face_point(r, m, int(r.next() % m.tris.size()), true), spread);
  });
  repeat(f, r, n / 2, [&](Rng& r) { return ray_random(f, r, spread); });
  r = f.section("origin-on", "origins exactly at a vertex, an edge point or a face point; random directions: t = 0",
                "h2");
  repeat(f, r, n / 2, [&](Rng& r) {
    I3 X;
    switch (r.next() % 3) {
      case 0: X = vertex_point(r, m); break;
      case 1: X = edge_point(r, m); break;
      default: X = face_point(r, m, int(r.next() % m.tris.size()), true);
    }
    I3 D = nonzero_bits3(r, 8);
    return f.ray(m.at(X), lattice3(D, m.e)) ? 1 : 0;
  });
  if (closed) {
    r = f.section("inside", "origins inside the closed mesh (at its centre), aimed exactly at vertices and edge points",
                  "h2");
    repeat(f, r, n / 2, [&](Rng& r) {
      I3 X = r.chance(50) ? vertex_point(r, m) : edge_point(r, m), C = m.centre();
      if (X == C) return 0;
      return f.ray(m.at(C), lattice3(sub3(X, C), m.e + int(r.range(-3, 3)))) ? 1 : 0;
    });
  }
  if (coplanar) {
    r = f.section("coplanar", "rays exactly in a face's plane: entering through an edge, or starting inside the face",
                  "hc");
    repeat(f, r, n, [&](Rng& r) { return ray_coplanar(f, r, int(r.next() % m.tris.size()), r.chance(30)); });
    r = f.section("nearly-parallel", "the coplanar rays moved 1 ulp off the plane or tilted by 2^-20..2^-40", "h");
    repeat(f, r, n / 2, [&](Rng& r) { return ray_nearly_parallel(f, r, int(r.next() % m.tris.size())); });
  }
  r = f.section("segments", "segments through vertices and edge points exactly, ending just short of them, or ending 1 ulp off them", "bf");
  repeat(f, r, n, [&](Rng& r) {
    I3 X = r.chance(50) ? vertex_point(r, m) : edge_point(r, m);
    return segment_through(f, r, X, spread, int(r.next() % 3));
  });
  if (coplanar) {
    r = f.section("segments-coplanar", "segments in a face's plane between lattice points of the plane", "bf");
    repeat(f, r, n / 2, [&](Rng& r) { return segment_coplanar(f, r, int(r.next() % m.tris.size())); });
  }
}

// Across the whole range: a mesh at 2^971 (ends of the lattice at
// +-(2^53 - 1) 2^971 = +-f64::MAX), queries whose ends lie on opposite
// sides of it, through a vertex or edge point X exactly: a ray from X - D
// along D 2^-k (t = 2^k), a segment from X - D to X + D, or either moved
// by a lattice offset (mostly missing). |D| >= 2^52 on one axis, so that
// the segment's q - p (2 D 2^971) overflows.
I3 across(Rng& r, const I3& X) {
  // Room for an offset of up to 2^46 on every coordinate.
  const int64_t lim = (int64_t(1) << 53) - 1 - (int64_t(1) << 47);
  I3 D;
  for (int k = 0; k < 3; ++k) {
    int64_t room = lim - std::llabs(X[k]);
    D[k] = r.range(-room, room);
  }
  int a = int(r.next() % 3);
  D[a] = r.sign() * r.range(int64_t(1) << 52, lim - std::llabs(X[a]));
  return D;
}

int ray_across(MeshFile& f, Rng& r, const I3& X) {
  const LatticeMesh& m = f.mesh();
  I3 D = across(r, X);
  I3 off = r.chance(30) ? bits3(r, 46) : I3{0, 0, 0};
  return f.ray(m.at(add3(sub3(X, D), off)), lattice3(D, m.e - int(r.range(0, 4)))) ? 1 : 0;
}

int segment_across(MeshFile& f, Rng& r, const I3& X) {
  const LatticeMesh& m = f.mesh();
  I3 D = across(r, X);
  I3 off = r.chance(40) ? bits3(r, 46) : I3{0, 0, 0};
  return f.segment(m.at(add3(sub3(X, D), off)), m.at(add3(add3(X, D), off))) ? 1 : 0;
}

void write_range_mesh(const std::string& outdir, int n) {
  LatticeMesh m = octasphere(1, int64_t(1) << 43, 971);
  m.name = "range";
  m.what = "an octahedron subdivided once (32 triangles; closed), radius 1.5 2^1019, rays and segments from one end "
           "of the range to the other";
  MeshFile f(m);
  Rng r = f.section("rays-across", "rays from beyond 2^1020 on one side through a vertex or edge point, or offset", "hm");
  repeat(f, r, n, [&](Rng& r) { return ray_across(f, r, r.chance(50) ? vertex_point(r, m) : edge_point(r, m)); });
  r = f.section("segments-across",
                "segments between ends on opposite sides of the range (q - p overflows), through a vertex or edge "
                "point, or offset",
                "bf");
  repeat(f, r, n, [&](Rng& r) { return segment_across(f, r, r.chance(50) ? vertex_point(r, m) : edge_point(r, m)); });
  f.finish(outdir);
}

// Writes ray_mesh-<name>.txt: the mesh and its common sections.
void write_mesh(const std::string& outdir, LatticeMesh m, const char* name, const char* what, int spread, bool closed,
                bool coplanar, int n) {
  m.name = name;
  m.what = what;
  MeshFile f(m);
  common_sections(f, spread, closed, coplanar, n);
  f.finish(outdir);
}

}  // namespace

void gen_ray_mesh_files(const std::string& outdir) {
  write_mesh(outdir, octahedron(24 * 20, -4), "octahedron",
             "the octahedron with vertices at +-30 on the axes (8 triangles; closed)", 12, true, true, 40);
  write_mesh(outdir, cube(24 * 16, -6), "cube",
             "the cube [-6, 6]^3 in 12 triangles (closed; each face two coplanar triangles)", 12, true, true, 40);
  write_mesh(outdir, octasphere(2, 1 << 12, -10), "octasphere",
             "an octahedron subdivided twice, vertices rounded onto a sphere of radius 96 (128 triangles; closed)", 18,
             true, false, 40);
  Rng r(fnv1a("ray_mesh/heightfield/mesh"));
  write_mesh(outdir, height_field(r, 8, 4, 6, -5), "heightfield",
             "an 8x8 tiled height field, random integer heights, random diagonals (128 triangles; open)", 12, false,
             true, 40);
  LatticeMesh far = octasphere(1, 1 << 10, 0);
  far.shift(I3{100000000, -70000000, 40000000});
  write_mesh(outdir, far, "far",
             "an octahedron subdivided once (32 triangles; closed), radius 24576, offset (1e8, -7e7, 4e7)", 17, true,
             false, 30);
  Rng rf(fnv1a("ray_mesh/far-heightfield/mesh"));
  LatticeMesh far_field = height_field(rf, 8, 4, 6, 0);
  far_field.shift(I3{1000000, -2000000, 3000000});
  write_mesh(outdir, far_field, "far-heightfield",
             "an 8x8 tiled height field (128 triangles; open), integer coordinates, offset (1e6, -2e6, 3e6)", 12,
             false, true, 40);
  LatticeMesh nested = octasphere(1, 1 << 20, -20), inner = octasphere(1, (1 << 20) - 1, -20);
  int base = int(nested.pts.size());
  for (const I3& p : inner.pts) nested.pts.push_back(p);
  for (const Tri3& t : inner.tris) nested.tris.push_back({t[0] + base, t[1] + base, t[2] + base});
  write_mesh(outdir, nested, "nested",
             "two octahedra subdivided once, radii 24 and 24 (1 - 2^-20): one inside the other, 64 triangles", 26,
             true, false, 30);
  write_range_mesh(outdir, 40);
}

}  // namespace fixtures
