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
// writes its files itself: see gen_nearest_files).

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Exact_rational.h>
#include <CGAL/Simple_cartesian.h>

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
    FILE* f = std::fopen(path_.c_str(), "wb");
    if (!f) die("cannot write %s", path_.c_str());
    if (std::fwrite(out_.data(), 1, out_.size(), f) != out_.size() || std::fclose(f) != 0)
      die("cannot write %s", path_.c_str());
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
    FILE* f = std::fopen(path.c_str(), "wb");
    if (!f) die("cannot write %s", path.c_str());
    if (std::fwrite(out.data(), 1, out.size(), f) != out.size() || std::fclose(f) != 0)
      die("cannot write %s", path.c_str());
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
};

}  // namespace

int main(int argc, char** argv) {
  if (argc < 2) die("usage: generate OUTDIR [KIND...]");
  check_conventions();
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
