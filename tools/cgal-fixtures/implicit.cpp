// orient3d_lpi, orient3d_tpi, orient2d_ssi, less_on_axis_lpi: predicates on
// constructed points (docs/fixture-format.md, "Predicates on constructed points"). The
// intersection point is constructed exactly with CGAL's
// Exact_predicates_exact_constructions_kernel (Epeck), then the exact
// predicate is asked of it; plain rational arithmetic (RatK) constructs and
// asks again, and any disagreement stops the generator (see `block` for the
// scaled sections). Every case is one point: a construction CGAL does not
// return as a single point is drawn again.
//
// Sections: random inputs; the point exactly on the plane (line) of the
// explicit points; the same moved by 1-2 ulps; lines nearly parallel to their
// planes (planes nearly parallel to one another); crossings that coincide
// exactly (every construction through one dyadic point); and any of those
// scaled to tiny, huge and mixed magnitudes.

#include "common.h"

namespace fixtures {
namespace {

template <class K>
typename K::Point_3 pt(const P3& v) {
  return typename K::Point_3(v[0], v[1], v[2]);
}

template <class K>
typename K::Point_2 pt(const P2& v) {
  return typename K::Point_2(v[0], v[1]);
}

// The point where the line through p, q meets the plane through r, s, t, if
// that is one point.
template <class K>
bool lpi(const P3* v, typename K::Point_3& out) {
  auto p = pt<K>(v[0]), q = pt<K>(v[1]), r = pt<K>(v[2]), s = pt<K>(v[3]), t = pt<K>(v[4]);
  if (p == q || CGAL::collinear(r, s, t)) return false;
  auto x = CGAL::intersection(typename K::Line_3(p, q), typename K::Plane_3(r, s, t));
  const typename K::Point_3* x3 = x ? boost::get<typename K::Point_3>(&*x) : nullptr;
  if (x3) out = *x3;
  return x3 != nullptr;
}

// The common point of the planes through v[0..3], v[3..6], v[6..9], if one.
template <class K>
bool tpi(const P3* v, typename K::Point_3& out) {
  for (int i = 0; i < 3; ++i)
    if (CGAL::collinear(pt<K>(v[3 * i]), pt<K>(v[3 * i + 1]), pt<K>(v[3 * i + 2]))) return false;
  auto plane = [&](int i) { return typename K::Plane_3(pt<K>(v[3 * i]), pt<K>(v[3 * i + 1]), pt<K>(v[3 * i + 2])); };
  auto x = CGAL::intersection(plane(0), plane(1), plane(2));
  const typename K::Point_3* x3 = x ? boost::get<typename K::Point_3>(&*x) : nullptr;
  if (x3) out = *x3;
  return x3 != nullptr;
}

// The point where the line through p, q meets the line through r, s.
template <class K>
bool ssi(const P2* v, typename K::Point_2& out) {
  if (v[0] == v[1] || v[2] == v[3]) return false;
  auto x = CGAL::intersection(typename K::Line_2(pt<K>(v[0]), pt<K>(v[1])),
                              typename K::Line_2(pt<K>(v[2]), pt<K>(v[3])));
  const typename K::Point_2* x2 = x ? boost::get<typename K::Point_2>(&*x) : nullptr;
  if (x2) out = *x2;
  return x2 != nullptr;
}

const P3* p3s(const Case& c) { return reinterpret_cast<const P3*>(c.data()); }
const P2* p2s(const Case& c) { return reinterpret_cast<const P2*>(c.data()); }

// The exact answers in kernel K, or 2 for a construction that is not one
// point.
template <class K>
int orient3d_lpi_sign(const Case& c) {
  const P3* v = p3s(c);
  typename K::Point_3 x;
  if (!lpi<K>(v + 3, x)) return 2;
  return int(CGAL::orientation(pt<K>(v[0]), pt<K>(v[1]), pt<K>(v[2]), x));
}

template <class K>
int orient3d_tpi_sign(const Case& c) {
  const P3* v = p3s(c);
  typename K::Point_3 x;
  if (!tpi<K>(v + 3, x)) return 2;
  return int(CGAL::orientation(pt<K>(v[0]), pt<K>(v[1]), pt<K>(v[2]), x));
}

template <class K>
int orient2d_ssi_sign(const Case& c) {
  const P2* v = p2s(c);
  typename K::Point_2 x;
  if (!ssi<K>(v + 2, x)) return 2;
  return int(CGAL::orientation(pt<K>(v[0]), pt<K>(v[1]), x));
}

// The case is the axis, then ten points.
template <class K>
int less_on_axis_lpi_sign(const Case& c) {
  const P3* v = reinterpret_cast<const P3*>(c.data() + 1);
  typename K::Point_3 x, y;
  if (!lpi<K>(v, x) || !lpi<K>(v + 5, y)) return 2;
  int axis = int(c[0]);
  return int(axis == 0 ? CGAL::compare_x(x, y) : axis == 1 ? CGAL::compare_y(x, y) : CGAL::compare_z(x, y));
}

// Plain f64: the point constructed by the textbook formula, then the f64
// predicate (only for the statistics the generator prints).
int sign_of(double d) { return (d > 0) - (d < 0); }

P3 round_lpi(const P3* v) {
  P3 n = pcross(psub(v[3], v[2]), psub(v[4], v[2])), e = psub(v[1], v[0]);
  return padd(v[0], pmul(e, pdot(n, psub(v[2], v[0])) / pdot(n, e)));
}

P3 round_tpi(const P3* v) {
  P3 n[3], d;
  for (int i = 0; i < 3; ++i) {
    n[i] = pcross(psub(v[3 * i + 1], v[3 * i]), psub(v[3 * i + 2], v[3 * i]));
    d[i] = pdot(n[i], v[3 * i]);
  }
  P3 c0 = pcross(n[1], n[2]), c1 = pcross(n[2], n[0]), c2 = pcross(n[0], n[1]);
  return pmul(padd(padd(pmul(c0, d[0]), pmul(c1, d[1])), pmul(c2, d[2])), 1.0 / pdot(n[0], c0));
}

int orient3d_f64(const P3& a, const P3& b, const P3& c, const P3& d) {
  return sign_of(pdot(psub(b, a), pcross(psub(c, a), psub(d, a))));
}

int orient3d_lpi_naive(const Case& c) {
  const P3* v = p3s(c);
  return orient3d_f64(v[0], v[1], v[2], round_lpi(v + 3));
}

int orient3d_tpi_naive(const Case& c) {
  const P3* v = p3s(c);
  return orient3d_f64(v[0], v[1], v[2], round_tpi(v + 3));
}

int orient2d_ssi_naive(const Case& c) {
  const P2* v = p2s(c);
  P2 e = {v[3][0] - v[2][0], v[3][1] - v[2][1]}, f = {v[5][0] - v[4][0], v[5][1] - v[4][1]};
  P2 g = {v[4][0] - v[2][0], v[4][1] - v[2][1]};
  double t = (g[0] * f[1] - g[1] * f[0]) / (e[0] * f[1] - e[1] * f[0]);
  P2 x = {v[2][0] + t * e[0], v[2][1] + t * e[1]};
  return sign_of((v[1][0] - v[0][0]) * (x[1] - v[0][1]) - (v[1][1] - v[0][1]) * (x[0] - v[0][0]));
}

int less_on_axis_lpi_naive(const Case& c) {
  const P3* v = reinterpret_cast<const P3*>(c.data() + 1);
  int axis = int(c[0]);
  return sign_of(round_lpi(v)[axis] - round_lpi(v + 5)[axis]);
}

// ---------------------------------------------------------------------------
// Building blocks: dyadic points (multiples of 2^-6 in [-1, 1)), affine
// combinations with weights that are multiples of 1/8 (exact on dyadic
// points), lines and planes through a point.

P3 dyadic3(Rng& r) { return P3{r.range(-64, 63) / 64.0, r.range(-64, 63) / 64.0, r.range(-64, 63) / 64.0}; }
P2 dyadic2(Rng& r) { return P2{r.range(-64, 63) / 64.0, r.range(-64, 63) / 64.0}; }
P3 arb3(Rng& r) { return P3{arbitrary(r), arbitrary(r), arbitrary(r)}; }
P2 arb2(Rng& r) { return P2{arbitrary(r), arbitrary(r)}; }
double weight(Rng& r) { return r.range(-16, 16) / 8.0; }

P3 combo3(Rng& r, const P3& a, const P3& b, const P3& c) {
  return padd(a, padd(pmul(psub(b, a), weight(r)), pmul(psub(c, a), weight(r))));
}

P2 combo2(Rng& r, const P2& a, const P2& b) {
  double w = weight(r);
  return P2{a[0] + w * (b[0] - a[0]), a[1] + w * (b[1] - a[1])};
}

// Three points whose centroid is x: a plane through x.
std::array<P3, 3> plane_through(Rng& r, const P3& x) {
  P3 u = dyadic3(r), v = dyadic3(r);
  return {padd(x, u), padd(x, v), psub(psub(x, u), v)};
}

// x + d and x - m d: a line through x.
template <class P>
std::array<P, 2> line_through(Rng& r, const P& x) {
  P d, p, q;
  double m = r.range(1, 8) / 4.0;
  for (size_t k = 0; k < x.size(); ++k) d[k] = r.range(-64, 63) / 64.0;
  for (size_t k = 0; k < x.size(); ++k) p[k] = x[k] + d[k], q[k] = x[k] - m * d[k];
  return {p, q};
}

Case cat3(std::initializer_list<P3> pts) {
  Case v;
  for (const P3& p : pts) v.insert(v.end(), p.begin(), p.end());
  return v;
}

Case cat2(std::initializer_list<P2> pts) {
  Case v;
  for (const P2& p : pts) v.insert(v.end(), p.begin(), p.end());
  return v;
}

// Moves 1 or 2 coordinates (not `skip` leading ones) by 1 or 2 ulps.
void nudge(Rng& r, Case& v, size_t skip = 0) {
  int n = 1 + r.chance(40);
  for (int i = 0; i < n; ++i) {
    double& x = v[skip + r.next() % (v.size() - skip)];
    x = step_ulps(x, int(r.range(1, 2)) * r.sign());
  }
}

// Each axis of every point (`dim` coordinates each, after `skip` leading
// values) times its own power of two; false where that is not exact.
bool scale_axes(Case& v, size_t skip, int dim, const std::vector<int>& e) {
  for (size_t i = skip; i < v.size(); ++i) {
    int k = e[(i - skip) % dim];
    double y = std::ldexp(v[i], k);
    if (!std::isfinite(y) || std::ldexp(y, -k) != v[i]) return false;
    v[i] = y;
  }
  return true;
}

// A kind: its exact and naive answers, how many leading values are not
// coordinates, the dimension, and a unit-scale case builder per section.
enum class Shape { Random, On, Parallel, Coincide };

struct ImplicitKind {
  // The answer with Epeck and with plain rationals.
  int (*exact)(const Case&);
  int (*rational)(const Case&);
  int (*naive)(const Case&);
  size_t skip;
  int dim;
  Case (*build)(Rng&, Shape);
};

// Emits `n` cases of `shape`, nudged or scaled as asked, drawing again any
// whose construction is not one point, or whose scaling would round. Scaling
// by powers of two (one, or one per axis) leaves every sign of these
// predicates as it is, so Epeck answers the case before its scaling (its
// lazy constructions return a wrong empty intersection of two lines whose
// coefficients overflow, near 1e155); the rational kernel answers the
// scaled case as written, and the two must agree.
void block(Writer& w, const ImplicitKind& k, const std::string& label, int n, Shape shape, bool nudged,
           int scaling) {
  Rng r = w.block(label);
  for (int i = 0; i < n;) {
    Case v = k.build(r, shape);
    if (nudged) nudge(r, v, k.skip);
    const Case unit = v;
    bool ok = true;
    if (scaling == 1 || scaling == 2) {  // tiny, huge: one power of two
      int e = scaling == 1 ? int(r.chance(50) ? r.range(-560, -500) : r.range(-1060, -1000))
                           : int(r.chance(50) ? r.range(500, 560) : r.range(900, 1000));
      ok = scale_axes(v, k.skip, k.dim, std::vector<int>(size_t(k.dim), e));
    } else if (scaling == 3) {  // mixed: each axis its own
      std::vector<int> e;
      for (int a = 0; a < k.dim; ++a) e.push_back(int(r.chance(50) ? r.range(800, 960) : r.range(-1050, -900)));
      ok = scale_axes(v, k.skip, k.dim, e);
    }
    if (!ok) continue;
    int s = k.exact(unit);
    if (k.rational(v) != s) die("%s: Epeck (%d) and rational (%d) disagree", label.c_str(), s, k.rational(v));
    if (s == 2) continue;
    w.emit(v, s, k.naive(v));
    ++i;
  }
}

void implicit_sections(Writer& w, const ImplicitKind& k, const char* on_what, int n) {
  w.section("random", "inputs uniform in [-1, 1]", "+-", "+-0");
  block(w, k, "uniform", n, Shape::Random, false, 0);
  w.section("on", std::string("the constructed point exactly on ") + on_what + ", no rounding in the construction",
            "0", "0");
  block(w, k, "dyadic combinations or shared input points", n, Shape::On, false, 0);
  w.section("near", std::string("the same moved by 1-2 ulps: the point 1-2 ulps off ") + on_what, "+-", "+-0");
  block(w, k, "exactly on, then 1-2 coordinates moved by 1-2 ulps", n, Shape::On, true, 0);
  w.section("nearly-parallel", "lines nearly parallel to their planes (or planes to one another): far points",
            "+-", "+-0");
  block(w, k, "directions rounded from parallel, some moved by 1-2 ulps", n / 2, Shape::Parallel, false, 0);
  block(w, k, "the same, moved by 1-2 ulps", n / 2, Shape::Parallel, true, 0);
  w.section("coincide", "every construction through one dyadic point, which lies on the other object", "0", "0");
  block(w, k, "lines and planes through a dyadic point", n, Shape::Coincide, false, 0);
  const char* names[3] = {"tiny", "huge", "mixed"};
  const char* what[3] = {"every coordinate times 2^-k, k in 500..560 or 1000..1060: products underflow",
                         "every coordinate times 2^k, k in 500..560 or 900..1000: products overflow",
                         "each axis times its own 2^k, k in 800..960 or -1050..-900"};
  for (int s = 0; s < 3; ++s) {
    w.section(names[s], what[s], "+-0", "+-0");
    block(w, k, "random", n / 4, Shape::Random, false, s + 1);
    block(w, k, "exactly on", n / 4, Shape::On, false, s + 1);
    block(w, k, "1-2 ulps off", n / 4, Shape::On, true, s + 1);
    block(w, k, "coinciding", n / 4, Shape::Coincide, false, s + 1);
  }
}

// ---------------------------------------------------------------------------
// The kinds' unit-scale cases.

// a, b, c, p, q, r, s, t.
Case build_lpi(Rng& r, Shape shape) {
  switch (shape) {
    case Shape::Random: {
      Case v;
      for (int i = 0; i < 24; ++i) v.push_back(r.sym());
      return v;
    }
    case Shape::On: {
      P3 a = dyadic3(r), b = dyadic3(r), c = dyadic3(r);
      switch (r.next() % 4) {
        case 0: return cat3({a, b, c, combo3(r, a, b, c), combo3(r, a, b, c), arb3(r), arb3(r), arb3(r)});
        case 1: return cat3({a, b, c, arb3(r), arb3(r), combo3(r, a, b, c), combo3(r, a, b, c), combo3(r, a, b, c)});
        case 2: {  // arbitrary doubles: the plane is the triangle's
          P3 x = arb3(r), y = arb3(r), z = arb3(r);
          return cat3({x, y, z, arb3(r), arb3(r), y, z, x});
        }
        default: {  // arbitrary doubles: the line lies in the triangle
          P3 x = arb3(r), y = arb3(r);
          return cat3({x, y, arb3(r), y, x, arb3(r), arb3(r), arb3(r)});
        }
      }
    }
    case Shape::Parallel: {
      P3 rr = arb3(r), s = arb3(r), t = arb3(r), p = arb3(r);
      P3 q = padd(p, padd(pmul(psub(s, rr), r.sym()), pmul(psub(t, rr), r.sym())));
      if (r.chance(30)) return cat3({rr, s, t, p, q, rr, s, t});  // on the plane anyway
      return cat3({arb3(r), arb3(r), arb3(r), p, q, rr, s, t});
    }
    case Shape::Coincide: {
      P3 x = dyadic3(r);
      auto [p, q] = line_through(r, x);
      auto pl = plane_through(r, x);
      auto tri = plane_through(r, x);
      return cat3({tri[0], tri[1], tri[2], p, q, pl[0], pl[1], pl[2]});
    }
  }
  return {};
}

// a, b, c, then three planes.
Case build_tpi(Rng& r, Shape shape) {
  switch (shape) {
    case Shape::Random: {
      Case v;
      for (int i = 0; i < 36; ++i) v.push_back(r.sym());
      return v;
    }
    case Shape::On: {
      P3 a = dyadic3(r), b = dyadic3(r), c = dyadic3(r);
      std::array<P3, 3> own = {combo3(r, a, b, c), combo3(r, a, b, c), combo3(r, a, b, c)};
      if (r.chance(30)) own = {b, c, a};  // arbitrary doubles below
      if (r.chance(30)) a = arb3(r), b = arb3(r), c = arb3(r), own = {c, a, b};
      std::array<P3, 3> planes[3] = {own, {arb3(r), arb3(r), arb3(r)}, {arb3(r), arb3(r), arb3(r)}};
      std::swap(planes[0], planes[r.next() % 3]);
      Case v = cat3({a, b, c});
      for (auto& pl : planes)
        for (auto& p : pl) v.insert(v.end(), p.begin(), p.end());
      return v;
    }
    case Shape::Parallel: {
      // The second plane is the first moved along its own directions and
      // nudged: nearly parallel.
      P3 a = arb3(r), b = arb3(r), c = arb3(r), off = pmul(arb3(r), 0.5);
      Case v = cat3({arb3(r), arb3(r), arb3(r), a, b, c, padd(a, off), padd(b, off), padd(c, off)});
      nudge(r, v, 9);
      P3 u = arb3(r), s = arb3(r), t = arb3(r);
      v.insert(v.end(), u.begin(), u.end());
      v.insert(v.end(), s.begin(), s.end());
      v.insert(v.end(), t.begin(), t.end());
      return v;
    }
    case Shape::Coincide: {
      P3 x = dyadic3(r);
      auto tri = plane_through(r, x);
      Case v = cat3({tri[0], tri[1], tri[2]});
      for (int i = 0; i < 3; ++i)
        for (const P3& p : plane_through(r, x)) v.insert(v.end(), p.begin(), p.end());
      return v;
    }
  }
  return {};
}

// a, b, p, q, r, s.
Case build_ssi(Rng& r, Shape shape) {
  switch (shape) {
    case Shape::Random: {
      Case v;
      for (int i = 0; i < 12; ++i) v.push_back(r.sym());
      return v;
    }
    case Shape::On: {
      P2 a = dyadic2(r), b = dyadic2(r);
      switch (r.next() % 3) {
        case 0: return cat2({a, b, combo2(r, a, b), combo2(r, a, b), arb2(r), arb2(r)});
        case 1: return cat2({a, b, arb2(r), arb2(r), combo2(r, a, b), combo2(r, a, b)});
        default: {  // arbitrary doubles: one line through a and b
          P2 x = arb2(r), y = arb2(r);
          return cat2({x, y, arb2(r), arb2(r), y, x});
        }
      }
    }
    case Shape::Parallel: {
      P2 p = arb2(r), q = arb2(r), rr = arb2(r);
      double m = r.sym();
      P2 s = {rr[0] + m * (q[0] - p[0]), rr[1] + m * (q[1] - p[1])};
      return cat2({arb2(r), arb2(r), p, q, rr, s});
    }
    case Shape::Coincide: {
      P2 x = dyadic2(r);
      auto [a, b] = line_through(r, x);
      auto [p, q] = line_through(r, x);
      auto [u, v] = line_through(r, x);
      return cat2({a, b, p, q, u, v});
    }
  }
  return {};
}

// axis, then p, q, r, s, t and p', q', r', s', t'.
Case build_axis(Rng& r, Shape shape) {
  int axis = int(r.next() % 3);
  Case v = {double(axis)};
  auto add = [&v](std::initializer_list<P3> pts) {
    for (const P3& p : pts) v.insert(v.end(), p.begin(), p.end());
  };
  switch (shape) {
    case Shape::Random:
      for (int i = 0; i < 30; ++i) v.push_back(r.sym());
      break;
    case Shape::On: {
      // Both planes on x[axis] = h (the same h), arbitrary otherwise.
      double h = r.chance(50) ? arbitrary(r) : r.range(-64, 63) / 64.0;
      auto on = [&] {
        P3 p = arb3(r);
        p[axis] = h;
        return p;
      };
      add({arb3(r), arb3(r), on(), on(), on(), arb3(r), arb3(r), on(), on(), on()});
      break;
    }
    case Shape::Parallel: {
      P3 rr = arb3(r), s = arb3(r), t = arb3(r), p = arb3(r);
      P3 q = padd(p, padd(pmul(psub(s, rr), r.sym()), pmul(psub(t, rr), r.sym())));
      add({p, q, rr, s, t, arb3(r), arb3(r), arb3(r), arb3(r), arb3(r)});
      break;
    }
    case Shape::Coincide: {
      P3 x = dyadic3(r);
      for (int i = 0; i < 2; ++i) {
        auto [p, q] = line_through(r, x);
        auto pl = plane_through(r, x);
        add({p, q, pl[0], pl[1], pl[2]});
      }
      break;
    }
  }
  return v;
}

}  // namespace

void gen_orient3d_lpi(Writer& w) {
  implicit_sections(w, {orient3d_lpi_sign<Epeck>, orient3d_lpi_sign<RatK>, orient3d_lpi_naive, 0, 3, build_lpi}, "the triangle's plane", 320);
}

void gen_orient3d_tpi(Writer& w) {
  implicit_sections(w, {orient3d_tpi_sign<Epeck>, orient3d_tpi_sign<RatK>, orient3d_tpi_naive, 0, 3, build_tpi}, "the triangle's plane", 200);
}

void gen_orient2d_ssi(Writer& w) {
  implicit_sections(w, {orient2d_ssi_sign<Epeck>, orient2d_ssi_sign<RatK>, orient2d_ssi_naive, 0, 2, build_ssi}, "the line through a and b", 320);
}

void gen_less_on_axis_lpi(Writer& w) {
  implicit_sections(w, {less_on_axis_lpi_sign<Epeck>, less_on_axis_lpi_sign<RatK>, less_on_axis_lpi_naive, 1, 3, build_axis},
                    "the other point's plane x[axis] = const", 240);
}

}  // namespace fixtures
