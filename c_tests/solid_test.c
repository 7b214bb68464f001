/* The 3D model through the C ABI (tfem_solid_*): the contact patch test
 * of two stacked cubes against its exact solution, and the refusals.
 *
 * Two unit cubes, body 1 on z in [-1, 0] and body 2 on z in [0, 1], each
 * meshed by N x N x N cells of Kuhn's six tetrahedra (the mesh of
 * tfem::fem::solid_mesh::Brick::uniform, built here in C), sides tagged
 * 1..6 and 11..16 (x = min, x = max, y = min, y = max, z = min, z = max).
 * The lower cube stands on rollers (u_z = 0 on its bottom), both are held
 * on rollers on x = 0 and y = 0, and a pressure p on the upper cube's top
 * presses it on the lower one through a frictionless contact pair (tag 6,
 * the lower top, planar side a; tag 15, the upper bottom). The exact
 * solution is uniaxial stress: sigma_zz = -p in every tetrahedron, every
 * other component 0, strains -p/E and nu p/E, displacements linear; the
 * whole interface is in contact (area 1) and the rollers carry p A. */

#include <math.h>
#include <stdio.h>
#include <string.h>

#include "tfem.h"

static int passed = 0, failed = 0;

#define CHECK(cond)                                          \
  do {                                                       \
    if (cond) {                                              \
      ++passed;                                              \
    } else {                                                 \
      ++failed;                                              \
      printf("FAIL %s:%d: %s\n", __FILE__, __LINE__, #cond); \
    }                                                        \
  } while (0)

#define OK(call) CHECK((call) == TFEM_STATUS_OK)

/* The call must fail with `expected` and its message contain `needle`. */
static void expect_error(tfem_solid_model *m, tfem_status got, tfem_status expected,
                         const char *needle, int line) {
  char msg[512] = "";
  if (m != NULL)
    tfem_solid_last_error(m, msg, sizeof msg);
  else
    tfem_last_error(NULL, msg, sizeof msg);
  if (got == expected && strstr(msg, needle) != NULL) {
    ++passed;
  } else {
    ++failed;
    printf("FAIL line %d: status %d (expected %d), message \"%s\" (expected \"%s\")\n", line,
           (int)got, (int)expected, msg, needle);
  }
}
#define EXPECT_ERROR(m, call, status, needle) expect_error(m, call, status, needle, __LINE__)

enum { N = 2, NP = N + 1, NODES_PER = NP * NP * NP, N_NODES = 2 * NODES_PER };
enum { TETS_PER = 6 * N * N * N, N_TETS = 2 * TETS_PER };
enum { N_FACES = 2 * 6 * 2 * N * N, N_CONTACT = 3 * 2 * N * N };
static const double P = 0.1, E = 1.0, NU = 0.25, TOL = 1e-9;

static double xyz[3 * N_NODES];
static int tets[4 * N_TETS], body[N_TETS], faces[3 * N_FACES], tags[N_FACES];
static int n_tets = 0, n_faces = 0;

/* Node (i, j, k) of the cube starting at node `first`. */
static int id(int first, int i, int j, int k) { return first + i + NP * (j + NP * k); }

/* The grid coordinate `axis` of node `v` of the cube starting at `first`. */
static int grid(int first, int v, int axis) {
  int r = v - first;
  int g[3] = {r % NP, (r / NP) % NP, r / (NP * NP)};
  return g[axis];
}

/* A unit cube from z0 to z0 + 1, body `b`, its sides tagged tag0 + 1 ...
 * tag0 + 6, from node `first`: Kuhn's six tetrahedra per cell (paths from
 * corner (0,0,0) to (1,1,1) by unit steps in every order, the odd orders
 * numbered backwards to keep J > 0), and every face of them on a side. */
static void cube(int first, double z0, int b, int tag0) {
  static const int orders[6][3] = {{0, 1, 2}, {1, 2, 0}, {2, 0, 1},
                                   {0, 2, 1}, {2, 1, 0}, {1, 0, 2}};
  for (int k = 0; k < NP; ++k)
    for (int j = 0; j < NP; ++j)
      for (int i = 0; i < NP; ++i) {
        int v = id(first, i, j, k);
        xyz[3 * v] = (double)i / N;
        xyz[3 * v + 1] = (double)j / N;
        xyz[3 * v + 2] = z0 + (double)k / N;
      }
  int start = n_tets;
  for (int k = 0; k < N; ++k)
    for (int j = 0; j < N; ++j)
      for (int i = 0; i < N; ++i)
        for (int o = 0; o < 6; ++o) {
          int p[3] = {0, 0, 0}, *t = &tets[4 * n_tets];
          t[0] = id(first, i, j, k);
          for (int s = 0; s < 3; ++s) {
            p[orders[o][s]] = 1;
            t[s + 1] = id(first, i + p[0], j + p[1], k + p[2]);
          }
          if (o >= 3) {
            int swap = t[2];
            t[2] = t[3];
            t[3] = swap;
          }
          body[n_tets++] = b;
        }
  for (int e = start; e < n_tets; ++e)
    for (int skip = 0; skip < 4; ++skip) {
      int f[3], n = 0;
      for (int q = 0; q < 4; ++q)
        if (q != skip) f[n++] = tets[4 * e + q];
      for (int axis = 0; axis < 3; ++axis)
        for (int end = 0; end < 2; ++end) {
          int at = end ? N : 0, on = 1;
          for (int q = 0; q < 3; ++q) on = on && grid(first, f[q], axis) == at;
          if (on) {
            memcpy(&faces[3 * n_faces], f, sizeof f);
            tags[n_faces++] = tag0 + 1 + 2 * axis + end;
          }
        }
    }
}

/* The scene up to its solve: mesh, faces, materials (body 2's only if
 * `both`), supports, load and contact pair. */
static tfem_solid_model *scene(int both) {
  tfem_solid_model *m = tfem_solid_create();
  CHECK(m != NULL);
  OK(tfem_solid_set_mesh(m, N_NODES, xyz, N_TETS, tets, body, 0));
  OK(tfem_solid_set_boundary_faces(m, N_FACES, faces, tags));
  OK(tfem_solid_set_material(m, 1, E, NU));
  if (both) OK(tfem_solid_set_material(m, 2, E, NU));
  OK(tfem_solid_fix_faces(m, 5, TFEM_AXIS_Z, 0.0));
  OK(tfem_solid_fix_faces(m, 1, TFEM_AXIS_X, 0.0));
  OK(tfem_solid_fix_faces(m, 11, TFEM_AXIS_X, 0.0));
  OK(tfem_solid_fix_faces(m, 3, TFEM_AXIS_Y, 0.0));
  OK(tfem_solid_fix_faces(m, 13, TFEM_AXIS_Y, 0.0));
  OK(tfem_solid_add_pressure(m, 16, P));
  int pair = -1;
  OK(tfem_solid_add_contact_pair(m, 6, 15, &pair));
  CHECK(pair == 0);
  return m;
}

static double u_first[3 * N_NODES];

/* Every result of the solved scene against the exact solution. */
static void check_exact(tfem_solid_model *m) {
  int nn = -1, nt = -1, nc = -1;
  OK(tfem_solid_get_sizes(m, &nn, &nt, &nc));
  CHECK(nn == N_NODES && nt == N_TETS && nc == N_CONTACT);

  int active[N_CONTACT];
  OK(tfem_solid_get_contact_active(m, active, N_CONTACT));
  int all = 1;
  for (int k = 0; k < N_CONTACT; ++k) all = all && active[k] == 1;
  CHECK(all);
  int ct[4 * N_CONTACT];
  OK(tfem_solid_get_contact_tetrahedra(m, ct, 4 * N_CONTACT));
  int in_range = 1;
  for (int k = 0; k < 4 * N_CONTACT; ++k) in_range = in_range && ct[k] >= 0 && ct[k] < N_NODES;
  CHECK(in_range);
  double area = -1, pair_area = -1;
  OK(tfem_solid_get_contact_area(m, &area));
  OK(tfem_solid_get_contact_pair_area(m, 0, &pair_area));
  CHECK(fabs(area - 1.0) < 1e-12 && fabs(pair_area - 1.0) < 1e-12);

  /* Uniaxial stress and its strains in every tetrahedron. */
  static double s[6 * N_TETS], e[6 * N_TETS];
  OK(tfem_solid_get_element_stresses(m, s, 6 * N_TETS));
  OK(tfem_solid_get_element_strains(m, e, 6 * N_TETS));
  double ws = 0, we = 0;
  for (int t = 0; t < N_TETS; ++t)
    for (int c = 0; c < 6; ++c) {
      double want_s = c == 2 ? -P : 0.0;
      double want_e = c < 2 ? NU * P / E : c == 2 ? -P / E : 0.0;
      ws = fmax(ws, fabs(s[6 * t + c] - want_s));
      we = fmax(we, fabs(e[6 * t + c] - want_e));
    }
  CHECK(ws <= TOL * P);
  CHECK(we <= TOL * P / E);

  /* Displacements: linear; the upper cube's u_z up to the shift the
   * contact penalty leaves at the interface. */
  static double u[3 * N_NODES];
  OK(tfem_solid_get_displacements(m, u, 3 * N_NODES));
  double shift = u[3 * NODES_PER + 2], wu = 0;
  for (int v = 0; v < N_NODES; ++v) {
    const double *x = &xyz[3 * v];
    double uz = v < NODES_PER ? -P / E * (x[2] + 1.0) : shift - P / E * x[2];
    wu = fmax(wu, fabs(u[3 * v] - NU * P / E * x[0]));
    wu = fmax(wu, fabs(u[3 * v + 1] - NU * P / E * x[1]));
    wu = fmax(wu, fabs(u[3 * v + 2] - uz));
  }
  CHECK(wu <= TOL * 2 * P / E);
  CHECK(shift <= -P / E + TOL * P / E); /* pressed onto the lower cube */
  memcpy(u_first, u, sizeof u);

  /* The rollers carry p A; the x and y reactions vanish. */
  static double r[3 * N_NODES], f[3 * N_NODES], pn[N_NODES];
  OK(tfem_solid_get_reactions(m, r, 3 * N_NODES));
  double sum[3] = {0, 0, 0}, wr = 0;
  for (int v = 0; v < N_NODES; ++v)
    for (int c = 0; c < 3; ++c) {
      sum[c] += r[3 * v + c];
      if (c < 2) wr = fmax(wr, fabs(r[3 * v + c]));
    }
  CHECK(fabs(sum[2] - P) <= 1e-12 && wr <= TOL * P);

  /* The contact forces: the pair's sum to zero, the upper cube is held up
   * by p A; the nodal pressure is p on the interface, 0 elsewhere. */
  OK(tfem_solid_get_contact_forces(m, f, 3 * N_NODES));
  double total[3] = {0, 0, 0}, upper = 0;
  for (int v = 0; v < N_NODES; ++v) {
    for (int c = 0; c < 3; ++c) total[c] += f[3 * v + c];
    if (v >= NODES_PER) upper += f[3 * v + 2];
  }
  CHECK(fabs(total[0]) + fabs(total[1]) + fabs(total[2]) <= 1e-12);
  CHECK(fabs(upper - P) <= TOL * P);
  OK(tfem_solid_get_contact_nodal_pressures(m, pn, N_NODES));
  double wp = 0;
  for (int v = 0; v < N_NODES; ++v)
    wp = fmax(wp, fabs(pn[v] - (xyz[3 * v + 2] == 0.0 ? P : 0.0)));
  CHECK(wp <= TOL * P);

  /* The compliance: the pressure's work on the top's uniform u_z. */
  double work = 0;
  OK(tfem_solid_get_external_work(m, &work));
  double top = u[3 * (N_NODES - 1) + 2];
  CHECK(fabs(work - (-P * top)) <= TOL * fabs(work));
  printf("worst errors: stress %.2e, strain %.2e, displacement %.2e, x/y reaction %.2e, "
         "nodal pressure %.2e, area %.2e\n",
         ws, we, wu, wr, wp, fabs(area - 1.0));

  /* The solve's statistics: three unknowns per node less the 45 rollers'. */
  tfem_solve_info info;
  int iterations = -1;
  OK(tfem_solid_get_solve_info(m, &info));
  OK(tfem_solid_get_iterations(m, &iterations));
  CHECK(info.unknowns == 3 * N_NODES - 5 * NP * NP);
  CHECK(info.factorizations >= 1 && iterations >= 1);
  CHECK(info.relative_residual < 1e-10);
  int warnings = -1;
  OK(tfem_solid_warning_count(m, &warnings));
  CHECK(warnings == 0);
}

/* The displacements are still those of the first solve, bit for bit. */
static void check_unchanged(tfem_solid_model *m, int line) {
  static double u[3 * N_NODES];
  tfem_status s = tfem_solid_get_displacements(m, u, 3 * N_NODES);
  if (s == TFEM_STATUS_OK && memcmp(u, u_first, sizeof u) == 0) {
    ++passed;
  } else {
    ++failed;
    printf("FAIL line %d: the results changed (status %d)\n", line, (int)s);
  }
}
#define UNCHANGED(m) check_unchanged(m, __LINE__)

/* A hand-written Gmsh MSH 4.1 file (that of tests/gmsh_solid.rs): nodes
 * 101..105, A = (0,0,0), B = (1,0,0), C = (0,1,0), D = (0,0,1),
 * E = (1,1,1); tetrahedra ABCD and BCDE of physical volume 1; triangle
 * ABC on surface 1, in physical groups 10 and 99; BCE on surface 2, group
 * 20. Read with index_base 1: node i is the i-th of $Nodes. */
static const char *MSH =
    "$MeshFormat\n4.1 0 8\n$EndMeshFormat\n"
    "$PhysicalNames\n4\n3 1 \"steel\"\n2 10 \"bottom\"\n2 20 \"slant\"\n2 99 \"all\"\n"
    "$EndPhysicalNames\n"
    "$Entities\n0 0 2 1\n1 0 0 0 1 1 0 2 10 99 0\n2 0 0 0 1 1 1 1 20 0\n"
    "1 0 0 0 1 1 1 1 1 0\n$EndEntities\n"
    "$Nodes\n1 5 101 105\n3 1 0 5\n101\n102\n103\n104\n105\n"
    "0 0 0\n1 0 0\n0 1 0\n0 0 1\n1 1 1\n$EndNodes\n"
    "$Elements\n3 4 1 8\n3 1 4 2\n1 101 102 103 104\n2 102 103 104 105\n"
    "2 1 2 1\n7 101 102 103\n2 2 2 1\n8 102 103 105\n$EndElements\n";

static void gmsh_file(const char *path) {
  FILE *file = fopen(path, "wb");
  CHECK(file != NULL);
  if (file == NULL) return;
  fputs(MSH, file);
  fclose(file);
  tfem_solid_model *g = tfem_solid_create();
  OK(tfem_solid_load_gmsh(g, path, 1));
  int nn = -1, nt = -1, nc = -1, nf = -1;
  OK(tfem_solid_get_sizes(g, &nn, &nt, &nc));
  OK(tfem_solid_get_boundary_face_count(g, &nf));
  CHECK(nn == 5 && nt == 2 && nc == 0 && nf == 3);
  double x[15];
  int t[8], b[2], f[9], tg[3];
  OK(tfem_solid_get_mesh_nodes(g, x, 15));
  OK(tfem_solid_get_mesh_tetrahedra(g, t, 8, b, 2));
  OK(tfem_solid_get_boundary_faces(g, f, 9, tg, 3));
  const double x_want[15] = {0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1, 1, 1, 1};
  const int t_want[8] = {1, 2, 3, 4, 2, 3, 4, 5}, f_want[9] = {1, 2, 3, 1, 2, 3, 2, 3, 5};
  const int tg_want[3] = {10, 99, 20};
  CHECK(memcmp(x, x_want, sizeof x) == 0 && memcmp(t, t_want, sizeof t) == 0);
  CHECK(b[0] == 1 && b[1] == 1);
  CHECK(memcmp(f, f_want, sizeof f) == 0 && memcmp(tg, tg_want, sizeof tg) == 0);
  /* Node numbers are 1-based from now on. */
  EXPECT_ERROR(g, tfem_solid_fix(g, 0, TFEM_AXIS_X, 0.0), TFEM_STATUS_INVALID_ARGUMENT,
               "index base 1");
  OK(tfem_solid_fix(g, 5, TFEM_AXIS_X, 0.0));
  /* A file that is not there keeps the mesh there was. */
  EXPECT_ERROR(g, tfem_solid_load_gmsh(g, "/nonexistent-folder-of-tfem/x.msh", 0), TFEM_STATUS_IO,
               "nonexistent-folder-of-tfem");
  OK(tfem_solid_get_sizes(g, &nn, &nt, NULL));
  CHECK(nn == 5 && nt == 2);
  EXPECT_ERROR(g, tfem_solid_load_gmsh(g, NULL, 0), TFEM_STATUS_NULL_POINTER, "`path`");
  tfem_solid_destroy(g);
}

/* argv[1], if given: the folder the VTU file goes to (else the current
 * one). */
int main(int argc, char **argv) {
  char vtu[4096];
  char msh[4096];
  snprintf(vtu, sizeof vtu, "%s%ssolid_test.vtu", argc > 1 ? argv[1] : "", argc > 1 ? "/" : "");
  snprintf(msh, sizeof msh, "%s%ssolid_test.msh", argc > 1 ? argv[1] : "", argc > 1 ? "/" : "");
  cube(0, -1.0, 1, 0);
  cube(NODES_PER, 0.0, 2, 10);
  if (n_tets != N_TETS || n_faces != N_FACES) {
    printf("mesh built wrong: %d tetrahedra, %d faces\n", n_tets, n_faces);
    return 1;
  }

  /* ---- The patch test. */
  tfem_solid_model *m = scene(1);
  tfem_contact_options options;
  OK(tfem_contact_options_default(&options));
  tfem_solve_info info;
  OK(tfem_solid_solve_contact(m, &options, &info));
  CHECK(info.unknowns == 3 * N_NODES - 5 * NP * NP);
  check_exact(m);

  /* The mesh reads back as given. */
  int count = -1;
  OK(tfem_solid_get_boundary_face_count(m, &count));
  CHECK(count == N_FACES);
  static double xyz_back[3 * N_NODES];
  static int tets_back[4 * N_TETS], body_back[N_TETS], faces_back[3 * N_FACES],
      tags_back[N_FACES];
  OK(tfem_solid_get_mesh_nodes(m, xyz_back, 3 * N_NODES));
  OK(tfem_solid_get_mesh_tetrahedra(m, tets_back, 4 * N_TETS, body_back, N_TETS));
  OK(tfem_solid_get_boundary_faces(m, faces_back, 3 * N_FACES, tags_back, N_FACES));
  CHECK(memcmp(xyz_back, xyz, sizeof xyz) == 0);
  CHECK(memcmp(tets_back, tets, sizeof tets) == 0 && memcmp(body_back, body, sizeof body) == 0);
  CHECK(memcmp(faces_back, faces, sizeof faces) == 0 && memcmp(tags_back, tags, sizeof tags) == 0);

  /* The VTU file: an XML unstructured grid of the tetrahedra with the
   * fields. */
  remove(vtu);
  OK(tfem_solid_write_vtu(m, vtu));
  FILE *file = fopen(vtu, "rb");
  CHECK(file != NULL);
  if (file != NULL) {
    static char head[4096];
    size_t got = fread(head, 1, sizeof head - 1, file);
    head[got] = 0;
    fclose(file);
    CHECK(strstr(head, "<VTKFile") != NULL && strstr(head, "UnstructuredGrid") != NULL);
    CHECK(strstr(head, "\"displacement\"") != NULL && strstr(head, "\"stress\"") != NULL &&
          strstr(head, "\"contact_pressure\"") != NULL);
  }
  EXPECT_ERROR(m, tfem_solid_write_vtu(m, NULL), TFEM_STATUS_NULL_POINTER, "`path`");
  EXPECT_ERROR(m, tfem_solid_write_vtu(m, "/nonexistent-folder-of-tfem/x.vtu"), TFEM_STATUS_IO,
               "nonexistent-folder-of-tfem");

  /* ---- Refusals: each returns its status with a message naming the
   * item, writes nothing and leaves the model and its results as they
   * were. */
  static double buf[3 * N_NODES];
  EXPECT_ERROR(m, tfem_solid_get_displacements(m, NULL, 3 * N_NODES), TFEM_STATUS_NULL_POINTER,
               "`out`");
  for (int k = 0; k < 3 * N_NODES; ++k) buf[k] = 42.0;
  EXPECT_ERROR(m, tfem_solid_get_displacements(m, buf, 3 * N_NODES - 1),
               TFEM_STATUS_BUFFER_TOO_SMALL, "are needed");
  int untouched = 1;
  for (int k = 0; k < 3 * N_NODES; ++k) untouched = untouched && buf[k] == 42.0;
  CHECK(untouched);
  EXPECT_ERROR(m, tfem_solid_get_element_stresses(m, buf, 6 * N_TETS - 1),
               TFEM_STATUS_BUFFER_TOO_SMALL, "are needed");
  EXPECT_ERROR(m, tfem_solid_fix(m, N_NODES, TFEM_AXIS_X, 0.0), TFEM_STATUS_INVALID_ARGUMENT,
               "node 54 is out of range");
  EXPECT_ERROR(m, tfem_solid_fix(m, -1, TFEM_AXIS_X, 0.0), TFEM_STATUS_INVALID_ARGUMENT,
               "node -1 is out of range");
  EXPECT_ERROR(m, tfem_solid_add_nodal_force(m, N_NODES, 0, 0, 1), TFEM_STATUS_INVALID_ARGUMENT,
               "node 54");
  EXPECT_ERROR(m, tfem_solid_fix(m, 0, 3, 0.0), TFEM_STATUS_INVALID_ARGUMENT, "component = 3");
  EXPECT_ERROR(m, tfem_solid_fix_faces(m, 5, -1, 0.0), TFEM_STATUS_INVALID_ARGUMENT,
               "component = -1");
  EXPECT_ERROR(m, tfem_solid_fix(m, 0, TFEM_AXIS_X, NAN), TFEM_STATUS_INVALID_ARGUMENT,
               "not finite");
  EXPECT_ERROR(m, tfem_solid_fix_faces(m, 99, TFEM_AXIS_X, 0.0), TFEM_STATUS_INVALID_ARGUMENT,
               "tag 99");
  EXPECT_ERROR(m, tfem_solid_add_pressure(m, 99, 1.0), TFEM_STATUS_INVALID_ARGUMENT, "tag 99");
  EXPECT_ERROR(m, tfem_solid_add_contact_pair(m, 6, 6, NULL), TFEM_STATUS_INVALID_ARGUMENT,
               "both are 6");
  EXPECT_ERROR(m, tfem_solid_set_material(m, 1, -1.0, NU), TFEM_STATUS_INVALID_MATERIAL,
               "body 1");
  EXPECT_ERROR(m, tfem_solid_set_material(m, 2, E, 0.5), TFEM_STATUS_INVALID_MATERIAL, "body 2");
  EXPECT_ERROR(m, tfem_solid_set_tempering(m, 4, 0.0), TFEM_STATUS_INVALID_ARGUMENT,
               "tempering mode = 4");
  EXPECT_ERROR(m, tfem_solid_set_tempering(m, 1, -1.0), TFEM_STATUS_INVALID_ARGUMENT, "finite");
  EXPECT_ERROR(m, tfem_solid_get_contact_pair_area(m, 1, buf), TFEM_STATUS_INVALID_ARGUMENT,
               "contact pair 1");
  EXPECT_ERROR(m, tfem_solid_get_warning_size(m, 0, NULL), TFEM_STATUS_INVALID_ARGUMENT,
               "warning index 0");
  /* Faces come before what names them. */
  EXPECT_ERROR(m, tfem_solid_add_boundary_faces(m, 1, faces, tags), TFEM_STATUS_INVALID_STATE,
               "tfem_solid_clear_constraints");
  /* A mesh with a node out of range keeps the mesh there was. */
  int bad[4 * N_TETS];
  memcpy(bad, tets, sizeof bad);
  bad[4 * 7 + 2] = N_NODES;
  EXPECT_ERROR(m, tfem_solid_set_mesh(m, N_NODES, xyz, N_TETS, bad, body, 0),
               TFEM_STATUS_INVALID_MESH, "tetrahedron 7: node index 54 is out of range");
  EXPECT_ERROR(m, tfem_solid_set_mesh(m, N_NODES, xyz, N_TETS, tets, body, 2),
               TFEM_STATUS_INVALID_ARGUMENT, "index_base = 2");
  EXPECT_ERROR(m, tfem_solid_set_mesh(m, N_NODES, NULL, N_TETS, tets, body, 0),
               TFEM_STATUS_NULL_POINTER, "`xyz`");
  /* 3D contact is frictionless: the stick law is refused, saying so. */
  options.law = 1;
  EXPECT_ERROR(m, tfem_solid_solve_contact(m, &options, NULL), TFEM_STATUS_INVALID_ARGUMENT,
               "frictionless");
  options.law = 0;
  options.max_iterations = 0;
  EXPECT_ERROR(m, tfem_solid_solve_contact(m, &options, NULL), TFEM_STATUS_INVALID_ARGUMENT,
               "max_iterations");
  UNCHANGED(m);
  /* ... and the model solves again to the same numbers. */
  OK(tfem_solid_solve(m, NULL));
  check_exact(m);
  UNCHANGED(m);

  /* A load step at half the load: half the stress, and a step back to the
   * full load's results. */
  {
    tfem_solve_info step_info;
    OK(tfem_solid_step(m, 0.5, NULL, &step_info));
    CHECK(step_info.unknowns == 3 * N_NODES - 5 * NP * NP);
    static double s[6 * N_TETS];
    OK(tfem_solid_get_element_stresses(m, s, 6 * N_TETS));
    double ws = 0;
    for (int t = 0; t < N_TETS; ++t)
      for (int c = 0; c < 6; ++c) ws = fmax(ws, fabs(s[6 * t + c] - (c == 2 ? -0.5 * P : 0.0)));
    CHECK(ws <= TOL * P);
    double area = 0;
    OK(tfem_solid_get_contact_area(m, &area));
    CHECK(fabs(area - 1.0) < 1e-12);
    OK(tfem_solid_revert_step(m));
    UNCHANGED(m);
    EXPECT_ERROR(m, tfem_solid_revert_step(m), TFEM_STATUS_INVALID_STATE, "no load step");
    EXPECT_ERROR(m, tfem_solid_step(m, INFINITY, NULL, NULL), TFEM_STATUS_INVALID_ARGUMENT,
                 "load");
    UNCHANGED(m);
  }

  /* Under index base 1, a contact side's refusal names the node by its
   * 1-based number: side a's node (1, 1, N) moved off the node it faced. */
  {
    static double moved[3 * N_NODES];
    static int tets1[4 * N_TETS], faces1[3 * N_FACES];
    memcpy(moved, xyz, sizeof xyz);
    int v = id(0, 1, 1, N);
    moved[3 * v] += 0.1 / N;
    for (int k = 0; k < 4 * N_TETS; ++k) tets1[k] = tets[k] + 1;
    for (int k = 0; k < 3 * N_FACES; ++k) faces1[k] = faces[k] + 1;
    tfem_solid_model *b1 = tfem_solid_create();
    OK(tfem_solid_set_mesh(b1, N_NODES, moved, N_TETS, tets1, body, 1));
    OK(tfem_solid_set_boundary_faces(b1, N_FACES, faces1, tags));
    OK(tfem_solid_set_material(b1, 1, E, NU));
    OK(tfem_solid_set_material(b1, 2, E, NU));
    OK(tfem_solid_fix_faces(b1, 5, TFEM_AXIS_Z, 0.0));
    OK(tfem_solid_add_contact_pair(b1, 6, 15, NULL));
    char needle[64];
    snprintf(needle, sizeof needle, "node %d of surface a faces no node", v + 1);
    EXPECT_ERROR(b1, tfem_solid_solve_contact(b1, NULL, NULL), TFEM_STATUS_INVALID_ARGUMENT,
                 needle);
    tfem_solid_destroy(b1);
  }

  /* A handle of the other kind, or none, is refused; its message is the
   * thread's. */
  tfem_model *two = tfem_create();
  EXPECT_ERROR(NULL, tfem_solid_solve((tfem_solid_model *)two, NULL),
               TFEM_STATUS_INVALID_ARGUMENT, "not a 3D model");
  EXPECT_ERROR(NULL, tfem_solve((tfem_model *)m, NULL), TFEM_STATUS_INVALID_ARGUMENT,
               "it is a 3D model");
  EXPECT_ERROR(NULL, tfem_solid_solve(NULL, NULL), TFEM_STATUS_NULL_POINTER, "`model`");
  char msg[256];
  CHECK(tfem_solid_last_error((tfem_solid_model *)two, msg, sizeof msg) ==
        TFEM_STATUS_INVALID_ARGUMENT);
  CHECK(strstr(msg, "not a 3D model") != NULL);
  tfem_destroy(two);
  UNCHANGED(m);

  /* ---- A body without material; results before a solve; an inner face. */
  tfem_solid_model *q = scene(0);
  EXPECT_ERROR(q, tfem_solid_get_displacements(q, buf, 3 * N_NODES), TFEM_STATUS_INVALID_STATE,
               "no solution");
  EXPECT_ERROR(q, tfem_solid_write_vtu(q, vtu), TFEM_STATUS_INVALID_STATE, "no solution");
  EXPECT_ERROR(q, tfem_solid_solve(q, NULL), TFEM_STATUS_INVALID_MATERIAL,
               "body 2 has no material");
  CHECK(tfem_solid_last_error_length(q) > 1);
  OK(tfem_solid_set_material(q, 2, E, NU));
  CHECK(tfem_solid_last_error_length(q) == 1);
  OK(tfem_solid_solve_contact(q, NULL, NULL));
  check_exact(q);
  tfem_solid_destroy(q);

  tfem_solid_model *r = tfem_solid_create();
  EXPECT_ERROR(r, tfem_solid_fix(r, 0, TFEM_AXIS_X, 0.0), TFEM_STATUS_INVALID_STATE, "no mesh");
  /* A failed call writes none of its outputs. */
  {
    int nn = 7, nt = 8, nc = 9, it = 10;
    double work = 11.5, area = 12.5;
    tfem_solve_info before, after;
    memset(&before, 0x5a, sizeof before);
    after = before;
    EXPECT_ERROR(r, tfem_solid_get_sizes(r, &nn, &nt, &nc), TFEM_STATUS_INVALID_STATE, "no mesh");
    EXPECT_ERROR(r, tfem_solid_solve(r, &after), TFEM_STATUS_INVALID_STATE, "no mesh");
    CHECK(nn == 7 && nt == 8 && nc == 9 && memcmp(&before, &after, sizeof before) == 0);
    OK(tfem_solid_set_mesh(r, N_NODES, xyz, N_TETS, tets, body, 0));
    EXPECT_ERROR(r, tfem_solid_get_external_work(r, &work), TFEM_STATUS_INVALID_STATE,
                 "no solution");
    EXPECT_ERROR(r, tfem_solid_get_contact_area(r, &area), TFEM_STATUS_INVALID_STATE,
                 "no solution");
    EXPECT_ERROR(r, tfem_solid_get_iterations(r, &it), TFEM_STATUS_INVALID_STATE, "no solution");
    EXPECT_ERROR(r, tfem_solid_solve_contact(r, NULL, &after), TFEM_STATUS_INVALID_MATERIAL,
                 "body 1 has no material");
    CHECK(work == 11.5 && area == 12.5 && it == 10 && memcmp(&before, &after, sizeof before) == 0);
  }
  OK(tfem_solid_set_mesh(r, N_NODES, xyz, N_TETS, tets, body, 0));
  int inner[3] = {tets[0], tets[1], tets[3]}, tag = 9;
  EXPECT_ERROR(r, tfem_solid_set_boundary_faces(r, 1, inner, &tag), TFEM_STATUS_INVALID_MESH,
               "shared by 2 tetrahedra");
  OK(tfem_solid_get_boundary_face_count(r, &count));
  CHECK(count == 0);
  tfem_solid_destroy(r);
  /* A destroyed handle is refused, and destroying it again is a no-op. */
  EXPECT_ERROR(NULL, tfem_solid_solve(r, NULL), TFEM_STATUS_INVALID_ARGUMENT, "destroyed");
  tfem_solid_destroy(r);

  tfem_solid_destroy(m);

  /* ---- A tetrahedral Gmsh file. */
  gmsh_file(msh);

  printf("solid_test: %d passed, %d failed\n", passed, failed);
  return failed == 0 ? 0 : 1;
}
