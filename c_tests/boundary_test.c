/* Regression tests through the C ABI for the defects a legacy user met at
 * the boundary, each in its own function named after the behaviour it
 * pins down: no answer is silently wrong, a failed call changes nothing,
 * no NaN or Inf comes back with OK, nothing is printed on stderr. Also the
 * outputs a host code needs (contact forces and gaps, the contact mesh
 * before a solve, external work, the thread count). */

#define _DEFAULT_SOURCE /* MAP_ANONYMOUS, MAP_NORESERVE */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <limits.h>
#include <stdint.h>
#include <string.h>
#include <sys/mman.h>
#include <sys/resource.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

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

static int has_warning(tfem_model *m, const char *needle) {
  int n = 0;
  if (tfem_warning_count(m, &n) != TFEM_STATUS_OK) return 0;
  for (int i = 0; i < n; ++i) {
    char w[512];
    if (tfem_get_warning(m, i, w, sizeof w) == TFEM_STATUS_OK && strstr(w, needle)) return 1;
  }
  return 0;
}

static int all_finite(const double *v, int n) {
  for (int i = 0; i < n; ++i)
    if (!isfinite(v[i])) return 0;
  return 1;
}

/* An nx x ny grid of the rectangle [x0, x0 + w] x [y0, y0 + h], two
 * triangles per cell (counter-clockwise), appended to the arrays. Tags its
 * left, right, bottom and top edges tag0 .. tag0 + 3. */
typedef struct {
  int nn, nt, ne;
  double xy[2 * 4096];
  int tri[3 * 4096], body[4096], edges[2 * 1024], tags[1024];
} mesh_t;

static void grid(mesh_t *g, int nx, int ny, double x0, double y0, double w, double h, int body,
                 int tag0) {
  int first = g->nn;
  for (int j = 0; j <= ny; ++j)
    for (int i = 0; i <= nx; ++i) {
      g->xy[2 * g->nn] = x0 + w * i / nx;
      g->xy[2 * g->nn + 1] = y0 + h * j / ny;
      g->nn++;
    }
#define ID(i, j) (first + (j) * (nx + 1) + (i))
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i) {
      int a = ID(i, j), b = ID(i + 1, j), c = ID(i + 1, j + 1), d = ID(i, j + 1);
      int t[6] = {a, b, c, a, c, d};
      memcpy(&g->tri[3 * g->nt], t, sizeof t);
      g->body[g->nt++] = body;
      g->body[g->nt++] = body;
    }
  for (int j = 0; j < ny; ++j) {
    int e[4] = {ID(0, j), ID(0, j + 1), ID(nx, j), ID(nx, j + 1)};
    memcpy(&g->edges[2 * g->ne], e, sizeof e);
    g->tags[g->ne++] = tag0;
    g->tags[g->ne++] = tag0 + 1;
  }
  for (int i = 0; i < nx; ++i) {
    int e[4] = {ID(i, 0), ID(i + 1, 0), ID(i, ny), ID(i + 1, ny)};
    memcpy(&g->edges[2 * g->ne], e, sizeof e);
    g->tags[g->ne++] = tag0 + 2;
    g->tags[g->ne++] = tag0 + 3;
  }
#undef ID
}

/* A model of the grids in g with their boundary edges; bodies 1 ..
 * `bodies` of Young's modulus e * ratio^(b - 1), nu = 0.3, plane `mode`. */
static tfem_model *model_of(const mesh_t *g, int bodies, double e, double ratio, int mode) {
  tfem_model *m = tfem_create();
  CHECK(tfem_set_mesh(m, g->nn, g->xy, g->nt, g->tri, g->body, 0) == TFEM_STATUS_OK);
  CHECK(tfem_set_boundary_edges(m, g->ne, g->edges, g->tags) == TFEM_STATUS_OK);
  for (int b = 1; b <= bodies; ++b, e *= ratio)
    CHECK(tfem_set_material(m, b, e, 0.3, mode) == TFEM_STATUS_OK);
  return m;
}

/* The block [0,4] x [0,1] (E = 1000, nu = 0.25, plane stress): left edge
 * (tag 1) u = 0, node 0 v = 0, traction 10 on the right (tag 2). Exact:
 * u = 10 x / E. Returns the largest error of u over the nodes. */
static mesh_t G;
static double tension_error(tfem_model *m) {
  double u[2 * 4096];
  if (tfem_get_displacements(m, u, 2 * G.nn) != TFEM_STATUS_OK) return INFINITY;
  double err = 0;
  for (int v = 0; v < G.nn; ++v) err = fmax(err, fabs(u[2 * v] - 10.0 * G.xy[2 * v] / 1000.0));
  return err;
}

static tfem_model *tension_block(const int *tri) {
  tfem_model *m = tfem_create();
  CHECK(tfem_set_mesh(m, G.nn, G.xy, G.nt, tri, G.body, 0) == TFEM_STATUS_OK);
  CHECK(tfem_set_boundary_edges(m, G.ne, G.edges, G.tags) == TFEM_STATUS_OK);
  CHECK(tfem_set_material(m, 1, 1000.0, 0.25, TFEM_PLANE_MODE_STRESS) == TFEM_STATUS_OK);
  CHECK(tfem_set_tempering(m, TFEM_TEMPERING_MODE_LAMBDA, 1e6) == TFEM_STATUS_OK);
  CHECK(tfem_fix_edges(m, 1, TFEM_COMPONENT_X, 0.0) == TFEM_STATUS_OK);
  CHECK(tfem_fix(m, 0, TFEM_COMPONENT_Y, 0.0) == TFEM_STATUS_OK);
  CHECK(tfem_add_traction(m, 2, 10.0, 0.0) == TFEM_STATUS_OK);
  return m;
}

static void a_clockwise_mesh_is_turned_and_solved_exactly(void) {
  int cw[3 * 4096], mixed[3 * 4096];
  for (int t = 0; t < G.nt; ++t) {
    int *c = &G.tri[3 * t];
    int r[3] = {c[0], c[2], c[1]};
    memcpy(&cw[3 * t], r, sizeof r);
    memcpy(&mixed[3 * t], t % 3 == 0 ? r : c, sizeof r);
  }
  tfem_model *ccw = tension_block(G.tri);
  CHECK(tfem_solve(ccw, NULL) == TFEM_STATUS_OK && tension_error(ccw) < 1e-12);
  CHECK(!has_warning(ccw, "clockwise"));
  for (int k = 0; k < 2; ++k) {
    tfem_model *m = tension_block(k == 0 ? cw : mixed);
    CHECK(has_warning(m, "numbered clockwise") && has_warning(m, "body 1"));
    CHECK(!has_warning(m, "inverted"));
    CHECK(tfem_solve(m, NULL) == TFEM_STATUS_OK);
    CHECK(tension_error(m) < 1e-12);
    double J[4096];
    CHECK(tfem_get_element_jacobians(m, J, G.nt) == TFEM_STATUS_OK);
    int positive = 1;
    for (int t = 0; t < G.nt; ++t) positive &= J[t] > 0.0;
    CHECK(positive);
    tfem_destroy(m);
  }
  tfem_destroy(ccw);
}

/* A triangle given twice (here in the other orientation) would count its
 * stiffness twice: refused naming both, and the model keeps its mesh. */
static void a_triangle_given_twice_is_refused_and_the_mesh_kept(void) {
  tfem_model *m = tension_block(G.tri);
  int tri[3 * 4096 + 3], body[4096 + 1];
  memcpy(tri, G.tri, sizeof(int) * 3 * G.nt);
  memcpy(body, G.body, sizeof(int) * G.nt);
  int again[3] = {G.tri[3 * 5], G.tri[3 * 5 + 2], G.tri[3 * 5 + 1]};
  memcpy(&tri[3 * G.nt], again, sizeof again);
  body[G.nt] = 1;
  char needle[64];
  snprintf(needle, sizeof needle, "triangle %d (nodes", G.nt);
  EXPECT_ERROR(m, tfem_set_mesh(m, G.nn, G.xy, G.nt + 1, tri, body, 0), TFEM_STATUS_INVALID_MESH,
               needle);
  EXPECT_ERROR(m, tfem_set_mesh(m, G.nn, G.xy, G.nt + 1, tri, body, 0), TFEM_STATUS_INVALID_MESH,
               "repeats triangle 5");
  CHECK(tfem_solve(m, NULL) == TFEM_STATUS_OK && tension_error(m) < 1e-12);
  tfem_destroy(m);
}

/* A host that loaded its mesh from a file reads it back as the model
 * holds it: nodes, triangles (counter-clockwise, in the index base) with
 * their bodies, boundary edges with their tags; a short buffer writes
 * nothing. */
static void the_mesh_reads_back_as_the_model_holds_it(void) {
  int count = -1;
  tfem_model *none = tfem_create();
  EXPECT_ERROR(none, tfem_get_boundary_edge_count(none, &count), TFEM_STATUS_INVALID_STATE, "no mesh");
  tfem_destroy(none);
  int cw[3 * 4096];
  for (int t = 0; t < G.nt; ++t) {
    int *c = &G.tri[3 * t];
    int r[3] = {c[0], c[2], c[1]};
    memcpy(&cw[3 * t], r, sizeof r);
  }
  tfem_model *m = tension_block(cw);
  static double xy[2 * 4096];
  static int tri[3 * 4096], body[4096], edges[2 * 1024], tags[1024];
  CHECK(tfem_get_mesh_nodes(m, xy, 2 * (size_t)G.nn) == TFEM_STATUS_OK);
  CHECK(memcmp(xy, G.xy, sizeof(double) * 2 * G.nn) == 0);
  CHECK(tfem_get_mesh_triangles(m, tri, 3 * (size_t)G.nt, body, (size_t)G.nt) == TFEM_STATUS_OK);
  int same = 1;
  for (int k = 0; k < 3 * G.nt; ++k) same &= tri[k] == G.tri[k];
  for (int t = 0; t < G.nt; ++t) same &= body[t] == G.body[t];
  CHECK(same); /* turned back to the counter-clockwise numbering */
  CHECK(tfem_get_mesh_triangles(m, tri, 3 * (size_t)G.nt, NULL, 0) == TFEM_STATUS_OK);
  CHECK(tfem_get_boundary_edge_count(m, &count) == TFEM_STATUS_OK && count == G.ne);
  CHECK(tfem_get_boundary_edges(m, edges, 2 * (size_t)count, tags, (size_t)count) == TFEM_STATUS_OK);
  CHECK(memcmp(edges, G.edges, sizeof(int) * 2 * G.ne) == 0 && memcmp(tags, G.tags, sizeof(int) * G.ne) == 0);
  edges[0] = -7;
  EXPECT_ERROR(m, tfem_get_boundary_edges(m, edges, 2 * (size_t)count, tags, (size_t)count - 1),
               TFEM_STATUS_BUFFER_TOO_SMALL, "tags");
  CHECK(edges[0] == -7);
  EXPECT_ERROR(m, tfem_get_mesh_triangles(m, tri, 3 * (size_t)G.nt - 1, body, (size_t)G.nt),
               TFEM_STATUS_BUFFER_TOO_SMALL, "triangles");
  EXPECT_ERROR(m, tfem_get_mesh_nodes(m, NULL, 0), TFEM_STATUS_NULL_POINTER, "xy");
  tfem_destroy(m);
}

static void a_fold_inside_a_counter_clockwise_body_stays_inverted(void) {
  double xy[2 * 4096];
  memcpy(xy, G.xy, sizeof xy);
  /* Node of row 1, column 1 pushed beyond its right neighbour. */
  int nx = 16, v = 1 * (nx + 1) + 1;
  xy[2 * v] += 1.5 * 4.0 / nx;
  tfem_model *m = tfem_create();
  CHECK(tfem_set_mesh(m, G.nn, xy, G.nt, G.tri, G.body, 0) == TFEM_STATUS_OK);
  CHECK(has_warning(m, "inverted") && !has_warning(m, "numbered clockwise"));
  double J[4096];
  int negative = 0;
  CHECK(tfem_get_element_jacobians(m, J, G.nt) == TFEM_STATUS_OK);
  for (int t = 0; t < G.nt; ++t) negative += J[t] < 0.0;
  CHECK(negative > 0);
  tfem_destroy(m);
}

static void resetting_boundary_edges_never_drops_a_load(void) {
  tfem_model *m = tension_block(G.tri);
  /* The edges without the loaded tag 2: refused, naming it. */
  int keep = 0, edges[2 * 1024], tags[1024];
  for (int e = 0; e < G.ne; ++e)
    if (G.tags[e] != 2) {
      edges[2 * keep] = G.edges[2 * e];
      edges[2 * keep + 1] = G.edges[2 * e + 1];
      tags[keep++] = G.tags[e];
    }
  EXPECT_ERROR(m, tfem_set_boundary_edges(m, keep, edges, tags), TFEM_STATUS_INVALID_ARGUMENT,
               "tag 2");
  /* Tag 2 moved onto an interior edge (the diagonal of the first cell). */
  int interior[2] = {G.tri[0], G.tri[2]}, two = 2;
  edges[2 * keep] = interior[0];
  edges[2 * keep + 1] = interior[1];
  tags[keep] = two;
  EXPECT_ERROR(m, tfem_set_boundary_edges(m, keep + 1, edges, tags),
               TFEM_STATUS_INVALID_ARGUMENT, "interior");
  /* Nothing changed: the load still acts. */
  CHECK(tfem_solve(m, NULL) == TFEM_STATUS_OK && tension_error(m) < 1e-12);
  tfem_destroy(m);
}

static void boundary_groups_can_be_added_one_call_at_a_time(void) {
  tfem_model *m = tfem_create();
  CHECK(tfem_set_mesh(m, G.nn, G.xy, G.nt, G.tri, G.body, 0) == TFEM_STATUS_OK);
  for (int tag = 1; tag <= 4; ++tag) {
    int n = 0, edges[2 * 1024], tags[1024];
    for (int e = 0; e < G.ne; ++e)
      if (G.tags[e] == tag) {
        edges[2 * n] = G.edges[2 * e];
        edges[2 * n + 1] = G.edges[2 * e + 1];
        tags[n++] = tag;
      }
    CHECK(tfem_add_boundary_edges(m, n, edges, tags) == TFEM_STATUS_OK);
    if (tag == 2) {
      EXPECT_ERROR(m, tfem_add_boundary_edges(m, n, edges, tags), TFEM_STATUS_INVALID_MESH,
                   "twice");
    }
  }
  CHECK(tfem_set_material(m, 1, 1000.0, 0.25, TFEM_PLANE_MODE_STRESS) == TFEM_STATUS_OK);
  CHECK(tfem_set_tempering(m, TFEM_TEMPERING_MODE_LAMBDA, 1e6) == TFEM_STATUS_OK);
  CHECK(tfem_fix_edges(m, 1, TFEM_COMPONENT_X, 0.0) == TFEM_STATUS_OK);
  CHECK(tfem_fix(m, 0, TFEM_COMPONENT_Y, 0.0) == TFEM_STATUS_OK);
  CHECK(tfem_add_traction(m, 2, 10.0, 0.0) == TFEM_STATUS_OK);
  CHECK(tfem_solve(m, NULL) == TFEM_STATUS_OK && tension_error(m) < 1e-12);
  tfem_destroy(m);
}

static void a_dof_prescribed_twice_with_different_values_is_refused(void) {
  tfem_model *m = tension_block(G.tri);
  CHECK(tfem_fix(m, 0, TFEM_COMPONENT_X, 0.0) == TFEM_STATUS_OK); /* same value: fine */
  EXPECT_ERROR(m, tfem_fix(m, 0, TFEM_COMPONENT_X, 0.5), TFEM_STATUS_INVALID_ARGUMENT, "node 0");
  EXPECT_ERROR(m, tfem_fix_edges(m, 1, TFEM_COMPONENT_X, 0.25), TFEM_STATUS_INVALID_ARGUMENT,
               "already prescribed");
  CHECK(tfem_solve(m, NULL) == TFEM_STATUS_OK && tension_error(m) < 1e-12);
  tfem_destroy(m);
}

/* Two 8 x 2 blocks touching along y = 0 (separate nodes): lower [0,1] x
 * [-0.25, 0] (body 1, E = 1e10), upper [0,1] x [0, 0.25] (body 2,
 * E = 1e11), nu = 0.3, plane strain; lower bottom v = 0, x held at the
 * left node of each block; pressure 1e7 on the upper top, and a force of
 * 3e6 N/m lifting its top left corner (node 45), so that the interface
 * opens at the left and the active set changes. */
static mesh_t B;
static tfem_model *two_blocks_unpaired(void) {
  tfem_model *m = model_of(&B, 2, 1e10, 10.0, TFEM_PLANE_MODE_STRAIN);
  CHECK(tfem_fix_edges(m, 12, TFEM_COMPONENT_Y, 0.0) == TFEM_STATUS_OK);
  CHECK(tfem_fix(m, 0, TFEM_COMPONENT_X, 0.0) == TFEM_STATUS_OK);
  CHECK(tfem_fix(m, 27, TFEM_COMPONENT_X, 0.0) == TFEM_STATUS_OK);
  CHECK(tfem_add_pressure(m, 23, 1e7) == TFEM_STATUS_OK);
  CHECK(tfem_add_nodal_force(m, 45, 0.0, 3e6) == TFEM_STATUS_OK);
  return m;
}
static tfem_model *two_blocks(void) {
  tfem_model *m = two_blocks_unpaired();
  CHECK(tfem_add_contact_pair(m, 13, 22, NULL) == TFEM_STATUS_OK);
  return m;
}

/* Every result of a contact solve, bit for bit. */
typedef struct {
  double u[2 * 64], r[2 * 64], s[3 * 64], p[64], k[1024];
  int active[64];
  tfem_contact_report rep;
} results_t;

static int results_of(tfem_model *m, results_t *out) {
  memset(out, 0, sizeof *out);
  int64_t n = 0, nnz = 0;
  int ok = tfem_get_displacements(m, out->u, 2 * B.nn) == TFEM_STATUS_OK &&
           tfem_get_reactions(m, out->r, 2 * B.nn) == TFEM_STATUS_OK &&
           tfem_get_element_stresses(m, out->s, 3 * B.nt) == TFEM_STATUS_OK &&
           tfem_get_contact_pressure(m, out->p, 64) == TFEM_STATUS_OK &&
           tfem_get_contact_active(m, out->active, 64) == TFEM_STATUS_OK &&
           tfem_get_contact_report(m, &out->rep) == TFEM_STATUS_OK &&
           tfem_get_system_matrix_size(m, &n, &nnz) == TFEM_STATUS_OK && nnz <= 1024;
  if (!ok) return 0;
  int64_t cp[256], ri[1024], dofs[256];
  return n < 256 && tfem_get_system_matrix(m, cp, 256, ri, 1024, out->k, 1024, dofs, 256) ==
                        TFEM_STATUS_OK;
}

static int same_results(const results_t *a, const results_t *b) {
  return memcmp(a->u, b->u, sizeof a->u) == 0 && memcmp(a->r, b->r, sizeof a->r) == 0 &&
         memcmp(a->s, b->s, sizeof a->s) == 0 && memcmp(a->p, b->p, sizeof a->p) == 0 &&
         memcmp(a->k, b->k, sizeof a->k) == 0 && memcmp(a->active, b->active, sizeof a->active) == 0 &&
         a->rep.iterations == b->rep.iterations && a->rep.active == b->rep.active &&
         a->rep.contact_length == b->rep.contact_length &&
         a->rep.max_penetration == b->rep.max_penetration;
}

static void changing_the_ordering_or_the_threads_keeps_every_result(void) {
  tfem_model *m = two_blocks();
  results_t before, after;
  CHECK(tfem_solve_contact(m, NULL, NULL) == TFEM_STATUS_OK);
  CHECK(results_of(m, &before));
  CHECK(tfem_set_ordering(m, TFEM_ORDERING_MODE_AMD, 0) == TFEM_STATUS_OK);
  CHECK(tfem_set_threads(m, 1) == TFEM_STATUS_OK);
  int threads = 0;
  CHECK(tfem_get_threads(m, &threads) == TFEM_STATUS_OK && threads == 1);
  CHECK(results_of(m, &after) && same_results(&before, &after));
  /* Solved again on one thread with AMD: the same answer to round-off. */
  CHECK(tfem_solve_contact(m, NULL, NULL) == TFEM_STATUS_OK && results_of(m, &after));
  double err = 0, scale = 0;
  for (int i = 0; i < 2 * B.nn; ++i) {
    err = fmax(err, fabs(after.u[i] - before.u[i]));
    scale = fmax(scale, fabs(before.u[i]));
  }
  CHECK(err <= 1e-10 * scale && memcmp(after.active, before.active, sizeof after.active) == 0);
  CHECK(tfem_set_threads(m, 0) == TFEM_STATUS_OK && tfem_get_threads(m, &threads) == TFEM_STATUS_OK &&
        threads >= 1);
  EXPECT_ERROR(m, tfem_set_threads(m, -2), TFEM_STATUS_INVALID_ARGUMENT, "threads = -2");
  EXPECT_ERROR(m, tfem_set_threads(m, 2147483647), TFEM_STATUS_INVALID_ARGUMENT, "more than 1024");
  tfem_destroy(m);
}

static void a_failed_solve_keeps_every_result_and_changes_no_later_solve(void) {
  tfem_contact_options capped, refactorising, singular;
  tfem_contact_options_default(&capped);
  capped.max_iterations = 1;
  tfem_contact_options_default(&refactorising);
  refactorising.refactorize = 1;
  singular = refactorising;
  singular.contact_modulus = 1e-200;

  tfem_model *fresh = two_blocks();
  results_t expected, got;
  CHECK(tfem_solve_contact(fresh, &refactorising, NULL) == TFEM_STATUS_OK);
  CHECK(results_of(fresh, &expected));

  tfem_model *m = two_blocks();
  CHECK(tfem_solve_contact(m, NULL, NULL) == TFEM_STATUS_OK);
  results_t before;
  CHECK(results_of(m, &before));
  EXPECT_ERROR(m, tfem_solve_contact(m, &capped, NULL), TFEM_STATUS_NOT_CONVERGED, "history");
  CHECK(results_of(m, &got) && same_results(&before, &got));
  CHECK(tfem_solve_contact(m, &singular, NULL) != TFEM_STATUS_OK);
  CHECK(results_of(m, &got) && same_results(&before, &got));
  /* A later solve gives what it gives on a fresh model, bit for bit. */
  CHECK(tfem_solve_contact(m, &refactorising, NULL) == TFEM_STATUS_OK);
  CHECK(results_of(m, &got) && same_results(&expected, &got));
  tfem_destroy(m);
  tfem_destroy(fresh);
}

static void no_nan_or_inf_comes_back_with_ok(void) {
  /* Huge loads: the displacements are finite, so is the residual. */
  tfem_model *m = tension_block(G.tri);
  CHECK(tfem_clear_loads(m) == TFEM_STATUS_OK);
  CHECK(tfem_add_traction(m, 2, 1e300, 0.0) == TFEM_STATUS_OK);
  tfem_solve_info info;
  tfem_status s = tfem_solve(m, &info);
  CHECK(s == TFEM_STATUS_OK || s == TFEM_STATUS_NUMERICAL_FAILURE);
  if (s == TFEM_STATUS_OK) CHECK(isfinite(info.relative_residual) && isfinite(info.condition_estimate));
  double out[3 * 4096];
  s = tfem_get_element_stresses(m, out, 3 * G.nt);
  CHECK(s != TFEM_STATUS_OK || all_finite(out, 3 * G.nt));
  s = tfem_get_reactions(m, out, 2 * G.nn);
  CHECK(s != TFEM_STATUS_OK || all_finite(out, 2 * G.nn));
  double w = 0;
  s = tfem_get_external_work(m, &w);
  CHECK(s == TFEM_STATUS_NUMERICAL_FAILURE || (s == TFEM_STATUS_OK && isfinite(w)));
  tfem_destroy(m);

  /* A residual that used to underflow to 0: the solution underflows
   * (1e-200 / 1e155), so the residual says it is wrong (~1). */
  m = tension_block(G.tri);
  CHECK(tfem_set_material(m, 1, 1e155, 0.25, TFEM_PLANE_MODE_STRESS) == TFEM_STATUS_OK);
  CHECK(tfem_clear_loads(m) == TFEM_STATUS_OK);
  CHECK(tfem_add_traction(m, 2, 1e-200, 0.0) == TFEM_STATUS_OK);
  CHECK(tfem_solve(m, &info) == TFEM_STATUS_OK && info.relative_residual > 0.5 &&
        isfinite(info.relative_residual));
  tfem_destroy(m);

  /* Coordinates whose area overflows: refused, naming a triangle. */
  double xy[2 * 4096];
  for (int i = 0; i < 2 * G.nn; ++i) xy[i] = G.xy[i] * 1e300;
  m = tfem_create();
  EXPECT_ERROR(m, tfem_set_mesh(m, G.nn, xy, G.nt, G.tri, G.body, 0), TFEM_STATUS_INVALID_MESH,
               "triangle 0");
  tfem_destroy(m);

  /* Contact under a pressure at the edge of double precision. */
  m = two_blocks();
  CHECK(tfem_clear_loads(m) == TFEM_STATUS_OK && tfem_add_pressure(m, 23, 1.7e308) == TFEM_STATUS_OK);
  tfem_contact_report rep;
  s = tfem_solve_contact(m, NULL, &rep);
  CHECK(s != TFEM_STATUS_OK || (isfinite(rep.max_penetration) && isfinite(rep.contact_length)));
  if (s == TFEM_STATUS_OK) {
    CHECK(tfem_get_contact_pressure(m, out, 64) != TFEM_STATUS_OK || all_finite(out, rep.elements));
  }
  tfem_destroy(m);
}

static void messages_stay_short_and_the_thread_slot_is_cleared(void) {
  double xy[6] = {0, 0, 1, 0, 0, 1}, k[36];
  char msg[512];
  CHECK(tfem_element_stiffness(xy, -4.9e-324, 0.3, 0, 0.0, k) == TFEM_STATUS_INVALID_MATERIAL);
  CHECK(tfem_last_error(NULL, msg, sizeof msg) == TFEM_STATUS_OK && strlen(msg) < 120 &&
        strstr(msg, "e-324") != NULL);
  CHECK(tfem_element_stiffness(xy, 1.0, 0.3, 0, 0.0, k) == TFEM_STATUS_OK);
  CHECK(tfem_last_error(NULL, msg, sizeof msg) == TFEM_STATUS_OK && msg[0] == '\0');
  CHECK(tfem_last_error_length(NULL) == 1);
}

/* A private directory for the files of the Gmsh tests, made once. */
static char gmsh_dir[256];
static const char *gmsh_path(const char *name) {
  static char path[512];
  if (gmsh_dir[0] == '\0') {
    const char *tmp = getenv("TMPDIR");
    snprintf(gmsh_dir, sizeof gmsh_dir, "%s/tfem_boundary_XXXXXX",
             tmp != NULL && tmp[0] != '\0' ? tmp : "/tmp");
    if (mkdtemp(gmsh_dir) == NULL) gmsh_dir[0] = '\0';
  }
  snprintf(path, sizeof path, "%s/%s", gmsh_dir, name);
  return path;
}

/* Found by an outside probe of the Gmsh reader: tfem_load_gmsh of a FIFO
 * waited forever in open() for a writer (the regular-file check came
 * after the open). It is an IO error naming the path and what it is. An
 * alarm turns a hang into a failed run, not a stalled suite. */
static void loading_a_fifo_is_an_io_error_not_a_hang(void) {
  const char *path = gmsh_path("fifo.msh");
  CHECK(mkfifo(path, 0600) == 0);
  tfem_model *m = tfem_create();
  alarm(30);
  EXPECT_ERROR(m, tfem_load_gmsh(m, path, 0), TFEM_STATUS_IO, "not a regular file but a FIFO");
  EXPECT_ERROR(m, tfem_load_gmsh(m, path, 0), TFEM_STATUS_IO, "fifo.msh");
  alarm(0);
  tfem_destroy(m);
  unlink(path);
}

/* The unit square as two triangles of body 7, its sides in physical
 * curves 11 (bottom), 12 (right), 13 (top) and 14 (left), every side also
 * in group 99 (the whole boundary) and the top also in group 50. */
static const char SQUARE_MSH[] =
    "$MeshFormat\n4.1 0 8\n$EndMeshFormat\n"
    "$Entities\n0 4 1 0\n"
    "1 0 0 0 1 0 0 2 11 99 0\n"
    "2 1 0 0 1 1 0 2 12 99 0\n"
    "3 0 1 0 1 1 0 3 13 99 50 0\n"
    "4 0 0 0 0 1 0 2 14 99 0\n"
    "1 0 0 0 1 1 0 1 7 0\n"
    "$EndEntities\n"
    "$Nodes\n1 4 1 4\n2 1 0 4\n1\n2\n3\n4\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n$EndNodes\n"
    "$Elements\n5 6 1 6\n"
    "1 1 1 1\n1 1 2\n1 2 1 1\n2 2 3\n1 3 1 1\n3 3 4\n1 4 1 1\n4 4 1\n"
    "2 1 2 2\n5 1 2 3\n6 1 3 4\n"
    "$EndElements\n";

/* Writes `text` to the file `name` of the private directory; its path. */
static const char *gmsh_file(const char *name, const char *text) {
  const char *path = gmsh_path(name);
  FILE *f = fopen(path, "wb");
  if (f != NULL) {
    fputs(text, f);
    fclose(f);
  }
  return path;
}

/* Found by an outside probe: a path that is not UTF-8 (a file named in
 * Latin-1) was refused ("path is not valid UTF-8") although the file
 * exists; on Unix a path is bytes and is taken as such. */
static void a_gmsh_file_named_in_latin_1_is_loaded(void) {
  const char *path = gmsh_file("lat\xe9.msh", SQUARE_MSH);
  tfem_model *m = tfem_create();
  CHECK(tfem_load_gmsh(m, path, 0) == TFEM_STATUS_OK);
  int nn = 0, nt = 0, nc = 0;
  CHECK(tfem_get_sizes(m, &nn, &nt, &nc) == TFEM_STATUS_OK && nn == 4 && nt == 2);
  tfem_destroy(m);
  unlink(path);
}

/* Found by an outside probe: the empty path gave ": No such file or
 * directory", naming nothing. */
static void an_empty_gmsh_path_is_named_as_such(void) {
  tfem_model *m = tfem_create();
  EXPECT_ERROR(m, tfem_load_gmsh(m, "", 0), TFEM_STATUS_IO, "the path is empty");
  tfem_destroy(m);
}

/* Found by an outside probe: the name of an unknown section was quoted
 * whole and raw, so a 10 MB token gave a 10 MB message and a binary one
 * embedded a NUL (a C caller saw the message cut) and control bytes. File
 * text is quoted short and printable: the whole message fits in a few
 * hundred bytes, with no control character before its terminating NUL. */
static void a_corrupt_gmsh_file_gets_a_short_printable_message(void) {
  static const char head[] = "$MeshFormat\n4.1 0 8\n$EndMeshFormat\n$Elements";
  for (int k = 0; k < 2; ++k) {
    const char *path = gmsh_path("corrupt.msh");
    FILE *f = fopen(path, "wb");
    if (f == NULL) {
      CHECK(f != NULL);
      return;
    }
    fwrite(head, 1, sizeof head - 1, f);
    if (k == 0) {
      for (int i = 0; i < 300; ++i) fputc(i % 256, f); /* NUL and control bytes */
    } else {
      for (int i = 0; i < 1000000; ++i) fputc('x', f);
    }
    fputs("\n$EndElements\n", f);
    fclose(f);
    tfem_model *m = tfem_create();
    CHECK(tfem_load_gmsh(m, path, 0) == TFEM_STATUS_IO);
    size_t length = tfem_last_error_length(m);
    char msg[512];
    tfem_last_error(m, msg, sizeof msg);
    CHECK(length <= 400 && strlen(msg) + 1 == length);
    int printable = 1;
    for (const unsigned char *c = (const unsigned char *)msg; *c != '\0'; ++c)
      if (*c < 0x20 || *c == 0x7f) printable = 0;
    CHECK(printable);
    if (length > 400 || !printable) printf("  message of %zu bytes: %.200s\n", length, msg);
    tfem_destroy(m);
    unlink(path);
  }
}

/* Found by an outside probe: errors and warnings of a Gmsh file named
 * tfem's internal indices ("boundary edge 2 (nodes 1, 3) is not a side of
 * any triangle", "not used by any triangle: 4") where the file has node
 * tags 1001… and element tags: they name the file's tags now. */
static void gmsh_messages_name_the_files_node_and_element_tags(void) {
  static const char head[] =
      "$MeshFormat\n4.1 0 8\n$EndMeshFormat\n"
      "$Entities\n0 1 1 0\n1 0 0 0 1 1 0 1 11 0\n1 0 0 0 1 1 0 1 7 0\n$EndEntities\n"
      "$Nodes\n1 5 1001 1007\n2 1 0 5\n1001\n1002\n1003\n1004\n1007\n"
      "0 0 0\n1 0 0\n1 1 0\n0 1 0\n0.5 0.5 0\n$EndNodes\n"
      "$Elements\n2 4 21 32\n2 1 2 2\n21 1001 1002 1003\n22 1001 1003 1004\n"
      "1 1 1 2\n31 1001 1002\n";
  char text[1024];
  /* Line 32 joins opposite corners: no side of a triangle. */
  snprintf(text, sizeof text, "%s32 1002 1004\n$EndElements\n", head);
  tfem_model *m = tfem_create();
  EXPECT_ERROR(m, tfem_load_gmsh(m, gmsh_file("renumbered.msh", text), 0),
               TFEM_STATUS_INVALID_MESH,
               "Gmsh line element 32 of curve 1 in physical group 11 (Gmsh nodes 1002, 1004) is not "
               "a side of any triangle");
  /* A good line 32: Gmsh node 1007 (index 4) is the unused one. */
  snprintf(text, sizeof text, "%s32 1002 1003\n$EndElements\n", head);
  CHECK(tfem_load_gmsh(m, gmsh_file("renumbered.msh", text), 0) == TFEM_STATUS_OK);
  CHECK(has_warning(m, "not used by any triangle get no unknowns: 4 (Gmsh node 1007)"));
  tfem_destroy(m);
  unlink(gmsh_path("renumbered.msh"));
}

/* An MSH 2.2 file gave TFEM_STATUS_IO ("version \"2.2\" is not
 * supported") although the header promises TFEM_STATUS_INVALID_MESH for
 * unsupported content: it is unsupported content now, the message says
 * how to convert the file, and the mesh loaded before stays. */
static void an_msh_2_2_file_is_unsupported_content_saying_how_to_convert_it(void) {
  static const char MSH22[] = "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n"
                              "$Nodes\n3\n1 0 0 0\n2 1 0 0\n3 0 1 0\n$EndNodes\n"
                              "$Elements\n1\n1 2 2 7 1 1 2 3\n$EndElements\n";
  tfem_model *m = tfem_create();
  CHECK(tfem_load_gmsh(m, gmsh_file("square.msh", SQUARE_MSH), 0) == TFEM_STATUS_OK);
  const char *path = gmsh_file("msh22.msh", MSH22);
  EXPECT_ERROR(m, tfem_load_gmsh(m, path, 0), TFEM_STATUS_INVALID_MESH, "MSH 2.2 is not supported");
  EXPECT_ERROR(m, tfem_load_gmsh(m, path, 0), TFEM_STATUS_INVALID_MESH,
               "gmsh old.msh -save -format msh41 -o new.msh");
  EXPECT_ERROR(m, tfem_load_gmsh(m, path, 0), TFEM_STATUS_INVALID_MESH, "Mesh.MshFileVersion = 4.1");
  int nn = 0, nt = 0, nc = 0;
  CHECK(tfem_get_sizes(m, &nn, &nt, &nc) == TFEM_STATUS_OK && nn == 4 && nt == 2);
  tfem_destroy(m);
  unlink(path);
  unlink(gmsh_path("square.msh"));
}

