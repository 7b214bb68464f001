/* The mortar weighting through the C ABI (tfem_set_contact_weighting):
 * the contact patch test on a non-matching interface, and every refusal
 * of what the weighting does not serve.
 *
 * Two blocks of width 1 and height 0.25 meet on y = 0, the lower one cut
 * in 7 columns, the upper one in 3 (a 3:7 interface), the upper one 10x
 * stiffer; uniform pressure p on top, the lower block on rollers. The
 * exact stress is uniform, sigma_yy = -p, and the mortar weighting must
 * transmit it to round-off: every element's stress, every slave node's
 * pressure and the nodal pressures read p. */

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

/* The call must fail with `expected` and its message contain `needle`. */
static void expect_error(tfem_model *m, tfem_status got, tfem_status expected, const char *needle,
                         int line) {
  char msg[512];
  tfem_last_error(m, msg, sizeof msg);
  if (got == expected && strstr(msg, needle) != NULL) {
    ++passed;
  } else {
    ++failed;
    printf("FAIL line %d: status %d (expected %d), message \"%s\" (expected \"%s\")\n", line,
           (int)got, (int)expected, msg, needle);
  }
}
#define EXPECT_ERROR(m, call, status, needle) expect_error(m, call, status, needle, __LINE__)

enum { NL = 7, NU = 3, ROWS = 2 };
enum { N_NODES = (NL + 1) * (ROWS + 1) + (NU + 1) * (ROWS + 1) };
enum { N_TRIS = 2 * ROWS * (NL + NU) };
enum { N_EDGES = 2 * NL + 2 * NU };
static const double P = 1e7, H = 0.25;

static double xy[2 * N_NODES];
static int tri[3 * N_TRIS], body[N_TRIS], edges[2 * N_EDGES], tags[N_EDGES];

/* A grid of `nx` x ROWS cells over [0,1] x [y0, y0 + H] from node `first`,
 * triangle `t0`: its bottom row, left to right, in `bottom`, its top row in
 * `top`. */
static int grid(int nx, double y0, int b, int first, int t0, int *bottom, int *top) {
  int n = first, t = t0;
  for (int j = 0; j <= ROWS; ++j)
    for (int i = 0; i <= nx; ++i, ++n) {
      xy[2 * n] = (double)i / nx;
      xy[2 * n + 1] = y0 + H * j / ROWS;
    }
  for (int j = 0; j < ROWS; ++j)
    for (int i = 0; i < nx; ++i) {
      int a = first + j * (nx + 1) + i, c = a + nx + 1;
      int quad[2][3] = {{a, a + 1, c + 1}, {a, c + 1, c}};
      for (int k = 0; k < 2; ++k, ++t) {
        memcpy(&tri[3 * t], quad[k], sizeof quad[k]);
        body[t] = b;
      }
    }
  for (int i = 0; i <= nx; ++i) {
    bottom[i] = first + i;
    top[i] = first + ROWS * (nx + 1) + i;
  }
  return t;
}

/* Edges counter-clockwise (body on the left): a bottom row left to right,
 * a top row right to left. */
static int add_row(int e, const int *row, int nx, int tag, int bottom) {
  for (int i = 0; i < nx; ++i, ++e) {
    edges[2 * e] = bottom ? row[i] : row[i + 1];
    edges[2 * e + 1] = bottom ? row[i + 1] : row[i];
    tags[e] = tag;
  }
  return e;
}

