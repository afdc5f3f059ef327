// ray_sphere, ray_cylinder, ray_cone, ray_quadric: a line against a surface
// whose equation in t has degree <= 2, answered by its exact real roots.

#include "ray.h"

#include <CGAL/squared_distance_3.h>

#include <numeric>

namespace fixtures {
namespace {

// ---------------------------------------------------------------------------
// ray_sphere: o d c r -> n [t0 t1]

Case sphere_case(const P3& o, const P3& d, const P3& c, double r) {
  Case v;
  append3(v, o);
  append3(v, d);
  append3(v, c);
  v.push_back(r);
  return v;
}

Poly2 sphere_poly(const Case& v) {
  QV d = qv3(v, 3), oc = qsub(qv3(v, 0), qv3(v, 6));
  Q r(v[9]);
  return Poly2{qdot(d, d), Q(2 * qdot(d, oc)), Q(qdot(oc, oc) - r * r)};
}

Q sphere_direct(const Case& v, const Q& t) {
  QV x = qsub(qadd(qv3(v, 0), qmul(qv3(v, 3), t)), qv3(v, 6));
  Q r(v[9]);
  return Q(qdot(x, x) - r * r);
}

// The squared distance from the centre to the line against r^2 (CGAL,
// rational kernel).
int sphere_cgal_count(const Case& v) {
  using R = CGAL::Exact_rational;
  RatK::Line_3 line(RatK::Point_3(Rq(v[0]), Rq(v[1]), Rq(v[2])), RatK::Vector_3(Rq(v[3]), Rq(v[4]), Rq(v[5])));
  R d2 = CGAL::squared_distance(line, RatK::Point_3(Rq(v[6]), Rq(v[7]), Rq(v[8])));
  R r2 = Rq(v[9]) * Rq(v[9]);
  return d2 < r2 ? 2 : d2 == r2 ? 1 : 0;
}

std::array<double, 3> sphere_naive(const Case& v) {
  double ox = v[0] - v[6], oy = v[1] - v[7], oz = v[2] - v[8];
  double a = v[3] * v[3] + v[4] * v[4] + v[5] * v[5];
  double b = 2 * (v[3] * ox + v[4] * oy + v[5] * oz);
  double c = ox * ox + oy * oy + oz * oz - v[9] * v[9];
  return {a, b, c};
}

const QuadKind kRaySphere = {"ray_sphere", 10, sphere_poly, sphere_direct, sphere_cgal_count, sphere_naive, true};

// Unit-ish sphere, origin in [-4, 4]^3; the direction random or aimed at a
// point within 1.3 r of the centre.
Case sphere_random(Rng& r, bool aimed) {
  P3 c = uniform3(r, 0), o = uniform3(r, aimed ? 2 : 1), d;
  double rad = 0.25 + 0.75 * r.unit();
  if (aimed)
    d = psub(padd(c, pmul(unit_dir(r), 1.3 * rad * r.unit())), o);
  else
    d = uniform3(r, 0);
  if (d == P3{0, 0, 0}) return {};
  return sphere_case(o, d, c, rad);
}

// Unit sphere, origin at distance L, aimed at a point at distance s from the
// centre perpendicular to the view: s in [0, 1) or (near the tangent
// distance) in [0.97, 1.03]. d = aim - o or its normalization.
Case sphere_far(Rng& r, double L, double rad) {
  P3 c = uniform3(r, 0), u = unit_dir(r);
  P3 o = padd(c, pmul(u, L));
  double s = r.chance(50) ? r.unit() : 0.97 + 0.06 * r.unit();
  P3 d = psub(padd(c, pmul(perp_dir(r, u), s * rad)), o);
  if (r.chance(50)) d = pnormalize(d);
  return sphere_case(o, d, c, rad);
}

// Exactly tangent: centre C 2^e, radius m N 2^e, tangent point
// T = C + m W 2^e with |W| = N, direction D = W x v (so D . W = 0), origin
// T - S D (all on the 2^e lattice), d = D f 2^ed with f = 1 or an odd
// integer: the double root is t = S 2^(e - ed) / f. axis: W = +-e_j, N = 1.
// m and S D have up to 30-34 bits, so b^2 and 4ac round in f64.
Case sphere_tangent(Rng& r, bool axis, bool odd_factor = false) {
  int64_t N = 1;
  I3 W = {0, 0, 0};
  if (axis)
    W[r.next() % 3] = r.sign();
  else
    W = pythagorean(r, 3, N);
  I3 D;
  do D = cross3(W, nonzero_bits3(r, 5));
  while (zero3(D));
  int64_t m = axis ? r.range(1, int64_t(1) << 30) : r.range(1, int64_t(1) << 20);
  int e = int(r.range(-40, 0)), ed = int(r.range(-8, 8));
  I3 C = bits3(r, 30);
  I3 T = add3(C, mul3(W, m));
  int64_t S = r.range(-(int64_t(1) << 20), int64_t(1) << 20);
  I3 O = sub3(T, mul3(D, S));
  int64_t f = odd_factor ? 2 * r.range(1, 49) + 1 : 1;
  return sphere_case(lattice3(O, e), lattice3(mul3(D, f), ed), lattice3(C, e), lattice(m * N, e));
}

// Origin exactly on the sphere: o = C + m W (2^e lattice) as above; d random
// (70%), tangent W x v (15%: t = 0 is a double root) or radial (15%).
Case sphere_on_surface(Rng& r) {
  int64_t N;
  I3 W = pythagorean(r, 3, N);
  int64_t m = r.range(1, int64_t(1) << 20);
  int e = int(r.range(-40, 0));
  I3 C = bits3(r, 30);
  P3 o = lattice3(add3(C, mul3(W, m)), e), d;
  int pick = int(r.range(0, 99));
  if (pick < 70) {
    d = uniform3(r, int(r.range(-3, 3)));
  } else if (pick < 85) {
    I3 D;
    do D = cross3(W, nonzero_bits3(r, 5));
    while (zero3(D));
    d = lattice3(D, int(r.range(-8, 8)));
  } else {
    d = lattice3(mul3(W, r.range(1, 9) * r.sign()), int(r.range(-8, 8)));
  }
  if (d == P3{0, 0, 0}) return {};
  return sphere_case(o, d, lattice3(C, e), lattice(m * N, e));
}

// ---------------------------------------------------------------------------
// Two distinct roots 1-3 ulps apart, for all three kinds.

// A double r1 and r2 = r1 moved up by k = 1..kmax ulps; r1 is itself +-2^e or
// +-(1 + u) 2^e moved down by 0..k ulps, so some pairs straddle a power of
// two (where the ulp changes). delta = r2 - r1 is exact (Sterbenz).
struct ClosePair {
  double r1, r2, delta;
};

ClosePair close_pair(Rng& r, int kmax) {
  int e = int(r.range(-300, 300)), k = int(r.range(1, kmax));
  double base = r.sign() * (r.chance(30) ? std::ldexp(1.0, e) : std::ldexp(1.0 + r.unit(), e));
  double r1 = step_ulps(base, -int(r.range(0, k)));
  double r2 = step_ulps(r1, k);
  return ClosePair{r1, r2, r2 - r1};
}

// The axes permuted at random, the same way in every vector.
void permute_axes(Rng& r, std::vector<P3*> vs) {
  int perm[3] = {0, 1, 2};
  for (int i = 2; i > 0; --i) std::swap(perm[i], perm[r.next() % (i + 1)]);
  for (P3* v : vs) {
    P3 x = *v;
    for (int i = 0; i < 3; ++i) (*v)[perm[i]] = x[i];
  }
}

// A line along axis 0 through a circle in the plane of axes 0 and 1 (a
// sphere's or a cylinder's section) whose chord has the parameters r1 and
// r2 of `p` as ends, or nearly: d = (dx, 0, 0), dx = +-2^j; centre
// c_0 = dx r1 / 2 and origin o_0 = -dx r2 / 2, so (c_0 - o_0) / dx =
// (r1 + r2) / 2 exactly; the centre h off the line along axis 1, radius R.
// The roots are (r1 + r2) / 2 +- sqrt(R^2 - h^2) / |dx|. exact: R^2 - h^2 =
// w^2 with w = |dx| delta / 2 (h = 0 and R = w, or R, h = w (2^m +- 2^-m) / 2),
// the roots exactly r1 and r2; otherwise R = w c1 and h = w c2 with c1 in
// [1/2, 3/2] and c2 in [0, c1) dyadic: irrational (or dyadic, not double)
// roots delta sqrt(c1^2 - c2^2) apart, so with delta of 1 or 2 ulps at most
// 3 ulps apart. o_1 and o_2 = c_2 are multiples of
// the last bits of h, so c_1 = o_1 + h is exact.
struct Chord {
  P3 o, d, c;
  double R;
};

Chord close_chord(Rng& r, const ClosePair& p, bool exact) {
  int j = int(r.range(-8, 8));
  double dx = r.sign() * std::ldexp(1.0, j), w = std::ldexp(p.delta, j - 1);
  double R, h;
  if (exact && r.chance(30)) {
    R = w, h = 0;
  } else if (exact) {
    double m = std::ldexp(1.0, int(r.range(1, 6)));
    R = w * (m + 1 / m) / 2, h = w * (m - 1 / m) / 2;
  } else {
    int64_t c1 = r.range(512, 1536), c2 = r.range(0, c1 - 1);
    R = w * std::ldexp(double(c1), -10), h = w * std::ldexp(double(c2), -10);
  }
  h *= r.sign();
  double y0 = h == 0 ? arbitrary(r) : lattice(r.bits(20), low_bit_exp(h)), z0 = arbitrary(r);
  Chord ch{{-dx * p.r2 / 2, y0, z0}, {dx, 0, 0}, {dx * p.r1 / 2, y0 + h, z0}, R};
  if (Q(ch.c[1]) != Q(y0) + Q(h)) die("close_chord: inexact offset");
  return ch;
}

void gen_ray_sphere(RayWriter& w) {
  const QuadKind& k = kRaySphere;
  w.section("random", "unit-ish spheres (centre in [-1,1]^3, r in [0.25,1]), origins in [-2,2]^3 or [-4,4]^3", "02", "012");
  quad_block(w, k, "origin in [-2,2]^3, random direction in [-1,1]^3", 60, [](Rng& r) { return sphere_random(r, false); });
  quad_block(w, k, "origin in [-4,4]^3 aimed at a point within 1.3 r of the centre", 60,
             [](Rng& r) { return sphere_random(r, true); });

  w.section("far-origin",
            "unit sphere (centre in [-1,1]^3), origin 1e6..1e8 away, aimed at a point s from the centre "
            "perpendicular to the view, s in [0,1) or [0.97,1.03]; d = aim - o or unit",
            "02", "012");
  for (const char* L : {"1e6", "1e7", "1e8"}) {
    double dist = std::strtod(L, nullptr);
    quad_block(w, k, std::string("|o - c| = ") + L, 60, [dist](Rng& r) { return sphere_far(r, dist, 1.0); });
  }

  w.section("tiny-far", "r = 1e-6 at distance 2^10..2^20 (~1e3..1e6) from the origin, aimed within 1.3 r", "02",
            "012");
  quad_block(w, k, "origin in [-1,1]^3, d = aim - o or unit", 80, [](Rng& r) {
    P3 o = uniform3(r, 0), u = unit_dir(r);
    P3 c = padd(o, pmul(u, length_factor(r, 10, 19)));
    P3 d = psub(padd(c, pmul(perp_dir(r, u), 1.3e-6 * r.unit())), o);
    if (r.chance(50)) d = pnormalize(d);
    return sphere_case(o, d, c, 1e-6);
  });

  w.section("grazing", "exactly tangent configurations (as in `tangent`) with one input moved by 1-3 ulps", "02",
            "012");
  quad_block(w, k, "axis-aligned tangents, one nonzero input moved", 50, [](Rng& r) {
    Case v = sphere_tangent(r, true);
    nudge_one(r, v, all_slots(10));
    return v;
  });
  quad_block(w, k, "Pythagorean tangents, one nonzero input moved", 50, [](Rng& r) {
    Case v = sphere_tangent(r, false);
    nudge_one(r, v, all_slots(10));
    return v;
  });

  w.section("tangent",
            "exactly tangent (n = 1, discriminant exactly 0): centre C 2^e, radius m N 2^e, tangent point "
            "T = C + m W 2^e with |W| = N, d = (W x v) 2^ed, origin T - S d; integers C, W, v, S (|S| < 2^20)",
            "1", "1");
  quad_block(w, k, "W = +-e_j (ray in the plane at height r above the centre), r = m 2^e, m < 2^30", 50,
             [](Rng& r) { return sphere_tangent(r, true); });
  quad_block(w, k, "W a Pythagorean quadruple (|W| = N <= 256), r = m N 2^e", 60,
             [](Rng& r) { return sphere_tangent(r, false); });

  w.section("unnormalized", "directions of length 2^-10..2^11 (~1e-3..2e3), not powers of two", "012", "012");
  quad_block(w, k, "aimed rays as in `random`, d = unit * (1 + u) 2^k, k in [-10, 10]", 60, [](Rng& r) {
    Case v = sphere_random(r, true);
    if (v.empty()) return v;
    P3 d = pmul(pnormalize(P3{v[3], v[4], v[5]}), length_factor(r, -10, 10));
    std::copy(d.begin(), d.end(), v.begin() + 3);
    return v;
  });
  quad_block(w, k, "exact tangents (Pythagorean) with d = (W x v) f 2^ed, f odd in 3..99: root S 2^(e-ed) / f", 50,
             [](Rng& r) { return sphere_tangent(r, false, true); });

  w.section("on-surface",
            "origin exactly on the sphere (o = C + m W, |W| = N, r = m N on a 2^e lattice): one root exactly 0; "
            "d random, tangent (double root 0) or radial",
            "2", "12");
  quad_block(w, k, "W Pythagorean, the other root -b/a", 60, [](Rng& r) { return sphere_on_surface(r); });

  w.section("centre", "origin at the centre: roots -r/|d| and r/|d|", "2", "2");
  quad_block(w, k, "centre in [-1,1]^3 or a 2^-20 lattice point, r in [2^-10, 2^10], |d| in [2^-10, 2^10]", 50,
             [](Rng& r) {
               P3 c = r.chance(50) ? uniform3(r, 0) : lattice3(bits3(r, 30), -20);
               P3 d = pmul(unit_dir(r), length_factor(r, -10, 9));
               return sphere_case(c, d, c, length_factor(r, -10, 9));
             });

  w.section("scaled",
            "cases from random, far-origin (1e6), tangent and on-surface multiplied exactly by 2^100 or 2^-100: "
            "everything (t unchanged) or all but d (t scaled)",
            "012", "012");
  for (int sgn_k : {1, -1}) {
    std::string label = std::string("scaled by 2^") + (sgn_k > 0 ? "100" : "-100");
    quad_block(w, k, label, 60, [sgn_k](Rng& r) {
      Case v;
      switch (r.next() % 4) {
        case 0: v = sphere_random(r, true); break;
        case 1: v = sphere_far(r, 1e6, 1.0); break;
        case 2: v = sphere_tangent(r, r.chance(50)); break;
        default: v = sphere_on_surface(r); break;
      }
      if (!v.empty()) scale_case(r, v, 100 * sgn_k);
      return v;
    });
  }

  w.section("close-roots",
            "two distinct roots 1-3 ulps apart: a line along an axis, d = +-2^j e, through a tiny sphere at "
            "(r1 + r2) / 2 from the origin (|r1| ~2^-300..2^300), h off the line; axes permuted",
            "2", "2");
  quad_block(w, k, "R^2 - h^2 = (|d| (r2 - r1) / 2)^2: roots exactly r1 and r2, doubles 1, 2 or 3 ulps apart", 60,
             [](Rng& r) {
               Chord ch = close_chord(r, close_pair(r, 3), true);
               permute_axes(r, {&ch.o, &ch.d, &ch.c});
               return sphere_case(ch.o, ch.d, ch.c, ch.R);
             });
  quad_block(w, k, "R and h other dyadic multiples of |d| (r2 - r1) / 2: roots within 1-3 ulps, not doubles", 50,
             [](Rng& r) {
               Chord ch = close_chord(r, close_pair(r, 2), false);
               permute_axes(r, {&ch.o, &ch.d, &ch.c});
               return sphere_case(ch.o, ch.d, ch.c, ch.R);
             });
}

// ---------------------------------------------------------------------------
// ray_cylinder: o d p a r -> n [t0 t1]

// A line o + t d and a shape around the axis through p along a with radius
// r: the inputs of ray_cylinder and ray_cone.
Case axial_case(const P3& o, const P3& d, const P3& p, const P3& a, double r) {
  Case v;
  append3(v, o);
  append3(v, d);
  append3(v, p);
  append3(v, a);
  v.push_back(r);
  return v;
}

Poly2 cylinder_poly(const Case& v) {
  QV a = qv3(v, 9);
  QV u = qcross(qv3(v, 3), a), s = qcross(qsub(qv3(v, 0), qv3(v, 6)), a);
  Q r(v[12]);
  return Poly2{qdot(u, u), Q(2 * qdot(u, s)), Q(qdot(s, s) - r * r * qdot(a, a))};
}

Q cylinder_direct(const Case& v, const Q& t) {
  QV a = qv3(v, 9);
  QV x = qadd(qv3(v, 0), qmul(qv3(v, 3), t));
  QV s = qcross(qsub(x, qv3(v, 6)), a);
  Q r(v[12]);
  return Q(qdot(s, s) - r * r * qdot(a, a));
}

// The squared distance between the line and the axis against r^2 (CGAL,
// rational kernel): the distance to the axis along a non-parallel line has
// its minimum there; a parallel line keeps its distance.
int cylinder_cgal_count(const Case& v) {
  using R = CGAL::Exact_rational;
  RatK::Vector_3 d(Rq(v[3]), Rq(v[4]), Rq(v[5])), a(Rq(v[9]), Rq(v[10]), Rq(v[11]));
  RatK::Line_3 line(RatK::Point_3(Rq(v[0]), Rq(v[1]), Rq(v[2])), d);
  RatK::Line_3 axis(RatK::Point_3(Rq(v[6]), Rq(v[7]), Rq(v[8])), a);
  R d2 = CGAL::squared_distance(line, axis);
  R r2 = Rq(v[12]) * Rq(v[12]);
  if (CGAL::cross_product(d, a) == CGAL::NULL_VECTOR) return d2 == r2 ? -1 : 0;
  return d2 < r2 ? 2 : d2 == r2 ? 1 : 0;
}

std::array<double, 3> cylinder_naive(const Case& v) {
  P3 d = {v[3], v[4], v[5]}, w = {v[0] - v[6], v[1] - v[7], v[2] - v[8]}, a = {v[9], v[10], v[11]};
  P3 u = pcross(d, a), s = pcross(w, a);
  return {pdot(u, u), 2 * pdot(u, s), pdot(s, s) - v[12] * v[12] * pdot(a, a)};
}

const QuadKind kRayCylinder = {"ray_cylinder", 13, cylinder_poly, cylinder_direct, cylinder_cgal_count,
                               cylinder_naive, true};

const P3 kExamAxis = {0, 1, 0};

// Random axis (unit direction times 2^-6..2^6), r in [0.1, 2], origin in
// [-4,4]^3 aimed at a point within 1.3 r of the axis.
Case cylinder_random(Rng& r) {
  P3 p = uniform3(r, 0), au = unit_dir(r);
  double rad = 0.1 + 1.9 * r.unit();
  P3 o = uniform3(r, 2);
  P3 aim = padd(padd(p, pmul(au, 2 * r.sym())), pmul(perp_dir(r, au), 1.3 * rad * r.unit()));
  P3 d = psub(aim, o);
  if (d == P3{0, 0, 0}) return {};
  return axial_case(o, d, p, pmul(au, length_factor(r, -6, 5)), rad);
}

// d an exact multiple of A 2^ea: A k 2^j, k = +-1 or an odd integer.
P3 parallel_dir(Rng& r, const I3& A) {
  int64_t k = r.chance(50) ? 1 : 2 * r.range(1, 7) + 1;
  return lattice3(mul3(A, k * r.sign()), int(r.range(-20, 20)));
}

// d exactly parallel to a (a = A 2^ea, A 10-bit); the origin at s r from the
// axis, s in [0, 0.95] (inside) or [1.05, 3] (outside).
Case cylinder_parallel(Rng& r, bool inside) {
  I3 A = nonzero_bits3(r, 10);
  P3 a = lattice3(A, int(r.range(-20, 20))), au = pnormalize(a);
  P3 p = uniform3(r, 0);
  double rad = 0.25 + r.unit();
  double s = inside ? 0.95 * r.unit() : 1.05 + 2 * r.unit();
  P3 o = padd(padd(p, pmul(perp_dir(r, au), s * rad)), pmul(au, 4 * r.sym()));
  Case v = axial_case(o, parallel_dir(r, A), p, a, rad);
  if (sgn(cylinder_poly(v).c) != (inside ? -1 : 1)) return {};
  return v;
}

// A line on the cylinder: W with |W| = N, A = W x v (so A . W = 0), axis
// through C, r = m N, origin C + m W + S A (2^e lattice), d parallel to A.
Case cylinder_on_surface(Rng& r) {
  int64_t N;
  I3 W = pythagorean(r, 3, N), A;
  do A = cross3(W, nonzero_bits3(r, 4));
  while (zero3(A));
  int64_t m = r.range(1, int64_t(1) << 20);
  int e = int(r.range(-40, 0));
  I3 C = bits3(r, 30);
  I3 O = add3(add3(C, mul3(W, m)), mul3(A, r.bits(20)));
  return axial_case(lattice3(O, e), parallel_dir(r, A), lattice3(C, e), lattice3(A, int(r.range(-10, 10))),
                    lattice(m * N, e));
}

// Exactly tangent: the tangent plane at T = C + m W has normal W; D = i A +
// j (W x A), j != 0, lies in it and is not parallel to the axis A; the line
// touches the cylinder at T only. axis: W, A coordinate axes.
Case cylinder_tangent(Rng& r, bool axis) {
  int64_t N = 1;
  I3 W = {0, 0, 0}, A = {0, 0, 0};
  if (axis) {
    int j = int(r.next() % 3), l = (j + 1 + int(r.next() % 2)) % 3;
    W[j] = r.sign();
    A[l] = r.sign() * (int64_t(1) << r.range(0, 10));
  } else {
    W = pythagorean(r, 3, N);
    do A = cross3(W, nonzero_bits3(r, 4));
    while (zero3(A));
  }
  I3 B = cross3(W, A);
  int64_t i = r.bits(3), j;
  do j = r.bits(3);
  while (j == 0);
  I3 D = add3(mul3(A, i), mul3(B, j));
  int64_t m = r.range(1, int64_t(1) << (axis ? 30 : 20));
  int e = int(r.range(-40, 0));
  I3 C = bits3(r, 30);
  I3 T = add3(C, mul3(W, m));
  int64_t span = int64_t(1) << (axis ? 24 : 14);
  I3 O = sub3(T, mul3(D, r.range(-span, span)));
  return axial_case(lattice3(O, e), lattice3(D, int(r.range(-8, 8))), lattice3(C, e),
                    lattice3(A, int(r.range(-10, 10))), lattice(m * N, e));
}

// r = 1, axis (0,1,0) (30%) or random unit; the origin L from the axis, aimed
// at a point s from the axis perpendicular to both the axis and the view,
// s in [0, 1) or [0.97, 1.03].
Case cylinder_far(Rng& r, double L) {
  P3 au = r.chance(30) ? kExamAxis : unit_dir(r), p = uniform3(r, 0);
  P3 u = perp_dir(r, au);
  P3 o = padd(padd(p, pmul(u, L)), pmul(au, L * r.sym()));
  P3 side = pnormalize(pcross(au, u));
  double s = r.chance(50) ? r.unit() : 0.97 + 0.06 * r.unit();
  P3 d = psub(padd(padd(p, pmul(au, 2 * r.sym())), pmul(side, s)), o);
  if (r.chance(50)) d = pnormalize(d);
  return axial_case(o, d, p, au, 1.0);
}

void gen_ray_cylinder(RayWriter& w) {
  const QuadKind& k = kRayCylinder;
  w.section("exam", "the cylinder x^2 + z^2 = 1 (p = 0, a = (0,1,0), r = 1), origins in [-4,4]^3", "02", "012");
  quad_block(w, k, "random directions in [-1,1]^3", 60, [](Rng& r) {
    P3 d = uniform3(r, 0);
    if (d == P3{0, 0, 0}) return Case{};
    return axial_case(uniform3(r, 2), d, P3{0, 0, 0}, kExamAxis, 1.0);
  });
  quad_block(w, k, "aimed at a point within 1.3 of the axis, |y| < 2", 60, [](Rng& r) {
    P3 o = uniform3(r, 2), aim;
    do aim = {1.3 * r.sym(), 2 * r.sym(), 1.3 * r.sym()};
    while (aim[0] * aim[0] + aim[2] * aim[2] > 1.69);
    P3 d = psub(aim, o);
    if (d == P3{0, 0, 0}) return Case{};
    return axial_case(o, d, P3{0, 0, 0}, kExamAxis, 1.0);
  });

  w.section("random-axis", "axis through p in [-1,1]^3, a random of length 2^-6..2^6, r in [0.1, 2]", "02", "012");
  quad_block(w, k, "origin in [-4,4]^3 aimed within 1.3 r of the axis", 60, cylinder_random);

  w.section("parallel", "d an exact multiple of a (a = A 2^e, A integer): degree 0; and d moved off parallel by 1-3 ulps",
            "0i", "012i");
  quad_block(w, k, "inside (origin 0..0.95 r from the axis): n = 0", 50,
             [](Rng& r) { return cylinder_parallel(r, true); });
  quad_block(w, k, "outside (origin 1.05..3 r from the axis): n = 0", 50,
             [](Rng& r) { return cylinder_parallel(r, false); });
  quad_block(w, k, "on the surface (o = C + m W + S A, |W| = N, A = W x v, r = m N): n = inf", 50,
             cylinder_on_surface);
  quad_block(w, k, "nearly parallel: the above with one coordinate of d moved by 1-3 ulps (far roots)", 50,
             [](Rng& r) {
               int pick = int(r.next() % 3);
               Case v = pick == 2 ? cylinder_on_surface(r) : cylinder_parallel(r, pick == 0);
               if (!v.empty()) nudge_one(r, v, {3, 4, 5});
               return v;
             });

  w.section("tangent",
            "exactly tangent (n = 1): axis through C 2^e along A, r = m N 2^e, tangent point T = C + m W (|W| = N, "
            "W . A = 0), d = i A + j (W x A), j != 0, origin T - S d",
            "1", "1");
  quad_block(w, k, "W and A coordinate axes (the exam's cylinder, moved and scaled)", 50,
             [](Rng& r) { return cylinder_tangent(r, true); });
  quad_block(w, k, "W a Pythagorean quadruple, A = W x v", 50, [](Rng& r) { return cylinder_tangent(r, false); });

  w.section("grazing", "exactly tangent configurations with one input moved by 1-3 ulps", "02", "012");
  quad_block(w, k, "axis-aligned and Pythagorean tangents, one nonzero input moved", 60, [](Rng& r) {
    Case v = cylinder_tangent(r, r.chance(50));
    nudge_one(r, v, all_slots(13));
    return v;
  });

  w.section("far-origin",
            "r = 1, origin 1e6..1e8 from the axis, aimed at a point s from the axis (s in [0,1) or [0.97,1.03]); "
            "d = aim - o or unit",
            "02", "012");
  for (const char* L : {"1e6", "1e7", "1e8"}) {
    double dist = std::strtod(L, nullptr);
    quad_block(w, k, std::string("distance ") + L, 50, [dist](Rng& r) { return cylinder_far(r, dist); });
  }

  w.section("unnormalized", "as random-axis with |d| and |a| of 2^-10..2^11, not powers of two", "02", "012");
  quad_block(w, k, "d = unit * (1 + u) 2^k, a likewise, k in [-10, 10]", 60, [](Rng& r) {
    Case v = cylinder_random(r);
    if (v.empty()) return v;
    P3 d = pmul(pnormalize(P3{v[3], v[4], v[5]}), length_factor(r, -10, 10));
    P3 a = pmul(pnormalize(P3{v[9], v[10], v[11]}), length_factor(r, -10, 10));
    std::copy(d.begin(), d.end(), v.begin() + 3);
    std::copy(a.begin(), a.end(), v.begin() + 9);
    return v;
  });

  w.section("close-roots",
            "two distinct roots 1-3 ulps apart: the sphere's close-roots chords as sections of a cylinder along "
            "axis 2 (a = (0, 0, A), A arbitrary), d = (+-2^j, 0, dz) with dz arbitrary; axes permuted",
            "2", "2");
  for (bool exact : {true, false}) {
    quad_block(w, k,
               exact ? "R^2 - h^2 = (|d_0| (r2 - r1) / 2)^2: roots exactly r1 and r2, doubles 1, 2 or 3 ulps apart"
                     : "R and h other dyadic multiples of |d_0| (r2 - r1) / 2: roots within 1-3 ulps, not doubles",
               exact ? 60 : 50, [exact](Rng& r) {
                 Chord ch = close_chord(r, close_pair(r, exact ? 3 : 2), exact);
                 P3 a = {0, 0, arbitrary(r)};
                 ch.d[2] = r.chance(30) ? 0.0 : arbitrary(r);
                 permute_axes(r, {&ch.o, &ch.d, &ch.c, &a});
                 return axial_case(ch.o, ch.d, ch.c, a, ch.R);
               });
  }
}

// ---------------------------------------------------------------------------
// ray_quadric: o d A B C D E F G H I J -> n [t ...]

Q quadric_at(const Case& v, const QV& x) {
  Q A(v[6]), B(v[7]), C(v[8]), D(v[9]), E(v[10]), F(v[11]), G(v[12]), H(v[13]), I(v[14]), J(v[15]);
  return Q(A * x[0] * x[0] + B * x[1] * x[1] + C * x[2] * x[2] + D * x[0] * x[1] + E * x[0] * x[2] +
           F * x[1] * x[2] + G * x[0] + H * x[1] + I * x[2] + J);
}

Poly2 quadric_poly(const Case& v) {
  QV o = qv3(v, 0), d = qv3(v, 3);
  Q A(v[6]), B(v[7]), C(v[8]), D(v[9]), E(v[10]), F(v[11]), G(v[12]), H(v[13]), I(v[14]);
  Q a = A * d[0] * d[0] + B * d[1] * d[1] + C * d[2] * d[2] + D * d[0] * d[1] + E * d[0] * d[2] + F * d[1] * d[2];
  Q b = 2 * (A * o[0] * d[0] + B * o[1] * d[1] + C * o[2] * d[2]) + D * (o[0] * d[1] + o[1] * d[0]) +
        E * (o[0] * d[2] + o[2] * d[0]) + F * (o[1] * d[2] + o[2] * d[1]) + G * d[0] + H * d[1] + I * d[2];
  return Poly2{a, b, quadric_at(v, o)};
}

Q quadric_direct(const Case& v, const Q& t) { return quadric_at(v, qadd(qv3(v, 0), qmul(qv3(v, 3), t))); }

std::array<double, 3> quadric_naive(const Case& v) {
  double ox = v[0], oy = v[1], oz = v[2], dx = v[3], dy = v[4], dz = v[5];
  double A = v[6], B = v[7], C = v[8], D = v[9], E = v[10], F = v[11], G = v[12], H = v[13], I = v[14], J = v[15];
  double a = A * dx * dx + B * dy * dy + C * dz * dz + D * dx * dy + E * dx * dz + F * dy * dz;
  double b = 2 * (A * ox * dx + B * oy * dy + C * oz * dz) + D * (ox * dy + oy * dx) + E * (ox * dz + oz * dx) +
             F * (oy * dz + oz * dy) + G * dx + H * dy + I * dz;
  double c = A * ox * ox + B * oy * oy + C * oz * oz + D * ox * oy + E * ox * oz + F * oy * oz + G * ox + H * oy +
             I * oz + J;
  return {a, b, c};
}

const QuadKind kRayQuadric = {"ray_quadric", 16, quadric_poly, quadric_direct, nullptr, quadric_naive, false};

// Quadrics are built as q(y) = sum lam_i y_i^2 + lin . y + kappa (integers)
// in y = L (x - x0), L an integer matrix of determinant +-1 (so L^-1 is an
// integer matrix too) and x0 = X0 / 4: integer points and directions of
// y-space map to exact points and directions of x-space, and every
// coefficient of Q(x) = q(L (x - x0)) is a small dyadic rational (checked to
// be exact as a double). An affine map keeps the type of the quadric, its
// lines, tangents and asymptotic directions.
using M3 = std::array<int64_t, 9>;  // row-major

struct YQuadric {
  I3 lam, lin;
  int64_t kappa;
};

I3 mat_vec(const M3& m, const I3& v) {
  return I3{m[0] * v[0] + m[1] * v[1] + m[2] * v[2], m[3] * v[0] + m[4] * v[1] + m[5] * v[2],
            m[6] * v[0] + m[7] * v[1] + m[8] * v[2]};
}

// A random unimodular matrix: row operations (add +-1 or +-2 times a row to
// another) on the identity, rows permuted and negated; entries stay small.
M3 unimodular(Rng& r) {
  for (;;) {
    M3 m = {1, 0, 0, 0, 1, 0, 0, 0, 1};
    for (int s = 0; s < 5; ++s) {
      int i = int(r.next() % 3), j = (i + 1 + int(r.next() % 2)) % 3;
      int64_t c = r.range(1, 2) * r.sign();
      for (int k = 0; k < 3; ++k) m[3 * i + k] += c * m[3 * j + k];
    }
    for (int i = 2; i > 0; --i) {
      int j = int(r.next() % (i + 1));
      for (int k = 0; k < 3; ++k) std::swap(m[3 * i + k], m[3 * j + k]);
    }
    for (int i = 0; i < 3; ++i)
      if (r.chance(50))
        for (int k = 0; k < 3; ++k) m[3 * i + k] = -m[3 * i + k];
    bool small = true;
    for (int64_t x : m) small &= std::llabs(x) <= 24;
    if (small) return m;
  }
}

M3 inverse_unimodular(const M3& m) {
  M3 adj = {m[4] * m[8] - m[5] * m[7], m[2] * m[7] - m[1] * m[8], m[1] * m[5] - m[2] * m[4],
            m[5] * m[6] - m[3] * m[8], m[0] * m[8] - m[2] * m[6], m[2] * m[3] - m[0] * m[5],
            m[3] * m[7] - m[4] * m[6], m[1] * m[6] - m[0] * m[7], m[0] * m[4] - m[1] * m[3]};
  int64_t det = m[0] * adj[0] + m[1] * adj[3] + m[2] * adj[6];
  if (det != 1 && det != -1) die("not unimodular");
  for (int64_t& x : adj) x *= det;
  return adj;
}

struct Frame {
  M3 L, Linv;
  I3 X0;  // x0 = X0 / 4
  Frame(Rng& r) : L(unimodular(r)), Linv(inverse_unimodular(L)), X0(bits3(r, 6)) {}
  // The x-space point of an integer y-space point, and direction.
  P3 point(const I3& y) const { return lattice3(add3(X0, mul3(mat_vec(Linv, y), 4)), -2); }
  I3 dir(const I3& v) const { return mat_vec(Linv, v); }
  P3 x0() const { return lattice3(X0, -2); }
};

// Q(x) = s 2^k q(L (x - x0)) as the ten coefficients; false if one is not
// exactly a double.
bool x_coefficients(const YQuadric& y, const Frame& f, int k, int s, Case& coef) {
  Q M[3][3], g[3];
  for (int i = 0; i < 3; ++i) {
    g[i] = 0;
    for (int l = 0; l < 3; ++l) g[i] += Q(f.L[3 * l + i]) * Q(y.lin[l]);
    for (int j = 0; j < 3; ++j) {
      M[i][j] = 0;
      for (int l = 0; l < 3; ++l) M[i][j] += Q(f.L[3 * l + i]) * Q(y.lam[l]) * Q(f.L[3 * l + j]);
    }
  }
  Q x0[3] = {Q(f.X0[0]) / 4, Q(f.X0[1]) / 4, Q(f.X0[2]) / 4};
  Q lin[3], J = y.kappa;
  for (int i = 0; i < 3; ++i) {
    lin[i] = g[i];
    J -= g[i] * x0[i];
    for (int j = 0; j < 3; ++j) {
      lin[i] -= 2 * M[i][j] * x0[j];
      J += x0[i] * M[i][j] * x0[j];
    }
  }
  std::vector<Q> c = {M[0][0], M[1][1], M[2][2], 2 * M[0][1], 2 * M[0][2], 2 * M[1][2], lin[0], lin[1], lin[2], J};
  Q factor = s;
  factor *= k >= 0 ? Q(std::ldexp(1.0, k)) : Q(1) / Q(std::ldexp(1.0, -k));
  coef.clear();
  for (Q& q : c) {
    q *= factor;
    double x = q.get_d();
    if (!std::isfinite(x) || Q(x) != q) return false;
    coef.push_back(x);
  }
  return true;
}

Case quadric_case(const P3& o, const P3& d, const Case& coef) {
  Case v;
  append3(v, o);
  append3(v, d);
  v.insert(v.end(), coef.begin(), coef.end());
  return v;
}

enum class QShape {
  Ellipsoid,
  Hyperboloid1,
  Hyperboloid2,
  EllipticParaboloid,
  HyperbolicParaboloid,
  Cone,
  PlanePair,
  ParallelPlanes,
  EllipticCylinder,
  ParabolicCylinder
};

YQuadric y_shape(Rng& r, QShape s) {
  int64_t l1 = r.range(1, 4), l2 = r.range(1, 4), l3 = r.range(1, 4), K = r.range(1, 16), mu = r.range(1, 4);
  int64_t c0 = r.range(-8, 8);
  switch (s) {
    case QShape::Ellipsoid: return {{l1, l2, l3}, {0, 0, 0}, -K};
    case QShape::Hyperboloid1: return {{l1, l2, -l3}, {0, 0, 0}, -K};
    case QShape::Hyperboloid2: return {{l1, -l2, -l3}, {0, 0, 0}, -K};
    case QShape::EllipticParaboloid: return {{l1, l2, 0}, {0, 0, -mu}, c0};
    case QShape::HyperbolicParaboloid: return {{l1, -l2, 0}, {0, 0, -mu}, c0};
    case QShape::Cone: return {{l1, l2, -l3}, {0, 0, 0}, 0};
    case QShape::PlanePair: return {{l1, -l2, 0}, {0, 0, 0}, 0};
    case QShape::ParallelPlanes: return {{l1, 0, 0}, {0, 0, 0}, -K};
    case QShape::EllipticCylinder: return {{l1, l2, 0}, {0, 0, 0}, -K};
    case QShape::ParabolicCylinder: return {{l1, 0, 0}, {0, -mu, 0}, c0};
  }
  return {};
}

// The coefficients of a random frame and scale, or false.
bool place(Rng& r, const YQuadric& y, const Frame& f, Case& coef) {
  return x_coefficients(y, f, int(r.range(-6, 6)), r.sign(), coef);
}

// A random quadric of one of `shapes`, a ray from x0 + [-8,8]^3 in a random
// direction or aimed at x0 + [-2,2]^3.
Case quadric_random(Rng& r, const std::vector<QShape>& shapes) {
  YQuadric y = y_shape(r, r.pick(shapes));
  Frame f(r);
  Case coef;
  if (!place(r, y, f, coef)) return {};
  P3 o = padd(f.x0(), uniform3(r, 3));
  P3 d = r.chance(50) ? uniform3(r, 0) : psub(padd(f.x0(), uniform3(r, 1)), o);
  if (d == P3{0, 0, 0}) return {};
  return quadric_case(o, d, coef);
}

// For lam = (s1^2, s2^2, -s3^2) and a Pythagorean triple (a, b, c):
// V = (a s2 s3, b s1 s3, c s1 s2) has sum lam_i V_i^2 = 0.
I3 null_vector(const I3& s, const I3& triple) {
  return I3{triple[0] * s[1] * s[2], triple[1] * s[0] * s[2], triple[2] * s[0] * s[1]};
}

I3 small_scales(Rng& r) { return I3{r.range(1, 3), r.range(1, 3), r.range(1, 3)}; }

// Direction with q2(d) = 0 and a nonzero linear term: along a paraboloid's
// axis (paraboloid) or along an asymptotic direction of a cone, a hyperboloid,
// a hyperbolic paraboloid or a plane pair (otherwise).
Case quadric_degree_one(Rng& r, bool paraboloid) {
  YQuadric y;
  I3 V;
  I3 s = small_scales(r);
  if (paraboloid) {
    y = y_shape(r, r.chance(50) ? QShape::EllipticParaboloid : QShape::HyperbolicParaboloid);
    V = {0, 0, r.range(1, 3) * r.sign()};
  } else {
    int64_t K = r.range(1, 40);
    switch (r.next() % 5) {
      case 0: y = {{s[0] * s[0], s[1] * s[1], -s[2] * s[2]}, {0, 0, 0}, 0}; break;             // cone
      case 1: y = {{s[0] * s[0], s[1] * s[1], -s[2] * s[2]}, {0, 0, 0}, -K}; break;            // one sheet
      case 2: y = {{-s[0] * s[0], -s[1] * s[1], s[2] * s[2]}, {0, 0, 0}, -K}; break;           // two sheets
      case 3: y = {{s[0] * s[0], -s[1] * s[1], 0}, {0, 0, -r.range(1, 4)}, r.range(-8, 8)}; break;  // saddle
      default: y = {{s[0] * s[0], -s[1] * s[1], 0}, {0, 0, 0}, 0}; break;                     // plane pair
    }
    if (y.lam[2] == 0)
      V = {s[1], s[0] * r.sign(), 0};
    else
      V = mul3(null_vector(s, pythagorean_triple(r)), r.sign());
  }
  Frame f(r);
  Case coef;
  if (!place(r, y, f, coef)) return {};
  P3 o = padd(f.x0(), uniform3(r, 2));
  // Half the directions times a large odd integer: then q2(d) = 0 is no
  // longer exact in f64.
  int64_t odd = r.chance(50) ? 1 : 2 * r.range(1 << 10, 1 << 15) + 1;
  return quadric_case(o, lattice3(mul3(f.dir(V), odd), int(r.range(-4, 4))), coef);
}

// The quadric y in a random frame and scale, and the line through the
// y-space point P + S V (|S| <= 2^16) along V 2^[-4,4], or an empty case.
Case line_in_frame(Rng& r, const YQuadric& y, const I3& P, const I3& V) {
  Frame f(r);
  Case coef;
  if (!place(r, y, f, coef)) return {};
  P3 o = f.point(add3(P, mul3(V, r.range(-(1 << 16), 1 << 16))));
  return quadric_case(o, lattice3(f.dir(V), int(r.range(-4, 4))), coef);
}

// A line P + S V lying on the quadric: a cone's ruling through its apex, a
// ruling of a hyperboloid of one sheet or of a hyperbolic paraboloid, a line
// in one plane of a plane pair, a line of a cylinder along its axis.
Case quadric_line_on(Rng& r) {
  I3 s = small_scales(r);
  YQuadric y;
  I3 P, V;
  switch (r.next() % 5) {
    case 0: {  // cone s1^2 y1^2 + s2^2 y2^2 = s3^2 y3^2
      y = {{s[0] * s[0], s[1] * s[1], -s[2] * s[2]}, {0, 0, 0}, 0};
      V = null_vector(s, pythagorean_triple(r));
      P = mul3(V, r.range(-3, 3));
      break;
    }
    case 1: {  // hyperboloid of one sheet, K = (s1 s2 s3 c k)^2
      I3 t = pythagorean_triple(r);
      int64_t k = r.range(1, 3);
      int64_t K = s[0] * s[1] * s[2] * t[2] * k;
      y = {{s[0] * s[0], s[1] * s[1], -s[2] * s[2]}, {0, 0, 0}, -K * K};
      P = {k * s[2] * t[0] * s[1], k * s[2] * t[1] * s[0], 0};
      V = {-t[1] * s[1] * s[2], t[0] * s[0] * s[2], r.sign() * t[2] * s[0] * s[1]};
      break;
    }
    case 2: {  // hyperbolic paraboloid (s1 y1 - s2 y2)(s1 y1 + s2 y2) = y3
      y = {{s[0] * s[0], -s[1] * s[1], 0}, {0, 0, -1}, 0};
      int64_t y1 = r.range(-6, 6), y2 = r.range(-6, 6);
      int64_t u0 = s[0] * y1 - s[1] * y2;
      P = {y1, y2, u0 * (s[0] * y1 + s[1] * y2)};
      V = {s[1], s[0], 2 * u0 * s[0] * s[1]};
      break;
    }
    case 3: {  // plane pair s1 y1 = +-s2 y2
      y = {{s[0] * s[0], -s[1] * s[1], 0}, {0, 0, 0}, 0};
      int64_t sg = r.sign(), a = r.range(-6, 6), c;
      do c = r.range(-4, 4);
      while (c == 0);
      P = {s[1] * a, sg * s[0] * a, r.range(-6, 6)};
      V = {s[1] * c, sg * s[0] * c, r.range(-4, 4)};
      break;
    }
    default: {  // elliptic cylinder along y3
      P = nonzero_bits3(r, 3);
      if (P[0] == 0 && P[1] == 0) P[0] = 1;
      y = {{s[0] * s[0], s[1] * s[1], 0}, {0, 0, 0}, -(s[0] * s[0] * P[0] * P[0] + s[1] * s[1] * P[1] * P[1])};
      V = {0, 0, r.range(1, 3) * r.sign()};
    }
  }
  return line_in_frame(r, y, P, V);
}

// Degree zero off the surface: a cylinder or a pair of parallel planes along
// its direction, a plane pair along its common line; random origin.
Case quadric_degree_zero_off(Rng& r) {
  YQuadric y;
  I3 V;
  switch (r.next() % 4) {
    case 0: y = y_shape(r, QShape::EllipticCylinder), V = {0, 0, 1}; break;
    case 1: {
      y = y_shape(r, QShape::ParallelPlanes);
      do V = {0, r.bits(3), r.bits(3)};
      while (zero3(V));
      break;
    }
    case 2: y = y_shape(r, QShape::ParabolicCylinder), V = {0, 0, 1}; break;
    default: y = y_shape(r, QShape::PlanePair), V = {0, 0, 1}; break;
  }
  Frame f(r);
  Case coef;
  if (!place(r, y, f, coef)) return {};
  return quadric_case(padd(f.x0(), uniform3(r, 2)), lattice3(f.dir(mul3(V, r.sign())), int(r.range(-4, 4))), coef);
}

// A plane or a double plane written as a quadric: q = mu (y1 - c) (A..F = 0
// in x-space too: an affine map keeps the degree) or q = l (y1 - c)^2, in a
// random frame. `mode` 0: the line lies in the plane (n = inf); 1: parallel
// to it, off it (n = 0); 2 (planes only): crossing it (n = 1, degree one).
Case quadric_plane(Rng& r, int mode, bool twice) {
  int64_t c = r.range(-8, 8), k = r.range(1, 4);
  YQuadric y = twice ? YQuadric{{k, 0, 0}, {-2 * k * c, 0, 0}, k * c * c} : YQuadric{{0, 0, 0}, {k, 0, 0}, -k * c};
  I3 P = {c, r.range(-8, 8), r.range(-8, 8)}, V;
  if (mode == 2) {
    do V = nonzero_bits3(r, 4);
    while (V[0] == 0);
  } else {
    do V = {0, r.bits(4), r.bits(4)};
    while (zero3(V));
  }
  if (mode == 1) P[0] += r.range(1, 3) * r.sign();
  return line_in_frame(r, y, P, V);
}

// The all-zero quadric (every coefficient 0, 30% of them written -0): every
// line lies on it. Each coordinate of o (of d) is 0, a subnormal, +-DBL_MAX
// or uniform * 2^e with one e per vector from the whole exponent range.
Case quadric_all_zero(Rng& r) {
  auto vec = [&r]() {
    int e = int(r.range(-1074, 1023));
    P3 v;
    for (double& x : v) switch (r.next() % 8) {
        case 0: x = 0.0; break;
        case 1: x = lattice(r.bits(40), -1074); break;
        case 2: x = r.sign() * DBL_MAX; break;
        default: x = std::ldexp(r.sym(), e);
      }
    return v;
  };
  P3 o = vec(), d = vec();
  if (d == P3{0, 0, 0}) return {};
  Case coef(10, 0.0);
  for (double& x : coef)
    if (r.chance(30)) x = -0.0;
  return quadric_case(o, d, coef);
}

// Exactly tangent: an integer point T on q (kappa chosen so that q(T) = 0;
// on a cone, T on a ruling), gradient G = 2 lam T + lin != 0, direction
// V = G x w with q2(V) != 0; the line T + (t - S) V touches at t = S.
Case quadric_tangent(Rng& r) {
  static const std::vector<QShape> shapes = {QShape::Ellipsoid,        QShape::Hyperboloid1,
                                             QShape::Hyperboloid2,     QShape::EllipticParaboloid,
                                             QShape::HyperbolicParaboloid, QShape::Cone,
                                             QShape::EllipticCylinder, QShape::ParabolicCylinder};
  QShape shape = r.pick(shapes);
  YQuadric y = y_shape(r, shape);
  I3 T;
  if (shape == QShape::Cone) {
    I3 s = small_scales(r);
    y = {{s[0] * s[0], s[1] * s[1], -s[2] * s[2]}, {0, 0, 0}, 0};
    T = mul3(null_vector(s, pythagorean_triple(r)), r.range(1, 3) * r.sign());
  } else {
    T = nonzero_bits3(r, 4);
    y.kappa = -(y.lam[0] * T[0] * T[0] + y.lam[1] * T[1] * T[1] + y.lam[2] * T[2] * T[2] + dot3(y.lin, T));
  }
  I3 G = add3(mul3(I3{y.lam[0] * T[0], y.lam[1] * T[1], y.lam[2] * T[2]}, 2), y.lin);
  if (zero3(G)) return {};
  I3 V = cross3(G, nonzero_bits3(r, 3));
  if (y.lam[0] * V[0] * V[0] + y.lam[1] * V[1] * V[1] + y.lam[2] * V[2] * V[2] == 0) return {};
  Frame f(r);
  Case coef;
  if (!place(r, y, f, coef)) return {};
  P3 o = f.point(sub3(T, mul3(V, r.range(-(1 << 16), 1 << 16))));
  return quadric_case(o, lattice3(f.dir(V), int(r.range(-4, 4))), coef);
}

// A sphere |x - c|^2 = r^2 or a cylinder |(x - p) x a|^2 = r^2 |a|^2 written
// as a quadric (c, p on a 2^-6 lattice, a a small integer vector, r in
// [0.5, 4]: exact coefficients), the origin 1e6..1e8 away, aimed at a point s
// from the centre / axis, s in [0, 1.03].
Case quadric_far(Rng& r, bool sphere) {
  const double Ls[3] = {1e6, 1e7, 1e8};
  double L = Ls[r.next() % 3];
  QV c = qv3(Case{lattice(r.bits(8), -6), lattice(r.bits(8), -6), lattice(r.bits(8), -6)}, 0);
  P3 cd = {c[0].get_d(), c[1].get_d(), c[2].get_d()};
  Q rad = Q(r.range(32, 256)) / 64;
  Q M[3][3];
  Q r2 = rad * rad;
  I3 A = nonzero_bits3(r, 3);
  QV a = {Q(A[0]), Q(A[1]), Q(A[2])};
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) M[i][j] = sphere ? Q(i == j) : Q((i == j ? qdot(a, a) : Q(0)) - a[i] * a[j]);
  if (!sphere) r2 *= qdot(a, a);
  Q lin[3], J = -r2;
  for (int i = 0; i < 3; ++i) {
    lin[i] = 0;
    for (int j = 0; j < 3; ++j) {
      lin[i] -= 2 * M[i][j] * c[j];
      J += c[i] * M[i][j] * c[j];
    }
  }
  Case coef;
  for (const Q& q : {M[0][0], M[1][1], M[2][2], Q(2 * M[0][1]), Q(2 * M[0][2]), Q(2 * M[1][2]), lin[0], lin[1],
                     lin[2], J}) {
    double x = q.get_d();
    if (Q(x) != q) die("quadric_far: inexact coefficient");
    coef.push_back(x);
  }
  P3 axis = sphere ? unit_dir(r) : pnormalize(P3{double(A[0]), double(A[1]), double(A[2])});
  P3 u = sphere ? axis : perp_dir(r, axis);
  P3 o = padd(cd, pmul(u, L));
  if (!sphere) o = padd(o, pmul(axis, L * r.sym()));
  P3 side = sphere ? perp_dir(r, u) : pnormalize(pcross(axis, u));
  P3 aim = padd(cd, pmul(side, 1.03 * r.unit() * rad.get_d()));
  if (!sphere) aim = padd(aim, pmul(axis, 2 * r.sym()));
  P3 d = psub(aim, o);
  if (r.chance(50)) d = pnormalize(d);
  return quadric_case(o, d, coef);
}

// D x_i x_j (+ J) along o + t d: D (o_i + t d_i)(o_j + t d_j) has the
// roots -o_i / d_i and -o_j / d_j (the plane pair x_i x_j = 0). mode 0:
// d_i, d_j = +-2^[-8,8], o_i = -r1 d_i, o_j = -r2 d_j: the roots are exactly
// r1 and r2 of a close pair. mode 1: d_i, d_j odd (3..15) times 2^[-8,8],
// o_i, o_j = -r1 d_i, -r2 d_j rounded: rational roots near r1 and r2. mode 2:
// as mode 0 with r2 = r1 + 1 ulp, D = +-2^k and J = D d_i d_j c delta^2,
// c in [-2, 3/16] (multiples of 2^-8): irrational roots (r1 + r2) / 2 +-
// delta sqrt(1/4 - c), 0.5 to 3 ulps apart.
// The third coordinate of o and d is arbitrary; D too, in modes 0 and 1.
Case quadric_close(Rng& r, int mode) {
  ClosePair p = close_pair(r, mode == 2 ? 1 : 3);
  int i = int(r.next() % 3), j = (i + 1 + int(r.next() % 2)) % 3, l = 3 - i - j;
  auto dir = [&r, mode] {
    double odd = mode == 1 ? double(2 * r.range(1, 7) + 1) : 1.0;
    return r.sign() * std::ldexp(odd, int(r.range(-8, 8)));
  };
  P3 o, d;
  d[i] = dir(), d[j] = dir(), d[l] = arbitrary(r);
  o[i] = -p.r1 * d[i], o[j] = -p.r2 * d[j], o[l] = arbitrary(r);
  Case coef(10, 0.0);
  double D = mode == 2 ? r.sign() * std::ldexp(1.0, int(r.range(-10, 10))) : arbitrary(r);
  coef[3 + std::min(i, j) + std::max(i, j) - 1] = D;  // xy, xz, yz: D, E, F
  if (mode == 2) {
    Q J = Q(D) * Q(d[i]) * Q(d[j]) * Q(p.delta) * Q(p.delta) * Q(r.range(-512, 48)) / 256;
    coef[9] = J.get_d();
    if (sgn(J) == 0 || Q(coef[9]) != J) return {};
  }
  return quadric_case(o, d, coef);
}

void gen_ray_quadric(RayWriter& w) {
  const QuadKind& k = kRayQuadric;
  w.section("random",
            "random quadrics: a diagonal form in y = L (x - x0), L unimodular, scaled by +-2^[-6,6]; rays from "
            "x0 + [-8,8]^3, random or aimed at x0 + [-2,2]^3",
            "02", "012i");
  quad_block(w, k, "ellipsoids, hyperboloids of one and two sheets", 60, [](Rng& r) {
    return quadric_random(r, {QShape::Ellipsoid, QShape::Hyperboloid1, QShape::Hyperboloid2});
  });
  quad_block(w, k, "elliptic and hyperbolic paraboloids, elliptic and parabolic cylinders", 50, [](Rng& r) {
    return quadric_random(r, {QShape::EllipticParaboloid, QShape::HyperbolicParaboloid, QShape::EllipticCylinder,
                              QShape::ParabolicCylinder});
  });
  quad_block(w, k, "cones, intersecting and parallel plane pairs", 50, [](Rng& r) {
    return quadric_random(r, {QShape::Cone, QShape::PlanePair, QShape::ParallelPlanes});
  });
  quad_block(w, k, "all ten coefficients uniform in [-1,1], origin in [-4,4]^3, direction in [-1,1]^3", 50,
             [](Rng& r) {
               Case coef(10);
               for (double& x : coef) x = r.sym();
               P3 d = uniform3(r, 0);
               if (d == P3{0, 0, 0}) return Case{};
               return quadric_case(uniform3(r, 2), d, coef);
             });

  w.section("degree-one", "leading coefficient exactly 0, linear one not: one root, -c/b", "1", "1");
  quad_block(w, k, "along a paraboloid's axis (elliptic and hyperbolic)", 50,
             [](Rng& r) { return quadric_degree_one(r, true); }, "1");
  quad_block(w, k,
             "along an asymptotic direction: cones, hyperboloids (one and two sheets), hyperbolic paraboloids, "
             "plane pairs",
             50, [](Rng& r) { return quadric_degree_one(r, false); }, "1");
  quad_block(w, k, "planes written as quadrics (A..F = 0: mu (y1 - c) in a random frame), lines crossing them", 50,
             [](Rng& r) { return quadric_plane(r, 2, false); }, "1");

  w.section("degree-zero", "leading and linear coefficients exactly 0: n = 0, or inf on the surface", "0i", "0i");
  quad_block(w, k, "lines on the quadric: cone rulings through the apex, rulings of one-sheet hyperboloids and "
             "hyperbolic paraboloids, lines in a plane of a plane pair, cylinder lines: n = inf", 60,
             quadric_line_on, "i");
  quad_block(w, k, "along a cylinder's or parallel plane pair's direction, along a plane pair's common line, "
             "origin off the surface: n = 0", 50, quadric_degree_zero_off, "0");
  quad_block(w, k, "the all-zero quadric (A..J all 0, some written -0): every line lies on it, n = inf; o and d "
             "from subnormal to DBL_MAX", 60, quadric_all_zero, "i");
  quad_block(w, k, "lines in a plane written as a quadric (A..F = 0) or in a double plane l (y1 - c)^2: n = inf", 50,
             [](Rng& r) { return quadric_plane(r, 0, r.chance(50)); }, "i");
  quad_block(w, k, "lines parallel to such a plane or double plane, off it: n = 0", 50,
             [](Rng& r) { return quadric_plane(r, 1, r.chance(50)); }, "0");

  w.section("tangent",
            "exactly tangent (double root): q(T) = 0 at an integer point, direction (grad q(T)) x w; ellipsoids, "
            "hyperboloids, paraboloids, cones, cylinders",
            "1", "1");
  quad_block(w, k, "the double root at S 2^-k", 60, quadric_tangent, "1");

  w.section("near-tangent", "the tangent cases with one nonzero input moved by 1-3 ulps", "02", "012");
  quad_block(w, k, "one of o, d, A..J moved", 60, [](Rng& r) {
    Case v = quadric_tangent(r);
    if (!v.empty()) nudge_one(r, v, all_slots(16));
    return v;
  });

  w.section("far-sphere-cylinder",
            "a sphere and a cylinder written as quadrics, origin 1e6..1e8 away aimed within 1.03 r", "02", "012");
  quad_block(w, k, "sphere x.x - 2 c.x + c.c - r^2", 50, [](Rng& r) { return quadric_far(r, true); });
  quad_block(w, k, "cylinder |(x - p) x a|^2 - r^2 |a|^2, a a small integer vector", 50,
             [](Rng& r) { return quadric_far(r, false); });

  w.section("close-roots",
            "two distinct roots 1-3 ulps apart (|r1| ~2^-300..2^300): the plane pair D x_i x_j = 0 (+ J) along "
            "o + t d, roots -o_i / d_i and -o_j / d_j",
            "2", "2");
  quad_block(w, k, "d_i, d_j = +-2^k, o_i = -r1 d_i, o_j = -r2 d_j: roots exactly r1 and r2, doubles 1, 2 or 3 "
             "ulps apart", 60, [](Rng& r) { return quadric_close(r, 0); }, "2");
  quad_block(w, k, "d_i, d_j odd (3..15) times 2^k, o_i = -r1 d_i and o_j = -r2 d_j rounded: rational roots "
             "within 1-3 ulps, not doubles", 50, [](Rng& r) { return quadric_close(r, 1); }, "2");
  quad_block(w, k, "D x_i x_j + J, J = D d_i d_j c (r2 - r1)^2, r2 - r1 one ulp, c in [-2, 3/16]: irrational roots "
             "(r1 + r2) / 2 +- (r2 - r1) sqrt(1/4 - c)", 50, [](Rng& r) { return quadric_close(r, 2); }, "2");
}

// ---------------------------------------------------------------------------
// ray_cone: o d p a r -> n [t0 [t1]]; the double cone
// |(x - p) x a|^2 |a|^2 = r^2 ((x - p) . a)^2, both nappes.

// With w = o - p, s = |a|^2, u = w x a, v = d x a, h = w . a, q = d . a:
// (s |v|^2 - r^2 q^2) t^2 + 2 (s u . v - r^2 h q) t + s |u|^2 - r^2 h^2.
Poly2 cone_poly(const Case& v) {
  QV w = qsub(qv3(v, 0), qv3(v, 6)), d = qv3(v, 3), a = qv3(v, 9);
  QV u = qcross(w, a), x = qcross(d, a);
  Q s = qdot(a, a), rr = Q(v[12]) * Q(v[12]), h = qdot(w, a), q = qdot(d, a);
  return Poly2{Q(s * qdot(x, x) - rr * q * q), Q(2 * (s * qdot(u, x) - rr * h * q)), Q(s * qdot(u, u) - rr * h * h)};
}

// The definition at o + t d in CGAL's rational kernel (its cross and scalar
// products), independent of the expansion above.
Q cone_direct(const Case& v, const Q& t) {
  using R = CGAL::Exact_rational;
  auto vec = [&v](size_t i) { return RatK::Vector_3(Rq(v[i]), Rq(v[i + 1]), Rq(v[i + 2])); };
  RatK::Vector_3 w = vec(0) + R(t.get_mpq_t()) * vec(3) - vec(6), a = vec(9);
  R h = w * a, rr = Rq(v[12]) * Rq(v[12]);
  return to_q(R(CGAL::cross_product(w, a).squared_length() * a.squared_length() - rr * h * h));
}

std::array<double, 3> cone_naive(const Case& v) {
  P3 w = {v[0] - v[6], v[1] - v[7], v[2] - v[8]}, d = {v[3], v[4], v[5]}, a = {v[9], v[10], v[11]};
  P3 u = pcross(w, a), x = pcross(d, a);
  double s = pdot(a, a), rr = v[12] * v[12], h = pdot(w, a), q = pdot(d, a);
  return {s * pdot(x, x) - rr * q * q, 2 * (s * pdot(u, x) - rr * h * q), s * pdot(u, u) - rr * h * h};
}

const QuadKind kRayCone = {"ray_cone", 13, cone_poly, cone_direct, nullptr, cone_naive, false};

// An exact cone in integers: the axis A, W perpendicular to A with |W| = N,
// and the radius m N at apex + A. D = A + m W is a ruling (D x A = m W x A
// has length |m| N |A|, and D . A = |A|^2, so |D x A|^2 |A|^2 = (m N)^2
// (D . A)^2), and G = |A|^2 W - m N^2 A is normal to the tangent plane along
// it (the gradient of the cone's polynomial at D, 2 s^2 D - 2 (s + m^2 N^2)
// (D . A) A with s = |A|^2, divided by 2 m s; G . D = 0). axis: A = +-2^k e_j
// and W a Pythagorean triple in the other two coordinates; otherwise W a
// Pythagorean quadruple and A = W x v (any axis).
struct ConeFrame {
  I3 A, W;
  int64_t N, m;
  I3 ruling() const { return add3(A, mul3(W, m)); }
  I3 tangent_normal() const { return sub3(mul3(W, dot3(A, A)), mul3(A, m * N * N)); }
};

ConeFrame cone_frame(Rng& r, bool axis) {
  ConeFrame f;
  if (axis) {
    I3 t = pythagorean_triple(r);
    int j = int(r.next() % 3);
    f.A = {0, 0, 0};
    f.A[j] = r.sign() * (int64_t(1) << r.range(0, 6));
    f.W = {0, 0, 0};
    f.W[(j + 1) % 3] = t[0];
    f.W[(j + 2) % 3] = t[1];
    f.N = t[2];
  } else {
    f.W = pythagorean(r, 2, f.N);
    do f.A = cross3(f.W, nonzero_bits3(r, 3));
    while (zero3(f.A));
  }
  f.m = r.range(1, 8) * r.sign();
  return f;
}

// The frame's cone with its apex at C 2^e and (A, m N) scaled by 2^ea, and
// the line through (O 2^e) along d.
Case frame_case(Rng& r, const ConeFrame& f, const I3& C, const I3& O, int e, const P3& d) {
  int ea = int(r.range(-10, 10));
  return axial_case(lattice3(O, e), d, lattice3(C, e), lattice3(f.A, ea), lattice(std::llabs(f.m) * f.N, ea));
}

// v divided by the gcd of its coordinates.
I3 primitive3(const I3& v) {
  int64_t g = std::gcd(std::gcd(std::llabs(v[0]), std::llabs(v[1])), std::llabs(v[2]));
  return g == 0 ? v : I3{v[0] / g, v[1] / g, v[2] / g};
}

// A direction in the tangent plane along the frame's ruling, not parallel to
// it (zero if the draw failed).
I3 tangent_dir(Rng& r, const ConeFrame& f) {
  I3 V = primitive3(cross3(f.tangent_normal(), nonzero_bits3(r, 2)));
  return zero3(cross3(V, f.ruling())) ? I3{0, 0, 0} : V;
}

// A ruling through the apex C 2^e: o = (C + S D) 2^e (S = 0: the apex), d
// an exact multiple of D (parallel_dir). n = inf.
Case cone_ruling(Rng& r, bool axis) {
  ConeFrame f = cone_frame(r, axis);
  I3 C = bits3(r, 30), D = f.ruling();
  int64_t S = r.chance(10) ? 0 : r.range(-(1 << 16), 1 << 16);
  return frame_case(r, f, C, add3(C, mul3(D, S)), int(r.range(-40, 0)), parallel_dir(r, D));
}

// A line parallel to a ruling D through (C + X) 2^e. tangent_plane false:
// X random (|X| < 2^20), degree one (n = 1, t = -c / b). true: X = i D + j V
// in the tangent plane along D, j != 0: the plane meets the cone in that
// ruling only, doubled, so the polynomial is a nonzero constant (n = 0).
Case cone_parallel_ruling(Rng& r, bool tangent_plane) {
  ConeFrame f = cone_frame(r, r.chance(50));
  I3 C = bits3(r, 30), D = f.ruling(), X;
  if (tangent_plane) {
    I3 V = tangent_dir(r, f);
    int64_t j = r.range(1, 1 << 8) * r.sign();
    if (zero3(V)) return {};
    X = add3(mul3(D, r.range(-(1 << 8), 1 << 8)), mul3(V, j));
  } else {
    X = nonzero_bits3(r, 20);
  }
  return frame_case(r, f, C, add3(C, X), int(r.range(-40, 0)), parallel_dir(r, D));
}

// Exactly tangent: T = C + S' D on a ruling (S' != 0: not the apex), V in
// the tangent plane along it, origin T - S V, d = V k 2^j: a double root at
// t = S 2^(e - j) / k.
Case cone_tangent(Rng& r, bool axis) {
  ConeFrame f = cone_frame(r, axis);
  I3 V = tangent_dir(r, f);
  if (zero3(V)) return {};
  int64_t Sp;
  do Sp = r.range(-(1 << 16), 1 << 16);
  while (Sp == 0);
  I3 C = bits3(r, 30), T = add3(C, mul3(f.ruling(), Sp));
  I3 O = sub3(T, mul3(V, r.range(-(1 << 12), 1 << 12)));
  int64_t k = r.chance(50) ? r.sign() : (2 * r.range(1, 7) + 1) * r.sign();
  return frame_case(r, f, C, O, int(r.range(-40, 0)), lattice3(mul3(V, k), int(r.range(-8, 8))));
}

// Unit-ish cone: apex in [-1,1]^3, axis a random unit vector (30%: +-e_j)
// times 2^-6..2^6 (not a power of two), r = k |a| with k in [0.2, 2].
struct UnitCone {
  P3 p, au, a;
  double r, k;
};

UnitCone unit_cone(Rng& r) {
  UnitCone c;
  c.p = uniform3(r, 0);
  if (r.chance(30)) {
    c.au = {0, 0, 0};
    c.au[r.next() % 3] = r.sign();
  } else {
    c.au = unit_dir(r);
  }
  double len = length_factor(r, -6, 5);
  c.a = pmul(c.au, len);
  c.k = 0.2 + 1.8 * r.unit();
  c.r = c.k * len;
  return c;
}

// A point at height h along the axis, s times the cone's radius there from
// the axis (s < 1 inside, > 1 outside).
P3 cone_aim(Rng& r, const UnitCone& c, double h, double s) {
  return padd(padd(c.p, pmul(c.au, h)), pmul(perp_dir(r, c.au), s * c.k * std::fabs(h)));
}

// Origin in [-4,4]^3; direction random, or aimed at a point within 1.3 of
// the radius at a height in [-2, 2] (either nappe).
Case cone_random(Rng& r, bool aimed) {
  UnitCone c = unit_cone(r);
  P3 o = uniform3(r, 2);
  P3 d = aimed ? psub(cone_aim(r, c, 2 * r.sym(), 1.3 * r.unit()), o) : uniform3(r, 0);
  if (d == P3{0, 0, 0}) return {};
  return axial_case(o, d, c.p, c.a, c.r);
}

// Through the apex C 2^e along V: o = (C + S V) 2^e, d = V k 2^j; the
// polynomial is (t + S 2^(e - j) / k)^2 times its value at d: a double root
// wherever V is not a ruling. Cones: a unit-ish cone with V random (3 in 4),
// or a frame's cone with V its axis, perpendicular to it (W), or A + m' W,
// |m'| != |m| (inside or outside).
Case cone_apex(Rng& r) {
  I3 C = bits3(r, 30), V;
  int e = int(r.range(-40, 0));
  int64_t S = r.chance(10) ? 0 : r.range(-(1 << 16), 1 << 16);
  int64_t k = r.chance(50) ? r.sign() : (2 * r.range(1, 7) + 1) * r.sign();
  int pick = int(r.range(0, 3));
  auto d_of = [&](const I3& v) { return lattice3(mul3(v, k), int(r.range(-20, 20))); };
  if (pick == 0) {
    ConeFrame f = cone_frame(r, r.chance(50));
    int64_t mp;
    do mp = r.range(-16, 16);
    while (mp == f.m || mp == -f.m);
    V = r.chance(30) ? f.A : r.chance(30) ? f.W : add3(f.A, mul3(f.W, mp));
    return frame_case(r, f, C, add3(C, mul3(V, S)), e, d_of(V));
  }
  UnitCone c = unit_cone(r);
  V = nonzero_bits3(r, 12);
  return axial_case(lattice3(add3(C, mul3(V, S)), e), d_of(V), lattice3(C, e), c.a, c.r);
}

// A unit-ish cone, the origin L from the apex in a random direction, aimed
// at a point at height +-[0.5, 2] s times the radius there from the axis,
// s in [0, 1) or [0.97, 1.03]; d = aim - o or unit.
Case cone_far(Rng& r, double L) {
  UnitCone c = unit_cone(r);
  P3 o = padd(c.p, pmul(unit_dir(r), L));
  double h = r.sign() * (0.5 + 1.5 * r.unit()), s = r.chance(50) ? r.unit() : 0.97 + 0.06 * r.unit();
  P3 d = psub(cone_aim(r, c, h, s), o);
  if (r.chance(50)) d = pnormalize(d);
  return axial_case(o, d, c.p, c.a, c.r);
}

// A case as in one of the sections above (random, ruling, apex, both
// parallel-ruling blocks, tangent, far-origin at 1e6, and near-ruling,
// near-apex and grazing: one input moved by 1-3 ulps), for scaling.
Case cone_any(Rng& r) {
  Case v;
  switch (r.next() % 10) {
    case 0: return cone_random(r, true);
    case 1: return cone_ruling(r, r.chance(50));
    case 2: return cone_apex(r);
    case 3: return cone_parallel_ruling(r, false);
    case 4: return cone_parallel_ruling(r, true);
    case 5: return cone_tangent(r, r.chance(50));
    case 6: return cone_far(r, 1e6);
    case 7: v = r.chance(50) ? cone_ruling(r, r.chance(50)) : cone_parallel_ruling(r, false); break;
    case 8: v = cone_apex(r); break;
    default: v = cone_tangent(r, r.chance(50)); break;
  }
  if (!v.empty()) nudge_one(r, v, all_slots(13));
  return v;
}

// The cone's polynomial is homogeneous in w = o - p, in d and in (a, r)
// jointly: scaling (o, p) by 2^ko, d by 2^kd and (a, r) by 2^ka (each in
// {-500, 0, 500}, not all 0) scales its roots by 2^(ko - kd).
void scale_cone_groups(Rng& r, Case& v) {
  int k[3];
  do
    for (int& x : k) x = 500 * int(r.range(-1, 1));
  while (k[0] == 0 && k[1] == 0 && k[2] == 0);
  for (size_t i = 0; i < v.size(); ++i) {
    Case one = {v[i]};
    scale(one, k[i < 3 || (i >= 6 && i < 9) ? 0 : i < 6 ? 1 : 2]);
    v[i] = one[0];
  }
}

void gen_ray_cone(RayWriter& w) {
  const QuadKind& k = kRayCone;
  w.section("random",
            "unit-ish cones: apex in [-1,1]^3, a a random unit vector (30%: +-e_j) times 2^-6..2^6, r = k |a|, "
            "k in [0.2, 2]; origins in [-4,4]^3",
            "02", "012");
  quad_block(w, k, "random directions in [-1,1]^3", 50, [](Rng& r) { return cone_random(r, false); });
  quad_block(w, k, "aimed at a point within 1.3 of the cone's radius at a height in [-2, 2] (either nappe)", 60,
             [](Rng& r) { return cone_random(r, true); });

  w.section("ruling",
            "lines on the cone (n = inf): apex C 2^e, a = A 2^ea, r = m N 2^ea with W . A = 0, |W| = N; the "
            "ruling D = A + m W; o = (C + S D) 2^e (S = 0: the apex), d = D k 2^j",
            "i", "i");
  quad_block(w, k, "A = +-2^k e_j, W a Pythagorean triple", 50, [](Rng& r) { return cone_ruling(r, true); }, "i");
  quad_block(w, k, "any axis: W a Pythagorean quadruple, A = W x v", 50, [](Rng& r) { return cone_ruling(r, false); },
             "i");

  w.section("apex",
            "lines through the apex, not on the cone: a double root at t = -S 2^(e-j) / k (o = (C + S V) 2^e, "
            "d = V k 2^j; S = 0: the origin at the apex)",
            "1", "1");
  quad_block(w, k, "unit-ish cones with V random; exact cones with V along the axis, across it or A + m' W", 100,
             cone_apex, "1");

  w.section("parallel-ruling",
            "d along a ruling D (as in `ruling`, axis-aligned or any axis), origin off it: degree one (n = 1, "
            "t = -c/b); in the tangent plane along D, the polynomial a nonzero constant (n = 0)",
            "01", "01");
  quad_block(w, k, "origin (C + X) 2^e, X random below 2^20: n = 1", 100,
             [](Rng& r) { return cone_parallel_ruling(r, false); }, "1");
  quad_block(w, k, "origin (C + i D + j V) 2^e, V in the tangent plane along D: n = 0", 50,
             [](Rng& r) { return cone_parallel_ruling(r, true); }, "0");

  w.section("near-ruling",
            "the ruling and parallel-ruling (n = 1) lines with one coordinate of d moved by 1 ulp: a tiny leading "
            "coefficient, one root far out (rulings: the other exactly 0, the origin being on the cone)",
            "2", "012");
  quad_block(w, k, "rulings through the apex, d moved 1 ulp", 50, [](Rng& r) {
    Case v = cone_ruling(r, r.chance(50));
    nudge_one(r, v, {3, 4, 5}, 1);
    return v;
  });
  quad_block(w, k, "lines parallel to a ruling, d moved 1 ulp", 50, [](Rng& r) {
    Case v = cone_parallel_ruling(r, false);
    if (!v.empty()) nudge_one(r, v, {3, 4, 5}, 1);
    return v;
  });

  w.section("near-apex", "the apex lines with one coordinate of o or p moved by 1-3 ulps", "02", "012");
  quad_block(w, k, "one of o, p moved", 50, [](Rng& r) {
    Case v = cone_apex(r);
    nudge_one(r, v, {0, 1, 2, 6, 7, 8});
    return v;
  });

  w.section("tangent",
            "exactly tangent (n = 1): T = (C + S' D) 2^e on a ruling D (S' != 0), V = (G x u) in the tangent plane "
            "along D (G = |A|^2 W - m N^2 A), not parallel to D; o = (T - S V) 2^e, d = V k 2^j",
            "1", "1");
  quad_block(w, k, "A = +-2^k e_j, W a Pythagorean triple", 50, [](Rng& r) { return cone_tangent(r, true); }, "1");
  quad_block(w, k, "any axis: W a Pythagorean quadruple, A = W x v", 50, [](Rng& r) { return cone_tangent(r, false); },
             "1");

  w.section("grazing", "the tangent lines with one input moved by 1-3 ulps", "02", "012");
  quad_block(w, k, "one of o, d, p, a, r moved", 60, [](Rng& r) {
    Case v = cone_tangent(r, r.chance(50));
    if (!v.empty()) nudge_one(r, v, all_slots(13));
    return v;
  });

  w.section("far-origin",
            "unit-ish cones, origin 1e6..1e8 from the apex, aimed at a point at height +-[0.5, 2] s times the "
            "radius there from the axis, s in [0,1) or [0.97,1.03]; d = aim - o or unit",
            "02", "012");
  for (const char* L : {"1e6", "1e7", "1e8"}) {
    double dist = std::strtod(L, nullptr);
    quad_block(w, k, std::string("|o - p| = ") + L, 50, [dist](Rng& r) { return cone_far(r, dist); });
  }

  w.section("scaled",
            "cases from random, ruling, apex, parallel-ruling (both blocks), tangent, far-origin (1e6), near-ruling, "
            "near-apex and grazing (any input moved by 1-3 ulps) multiplied exactly by 2^500 or 2^-500: everything "
            "(t unchanged) or all but d (t scaled); or each group by its own power",
            "012i", "012i");
  for (int sgn_k : {1, -1}) {
    std::string label = std::string("scaled by 2^") + (sgn_k > 0 ? "500" : "-500");
    quad_block(w, k, label, 60, [sgn_k](Rng& r) {
      Case v = cone_any(r);
      if (!v.empty()) scale_case(r, v, 500 * sgn_k);
      return v;
    });
  }
  quad_block(w, k, "(o, p), d and (a, r) each times 2^-500, 1 or 2^500 (not all 1): t times 2^(k_op - k_d)", 60,
             [](Rng& r) {
               Case v = cone_any(r);
               if (!v.empty()) scale_cone_groups(r, v);
               return v;
             });
}

const char* const kRayHeaderQuad =
    "# The polynomial in t has exact rational coefficients; n comes from the exact sign of its\n"
    "# discriminant (and its degree). Roots are rounded to the nearest binary64 (ties to even):\n"
    "# rational roots by MPFR's correctly rounded conversion, irrational ones from a 320-bit MPFR\n"
    "# value proved correctly rounded by exact rational signs of the polynomial at the midpoints\n"
    "# to the neighbouring doubles. Every root is a normal double or exactly 0; cases whose two\n"
    "# distinct roots round to the same double are left out (the format promises t0 < t1).\n";

}  // namespace

