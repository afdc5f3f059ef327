// orient2d, orient3d, plane_side, incircle, insphere: exact signs from CGAL,
// the degenerate configurations they are built around (collinear, coplanar,
// cocircular, cospherical), and their shared section structure.

#include "common.h"

namespace fixtures {
namespace {

// ---------------------------------------------------------------------------
// Exact signs. Epick (filtered, exact fallback) gives the answer; the plain
// rational kernel recomputes it, and any disagreement stops the generator.

int orient2d_exact(const double* v) {
  Epick::Point_2 a(v[0], v[1]), b(v[2], v[3]), c(v[4], v[5]);
  int s = int(CGAL::orientation(a, b, c));
  auto q = [](double x) { return CGAL::Exact_rational(x); };
  RatK::Point_2 ra(q(v[0]), q(v[1])), rb(q(v[2]), q(v[3])), rc(q(v[4]), q(v[5]));
  if (int(CGAL::orientation(ra, rb, rc)) != s) die("Epick and rational orient2d disagree");
  return s;
}

int orient3d_exact(const double* v) {
  Epick::Point_3 a(v[0], v[1], v[2]), b(v[3], v[4], v[5]), c(v[6], v[7], v[8]), d(v[9], v[10], v[11]);
  int s = int(CGAL::orientation(a, b, c, d));
  auto q = [](double x) { return CGAL::Exact_rational(x); };
  RatK::Point_3 ra(q(v[0]), q(v[1]), q(v[2])), rb(q(v[3]), q(v[4]), q(v[5])),
      rc(q(v[6]), q(v[7]), q(v[8])), rd(q(v[9]), q(v[10]), q(v[11]));
  if (int(CGAL::orientation(ra, rb, rc, rd)) != s) die("Epick and rational orient3d disagree");
  return s;
}

int plane_side_exact(const double* v) {
  double p[12], q[12];
  std::memcpy(p, v, 9 * sizeof(double));
  std::memcpy(q, v, 9 * sizeof(double));
  std::memcpy(p + 9, v + 9, 3 * sizeof(double));
  std::memcpy(q + 9, v + 12, 3 * sizeof(double));
  return orient3d_exact(p) * orient3d_exact(q);
}

// CGAL's side_of_oriented_circle: 1 when d is inside the circle through
// counterclockwise a, b, c.
int incircle_exact(const double* v) {
  Epick::Point_2 a(v[0], v[1]), b(v[2], v[3]), c(v[4], v[5]), d(v[6], v[7]);
  int s = int(CGAL::side_of_oriented_circle(a, b, c, d));
  auto q = [](double x) { return CGAL::Exact_rational(x); };
  RatK::Point_2 ra(q(v[0]), q(v[1])), rb(q(v[2]), q(v[3])), rc(q(v[4]), q(v[5])), rd(q(v[6]), q(v[7]));
  if (int(CGAL::side_of_oriented_circle(ra, rb, rc, rd)) != s) die("Epick and rational incircle disagree");
  return s;
}

// CGAL's side_of_oriented_sphere: 1 when e is inside the sphere through
// a, b, c, d with orientation(a, b, c, d) positive.
int insphere_exact(const double* v) {
  auto ep = [v](int i) { return Epick::Point_3(v[3 * i], v[3 * i + 1], v[3 * i + 2]); };
  auto q = [](double x) { return CGAL::Exact_rational(x); };
  auto rp = [v, q](int i) { return RatK::Point_3(q(v[3 * i]), q(v[3 * i + 1]), q(v[3 * i + 2])); };
  int s = int(CGAL::side_of_oriented_sphere(ep(0), ep(1), ep(2), ep(3), ep(4)));
  if (int(CGAL::side_of_oriented_sphere(rp(0), rp(1), rp(2), rp(3), rp(4))) != s)
    die("Epick and rational insphere disagree");
  return s;
}

// Plain double evaluations, only to report how hard each section is.
int sign_of(double d) { return (d > 0) - (d < 0); }

int orient2d_naive(const double* v) {
  return sign_of((v[2] - v[0]) * (v[5] - v[1]) - (v[3] - v[1]) * (v[4] - v[0]));
}

int orient3d_naive(const double* v) {
  double bx = v[3] - v[0], by = v[4] - v[1], bz = v[5] - v[2];
  double cx = v[6] - v[0], cy = v[7] - v[1], cz = v[8] - v[2];
  double dx = v[9] - v[0], dy = v[10] - v[1], dz = v[11] - v[2];
  return sign_of(bx * (cy * dz - cz * dy) - by * (cx * dz - cz * dx) + bz * (cx * dy - cy * dx));
}

// det[[a-d, |a-d|^2], [b-d, |b-d|^2], [c-d, |c-d|^2]] (Shewchuk's incircle).
int incircle_naive(const double* v) {
  double r[3][3];
  for (int i = 0; i < 3; ++i) {
    double x = v[2 * i] - v[6], y = v[2 * i + 1] - v[7];
    r[i][0] = x, r[i][1] = y, r[i][2] = x * x + y * y;
  }
  return sign_of(r[0][2] * (r[1][0] * r[2][1] - r[1][1] * r[2][0]) +
                 r[1][2] * (r[2][0] * r[0][1] - r[2][1] * r[0][0]) +
                 r[2][2] * (r[0][0] * r[1][1] - r[0][1] * r[1][0]));
}

// -det[[a-e, |a-e|^2], ..., [d-e, |d-e|^2]], expanded along the lift column:
// CGAL's sign (the opposite of Shewchuk's insphere).
int insphere_naive(const double* v) {
  double r[4][4];
  for (int i = 0; i < 4; ++i) {
    double x = v[3 * i] - v[12], y = v[3 * i + 1] - v[13], z = v[3 * i + 2] - v[14];
    r[i][0] = x, r[i][1] = y, r[i][2] = z, r[i][3] = x * x + y * y + z * z;
  }
  auto minor = [&r](int a, int b, int c) {
    return r[a][0] * (r[b][1] * r[c][2] - r[b][2] * r[c][1]) - r[a][1] * (r[b][0] * r[c][2] - r[b][2] * r[c][0]) +
           r[a][2] * (r[b][0] * r[c][1] - r[b][1] * r[c][0]);
  };
  double det = -r[0][3] * minor(1, 2, 3) + r[1][3] * minor(0, 2, 3) - r[2][3] * minor(0, 1, 3) +
               r[3][3] * minor(0, 1, 2);
  return -sign_of(det);
}

int plane_side_naive(const double* v) {
  double p[12], q[12];
  std::memcpy(p, v, 9 * sizeof(double));
  std::memcpy(q, v, 9 * sizeof(double));
  std::memcpy(p + 9, v + 9, 3 * sizeof(double));
  std::memcpy(q + 9, v + 12, 3 * sizeof(double));
  return orient3d_naive(p) * orient3d_naive(q);
}

}  // namespace

// Fails loudly if the kernels' conventions are not the ones docs/fixture-format.md states.
void check_conventions() {
  const double l[6] = {0, 0, 1, 0, 0, 1};  // counterclockwise
  const double o[12] = {0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1};  // det(I) = 1
  if (orient2d_exact(l) != 1 || orient2d_naive(l) != 1) die("orient2d convention");
  if (orient3d_exact(o) != 1 || orient3d_naive(o) != 1) die("orient3d convention");
  // The unit circle through counterclockwise (1,0), (0,1), (-1,0): the
  // origin inside, (0,-1) on it, (2,0) outside; reversed order flips it.
  const double c_in[8] = {1, 0, 0, 1, -1, 0, 0, 0}, c_on[8] = {1, 0, 0, 1, -1, 0, 0, -1};
  const double c_out[8] = {1, 0, 0, 1, -1, 0, 2, 0}, c_cw[8] = {0, 1, 1, 0, -1, 0, 0, 0};
  if (incircle_exact(c_in) != 1 || incircle_naive(c_in) != 1 || incircle_exact(c_on) != 0 ||
      incircle_exact(c_out) != -1 || incircle_naive(c_out) != -1 || incircle_exact(c_cw) != -1)
    die("incircle convention");
  // The positively oriented tetrahedron 0, e1, e2, e3 (orient3d = 1): its
  // circumsphere holds (1/4, 1/4, 1/4) and passes through (1, 1, 1).
  double s_in[15] = {0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1, 0.25, 0.25, 0.25};
  if (insphere_exact(s_in) != 1 || insphere_naive(s_in) != 1) die("insphere convention");
  s_in[12] = s_in[13] = s_in[14] = 1;
  if (insphere_exact(s_in) != 0) die("insphere convention (on the sphere)");
  s_in[12] = s_in[13] = s_in[14] = 2;
  if (insphere_exact(s_in) != -1 || insphere_naive(s_in) != -1) die("insphere convention (outside)");
}

namespace {

// ---------------------------------------------------------------------------
// Exactly degenerate configurations

enum class Variant {
  LatticeSmall,  // dyadic points of a line/plane, coordinates below 2^22
  LatticeFar,    // integer points up to 2^50 apart, some close together
  Offset40,      // coordinates 2^40 plus dyadic offsets, all 53 bits used
  Axis,          // one coordinate shared, the others arbitrary doubles
  Diagonal,      // one coordinate = +-2^k times another, arbitrary doubles
  Repeated,      // a point repeated
  CollinearTri,  // 3D only: the triangle is a segment, the query anywhere
  Aniso,         // mixed: lattice scaled by 2^~950 on some axes, 2^~-1040 on others
  SharedHuge,    // mixed: one huge coordinate shared by all points, the rest tiny
  // incircle and insphere only (the others give collinear or coplanar
  // points there, which the lifted determinant also takes to zero):
  Cyclic,        // integer points on a circle / sphere around a 30-bit centre, times 2^e
  CyclicFar,     // the same with radii ~2^20-2^28
  CyclicOffset,  // a small circle / sphere around 2^40 + dyadic offsets (53-bit values)
  Cocircular,    // insphere only: four points on a circle in a tilted plane, the fifth anywhere
};

const std::vector<Variant> kPlainVariants2 = {Variant::LatticeSmall, Variant::LatticeFar, Variant::Offset40,
                                              Variant::Axis,         Variant::Diagonal,   Variant::Repeated};
const std::vector<Variant> kPlainVariants3 = {Variant::LatticeSmall, Variant::LatticeFar, Variant::Offset40,
                                              Variant::Axis,         Variant::Diagonal,   Variant::Repeated,
                                              Variant::CollinearTri};
const std::vector<Variant> kMixedVariants = {Variant::Aniso, Variant::SharedHuge};
const std::vector<Variant> kCircleVariants = {Variant::Cyclic,       Variant::CyclicFar, Variant::CyclicOffset,
                                              Variant::LatticeSmall, Variant::Axis,      Variant::Repeated};
const std::vector<Variant> kSphereVariants = {Variant::Cyclic,       Variant::CyclicFar, Variant::CyclicOffset,
                                              Variant::Cocircular,   Variant::LatticeSmall, Variant::Axis,
                                              Variant::Repeated};

bool cyclic(Variant v) {
  return v == Variant::Cyclic || v == Variant::CyclicFar || v == Variant::CyclicOffset || v == Variant::Cocircular;
}

const char* variant_name(Variant v) {
  switch (v) {
    case Variant::LatticeSmall: return "dyadic lattice points, multiples of 2^-e, e in 30..70";
    case Variant::LatticeFar: return "integer lattice points up to 2^50 apart";
    case Variant::Offset40: return "coordinates 2^40 + dyadic offsets (53-bit values)";
    case Variant::Axis: return "one coordinate shared, others arbitrary";
    case Variant::Diagonal: return "one coordinate = +-2^k * another, arbitrary values";
    case Variant::Repeated: return "repeated points";
    case Variant::CollinearTri: return "collinear triangle, query anywhere";
    case Variant::Aniso: return "lattice scaled by ~2^950 on some axes and ~2^-1040 on others";
    case Variant::SharedHuge: return "huge coordinate equal across points, tiny others";
    case Variant::Cyclic: return "integer points on a circle or sphere (radius < 2^8) around a 30-bit centre, times 2^e";
    case Variant::CyclicFar: return "integer points on a circle (radius ~2^21) or sphere (~2^20..2^28), times 2^e";
    case Variant::CyclicOffset: return "a small circle or sphere around 2^40 + dyadic offsets (53-bit values)";
    case Variant::Cocircular: return "four integer points on a circle in a tilted plane, the fifth anywhere";
  }
  return "";
}

// At least three points, all exactly on one line.
std::vector<P2> make_line(Rng& r, Variant v) {
  std::vector<P2> pts;
  // Points A + t D with integers below 2^53, each axis scaled by 2^e[axis].
  auto lattice_line = [&](std::array<int64_t, 2> a, int bd, int bt_small, int bt_big, std::array<int, 2> e) {
    std::array<int64_t, 2> d;
    do d = {r.bits(bd), r.bits(bd)};
    while (d[0] == 0 && d[1] == 0);
    for (int i = 0; i < 5; ++i) {
      int64_t t = r.bits(i < 3 ? bt_small : bt_big);
      pts.push_back({lattice(a[0] + t * d[0], e[0]), lattice(a[1] + t * d[1], e[1])});
    }
  };
  switch (v) {
    case Variant::LatticeSmall: {
      int e = int(r.range(-70, -30));
      lattice_line({r.bits(30), r.bits(30)}, 10, 10, 10, {e, e});
      break;
    }
    case Variant::LatticeFar: {
      int e = int(r.range(-20, 10));
      lattice_line({r.bits(20), r.bits(20)}, 12, 3, 38, {e, e});
      break;
    }
    case Variant::Offset40: {
      auto base = [&] { return r.sign() * ((int64_t(1) << 52) + r.range(0, int64_t(1) << 32)); };
      lattice_line({base(), base()}, 10, 10, 10, {-12, -12});
      break;
    }
    case Variant::Axis: {
      int axis = int(r.next() % 2);
      double c = arbitrary(r);
      for (int i = 0; i < 5; ++i) {
        P2 p = {arbitrary(r), arbitrary(r)};
        p[axis] = c;
        pts.push_back(p);
      }
      break;
    }
    case Variant::Diagonal: {
      int k = int(r.range(-3, 3)), s = r.sign(), axis = int(r.next() % 2);
      for (int i = 0; i < 5; ++i) {
        double x = arbitrary(r);
        P2 p = {x, s * std::ldexp(x, k)};
        if (axis) std::swap(p[0], p[1]);
        pts.push_back(p);
      }
      break;
    }
    case Variant::Repeated: {
      P2 a = {arbitrary(r), arbitrary(r)}, b = {arbitrary(r), arbitrary(r)};
      pts = r.chance(75) ? std::vector<P2>{a, a, b} : std::vector<P2>{a, a, a};
      break;
    }
    case Variant::Aniso:
      lattice_line({r.bits(30), r.bits(30)}, 10, 10, 10, aniso_exps<2>(r));
      break;
    case Variant::SharedHuge: {
      int axis = int(r.next() % 2);
      double h = std::ldexp(r.sym(), int(r.range(990, 1023)));
      for (int i = 0; i < 5; ++i) {
        P2 p;
        p[axis] = h;
        p[1 - axis] = std::ldexp(r.sym(), int(r.range(-1040, -990)));
        pts.push_back(p);
      }
      break;
    }
    case Variant::CollinearTri: die("CollinearTri is a 3D variant");
    default: die("a cyclic variant is not a line");
  }
  return pts;
}

// A triangle and points exactly on its plane (for a collinear triangle:
// points anywhere, since every orientation with it is zero).
struct Plane {
  std::array<P3, 3> tri;
  std::vector<P3> on;
};

Plane make_plane(Rng& r, Variant v) {
  std::vector<P3> pts;
  // Points A + s U + t V with integers below 2^53, axis i scaled by 2^e[i].
  auto lattice_plane = [&](std::array<int64_t, 3> a, int bd, int bt_small, int bt_big, std::array<int, 3> e) {
    std::array<int64_t, 3> u, w;
    for (int i = 0; i < 3; ++i) u[i] = r.bits(bd), w[i] = r.bits(bd);
    for (int i = 0; i < 7; ++i) {
      int bt = i < 4 ? bt_small : bt_big;
      int64_t s = r.bits(bt), t = r.bits(bt);
      P3 p;
      for (int k = 0; k < 3; ++k) p[k] = lattice(a[k] + s * u[k] + t * w[k], e[k]);
      pts.push_back(p);
    }
  };
  auto arb3 = [&] { return P3{arbitrary(r), arbitrary(r), arbitrary(r)}; };
  switch (v) {
    case Variant::LatticeSmall: {
      int e = int(r.range(-70, -30));
      lattice_plane({r.bits(30), r.bits(30), r.bits(30)}, 10, 10, 10, {e, e, e});
      break;
    }
    case Variant::LatticeFar: {
      int e = int(r.range(-20, 10));
      lattice_plane({r.bits(20), r.bits(20), r.bits(20)}, 6, 3, 40, {e, e, e});
      break;
    }
    case Variant::Offset40: {
      auto base = [&] { return r.sign() * ((int64_t(1) << 52) + r.range(0, int64_t(1) << 32)); };
      lattice_plane({base(), base(), base()}, 8, 10, 10, {-12, -12, -12});
      break;
    }
    case Variant::Axis: {
      int axis = int(r.next() % 3);
      double c = arbitrary(r);
      for (int i = 0; i < 7; ++i) {
        P3 p = arb3();
        p[axis] = c;
        pts.push_back(p);
      }
      break;
    }
    case Variant::Diagonal: {
      int k = int(r.range(-3, 3)), s = r.sign();
      int i = int(r.next() % 3), j = (i + 1 + int(r.next() % 2)) % 3;
      for (int n = 0; n < 7; ++n) {
        P3 p = arb3();
        p[i] = s * std::ldexp(p[j], k);
        pts.push_back(p);
      }
      break;
    }
    case Variant::Repeated: {
      Plane pl;
      if (r.chance(50)) {
        pl.tri = {arb3(), arb3(), arb3()};
        pl.on = {pl.tri[0], pl.tri[1], pl.tri[2]};
      } else {
        P3 a = arb3();
        pl.tri = {a, a, arb3()};
        for (int i = 0; i < 4; ++i) pl.on.push_back(arb3());
      }
      return pl;
    }
    case Variant::CollinearTri: {
      Plane pl;
      if (r.chance(50)) {
        int e = int(r.range(-40, 0));
        std::array<int64_t, 3> a = {r.bits(30), r.bits(30), r.bits(30)}, d;
        do d = {r.bits(10), r.bits(10), r.bits(10)};
        while (d[0] == 0 && d[1] == 0 && d[2] == 0);
        for (auto& p : pl.tri) {
          int64_t t = r.bits(12);
          p = {lattice(a[0] + t * d[0], e), lattice(a[1] + t * d[1], e), lattice(a[2] + t * d[2], e)};
        }
      } else {
        int k = int(r.range(-2, 2));
        for (auto& p : pl.tri) {
          double x = arbitrary(r);
          p = {x, x, std::ldexp(x, k)};
        }
      }
      for (int i = 0; i < 4; ++i) pl.on.push_back(arb3());
      return pl;
    }
    case Variant::Aniso:
      lattice_plane({r.bits(30), r.bits(30), r.bits(30)}, 10, 10, 10, aniso_exps<3>(r));
      break;
    case Variant::SharedHuge: {
      int axis = int(r.next() % 3);
      double h = std::ldexp(r.sym(), int(r.range(990, 1023)));
      for (int i = 0; i < 7; ++i) {
        P3 p;
        for (double& x : p) x = std::ldexp(r.sym(), int(r.range(-1040, -990)));
        p[axis] = h;
        pts.push_back(p);
      }
      break;
    }
    default: die("a cyclic variant is not a plane");
  }
  Plane pl;
  pl.tri = {pts[0], pts[1], pts[2]};
  pl.on.assign(pts.begin() + 3, pts.end());
  return pl;
}

// Integer points on circles and spheres, from Gaussian integers and
// quaternions: a product of Gaussian integers (quaternions) has the product
// of their norms as its norm, so products of the same factors, each
// conjugated or not (each chosen among the quaternions of one norm), lie on
// one circle |z|^2 = N (one sphere |W| = N, W the rotation of i by the
// product: the Pythagorean quadruple of `pythagorean` in the ray kinds).
using I2 = std::array<int64_t, 2>;
using Quat = std::array<int64_t, 4>;

// Gaussian primes of norms 5, 13, 17, 29, 37, 41, 53, 61, 73.
const I2 kGaussPrimes[] = {{2, 1}, {3, 2}, {4, 1}, {5, 2}, {6, 1}, {5, 4}, {7, 2}, {6, 5}, {8, 3}};

I2 gmul(const I2& a, const I2& b) { return I2{a[0] * b[0] - a[1] * b[1], a[0] * b[1] + a[1] * b[0]}; }

// n points on the circle |z|^2 = prod of the norms of the first k Gaussian
// primes: each a product of those primes, each conjugated or not, times a
// unit.
std::vector<I2> circle_points(Rng& r, int k, size_t n) {
  std::vector<I2> out;
  for (size_t i = 0; i < n; ++i) {
    I2 z = {1, 0};
    for (int j = 0; j < k; ++j) {
      I2 g = kGaussPrimes[j];
      if (r.chance(50)) g[1] = -g[1];
      z = gmul(z, g);
    }
    for (int u = int(r.next() % 4); u > 0; --u) z = {-z[1], z[0]};  // times i
    out.push_back(z);
  }
  return out;
}

Quat qmul(const Quat& a, const Quat& b) {
  return Quat{a[0] * b[0] - a[1] * b[1] - a[2] * b[2] - a[3] * b[3],
              a[0] * b[1] + a[1] * b[0] + a[2] * b[3] - a[3] * b[2],
              a[0] * b[2] - a[1] * b[3] + a[2] * b[0] + a[3] * b[1],
              a[0] * b[3] + a[1] * b[2] - a[2] * b[1] + a[3] * b[0]};
}

int64_t qnorm(const Quat& q) { return q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3]; }

// Every integer quaternion of norm p (brute force; p is small).
std::vector<Quat> quats_of_norm(int64_t p) {
  std::vector<Quat> out;
  int64_t m = 0;
  while ((m + 1) * (m + 1) <= p) ++m;
  for (int64_t a = -m; a <= m; ++a)
    for (int64_t b = -m; b <= m; ++b)
      for (int64_t c = -m; c <= m; ++c)
        for (int64_t d = -m; d <= m; ++d)
          if (qnorm({a, b, c, d}) == p) out.push_back({a, b, c, d});
  return out;
}

// n points on the sphere |W| = N, N = the product of the first k norms of
// {3, 5, 7, 11, 13, 3, 5, ...}: W is the rotation of i by a product of one
// random quaternion of each of those norms.
std::vector<I3> sphere_points(Rng& r, int k, size_t n) {
  static const int64_t norms[5] = {3, 5, 7, 11, 13};
  static const std::vector<Quat> factors[5] = {quats_of_norm(3), quats_of_norm(5), quats_of_norm(7),
                                               quats_of_norm(11), quats_of_norm(13)};
  std::vector<I3> out;
  for (size_t i = 0; i < n; ++i) {
    Quat q = {1, 0, 0, 0};
    int64_t N = 1;
    for (int j = 0; j < k; ++j) {
      q = qmul(q, r.pick(factors[j % 5]));
      N *= norms[j % 5];
    }
    if (qnorm(q) != N) die("quaternion norm");
    I3 w = {q[0] * q[0] + q[1] * q[1] - q[2] * q[2] - q[3] * q[3], 2 * (q[0] * q[3] + q[1] * q[2]),
            2 * (q[1] * q[3] - q[0] * q[2])};
    if (w[0] * w[0] + w[1] * w[1] + w[2] * w[2] != N * N) die("not on the sphere");
    out.push_back(w);
  }
  return out;
}

// A 30-bit (CyclicFar: 20-bit) centre, or (CyclicOffset) one near 2^52 at
// 2^-12, and the exponent the integer points are scaled by.
int64_t cyclic_centre(Rng& r, Variant v) {
  switch (v) {
    case Variant::CyclicFar: return r.bits(20);
    case Variant::CyclicOffset: return r.sign() * ((int64_t(1) << 52) + r.range(0, int64_t(1) << 32));
    default: return r.bits(30);
  }
}

int cyclic_exp(Rng& r, Variant v) {
  switch (v) {
    case Variant::CyclicFar: return int(r.range(-20, 10));
    case Variant::CyclicOffset: return -12;
    default: return int(r.range(-70, -30));
  }
}

// n points exactly on one circle: C + z, z from circle_points with 2-4
// primes (CyclicFar: 8-9, radius ~2^21), times 2^e.
std::vector<P2> make_circle(Rng& r, Variant v, size_t n) {
  int k = v == Variant::CyclicFar ? int(r.range(8, 9)) : int(r.range(2, 4));
  I2 C = {cyclic_centre(r, v), cyclic_centre(r, v)};
  int e = cyclic_exp(r, v);
  std::vector<P2> pts;
  for (const I2& z : circle_points(r, k, n)) pts.push_back({lattice(C[0] + z[0], e), lattice(C[1] + z[1], e)});
  return pts;
}

// n points exactly on one sphere: C + W, W from sphere_points with 2-3
// factors (CyclicFar: 8-10, radius ~2^20..2^28), times 2^e. Cocircular:
// four points M (x, y, h) + C, (x, y) on a circle from circle_points and M
// the integer matrix |q|^2 times the rotation of a random quaternion q
// (a similarity, so the circle maps to a circle in a tilted plane), then
// one lattice point anywhere near them.
std::vector<P3> make_sphere(Rng& r, Variant v, size_t n) {
  I3 C = {cyclic_centre(r, v), cyclic_centre(r, v), cyclic_centre(r, v)};
  int e = v == Variant::Cocircular ? int(r.range(-40, 0)) : cyclic_exp(r, v);
  std::vector<I3> ws;
  if (v == Variant::Cocircular) {
    Quat q;
    do q = {r.range(-3, 3), r.range(-3, 3), r.range(-3, 3), r.range(-3, 3)};
    while (qnorm(q) == 0);
    int64_t a = q[0], b = q[1], c = q[2], d = q[3];
    const int64_t M[3][3] = {{a * a + b * b - c * c - d * d, 2 * (b * c - a * d), 2 * (b * d + a * c)},
                             {2 * (b * c + a * d), a * a - b * b + c * c - d * d, 2 * (c * d - a * b)},
                             {2 * (b * d - a * c), 2 * (c * d + a * b), a * a - b * b - c * c + d * d}};
    int64_t h = r.bits(10);
    for (const I2& z : circle_points(r, int(r.range(2, 3)), 4)) {
      const int64_t x[3] = {z[0], z[1], h};
      ws.push_back({M[0][0] * x[0] + M[0][1] * x[1] + M[0][2] * x[2], M[1][0] * x[0] + M[1][1] * x[1] + M[1][2] * x[2],
                    M[2][0] * x[0] + M[2][1] * x[1] + M[2][2] * x[2]});
    }
    while (ws.size() < n) ws.push_back({r.bits(12), r.bits(12), r.bits(12)});
  } else {
    ws = sphere_points(r, v == Variant::CyclicFar ? int(r.range(8, 10)) : int(r.range(2, 3)), n);
  }
  std::vector<P3> pts;
  for (const I3& w : ws) pts.push_back(lattice3(add3(C, w), e));
  return pts;
}

// ---------------------------------------------------------------------------
// Sign kinds: orient2d, orient3d, plane_side, incircle, insphere share their
// section structure.

struct SignKind {
  int (*exact)(const double*);
  int (*naive)(const double*);
  // Reorders the points without changing which configuration it is.
  void (*shuffle)(Rng&, Case&);
  // A case whose exact answer is 0, of the given variant.
  Case (*degenerate)(Rng&, Variant);
  const std::vector<Variant>* plain_variants;
  // What the degenerate section holds, and the label prefix for the
  // variants that are not cyclic (for incircle and insphere: "collinear: ",
  // "coplanar: ").
  const char* degenerate_what;
  const char* flat_prefix;
};

template <size_t D>
void shuffle_points(Rng& r, Case& v, size_t first, size_t count) {
  for (size_t i = count - 1; i > 0; --i) {
    size_t j = r.next() % (i + 1);
    for (size_t k = 0; k < D; ++k) std::swap(v[(first + i) * D + k], v[(first + j) * D + k]);
  }
}

void shuffle_orient2d(Rng& r, Case& v) { shuffle_points<2>(r, v, 0, 3); }
void shuffle_orient3d(Rng& r, Case& v) { shuffle_points<3>(r, v, 0, 4); }
void shuffle_incircle(Rng& r, Case& v) { shuffle_points<2>(r, v, 0, 4); }
void shuffle_insphere(Rng& r, Case& v) { shuffle_points<3>(r, v, 0, 5); }
void shuffle_plane_side(Rng& r, Case& v) {
  shuffle_points<3>(r, v, 0, 3);
  shuffle_points<3>(r, v, 3, 2);
}

void append(Case& v, const P2& p) { v.insert(v.end(), p.begin(), p.end()); }
void append(Case& v, const P3& p) { v.insert(v.end(), p.begin(), p.end()); }

Case degenerate_orient2d(Rng& r, Variant variant) {
  std::vector<P2> pts = make_line(r, variant);
  Case v;
  for (size_t i = 0; i < 3; ++i) {
    // Distinct picks (the Repeated variant repeats points by itself).
    size_t j = i + r.next() % (pts.size() - i);
    std::swap(pts[i], pts[j]);
    append(v, pts[i]);
  }
  return v;
}

Case degenerate_orient3d(Rng& r, Variant variant) {
  Plane pl = make_plane(r, variant);
  Case v;
  for (const P3& p : pl.tri) append(v, p);
  append(v, r.pick(pl.on));
  return v;
}

Case degenerate_plane_side(Rng& r, Variant variant) {
  Plane pl = make_plane(r, variant);
  Case v;
  for (const P3& p : pl.tri) append(v, p);
  append(v, r.pick(pl.on));
  if (r.chance(50)) {
    append(v, r.pick(pl.on));
  } else {
    // q off the plane (most likely), at the scale of the configuration.
    int e = std::max(-1000, std::min(1000, max_exp(v)));
    append(v, P3{std::ldexp(r.sym(), e), std::ldexp(r.sym(), e), std::ldexp(r.sym(), e)});
  }
  return v;
}

// Four points on one circle (cyclic variants) or one line (the others).
Case degenerate_incircle(Rng& r, Variant variant) {
  std::vector<P2> pts = cyclic(variant) ? make_circle(r, variant, 4) : make_line(r, variant);
  Case v;
  for (int i = 0; i < 4; ++i) append(v, cyclic(variant) ? pts[i] : r.pick(pts));
  return v;
}

// Five points on one sphere, four on one circle (cyclic variants), a point
// repeated among arbitrary ones (Repeated) or five on one plane (the others).
Case degenerate_insphere(Rng& r, Variant variant) {
  Case v;
  if (cyclic(variant)) {
    for (const P3& p : make_sphere(r, variant, 5)) append(v, p);
    return v;
  }
  if (variant == Variant::Repeated) {
    P3 a = {arbitrary(r), arbitrary(r), arbitrary(r)};
    append(v, a);
    append(v, a);
    for (int i = 0; i < 3; ++i) append(v, P3{arbitrary(r), arbitrary(r), arbitrary(r)});
    return v;
  }
  Plane pl = make_plane(r, variant);
  std::vector<P3> pts(pl.tri.begin(), pl.tri.end());
  pts.insert(pts.end(), pl.on.begin(), pl.on.end());
  for (int i = 0; i < 5; ++i) append(v, r.pick(pts));
  return v;
}

const char* const kFlatWhat = "exactly collinear / coplanar points, no rounding in their construction";
const SignKind kOrient2d = {orient2d_exact,      orient2d_naive,   shuffle_orient2d, degenerate_orient2d,
                            &kPlainVariants2,    kFlatWhat,        ""};
const SignKind kOrient3d = {orient3d_exact,      orient3d_naive,   shuffle_orient3d, degenerate_orient3d,
                            &kPlainVariants3,    kFlatWhat,        ""};
const SignKind kPlaneSide = {plane_side_exact,   plane_side_naive, shuffle_plane_side, degenerate_plane_side,
                             &kPlainVariants3,   kFlatWhat,        ""};
const SignKind kIncircle = {incircle_exact,      incircle_naive,   shuffle_incircle, degenerate_incircle,
                            &kCircleVariants,
                            "exactly cocircular points (or collinear, or repeated), no rounding in their construction",
                            "collinear: "};
const SignKind kInsphere = {insphere_exact,      insphere_naive,   shuffle_insphere, degenerate_insphere,
                            &kSphereVariants,
                            "exactly cospherical points (or four cocircular, or all coplanar, or repeated), no "
                            "rounding in their construction",
                            "coplanar: "};

void emit(Writer& w, const SignKind& k, const Case& v) { w.emit(v, k.exact(v.data()), k.naive(v.data())); }

// Moves 1 to 3 coordinates by 1 to 3 ulps each: the smallest changes that
// can turn a degenerate configuration into a nondegenerate one.
void perturb(Rng& r, Case& v) {
  int n = 1 + r.chance(30) + r.chance(10);
  for (int i = 0; i < n; ++i) {
    double& x = v[r.next() % v.size()];
    x = step_ulps(x, int(r.range(1, 3)) * r.sign());
  }
}

// Each coordinate is `coord(rng)`.
template <class F>
void random_block(Writer& w, const SignKind& k, const std::string& label, int n, size_t ncoords, F coord) {
  Rng r = w.block(label);
  for (int i = 0; i < n; ++i) {
    Case v(ncoords);
    for (double& x : v) x = coord(r);
    emit(w, k, v);
  }
}

// Degenerate configurations of every variant in `variants`, optionally
// perturbed (`perturb_pct` percent of them) and scaled (`target`: exponent
// range for the largest coordinate; empty for no scaling).
void variant_blocks(Writer& w, const SignKind& k, const std::vector<Variant>& variants, int n_each,
                    int perturb_pct, std::array<int, 2> target, bool scaled) {
  for (Variant var : variants) {
    std::string label = std::string(cyclic(var) ? "" : k.flat_prefix) + variant_name(var);
    if (perturb_pct > 0) label += ", " + std::to_string(perturb_pct) + "% moved by 1-3 ulps";
    if (scaled) label += ", scaled to max ~2^[" + std::to_string(target[0]) + "," + std::to_string(target[1]) + "]";
    Rng r = w.block(label);
    for (int i = 0; i < n_each; ++i) {
      Case v = k.degenerate(r, var);
      if (scaled) scale_towards(v, int(r.range(target[0], target[1])));
      if (r.chance(perturb_pct)) perturb(r, v);
      k.shuffle(r, v);
      emit(w, k, v);
    }
  }
}

// Sizes of the shared sections; `scale` trades file size for coverage.
struct Counts {
  int random, grid, degenerate_each, near_each, tiny, huge, mixed;
};

void common_sections(Writer& w, const SignKind& k, size_t ncoords, const Counts& c) {
  const auto& plain = *k.plain_variants;

  w.section("random", "coordinates uniform in [-1, 1]", "+-", "+-0");
  random_block(w, k, "uniform in [-1, 1]", c.random, ncoords, [](Rng& r) { return r.sym(); });

  w.section("random-grid", "coordinates on a coarse grid in [-1, 1]: many exact zeros", "+-0", "+-0");
  {
    Rng r = w.block("multiples of 1/d, d in {2, 8} per case");
    for (int i = 0; i < c.grid; ++i) {
      int d = r.chance(50) ? 2 : 8;
      Case v(ncoords);
      for (double& x : v) x = double(r.range(-d, d)) / d;
      emit(w, k, v);
    }
  }

  w.section("degenerate", k.degenerate_what, "0", "0");
  variant_blocks(w, k, plain, c.degenerate_each, 0, {0, 0}, false);

  w.section("near-degenerate", "degenerate configurations with coordinates moved by 1-3 ulps", "+-0", "+-0");
  variant_blocks(w, k, plain, c.near_each, 85, {0, 0}, false);

  w.section("tiny", "coordinates around 1e-160 and subnormals: products underflow", "+-0", "+-0");
  random_block(w, k, "uniform * 2^e, e in [-540, -520] (~1e-160)", c.tiny, ncoords,
               [](Rng& r) { return std::ldexp(r.sym(), int(r.range(-540, -520))); });
  random_block(w, k, "uniform * 2^e, e in [-1022, -990] (differences subnormal)", c.tiny / 2, ncoords,
               [](Rng& r) { return std::ldexp(r.sym(), int(r.range(-1022, -990))); });
  {
    Rng r = w.block("subnormal: m * 2^-1074, |m| <= 2^b, b in 1..52 per case");
    for (int i = 0; i < c.tiny; ++i) {
      int b = int(r.range(1, 52));
      Case v(ncoords);
      for (double& x : v) x = lattice(r.bits(b), -1074);
      emit(w, k, v);
    }
  }
  variant_blocks(w, k, plain, c.tiny / 8, 70, {-560, -500}, true);
  variant_blocks(w, k, plain, c.tiny / 8, 70, {-1074, -1000}, true);

  w.section("huge", "coordinates around 1e+160 and up to 1.8e+308: products and differences overflow", "+-0",
            "+-0");
  random_block(w, k, "uniform * 2^e, e in [520, 540] (~1e+160)", c.huge, ncoords,
               [](Rng& r) { return std::ldexp(r.sym(), int(r.range(520, 540))); });
  random_block(w, k, "uniform * 2^e, e in [1000, 1023] (up to ~1e+308)", c.huge, ncoords,
               [](Rng& r) { return std::ldexp(r.sym(), int(r.range(1000, 1023))); });
  {
    const std::vector<double> pool = {DBL_MAX, -DBL_MAX, std::nextafter(DBL_MAX, 0), -std::nextafter(DBL_MAX, 0),
                                      0x1p1023, -0x1p1023, 0x1p1022, 1e308, -1e308, 0.0};
    random_block(w, k, "values from {+-DBL_MAX, +-(DBL_MAX - ulp), +-2^1023, 2^1022, +-1e308, 0}", c.huge, ncoords,
                 [&pool](Rng& r) { return r.pick(pool); });
  }
  variant_blocks(w, k, plain, c.huge / 8, 70, {500, 560}, true);
  variant_blocks(w, k, plain, c.huge / 8, 70, {1000, 1023}, true);

  w.section("mixed", "1e-300 beside 1e+300 in the same case; signs often decided by the tiny parts only",
            "+-0", "+-0");
  {
    Rng r = w.block("coordinates drawn from a per-case pool of 2 huge, 3 tiny values and 0");
    for (int i = 0; i < c.mixed; ++i) {
      std::vector<double> pool = {0.0};
      for (int j = 0; j < 2; ++j) pool.push_back(std::ldexp(r.sym(), int(r.range(990, 1023))));
      for (int j = 0; j < 3; ++j) pool.push_back(std::ldexp(r.sym(), int(r.range(-1074, -990))));
      Case v(ncoords);
      for (double& x : v) x = r.pick(pool);
      emit(w, k, v);
    }
  }
  random_block(w, k, "each coordinate independently ~1e-300, ~1 or ~1e+300", c.mixed, ncoords, [](Rng& r) {
    static const int exps[3] = {-1000, 0, 1000};
    return std::ldexp(r.sym(), exps[r.next() % 3] + int(r.range(-10, 10)));
  });
  variant_blocks(w, k, kMixedVariants, c.mixed / 2, 70, {0, 0}, false);
}

// The "classroom example" of Kettner, Mehlhorn, Pion, Schirra and Yap,
// "Classroom examples of robustness problems in geometric computations"
// (CGTA 40, 2008): p on a 256 x 256 grid of consecutive doubles around
// (0.5, 0.5), against the line through (12, 12) and (24, 24). Plain f64
// evaluation gets about 18% of the full grid wrong, in a band around the
// diagonal. The full grid would be 65536 lines; the sublattice
// (x + 7y) % m == 0 keeps every value of x - y and every row and column.
bool on_sublattice(int x, int y, int m) { return (x + 7 * y) % m == 0; }
constexpr double kUlpAtHalf = 0x1p-53;

// incircle and insphere: coordinates where the lifted determinant's terms
// (degree `deg` in the coordinates: 4 for incircle, 5 for insphere)
// underflow or overflow while the differences and their squares stay normal.
void lifted_sections(Writer& w, const SignKind& k, size_t ncoords, int deg, int n) {
  const std::string d = std::to_string(deg);
  // 2^(deg e) below 2^-1074 (above 2^1024) by at least 2^deg.
  const int under = -1074 / deg - 2, over = 1024 / deg + 2;
  for (auto [name, lo, hi, what] :
       {std::tuple<const char*, int, int, const char*>{"lifted-underflow", under - 30, under, "underflow"},
        {"lifted-overflow", over, over + 30, "overflow"}}) {
    std::string band = "2^e, e in [" + std::to_string(lo) + ", " + std::to_string(hi) + "]";
    w.section(name, "coordinates ~" + band + ": squares normal, the degree-" + d + " terms " + what, "+-0", "+-0");
    int l = lo, h = hi;
    random_block(w, k, "uniform * " + band, n, ncoords,
                 [l, h](Rng& r) { return std::ldexp(r.sym(), int(r.range(l, h))); });
    variant_blocks(w, k, *k.plain_variants, n / 8, 70, {lo, hi}, true);
  }
}

// incircle and insphere: points computed in f64 on a circle or sphere,
// c + R v / |v| with v uniform in the unit disk or ball (|v| > 0.1), so
// rounded off it by an ulp or so: the exact sign is rarely 0.
void float_points_section(Writer& w, const SignKind& k, int dim, int npoints, int n) {
  w.section("float-points",
            "points c + R v / |v| computed in f64 (v uniform in the unit " + std::string(dim == 2 ? "disk" : "ball") +
                "): on the circle or sphere up to rounding",
            "+-", "+-0");
  struct Scale {
    const char* label;
    int ce_lo, ce_hi, re_lo, re_hi;
  };
  const Scale scales[] = {{"c in [-1,1]^d, R in [1/4, 2]", 0, 0, -2, 0},
                          {"c ~2^20..2^30 from the origin, R in [1/4, 2]", 20, 30, -2, 0},
                          {"c in [-1,1]^d, R ~2^-30..2^-20 (tiny circles and spheres)", 0, 0, -30, -20}};
  for (const Scale& sc : scales) {
    Rng r = w.block(sc.label);
    for (int i = 0; i < n; ++i) {
      int ce = int(r.range(sc.ce_lo, sc.ce_hi));
      double R = length_factor(r, sc.re_lo, sc.re_hi - 1);
      P3 c = uniform3(r, ce);
      Case v;
      for (int j = 0; j < npoints; ++j) {
        P3 u = dim == 3 ? unit_dir(r) : P3{0, 0, 0};
        while (dim == 2) {
          double x = r.sym(), y = r.sym(), n2 = x * x + y * y;
          if (n2 > 0.01 && n2 <= 1) {
            u = {x / std::sqrt(n2), y / std::sqrt(n2), 0};
            break;
          }
        }
        for (int a = 0; a < dim; ++a) v.push_back(c[a] + R * u[a]);
      }
      emit(w, k, v);
    }
  }
}

// The sections of incircle (dim 2) and insphere (dim 3): dim + 2 points,
// the lifted determinant's terms of degree dim + 2.
void lifted_kind_sections(Writer& w, const SignKind& k, int dim, const Counts& c, int n_lifted, int n_float) {
  size_t ncoords = size_t(dim * (dim + 2));
  common_sections(w, k, ncoords, c);
  lifted_sections(w, k, ncoords, dim + 2, n_lifted);
  float_points_section(w, k, dim, dim + 2, n_float);
}

}  // namespace