static tfem_model *patch(int *lower_bottom, int *upper_top) {
  int lb[NL + 1], lt[NL + 1], ub[NU + 1], ut[NU + 1];
  int t = grid(NL, -H, 1, 0, 0, lb, lt);
  grid(NU, 0.0, 2, (NL + 1) * (ROWS + 1), t, ub, ut);
  int e = add_row(0, lb, NL, 1, 1);
  e = add_row(e, lt, NL, 3, 0);
  e = add_row(e, ub, NU, 4, 1);
  add_row(e, ut, NU, 5, 0);
  memcpy(lower_bottom, lb, sizeof lb);
  memcpy(upper_top, ut, sizeof ut);
  tfem_model *m = tfem_create();
  CHECK(tfem_set_mesh(m, N_NODES, xy, N_TRIS, tri, body, 0) == TFEM_STATUS_OK);
  CHECK(tfem_set_boundary_edges(m, N_EDGES, edges, tags) == TFEM_STATUS_OK);
  CHECK(tfem_set_material(m, 1, 1e10, 0.3, TFEM_PLANE_MODE_STRAIN) == TFEM_STATUS_OK);
  CHECK(tfem_set_material(m, 2, 1e11, 0.3, TFEM_PLANE_MODE_STRAIN) == TFEM_STATUS_OK);
  CHECK(tfem_fix_edges(m, 1, TFEM_COMPONENT_Y, 0.0) == TFEM_STATUS_OK);
  /* u_x = 0 on x = 0 holds in the exact solution: one node per body. */
  CHECK(tfem_fix(m, lb[0], TFEM_COMPONENT_X, 0.0) == TFEM_STATUS_OK);
  CHECK(tfem_fix(m, ut[0], TFEM_COMPONENT_X, 0.0) == TFEM_STATUS_OK);
  CHECK(tfem_add_pressure(m, 5, P) == TFEM_STATUS_OK);
  int pair = -1;
  CHECK(tfem_add_contact_pair(m, 3, 4, &pair) == TFEM_STATUS_OK && pair == 0);
  return m;
}

static void patch_test_is_exact(void) {
  int lb[NL + 1], ut[NU + 1];
  tfem_model *m = patch(lb, ut);
  int w = -1;
  CHECK(tfem_get_contact_weighting(m, &w) == TFEM_STATUS_OK && w == TFEM_CONTACT_WEIGHTING_AUTO);
  CHECK(tfem_set_contact_weighting(m, TFEM_CONTACT_WEIGHTING_MORTAR) == TFEM_STATUS_OK);
  CHECK(tfem_get_contact_weighting(m, &w) == TFEM_STATUS_OK && w == TFEM_CONTACT_WEIGHTING_MORTAR);
  tfem_contact_report r;
  CHECK(tfem_solve_contact(m, NULL, &r) == TFEM_STATUS_OK);
  /* The coarser side (the upper block's NU + 1 nodes) is the slave. */
  CHECK(r.elements == NU + 1 && r.active == NU + 1);
  CHECK(fabs(r.contact_length - 1.0) < 1e-12);

  double s[3 * N_TRIS];
  CHECK(tfem_get_element_stresses(m, s, 3 * N_TRIS) == TFEM_STATUS_OK);
  double worst = 0.0;
  for (int t = 0; t < N_TRIS; ++t) {
    double e = fabs(s[3 * t + 1] + P) + fabs(s[3 * t]) + fabs(s[3 * t + 2]);
    if (e > worst) worst = e;
  }
  printf("mortar patch test 3:7: largest stress error %.2e of p\n", worst / P);
  CHECK(worst < 1e-10 * P);

  int node[NU + 1];
  double trib[NU + 1], gap[NU + 1], pres[NU + 1];
  CHECK(tfem_get_contact_slave_nodes(m, node, trib, gap, pres, NU + 1) == TFEM_STATUS_OK);
  double total = 0.0;
  for (int k = 0; k <= NU; ++k) {
    CHECK(fabs(pres[k] / P - 1.0) < 1e-10);
    CHECK(gap[k] < 0.0);
    CHECK(node[k] >= (NL + 1) * (ROWS + 1));
    total += trib[k];
  }
  CHECK(fabs(total - 1.0) < 1e-12);
  /* One column only (the others NULL). */
  double only[NU + 1];
  CHECK(tfem_get_contact_slave_nodes(m, NULL, NULL, NULL, only, NU + 1) == TFEM_STATUS_OK);
  CHECK(memcmp(only, pres, sizeof only) == 0);

  double np[N_NODES];
  CHECK(tfem_get_contact_nodal_pressures(m, np, N_NODES) == TFEM_STATUS_OK);
  int read = 0;
  for (int v = 0; v < N_NODES; ++v)
    if (np[v] != 0.0) {
      ++read;
      CHECK(fabs(np[v] / P - 1.0) < 1e-10);
    }
  CHECK(read == (NL + 1) + (NU + 1));

  /* The supports carry the load: sum of the y reactions = p times the width. */
  double reac[2 * N_NODES];
  CHECK(tfem_get_reactions(m, reac, 2 * N_NODES) == TFEM_STATUS_OK);
  double ry = 0.0;
  for (int i = 0; i <= NL; ++i) ry += reac[2 * lb[i] + 1];
  CHECK(fabs(ry / P - 1.0) < 1e-10);
  /* The contact forces balance over the pair. */
  double f[2 * N_NODES], fy = 0.0, fy_up = 0.0;
  CHECK(tfem_get_contact_forces(m, f, 2 * N_NODES) == TFEM_STATUS_OK);
  for (int v = 0; v < N_NODES; ++v) {
    fy += f[2 * v + 1];
    if (v >= (NL + 1) * (ROWS + 1)) fy_up += f[2 * v + 1];
  }
  CHECK(fabs(fy) < 1e-9 * P && fabs(fy_up / P - 1.0) < 1e-10);
  tfem_destroy(m);
}

