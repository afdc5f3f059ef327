// Shared by every fixture family of the generator (see generate.cpp): the
// kernels and number types, failing loudly, the fixed-seed randomness, exact
// IEEE helpers, the writer of one-case-per-line sign files, the `%.17g`
// formatting every file uses, and the families' entry points. Header-only
// (`inline`), so each family is one translation unit of its own.
#pragma once

#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
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
#include <tuple>
#include <string>
#include <vector>

namespace fixtures {

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

[[noreturn]] inline void die(const char* fmt, ...) {
  va_list ap;
  va_start(ap, fmt);
  std::fputs("generate: ", stderr);
  std::vfprintf(stderr, fmt, ap);
  std::fputc('\n', stderr);
  va_end(ap);
  std::exit(1);
}

// Writes a fixture file whole, or dies.
inline void write_file(const std::string& path, const std::string& data) {
  FILE* f = std::fopen(path.c_str(), "wb");
  if (!f) die("cannot write %s", path.c_str());
  if (std::fwrite(data.data(), 1, data.size(), f) != data.size() || std::fclose(f) != 0)
    die("cannot write %s", path.c_str());
}

// ---------------------------------------------------------------------------
// Randomness

inline uint64_t splitmix64(uint64_t& state) {
  uint64_t z = (state += 0x9e3779b97f4a7c15ULL);
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
  return z ^ (z >> 31);
}

inline uint64_t fnv1a(const std::string& s) {
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
inline double step_ulps(double x, int ulps) {
  for (int i = 0; i < std::abs(ulps); ++i) x = std::nextafter(x, ulps > 0 ? INFINITY : -INFINITY);
  return x;
}

// Exponent of the lowest set bit of x != 0 (x = odd * 2^result).
inline int low_bit_exp(double x) {
  int e;
  double m = std::frexp(std::fabs(x), &e);  // x = m 2^e, m in [0.5, 1), exact
  uint64_t mant = uint64_t(std::ldexp(m, 53));
  return e - 53 + __builtin_ctzll(mant);
}

// The largest k <= want such that every value times 2^-k is exact (no bit
// falls below 2^-1074).
inline int clip_down_shift(const Case& v, int want) {
  for (double x : v)
    if (x != 0) want = std::min(want, low_bit_exp(x) + 1074);
  return want;
}

// The largest k <= want such that every value times 2^k stays finite.
inline int clip_up_shift(const Case& v, int want) {
  for (double x : v)
    if (x != 0) want = std::min(want, 1023 - std::ilogb(x));
  return want;
}

inline int max_exp(const Case& v) {
  int e = INT32_MIN;
  for (double x : v)
    if (x != 0) e = std::max(e, std::ilogb(x));
  return e;
}

inline void scale(Case& v, int k) {
  for (double& x : v) {
    double y = std::ldexp(x, k);
    if (!std::isfinite(y) || std::ldexp(y, -k) != x) die("inexact scaling of %.17g by 2^%d", x, k);
    x = y;
  }
}

// Scales the case by a power of two so that its largest coordinate lands near
// 2^target, as far as exactness allows; exact scaling keeps the sign.
inline void scale_towards(Case& v, int target) {
  int top = max_exp(v);
  if (top == INT32_MIN) return;
  int k = target - top;
  k = k < 0 ? -clip_down_shift(v, -k) : clip_up_shift(v, k);
  scale(v, k);
}

// An integer lattice coordinate v times 2^e; the lattice constructions below
// keep |v| < 2^53 so that this is exact.
inline double lattice(int64_t v, int e) {
  const int64_t lim = int64_t(1) << 53;
  if (v >= lim || v <= -lim) die("lattice value %" PRId64 " needs more than 53 bits", v);
  double x = std::ldexp(double(v), e);
  if (!std::isfinite(x) || std::ldexp(x, -e) != double(v)) die("lattice value %" PRId64 " * 2^%d is inexact", v, e);
  return x;
}

// A double with arbitrary low-order bits, of moderate size.
inline double arbitrary(Rng& r) { return std::ldexp(r.sym(), int(r.range(-3, 3))); }

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

// ---------------------------------------------------------------------------
// Output

// One fixture file. Sections group blocks of cases; each section states which
// signs it must contain (so a construction that silently stopped producing,
// say, zeros is caught) and which it may contain (a degenerate section that
// produced a nonzero sign means the construction was not exact).
class Writer {
 public:
  // `kernels` names the CGAL kernel the answers come from.
  Writer(std::string path, std::string kind, const std::string& kernels = "Epick")
      : path_(std::move(path)), kind_(std::move(kind)) {
    out_ += "# " + kind_ + " fixtures: expected answers from CGAL's exact kernels (" + kernels + ", checked\n";
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
// Coordinates

using I3 = std::array<int64_t, 3>;

// `%.17g`, checked to read back to the same bits.
inline std::string format_coord(double x) {
  if (!std::isfinite(x)) die("non-finite coordinate");
  char buf[40];
  std::snprintf(buf, sizeof buf, "%.17g", x);
  double back = std::strtod(buf, nullptr);
  if (std::memcmp(&back, &x, sizeof x) != 0) die("%s does not round-trip", buf);
  return buf;
}

inline P3 lattice3(const I3& v, const std::array<int, 3>& e) {
  return P3{lattice(v[0], e[0]), lattice(v[1], e[1]), lattice(v[2], e[2])};
}
inline P3 lattice3(const I3& v, int e) { return lattice3(v, {e, e, e}); }

inline I3 bits3(Rng& r, int b) { return I3{r.bits(b), r.bits(b), r.bits(b)}; }
inline I3 add3(const I3& a, const I3& b) { return I3{a[0] + b[0], a[1] + b[1], a[2] + b[2]}; }

// Coordinates uniform in [-2^e, 2^e), 53 random bits each.
inline P3 uniform3(Rng& r, int e) {
  return P3{std::ldexp(r.sym(), e), std::ldexp(r.sym(), e), std::ldexp(r.sym(), e)};
}

// Coordinates uniform * 2^e with e drawn once for the point from [lo, hi].
inline P3 uniform3_in(Rng& r, int lo, int hi) { return uniform3(r, int(r.range(lo, hi))); }

template <class T>
inline void shuffle(Rng& r, std::vector<T>& v) {
  for (size_t i = v.size(); i > 1; --i) std::swap(v[i - 1], v[r.next() % i]);
}

// Double-precision vector helpers, for building inputs (rounding allowed
// there: the answers are computed from whatever doubles result).
inline P3 padd(const P3& a, const P3& b) { return P3{a[0] + b[0], a[1] + b[1], a[2] + b[2]}; }
inline P3 psub(const P3& a, const P3& b) { return P3{a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
inline P3 pmul(const P3& a, double s) { return P3{a[0] * s, a[1] * s, a[2] * s}; }
inline double pdot(const P3& a, const P3& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
inline P3 pcross(const P3& a, const P3& b) {
  return P3{a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
inline P3 pnormalize(const P3& a) { return pmul(a, 1.0 / std::sqrt(pdot(a, a))); }

// A direction uniform on the unit sphere (rejection sampling; sqrt and
// division are correctly rounded, so this is deterministic).
inline P3 unit_dir(Rng& r) {
  for (;;) {
    P3 v = uniform3(r, 0);
    double n2 = pdot(v, v);
    if (n2 > 0.01 && n2 <= 1) return pnormalize(v);
  }
}

// A non-power-of-two factor in [2^lo, 2^(hi+1)).
inline double length_factor(Rng& r, int lo, int hi) { return std::ldexp(1.0 + r.unit(), int(r.range(lo, hi))); }

// ---------------------------------------------------------------------------
// The fixture families, one translation unit each.

// predicates.cpp: one file per kind, one case per line.
void check_conventions();
void gen_orient2d(Writer& w);
void gen_orient3d(Writer& w);
void gen_plane_side(Writer& w);
void gen_incircle(Writer& w);
void gen_insphere(Writer& w);

// implicit.cpp: predicates on constructed points, one case per line; the
// points constructed with Epeck (exact constructions).
void gen_orient3d_lpi(Writer& w);
void gen_orient3d_tpi(Writer& w);
void gen_orient2d_ssi(Writer& w);
void gen_less_on_axis_lpi(Writer& w);

// nearest.cpp: nearest-<set>.txt, one point set per file.
void gen_nearest_files(const std::string& outdir);

// ray_quadrics.cpp, ray_triangle.cpp: ray_<kind>.txt (ray.h: their shared
// machinery, with check_root_rounding).
void gen_ray_sphere_files(const std::string& outdir);
void gen_ray_cylinder_files(const std::string& outdir);
void gen_ray_cone_files(const std::string& outdir);
void gen_ray_quadric_files(const std::string& outdir);
void gen_ray_triangle_files(const std::string& outdir);

// ray_mesh.cpp: ray_mesh-<mesh>.txt, one mesh per file; mesh_points.cpp:
// mesh_side-<mesh>.txt and mesh_closest-<mesh>.txt.
void gen_ray_mesh_files(const std::string& outdir);
void gen_mesh_side_files(const std::string& outdir);
void gen_mesh_closest_files(const std::string& outdir);

}  // namespace fixtures