// ---------------------------------------------------------------------------
// Kinds

void gen_orient2d(Writer& w) {
  const SignKind& k = kOrient2d;
  common_sections(w, k, 6, Counts{400, 200, 60, 100, 160, 160, 200});

  w.section("classroom", "Kettner et al.'s grid: orient2d(p, (12,12), (24,24)), p = (0.5 + x 2^-53, 0.5 + y 2^-53)",
            "+-0", "+-0");
  w.block("x, y in 0..255 with (x + 7y) % 24 == 0; the sign is that of y - x");
  for (int x = 0; x < 256; ++x)
    for (int y = 0; y < 256; ++y) {
      if (!on_sublattice(x, y, 24)) continue;
      emit(w, k, {0.5 + x * kUlpAtHalf, 0.5 + y * kUlpAtHalf, 12, 12, 24, 24});
    }
}

void gen_orient3d(Writer& w) {
  const SignKind& k = kOrient3d;
  common_sections(w, k, 12, Counts{300, 200, 40, 70, 120, 120, 160});

  w.section("classroom", "3D analogues of Kettner et al.'s grid, p on a grid of consecutive doubles", "+-0",
            "+-0");
  w.block("plane x = y: orient3d(p, (12,12,12), (24,24,24), (12,12,24)), p = (0.5 + x u, 0.5 + y u, 0.5), "
          "u = 2^-53, (x + 7y) % 48 == 0");
  for (int x = 0; x < 256; ++x)
    for (int y = 0; y < 256; ++y)
      if (on_sublattice(x, y, 48))
        emit(w, k, {0.5 + x * kUlpAtHalf, 0.5 + y * kUlpAtHalf, 0.5, 12, 12, 12, 24, 24, 24, 12, 12, 24});
  w.block("plane x + y = 2z: orient3d(p, (12,12,12), (24,24,24), (24,0,12)), p = (0.5 + x u, 0.5, 0.5 + y u), "
          "u = 2^-53, (x + 7y) % 48 == 0");
  for (int x = 0; x < 256; ++x)
    for (int y = 0; y < 256; ++y)
      if (on_sublattice(x, y, 48))
        emit(w, k, {0.5 + x * kUlpAtHalf, 0.5, 0.5 + y * kUlpAtHalf, 12, 12, 12, 24, 24, 24, 24, 0, 12});
}

