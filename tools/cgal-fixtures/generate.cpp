// Writes exactray's test fixtures: inputs chosen to be hard for floating
// point, with the expected answers computed by CGAL's exact kernels.
// The file format is described in FORMAT.md (one case per line, `#` comments;
// a nearest file holds one point set and its queries, see NearestSet).
//
// Usage: generate OUTDIR [KIND...]   (no KIND: every kind in KINDS below)
//
// Determinism: the output must be byte-identical on every machine and every
// run, so the inputs come only from our own splitmix64 and from exact IEEE
// operations (+, -, * on exactly representable results, ldexp, nextafter),
// never from std:: distributions or libm functions whose results vary between
// library versions. Every block of cases gets its own generator seeded from
// its label, so editing one block leaves the others' cases unchanged.
//
// Adding a kind: write `void gen_<kind>(Writer&)` and add a row to KINDS (a
// kind with several files per run, like nearest with one point set per file,
// writes its files itself: see gen_nearest_files; so do the ray kinds, whose
// answers are root counts and roots rather than signs: see RayWriter).
//
// Exact arithmetic beyond CGAL: GMP rationals (gmpxx) for the polynomials in
// t of the ray kinds, MPFR for their irrational roots (proved correctly
// rounded with rationals; see prove_nearest).

#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Exact_rational.h>
#include <CGAL/Simple_cartesian.h>
#include <CGAL/intersections.h>
#include <CGAL/squared_distance_3.h>
#include <gmpxx.h>
#include <mpfr.h>

#include <algorithm>
#include <array>
#include <cfloat>
#include <cinttypes>
#include <cmath>
#include <cstdarg>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <map>
#include <string>
#include <vector>

namespace {

using Epick = CGAL::Exact_predicates_inexact_constructions_kernel;
// Exact constructions: a Ray_3 built from a point and a vector stores the
// constructed second point o + d, which Epick rounds to doubles (so Epick's
// do_intersect(Ray_3, Triangle_3) answers for a slightly different ray);
// Epeck keeps it exact.
using Epeck = CGAL::Exact_predicates_exact_constructions_kernel;
// A second, independent exact evaluation: plain rational arithmetic, no
// filters. Epick's filtered predicates must agree with it on every case.
using RatK = CGAL::Simple_cartesian<CGAL::Exact_rational>;

using P2 = std::array<double, 2>;
using P3 = std::array<double, 3>;
using Case = std::vector<double>;

[[noreturn]] void die(const char* fmt, ...) {
  va_list ap;
  va_start(ap, fmt);
  std::fputs("generate: ", stderr);
  std::vfprintf(stderr, fmt, ap);
  std::fputc('\n', stderr);
  va_end(ap);
  std::exit(1);
}

// Writes a fixture file whole, or dies.
void write_file(const std::string& path, const std::string& data) {
  FILE* f = std::fopen(path.c_str(), "wb");
  if (!f) die("cannot write %s", path.c_str());
  if (std::fwrite(data.data(), 1, data.size(), f) != data.size() || std::fclose(f) != 0)
    die("cannot write %s", path.c_str());
}

// ---------------------------------------------------------------------------
// Randomness

uint64_t splitmix64(uint64_t& state) {
  uint64_t z = (state += 0x9e3779b97f4a7c15ULL);
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
  return z ^ (z >> 31);
}

uint64_t fnv1a(const std::string& s) {
  uint64_t h = 0xcbf29ce484222325ULL;
  for (unsigned char c : s) {
    h ^= c;
    h *= 0x100000001b3ULL;
  }
  return h;
}

class Rng {
 public:
  explicit Rng(uint64_t seed) : state_(seed) {}
  uint64_t next() { return splitmix64(state_); }
  // Uniform in [lo, hi]; the modulo bias is irrelevant for test data.
  int64_t range(int64_t lo, int64_t hi) {
    return lo + int64_t(next() % uint64_t(hi - lo + 1));
  }
  bool chance(int percent) { return int(next() % 100) < percent; }
  int sign() { return (next() >> 63) ? 1 : -1; }
  // Uniform in [0, 1) with 53 random bits; the arithmetic is exact.
  double unit() { return double(next() >> 11) * 0x1p-53; }
  // Uniform in [-1, 1); 2u - 1 is exact for every u above.
  double sym() { return 2.0 * unit() - 1.0; }
  // An integer in [-2^bits, 2^bits].
  int64_t bits(int bits) { return range(-(int64_t(1) << bits), int64_t(1) << bits); }
  template <class T>
  const T& pick(const std::vector<T>& v) { return v[next() % v.size()]; }

 private:
  uint64_t state_;
};

// ---------------------------------------------------------------------------
// Exact IEEE helpers

// x moved by `ulps` representable steps (negative: towards -inf).
double step_ulps(double x, int ulps) {
  for (int i = 0; i < std::abs(ulps); ++i) x = std::nextafter(x, ulps > 0 ? INFINITY : -INFINITY);
  return x;
}

// Exponent of the lowest set bit of x != 0 (x = odd * 2^result).
int low_bit_exp(double x) {
  int e;
  double m = std::frexp(std::fabs(x), &e);  // x = m 2^e, m in [0.5, 1), exact
  uint64_t mant = uint64_t(std::ldexp(m, 53));
  return e - 53 + __builtin_ctzll(mant);
}

// The largest k <= want such that every value times 2^-k is exact (no bit
// falls below 2^-1074).
int clip_down_shift(const Case& v, int want) {
  for (double x : v)
    if (x != 0) want = std::min(want, low_bit_exp(x) + 1074);
  return want;
}

// The largest k <= want such that every value times 2^k stays finite.
int clip_up_shift(const Case& v, int want) {
  for (double x : v)
    if (x != 0) want = std::min(want, 1023 - std::ilogb(x));
  return want;
}

int max_exp(const Case& v) {
  int e = INT32_MIN;
  for (double x : v)
    if (x != 0) e = std::max(e, std::ilogb(x));
  return e;
}

void scale(Case& v, int k) {
  for (double& x : v) {
    double y = std::ldexp(x, k);
    if (!std::isfinite(y) || std::ldexp(y, -k) != x) die("inexact scaling of %.17g by 2^%d", x, k);
    x = y;
  }
}

// Scales the case by a power of two so that its largest coordinate lands near
// 2^target, as far as exactness allows; exact scaling keeps the sign.
void scale_towards(Case& v, int target) {
  int top = max_exp(v);
  if (top == INT32_MIN) return;
  int k = target - top;
  k = k < 0 ? -clip_down_shift(v, -k) : clip_up_shift(v, k);
  scale(v, k);
}

// An integer lattice coordinate v times 2^e; the lattice constructions below
// keep |v| < 2^53 so that this is exact.
double lattice(int64_t v, int e) {
  const int64_t lim = int64_t(1) << 53;
  if (v >= lim || v <= -lim) die("lattice value %" PRId64 " needs more than 53 bits", v);
  double x = std::ldexp(double(v), e);
  if (!std::isfinite(x) || std::ldexp(x, -e) != double(v)) die("lattice value %" PRId64 " * 2^%d is inexact", v, e);
  return x;
}

// A double with arbitrary low-order bits, of moderate size.
double arbitrary(Rng& r) { return std::ldexp(r.sym(), int(r.range(-3, 3))); }

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

int plane_side_naive(const double* v) {
  double p[12], q[12];
  std::memcpy(p, v, 9 * sizeof(double));
  std::memcpy(q, v, 9 * sizeof(double));
  std::memcpy(p + 9, v + 9, 3 * sizeof(double));
  std::memcpy(q + 9, v + 12, 3 * sizeof(double));
  return orient3d_naive(p) * orient3d_naive(q);
}

// Fails loudly if the kernels' conventions are not the ones FORMAT.md states.
void check_conventions() {
  const double l[6] = {0, 0, 1, 0, 0, 1};  // counterclockwise
  const double o[12] = {0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1};  // det(I) = 1
  if (orient2d_exact(l) != 1 || orient2d_naive(l) != 1) die("orient2d convention");
  if (orient3d_exact(o) != 1 || orient3d_naive(o) != 1) die("orient3d convention");
}

// ---------------------------------------------------------------------------
// Output

// One fixture file. Sections group blocks of cases; each section states which
// signs it must contain (so a construction that silently stopped producing,
// say, zeros is caught) and which it may contain (a degenerate section that
// produced a nonzero sign means the construction was not exact).
class Writer {
 public:
  Writer(std::string path, std::string kind) : path_(std::move(path)), kind_(std::move(kind)) {
    out_ += "# " + kind_ + " fixtures: expected answers from CGAL's exact kernels (Epick, checked\n";
    out_ += "# against plain rational arithmetic). Generated by tools/cgal-fixtures/generate.cpp;\n";
    out_ += "# do not edit, rerun tools/cgal-fixtures/regenerate.sh.\n";
  }

  void section(const std::string& name, const std::string& what, const char* must, const char* allowed) {
    end_section();
    section_ = name;
    must_ = must;
    allowed_ = allowed;
    stats_ = Stats{};
    out_ += "\n# section " + name + ": " + what + "\n";
  }

  // Starts a block of cases within the current section and returns the
  // block's own random generator.
  Rng block(const std::string& label) {
    if (section_.empty()) die("block outside a section");
    out_ += "# " + section_ + ": " + label + "\n";
    return Rng(fnv1a(kind_ + "/" + section_ + "/" + label));
  }

  void emit(const Case& v, int exact, int naive) {
    for (double x : v) {
      if (!std::isfinite(x)) die("%s/%s: non-finite coordinate", kind_.c_str(), section_.c_str());
      char buf[40];
      std::snprintf(buf, sizeof buf, "%.17g", x);
      double back = std::strtod(buf, nullptr);
      if (std::memcmp(&back, &x, sizeof x) != 0) die("%s does not round-trip", buf);
      out_ += buf;
      out_ += ' ';
    }
    out_ += std::to_string(exact);
    out_ += '\n';
    ++stats_.n;
    ++stats_.by_sign[exact + 1];
    if (naive != exact) ++stats_.naive_wrong;
  }

  void finish() {
    end_section();
    write_file(path_, out_);
    std::fprintf(stderr, "%-10s %6d cases  %8zu bytes  %s\n", kind_.c_str(), total_, out_.size(), path_.c_str());
  }

 private:
  struct Stats {
    int n = 0;
    int by_sign[3] = {0, 0, 0};  // -1, 0, 1
    int naive_wrong = 0;
  };

  void end_section() {
    if (section_.empty()) return;
    const char* names = "-0+";
    for (int s = 0; s < 3; ++s) {
      bool must = std::strchr(must_, names[s]) != nullptr;
      bool allowed = std::strchr(allowed_, names[s]) != nullptr;
      if (must && stats_.by_sign[s] == 0)
        die("%s/%s: no case with sign %c", kind_.c_str(), section_.c_str(), names[s]);
      if (!allowed && stats_.by_sign[s] != 0)
        die("%s/%s: %d cases with sign %c", kind_.c_str(), section_.c_str(), stats_.by_sign[s], names[s]);
    }
    std::fprintf(stderr, "%-10s %-16s %5d cases  (-:%d 0:%d +:%d)  plain f64 wrong on %d\n", kind_.c_str(),
                 section_.c_str(), stats_.n, stats_.by_sign[0], stats_.by_sign[1], stats_.by_sign[2],
                 stats_.naive_wrong);
    total_ += stats_.n;
    section_.clear();
  }

  std::string path_, kind_, out_, section_;
  const char* must_ = "";
  const char* allowed_ = "";
  Stats stats_;
  int total_ = 0;
};

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
};

const std::vector<Variant> kPlainVariants2 = {Variant::LatticeSmall, Variant::LatticeFar, Variant::Offset40,
                                              Variant::Axis,         Variant::Diagonal,   Variant::Repeated};
const std::vector<Variant> kPlainVariants3 = {Variant::LatticeSmall, Variant::LatticeFar, Variant::Offset40,
                                              Variant::Axis,         Variant::Diagonal,   Variant::Repeated,
                                              Variant::CollinearTri};
const std::vector<Variant> kMixedVariants = {Variant::Aniso, Variant::SharedHuge};

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
  }
  return "";
}

// Per-axis powers of two for an anisotropic lattice: at least one huge and
// one tiny axis. Scaling each axis by its own factor is an affine map, so it
// keeps collinearity and coplanarity exactly.
template <size_t D>
std::array<int, D> aniso_exps(Rng& r) {
  std::array<int, D> e;
  for (size_t i = 0; i < D; ++i) e[i] = r.chance(50) ? int(r.range(900, 960)) : int(r.range(-1074, -1000));
  e[0] = int(r.range(900, 960));
  e[1] = int(r.range(-1074, -1000));
  for (size_t i = D - 1; i > 0; --i) std::swap(e[i], e[r.next() % (i + 1)]);
  return e;
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
  }
  Plane pl;
  pl.tri = {pts[0], pts[1], pts[2]};
  pl.on.assign(pts.begin() + 3, pts.end());
  return pl;
}

// ---------------------------------------------------------------------------
// Sign kinds: orient2d, orient3d, plane_side share their section structure.

struct SignKind {
  int (*exact)(const double*);
  int (*naive)(const double*);
  // Reorders the points without changing which configuration it is.
  void (*shuffle)(Rng&, Case&);
  // A case whose exact answer is 0, of the given variant.
  Case (*degenerate)(Rng&, Variant);
  const std::vector<Variant>* plain_variants;
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

const SignKind kOrient2d = {orient2d_exact, orient2d_naive, shuffle_orient2d, degenerate_orient2d,
                            &kPlainVariants2};
const SignKind kOrient3d = {orient3d_exact, orient3d_naive, shuffle_orient3d, degenerate_orient3d,
                            &kPlainVariants3};
const SignKind kPlaneSide = {plane_side_exact, plane_side_naive, shuffle_plane_side, degenerate_plane_side,
                             &kPlainVariants3};

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
    std::string label = variant_name(var);
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