/* An error about an element named the Gmsh entity alone ("surface 1 has
 * elements of Gmsh type 3"), or not even that ("node 3 has z = 0.5"),
 * where the user knows the part by its physical group: the entity's
 * group is named now, by tag and by its name in $PhysicalNames. One
 * element of Gmsh type `type` with `nodes` on surface 1 (group 7,
 * "plate"), its third node at height `z3`. */
static tfem_status load_one_gmsh_element(tfem_model *m, int type, const char *nodes, double z3) {
  char text[1024];
  snprintf(text, sizeof text,
           "$MeshFormat\n4.1 0 8\n$EndMeshFormat\n"
           "$PhysicalNames\n1\n2 7 \"plate\"\n$EndPhysicalNames\n"
           "$Entities\n0 0 1 0\n1 0 0 0 1 1 0 1 7 0\n$EndEntities\n"
           "$Nodes\n1 4 1 4\n2 1 0 4\n1\n2\n3\n4\n0 0 0\n1 0 0\n1 1 %g\n0 1 0\n$EndNodes\n"
           "$Elements\n1 1 1 1\n2 1 %d 1\n1 %s\n$EndElements\n",
           z3, type, nodes);
  tfem_status st = tfem_load_gmsh(m, gmsh_file("one_element.msh", text), 0);
  unlink(gmsh_path("one_element.msh"));
  return st;
}

static void a_gmsh_element_error_names_its_physical_group(void) {
  tfem_model *m = tfem_create();
  EXPECT_ERROR(m, load_one_gmsh_element(m, 3, "1 2 3 4", 0.0), TFEM_STATUS_INVALID_MESH,
               "surface 1 in physical group 7 \"plate\" has elements of Gmsh type 3 (4-node quadrangles)");
  EXPECT_ERROR(m, load_one_gmsh_element(m, 2, "1 2 2", 0.0), TFEM_STATUS_INVALID_MESH,
               "triangle 0 (Gmsh element 1 of surface 1 in physical group 7 \"plate\"): node 1 (Gmsh node "
               "2) is repeated");
  EXPECT_ERROR(m, load_one_gmsh_element(m, 2, "1 2 3", 0.5), TFEM_STATUS_INVALID_MESH,
               "node 3 of surface 1 in physical group 7 \"plate\" has z = 0.5");
  CHECK(load_one_gmsh_element(m, 2, "1 2 3", 0.0) == TFEM_STATUS_OK);
  tfem_destroy(m);
}

/* Found by an outside probe: only the first physical group of each
 * Gmsh curve was kept, the others dropped without a word, so with the top
 * side in groups 13, 99 (the whole boundary) and 50, tfem_add_pressure(50)
 * and tfem_fix_edges(99) failed "no boundary edge has tag …". Every group
 * of a curve now tags its edges. The square of SQUARE_MSH (plane strain,
 * nu = 0.3) under a pressure on `pressed`, x fixed on `fix_x` and y on
 * `fix_y`: whether every element's stress is (sxx, -p, 0). */
static int square_in_groups_stress_is(int pressed, int fix_x, int fix_y, double sxx_over_p) {
  const double p = 1e6;
  tfem_model *m = tfem_create();
  double s[6] = {0};
  int ok = tfem_load_gmsh(m, gmsh_file("square.msh", SQUARE_MSH), 0) == TFEM_STATUS_OK &&
           tfem_set_material(m, 7, 1e9, 0.3, 0) == TFEM_STATUS_OK &&
           tfem_fix_edges(m, fix_x, 0, 0.0) == TFEM_STATUS_OK &&
           tfem_fix_edges(m, fix_y, 1, 0.0) == TFEM_STATUS_OK &&
           tfem_add_pressure(m, pressed, p) == TFEM_STATUS_OK &&
           tfem_solve(m, NULL) == TFEM_STATUS_OK &&
           tfem_get_element_stresses(m, s, 6) == TFEM_STATUS_OK;
  if (!ok) {
    char msg[512];
    tfem_last_error(m, msg, sizeof msg);
    printf("  square in groups (%d, %d, %d): %s\n", pressed, fix_x, fix_y, msg);
  }
  for (int t = 0; t < 2; ++t)
    ok = ok && fabs(s[3 * t] - sxx_over_p * p) < 1e-9 * p && fabs(s[3 * t + 1] + p) < 1e-9 * p &&
         fabs(s[3 * t + 2]) < 1e-9 * p;
  tfem_destroy(m);
  unlink(gmsh_path("square.msh"));
  return ok;
}

static void a_pressure_on_a_gmsh_curves_second_group_acts(void) {
  CHECK(square_in_groups_stress_is(50, 14, 11, 0.0));
}

static void a_pressure_on_a_gmsh_curves_first_group_still_acts(void) {
  CHECK(square_in_groups_stress_is(11, 14, 13, 0.0));
}

/* x fixed on every side through group 99: eps_xx = 0, so in plane strain
 * sxx = nu/(1 - nu) syy (0 with the left side only). */
static void fixing_a_gmsh_group_of_every_curve_fixes_the_whole_boundary(void) {
  CHECK(square_in_groups_stress_is(50, 99, 11, -0.3 / 0.7));
}

/* Found by the same probe: a physical point group (no place in the model)
 * was dropped without a word; a warning names it. */
static void a_gmsh_physical_point_group_is_named_in_a_warning(void) {
  static const char msh[] =
      "$MeshFormat\n4.1 0 8\n$EndMeshFormat\n"
      "$Entities\n1 0 1 0\n5 0.5 0.5 0 1 30\n1 0 0 0 1 1 0 1 7 0\n$EndEntities\n"
      "$Nodes\n1 3 1 3\n2 1 0 3\n1\n2\n3\n0 0 0\n1 0 0\n0 1 0\n$EndNodes\n"
      "$Elements\n1 1 1 1\n2 1 2 1\n1 1 2 3\n$EndElements\n";
  tfem_model *m = tfem_create();
  CHECK(tfem_load_gmsh(m, gmsh_file("point_group.msh", msh), 0) == TFEM_STATUS_OK);
  CHECK(has_warning(m, "point 5 (group 30)"));
  tfem_destroy(m);
  unlink(gmsh_path("point_group.msh"));
}

/* Reads warning i through tfem_get_warning_size: the size counts the NUL,
 * a buffer of that size takes the warning whole, one byte less truncates
 * it (BUFFER_TOO_SMALL). Returns the warning (malloc'd) or NULL. */
static char *warning_by_its_size(tfem_model *m, int i) {
  size_t size = 0;
  CHECK(tfem_get_warning_size(m, i, &size) == TFEM_STATUS_OK && size >= 1);
  char *w = malloc(size + 1);
  if (w == NULL) return NULL;
  if (size > 1) CHECK(tfem_get_warning(m, i, w, size - 1) == TFEM_STATUS_BUFFER_TOO_SMALL && strlen(w) + 2 == size);
  CHECK(tfem_get_warning(m, i, w, size) == TFEM_STATUS_OK && strlen(w) + 1 == size);
  return w;
}

/* The size of a warning, for a buffer that holds all of it (the Fortran
 * helper copied warnings through 4096 bytes, and nothing gave their
 * size): tfem_get_warning_size counts it with its NUL and a buffer of that
 * size takes it whole, also past 4096 bytes. The long warning: automatic
 * pairing leaving out a tag whose edges bound 1000 bodies names the bodies
 * (6 KB). (It was a Gmsh point in 1500 physical groups, whose warning
 * named every group, 8 KB; it names ten now: below. Should the pairing
 * warning be bounded too, this test needs another warning over 4096
 * bytes, or none is left and the check of the size past 4096 goes.) An
 * index out of range is refused, the size unchanged. */
static void a_warning_of_any_length_is_read_whole_by_its_size(void) {
  enum { N = 1000 };
  static double xy[6 * N];
  static int tri[3 * N], body[N], edges[2 * N], tags[N];
  for (int k = 0; k < N; ++k) { /* triangle k alone in body 1001 + k, its bottom edge tagged 1 */
    double x = 2.0 * k;
    const double p[6] = {x, 0, x + 1, 0, x, 1};
    memcpy(xy + 6 * k, p, sizeof p);
    tri[3 * k] = 3 * k, tri[3 * k + 1] = 3 * k + 1, tri[3 * k + 2] = 3 * k + 2;
    body[k] = 1001 + k;
    edges[2 * k] = 3 * k, edges[2 * k + 1] = 3 * k + 1;
    tags[k] = 1;
  }
  tfem_model *m = tfem_create();
  CHECK(tfem_set_mesh(m, 3 * N, xy, N, tri, body, 0) == TFEM_STATUS_OK);
  CHECK(tfem_set_boundary_edges(m, N, edges, tags) == TFEM_STATUS_OK);
  int first = -1, pairs = -1;
  CHECK(tfem_add_contact_pairs_auto(m, 0, NULL, 0.1, &first, &pairs) == TFEM_STATUS_OK && pairs == 0);
  int count = 0, found = 0;
  CHECK(tfem_warning_count(m, &count) == TFEM_STATUS_OK);
  for (int i = 0; i < count; ++i) {
    char *w = warning_by_its_size(m, i);
    if (w && strstr(w, "left out tag 1: its edges bound bodies 1001, 1002, ") && strstr(w, ", 2000,"))
      found = strlen(w) + 1 > 4096;
    free(w);
  }
  CHECK(found);
  size_t size = 7;
  EXPECT_ERROR(m, tfem_get_warning_size(m, count, &size), TFEM_STATUS_INVALID_ARGUMENT, "out of range");
  CHECK(size == 7);
  tfem_destroy(m);
}

/* A Gmsh point in 1500 physical groups was warned about naming every
 * group (8225 bytes): the warning names the point, the first ten groups
 * and how many there are, in a few hundred bytes. */
static void a_gmsh_point_in_1500_groups_gives_a_short_warning(void) {
  static char msh[16384];
  int n = sprintf(msh, "$MeshFormat\n4.1 0 8\n$EndMeshFormat\n$Entities\n1 0 1 0\n5 0.5 0.5 0 1500");
  for (int k = 1; k <= 1500; ++k) n += sprintf(msh + n, " %d", 100 + k);
  sprintf(msh + n, "\n1 0 0 0 1 1 0 1 7 0\n$EndEntities\n"
                   "$Nodes\n1 3 1 3\n2 1 0 3\n1\n2\n3\n0 0 0\n1 0 0\n0 1 0\n$EndNodes\n"
                   "$Elements\n1 1 1 1\n2 1 2 1\n1 1 2 3\n$EndElements\n");
  tfem_model *m = tfem_create();
  CHECK(tfem_load_gmsh(m, gmsh_file("many_groups.msh", msh), 0) == TFEM_STATUS_OK);
  int count = 0, found = 0;
  CHECK(tfem_warning_count(m, &count) == TFEM_STATUS_OK);
  for (int i = 0; i < count; ++i) {
    char *w = warning_by_its_size(m, i);
    if (w && strstr(w, "point 5 (group 101, 102, 103, 104, 105, 106, 107, 108, 109, 110 and 1490 more, 1500 in all)"))
      found = strlen(w) + 1 < 512 && strstr(w, "111") == NULL;
    free(w);
  }
  CHECK(found);
  tfem_destroy(m);
  unlink(gmsh_path("many_groups.msh"));
}

/* Found by a host-code probe: a Fortran type(c_ptr) does not tell a model
 * from a contact context, and tfem_error_message(context) read the context
 * as a model. A handle of the other kind, or a destroyed one, is refused
 * before anything is read through it; destroying it again is a no-op. */
static void a_handle_of_the_other_kind_or_destroyed_is_refused(void) {
  tfem_model *m = two_blocks();
  tfem_contact *c = tfem_contact_create(0);
  char msg[512];
  int threads = 0;
  CHECK(c != NULL);
  CHECK(tfem_get_threads((tfem_model *)c, &threads) == TFEM_STATUS_INVALID_ARGUMENT);
  CHECK(tfem_last_error(NULL, msg, sizeof msg) == TFEM_STATUS_OK && strstr(msg, "`model` is not a model") &&
        strstr(msg, "contact context"));
  CHECK(tfem_last_error((tfem_model *)c, msg, sizeof msg) == TFEM_STATUS_INVALID_ARGUMENT &&
        strstr(msg, "contact context") != NULL);
  CHECK(tfem_last_error_length((tfem_model *)c) == strlen(msg) + 1);
  CHECK(tfem_contact_last_error((tfem_contact *)m, msg, sizeof msg) == TFEM_STATUS_INVALID_ARGUMENT &&
        strstr(msg, "is not a contact context") && strstr(msg, "a model"));
  CHECK(tfem_contact_set_active((tfem_contact *)m, NULL, 0) == TFEM_STATUS_INVALID_ARGUMENT);
  tfem_contact_destroy((tfem_contact *)m); /* not a context: a no-op */
  tfem_destroy((tfem_model *)c);           /* not a model: a no-op */
  CHECK(tfem_solve_contact(m, NULL, NULL) == TFEM_STATUS_OK);
  tfem_destroy(m);
  CHECK(tfem_get_threads(m, &threads) == TFEM_STATUS_INVALID_ARGUMENT);
  CHECK(tfem_last_error(NULL, msg, sizeof msg) == TFEM_STATUS_OK && strstr(msg, "destroyed") != NULL);
  tfem_destroy(m); /* twice: a no-op */
  CHECK(tfem_contact_last_error(c, msg, sizeof msg) == TFEM_STATUS_OK);
  tfem_contact_destroy(c);
  CHECK(tfem_contact_last_error(c, msg, sizeof msg) == TFEM_STATUS_INVALID_ARGUMENT);
}

static void a_host_gets_contact_forces_gaps_and_the_contact_mesh_before_a_solve(void) {
  tfem_model *m = two_blocks();
  int n = 0;
  CHECK(tfem_get_contact_mesh_size(m, &n) == TFEM_STATUS_OK && n == 16);
  int nodes[3 * 64], pair[64], apex[64], before[3 * 64];
  CHECK(tfem_get_contact_mesh(m, before, 3 * 64) == TFEM_STATUS_OK);
  CHECK(tfem_get_contact_element_pairs(m, pair, 64) == TFEM_STATUS_OK);
  CHECK(tfem_get_contact_element_apexes(m, apex, 64) == TFEM_STATUS_OK);
  int consistent = 1;
  for (int e = 0; e < n; ++e) {
    consistent &= pair[e] == 0;
    consistent &= apex[e] == before[3 * e] || apex[e] == before[3 * e + 1] || apex[e] == before[3 * e + 2];
  }
  CHECK(consistent);
  int ba = 0, bb = 0;
  CHECK(tfem_get_contact_pair_bodies(m, 0, &ba, &bb) == TFEM_STATUS_OK && ba == 1 && bb == 2);
  EXPECT_ERROR(m, tfem_get_contact_pair_bodies(m, 1, &ba, NULL), TFEM_STATUS_INVALID_ARGUMENT, "pair = 1");

  tfem_contact_report rep;
  CHECK(tfem_solve_contact(m, NULL, &rep) == TFEM_STATUS_OK);
  CHECK(tfem_get_contact_elements(m, nodes, 3 * 64) == TFEM_STATUS_OK);
  CHECK(memcmp(nodes, before, 3 * (size_t)n * sizeof(int)) == 0);

  CHECK(rep.active < n);
  /* The contact forces balance: zero sum over the pair; on the upper body
   * they carry the applied loads (1e7 Pa over a length of 1, less the
   * 3e6 N/m lift). */
  double f[2 * 64], gap[64];
  CHECK(tfem_get_contact_forces(m, f, 2 * B.nn) == TFEM_STATUS_OK);
  double sum_y = 0, upper_y = 0, scale = 0;
  for (int v = 0; v < B.nn; ++v) {
    sum_y += f[2 * v + 1];
    if (v >= 27) upper_y += f[2 * v + 1];
    scale = fmax(scale, fabs(f[2 * v + 1]));
  }
  CHECK(fabs(sum_y) <= 1e-9 * scale && fabs(upper_y - 7e6) <= 1e-6 * 7e6);
  /* Gaps: at most the reported penetration into, zero off the interface. */
  CHECK(tfem_get_contact_gaps(m, gap, B.nn) == TFEM_STATUS_OK);
  double min_gap = 0;
  for (int v = 0; v < B.nn; ++v) min_gap = fmin(min_gap, gap[v]);
  CHECK(min_gap < 0 && fabs(-min_gap - rep.max_penetration) <= 1e-12 + 1e-9 * rep.max_penetration);
  CHECK(gap[0] == 0.0 && gap[B.nn - 1] == 0.0);

  /* The work of the loads: the pressure's consistent nodal forces on the
   * top edges and the lift, times their displacements. */
  double w = 0, u[2 * 64];
  CHECK(tfem_get_external_work(m, &w) == TFEM_STATUS_OK && tfem_get_displacements(m, u, 2 * B.nn) == TFEM_STATUS_OK);
  double by_hand = 0;
  for (int i = 0; i < 8; ++i) {
    int a = 27 + 2 * 9 + i, b = a + 1; /* top row of the upper block */
    by_hand += -1e7 * 0.125 * 0.5 * (u[2 * a + 1] + u[2 * b + 1]);
  }
  by_hand += 3e6 * u[2 * 45 + 1];
  CHECK(fabs(w - by_hand) <= 1e-12 * fabs(by_hand));
  tfem_destroy(m);
}

/* A block (body 2, tags 5-8) on a block (body 1, tags 1-4, bottom clamped)
 * across a curved gap: body 2's bottom touches over |x| <= 0.25 and rises
 * as y = 0.02 (|x| - 0.25)^2 beyond, its top flat, so contact spreads
 * outwards as it is pressed. Its top is
 * loaded by the traction (0.18 p, -p), p = 10 (E = 1000, nu = 0.3, plane
 * strain); nothing holds it sideways but friction, mu = 0.3 on pair (4, 7). */
static mesh_t S;
static tfem_model *sheared_on_a_curved_gap(void) {
  memset(&S, 0, sizeof S);
  grid(&S, 16, 4, -1.0, -0.5, 2.0, 0.5, 1, 1);
  int first = S.nn;
  grid(&S, 16, 4, -1.0, 0.0, 2.0, 0.5, 2, 5);
  for (int v = first; v < S.nn; ++v) {
    double x = S.xy[2 * v], y = S.xy[2 * v + 1];
    double off = fmax(fabs(x) - 0.25, 0.0);
    S.xy[2 * v + 1] = y + 0.02 * off * off * (1.0 - y / 0.5);
  }
  tfem_model *m = model_of(&S, 2, 1000.0, 1.0, TFEM_PLANE_MODE_STRAIN);
  CHECK(tfem_fix_edges(m, 3, TFEM_COMPONENT_X, 0.0) == TFEM_STATUS_OK);
  CHECK(tfem_fix_edges(m, 3, TFEM_COMPONENT_Y, 0.0) == TFEM_STATUS_OK);
  CHECK(tfem_add_traction(m, 8, 1.8, -10.0) == TFEM_STATUS_OK);
  CHECK(tfem_add_contact_pair(m, 4, 7, NULL) == TFEM_STATUS_OK);
  CHECK(tfem_set_friction(m, 0, 0.3) == TFEM_STATUS_OK);
  return m;
}

/* The resultant contact force on body 2 (nodes from `first` on). */
static void body_2_contact_force(tfem_model *m, int first, double f[2]) {
  static double c[2 * 4096];
  f[0] = f[1] = NAN;
  if (tfem_get_contact_forces(m, c, 2 * (size_t)S.nn) != TFEM_STATUS_OK) return;
  f[0] = f[1] = 0.0;
  for (int v = first; v < S.nn; ++v) {
    f[0] += c[2 * v];
    f[1] += c[2 * v + 1];
  }
}

/* Found by a user loading a press through the C API: a body held sideways
 * by friction alone, pressed and sheared together (Q/P = 0.18 < mu), was
 * SINGULAR ("not restrained") in one solve, since elements closing during
 * a step carried no shear. Contact that forms under shear now sticks where
 * it closes (docs/method.md §6.15): the solve carries Q, and one load step
 * and five give one answer. */
static void a_body_held_sideways_by_friction_alone_is_pressed_and_sheared_in_one_solve(void) {
  int first = 17 * 5;
  tfem_model *m = sheared_on_a_curved_gap();
  tfem_status st = tfem_solve_contact(m, NULL, NULL);
  if (st != TFEM_STATUS_OK) {
    char msg[512];
    tfem_last_error(m, msg, sizeof msg);
    printf("  %s\n", msg);
  }
  CHECK(st == TFEM_STATUS_OK);
  double f[2];
  body_2_contact_force(m, first, f);
  /* Equilibrium: the contact carries the load on the 2-long top. */
  CHECK(fabs(f[0] + 3.6) <= 1e-6 * 20.0);
  CHECK(fabs(f[1] - 20.0) <= 1e-6 * 20.0);
  double one[2 * 4096], five[2 * 4096];
  tfem_model *s1 = sheared_on_a_curved_gap(), *s5 = sheared_on_a_curved_gap();
  CHECK(tfem_step(s1, 1.0, NULL, NULL) == TFEM_STATUS_OK);
  for (int k = 1; k <= 5; ++k) CHECK(tfem_step(s5, k / 5.0, NULL, NULL) == TFEM_STATUS_OK);
  CHECK(tfem_get_contact_nodal_tractions(s1, one, 2 * (size_t)S.nn) == TFEM_STATUS_OK);
  CHECK(tfem_get_contact_nodal_tractions(s5, five, 2 * (size_t)S.nn) == TFEM_STATUS_OK);
  double diff = 0, peak = 0;
  for (int v = 0; v < S.nn; ++v) {
    diff = fmax(diff, fabs(one[2 * v + 1] - five[2 * v + 1]));
    peak = fmax(peak, fabs(one[2 * v]));
  }
  CHECK(all_finite(one, 2 * S.nn) && peak > 0.0);
  /* Measured 2.5e-6 of the peak pressure. */
  CHECK(diff <= 1e-3 * 0.3 * peak);
  tfem_destroy(m);
  tfem_destroy(s1);
  tfem_destroy(s5);
}

/* Found by the API fuzzer: a frictional step on loads changed since the
 * step before (no straight path between them: taken whole), reverted and
 * taken again, went in sub-steps the second time (the history had
 * forgotten which loads its state came from) and gave other results. */
static void a_frictional_step_on_new_loads_repeats_bit_for_bit_after_a_revert(void) {
  tfem_model *m = sheared_on_a_curved_gap();
  tfem_contact_report first, again;
  CHECK(tfem_step(m, 0.5, NULL, NULL) == TFEM_STATUS_OK);
  CHECK(tfem_add_traction(m, 8, 0.5, 0.0) == TFEM_STATUS_OK);
  CHECK(tfem_step(m, 1.0, NULL, &first) == TFEM_STATUS_OK);
  static double u[2 * 4096], v[2 * 4096];
  CHECK(tfem_get_displacements(m, u, 2 * (size_t)S.nn) == TFEM_STATUS_OK);
  CHECK(tfem_revert_step(m) == TFEM_STATUS_OK);
  CHECK(tfem_step(m, 1.0, NULL, &again) == TFEM_STATUS_OK);
  CHECK(tfem_get_displacements(m, v, 2 * (size_t)S.nn) == TFEM_STATUS_OK);
  CHECK(first.iterations == again.iterations);
  CHECK(memcmp(u, v, 2 * (size_t)S.nn * sizeof(double)) == 0);
  tfem_destroy(m);
}

static void a_load_history_steps_reverts_and_restarts_bit_for_bit(void) {
  tfem_model *m = two_blocks();
  tfem_contact_report rep;
  int64_t factorisations = 0;
  for (int k = 1; k <= 4; ++k) {
    CHECK(tfem_step(m, k / 4.0, NULL, &rep) == TFEM_STATUS_OK);
    factorisations += rep.info.factorizations;
  }
  CHECK(factorisations == 1);
  /* The last step is the one-step answer. */
  tfem_model *one = two_blocks();
  CHECK(tfem_solve_contact(one, NULL, NULL) == TFEM_STATUS_OK);
  double u[2 * 64], v[2 * 64];
  CHECK(tfem_get_displacements(m, u, 2 * B.nn) == TFEM_STATUS_OK);
  CHECK(tfem_get_displacements(one, v, 2 * B.nn) == TFEM_STATUS_OK);
  double err = 0, scale = 0;
  for (int i = 0; i < 2 * B.nn; ++i) {
    err = fmax(err, fabs(u[i] - v[i]));
    scale = fmax(scale, fabs(v[i]));
  }
  CHECK(err <= 1e-12 * scale);
  /* Save the state, step on, restore it in a new model: the same bits. */
  size_t size = 0;
  CHECK(tfem_get_contact_state_size(m, &size) == TFEM_STATUS_OK && size > 0);
  uint8_t *state = malloc(size);
  CHECK(state != NULL && tfem_get_contact_state(m, state, size) == TFEM_STATUS_OK);
  EXPECT_ERROR(m, tfem_get_contact_state(m, state, size - 1), TFEM_STATUS_BUFFER_TOO_SMALL, "buffer");
  /* Counted in bytes, as the state is (it said "values"). */
  EXPECT_ERROR(m, tfem_get_contact_state(m, state, size - 1), TFEM_STATUS_BUFFER_TOO_SMALL, "bytes but");
  CHECK(tfem_step(m, 1.5, NULL, NULL) == TFEM_STATUS_OK);
  CHECK(tfem_get_displacements(m, u, 2 * B.nn) == TFEM_STATUS_OK);
  tfem_model *restarted = two_blocks();
  CHECK(tfem_set_contact_state(restarted, state, size) == TFEM_STATUS_OK);
  CHECK(tfem_step(restarted, 1.5, NULL, NULL) == TFEM_STATUS_OK);
  CHECK(tfem_get_displacements(restarted, v, 2 * B.nn) == TFEM_STATUS_OK);
  CHECK(memcmp(u, v, 2 * (size_t)B.nn * sizeof(double)) == 0);
  /* Revert: back to the state of factor 1. */
  CHECK(tfem_revert_step(m) == TFEM_STATUS_OK);
  CHECK(tfem_get_displacements(m, v, 2 * B.nn) == TFEM_STATUS_OK);
  CHECK(fabs(v[1] - u[1] / 1.5) <= 1e-9 * fabs(u[1]) + 1e-30);
  EXPECT_ERROR(m, tfem_revert_step(m), TFEM_STATUS_INVALID_STATE, "no load step");
  state[0] ^= 0xff;
  EXPECT_ERROR(restarted, tfem_set_contact_state(restarted, state, size), TFEM_STATUS_INVALID_ARGUMENT,
               "magic");
  EXPECT_ERROR(m, tfem_step(m, NAN, NULL, NULL), TFEM_STATUS_INVALID_ARGUMENT, "load_factor");
  /* A first step that fails leaves no history behind (found by the API
   * fuzzer: the state of the failed step was kept). */
  tfem_model *fresh = two_blocks();
  tfem_contact_options capped;
  tfem_contact_options_default(&capped);
  capped.max_iterations = 1;
  EXPECT_ERROR(fresh, tfem_step(fresh, 1.0, &capped, NULL), TFEM_STATUS_NOT_CONVERGED, "");
  EXPECT_ERROR(fresh, tfem_get_contact_state_size(fresh, &size), TFEM_STATUS_INVALID_STATE, "no load step");
  tfem_destroy(fresh);
  free(state);
  tfem_destroy(restarted);
  tfem_destroy(one);
  tfem_destroy(m);
}

/* A punch on a block: the 4 x 4 grid of [0, 1]^2 (body 1, tags 1-4)
 * under the 4 x 1 grid of [0, 1] x [1, 1.25] (body 2, tags 5-8);
 * `first_punch` is the punch's first node in P. */
static void punch_mesh(mesh_t *P, int *first_punch) {
  memset(P, 0, sizeof *P);
  grid(P, 4, 4, 0.0, 0.0, 1.0, 1.0, 1, 1);
  *first_punch = P->nn;
  grid(P, 4, 1, 0.0, 1.0, 1.0, 0.25, 2, 5);
}

/* The model of punch_mesh: the block (E = 2e11) clamped at its bottom
 * (tag 3), every punch node moved down by 1e-3 (E = `punch_e`), nu = 0.3,
 * plane strain, paired (4, 7). */
static tfem_model *punch_scene(mesh_t *P, int first_punch, double punch_e) {
  tfem_model *m = model_of(P, 2, 2e11, 1.0, TFEM_PLANE_MODE_STRAIN);
  CHECK(tfem_set_material(m, 2, punch_e, 0.3, TFEM_PLANE_MODE_STRAIN) == TFEM_STATUS_OK);
  CHECK(tfem_fix_edges(m, 3, TFEM_COMPONENT_X, 0.0) == TFEM_STATUS_OK);
  CHECK(tfem_fix_edges(m, 3, TFEM_COMPONENT_Y, 0.0) == TFEM_STATUS_OK);
  for (int v = first_punch; v < P->nn; ++v) {
    CHECK(tfem_fix(m, v, TFEM_COMPONENT_X, 0.0) == TFEM_STATUS_OK);
    CHECK(tfem_fix(m, v, TFEM_COMPONENT_Y, -1e-3) == TFEM_STATUS_OK);
  }
  CHECK(tfem_add_contact_pair(m, 4, 7, NULL) == TFEM_STATUS_OK);
  return m;
}

/* A rigid punch (every node of body 2 moved down 1e-3) on a block E =
 * 2e11: with E_c = 1e23 the penalty's overlap falls below the rounding of
 * u and the contact forces are rounding while the system is well
 * conditioned; the solve says so (docs/method.md §6.14). The default E_c
 * does not warn. */
static void a_contact_modulus_too_stiff_for_its_overlap_is_warned_about(void) {
  static mesh_t P;
  int first_punch;
  punch_mesh(&P, &first_punch);
  for (int k = 0; k < 2; ++k) {
    tfem_model *m = punch_scene(&P, first_punch, 2e11);
    tfem_contact_options o;
    tfem_contact_options_default(&o);
    if (k == 1) o.contact_modulus = 1e23;
    CHECK(tfem_solve_contact(m, &o, NULL) == TFEM_STATUS_OK);
    CHECK(has_warning(m, "correct digits") == (k == 1));
    tfem_destroy(m);
  }
}

/* Found by an outside probe of rigid tools: a rigid punch (every node
 * prescribed) given a nominal E = 1e3 against a block of 2e11 set the
 * contact modulus (the smaller E of the pair): the overlap took 99.98 % of
 * the indentation and the punch force was 2e-4 of the right one, status
 * OK. A wholly prescribed side now leaves E_c to the other body. */
static void a_rigid_punchs_nominal_modulus_does_not_set_the_penalty(void) {
  static mesh_t P;
  int first_punch;
  punch_mesh(&P, &first_punch);
  double force[2] = {0, 0};
  double e[2] = {2e11, 1e3};
  for (int k = 0; k < 2; ++k) {
    tfem_model *m = punch_scene(&P, first_punch, e[k]);
    CHECK(tfem_solve_contact(m, NULL, NULL) == TFEM_STATUS_OK);
    static double r[2 * 4096];
    CHECK(tfem_get_reactions(m, r, 2 * P.nn) == TFEM_STATUS_OK);
    for (int v = first_punch; v < P.nn; ++v) force[k] -= r[2 * v + 1];
    tfem_destroy(m);
  }
  CHECK(force[0] > 1e7 && fabs(force[1] - force[0]) <= 1e-13 * force[0]);
}

/* Found by the same probe: a model with every DOF prescribed was refused
 * as singular, "body 1 is not restrained (free mode: )", and a load step
 * of a contact between two prescribed sides said "0 interface unknowns are
 * too many". The first now says what is the matter; the second is a
 * contact solve of the step's loads. */
static void nothing_to_solve_is_said_in_words(void) {
  static mesh_t P;
  int first_punch;
  punch_mesh(&P, &first_punch);
  tfem_model *m = punch_scene(&P, first_punch, 2e11);
  for (int v = 0; v < first_punch; ++v) {
    CHECK(tfem_fix(m, v, TFEM_COMPONENT_X, 0.0) == TFEM_STATUS_OK);
    CHECK(tfem_fix(m, v, TFEM_COMPONENT_Y, 0.0) == TFEM_STATUS_OK);
  }
  EXPECT_ERROR(m, tfem_solve_contact(m, NULL, NULL), TFEM_STATUS_INVALID_STATE, "every DOF of the model is prescribed");
  EXPECT_ERROR(m, tfem_step(m, 1.0, NULL, NULL), TFEM_STATUS_INVALID_STATE, "leave at least one DOF free");
  tfem_destroy(m);

  m = model_of(&P, 2, 2e11, 1.0, TFEM_PLANE_MODE_STRAIN);
  for (int v = 0; v < P.nn; ++v) {
    CHECK(tfem_fix(m, v, TFEM_COMPONENT_X, 0.0) == TFEM_STATUS_OK);
    CHECK(tfem_fix(m, v, TFEM_COMPONENT_Y, 0.0) == TFEM_STATUS_OK);
  }
  EXPECT_ERROR(m, tfem_solve(m, NULL), TFEM_STATUS_INVALID_STATE, "nothing to solve");
  tfem_destroy(m);

  m = punch_scene(&P, first_punch, 2e11);
  CHECK(tfem_fix_edges(m, 4, TFEM_COMPONENT_X, 0.0) == TFEM_STATUS_OK);
  CHECK(tfem_fix_edges(m, 4, TFEM_COMPONENT_Y, 0.0) == TFEM_STATUS_OK);
  CHECK(tfem_solve_contact(m, NULL, NULL) == TFEM_STATUS_OK);
  /* With no interface to condense, a load step is the contact solve of its
   * scaled loads: at factor 1, the solve's field to the bit. */
  static double u_solve[2 * 4096], u_step[2 * 4096];
  size_t n_u = 2 * (size_t)P.nn;
  CHECK(n_u <= 2 * 4096);
  CHECK(tfem_get_displacements(m, u_solve, n_u) == TFEM_STATUS_OK);
  CHECK(tfem_step(m, 1.0, NULL, NULL) == TFEM_STATUS_OK);
  CHECK(tfem_get_displacements(m, u_step, n_u) == TFEM_STATUS_OK);
  CHECK(memcmp(u_solve, u_step, n_u * sizeof(double)) == 0);
  tfem_destroy(m);
}

/* A "rigid" punch modelled as elastic with E = 1e25 (every node of body
 * 2 moved down 1e-3, E_c the block's 2e11): its reaction K u - f cancels
 * terms of 1e25 * 1e-3 to their rounding and is wrong; the solve says so,
 * naming the body (docs/method.md 6.14). E = 2e11 does not warn. */
static void a_rigid_body_modelled_by_a_huge_modulus_has_its_reactions_warned_about(void) {
  static mesh_t P;
  int first_punch;
  punch_mesh(&P, &first_punch);
  for (int k = 0; k < 2; ++k) {
    tfem_model *m = punch_scene(&P, first_punch, k == 1 ? 1e25 : 2e11);
    CHECK(tfem_solve_contact(m, NULL, NULL) == TFEM_STATUS_OK);
    CHECK(has_warning(m, "the reactions of body 2") == (k == 1));
    CHECK(!has_warning(m, "the reactions of body 1"));
    tfem_destroy(m);
  }
}

/* two_blocks() stepped to 0.5, its contact state saved (malloc'ed into
 * *state, *size bytes), then stepped to 1.0. */
static tfem_model *stepped_past_a_saved_state(uint8_t **state, size_t *size) {
  tfem_model *m = two_blocks();
  CHECK(tfem_step(m, 0.5, NULL, NULL) == TFEM_STATUS_OK);
  CHECK(tfem_get_contact_state_size(m, size) == TFEM_STATUS_OK && *size > 0);
  *state = malloc(*size);
  CHECK(*state != NULL && tfem_get_contact_state(m, *state, *size) == TFEM_STATUS_OK);
  CHECK(tfem_step(m, 1.0, NULL, NULL) == TFEM_STATUS_OK);
  return m;
}

/* Found by a probe of load histories: reverting a step after friction was
 * turned on brought back the contact state of the old contact mesh, and
 * every later step was refused; a state restored into a model of another
 * stiffness brought its interface factor along (contact pressures off by
 * tens of percent, status OK); a changed byte went unnoticed. */