void gen_plane_side(Writer& w) {
  const SignKind& k = kPlaneSide;
  common_sections(w, k, 15, Counts{250, 200, 35, 60, 100, 100, 140});

  w.section("classroom", "triangles through (12,12,12), (24,24,24); p and q on grids of consecutive doubles",
            "+-0", "+-0");
  Rng r = w.block("plane x = y (third vertex (12,12,24)), p = (0.5 + x u, 0.5 + y u, 0.5), u = 2^-53, "
                  "(x + 7y) % 48 == 0; q mirrored (y, x), another grid point, or (1,0,0)");
  for (int x = 0; x < 256; ++x)
    for (int y = 0; y < 256; ++y) {
      if (!on_sublattice(x, y, 48)) continue;
      double qx, qy;
      switch (r.next() % 3) {
        case 0: qx = 0.5 + y * kUlpAtHalf, qy = 0.5 + x * kUlpAtHalf; break;
        case 1: qx = 0.5 + double(r.range(0, 255)) * kUlpAtHalf, qy = 0.5 + double(r.range(0, 255)) * kUlpAtHalf; break;
        default: qx = 1, qy = 0; break;
      }
      emit(w, k, {12, 12, 12, 24, 24, 24, 12, 12, 24, 0.5 + x * kUlpAtHalf, 0.5 + y * kUlpAtHalf, 0.5, qx, qy, 0.5});
    }
  r = w.block("plane x + y = 2z (third vertex (24,0,12)), p = (0.5 + x u, 0.5, 0.5 + y u), u = 2^-53, "
              "(x + 7y) % 48 == 0; q another grid point or (0,0,1)");
  for (int x = 0; x < 256; ++x)
    for (int y = 0; y < 256; ++y) {
      if (!on_sublattice(x, y, 48)) continue;
      double qx = 0, qz = 1;
      if (r.chance(67)) qx = 0.5 + double(r.range(0, 255)) * kUlpAtHalf, qz = 0.5 + double(r.range(0, 255)) * kUlpAtHalf;
      emit(w, k, {12, 12, 12, 24, 24, 24, 24, 0, 12, 0.5 + x * kUlpAtHalf, 0.5, 0.5 + y * kUlpAtHalf, qx, 0.5, qz});
    }
}