void gen_ray_sphere_files(const std::string& outdir) {
  write_ray_file(outdir, "ray_sphere",
                 "# Line: ox oy oz dx dy dz cx cy cz r n [t0 t1]; the line o + t d against |x - c| = r.\n"
                 "# n = 1 (tangent) writes the double root twice.\n" +
                     std::string(kRayHeaderQuad) +
                     "# The count is checked against CGAL's squared line-point distance (rational kernel).\n",
                 gen_ray_sphere);
}

void gen_ray_cylinder_files(const std::string& outdir) {
  write_ray_file(outdir, "ray_cylinder",
                 "# Line: ox oy oz dx dy dz px py pz ax ay az r n [t0 t1]; the line o + t d against\n"
                 "# |(x - p) x a|^2 = r^2 |a|^2. n = 1 (tangent) writes the double root twice; n = inf: the\n"
                 "# line lies on the cylinder.\n" +
                     std::string(kRayHeaderQuad) +
                     "# The count is checked against CGAL's squared line-line distance (rational kernel).\n",
                 gen_ray_cylinder);
}

void gen_ray_cone_files(const std::string& outdir) {
  write_ray_file(outdir, "ray_cone",
                 "# Line: ox oy oz dx dy dz px py pz ax ay az r n [t0 [t1]]; the line o + t d against the\n"
                 "# double cone |(x - p) x a|^2 |a|^2 = r^2 ((x - p) . a)^2 (apex p, axis a, radius r at p + a;\n"
                 "# both nappes). Exactly n roots follow (one for a double root or degree one); n = inf: the\n"
                 "# line is a ruling of the cone.\n" +
                     std::string(kRayHeaderQuad) +
                     "# The expansion is checked against the definition in CGAL's rational kernel at t = -1, 0, 1.\n",
                 gen_ray_cone);
}

void gen_ray_quadric_files(const std::string& outdir) {
  write_ray_file(outdir, "ray_quadric",
                 "# Line: ox oy oz dx dy dz A B C D E F G H I J n [t0 [t1]]; the line o + t d against\n"
                 "# A x^2 + B y^2 + C z^2 + D xy + E xz + F yz + G x + H y + I z + J = 0. Exactly n roots\n"
                 "# follow (one for a double root or degree one); n = inf: the polynomial is zero.\n" +
                     std::string(kRayHeaderQuad),
                 gen_ray_quadric);
}

}  // namespace fixtures