static void a_contact_state_never_outlives_its_problem(void) {
  size_t size = 0;
  uint8_t *state = NULL;
  tfem_model *m = stepped_past_a_saved_state(&state, &size);
  CHECK(tfem_set_friction(m, 0, 0.3) == TFEM_STATUS_OK);
  EXPECT_ERROR(m, tfem_revert_step(m), TFEM_STATUS_INVALID_STATE, "cannot be reverted");
  CHECK(tfem_step(m, 1.0, NULL, NULL) == TFEM_STATUS_OK);
  /* The upper block three times stiffer, the same contact mesh: the step
   * starts from the state's set with this model's own interface factor. */
  tfem_model *stiffer = two_blocks(), *one = two_blocks();
  CHECK(tfem_set_material(stiffer, 2, 3e11, 0.3, TFEM_PLANE_MODE_STRAIN) == TFEM_STATUS_OK);
  CHECK(tfem_set_material(one, 2, 3e11, 0.3, TFEM_PLANE_MODE_STRAIN) == TFEM_STATUS_OK);
  CHECK(tfem_set_contact_state(stiffer, state, size) == TFEM_STATUS_OK);
  CHECK(tfem_step(stiffer, 1.0, NULL, NULL) == TFEM_STATUS_OK);
  CHECK(tfem_solve_contact(one, NULL, NULL) == TFEM_STATUS_OK);
  double p[64], q[64], err = 0, scale = 0;
  int n = 0;
  CHECK(tfem_get_contact_mesh_size(one, &n) == TFEM_STATUS_OK && n > 0 && n <= 64);
  CHECK(tfem_get_contact_pressure(stiffer, p, 64) == TFEM_STATUS_OK);
  CHECK(tfem_get_contact_pressure(one, q, 64) == TFEM_STATUS_OK);
  for (int k = 0; k < n; ++k) {
    err = fmax(err, fabs(p[k] - q[k]));
    scale = fmax(scale, fabs(q[k]));
  }
  CHECK(scale > 0 && err <= 1e-9 * scale);
  state[size / 2] ^= 0x10;
  EXPECT_ERROR(one, tfem_set_contact_state(one, state, size), TFEM_STATUS_INVALID_ARGUMENT, "changed");
  free(state);
  tfem_destroy(one);
  tfem_destroy(stiffer);
  tfem_destroy(m);
}

/* A failed solve or a failed step with other options after a load step
 * leaves the history as it was: the next step continues it without a
 * factorisation, bit for bit as if the failed call had not been made
 * (found by the API fuzzer: the failed call ended the history). */
static void a_failed_call_between_load_steps_keeps_the_history(void) {
  tfem_contact_options capped, other;
  tfem_contact_options_default(&capped);
  capped.max_iterations = 1;
  other = capped;
  other.contact_modulus = 5e9; /* another history: it starts with its own K1 */
  double u[2][2 * 64];
  int64_t factorisations[2] = {-1, -1};
  for (int failing = 0; failing < 2; ++failing) {
    tfem_model *m = two_blocks();
    tfem_contact_report rep;
    CHECK(tfem_step(m, 0.5, NULL, NULL) == TFEM_STATUS_OK);
    if (failing) {
      EXPECT_ERROR(m, tfem_solve_contact(m, &capped, NULL), TFEM_STATUS_NOT_CONVERGED, "did not settle");
      EXPECT_ERROR(m, tfem_step(m, 1.0, &other, NULL), TFEM_STATUS_NOT_CONVERGED, "did not settle");
    }
    CHECK(tfem_step(m, 1.0, NULL, &rep) == TFEM_STATUS_OK);
    factorisations[failing] = rep.info.factorizations;
    CHECK(tfem_get_displacements(m, u[failing], 2 * B.nn) == TFEM_STATUS_OK);
    tfem_destroy(m);
  }
  CHECK(factorisations[0] == 0 && factorisations[1] == 0);
  CHECK(memcmp(u[0], u[1], 2 * (size_t)B.nn * sizeof(double)) == 0);
}

static void expect_contact_error(tfem_contact *c, tfem_status got, tfem_status expected,
                                 const char *needle, const char *needle2, int line) {
  char msg[512];
  tfem_contact_last_error(c, msg, sizeof msg);
  if (got == expected && strstr(msg, needle) != NULL && strstr(msg, needle2) != NULL) {
    ++passed;
  } else {
    ++failed;
    printf("FAIL line %d: status %d (expected %d), message \"%s\" (expected \"%s\" and \"%s\")\n",
           line, (int)got, (int)expected, msg, needle, needle2);
  }
}

/* A host code that gives one side of an interface clockwise (its body on
 * the right of every edge) turned its normals inward: B would start
 * inverted. Refused when the pair is declared, naming both sides; a side
 * with one edge turned against its neighbours is refused at once, naming
 * the edge. Two flat sides of 5 nodes on y = 0: the lower body below
 * (tag 3), the upper body above (tag 4). */
static void a_host_side_given_clockwise_is_refused(void) {
  int lower[5], upper[5];
  double xy[10];
  int64_t eq_lower[10], eq_upper[10];
  for (int i = 0; i < 5; ++i) {
    lower[i] = 100 + i;
    upper[i] = 200 + i;
    xy[2 * i] = 0.25 * i;
    xy[2 * i + 1] = 0.0;
    eq_lower[2 * i] = 2 * i;
    eq_lower[2 * i + 1] = 2 * i + 1;
    eq_upper[2 * i] = 10 + 2 * i;
    eq_upper[2 * i + 1] = 11 + 2 * i;
  }
  /* Counter-clockwise: the lower body's top runs in +x, the upper body's
   * bottom in -x. */
  int ccw_lower[8], ccw_upper[8], cw_lower[8], one_turned[8];
  for (int e = 0; e < 4; ++e) {
    ccw_lower[2 * e] = lower[e], ccw_lower[2 * e + 1] = lower[e + 1];
    ccw_upper[2 * e] = upper[e + 1], ccw_upper[2 * e + 1] = upper[e];
    cw_lower[2 * e] = lower[e + 1], cw_lower[2 * e + 1] = lower[e];
    one_turned[2 * e] = ccw_lower[2 * e], one_turned[2 * e + 1] = ccw_lower[2 * e + 1];
  }
  one_turned[4] = lower[3], one_turned[5] = lower[2]; /* edge 2 turned */

  int a = -1, b = -1, pair = -7;
  tfem_contact *c = tfem_contact_create(0);
  CHECK(tfem_contact_add_side(c, 3, 1, 1e9, 0.3, 0, 5, lower, xy, eq_lower, 4, cw_lower, &a) == TFEM_STATUS_OK);
  CHECK(tfem_contact_add_side(c, 4, 2, 1e9, 0.3, 0, 5, upper, xy, eq_upper, 4, ccw_upper, &b) == TFEM_STATUS_OK);
  expect_contact_error(c, tfem_contact_add_pair(c, a, b, &pair), TFEM_STATUS_INVALID_CONTACT, "side 0 (tag 3)",
                       "side 1 (tag 4)", __LINE__);
  CHECK(pair == -7);
  int n_nodes = -1, n_elements = -1;
  int64_t n_pattern = -1;
  CHECK(tfem_contact_sizes(c, &n_nodes, &n_elements, &n_pattern) != TFEM_STATUS_OK); /* no pair */
  tfem_contact_destroy(c);

  c = tfem_contact_create(0);
  expect_contact_error(c, tfem_contact_add_side(c, 3, 1, 1e9, 0.3, 0, 5, lower, xy, eq_lower, 4, one_turned, &a),
                       TFEM_STATUS_INVALID_CONTACT, "edge 2 (nodes 103, 102) of contact side 0 (tag 3)",
                       "at node 102", __LINE__);
  /* The same context takes the right side afterwards, and the pair. */
  CHECK(tfem_contact_add_side(c, 3, 1, 1e9, 0.3, 0, 5, lower, xy, eq_lower, 4, ccw_lower, &a) == TFEM_STATUS_OK);
  CHECK(tfem_contact_add_side(c, 4, 2, 1e9, 0.3, 0, 5, upper, xy, eq_upper, 4, ccw_upper, &b) == TFEM_STATUS_OK);
  CHECK(tfem_contact_add_pair(c, a, b, &pair) == TFEM_STATUS_OK && pair == 0);
  CHECK(tfem_contact_sizes(c, &n_nodes, &n_elements, &n_pattern) == TFEM_STATUS_OK && n_nodes == 10 &&
        n_elements == 8);
  /* An evaluation that overflows fails with NUMERICAL_FAILURE and writes
   * nothing (found by the API fuzzer: the buffers were written first). */
  double u[20], r[20], p[8], *values = malloc((size_t)n_pattern * sizeof(double));
  int on[8] = {1, 1, 1, 1, 1, 1, 1, 1};
  CHECK(values != NULL && tfem_contact_set_active(c, on, 8) == TFEM_STATUS_OK);
  for (int i = 0; i < 20; ++i) u[i] = (i % 2 ? -1e300 : 1e300) * (i < 10 ? 1 : -1), r[i] = 7.0;
  for (int i = 0; i < 8; ++i) p[i] = 7.0;
  for (int64_t k = 0; k < n_pattern; ++k) values[k] = 7.0;
  expect_contact_error(c, tfem_contact_evaluate(c, u, 20, values, (size_t)n_pattern, r, 20),
                       TFEM_STATUS_NUMERICAL_FAILURE, "not finite", "interface node", __LINE__);
  expect_contact_error(c, tfem_contact_pressures(c, u, 20, p, 8), TFEM_STATUS_NUMERICAL_FAILURE, "not finite",
                       "contact element", __LINE__);
  int untouched = 1;
  for (int i = 0; i < 20; ++i) untouched &= r[i] == 7.0;
  for (int i = 0; i < 8; ++i) untouched &= p[i] == 7.0;
  for (int64_t k = 0; k < n_pattern; ++k) untouched &= values[k] == 7.0;
  CHECK(untouched);
  free(values);
  tfem_contact_destroy(c);
}

/* Defects the API fuzzer found at the friction boundary (c_tests/README.md),
 * each a regression test: a failed solve after a frictional one is
 * NOT_CONVERGED, not an internal error, and keeps every result; reactions
 * carry the frictional shear at a prescribed interface node, so that
 * loads, contact forces and reactions balance on each body; a contact
 * state set after frictional steps keeps the last step's displacements. */
/* The API fuzzer's reproducer: two 4x1-cell blocks on y = 0 (rows of 5
 * nodes at y = -0.25, 0, 0, 0.25; E 1e10 below, 1e11 above), v = 0 on the
 * bottom, u = 0 at node 0 and at node 10 (the upper block's bottom left,
 * on the interface), pressure 1e7 and traction (1e6, 0) on the top. */
static tfem_model *four_cell_blocks(double mu) {
  double xy[40], ys[4] = {-0.25, 0.0, 0.0, 0.25};
  int tri[48], body[16], edges[32], tags[16], nt = 0, ne = 0;
  for (int r = 0; r < 4; ++r)
    for (int i = 0; i <= 4; ++i) xy[2 * (5 * r + i)] = i / 4.0, xy[2 * (5 * r + i) + 1] = ys[r];
  for (int b = 0; b < 2; ++b)
    for (int i = 0; i < 4; ++i) {
      int p = 10 * b + i, q = p + 5;
      tri[3 * nt] = p, tri[3 * nt + 1] = p + 1, tri[3 * nt + 2] = q + 1, body[nt++] = b + 1;
      tri[3 * nt] = p, tri[3 * nt + 1] = q + 1, tri[3 * nt + 2] = q, body[nt++] = b + 1;
    }
  for (int r = 0; r < 4; ++r)
    for (int i = 0; i < 4; ++i) {
      int p = 5 * r + i, fwd = r == 0 || r == 2;
      edges[2 * ne] = fwd ? p : p + 1, edges[2 * ne + 1] = fwd ? p + 1 : p, tags[ne++] = r + 1;
    }
  tfem_model *m = tfem_create();
  CHECK(tfem_set_mesh(m, 20, xy, nt, tri, body, 0) == TFEM_STATUS_OK);
  CHECK(tfem_set_boundary_edges(m, ne, edges, tags) == TFEM_STATUS_OK);
  CHECK(tfem_set_material(m, 1, 1e10, 0.3, TFEM_PLANE_MODE_STRAIN) == TFEM_STATUS_OK);
  CHECK(tfem_set_material(m, 2, 1e11, 0.3, TFEM_PLANE_MODE_STRAIN) == TFEM_STATUS_OK);
  CHECK(tfem_fix_edges(m, 1, TFEM_COMPONENT_Y, 0.0) == TFEM_STATUS_OK);
  CHECK(tfem_fix(m, 0, TFEM_COMPONENT_X, 0.0) == TFEM_STATUS_OK);
  CHECK(tfem_fix(m, 10, TFEM_COMPONENT_X, 0.0) == TFEM_STATUS_OK);
  CHECK(tfem_add_pressure(m, 4, 1e7) == TFEM_STATUS_OK);
  CHECK(tfem_add_traction(m, 4, 1e6, 0.0) == TFEM_STATUS_OK);
  CHECK(tfem_add_contact_pair(m, 2, 3, NULL) == TFEM_STATUS_OK);
  CHECK(tfem_set_friction(m, 0, mu) == TFEM_STATUS_OK);
  return m;
}

static tfem_model *two_blocks_pushed_sideways(void) {
  tfem_model *m = two_blocks();
  CHECK(tfem_add_nodal_force(m, 53, 1e6, 0.0) == TFEM_STATUS_OK); /* top right corner */
  CHECK(tfem_set_friction(m, 0, 0.1) == TFEM_STATUS_OK);
  return m;
}
static void fuzz_found_defects_at_the_friction_boundary(void) {
  tfem_model *m = two_blocks_pushed_sideways();
  results_t a, b;
  CHECK(tfem_solve_contact(m, NULL, NULL) == TFEM_STATUS_OK && results_of(m, &a));
  tfem_contact_options one = {0, 0.0, 0.0, 0, 1, 0};
  EXPECT_ERROR(m, tfem_solve_contact(m, &one, NULL), TFEM_STATUS_NOT_CONVERGED, "settle");
  CHECK(results_of(m, &b) && same_results(&a, &b));

  /* The only x load is the upper body's 1e6 at node 53 (a pressure on a
   * horizontal top, a vertical nodal force besides): each body's x loads,
   * reactions and contact forces sum to zero; node 27, prescribed in x, is
   * on the interface. */
  double f[2 * 64], r[2 * 64];
  CHECK(tfem_get_contact_forces(m, f, 2 * B.nn) == TFEM_STATUS_OK);
  CHECK(tfem_get_reactions(m, r, 2 * B.nn) == TFEM_STATUS_OK);
  for (int body = 0; body < 2; ++body) {
    double sum = body ? 1e6 : 0.0, size = 0.0;
    for (int v = 27 * body; v < 27 * (body + 1); ++v) {
      sum += f[2 * v] + r[2 * v];
      size += fabs(f[2 * v]) + fabs(r[2 * v]);
    }
    CHECK(size > 0.0 && fabs(sum) <= 1e-9 * size);
  }
  tfem_destroy(m);
  /* The same on the fuzzer's scene: the upper block carries the top's x
   * traction 1e6 × its width 1. */
  m = four_cell_blocks(0.3);
  CHECK(tfem_solve_contact(m, NULL, NULL) == TFEM_STATUS_OK);
  CHECK(tfem_get_contact_forces(m, f, 40) == TFEM_STATUS_OK && tfem_get_reactions(m, r, 40) == TFEM_STATUS_OK);
  double x_sum = 1e6, x_size = 1e6;
  for (int v = 10; v < 20; ++v) x_sum += f[2 * v] + r[2 * v], x_size += fabs(f[2 * v]) + fabs(r[2 * v]);
  CHECK(fabs(x_sum) <= 1e-9 * x_size);
  tfem_destroy(m);

  tfem_model *h = two_blocks_pushed_sideways(), *twin = two_blocks_pushed_sideways();
  double u[2 * 64], v[2 * 64];
  size_t size = 0;
  for (int k = 0; k < 2; ++k) CHECK(tfem_step(k ? twin : h, 0.5, NULL, NULL) == TFEM_STATUS_OK);
  CHECK(tfem_get_contact_state_size(h, &size) == TFEM_STATUS_OK && size > 0);
  uint8_t *saved = malloc(size);
  CHECK(saved != NULL && tfem_get_contact_state(h, saved, size) == TFEM_STATUS_OK);
  for (int k = 0; k < 2; ++k) {
    tfem_model *x = k ? twin : h;
    CHECK(tfem_step(x, 1.0, NULL, NULL) == TFEM_STATUS_OK);
    CHECK(tfem_step(x, 1.0, NULL, NULL) == TFEM_STATUS_OK);
  }
  CHECK(tfem_set_contact_state(h, saved, size) == TFEM_STATUS_OK);
  CHECK(tfem_get_displacements(h, u, 2 * B.nn) == TFEM_STATUS_OK);
  CHECK(tfem_get_displacements(twin, v, 2 * B.nn) == TFEM_STATUS_OK);
  CHECK(memcmp(u, v, 2 * (size_t)B.nn * sizeof(double)) == 0);
  free(saved);
  tfem_destroy(h);
  tfem_destroy(twin);
}

/* Coulomb friction through the C ABI: bad coefficients are refused naming
 * the pair and change nothing; μ = 0 is the frictionless solve bit for bit;
 * with μ > 0 every element obeys Coulomb's law, dissipates nothing
 * negative, and a frictional load history restarts bit for bit. */
static void friction_obeys_coulomb_and_restarts_bit_for_bit(void) {
  tfem_model *plain = two_blocks();
  tfem_model *m = two_blocks();
  EXPECT_ERROR(m, tfem_set_friction(m, 0, -0.1), TFEM_STATUS_INVALID_ARGUMENT, "pair 0");
  EXPECT_ERROR(m, tfem_set_friction(m, 0, NAN), TFEM_STATUS_INVALID_ARGUMENT, "pair 0");
  EXPECT_ERROR(m, tfem_set_friction(m, 1, 0.3), TFEM_STATUS_INVALID_ARGUMENT, "pair 1");
  EXPECT_ERROR(m, tfem_set_friction(m, -1, 0.3), TFEM_STATUS_INVALID_ARGUMENT, "pair -1");
  CHECK(tfem_set_friction(m, 0, 0.0) == TFEM_STATUS_OK);
  results_t a, b;
  CHECK(tfem_solve_contact(plain, NULL, NULL) == TFEM_STATUS_OK && results_of(plain, &a));
  CHECK(tfem_solve_contact(m, NULL, NULL) == TFEM_STATUS_OK && results_of(m, &b));
  CHECK(same_results(&a, &b));

  double mu = 0.1;
  CHECK(tfem_set_friction(m, 0, mu) == TFEM_STATUS_OK);
  CHECK(tfem_solve_contact(m, NULL, NULL) == TFEM_STATUS_OK);
  int n = 0;
  CHECK(tfem_get_sizes(m, NULL, NULL, &n) == TFEM_STATUS_OK && n > 0 && n <= 64);
  double p[64], tau[64], d[64];
  int state[64], slips = 0, sticks = 0;
  CHECK(tfem_get_contact_pressure(m, p, (size_t)n) == TFEM_STATUS_OK);
  CHECK(tfem_get_contact_shear(m, tau, (size_t)n) == TFEM_STATUS_OK);
  CHECK(tfem_get_contact_friction_state(m, state, (size_t)n) == TFEM_STATUS_OK);
  CHECK(tfem_get_contact_dissipation(m, d, (size_t)n) == TFEM_STATUS_OK);
  EXPECT_ERROR(m, tfem_get_contact_shear(m, tau, (size_t)n - 1), TFEM_STATUS_BUFFER_TOO_SMALL, "out");
  for (int k = 0; k < n; ++k) {
    double limit = mu * p[k];
    if (state[k] == 0) CHECK(tau[k] == 0.0 && p[k] == 0.0);
    if (state[k] == 1) {
      CHECK(fabs(tau[k]) <= limit * (1 + 1e-9));
      ++sticks;
    }
    if (state[k] == 2) {
      CHECK(fabs(fabs(tau[k]) - limit) <= 1e-9 * limit);
      ++slips;
    }
    CHECK(d[k] >= 0.0);
  }
  CHECK(sticks > 0 && slips > 0);

  /* A non-proportional history moved by tfem_set_prescribed: a state saved
   * after the first step restarts the second bit for bit. */
  tfem_model *h = two_blocks();
  CHECK(tfem_set_friction(h, 0, mu) == TFEM_STATUS_OK);
  EXPECT_ERROR(h, tfem_set_prescribed(h, 45, TFEM_COMPONENT_X, 1e-6), TFEM_STATUS_INVALID_ARGUMENT,
               "not prescribed");
  CHECK(tfem_step(h, 1.0, NULL, NULL) == TFEM_STATUS_OK);
  size_t size = 0;
  CHECK(tfem_get_contact_state_size(h, &size) == TFEM_STATUS_OK && size > 0);
  uint8_t *saved = malloc(size);
  CHECK(saved != NULL && tfem_get_contact_state(h, saved, size) == TFEM_STATUS_OK);
  CHECK(tfem_set_prescribed(h, 27, TFEM_COMPONENT_X, 2e-5) == TFEM_STATUS_OK);
  tfem_contact_report rep;
  CHECK(tfem_step(h, 1.0, NULL, &rep) == TFEM_STATUS_OK && rep.info.factorizations == 0);
  double u[2 * 64], v[2 * 64];
  CHECK(tfem_get_displacements(h, u, 2 * B.nn) == TFEM_STATUS_OK);
  tfem_model *r = two_blocks();
  CHECK(tfem_set_friction(r, 0, mu) == TFEM_STATUS_OK);
  CHECK(tfem_set_prescribed(r, 27, TFEM_COMPONENT_X, 2e-5) == TFEM_STATUS_OK);
  CHECK(tfem_set_contact_state(r, saved, size) == TFEM_STATUS_OK);
  CHECK(tfem_step(r, 1.0, NULL, NULL) == TFEM_STATUS_OK);
  CHECK(tfem_get_displacements(r, v, 2 * B.nn) == TFEM_STATUS_OK);
  CHECK(memcmp(u, v, 2 * (size_t)B.nn * sizeof(double)) == 0);
  free(saved);
  tfem_destroy(r);
  tfem_destroy(h);
  tfem_destroy(m);
  tfem_destroy(plain);
}

/* Automatic pairing through the C ABI: the facing tags of the two blocks
 * are found and solve bit for bit as the declared pair; bad tolerances and
 * unknown tags are refused, naming them, with nothing added. */
static void facing_tags_are_paired_automatically(void) {
  tfem_model *declared = two_blocks();
  tfem_model *m = two_blocks_unpaired();
  int first = -1, count = -1, nc = -1;
  EXPECT_ERROR(m, tfem_add_contact_pairs_auto(m, 0, NULL, -1.0, &first, &count), TFEM_STATUS_INVALID_ARGUMENT,
               "tolerance");
  EXPECT_ERROR(m, tfem_add_contact_pairs_auto(m, 0, NULL, NAN, NULL, NULL), TFEM_STATUS_INVALID_ARGUMENT,
               "tolerance");
  const int unknown[2] = {13, 99};
  EXPECT_ERROR(m, tfem_add_contact_pairs_auto(m, 2, unknown, 1e-6, NULL, NULL), TFEM_STATUS_INVALID_ARGUMENT, "99");
  EXPECT_ERROR(m, tfem_add_contact_pairs_auto(m, 2, NULL, 1e-6, NULL, NULL), TFEM_STATUS_NULL_POINTER, "tags");
  CHECK(tfem_get_contact_mesh_size(m, &nc) == TFEM_STATUS_OK && nc == 0);
  CHECK(tfem_add_contact_pairs_auto(m, 0, NULL, 1e-6, &first, &count) == TFEM_STATUS_OK);
  CHECK(first == 0 && count == 1);
  int bodies[2] = {0, 0};
  CHECK(tfem_get_contact_pair_bodies(m, 0, &bodies[0], &bodies[1]) == TFEM_STATUS_OK);
  CHECK((bodies[0] == 1 && bodies[1] == 2) || (bodies[0] == 2 && bodies[1] == 1));
  /* Again: the pair is declared already, nothing is added. */
  CHECK(tfem_add_contact_pairs_auto(m, 0, NULL, 1e-6, &first, &count) == TFEM_STATUS_OK && count == 0);
  results_t a, b;
  CHECK(tfem_solve_contact(declared, NULL, NULL) == TFEM_STATUS_OK && results_of(declared, &a));
  CHECK(tfem_solve_contact(m, NULL, NULL) == TFEM_STATUS_OK && results_of(m, &b));
  CHECK(same_results(&a, &b));
  tfem_destroy(m);
  tfem_destroy(declared);
}

/* Three unit blocks stacked (bodies 1, 2, 3 from the bottom): whatever
 * the tolerance, only the two bed joints pair — not the outer faces back
 * to back (found by a probe at 2.5: a 2-unit overlap solved with OK), not
 * the faces of blocks 1 and 3 across block 2 (at 1.5); and a gap of
 * exactly the tolerance pairs (0.1 was computed as 0.10000000000000009). */
static void automatic_pairing_pairs_only_faces_that_see_each_other(void) {
  const double tolerances[3] = {2.5, 1.5, 1e-9};
  for (int k = 0; k < 3; ++k) {
    static mesh_t S;
    memset(&S, 0, sizeof S);
    for (int b = 0; b < 3; ++b) grid(&S, 2, 2, 0.0, b, 1.0, 1.0, b + 1, 4 * b + 1);
    tfem_model *m = model_of(&S, 3, 1e9, 1.0, TFEM_PLANE_MODE_STRAIN);
    int first = -1, count = -1;
    CHECK(tfem_add_contact_pairs_auto(m, 0, NULL, tolerances[k], &first, &count) == TFEM_STATUS_OK);
    CHECK(count == 2);
    for (int p = 0; p < count; ++p) {
      int a = 0, b = 0;
      CHECK(tfem_get_contact_pair_bodies(m, p, &a, &b) == TFEM_STATUS_OK);
      CHECK(abs(a - b) == 1);
    }
    tfem_destroy(m);
  }
  static mesh_t T;
  memset(&T, 0, sizeof T);
  grid(&T, 2, 2, 0.0, 0.0, 1.0, 1.0, 1, 1);
  grid(&T, 2, 2, 0.0, 1.1, 1.0, 1.0, 2, 5);
  tfem_model *m = model_of(&T, 2, 1e9, 1.0, TFEM_PLANE_MODE_STRAIN);
  int first = -1, count = -1;
  CHECK(tfem_add_contact_pairs_auto(m, 0, NULL, 0.1, &first, &count) == TFEM_STATUS_OK && count == 1);
  tfem_destroy(m);
}

/* Two unit blocks stacked in S, 2 x 2 cells each (tags 1..4 below,
 * 5..8 above); `again` gets tag 99 for each of the lower block's edges (a
 * Gmsh "whole boundary" group). Returns the lower block's edge count. */
static int stacked_unit_blocks(mesh_t *S, int *again) {
  memset(S, 0, sizeof *S);
  grid(S, 2, 2, 0.0, 0.0, 1.0, 1.0, 1, 1);
  int lower_edges = S->ne;
  grid(S, 2, 2, 0.0, 1.0, 1.0, 1.0, 2, 5);
  for (int k = 0; k < lower_edges; ++k) again[k] = 99;
  return lower_edges;
}

/* Every edge of the lower block also under tag 99 (a Gmsh file's "whole
 * boundary" group, kept since every group of a curve tags its edges): the
 * interface (4, 7) is not paired again as (99, 7), by hand or
 * automatically — its contact would count twice. */
static void an_interface_is_paired_once_whatever_tags_its_edges_carry(void) {
  static mesh_t S;
  int again[99], lower_edges = stacked_unit_blocks(&S, again);
  for (int by_hand = 0; by_hand < 2; ++by_hand) {
    tfem_model *m = model_of(&S, 2, 1e9, 1.0, TFEM_PLANE_MODE_STRAIN);
    CHECK(tfem_add_boundary_edges(m, lower_edges, S.edges, again) == TFEM_STATUS_OK);
    int first = -1, count = -1;
    if (by_hand) {
      CHECK(tfem_add_contact_pair(m, 4, 7, NULL) == TFEM_STATUS_OK);
      EXPECT_ERROR(m, tfem_add_contact_pair(m, 99, 7, NULL), TFEM_STATUS_INVALID_CONTACT,
                   "covers the interface of contact pair 0");
    } else {
      CHECK(tfem_add_contact_pairs_auto(m, 0, NULL, 1e-9, &first, &count) == TFEM_STATUS_OK && count == 1);
    }
    int nc = -1;
    CHECK(tfem_get_contact_mesh_size(m, &nc) == TFEM_STATUS_OK && nc == 4);
    tfem_destroy(m);
  }
}

/* Automatic pairing said nothing of what it left out. Two unit blocks
 * stacked (tags 1..4 and 5..8): with the lower block's edges also under
 * tag 99, the interface found again as (7, 99) is not paired and a warning
 * names both pairs of tags; with the lower block's top and the upper
 * block's right side under one tag 50, that tag is left out and a warning
 * names it and its bodies. */
static void automatic_pairing_names_what_it_leaves_out(void) {
  static mesh_t S;
  int again[99], lower_edges = stacked_unit_blocks(&S, again);
  tfem_model *m = model_of(&S, 2, 1e9, 1.0, TFEM_PLANE_MODE_STRAIN);
  CHECK(tfem_add_boundary_edges(m, lower_edges, S.edges, again) == TFEM_STATUS_OK);
  int first = -1, count = -1, n = -1;
  CHECK(tfem_add_contact_pairs_auto(m, 0, NULL, 1e-9, &first, &count) == TFEM_STATUS_OK && count == 1);
  CHECK(tfem_warning_count(m, &n) == TFEM_STATUS_OK && n == 1);
  CHECK(has_warning(m, "did not pair tags 7 (body 2) and 99 (body 1)"));
  CHECK(has_warning(m, "contact pair (4, 7)"));
  tfem_destroy(m);

  int merged[1024];
  for (int k = 0; k < S.ne; ++k) merged[k] = (S.tags[k] == 4 || S.tags[k] == 6) ? 50 : S.tags[k];
  tfem_model *t = model_of(&S, 2, 1e9, 1.0, TFEM_PLANE_MODE_STRAIN);
  CHECK(tfem_set_boundary_edges(t, S.ne, S.edges, merged) == TFEM_STATUS_OK);
  CHECK(tfem_add_contact_pairs_auto(t, 0, NULL, 1e-9, &first, &count) == TFEM_STATUS_OK && count == 0);
  CHECK(has_warning(t, "left out tag 50: its edges bound bodies 1, 2"));
  tfem_destroy(t);
}

/* Two blocks meshed 6 and 4 cells across (3:2, no interface node but the
 * ends faces another) under a uniform pressure: every interface node reads
 * the pressure, the others read zero. */
static mesh_t N;
static void a_non_matching_interface_reads_a_uniform_pressure_at_every_node(void) {
  tfem_model *m = model_of(&N, 2, 1e10, 1.0, TFEM_PLANE_MODE_STRAIN);
  CHECK(tfem_fix_edges(m, 32, TFEM_COMPONENT_Y, 0.0) == TFEM_STATUS_OK);
  CHECK(tfem_fix(m, 0, TFEM_COMPONENT_X, 0.0) == TFEM_STATUS_OK);
  CHECK(tfem_fix(m, 21, TFEM_COMPONENT_X, 0.0) == TFEM_STATUS_OK); /* the upper block's first node */
  CHECK(tfem_add_pressure(m, 43, 1e7) == TFEM_STATUS_OK);
  CHECK(tfem_add_contact_pair(m, 33, 42, NULL) == TFEM_STATUS_OK);
  double p[64];
  EXPECT_ERROR(m, tfem_get_contact_nodal_pressures(m, p, 64), TFEM_STATUS_INVALID_STATE, "solve");
  CHECK(tfem_solve_contact(m, NULL, NULL) == TFEM_STATUS_OK);
  EXPECT_ERROR(m, tfem_get_contact_nodal_pressures(m, p, (size_t)N.nn - 1), TFEM_STATUS_BUFFER_TOO_SMALL, "out");
  CHECK(tfem_get_contact_nodal_pressures(m, p, (size_t)N.nn) == TFEM_STATUS_OK);
  int on_interface = 0;
  for (int v = 0; v < N.nn; ++v) {
    double y = N.xy[2 * v + 1];
    if (y == 0.0) {
      on_interface++;
      CHECK(fabs(p[v] / 1e7 - 1.0) < 1e-9);
    } else {
      CHECK(p[v] == 0.0);
    }
  }
  CHECK(on_interface == 7 + 5);
  tfem_destroy(m);
}

/* A host equation below the index base marks a fixed DOF, INT64_MIN too:
 * at base 1 it overflowed (found by the fuzzer) into equation 2^63 - 1, and
 * the pattern, the element equations and gather went wrong. The context
 * must be the same as with base - 1 as the marker. */
static void an_equation_of_int64_min_marks_a_fixed_dof_at_any_base(void) {
  for (int base = 0; base <= 1; ++base) {
    int64_t entries[2] = {-1, -1}, eqs[2][64];
    int n_nodes[2] = {0, 0}, n_elements[2] = {0, 0};
    for (int variant = 0; variant < 2; ++variant) {
      tfem_contact *c = tfem_contact_create(base);
      int na[2] = {1, 2}, nb[2] = {3, 4}, ea[2] = {1, 2}, eb[2] = {3, 4};
      double xa[4] = {1.0, 0.0, 0.0, 0.0}, xb[4] = {0.0, -0.01, 1.0, -0.01};
      int64_t qa[4] = {base + 0, base + 1, base + 2, base + 3};
      int64_t qb[4] = {variant ? INT64_MIN : base - 1, base + 5, base + 6, base + 7};
      CHECK(tfem_contact_add_side(c, 1, 1, 1e10, 0.3, 0, 2, na, xa, qa, 1, ea, NULL) == TFEM_STATUS_OK);
      CHECK(tfem_contact_add_side(c, 2, 2, 1e10, 0.3, 0, 2, nb, xb, qb, 1, eb, NULL) == TFEM_STATUS_OK);
      CHECK(tfem_contact_add_pair(c, 0, 1, NULL) == TFEM_STATUS_OK);
      CHECK(tfem_contact_sizes(c, &n_nodes[variant], &n_elements[variant], &entries[variant]) ==
            TFEM_STATUS_OK);
      CHECK(n_elements[variant] > 0 && 6 * n_elements[variant] <= 64);
      CHECK(tfem_contact_element_equations(c, eqs[variant], (size_t)(6 * n_elements[variant])) ==
            TFEM_STATUS_OK);
      double host[8] = {0}, u[8];
      CHECK(tfem_contact_gather(c, host, 8, u, (size_t)(2 * n_nodes[variant])) == TFEM_STATUS_OK);
      tfem_contact_destroy(c);
    }
    CHECK(entries[0] == entries[1] && n_elements[0] == n_elements[1]);
    for (int i = 0; i < 6 * n_elements[0]; ++i) CHECK(eqs[0][i] == eqs[1][i] && eqs[1][i] >= base - 1);
  }
}

/* Three bodies: a lower block, and two blocks B and C side by side on it
 * touching at x = 0.5, pressed down by p and together by q (frictionless,
 * three pairs). Exact: uniform stress, p on every bed node, q on every
 * three pairs). Exact: uniform stress, p on every bed node, q on every
 * head-joint node. Where B and C meet the lower block, its node lies on
 * two bed pairs and reads p; the corners of B and C lie on a bed and a
 * head pair and read the mean of their faces' pressures over equal
 * tributaries, (p + q) / 2. Found wrong at these three nodes: the pairs
 * were read together, each counting the edge beyond its end and one
 * normal for both faces. */
