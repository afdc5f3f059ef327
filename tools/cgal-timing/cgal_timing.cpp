// Times CGAL's Exact_predicates_inexact_constructions_kernel predicates on
// the cases the exactray report exported (`--export-inputs DIR`), the way
// the report timed exactray, checks every answer against exactray's, and
// prints the report's table with a CGAL column (README.md beside this file).
//
//   cgal-timing DIR [--only family,family...]
//
// DIR holds what benches/src/bin/report/export.rs writes: manifest.txt (how the
// report timed, and the classes), <family>-<inputs>.f64 (cases),
// <family>-<inputs>.sign (exactray's answers) and times.txt (the report's
// ns per case).

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

namespace {

using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using P2 = K::Point_2;
using P3 = K::Point_3;
using Clock = std::chrono::steady_clock;

[[noreturn]] void die(const std::string& msg) {
  std::fprintf(stderr, "cgal-timing: %s\n", msg.c_str());
  std::exit(1);
}

// What the report's `black_box` does: the compiler must assume the value is
// read (a result) or may have changed (a case's address), so it neither
// drops a call nor hoists one out of the repetition loop.
template <class T>
inline void keep(const T& value) {
  asm volatile("" : : "r,m"(value) : "memory");
}
template <class T>
inline void launder(T*& ptr) {
  asm volatile("" : "+r"(ptr) : : "memory");
}

// How the report timed (manifest.txt's `timing` line).
struct Timing {
  size_t working_set = 0;
  size_t reps = 0;
  double min_loop_s = 0;
};

struct ClassEntry {
  std::string family, inputs;
  size_t cases = 0, coords = 0;
};

std::vector<char> read_file(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) die("cannot read " + path);
  return std::vector<char>(std::istreambuf_iterator<char>(in), {});
}

template <class P>
P point_at(const double* c);
template <>
P2 point_at<P2>(const double* c) {
  return P2(c[0], c[1]);
}
template <>
P3 point_at<P3>(const double* c) {
  return P3(c[0], c[1], c[2]);
}

// One predicate family: its point type, points per case and CGAL's answer
// in `docs/fixture-format.md`'s sign conventions (which are CGAL's own).
struct Orient2d {
  using P = P2;
  static constexpr int N = 3;
  static int answer(const P* p) { return CGAL::orientation(p[0], p[1], p[2]); }
};
struct Orient3d {
  using P = P3;
  static constexpr int N = 4;
  static int answer(const P* p) { return CGAL::orientation(p[0], p[1], p[2], p[3]); }
};
struct Incircle {
  using P = P2;
  static constexpr int N = 4;
  static int answer(const P* p) { return CGAL::side_of_oriented_circle(p[0], p[1], p[2], p[3]); }
};
struct Insphere {
  using P = P3;
  static constexpr int N = 5;
  static int answer(const P* p) {
    return CGAL::side_of_oriented_sphere(p[0], p[1], p[2], p[3], p[4]);
  }
};
// Where p and q lie against the plane of x0 x1 x2, as a user of CGAL's
// predicates would ask it: two orientations (the report's peers do the same).
struct PlaneSide {
  using P = P3;
  static constexpr int N = 5;
  static int answer(const P* p) {
    return int(CGAL::orientation(p[0], p[1], p[2], p[3])) *
           int(CGAL::orientation(p[0], p[1], p[2], p[4]));
  }
};

// Answers the first `count` cases `iters` times; the elapsed seconds.
template <class F>
double run_loop(const std::vector<typename F::P>& pts, size_t count, uint64_t iters) {
  auto start = Clock::now();
  for (uint64_t it = 0; it < iters; ++it) {
    for (size_t i = 0; i < count; ++i) {
      const typename F::P* p = pts.data() + i * F::N;
      launder(p);
      keep(F::answer(p));
    }
  }
  return std::chrono::duration<double>(Clock::now() - start).count();
}

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  size_t n = v.size();
  return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

// The report's `time_methods` for one method: warm up and size the loop to
// last at least `min_loop`, then the median of `reps` loops, in ns per case.
template <class F>
double time_class(const std::vector<typename F::P>& pts, size_t count, const Timing& t) {
  uint64_t n = 1, iters;
  for (;;) {
    double s = run_loop<F>(pts, count, n);
    if (s >= t.min_loop_s / 4) {
      double per = s / double(n);
      iters = std::max<uint64_t>(1, uint64_t(std::ceil(t.min_loop_s / per)));
      break;
    }
    n *= 4;
  }
  std::vector<double> samples;
  for (size_t r = 0; r < t.reps; ++r)
    samples.push_back(run_loop<F>(pts, count, iters) * 1e9 / (double(iters) * double(count)));
  return median(samples);
}

struct Result {
  std::string family, inputs;
  size_t cases = 0, mismatches = 0;
  double cgal_ns = 0;
};

