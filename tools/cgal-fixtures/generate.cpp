// Writes exactray's test fixtures: inputs chosen to be hard for floating
// point, with the expected answers computed by CGAL's exact kernels.
// The file format is described in docs/fixture-format.md (one case per line, `#` comments;
// a nearest file holds one point set and its queries, see NearestSet).
//
// Usage: generate OUTDIR [KIND...]   (no KIND: every kind in KINDS below)
//
// This file is the driver: the table of kinds and main. The families live in
// their own files: common.h (number types, randomness, exact IEEE helpers,
// the sign-file Writer), predicates.cpp (orient2d, orient3d, plane_side),
// implicit.cpp (orient3d_lpi, orient3d_tpi, orient2d_ssi, less_on_axis_lpi:
// predicates on constructed points, constructed with Epeck),
// nearest.cpp, ray.h (what the ray kinds share: exact roots, RayWriter),
// ray_quadrics.cpp (ray_sphere, ray_cylinder, ray_cone, ray_quadric),
// ray_triangle.cpp and ray_mesh.cpp (one mesh per file with closest-hit and
// shadow-segment queries).
//
// Determinism: the output must be byte-identical on every machine and every
// run, so the inputs come only from our own splitmix64 and from exact IEEE
// operations (+, -, * on exactly representable results, ldexp, nextafter),
// never from std:: distributions or libm functions whose results vary between
// library versions. Every block of cases gets its own generator seeded from
// its label, so editing one block leaves the others' cases unchanged.
//
// Adding a kind: write `void gen_<kind>(Writer&)`, declare it in common.h and
// add a row to KINDS (a kind with several files per run, like nearest with
// one point set per file, writes its files itself: see gen_nearest_files; so
// do the ray kinds, whose answers are root counts and roots rather than
// signs: see RayWriter).
//
// Exact arithmetic beyond CGAL: GMP rationals (gmpxx) for the polynomials in
// t of the ray kinds, MPFR for their irrational roots (proved correctly
// rounded with rationals; see prove_nearest).

#include "common.h"
#include "ray.h"

namespace fixtures {
namespace {

struct KindEntry {
  const char* name;
  // Writes <OUTDIR>/<name>.txt ...
  void (*generate)(Writer&);
  // ... or, for a kind with several files, writes <OUTDIR>/<name>-<set>.txt
  // itself.
  void (*generate_files)(const std::string& outdir);
  // The kernel the answers come from, for the file's header (Epick unless
  // named).
  const char* kernels = "Epick";
};

// One row per fixture kind.
const KindEntry KINDS[] = {
    {"orient2d", gen_orient2d, nullptr},
    {"orient3d", gen_orient3d, nullptr},
    {"plane_side", gen_plane_side, nullptr},
    {"incircle", gen_incircle, nullptr},
    {"insphere", gen_insphere, nullptr},
    {"orient3d_lpi", gen_orient3d_lpi, nullptr, "Epeck"},
    {"orient3d_tpi", gen_orient3d_tpi, nullptr, "Epeck"},
    {"orient2d_ssi", gen_orient2d_ssi, nullptr, "Epeck"},
    {"less_on_axis_lpi", gen_less_on_axis_lpi, nullptr, "Epeck"},
    {"nearest", nullptr, gen_nearest_files},
    {"ray_sphere", nullptr, gen_ray_sphere_files},
    {"ray_cylinder", nullptr, gen_ray_cylinder_files},
    {"ray_cone", nullptr, gen_ray_cone_files},
    {"ray_quadric", nullptr, gen_ray_quadric_files},
    {"ray_triangle", nullptr, gen_ray_triangle_files},
    {"ray_mesh", nullptr, gen_ray_mesh_files},
    {"mesh_side", nullptr, gen_mesh_side_files, "Epeck"},
    {"mesh_closest", nullptr, gen_mesh_closest_files, "Epeck"},
};

}  // namespace
}  // namespace fixtures

int main(int argc, char** argv) {
  using namespace fixtures;
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
    Writer w(outdir + "/" + k.name + ".txt", k.name, k.kernels);
    k.generate(w);
    w.finish();
  }
  return 0;
}