static void refusals_name_what_the_weighting_does_not_serve(void) {
  int lb[NL + 1], ut[NU + 1];
  tfem_model *m = patch(lb, ut);
  EXPECT_ERROR(NULL, tfem_set_contact_weighting(NULL, 1), TFEM_STATUS_NULL_POINTER, "model");
  EXPECT_ERROR(m, tfem_set_contact_weighting(m, 3), TFEM_STATUS_INVALID_ARGUMENT, "weighting = 3");
  EXPECT_ERROR(m, tfem_set_contact_weighting(m, -1), TFEM_STATUS_INVALID_ARGUMENT,
               "weighting = -1");
  int w = -1;
  CHECK(tfem_get_contact_weighting(m, &w) == TFEM_STATUS_OK && w == TFEM_CONTACT_WEIGHTING_AUTO);
  EXPECT_ERROR(m, tfem_get_contact_weighting(m, NULL), TFEM_STATUS_NULL_POINTER, "weighting");

  /* Straight sides take the strip by default: there are no slave nodes. */
  CHECK(tfem_solve_contact(m, NULL, NULL) == TFEM_STATUS_OK);
  double pres[NU + 1];
  EXPECT_ERROR(m, tfem_get_contact_slave_nodes(m, NULL, NULL, NULL, pres, NU + 1),
               TFEM_STATUS_INVALID_STATE, "strip weighting");

  CHECK(tfem_set_contact_weighting(m, TFEM_CONTACT_WEIGHTING_MORTAR) == TFEM_STATUS_OK);
  /* The change discarded the strip's results. */
  double cp[64];
  EXPECT_ERROR(m, tfem_get_contact_pressure(m, cp, 64), TFEM_STATUS_INVALID_STATE, "no results");
  CHECK(tfem_solve_contact(m, NULL, NULL) == TFEM_STATUS_OK);
  EXPECT_ERROR(m, tfem_get_contact_pressure(m, cp, 64), TFEM_STATUS_INVALID_STATE,
               "mortar weighting");
  int act[64];
  EXPECT_ERROR(m, tfem_get_contact_active(m, act, 64), TFEM_STATUS_INVALID_STATE,
               "per slave node");
  EXPECT_ERROR(m, tfem_get_contact_slave_nodes(m, NULL, NULL, NULL, pres, NU),
               TFEM_STATUS_BUFFER_TOO_SMALL, "length = 3");
  /* The refused calls left the results alone. */
  CHECK(tfem_get_contact_slave_nodes(m, NULL, NULL, NULL, pres, NU + 1) == TFEM_STATUS_OK);
  CHECK(fabs(pres[0] / P - 1.0) < 1e-10);

  /* Load steps: the patch is linear, so a step of factor t carries t p;
   * the second step reuses the first one's factor. */
  tfem_contact_report rep;
  CHECK(tfem_step(m, 0.5, NULL, &rep) == TFEM_STATUS_OK);
  CHECK(rep.info.factorizations == 1);
  CHECK(tfem_get_contact_slave_nodes(m, NULL, NULL, NULL, pres, NU + 1) == TFEM_STATUS_OK);
  for (int i = 0; i <= NU; ++i) CHECK(fabs(pres[i] / (0.5 * P) - 1.0) < 1e-10);
  CHECK(tfem_step(m, 1.0, NULL, &rep) == TFEM_STATUS_OK);
  CHECK(rep.info.factorizations == 0);
  CHECK(tfem_get_contact_slave_nodes(m, NULL, NULL, NULL, pres, NU + 1) == TFEM_STATUS_OK);
  for (int i = 0; i <= NU; ++i) CHECK(fabs(pres[i] / P - 1.0) < 1e-10);
  /* Its contact state, as the strip's: the slave nodes' set and the
   * interface factor. */
  size_t state_size = 0;
  CHECK(tfem_get_contact_state_size(m, &state_size) == TFEM_STATUS_OK);
  CHECK(state_size > 2 * (size_t)(NU + 1));
  CHECK(tfem_revert_step(m) == TFEM_STATUS_OK);
  CHECK(tfem_get_contact_slave_nodes(m, NULL, NULL, NULL, pres, NU + 1) == TFEM_STATUS_OK);
  CHECK(fabs(pres[0] / (0.5 * P) - 1.0) < 1e-10);
  /* The half step's field, never read before the revert, is recovered
   * now: half the full solve's. */
  static double u_half[2 * N_NODES], u_full[2 * N_NODES];
  CHECK(tfem_get_displacements(m, u_half, 2 * N_NODES) == TFEM_STATUS_OK);
  CHECK(tfem_solve_contact(m, NULL, NULL) == TFEM_STATUS_OK);
  CHECK(tfem_get_displacements(m, u_full, 2 * N_NODES) == TFEM_STATUS_OK);
  double u_scale = 0.0, u_diff = 0.0;
  for (int i = 0; i < 2 * N_NODES; ++i) {
    u_scale = fmax(u_scale, fabs(u_full[i]));
    u_diff = fmax(u_diff, fabs(2.0 * u_half[i] - u_full[i]));
  }
  CHECK(u_scale > 0.0 && u_diff <= 1e-10 * u_scale);

  tfem_contact_options o;
  CHECK(tfem_contact_options_default(&o) == TFEM_STATUS_OK);
  o.law = TFEM_CONTACT_LAW_STICK;
  EXPECT_ERROR(m, tfem_solve_contact(m, &o, NULL), TFEM_STATUS_INVALID_ARGUMENT, "stick law");
  CHECK(tfem_get_contact_slave_nodes(m, NULL, NULL, NULL, pres, NU + 1) == TFEM_STATUS_OK);
  /* Friction is refused where it is set, naming the pair, and the model
   * keeps its results and its frictionless pair. */
  EXPECT_ERROR(m, tfem_set_friction(m, 0, 0.3), TFEM_STATUS_INVALID_ARGUMENT, "contact pair 0");
  CHECK(tfem_get_contact_slave_nodes(m, NULL, NULL, NULL, pres, NU + 1) == TFEM_STATUS_OK);
  CHECK(tfem_solve_contact(m, NULL, NULL) == TFEM_STATUS_OK);
  tfem_destroy(m);
}