// Reads one class, checks CGAL's answer on every case against exactray's,
// and times CGAL as the report timed exactray.
template <class F>
Result measure(const std::string& dir, const ClassEntry& c, const Timing& t) {
  const std::string stem = dir + "/" + c.family + "-" + c.inputs;
  std::vector<char> raw = read_file(stem + ".f64");
  std::vector<char> signs = read_file(stem + ".sign");
  const size_t dim = sizeof(typename F::P) / sizeof(double);
  if (c.coords != F::N * dim || raw.size() != c.cases * c.coords * sizeof(double) ||
      signs.size() != c.cases)
    die(stem + ": sizes do not match manifest.txt");
  std::vector<double> coords(c.cases * c.coords);
  std::memcpy(coords.data(), raw.data(), raw.size());
  std::vector<typename F::P> pts;
  pts.reserve(c.cases * F::N);
  for (size_t i = 0; i < c.cases * F::N; ++i)
    pts.push_back(point_at<typename F::P>(&coords[i * dim]));

  Result r{c.family, c.inputs, c.cases, 0, 0};
  for (size_t i = 0; i < c.cases; ++i) {
    int mine = F::answer(&pts[i * F::N]);
    int theirs = static_cast<signed char>(signs[i]);
    if (mine == theirs) continue;
    if (++r.mismatches <= 5) {
      std::fprintf(stderr, "mismatch %s %s case %zu: CGAL %d, exactray %d:", c.family.c_str(),
                   c.inputs.c_str(), i, mine, theirs);
      for (size_t k = 0; k < c.coords; ++k) std::fprintf(stderr, " %.17g", coords[i * c.coords + k]);
      std::fputc('\n', stderr);
    }
  }
  r.cgal_ns = time_class<F>(pts, std::min(t.working_set, c.cases), t);
  return r;
}

std::string ns(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, v < 10 ? "%.2f" : v < 1000 ? "%.1f" : "%.0f", v);
  return buf;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 2) die("usage: cgal-timing DIR [--only family,family...]");
  const std::string dir = argv[1];
  std::vector<std::string> only;
  for (int i = 2; i < argc; ++i) {
    if (std::string(argv[i]) == "--only" && i + 1 < argc) {
      std::stringstream list(argv[++i]);
      for (std::string f; std::getline(list, f, ',');) only.push_back(f);
    } else {
      die(std::string("unknown argument ") + argv[i]);
    }
  }

  Timing timing;
  std::vector<ClassEntry> classes;
  {
    std::ifstream m(dir + "/manifest.txt");
    if (!m) die("cannot read " + dir + "/manifest.txt (run the report with --export-inputs " + dir + ")");
    for (std::string line; std::getline(m, line);) {
      if (line.empty() || line[0] == '#') continue;
      std::istringstream in(line);
      std::string first;
      in >> first;
      if (first == "timing") {
        double min_loop_ns;
        in >> timing.working_set >> timing.reps >> min_loop_ns;
        timing.min_loop_s = min_loop_ns * 1e-9;
      } else {
        ClassEntry c;
        c.family = first;
        in >> c.inputs >> c.cases >> c.coords;
        if (only.empty() || std::count(only.begin(), only.end(), c.family)) classes.push_back(c);
      }
      if (!in) die("cannot parse manifest line: " + line);
    }
  }
  if (timing.reps == 0) die("manifest.txt has no timing line");

  // exactray's times from the same report run.
  std::map<std::pair<std::string, std::string>, double> exactray;
  {
    std::ifstream in(dir + "/times.txt");
    for (std::string line; std::getline(in, line);) {
      if (line.empty() || line[0] == '#') continue;
      std::istringstream row(line);
      std::string family, inputs, method;
      double t;
      if (row >> family >> inputs >> method >> t && method == "exactray")
        exactray[{family, inputs}] = t;
    }
  }

  std::vector<Result> results;
  for (const ClassEntry& c : classes) {
    std::fprintf(stderr, "%s %s...\n", c.family.c_str(), c.inputs.c_str());
    if (c.family == "orient2d") results.push_back(measure<Orient2d>(dir, c, timing));
    else if (c.family == "orient3d") results.push_back(measure<Orient3d>(dir, c, timing));
    else if (c.family == "incircle") results.push_back(measure<Incircle>(dir, c, timing));
    else if (c.family == "insphere") results.push_back(measure<Insphere>(dir, c, timing));
    else if (c.family == "plane_side") results.push_back(measure<PlaneSide>(dir, c, timing));
    else die("unknown family " + c.family);
  }

  size_t most = 0;
  for (const ClassEntry& c : classes) most = std::max(most, c.cases);
  if (timing.working_set >= most)
    std::printf("ns per case: the median of %zu loops over every case of a class (the report's timing, --stream)\n\n",
                timing.reps);
  else
    std::printf("ns per case: the median of %zu loops over the first %zu cases of a class (the report's timing)\n\n",
                timing.reps, timing.working_set);
  std::printf("| family | inputs | exactray ns | CGAL ns | exactray / CGAL | cases | answers differing |\n");
  std::printf("|---|---|---|---|---|---|---|\n");
  size_t slower = 0, differing = 0;
  for (const Result& r : results) {
    auto e = exactray.find({r.family, r.inputs});
    std::string ens = "-", ratio = "-";
    if (e != exactray.end()) {
      ens = ns(e->second);
      char buf[32];
      std::snprintf(buf, sizeof buf, "%.2fx", e->second / r.cgal_ns);
      ratio = buf;
      slower += e->second > r.cgal_ns;
    }
    differing += r.mismatches;
    std::printf("| %s | %s | %s | %s | %s | %zu | %zu |\n", r.family.c_str(), r.inputs.c_str(),
                ens.c_str(), ns(r.cgal_ns).c_str(), ratio.c_str(), r.cases, r.mismatches);
  }
  std::printf("\nexactray slower than CGAL on %zu of %zu classes; %zu answers differ.\n", slower,
              results.size(), differing);
  return differing ? 3 : 0;
}