  w.section("degenerate", "exactly collinear / coplanar points, no rounding in their construction", "0", "0");
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

// ---------------------------------------------------------------------------
// nearest: one point set per file (nearest-<set>.txt), its points, then its
// queries, each with every index at exactly the smallest distance.

using I3 = std::array<int64_t, 3>;
using Indices = std::vector<size_t>;

// `%.17g`, checked to read back to the same bits.
std::string format_coord(double x) {
  if (!std::isfinite(x)) die("non-finite coordinate");
  char buf[40];
  std::snprintf(buf, sizeof buf, "%.17g", x);
  double back = std::strtod(buf, nullptr);
  if (std::memcmp(&back, &x, sizeof x) != 0) die("%s does not round-trip", buf);
  return buf;
}

// Every index at the smallest distance from q, ascending: Epick's filtered
// compare_distance_to_point, exact (it falls back to exact arithmetic where
// the interval filter fails, including on overflow and underflow).
Indices nearest_epick(const std::vector<Epick::Point_3>& pts, const Epick::Point_3& q) {
  Indices best;
  for (size_t i = 0; i < pts.size(); ++i) {
    if (best.empty()) {
      best.push_back(i);
      continue;
    }
    switch (CGAL::compare_distance_to_point(q, pts[i], pts[best[0]])) {
      case CGAL::SMALLER: best.assign(1, i); break;
      case CGAL::EQUAL: best.push_back(i); break;
      default: break;
    }
  }
  return best;
}

// The same from exact rational squared distances, no filters.
Indices nearest_rational(const std::vector<RatK::Point_3>& pts, const RatK::Point_3& q) {
  Indices best;
  CGAL::Exact_rational best_d;
  for (size_t i = 0; i < pts.size(); ++i) {
    CGAL::Exact_rational d = CGAL::squared_distance(q, pts[i]);
    if (best.empty() || d < best_d) {
      best.assign(1, i);
      best_d = d;
    } else if (d == best_d) {
      best.push_back(i);
    }
  }
  return best;
}

// Plain f64 squared distances (which overflow and underflow), only to report
// how hard each section is: the first index with the smallest value.
size_t nearest_naive(const std::vector<P3>& pts, const P3& q) {
  size_t best = 0;
  double best_d = 0;
  for (size_t i = 0; i < pts.size(); ++i) {
    double dx = pts[i][0] - q[0], dy = pts[i][1] - q[1], dz = pts[i][2] - q[2];
    double d = dx * dx + dy * dy + dz * dz;
    if (i == 0 || d < best_d) best = i, best_d = d;
  }
  return best;
}

// One nearest fixture file. Points and queries are collected in the order they
// are made and written points first; the answers are computed at the end,
// against the whole set. Query sections state which answer sizes (numbers of
// tied points) they must contain, so a construction that silently stopped
// producing, say, 8-way ties is caught.
class NearestSet {
 public:
  NearestSet(std::string name, const std::string& what) : name_(std::move(name)) {
    head_ += "# nearest fixtures, point set \"" + name_ + "\": " + what + "\n";
    head_ += "# Each q line lists every point index at exactly the smallest distance (CGAL Epick\n";
    head_ += "# compare_distance_to_point, checked against exact rational squared distances).\n";
    head_ += "# Generated by tools/cgal-fixtures/generate.cpp; do not edit, rerun\n";
    head_ += "# tools/cgal-fixtures/regenerate.sh.\n";
  }

  // Starts a section of queries.
  void section(const std::string& name, const std::string& what, std::vector<size_t> must_sizes) {
    sections_.push_back(Section{name, std::move(must_sizes)});
    pending_queries_ += "\n# section " + name + ": " + what + "\n";
  }

  // Starts a block of points and/or queries and returns its own generator.
  // The label is written before the block's first point and before its first
  // query.
  Rng block(const std::string& label) {
    std::string where = sections_.empty() ? "points" : sections_.back().name;
    label_ = "# " + where + ": " + label + "\n";
    point_label_due_ = query_label_due_ = true;
    return Rng(fnv1a("nearest/" + name_ + "/" + where + "/" + label));
  }

  size_t point(const P3& p) {
    if (point_label_due_) points_text_ += label_, point_label_due_ = false;
    points_text_ += "p " + format_coord(p[0]) + " " + format_coord(p[1]) + " " + format_coord(p[2]) + "\n";
    points_.push_back(p);
    return points_.size() - 1;
  }

  void query(const P3& q) {
    if (sections_.empty()) die("nearest-%s: query outside a section", name_.c_str());
    if (query_label_due_) pending_queries_ += label_, query_label_due_ = false;
    queries_.push_back(Query{q, sections_.size() - 1, std::move(pending_queries_)});
    pending_queries_.clear();
  }

  size_t size() const { return points_.size(); }
  const P3& at(size_t i) const { return points_[i]; }

  void finish(const std::string& path) {
    if (points_.empty() || queries_.empty()) die("nearest-%s: no points or no queries", name_.c_str());
    std::vector<Epick::Point_3> ep;
    std::vector<RatK::Point_3> rp;
    auto q = [](double x) { return CGAL::Exact_rational(x); };
    for (const P3& p : points_) {
      ep.emplace_back(p[0], p[1], p[2]);
      rp.emplace_back(q(p[0]), q(p[1]), q(p[2]));
    }
    std::string out = head_;
    out += "\n# " + std::to_string(points_.size()) + " points\n" + points_text_;
    out += "\n# " + std::to_string(queries_.size()) + " queries\n";
    std::vector<Stats> stats(sections_.size());
    for (const Query& query : queries_) {
      const P3& x = query.q;
      Indices answer = nearest_epick(ep, Epick::Point_3(x[0], x[1], x[2]));
      if (nearest_rational(rp, RatK::Point_3(q(x[0]), q(x[1]), q(x[2]))) != answer)
        die("nearest-%s: Epick and rational distances disagree", name_.c_str());
      Stats& st = stats[query.section];
      ++st.n;
      ++st.by_size[answer.size()];
      if (points_[answer[0]] == x) ++st.at_point;
      size_t naive = nearest_naive(points_, x);
      if (std::find(answer.begin(), answer.end(), naive) == answer.end()) ++st.naive_wrong;
      out += query.before;
      out += "q " + format_coord(x[0]) + " " + format_coord(x[1]) + " " + format_coord(x[2]);
      for (size_t i : answer) out += " " + std::to_string(i);
      out += '\n';
    }
    std::string kind = "nearest-" + name_;
    for (size_t s = 0; s < sections_.size(); ++s) {
      const Stats& st = stats[s];
      if (st.n == 0) die("%s/%s: no queries", kind.c_str(), sections_[s].name.c_str());
      for (size_t want : sections_[s].must_sizes)
        if (!st.by_size.count(want))
          die("%s/%s: no query with exactly %zu nearest points", kind.c_str(), sections_[s].name.c_str(), want);
      std::string sizes;
      for (const auto& [size, n] : st.by_size) sizes += " " + std::to_string(size) + ":" + std::to_string(n);
      std::fprintf(stderr, "%-18s %-15s %4d cases  (tied points%s; at a point %d)  plain f64 wrong on %d\n",
                   kind.c_str(), sections_[s].name.c_str(), st.n, sizes.c_str(), st.at_point, st.naive_wrong);
    }
    write_file(path, out);
    std::fprintf(stderr, "%-18s %5zu points %4zu queries  %8zu bytes  %s\n", kind.c_str(), points_.size(),
                 queries_.size(), out.size(), path.c_str());
  }

 private:
  struct Section {
    std::string name;
    std::vector<size_t> must_sizes;
  };
  struct Query {
    P3 q;
    size_t section;
    std::string before;  // comment lines written before it
  };
  struct Stats {
    int n = 0;
    std::map<size_t, int> by_size;
    int at_point = 0;
    int naive_wrong = 0;
  };