/* The mortar weighting forced on a model whose pair has friction is
 * refused by tfem_set_contact_weighting, naming the pair; the model keeps
 * its weighting and solves as before. */
static void the_mortar_weighting_refuses_a_frictional_pair_when_it_is_set(void) {
  int lb[NL + 1], ut[NU + 1];
  tfem_model *m = patch(lb, ut);
  CHECK(tfem_set_friction(m, 0, 0.3) == TFEM_STATUS_OK);
  CHECK(tfem_solve_contact(m, NULL, NULL) == TFEM_STATUS_OK);
  EXPECT_ERROR(m, tfem_set_contact_weighting(m, TFEM_CONTACT_WEIGHTING_MORTAR),
               TFEM_STATUS_INVALID_ARGUMENT, "contact pair 0 has friction");
  int w = -1;
  CHECK(tfem_get_contact_weighting(m, &w) == TFEM_STATUS_OK && w == TFEM_CONTACT_WEIGHTING_AUTO);
  /* The refused call kept the results. */
  double cp[64];
  CHECK(tfem_get_contact_pressure(m, cp, 64) == TFEM_STATUS_OK);
  CHECK(tfem_set_friction(m, 0, 0.0) == TFEM_STATUS_OK);
  CHECK(tfem_set_contact_weighting(m, TFEM_CONTACT_WEIGHTING_MORTAR) == TFEM_STATUS_OK);
  tfem_destroy(m);
}

/* Found by the API fuzzer: the seed's straight blocks, the interface cut
 * at x = 1/2 into pairs (2, 3) and (5, 6) under the mortar weighting (one
 * interface: one weighted gap at the shared slave node). Pair 0 read the
 * pressure at nodes on pair 1's sides only, and pair 1 read 0 at the
 * shared slave node ending its own side. Each pair reads the uniform
 * pressure at every node of its two sides and nothing elsewhere. Lower
 * block [0,1]x[-0.25,0], 5 nodes a row (nodes 0-9); upper [0,1]x[0,0.25],
 * 3 a row (10-15, the slave side). */