static mesh_t T;
static void a_node_on_several_pairs_reads_their_forces_over_their_tributaries(void) {
  const double p = 1e7, q = 4e6;
  tfem_model *m = model_of(&T, 3, 1e10, 1.0, TFEM_PLANE_MODE_STRESS);
  CHECK(tfem_fix_edges(m, 52, TFEM_COMPONENT_Y, 0.0) == TFEM_STATUS_OK);
  CHECK(tfem_fix(m, 0, TFEM_COMPONENT_X, 0.0) == TFEM_STATUS_OK);
  CHECK(tfem_fix(m, 27, TFEM_COMPONENT_X, 0.0) == TFEM_STATUS_OK); /* B's first node */
  CHECK(tfem_add_pressure(m, 63, p) == TFEM_STATUS_OK);
  CHECK(tfem_add_pressure(m, 73, p) == TFEM_STATUS_OK);
  CHECK(tfem_add_pressure(m, 60, q) == TFEM_STATUS_OK);
  CHECK(tfem_add_pressure(m, 71, q) == TFEM_STATUS_OK);
  CHECK(tfem_add_contact_pair(m, 53, 62, NULL) == TFEM_STATUS_OK);
  CHECK(tfem_add_contact_pair(m, 53, 72, NULL) == TFEM_STATUS_OK);
  CHECK(tfem_add_contact_pair(m, 61, 70, NULL) == TFEM_STATUS_OK);
  CHECK(tfem_solve_contact(m, NULL, NULL) == TFEM_STATUS_OK);
  double r[128];
  CHECK(tfem_get_contact_nodal_pressures(m, r, (size_t)T.nn) == TFEM_STATUS_OK);
  int bed = 0, head = 0, corners = 0, shared = 0;
  for (int v = 0; v < T.nn; ++v) {
    double x = T.xy[2 * v], y = T.xy[2 * v + 1];
    int on_bed = y == 0.0, on_head = x == 0.5 && y >= 0.0 && v >= 27;
    double want = 0.0;
    if (on_bed && on_head) {
      want = 0.5 * (p + q);
      corners++;
    } else if (on_bed) {
      want = p;
      bed++;
      shared += x == 0.5;
    } else if (on_head) {
      want = q;
      head++;
    }
    CHECK(fabs(r[v] - want) <= 1e-9 * p);
  }
  /* 9 lower bed nodes, 4 + 4 upper ones besides the 2 corners, 2 + 2
   * head-joint nodes above the corners. */
  CHECK(bed == 9 + 4 + 4 && corners == 2 && head == 4 && shared == 1);

  /* Pair by pair, each node reads its face of that pair alone: p on the
   * two bed pairs (the shared node on both), q on the head pair, the
   * corners p on their bed pair and q on the head pair; 0 off the pair,
   * including the nodes of its strip beyond the other side's end (which
   * ends on a node here: one ending inside an edge gives the first node
   * past it the other side's pressure near the end, as the header says). */
  for (int pair = 0; pair < 3; ++pair) {
    CHECK(tfem_get_contact_pair_nodal_pressures(m, pair, r, (size_t)T.nn) == TFEM_STATUS_OK);
    int on = 0, right = 1;
    for (int v = 0; v < T.nn; ++v) {
      double x = T.xy[2 * v], y = T.xy[2 * v + 1];
      int body = v < 27 ? 1 : v < 42 ? 2 : 3; /* the lower block, B, C */
      int in_pair = pair == 0 ? y == 0.0 && x <= 0.5 && body != 3
                  : pair == 1 ? y == 0.0 && x >= 0.5 && body != 2
                              : x == 0.5 && y >= 0.0 && body != 1;
      double want = in_pair ? (pair == 2 ? q : p) : 0.0;
      on += in_pair;
      if (fabs(r[v] - want) > 1e-9 * p) {
        right = 0;
        printf("pair %d node %d (%g, %g): %.10g, want %.10g\n", pair, v, x, y, r[v], want);
      }
    }
    CHECK(right && on == (pair == 2 ? 6 : 10));
  }
  EXPECT_ERROR(m, tfem_get_contact_pair_nodal_pressures(m, 3, r, (size_t)T.nn), TFEM_STATUS_INVALID_ARGUMENT,
               "contact pair 3");
  EXPECT_ERROR(m, tfem_get_contact_pair_nodal_pressures(m, -1, r, (size_t)T.nn), TFEM_STATUS_INVALID_ARGUMENT,
               "contact pair -1");
  tfem_destroy(m);
}

/* The outside probe's three-body corner (docs/method.md §6.11, "Sides
 * that end inside an edge"): base C = [0,2] x [-1,0] (E = 1e9, 7 cells
 * across: no node under the corner (1, 0)) under A = [0,1] x [0,1] (2e9)
 * and B = [1,2] x [0,1] (5e8), the head joint closed by u = 0 on A's left
 * and B's right, C free to the right; p on A and B, pairs found
 * automatically. Exact: sigma_yy = -p everywhere, sigma_xx = 0 in C and
 * uniform in A and B, contact length 2 + 1. Found wrong: the base
 * edge across the corner was counted whole by both bed pairs (twice its
 * stiffness there): 4.7e-2 p in A, element pressures down to 0.6 p,
 * contact length 3.14286. */
static mesh_t K;
static void a_side_ending_inside_an_edge_of_the_other_carries_the_uniform_stress(void) {
  const double p = 1e6, nu = 0.3;
  tfem_model *m = tfem_create();
  CHECK(tfem_set_mesh(m, K.nn, K.xy, K.nt, K.tri, K.body, 0) == TFEM_STATUS_OK);
  CHECK(tfem_set_boundary_edges(m, K.ne, K.edges, K.tags) == TFEM_STATUS_OK);
  CHECK(tfem_set_material(m, 1, 1e9, nu, TFEM_PLANE_MODE_STRAIN) == TFEM_STATUS_OK);
  CHECK(tfem_set_material(m, 2, 2e9, nu, TFEM_PLANE_MODE_STRAIN) == TFEM_STATUS_OK);
  CHECK(tfem_set_material(m, 3, 5e8, nu, TFEM_PLANE_MODE_STRAIN) == TFEM_STATUS_OK);
  CHECK(tfem_fix_edges(m, 82, TFEM_COMPONENT_Y, 0.0) == TFEM_STATUS_OK);
  CHECK(tfem_fix_edges(m, 80, TFEM_COMPONENT_X, 0.0) == TFEM_STATUS_OK);
  CHECK(tfem_fix_edges(m, 90, TFEM_COMPONENT_X, 0.0) == TFEM_STATUS_OK);
  CHECK(tfem_fix_edges(m, 101, TFEM_COMPONENT_X, 0.0) == TFEM_STATUS_OK);
  CHECK(tfem_add_pressure(m, 93, p) == TFEM_STATUS_OK);
  CHECK(tfem_add_pressure(m, 103, p) == TFEM_STATUS_OK);
  int first = -1, count = -1;
  CHECK(tfem_add_contact_pairs_auto(m, 0, NULL, 1e-9, &first, &count) == TFEM_STATUS_OK);
  CHECK(count == 3); /* C-A, C-B, A|B */
  tfem_contact_report r;
  CHECK(tfem_solve_contact(m, NULL, &r) == TFEM_STATUS_OK);
  CHECK(r.active == r.elements);
  CHECK(fabs(r.contact_length - 3.0) < 1e-12);
  static double s[3 * 4096];
  CHECK(tfem_get_element_stresses(m, s, 3 * (size_t)K.nt) == TFEM_STATUS_OK);
  /* sigma_xx in A and B is uniform, -nu/(1 - nu) p only up to the head
   * joint's penalty overlap (1.1e-2 p, also with a base node under the
   * corner): it is compared with its value in their first element. */
  double worst = 0.0, sxx_ab = 0.0;
  int seen = 0;
  for (int t = 0; t < K.nt; ++t) {
    if (K.body[t] != 1 && !seen++) sxx_ab = s[3 * t];
    double sxx = K.body[t] == 1 ? 0.0 : sxx_ab;
    double d = fmax(fabs(s[3 * t] - sxx), fmax(fabs(s[3 * t + 1] + p), fabs(s[3 * t + 2])));
    worst = fmax(worst, d / p);
  }
  CHECK(fabs(sxx_ab / p + nu / (1.0 - nu)) < 2e-2);
  if (worst > 1e-9) printf("corner: stress error %.3e of p\n", worst);
  CHECK(worst <= 1e-9);
  /* Every element of a bed pair reports p, the cut ones too. */
  static double pe[1024];
  static int pair[1024];
  CHECK(r.elements <= 1024);
  CHECK(tfem_get_contact_pressure(m, pe, (size_t)r.elements) == TFEM_STATUS_OK);
  CHECK(tfem_get_contact_element_pairs(m, pair, (size_t)r.elements) == TFEM_STATUS_OK);
  int beds = 0;
  for (int k = 0; k < r.elements; ++k) {
    if (pair[k] == first + 2) continue; /* the head joint */
    beds++;
    CHECK(fabs(pe[k] - p) <= 1e-9 * p);
  }
  CHECK(beds > 0);
  tfem_destroy(m);
}

/* A host's NaN or Inf is refused where it enters the contact context, named
 * by node and equation, and nothing is written: gather would otherwise hand
 * it back as a displacement with OK, scatter_add add it into the host's
 * vector. An entry at an equation no interface node uses is not read. */
static void a_non_finite_host_value_is_refused_by_gather_and_scatter_add(void) {
  const int base = 1;
  tfem_contact *c = tfem_contact_create(base);
  int na[2] = {1, 2}, nb[2] = {3, 4}, ea[2] = {1, 2}, eb[2] = {3, 4};
  double xa[4] = {1.0, 0.0, 0.0, 0.0}, xb[4] = {0.0, -0.01, 1.0, -0.01};
  int64_t qa[4] = {1, 2, 3, 4}, qb[4] = {0, 6, 7, 8}; /* equation 5 is nobody's */
  CHECK(tfem_contact_add_side(c, 1, 1, 1e10, 0.3, 0, 2, na, xa, qa, 1, ea, NULL) == TFEM_STATUS_OK);
  CHECK(tfem_contact_add_side(c, 2, 2, 1e10, 0.3, 0, 2, nb, xb, qb, 1, eb, NULL) == TFEM_STATUS_OK);
  CHECK(tfem_contact_add_pair(c, 0, 1, NULL) == TFEM_STATUS_OK);
  char msg[512];
  double host[8] = {0.1, 0.2, 0.3, 0.4, 0.5, 0.6, 0.7, 0.8}, u[8];
  for (int k = 0; k < 8; ++k) u[k] = -7.0;

  host[6] = NAN; /* equation 7: node 4, x */
  CHECK(tfem_contact_gather(c, host, 8, u, 8) == TFEM_STATUS_INVALID_ARGUMENT);
  tfem_contact_last_error(c, msg, sizeof msg);
  CHECK(strstr(msg, "`u_equations`") && strstr(msg, "interface node 4") && strstr(msg, "equation 7"));
  int untouched = 1;
  for (int k = 0; k < 8; ++k) untouched &= u[k] == -7.0;
  CHECK(untouched);

  host[6] = 0.7;
  host[4] = INFINITY; /* equation 5: no interface node's */
  CHECK(tfem_contact_gather(c, host, 8, u, 8) == TFEM_STATUS_OK && all_finite(u, 8));

  double residual[8] = {1, 2, 3, 4, 5, 6, 7, 8}, vector[8] = {0};
  residual[3] = -INFINITY; /* node 2, y */
  CHECK(tfem_contact_scatter_add(c, residual, 8, vector, 8) == TFEM_STATUS_INVALID_ARGUMENT);
  tfem_contact_last_error(c, msg, sizeof msg);
  CHECK(strstr(msg, "`residual`") && strstr(msg, "interface node 2"));
  int zero = 1;
  for (int k = 0; k < 8; ++k) zero &= vector[k] == 0.0;
  CHECK(zero);
  residual[3] = 4.0;
  CHECK(tfem_contact_scatter_add(c, residual, 8, vector, 8) == TFEM_STATUS_OK && vector[3] == 4.0);
  tfem_contact_destroy(c);
}

/* Two sides of a host's interface on y = 0 over [0, 2 s]: side 0 (tag 1,
 * body 1, below) with the host's nodes 10, 11, 12, side 1 (tag 2, body 2,
 * above) with nodes 20, 21, 22 at x_b (3 values, scaled by s); equations
 * 0..11. Every node number is the host's own, far from any position. */
static tfem_contact *two_host_sides(double s, const double *x_b) {
  tfem_contact *c = tfem_contact_create(0);
  int na[3] = {10, 11, 12}, nb[3] = {20, 21, 22}, ea[4] = {12, 11, 11, 10}, eb[4] = {20, 21, 21, 22};
  double xa[6] = {0, 0, s, 0, 2 * s, 0}, xb[6] = {x_b[0] * s, 0, x_b[1] * s, 0, x_b[2] * s, 0};
  int64_t qa[6] = {0, 1, 2, 3, 4, 5}, qb[6] = {6, 7, 8, 9, 10, 11};
  CHECK(tfem_contact_add_side(c, 1, 1, 1e9, 0.3, 0, 3, na, xa, qa, 2, ea, NULL) == TFEM_STATUS_OK);
  CHECK(tfem_contact_add_side(c, 2, 2, 1e9, 0.3, 0, 3, nb, xb, qb, 2, eb, NULL) == TFEM_STATUS_OK);
  return c;
}
static const double MATCHING[3] = {0.0, 1.0, 2.0};

/* Every message of the host context names nodes by the host's numbers (in
 * its index base), never by their position inside a side, and a side by
 * its index and tag (found naming node 1 for the host's 1021, "side 2" for
 * tag 2, and the host's nodes 49, 48 at base 1 as 4, 3). */
static void host_messages_name_the_hosts_nodes_and_sides(void) {
  tfem_contact *c = tfem_contact_create(0);
  int n[3] = {1020, 1021, 1022}, against[4] = {1021, 1020, 1021, 1022}, zero[4] = {1020, 1020, 1020, 1021};
  double xy[6] = {0, 0, 1, 0, 2, 0};
  int64_t q[6] = {0, 1, 2, 3, 4, 5};
  expect_contact_error(c, tfem_contact_add_side(c, 2, 2, 1e9, 0.3, 0, 3, n, xy, q, 2, against, NULL),
                       TFEM_STATUS_INVALID_CONTACT, "edge 1 (nodes 1021, 1022) of contact side 0 (tag 2)",
                       "runs against edge 0 at node 1021", __LINE__);
  expect_contact_error(c, tfem_contact_add_side(c, 2, 2, 1e9, 0.3, 0, 3, n, xy, q, 2, zero, NULL),
                       TFEM_STATUS_INVALID_CONTACT, "edge 0 (nodes 1020, 1020) of contact side 0 (tag 2)",
                       "zero length", __LINE__);
  tfem_contact_destroy(c);

  c = tfem_contact_create(1);
  int n1[3] = {47, 48, 49}, turned[4] = {48, 47, 48, 49}; /* edge 2 (base 1) leaves 48 as edge 1 does */
  int64_t q1[6] = {1, 2, 3, 4, 5, 6};
  expect_contact_error(c, tfem_contact_add_side(c, 7, 2, 1e9, 0.3, 0, 3, n1, xy, q1, 2, turned, NULL),
                       TFEM_STATUS_INVALID_CONTACT, "edge 2 (nodes 48, 49) of contact side 0 (tag 7)",
                       "at node 48", __LINE__);
  tfem_contact_destroy(c);

  c = two_host_sides(1.0, MATCHING);
  int tri[3] = {10, 12, 21};
  expect_contact_error(c, tfem_contact_add_pair_with_mesh(c, 0, 1, 1, tri, NULL), TFEM_STATUS_INVALID_CONTACT,
                       "nodes 10 and 12 are not an edge", "side 0 (tag 1)", __LINE__);
  tfem_contact_destroy(c);

  /* Side 1 over [0, 2] but with nodes at x = 0, 0.5, 2 (no match at 0.5
   * and 1), turned clockwise: the strip is refused, naming both sides. */
  c = tfem_contact_create(0);
  int na[3] = {10, 11, 12}, nb[3] = {20, 21, 22}, ea[4] = {12, 11, 11, 10}, cw[4] = {21, 20, 22, 21};
  double xa[6] = {0, 0, 1, 0, 2, 0}, xb[6] = {0, 0, 0.5, 0, 2, 0};
  int64_t qa[6] = {0, 1, 2, 3, 4, 5}, qb[6] = {6, 7, 8, 9, 10, 11};
  CHECK(tfem_contact_add_side(c, 101, 1, 1e9, 0.3, 0, 3, na, xa, qa, 2, ea, NULL) == TFEM_STATUS_OK);
  CHECK(tfem_contact_add_side(c, 202, 2, 1e9, 0.3, 0, 3, nb, xb, qb, 2, cw, NULL) == TFEM_STATUS_OK);
  expect_contact_error(c, tfem_contact_add_pair(c, 0, 1, NULL), TFEM_STATUS_INVALID_CONTACT,
                       "side 0 (tag 101) and side 1 (tag 202) do not face", "left", __LINE__);
  tfem_contact_destroy(c);

  /* Side 1 beyond side 0's end (x = 2.2 to 4.2): no match and no strip;
   * the nearest node named is the host's. */
  c = tfem_contact_create(0);
  int eb[4] = {20, 21, 21, 22};
  double far[6] = {2.2, 0, 2.7, 0, 4.2, 0};
  CHECK(tfem_contact_add_side(c, 101, 1, 1e9, 0.3, 0, 3, na, xa, qa, 2, ea, NULL) == TFEM_STATUS_OK);
  CHECK(tfem_contact_add_side(c, 202, 2, 1e9, 0.3, 0, 3, nb, far, qb, 2, eb, NULL) == TFEM_STATUS_OK);
  tfem_status st = tfem_contact_add_pair(c, 0, 1, NULL);
  char msg[1024];
  tfem_contact_last_error(c, msg, sizeof msg);
  int names_host_nodes = strstr(msg, "node 20 (contact side 1 (tag 202)) has no matching node on side 0 (tag "
                                     "101): nearest node 12") != NULL;
  int names_no_position = strstr(msg, "node 2 ") == NULL && strstr(msg, "node 3 ") == NULL;
  CHECK(st == TFEM_STATUS_INVALID_CONTACT && names_host_nodes && names_no_position);
  if (!(names_host_nodes && names_no_position)) printf("  message: %s\n", msg);
  tfem_contact_destroy(c);
}

/* A pair of two sides already paired, either way round, is refused naming
 * it: it was accepted and doubled every element of B, the residual, the
 * stiffness and the contact length. The context keeps its one pair. */
static void a_host_pair_declared_twice_is_refused(void) {
  tfem_contact *c = two_host_sides(1.0, MATCHING);
  int pair = -7, n_elements = -1;
  CHECK(tfem_contact_add_pair(c, 0, 1, &pair) == TFEM_STATUS_OK && pair == 0);
  expect_contact_error(c, tfem_contact_add_pair(c, 0, 1, &pair), TFEM_STATUS_INVALID_CONTACT,
                       "contact pair (0, 1)", "already declared", __LINE__);
  expect_contact_error(c, tfem_contact_add_pair(c, 1, 0, &pair), TFEM_STATUS_INVALID_CONTACT,
                       "contact pair (1, 0)", "already declared", __LINE__);
  int tri[3] = {10, 11, 21};
  expect_contact_error(c, tfem_contact_add_pair_with_mesh(c, 1, 0, 1, tri, &pair), TFEM_STATUS_INVALID_CONTACT,
                       "contact pair (1, 0)", "already declared", __LINE__);
  CHECK(pair == 0);
  CHECK(tfem_contact_sizes(c, NULL, &n_elements, NULL) == TFEM_STATUS_OK && n_elements == 4);
  tfem_contact_destroy(c);
}

/* A triangle given twice in a contact mesh (the same three nodes, in any
 * order) is refused by both APIs, naming both triangles: it was accepted
 * and doubled that element of B. */
static void a_contact_triangle_given_twice_is_refused(void) {
  tfem_model *m = two_blocks();
  int n = 0, tris[3 * 17];
  CHECK(tfem_get_contact_mesh_size(m, &n) == TFEM_STATUS_OK && n == 16);
  CHECK(tfem_get_contact_mesh(m, tris, 3 * 16) == TFEM_STATUS_OK);
  tfem_destroy(m);
  tris[48] = tris[9 + 2], tris[49] = tris[9], tris[50] = tris[9 + 1]; /* triangle 3 again, turned */
  m = two_blocks_unpaired();
  EXPECT_ERROR(m, tfem_add_contact_pair_with_mesh(m, 13, 22, 17, tris, NULL, NULL), TFEM_STATUS_INVALID_CONTACT,
               "contact triangle 16 repeats contact triangle 3");
  CHECK(tfem_add_contact_pair_with_mesh(m, 13, 22, 16, tris, NULL, NULL) == TFEM_STATUS_OK);
  tfem_destroy(m);

  tfem_contact *c = two_host_sides(1.0, MATCHING);
  int host[6] = {10, 11, 21, 21, 10, 11};
  expect_contact_error(c, tfem_contact_add_pair_with_mesh(c, 0, 1, 2, host, NULL), TFEM_STATUS_INVALID_CONTACT,
                       "contact triangle 1 repeats contact triangle 0", "nodes 21, 10, 11", __LINE__);
  CHECK(tfem_contact_sizes(c, NULL, NULL, NULL) == TFEM_STATUS_INVALID_STATE); /* no pair */
  tfem_contact_destroy(c);
}

/* A NaN or an infinity in the host's displacements is its input, refused
 * as invalid (naming the node and the value) by every call taking `u`: it
 * was reported as an overflow (NUMERICAL_FAILURE, "rescale the model").
 * The buffers are unchanged. */
static void a_non_finite_displacement_is_invalid_input_not_an_overflow(void) {
  tfem_contact *c = two_host_sides(1.0, MATCHING);
  CHECK(tfem_contact_add_pair(c, 0, 1, NULL) == TFEM_STATUS_OK);
  int64_t n_entries = 0;
  CHECK(tfem_contact_sizes(c, NULL, NULL, &n_entries) == TFEM_STATUS_OK && n_entries > 0);
  double u[12] = {0}, r[12], g[6], p[4], *v = malloc((size_t)n_entries * sizeof(double));
  CHECK(v != NULL);
  for (int k = 0; k < 12; ++k) r[k] = 7.0;
  for (int k = 0; k < 6; ++k) g[k] = 7.0;
  for (int k = 0; k < 4; ++k) p[k] = 7.0;
  for (int64_t k = 0; k < n_entries; ++k) v[k] = 7.0;
  int changed = 7;
  for (int bad = 0; bad < 2; ++bad) {
    u[3] = bad ? INFINITY : NAN; /* node 11, y */
    const char *value = bad ? "inf" : "NaN";
    expect_contact_error(c, tfem_contact_evaluate(c, u, 12, v, (size_t)n_entries, r, 12),
                         TFEM_STATUS_INVALID_ARGUMENT, "interface node 11", value, __LINE__);
    expect_contact_error(c, tfem_contact_pressures(c, u, 12, p, 4), TFEM_STATUS_INVALID_ARGUMENT,
                         "interface node 11", value, __LINE__);
    expect_contact_error(c, tfem_contact_gaps(c, u, 12, g, 6), TFEM_STATUS_INVALID_ARGUMENT, "interface node 11",
                         value, __LINE__);
    expect_contact_error(c, tfem_contact_update(c, u, 12, &changed), TFEM_STATUS_INVALID_ARGUMENT,
                         "interface node 11", value, __LINE__);
  }
  int untouched = changed == 7;
  for (int k = 0; k < 12; ++k) untouched &= r[k] == 7.0;
  for (int k = 0; k < 6; ++k) untouched &= g[k] == 7.0;
  for (int k = 0; k < 4; ++k) untouched &= p[k] == 7.0;
  for (int64_t k = 0; k < n_entries; ++k) untouched &= v[k] == 7.0;
  CHECK(untouched);
  free(v);
  tfem_contact_destroy(c);
}

/* scatter_add whose sum would overflow the host's vector is refused
 * (NUMERICAL_FAILURE naming the node and the equation), and an entry of
 * the host's vector that is not finite already is refused as its input;
 * the vector is unchanged either way. It returned OK with inf written. */
static void scatter_add_refuses_an_overflow_leaving_the_host_vector_unchanged(void) {
  tfem_contact *c = two_host_sides(1.0, MATCHING);
  CHECK(tfem_contact_add_pair(c, 0, 1, NULL) == TFEM_STATUS_OK);
  double residual[12], host[12];
  for (int k = 0; k < 12; ++k) residual[k] = 1.0, host[k] = 0.0;
  residual[9] = 1e308, host[9] = 1e308; /* node 21, y: equation 9 */
  expect_contact_error(c, tfem_contact_scatter_add(c, residual, 12, host, 12), TFEM_STATUS_NUMERICAL_FAILURE,
                       "equation 9 (y of interface node 21)", "overflows", __LINE__);
  int unchanged = host[9] == 1e308;
  for (int k = 0; k < 12; ++k) unchanged &= k == 9 || host[k] == 0.0;
  CHECK(unchanged);
  host[9] = NAN, residual[9] = 1.0;
  expect_contact_error(c, tfem_contact_scatter_add(c, residual, 12, host, 12), TFEM_STATUS_INVALID_ARGUMENT,
                       "`host_vector` holds NaN at equation 9", "interface node 21", __LINE__);
  host[9] = -1e308;
  CHECK(tfem_contact_scatter_add(c, residual, 12, host, 12) == TFEM_STATUS_OK && all_finite(host, 12));
  tfem_contact_destroy(c);

  /* Two DOFs tied to one equation (5): each sum alone fits, both do not. */
  c = tfem_contact_create(0);
  int na[2] = {1, 2}, nb[2] = {3, 4}, ea[2] = {2, 1}, eb[2] = {3, 4};
  double xa[4] = {0, 0, 1, 0}, xb[4] = {0, 0, 1, 0};
  int64_t qa[4] = {0, 1, 2, 5}, qb[4] = {4, 5, 6, 7};
  CHECK(tfem_contact_add_side(c, 1, 1, 1e9, 0.3, 0, 2, na, xa, qa, 1, ea, NULL) == TFEM_STATUS_OK);
  CHECK(tfem_contact_add_side(c, 2, 2, 1e9, 0.3, 0, 2, nb, xb, qb, 1, eb, NULL) == TFEM_STATUS_OK);
  double r8[8] = {0, 0, 0, 1e308, 0, 1e308, 0, 0}, h8[8] = {0};
  expect_contact_error(c, tfem_contact_scatter_add(c, r8, 8, h8, 8), TFEM_STATUS_NUMERICAL_FAILURE,
                       "equation 5 (y of interface node 3)", "overflows", __LINE__);
  CHECK(h8[5] == 0.0);
  tfem_contact_destroy(c);
}

/* The contact length with no element active is +0.0 (it was -0.0). */
static void the_contact_length_with_nothing_active_is_plus_zero(void) {
  tfem_contact *c = two_host_sides(1.0, MATCHING);
  CHECK(tfem_contact_add_pair(c, 0, 1, NULL) == TFEM_STATUS_OK);
  int off[4] = {0, 0, 0, 0};
  double length = -1.0;
  CHECK(tfem_contact_set_active(c, off, 4) == TFEM_STATUS_OK);
  CHECK(tfem_contact_length(c, &length) == TFEM_STATUS_OK && length == 0.0 && !signbit(length));
  tfem_contact_destroy(c);
}

/* Under the mortar weighting a contact solve that settles with no slave
 * node active reported a contact length of -0.0 (a sum of nothing starts
 * from -0.0 in Rust): two blocks clamped apart across a gap of 0.1. */
static mesh_t Z;
static void a_mortar_solve_with_nothing_active_reports_plus_zero(void) {
  grid(&Z, 4, 1, 0.0, -1.0, 1.0, 1.0, 1, 200);
  grid(&Z, 3, 1, 0.0, 0.1, 1.0, 1.0, 2, 210);
  tfem_model *m = model_of(&Z, 2, 1000.0, 1.0, TFEM_PLANE_MODE_STRAIN);
  CHECK(tfem_fix_edges(m, 202, TFEM_COMPONENT_X, 0.0) == TFEM_STATUS_OK);
  CHECK(tfem_fix_edges(m, 202, TFEM_COMPONENT_Y, 0.0) == TFEM_STATUS_OK);
  CHECK(tfem_fix_edges(m, 213, TFEM_COMPONENT_X, 0.0) == TFEM_STATUS_OK);
  CHECK(tfem_fix_edges(m, 213, TFEM_COMPONENT_Y, 0.0) == TFEM_STATUS_OK);
  CHECK(tfem_add_contact_pair(m, 203, 212, NULL) == TFEM_STATUS_OK);
  CHECK(tfem_set_contact_weighting(m, TFEM_CONTACT_WEIGHTING_MORTAR) == TFEM_STATUS_OK);
  tfem_contact_report rep;
  memset(&rep, 0xff, sizeof rep);
  CHECK(tfem_solve_contact(m, NULL, &rep) == TFEM_STATUS_OK);
  CHECK(rep.active == 0);
  CHECK(rep.contact_length == 0.0 && !signbit(rep.contact_length));
  CHECK(rep.max_penetration == 0.0 && !signbit(rep.max_penetration));
  double p[2 * 64];
  CHECK(tfem_get_contact_nodal_pressures(m, p, (size_t)Z.nn) == TFEM_STATUS_OK);
  for (int v = 0; v < Z.nn; ++v) CHECK(p[v] == 0.0 && !signbit(p[v]));
  tfem_destroy(m);
}

/* A non-matching host pair (side 1's nodes at 0, 2/3, 2 against 0, 1, 2)
 * is accepted at every length scale: its degeneracy test compared a length
 * with an area and refused every pair beyond ~1e12 length units. */
static void a_non_matching_host_pair_is_accepted_at_any_length_scale(void) {
  const double scales[] = {1e-9, 1.0, 3e12, 1e13};
  const double non_matching[3] = {0.0, 2.0 / 3.0, 2.0};
  for (int k = 0; k < 4; ++k) {
    tfem_contact *c = two_host_sides(scales[k], non_matching);
    int n_elements = -1;
    double length = -1.0;
    tfem_status st = tfem_contact_add_pair(c, 0, 1, NULL);
    if (st != TFEM_STATUS_OK) {
      char msg[512];
      tfem_contact_last_error(c, msg, sizeof msg);
      printf("  scale %g: %s\n", scales[k], msg);
    }
    CHECK(st == TFEM_STATUS_OK);
    CHECK(tfem_contact_sizes(c, NULL, &n_elements, NULL) == TFEM_STATUS_OK && n_elements == 4);
    int on[4] = {1, 1, 1, 1};
    CHECK(tfem_contact_set_active(c, on, 4) == TFEM_STATUS_OK);
    CHECK(tfem_contact_length(c, &length) == TFEM_STATUS_OK && fabs(length / (2 * scales[k]) - 1) < 1e-14);
    tfem_contact_destroy(c);
  }
}

/* Honest arrays the machine cannot hold: INT_MAX nodes, 32 GiB of
 * coordinates (a read-only mapping of zero pages, which reserves no
 * memory), in an address space capped at 512 MiB above what the process
 * uses. The library's copy must fail as TFEM_STATUS_OUT_OF_MEMORY naming
 * the array and leave the model and the contact context unchanged; so must
 * the first structures it builds from a copy that fits (16 Mi contact
 * triangles or 24 Mi edges: 384 MiB each, under the cap, then as much
 * again). Found aborting the host in Rust's infallible allocation.
 * Skipped under AddressSanitizer, whose shadow memory cannot live under an
 * address-space cap, and wherever the cap cannot be set or does not bite
 * (a 1 GiB malloc must fail under it). */
static void an_array_too_large_to_copy_is_out_of_memory_not_an_abort(void) {
#if defined(__SANITIZE_ADDRESS__)
  printf("skipped under AddressSanitizer: %s\n", __func__);
#else
  size_t bytes = (size_t)INT_MAX * 2 * sizeof(double);
  void *zeros = mmap(NULL, bytes, PROT_READ, MAP_PRIVATE | MAP_ANONYMOUS | MAP_NORESERVE, -1, 0);
  if (zeros == MAP_FAILED) {
    printf("skipped, no %zu-byte mapping: %s\n", bytes, __func__);
    return;
  }
  long pages = 0;
  FILE *statm = fopen("/proc/self/statm", "r");
  int have_size = statm != NULL && fscanf(statm, "%ld", &pages) == 1;
  if (statm) fclose(statm);
  struct rlimit saved, capped;
  if (!have_size || getrlimit(RLIMIT_AS, &saved) != 0) {
    printf("skipped, no process size or address-space limit: %s\n", __func__);
    munmap(zeros, bytes);
    return;
  }
  capped = saved;
  capped.rlim_cur = (rlim_t)pages * (rlim_t)sysconf(_SC_PAGESIZE) + ((rlim_t)512 << 20);
  if (saved.rlim_max != RLIM_INFINITY && capped.rlim_cur > saved.rlim_max) {
    printf("skipped, hard address-space limit too low: %s\n", __func__);
    munmap(zeros, bytes);
    return;
  }

  tfem_model *m = tfem_create();
  CHECK(tfem_set_mesh(m, B.nn, B.xy, B.nt, B.tri, B.body, 0) == TFEM_STATUS_OK);
  CHECK(tfem_set_boundary_edges(m, B.ne, B.edges, B.tags) == TFEM_STATUS_OK);
  tfem_contact *c = tfem_contact_create(0);
  int na[2] = {0, 1}, nb[2] = {2, 3}, ea[2] = {0, 1}, eb[2] = {2, 3};
  double xa[4] = {0.0, 0.0, 1.0, 0.0}, xb[4] = {1.0, 0.0, 0.0, 0.0};
  int64_t qa[4] = {0, 1, 2, 3}, qb[4] = {4, 5, 6, 7};
  CHECK(tfem_contact_add_side(c, 1, 1, 1.0, 0.3, 0, 2, na, xa, qa, 1, ea, NULL) == TFEM_STATUS_OK);
  CHECK(tfem_contact_add_side(c, 2, 2, 1.0, 0.3, 0, 2, nb, xb, qb, 1, eb, NULL) == TFEM_STATUS_OK);

  CHECK(setrlimit(RLIMIT_AS, &capped) == 0);
  void *probe = malloc((size_t)1 << 30);
  if (probe != NULL) {
    free(probe);
    CHECK(setrlimit(RLIMIT_AS, &saved) == 0);
    printf("skipped, the address-space cap does not bite: %s\n", __func__);
  } else {
    const int tris = 16 << 20, edges = 24 << 20;
    int one[3] = {0, 0, 0};
    char msg[512];
    EXPECT_ERROR(m, tfem_set_mesh(m, INT_MAX, zeros, 1, one, one, 0), TFEM_STATUS_OUT_OF_MEMORY, "`xy`");
    EXPECT_ERROR(m, tfem_set_boundary_edges(m, edges, zeros, zeros), TFEM_STATUS_OUT_OF_MEMORY,
                 "boundary edges");
    EXPECT_ERROR(m, tfem_add_contact_pair_with_mesh(m, 13, 22, tris, zeros, NULL, NULL),
                 TFEM_STATUS_OUT_OF_MEMORY, "contact mesh");
    tfem_status st = tfem_contact_add_side(c, 3, 3, 1.0, 0.3, 0, INT_MAX, zeros, zeros, zeros, 0, NULL, NULL);
    tfem_contact_last_error(c, msg, sizeof msg);
    CHECK(st == TFEM_STATUS_OUT_OF_MEMORY && strstr(msg, "`nodes`") != NULL);
    st = tfem_contact_add_side(c, 3, 3, 1.0, 0.3, 0, 2, na, xa, qa, edges, zeros, NULL);
    tfem_contact_last_error(c, msg, sizeof msg);
    CHECK(st == TFEM_STATUS_OUT_OF_MEMORY && strstr(msg, "(tag 3)") != NULL);
    st = tfem_contact_add_pair_with_mesh(c, 0, 1, tris, zeros, NULL);
    tfem_contact_last_error(c, msg, sizeof msg);
    CHECK(st == TFEM_STATUS_OUT_OF_MEMORY && strstr(msg, "contact mesh") != NULL);
    CHECK(setrlimit(RLIMIT_AS, &saved) == 0);
  }
  munmap(zeros, bytes);

  /* Nothing changed: the model's mesh, edges and pairs, the context's sides. */
  int nn = -1, nt = -1, pair = -1, side = -1;
  CHECK(tfem_get_sizes(m, &nn, &nt, NULL) == TFEM_STATUS_OK && nn == B.nn && nt == B.nt);
  CHECK(tfem_add_contact_pair(m, 13, 22, &pair) == TFEM_STATUS_OK && pair == 0);
  CHECK(tfem_contact_add_side(c, 3, 3, 1.0, 0.3, 0, 2, na, xa, qa, 1, ea, &side) == TFEM_STATUS_OK &&
        side == 2);
  CHECK(tfem_contact_add_pair(c, 0, 1, &pair) == TFEM_STATUS_OK && pair == 0);
  tfem_contact_destroy(c);
  tfem_destroy(m);
#endif
}

