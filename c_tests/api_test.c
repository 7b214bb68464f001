/* Drives the whole C API of tfem, including every error path: each bad
 * call must return its status, say something useful, and leave the model
 * as it was. */

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "tfem.h"

static int passed = 0, failed = 0;

#define CHECK(cond)                                                     \
  do {                                                                  \
    if (cond) {                                                         \
      ++passed;                                                         \
    } else {                                                            \
      ++failed;                                                         \
      printf("FAIL %s:%d: %s\n", __FILE__, __LINE__, #cond);            \
    }                                                                   \
  } while (0)

/* The call must fail with `expected` and its message must contain `needle`. */
static void expect_error(tfem_model *m, tfem_status got, tfem_status expected, const char *needle,
                         int line) {
  char msg[512];
  tfem_last_error(m, msg, sizeof msg);
  if (got == expected && strstr(msg, needle) != NULL) {
    ++passed;
  } else {
    ++failed;
    printf("FAIL line %d: status %d (expected %d), message \"%s\" (expected to contain \"%s\")\n",
           line, (int)got, (int)expected, msg, needle);
  }
}
#define EXPECT_ERROR(m, call, status, needle) expect_error(m, call, status, needle, __LINE__)

/* A 2 x 1 rectangle [0,2]x[0,1] of 4 triangles, body 7:
 *   3---4---5
 *   | / | / |
 *   0---1---2
 * edges: left (tag 1) 0-3, right (tag 2) 2-5, bottom (tag 3). */
static const double XY[12] = {0, 0, 1, 0, 2, 0, 0, 1, 1, 1, 2, 1};
static const int TRI[12] = {0, 1, 4, 0, 4, 3, 1, 2, 5, 1, 5, 4};
static const int BODY[4] = {7, 7, 7, 7};
static const int EDGES[8] = {0, 3, 2, 5, 0, 1, 1, 2};
static const int TAGS[4] = {1, 2, 3, 3};

static void build(tfem_model *m, int base) {
  int tri[12], edges[8];
  for (int i = 0; i < 12; ++i) tri[i] = TRI[i] + base;
  for (int i = 0; i < 8; ++i) edges[i] = EDGES[i] + base;
  CHECK(tfem_set_mesh(m, 6, XY, 4, tri, BODY, base) == TFEM_STATUS_OK);
  CHECK(tfem_set_boundary_edges(m, 4, edges, TAGS) == TFEM_STATUS_OK);
  CHECK(tfem_set_material(m, 7, 1000.0, 0.25, TFEM_PLANE_MODE_STRESS) == TFEM_STATUS_OK);
}

/* Uniaxial tension: left edge u = 0, node 0 v = 0, traction 10 on the right.
 * Exact: u = 10 x / E, v = -nu 10 y / E (plane stress). */
static void restrain_and_load(tfem_model *m, int base) {
  CHECK(tfem_fix_edges(m, 1, TFEM_COMPONENT_X, 0.0) == TFEM_STATUS_OK);
  CHECK(tfem_fix(m, 0 + base, TFEM_COMPONENT_Y, 0.0) == TFEM_STATUS_OK);
  CHECK(tfem_add_traction(m, 2, 10.0, 0.0) == TFEM_STATUS_OK);
}

static void check_tension(tfem_model *m) {
  double u[12];
  CHECK(tfem_get_displacements(m, u, 12) == TFEM_STATUS_OK);
  double err = 0;
  for (int i = 0; i < 6; ++i) {
    err = fmax(err, fabs(u[2 * i] - 10.0 * XY[2 * i] / 1000.0));
    err = fmax(err, fabs(u[2 * i + 1] + 0.25 * 10.0 * XY[2 * i + 1] / 1000.0));
  }
  CHECK(err < 1e-14);
  double r[12];
  CHECK(tfem_get_reactions(m, r, 12) == TFEM_STATUS_OK);
  /* Reactions balance the applied 10 N/m over a height of 1. */
  CHECK(fabs(r[0] + r[6] + 10.0) < 1e-12);
  double s[12];
  CHECK(tfem_get_element_stresses(m, s, 12) == TFEM_STATUS_OK);
  for (int e = 0; e < 4; ++e) CHECK(fabs(s[3 * e] - 10.0) < 1e-12 && fabs(s[3 * e + 1]) < 1e-12);
}

/* The matrix of the last tension solve: K u = f on the unknowns, with f the
 * traction's consistent nodal forces (5 N in x at nodes 2 and 5); upper
 * triangle, rows ascending, diagonal last, indices in the index base. */
static void check_matrix(tfem_model *m, int base) {
  int64_t n = -1, nnz = -1;
  CHECK(tfem_get_system_matrix_size(m, &n, &nnz) == TFEM_STATUS_OK && n == 9 && nnz > n);
  if (n != 9 || nnz <= n || nnz > 64) return;
  int64_t cp[10], ri[64], dofs[9];
  double k[64], u[12];
  CHECK(tfem_get_system_matrix(m, cp, 10, ri, 64, k, 64, dofs, 9) == TFEM_STATUS_OK);
  CHECK(tfem_get_displacements(m, u, 12) == TFEM_STATUS_OK);
  CHECK(cp[0] == base && cp[n] == nnz + base);
  double x[9], ku[9] = {0};
  for (int j = 0; j < n; ++j) x[j] = u[dofs[j] - base];
  for (int j = 0; j < n; ++j) {
    for (int64_t p = cp[j] - base; p < cp[j + 1] - base; ++p) {
      int64_t i = ri[p] - base;
      CHECK(i >= 0 && i <= j && (p == cp[j] - base || ri[p - 1] < ri[p]));
      if (i < 0 || i > j) return;
      ku[i] += k[p] * x[j];
      if (i != j) ku[j] += k[p] * x[i];
    }
    CHECK(ri[cp[j + 1] - base - 1] - base == j && k[cp[j + 1] - base - 1] > 0.0);
  }
  double err = 0;
  for (int j = 0; j < n; ++j) {
    int64_t d = dofs[j] - base;
    double f = (d == 2 * 2 || d == 2 * 5) ? 5.0 : 0.0;
    err = fmax(err, fabs(ku[j] - f));
  }
  CHECK(err < 1e-12);
}

int main(void) {
  char msg[512];
  const char *v = tfem_version();
  CHECK(v != NULL && v[0] >= '0' && v[0] <= '9');

  /* NULL handles. */
  tfem_destroy(NULL);
  CHECK(tfem_solve(NULL, NULL) == TFEM_STATUS_NULL_POINTER);
  CHECK(tfem_last_error(NULL, msg, sizeof msg) == TFEM_STATUS_OK && strstr(msg, "model") != NULL);
  CHECK(tfem_set_mesh(NULL, 6, XY, 4, TRI, BODY, 0) == TFEM_STATUS_NULL_POINTER);

  tfem_model *m = tfem_create();
  CHECK(m != NULL);
  CHECK(tfem_last_error(m, msg, sizeof msg) == TFEM_STATUS_OK && msg[0] == '\0');

  /* Wrong order. */
  EXPECT_ERROR(m, tfem_solve(m, NULL), TFEM_STATUS_INVALID_STATE, "mesh");
  double buf[64];
  EXPECT_ERROR(m, tfem_get_displacements(m, buf, 64), TFEM_STATUS_INVALID_STATE, "solve");
  EXPECT_ERROR(m, tfem_get_system_matrix_size(m, NULL, NULL), TFEM_STATUS_INVALID_STATE, "solve");
  EXPECT_ERROR(m, tfem_fix(m, 0, 0, 0.0), TFEM_STATUS_INVALID_STATE, "mesh");
  EXPECT_ERROR(m, tfem_solve_contact(m, NULL, NULL), TFEM_STATUS_INVALID_STATE, "mesh");

  /* Bad meshes, each naming the offending item. */
  int bad[12];
  memcpy(bad, TRI, sizeof bad);
  bad[5] = 6;
  EXPECT_ERROR(m, tfem_set_mesh(m, 6, XY, 4, bad, BODY, 0), TFEM_STATUS_INVALID_MESH, "triangle 1");
  memcpy(bad, TRI, sizeof bad);
  bad[7] = 1;
  EXPECT_ERROR(m, tfem_set_mesh(m, 6, XY, 4, bad, BODY, 0), TFEM_STATUS_INVALID_MESH, "triangle 2: node 1 is repeated");
  double xy_nan[12];
  memcpy(xy_nan, XY, sizeof xy_nan);
  xy_nan[9] = NAN;
  EXPECT_ERROR(m, tfem_set_mesh(m, 6, xy_nan, 4, TRI, BODY, 0), TFEM_STATUS_INVALID_MESH, "node 4");
  EXPECT_ERROR(m, tfem_set_mesh(m, 0, XY, 0, TRI, BODY, 0), TFEM_STATUS_INVALID_MESH, "empty");
  EXPECT_ERROR(m, tfem_set_mesh(m, -1, XY, 4, TRI, BODY, 0), TFEM_STATUS_INVALID_ARGUMENT, "n_nodes");
  EXPECT_ERROR(m, tfem_set_mesh(m, 6, NULL, 4, TRI, BODY, 0), TFEM_STATUS_NULL_POINTER, "xy");
  EXPECT_ERROR(m, tfem_set_mesh(m, 6, XY, 4, TRI, BODY, 2), TFEM_STATUS_INVALID_ARGUMENT, "index_base");
  /* Fortran numbering: index 0 is out of range with base 1. */
  EXPECT_ERROR(m, tfem_set_mesh(m, 6, XY, 4, TRI, BODY, 1), TFEM_STATUS_INVALID_MESH, "index base 1");

  build(m, 0);
  int nn = 0, nt = 0, nc = -1;
  CHECK(tfem_get_sizes(m, &nn, &nt, &nc) == TFEM_STATUS_OK && nn == 6 && nt == 4 && nc == 0);
  double J[4];
  CHECK(tfem_get_element_jacobians(m, J, 4) == TFEM_STATUS_OK && fabs(J[0] - 1.0) < 1e-15);

  /* A failed set_mesh leaves the previous mesh in place. */
  bad[7] = 1;
  CHECK(tfem_set_mesh(m, 6, XY, 4, bad, BODY, 0) == TFEM_STATUS_INVALID_MESH);
  CHECK(tfem_get_sizes(m, &nn, &nt, NULL) == TFEM_STATUS_OK && nn == 6 && nt == 4);

  /* Boundary edges. */
  int e_bad[2] = {0, 5};
  int t1 = 1;
  EXPECT_ERROR(m, tfem_set_boundary_edges(m, 1, e_bad, &t1), TFEM_STATUS_INVALID_MESH, "not a side");
  e_bad[1] = 9;
  EXPECT_ERROR(m, tfem_set_boundary_edges(m, 1, e_bad, &t1), TFEM_STATUS_INVALID_ARGUMENT, "edge node 9");

  /* Materials. */
  EXPECT_ERROR(m, tfem_set_material(m, 7, -1.0, 0.3, 0), TFEM_STATUS_INVALID_MATERIAL, "body 7");
  EXPECT_ERROR(m, tfem_set_material(m, 7, 1.0, 0.5, TFEM_PLANE_MODE_STRAIN), TFEM_STATUS_INVALID_MATERIAL, "Poisson");
  EXPECT_ERROR(m, tfem_set_material(m, 7, 1.0, 0.3, 5), TFEM_STATUS_INVALID_ARGUMENT, "plane");
  EXPECT_ERROR(m, tfem_set_material(m, 8, 1.0, 0.3, 0), TFEM_STATUS_INVALID_MATERIAL, "body 8");

  /* Constraints and loads. */
  EXPECT_ERROR(m, tfem_fix(m, 6, 0, 0.0), TFEM_STATUS_INVALID_ARGUMENT, "node 6");
  EXPECT_ERROR(m, tfem_fix(m, 0, 2, 0.0), TFEM_STATUS_INVALID_ARGUMENT, "component");
  EXPECT_ERROR(m, tfem_fix(m, 0, 0, INFINITY), TFEM_STATUS_INVALID_ARGUMENT, "not finite");
  EXPECT_ERROR(m, tfem_fix_edges(m, 99, 0, 0.0), TFEM_STATUS_INVALID_ARGUMENT, "tag 99");
  EXPECT_ERROR(m, tfem_add_pressure(m, 99, 1.0), TFEM_STATUS_INVALID_ARGUMENT, "tag 99");
  EXPECT_ERROR(m, tfem_add_traction(m, 2, NAN, 0.0), TFEM_STATUS_INVALID_ARGUMENT, "traction");
  EXPECT_ERROR(m, tfem_set_body_force(m, 3, 0.0, 1.0), TFEM_STATUS_INVALID_ARGUMENT, "body 3");
  EXPECT_ERROR(m, tfem_set_tempering(m, 1, -2.0), TFEM_STATUS_INVALID_ARGUMENT, "lambda");
  EXPECT_ERROR(m, tfem_set_tempering(m, 9, 1.0), TFEM_STATUS_INVALID_ARGUMENT, "mode");

  /* Unrestrained: singular, naming the body. */
  CHECK(tfem_add_traction(m, 2, 10.0, 0.0) == TFEM_STATUS_OK);
  EXPECT_ERROR(m, tfem_solve(m, NULL), TFEM_STATUS_SINGULAR, "body 7");
  EXPECT_ERROR(m, tfem_get_displacements(m, buf, 64), TFEM_STATUS_INVALID_STATE, "solve");
  /* Sliding mode only: x fixed on the left, nothing in y. */
  CHECK(tfem_fix_edges(m, 1, TFEM_COMPONENT_X, 0.0) == TFEM_STATUS_OK);
  EXPECT_ERROR(m, tfem_solve(m, NULL), TFEM_STATUS_SINGULAR, "translation in y");
  CHECK(tfem_clear_loads(m) == TFEM_STATUS_OK);
  CHECK(tfem_clear_constraints(m) == TFEM_STATUS_OK);
  EXPECT_ERROR(m, tfem_solve_contact(m, NULL, NULL), TFEM_STATUS_INVALID_STATE, "contact pair");
  EXPECT_ERROR(m, tfem_add_contact_pair(m, 1, 2, NULL), TFEM_STATUS_INVALID_CONTACT, "body 7");
  EXPECT_ERROR(m, tfem_add_contact_pair(m, 1, 42, NULL), TFEM_STATUS_INVALID_CONTACT, "tag 42");

  /* A good solve. This mesh is as coarse as the body (h ~ lambda = 2 by
   * default): the default tempering leaves its healthy elements alone, an
   * explicit lambda = 2 (h^3/lambda > J) softens them, and says so. */
  restrain_and_load(m, 0);
  int nw = -1;
  CHECK(tfem_solve(m, NULL) == TFEM_STATUS_OK);
  CHECK(tfem_warning_count(m, &nw) == TFEM_STATUS_OK && nw == 0);
  check_tension(m);
  CHECK(tfem_set_tempering(m, TFEM_TEMPERING_MODE_LAMBDA, 2.0) == TFEM_STATUS_OK);
  CHECK(tfem_solve(m, NULL) == TFEM_STATUS_OK);
  CHECK(tfem_warning_count(m, &nw) == TFEM_STATUS_OK && nw == 1);
  CHECK(tfem_get_warning(m, 0, msg, sizeof msg) == TFEM_STATUS_OK && strstr(msg, "softens") != NULL);
  CHECK(tfem_set_tempering(m, TFEM_TEMPERING_MODE_LAMBDA, 1000.0) == TFEM_STATUS_OK);
  tfem_solve_info info;
  CHECK(tfem_solve(m, &info) == TFEM_STATUS_OK);
  CHECK(tfem_warning_count(m, &nw) == TFEM_STATUS_OK && nw == 0);
  CHECK(info.unknowns == 12 - 3 && info.factorizations == 1 && info.relative_residual < 1e-12);
  CHECK(info.time_total >= 0.0 && info.condition_estimate >= 1.0);
  check_tension(m);
  check_matrix(m, 0);
  {
    /* Every matrix buffer is checked before any is written. */
    int64_t cp[10] = {-7}, ri[64], dofs[9];
    double k[64];
    EXPECT_ERROR(m, tfem_get_system_matrix(m, cp, 10, ri, 8, k, 64, dofs, 9), TFEM_STATUS_BUFFER_TOO_SMALL, "row_idx");
    CHECK(cp[0] == -7);
    EXPECT_ERROR(m, tfem_get_system_matrix(m, cp, 10, ri, 64, k, 64, NULL, 9), TFEM_STATUS_NULL_POINTER, "dofs");
    CHECK(cp[0] == -7);
  }

  /* Result buffers: too short leaves the buffer untouched; NULL is refused. */
  double short_buf[11];
  for (int i = 0; i < 11; ++i) short_buf[i] = -7.0;
  EXPECT_ERROR(m, tfem_get_displacements(m, short_buf, 11), TFEM_STATUS_BUFFER_TOO_SMALL, "12");
  CHECK(short_buf[0] == -7.0 && short_buf[10] == -7.0);
  EXPECT_ERROR(m, tfem_get_displacements(m, NULL, 12), TFEM_STATUS_NULL_POINTER, "out");
  EXPECT_ERROR(m, tfem_get_element_strains(m, buf, 11), TFEM_STATUS_BUFFER_TOO_SMALL, "12");
  EXPECT_ERROR(m, tfem_get_contact_active(m, NULL, 0), TFEM_STATUS_INVALID_STATE, "contact");
  /* The failed calls did not discard the results. */
  check_tension(m);
  /* Any change discards them. */
  CHECK(tfem_add_traction(m, 2, 1.0, 0.0) == TFEM_STATUS_OK);
  EXPECT_ERROR(m, tfem_get_displacements(m, buf, 64), TFEM_STATUS_INVALID_STATE, "solve");

  /* Error messages: truncation keeps a NUL and reports it. */
  char tiny[8];
  tfem_fix(m, 100, 0, 0.0);
  CHECK(tfem_last_error(m, tiny, sizeof tiny) == TFEM_STATUS_BUFFER_TOO_SMALL && strlen(tiny) == 7);
  CHECK(tfem_last_error_length(m) > 8);

  /* Plain FEM is available and identical on this healthy mesh. */
  CHECK(tfem_set_tempering(m, TFEM_TEMPERING_MODE_OFF, 0.0) == TFEM_STATUS_OK);
  CHECK(tfem_clear_loads(m) == TFEM_STATUS_OK);
  CHECK(tfem_add_traction(m, 2, 10.0, 0.0) == TFEM_STATUS_OK);
  CHECK(tfem_solve(m, NULL) == TFEM_STATUS_OK);
  check_tension(m);

  /* Orderings: the same answer from AMD and from nested dissection, as one
   * tree or as two concurrent subtrees; bad values are refused by name and
   * leave the results in place. */
  CHECK(tfem_set_ordering(m, TFEM_ORDERING_MODE_AMD, 1) == TFEM_STATUS_OK);
  CHECK(tfem_solve(m, NULL) == TFEM_STATUS_OK);
  check_tension(m);
  CHECK(tfem_set_ordering(m, TFEM_ORDERING_MODE_NESTED_DISSECTION, 0) == TFEM_STATUS_OK);
  CHECK(tfem_solve(m, NULL) == TFEM_STATUS_OK);
  check_tension(m);
  EXPECT_ERROR(m, tfem_set_ordering(m, 3, 1), TFEM_STATUS_INVALID_ARGUMENT, "ordering = 3");
  EXPECT_ERROR(m, tfem_set_ordering(m, TFEM_ORDERING_MODE_AUTO, 2), TFEM_STATUS_INVALID_ARGUMENT, "parallel_subtrees = 2");
  EXPECT_ERROR(NULL, tfem_set_ordering(NULL, 0, 1), TFEM_STATUS_NULL_POINTER, "model");
  check_tension(m);
  CHECK(tfem_set_ordering(m, TFEM_ORDERING_MODE_AUTO, 1) == TFEM_STATUS_OK);

  /* Warnings: none for this clean mesh. */
  CHECK(tfem_warning_count(m, &nw) == TFEM_STATUS_OK && nw == 0);
  EXPECT_ERROR(m, tfem_get_warning(m, 0, msg, sizeof msg), TFEM_STATUS_INVALID_ARGUMENT, "warning index");
  tfem_destroy(m);

  /* The same problem with Fortran (1-based) numbering. */
  m = tfem_create();
  build(m, 1);
  CHECK(tfem_set_tempering(m, TFEM_TEMPERING_MODE_LAMBDA, 1000.0) == TFEM_STATUS_OK);
  restrain_and_load(m, 1);
  CHECK(tfem_solve(m, NULL) == TFEM_STATUS_OK);
  check_tension(m);
  check_matrix(m, 1);
  EXPECT_ERROR(m, tfem_fix(m, 0, 0, 0.0), TFEM_STATUS_INVALID_ARGUMENT, "index base 1");
  /* An unused node is warned about (1-based in the message). */
  double xy7[14];
  memcpy(xy7, XY, sizeof XY);
  xy7[12] = 5;
  xy7[13] = 5;
  int tri1[12];
  for (int i = 0; i < 12; ++i) tri1[i] = TRI[i] + 1;
  CHECK(tfem_set_mesh(m, 7, xy7, 4, tri1, BODY, 1) == TFEM_STATUS_OK);
  CHECK(tfem_warning_count(m, &nw) == TFEM_STATUS_OK && nw == 1);
  CHECK(tfem_get_warning(m, 0, msg, sizeof msg) == TFEM_STATUS_OK && strstr(msg, "7") != NULL);
  tfem_destroy(m);

  /* Gmsh files: a missing file and a NULL path are clear errors. */
  m = tfem_create();
  EXPECT_ERROR(m, tfem_load_gmsh(m, "/nonexistent/mesh.msh", 1), TFEM_STATUS_IO, "/nonexistent/mesh.msh");
  EXPECT_ERROR(m, tfem_load_gmsh(m, NULL, 1), TFEM_STATUS_NULL_POINTER, "path");
  tfem_destroy(m);

  /* Pure element functions. */
  double xy[6] = {0, 0, 1, 0, 2, 0}, K[36], L[9];
  CHECK(tfem_element_stiffness(xy, 1.0, 0.3, 0, 1e-3, K) == TFEM_STATUS_OK);
  EXPECT_ERROR(NULL, tfem_element_stiffness(xy, 1.0, 0.3, 0, 0.0, K), TFEM_STATUS_DEGENERATE_ELEMENT, "zero Jacobian");
  EXPECT_ERROR(NULL, tfem_element_stiffness(xy, 1.0, 0.3, 0, -1.0, K), TFEM_STATUS_INVALID_ARGUMENT, "jmin");
  EXPECT_ERROR(NULL, tfem_element_stiffness(NULL, 1.0, 0.3, 0, 1.0, K), TFEM_STATUS_NULL_POINTER, "xy");
  EXPECT_ERROR(NULL, tfem_element_stiffness(xy, 1.0, 0.3, 0, 1.0, NULL), TFEM_STATUS_NULL_POINTER, "out");
  EXPECT_ERROR(NULL, tfem_laplacian_stiffness(xy, 0.0, 1.0, L), TFEM_STATUS_INVALID_ARGUMENT, "kappa");
  tfem_contact_options o;
  CHECK(tfem_contact_options_default(&o) == TFEM_STATUS_OK && o.law == TFEM_CONTACT_LAW_FRICTIONLESS && o.max_iterations > 0);

  /* Gmsh files whose headers lie about their sizes (regression: a $Nodes
   * header claiming 10^15 nodes aborted the process, 2^62 gave INTERNAL and
   * a panic message on stderr). Each is an IO error naming $Nodes and the
   * count, and the model keeps the mesh it had. */
  {
    static const char msh[] =
        "$MeshFormat\n4.1 0 8\n$EndMeshFormat\n"
        "$Entities\n0 0 1 0\n1 0 0 0 1 1 0 1 7 0\n$EndEntities\n"
        "$Nodes\n%s\n2 1 0 3\n1\n2\n3\n0 0 0\n1 0 0\n0 1 0\n$EndNodes\n"
        "$Elements\n1 1 1 1\n2 1 2 1\n1 1 2 3\n$EndElements\n";
    /* A name of our own in the temporary directory (the stack address
     * differs from run to run). */
    char path[512];
    const char *tmp = getenv("TMPDIR");
    int here = 0;
    snprintf(path, sizeof path, "%s/tfem_api_test_%lx.msh", tmp != NULL && tmp[0] != '\0' ? tmp : "/tmp",
             (unsigned long)(uintptr_t)&here);
    const char *headers[3] = {"1 3 1 3", "1 1000000000000000 1 3", "1 4611686018427387904 1 3"};
    const char *counts[3] = {"", "1000000000000000", "4611686018427387904"};
    m = tfem_create();
    for (int k = 0; k < 3; ++k) {
      FILE *f = fopen(path, "w");
      CHECK(f != NULL);
      if (f == NULL) break;
      fprintf(f, msh, headers[k]);
      fclose(f);
      tfem_status s = tfem_load_gmsh(m, path, 0);
      if (k == 0) {
        CHECK(s == TFEM_STATUS_OK);
      } else {
        EXPECT_ERROR(m, s, TFEM_STATUS_IO, "$Nodes");
        tfem_last_error(m, msg, sizeof msg);
        CHECK(strstr(msg, counts[k]) != NULL);
      }
      /* The mesh of the first file is still there. */
      int n_nodes = -1, n_triangles = -1;
      CHECK(tfem_get_sizes(m, &n_nodes, &n_triangles, NULL) == TFEM_STATUS_OK && n_nodes == 3 && n_triangles == 1);
    }
    /* The same file cut short. */
    FILE *f = fopen(path, "w");
    if (f != NULL) {
      fputs("$MeshFormat\n4.1 0 8\n$EndMeshFormat\n$Nodes\n1 3 1 3\n2 1 0 3\n1\n2\n", f);
      fclose(f);
    }
    EXPECT_ERROR(m, tfem_load_gmsh(m, path, 0), TFEM_STATUS_IO, "$Nodes");
    int n_nodes = -1;
    CHECK(tfem_get_sizes(m, &n_nodes, NULL, NULL) == TFEM_STATUS_OK && n_nodes == 3);
    remove(path);
    tfem_destroy(m);
  }

  /* tfem_write_vtu: the solved uniaxial tension as a VTK XML grid of 6
   * points and 4 cells with its fields (their values read back in
   * tests/vtu.rs); before a solve and into a missing directory it is
   * refused, naming the reason and the path, and the results stay. */
  {
    char path[512];
    const char *tmp = getenv("TMPDIR");
    int here = 0;
    snprintf(path, sizeof path, "%s/tfem_api_test_%lx.vtu", tmp != NULL && tmp[0] != '\0' ? tmp : "/tmp",
             (unsigned long)(uintptr_t)&here);
    m = tfem_create();
    build(m, 0);
    restrain_and_load(m, 0);
    EXPECT_ERROR(m, tfem_write_vtu(m, path), TFEM_STATUS_INVALID_STATE, "solve");
    CHECK(tfem_write_vtu(m, NULL) == TFEM_STATUS_NULL_POINTER);
    CHECK(tfem_solve(m, NULL) == TFEM_STATUS_OK);
    CHECK(tfem_write_vtu(m, path) == TFEM_STATUS_OK);
    static char text[1 << 16];
    size_t n = 0;
    FILE *f = fopen(path, "r");
    CHECK(f != NULL);
    if (f != NULL) {
      n = fread(text, 1, sizeof text - 1, f);
      fclose(f);
    }
    text[n] = '\0';
    CHECK(strstr(text, "<VTKFile") != NULL && strstr(text, "UnstructuredGrid") != NULL);
    CHECK(strstr(text, "NumberOfPoints=\"6\"") != NULL && strstr(text, "NumberOfCells=\"4\"") != NULL);
    CHECK(strstr(text, "Name=\"displacement\"") != NULL && strstr(text, "Name=\"stress\"") != NULL);
    double u[12];
    CHECK(tfem_get_displacements(m, u, 12) == TFEM_STATUS_OK && fabs(u[4] - 0.02) < 1e-12);
    remove(path);
    EXPECT_ERROR(m, tfem_write_vtu(m, "/nonexistent/directory/out.vtu"), TFEM_STATUS_IO,
                 "/nonexistent/directory/out.vtu");
    /* The failed writes changed nothing. */
    double v[12];
    CHECK(tfem_get_displacements(m, v, 12) == TFEM_STATUS_OK && memcmp(u, v, sizeof u) == 0);
    tfem_destroy(m);
  }

  printf("api_test: %d passed, %d failed\n", passed, failed);
  printf("%d passed, %d failed\n", passed, failed);
  return failed == 0 ? 0 : 1;
}