void gen_incircle(Writer& w) {
  const SignKind& k = kIncircle;
  lifted_kind_sections(w, k, 2, Counts{250, 150, 35, 50, 100, 100, 140}, 100, 80);

  w.section("classroom",
            "Kettner et al.'s grid against a circle: incircle((8.5,4.5), (3.5,9.5), (0.5,8.5), p), the circle of "
            "radius 5 around (3.5,4.5) through (0.5,0.5), p = (0.5 + x 2^-53, 0.5 + y 2^-53)",
            "+-0", "+-0");
  w.block("x, y in -128..127 with (x + 7y) % 32 == 0; inside where 3x + 4y > 0, outside on the tangent 3x + 4y = 0 "
          "except at p = (0.5,0.5)");
  for (int x = -128; x < 128; ++x)
    for (int y = -128; y < 128; ++y)
      if (on_sublattice(x, y, 32)) emit(w, k, {8.5, 4.5, 3.5, 9.5, 0.5, 8.5, 0.5 + x * kUlpAtHalf, 0.5 + y * kUlpAtHalf});
}

void gen_insphere(Writer& w) {
  const SignKind& k = kInsphere;
  lifted_kind_sections(w, k, 3, Counts{200, 150, 30, 40, 80, 80, 110}, 80, 60);

  w.section("classroom",
            "Kettner et al.'s grid against a sphere: the sphere of radius 7 around (2.5,3.5,6.5) through "
            "(0.5,0.5,0.5), through a = c + 7 e1, b = c + 7 e2, c + 7 e3 and c + (-6,-2,3); p on a grid of "
            "consecutive doubles around (0.5,0.5,0.5)",
            "+-0", "+-0");
  // p varies in axes (i, j) of (0.5, 0.5, 0.5).
  for (auto [i, j, label] : {std::tuple<int, int, const char*>{0, 1, "p = (0.5 + x u, 0.5 + y u, 0.5)"},
                             {1, 2, "p = (0.5, 0.5 + x u, 0.5 + y u)"}}) {
    w.block(std::string(label) + ", u = 2^-53, x, y in -128..127 with (x + 7y) % 96 == 0");
    for (int x = -128; x < 128; ++x)
      for (int y = -128; y < 128; ++y) {
        if (!on_sublattice(x, y, 96)) continue;
        Case v = {9.5, 3.5, 6.5, 2.5, 10.5, 6.5, 2.5, 3.5, 13.5, -3.5, 1.5, 9.5, 0.5, 0.5, 0.5};
        v[12 + i] += x * kUlpAtHalf;
        v[12 + j] += y * kUlpAtHalf;
        emit(w, k, v);
      }
  }
}

}  // namespace fixtures