/* Two n x n blocks of unit squares' halves, the upper on the lower (no
 * shared nodes), in freshly allocated arrays: large enough that every
 * stage of a solve takes memory worth capping. Tags: bottoms 1 and 3,
 * tops 2 and 4. */
typedef struct {
  int nn, nt, ne;
  double *xy;
  int *tri, *body, *edges, *tags;
} blocks_t;

static int blocks_of(int n, blocks_t *g) {
  int nn1 = (n + 1) * (n + 1);
  g->nn = 2 * nn1, g->nt = 4 * n * n, g->ne = 4 * n;
  g->xy = malloc(sizeof(double) * 2 * g->nn);
  g->tri = malloc(sizeof(int) * 3 * g->nt), g->body = malloc(sizeof(int) * g->nt);
  g->edges = malloc(sizeof(int) * 2 * g->ne), g->tags = malloc(sizeof(int) * g->ne);
  if (!g->xy || !g->tri || !g->body || !g->edges || !g->tags) return 0;
  int t = 0, e = 0;
  for (int b = 0; b < 2; b++) {
    for (int j = 0; j <= n; j++)
      for (int i = 0; i <= n; i++) {
        int v = b * nn1 + j * (n + 1) + i;
        g->xy[2 * v] = (double)i / n;
        g->xy[2 * v + 1] = b + (double)j / n;
      }
    for (int j = 0; j < n; j++)
      for (int i = 0; i < n; i++) {
        int a = b * nn1 + j * (n + 1) + i, c = a + 1, d = a + n + 1, f = d + 1;
        int two[6] = {a, c, f, a, f, d};
        memcpy(&g->tri[3 * t], two, sizeof two);
        g->body[t++] = b + 1;
        g->body[t++] = b + 1;
      }
    for (int i = 0; i < n; i++) {
      int lo = b * nn1 + i, hi = b * nn1 + n * (n + 1) + i;
      int two[4] = {lo, lo + 1, hi, hi + 1};
      memcpy(&g->edges[2 * e], two, sizeof two);
      g->tags[e++] = 2 * b + 1;
      g->tags[e++] = 2 * b + 2;
    }
  }
  return 1;
}

/* The blocks' mesh in `m`, the upper pressed on the lower (contact pair 0
 * between them). */
static int pressed(tfem_model *m, const blocks_t *g) {
  return tfem_set_mesh(m, g->nn, g->xy, g->nt, g->tri, g->body, 0) == TFEM_STATUS_OK &&
         tfem_set_boundary_edges(m, g->ne, g->edges, g->tags) == TFEM_STATUS_OK &&
         tfem_set_material(m, 1, 1e3, 0.3, TFEM_PLANE_MODE_STRAIN) == TFEM_STATUS_OK &&
         tfem_set_material(m, 2, 1e3, 0.3, TFEM_PLANE_MODE_STRAIN) == TFEM_STATUS_OK &&
         tfem_fix_edges(m, 1, TFEM_COMPONENT_X, 0.0) == TFEM_STATUS_OK &&
         tfem_fix_edges(m, 1, TFEM_COMPONENT_Y, 0.0) == TFEM_STATUS_OK &&
         tfem_fix_edges(m, 4, TFEM_COMPONENT_X, 0.0) == TFEM_STATUS_OK &&
         tfem_add_pressure(m, 4, 1.0) == TFEM_STATUS_OK &&
         tfem_add_contact_pair(m, 2, 3, NULL) == TFEM_STATUS_OK;
}

/* Whether u equals u_ref to 1e-12 of its largest value (the factorisation
 * may add in another order on another run). */
static int same(const double *u, const double *u_ref, int n) {
  double scale = 0.0, diff = 0.0;
  for (int i = 0; i < n; ++i) {
    scale = fmax(scale, fabs(u_ref[i]));
    diff = fmax(diff, fabs(u[i] - u_ref[i]));
  }
  return diff <= 1e-12 * scale;
}

/* The child of the test below, in a fresh process (exec'd, so that no
 * thread of the parent's is missing in it), under an address space capped
 * at `mib` MiB above what it uses: gives the pressed blocks their mesh
 * (mode "mesh"), solves them ("solve") or takes a load step ("step"), then
 * reads the results. Exit 0: done, every result read; 1:
 * TFEM_STATUS_OUT_OF_MEMORY, after which, with the cap lifted, the same
 * calls succeed with the displacements of an uncapped model; 2: anything
 * else. A reference model solved first, before the cap, has the threads
 * take their dense kernels' buffers, so that the cap bites on the solve's
 * own stages. */
static int solve_under_cap(double mib, const char *mode) {
  int step = strcmp(mode, "step") == 0, clockwise = strcmp(mode, "clockwise") == 0;
  int mesh = clockwise || strcmp(mode, "mesh") == 0;
  int cold = strcmp(mode, "cold") == 0, split = strcmp(mode, "split") == 0;
  blocks_t g;
  tfem_model *ref = tfem_create(), *m = tfem_create();
  /* "split": 2 x 110^2 cells (49k unknowns), so that with two threads or
   * more the factorisation is split into two concurrent subtrees. */
  /* The mesh's copy and its own arrays must outgrow the allocator's
   * slack to be capped: a larger mesh there, and no model set before. */
  if (!blocks_of(mesh ? 100 : split ? 110 : 30, &g) || !ref || !m ||
      (!mesh && (!pressed(ref, &g) || !pressed(m, &g))))
    return 2;
  /* "clockwise": the upper block's triangles numbered clockwise, which the
   * mesh turns (its orientation pass takes the most memory per triangle). */
  for (int t = 0; clockwise && t < g.nt; ++t)
    if (g.body[t] == 2) {
      int keep = g.tri[3 * t + 1];
      g.tri[3 * t + 1] = g.tri[3 * t + 2];
      g.tri[3 * t + 2] = keep;
    }
  int nn = 2 * g.nn, nt = g.nt;
  double *u_ref = malloc(sizeof(double) * nn), *u = malloc(sizeof(double) * nn);
  double *s = malloc(sizeof(double) * 3 * nt), *p = malloc(sizeof(double) * g.nn);
  if (!u_ref || !u || !s || !p) return 2;
  tfem_status st = TFEM_STATUS_OK;
  if (!mesh && !cold) {
    st = step ? tfem_step(ref, 1.0, NULL, NULL) : tfem_solve_contact(ref, NULL, NULL);
    if (st != TFEM_STATUS_OK || tfem_get_displacements(ref, u_ref, nn) != TFEM_STATUS_OK) return 2;
  }
  long pages = 0;
  FILE *statm = fopen("/proc/self/statm", "r");
  int have = statm && fscanf(statm, "%ld", &pages) == 1;
  if (statm) fclose(statm);
  struct rlimit saved, capped;
  if (!have || getrlimit(RLIMIT_AS, &saved) != 0) return 2;
  capped = saved;
  capped.rlim_cur = (rlim_t)pages * (rlim_t)sysconf(_SC_PAGESIZE) + (rlim_t)(mib * 1048576.0);
  if (saved.rlim_max != RLIM_INFINITY && capped.rlim_cur > saved.rlim_max) return 2;
  if (setrlimit(RLIMIT_AS, &capped) != 0) return 2;
  if (mesh) {
    /* Refused, the model has still no mesh; either way, with the cap
     * lifted, it takes the whole scene. */
    st = tfem_set_mesh(m, g.nn, g.xy, g.nt, g.tri, g.body, 0);
    int sizes[3];
    if (st == TFEM_STATUS_OUT_OF_MEMORY &&
        tfem_get_sizes(m, &sizes[0], &sizes[1], &sizes[2]) != TFEM_STATUS_INVALID_STATE)
      return 2;
    if ((st != TFEM_STATUS_OK && st != TFEM_STATUS_OUT_OF_MEMORY) ||
        setrlimit(RLIMIT_AS, &saved) != 0 || !pressed(m, &g) ||
        tfem_get_sizes(m, &sizes[0], &sizes[1], &sizes[2]) != TFEM_STATUS_OK ||
        sizes[0] != g.nn || sizes[1] != g.nt)
      return 2;
    return st == TFEM_STATUS_OUT_OF_MEMORY;
  }
  st = step ? tfem_step(m, 1.0, NULL, NULL) : tfem_solve_contact(m, NULL, NULL);
  int out_of_memory = st == TFEM_STATUS_OUT_OF_MEMORY;
  char msg[512] = "";
  if (out_of_memory) {
    if (setrlimit(RLIMIT_AS, &saved) != 0) return 2;
    st = step ? tfem_step(m, 1.0, NULL, NULL) : tfem_solve_contact(m, NULL, NULL);
  } else if (st != TFEM_STATUS_OK) {
    tfem_last_error(m, msg, sizeof msg);
    printf("  cap +%.2f MiB (%s): status %d: %s\n", mib, mode, (int)st, msg);
    return 2;
  }
  /* The results, under the cap when the call succeeded under it (reading
   * them may take memory too: recovering a step's field, say); refused
   * for memory, they must read once the cap is lifted. */
  for (int pass = 0; pass < 2; ++pass) {
    tfem_status read[3] = {tfem_get_displacements(m, u, nn),
                           tfem_get_element_stresses(m, s, 3 * nt),
                           tfem_get_contact_nodal_pressures(m, p, nn / 2)};
    int all = 1, memory = 1;
    for (int k = 0; k < 3; ++k) {
      all &= read[k] == TFEM_STATUS_OK;
      memory &= read[k] == TFEM_STATUS_OK || read[k] == TFEM_STATUS_OUT_OF_MEMORY;
    }
    if (all) break;
    if (!memory || pass == 1 || setrlimit(RLIMIT_AS, &saved) != 0) return 2;
    out_of_memory = 1;
  }
  if (setrlimit(RLIMIT_AS, &saved) != 0) return 2;
  if (cold && (tfem_solve_contact(ref, NULL, NULL) != TFEM_STATUS_OK ||
               tfem_get_displacements(ref, u_ref, nn) != TFEM_STATUS_OK))
    return 2;
  if (st != TFEM_STATUS_OK || !same(u, u_ref, nn)) return 2;
  return out_of_memory ? 1 : 0;
}

/* A solve or a load step under an address-space limit (`ulimit -v`)
 * anywhere from a few hundred kilobytes to what it needs must come back
 * with TFEM_STATUS_OUT_OF_MEMORY, the model unchanged (the same call
 * succeeds once the limit is lifted), or succeed: never abort the host.
 * Found aborting at most limits below what the solve needs: the
 * set-up's vectors, the matrix pattern, the ordering's graph and faer's
 * per-thread packing buffer (twice the last-level cache, taken at a
 * thread's first dense product) were allocated infallibly. Each limit is
 * tried in a fresh process, in steps of 0.05 MiB, until the call
 * succeeds. Skipped under AddressSanitizer (its shadow memory cannot live
 * under an address-space cap). */
static void a_solve_under_any_memory_limit_fails_cleanly_or_succeeds(void) {
#if defined(__SANITIZE_ADDRESS__)
  printf("skipped under AddressSanitizer: %s\n", __func__);
#else
  /* "cold": no solve before, so that the threads take their dense
   * kernels' buffers (64 MiB each here, with an allocator arena each) in
   * the capped solve: larger steps. "split": 49k unknowns, whose
   * factorisation is split into two concurrent subtrees on two threads or
   * more: 0.1 MiB steps. */
  const char *modes[6] = {"mesh", "clockwise", "solve", "step", "split", "cold"};
  for (int k = 0; k < 6; ++k) {
    int tried = 0, refused = 0, solved = 0, bad = 0;
    double by = k == 5 ? 2.0 : k == 4 ? 0.1 : 0.05;
    for (double mib = 0.0; mib < 2048.0 && !solved && !bad; mib += by) {
      char cap[32];
      snprintf(cap, sizeof cap, "%.2f", mib);
      fflush(stdout);
      pid_t pid = fork();
      if (pid == 0) {
        char *args[] = {"boundary_test", "--solve-under-cap", cap, (char *)modes[k], NULL};
        execv("/proc/self/exe", args);
        _exit(3);
      }
      int ws = 0;
      if (pid < 0 || waitpid(pid, &ws, 0) != pid) {
        bad = 1;
        break;
      }
      ++tried;
      if (WIFSIGNALED(ws)) {
        printf("  cap +%s MiB (%s): killed by signal %d\n", cap, modes[k], WTERMSIG(ws));
        bad = 1;
      } else if (WEXITSTATUS(ws) == 1) {
        ++refused;
      } else if (WEXITSTATUS(ws) == 0) {
        solved = 1;
      } else {
        printf("  cap +%s MiB (%s): exit %d\n", cap, modes[k], WEXITSTATUS(ws));
        bad = 1;
      }
    }
    printf("%s under a memory limit: %d limits tried, %d refused, then %s\n", modes[k], tried,
           refused, solved ? "solved" : "failed");
    CHECK(!bad);
    CHECK(solved);
    CHECK(refused >= 20); /* the limits bit, over at least 1 MiB */
  }
#endif
}

/* Found by a review: a host node number below the index base (0 at base
 * 1, or negative) was accepted as a node. Refused with INVALID_ARGUMENT
 * naming the side, the entry and the number, in a side and in a host's
 * contact triangle; the context is unchanged (the side given right is
 * then side 0, the pair then pair 0). */
static void a_host_node_below_the_index_base_is_refused(void) {
  tfem_contact *c = tfem_contact_create(1);
  int nodes[2] = {7, 0}, edges[2] = {7, 0}, side = -1;
  double xy[4] = {0.0, 0.0, 1.0, 0.0};
  int64_t eq[4] = {1, 2, 3, 4};
  expect_contact_error(c, tfem_contact_add_side(c, 5, 1, 1e9, 0.3, 0, 2, nodes, xy, eq, 1, edges, &side),
                       TFEM_STATUS_INVALID_ARGUMENT, "side 0 (tag 5): node 0 (entry 2)",
                       "below the index base 1", __LINE__);
  nodes[1] = -3, edges[1] = -3;
  expect_contact_error(c, tfem_contact_add_side(c, 5, 1, 1e9, 0.3, 0, 2, nodes, xy, eq, 1, edges, &side),
                       TFEM_STATUS_INVALID_ARGUMENT, "node -3 (entry 2)", "below the index base 1", __LINE__);
  CHECK(side == -1);
  tfem_contact_destroy(c);

  c = two_host_sides(1.0, MATCHING); /* base 0 */
  int tris[6] = {10, 11, 21, 11, -1, 21}, pair = -1;
  expect_contact_error(c, tfem_contact_add_pair_with_mesh(c, 0, 1, 2, tris, &pair), TFEM_STATUS_INVALID_ARGUMENT,
                       "pair 0 (sides 0 and 1), contact triangle 1: node -1 (its second)",
                       "below the index base 0", __LINE__);
  CHECK(pair == -1 && tfem_contact_add_pair(c, 0, 1, &pair) == TFEM_STATUS_OK && pair == 0);
  tfem_contact_destroy(c);
}

/* Found by a review: equation numbers up to INT64_MAX were accepted by
 * tfem_contact_add_side and refused only at tfem_contact_gather. The
 * host's system size is not known at declaration, but no array of
 * doubles spans more than PTRDIFF_MAX bytes: an equation from index_base
 * + PTRDIFF_MAX / 8 on is refused there, naming the node and the
 * equation, the context unchanged; the largest one below is accepted, and
 * so is any value below the base (a DOF without an equation). */
static void an_equation_no_host_vector_can_hold_is_refused_at_declaration(void) {
  const int64_t vectors = (int64_t)(PTRDIFF_MAX / sizeof(double));
  for (int base = 0; base <= 1; ++base) {
    int64_t last = vectors - 1 + base, bad[2] = {INT64_MAX, last + 1};
    char needle[96];
    for (int k = 0; k < 2; ++k) {
      tfem_contact *c = tfem_contact_create(base);
      int nodes[2] = {7, 8}, edges[2] = {7, 8}, side = -1;
      double xy[4] = {0.0, 0.0, 1.0, 0.0};
      int64_t eq[4] = {base, base + 1, base + 2, bad[k]};
      snprintf(needle, sizeof needle, "node 8 (entry %d) has equation %lld for its y unknown", 1 + base,
               (long long)bad[k]);
      expect_contact_error(c, tfem_contact_add_side(c, 5, 1, 1e9, 0.3, 0, 2, nodes, xy, eq, 1, edges, &side),
                           TFEM_STATUS_INVALID_ARGUMENT, needle, "beyond any host vector", __LINE__);
      eq[3] = last;
      CHECK(side == -1 && tfem_contact_add_side(c, 5, 1, 1e9, 0.3, 0, 2, nodes, xy, eq, 1, edges, &side) ==
                              TFEM_STATUS_OK && side == 0);
      eq[1] = INT64_MIN, eq[3] = base - 5;
      nodes[0] = 9, nodes[1] = 10, edges[0] = 9, edges[1] = 10;
      CHECK(tfem_contact_add_side(c, 6, 2, 1e9, 0.3, 0, 2, nodes, xy, eq, 1, edges, &side) == TFEM_STATUS_OK);
      tfem_contact_destroy(c);
    }
  }
}

/* The size of a contact context's message, for a buffer that holds all
 * of it (the Fortran helper copied it through 4096 bytes): the message's
 * length plus the NUL, 1 after a success, and for a handle that is not a
 * live context the size of the message saying so. */
static void a_contact_message_size_is_known_before_it_is_copied(void) {
  tfem_contact *c = tfem_contact_create(0);
  CHECK(tfem_contact_last_error_length(c) == 1);
  CHECK(tfem_contact_add_pair(c, 0, 1, NULL) == TFEM_STATUS_INVALID_ARGUMENT);
  char msg[512];
  CHECK(tfem_contact_last_error(c, msg, sizeof msg) == TFEM_STATUS_OK);
  CHECK(tfem_contact_last_error_length(c) == strlen(msg) + 1);
  char *exact = malloc(tfem_contact_last_error_length(c));
  CHECK(exact != NULL && tfem_contact_last_error(c, exact, tfem_contact_last_error_length(c)) == TFEM_STATUS_OK &&
        strcmp(exact, msg) == 0);
  free(exact);
  tfem_model *m = tfem_create();
  CHECK(tfem_contact_last_error(((tfem_contact *)(void *)m), msg, sizeof msg) == TFEM_STATUS_INVALID_ARGUMENT);
  CHECK(tfem_contact_last_error_length((tfem_contact *)(void *)m) == strlen(msg) + 1);
  CHECK(tfem_contact_last_error_length(NULL) == 1);
  tfem_destroy(m);
  tfem_contact_destroy(c);
}

/* Found by a review: a step could not be reverted once a DOF was fixed
 * since, as if that remade the contact mesh its state belongs to. A new
 * prescribed DOF changes the stiffness (and so the interface factor, made
 * anew by the next step), not the contact mesh, as new materials do,
 * which never blocked a revert. The next step starts from the state
 * before the reverted step, bit for bit as a new model with that DOF
 * fixed given that state; turning friction on (which remakes the contact
 * mesh) still blocks the revert, and the message names that change. */
static void a_step_is_reverted_across_a_newly_fixed_dof(void) {
  size_t size = 0;
  uint8_t *state = NULL;
  tfem_model *m = stepped_past_a_saved_state(&state, &size);
  CHECK(tfem_fix(m, 45, TFEM_COMPONENT_X, 0.0) == TFEM_STATUS_OK); /* the upper top left corner */
  CHECK(tfem_revert_step(m) == TFEM_STATUS_OK);
  CHECK(tfem_step(m, 1.0, NULL, NULL) == TFEM_STATUS_OK);
  tfem_model *fresh = two_blocks();
  CHECK(tfem_fix(fresh, 45, TFEM_COMPONENT_X, 0.0) == TFEM_STATUS_OK);
  CHECK(tfem_set_contact_state(fresh, state, size) == TFEM_STATUS_OK);
  CHECK(tfem_step(fresh, 1.0, NULL, NULL) == TFEM_STATUS_OK);
  double u[2 * 64], v[2 * 64];
  CHECK(tfem_get_displacements(m, u, 2 * B.nn) == TFEM_STATUS_OK);
  CHECK(tfem_get_displacements(fresh, v, 2 * B.nn) == TFEM_STATUS_OK);
  CHECK(memcmp(u, v, 2 * (size_t)B.nn * sizeof(double)) == 0);
  CHECK(tfem_step(m, 1.5, NULL, NULL) == TFEM_STATUS_OK);
  CHECK(tfem_set_friction(m, 0, 0.3) == TFEM_STATUS_OK);
  EXPECT_ERROR(m, tfem_revert_step(m), TFEM_STATUS_INVALID_STATE, "cannot be reverted: friction on/off changed");
  free(state);
  tfem_destroy(fresh);
  tfem_destroy(m);
}

/* A failed call writes none of its outputs (header, Conventions): every
 * buffer and every value or struct returned through a pointer keeps its
 * bytes, whatever the failure (NULL or destroyed handle, wrong state,
 * buffer too short or NULL beside others that are long enough, bad
 * argument, a solve that fails after its work). The only exceptions are
 * the message copies, checked at the end. Outputs are filled with a
 * sentinel byte before each call and must come back with every byte of it. */
#define SENTINEL 0xA5
typedef union {
  double d[8192];
  int64_t l[8192];
  int i[16384];
  size_t z[8192];
  uint8_t b[65536];
  char c[65536];
  tfem_solve_info info;
  tfem_contact_report rep;
} outbuf_t;
static outbuf_t O[4];

static int outputs_intact(void) {
  const unsigned char *b = (const unsigned char *)O;
  for (size_t k = 0; k < sizeof O; ++k)
    if (b[k] != SENTINEL) return 0;
  return 1;
}
static void expect_unwritten(tfem_status got, tfem_status expected, const char *call, int line) {
  int intact = outputs_intact();
  if (got == expected && intact) {
    ++passed;
  } else {
    ++failed;
    printf("FAIL line %d: %s: status %d (expected %d), outputs %s\n", line, call, (int)got,
           (int)expected, intact ? "intact" : "WRITTEN");
  }
}
/* Runs `call` on sentinel-filled outputs O[0..3]: it must return `status`
 * and leave every byte of them as it was. */
