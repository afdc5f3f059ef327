// Shared by the ray kinds (ray_quadrics.cpp, ray_triangle.cpp): exact
// rational vectors, input constructions, exact and correctly rounded roots,
// and the writer of ray files.
#pragma once

#include "common.h"

#include <gmpxx.h>
#include <mpfr.h>

namespace fixtures {

// ---------------------------------------------------------------------------
// Ray kinds: ray_sphere, ray_cylinder, ray_cone, ray_quadric, ray_triangle.
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

inline QV qv3(const Case& v, size_t i) { return QV{Q(v[i]), Q(v[i + 1]), Q(v[i + 2])}; }
inline QV qadd(const QV& a, const QV& b) { return QV{Q(a[0] + b[0]), Q(a[1] + b[1]), Q(a[2] + b[2])}; }
inline QV qsub(const QV& a, const QV& b) { return QV{Q(a[0] - b[0]), Q(a[1] - b[1]), Q(a[2] - b[2])}; }
inline QV qmul(const QV& a, const Q& s) { return QV{Q(a[0] * s), Q(a[1] * s), Q(a[2] * s)}; }
inline Q qdot(const QV& a, const QV& b) { return Q(a[0] * b[0] + a[1] * b[1] + a[2] * b[2]); }
inline QV qcross(const QV& a, const QV& b) {
  return QV{Q(a[1] * b[2] - a[2] * b[1]), Q(a[2] * b[0] - a[0] * b[2]), Q(a[0] * b[1] - a[1] * b[0])};
}
inline bool qzero(const QV& a) { return sgn(a[0]) == 0 && sgn(a[1]) == 0 && sgn(a[2]) == 0; }

inline Q to_q(const CGAL::Exact_rational& x) { return Q(x.backend().data()); }
inline CGAL::Exact_rational Rq(double x) { return CGAL::Exact_rational(x); }

// A unit direction perpendicular to the unit vector u (up to rounding).
inline P3 perp_dir(Rng& r, const P3& u) {
  for (;;) {
    P3 w = unit_dir(r);
    P3 p = psub(w, pmul(u, pdot(w, u)));
    if (pdot(p, p) > 0.01) return pnormalize(p);
  }
}


inline I3 cross3(const I3& a, const I3& b) {
  return I3{a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
inline int64_t dot3(const I3& a, const I3& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
inline I3 mul3(const I3& a, int64_t s) { return I3{a[0] * s, a[1] * s, a[2] * s}; }
inline I3 sub3(const I3& a, const I3& b) { return I3{a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
inline bool zero3(const I3& a) { return a[0] == 0 && a[1] == 0 && a[2] == 0; }
inline I3 nonzero_bits3(Rng& r, int b) {
  I3 v;
  do v = bits3(r, b);
  while (zero3(v));
  return v;
}

// An integer vector W with |W| = N exactly (a Pythagorean quadruple, from
// x = m^2 + n^2 - p^2 - q^2, y = 2(mq + np), z = 2(nq - mp),
// N = m^2 + n^2 + p^2 + q^2), in a random order and with random signs.
inline I3 pythagorean(Rng& r, int bits, int64_t& N) {
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
inline I3 pythagorean_triple(Rng& r) {
  int64_t m = r.range(2, 12), n = r.range(1, m - 1);
  I3 t = {m * m - n * n, 2 * m * n, m * m + n * n};
  if (r.chance(50)) std::swap(t[0], t[1]);
  t[0] *= r.sign();
  t[1] *= r.sign();
  return t;
}

inline void append3(Case& v, const P3& p) { v.insert(v.end(), p.begin(), p.end()); }

// 1-3 (1-max_ulps) representable steps on one nonzero input (chosen among
// `slots`).
inline void nudge_one(Rng& r, Case& v, const std::vector<size_t>& slots, int max_ulps = 3) {
  for (;;) {
    size_t i = slots[r.next() % slots.size()];
    if (v[i] == 0) continue;
    v[i] = step_ulps(v[i], int(r.range(1, max_ulps)) * r.sign());
    return;
  }
}

// Every input of a ray case (o, d, then the shape) times 2^k exactly, or
// half the time every input but d (slots 3-5): a root t stays t, or
// becomes t 2^k.
inline void scale_case(Rng& r, Case& v, int k) {
  bool keep_d = r.chance(50);
  for (size_t i = 0; i < v.size(); ++i)
    if (!(keep_d && i >= 3 && i < 6)) {
      Case one = {v[i]};
      scale(one, k);
      v[i] = one[0];
    }
}

inline std::vector<size_t> all_slots(size_t n) {
  std::vector<size_t> s(n);
  for (size_t i = 0; i < n; ++i) s[i] = i;
  return s;
}

// ---------------------------------------------------------------------------
// Exact roots

struct Poly2 {
  Q a, b, c;  // a t^2 + b t + c
};

inline Q peval(const Poly2& p, const Q& t) { return Q((p.a * t + p.b) * t + p.c); }

struct Roots {
  int n = 0;              // distinct real roots; -1: every t is a root
  std::vector<double> t;  // the roots rounded to nearest, ascending
  bool representable = true;
};

constexpr int kMpfrBits = 320;

inline bool odd_bits(double x) {
  uint64_t u;
  std::memcpy(&u, &x, sizeof u);
  return u & 1;
}

// Roots are kept finite and normal (or exactly zero).
inline bool in_normal_range(double x) { return x == 0 || (std::fabs(x) >= 0x1p-1021 && std::fabs(x) <= 0x1p1022); }

// Proves that x is the root r rounded to nearest, ties to even, given
// cmp(y) = sign(y - r) exactly for rational y: r lies strictly between the
// midpoints from x to its neighbouring doubles, or exactly on one of them
// with x even. When r is exactly a midpoint and x is the odd neighbour, the
// even one is returned (and proved). Dies when the proof fails.
template <class Cmp>
inline double prove_nearest(double x, Cmp cmp, const char* what) {
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
inline double nearest_rational(const Q& q, bool& ok) {
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
inline void two_roots(const Poly2& p, const Q& disc, Roots& R) {
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

inline Roots solve_exact(const Poly2& p) {
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
inline void check_root_rounding() {
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

inline NaiveRoots naive_solve(double a, double b, double c) {
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
inline uint64_t ulp_distance(double x, double y) {
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

inline char category(int n) { return n < 0 ? 'i' : char('0' + n); }

// Writes the case and returns true, or returns false (writing nothing) when a
// root is not a normal double, when two distinct roots round to the same
// double (the format promises t0 < t1), or when the root count is not in
// `accept`.
inline bool emit_quad(RayWriter& w, const QuadKind& k, const Case& v, const char* accept = nullptr) {
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
inline void quad_block(RayWriter& w, const QuadKind& k, const std::string& label, int n, F make,
                const char* accept = nullptr) {
  Rng r = w.block(label);
  int made = 0;
  for (int tries = 0; made < n; ++tries) {
    if (tries > 100 * n) die("%s: block \"%s\" keeps failing", k.name, label.c_str());
    Case v = make(r);
    if (!v.empty() && emit_quad(w, k, v, accept)) ++made;
  }
}

// Writes <outdir>/<kind>.txt: the header, then the cases `gen` emits.
inline void write_ray_file(const std::string& outdir, const std::string& kind, const std::string& header,
                    void (*gen)(RayWriter&)) {
  RayWriter w(kind, header);
  gen(w);
  w.finish(outdir + "/" + kind + ".txt");
}

}  // namespace fixtures