  std::string name_, head_, points_text_, pending_queries_, label_;
  bool point_label_due_ = false, query_label_due_ = false;
  std::vector<P3> points_;
  std::vector<Query> queries_;
  std::vector<Section> sections_;
};

// ---------------------------------------------------------------------------
// Point constructions for the nearest sets

P3 lattice3(const I3& v, const std::array<int, 3>& e) {
  return P3{lattice(v[0], e[0]), lattice(v[1], e[1]), lattice(v[2], e[2])};
}
P3 lattice3(const I3& v, int e) { return lattice3(v, {e, e, e}); }

I3 bits3(Rng& r, int b) { return I3{r.bits(b), r.bits(b), r.bits(b)}; }
I3 add3(const I3& a, const I3& b) { return I3{a[0] + b[0], a[1] + b[1], a[2] + b[2]}; }

// Coordinates uniform in [-2^e, 2^e), 53 random bits each.
P3 uniform3(Rng& r, int e) {
  return P3{std::ldexp(r.sym(), e), std::ldexp(r.sym(), e), std::ldexp(r.sym(), e)};
}

// Coordinates uniform * 2^e with e drawn once for the point from [lo, hi].
P3 uniform3_in(Rng& r, int lo, int hi) { return uniform3(r, int(r.range(lo, hi))); }

template <class T>
void shuffle(Rng& r, std::vector<T>& v) {
  for (size_t i = v.size(); i > 1; --i) std::swap(v[i - 1], v[r.next() % i]);
}

// p with `n` distinct coordinates moved by 1-3 ulps each, in random
// directions (away from the overflow threshold where needed).
P3 nudge(Rng& r, P3 p, int n) {
  std::vector<int> axes = {0, 1, 2};
  shuffle(r, axes);
  for (int i = 0; i < n; ++i) {
    double& x = p[axes[i]];
    int k = int(r.range(1, 3));
    k *= r.sign();
    double y = step_ulps(x, k);
    x = std::isfinite(y) ? y : step_ulps(x, -k);
  }
  return p;
}

int nudge_count(Rng& r) {
  int n = 1 + r.chance(30);
  return n + r.chance(10);
}

// An n x n x n grid: points (base + step (i, j, k)) 2^e, step even so that
// the midpoints between grid coordinates are lattice points too.
struct Grid {
  std::string label;
  I3 base;
  int64_t step;
  int n;
  int e;
};

void add_grid(NearestSet& s, const Grid& g) {
  Rng r = s.block(g.label + ", listed in random order");
  std::vector<P3> pts;
  for (int i = 0; i < g.n; ++i)
    for (int j = 0; j < g.n; ++j)
      for (int k = 0; k < g.n; ++k)
        pts.push_back(lattice3(add3(g.base, I3{g.step * i, g.step * j, g.step * k}), g.e));
  shuffle(r, pts);
  for (const P3& p : pts) s.point(p);
}

// Per axis: 0 a grid coordinate, 1 halfway between two, 2 outside the grid.
// The exact answer has 2^(number of halfway axes) points.
P3 grid_query(Rng& r, const Grid& g, std::array<int, 3> where) {
  for (size_t i = 2; i > 0; --i) std::swap(where[i], where[r.next() % (i + 1)]);
  I3 v;
  for (int a = 0; a < 3; ++a) {
    switch (where[a]) {
      case 0: v[a] = g.base[a] + g.step * r.range(0, g.n - 1); break;
      case 1: v[a] = g.base[a] + g.step * r.range(0, g.n - 2) + g.step / 2; break;
      default:
        // Half a step to 3 steps below or above the grid.
        v[a] = r.chance(50) ? g.base[a] - g.step / 2 * r.range(1, 6)
                            : g.base[a] + g.step * (g.n - 1) + g.step / 2 * r.range(1, 6);
    }
  }
  return lattice3(v, g.e);
}

// The grid sections: exact 8-, 4-, 2-way ties, grid points, outside the grid,
// and cell centres moved by 1-3 ulps (`near` false skips the last: for grids
// whose spacing is a few ulps, such moves land on other ties).
void grid_sections(NearestSet& s, const std::vector<Grid>& grids, int each, const std::vector<bool>& near) {
  struct Kind {
    const char* name;
    const char* what;
    std::array<int, 3> where;
    std::vector<size_t> must;
  };
  const Kind kinds[] = {
      {"cell-centres", "centres of grid cells: 8 points at the same distance", {1, 1, 1}, {8}},
      {"face-centres", "centres of cell faces: 4 points at the same distance", {1, 1, 0}, {4}},
      {"edge-midpoints", "midpoints of cell edges: 2 points at the same distance", {1, 0, 0}, {2}},
      {"grid-points", "queries at grid points: distance 0", {0, 0, 0}, {1}},
  };
  for (const Kind& k : kinds) {
    s.section(k.name, k.what, k.must);
    for (const Grid& g : grids) {
      Rng r = s.block(g.label + ": " + std::to_string(each) + " queries");
      for (int i = 0; i < each; ++i) s.query(grid_query(r, g, k.where));
    }
  }
  s.section("outside", "outside the grid on 1-2 axes, halfway or on the grid on the others: 1, 2 or 4 ties",
            {1, 2, 4});
  for (const Grid& g : grids) {
    Rng r = s.block(g.label + ": " + std::to_string(each) + " queries");
    for (int i = 0; i < each; ++i) {
      std::array<int, 3> where = {2, int(r.next() % 3), int(r.next() % 3)};
      s.query(grid_query(r, g, where));
    }
  }
  s.section("near-centres", "cell centres with 1, 2 or 3 coordinates moved by 1-3 ulps: 4, 2 or 1 nearest",
            {1, 2, 4});
  for (size_t gi = 0; gi < grids.size(); ++gi) {
    if (!near[gi]) continue;
    const Grid& g = grids[gi];
    Rng r = s.block(g.label + ": " + std::to_string(each) + " queries");
    for (int i = 0; i < each; ++i) s.query(nudge(r, grid_query(r, g, {1, 1, 1}), 1 + i % 3));
  }
}

// Offsets of equal length: Pythagorean quadruples, one group per norm.
const std::vector<std::vector<I3>> kEqualNorms = {
    {{1, 2, 2}, {3, 0, 0}},                // 9
    {{2, 3, 6}, {7, 0, 0}},                // 49
    {{1, 4, 8}, {4, 4, 7}, {9, 0, 0}},     // 81
    {{2, 6, 9}, {6, 6, 7}, {11, 0, 0}},    // 121
    {{4, 1, 0}, {3, 2, 2}},                // 17
    {{5, 1, 0}, {4, 3, 1}},                // 26
};

// Every distinct vector made from v by sign changes (and permutations).
std::vector<I3> signs_and_perms(const I3& v, bool permute) {
  static const int P[6][3] = {{0, 1, 2}, {0, 2, 1}, {1, 0, 2}, {1, 2, 0}, {2, 0, 1}, {2, 1, 0}};
  std::vector<I3> out;
  for (int p = 0; p < (permute ? 6 : 1); ++p)
    for (int s = 0; s < 8; ++s) {
      I3 w;
      for (int k = 0; k < 3; ++k) w[k] = v[P[p][k]] * (((s >> k) & 1) ? -1 : 1);
      if (std::find(out.begin(), out.end(), w) == out.end()) out.push_back(w);
    }
  return out;
}

// Up to k distinct integer offsets of exactly equal length: sign changes and
// permutations of one random vector with `ub`-bit components, or (permute
// only) t times Pythagorean quadruples of one norm.
std::vector<I3> equal_norm_offsets(Rng& r, int ub, bool permute, size_t k) {
  std::vector<I3> pool;
  if (permute && r.chance(40)) {
    int64_t t = r.range(1, int64_t(1) << (ub - 4));
    for (const I3& form : r.pick(kEqualNorms))
      for (const I3& w : signs_and_perms(I3{t * form[0], t * form[1], t * form[2]}, true)) pool.push_back(w);
  } else {
    I3 u;
    for (int64_t& x : u) do x = r.bits(ub); while (x == 0);
    pool = signs_and_perms(u, permute);
  }
  shuffle(r, pool);
  if (pool.size() > k) pool.resize(k);
  return pool;
}

enum class TieMode { Exact, PointsMoved, QueryMoved };

// A query Q 2^e and 2-6 points (Q + O) 2^e at exactly the same distance from
// it (per-axis exponents e; `permute` false: sign changes only, which an
// anisotropic scaling keeps), plus one point just farther (one component of
// an offset one unit longer). PointsMoved: 1-2 of the tied points get 1-3
// coordinates moved by 1-3 ulps; QueryMoved: the query does. The points are
// listed in random order, so the moved point comes before or after its rivals.
void tie_config(NearestSet& s, Rng& r, std::array<int, 3> e, int qb, int ub, bool permute, TieMode mode) {
  I3 Q = bits3(r, qb);
  std::vector<I3> offsets = equal_norm_offsets(r, ub, permute, size_t(r.range(2, 6)));
  std::vector<P3> pts;
  for (const I3& o : offsets) pts.push_back(lattice3(add3(Q, o), e));
  if (mode == TieMode::PointsMoved) {
    int moved = 1 + r.chance(40);
    for (int i = 0; i < moved; ++i) {
      P3& p = pts[r.next() % pts.size()];
      p = nudge(r, p, nudge_count(r));
    }
  }
  I3 far = offsets[0];
  int axis = 0;
  for (int a = 1; a < 3; ++a)
    if (std::llabs(far[a]) > std::llabs(far[axis])) axis = a;
  far[axis] += far[axis] >= 0 ? 1 : -1;
  pts.push_back(lattice3(add3(Q, far), e));
  shuffle(r, pts);
  for (const P3& p : pts) s.point(p);
  P3 q = lattice3(Q, e);
  if (mode == TieMode::QueryMoved) q = nudge(r, q, nudge_count(r));
  s.query(q);
}

struct TieScale {
  std::string label;
  int e_lo, e_hi, qb, ub;
};

// The three tie sections, each with `n` configurations per scale.
void tie_sections(NearestSet& s, const std::vector<TieScale>& scales, int n, bool permute) {
  struct Mode {
    TieMode mode;
    const char* name;
    const char* what;
    std::vector<size_t> must;
  };
  const Mode modes[] = {
      {TieMode::Exact, "exact-ties", "2-6 points at exactly the same distance (and one just farther)", {2, 3}},
      {TieMode::PointsMoved, "points-moved",
       "the same with 1-2 of the tied points moved by 1-3 ulps in 1-3 coordinates", {1}},
      {TieMode::QueryMoved, "query-moved", "the same with the query moved by 1-3 ulps in 1-3 coordinates", {1}},
  };
  for (const Mode& m : modes) {
    s.section(m.name, m.what, m.must);
    for (const TieScale& sc : scales) {
      Rng r = s.block(std::to_string(n) + " configurations (query Q 2^e, points (Q + O) 2^e), " + sc.label);
      for (int i = 0; i < n; ++i) {
        int e = int(r.range(sc.e_lo, sc.e_hi));
        tie_config(s, r, {e, e, e}, sc.qb, sc.ub, permute, m.mode);
      }
    }
  }
}

// Queries equal to random points of the set, and random points moved by 1-3
// ulps in 1-3 coordinates.
void at_points_section(NearestSet& s, int n) {
  s.section("at-points", "queries at a point of the set, or 1-3 ulps from one", {1});
  Rng r = s.block(std::to_string(n) + " queries equal to a random point");
  for (int i = 0; i < n; ++i) s.query(s.at(r.next() % s.size()));
  r = s.block(std::to_string(n) + " queries: a random point with 1-3 coordinates moved by 1-3 ulps");
  for (int i = 0; i < n; ++i) {
    P3 p = s.at(r.next() % s.size());
    s.query(nudge(r, p, nudge_count(r)));
  }
}

// ---------------------------------------------------------------------------
// The nearest sets

void nearest_uniform(NearestSet& s) {
  Rng r = s.block("2000 points uniform in [-1, 1]^3");
  for (int i = 0; i < 2000; ++i) s.point(uniform3(r, 0));
  s.section("random", "queries uniform in [-1, 1]^3 and in [-2, 2]^3 (partly outside the cloud)", {1});
  r = s.block("200 queries uniform in [-1, 1]^3");
  for (int i = 0; i < 200; ++i) s.query(uniform3(r, 0));
  r = s.block("40 queries uniform in [-2, 2]^3");
  for (int i = 0; i < 40; ++i) s.query(uniform3(r, 1));
  at_points_section(s, 30);
}

void nearest_grid(NearestSet& s) {
  const std::vector<Grid> grids = {
      {"integer grid {-4..3}^3", {-8, -8, -8}, 2, 8, -1},
      {"dyadic grid (2^30, 2^30 + 2^24, -2^30) + 2^-19 {0..5}^3 (50-bit coordinates)",
       {int64_t(1) << 50, (int64_t(1) << 50) + (int64_t(1) << 44), -(int64_t(1) << 50)}, 2, 6, -20},
      {"grid spaced 2 ulps apart in [1, 2): halfway = 1 ulp",
       {(int64_t(1) << 52) + 12345678901, (int64_t(1) << 52) + 987654321, (int64_t(1) << 52) + 3}, 2, 5, -52},
  };
  for (const Grid& g : grids) add_grid(s, g);
  grid_sections(s, grids, 25, {true, true, false});
}

void nearest_near_ties(NearestSet& s) {
  tie_sections(s,
               {{"Q 50-bit, offsets 12-bit, scale 2^[-56,-48]", -56, -48, 50, 12},
                {"Q 50-bit, offsets 24-bit, scale 2^[-56,-48]", -56, -48, 50, 24},
                {"Q 50-bit, offsets 36-bit, scale 2^[-56,-48]", -56, -48, 50, 36}},
               25, true);
  // One configuration around (nearly) the origin: there |p - q| ~ |p|, and
  // 1-ulp moves change squared distances by about one rounding error.
  s.section("sphere", "points on one sphere around a query near the origin, most moved by 1-3 ulps", {1});
  Rng r = s.block("t (1,4,8), (4,4,7), (9,0,0) with all signs and orders, t 40-bit, around Q 8-bit, scale "
                  "2^-80; 70% moved; queries Q exactly and moved by 1-3 ulps");
  I3 Q = bits3(r, 8);
  int64_t t = r.range(int64_t(1) << 39, int64_t(1) << 40);
  std::vector<P3> pts;
  for (const I3& form : kEqualNorms[2])
    for (const I3& w : signs_and_perms(I3{t * form[0], t * form[1], t * form[2]}, true)) {
      P3 p = lattice3(add3(Q, w), -80);
      pts.push_back(r.chance(70) ? nudge(r, p, nudge_count(r)) : p);
    }
  shuffle(r, pts);
  for (const P3& p : pts) s.point(p);
  s.query(lattice3(Q, -80));
  for (int i = 0; i < 24; ++i) s.query(nudge(r, lattice3(Q, -80), nudge_count(r)));
}

void nearest_duplicates(NearestSet& s) {
  Rng r = s.block("600 points uniform in [-1, 1]^3, 100 of them repeated 1-4 more times, in random order");
  std::vector<P3> pts, repeated;
  for (int i = 0; i < 600; ++i) pts.push_back(uniform3(r, 0));
  for (int i = 0; i < 100; ++i) {
    P3 p = pts[i];
    repeated.push_back(p);
    for (int c = int(r.range(1, 4)); c > 0; --c) pts.push_back(p);
  }
  shuffle(r, pts);
  for (const P3& p : pts) s.point(p);
  r = s.block("one point 20 times, coordinates (2^52 + V) 2^-51 in [1.5, 2.5], V 50-bit");
  const int64_t two = int64_t(1) << 52;
  P3 twenty = lattice3(add3(I3{two, two, two}, bits3(r, 50)), -51);
  for (int i = 0; i < 20; ++i) s.point(twenty);

  s.section("at-duplicates", "queries at a repeated point: every copy is listed", {2, 3, 4, 5});
  r = s.block("40 queries at repeated points");
  for (int i = 0; i < 40; ++i) s.query(r.pick(repeated));
  s.section("near-duplicates", "queries 1-3 ulps from a repeated point", {2, 3, 4, 5});
  r = s.block("40 queries near repeated points");
  for (int i = 0; i < 40; ++i) {
    P3 p = r.pick(repeated);
    s.query(nudge(r, p, nudge_count(r)));
  }
  s.section("twenty-copies", "queries at and near the point listed 20 times", {20});
  r = s.block("10 queries");
  s.query(twenty);
  for (int i = 0; i < 9; ++i) s.query(nudge(r, twenty, nudge_count(r)));
  s.section("duplicated-ties", "2-4 points at exactly the same distance, each listed 1-3 times", {4});
  r = s.block("30 configurations at (-2, -2, -2) + Q 2^-51, Q 50-bit, offsets 20-bit");
  for (int i = 0; i < 30; ++i) {
    I3 Q = add3(bits3(r, 50), I3{-(int64_t(1) << 52), -(int64_t(1) << 52), -(int64_t(1) << 52)});
    std::vector<P3> tied;
    for (const I3& o : equal_norm_offsets(r, 20, true, size_t(r.range(2, 4)))) {
      P3 p = lattice3(add3(Q, o), -51);
      for (int c = int(r.range(1, 3)); c > 0; --c) tied.push_back(p);
    }
    shuffle(r, tied);
    for (const P3& p : tied) s.point(p);
    s.query(lattice3(Q, -51));
  }
  s.section("random", "queries uniform in [-1, 1]^3", {1});
  r = s.block("60 queries");
  for (int i = 0; i < 60; ++i) s.query(uniform3(r, 0));
}

void nearest_clustered(NearestSet& s) {
  struct Cluster {
    I3 c;
    int e, ub;
  };
  std::vector<Cluster> clusters;
  Rng r = s.block("25 clusters of 48 points (C + U) 2^e: C 52-bit, e in [-54, -42], U ub-bit, ub in {2, 6, 12, "
                  "20, 30, 40} (ub 2: points a few ulps apart, some repeated)");
  const std::vector<int> ubs = {2, 6, 12, 20, 30, 40};
  for (int c = 0; c < 25; ++c) {
    Cluster cl;
    for (int64_t& x : cl.c) {
      x = r.range(int64_t(1) << 51, (int64_t(1) << 52) - 1);
      x *= r.sign();
    }
    cl.e = int(r.range(-54, -42));
    cl.ub = ubs[c % ubs.size()];
    clusters.push_back(cl);
    for (int i = 0; i < 48; ++i) s.point(lattice3(add3(cl.c, bits3(r, cl.ub)), cl.e));
  }
  s.section("in-clusters", "queries within the clusters' extent", {1});
  r = s.block("100 queries (C + V) 2^e, V (ub+1)-bit, for a random cluster");
  for (int i = 0; i < 100; ++i) {
    const Cluster& cl = r.pick(clusters);
    s.query(lattice3(add3(cl.c, bits3(r, cl.ub + 1)), cl.e));
  }
  s.section("cluster-centres", "queries at the clusters' centres C 2^e", {1});
  r = s.block("25 queries");
  for (const Cluster& cl : clusters) s.query(lattice3(cl.c, cl.e));
  s.section("between", "queries uniform in [-2^10, 2^10]^3 and in [-2^30, 2^30]^3", {1});
  r = s.block("50 queries in [-2^10, 2^10]^3");
  for (int i = 0; i < 50; ++i) s.query(uniform3(r, 10));
  r = s.block("20 queries in [-2^30, 2^30]^3");
  for (int i = 0; i < 20; ++i) s.query(uniform3(r, 30));
}

// Huge and tiny share their structure: random points in two exponent bands,
// an exactly scaled grid, exactly scaled tie configurations.
struct Band {
  const char* label;
  int lo, hi;
};

void magnitude_set(NearestSet& s, const Band (&bands)[2], const Grid& grid, const TieScale& ties,
                   int tie_count) {
  for (const Band& b : bands) {
    Rng r = s.block(std::string("250 points, coordinates uniform * 2^e, e in ") + b.label + " per point");
    for (int i = 0; i < 250; ++i) s.point(uniform3_in(r, b.lo, b.hi));
  }
  add_grid(s, grid);
  s.section("random", "queries drawn like the points", {1});
  for (const Band& b : bands) {
    Rng r = s.block(std::string("40 queries, e in ") + b.label);
    for (int i = 0; i < 40; ++i) s.query(uniform3_in(r, b.lo, b.hi));
  }
  at_points_section(s, 20);
  s.section("grid", "the grid's cell centres, face centres, edge midpoints: 8, 4, 2 ties", {2, 4, 8});
  {
    Rng r = s.block("45 queries");
    for (int i = 0; i < 45; ++i) {
      int h = 1 + i % 3;
      s.query(grid_query(r, grid, {1, h > 1 ? 1 : 0, h > 2 ? 1 : 0}));
    }
  }
  // Only the exact and points-moved modes: fewer lines.
  s.section("exact-ties", "2-6 points at exactly the same distance (and one just farther)", {2, 3});
  Rng r = s.block(std::to_string(tie_count) + " configurations (query Q 2^e, points (Q + O) 2^e), " + ties.label);
  for (int i = 0; i < tie_count; ++i) {
    int e = int(r.range(ties.e_lo, ties.e_hi));
    tie_config(s, r, {e, e, e}, ties.qb, ties.ub, true, TieMode::Exact);
  }
  s.section("points-moved", "the same with 1-2 of the tied points moved by 1-3 ulps in 1-3 coordinates", {1});
  r = s.block(std::to_string(tie_count) + " configurations (query Q 2^e, points (Q + O) 2^e), " + ties.label);
  for (int i = 0; i < tie_count; ++i) {
    int e = int(r.range(ties.e_lo, ties.e_hi));
    tie_config(s, r, {e, e, e}, ties.qb, ties.ub, true, TieMode::PointsMoved);
  }
}

void nearest_huge(NearestSet& s) {
  const Band bands[2] = {{"[500, 540] (~1e+150..1e+162)", 500, 540}, {"[990, 1023] (~1e+298..1e+308)", 990, 1023}};
  magnitude_set(s, bands, {"integer grid (2^20, -2^20, 2^20) + {0..5}^3, times 2^940 (~1e+289)",
                    {int64_t(1) << 21, -(int64_t(1) << 21), int64_t(1) << 21}, 2, 6, 939},
                {"Q 50-bit, offsets 30-bit, scale 2^[900, 970]", 900, 970, 50, 30}, 30);
  Rng r = s.block("40 points from {+-DBL_MAX, +-(DBL_MAX - ulp), +-2^1023, +-2^1022, 0}");
  const std::vector<double> pool = {DBL_MAX,   -DBL_MAX,  std::nextafter(DBL_MAX, 0), -std::nextafter(DBL_MAX, 0),
                                    0x1p1023, -0x1p1023, 0x1p1022,                   -0x1p1022,
                                    0.0};
  for (int i = 0; i < 40; ++i) s.point(P3{r.pick(pool), r.pick(pool), r.pick(pool)});
  s.section("extreme", "queries with coordinates from the same pool: differences overflow", {});
  r = s.block("20 queries");
  for (int i = 0; i < 20; ++i) s.query(P3{r.pick(pool), r.pick(pool), r.pick(pool)});
}

void nearest_tiny(NearestSet& s) {
  const Band bands[2] = {{"[-540, -520] (~1e-160)", -540, -520},
                         {"[-1070, -1000] (~1e-301..1e-322, subnormals)", -1070, -1000}};
  magnitude_set(s, bands, {"subnormal grid (2^40, -2^40, 2^40) + {0..5}^3, times 2^-1073",
                    {int64_t(1) << 41, -(int64_t(1) << 41), int64_t(1) << 41}, 2, 6, -1074},
                {"Q 50-bit, offsets 20-bit, scale 2^[-1074, -1040] (subnormal at the low end)", -1074, -1040,
                 50, 20},
                30);
  Rng r = s.block("60 subnormal points m 2^-1074, |m| <= 2^b, b in 1..20 per point (some repeated)");
  for (int i = 0; i < 60; ++i) {
    int b = int(r.range(1, 20));
    s.point(lattice3(bits3(r, b), -1074));
  }
  s.section("subnormal", "queries m 2^-1074, |m| <= 2^b, b in 1..21", {});
  r = s.block("25 queries");
  for (int i = 0; i < 25; ++i) s.query(lattice3(bits3(r, int(r.range(1, 21))), -1074));
}

void nearest_mixed(NearestSet& s) {
  auto mixed_coord = [](Rng& r) {
    static const int exps[3] = {-1000, 0, 1000};
    double x = r.sym();
    int e = exps[r.next() % 3];
    return std::ldexp(x, e + int(r.range(-10, 10)));
  };
  Rng r = s.block("300 points, each coordinate independently ~1e-300, ~1 or ~1e+300");
  for (int i = 0; i < 300; ++i) s.point(P3{mixed_coord(r), mixed_coord(r), mixed_coord(r)});
  r = s.block("60 points near the origin, coordinates uniform * 2^e, e in [-1074, -1000]");
  for (int i = 0; i < 60; ++i) s.point(uniform3_in(r, -1074, -1000));
  struct Shared {
    double h;
    int axis;
  };
  std::vector<Shared> shared;
  r = s.block("8 groups: 6 points with one huge coordinate H shared (or H moved by 1 ulp), the others tiny");
  for (int g = 0; g < 8; ++g) {
    Shared sh;
    sh.h = r.sym();
    sh.h = std::ldexp(sh.h, int(r.range(990, 1023)));
    sh.axis = int(r.next() % 3);
    shared.push_back(sh);
    for (int i = 0; i < 6; ++i) {
      P3 p = uniform3_in(r, -1060, -990);
      p[sh.axis] = i < 4 ? sh.h : step_ulps(sh.h, r.sign());
      s.point(p);
    }
  }
  s.section("random", "queries drawn like the first 300 points", {1});
  r = s.block("40 queries");
  for (int i = 0; i < 40; ++i) s.query(P3{mixed_coord(r), mixed_coord(r), mixed_coord(r)});
  s.section("near-origin", "tiny queries: every squared distance to the tiny points underflows", {1});
  r = s.block("30 queries uniform * 2^e, e in [-1074, -1000]");
  for (int i = 0; i < 30; ++i) s.query(uniform3_in(r, -1074, -1000));
  s.section("shared-huge", "queries with the huge coordinate H (or H moved by 1 ulp) and tiny others", {1});
  r = s.block("32 queries");
  for (int i = 0; i < 32; ++i) {
    const Shared& sh = r.pick(shared);
    P3 q = uniform3_in(r, -1060, -990);
    q[sh.axis] = r.chance(75) ? sh.h : step_ulps(sh.h, r.sign());
    s.query(q);
  }
  at_points_section(s, 20);
  // Sign changes keep exact ties under a per-axis scaling: one axis around
  // 2^[900, 960], another around 2^[-1074, -1000].
  s.section("aniso-ties", "(Q + O) scaled by ~2^950 on some axes and ~2^-1040 on others, O by sign changes: ties",
            {2, 3});
  r = s.block("30 configurations, Q 50-bit, offsets 40-bit");
  for (int i = 0; i < 30; ++i) tie_config(s, r, aniso_exps<3>(r), 50, 40, false, TieMode::Exact);
  s.section("aniso-moved", "the same with 1-2 of the tied points moved by 1-3 ulps", {1});
  r = s.block("30 configurations, Q 50-bit, offsets 40-bit");
  for (int i = 0; i < 30; ++i) tie_config(s, r, aniso_exps<3>(r), 50, 40, false, TieMode::PointsMoved);
}

struct NearestSetEntry {
  const char* name;
  const char* what;
  void (*generate)(NearestSet&);
};

const NearestSetEntry kNearestSets[] = {
    {"uniform", "2000 points uniform in [-1, 1]^3", nearest_uniform},
    {"grid", "three grids (integer, dyadic near 2^30, spaced 2 ulps): exact 2-, 4- and 8-way ties", nearest_grid},
    {"near-ties", "points at exactly equal distances, and the same moved by 1-3 ulps", nearest_near_ties},
    {"duplicates", "repeated points: every copy is a nearest point", nearest_duplicates},
    {"clustered", "25 clusters, from a few ulps to ~2^-11 of their centres' magnitude wide", nearest_clustered},
    {"huge", "coordinates ~1e+150..1.8e+308: squared distances overflow", nearest_huge},
    {"tiny", "coordinates ~1e-160..5e-324: squared distances underflow", nearest_tiny},
    {"mixed", "1e-300, 1 and 1e+300 in one set", nearest_mixed},
};

void gen_nearest_files(const std::string& outdir) {
  for (const NearestSetEntry& e : kNearestSets) {
    NearestSet s(e.name, e.what);
    e.generate(s);
    s.finish(outdir + "/nearest-" + e.name + ".txt");
  }
}

// ---------------------------------------------------------------------------
// Ray kinds: ray_sphere, ray_cylinder, ray_quadric, ray_triangle.
//
// A case is a ray (or a line) and a shape; its answer is a number of roots
// (a hit class for triangles) and the roots rounded to the nearest binary64.
// The polynomial in t has exact rational coefficients (GMP); the number of
// roots is read off the exact sign of its discriminant (and its degree). A
// rational root (degree one, double root, triangle parameter) is rounded by
// MPFR's correctly rounded mpq -> 53-bit conversion. An irrational root is
// approximated with MPFR at kMpfrBits bits from the exact discriminant, rounded
// to a double, and then proved to be the correctly rounded root by exact
// rational sign evaluations at the midpoints to both neighbouring doubles
// (prove_nearest); a failed proof stops the generator.

using Q = mpq_class;
using QV = std::array<Q, 3>;

QV qv3(const Case& v, size_t i) { return QV{Q(v[i]), Q(v[i + 1]), Q(v[i + 2])}; }
QV qadd(const QV& a, const QV& b) { return QV{Q(a[0] + b[0]), Q(a[1] + b[1]), Q(a[2] + b[2])}; }
QV qsub(const QV& a, const QV& b) { return QV{Q(a[0] - b[0]), Q(a[1] - b[1]), Q(a[2] - b[2])}; }
QV qmul(const QV& a, const Q& s) { return QV{Q(a[0] * s), Q(a[1] * s), Q(a[2] * s)}; }
Q qdot(const QV& a, const QV& b) { return Q(a[0] * b[0] + a[1] * b[1] + a[2] * b[2]); }
QV qcross(const QV& a, const QV& b) {
  return QV{Q(a[1] * b[2] - a[2] * b[1]), Q(a[2] * b[0] - a[0] * b[2]), Q(a[0] * b[1] - a[1] * b[0])};
}
bool qzero(const QV& a) { return sgn(a[0]) == 0 && sgn(a[1]) == 0 && sgn(a[2]) == 0; }

Q to_q(const CGAL::Exact_rational& x) { return Q(x.backend().data()); }
CGAL::Exact_rational Rq(double x) { return CGAL::Exact_rational(x); }

// Double-precision vector helpers, for building inputs (rounding allowed
// there: the answers are computed from whatever doubles result).
P3 padd(const P3& a, const P3& b) { return P3{a[0] + b[0], a[1] + b[1], a[2] + b[2]}; }
P3 psub(const P3& a, const P3& b) { return P3{a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
P3 pmul(const P3& a, double s) { return P3{a[0] * s, a[1] * s, a[2] * s}; }
double pdot(const P3& a, const P3& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
P3 pcross(const P3& a, const P3& b) {
  return P3{a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
P3 pnormalize(const P3& a) { return pmul(a, 1.0 / std::sqrt(pdot(a, a))); }

// A direction uniform on the unit sphere (rejection sampling; sqrt and
// division are correctly rounded, so this is deterministic).
P3 unit_dir(Rng& r) {
  for (;;) {
    P3 v = uniform3(r, 0);
    double n2 = pdot(v, v);
    if (n2 > 0.01 && n2 <= 1) return pnormalize(v);
  }
}

// A unit direction perpendicular to the unit vector u (up to rounding).
P3 perp_dir(Rng& r, const P3& u) {
  for (;;) {
    P3 w = unit_dir(r);
    P3 p = psub(w, pmul(u, pdot(w, u)));
    if (pdot(p, p) > 0.01) return pnormalize(p);
  }
}

// A non-power-of-two factor in [2^lo, 2^(hi+1)).
double length_factor(Rng& r, int lo, int hi) { return std::ldexp(1.0 + r.unit(), int(r.range(lo, hi))); }

I3 cross3(const I3& a, const I3& b) {
  return I3{a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
int64_t dot3(const I3& a, const I3& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
I3 mul3(const I3& a, int64_t s) { return I3{a[0] * s, a[1] * s, a[2] * s}; }
I3 sub3(const I3& a, const I3& b) { return I3{a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
bool zero3(const I3& a) { return a[0] == 0 && a[1] == 0 && a[2] == 0; }
I3 nonzero_bits3(Rng& r, int b) {
  I3 v;
  do v = bits3(r, b);
  while (zero3(v));
  return v;
}

// An integer vector W with |W| = N exactly (a Pythagorean quadruple, from
// x = m^2 + n^2 - p^2 - q^2, y = 2(mq + np), z = 2(nq - mp),
// N = m^2 + n^2 + p^2 + q^2), in a random order and with random signs.
I3 pythagorean(Rng& r, int bits, int64_t& N) {
  for (;;) {
    int64_t m = r.bits(bits), n = r.bits(bits), p = r.bits(bits), q = r.bits(bits);
    N = m * m + n * n + p * p + q * q;
    if (N == 0) continue;
    I3 w = {m * m + n * n - p * p - q * q, 2 * (m * q + n * p), 2 * (n * q - m * p)};
    if (dot3(w, w) != N * N) die("not a Pythagorean quadruple");
    for (int i = 2; i > 0; --i) std::swap(w[i], w[r.next() % (i + 1)]);
    for (int64_t& x : w) x *= r.sign();
    return w;
  }
}

// A Pythagorean triple (a, b, c), a^2 + b^2 = c^2, c > 0, a b != 0.
I3 pythagorean_triple(Rng& r) {
  int64_t m = r.range(2, 12), n = r.range(1, m - 1);
  I3 t = {m * m - n * n, 2 * m * n, m * m + n * n};
  if (r.chance(50)) std::swap(t[0], t[1]);
  t[0] *= r.sign();
  t[1] *= r.sign();
  return t;
}

void append3(Case& v, const P3& p) { v.insert(v.end(), p.begin(), p.end()); }

// 1-3 representable steps on one nonzero input (chosen among `slots`).
void nudge_one(Rng& r, Case& v, const std::vector<size_t>& slots) {
  for (;;) {
    size_t i = slots[r.next() % slots.size()];
    if (v[i] == 0) continue;
    v[i] = step_ulps(v[i], int(r.range(1, 3)) * r.sign());
    return;
  }
}

std::vector<size_t> all_slots(size_t n) {
  std::vector<size_t> s(n);
  for (size_t i = 0; i < n; ++i) s[i] = i;
  return s;
}

// ---------------------------------------------------------------------------
// Exact roots

struct Poly2 {
  Q a, b, c;  // a t^2 + b t + c
};

Q peval(const Poly2& p, const Q& t) { return Q((p.a * t + p.b) * t + p.c); }

struct Roots {
  int n = 0;              // distinct real roots; -1: every t is a root
  std::vector<double> t;  // the roots rounded to nearest, ascending
  bool representable = true;
};

constexpr int kMpfrBits = 320;

bool odd_bits(double x) {
  uint64_t u;
  std::memcpy(&u, &x, sizeof u);
  return u & 1;
}

// Roots are kept finite and normal (or exactly zero).
bool in_normal_range(double x) { return x == 0 || (std::fabs(x) >= 0x1p-1021 && std::fabs(x) <= 0x1p1022); }

// Proves that x is the root r rounded to nearest, ties to even, given
// cmp(y) = sign(y - r) exactly for rational y: r lies strictly between the
// midpoints from x to its neighbouring doubles, or exactly on one of them
// with x even. When r is exactly a midpoint and x is the odd neighbour, the
// even one is returned (and proved). Dies when the proof fails.
template <class Cmp>
double prove_nearest(double x, Cmp cmp, const char* what) {
  for (int pass = 0; pass < 2; ++pass) {
    double below = std::nextafter(x, -INFINITY), above = std::nextafter(x, INFINITY);
    Q lo = (Q(below) + Q(x)) / 2, hi = (Q(x) + Q(above)) / 2;
    int cl = cmp(lo), ch = cmp(hi);
    if (cl < 0 && ch > 0) return x;
    if (cl == 0 || ch == 0) {
      if (!odd_bits(x)) return x;
      x = cl == 0 ? below : above;
      continue;
    }
    break;
  }
  die("%s: correct rounding of %.17g not proved", what, x);
}

// A rational rounded to nearest: mpq -> 53-bit MPFR with MPFR_RNDN is
// correctly rounded; the midpoint check repeats the proof. `ok` false: the
// value is not a normal double (or zero).
double nearest_rational(const Q& q, bool& ok) {
  mpfr_t m;
  mpfr_init2(m, 53);
  mpfr_set_q(m, q.get_mpq_t(), MPFR_RNDN);
  double x = mpfr_get_d(m, MPFR_RNDN) + 0.0;  // no -0
  mpfr_clear(m);
  if (!std::isfinite(x) || !in_normal_range(x) || (x == 0) != (sgn(q) == 0)) {
    ok = false;
    return 0;
  }
  return prove_nearest(x, [&q](const Q& y) { return sgn(Q(y - q)); }, "rational root");
}

// Two distinct roots (discriminant `disc` > 0).
void two_roots(const Poly2& p, const Q& disc, Roots& R) {
  mpfr_t a, b, c, s, q, r1, r2;
  for (mpfr_ptr x : {a, b, c, s, q, r1, r2}) mpfr_init2(x, kMpfrBits);
  mpfr_set_q(a, p.a.get_mpq_t(), MPFR_RNDN);
  mpfr_set_q(b, p.b.get_mpq_t(), MPFR_RNDN);
  mpfr_set_q(c, p.c.get_mpq_t(), MPFR_RNDN);
  mpfr_set_q(s, disc.get_mpq_t(), MPFR_RNDN);
  mpfr_sqrt(s, s, MPFR_RNDN);
  // q = -(b + sign(b) sqrt(disc)) / 2: no cancellation; the roots are q/a, c/q.
  if (sgn(p.b) >= 0)
    mpfr_add(q, b, s, MPFR_RNDN);
  else
    mpfr_sub(q, b, s, MPFR_RNDN);
  mpfr_div_si(q, q, -2, MPFR_RNDN);
  mpfr_div(r1, q, a, MPFR_RNDN);
  mpfr_div(r2, c, q, MPFR_RNDN);
  if (mpfr_cmp(r1, r2) > 0) mpfr_swap(r1, r2);
  double x1 = mpfr_get_d(r1, MPFR_RNDN) + 0.0, x2 = mpfr_get_d(r2, MPFR_RNDN) + 0.0;  // no -0
  bool z1 = mpfr_zero_p(r1), z2 = mpfr_zero_p(r2);
  for (mpfr_ptr x : {a, b, c, s, q, r1, r2}) mpfr_clear(x);
  R.n = 2;
  for (auto [x, z] : {std::pair<double, bool>{x1, z1}, {x2, z2}})
    if (!std::isfinite(x) || !in_normal_range(x) || (x == 0) != z) R.representable = false;
  if (!R.representable) return;
  // The vertex separates the roots; on each side p is monotone with one root.
  const Q v = -p.b / (2 * p.a);
  const int sa = sgn(p.a);
  auto lower = [&](const Q& y) {
    if (y >= v) return 1;
    int s = sgn(peval(p, y));
    return s == 0 ? 0 : s == sa ? -1 : 1;  // left of the lower root p has a's sign
  };
  auto upper = [&](const Q& y) {
    if (y <= v) return -1;
    int s = sgn(peval(p, y));
    return s == 0 ? 0 : s == -sa ? -1 : 1;  // between the roots p has the opposite sign
  };
  R.t = {prove_nearest(x1, lower, "lower root"), prove_nearest(x2, upper, "upper root")};
}

Roots solve_exact(const Poly2& p) {
  Roots R;
  bool ok = true;
  if (sgn(p.a) == 0) {
    if (sgn(p.b) == 0) {
      R.n = sgn(p.c) == 0 ? -1 : 0;
      return R;
    }
    R.n = 1;
    R.t = {nearest_rational(Q(-p.c / p.b), ok)};
    R.representable = ok;
    return R;
  }
  Q disc = p.b * p.b - 4 * p.a * p.c;
  switch (sgn(disc)) {
    case -1: R.n = 0; break;
    case 0:
      // A double root: p does not change sign there, the root is -b / 2a.
      R.n = 1;
      R.t = {nearest_rational(Q(-p.b / (2 * p.a)), ok)};
      R.representable = ok;
      break;
    default: two_roots(p, disc, R);
  }
  return R;
}

// Fails loudly if the root machinery disagrees with IEEE arithmetic, which
// rounds sqrt and division correctly: the roots of t^2 - x are -+sqrt(x),
// the root of b t + c is -c / b, the roots of (t - x)(t - y) are x and y;
// roots exactly halfway between two doubles round to the even one.
void check_root_rounding() {
  Rng r(fnv1a("check_root_rounding"));
  for (int i = 0; i < 2000; ++i) {
    double x = std::ldexp(r.unit() + 0x1p-60, int(r.range(-600, 600)));
    Roots R = solve_exact(Poly2{Q(1), Q(0), Q(-x)});
    if (R.n != 2 || R.t[0] != -std::sqrt(x) || R.t[1] != std::sqrt(x)) die("root check: sqrt(%.17g)", x);
    double b = std::ldexp(r.sym(), int(r.range(-300, 300))), c = std::ldexp(r.sym(), int(r.range(-300, 300)));
    if (b == 0) continue;
    R = solve_exact(Poly2{Q(0), Q(b), Q(c)});
    if (R.n != 1 || R.t[0] != -c / b) die("root check: -c/b");
    double y = std::ldexp(r.sym(), int(r.range(-60, 60)));
    if (y == c) continue;
    R = solve_exact(Poly2{Q(1), Q(-(Q(c) + Q(y))), Q(Q(c) * Q(y))});
    if (R.n != 2 || R.t[0] != std::min(c, y) || R.t[1] != std::max(c, y)) die("root check: (t - x)(t - y)");
  }
  // Halfway cases: 1 + 2^-53 rounds to 1 (even), 1 + 3 2^-53 to 1 + 2^-51;
  // through the two-root path (t - m)(t + 5) and the double root (t - m)^2.
  const Q ulp_half = Q(1) / Q(std::ldexp(1.0, 53));
  const Q m1 = 1 + ulp_half, m3 = 1 + 3 * ulp_half;
  for (auto [m, want] : {std::pair<Q, double>{m1, 1.0}, {m3, 1 + 0x1p-51}}) {
    Roots R = solve_exact(Poly2{Q(1), Q(5 - m), Q(-5 * m)});
    if (R.n != 2 || R.t[0] != -5 || R.t[1] != want) die("root check: halfway (two roots)");
    R = solve_exact(Poly2{Q(1), Q(-2 * m), Q(m * m)});
    if (R.n != 1 || R.t[0] != want) die("root check: halfway (double root)");
  }
}

// The textbook evaluation in f64, only for the statistics: the root count
// from the sign of b^2 - 4ac, roots (-b -+ sqrt(b^2 - 4ac)) / 2a. n = -2:
// overflow or NaN.
struct NaiveRoots {
  int n;
  std::vector<double> t;
};

NaiveRoots naive_solve(double a, double b, double c) {
  if (!std::isfinite(a) || !std::isfinite(b) || !std::isfinite(c)) return {-2, {}};
  if (a == 0) {
    if (b == 0) return {c == 0 ? -1 : 0, {}};
    return {1, {-c / b}};
  }
  double disc = b * b - 4 * a * c;
  if (!std::isfinite(disc)) return {-2, {}};
  if (disc < 0) return {0, {}};
  if (disc == 0) return {1, {-b / (2 * a)}};
  double s = std::sqrt(disc);
  double t0 = (-b - s) / (2 * a), t1 = (-b + s) / (2 * a);
  if (t0 > t1) std::swap(t0, t1);
  return {2, {t0, t1}};
}

// Representable steps between x and y (saturating; non-finite: maximal).
uint64_t ulp_distance(double x, double y) {
  if (!std::isfinite(x) || !std::isfinite(y)) return UINT64_MAX;
  auto key = [](double v) {
    int64_t i;
    std::memcpy(&i, &v, sizeof i);
    return i < 0 ? __int128(INT64_MIN) - i : __int128(i);
  };
  __int128 d = key(x) - key(y);
  if (d < 0) d = -d;
  return d > __int128(UINT64_MAX) ? UINT64_MAX : uint64_t(d);
}

// ---------------------------------------------------------------------------
// Output for the ray kinds: `inputs answer`, with per-block and per-section
// statistics: how many cases have each root count (or hit class) and how many
// a naive f64 evaluation gets wrong (the count, or a root more than 4 ulps
// from the correctly rounded one).

constexpr int kMinBlock = 50;  // every block holds at least this many cases
constexpr uint64_t kNaiveUlps = 4;

class RayWriter {
 public:
  RayWriter(std::string kind, const std::string& header) : kind_(std::move(kind)) {
    out_ += "# " + kind_ + " fixtures. Generated by tools/cgal-fixtures/generate.cpp; do not edit, rerun\n";
    out_ += "# tools/cgal-fixtures/regenerate.sh.\n";
    out_ += header;
  }

  // must/allowed: answer categories among "012i" (i: infinitely many roots).
  void section(const std::string& name, const std::string& what, const char* must, const char* allowed) {
    end_section();
    section_ = name;
    must_ = must;
    allowed_ = allowed;
    out_ += "\n# section " + name + ": " + what + "\n";
  }

  Rng block(const std::string& label) {
    if (section_.empty()) die("block outside a section");
    end_block();
    block_label_ = label;
    in_block_ = true;
    out_ += "# " + section_ + ": " + label + "\n";
    return Rng(fnv1a(kind_ + "/" + section_ + "/" + label));
  }

  // n: the answer's category (-1: infinitely many); roots: its distinct
  // roots (or the triangle's t); answer: the text after the inputs.
  void emit(const Case& in, int n, const std::vector<double>& roots, const std::string& answer,
            const NaiveRoots& naive) {
    if (!in_block_) die("%s: case outside a block", kind_.c_str());
    for (double x : in) {
      out_ += format_coord(x);
      out_ += ' ';
    }
    out_ += answer;
    out_ += '\n';
    int cat = n < 0 ? 3 : n;
    bool count_wrong = naive.n != n;
    bool roots_wrong = false;
    if (!count_wrong)
      for (size_t i = 0; i < roots.size(); ++i) roots_wrong |= ulp_distance(roots[i], naive.t[i]) > kNaiveUlps;
    for (Stats* s : {&block_stats_, &section_stats_}) {
      ++s->n;
      ++s->by[cat];
      s->naive_count += count_wrong;
      s->naive_roots += roots_wrong;
    }
  }

  void finish(const std::string& path) {
    end_section();
    write_file(path, out_);
    std::fprintf(stderr, "%-12s %5d cases  %8zu bytes  %s\n", kind_.c_str(), total_, out_.size(), path.c_str());
  }

 private:
  struct Stats {
    int n = 0;
    int by[4] = {0, 0, 0, 0};  // 0, 1, 2, inf
    int naive_count = 0, naive_roots = 0;
  };

  static std::string describe(const Stats& s) {
    char buf[200];
    std::snprintf(buf, sizeof buf, "%4d cases  (0:%d 1:%d 2:%d inf:%d)  naive f64: count wrong %d, roots > 4 ulps %d",
                  s.n, s.by[0], s.by[1], s.by[2], s.by[3], s.naive_count, s.naive_roots);
    return buf;
  }

  void end_block() {
    if (!in_block_) return;
    if (block_stats_.n < kMinBlock)
      die("%s/%s: block \"%s\" has %d cases, fewer than %d", kind_.c_str(), section_.c_str(), block_label_.c_str(),
          block_stats_.n, kMinBlock);
    std::string label = block_label_.size() > 60 ? block_label_.substr(0, 57) + "..." : block_label_;
    std::fprintf(stderr, "%-12s   %-60s %s\n", kind_.c_str(), label.c_str(), describe(block_stats_).c_str());
    block_stats_ = Stats{};
    in_block_ = false;
  }

  void end_section() {
    end_block();
    if (section_.empty()) return;
    const char* names = "012i";
    for (int c = 0; c < 4; ++c) {
      bool must = std::strchr(must_, names[c]) != nullptr;
      bool allowed = std::strchr(allowed_, names[c]) != nullptr;
      if (must && section_stats_.by[c] == 0)
        die("%s/%s: no case with answer %c", kind_.c_str(), section_.c_str(), names[c]);
      if (!allowed && section_stats_.by[c] != 0)
        die("%s/%s: %d cases with answer %c", kind_.c_str(), section_.c_str(), section_stats_.by[c], names[c]);
    }
    std::fprintf(stderr, "%-12s %-18s %s\n", kind_.c_str(), section_.c_str(), describe(section_stats_).c_str());
    total_ += section_stats_.n;
    section_stats_ = Stats{};
    section_.clear();
  }

  std::string kind_, out_, section_, block_label_;
  const char* must_ = "";
  const char* allowed_ = "";
  bool in_block_ = false;
  Stats block_stats_, section_stats_;
  int total_ = 0;
};

// ---------------------------------------------------------------------------
// The three kinds whose answer is the real roots of a polynomial of degree <= 2
// in t: its coefficients, the defining expression at o + t d (to check the
// expansion), an independent CGAL root count where there is one, and the
// textbook f64 coefficients.

struct QuadKind {
  const char* name;
  size_t ninputs;
  Poly2 (*poly)(const Case&);
  Q (*direct)(const Case&, const Q& t);
  int (*cgal_count)(const Case&);  // nullptr: none
  std::array<double, 3> (*naive_coeffs)(const Case&);
  bool tangent_twice;  // n = 1 writes the root twice (t0 = t1)
};

char category(int n) { return n < 0 ? 'i' : char('0' + n); }

// Writes the case and returns true, or returns false (writing nothing) when a
// root is not a normal double, when two distinct roots round to the same
// double (the format promises t0 < t1), or when the root count is not in
// `accept`.
bool emit_quad(RayWriter& w, const QuadKind& k, const Case& v, const char* accept = nullptr) {
  if (v.size() != k.ninputs) die("%s: %zu inputs", k.name, v.size());
  Poly2 p = k.poly(v);
  // Three values fix a quadratic: the expansion agrees with the definition.
  for (int t = -1; t <= 1; ++t)
    if (peval(p, Q(t)) != k.direct(v, Q(t))) die("%s: expanded polynomial disagrees with the definition", k.name);
  Roots R = solve_exact(p);
  if (!R.representable) return false;
  if (R.n == 2 && R.t[0] == R.t[1]) return false;
  if (k.cgal_count && k.cgal_count(v) != R.n)
    die("%s: CGAL's distance comparison and the discriminant disagree", k.name);
  if (accept && !std::strchr(accept, category(R.n))) return false;
  std::string answer = R.n < 0 ? "inf" : std::to_string(R.n);
  for (double t : R.t) answer += " " + format_coord(t);
  if (R.n == 1 && k.tangent_twice) answer += " " + format_coord(R.t[0]);
  std::array<double, 3> c = k.naive_coeffs(v);
  w.emit(v, R.n, R.t, answer, naive_solve(c[0], c[1], c[2]));
  return true;
}

// A block of n cases from make(rng) (an empty Case: try again), each kept
// only if emit_quad accepts it.
template <class F>
void quad_block(RayWriter& w, const QuadKind& k, const std::string& label, int n, F make,
                const char* accept = nullptr) {
  Rng r = w.block(label);
  int made = 0;
  for (int tries = 0; made < n; ++tries) {
    if (tries > 100 * n) die("%s: block \"%s\" keeps failing", k.name, label.c_str());
    Case v = make(r);
    if (!v.empty() && emit_quad(w, k, v, accept)) ++made;
  }
}

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
      if (v.empty()) return v;
      bool keep_d = r.chance(50);
      for (size_t i = 0; i < v.size(); ++i)
        if (!(keep_d && i >= 3 && i < 6)) {
          Case one = {v[i]};
          scale(one, 100 * sgn_k);
          v[i] = one[0];
        }
      return v;
    });
  }
}

// ---------------------------------------------------------------------------
// ray_cylinder: o d p a r -> n [t0 t1]

Case cylinder_case(const P3& o, const P3& d, const P3& p, const P3& a, double r) {
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
  return cylinder_case(o, d, p, pmul(au, length_factor(r, -6, 5)), rad);
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
  Case v = cylinder_case(o, parallel_dir(r, A), p, a, rad);
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
  return cylinder_case(lattice3(O, e), parallel_dir(r, A), lattice3(C, e), lattice3(A, int(r.range(-10, 10))),
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
  return cylinder_case(lattice3(O, e), lattice3(D, int(r.range(-8, 8))), lattice3(C, e),
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
  return cylinder_case(o, d, p, au, 1.0);
}

void gen_ray_cylinder(RayWriter& w) {
  const QuadKind& k = kRayCylinder;
  w.section("exam", "the cylinder x^2 + z^2 = 1 (p = 0, a = (0,1,0), r = 1), origins in [-4,4]^3", "02", "012");
  quad_block(w, k, "random directions in [-1,1]^3", 60, [](Rng& r) {
    P3 d = uniform3(r, 0);
    if (d == P3{0, 0, 0}) return Case{};
    return cylinder_case(uniform3(r, 2), d, P3{0, 0, 0}, kExamAxis, 1.0);
  });
  quad_block(w, k, "aimed at a point within 1.3 of the axis, |y| < 2", 60, [](Rng& r) {
    P3 o = uniform3(r, 2), aim;
    do aim = {1.3 * r.sym(), 2 * r.sym(), 1.3 * r.sym()};
    while (aim[0] * aim[0] + aim[2] * aim[2] > 1.69);
    P3 d = psub(aim, o);
    if (d == P3{0, 0, 0}) return Case{};
    return cylinder_case(o, d, P3{0, 0, 0}, kExamAxis, 1.0);
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
  Frame f(r);
  Case coef;
  if (!place(r, y, f, coef)) return {};
  P3 o = f.point(add3(P, mul3(V, r.range(-(1 << 16), 1 << 16))));
  return quadric_case(o, lattice3(f.dir(V), int(r.range(-4, 4))), coef);
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

  w.section("degree-zero", "leading and linear coefficients exactly 0: n = 0, or inf on the surface", "0i", "0i");
  quad_block(w, k, "lines on the quadric: cone rulings through the apex, rulings of one-sheet hyperboloids and "
             "hyperbolic paraboloids, lines in a plane of a plane pair, cylinder lines: n = inf", 60,
             quadric_line_on, "i");
  quad_block(w, k, "along a cylinder's or parallel plane pair's direction, along a plane pair's common line, "
             "origin off the surface: n = 0", 50, quadric_degree_zero_off, "0");

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
}

// ---------------------------------------------------------------------------
// ray_triangle: o d v0 v1 v2 -> hit [t]
//
// hit 1: the ray's line is not in the triangle's plane and meets the closed
// triangle at t >= 0; hit 2: the line lies in the plane (exactly: n . d = 0
// and n . (o - v0) = 0 for n = (v1 - v0) x (v2 - v0)) and the ray touches the
// triangle. A degenerate triangle (collinear vertices, n = 0) is the segment
// between its two farthest vertices (or a point); every line through it lies
// in a plane containing it, so a ray touching it is hit 2.

struct TriExact {
  int hit;
  Q t;
};

struct {
  int checked = 0, wrong = 0, degenerate = 0;
} g_epick_tri;

TriExact triangle_exact(const Case& v) {
  QV o = qv3(v, 0), d = qv3(v, 3), a = qv3(v, 6), b = qv3(v, 9), c = qv3(v, 12);
  QV n = qcross(qsub(b, a), qsub(c, a));
  bool degenerate = qzero(n);
  bool coplanar = degenerate || (sgn(qdot(n, d)) == 0 && sgn(qdot(n, qsub(o, a))) == 0);
  auto ep = [&v](size_t i) { return Epeck::Point_3(v[i], v[i + 1], v[i + 2]); };
  auto rp = [&v](size_t i) { return RatK::Point_3(Rq(v[i]), Rq(v[i + 1]), Rq(v[i + 2])); };
  Epeck::Ray_3 ray(ep(0), Epeck::Vector_3(v[3], v[4], v[5]));
  RatK::Ray_3 rray(rp(0), RatK::Vector_3(Rq(v[3]), Rq(v[4]), Rq(v[5])));
  bool touch, touch_rat;
  if (!degenerate) {
    touch = CGAL::do_intersect(ray, Epeck::Triangle_3(ep(6), ep(9), ep(12)));
    touch_rat = CGAL::do_intersect(rray, RatK::Triangle_3(rp(6), rp(9), rp(12)));
  } else {
    const QV* q[3] = {&a, &b, &c};
    size_t best_i = 0, best_j = 1;
    Q best = -1;
    for (size_t i = 0; i < 3; ++i)
      for (size_t j = i + 1; j < 3; ++j) {
        QV e = qsub(*q[j], *q[i]);
        Q len = qdot(e, e);
        if (len > best) best = len, best_i = i, best_j = j;
      }
    if (sgn(best) == 0) {
      touch = ray.has_on(ep(6));
      touch_rat = rray.has_on(rp(6));
    } else {
      touch = CGAL::do_intersect(ray, Epeck::Segment_3(ep(6 + 3 * best_i), ep(6 + 3 * best_j)));
      touch_rat = CGAL::do_intersect(rray, RatK::Segment_3(rp(6 + 3 * best_i), rp(6 + 3 * best_j)));
    }
  }
  if (touch != touch_rat) die("ray_triangle: Epeck and rational do_intersect disagree");
  if (!degenerate) {
    // Only reported: Epick's ray goes through the rounded point o + d.
    Epick::Point_3 eo(v[0], v[1], v[2]);
    Epick::Ray_3 eray(eo, Epick::Vector_3(v[3], v[4], v[5]));
    auto pt = [&v](size_t i) { return Epick::Point_3(v[i], v[i + 1], v[i + 2]); };
    ++g_epick_tri.checked;
    if (eray.is_degenerate())  // o + d rounds to o: a precondition violation
      ++g_epick_tri.degenerate;
    else if (CGAL::do_intersect(eray, Epick::Triangle_3(pt(6), pt(9), pt(12))) != touch)
      ++g_epick_tri.wrong;
  }
  if (coplanar) {
    if (!degenerate) {
      // In the plane: the origin in the closed triangle, or the ray meets an edge.
      RatK::Triangle_3 tri(rp(6), rp(9), rp(12));
      bool mine = tri.has_on(rp(0)) || CGAL::do_intersect(rray, RatK::Segment_3(rp(6), rp(9))) ||
                  CGAL::do_intersect(rray, RatK::Segment_3(rp(9), rp(12))) ||
                  CGAL::do_intersect(rray, RatK::Segment_3(rp(12), rp(6)));
      if (mine != touch) die("ray_triangle: coplanar edge test and do_intersect disagree");
    }
    return TriExact{touch ? 2 : 0, Q(0)};
  }
  // Parallel to the plane, off it: no common point.
  Q nd = qdot(n, d);
  if (sgn(nd) == 0) {
    if (touch) die("ray_triangle: do_intersect touches a parallel plane");
    return TriExact{0, Q(0)};
  }
  // Otherwise the line meets the plane once, at t = n.(v0 - o) / n.d; it
  // meets the closed triangle iff d . ((v_i - o) x (v_{i+1} - o)) have no
  // two opposite signs.
  Q t = qdot(n, qsub(a, o)) / nd;
  const QV* q[3] = {&a, &b, &c};
  int pos = 0, neg = 0;
  for (int i = 0; i < 3; ++i) {
    int s = sgn(qdot(d, qcross(qsub(*q[i], o), qsub(*q[(i + 1) % 3], o))));
    pos += s > 0;
    neg += s < 0;
  }
  bool mine = !(pos > 0 && neg > 0) && sgn(t) >= 0;
  if (mine != touch) die("ray_triangle: the signed-volume test and do_intersect disagree");
  if (!touch) return TriExact{0, Q(0)};
  // CGAL's constructed intersection point (rational kernel) gives the same t.
  auto x = CGAL::intersection(rray, RatK::Triangle_3(rp(6), rp(9), rp(12)));
  const RatK::Point_3* p = x ? boost::get<RatK::Point_3>(&*x) : nullptr;
  if (!p) die("ray_triangle: CGAL's intersection is not a point");
  RatK::Vector_3 rd(Rq(v[3]), Rq(v[4]), Rq(v[5]));
  if (to_q(((*p - rp(0)) * rd) / (rd * rd)) != t) die("ray_triangle: CGAL's intersection point has another t");
  return TriExact{1, t};
}

// Moeller-Trumbore in f64 without tolerances, only for the statistics:
// det == 0 (parallel or coplanar) counts as a miss.
NaiveRoots triangle_naive(const Case& v) {
  P3 o = {v[0], v[1], v[2]}, d = {v[3], v[4], v[5]}, a = {v[6], v[7], v[8]};
  P3 e1 = psub(P3{v[9], v[10], v[11]}, a), e2 = psub(P3{v[12], v[13], v[14]}, a);
  P3 p = pcross(d, e2);
  double det = pdot(e1, p);
  if (!(det != 0) || !std::isfinite(det)) return {0, {}};
  double inv = 1 / det;
  P3 s = psub(o, a);
  double u = pdot(s, p) * inv;
  if (!(u >= 0 && u <= 1)) return {0, {}};
  P3 q = pcross(s, e1);
  double w = pdot(d, q) * inv;
  if (!(w >= 0 && u + w <= 1)) return {0, {}};
  double t = pdot(e2, q) * inv;
  if (!(t >= 0)) return {0, {}};
  return {1, {t}};
}

bool emit_triangle(RayWriter& w, const Case& v, const char* accept) {
  if (v.size() != 15) die("ray_triangle: %zu inputs", v.size());
  TriExact x = triangle_exact(v);
  if (accept && !std::strchr(accept, category(x.hit))) return false;
  std::string answer = std::to_string(x.hit);
  std::vector<double> ts;
  if (x.hit == 1) {
    bool ok = true;
    double t = nearest_rational(x.t, ok);
    if (!ok) return false;
    ts = {t};
    answer += " " + format_coord(t);
  }
  w.emit(v, x.hit, ts, answer, triangle_naive(v));
  return true;
}

// A block of at least n cases; make(rng) returns a group of cases (say, one
// ray against every triangle sharing a vertex), possibly empty.
template <class F>
void tri_block(RayWriter& w, const std::string& label, int n, F make, const char* accept = nullptr) {
  Rng r = w.block(label);
  int made = 0;
  for (int tries = 0; made < n; ++tries) {
    if (tries > 100 * n) die("ray_triangle: block \"%s\" keeps failing", label.c_str());
    for (const Case& v : make(r)) made += emit_triangle(w, v, accept);
  }
}

using Tri = std::array<P3, 3>;

// The case with the triangle's vertices rotated and possibly reversed.
Case tri_case(Rng& r, const P3& o, const P3& d, Tri t) {
  std::rotate(t.begin(), t.begin() + r.next() % 3, t.end());
  if (r.chance(50)) std::swap(t[1], t[2]);
  Case v;
  append3(v, o);
  append3(v, d);
  for (const P3& p : t) append3(v, p);
  return v;
}

// A grid of (n+1)^2 lattice points B + i U + j V (units 2^e), each square
// split along its (i,j)-(i+1,j+1) diagonal: interior vertices are shared by
// six triangles, interior edges by two. U, V are multiples of 24, so points
// k/24 of the way along an edge are lattice points (with non-dyadic
// barycentric coordinates such as 1/3).
struct Mesh {
  int n = 4, e = 0;
  std::vector<I3> pts;
  std::vector<std::array<int, 3>> tris;
  I3 normal;
  std::vector<std::pair<int, int>> inner_edges;

  Mesh(Rng& r, bool tilted) {
    e = int(r.range(-30, 0));
    I3 B = bits3(r, 24), U = {0, 0, 0}, V = {0, 0, 0};
    if (tilted) {
      do U = mul3(nonzero_bits3(r, 4), 24), V = mul3(nonzero_bits3(r, 4), 24);
      while (zero3(cross3(U, V)));
    } else {
      int ax = int(r.next() % 3);
      U[(ax + 1) % 3] = 24 << r.range(0, 4);
      V[(ax + 2) % 3] = 24 << r.range(0, 4);
    }
    normal = cross3(U, V);
    for (int j = 0; j <= n; ++j)
      for (int i = 0; i <= n; ++i) pts.push_back(add3(B, add3(mul3(U, i), mul3(V, j))));
    auto id = [this](int i, int j) { return j * (n + 1) + i; };
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i) {
        tris.push_back({id(i, j), id(i + 1, j), id(i + 1, j + 1)});
        tris.push_back({id(i, j), id(i + 1, j + 1), id(i, j + 1)});
      }
    std::map<std::pair<int, int>, int> count;
    for (const auto& t : tris)
      for (int k = 0; k < 3; ++k) ++count[std::minmax(t[k], t[(k + 1) % 3])];
    for (const auto& [edge, c] : count)
      if (c == 2) inner_edges.push_back(edge);
  }

  P3 at(const I3& x) const { return lattice3(x, e); }
  Tri tri(int t) const { return Tri{at(pts[tris[t][0]]), at(pts[tris[t][1]]), at(pts[tris[t][2]])}; }
  std::vector<int> tris_with(int a, int b = -1) const {
    std::vector<int> out;
    for (int t = 0; t < int(tris.size()); ++t) {
      const auto& x = tris[t];
      bool has_a = x[0] == a || x[1] == a || x[2] == a;
      bool has_b = b < 0 || x[0] == b || x[1] == b || x[2] == b;
      if (has_a && has_b) out.push_back(t);
    }
    return out;
  }
  // An interior vertex.
  int inner_vertex(Rng& r) const { return int(r.range(1, n - 1)) * (n + 1) + int(r.range(1, n - 1)); }
  // k/24 of the way along an interior edge, k in 1..23 (the midpoint half the time).
  I3 edge_point(Rng& r, const std::pair<int, int>& edge) const {
    int64_t k = r.chance(50) ? 12 : r.range(1, 23);
    const I3 &a = pts[edge.first], &b = pts[edge.second];
    I3 step = sub3(b, a);
    for (int64_t& c : step) c /= 24;  // exact: b - a is a multiple of 24
    return add3(a, mul3(step, k));
  }
};

// A direction D (b-bit integers) not parallel to the plane with normal N.
I3 transversal(Rng& r, const I3& N, int b = 8) {
  I3 D;
  do D = nonzero_bits3(r, b);
  while (dot3(D, N) == 0);
  return D;
}

// A ray through the lattice point X: o = (X - S D) 2^e, d = D 2^k, S > 0;
// D 20-bit, S < 2^20, so that f64 products round.
void ray_through(Rng& r, const I3& X, int e, const I3& N, P3& o, P3& d) {
  I3 D = transversal(r, N, 20);
  o = lattice3(sub3(X, mul3(D, r.range(1, 1 << 20))), e);
  d = lattice3(D, int(r.range(-6, 6)));
}

// A ray through the double point X (not on a lattice: X was moved by an
// ulp): o = X - S D 2^e computed in f64 (D 10-bit, S < 2^13: o keeps X's
// last bits), kept only if exact.
bool ray_through_exact(Rng& r, const P3& X, int e, const I3& N, P3& o, P3& d) {
  I3 D = transversal(r, N, 10);
  int64_t S = r.range(1, 1 << 13);
  P3 step = lattice3(mul3(D, S), e);
  o = psub(X, step);
  for (int i = 0; i < 3; ++i)
    if (Q(o[i]) != Q(X[i]) - Q(step[i])) return false;
  d = lattice3(D, int(r.range(-6, 6)));
  return true;
}

// A random triangle in [-1,1]^3, origin in [-4,4]^3; aimed: through
// v0 + w1 (v1 - v0) + w2 (v2 - v0), w in [-0.1, 1.1] (in and around).
Case tri_random(Rng& r, bool aimed) {
  Tri t = {uniform3(r, 0), uniform3(r, 0), uniform3(r, 0)};
  P3 o = uniform3(r, 2), d;
  if (aimed) {
    double w1 = -0.1 + 1.2 * r.unit(), w2 = -0.1 + 1.2 * r.unit();
    d = psub(padd(t[0], padd(pmul(psub(t[1], t[0]), w1), pmul(psub(t[2], t[0]), w2))), o);
  } else {
    d = uniform3(r, 0);
  }
  if (d == P3{0, 0, 0}) return {};
  return tri_case(r, o, d, t);
}

// A lattice triangle B + i U + j V (times 8, units 2^e) in a random plane.
struct LatticeTri {
  I3 v[3], U, V, N;
  int e;
  LatticeTri(Rng& r) {
    e = int(r.range(-20, 0));
    I3 B = bits3(r, 20);
    do U = nonzero_bits3(r, 4), V = nonzero_bits3(r, 4);
    while (zero3(cross3(U, V)));
    N = cross3(U, V);
    int64_t ij[3][2];
    do
      for (auto& p : ij) p[0] = r.range(-4, 4), p[1] = r.range(-4, 4);
    while ((ij[1][0] - ij[0][0]) * (ij[2][1] - ij[0][1]) == (ij[1][1] - ij[0][1]) * (ij[2][0] - ij[0][0]));
    for (int k = 0; k < 3; ++k) v[k] = mul3(add3(B, add3(mul3(U, ij[k][0]), mul3(V, ij[k][1]))), 8);
  }
  Tri tri() const { return Tri{lattice3(v[0], e), lattice3(v[1], e), lattice3(v[2], e)}; }
  // (a v0 + b v1 + c v2) / 8 with a + b + c = 8, a, b, c >= 0: in the closed
  // triangle; mode 0 anywhere, 1 on an edge, 2 a vertex.
  I3 bary(Rng& r, int mode) const {
    int64_t w[3];
    if (mode == 2) {
      w[0] = 8, w[1] = w[2] = 0;
    } else if (mode == 1) {
      w[0] = r.range(0, 8), w[1] = 8 - w[0], w[2] = 0;
    } else {
      w[0] = r.range(0, 8), w[1] = r.range(0, 8 - w[0]), w[2] = 8 - w[0] - w[1];
    }
    for (int i = 2; i > 0; --i) std::swap(w[i], w[r.next() % (i + 1)]);
    I3 x = add3(add3(mul3(v[0], w[0]), mul3(v[1], w[1])), mul3(v[2], w[2]));
    for (int64_t& c : x) c /= 8;
    return x;
  }
  I3 in_plane_dir(Rng& r) const {
    I3 D;
    do D = add3(mul3(U, r.range(-8, 8)), mul3(V, r.range(-8, 8)));
    while (zero3(D));
    return D;
  }
};

Case coplanar_case(Rng& r, int mode) {
  LatticeTri T(r);
  I3 O, D = T.in_plane_dir(r);
  switch (mode) {
    case 0:  // anywhere in the plane
      O = add3(mul3(T.v[0], 1), add3(mul3(T.U, r.range(-64, 64)), mul3(T.V, r.range(-64, 64))));
      break;
    case 1: {  // through a vertex
      O = sub3(T.v[r.next() % 3], mul3(D, r.range(1, 8)));
      break;
    }
    case 2: {  // on an edge's line, along the edge
      int a = int(r.next() % 3), b = (a + 1) % 3;
      I3 e = sub3(T.v[b], T.v[a]);
      I3 step = e;
      for (int64_t& c : step) c /= 8;
      O = add3(T.v[a], mul3(step, r.range(-16, 24)));
      D = mul3(step, r.sign() * r.range(1, 3));
      break;
    }
    case 3:  // from inside or on the boundary
      O = T.bary(r, int(r.range(0, 2)));
      break;
    default: {  // from outside near a vertex, pointing away (or back through it)
      int k = int(r.next() % 3);
      D = sub3(mul3(T.v[k], 2), add3(T.v[(k + 1) % 3], T.v[(k + 2) % 3]));
      for (int64_t& c : D) c /= 8;
      O = add3(T.v[k], mul3(D, r.range(1, 4)));
      if (r.chance(50)) D = mul3(D, -1);
    }
  }
  return tri_case(r, lattice3(O, T.e), lattice3(D, int(r.range(-6, 6))), T.tri());
}

// Collinear vertices: X + a L, X + b L, X (a, b in [-8, 8]: distinct,
// repeated or all equal), or points (x, x, x 2^k) with arbitrary x.
Case degenerate_tri(Rng& r, bool aimed) {
  int e = int(r.range(-30, 0));
  if (!aimed && r.chance(30)) {
    int k = int(r.range(-2, 2));
    Tri t;
    for (P3& p : t) {
      double x = arbitrary(r);
      p = {x, x, std::ldexp(x, k)};
    }
    P3 o = uniform3(r, 2), d = psub(padd(t[0], uniform3(r, -4)), o);
    return tri_case(r, o, d, t);
  }
  I3 X = mul3(bits3(r, 20), 8), L = nonzero_bits3(r, 6);
  int64_t a = r.range(-8, 8), b = r.range(-8, 8);
  switch (r.next() % 4) {
    case 0: b = a; break;
    case 1: a = b = 0; break;
    default: break;
  }
  Tri t = {lattice3(X, e), lattice3(add3(X, mul3(L, 8 * a)), e), lattice3(add3(X, mul3(L, 8 * b)), e)};
  P3 o, d;
  if (aimed) {
    int64_t lo = std::min<int64_t>({0, a, b}) * 8, hi = std::max<int64_t>({0, a, b}) * 8;
    I3 Y = add3(X, mul3(L, r.range(lo, hi)));
    I3 E;
    do E = nonzero_bits3(r, 8);
    while (zero3(cross3(E, L)));
    o = lattice3(sub3(Y, mul3(E, r.range(1, 1 << 10))), e);
    d = lattice3(E, int(r.range(-6, 6)));
  } else {
    o = padd(lattice3(X, e), uniform3(r, e + 12));
    d = psub(padd(lattice3(X, e), uniform3(r, e + 8)), o);
  }
  if (d == P3{0, 0, 0}) return {};
  return tri_case(r, o, d, t);
}

// One ray through a point of the mesh (an interior edge point or vertex),
// against every triangle sharing it.
// A random inner vertex (or a point of an inner edge) of the mesh, as X,
// and the triangles sharing it.
std::vector<int> shared_point(Rng& r, const Mesh& m, bool vertex, I3& X) {
  std::vector<int> ts;
  if (vertex) {
    int v = m.inner_vertex(r);
    X = m.pts[v];
    ts = m.tris_with(v);
  } else {
    auto edge = r.pick(m.inner_edges);
    X = m.edge_point(r, edge);
    ts = m.tris_with(edge.first, edge.second);
  }
  if (ts.size() != (vertex ? 6u : 2u)) die("mesh: %zu triangles at a shared %s", ts.size(), vertex ? "vertex" : "edge");
  return ts;
}

std::vector<Case> mesh_rays(Rng& r, bool tilted, bool vertex) {
  Mesh m(r, tilted);
  I3 X;
  std::vector<int> ts = shared_point(r, m, vertex, X);
  P3 o, d;
  ray_through(r, X, m.e, m.normal, o, d);
  std::vector<Case> out;
  for (int t : ts) out.push_back(tri_case(r, o, d, m.tri(t)));
  return out;
}

// The same through the point moved by 1 ulp in one coordinate.
std::vector<Case> mesh_rays_moved(Rng& r, bool tilted, bool vertex) {
  Mesh m(r, tilted);
  I3 X;
  std::vector<int> ts = shared_point(r, m, vertex, X);
  P3 x = m.at(X);
  double& c = x[r.next() % 3];
  c = step_ulps(c, r.sign());
  P3 o, d;
  if (!ray_through_exact(r, x, m.e, m.normal, o, d)) return {};
  std::vector<Case> out;
  for (int t : ts) out.push_back(tri_case(r, o, d, m.tri(t)));
  return out;
}

Case scaled_tri(Rng& r, int k) {
  Case v;
  switch (r.next() % 4) {
    case 0: v = tri_random(r, true); break;
    case 1: v = r.pick(mesh_rays(r, r.chance(50), r.chance(50))); break;
    case 2: v = coplanar_case(r, int(r.range(0, 4))); break;
    default: {
      LatticeTri T(r);
      v = tri_case(r, lattice3(T.bary(r, int(r.range(0, 2))), T.e), uniform3(r, 0), T.tri());
    }
  }
  if (v.empty()) return v;
  bool keep_d = r.chance(50);
  for (size_t i = 0; i < v.size(); ++i)
    if (!(keep_d && i >= 3 && i < 6)) {
      Case one = {v[i]};
      scale(one, k);
      v[i] = one[0];
    }
  return v;
}

void gen_ray_triangle(RayWriter& w) {
  auto one = [](Case v) { return v.empty() ? std::vector<Case>{} : std::vector<Case>{v}; };

  w.section("random", "triangles in [-1,1]^3, origins in [-4,4]^3", "01", "012");
  tri_block(w, "random directions", 60, [&](Rng& r) { return one(tri_random(r, false)); });
  tri_block(w, "aimed at v0 + w1 (v1 - v0) + w2 (v2 - v0), w in [-0.1, 1.1]", 60,
            [&](Rng& r) { return one(tri_random(r, true)); });

  w.section("mesh-edges",
            "5x5 grids of lattice points, squares split by a diagonal; a ray exactly through a point k/24 along an "
            "interior edge (the midpoint half the time), against both triangles sharing the edge",
            "1", "1");
  tri_block(w, "axis-aligned plane, squares of side 2^k", 50, [](Rng& r) { return mesh_rays(r, false, false); });
  tri_block(w, "tilted plane (integer edge vectors)", 50, [](Rng& r) { return mesh_rays(r, true, false); });

  w.section("mesh-vertices", "a ray exactly through an interior vertex, against all six triangles sharing it", "1",
            "1");
  tri_block(w, "axis-aligned plane", 54, [](Rng& r) { return mesh_rays(r, false, true); });
  tri_block(w, "tilted plane", 54, [](Rng& r) { return mesh_rays(r, true, true); });

  w.section("near-edge",
            "the mesh rays through a shared edge point or vertex moved by 1 ulp in one coordinate (in the plane or "
            "off it), against every triangle sharing it",
            "01", "01");
  tri_block(w, "edge points, axis-aligned plane", 50, [](Rng& r) { return mesh_rays_moved(r, false, false); });
  tri_block(w, "edge points, tilted plane", 50, [](Rng& r) { return mesh_rays_moved(r, true, false); });
  tri_block(w, "vertices, both planes", 54, [](Rng& r) { return mesh_rays_moved(r, r.chance(50), true); });

  w.section("coplanar", "lattice triangles, origin and direction exactly in their plane: hit 2 or 0", "02", "02");
  tri_block(w, "random origin and direction in the plane", 60, [&](Rng& r) { return one(coplanar_case(r, 0)); });
  tri_block(w, "through a vertex, along an edge's line, from inside or the boundary, pointing away from a vertex", 60,
            [&](Rng& r) { return one(coplanar_case(r, int(r.range(1, 4)))); });

  w.section("origin-on", "origin exactly in the closed triangle (inside, on an edge, at a vertex): t = 0", "1", "1");
  tri_block(w, "lattice triangles, random directions", 60, [&](Rng& r) {
    LatticeTri T(r);
    return one(tri_case(r, lattice3(T.bary(r, int(r.range(0, 2))), T.e), uniform3(r, 0), T.tri()));
  }, "1");

  w.section("origin-near", "the same with the origin moved by 1 ulp in one coordinate: tiny t, or just behind", "01",
            "01");
  tri_block(w, "lattice triangles, random directions", 60, [&](Rng& r) {
    LatticeTri T(r);
    P3 o = lattice3(T.bary(r, int(r.range(0, 2))), T.e);
    double& c = o[r.next() % 3];
    c = step_ulps(c, r.sign());
    return one(tri_case(r, o, uniform3(r, 0), T.tri()));
  }, "01");

  w.section("pointing-away", "the line meets the closed triangle at t = -S < 0: hit 0", "0", "0");
  tri_block(w, "o = X + S D, d = D, X inside, on an edge or at a vertex", 50, [&](Rng& r) {
    LatticeTri T(r);
    I3 X = T.bary(r, int(r.range(0, 2))), D = transversal(r, T.N, 20);
    return one(tri_case(r, lattice3(add3(X, mul3(D, r.range(1, 1 << 20))), T.e), lattice3(D, int(r.range(-6, 6))),
                        T.tri()));
  });

  w.section("parallel", "direction in the triangle's plane, origin off it (by lattice steps or by 1 ulp): hit 0", "0",
            "0");
  tri_block(w, "o = in-plane point + k N or moved by 1 ulp", 50, [&](Rng& r) {
    LatticeTri T(r);
    I3 X = T.bary(r, int(r.range(0, 2)));
    P3 o;
    if (r.chance(50)) {
      int64_t k;
      do k = r.range(-3, 3);
      while (k == 0);
      o = lattice3(add3(X, mul3(T.N, k)), T.e);
    } else {
      o = lattice3(X, T.e);
      double& c = o[r.next() % 3];
      c = step_ulps(c, r.sign());
    }
    Case v = tri_case(r, o, lattice3(T.in_plane_dir(r), int(r.range(-6, 6))), T.tri());
    QV n = qcross(qsub(qv3(v, 9), qv3(v, 6)), qsub(qv3(v, 12), qv3(v, 6)));
    if (sgn(qdot(n, qsub(qv3(v, 0), qv3(v, 6)))) == 0) return std::vector<Case>{};  // still in the plane
    return one(v);
  });

  w.section("degenerate",
            "collinear vertices (distinct, a repeated vertex, all equal, or (x, x, x 2^k)): the triangle is a "
            "segment or a point; touching it is hit 2",
            "02", "02");
  tri_block(w, "random rays near the segment", 50, [&](Rng& r) { return one(degenerate_tri(r, false)); });
  tri_block(w, "rays exactly through a lattice point of the segment", 50,
            [&](Rng& r) { return one(degenerate_tri(r, true)); });

  w.section("far-scaled",
            "origins 1e6..1e8 from a unit triangle; cases scaled exactly by 2^k (everything, or all but d)", "01",
            "012");
  tri_block(w, "far origin aimed at w in [-0.05, 1.05] (in and near the triangle), d = aim - o or unit", 60,
            [&](Rng& r) {
              Tri t = {uniform3(r, 0), uniform3(r, 0), uniform3(r, 0)};
              const double Ls[3] = {1e6, 1e7, 1e8};
              P3 o = pmul(unit_dir(r), Ls[r.next() % 3]);
              double w1 = -0.05 + 1.1 * r.unit(), w2 = -0.05 + 1.1 * r.unit();
              P3 d = psub(padd(t[0], padd(pmul(psub(t[1], t[0]), w1), pmul(psub(t[2], t[0]), w2))), o);
              if (r.chance(50)) d = pnormalize(d);
              return one(tri_case(r, o, d, t));
            });
  tri_block(w, "random, mesh, coplanar and origin-on cases scaled by 2^k, k in {100, 400, 900}", 60, [&](Rng& r) {
    static const int ks[3] = {100, 400, 900};
    return one(scaled_tri(r, ks[r.next() % 3]));
  });
  tri_block(w, "the same scaled by 2^-k", 60, [&](Rng& r) {
    static const int ks[3] = {100, 400, 900};
    return one(scaled_tri(r, -ks[r.next() % 3]));
  });
}

const char* const kRayHeaderQuad =
    "# The polynomial in t has exact rational coefficients; n comes from the exact sign of its\n"
    "# discriminant (and its degree). Roots are rounded to the nearest binary64 (ties to even):\n"
    "# rational roots by MPFR's correctly rounded conversion, irrational ones from a 320-bit MPFR\n"
    "# value proved correctly rounded by exact rational signs of the polynomial at the midpoints\n"
    "# to the neighbouring doubles. Every root is a normal double or exactly 0; cases whose two\n"
    "# distinct roots round to the same double are left out (the format promises t0 < t1).\n";

// Writes <outdir>/<kind>.txt: the header, then the cases `gen` emits.
void write_ray_file(const std::string& outdir, const std::string& kind, const std::string& header,
                    void (*gen)(RayWriter&)) {
  RayWriter w(kind, header);
  gen(w);
  w.finish(outdir + "/" + kind + ".txt");
}

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

void gen_ray_quadric_files(const std::string& outdir) {
  write_ray_file(outdir, "ray_quadric",
                 "# Line: ox oy oz dx dy dz A B C D E F G H I J n [t0 [t1]]; the line o + t d against\n"
                 "# A x^2 + B y^2 + C z^2 + D xy + E xz + F yz + G x + H y + I z + J = 0. Exactly n roots\n"
                 "# follow (one for a double root or degree one); n = inf: the polynomial is zero.\n" +
                     std::string(kRayHeaderQuad),
                 gen_ray_quadric);
}

void gen_ray_triangle_files(const std::string& outdir) {
  write_ray_file(outdir, "ray_triangle",
                 "# Line: ox oy oz dx dy dz v0x v0y v0z v1x v1y v1z v2x v2y v2z hit [t]; the ray o + t d,\n"
                 "# t >= 0, against the closed triangle. hit 1: one common point, t its exact parameter\n"
                 "# rounded to nearest (MPFR, correctly rounded); hit 2: the ray lies in the triangle's\n"
                 "# plane and touches it; 0: no common point. Epeck's do_intersect(Ray_3, Triangle_3),\n"
                 "# checked against the rational kernel and a signed-volume (or in-plane edge) test; t\n"
                 "# checked against the rational kernel's intersection point. A degenerate triangle\n"
                 "# (collinear vertices) is the segment between its farthest vertices (or a point): every\n"
                 "# line through it lies in a plane containing it, so touching it is hit 2.\n",
                 gen_ray_triangle);
  std::fprintf(stderr,
               "ray_triangle: Epick's do_intersect(Ray_3(o, d), Triangle_3) (o + d rounded) is wrong on %d of %d "
               "non-degenerate cases; on %d more, o + d rounds to o\n",
               g_epick_tri.wrong, g_epick_tri.checked, g_epick_tri.degenerate);
}

struct KindEntry {
  const char* name;
  // Writes <OUTDIR>/<name>.txt ...
  void (*generate)(Writer&);
  // ... or, for a kind with several files, writes <OUTDIR>/<name>-<set>.txt
  // itself.
  void (*generate_files)(const std::string& outdir);
};

// One row per fixture kind.
const KindEntry KINDS[] = {
    {"orient2d", gen_orient2d, nullptr},
    {"orient3d", gen_orient3d, nullptr},
    {"plane_side", gen_plane_side, nullptr},
    {"nearest", nullptr, gen_nearest_files},
    {"ray_sphere", nullptr, gen_ray_sphere_files},
    {"ray_cylinder", nullptr, gen_ray_cylinder_files},
    {"ray_quadric", nullptr, gen_ray_quadric_files},
    {"ray_triangle", nullptr, gen_ray_triangle_files},
};

}  // namespace

int main(int argc, char** argv) {
  if (argc < 2) die("usage: generate OUTDIR [KIND...]");
  check_conventions();
  check_root_rounding();
  std::string outdir = argv[1];
  for (int i = 2; i < argc; ++i) {
    bool known = false;
    for (const KindEntry& k : KINDS) known |= std::strcmp(argv[i], k.name) == 0;
    if (!known) die("unknown kind %s", argv[i]);
  }
  for (const KindEntry& k : KINDS) {
    bool selected = argc == 2;
    for (int i = 2; i < argc; ++i) selected |= std::strcmp(argv[i], k.name) == 0;
    if (!selected) continue;
    if (k.generate_files) {
      k.generate_files(outdir);
      continue;
    }
    Writer w(outdir + "/" + k.name + ".txt", k.name);
    k.generate(w);
    w.finish();
  }
  return 0;
}