#define UNWRITTEN(call, status)                          \
  do {                                                   \
    memset(O, SENTINEL, sizeof O);                       \
    expect_unwritten((call), (status), #call, __LINE__); \
  } while (0)

static void a_failed_call_writes_none_of_its_outputs(void) {
  const tfem_status NUL = TFEM_STATUS_NULL_POINTER, ARG = TFEM_STATUS_INVALID_ARGUMENT,
                    STATE = TFEM_STATUS_INVALID_STATE, SHORT = TFEM_STATUS_BUFFER_TOO_SMALL,
                    MATERIAL = TFEM_STATUS_INVALID_MATERIAL;
  const size_t L = 8192;

  /* No model, or a destroyed one. */
  tfem_model *dead = tfem_create();
  tfem_destroy(dead);
  UNWRITTEN(tfem_warning_count(NULL, O[0].i), NUL);
  UNWRITTEN(tfem_get_sizes(NULL, O[0].i, O[1].i, O[2].i), NUL);
  UNWRITTEN(tfem_get_displacements(NULL, O[0].d, L), NUL);
  UNWRITTEN(tfem_get_contact_report(NULL, &O[0].rep), NUL);
  UNWRITTEN(tfem_get_threads(dead, O[0].i), ARG);
  UNWRITTEN(tfem_get_system_matrix(dead, O[0].l, L, O[1].l, L, O[2].d, L, O[3].l, L), ARG);
  UNWRITTEN(tfem_get_contact_weighting(dead, O[0].i), ARG);
  /* (An exception: the message copy says why the handle is refused.) */
  memset(O, SENTINEL, sizeof O);
  CHECK(tfem_last_error(dead, O[0].c, 512) == ARG && strstr(O[0].c, "destroyed") != NULL);

  /* No mesh yet. */
  tfem_model *m = tfem_create();
  UNWRITTEN(tfem_get_sizes(m, O[0].i, O[1].i, O[2].i), STATE);
  UNWRITTEN(tfem_get_boundary_edge_count(m, O[0].i), STATE);
  UNWRITTEN(tfem_get_mesh_nodes(m, O[0].d, L), STATE);
  UNWRITTEN(tfem_get_mesh_triangles(m, O[0].i, L, O[1].i, L), STATE);
  UNWRITTEN(tfem_get_boundary_edges(m, O[0].i, L, O[1].i, L), STATE);
  UNWRITTEN(tfem_get_element_jacobians(m, O[0].d, L), STATE);
  UNWRITTEN(tfem_add_contact_pair(m, 13, 22, O[0].i), STATE);
  tfem_destroy(m);

  /* Pure functions refusing their arguments, or failing on the triangle. */
  const double xy[6] = {0, 0, 1, 0, 0, 1}, flat[6] = {0, 0, 1, 0, 2, 0};
  UNWRITTEN(tfem_element_stiffness(xy, 1e9, 0.7, TFEM_PLANE_MODE_STRAIN, 0.0, O[0].d), MATERIAL);
  UNWRITTEN(tfem_element_stiffness(NULL, 1e9, 0.3, TFEM_PLANE_MODE_STRAIN, 0.0, O[0].d), NUL);
  memset(O, SENTINEL, sizeof O);
  tfem_status s = tfem_element_stiffness(flat, 1e9, 0.3, TFEM_PLANE_MODE_STRAIN, 0.0, O[0].d);
  CHECK(s != TFEM_STATUS_OK && outputs_intact()); /* J = 0 in plain FEM */
  UNWRITTEN(tfem_laplacian_stiffness(xy, -1.0, 0.0, O[0].d), ARG);

  /* A mesh, not solved: no results yet. */
  m = two_blocks();
  UNWRITTEN(tfem_get_displacements(m, O[0].d, L), STATE);
  UNWRITTEN(tfem_get_element_strains(m, O[0].d, L), STATE);
  UNWRITTEN(tfem_get_element_stresses(m, O[0].d, L), STATE);
  UNWRITTEN(tfem_get_reactions(m, O[0].d, L), STATE);
  UNWRITTEN(tfem_get_system_matrix_size(m, O[0].l, O[1].l), STATE);
  UNWRITTEN(tfem_get_system_matrix(m, O[0].l, L, O[1].l, L, O[2].d, L, O[3].l, L), STATE);
  UNWRITTEN(tfem_get_external_work(m, O[0].d), STATE);
  UNWRITTEN(tfem_get_contact_report(m, &O[0].rep), STATE);
  UNWRITTEN(tfem_get_contact_active(m, O[0].i, L), STATE);
  UNWRITTEN(tfem_get_contact_pressure(m, O[0].d, L), STATE);
  UNWRITTEN(tfem_get_contact_elements(m, O[0].i, L), STATE);
  UNWRITTEN(tfem_get_contact_forces(m, O[0].d, L), STATE);
  UNWRITTEN(tfem_get_contact_nodal_pressures(m, O[0].d, L), STATE);
  UNWRITTEN(tfem_get_contact_pair_nodal_pressures(m, 0, O[0].d, L), STATE);
  UNWRITTEN(tfem_get_contact_gaps(m, O[0].d, L), STATE);
  UNWRITTEN(tfem_get_contact_shear(m, O[0].d, L), STATE);
  UNWRITTEN(tfem_get_contact_friction_state(m, O[0].i, L), STATE);
  UNWRITTEN(tfem_get_contact_dissipation(m, O[0].d, L), STATE);
  UNWRITTEN(tfem_get_contact_slave_nodes(m, O[0].i, O[1].d, O[2].d, O[3].d, L), STATE);
  UNWRITTEN(tfem_get_contact_state_size(m, O[0].z), STATE);
  UNWRITTEN(tfem_get_contact_state(m, O[0].b, L), STATE);

  /* Bad arguments: what would be written (an index, a count) is not. */
  UNWRITTEN(tfem_get_warning_size(m, 999, O[0].z), ARG);
  UNWRITTEN(tfem_get_warning(m, 999, O[0].c, 512), ARG);
  UNWRITTEN(tfem_get_contact_pair_bodies(m, 1, O[0].i, O[1].i), ARG);
  UNWRITTEN(tfem_add_contact_pair(m, 13, 22, O[0].i), TFEM_STATUS_INVALID_CONTACT);
  const int bad_triangle[3] = {0, 1, 9999};
  UNWRITTEN(tfem_add_contact_pair_with_mesh(m, 13, 22, 1, bad_triangle, O[0].i, O[1].i), ARG);
  UNWRITTEN(tfem_add_contact_pairs_auto(m, 0, NULL, -1.0, O[0].i, O[1].i), ARG);
  const int unknown_tag = 4242;
  memset(O, SENTINEL, sizeof O);
  s = tfem_add_contact_pairs_auto(m, 1, &unknown_tag, 0.1, O[0].i, O[1].i);
  CHECK(s != TFEM_STATUS_OK && outputs_intact());

  /* Solves that fail: before any work (bad options), after it (the
   * active-set cap, a body free to move). */
  tfem_contact_options bad, capped;
  tfem_contact_options_default(&bad);
  bad.law = 7;
  tfem_contact_options_default(&capped);
  capped.max_iterations = 1;
  UNWRITTEN(tfem_solve_contact(m, &bad, &O[0].rep), ARG);
  UNWRITTEN(tfem_solve_contact(m, &capped, &O[0].rep), TFEM_STATUS_NOT_CONVERGED);
  UNWRITTEN(tfem_step(m, NAN, NULL, &O[0].rep), ARG);
  tfem_model *loose = model_of(&B, 2, 1e10, 10.0, TFEM_PLANE_MODE_STRAIN);
  CHECK(tfem_add_pressure(loose, 23, 1e7) == TFEM_STATUS_OK);
  UNWRITTEN(tfem_solve(loose, &O[0].info), TFEM_STATUS_SINGULAR);
  tfem_destroy(loose);

  /* Solved: a buffer too short, or NULL, beside others long enough. */
  CHECK(tfem_step(m, 1.0, NULL, NULL) == TFEM_STATUS_OK);
  int ne = 0, nc = 0;
  int64_t n = 0, nnz = 0;
  size_t state = 0;
  CHECK(tfem_get_boundary_edge_count(m, &ne) == TFEM_STATUS_OK && ne > 0);
  CHECK(tfem_get_sizes(m, NULL, NULL, &nc) == TFEM_STATUS_OK && nc > 0);
  CHECK(tfem_get_contact_state_size(m, &state) == TFEM_STATUS_OK && state > 0 && state <= L);
  const size_t nn = (size_t)B.nn, nt = (size_t)B.nt, ce = (size_t)nc;
  UNWRITTEN(tfem_get_mesh_nodes(m, O[0].d, 2 * nn - 1), SHORT);
  UNWRITTEN(tfem_get_mesh_triangles(m, O[0].i, 3 * nt, O[1].i, nt - 1), SHORT);
  UNWRITTEN(tfem_get_mesh_triangles(m, O[0].i, 3 * nt - 1, O[1].i, nt), SHORT);
  UNWRITTEN(tfem_get_mesh_triangles(m, NULL, 0, O[1].i, nt), NUL);
  UNWRITTEN(tfem_get_boundary_edges(m, O[0].i, 2 * (size_t)ne, O[1].i, (size_t)ne - 1), SHORT);
  UNWRITTEN(tfem_get_boundary_edges(m, O[0].i, 2 * (size_t)ne - 1, O[1].i, (size_t)ne), SHORT);
  UNWRITTEN(tfem_get_displacements(m, O[0].d, 2 * nn - 1), SHORT);
  UNWRITTEN(tfem_get_element_stresses(m, O[0].d, 3 * nt - 1), SHORT);
  UNWRITTEN(tfem_get_reactions(m, NULL, 2 * nn), NUL);
  UNWRITTEN(tfem_get_contact_active(m, O[0].i, ce - 1), SHORT);
  UNWRITTEN(tfem_get_contact_pressure(m, O[0].d, ce - 1), SHORT);
  UNWRITTEN(tfem_get_contact_elements(m, O[0].i, 3 * ce - 1), SHORT);
  UNWRITTEN(tfem_get_contact_mesh(m, O[0].i, 3 * ce - 1), SHORT);
  UNWRITTEN(tfem_get_contact_element_pairs(m, O[0].i, ce - 1), SHORT);
  UNWRITTEN(tfem_get_contact_element_apexes(m, O[0].i, ce - 1), SHORT);
  UNWRITTEN(tfem_get_contact_forces(m, O[0].d, 2 * nn - 1), SHORT);
  UNWRITTEN(tfem_get_contact_nodal_pressures(m, O[0].d, nn - 1), SHORT);
  UNWRITTEN(tfem_get_contact_pair_nodal_pressures(m, 3, O[0].d, nn), ARG);
  UNWRITTEN(tfem_get_contact_gaps(m, O[0].d, nn - 1), SHORT);
  UNWRITTEN(tfem_get_contact_shear(m, O[0].d, ce - 1), SHORT);
  UNWRITTEN(tfem_get_contact_friction_state(m, O[0].i, ce - 1), SHORT);
  UNWRITTEN(tfem_get_contact_dissipation(m, O[0].d, ce - 1), SHORT);
  UNWRITTEN(tfem_get_contact_state(m, O[0].b, state - 1), SHORT);
  UNWRITTEN(tfem_get_contact_state(m, NULL, state), NUL);
  UNWRITTEN(tfem_get_contact_slave_nodes(m, O[0].i, O[1].d, O[2].d, O[3].d, L), STATE);
  /* A step has no system matrix; a contact solve has. */
  UNWRITTEN(tfem_get_system_matrix_size(m, O[0].l, O[1].l), STATE);
  CHECK(tfem_solve_contact(m, NULL, NULL) == TFEM_STATUS_OK);
  CHECK(tfem_get_system_matrix_size(m, &n, &nnz) == TFEM_STATUS_OK && n > 0 && nnz > 0);
  const size_t un = (size_t)n, nz = (size_t)nnz;
  UNWRITTEN(tfem_get_system_matrix(m, O[0].l, un + 1, O[1].l, nz, O[2].d, nz, O[3].l, un - 1), SHORT);
  UNWRITTEN(tfem_get_system_matrix(m, O[0].l, un + 1, O[1].l, nz, O[2].d, nz - 1, O[3].l, un), SHORT);
  UNWRITTEN(tfem_get_system_matrix(m, O[0].l, un + 1, O[1].l, nz, NULL, nz, O[3].l, un), NUL);
  UNWRITTEN(tfem_get_system_matrix(m, O[0].l, un, O[1].l, nz, O[2].d, nz, O[3].l, un), SHORT);

  /* Under the mortar weighting: the slave nodes' columns all or none. */
  CHECK(tfem_set_contact_weighting(m, TFEM_CONTACT_WEIGHTING_MORTAR) == TFEM_STATUS_OK);
  tfem_contact_report rep;
  CHECK(tfem_solve_contact(m, NULL, &rep) == TFEM_STATUS_OK && rep.elements > 1);
  const size_t slaves = (size_t)rep.elements;
  UNWRITTEN(tfem_get_contact_slave_nodes(m, O[0].i, O[1].d, O[2].d, O[3].d, slaves - 1), SHORT);
  UNWRITTEN(tfem_get_contact_slave_nodes(m, NULL, O[1].d, NULL, O[3].d, slaves - 1), SHORT);
  UNWRITTEN(tfem_get_contact_active(m, O[0].i, L), STATE);
  UNWRITTEN(tfem_get_contact_state_size(m, O[0].z), STATE);
  tfem_destroy(m);

  /* The host contact context. */
  UNWRITTEN(tfem_contact_sizes(NULL, O[0].i, O[1].i, O[2].l), NUL);
  tfem_contact *c = tfem_contact_create(0);
  UNWRITTEN(tfem_contact_sizes(c, O[0].i, O[1].i, O[2].l), STATE); /* no pair */
  UNWRITTEN(tfem_contact_length(c, O[0].d), STATE);
  UNWRITTEN(tfem_contact_get_active(c, O[0].i, L), STATE);
  tfem_contact_destroy(c);
  c = two_host_sides(1.0, MATCHING);
  int na[2] = {30, 31}, ea[2] = {30, 31};
  double xa[4] = {0, 1, 1, 1};
  int64_t qa[4] = {12, 13, 14, 15};
  UNWRITTEN(tfem_contact_add_side(c, 3, 3, 1e9, 0.7, 0, 2, na, xa, qa, 1, ea, O[0].i), MATERIAL);
  UNWRITTEN(tfem_contact_add_pair(c, 0, 0, O[0].i), TFEM_STATUS_INVALID_CONTACT);
  UNWRITTEN(tfem_contact_add_pair(c, 0, 7, O[0].i), ARG);
  const int host_triangle[3] = {10, 11, 99};
  memset(O, SENTINEL, sizeof O);
  s = tfem_contact_add_pair_with_mesh(c, 0, 1, 1, host_triangle, O[0].i);
  CHECK(s != TFEM_STATUS_OK && outputs_intact());
  CHECK(tfem_contact_add_pair(c, 0, 1, NULL) == TFEM_STATUS_OK);
  int hn = 0, he = 0;
  int64_t entries = 0;
  CHECK(tfem_contact_sizes(c, &hn, &he, &entries) == TFEM_STATUS_OK && hn == 6 && he > 0 && entries > 0);
  const size_t en = (size_t)entries, hen = (size_t)he;
  double u[12] = {0}, host[12] = {0}, nan_u[12] = {0};
  nan_u[3] = NAN;
  UNWRITTEN(tfem_contact_add_pair(c, 1, 0, O[0].i), STATE); /* B is built: pairs are fixed */
  UNWRITTEN(tfem_contact_nodes(c, O[0].i, 5), SHORT);
  UNWRITTEN(tfem_contact_pattern(c, O[0].l, O[1].l, en - 1), SHORT);
  UNWRITTEN(tfem_contact_pattern(c, O[0].l, NULL, en), NUL);
  UNWRITTEN(tfem_contact_evaluate(c, u, 12, O[0].d, en, O[1].d, 11), SHORT);
  UNWRITTEN(tfem_contact_evaluate(c, u, 12, O[0].d, en - 1, O[1].d, 12), SHORT);
  UNWRITTEN(tfem_contact_evaluate(c, u, 11, O[0].d, en, O[1].d, 12), ARG);
  UNWRITTEN(tfem_contact_evaluate(c, nan_u, 12, O[0].d, en, O[1].d, 12), ARG);
  UNWRITTEN(tfem_contact_gather(c, host, 12, O[0].d, 11), SHORT);
  UNWRITTEN(tfem_contact_gather(c, host, 11, O[0].d, 12), ARG); /* equation 11 past the vector */
  UNWRITTEN(tfem_contact_scatter_add(c, u, 12, O[0].d, 11), ARG);
  UNWRITTEN(tfem_contact_scatter_add(c, nan_u, 12, O[0].d, 12), ARG);
  UNWRITTEN(tfem_contact_update(c, nan_u, 12, O[0].i), ARG);
  UNWRITTEN(tfem_contact_update(c, u, 11, O[0].i), ARG);
  UNWRITTEN(tfem_contact_get_active(c, O[0].i, hen - 1), SHORT);
  UNWRITTEN(tfem_contact_gaps(c, u, 12, O[0].d, 5), SHORT);
  UNWRITTEN(tfem_contact_gaps(c, nan_u, 12, O[0].d, 6), ARG);
  UNWRITTEN(tfem_contact_pressures(c, u, 12, O[0].d, hen - 1), SHORT);
  UNWRITTEN(tfem_contact_pressures(c, nan_u, 12, O[0].d, hen), ARG);
  UNWRITTEN(tfem_contact_elements(c, O[0].i, 3 * hen - 1), SHORT);
  UNWRITTEN(tfem_contact_element_equations(c, O[0].l, 6 * hen - 1), SHORT);
  UNWRITTEN(tfem_contact_element_blocks(c, O[0].d, 36 * hen - 1), SHORT);
  UNWRITTEN(tfem_contact_length(c, NULL), NUL);

  /* The exceptions: the message copies write the truncated message with
   * BUFFER_TOO_SMALL, and the message refusing a handle that is not live
   * with INVALID_ARGUMENT (tfem_last_error's above). */
  memset(O, SENTINEL, sizeof O);
  CHECK(tfem_contact_evaluate(c, nan_u, 12, NULL, 0, NULL, 0) == ARG);
  CHECK(tfem_contact_last_error(c, O[0].c, 8) == SHORT && strlen(O[0].c) == 7);
  tfem_contact_destroy(c);
  memset(O, SENTINEL, sizeof O);
  CHECK(tfem_contact_last_error(c, O[0].c, 512) == ARG && strstr(O[0].c, "destroyed") != NULL);
}

/* The nodal tractions (p, tau) of a frictionless interface: p is the
 * nodal pressure, bit for bit, and tau is round-off (issue: a nodal shear
 * accessor beside the nodal pressures). */
static void nodal_tractions_read_the_pressure_and_no_shear_when_frictionless(void) {
  tfem_model *m = two_blocks();
  CHECK(tfem_solve_contact(m, NULL, NULL) == TFEM_STATUS_OK);
  double t[2 * 64], p[64], pmax = 0.0, smax = 0.0;
  CHECK(tfem_get_contact_nodal_tractions(m, t, 2 * B.nn) == TFEM_STATUS_OK);
  CHECK(tfem_get_contact_nodal_pressures(m, p, B.nn) == TFEM_STATUS_OK);
  int same = 1;
  for (int i = 0; i < B.nn; ++i) {
    same &= t[2 * i] == p[i];
    pmax = fmax(pmax, t[2 * i]);
    smax = fmax(smax, fabs(t[2 * i + 1]));
  }
  CHECK(same);
  CHECK(pmax > 0.0 && smax <= 1e-8 * pmax);
  double tp[2 * 64];
  CHECK(tfem_get_contact_pair_nodal_tractions(m, 0, tp, 2 * B.nn) == TFEM_STATUS_OK);
  CHECK(memcmp(tp, t, sizeof(double) * 2 * (size_t)B.nn) == 0);
  EXPECT_ERROR(m, tfem_get_contact_pair_nodal_tractions(m, 1, tp, 2 * B.nn),
               TFEM_STATUS_INVALID_ARGUMENT, "contact pair 1");
  EXPECT_ERROR(m, tfem_get_contact_nodal_tractions(m, t, B.nn), TFEM_STATUS_BUFFER_TOO_SMALL,
               "are needed");
  tfem_destroy(m);
}

/* Two solid cylinders of radius 1 stacked on the axis (axisymmetric,
 * TFEM_PLANE_MODE_AXISYMMETRIC: x the radius), 4 cells over the radius
 * below and 3 above (non-matching), the lower held axially at its bottom,
 * u_r = 0 on the axis, a pressure p on the upper's top. Exact: σ_zz = −p,
 * every other stress, the hoop stress included, 0; the base carries the
 * whole ring's force p π. */
static mesh_t S;
static tfem_model *stacked_cylinders(void) {
  memset(&S, 0, sizeof S);
  grid(&S, 4, 2, 0.0, -0.5, 1.0, 0.5, 1, 1); /* axis 1, side 2, base 3, top 4 */
  grid(&S, 3, 2, 0.0, 0.0, 1.0, 0.5, 2, 5);  /* axis 5, side 6, bottom 7, top 8 */
  tfem_model *m = model_of(&S, 2, 1000.0, 10.0, TFEM_PLANE_MODE_AXISYMMETRIC);
  CHECK(tfem_fix_edges(m, 3, TFEM_COMPONENT_Y, 0.0) == TFEM_STATUS_OK);
  CHECK(tfem_add_pressure(m, 8, 2.0) == TFEM_STATUS_OK);
  int pair = -1;
  CHECK(tfem_add_contact_pair(m, 4, 7, &pair) == TFEM_STATUS_OK);
  return m;
}

static void axisymmetric_cylinders_pressed_together_carry_a_uniform_stress_and_the_rings_force(void) {
  tfem_model *m = stacked_cylinders();
  EXPECT_ERROR(m, tfem_solve_contact(m, NULL, NULL), TFEM_STATUS_INVALID_ARGUMENT,
               "lies on the axis");
  CHECK(tfem_fix_edges(m, 1, TFEM_COMPONENT_X, 0.0) == TFEM_STATUS_OK);
  CHECK(tfem_fix_edges(m, 5, TFEM_COMPONENT_X, 0.0) == TFEM_STATUS_OK);
  CHECK(tfem_solve_contact(m, NULL, NULL) == TFEM_STATUS_OK);
  double s[3 * 64], hoop[64], r[2 * 64], err = 0.0, base = 0.0;
  CHECK(tfem_get_element_stresses(m, s, 3 * (size_t)S.nt) == TFEM_STATUS_OK);
  CHECK(tfem_get_element_out_of_plane_stresses(m, hoop, (size_t)S.nt) == TFEM_STATUS_OK);
  for (int t = 0; t < S.nt; ++t) {
    err = fmax(err, fmax(fabs(s[3 * t]), fabs(s[3 * t + 1] + 2.0)));
    err = fmax(err, fmax(fabs(s[3 * t + 2]), fabs(hoop[t])));
  }
  CHECK(err < 1e-12 * 2.0);
  CHECK(tfem_get_reactions(m, r, 2 * (size_t)S.nn) == TFEM_STATUS_OK);
  for (int v = 0; v < S.nn; ++v)
    if (S.xy[2 * v + 1] == -0.5) base += r[2 * v + 1];
  CHECK(fabs(base - 2.0 * M_PI) < 1e-12 * 2.0 * M_PI);
  tfem_destroy(m);
}

/* What the axisymmetric mode refuses, naming the item, and leaves the
 * model as it was: an unknown plane mode, a body across the axis, plane and
 * axisymmetric bodies together, the mortar weighting. */
static void the_axisymmetric_mode_refuses_what_it_cannot_model_by_name(void) {
  tfem_model *m = stacked_cylinders();
  EXPECT_ERROR(m, tfem_set_material(m, 1, 1.0, 0.3, 3), TFEM_STATUS_INVALID_ARGUMENT, "plane = 3");
  EXPECT_ERROR(m, tfem_set_material(m, 2, 1.0, 0.3, TFEM_PLANE_MODE_STRAIN),
               TFEM_STATUS_INVALID_MATERIAL, "body 1");
  EXPECT_ERROR(m, tfem_set_contact_weighting(m, TFEM_CONTACT_WEIGHTING_MORTAR),
               TFEM_STATUS_INVALID_ARGUMENT, "axisymmetric");
  CHECK(tfem_set_material(m, 2, 1000.0, 0.3, TFEM_PLANE_MODE_AXISYMMETRIC) == TFEM_STATUS_OK);
  tfem_destroy(m);
  mesh_t *g = calloc(1, sizeof *g);
  grid(g, 2, 2, -0.25, 0.0, 1.0, 1.0, 1, 1);
  m = tfem_create();
  CHECK(tfem_set_mesh(m, g->nn, g->xy, g->nt, g->tri, g->body, 0) == TFEM_STATUS_OK);
  EXPECT_ERROR(m, tfem_set_material(m, 1, 1.0, 0.3, TFEM_PLANE_MODE_AXISYMMETRIC),
               TFEM_STATUS_INVALID_MATERIAL, "node 0");
  double xy[6] = {-0.1, 0.0, 1.0, 0.0, 0.5, 1.0}, k[36];
  EXPECT_ERROR(NULL, tfem_element_stiffness(xy, 1.0, 0.3, TFEM_PLANE_MODE_AXISYMMETRIC, 1e-3, k),
               TFEM_STATUS_INVALID_ARGUMENT, "corner 1");
  tfem_destroy(m);
  free(g);
}

/* tfem_solve_adaptive refines the seed-like two blocks to a tolerance on the
 * compliance, keeps the given nodes where they were, reads back the refined
 * mesh and each cycle; bad arguments name themselves and change nothing. */
static void an_adaptive_solve_meets_its_tolerance_and_the_refined_mesh_reads_back(void) {
  tfem_model *m = two_blocks();
  int nn0 = 0, nt0 = 0, nn = 0, nt = 0;
  CHECK(tfem_get_sizes(m, &nn0, &nt0, NULL) == TFEM_STATUS_OK);
  EXPECT_ERROR(m, tfem_solve_adaptive(m, NAN, TFEM_ADAPT_GOAL_COMPLIANCE, 100000, 20, NULL, NULL),
               TFEM_STATUS_INVALID_ARGUMENT, "tolerance");
  EXPECT_ERROR(m, tfem_solve_adaptive(m, 1e-2, 7, 100000, 20, NULL, NULL),
               TFEM_STATUS_INVALID_ARGUMENT, "goal = 7");
  EXPECT_ERROR(m, tfem_solve_adaptive(m, 1e-2, TFEM_ADAPT_GOAL_ENERGY, 0, 20, NULL, NULL),
               TFEM_STATUS_INVALID_ARGUMENT, "max_unknowns");
  EXPECT_ERROR(m, tfem_get_adapt_cycles(m, NULL, NULL, NULL, 0), TFEM_STATUS_INVALID_STATE,
               "tfem_solve_adaptive");
  CHECK(tfem_get_sizes(m, &nn, &nt, NULL) == TFEM_STATUS_OK && nn == nn0 && nt == nt0);
  tfem_adapt_report rep;
  CHECK(tfem_solve_adaptive(m, 2e-2, TFEM_ADAPT_GOAL_COMPLIANCE, 100000, 30, NULL, &rep) ==
        TFEM_STATUS_OK);
  CHECK(rep.reached == 1 && rep.cycles >= 2 && rep.estimate <= 2e-2 && rep.estimate > 0.0);
  CHECK(tfem_get_sizes(m, &nn, &nt, NULL) == TFEM_STATUS_OK && nn > nn0 && nt == rep.triangles);
  double *xy = malloc(sizeof(double) * 2 * (size_t)nn);
  CHECK(tfem_get_mesh_nodes(m, xy, 2 * (size_t)nn) == TFEM_STATUS_OK);
  CHECK(memcmp(xy, B.xy, sizeof(double) * 2 * (size_t)nn0) == 0);
  free(xy);
  int64_t unknowns[64];
  double estimates[64];
  EXPECT_ERROR(m, tfem_get_adapt_cycles(m, unknowns, estimates, NULL, 1),
               TFEM_STATUS_BUFFER_TOO_SMALL, "are needed");
  CHECK(tfem_get_adapt_cycles(m, unknowns, estimates, NULL, 64) == TFEM_STATUS_OK);
  CHECK(unknowns[rep.cycles - 1] == rep.unknowns && estimates[rep.cycles - 1] == rep.estimate);
  CHECK(estimates[0] > estimates[rep.cycles - 1] && unknowns[0] < unknowns[rep.cycles - 1]);
  double u[2];
  CHECK(tfem_get_displacements(m, u, 2) == TFEM_STATUS_BUFFER_TOO_SMALL);
  tfem_destroy(m);
}

/* tfem_set_prescribed_edges changes a whole tag's prescribed values, all or
 * nothing: what it refuses names the tag or node and changes nothing. */
static void a_tags_prescribed_values_change_together_or_not_at_all(void) {
  tfem_model *m = two_blocks();
  CHECK(tfem_set_prescribed_edges(m, 12, TFEM_COMPONENT_Y, -1e-5) == TFEM_STATUS_OK);
  CHECK(tfem_solve_contact(m, NULL, NULL) == TFEM_STATUS_OK);
  double u[2 * 64], again[2 * 64];
  CHECK(tfem_get_displacements(m, u, 2 * B.nn) == TFEM_STATUS_OK);
  int moved = 0, lowered = 1;
  for (int i = 0; i < B.nn; ++i) {
    if (B.xy[2 * i + 1] == -0.25) {
      ++moved;
      lowered &= u[2 * i + 1] == -1e-5;
    }
  }
  CHECK(moved > 0 && lowered);
  EXPECT_ERROR(m, tfem_set_prescribed_edges(m, 12, TFEM_COMPONENT_X, 0.0),
               TFEM_STATUS_INVALID_ARGUMENT, "is not prescribed");
  EXPECT_ERROR(m, tfem_set_prescribed_edges(m, 999, TFEM_COMPONENT_Y, 0.0),
               TFEM_STATUS_INVALID_ARGUMENT, "tag 999");
  EXPECT_ERROR(m, tfem_set_prescribed_edges(m, 12, TFEM_COMPONENT_Y, NAN),
               TFEM_STATUS_INVALID_ARGUMENT, "not finite");
  EXPECT_ERROR(m, tfem_set_prescribed_edges(m, 12, 7, 0.0), TFEM_STATUS_INVALID_ARGUMENT,
               "component");
  /* Nothing changed: the results are still there, bit for bit. */
  CHECK(tfem_get_displacements(m, again, 2 * B.nn) == TFEM_STATUS_OK);
  CHECK(memcmp(u, again, sizeof(double) * 2 * (size_t)B.nn) == 0);
  tfem_destroy(m);
}

/* A quarter of the ring 1 <= r <= 2 (centre (0, 0), x, y >= 0), NR cells
 * over the radius and NA over the angle, body 1, plane strain: u_x = 0 on
 * x = 0 (tag 1, its edges from the outer arc inwards), u_y = 0 on y = 0
 * (tag 2), the outer arc tag 3, the inner arc tag 4 pressed by 10. Every
 * node of the arcs lies on its circle to round-off (x = 0 and y = 0 exactly
 * on the straight sides). */
enum { RING_NR = 2, RING_NA = 4 };
#define RING_ID(i, j) ((j) * (RING_NR + 1) + (i))
static tfem_model *quarter_ring(int *nn0, int *ne0) {
  double xy[2 * (RING_NR + 1) * (RING_NA + 1)];
  int tri[3 * 2 * RING_NR * RING_NA], body[2 * RING_NR * RING_NA], nt = 0;
  int edges[2 * 2 * (RING_NR + RING_NA)], tags[2 * (RING_NR + RING_NA)], ne = 0;
  for (int j = 0; j <= RING_NA; ++j)
    for (int i = 0; i <= RING_NR; ++i) {
      double r = 1.0 + (double)i / RING_NR, a = 0.5 * M_PI * j / RING_NA;
      xy[2 * RING_ID(i, j)] = j == RING_NA ? 0.0 : r * cos(a);
      xy[2 * RING_ID(i, j) + 1] = j == 0 ? 0.0 : r * sin(a);
    }
  for (int j = 0; j < RING_NA; ++j)
    for (int i = 0; i < RING_NR; ++i) {
      int a = RING_ID(i, j), b = RING_ID(i + 1, j), c = RING_ID(i + 1, j + 1), d = RING_ID(i, j + 1);
      int t[6] = {a, b, c, a, c, d};
      memcpy(&tri[3 * nt], t, sizeof t);
      body[nt++] = 1;
      body[nt++] = 1;
    }
  for (int i = RING_NR; i > 0; --i) {
    edges[2 * ne] = RING_ID(i, RING_NA), edges[2 * ne + 1] = RING_ID(i - 1, RING_NA);
    tags[ne++] = 1;
  }
  for (int i = 0; i < RING_NR; ++i) {
    edges[2 * ne] = RING_ID(i, 0), edges[2 * ne + 1] = RING_ID(i + 1, 0);
    tags[ne++] = 2;
  }
  for (int j = 0; j < RING_NA; ++j) {
    edges[2 * ne] = RING_ID(RING_NR, j), edges[2 * ne + 1] = RING_ID(RING_NR, j + 1);
    tags[ne++] = 3;
    edges[2 * ne] = RING_ID(0, j + 1), edges[2 * ne + 1] = RING_ID(0, j);
    tags[ne++] = 4;
  }
  *nn0 = (RING_NR + 1) * (RING_NA + 1);
  *ne0 = ne;
  tfem_model *m = tfem_create();
  CHECK(tfem_set_mesh(m, *nn0, xy, nt, tri, body, 0) == TFEM_STATUS_OK);
  CHECK(tfem_set_boundary_edges(m, ne, edges, tags) == TFEM_STATUS_OK);
  CHECK(tfem_set_material(m, 1, 1000.0, 0.3, TFEM_PLANE_MODE_STRAIN) == TFEM_STATUS_OK);
  CHECK(tfem_fix_edges(m, 1, TFEM_COMPONENT_X, 0.0) == TFEM_STATUS_OK);
  CHECK(tfem_fix_edges(m, 2, TFEM_COMPONENT_Y, 0.0) == TFEM_STATUS_OK);
  CHECK(tfem_add_pressure(m, 4, 10.0) == TFEM_STATUS_OK);
  return m;
}

/* The nodes of the model's edges tagged `tag`: how many edges, the largest
 * distance of their nodes from radius r about (0, 0), and the largest
 * radius of those numbered from `first` on (nodes the refinement added;
 * -1 if none). */
typedef struct {
  int edges;
  double off, added_max;
} ring_side_t;
static ring_side_t ring_side(tfem_model *m, int tag, double r, int first) {
  ring_side_t out = {0, INFINITY, -1.0};
  int nn = 0, ne = 0;
  if (tfem_get_sizes(m, &nn, NULL, NULL) != TFEM_STATUS_OK ||
      tfem_get_boundary_edge_count(m, &ne) != TFEM_STATUS_OK)
    return out;
  double *xy = malloc(sizeof(double) * 2 * (size_t)nn);
  int *edges = malloc(sizeof(int) * 2 * (size_t)ne), *tags = malloc(sizeof(int) * (size_t)ne);
  if (tfem_get_mesh_nodes(m, xy, 2 * (size_t)nn) == TFEM_STATUS_OK &&
      tfem_get_boundary_edges(m, edges, 2 * (size_t)ne, tags, (size_t)ne) == TFEM_STATUS_OK) {
    out.off = 0.0;
    for (int e = 0; e < ne; ++e) {
      if (tags[e] != tag) continue;
      ++out.edges;
      for (int k = 0; k < 2; ++k) {
        int v = edges[2 * e + k];
        double rv = hypot(xy[2 * v], xy[2 * v + 1]);
        out.off = fmax(out.off, fabs(rv - r));
        if (v >= first) out.added_max = fmax(out.added_max, rv);
      }
    }
  }
  free(xy), free(edges), free(tags);
  return out;
}

/* tfem_set_boundary_circle refuses an ill-defined circle (a centre not
 * finite, a radius not finite or <= 0), a tag of no edge and a circle a
 * node of the tag's edges is off (naming that node, not one on it), each
 * with INVALID_ARGUMENT, and changes nothing: the results of the solve
 * before stay, bit for bit, the mesh keeps its sizes, and an adaptive solve
 * still puts its new nodes on the circle declared before the refusals. */
static void a_bad_boundary_circle_is_refused_and_changes_nothing(void) {
  int nn0 = 0, ne0 = 0, nn = 0, nt = 0, ne = 0, nt0 = 0;
  tfem_model *m = quarter_ring(&nn0, &ne0);
  CHECK(tfem_set_boundary_circle(m, 3, 0.0, 0.0, 2.0) == TFEM_STATUS_OK);
  CHECK(tfem_solve(m, NULL) == TFEM_STATUS_OK);
  double u[2 * 64], again[2 * 64];
  CHECK(tfem_get_displacements(m, u, 2 * (size_t)nn0) == TFEM_STATUS_OK);
  CHECK(tfem_get_sizes(m, NULL, &nt0, NULL) == TFEM_STATUS_OK);
  const struct {
    double cx, cy, r;
    const char *needle;
  } bad[] = {
      {NAN, 0.0, 2.0, "centre"},       {0.0, NAN, 2.0, "centre"},
      {INFINITY, 0.0, 2.0, "centre"},  {0.0, -INFINITY, 2.0, "centre"},
      {0.0, 0.0, 0.0, "radius"},       {0.0, 0.0, -0.0, "radius"},
      {0.0, 0.0, -2.0, "radius"},      {0.0, 0.0, NAN, "radius"},
      {0.0, 0.0, INFINITY, "radius"},  {0.0, 0.0, -INFINITY, "radius"},
      {NAN, NAN, NAN, "centre"},       {0.0, 0.0, 2.0 * (1.0 + 2e-6), "from the curve"},
      {0.0, 0.0, 1.0, "from the curve"}, {1e-5, 0.0, 2.0, "from the curve"},
  };
  for (size_t k = 0; k < sizeof bad / sizeof bad[0]; ++k)
    EXPECT_ERROR(m, tfem_set_boundary_circle(m, 3, bad[k].cx, bad[k].cy, bad[k].r),
                 TFEM_STATUS_INVALID_ARGUMENT, bad[k].needle);
  EXPECT_ERROR(m, tfem_set_boundary_circle(m, 99, 0.0, 0.0, 2.0), TFEM_STATUS_INVALID_ARGUMENT,
               "no boundary edge has tag 99");
  EXPECT_ERROR(m, tfem_set_boundary_circle(m, INT_MIN, 0.0, 0.0, 2.0),
               TFEM_STATUS_INVALID_ARGUMENT, "no boundary edge has tag");
  /* Tag 1's first edge runs from the outer arc (on r = 2) inwards: the
   * node named is the next one, at r = 1.5. */
  char needle[64];
  snprintf(needle, sizeof needle, "node %d of an edge tagged 1 lies", RING_ID(RING_NR - 1, RING_NA));
  EXPECT_ERROR(m, tfem_set_boundary_circle(m, 1, 0.0, 0.0, 2.0), TFEM_STATUS_INVALID_ARGUMENT,
               needle);
  snprintf(needle, sizeof needle, "node %d of", RING_ID(RING_NR, RING_NA));
  char msg[512] = "";
  tfem_last_error(m, msg, sizeof msg);
  CHECK(strstr(msg, needle) == NULL);
  /* The model as it was: results kept bit for bit, the same mesh. */
  CHECK(tfem_get_displacements(m, again, 2 * (size_t)nn0) == TFEM_STATUS_OK);
  CHECK(memcmp(u, again, sizeof(double) * 2 * (size_t)nn0) == 0);
  CHECK(tfem_get_sizes(m, &nn, &nt, NULL) == TFEM_STATUS_OK && nn == nn0 && nt == nt0);
  CHECK(tfem_get_boundary_edge_count(m, &ne) == TFEM_STATUS_OK && ne == ne0);
  /* and the circle of tag 3 is still the first one: the refinement puts
   * the nodes it adds there (a circle refused on tag 4 left it none: its
   * new nodes are the chords' midpoints, inside r = 1). */
  EXPECT_ERROR(m, tfem_set_boundary_circle(m, 4, 0.0, 0.0, 1.5), TFEM_STATUS_INVALID_ARGUMENT,
               "from the curve");
  CHECK(tfem_solve_adaptive(m, 1e-2, TFEM_ADAPT_GOAL_ENERGY, 100000, 4, NULL, NULL) ==
        TFEM_STATUS_OK);
  ring_side_t outer = ring_side(m, 3, 2.0, nn0), inner = ring_side(m, 4, 1.0, nn0);
  CHECK(outer.edges > RING_NA && outer.off <= 1e-12 && outer.added_max > 0.0);
  CHECK(inner.edges > RING_NA && inner.added_max > 0.0 && inner.added_max < 1.0 - 1e-6);
  tfem_destroy(m);
}

/* tfem_solve_adaptive puts the nodes it adds on the edges of a tag with a
 * declared circle on that circle: the quarter ring's arcs (tags 3, r = 2,
 * and 4, r = 1), refined over a few cycles, keep every node on them to
 * round-off. Without the declarations the new nodes are the chords'
 * midpoints, inside the circle: the declaration is what moves them. A
 * circle within 1e-6 of the radius of the nodes is accepted, and declared
 * again on the tag it replaces the first. */
static void an_adaptive_solve_puts_new_boundary_nodes_on_the_declared_circle(void) {
  for (int declared = 1; declared >= 0; --declared) {
    int nn0 = 0, ne0 = 0;
    tfem_model *m = quarter_ring(&nn0, &ne0);
    if (declared) {
      CHECK(tfem_set_boundary_circle(m, 3, 0.0, 0.0, 2.0 * (1.0 + 5e-7)) == TFEM_STATUS_OK);
      CHECK(tfem_set_boundary_circle(m, 3, 0.0, 0.0, 2.0) == TFEM_STATUS_OK);
      CHECK(tfem_set_boundary_circle(m, 4, 0.0, 0.0, 1.0) == TFEM_STATUS_OK);
    }
    tfem_adapt_report rep;
    CHECK(tfem_solve_adaptive(m, 1e-2, TFEM_ADAPT_GOAL_ENERGY, 100000, 5, NULL, &rep) ==
          TFEM_STATUS_OK);
    CHECK(rep.cycles >= 3);
    int nn = 0, nt = 0;
    CHECK(tfem_get_sizes(m, &nn, &nt, NULL) == TFEM_STATUS_OK && nn > nn0 && nt == rep.triangles);
    ring_side_t outer = ring_side(m, 3, 2.0, nn0), inner = ring_side(m, 4, 1.0, nn0);
    CHECK(outer.edges > RING_NA && inner.edges > RING_NA);
    CHECK(outer.added_max > 0.0 && inner.added_max > 0.0);
    if (declared) {
      CHECK(outer.off <= 1e-12 && inner.off <= 1e-12);
    } else {
      CHECK(outer.added_max < 2.0 - 1e-6 && inner.added_max < 1.0 - 1e-6);
    }
    double *u = malloc(sizeof(double) * 2 * (size_t)nn);
    CHECK(tfem_get_displacements(m, u, 2 * (size_t)nn) == TFEM_STATUS_OK && all_finite(u, 2 * nn));
    free(u);
    tfem_destroy(m);
  }
}

/* Before a mesh there is no edge to put on a circle: INVALID_STATE, whatever
 * the circle, and the model takes a mesh and a circle afterwards. A NULL
 * model is NULL_POINTER. */
static void a_boundary_circle_before_a_mesh_is_an_invalid_state(void) {
  tfem_model *m = tfem_create();
  EXPECT_ERROR(m, tfem_set_boundary_circle(m, 3, 0.0, 0.0, 2.0), TFEM_STATUS_INVALID_STATE,
               "no mesh");
  EXPECT_ERROR(m, tfem_set_boundary_circle(m, 3, NAN, 0.0, -1.0), TFEM_STATUS_INVALID_STATE,
               "no mesh");
  CHECK(tfem_set_boundary_circle(NULL, 3, 0.0, 0.0, 2.0) == TFEM_STATUS_NULL_POINTER);
  tfem_destroy(m);
  int nn0 = 0, ne0 = 0;
  m = quarter_ring(&nn0, &ne0);
  CHECK(tfem_set_boundary_circle(m, 3, 0.0, 0.0, 2.0) == TFEM_STATUS_OK);
  tfem_destroy(m);
}

/* ---- The 3D model (tfem_solid_*) and its host contact context
 * (tfem_solid_contact_*): a failed call writes none of its outputs and
 * leaves the model, or the context, as it was, bit for bit. ---- */

/* Two unit cubes of SC x SC x SC cells of Kuhn's six tetrahedra (as
 * c_tests/solid_test.c builds them), body 1 on z in [-1, 0] and body 2 on
 * z in [gap, 1 + gap], sides tagged 1..6 and 11..16 (x = min, x = max,
 * y = min, y = max, z = min, z = max). */
enum { SC = 2, SCP = SC + 1, SC_NODES_PER = SCP * SCP * SCP, SC_NODES = 2 * SC_NODES_PER };
enum { SC_TETS = 2 * 6 * SC * SC * SC, SC_FACES = 2 * 6 * 2 * SC * SC, SC_CONTACT = 3 * 2 * SC * SC };
enum { SC_SIDE_NODES = SCP * SCP, SC_SIDE_TRIS = 2 * SC * SC, SC_NL = 6 * SC_SIDE_NODES };
typedef struct {
  double xyz[3 * SC_NODES];
  int tets[4 * SC_TETS], body[SC_TETS], faces[3 * SC_FACES], tags[SC_FACES];
  int nt, nf;
} cubes_t;
static cubes_t C3;

static int cube_id(int first, int i, int j, int k) { return first + i + SCP * (j + SCP * k); }
static int cube_grid(int first, int v, int axis) {
  int r = v - first, g[3] = {r % SCP, (r / SCP) % SCP, r / (SCP * SCP)};
  return g[axis];
}
static void kuhn_cube(cubes_t *c, int first, double z0, int b, int tag0) {
  static const int orders[6][3] = {{0, 1, 2}, {1, 2, 0}, {2, 0, 1}, {0, 2, 1}, {2, 1, 0}, {1, 0, 2}};
  for (int k = 0; k < SCP; ++k)
    for (int j = 0; j < SCP; ++j)
      for (int i = 0; i < SCP; ++i) {
        int v = cube_id(first, i, j, k);
        c->xyz[3 * v] = (double)i / SC;
        c->xyz[3 * v + 1] = (double)j / SC;
        c->xyz[3 * v + 2] = z0 + (double)k / SC;
      }
  int start = c->nt;
  for (int k = 0; k < SC; ++k)
    for (int j = 0; j < SC; ++j)
      for (int i = 0; i < SC; ++i)
        for (int o = 0; o < 6; ++o) {
          int p[3] = {0, 0, 0}, *t = &c->tets[4 * c->nt];
          t[0] = cube_id(first, i, j, k);
          for (int s = 0; s < 3; ++s) {
            p[orders[o][s]] = 1;
            t[s + 1] = cube_id(first, i + p[0], j + p[1], k + p[2]);
          }
          if (o >= 3) {
            int swap = t[2];
            t[2] = t[3];
            t[3] = swap;
          }
          c->body[c->nt++] = b;
        }
  for (int e = start; e < c->nt; ++e)
    for (int skip = 0; skip < 4; ++skip) {
      int f[3], n = 0;
      for (int q = 0; q < 4; ++q)
        if (q != skip) f[n++] = c->tets[4 * e + q];
      for (int axis = 0; axis < 3; ++axis)
        for (int end = 0; end < 2; ++end) {
          int at = end ? SC : 0, on = 1;
          for (int q = 0; q < 3; ++q) on = on && cube_grid(first, f[q], axis) == at;
          if (on) {
            memcpy(&c->faces[3 * c->nf], f, sizeof f);
            c->tags[c->nf++] = tag0 + 1 + 2 * axis + end;
          }
        }
    }
}
static void stacked_cubes_mesh(cubes_t *c, double gap) {
  memset(c, 0, sizeof *c);
  kuhn_cube(c, 0, -1.0, 1, 0);
  kuhn_cube(c, SC_NODES_PER, gap, 2, 10);
}

/* The stacked cubes on rollers (u_z = 0 under the lower one, u_x = 0 on
 * x = 0 and u_y = 0 on y = 0 of both) in frictionless contact (the lower
 * top, tag 6, planar side a; the upper bottom, tag 15): touching and
 * pressed by a pressure on the upper top, or (gap > 0) pressed down by a
 * prescribed u_z = -2 gap there, which the contact loop takes two
 * iterations to settle. */
static tfem_solid_model *stacked_cubes(double gap) {
  stacked_cubes_mesh(&C3, gap);
  tfem_solid_model *m = tfem_solid_create();
  CHECK(m != NULL);
  CHECK(tfem_solid_set_mesh(m, SC_NODES, C3.xyz, SC_TETS, C3.tets, C3.body, 0) == TFEM_STATUS_OK);
  CHECK(tfem_solid_set_boundary_faces(m, SC_FACES, C3.faces, C3.tags) == TFEM_STATUS_OK);
  CHECK(tfem_solid_set_material(m, 1, 1.0, 0.25) == TFEM_STATUS_OK);
  CHECK(tfem_solid_set_material(m, 2, 1.0, 0.25) == TFEM_STATUS_OK);
  CHECK(tfem_solid_fix_faces(m, 5, TFEM_AXIS_Z, 0.0) == TFEM_STATUS_OK);
  CHECK(tfem_solid_fix_faces(m, 1, TFEM_AXIS_X, 0.0) == TFEM_STATUS_OK);
  CHECK(tfem_solid_fix_faces(m, 11, TFEM_AXIS_X, 0.0) == TFEM_STATUS_OK);
  CHECK(tfem_solid_fix_faces(m, 3, TFEM_AXIS_Y, 0.0) == TFEM_STATUS_OK);
  CHECK(tfem_solid_fix_faces(m, 13, TFEM_AXIS_Y, 0.0) == TFEM_STATUS_OK);
  if (gap > 0) CHECK(tfem_solid_fix_faces(m, 16, TFEM_AXIS_Z, -2 * gap) == TFEM_STATUS_OK);
  else CHECK(tfem_solid_add_pressure(m, 16, 0.1) == TFEM_STATUS_OK);
  CHECK(tfem_solid_add_contact_pair(m, 6, 15, NULL) == TFEM_STATUS_OK);
  return m;
}

/* Everything a 3D model gives back, each getter's status with it (the
 * solve statistics without their timings), to compare bit for bit. */
typedef struct {
  int st[24];
  int sizes[3], face_count, warnings, iterations;
  double xyz[3 * SC_NODES];
  int tets[4 * SC_TETS], bodies[SC_TETS], faces[3 * SC_FACES], tags[SC_FACES];
  double u[3 * SC_NODES], strain[6 * SC_TETS], stress[6 * SC_TETS], reaction[3 * SC_NODES];
  double force[3 * SC_NODES], pressure[SC_NODES], work, area, pair_area;
  int contact_tets[4 * SC_CONTACT], active[SC_CONTACT];
  tfem_solve_info info;
  size_t last_error_length;
} solid_state_t;

static void solid_state_of(tfem_solid_model *m, solid_state_t *s) {
  memset(s, 0, sizeof *s);
  int k = 0;
  tfem_solve_info info;
  s->st[k++] = tfem_solid_get_sizes(m, &s->sizes[0], &s->sizes[1], &s->sizes[2]);
  s->st[k++] = tfem_solid_get_boundary_face_count(m, &s->face_count);
  s->st[k++] = tfem_solid_warning_count(m, &s->warnings);
  s->st[k++] = tfem_solid_get_mesh_nodes(m, s->xyz, 3 * SC_NODES);
  s->st[k++] = tfem_solid_get_mesh_tetrahedra(m, s->tets, 4 * SC_TETS, s->bodies, SC_TETS);
  s->st[k++] = tfem_solid_get_boundary_faces(m, s->faces, 3 * SC_FACES, s->tags, SC_FACES);
  s->st[k++] = tfem_solid_get_iterations(m, &s->iterations);
  s->st[k++] = tfem_solid_get_displacements(m, s->u, 3 * SC_NODES);
  s->st[k++] = tfem_solid_get_element_strains(m, s->strain, 6 * SC_TETS);
  s->st[k++] = tfem_solid_get_element_stresses(m, s->stress, 6 * SC_TETS);
  s->st[k++] = tfem_solid_get_reactions(m, s->reaction, 3 * SC_NODES);
  s->st[k++] = tfem_solid_get_contact_forces(m, s->force, 3 * SC_NODES);
  s->st[k++] = tfem_solid_get_contact_nodal_pressures(m, s->pressure, SC_NODES);
  s->st[k++] = tfem_solid_get_external_work(m, &s->work);
  s->st[k++] = tfem_solid_get_contact_area(m, &s->area);
  s->st[k++] = tfem_solid_get_contact_pair_area(m, 0, &s->pair_area);
  s->st[k++] = tfem_solid_get_contact_tetrahedra(m, s->contact_tets, 4 * SC_CONTACT);
  s->st[k++] = tfem_solid_get_contact_active(m, s->active, SC_CONTACT);
  s->st[k++] = tfem_solid_get_solve_info(m, &info);
  if (s->st[k - 1] == TFEM_STATUS_OK) {
    s->info.unknowns = info.unknowns;
    s->info.matrix_nnz = info.matrix_nnz;
    s->info.factor_nnz = info.factor_nnz;
    s->info.factorizations = info.factorizations;
    s->info.interface_unknowns = info.interface_unknowns;
    s->info.relative_residual = info.relative_residual;
    s->info.condition_estimate = info.condition_estimate;
    s->info.memory_bytes = info.memory_bytes;
    s->info.factorization_bytes = info.factorization_bytes;
  }
  /* (last: the getters above succeed or fail, and leave their message) */
  s->last_error_length = 0;
}

static solid_state_t solid_before, solid_after;
static void expect_solid_as_it_was(tfem_solid_model *m, const char *what, int line) {
  solid_state_of(m, &solid_after);
  if (memcmp(&solid_before, &solid_after, sizeof solid_before) == 0) {
    ++passed;
  } else {
    ++failed;
    printf("FAIL line %d: after %s the 3D model gives other results\n", line, what);
  }
}
/* `call` on sentinel-filled outputs must return `status`, write nothing,
 * and leave every result of the 3D model m as solid_before holds them. */
#define SOLID_UNWRITTEN(m, call, status)                 \
  do {                                                   \
    UNWRITTEN(call, status);                             \
    expect_solid_as_it_was(m, #call, __LINE__);          \
  } while (0)

/* The faces of the stacked cubes tagged `tag`, turned counter-clockwise
 * seen from outside (outward normal along out_z), as a host's side in
 * host node numbers v + base, with equations 3 v + c + base (none for u_x
 * on x = 0, as the rollers fix it). */
typedef struct {
  int nodes[SC_SIDE_NODES];
  double xyz[3 * SC_SIDE_NODES];
  int64_t equations[3 * SC_SIDE_NODES];
  int triangles[3 * SC_SIDE_TRIS];
  int n_nodes, n_triangles;
} host_side_t;
static void host_side_of(int tag, double out_z, int base, host_side_t *s) {
  memset(s, 0, sizeof *s);
  for (int f = 0; f < C3.nf; ++f) {
    if (C3.tags[f] != tag) continue;
    int t[3] = {C3.faces[3 * f], C3.faces[3 * f + 1], C3.faces[3 * f + 2]};
    const double *a = &C3.xyz[3 * t[0]], *b = &C3.xyz[3 * t[1]], *c = &C3.xyz[3 * t[2]];
    double nz = (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]);
    if (nz * out_z < 0) {
      int swap = t[1];
      t[1] = t[2];
      t[2] = swap;
    }
    for (int q = 0; q < 3; ++q) {
      s->triangles[3 * s->n_triangles + q] = t[q] + base;
      int known = 0;
      for (int i = 0; i < s->n_nodes; ++i) known = known || s->nodes[i] == t[q] + base;
      if (known) continue;
      int i = s->n_nodes++;
      s->nodes[i] = t[q] + base;
      for (int k = 0; k < 3; ++k) {
        s->xyz[3 * i + k] = C3.xyz[3 * t[q] + k];
        s->equations[3 * i + k] = k == 0 && C3.xyz[3 * t[q]] == 0.0 ? base - 1 : 3 * t[q] + k + base;
      }
    }
    ++s->n_triangles;
  }
}

/* Everything a 3D context gives back at the displacements u (sizes,
 * nodes, B, pattern, element equations and blocks, flags, values and
 * residual, gaps, area), each status with it. */
typedef struct {
  int st[12];
  int n_nodes, n_tets;
  int64_t n_entries;
  int nodes[2 * SC_SIDE_NODES], tets[4 * SC_CONTACT], active[SC_CONTACT];
  int64_t rows[144 * SC_CONTACT], cols[144 * SC_CONTACT], equations[12 * SC_CONTACT];
  double blocks[144 * SC_CONTACT], values[144 * SC_CONTACT], residual[SC_NL], gaps[SC_CONTACT], area;
} host_state_t;
static host_state_t host_before, host_after;
static void host_state_of(tfem_solid_contact *c, const double *u, host_state_t *s) {
  memset(s, 0, sizeof *s);
  int k = 0;
  const size_t E = 144 * SC_CONTACT;
  s->st[k++] = tfem_solid_contact_sizes(c, &s->n_nodes, &s->n_tets, &s->n_entries);
  s->st[k++] = tfem_solid_contact_nodes(c, s->nodes, 2 * SC_SIDE_NODES);
  s->st[k++] = tfem_solid_contact_tetrahedra(c, s->tets, 4 * SC_CONTACT);
  s->st[k++] = tfem_solid_contact_pattern(c, s->rows, s->cols, E);
  s->st[k++] = tfem_solid_contact_element_equations(c, s->equations, 12 * SC_CONTACT);
  s->st[k++] = tfem_solid_contact_element_blocks(c, s->blocks, E);
  s->st[k++] = tfem_solid_contact_get_active(c, s->active, SC_CONTACT);
  s->st[k++] = tfem_solid_contact_evaluate(c, u, SC_NL, s->values, E, s->residual, SC_NL);
  s->st[k++] = tfem_solid_contact_gaps(c, u, SC_NL, s->gaps, SC_CONTACT);
  s->st[k++] = tfem_solid_contact_area(c, &s->area);
}
static void expect_host_as_it_was(tfem_solid_contact *c, const double *u, const char *what, int line) {
  host_state_of(c, u, &host_after);
  if (memcmp(&host_before, &host_after, sizeof host_before) == 0) {
    ++passed;
  } else {
    ++failed;
    printf("FAIL line %d: after %s the 3D contact context gives other values\n", line, what);
  }
}
#define HOST_UNWRITTEN(c, u, call, status)               \
  do {                                                   \
    UNWRITTEN(call, status);                             \
    expect_host_as_it_was(c, u, #call, __LINE__);        \
  } while (0)

static void a_failed_3d_call_writes_nothing_and_leaves_the_model_as_it_was(void) {
  const tfem_status NUL = TFEM_STATUS_NULL_POINTER, ARG = TFEM_STATUS_INVALID_ARGUMENT,
                    STATE = TFEM_STATUS_INVALID_STATE, SHORT = TFEM_STATUS_BUFFER_TOO_SMALL,
                    MATERIAL = TFEM_STATUS_INVALID_MATERIAL, MESH = TFEM_STATUS_INVALID_MESH;
  const size_t L = 8192;
  tfem_contact_options bad;

  /* No model, a destroyed one, or a handle of another kind: the 3D
   * model's getters and mutators, and the 2D ones given 3D handles. */
  tfem_model *two = tfem_create();
  tfem_contact *two_c = tfem_contact_create(0);
  tfem_solid_contact *sc = tfem_solid_contact_create(0, NULL);
  tfem_solid_model *live = stacked_cubes(0.0);
  CHECK(tfem_solid_solve_contact(live, NULL, NULL) == TFEM_STATUS_OK);
  solid_state_of(live, &solid_before);
  static solid_state_t live_state;
  live_state = solid_before;
  /* (destroyed after the others are made: a new handle may take the
   * address of a destroyed one, and then reaches it) */
  tfem_solid_model *dead = tfem_solid_create();
  tfem_solid_destroy(dead);
  tfem_solid_model *const wrong[4] = {NULL, dead, (tfem_solid_model *)two, (tfem_solid_model *)sc};
  for (int w = 0; w < 4; ++w) {
    tfem_solid_model *h = wrong[w];
    const tfem_status want = h ? ARG : NUL;
    SOLID_UNWRITTEN(live, tfem_solid_warning_count(h, O[0].i), want);
    SOLID_UNWRITTEN(live, tfem_solid_get_warning_size(h, 0, O[0].z), want);
    SOLID_UNWRITTEN(live, tfem_solid_get_warning(h, 0, O[0].c, 512), want);
    SOLID_UNWRITTEN(live, tfem_solid_get_sizes(h, O[0].i, O[1].i, O[2].i), want);
    SOLID_UNWRITTEN(live, tfem_solid_get_boundary_face_count(h, O[0].i), want);
    SOLID_UNWRITTEN(live, tfem_solid_get_mesh_nodes(h, O[0].d, L), want);
    SOLID_UNWRITTEN(live, tfem_solid_get_mesh_tetrahedra(h, O[0].i, L, O[1].i, L), want);
    SOLID_UNWRITTEN(live, tfem_solid_get_boundary_faces(h, O[0].i, L, O[1].i, L), want);
    SOLID_UNWRITTEN(live, tfem_solid_get_solve_info(h, &O[0].info), want);
    SOLID_UNWRITTEN(live, tfem_solid_get_iterations(h, O[0].i), want);
    SOLID_UNWRITTEN(live, tfem_solid_get_displacements(h, O[0].d, L), want);
    SOLID_UNWRITTEN(live, tfem_solid_get_element_strains(h, O[0].d, L), want);
    SOLID_UNWRITTEN(live, tfem_solid_get_element_stresses(h, O[0].d, L), want);
    SOLID_UNWRITTEN(live, tfem_solid_get_reactions(h, O[0].d, L), want);
    SOLID_UNWRITTEN(live, tfem_solid_get_external_work(h, O[0].d), want);
    SOLID_UNWRITTEN(live, tfem_solid_get_contact_tetrahedra(h, O[0].i, L), want);
    SOLID_UNWRITTEN(live, tfem_solid_get_contact_active(h, O[0].i, L), want);
    SOLID_UNWRITTEN(live, tfem_solid_get_contact_forces(h, O[0].d, L), want);
    SOLID_UNWRITTEN(live, tfem_solid_get_contact_nodal_pressures(h, O[0].d, L), want);
    SOLID_UNWRITTEN(live, tfem_solid_get_contact_area(h, O[0].d), want);
    SOLID_UNWRITTEN(live, tfem_solid_get_contact_pair_area(h, 0, O[0].d), want);
    SOLID_UNWRITTEN(live, tfem_solid_set_mesh(h, SC_NODES, C3.xyz, SC_TETS, C3.tets, C3.body, 0), want);
    SOLID_UNWRITTEN(live, tfem_solid_set_boundary_faces(h, SC_FACES, C3.faces, C3.tags), want);
    SOLID_UNWRITTEN(live, tfem_solid_set_material(h, 1, 1.0, 0.25), want);
    SOLID_UNWRITTEN(live, tfem_solid_set_tempering(h, 0, 0.0), want);
    SOLID_UNWRITTEN(live, tfem_solid_set_ordering(h, 0), want);
    SOLID_UNWRITTEN(live, tfem_solid_fix(h, 0, TFEM_AXIS_X, 0.0), want);
    SOLID_UNWRITTEN(live, tfem_solid_add_pressure(h, 16, 1.0), want);
    SOLID_UNWRITTEN(live, tfem_solid_add_contact_pair(h, 6, 15, O[0].i), want);
    SOLID_UNWRITTEN(live, tfem_solid_clear_loads(h), want);
    SOLID_UNWRITTEN(live, tfem_solid_solve(h, &O[0].info), want);
    SOLID_UNWRITTEN(live, tfem_solid_solve_contact(h, NULL, &O[0].info), want);
    SOLID_UNWRITTEN(live, tfem_solid_step(h, 0.5, NULL, &O[0].info), want);
    SOLID_UNWRITTEN(live, tfem_solid_revert_step(h), want);
    SOLID_UNWRITTEN(live, tfem_solid_write_vtu(h, "/nonexistent-folder-of-tfem/x.vtu"), want);
    tfem_solid_destroy(h); /* not a live 3D model: a no-op */
  }
  /* The 2D functions refuse the 3D handles. */
  SOLID_UNWRITTEN(live, tfem_get_sizes((tfem_model *)live, O[0].i, O[1].i, O[2].i), ARG);
  SOLID_UNWRITTEN(live, tfem_get_displacements((tfem_model *)live, O[0].d, L), ARG);
  SOLID_UNWRITTEN(live, tfem_set_material((tfem_model *)live, 1, 1.0, 0.25, TFEM_PLANE_MODE_STRAIN), ARG);
  SOLID_UNWRITTEN(live, tfem_solve_contact((tfem_model *)live, NULL, &O[0].rep), ARG);
  SOLID_UNWRITTEN(live, tfem_contact_sizes((tfem_contact *)live, O[0].i, O[1].i, O[2].l), ARG);
  SOLID_UNWRITTEN(live, tfem_contact_sizes((tfem_contact *)sc, O[0].i, O[1].i, O[2].l), ARG);
  SOLID_UNWRITTEN(live, tfem_solid_contact_sizes((tfem_solid_contact *)live, O[0].i, O[1].i, O[2].l), ARG);
  SOLID_UNWRITTEN(live, tfem_solid_contact_sizes((tfem_solid_contact *)two_c, O[0].i, O[1].i, O[2].l), ARG);
  tfem_destroy((tfem_model *)live);          /* not a 2D model: a no-op */
  tfem_contact_destroy((tfem_contact *)live); /* not a 2D context: a no-op */
  tfem_solid_contact_destroy((tfem_solid_contact *)live);
  expect_solid_as_it_was(live, "destroying it as another kind of handle", __LINE__);
  /* (The exceptions: the message copies say why the handle is refused.) */
  memset(O, SENTINEL, sizeof O);
  CHECK(tfem_solid_last_error(dead, O[0].c, 512) == ARG && strstr(O[0].c, "destroyed") != NULL);
  CHECK(tfem_solid_last_error_length(dead) == strlen(O[0].c) + 1);
  memset(O, SENTINEL, sizeof O);
  CHECK(tfem_solid_last_error((tfem_solid_model *)two, O[0].c, 512) == ARG && strstr(O[0].c, "not a 3D model") != NULL);
  memset(O, SENTINEL, sizeof O);
  CHECK(tfem_solid_last_error(NULL, O[0].c, 512) == NUL && outputs_intact());
  CHECK(tfem_solid_last_error_length(NULL) == 1);
  CHECK(tfem_last_error(two, O[0].c, 512) == TFEM_STATUS_OK); /* the 2D model is still live */

  /* No mesh yet. */
  tfem_solid_model *m = tfem_solid_create();
  solid_state_of(m, &solid_before);
  SOLID_UNWRITTEN(m, tfem_solid_get_sizes(m, O[0].i, O[1].i, O[2].i), STATE);
  SOLID_UNWRITTEN(m, tfem_solid_get_boundary_face_count(m, O[0].i), STATE);
  SOLID_UNWRITTEN(m, tfem_solid_get_mesh_nodes(m, O[0].d, L), STATE);
  SOLID_UNWRITTEN(m, tfem_solid_get_mesh_tetrahedra(m, O[0].i, L, O[1].i, L), STATE);
  SOLID_UNWRITTEN(m, tfem_solid_get_boundary_faces(m, O[0].i, L, O[1].i, L), STATE);
  SOLID_UNWRITTEN(m, tfem_solid_get_warning_size(m, 0, O[0].z), ARG);
  SOLID_UNWRITTEN(m, tfem_solid_get_warning(m, 0, O[0].c, 512), ARG);
  SOLID_UNWRITTEN(m, tfem_solid_set_boundary_faces(m, SC_FACES, C3.faces, C3.tags), STATE);
  SOLID_UNWRITTEN(m, tfem_solid_fix(m, 0, TFEM_AXIS_X, 0.0), STATE);
  SOLID_UNWRITTEN(m, tfem_solid_fix_faces(m, 5, TFEM_AXIS_Z, 0.0), STATE);
  SOLID_UNWRITTEN(m, tfem_solid_add_pressure(m, 16, 0.1), STATE);
  SOLID_UNWRITTEN(m, tfem_solid_add_traction(m, 16, 0.0, 0.0, 0.1), STATE);
  SOLID_UNWRITTEN(m, tfem_solid_add_nodal_force(m, 0, 0.0, 0.0, 1.0), STATE);
  SOLID_UNWRITTEN(m, tfem_solid_add_contact_pair(m, 6, 15, O[0].i), STATE);
  SOLID_UNWRITTEN(m, tfem_solid_solve(m, &O[0].info), STATE);
  SOLID_UNWRITTEN(m, tfem_solid_solve_contact(m, NULL, &O[0].info), STATE);
  SOLID_UNWRITTEN(m, tfem_solid_step(m, 1.0, NULL, &O[0].info), STATE);
  SOLID_UNWRITTEN(m, tfem_solid_revert_step(m), STATE);
  SOLID_UNWRITTEN(m, tfem_solid_get_displacements(m, O[0].d, L), STATE);
  SOLID_UNWRITTEN(m, tfem_solid_get_solve_info(m, &O[0].info), STATE);
  tfem_solid_destroy(m);

  /* A mesh, not solved: no results yet; body 2 without a material. */
  m = tfem_solid_create();
  CHECK(tfem_solid_set_mesh(m, SC_NODES, C3.xyz, SC_TETS, C3.tets, C3.body, 0) == TFEM_STATUS_OK);
  CHECK(tfem_solid_set_boundary_faces(m, SC_FACES, C3.faces, C3.tags) == TFEM_STATUS_OK);
  CHECK(tfem_solid_set_material(m, 1, 1.0, 0.25) == TFEM_STATUS_OK);
  CHECK(tfem_solid_fix_faces(m, 5, TFEM_AXIS_Z, 0.0) == TFEM_STATUS_OK);
  solid_state_of(m, &solid_before);
  SOLID_UNWRITTEN(m, tfem_solid_get_solve_info(m, &O[0].info), STATE);
  SOLID_UNWRITTEN(m, tfem_solid_get_iterations(m, O[0].i), STATE);
  SOLID_UNWRITTEN(m, tfem_solid_get_displacements(m, O[0].d, L), STATE);
  SOLID_UNWRITTEN(m, tfem_solid_get_element_strains(m, O[0].d, L), STATE);
  SOLID_UNWRITTEN(m, tfem_solid_get_element_stresses(m, O[0].d, L), STATE);
  SOLID_UNWRITTEN(m, tfem_solid_get_reactions(m, O[0].d, L), STATE);
  SOLID_UNWRITTEN(m, tfem_solid_get_external_work(m, O[0].d), STATE);
  SOLID_UNWRITTEN(m, tfem_solid_get_contact_tetrahedra(m, O[0].i, L), STATE);
  SOLID_UNWRITTEN(m, tfem_solid_get_contact_active(m, O[0].i, L), STATE);
  SOLID_UNWRITTEN(m, tfem_solid_get_contact_forces(m, O[0].d, L), STATE);
  SOLID_UNWRITTEN(m, tfem_solid_get_contact_nodal_pressures(m, O[0].d, L), STATE);
  SOLID_UNWRITTEN(m, tfem_solid_get_contact_area(m, O[0].d), STATE);
  SOLID_UNWRITTEN(m, tfem_solid_get_contact_pair_area(m, 0, O[0].d), STATE);
  SOLID_UNWRITTEN(m, tfem_solid_write_vtu(m, "/nonexistent-folder-of-tfem/x.vtu"), STATE);
  SOLID_UNWRITTEN(m, tfem_solid_revert_step(m), STATE);
  SOLID_UNWRITTEN(m, tfem_solid_solve(m, &O[0].info), MATERIAL);
  SOLID_UNWRITTEN(m, tfem_solid_step(m, 1.0, NULL, &O[0].info), MATERIAL);
  tfem_solid_destroy(m);

  /* Solved: every refusal of a getter (a buffer too short, or NULL beside
   * others long enough; an index out of range) and of a mutator (a bad
   * argument, a state, a solve that fails before or after its work)
   * writes nothing and leaves every result as it was. */
  m = stacked_cubes(0.0);
  CHECK(tfem_solid_solve_contact(m, NULL, NULL) == TFEM_STATUS_OK);
  int nc = 0, warnings = -1;
  CHECK(tfem_solid_get_sizes(m, NULL, NULL, &nc) == TFEM_STATUS_OK && nc == SC_CONTACT);
  CHECK(tfem_solid_warning_count(m, &warnings) == TFEM_STATUS_OK && warnings == 0);
  solid_state_of(m, &solid_before);
  const size_t nn = SC_NODES, nt = SC_TETS, nf = SC_FACES, ce = SC_CONTACT;
  SOLID_UNWRITTEN(m, tfem_solid_get_mesh_nodes(m, O[0].d, 3 * nn - 1), SHORT);
  SOLID_UNWRITTEN(m, tfem_solid_get_mesh_nodes(m, NULL, 3 * nn), NUL);
  SOLID_UNWRITTEN(m, tfem_solid_get_mesh_tetrahedra(m, O[0].i, 4 * nt, O[1].i, nt - 1), SHORT);
  SOLID_UNWRITTEN(m, tfem_solid_get_mesh_tetrahedra(m, O[0].i, 4 * nt - 1, O[1].i, nt), SHORT);
  SOLID_UNWRITTEN(m, tfem_solid_get_mesh_tetrahedra(m, NULL, 0, O[1].i, nt), NUL);
  SOLID_UNWRITTEN(m, tfem_solid_get_boundary_faces(m, O[0].i, 3 * nf, O[1].i, nf - 1), SHORT);
  SOLID_UNWRITTEN(m, tfem_solid_get_boundary_faces(m, O[0].i, 3 * nf - 1, O[1].i, nf), SHORT);
  SOLID_UNWRITTEN(m, tfem_solid_get_boundary_faces(m, NULL, 3 * nf, O[1].i, nf), NUL);
  SOLID_UNWRITTEN(m, tfem_solid_get_sizes(NULL, O[0].i, O[1].i, O[2].i), NUL);
  SOLID_UNWRITTEN(m, tfem_solid_get_boundary_face_count(m, NULL), NUL);
  SOLID_UNWRITTEN(m, tfem_solid_warning_count(m, NULL), NUL);
  SOLID_UNWRITTEN(m, tfem_solid_get_warning_size(m, 0, O[0].z), ARG);
  SOLID_UNWRITTEN(m, tfem_solid_get_warning_size(m, -1, O[0].z), ARG);
  SOLID_UNWRITTEN(m, tfem_solid_get_warning(m, INT_MIN, O[0].c, 512), ARG);
  SOLID_UNWRITTEN(m, tfem_solid_get_solve_info(m, NULL), NUL);
  SOLID_UNWRITTEN(m, tfem_solid_get_iterations(m, NULL), NUL);
  SOLID_UNWRITTEN(m, tfem_solid_get_displacements(m, O[0].d, 3 * nn - 1), SHORT);
  SOLID_UNWRITTEN(m, tfem_solid_get_displacements(m, NULL, 3 * nn), NUL);
  SOLID_UNWRITTEN(m, tfem_solid_get_element_strains(m, O[0].d, 6 * nt - 1), SHORT);
  SOLID_UNWRITTEN(m, tfem_solid_get_element_stresses(m, O[0].d, 6 * nt - 1), SHORT);
  SOLID_UNWRITTEN(m, tfem_solid_get_element_stresses(m, O[0].d, 0), SHORT);
  SOLID_UNWRITTEN(m, tfem_solid_get_reactions(m, O[0].d, 3 * nn - 1), SHORT);
  SOLID_UNWRITTEN(m, tfem_solid_get_reactions(m, NULL, 3 * nn), NUL);
  SOLID_UNWRITTEN(m, tfem_solid_get_external_work(m, NULL), NUL);
  SOLID_UNWRITTEN(m, tfem_solid_get_contact_tetrahedra(m, O[0].i, 4 * ce - 1), SHORT);
  SOLID_UNWRITTEN(m, tfem_solid_get_contact_active(m, O[0].i, ce - 1), SHORT);
  SOLID_UNWRITTEN(m, tfem_solid_get_contact_active(m, NULL, ce), NUL);
  SOLID_UNWRITTEN(m, tfem_solid_get_contact_forces(m, O[0].d, 3 * nn - 1), SHORT);
  SOLID_UNWRITTEN(m, tfem_solid_get_contact_nodal_pressures(m, O[0].d, nn - 1), SHORT);
  SOLID_UNWRITTEN(m, tfem_solid_get_contact_area(m, NULL), NUL);
  SOLID_UNWRITTEN(m, tfem_solid_get_contact_pair_area(m, 1, O[0].d), ARG);
  SOLID_UNWRITTEN(m, tfem_solid_get_contact_pair_area(m, -1, O[0].d), ARG);
  SOLID_UNWRITTEN(m, tfem_solid_get_contact_pair_area(m, INT_MAX, O[0].d), ARG);
  SOLID_UNWRITTEN(m, tfem_solid_get_contact_pair_area(m, 0, NULL), NUL);

  /* Mutators refusing their arguments. */
  int bad_tets[4 * SC_TETS], bad_faces[3 * SC_FACES];
  double bad_xyz[3 * SC_NODES];
  memcpy(bad_tets, C3.tets, sizeof bad_tets);
  bad_tets[4 * 5 + 1] = SC_NODES; /* a node out of range */
  SOLID_UNWRITTEN(m, tfem_solid_set_mesh(m, SC_NODES, C3.xyz, SC_TETS, bad_tets, C3.body, 0), MESH);
  bad_tets[4 * 5 + 1] = bad_tets[4 * 5 + 2]; /* a node repeated in a tetrahedron */
  SOLID_UNWRITTEN(m, tfem_solid_set_mesh(m, SC_NODES, C3.xyz, SC_TETS, bad_tets, C3.body, 0), MESH);
  bad_tets[4 * 5 + 1] = -1;
  SOLID_UNWRITTEN(m, tfem_solid_set_mesh(m, SC_NODES, C3.xyz, SC_TETS, bad_tets, C3.body, 0), MESH);
  memcpy(bad_xyz, C3.xyz, sizeof bad_xyz);
  bad_xyz[7] = NAN;
  SOLID_UNWRITTEN(m, tfem_solid_set_mesh(m, SC_NODES, bad_xyz, SC_TETS, C3.tets, C3.body, 0), MESH);
  bad_xyz[7] = -INFINITY;
  SOLID_UNWRITTEN(m, tfem_solid_set_mesh(m, SC_NODES, bad_xyz, SC_TETS, C3.tets, C3.body, 0), MESH);
  SOLID_UNWRITTEN(m, tfem_solid_set_mesh(m, SC_NODES, C3.xyz, SC_TETS, C3.tets, C3.body, 2), ARG);
  SOLID_UNWRITTEN(m, tfem_solid_set_mesh(m, SC_NODES, C3.xyz, SC_TETS, C3.tets, C3.body, -1), ARG);
  SOLID_UNWRITTEN(m, tfem_solid_set_mesh(m, -1, C3.xyz, SC_TETS, C3.tets, C3.body, 0), ARG);
  SOLID_UNWRITTEN(m, tfem_solid_set_mesh(m, SC_NODES, C3.xyz, INT_MIN, C3.tets, C3.body, 0), ARG);
  SOLID_UNWRITTEN(m, tfem_solid_set_mesh(m, SC_NODES, NULL, SC_TETS, C3.tets, C3.body, 0), NUL);
  SOLID_UNWRITTEN(m, tfem_solid_set_mesh(m, SC_NODES, C3.xyz, SC_TETS, NULL, C3.body, 0), NUL);
  SOLID_UNWRITTEN(m, tfem_solid_set_mesh(m, SC_NODES, C3.xyz, SC_TETS, C3.tets, NULL, 0), NUL);
  SOLID_UNWRITTEN(m, tfem_solid_load_gmsh(m, NULL, 0), NUL);
  SOLID_UNWRITTEN(m, tfem_solid_load_gmsh(m, "/nonexistent-folder-of-tfem/x.msh", 0), TFEM_STATUS_IO);
  SOLID_UNWRITTEN(m, tfem_solid_load_gmsh(m, "", 0), TFEM_STATUS_IO);
  /* (faces come before the constraints, loads and pairs that name them) */
  SOLID_UNWRITTEN(m, tfem_solid_set_boundary_faces(m, SC_FACES, C3.faces, C3.tags), STATE);
  SOLID_UNWRITTEN(m, tfem_solid_add_boundary_faces(m, 1, C3.faces, C3.tags), STATE);
  memcpy(bad_faces, C3.faces, sizeof bad_faces);
  bad_faces[4] = SC_NODES;
  SOLID_UNWRITTEN(m, tfem_solid_set_boundary_faces(m, SC_FACES, bad_faces, C3.tags), MESH);
  SOLID_UNWRITTEN(m, tfem_solid_set_boundary_faces(m, -1, C3.faces, C3.tags), ARG);
  SOLID_UNWRITTEN(m, tfem_solid_set_boundary_faces(m, SC_FACES, C3.faces, NULL), NUL);
  SOLID_UNWRITTEN(m, tfem_solid_add_boundary_faces(m, 2, NULL, C3.tags), NUL);
  SOLID_UNWRITTEN(m, tfem_solid_set_material(m, 1, -1.0, 0.25), MATERIAL);
  SOLID_UNWRITTEN(m, tfem_solid_set_material(m, 1, 0.0, 0.25), MATERIAL);
  SOLID_UNWRITTEN(m, tfem_solid_set_material(m, 1, NAN, 0.25), MATERIAL);
  SOLID_UNWRITTEN(m, tfem_solid_set_material(m, 2, INFINITY, 0.25), MATERIAL);
  SOLID_UNWRITTEN(m, tfem_solid_set_material(m, 2, 1.0, 0.5), MATERIAL);
  SOLID_UNWRITTEN(m, tfem_solid_set_material(m, 2, 1.0, -1.0), MATERIAL);
  SOLID_UNWRITTEN(m, tfem_solid_set_material(m, 2, 1.0, NAN), MATERIAL);
  SOLID_UNWRITTEN(m, tfem_solid_set_tempering(m, 4, 0.0), ARG);
  SOLID_UNWRITTEN(m, tfem_solid_set_tempering(m, -1, 0.0), ARG);
  SOLID_UNWRITTEN(m, tfem_solid_set_tempering(m, 1, -1.0), ARG);
  SOLID_UNWRITTEN(m, tfem_solid_set_tempering(m, 1, 0.0), ARG);
  SOLID_UNWRITTEN(m, tfem_solid_set_tempering(m, 2, NAN), ARG);
  SOLID_UNWRITTEN(m, tfem_solid_set_tempering(m, 2, INFINITY), ARG);
  SOLID_UNWRITTEN(m, tfem_solid_set_ordering(m, 3), ARG);
  SOLID_UNWRITTEN(m, tfem_solid_set_ordering(m, -1), ARG);
  SOLID_UNWRITTEN(m, tfem_solid_fix(m, SC_NODES, TFEM_AXIS_X, 0.0), ARG);
  SOLID_UNWRITTEN(m, tfem_solid_fix(m, -1, TFEM_AXIS_X, 0.0), ARG);
  SOLID_UNWRITTEN(m, tfem_solid_fix(m, INT_MIN, TFEM_AXIS_X, 0.0), ARG);
  SOLID_UNWRITTEN(m, tfem_solid_fix(m, 0, 3, 0.0), ARG);
  SOLID_UNWRITTEN(m, tfem_solid_fix(m, 0, -1, 0.0), ARG);
  SOLID_UNWRITTEN(m, tfem_solid_fix(m, 0, TFEM_AXIS_Z, NAN), ARG);
  SOLID_UNWRITTEN(m, tfem_solid_fix(m, 0, TFEM_AXIS_Z, -INFINITY), ARG);
  SOLID_UNWRITTEN(m, tfem_solid_fix_faces(m, 99, TFEM_AXIS_X, 0.0), ARG);
  SOLID_UNWRITTEN(m, tfem_solid_fix_faces(m, 5, 3, 0.0), ARG);
  SOLID_UNWRITTEN(m, tfem_solid_fix_faces(m, 5, TFEM_AXIS_Z, NAN), ARG);
  SOLID_UNWRITTEN(m, tfem_solid_add_pressure(m, 99, 0.1), ARG);
  SOLID_UNWRITTEN(m, tfem_solid_add_pressure(m, 16, NAN), ARG);
  SOLID_UNWRITTEN(m, tfem_solid_add_pressure(m, 16, INFINITY), ARG);
  SOLID_UNWRITTEN(m, tfem_solid_add_traction(m, 99, 0.0, 0.0, 1.0), ARG);
  SOLID_UNWRITTEN(m, tfem_solid_add_traction(m, 16, 0.0, NAN, 1.0), ARG);
  SOLID_UNWRITTEN(m, tfem_solid_add_traction(m, 16, 0.0, 0.0, -INFINITY), ARG);
  SOLID_UNWRITTEN(m, tfem_solid_add_nodal_force(m, SC_NODES, 0.0, 0.0, 1.0), ARG);
  SOLID_UNWRITTEN(m, tfem_solid_add_nodal_force(m, -1, 0.0, 0.0, 1.0), ARG);
  SOLID_UNWRITTEN(m, tfem_solid_add_nodal_force(m, 0, NAN, 0.0, 1.0), ARG);
  SOLID_UNWRITTEN(m, tfem_solid_add_contact_pair(m, 6, 6, O[0].i), ARG);
  SOLID_UNWRITTEN(m, tfem_solid_add_contact_pair(m, 6, 99, O[0].i), ARG);
  SOLID_UNWRITTEN(m, tfem_solid_add_contact_pair(m, 99, 15, O[0].i), ARG);
  /* Solves and steps that fail before their work: the options, the load
   * factor; a revert with no step. */
  tfem_contact_options_default(&bad);
  bad.law = TFEM_CONTACT_LAW_STICK;
  SOLID_UNWRITTEN(m, tfem_solid_solve_contact(m, &bad, &O[0].info), ARG);
  SOLID_UNWRITTEN(m, tfem_solid_step(m, 1.0, &bad, &O[0].info), ARG);
  tfem_contact_options_default(&bad);
  bad.inversion_test = TFEM_INVERSION_TEST_LITERAL;
  SOLID_UNWRITTEN(m, tfem_solid_solve_contact(m, &bad, &O[0].info), ARG);
  tfem_contact_options_default(&bad);
  bad.max_iterations = 0;
  SOLID_UNWRITTEN(m, tfem_solid_solve_contact(m, &bad, &O[0].info), ARG);
  tfem_contact_options_default(&bad);
  bad.contact_modulus = -1.0;
  SOLID_UNWRITTEN(m, tfem_solid_solve_contact(m, &bad, &O[0].info), ARG);
  tfem_contact_options_default(&bad);
  bad.lambda = NAN;
  SOLID_UNWRITTEN(m, tfem_solid_solve_contact(m, &bad, &O[0].info), ARG);
  tfem_contact_options_default(&bad);
  bad.law = 7;
  SOLID_UNWRITTEN(m, tfem_solid_step(m, 1.0, &bad, &O[0].info), ARG);
  SOLID_UNWRITTEN(m, tfem_solid_step(m, NAN, NULL, &O[0].info), ARG);
  SOLID_UNWRITTEN(m, tfem_solid_step(m, -INFINITY, NULL, &O[0].info), ARG);
  SOLID_UNWRITTEN(m, tfem_solid_step(m, 1e301, NULL, &O[0].info), ARG);
  SOLID_UNWRITTEN(m, tfem_solid_revert_step(m), STATE); /* (a solve is no step) */
  /* ... and after their work: a contact modulus that leaves body 2 held
   * by nothing (SINGULAR), a step unloading it (SINGULAR). */
  tfem_contact_options_default(&bad);
  bad.contact_modulus = 1e-300;
  SOLID_UNWRITTEN(m, tfem_solid_solve_contact(m, &bad, &O[0].info), TFEM_STATUS_SINGULAR);
  SOLID_UNWRITTEN(m, tfem_solid_step(m, -1.0, NULL, &O[0].info), TFEM_STATUS_SINGULAR);
  SOLID_UNWRITTEN(m, tfem_solid_write_vtu(m, NULL), NUL);
  SOLID_UNWRITTEN(m, tfem_solid_write_vtu(m, "/nonexistent-folder-of-tfem/x.vtu"), TFEM_STATUS_IO);
  SOLID_UNWRITTEN(m, tfem_solid_write_vtu(m, ""), TFEM_STATUS_IO);

  /* A step, then the refusals again: the step's results stay, and so does
   * its revert (once). */
  CHECK(tfem_solid_step(m, 0.5, NULL, NULL) == TFEM_STATUS_OK);
  solid_state_of(m, &solid_before);
  SOLID_UNWRITTEN(m, tfem_solid_step(m, NAN, NULL, &O[0].info), ARG);
  SOLID_UNWRITTEN(m, tfem_solid_step(m, -1.0, NULL, &O[0].info), TFEM_STATUS_SINGULAR);
  SOLID_UNWRITTEN(m, tfem_solid_solve_contact(m, &bad, &O[0].info), TFEM_STATUS_SINGULAR);
  SOLID_UNWRITTEN(m, tfem_solid_fix(m, 0, 5, 0.0), ARG);
  SOLID_UNWRITTEN(m, tfem_solid_get_displacements(m, O[0].d, 3 * nn - 1), SHORT);
  CHECK(tfem_solid_revert_step(m) == TFEM_STATUS_OK);
  solid_state_of(m, &solid_before);
  SOLID_UNWRITTEN(m, tfem_solid_revert_step(m), STATE);
  /* (the results reverted to are the solve's) */
  solid_state_of(m, &solid_after);
  tfem_solid_model *again = stacked_cubes(0.0);
  CHECK(tfem_solid_solve_contact(again, NULL, NULL) == TFEM_STATUS_OK);
  solid_state_of(again, &solid_before);
  CHECK(memcmp(&solid_before, &solid_after, sizeof solid_before) == 0);
  tfem_solid_destroy(again);

  /* The model is still usable: the same problem solved again gives the
   * same results, bit for bit, and so does a step after every refusal. */
  solid_state_of(m, &solid_before);
  CHECK(tfem_solid_solve_contact(m, NULL, NULL) == TFEM_STATUS_OK);
  expect_solid_as_it_was(m, "the solve after the refusals", __LINE__);
  CHECK(tfem_solid_last_error_length(m) == 1);
  tfem_solid_destroy(m);

  /* A solve that fails after its work on a problem with results: the gap
   * closed in two iterations, refused at one (NOT_CONVERGED). */
  m = stacked_cubes(0.01);
  CHECK(tfem_solid_solve_contact(m, NULL, NULL) == TFEM_STATUS_OK);
  int iterations = 0;
  CHECK(tfem_solid_get_iterations(m, &iterations) == TFEM_STATUS_OK && iterations >= 2);
  solid_state_of(m, &solid_before);
  tfem_contact_options_default(&bad);
  bad.max_iterations = 1;
  SOLID_UNWRITTEN(m, tfem_solid_solve_contact(m, &bad, &O[0].info), TFEM_STATUS_NOT_CONVERGED);
  SOLID_UNWRITTEN(m, tfem_solid_step(m, 0.0, &bad, &O[0].info), TFEM_STATUS_NOT_CONVERGED);
  CHECK(tfem_solid_solve_contact(m, NULL, NULL) == TFEM_STATUS_OK);
  expect_solid_as_it_was(m, "the solve after the refused ones", __LINE__);
  tfem_solid_destroy(m);
  /* (The exception: the message copies write the message cut to the
   * buffer with BUFFER_TOO_SMALL.) */
  m = tfem_solid_create();
  CHECK(tfem_solid_fix(m, 0, TFEM_AXIS_X, 0.0) == STATE);
  memset(O, SENTINEL, sizeof O);
  CHECK(tfem_solid_last_error(m, O[0].c, 8) == SHORT && strlen(O[0].c) == 7);
  memset(O, SENTINEL, sizeof O);
  CHECK(tfem_solid_last_error(m, O[0].c, 0) == SHORT && outputs_intact());
  tfem_solid_destroy(m);

  /* The host contact context: refused handles first. */
  dead = tfem_solid_create();
  tfem_solid_destroy(dead);
  double u[SC_NL], nan_u[SC_NL], huge_u[SC_NL], host[3 * SC_NODES];
  memset(u, 0, sizeof u);
  memset(nan_u, 0, sizeof nan_u);
  memset(huge_u, 0, sizeof huge_u);
  nan_u[5] = NAN;
  tfem_solid_contact *const wrong_c[4] = {NULL, (tfem_solid_contact *)dead, (tfem_solid_contact *)two_c,
                                           (tfem_solid_contact *)live};
  for (int w = 0; w < 4; ++w) {
    tfem_solid_contact *h = wrong_c[w];
    const tfem_status want = h ? ARG : NUL;
    UNWRITTEN(tfem_solid_contact_add_side(h, 6, 1, 1.0, 0, NULL, NULL, NULL, 0, NULL, O[0].i), want);
    UNWRITTEN(tfem_solid_contact_add_pair(h, 0, 1, O[0].i), want);
    UNWRITTEN(tfem_solid_contact_setup(h), want);
    UNWRITTEN(tfem_solid_contact_sizes(h, O[0].i, O[1].i, O[2].l), want);
    UNWRITTEN(tfem_solid_contact_nodes(h, O[0].i, L), want);
    UNWRITTEN(tfem_solid_contact_tetrahedra(h, O[0].i, L), want);
    UNWRITTEN(tfem_solid_contact_pattern(h, O[0].l, O[1].l, L), want);
    UNWRITTEN(tfem_solid_contact_element_equations(h, O[0].l, L), want);
    UNWRITTEN(tfem_solid_contact_element_blocks(h, O[0].d, L), want);
    UNWRITTEN(tfem_solid_contact_evaluate(h, u, SC_NL, O[0].d, L, O[1].d, L), want);
    UNWRITTEN(tfem_solid_contact_gather(h, host, 3 * SC_NODES, O[0].d, L), want);
    UNWRITTEN(tfem_solid_contact_update(h, u, SC_NL, O[0].i, O[1].i, O[2].i), want);
    UNWRITTEN(tfem_solid_contact_restart(h), want);
    UNWRITTEN(tfem_solid_contact_get_active(h, O[0].i, L), want);
    UNWRITTEN(tfem_solid_contact_gaps(h, u, SC_NL, O[0].d, L), want);
    UNWRITTEN(tfem_solid_contact_area(h, O[0].d), want);
    memset(O, SENTINEL, sizeof O);
    CHECK(tfem_solid_contact_scatter_add(h, u, SC_NL, O[0].d, 3 * SC_NODES) == want && outputs_intact());
    tfem_solid_contact_destroy(h); /* a no-op */
  }
  CHECK(tfem_last_error(two, O[0].c, 512) == TFEM_STATUS_OK && tfem_contact_last_error(two_c, O[0].c, 512) ==
        TFEM_STATUS_OK);
  solid_before = live_state;
  expect_solid_as_it_was(live, "the 3D context's refusals of the 3D model", __LINE__);
  memset(O, SENTINEL, sizeof O);
  CHECK(tfem_solid_contact_create(2, NULL) == NULL && outputs_intact());
  tfem_contact_options_default(&bad);
  bad.law = TFEM_CONTACT_LAW_STICK;
  CHECK(tfem_solid_contact_create(0, &bad) == NULL);

  /* No pair yet: what needs B refuses; the sides' refusals. */
  tfem_solid_contact *c = sc;
  UNWRITTEN(tfem_solid_contact_setup(c), STATE);
  UNWRITTEN(tfem_solid_contact_sizes(c, O[0].i, O[1].i, O[2].l), STATE);
  UNWRITTEN(tfem_solid_contact_tetrahedra(c, O[0].i, L), STATE);
  UNWRITTEN(tfem_solid_contact_pattern(c, O[0].l, O[1].l, L), STATE);
  UNWRITTEN(tfem_solid_contact_element_equations(c, O[0].l, L), STATE);
  UNWRITTEN(tfem_solid_contact_element_blocks(c, O[0].d, L), STATE);
  UNWRITTEN(tfem_solid_contact_get_active(c, O[0].i, L), STATE);
  UNWRITTEN(tfem_solid_contact_evaluate(c, NULL, 0, O[0].d, L, O[1].d, L), STATE);
  UNWRITTEN(tfem_solid_contact_update(c, NULL, 0, O[0].i, O[1].i, O[2].i), STATE);
  UNWRITTEN(tfem_solid_contact_gaps(c, NULL, 0, O[0].d, L), STATE);
  UNWRITTEN(tfem_solid_contact_area(c, O[0].d), STATE);
  UNWRITTEN(tfem_solid_contact_set_active(c, NULL, 0), STATE);
  UNWRITTEN(tfem_solid_contact_restart(c), STATE);
  stacked_cubes_mesh(&C3, 0.0);
  host_side_t lower, upper, side;
  host_side_of(6, 1.0, 0, &lower);
  host_side_of(15, -1.0, 0, &upper);
#define ADD_SIDE(c, s, tag, body, young, out) \
  tfem_solid_contact_add_side(c, tag, body, young, (s).n_nodes, (s).nodes, (s).xyz, (s).equations, (s).n_triangles, \
                              (s).triangles, out)
  side = lower;
  UNWRITTEN(tfem_solid_contact_add_side(c, 6, 1, 1.0, side.n_nodes, NULL, side.xyz, side.equations, side.n_triangles,
                                        side.triangles, O[0].i), NUL);
  UNWRITTEN(tfem_solid_contact_add_side(c, 6, 1, 1.0, side.n_nodes, side.nodes, NULL, side.equations,
                                        side.n_triangles, side.triangles, O[0].i), NUL);
  UNWRITTEN(tfem_solid_contact_add_side(c, 6, 1, 1.0, side.n_nodes, side.nodes, side.xyz, NULL, side.n_triangles,
                                        side.triangles, O[0].i), NUL);
  UNWRITTEN(tfem_solid_contact_add_side(c, 6, 1, 1.0, side.n_nodes, side.nodes, side.xyz, side.equations,
                                        side.n_triangles, NULL, O[0].i), NUL);
  UNWRITTEN(tfem_solid_contact_add_side(c, 6, 1, 1.0, -1, side.nodes, side.xyz, side.equations, side.n_triangles,
                                        side.triangles, O[0].i), ARG);
  UNWRITTEN(tfem_solid_contact_add_side(c, 6, 1, 1.0, side.n_nodes, side.nodes, side.xyz, side.equations, -1,
                                        side.triangles, O[0].i), ARG);
  UNWRITTEN(tfem_solid_contact_add_side(c, 6, 1, 1.0, side.n_nodes, side.nodes, side.xyz, side.equations, 0,
                                        side.triangles, O[0].i), ARG);
  UNWRITTEN(ADD_SIDE(c, side, 6, 1, -1.0, O[0].i), ARG);
  UNWRITTEN(ADD_SIDE(c, side, 6, 1, NAN, O[0].i), ARG);
  UNWRITTEN(ADD_SIDE(c, side, 6, 1, INFINITY, O[0].i), ARG);
  side.triangles[4] = 999; /* a node the side does not give */
  UNWRITTEN(ADD_SIDE(c, side, 6, 1, 1.0, O[0].i), ARG);
  side = lower;
  side.nodes[2] = -1; /* below the index base */
  UNWRITTEN(ADD_SIDE(c, side, 6, 1, 1.0, O[0].i), ARG);
  side = lower;
  side.xyz[4] = NAN;
  UNWRITTEN(ADD_SIDE(c, side, 6, 1, 1.0, O[0].i), ARG);
  side = lower;
  side.equations[7] = INT64_MAX; /* beyond any host vector */
  UNWRITTEN(ADD_SIDE(c, side, 6, 1, 1.0, O[0].i), ARG);
  CHECK(ADD_SIDE(c, lower, 6, 1, 1.0, NULL) == TFEM_STATUS_OK);
  side = upper;
  memcpy(side.nodes, lower.nodes, sizeof side.nodes); /* the lower side's nodes at other coordinates */
  UNWRITTEN(ADD_SIDE(c, side, 15, 2, 1.0, O[0].i), ARG);
  UNWRITTEN(tfem_solid_contact_add_pair(c, 0, 1, O[0].i), ARG); /* side 1 does not exist */
  UNWRITTEN(tfem_solid_contact_add_pair(c, -1, 0, O[0].i), ARG);
  UNWRITTEN(tfem_solid_contact_add_pair(c, 0, 0, O[0].i), ARG); /* one body */
  UNWRITTEN(tfem_solid_contact_add_pair(c, INT_MIN, INT_MAX, O[0].i), ARG);
  CHECK(ADD_SIDE(c, upper, 15, 2, 1.0, NULL) == TFEM_STATUS_OK);
  CHECK(tfem_solid_contact_add_pair(c, 0, 1, NULL) == TFEM_STATUS_OK);
  CHECK(tfem_solid_contact_setup(c) == TFEM_STATUS_OK);
  int hn = 0, ht = 0;
  int64_t entries = 0;
  CHECK(tfem_solid_contact_sizes(c, &hn, &ht, &entries) == TFEM_STATUS_OK && hn == 2 * SC_SIDE_NODES &&
        ht == SC_CONTACT && entries > 0 && entries <= 144 * SC_CONTACT);
  for (int k = 0; k < SC_NL; ++k) u[k] = 1e-3 * ((k * 7) % 11 - 5);
  for (int k = 0; k < 3 * SC_NODES; ++k) host[k] = 1e-3 * ((k * 5) % 13 - 6);
  host_state_of(c, u, &host_before);
  for (int k = 0; k < 10; ++k) CHECK(host_before.st[k] == TFEM_STATUS_OK);
  const size_t en = (size_t)entries, hnl = 3 * (size_t)hn, ct = (size_t)ht, neq = 3 * SC_NODES;

  /* B is built: sides and pairs are fixed. */
  HOST_UNWRITTEN(c, u, ADD_SIDE(c, lower, 7, 3, 1.0, O[0].i), STATE);
  HOST_UNWRITTEN(c, u, tfem_solid_contact_add_pair(c, 0, 1, O[0].i), STATE);
  /* Buffers too short, or NULL beside others long enough. */
  HOST_UNWRITTEN(c, u, tfem_solid_contact_nodes(c, O[0].i, (size_t)hn - 1), SHORT);
  HOST_UNWRITTEN(c, u, tfem_solid_contact_nodes(c, NULL, (size_t)hn), NUL);
  HOST_UNWRITTEN(c, u, tfem_solid_contact_tetrahedra(c, O[0].i, 4 * ct - 1), SHORT);
  HOST_UNWRITTEN(c, u, tfem_solid_contact_pattern(c, O[0].l, O[1].l, en - 1), SHORT);
  HOST_UNWRITTEN(c, u, tfem_solid_contact_pattern(c, O[0].l, NULL, en), NUL);
  HOST_UNWRITTEN(c, u, tfem_solid_contact_pattern(c, NULL, O[1].l, en), NUL);
  HOST_UNWRITTEN(c, u, tfem_solid_contact_element_equations(c, O[0].l, 12 * ct - 1), SHORT);
  HOST_UNWRITTEN(c, u, tfem_solid_contact_element_blocks(c, O[0].d, 144 * ct - 1), SHORT);
  HOST_UNWRITTEN(c, u, tfem_solid_contact_element_blocks(c, NULL, 144 * ct), NUL);
  HOST_UNWRITTEN(c, u, tfem_solid_contact_get_active(c, O[0].i, ct - 1), SHORT);
  HOST_UNWRITTEN(c, u, tfem_solid_contact_area(c, NULL), NUL);
  /* Evaluating: a NULL or short u, a NaN, a buffer too short. */
  HOST_UNWRITTEN(c, u, tfem_solid_contact_evaluate(c, NULL, hnl, O[0].d, en, O[1].d, hnl), NUL);
  HOST_UNWRITTEN(c, u, tfem_solid_contact_evaluate(c, u, hnl - 1, O[0].d, en, O[1].d, hnl), ARG);
  HOST_UNWRITTEN(c, u, tfem_solid_contact_evaluate(c, u, hnl + 3, O[0].d, en, O[1].d, hnl), ARG);
  HOST_UNWRITTEN(c, u, tfem_solid_contact_evaluate(c, u, hnl, O[0].d, en - 1, O[1].d, hnl), SHORT);
  HOST_UNWRITTEN(c, u, tfem_solid_contact_evaluate(c, u, hnl, O[0].d, en, O[1].d, hnl - 1), SHORT);
  HOST_UNWRITTEN(c, u, tfem_solid_contact_evaluate(c, nan_u, hnl, O[0].d, en, O[1].d, hnl), ARG);
  /* Host vectors: an equation beyond the vector, a NaN there, a short u. */
  HOST_UNWRITTEN(c, u, tfem_solid_contact_gather(c, host, 3, O[0].d, hnl), ARG);
  HOST_UNWRITTEN(c, u, tfem_solid_contact_gather(c, host, neq, O[0].d, hnl - 1), SHORT);
  HOST_UNWRITTEN(c, u, tfem_solid_contact_gather(c, NULL, neq, O[0].d, hnl), NUL);
  HOST_UNWRITTEN(c, u, tfem_solid_contact_gather(c, host, neq, NULL, hnl), NUL);
  double nan_host[3 * SC_NODES];
  memcpy(nan_host, host, sizeof host);
  for (int k = 0; k < 3 * SC_NODES; ++k) nan_host[k] = NAN; /* (every equation: the sides' too) */
  HOST_UNWRITTEN(c, u, tfem_solid_contact_gather(c, nan_host, neq, O[0].d, hnl), ARG);
  /* scatter_add: the host vector (O[0]) unchanged by every refusal */
#define SCATTER_UNCHANGED(call, status)                                          \
  do {                                                                           \
    memset(O, SENTINEL, sizeof O);                                               \
    memcpy(O[0].d, host, sizeof host);                                           \
    tfem_status got_ = (call);                                                   \
    int same_ = memcmp(O[0].d, host, sizeof host) == 0;                          \
    memset(O[0].d, SENTINEL, sizeof host);                                       \
    int intact_ = outputs_intact();                                              \
    CHECK(got_ == (status) && same_ && intact_);                                 \
    if (got_ != (status)) printf("  (line %d: status %d)\n", __LINE__, (int)got_); \
    expect_host_as_it_was(c, u, #call, __LINE__);                                \
  } while (0)
  SCATTER_UNCHANGED(tfem_solid_contact_scatter_add(c, nan_u, hnl, O[0].d, neq), ARG);
  SCATTER_UNCHANGED(tfem_solid_contact_scatter_add(c, u, hnl - 3, O[0].d, neq), ARG);
  SCATTER_UNCHANGED(tfem_solid_contact_scatter_add(c, u, hnl, O[0].d, 3), ARG);
  SCATTER_UNCHANGED(tfem_solid_contact_scatter_add(c, NULL, hnl, O[0].d, neq), NUL);
  /* (the sides pulled 2e308 apart: the gaps and the residual overflow) */
  for (int k = 0; k < SC_NL; ++k) huge_u[k] = k % 3 != 2 ? 0.0 : k < 3 * SC_SIDE_NODES ? -1e308 : 1e308;
  {
    double keep = host[3 * (SC_NODES - 1) + 2];
    for (int k = 0; k < 3 * SC_NODES; ++k) host[k] = k % 3 == 2 ? 1e308 : host[k];
    SCATTER_UNCHANGED(tfem_solid_contact_scatter_add(c, huge_u, hnl, O[0].d, neq), TFEM_STATUS_NUMERICAL_FAILURE);
    for (int k = 0; k < 3 * SC_NODES; ++k) host[k] = k % 3 == 2 ? INFINITY : host[k];
    SCATTER_UNCHANGED(tfem_solid_contact_scatter_add(c, u, hnl, O[0].d, neq), ARG);
    for (int k = 0; k < 3 * SC_NODES; ++k) host[k] = 1e-3 * ((k * 5) % 13 - 6);
    (void)keep;
  }
  /* The active set: a NaN, a wrong length, a flag other than 0 or 1, a
   * count that is not B's; the flags and the loop stay. */
  HOST_UNWRITTEN(c, u, tfem_solid_contact_update(c, nan_u, hnl, O[0].i, O[1].i, O[2].i), ARG);
  HOST_UNWRITTEN(c, u, tfem_solid_contact_update(c, u, hnl - 1, O[0].i, O[1].i, O[2].i), ARG);
  HOST_UNWRITTEN(c, u, tfem_solid_contact_update(c, NULL, hnl, O[0].i, O[1].i, O[2].i), NUL);
  int flags[SC_CONTACT];
  for (int k = 0; k < SC_CONTACT; ++k) flags[k] = k % 2;
  flags[3] = 2;
  HOST_UNWRITTEN(c, u, tfem_solid_contact_set_active(c, flags, ct), ARG);
  flags[3] = -1;
  HOST_UNWRITTEN(c, u, tfem_solid_contact_set_active(c, flags, ct), ARG);
  flags[3] = 0;
  HOST_UNWRITTEN(c, u, tfem_solid_contact_set_active(c, flags, ct - 1), ARG);
  HOST_UNWRITTEN(c, u, tfem_solid_contact_set_active(c, flags, ct + 1), ARG);
  HOST_UNWRITTEN(c, u, tfem_solid_contact_set_active(c, NULL, ct), NUL);
  /* Gaps: short, a NaN, an overflow. */
  HOST_UNWRITTEN(c, u, tfem_solid_contact_gaps(c, u, hnl, O[0].d, ct - 1), SHORT);
  HOST_UNWRITTEN(c, u, tfem_solid_contact_gaps(c, nan_u, hnl, O[0].d, ct), ARG);
  HOST_UNWRITTEN(c, u, tfem_solid_contact_gaps(c, u, hnl - 1, O[0].d, ct), ARG);
  HOST_UNWRITTEN(c, u, tfem_solid_contact_gaps(c, huge_u, hnl, O[0].d, ct), TFEM_STATUS_NUMERICAL_FAILURE);
  /* An evaluation whose residual overflows. */
  HOST_UNWRITTEN(c, u, tfem_solid_contact_evaluate(c, huge_u, hnl, O[0].d, en, O[1].d, hnl),
                 TFEM_STATUS_NUMERICAL_FAILURE);
  /* The loop's cap: max_iterations = 1 refuses a second update of one
   * loop, the flags and outputs unchanged. */
  tfem_solid_contact *capped;
  tfem_contact_options_default(&bad);
  bad.max_iterations = 1;
  capped = tfem_solid_contact_create(0, &bad);
  CHECK(capped != NULL);
  CHECK(ADD_SIDE(capped, lower, 6, 1, 1.0, NULL) == TFEM_STATUS_OK);
  CHECK(ADD_SIDE(capped, upper, 15, 2, 1.0, NULL) == TFEM_STATUS_OK);
  CHECK(tfem_solid_contact_add_pair(capped, 0, 1, NULL) == TFEM_STATUS_OK);
  double zero[SC_NL];
  memset(zero, 0, sizeof zero);
  CHECK(tfem_solid_contact_update(capped, zero, hnl, NULL, NULL, NULL) == TFEM_STATUS_OK);
  host_state_t capped_before;
  host_state_of(capped, u, &capped_before);
  memset(O, SENTINEL, sizeof O);
  CHECK(tfem_solid_contact_update(capped, zero, hnl, O[0].i, O[1].i, O[2].i) == TFEM_STATUS_NOT_CONVERGED &&
        outputs_intact());
  host_state_of(capped, u, &host_after);
  CHECK(memcmp(&capped_before, &host_after, sizeof host_after) == 0);
  tfem_solid_contact_destroy(capped);
  /* Sides that do not face each other: refused when B is built, the
   * context unchanged (and refused again the same way). */
  tfem_solid_contact *turned = tfem_solid_contact_create(0, NULL);
  host_side_of(15, 1.0, 0, &side);
  CHECK(ADD_SIDE(turned, lower, 6, 1, 1.0, NULL) == TFEM_STATUS_OK);
  CHECK(ADD_SIDE(turned, side, 15, 2, 1.0, NULL) == TFEM_STATUS_OK);
  CHECK(tfem_solid_contact_add_pair(turned, 0, 1, NULL) == TFEM_STATUS_OK);
  UNWRITTEN(tfem_solid_contact_sizes(turned, O[0].i, O[1].i, O[2].l), ARG);
  UNWRITTEN(tfem_solid_contact_evaluate(turned, u, hnl, O[0].d, L, O[1].d, L), ARG);
  UNWRITTEN(tfem_solid_contact_setup(turned), ARG);
  tfem_solid_contact_destroy(turned);

  /* The context is still usable, with every value it gave before. */
  expect_host_as_it_was(c, u, "every refusal", __LINE__);
  CHECK(tfem_solid_contact_last_error_length(c) == 1);
  /* (The exceptions: the message copies.) */
  CHECK(tfem_solid_contact_gaps(c, nan_u, hnl, NULL, 0) != TFEM_STATUS_OK);
  memset(O, SENTINEL, sizeof O);
  CHECK(tfem_solid_contact_last_error(c, O[0].c, 8) == SHORT && strlen(O[0].c) == 7);
  tfem_solid_contact_destroy(c);
  memset(O, SENTINEL, sizeof O);
  CHECK(tfem_solid_contact_last_error(c, O[0].c, 512) == ARG && strstr(O[0].c, "destroyed") != NULL);
  CHECK(tfem_solid_contact_last_error_length(c) == strlen(O[0].c) + 1);
#undef ADD_SIDE
#undef SCATTER_UNCHANGED

  tfem_solid_destroy(live);
  tfem_destroy(two);
  tfem_contact_destroy(two_c);
}

int main(int argc, char **argv) {
  if (argc == 4 && strcmp(argv[1], "--solve-under-cap") == 0)
    return solve_under_cap(atof(argv[2]), argv[3]);

  /* Nothing the library does may reach stderr: it goes to a file, checked
   * at the end. */
  fflush(stderr);
  int saved = dup(2);
  FILE *capture = tmpfile();
  dup2(fileno(capture), 2);

  grid(&G, 16, 4, 0.0, 0.0, 4.0, 1.0, 1, 1);
  grid(&B, 8, 2, 0.0, -0.25, 1.0, 0.25, 1, 10);
  grid(&B, 8, 2, 0.0, 0.0, 1.0, 0.25, 2, 20);
  grid(&N, 6, 2, 0.0, -0.25, 1.0, 0.25, 1, 30);
  grid(&N, 4, 2, 0.0, 0.0, 1.0, 0.25, 2, 40);
  grid(&T, 8, 2, 0.0, -0.25, 1.0, 0.25, 1, 50);
  grid(&T, 4, 2, 0.0, 0.0, 0.5, 0.25, 2, 60);
  grid(&T, 4, 2, 0.5, 0.0, 0.5, 0.25, 3, 70);
  grid(&K, 7, 3, 0.0, -1.0, 2.0, 1.0, 1, 80);
  grid(&K, 4, 4, 0.0, 0.0, 1.0, 1.0, 2, 90);
  grid(&K, 4, 5, 1.0, 0.0, 1.0, 1.0, 3, 100);

  a_clockwise_mesh_is_turned_and_solved_exactly();
  a_fold_inside_a_counter_clockwise_body_stays_inverted();
  resetting_boundary_edges_never_drops_a_load();
  boundary_groups_can_be_added_one_call_at_a_time();
  a_dof_prescribed_twice_with_different_values_is_refused();
  changing_the_ordering_or_the_threads_keeps_every_result();
  a_failed_solve_keeps_every_result_and_changes_no_later_solve();
  no_nan_or_inf_comes_back_with_ok();
  messages_stay_short_and_the_thread_slot_is_cleared();
  a_handle_of_the_other_kind_or_destroyed_is_refused();
  a_host_gets_contact_forces_gaps_and_the_contact_mesh_before_a_solve();
  a_load_history_steps_reverts_and_restarts_bit_for_bit();
  a_contact_state_never_outlives_its_problem();
  a_contact_modulus_too_stiff_for_its_overlap_is_warned_about();
  a_triangle_given_twice_is_refused_and_the_mesh_kept();
  the_mesh_reads_back_as_the_model_holds_it();
  a_host_side_given_clockwise_is_refused();
  a_failed_call_between_load_steps_keeps_the_history();
  a_mortar_solve_with_nothing_active_reports_plus_zero();
  friction_obeys_coulomb_and_restarts_bit_for_bit();
  fuzz_found_defects_at_the_friction_boundary();
  facing_tags_are_paired_automatically();
  automatic_pairing_pairs_only_faces_that_see_each_other();
  an_interface_is_paired_once_whatever_tags_its_edges_carry();
  automatic_pairing_names_what_it_leaves_out();
  a_non_matching_interface_reads_a_uniform_pressure_at_every_node();
  a_node_on_several_pairs_reads_their_forces_over_their_tributaries();
  a_side_ending_inside_an_edge_of_the_other_carries_the_uniform_stress();
  an_equation_of_int64_min_marks_a_fixed_dof_at_any_base();
  an_array_too_large_to_copy_is_out_of_memory_not_an_abort();
  a_non_finite_host_value_is_refused_by_gather_and_scatter_add();
  host_messages_name_the_hosts_nodes_and_sides();
  a_host_node_below_the_index_base_is_refused();
  an_equation_no_host_vector_can_hold_is_refused_at_declaration();
  a_contact_message_size_is_known_before_it_is_copied();
  a_step_is_reverted_across_a_newly_fixed_dof();
  a_host_pair_declared_twice_is_refused();
  a_contact_triangle_given_twice_is_refused();
  a_non_finite_displacement_is_invalid_input_not_an_overflow();
  scatter_add_refuses_an_overflow_leaving_the_host_vector_unchanged();
  the_contact_length_with_nothing_active_is_plus_zero();
  a_non_matching_host_pair_is_accepted_at_any_length_scale();
  loading_a_fifo_is_an_io_error_not_a_hang();
  a_gmsh_file_named_in_latin_1_is_loaded();
  an_empty_gmsh_path_is_named_as_such();
  a_corrupt_gmsh_file_gets_a_short_printable_message();
  gmsh_messages_name_the_files_node_and_element_tags();
  an_msh_2_2_file_is_unsupported_content_saying_how_to_convert_it();
  a_gmsh_element_error_names_its_physical_group();
  a_pressure_on_a_gmsh_curves_second_group_acts();
  a_pressure_on_a_gmsh_curves_first_group_still_acts();
  fixing_a_gmsh_group_of_every_curve_fixes_the_whole_boundary();
  a_gmsh_physical_point_group_is_named_in_a_warning();
  a_rigid_punchs_nominal_modulus_does_not_set_the_penalty();
  a_body_held_sideways_by_friction_alone_is_pressed_and_sheared_in_one_solve();
  a_frictional_step_on_new_loads_repeats_bit_for_bit_after_a_revert();
  a_rigid_body_modelled_by_a_huge_modulus_has_its_reactions_warned_about();
  nothing_to_solve_is_said_in_words();
  a_warning_of_any_length_is_read_whole_by_its_size();
  a_gmsh_point_in_1500_groups_gives_a_short_warning();
  a_solve_under_any_memory_limit_fails_cleanly_or_succeeds();
  a_failed_call_writes_none_of_its_outputs();
  nodal_tractions_read_the_pressure_and_no_shear_when_frictionless();
  a_tags_prescribed_values_change_together_or_not_at_all();
  axisymmetric_cylinders_pressed_together_carry_a_uniform_stress_and_the_rings_force();
  the_axisymmetric_mode_refuses_what_it_cannot_model_by_name();
  an_adaptive_solve_meets_its_tolerance_and_the_refined_mesh_reads_back();
  a_bad_boundary_circle_is_refused_and_changes_nothing();
  an_adaptive_solve_puts_new_boundary_nodes_on_the_declared_circle();
  a_boundary_circle_before_a_mesh_is_an_invalid_state();
  a_failed_3d_call_writes_nothing_and_leaves_the_model_as_it_was();

  if (gmsh_dir[0] != '\0') rmdir(gmsh_dir);

  fflush(stderr);
  fseek(capture, 0, SEEK_END);
  long printed = ftell(capture);
  dup2(saved, 2);
  CHECK(printed == 0);
  printf("boundary_test: %d passed, %d failed\n", passed, failed);
  return failed == 0 ? 0 : 1;
}