static void each_pair_of_a_cut_mortar_interface_reads_its_own_sides(void) {
  double cx[2 * 16];
  int n = 0;
  for (int j = 0; j < 2; ++j)
    for (int i = 0; i < 5; ++i, ++n) cx[2 * n] = 0.25 * i, cx[2 * n + 1] = -0.25 + 0.25 * j;
  for (int j = 0; j < 2; ++j)
    for (int i = 0; i < 3; ++i, ++n) cx[2 * n] = 0.5 * i, cx[2 * n + 1] = 0.25 * j;
  int ct[3 * 12], cb[12], t = 0;
  for (int i = 0; i < 4; ++i) {
    int a = i, b = i + 1, c = i + 6, d = i + 5;
    ct[3 * t] = a, ct[3 * t + 1] = b, ct[3 * t + 2] = c, cb[t++] = 1;
    ct[3 * t] = a, ct[3 * t + 1] = c, ct[3 * t + 2] = d, cb[t++] = 1;
  }
  for (int i = 0; i < 2; ++i) {
    int a = 10 + i, b = 11 + i, c = 14 + i, d = 13 + i;
    ct[3 * t] = a, ct[3 * t + 1] = b, ct[3 * t + 2] = c, cb[t++] = 2;
    ct[3 * t] = a, ct[3 * t + 1] = c, ct[3 * t + 2] = d, cb[t++] = 2;
  }
  int ce[] = {0, 1, 1, 2, 2, 3, 3, 4, 6, 5, 7, 6, 8, 7, 9, 8, 10, 11, 11, 12, 14, 13, 15, 14};
  int cg[] = {1, 1, 1, 1, 2, 2, 5, 5, 3, 6, 4, 4};
  tfem_model *m = tfem_create();
  CHECK(tfem_set_mesh(m, 16, cx, 12, ct, cb, 0) == TFEM_STATUS_OK);
  CHECK(tfem_set_boundary_edges(m, 12, ce, cg) == TFEM_STATUS_OK);
  CHECK(tfem_set_material(m, 1, 1e10, 0.3, TFEM_PLANE_MODE_STRAIN) == TFEM_STATUS_OK);
  CHECK(tfem_set_material(m, 2, 1e11, 0.3, TFEM_PLANE_MODE_STRAIN) == TFEM_STATUS_OK);
  CHECK(tfem_fix_edges(m, 1, TFEM_COMPONENT_Y, 0.0) == TFEM_STATUS_OK);
  CHECK(tfem_fix(m, 2, TFEM_COMPONENT_X, 0.0) == TFEM_STATUS_OK);
  CHECK(tfem_fix(m, 14, TFEM_COMPONENT_X, 0.0) == TFEM_STATUS_OK);
  CHECK(tfem_add_pressure(m, 4, P) == TFEM_STATUS_OK);
  CHECK(tfem_set_contact_weighting(m, TFEM_CONTACT_WEIGHTING_MORTAR) == TFEM_STATUS_OK);
  CHECK(tfem_add_contact_pair(m, 2, 3, NULL) == TFEM_STATUS_OK);
  CHECK(tfem_add_contact_pair(m, 5, 6, NULL) == TFEM_STATUS_OK);
  CHECK(tfem_solve_contact(m, NULL, NULL) == TFEM_STATUS_OK);
  double p[2][16];
  CHECK(tfem_get_contact_pair_nodal_pressures(m, 0, p[0], 16) == TFEM_STATUS_OK);
  CHECK(tfem_get_contact_pair_nodal_pressures(m, 1, p[1], 16) == TFEM_STATUS_OK);
  /* The interface nodes: lower 5..9, upper 10..12. */
  int ok = 1;
  for (int v = 5; v <= 12; ++v) {
    double x = cx[2 * v];
    for (int k = 0; k < 2; ++k) {
      int on_side = k == 0 ? x <= 0.5 : x >= 0.5;
      ok &= on_side ? fabs(p[k][v] - P) <= 1e-9 * P : p[k][v] == 0.0;
    }
  }
  CHECK(ok);
  tfem_destroy(m);
}

int main(void) {
  patch_test_is_exact();
  each_pair_of_a_cut_mortar_interface_reads_its_own_sides();
  refusals_name_what_the_weighting_does_not_serve();
  the_mortar_weighting_refuses_a_frictional_pair_when_it_is_set();
  printf("mortar_test: %d passed, %d failed\n", passed, failed);
  return failed == 0 ? 0 : 1;
}
