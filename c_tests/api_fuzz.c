/* api_fuzz: a seeded random API-sequence tester of every entry point of the
 * tfem C ABI (include/tfem.h).
 *
 *   api_fuzz [--seed S] [--cases N] [--threads T] [--long] [--seconds S]
 *   api_fuzz --seed S --replay-case K [--minimize] [--class NAME]
 *
 * Each case is a sequence of calls generated from (seed, case number) alone:
 * either a valid scene built here (a unit square clamped and pulled, the
 * seed's two blocks in contact, a clockwise mesh, a user-made contact mesh,
 * a Gmsh file, the literal-test cycle, load steps, a host's contact
 * context, friction, automatic pairs, prescribed values moved, the mortar
 * weighting, axisymmetric bodies, the adaptive solve, a quarter ring with
 * its arcs' circles declared; boundary
 * edges set at once or one group at a time, threads set anywhere)
 * mutated (wrong indices, counts,
 * NULLs, short buffers, NaN/Inf/denormal/huge values, wrong enums, index
 * base, calls inserted, deleted, duplicated, reordered, a group of edges
 * added twice or late, threads set to 1/2/0/negative around the solves),
 * or a fully random sequence of any entry points. A share of the cases
 * (--solid-share, 8%) are 3D cases: the 3D model (tfem_solid_*) and its
 * host contact context (tfem_solid_contact_*) in scenes (a cube pulled,
 * the stacked cubes pressed into contact, across a gap, load steps on
 * them, a 3D host, a tetrahedral Gmsh file) mutated or pristine, or in
 * random sequences, with handles of another kind or destroyed ones given
 * to 3D and 2D functions alike. Every call is checked against the
 * header's promises:
 *   - output buffers are allocated with canaries before and after; nothing
 *     may be written beyond the declared length, nor at all by a failed
 *     call (except the documented truncation of messages);
 *   - every output of an OK call is finite;
 *   - every failed call leaves a non-empty, bounded (<= 512 bytes) message
 *     in the model's slot or the thread's slot, and a successful one an
 *     empty message;
 *   - the library writes nothing on stderr (fd 2 is a file, measured
 *     around each call);
 *   - no crash, abort or hang (cases run in batches in forked children;
 *     a batch that dies is bisected down to the case);
 *   - bit-identical replay: the case is run again on a fresh model without
 *     the calls that failed, and every output of every OK call must be
 *     identical (a failed call must leave the model as it was; the
 *     tfem_set_threads calls are replayed too, so like is compared with
 *     like: results may differ in round-off between thread counts only);
 *   - semantic oracles, against a shadow model of what the case declared:
 *     exact solutions of the pristine scenes, global equilibrium of the
 *     reactions, boundary edges that leave a load or a contact pair without
 *     edges or give an edge a tag it has (must be refused), conflicting
 *     prescribed values (must be refused), results that vanish or change
 *     without a solve or a change of the problem, contact forces summing to
 *     zero per pair and balancing loads and reactions per body, the
 *     smallest contact gap against the report's penetration, the contact
 *     mesh before a solve against the contact elements after it, apexes,
 *     pair indices and bodies, the external work against sum f.u, the
 *     thread count set, tfem_set_friction / tfem_set_prescribed /
 *     tfem_add_contact_pairs_auto accepted exactly when valid (first and
 *     count against the pairs then known), Coulomb's law per contact
 *     element from the friction getters, and twin models (mu = 0 never
 *     set, the pair declared instead of found, DOFs fixed at the values
 *     tfem_set_prescribed gave them, a load step's contact state restored
 *     in a fresh model) giving the same results; load steps repeated
 *     after a revert or a restored state bit for bit, under either
 *     weighting; axisymmetric bodies (a body across the axis, a mix with
 *     plane ones or the mortar weighting refused, no solve OK with a node
 *     on the axis whose u_r is not fixed to 0, the ring's closed form, the
 *     ring element symmetric and free in an axial translation), the
 *     out-of-plane stresses against the strains, the adaptive solve
 *     (bad arguments refused, its report against tfem_get_adapt_cycles,
 *     its limits, the tolerance, the warning of a limit, the mesh read
 *     back), tfem_set_boundary_circle accepted or refused as the shadow's
 *     mesh says (naming the node off the circle) and the nodes an adaptive
 *     solve adds on a declared circle lying on it; the 3D model's and
 *     context's arguments accepted or refused as the header says, their
 *     results kept or gone, the mesh and faces read back, contact forces
 *     summing to zero, pressures only on the pairs' faces, steps reverted
 *     and repeated bit for bit and proportional to the loads, the closed
 *     forms of the pristine 3D scenes, the context's pattern, values,
 *     gather, scatter_add and flags against its own element outputs, and
 *     handles of another kind or destroyed refused (INVALID_ARGUMENT, the
 *     message saying so) and destroyed as a no-op. A summary line counts
 *     the oracle checks made.
 * --replay-case K reruns one case verbosely and prints it as a C program
 * (a reproducer a developer can paste); --minimize first shrinks it to the
 * fewest calls that still show the violation.
 *
 * Plain C11 + POSIX (fork, pthreads); compiles with -Wall -Wextra -Werror
 * and with -fsanitize=address,undefined. See c_tests/README.md. */

#define _GNU_SOURCE
#include <dirent.h>
#include <errno.h>
#include <fcntl.h>
#include <float.h>
#include <inttypes.h>
#include <limits.h>
#include <math.h>
#include <pthread.h>
#include <signal.h>
#include <stdarg.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/mman.h>
#include <sys/stat.h>
#include <sys/time.h>
#include <sys/types.h>
#include <sys/wait.h>
#include <time.h>
#include <unistd.h>

#include "tfem.h"

/* Sanitizer settings: an error ends the process (the batch is then bisected
 * to the case), leaks are not checked in the forked children. */
const char *__asan_default_options(void);
const char *__asan_default_options(void) {
  return "abort_on_error=1:detect_leaks=0:allocator_may_return_null=0";
}
const char *__ubsan_default_options(void);
const char *__ubsan_default_options(void) { return "halt_on_error=1:abort_on_error=1:print_stacktrace=1"; }

/* ------------------------------------------------------------------------ */
/* Violation classes                                                         */
/* ------------------------------------------------------------------------ */

enum {
  V_CRASH,          /* killed by a signal other than SIGABRT */
  V_ABORT,          /* SIGABRT (Rust abort, allocation failure, sanitizer) */
  V_HANG,           /* the case did not finish in time */
  V_NAN_OK,         /* a NaN or Inf output with TFEM_STATUS_OK */
  V_CANARY,         /* a write before or beyond an output buffer */
  V_WRITE_ON_FAIL,  /* an output written by a failed call */
  V_STATE,          /* replay without the failed calls differs */
  V_NONDET,         /* replay differs although no call failed */
  V_STDERR,         /* the library wrote on stderr */
  V_LONG_MSG,       /* a message longer than MAX_MSG bytes */
  V_EMPTY_MSG,      /* a failed call without a message */
  V_INTERNAL,       /* TFEM_STATUS_INTERNAL (a caught panic) */
  V_BAD_STATUS,     /* a status outside the enum */
  V_SLOT,           /* thread error slot not as documented */
  V_LASTERR,        /* tfem_last_error / _length inconsistent */
  V_ORACLE,         /* a pristine scene's exact solution is not met */
  V_DROPPED_LOAD,   /* solve OK while a load's tag no longer names an edge */
  V_EQUILIBRIUM,    /* reactions do not balance the applied loads */
  V_DOUBLE_FIX,     /* a DOF prescribed twice with different values: OK */
  V_RESULTS_LOST,   /* results vanished without a change of the problem */
  V_MATRIX_DROPPED, /* a failed solve dropped the matrix, kept the results */
  V_DOUBLE_EDGE,    /* an edge given a tag it already has: OK */
  V_RESULTS_CHANGED,/* displacements or matrix changed without a solve or a change */
  V_CONTACT,        /* contact forces, gaps, mesh, apexes, pairs: oracles */
  V_WORK,           /* external work differs from sum f.u */
  V_THREADS,        /* tfem_set_threads / tfem_get_threads not as documented */
  V_NULL_ARG,       /* NULL pointer handling not as documented */
  V_OTHER,          /* other contract checks (sizes, structure, sanity) */
  V_STEP,           /* a load step repeated (revert, restored state) differs; a step scene's status */
  V_HOST,           /* contact context: pattern, gather, scatter, flags, values */
  V_FRICTION,       /* tfem_set_friction refusals, Coulomb's law of the friction getters */
  V_PRESCRIBED,     /* tfem_set_prescribed refusals and acceptances */
  V_AUTO_PAIRS,     /* tfem_add_contact_pairs_auto: first, count, refusals, pairs found */
  V_TWIN,           /* a twin model (the same problem declared another way) differs */
  V_WEIGHTING,      /* the contact weighting: set/get, the families, slave nodes, what the mortar refuses */
  V_NEG_ZERO,       /* a result output -0.0 (the library normalises its results to +0.0) */
  V_ADAPT,          /* tfem_solve_adaptive / tfem_get_adapt_cycles not as documented */
  V_AXI,            /* axisymmetric bodies: refusals, the ring's exact solution, out-of-plane stresses */
  V_CIRCLE,         /* tfem_set_boundary_circle accepted or refused otherwise, new nodes off a declared circle */
  V_SOLID,          /* the 3D model (tfem_solid_*): refusals, results kept or gone, read-back, contact, steps, exact solutions */
  V_SOLID_HOST,     /* the 3D contact context (tfem_solid_contact_*): refusals, pattern, gather, scatter_add, flags */
  V_HANDLE,         /* a handle of another kind or destroyed: accepted, refused otherwise, or destroyed by a no-op */
  NV
};

static const char *const V_NAME[NV] = {
    "crash",          "abort",         "hang",          "nan_inf_ok",     "canary",
    "write_on_fail",  "state_change",  "nondeterminism", "stderr",        "long_message",
    "empty_message",  "internal",      "bad_status",    "thread_slot",    "last_error_api",
    "oracle",         "dropped_load",  "equilibrium",   "double_fix",     "results_lost",
    "matrix_dropped", "double_edge",   "results_changed", "contact",      "external_work",
    "threads",        "null_pointer",  "other",          "step_repeat",  "host_contact",
    "friction",       "prescribed",    "auto_pairs",     "twin",          "weighting",
    "negative_zero",  "adapt",         "axisymmetric",  "circle",        "solid",
    "solid_host",     "handle",
};

static const char *const V_DESC[NV] = {
    "process killed by a signal",
    "process aborted (SIGABRT)",
    "case did not finish within the time limit",
    "NaN or Inf returned with TFEM_STATUS_OK",
    "write before or beyond an output buffer",
    "output written by a call that failed",
    "replay without the failed calls differs (a failed call changed the model)",
    "replay differs although no call failed (nondeterminism)",
    "library wrote on stderr",
    "error message longer than 512 bytes",
    "failed call without a message",
    "TFEM_STATUS_INTERNAL (caught panic)",
    "status outside the tfem_status enum",
    "thread error slot (tfem_last_error(NULL)) not as documented",
    "tfem_last_error / tfem_last_error_length inconsistent",
    "pristine scene does not meet its exact solution",
    "solve OK although a load's tag no longer names any edge (load silently dropped)",
    "reactions do not balance the applied loads",
    "a DOF prescribed twice with different values is accepted silently",
    "results vanished without a change of the problem",
    "a failed solve dropped the system matrix but kept the results",
    "an edge given again with a tag it already has is accepted (its loads would count twice)",
    "displacements or system matrix changed without a successful solve or a change of the problem",
    "contact oracle: pair or body balance of the contact forces, gaps vs penetration, mesh, apexes, pairs",
    "tfem_get_external_work differs from the sum of f.u over the loads known here",
    "tfem_set_threads / tfem_get_threads not as documented",
    "NULL pointer: OK with a required one, or refused where the header allows NULL",
    "other contract check",
    "a load step repeated after tfem_revert_step or tfem_set_contact_state differs from the original, or a load-step call not as expected",
    "contact context: pattern, gather, scatter_add, active flags, pressures or values inconsistent",
    "tfem_set_friction not as documented, or the friction getters break Coulomb's law",
    "tfem_set_prescribed accepts what it must refuse, or refuses a prescribed DOF",
    "tfem_add_contact_pairs_auto: first/count inconsistent with the pairs, a refusal missed, or the pairs expected not found",
    "a twin model (mu = 0 never set, the pair declared instead of found, a re-fix instead of tfem_set_prescribed) differs",
    "contact weighting: tfem_set/get_contact_weighting, the outputs of each family (per element of B, per slave node), "
    "tfem_get_contact_slave_nodes or a refusal not as documented",
    "a result of an OK call is -0.0 (the library's results carry +0.0: displacements, strains, stresses, reactions, "
    "external work, contact pressures, shear, dissipation, forces, gaps, slave nodes, the report's length and penetration)",
    "tfem_solve_adaptive / tfem_get_adapt_cycles: a bad argument accepted or refused otherwise than INVALID_ARGUMENT, "
    "the report against the cycles, the limits, the tolerance, the mesh read back or the warning",
    "axisymmetric bodies: one crossing the axis, mixed with plane ones or under the mortar weighting accepted, a solve OK "
    "with a node on the axis whose u_r is not fixed to 0, the ring's exact solution, the out-of-plane stresses, the "
    "ring element",
    "tfem_set_boundary_circle: accepted or refused otherwise than the header says (no mesh, a circle ill defined, a "
    "tag of no edge, a node off the circle, named), or a node an adaptive solve added on a declared circle off it",
    "the 3D model (tfem_solid_*): an argument accepted or refused otherwise than the header says, results gone or "
    "changed without a change of the problem (or returned after one), the mesh read back otherwise than given, "
    "contact forces that do not sum to zero, a pressure off the pairs' faces, a step repeated or reverted otherwise, "
    "a pristine scene's exact solution not met",
    "the 3D contact context (tfem_solid_contact_*): a side, pair or call accepted or refused otherwise than the header "
    "says, the pattern against the element equations, the values against the element blocks, gather, scatter_add, "
    "the active flags, the area",
    "a handle of another kind (a 2D model or context given to a 3D function, or the other way round) or a destroyed "
    "one: accepted, refused otherwise than INVALID_ARGUMENT (its message in the thread's slot; the *_last_error "
    "functions' in their buffer), or a *_destroy of it that was not a no-op",
};

/* The families of the contact pairs (what a pair is weighted by: the
 * elements of B, the mortar weighting's weighted gaps; not known here),
 * as bits (sh_families). */
enum { FAM_STRIP = 1, FAM_MORTAR = 2, FAM_UNKNOWN = 4 };

/* Oracles checked (not vacuous): counted when they could conclude. */
enum {
  O_PAIR_SUM,      /* contact forces of a pair sum to zero */
  O_BODY_BALANCE,  /* contact forces + loads + reactions on a body */
  O_GAP_PEN,       /* smallest gap = -max_penetration */
  O_WORK,          /* external work = sum f.u */
  O_MESH_EQ,       /* contact mesh before = contact elements after */
  O_APEX,          /* apexes are element nodes */
  O_THREADS,       /* tfem_get_threads = the n set */
  O_DISP_KEPT,     /* displacements and system matrix bit-identical while kept */
  O_EDGES_REFUSED, /* boundary edges refused as the header requires */
  O_FIX_REFUSED,   /* a different value for a prescribed DOF refused */
  O_STEP_REPEAT,   /* a step repeated bit for bit (revert, restored state) */
  O_HOST_PATTERN,  /* pattern = element equations; evaluate values = blocks */
  O_HOST_GATHER,   /* gather / scatter_add exact against the element equations */
  O_HOST_ACTIVE,   /* set_active then get_active; pressures zero where inactive */
  O_COULOMB,       /* Coulomb's law per contact element (shear, state, dissipation) */
  O_FRICTION_ARGS, /* tfem_set_friction accepted or refused as the shadow expects */
  O_PRESCRIBED,    /* tfem_set_prescribed accepted or refused as the shadow expects */
  O_AUTO_PAIRS,    /* first/count of tfem_add_contact_pairs_auto against the pairs */
  O_TWIN,          /* results equal to a twin model's */
  O_PAIR_PRESSURE, /* one pair's nodal pressures against all pairs' */
  O_VTU,           /* a .vtu written: the grid's points and cells, or refused for an unwritable path */
  O_WARNING_SIZE,  /* tfem_get_warning_size against tfem_get_warning and tfem_warning_count */
  O_WEIGHTING,     /* set/get weighting outcomes, and what the mortar weighting refuses */
  O_SLAVE,         /* a mortar solve's slave nodes against its report */
  O_RESTART,       /* a load step's contact state restored in a fresh model: the same step */
  O_ADAPT,         /* an adaptive solve's report against its cycles, limits, mesh and warning */
  O_OUT_OF_PLANE,  /* out-of-plane stresses against the strains and the materials */
  O_AXI,           /* axisymmetric refusals (axis, crossing, mixing, mortar) and the ring element */
  O_CIRCLE,        /* a boundary circle accepted or refused as the shadow expects; refined nodes on it */
  O_SOLID_ARGS,    /* a 3D call accepted or refused as the shadow expects */
  O_SOLID_KEPT,    /* 3D results kept bit for bit, gone after a change, kept by a failed call */
  O_SOLID_MESH,    /* the 3D mesh, faces and sizes read back as given */
  O_SOLID_CONTACT, /* 3D contact forces summing to zero, pressures on the pairs' faces, flags, areas */
  O_SOLID_STEP,    /* 3D steps: reverted, repeated bit for bit, proportional to the loads */
  O_SOLID_EXACT,   /* a pristine 3D scene's closed form */
  O_SOLID_HOST,    /* the 3D context: sides, pairs, pattern, values, gather, scatter_add, flags */
  O_HANDLE,        /* a handle of another kind or destroyed refused, its message, a destroy of it a no-op */
  NO
};
static const char *const O_NAME[NO] = {"pair_sum", "body_balance", "gap_penetration", "work", "mesh_eq",
                                       "apex", "threads", "results_kept", "edges_refused", "fix_refused",
                                       "step_repeat", "host_pattern", "host_gather", "host_active",
                                       "coulomb", "friction_args", "prescribed", "auto_pairs", "twin",
                                       "pair_pressure", "vtu_file", "warning_size", "weighting",
                                       "slave_nodes", "restart", "adapt", "out_of_plane",
                                       "axisymmetric", "circle", "solid_args", "solid_kept", "solid_mesh",
                                       "solid_contact", "solid_step", "solid_exact", "solid_host", "handles"};

/* A library defect this tester found (c_tests/README.md, "The 3 entry
 * points of friction, prescribed values and automatic pairs"): with
 * friction (mu > 0 on a pair), a DOF prescribed at a node of a contact
 * element leaves the contact forces + loads + reactions of that node's
 * body unbalanced (the x sum of the upper block: -1.3e5 of 1.2e7 with
 * four cells a side, mu = 0.3). The
 * body balance of such results is skipped so that CI stays green; build
 * with -DAPI_FUZZ_FRICTION_REACTIONS=1 to check it (it then fails). */
/* Fixed (c_tests/README.md): checked unless built with -DAPI_FUZZ_FRICTION_REACTIONS=0. */
#ifndef API_FUZZ_FRICTION_REACTIONS
#define API_FUZZ_FRICTION_REACTIONS 1
#endif

/* Another (same README section): after frictional load steps in which
 * elements slip, tfem_set_contact_state loses the last step's displacements
 * when they had not been asked for before it (INVALID_STATE "the load
 * step's factorisation is gone"); frictionless, or asked for first, they
 * stay. The results are taken as not known here after such a call unless
 * built with -DAPI_FUZZ_FRICTION_STATE_RESULTS=1 (then results_lost). */
/* Fixed (c_tests/README.md): checked unless built with -DAPI_FUZZ_FRICTION_STATE_RESULTS=0. */
#ifndef API_FUZZ_FRICTION_STATE_RESULTS
#define API_FUZZ_FRICTION_STATE_RESULTS 1
#endif

/* A third (same README section), a panic across the C ABI: after a contact
 * solve in which elements slip, a second tfem_solve_contact that does not
 * settle within max_iterations (1 to 5 on two 4-cell blocks, mu = 0.05)
 * returns TFEM_STATUS_INTERNAL "index out of bounds: the len is 8 but the
 * index is 8" instead of NOT_CONVERGED. Not counted (with friction set,
 * for that message) unless built with -DAPI_FUZZ_FRICTION_PANIC=1. */
/* Fixed (c_tests/README.md): checked unless built with -DAPI_FUZZ_FRICTION_PANIC=0. */
#ifndef API_FUZZ_FRICTION_PANIC
#define API_FUZZ_FRICTION_PANIC 1
#endif

/* A fourth (same README section), small: the dissipation of a slipping
 * element can come out below 0 by round-off (-2.4e-17 J/m, the largest of
 * the step 1.4e-14: seed 16 case 14077 of the commit that added it), where
 * the header promises >= 0. Accepted down to -1e-12 mu max|p| max|u| (the
 * round-off of tau times a slip) unless built with
 * -DAPI_FUZZ_DISSIPATION_SIGN=1 (then any negative value is a finding, as
 * in c_tests/boundary_test.c). */
/* Fixed (c_tests/README.md): checked unless built with -DAPI_FUZZ_DISSIPATION_SIGN=0. */
#ifndef API_FUZZ_DISSIPATION_SIGN
#define API_FUZZ_DISSIPATION_SIGN 1
#endif

/* A finding (c_tests/README.md, "The 3 entry points of the mortar
 * weighting"), at round-off: an active slave node can
 * end with a positive mean gap at round-off and so a negative pressure
 * (no load: gap 4.3e-18, pressure -4.3e-6, seed 11 case 6858 of the commit
 * that added it; a displacement of 1e200 prescribed: gap 4.9e183, pressure
 * -1.96e195), where the header says "positive in compression, 0 when
 * inactive". A wrong sign is accepted when |gap| <= 1e-12 max|u| unless
 * built with -DAPI_FUZZ_MORTAR_TENSION=1. */
#ifndef API_FUZZ_MORTAR_TENSION
#define API_FUZZ_MORTAR_TENSION 0
#endif

/* A library defect this tester found (c_tests/README.md, "One contact
 * trunk, first stage"): since 56d2e1d a load step that begins a history
 * whose interface is not condensed (refactorize set in its options; also
 * an interface too large or of no free unknown) from no contact state of
 * its own (the first step, after a solve, or after steps of other
 * options) cannot be reverted: tfem_revert_step returns INVALID_ARGUMENT
 * "the contact state is of 0 contact parts (of other contact
 * constraints), this step's contact constraints have 16 (frictionless)
 * ...", the model unchanged, where the header says that such a step is
 * reverted as any other (under the mortar weighting, whose steps accepted
 * refactorize before, the revert was OK). Checked (a finding) unless built
 * with -DAPI_FUZZ_REVERT_AFRESH=0, which accepts that refusal. */
#ifndef API_FUZZ_REVERT_AFRESH
#define API_FUZZ_REVERT_AFRESH 1
#endif

/* A library defect this tester found, since fixed (c_tests/README.md,
 * "The automatic weighting"; regression test in c_tests/mortar_test.c):
 * an interface cut into two pairs under the mortar weighting read, per
 * pair (tfem_get_contact_pair_nodal_pressures), the first pair's pressure
 * at master nodes on the second pair's sides only. Checked (finding:
 * contact); -DAPI_FUZZ_MORTAR_CUT_READING=0 skips the per-pair reading
 * where a solve with some pair under the mortar weighting has two pairs
 * or more. */
#ifndef API_FUZZ_MORTAR_CUT_READING
#define API_FUZZ_MORTAR_CUT_READING 1
#endif

/* Library defects this tester found (c_tests/README.md, "The 3 entry
 * points of the adaptive solve"): a tfem_solve_adaptive that fails after a
 * cycle's solve (NUMERICAL_FAILURE of an estimate that overflows,
 * SINGULAR, NOT_CONVERGED) does not leave the model as it was: the solve's
 * warnings stay (tfem_warning_count 0 -> 1: "the reactions of body ... may
 * carry as few as 0 correct digits"), the results of the solve before it
 * are gone (INVALID_STATE "no results") and, since fc3c91f, so are the
 * cycles of the adaptive solve before it (INVALID_STATE "no adaptive
 * solve"), also when the call is refused for its tolerance (0, NaN, ...:
 * INVALID_ARGUMENT, where the header says that bad arguments change
 * nothing). One its refinement refuses after a cycle's solve
 * (INVALID_ARGUMENT: the nodes put on a circle of tfem_set_boundary_circle
 * would fold a triangle; the ring scene) keeps that cycle's results where
 * there were none, or loses those of the solve before it.
 * Checked (findings: state_change, results_lost,
 * matrix_dropped, adapt, other) unless built with
 * -DAPI_FUZZ_ADAPT_FAILURE_RESTORES=0, which takes what follows such a
 * failure as not known here (no replay comparison after it, the results
 * and cycles not known). */
#ifndef API_FUZZ_ADAPT_FAILURE_RESTORES
#define API_FUZZ_ADAPT_FAILURE_RESTORES 1
#endif

/* Messages name the item and say why; what must not happen is an
 * unbounded one (a denormal printed in full, a whole history, a parser
 * dump): 512 bytes leaves room for two reasons naming two bodies. */
#define MAX_MSG 512

/* ------------------------------------------------------------------------ */
/* Random numbers (splitmix64), deterministic from (seed, case)              */
/* ------------------------------------------------------------------------ */

typedef struct {
  uint64_t s;
} rng_t;

static uint64_t mix64(uint64_t z) {
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
  return z ^ (z >> 31);
}
static uint64_t rnext(rng_t *r) {
  r->s += 0x9e3779b97f4a7c15ULL;
  return mix64(r->s);
}
static int rint_(rng_t *r, int n) { return n <= 0 ? 0 : (int)(rnext(r) % (uint64_t)n); }
static int rrange(rng_t *r, int lo, int hi) { return lo + rint_(r, hi - lo + 1); }
static double runif(rng_t *r) { return (double)(rnext(r) >> 11) * (1.0 / 9007199254740992.0); }
static int chance(rng_t *r, double p) { return runif(r) < p; }

/* ------------------------------------------------------------------------ */
/* Small helpers                                                             */
/* ------------------------------------------------------------------------ */

static void *xmalloc(size_t n) {
  void *p = malloc(n ? n : 1);
  if (!p) {
    fprintf(stdout, "api_fuzz: out of memory\n");
    exit(3);
  }
  return p;
}
static void *xcalloc(size_t n, size_t s) {
  void *p = calloc(n ? n : 1, s ? s : 1);
  if (!p) {
    fprintf(stdout, "api_fuzz: out of memory\n");
    exit(3);
  }
  return p;
}
static void *xrealloc(void *p, size_t n) {
  void *q = realloc(p, n ? n : 1);
  if (!q) {
    fprintf(stdout, "api_fuzz: out of memory\n");
    exit(3);
  }
  return q;
}
static double now_s(void) {
  struct timespec t;
  clock_gettime(CLOCK_MONOTONIC, &t);
  return (double)t.tv_sec + 1e-9 * (double)t.tv_nsec;
}


/* A double as a C expression that gives the same bits back. */
static const char *cdbl(double v, char buf[64]) {
  if (isnan(v)) {
    snprintf(buf, 64, "%s", signbit(v) ? "(-NAN)" : "NAN");
  } else if (isinf(v)) {
    snprintf(buf, 64, "%s", v < 0 ? "(-INFINITY)" : "INFINITY");
  } else if (v == 0.0 && signbit(v)) {
    snprintf(buf, 64, "(-0.0)");
  } else {
    snprintf(buf, 64, "%.17g", v);
    if (!strpbrk(buf, ".en")) strcat(buf, ".0");
  }
  return buf;
}

static const char *status_name(int s) {
  static const char *const n[] = {"OK",          "NULL_POINTER",      "INVALID_ARGUMENT",
                                  "INVALID_MESH", "INVALID_MATERIAL", "INVALID_STATE",
                                  "BUFFER_TOO_SMALL", "SINGULAR",     "NOT_CONVERGED",
                                  "DEGENERATE_ELEMENT", "INVALID_CONTACT", "NUMERICAL_FAILURE",
                                  "INTERNAL",    "OUT_OF_MEMORY",     "IO"};
  return (s >= 0 && s <= 14) ? n[s] : "?";
}

/* ------------------------------------------------------------------------ */
/* Entry points                                                              */
/* ------------------------------------------------------------------------ */

enum {
  F_VERSION,
  F_LAST_ERROR,
  F_LAST_ERROR_LENGTH,
  F_WARNING_COUNT,
  F_GET_WARNING,
  F_SET_MESH,
  F_LOAD_GMSH,
  F_SET_BOUNDARY_EDGES,
  F_SET_MATERIAL,
  F_SET_TEMPERING,
  F_SET_ORDERING,
  F_FIX,
  F_FIX_EDGES,
  F_CLEAR_CONSTRAINTS,
  F_ADD_PRESSURE,
  F_ADD_TRACTION,
  F_ADD_NODAL_FORCE,
  F_SET_BODY_FORCE,
  F_CLEAR_LOADS,
  F_SOLVE,
  F_GET_SIZES,
  F_GET_DISPLACEMENTS,
  F_GET_STRAINS,
  F_GET_STRESSES,
  F_GET_JACOBIANS,
  F_GET_REACTIONS,
  F_GET_MATRIX_SIZE,
  F_GET_MATRIX,
  F_ELEMENT_STIFFNESS,
  F_LAPLACIAN_STIFFNESS,
  F_ADD_CONTACT_PAIR,
  F_ADD_CONTACT_PAIR_WITH_MESH,
  F_CONTACT_OPTIONS_DEFAULT,
  F_SOLVE_CONTACT,
  F_GET_CONTACT_ACTIVE,
  F_GET_CONTACT_PRESSURE,
  F_GET_CONTACT_ELEMENTS,
  F_GET_CONTACT_REPORT,
  F_ADD_BOUNDARY_EDGES,
  F_GET_EXTERNAL_WORK,
  F_GET_CONTACT_FORCES,
  F_GET_CONTACT_GAPS,
  F_GET_CONTACT_NODAL_PRESSURES,
  F_GET_CONTACT_MESH_SIZE,
  F_GET_CONTACT_MESH,
  F_GET_CONTACT_ELEMENT_PAIRS,
  F_GET_CONTACT_ELEMENT_APEXES,
  F_GET_CONTACT_PAIR_BODIES,
  F_SET_THREADS,
  F_GET_THREADS,
  /* load steps */
  F_STEP,
  F_REVERT_STEP,
  F_GET_CONTACT_STATE_SIZE,
  F_GET_CONTACT_STATE,
  F_SET_CONTACT_STATE,
  /* the contact context for host codes (a second handle) */
  F_CONTACT_CREATE,
  F_CONTACT_DESTROY,
  F_CONTACT_LAST_ERROR,
  F_CONTACT_SET_OPTIONS,
  F_CONTACT_ADD_SIDE,
  F_CONTACT_ADD_PAIR,
  F_CONTACT_ADD_PAIR_WITH_MESH,
  F_CONTACT_SIZES,
  F_CONTACT_NODES,
  F_CONTACT_PATTERN,
  F_CONTACT_EVALUATE,
  F_CONTACT_GATHER,
  F_CONTACT_SCATTER_ADD,
  F_CONTACT_UPDATE,
  F_CONTACT_RESTART,
  F_CONTACT_GET_ACTIVE,
  F_CONTACT_SET_ACTIVE,
  F_CONTACT_GAPS,
  F_CONTACT_PRESSURES,
  F_CONTACT_ELEMENTS,
  F_CONTACT_ELEMENT_EQUATIONS,
  F_CONTACT_ELEMENT_BLOCKS,
  F_CONTACT_LENGTH,
  /* friction results */
  F_GET_CONTACT_SHEAR,
  F_GET_CONTACT_FRICTION_STATE,
  F_GET_CONTACT_DISSIPATION,
  /* friction, non-proportional prescribed values, automatic pairing */
  F_SET_FRICTION,
  F_SET_PRESCRIBED,
  F_ADD_CONTACT_PAIRS_AUTO,
  F_GET_CONTACT_PAIR_NODAL_PRESSURES,
  /* added 2026-11-24: the VTU writer, warning sizes, a context's message length */
  F_WRITE_VTU,
  F_GET_WARNING_SIZE,
  F_CONTACT_LAST_ERROR_LENGTH,
  /* added 2026-11-25: the mortar weighting */
  F_SET_CONTACT_WEIGHTING,
  F_GET_CONTACT_WEIGHTING,
  F_GET_CONTACT_SLAVE_NODES,
  /* added 2026-11-29: axisymmetric bodies' hoop stress, the adaptive solve */
  F_GET_OUT_OF_PLANE,
  F_SOLVE_ADAPTIVE,
  F_GET_ADAPT_CYCLES,
  /* the exact shape of a tagged boundary */
  F_SET_BOUNDARY_CIRCLE,
  /* the 3D model (tfem_solid_*), a handle of its own */
  F_S_LAST_ERROR,
  F_S_LAST_ERROR_LENGTH,
  F_S_WARNING_COUNT,
  F_S_GET_WARNING_SIZE,
  F_S_GET_WARNING,
  F_S_SET_MESH,
  F_S_LOAD_GMSH,
  F_S_SET_FACES,
  F_S_ADD_FACES,
  F_S_GET_SIZES,
  F_S_FACE_COUNT,
  F_S_MESH_NODES,
  F_S_MESH_TETS,
  F_S_GET_FACES,
  F_S_SET_MATERIAL,
  F_S_SET_TEMPERING,
  F_S_SET_ORDERING,
  F_S_FIX,
  F_S_FIX_FACES,
  F_S_CLEAR_CONSTRAINTS,
  F_S_ADD_PRESSURE,
  F_S_ADD_TRACTION,
  F_S_ADD_NODAL_FORCE,
  F_S_CLEAR_LOADS,
  F_S_ADD_PAIR,
  F_S_CLEAR_PAIRS,
  F_S_SOLVE,
  F_S_SOLVE_CONTACT,
  F_S_STEP,
  F_S_REVERT_STEP,
  F_S_SOLVE_INFO,
  F_S_ITERATIONS,
  F_S_DISPLACEMENTS,
  F_S_STRAINS,
  F_S_STRESSES,
  F_S_REACTIONS,
  F_S_WORK,
  F_S_CONTACT_TETS,
  F_S_CONTACT_ACTIVE,
  F_S_CONTACT_FORCES,
  F_S_NODAL_PRESSURES,
  F_S_AREA,
  F_S_PAIR_AREA,
  F_S_WRITE_VTU,
  F_S_DESTROY,  /* tfem_solid_destroy of the handle the call passes (the model's own: it is gone) */
  F_S_RECREATE, /* tfem_solid_destroy(sm); sm = tfem_solid_create() */
  /* the 3D contact context for host codes (tfem_solid_contact_*), a handle of its own */
  F_SC_CREATE,
  F_SC_DESTROY,
  F_SC_LAST_ERROR,
  F_SC_LAST_ERROR_LENGTH,
  F_SC_ADD_SIDE,
  F_SC_ADD_PAIR,
  F_SC_SETUP,
  F_SC_SIZES,
  F_SC_NODES,
  F_SC_TETS,
  F_SC_PATTERN,
  F_SC_ELEMENT_EQUATIONS,
  F_SC_ELEMENT_BLOCKS,
  F_SC_EVALUATE,
  F_SC_GATHER,
  F_SC_SCATTER_ADD,
  F_SC_UPDATE,
  F_SC_RESTART,
  F_SC_GET_ACTIVE,
  F_SC_SET_ACTIVE,
  F_SC_GAPS,
  F_SC_AREA,
  F_DESTROY_NULL, /* tfem_destroy(NULL) */
  F_RECREATE,     /* tfem_destroy(m); m = tfem_create() */
  F_TWIN,         /* not a call: the twin-model oracle (see oracle_twin) */
  NF
};

/* Output kinds (K_Z size_t, K_U8 the bytes of a contact state, K_AR a
 * tfem_adapt_report, K_T doubles that are timings: checked finite and >= 0,
 * never compared on the replay). */
enum { K_D, K_I, K_L, K_C, K_SI, K_RE, K_OP, K_Z, K_U8, K_AR, K_T };
static size_t ksize(int k) {
  switch (k) {
  case K_D: return sizeof(double);
  case K_I: return sizeof(int);
  case K_L: return sizeof(int64_t);
  case K_C: return 1;
  case K_Z: return sizeof(size_t);
  case K_U8: return 1;
  case K_SI: return sizeof(tfem_solve_info);
  case K_RE: return sizeof(tfem_contact_report);
  case K_AR: return sizeof(tfem_adapt_report);
  case K_T: return sizeof(double);
  default: return sizeof(tfem_contact_options);
  }
}

/* Required lengths of output buffers. */
enum { R_SCALAR, R_2NN, R_3NT, R_NT, R_NC, R_3NC, R_N1, R_NNZ, R_N, R_MSG, R_WARN, R_36, R_9, R_NN, R_CM, R_3CM,
       /* the contact state; a context's interface nodes (x1, x2), elements of B (x1, x3, x6, x36), pattern
        * entries, message, the host's equations */
       R_STATE, R_CN, R_2CN, R_CE, R_3CE, R_6CE, R_36CE, R_CP, R_CMSG, R_NEQ,
       /* slave nodes of a mortar solve (the report's elements); the cycles of the last adaptive solve */
       R_SLAVE, R_CYC,
       /* the 3D model: nodes (x3, x1), tetrahedra (x6, x4, x1), tetrahedra of B (x1, x4), faces (x3, x1),
        * message, warning; the 3D context: interface nodes (x1, x3), tetrahedra of B (x1, x4, x12, x144),
        * pattern entries, message, the host's equations */
       R_S3NN, R_SNN, R_S6NT, R_S4NT, R_SNT, R_SNC, R_S4NC, R_S3NF, R_SNF, R_SMSG, R_SWARN,
       R_SCN, R_S3CN, R_SCT, R_S4CT, R_S12CT, R_S144CT, R_SCP, R_SCMSG, R_SNEQ };

#define MAXI 8
#define MAXD 4
#define MAXIN 4
#define MAXOUT 4

typedef struct {
  const char *name;
  int model;       /* 1: the first argument is the model; 2: the contact context; 3: the 3D model; 4: the 3D
                    * contact context */
  const char *ir;  /* roles of the int arguments */
  const char *dr;  /* roles of the double arguments */
  const char *ink; /* input arrays: 'x' coords (double), 'n' node indices, 'b' bodies, 't' tags, 'o' options
                    * (may be NULL), 'r' options (required), 'h' host node numbers, 'q' host equations
                    * (int64); made when the call runs (runtime inputs, from a recipe in the int
                    * arguments): 'U' doubles, 'a' active flags, 's' contact state bytes */
  const char *outk; /* output kinds: d i l c S R O A (an adapt report) t (timings); upper-case letter = scalar
                     * pointer */
  unsigned char req[MAXOUT];
  int scalar_out;   /* outputs are single objects (pointer, no length) */
} fndesc;

/* int roles: c count, B index base, f gmsh file, n node, t tag, b body,
 *   P plane, M tempering mode, O ordering, x 0/1 flag, C component,
 *   L law, T inversion test, m max iterations, w warning index,
 *   q contact pair index, h threads, s side index, R recipe of a runtime
 *   input (see make_inputs), D its length offset, k its seed, S contact
 *   state mode, A active-flags recipe, g host-vector recipe, V the path of
 *   a .vtu (vtu_path: a file in the private directory or an unwritable
 *   path there; out of range: NULL), W contact weighting (0 strip,
 *   1 mortar, 2 automatic; wild: -1, 3, INT_MAX, INT_MIN), Z adaptive goal
 *   (0 energy, 1 compliance), Y adaptive max_cycles (1..6; wild 0, -1,
 *   INT_MIN), N adaptive max_unknowns (an int64_t: INT_MAX passes INT64_MAX,
 *   INT_MIN INT64_MIN; 200..20000; wild 0, -1, 1, 50, INT_MAX, INT_MIN), F a 3D Gmsh file (sg_path),
 *   K a 3D component (tfem_axis 0..2), Q a 3D contact pair (0-based), e a 3D context's side (in its base)
 * double roles: E young, p poisson, J jmin, K kappa, v tempering value,
 *   u displacement, f force, G contact modulus, l lambda, a load factor,
 *   y friction coefficient, d pairing tolerance, e adaptive tolerance, X a
 *   circle's centre coordinate, r its radius */
static const fndesc FN[NF] = {
    [F_VERSION] = {"tfem_version", 0, "", "", "", "", {0}, 0},
    [F_LAST_ERROR] = {"tfem_last_error", 1, "", "", "", "c", {R_MSG}, 0},
    [F_LAST_ERROR_LENGTH] = {"tfem_last_error_length", 1, "", "", "", "", {0}, 0},
    [F_WARNING_COUNT] = {"tfem_warning_count", 1, "", "", "", "i", {R_SCALAR}, 1},
    [F_GET_WARNING] = {"tfem_get_warning", 1, "w", "", "", "c", {R_WARN}, 0},
    [F_SET_MESH] = {"tfem_set_mesh", 1, "ccB", "", "xnb", "", {0}, 0},
    [F_LOAD_GMSH] = {"tfem_load_gmsh", 1, "fB", "", "", "", {0}, 0},
    [F_SET_BOUNDARY_EDGES] = {"tfem_set_boundary_edges", 1, "c", "", "nt", "", {0}, 0},
    [F_SET_MATERIAL] = {"tfem_set_material", 1, "bP", "Ep", "", "", {0}, 0},
    [F_SET_TEMPERING] = {"tfem_set_tempering", 1, "M", "v", "", "", {0}, 0},
    [F_SET_ORDERING] = {"tfem_set_ordering", 1, "Ox", "", "", "", {0}, 0},
    [F_FIX] = {"tfem_fix", 1, "nC", "u", "", "", {0}, 0},
    [F_FIX_EDGES] = {"tfem_fix_edges", 1, "tC", "u", "", "", {0}, 0},
    [F_CLEAR_CONSTRAINTS] = {"tfem_clear_constraints", 1, "", "", "", "", {0}, 0},
    [F_ADD_PRESSURE] = {"tfem_add_pressure", 1, "t", "f", "", "", {0}, 0},
    [F_ADD_TRACTION] = {"tfem_add_traction", 1, "t", "ff", "", "", {0}, 0},
    [F_ADD_NODAL_FORCE] = {"tfem_add_nodal_force", 1, "n", "ff", "", "", {0}, 0},
    [F_SET_BODY_FORCE] = {"tfem_set_body_force", 1, "b", "ff", "", "", {0}, 0},
    [F_CLEAR_LOADS] = {"tfem_clear_loads", 1, "", "", "", "", {0}, 0},
    [F_SOLVE] = {"tfem_solve", 1, "", "", "", "S", {R_SCALAR}, 1},
    [F_GET_SIZES] = {"tfem_get_sizes", 1, "", "", "", "iii", {R_SCALAR, R_SCALAR, R_SCALAR}, 1},
    [F_GET_DISPLACEMENTS] = {"tfem_get_displacements", 1, "", "", "", "d", {R_2NN}, 0},
    [F_GET_STRAINS] = {"tfem_get_element_strains", 1, "", "", "", "d", {R_3NT}, 0},
    [F_GET_STRESSES] = {"tfem_get_element_stresses", 1, "", "", "", "d", {R_3NT}, 0},
    [F_GET_JACOBIANS] = {"tfem_get_element_jacobians", 1, "", "", "", "d", {R_NT}, 0},
    [F_GET_REACTIONS] = {"tfem_get_reactions", 1, "", "", "", "d", {R_2NN}, 0},
    [F_GET_MATRIX_SIZE] = {"tfem_get_system_matrix_size", 1, "", "", "", "ll", {R_SCALAR, R_SCALAR}, 1},
    [F_GET_MATRIX] = {"tfem_get_system_matrix", 1, "", "", "", "lldl", {R_N1, R_NNZ, R_NNZ, R_N}, 0},
    [F_ELEMENT_STIFFNESS] = {"tfem_element_stiffness", 0, "P", "EpJ", "x", "d", {R_36}, 0},
    [F_LAPLACIAN_STIFFNESS] = {"tfem_laplacian_stiffness", 0, "", "KJ", "x", "d", {R_9}, 0},
    [F_ADD_CONTACT_PAIR] = {"tfem_add_contact_pair", 1, "tt", "", "", "i", {R_SCALAR}, 1},
    [F_ADD_CONTACT_PAIR_WITH_MESH] = {"tfem_add_contact_pair_with_mesh", 1, "ttc", "", "n", "ii",
                                      {R_SCALAR, R_SCALAR}, 1},
    [F_CONTACT_OPTIONS_DEFAULT] = {"tfem_contact_options_default", 0, "", "", "", "O", {R_SCALAR}, 1},
    [F_SOLVE_CONTACT] = {"tfem_solve_contact", 1, "LTmx", "Gl", "o", "R", {R_SCALAR}, 1},
    [F_GET_CONTACT_ACTIVE] = {"tfem_get_contact_active", 1, "", "", "", "i", {R_NC}, 0},
    [F_GET_CONTACT_PRESSURE] = {"tfem_get_contact_pressure", 1, "", "", "", "d", {R_NC}, 0},
    [F_GET_CONTACT_ELEMENTS] = {"tfem_get_contact_elements", 1, "", "", "", "i", {R_3NC}, 0},
    [F_GET_CONTACT_REPORT] = {"tfem_get_contact_report", 1, "", "", "", "R", {R_SCALAR}, 1},
    [F_ADD_BOUNDARY_EDGES] = {"tfem_add_boundary_edges", 1, "c", "", "nt", "", {0}, 0},
    [F_GET_EXTERNAL_WORK] = {"tfem_get_external_work", 1, "", "", "", "d", {R_SCALAR}, 1},
    [F_GET_CONTACT_FORCES] = {"tfem_get_contact_forces", 1, "", "", "", "d", {R_2NN}, 0},
    [F_GET_CONTACT_GAPS] = {"tfem_get_contact_gaps", 1, "", "", "", "d", {R_NN}, 0},
    [F_GET_CONTACT_NODAL_PRESSURES] = {"tfem_get_contact_nodal_pressures", 1, "", "", "", "d", {R_NN}, 0},
    [F_GET_CONTACT_MESH_SIZE] = {"tfem_get_contact_mesh_size", 1, "", "", "", "i", {R_SCALAR}, 1},
    [F_GET_CONTACT_MESH] = {"tfem_get_contact_mesh", 1, "", "", "", "i", {R_3CM}, 0},
    [F_GET_CONTACT_ELEMENT_PAIRS] = {"tfem_get_contact_element_pairs", 1, "", "", "", "i", {R_CM}, 0},
    [F_GET_CONTACT_ELEMENT_APEXES] = {"tfem_get_contact_element_apexes", 1, "", "", "", "i", {R_CM}, 0},
    [F_GET_CONTACT_PAIR_BODIES] = {"tfem_get_contact_pair_bodies", 1, "q", "", "", "ii", {R_SCALAR, R_SCALAR}, 1},
    [F_SET_THREADS] = {"tfem_set_threads", 1, "h", "", "", "", {0}, 0},
    [F_GET_THREADS] = {"tfem_get_threads", 1, "", "", "", "i", {R_SCALAR}, 1},
    [F_STEP] = {"tfem_step", 1, "LTmx", "Gla", "o", "R", {R_SCALAR}, 1},
    [F_REVERT_STEP] = {"tfem_revert_step", 1, "", "", "", "", {0}, 0},
    [F_GET_CONTACT_STATE_SIZE] = {"tfem_get_contact_state_size", 1, "", "", "", "z", {R_SCALAR}, 1},
    [F_GET_CONTACT_STATE] = {"tfem_get_contact_state", 1, "", "", "", "u", {R_STATE}, 0},
    [F_SET_CONTACT_STATE] = {"tfem_set_contact_state", 1, "SDk", "", "s", "", {0}, 0},
    [F_CONTACT_CREATE] = {"tfem_contact_create", 0, "B", "", "", "", {0}, 0},
    [F_CONTACT_DESTROY] = {"tfem_contact_destroy", 2, "", "", "", "", {0}, 0},
    [F_CONTACT_LAST_ERROR] = {"tfem_contact_last_error", 2, "", "", "", "c", {R_CMSG}, 0},
    [F_CONTACT_SET_OPTIONS] = {"tfem_contact_set_options", 2, "LTmx", "Gl", "r", "", {0}, 0},
    [F_CONTACT_ADD_SIDE] = {"tfem_contact_add_side", 2, "tbPcc", "Ep", "hxqh", "i", {R_SCALAR}, 1},
    [F_CONTACT_ADD_PAIR] = {"tfem_contact_add_pair", 2, "ss", "", "", "i", {R_SCALAR}, 1},
    [F_CONTACT_ADD_PAIR_WITH_MESH] = {"tfem_contact_add_pair_with_mesh", 2, "ssc", "", "h", "i", {R_SCALAR}, 1},
    [F_CONTACT_SIZES] = {"tfem_contact_sizes", 2, "", "", "", "iil", {R_SCALAR, R_SCALAR, R_SCALAR}, 1},
    [F_CONTACT_NODES] = {"tfem_contact_nodes", 2, "", "", "", "i", {R_CN}, 0},
    [F_CONTACT_PATTERN] = {"tfem_contact_pattern", 2, "", "", "", "ll", {R_CP, R_CP}, 0},
    [F_CONTACT_EVALUATE] = {"tfem_contact_evaluate", 2, "RDk", "", "U", "dd", {R_CP, R_2CN}, 0},
    [F_CONTACT_GATHER] = {"tfem_contact_gather", 2, "gDk", "", "U", "d", {R_2CN}, 0},
    [F_CONTACT_SCATTER_ADD] = {"tfem_contact_scatter_add", 2, "RDk", "", "UU", "d", {R_NEQ}, 0},
    [F_CONTACT_UPDATE] = {"tfem_contact_update", 2, "RDk", "", "U", "i", {R_SCALAR}, 1},
    [F_CONTACT_RESTART] = {"tfem_contact_restart", 2, "", "", "", "", {0}, 0},
    [F_CONTACT_GET_ACTIVE] = {"tfem_contact_get_active", 2, "", "", "", "i", {R_CE}, 0},
    [F_CONTACT_SET_ACTIVE] = {"tfem_contact_set_active", 2, "ADk", "", "a", "", {0}, 0},
    [F_CONTACT_GAPS] = {"tfem_contact_gaps", 2, "RDk", "", "U", "d", {R_CN}, 0},
    [F_CONTACT_PRESSURES] = {"tfem_contact_pressures", 2, "RDk", "", "U", "d", {R_CE}, 0},
    [F_CONTACT_ELEMENTS] = {"tfem_contact_elements", 2, "", "", "", "i", {R_3CE}, 0},
    [F_CONTACT_ELEMENT_EQUATIONS] = {"tfem_contact_element_equations", 2, "", "", "", "l", {R_6CE}, 0},
    [F_CONTACT_ELEMENT_BLOCKS] = {"tfem_contact_element_blocks", 2, "", "", "", "d", {R_36CE}, 0},
    [F_CONTACT_LENGTH] = {"tfem_contact_length", 2, "", "", "", "d", {R_SCALAR}, 1},
    [F_GET_CONTACT_SHEAR] = {"tfem_get_contact_shear", 1, "", "", "", "d", {R_NC}, 0},
    [F_GET_CONTACT_FRICTION_STATE] = {"tfem_get_contact_friction_state", 1, "", "", "", "i", {R_NC}, 0},
    [F_GET_CONTACT_DISSIPATION] = {"tfem_get_contact_dissipation", 1, "", "", "", "d", {R_NC}, 0},
    [F_SET_FRICTION] = {"tfem_set_friction", 1, "q", "y", "", "", {0}, 0},
    [F_SET_PRESCRIBED] = {"tfem_set_prescribed", 1, "nC", "u", "", "", {0}, 0},
    [F_ADD_CONTACT_PAIRS_AUTO] = {"tfem_add_contact_pairs_auto", 1, "c", "d", "t", "ii", {R_SCALAR, R_SCALAR}, 1},
    [F_GET_CONTACT_PAIR_NODAL_PRESSURES] = {"tfem_get_contact_pair_nodal_pressures", 1, "q", "", "", "d", {R_NN}, 0},
    [F_WRITE_VTU] = {"tfem_write_vtu", 1, "V", "", "", "", {0}, 0},
    [F_GET_WARNING_SIZE] = {"tfem_get_warning_size", 1, "w", "", "", "z", {R_SCALAR}, 1},
    [F_CONTACT_LAST_ERROR_LENGTH] = {"tfem_contact_last_error_length", 2, "", "", "", "", {0}, 0},
    [F_SET_CONTACT_WEIGHTING] = {"tfem_set_contact_weighting", 1, "W", "", "", "", {0}, 0},
    [F_GET_CONTACT_WEIGHTING] = {"tfem_get_contact_weighting", 1, "", "", "", "i", {R_SCALAR}, 1},
    [F_GET_CONTACT_SLAVE_NODES] = {"tfem_get_contact_slave_nodes", 1, "", "", "", "iddd",
                                   {R_SLAVE, R_SLAVE, R_SLAVE, R_SLAVE}, 0},
    [F_GET_OUT_OF_PLANE] = {"tfem_get_element_out_of_plane_stresses", 1, "", "", "", "d", {R_NT}, 0},
    /* (iv: the contact options' law, test, max_iterations, refactorize as in
     * tfem_solve_contact, then goal, max_cycles, max_unknowns; dv: E_c,
     * lambda, then the tolerance) */
    [F_SOLVE_ADAPTIVE] = {"tfem_solve_adaptive", 1, "LTmxZYN", "Gle", "o", "A", {R_SCALAR}, 1},
    [F_GET_ADAPT_CYCLES] = {"tfem_get_adapt_cycles", 1, "", "", "", "ldt", {R_CYC, R_CYC, R_CYC}, 0},
    /* (dv: the centre's x and y, the radius) */
    [F_SET_BOUNDARY_CIRCLE] = {"tfem_set_boundary_circle", 1, "t", "XXr", "", "", {0}, 0},
    /* the 3D model (iv of F_S_SOLVE_CONTACT and F_S_STEP: the options as in tfem_solve_contact) */
    [F_S_LAST_ERROR] = {"tfem_solid_last_error", 3, "", "", "", "c", {R_SMSG}, 0},
    [F_S_LAST_ERROR_LENGTH] = {"tfem_solid_last_error_length", 3, "", "", "", "", {0}, 0},
    [F_S_WARNING_COUNT] = {"tfem_solid_warning_count", 3, "", "", "", "i", {R_SCALAR}, 1},
    [F_S_GET_WARNING_SIZE] = {"tfem_solid_get_warning_size", 3, "w", "", "", "z", {R_SCALAR}, 1},
    [F_S_GET_WARNING] = {"tfem_solid_get_warning", 3, "w", "", "", "c", {R_SWARN}, 0},
    [F_S_SET_MESH] = {"tfem_solid_set_mesh", 3, "ccB", "", "xnb", "", {0}, 0},
    [F_S_LOAD_GMSH] = {"tfem_solid_load_gmsh", 3, "FB", "", "", "", {0}, 0},
    [F_S_SET_FACES] = {"tfem_solid_set_boundary_faces", 3, "c", "", "nt", "", {0}, 0},
    [F_S_ADD_FACES] = {"tfem_solid_add_boundary_faces", 3, "c", "", "nt", "", {0}, 0},
    [F_S_GET_SIZES] = {"tfem_solid_get_sizes", 3, "", "", "", "iii", {R_SCALAR, R_SCALAR, R_SCALAR}, 1},
    [F_S_FACE_COUNT] = {"tfem_solid_get_boundary_face_count", 3, "", "", "", "i", {R_SCALAR}, 1},
    [F_S_MESH_NODES] = {"tfem_solid_get_mesh_nodes", 3, "", "", "", "d", {R_S3NN}, 0},
    [F_S_MESH_TETS] = {"tfem_solid_get_mesh_tetrahedra", 3, "", "", "", "ii", {R_S4NT, R_SNT}, 0},
    [F_S_GET_FACES] = {"tfem_solid_get_boundary_faces", 3, "", "", "", "ii", {R_S3NF, R_SNF}, 0},
    [F_S_SET_MATERIAL] = {"tfem_solid_set_material", 3, "b", "Ep", "", "", {0}, 0},
    [F_S_SET_TEMPERING] = {"tfem_solid_set_tempering", 3, "M", "v", "", "", {0}, 0},
    [F_S_SET_ORDERING] = {"tfem_solid_set_ordering", 3, "O", "", "", "", {0}, 0},
    [F_S_FIX] = {"tfem_solid_fix", 3, "nK", "u", "", "", {0}, 0},
    [F_S_FIX_FACES] = {"tfem_solid_fix_faces", 3, "tK", "u", "", "", {0}, 0},
    [F_S_CLEAR_CONSTRAINTS] = {"tfem_solid_clear_constraints", 3, "", "", "", "", {0}, 0},
    [F_S_ADD_PRESSURE] = {"tfem_solid_add_pressure", 3, "t", "f", "", "", {0}, 0},
    [F_S_ADD_TRACTION] = {"tfem_solid_add_traction", 3, "t", "fff", "", "", {0}, 0},
    [F_S_ADD_NODAL_FORCE] = {"tfem_solid_add_nodal_force", 3, "n", "fff", "", "", {0}, 0},
    [F_S_CLEAR_LOADS] = {"tfem_solid_clear_loads", 3, "", "", "", "", {0}, 0},
    [F_S_ADD_PAIR] = {"tfem_solid_add_contact_pair", 3, "tt", "", "", "i", {R_SCALAR}, 1},
    [F_S_CLEAR_PAIRS] = {"tfem_solid_clear_contact_pairs", 3, "", "", "", "", {0}, 0},
    [F_S_SOLVE] = {"tfem_solid_solve", 3, "", "", "", "S", {R_SCALAR}, 1},
    [F_S_SOLVE_CONTACT] = {"tfem_solid_solve_contact", 3, "LTmx", "Gl", "o", "S", {R_SCALAR}, 1},
    [F_S_STEP] = {"tfem_solid_step", 3, "LTmx", "Gla", "o", "S", {R_SCALAR}, 1},
    [F_S_REVERT_STEP] = {"tfem_solid_revert_step", 3, "", "", "", "", {0}, 0},
    [F_S_SOLVE_INFO] = {"tfem_solid_get_solve_info", 3, "", "", "", "S", {R_SCALAR}, 1},
    [F_S_ITERATIONS] = {"tfem_solid_get_iterations", 3, "", "", "", "i", {R_SCALAR}, 1},
    [F_S_DISPLACEMENTS] = {"tfem_solid_get_displacements", 3, "", "", "", "d", {R_S3NN}, 0},
    [F_S_STRAINS] = {"tfem_solid_get_element_strains", 3, "", "", "", "d", {R_S6NT}, 0},
    [F_S_STRESSES] = {"tfem_solid_get_element_stresses", 3, "", "", "", "d", {R_S6NT}, 0},
    [F_S_REACTIONS] = {"tfem_solid_get_reactions", 3, "", "", "", "d", {R_S3NN}, 0},
    [F_S_WORK] = {"tfem_solid_get_external_work", 3, "", "", "", "d", {R_SCALAR}, 1},
    [F_S_CONTACT_TETS] = {"tfem_solid_get_contact_tetrahedra", 3, "", "", "", "i", {R_S4NC}, 0},
    [F_S_CONTACT_ACTIVE] = {"tfem_solid_get_contact_active", 3, "", "", "", "i", {R_SNC}, 0},
    [F_S_CONTACT_FORCES] = {"tfem_solid_get_contact_forces", 3, "", "", "", "d", {R_S3NN}, 0},
    [F_S_NODAL_PRESSURES] = {"tfem_solid_get_contact_nodal_pressures", 3, "", "", "", "d", {R_SNN}, 0},
    [F_S_AREA] = {"tfem_solid_get_contact_area", 3, "", "", "", "d", {R_SCALAR}, 1},
    [F_S_PAIR_AREA] = {"tfem_solid_get_contact_pair_area", 3, "Q", "", "", "d", {R_SCALAR}, 1},
    [F_S_WRITE_VTU] = {"tfem_solid_write_vtu", 3, "V", "", "", "", {0}, 0},
    [F_S_DESTROY] = {"tfem_solid_destroy", 3, "", "", "", "", {0}, 0},
    [F_S_RECREATE] = {"tfem_solid_destroy+tfem_solid_create", 0, "", "", "", "", {0}, 0},
    /* the 3D contact context (F_SC_CREATE: the options as in tfem_solve_contact, then the index base) */
    [F_SC_CREATE] = {"tfem_solid_contact_create", 0, "LTmxB", "Gl", "o", "", {0}, 0},
    [F_SC_DESTROY] = {"tfem_solid_contact_destroy", 4, "", "", "", "", {0}, 0},
    [F_SC_LAST_ERROR] = {"tfem_solid_contact_last_error", 4, "", "", "", "c", {R_SCMSG}, 0},
    [F_SC_LAST_ERROR_LENGTH] = {"tfem_solid_contact_last_error_length", 4, "", "", "", "", {0}, 0},
    [F_SC_ADD_SIDE] = {"tfem_solid_contact_add_side", 4, "tbcc", "E", "hxqh", "i", {R_SCALAR}, 1},
    [F_SC_ADD_PAIR] = {"tfem_solid_contact_add_pair", 4, "ee", "", "", "i", {R_SCALAR}, 1},
    [F_SC_SETUP] = {"tfem_solid_contact_setup", 4, "", "", "", "", {0}, 0},
    [F_SC_SIZES] = {"tfem_solid_contact_sizes", 4, "", "", "", "iil", {R_SCALAR, R_SCALAR, R_SCALAR}, 1},
    [F_SC_NODES] = {"tfem_solid_contact_nodes", 4, "", "", "", "i", {R_SCN}, 0},
    [F_SC_TETS] = {"tfem_solid_contact_tetrahedra", 4, "", "", "", "i", {R_S4CT}, 0},
    [F_SC_PATTERN] = {"tfem_solid_contact_pattern", 4, "", "", "", "ll", {R_SCP, R_SCP}, 0},
    [F_SC_ELEMENT_EQUATIONS] = {"tfem_solid_contact_element_equations", 4, "", "", "", "l", {R_S12CT}, 0},
    [F_SC_ELEMENT_BLOCKS] = {"tfem_solid_contact_element_blocks", 4, "", "", "", "d", {R_S144CT}, 0},
    [F_SC_EVALUATE] = {"tfem_solid_contact_evaluate", 4, "RDk", "", "U", "dd", {R_SCP, R_S3CN}, 0},
    [F_SC_GATHER] = {"tfem_solid_contact_gather", 4, "gDk", "", "U", "d", {R_S3CN}, 0},
    [F_SC_SCATTER_ADD] = {"tfem_solid_contact_scatter_add", 4, "RDk", "", "UU", "d", {R_SNEQ}, 0},
    [F_SC_UPDATE] = {"tfem_solid_contact_update", 4, "RDk", "", "U", "iii", {R_SCALAR, R_SCALAR, R_SCALAR}, 1},
    [F_SC_RESTART] = {"tfem_solid_contact_restart", 4, "", "", "", "", {0}, 0},
    [F_SC_GET_ACTIVE] = {"tfem_solid_contact_get_active", 4, "", "", "", "i", {R_SCT}, 0},
    [F_SC_SET_ACTIVE] = {"tfem_solid_contact_set_active", 4, "ADk", "", "a", "", {0}, 0},
    [F_SC_GAPS] = {"tfem_solid_contact_gaps", 4, "RDk", "", "U", "d", {R_SCT}, 0},
    [F_SC_AREA] = {"tfem_solid_contact_area", 4, "", "", "", "d", {R_SCALAR}, 1},
    [F_DESTROY_NULL] = {"tfem_destroy(NULL)", 0, "", "", "", "", {0}, 0},
    [F_RECREATE] = {"tfem_destroy+tfem_create", 0, "", "", "", "", {0}, 0},
    [F_TWIN] = {"(twin model oracle)", 0, "", "", "", "", {0}, 0},
};

static int fn_ni(int f) { return (int)strlen(FN[f].ir); }
static int fn_nd(int f) { return (int)strlen(FN[f].dr); }
static int fn_nin(int f) { return (int)strlen(FN[f].ink); }
static int fn_nout(int f) { return (int)strlen(FN[f].outk); }
static int out_kind(int f, int j) {
  switch (FN[f].outk[j]) {
  case 'd': return K_D;
  case 'i': return K_I;
  case 'l': return K_L;
  case 'c': return K_C;
  case 'S': return K_SI;
  case 'R': return K_RE;
  case 'z': return K_Z;
  case 'u': return K_U8;
  case 'A': return K_AR;
  case 't': return K_T;
  default: return K_OP;
  }
}
/* Functions whose failure may write (documented truncation of messages). */
static int writes_on_failure(int f) {
  return f == F_LAST_ERROR || f == F_GET_WARNING || f == F_CONTACT_LAST_ERROR || f == F_S_LAST_ERROR || f == F_S_GET_WARNING ||
         f == F_SC_LAST_ERROR;
}
/* ... and with which status: the 3D ones exactly as the header says (the
 * warning cut to the buffer with BUFFER_TOO_SMALL, "on any other error
 * buffer is unchanged"; a message cut so, or the message refusing a handle
 * that is not live with INVALID_ARGUMENT). */
static int may_write_on_failure(int f, int st) {
  if (f == F_S_GET_WARNING) return st == TFEM_STATUS_BUFFER_TOO_SMALL;
  if (f == F_S_LAST_ERROR || f == F_SC_LAST_ERROR)
    return st == TFEM_STATUS_BUFFER_TOO_SMALL || st == TFEM_STATUS_INVALID_ARGUMENT;
  return writes_on_failure(f);
}
/* The input arrays made when the call runs (from a recipe). */
static int in_runtime(int f, int j) { char r = FN[f].ink[j]; return r == 'U' || r == 'a' || r == 's'; }

/* Output pointers the header allows to be NULL ("may be NULL"). */
static int out_nullable(int f, int j) {
  switch (f) {
  case F_SOLVE: case F_GET_SIZES: case F_GET_MATRIX_SIZE: case F_ADD_CONTACT_PAIR:
  case F_ADD_CONTACT_PAIR_WITH_MESH: case F_SOLVE_CONTACT: case F_GET_CONTACT_PAIR_BODIES:
  case F_STEP: case F_CONTACT_ADD_SIDE: case F_CONTACT_ADD_PAIR: case F_CONTACT_ADD_PAIR_WITH_MESH:
  case F_CONTACT_SIZES: case F_CONTACT_EVALUATE: case F_CONTACT_UPDATE: case F_ADD_CONTACT_PAIRS_AUTO:
  case F_GET_CONTACT_SLAVE_NODES: /* ("any pointer may be NULL") */
  case F_SOLVE_ADAPTIVE: case F_GET_ADAPT_CYCLES:
  case F_S_GET_SIZES: case F_S_ADD_PAIR: case F_S_SOLVE: case F_S_SOLVE_CONTACT: case F_S_STEP: case F_SC_ADD_SIDE:
  case F_SC_ADD_PAIR: case F_SC_SIZES: case F_SC_EVALUATE: case F_SC_UPDATE:
    return 1;
  case F_S_MESH_TETS: case F_S_GET_FACES: /* ("bodies" / "tags" may be NULL) */
    return j == 1;
  default: (void)j; return 0;
  }
}

/* Does a call of f only read the model (a getter, a message, a file
 * written)? Its failure changes nothing there is to compare (the replay
 * checks that it changed nothing at all). */
static int reads_only(int f) {
  switch (f) {
  case F_VERSION: case F_LAST_ERROR: case F_LAST_ERROR_LENGTH: case F_WARNING_COUNT: case F_GET_WARNING:
  case F_GET_SIZES: case F_GET_DISPLACEMENTS: case F_GET_STRAINS: case F_GET_STRESSES: case F_GET_JACOBIANS:
  case F_GET_REACTIONS: case F_GET_MATRIX_SIZE: case F_GET_MATRIX: case F_GET_CONTACT_ACTIVE:
  case F_GET_CONTACT_PRESSURE: case F_GET_CONTACT_ELEMENTS: case F_GET_CONTACT_REPORT: case F_GET_EXTERNAL_WORK:
  case F_GET_CONTACT_FORCES: case F_GET_CONTACT_GAPS: case F_GET_CONTACT_NODAL_PRESSURES:
  case F_GET_CONTACT_MESH_SIZE: case F_GET_CONTACT_MESH: case F_GET_CONTACT_ELEMENT_PAIRS:
  case F_GET_CONTACT_ELEMENT_APEXES: case F_GET_CONTACT_PAIR_BODIES: case F_GET_THREADS:
  case F_GET_CONTACT_STATE_SIZE: case F_GET_CONTACT_STATE: case F_GET_CONTACT_SHEAR:
  case F_GET_CONTACT_FRICTION_STATE: case F_GET_CONTACT_DISSIPATION: case F_GET_CONTACT_PAIR_NODAL_PRESSURES:
  case F_WRITE_VTU: case F_GET_WARNING_SIZE: case F_GET_CONTACT_WEIGHTING: case F_GET_CONTACT_SLAVE_NODES:
  case F_GET_OUT_OF_PLANE: case F_GET_ADAPT_CYCLES:
    return 1;
  default: return 0;
  }
}

/* Does a successful call of f change the problem (and so discard results)? */
static int changes_problem(int f) {
  switch (f) {
  case F_SET_MESH: case F_LOAD_GMSH: case F_SET_BOUNDARY_EDGES: case F_ADD_BOUNDARY_EDGES: case F_SET_MATERIAL:
  case F_SET_TEMPERING: case F_FIX: case F_FIX_EDGES: case F_ADD_PRESSURE:
  case F_ADD_TRACTION: case F_ADD_NODAL_FORCE: case F_SET_BODY_FORCE: case F_CLEAR_LOADS:
  case F_ADD_CONTACT_PAIR: case F_ADD_CONTACT_PAIR_WITH_MESH:
    return 1;
  default: return 0;
  }
}

/* ------------------------------------------------------------------------ */
/* Calls and cases                                                           */
/* ------------------------------------------------------------------------ */

/* Length specification of an output buffer, resolved when first run. */
enum { LS_EXACT, LS_REL, LS_FIXED };

typedef struct {
  int n;      /* elements */
  void *p;    /* double* for 'x', int* otherwise */
  int null_;  /* pass NULL */
} in_arr;

typedef struct {
  int ls;
  long delta;
  int null_;
  int resolved;
  size_t len;  /* the declared length passed (elements) */
  long req;    /* the required length found when resolved (-1 unknown) */
} out_spec;

typedef struct {
  int fn;
  int null_model;
  /* the handle passed (not NULL): 0 the function's own, else one of another
   * kind (1 the 2D model, 2 a 2D context, 3 the 3D model, 4 the 3D context)
   * or 5 one of its own kind destroyed just before the call (call_handle) */
  int handle;
  int iv[MAXI];
  double dv[MAXD];
  in_arr in[MAXIN];
  out_spec out[MAXOUT];
  int mutated;   /* touched by a mutation (for the oracle) */
  /* oracle on get_displacements: u[comp] of node (0-based) = expect */
  int oracle;
  int or_node, or_comp;
  double or_expect, or_rtol;
  /* end-of-case oracles of a pristine scene (see case_oracles): the role
   * of the call and its group */
  int tag, grp;
  int in_made; /* runtime inputs made (the replay passes the same) */
  /* the twin model of a pristine scene (oracle_twin): tw 0 the same call,
   * 1 left out, 2 with dv[0] = tw_val, 3 tfem_add_contact_pair(tw_a, tw_b)
   * instead, 4 boundary edges with tags 5 and 6 given as 2 and 3 (the
   * curved interface uncut; not in mode 4, whose twin makes the calls as
   * they are); expect: pairs tfem_add_contact_pairs_auto must add (-1
   * unknown); got: the pairs it added (original run) */
  int tw, tw_a, tw_b, expect, got;
  /* the status a pristine scene's call must return, plus 1 (0: not checked) */
  int want;
  /* a tfem_solve_adaptive refused by its refinement (INVALID_ARGUMENT naming
   * a declared curve), after a cycle's solve (original run) */
  int refine_refused;
  double tw_val;
  /* original run */
  int status;
  int ran;
  unsigned char *saved[MAXOUT + 1];
  size_t saved_n[MAXOUT + 1];
} call_t;

typedef struct {
  call_t *c;
  int n, cap;
  uint64_t seed;
  long index;
  const char *kind;
  int pristine; /* a scene left unmutated: its oracles apply */
  /* A host scene coupled to a model of the same bodies: host node number
   * = hm_mul * model node (0-based) + hm_off; host equation e (0-based) is
   * the model's DOF hmap[e] (2 node + component); neq equations. */
  int coupled, hm_mul, hm_off, neq;
  int *hmap;
  /* a 3D case (the runner makes the 3D handles); coupled = 2: its host
   * equation e (0-based) is the 3D model's DOF e (3 node + component) */
  int solid;
} case_t;

static void in_set(call_t *c, int j, const void *v, int n, size_t el) {
  free(c->in[j].p);
  c->in[j].p = xmalloc((size_t)(n > 0 ? n : 0) * el + 1);
  if (n > 0 && v) memcpy(c->in[j].p, v, (size_t)n * el);
  c->in[j].n = n > 0 ? n : 0;
}
static size_t in_el(int fn, int j) {
  char r = FN[fn].ink[j];
  return r == 'x' || r == 'U' ? sizeof(double) : r == 'q' ? sizeof(int64_t) : r == 's' ? 1 : sizeof(int);
}

static call_t *add_call(case_t *cs, int fn) {
  if (cs->n == cs->cap) {
    cs->cap = cs->cap ? 2 * cs->cap : 32;
    cs->c = xrealloc(cs->c, (size_t)cs->cap * sizeof(call_t));
  }
  call_t *c = &cs->c[cs->n++];
  memset(c, 0, sizeof *c);
  c->fn = fn;
  for (int j = 0; j < MAXOUT; ++j) c->out[j].ls = LS_EXACT;
  return c;
}

static void call_copy(call_t *dst, const call_t *src) {
  *dst = *src;
  for (int j = 0; j < MAXIN; ++j) {
    dst->in[j].p = NULL;
    if (src->in[j].p) {
      size_t el = in_el(src->fn, j);
      dst->in[j].p = xmalloc((size_t)src->in[j].n * el + 1);
      memcpy(dst->in[j].p, src->in[j].p, (size_t)src->in[j].n * el);
    }
  }
  for (int j = 0; j <= MAXOUT; ++j) {
    dst->saved[j] = NULL;
    dst->saved_n[j] = 0;
  }
}
static void call_free(call_t *c) {
  for (int j = 0; j < MAXIN; ++j) free(c->in[j].p);
  for (int j = 0; j <= MAXOUT; ++j) free(c->saved[j]);
}
static void case_free(case_t *cs) {
  for (int i = 0; i < cs->n; ++i) call_free(&cs->c[i]);
  free(cs->c);
  free(cs->hmap);
  memset(cs, 0, sizeof *cs);
}
static void case_insert_copy(case_t *cs, int at, const call_t *src) {
  call_t tmp;
  call_copy(&tmp, src);
  add_call(cs, F_VERSION);
  memmove(&cs->c[at + 1], &cs->c[at], (size_t)(cs->n - 1 - at) * sizeof(call_t));
  cs->c[at] = tmp;
}
static void case_delete(case_t *cs, int at) {
  call_free(&cs->c[at]);
  memmove(&cs->c[at], &cs->c[at + 1], (size_t)(cs->n - 1 - at) * sizeof(call_t));
  cs->n--;
}

/* ------------------------------------------------------------------------ */
/* Meshes built here                                                         */
/* ------------------------------------------------------------------------ */

typedef struct {
  int nn, nt, ne;
  double *xy;
  int *tri, *body;
  int *edge, *tag; /* 0-based */
  int capn, capt, cape;
} mesh_t;

static int mesh_node(mesh_t *m, double x, double y) {
  if (m->nn == m->capn) {
    m->capn = m->capn ? 2 * m->capn : 64;
    m->xy = xrealloc(m->xy, sizeof(double) * 2 * (size_t)m->capn);
  }
  m->xy[2 * m->nn] = x;
  m->xy[2 * m->nn + 1] = y;
  return m->nn++;
}
static void mesh_tri(mesh_t *m, int a, int b, int c, int body) {
  if (m->nt == m->capt) {
    m->capt = m->capt ? 2 * m->capt : 64;
    m->tri = xrealloc(m->tri, sizeof(int) * 3 * (size_t)m->capt);
    m->body = xrealloc(m->body, sizeof(int) * (size_t)m->capt);
  }
  m->tri[3 * m->nt] = a;
  m->tri[3 * m->nt + 1] = b;
  m->tri[3 * m->nt + 2] = c;
  m->body[m->nt++] = body;
}
static void mesh_edge(mesh_t *m, int p, int q, int tag) {
  if (m->ne == m->cape) {
    m->cape = m->cape ? 2 * m->cape : 64;
    m->edge = xrealloc(m->edge, sizeof(int) * 2 * (size_t)m->cape);
    m->tag = xrealloc(m->tag, sizeof(int) * (size_t)m->cape);
  }
  m->edge[2 * m->ne] = p;
  m->edge[2 * m->ne + 1] = q;
  m->tag[m->ne++] = tag;
}
static void mesh_free(mesh_t *m) {
  free(m->xy);
  free(m->tri);
  free(m->body);
  free(m->edge);
  free(m->tag);
  memset(m, 0, sizeof *m);
}

/* Points from a to b with spacing at most h through the stops (meshgen.rs). */
static int subdivide(double a, double b, const double *stops, int ns, double h, double *out) {
  double knots[16];
  int nk = 0;
  knots[nk++] = a;
  for (int i = 0; i < ns; ++i)
    if (stops[i] > a && stops[i] < b) knots[nk++] = stops[i];
  knots[nk++] = b;
  int n_out = 0;
  out[n_out++] = a;
  for (int w = 0; w + 1 < nk; ++w) {
    double span = knots[w + 1] - knots[w];
    int n = (int)ceil(span / h - 1e-9);
    if (n < 1) n = 1;
    for (int k = 1; k <= n; ++k) out[n_out++] = k == n ? knots[w + 1] : knots[w] + span * k / n;
  }
  return n_out;
}
static int subdivide_symmetric(double a, double b, const double *stops, int ns, double h, double *out) {
  double mid = 0.5 * (a + b), left[16];
  int nl = 0;
  for (int i = 0; i < ns; ++i)
    if (stops[i] > a && stops[i] < mid) left[nl++] = stops[i];
  double half[4096];
  int nh = subdivide(a, mid, left, nl, h, half);
  int n = 0;
  for (int i = 0; i < nh; ++i) out[n++] = half[i];
  for (int i = nh - 2; i >= 0; --i) out[n++] = mid + (mid - half[i]);
  out[n - 1] = b;
  return n;
}

/* A structured grid xs × ys, cells split along the forward diagonal, or
 * mirrored at x = mirror (when mirror is finite). rows[j*nx+i] = node. */
static void add_grid(mesh_t *m, const double *xs, int nx, const double *ys, int ny, int body,
                     double mirror, int *rows) {
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i) rows[j * nx + i] = mesh_node(m, xs[i], ys[j]);
  for (int j = 0; j + 1 < ny; ++j)
    for (int i = 0; i + 1 < nx; ++i) {
      int a = rows[j * nx + i], b = rows[j * nx + i + 1];
      int c = rows[(j + 1) * nx + i + 1], d = rows[(j + 1) * nx + i];
      int forward = isfinite(mirror) ? 0.5 * (xs[i] + xs[i + 1]) < mirror : 1;
      if (forward) {
        mesh_tri(m, a, b, c, body);
        mesh_tri(m, a, c, d, body);
      } else {
        mesh_tri(m, a, b, d, body);
        mesh_tri(m, b, c, d, body);
      }
    }
}

/* The boundary edges of a mesh, oriented as in their triangle, sorted. */
static int cmp_edge(const void *a, const void *b) {
  const int *x = a, *y = b;
  if (x[0] != y[0]) return x[0] < y[0] ? -1 : 1;
  return (x[1] > y[1]) - (x[1] < y[1]);
}
static int boundary_edges(const mesh_t *m, int **out) {
  int n = 3 * m->nt;
  int *all = xmalloc(sizeof(int) * 4 * (size_t)n); /* (min, max, p, q) */
  for (int t = 0; t < m->nt; ++t)
    for (int k = 0; k < 3; ++k) {
      int p = m->tri[3 * t + k], q = m->tri[3 * t + (k + 1) % 3];
      int *e = &all[4 * (3 * t + k)];
      e[0] = p < q ? p : q;
      e[1] = p < q ? q : p;
      e[2] = p;
      e[3] = q;
    }
  qsort(all, (size_t)n, 4 * sizeof(int), cmp_edge);
  int *res = xmalloc(sizeof(int) * 2 * (size_t)n);
  int nr = 0;
  for (int i = 0; i < n;) {
    int j = i;
    while (j < n && all[4 * j] == all[4 * i] && all[4 * j + 1] == all[4 * i + 1]) ++j;
    if (j - i == 1) {
      res[2 * nr] = all[4 * i + 2];
      res[2 * nr + 1] = all[4 * i + 3];
      ++nr;
    }
    i = j;
  }
  free(all);
  qsort(res, (size_t)nr, 2 * sizeof(int), cmp_edge);
  *out = res;
  return nr;
}

/* ------------------------------------------------------------------------ */
/* Gmsh files (written once, before any fork, into a private directory)      */
/* ------------------------------------------------------------------------ */

enum {
  G_VALID, G_NODES_1E15, G_NODES_2P62, G_TRUNCATED, G_EMPTY, G_GARBAGE, G_TILTED, G_NO_ENTITIES,
  G_CLOCKWISE, G_UNDEFINED_NODE, G_ELEMENTS_1E15, G_BLOCKS_1E15, G_NEGATIVE, G_NONEXISTENT,
  G_DIRECTORY, G_BAD_UTF8, G_QUADS, G_SHORT_BLOCK, NGMSH
};
static const char *const G_NAME[NGMSH] = {
    "valid", "nodes_1e15", "nodes_2p62", "truncated", "empty", "garbage", "tilted",
    "no_entities", "clockwise", "undefined_node", "elements_1e15", "blocks_1e15",
    "negative", "nonexistent", "directory", "bad_utf8", "quads", "short_block"};

static char g_dir[256];
static char *g_path[NGMSH];
static char *g_text[NGMSH];
static size_t g_len[NGMSH];

static char *gmsh_square(const char *nodes_header, const char *elements_header, int with_entities,
                         int clockwise, double z4, int bad_node, int quads, int short_block) {
  char *s = xmalloc(8192);
  int n = 0;
  n += sprintf(s + n, "$MeshFormat\n4.1 0 8\n$EndMeshFormat\n");
  if (with_entities)
    n += sprintf(s + n,
                 "$Entities\n0 4 1 0\n1 0 0 0 0 1 0 1 1 0\n2 1 0 0 1 1 0 1 2 0\n"
                 "3 0 0 0 1 0 0 1 3 0\n4 0 1 0 1 1 0 1 4 0\n1 0 0 0 1 1 0 1 1 0\n$EndEntities\n");
  n += sprintf(s + n, "$Nodes\n%s\n2 1 0 9\n", nodes_header);
  int listed = short_block ? 3 : 9;
  for (int k = 1; k <= listed; ++k) n += sprintf(s + n, "%d\n", k);
  for (int k = 0; k < listed; ++k)
    n += sprintf(s + n, "%g %g %g\n", 0.5 * (k % 3), 0.5 * (k / 3), k == 4 ? z4 : 0.0);
  n += sprintf(s + n, "$EndNodes\n$Elements\n%s\n", elements_header);
  if (quads) {
    n += sprintf(s + n, "2 1 3 4\n");
    for (int j = 0, e = 1; j < 2; ++j)
      for (int i = 0; i < 2; ++i, ++e) {
        int a = 1 + i + 3 * j;
        n += sprintf(s + n, "%d %d %d %d %d\n", e, a, a + 1, a + 4, a + 3);
      }
  } else {
    n += sprintf(s + n, "2 1 2 8\n");
    for (int j = 0, e = 1; j < 2; ++j)
      for (int i = 0; i < 2; ++i) {
        int a = 1 + i + 3 * j, b = a + 1, c = a + 4, d = a + 3;
        if (bad_node && e == 1) a = 99;
        if (clockwise) {
          n += sprintf(s + n, "%d %d %d %d\n%d %d %d %d\n", e, a, c, b, e + 1, a, d, c);
        } else {
          n += sprintf(s + n, "%d %d %d %d\n%d %d %d %d\n", e, a, b, c, e + 1, a, c, d);
        }
        e += 2;
      }
  }
  n += sprintf(s + n, "1 1 1 2\n9 1 4\n10 4 7\n1 2 1 2\n11 3 6\n12 6 9\n");
  n += sprintf(s + n, "1 3 1 2\n13 1 2\n14 2 3\n1 4 1 2\n15 7 8\n16 8 9\n$EndElements\n");
  return s;
}

/* The files tfem_solid_load_gmsh is given: the tetrahedral mesh of
 * c_tests/solid_test.c (nodes A..E, tetrahedra ABCD and BCDE of physical
 * volume 1, triangle ABC in physical surfaces 10 and 99, BCE in 20), the
 * same cut short, claiming 10^15 nodes, and 2D files (the valid square:
 * no tetrahedra), garbage, none, the directory, an empty file. */
enum { SG_VALID, SG_TRUNCATED, SG_NODES_1E15, SG_2D, SG_GARBAGE, SG_NONEXISTENT, SG_DIRECTORY, SG_EMPTY, NSG };
static const char *const SG_NAME[NSG] = {"solid", "solid_truncated", "solid_nodes_1e15", NULL, NULL, NULL, NULL, NULL};
static const int SG_2D_FILE[NSG] = {-1, -1, -1, G_VALID, G_GARBAGE, G_NONEXISTENT, G_DIRECTORY, G_EMPTY};
static char *sg_path[NSG];
static char *sg_text[NSG];
static size_t sg_len[NSG];
static const char SOLID_MSH[] =
    "$MeshFormat\n4.1 0 8\n$EndMeshFormat\n"
    "$PhysicalNames\n4\n3 1 \"steel\"\n2 10 \"bottom\"\n2 20 \"slant\"\n2 99 \"all\"\n"
    "$EndPhysicalNames\n"
    "$Entities\n0 0 2 1\n1 0 0 0 1 1 0 2 10 99 0\n2 0 0 0 1 1 1 1 20 0\n"
    "1 0 0 0 1 1 1 1 1 0\n$EndEntities\n"
    "$Nodes\n1 5 101 105\n3 1 0 5\n101\n102\n103\n104\n105\n"
    "0 0 0\n1 0 0\n0 1 0\n0 0 1\n1 1 1\n$EndNodes\n"
    "$Elements\n3 4 1 8\n3 1 4 2\n1 101 102 103 104\n2 102 103 104 105\n"
    "2 1 2 1\n7 101 102 103\n2 2 2 1\n8 102 103 105\n$EndElements\n";

static void on_signal(int sig);
static pid_t g_owner; /* the process that made g_dir (children leave it) */

static void gmsh_files_init(void) {
  snprintf(g_dir, sizeof g_dir, "/tmp/api_fuzz_XXXXXX");
  if (!mkdtemp(g_dir)) {
    perror("mkdtemp");
    exit(3);
  }
  g_owner = getpid();
  signal(SIGINT, on_signal);
  signal(SIGTERM, on_signal);
  signal(SIGPIPE, on_signal);
  signal(SIGHUP, on_signal);
  const char *nh = "1 9 1 9", *eh = "5 16 1 16";
  for (int g = 0; g < NGMSH; ++g) {
    char *t = NULL;
    switch (g) {
    case G_VALID: t = gmsh_square(nh, eh, 1, 0, 0.0, 0, 0, 0); break;
    case G_NODES_1E15: t = gmsh_square("1 1000000000000000 1 9", eh, 1, 0, 0.0, 0, 0, 0); break;
    case G_NODES_2P62: t = gmsh_square("1 4611686018427387904 1 9", eh, 1, 0, 0.0, 0, 0, 0); break;
    case G_TRUNCATED:
      t = gmsh_square(nh, eh, 1, 0, 0.0, 0, 0, 0);
      t[strstr(t, "$EndNodes") - t - 20] = 0;
      break;
    case G_EMPTY: t = xcalloc(1, 1); break;
    case G_GARBAGE: {
      t = xmalloc(301);
      rng_t r = {12345};
      for (int i = 0; i < 300; ++i) t[i] = (char)(1 + rint_(&r, 255));
      t[300] = 0;
      break;
    }
    case G_TILTED: t = gmsh_square(nh, eh, 1, 0, 0.5, 0, 0, 0); break;
    case G_NO_ENTITIES: t = gmsh_square(nh, eh, 0, 0, 0.0, 0, 0, 0); break;
    case G_CLOCKWISE: t = gmsh_square(nh, eh, 1, 1, 0.0, 0, 0, 0); break;
    case G_UNDEFINED_NODE: t = gmsh_square(nh, eh, 1, 0, 0.0, 1, 0, 0); break;
    case G_ELEMENTS_1E15: t = gmsh_square(nh, "5 1000000000000000 1 16", 1, 0, 0.0, 0, 0, 0); break;
    case G_BLOCKS_1E15: t = gmsh_square("1000000000000000 9 1 9", eh, 1, 0, 0.0, 0, 0, 0); break;
    case G_NEGATIVE: t = gmsh_square("1 -9 1 9", eh, 1, 0, 0.0, 0, 0, 0); break;
    case G_QUADS: t = gmsh_square(nh, "5 12 1 12", 1, 0, 0.0, 0, 1, 0); break;
    case G_SHORT_BLOCK: t = gmsh_square(nh, eh, 1, 0, 0.0, 0, 0, 1); break;
    default: break;
    }
    char path[512];
    if (g == G_NONEXISTENT) {
      snprintf(path, sizeof path, "%s/does_not_exist.msh", g_dir);
    } else if (g == G_DIRECTORY) {
      snprintf(path, sizeof path, "%s", g_dir);
    } else if (g == G_BAD_UTF8) {
      snprintf(path, sizeof path, "%s/\xff\xfe.msh", g_dir);
    } else {
      snprintf(path, sizeof path, "%s/%s.msh", g_dir, G_NAME[g]);
      FILE *f = fopen(path, "wb");
      if (!f) {
        perror(path);
        exit(3);
      }
      fwrite(t, 1, strlen(t), f);
      fclose(f);
    }
    g_path[g] = strdup(path);
    g_text[g] = t;
    g_len[g] = t ? strlen(t) : 0;
  }
  for (int g = 0; g < NSG; ++g) {
    if (SG_2D_FILE[g] >= 0) { /* (a 2D file's path; its text is the 2D file's) */
      sg_path[g] = strdup(g_path[SG_2D_FILE[g]]);
      continue;
    }
    char *t = strdup(SOLID_MSH), path[512];
    if (g == SG_TRUNCATED) t[strstr(t, "$Elements") - t + 30] = 0;
    if (g == SG_NODES_1E15) {
      char *at = strstr(t, "1 5 101 105");
      size_t head = (size_t)(at - t);
      char *u = xmalloc(strlen(t) + 64);
      snprintf(u, strlen(t) + 64, "%.*s1 1000000000000000 101 105%s", (int)head, t, at + strlen("1 5 101 105"));
      free(t);
      t = u;
    }
    snprintf(path, sizeof path, "%s/%s.msh", g_dir, SG_NAME[g]);
    FILE *f = fopen(path, "wb");
    if (!f) {
      perror(path);
      exit(3);
    }
    fwrite(t, 1, strlen(t), f);
    fclose(f);
    sg_path[g] = strdup(path);
    sg_text[g] = t;
    sg_len[g] = strlen(t);
  }
}
/* The paths tfem_write_vtu is given: a file in the private directory
 * (unlinked after the call), one whose name is not UTF-8 (any bytes, on
 * Unix), and paths there that cannot be written (a missing directory, the
 * directory itself, the empty path); an index out of range passes NULL.
 * Never any other path. */
enum { VP_FILE, VP_BAD_UTF8, VP_NO_DIR, VP_DIRECTORY, VP_EMPTY, NVTU };
static int vtu_writable(int k) { return k == VP_FILE || k == VP_BAD_UTF8; }
static const char *vtu_path(int k, long index, int idx, char *buf, size_t cap) {
  switch (k) {
  case VP_FILE: snprintf(buf, cap, "%s/out_%ld_%d.vtu", g_dir, index, idx); return buf;
  case VP_BAD_UTF8: snprintf(buf, cap, "%s/\xff\xfe_%ld_%d.vtu", g_dir, index, idx); return buf;
  case VP_NO_DIR: snprintf(buf, cap, "%s/no_such_dir/out.vtu", g_dir); return buf;
  case VP_DIRECTORY: snprintf(buf, cap, "%s", g_dir); return buf;
  case VP_EMPTY: buf[0] = 0; return buf;
  default: return NULL;
  }
}
/* Removes the .vtu files a child that died left in the private directory. */
static void vtu_leftovers_cleanup(void) {
  DIR *d = opendir(g_dir);
  if (!d) return;
  struct dirent *e;
  char p[600];
  while ((e = readdir(d)) != NULL) {
    size_t n = strlen(e->d_name);
    if (n > 4 && strcmp(e->d_name + n - 4, ".vtu") == 0) {
      snprintf(p, sizeof p, "%s/%s", g_dir, e->d_name);
      unlink(p);
    }
  }
  closedir(d);
}

static void gmsh_files_cleanup(void) {
  if (!g_dir[0] || getpid() != g_owner) return;
  vtu_leftovers_cleanup();
  for (int g = 0; g < NGMSH; ++g) {
    if (g_text[g] && g != G_DIRECTORY && g != G_NONEXISTENT && g != G_BAD_UTF8) unlink(g_path[g]);
    free(g_path[g]);
    free(g_text[g]);
    g_path[g] = g_text[g] = NULL;
  }
  for (int g = 0; g < NSG; ++g) {
    if (sg_text[g]) unlink(sg_path[g]);
    free(sg_path[g]);
    free(sg_text[g]);
    sg_path[g] = sg_text[g] = NULL;
  }
  char extra[2][400];
  snprintf(extra[0], sizeof extra[0], "%s/stderr", g_dir);
  snprintf(extra[1], sizeof extra[1], "%s/repro.c", g_dir);
  unlink(extra[0]);
  unlink(extra[1]);
  rmdir(g_dir);
  g_dir[0] = 0;
}

/* Interrupted (Ctrl-C, a closed pipe): remove the private directory. */
static void on_signal(int sig) {
  if (getpid() == g_owner && g_dir[0]) {
    char p[400];
    for (int g = 0; g < NGMSH; ++g)
      if (g_path[g] && g != G_DIRECTORY && g != G_NONEXISTENT && g != G_BAD_UTF8) unlink(g_path[g]);
    for (int g = 0; g < NSG; ++g)
      if (sg_text[g]) unlink(sg_path[g]);
    snprintf(p, sizeof p, "%s/stderr", g_dir);
    unlink(p);
    snprintf(p, sizeof p, "%s/repro.c", g_dir);
    unlink(p);
    vtu_leftovers_cleanup();
    rmdir(g_dir);
  }
  signal(sig, SIG_DFL);
  raise(sig);
}

/* ------------------------------------------------------------------------ */
/* Generation context and value pools                                        */
/* ------------------------------------------------------------------------ */

typedef struct {
  int nn, nt, base;
  int tags[8], ntags;
  int bodies[4], nbodies;
  const mesh_t *mesh; /* the scene's mesh (0-based), or NULL */
  /* a contact context: its index base, host node numbers in use, sides */
  int hbase, nh, nsides;
  int hids[64];
} ctx_t;

static double wild_double(rng_t *r) {
  static const double pool[] = {0.0, -0.0, 1.0, -1.0, 0.5, 1e-300, 4.9406564584124654e-324,
                                2.2250738585072014e-308, 1e-310, 1e300, DBL_MAX, -1e300,
                                -DBL_MAX, 1e10, 1e11, 1e7, 1e-7, 1e15, 3.0e200, 0.49999999999999994};
  int k = rint_(r, 26);
  if (k < 20) return pool[k];
  switch (k) {
  case 20: return NAN;
  case 21: return -NAN;
  case 22: return INFINITY;
  case 23: return -INFINITY;
  case 24: return (runif(r) - 0.5) * pow(10.0, rrange(r, -10, 10));
  default: return ldexp(1.0, rrange(r, -1074, 1023)) * (chance(r, 0.5) ? 1 : -1);
  }
}

static double plausible_double(rng_t *r, char role) {
  switch (role) {
  case 'E': { static const double v[] = {1000.0, 1e10, 1e11, 210e9, 1.0}; return v[rint_(r, 5)]; }
  case 'p': { static const double v[] = {0.25, 0.3, 0.0, 0.45, -0.5}; return v[rint_(r, 5)]; }
  case 'J': { static const double v[] = {0.0, 1e-3, 1e-6, 0.1}; return v[rint_(r, 4)]; }
  case 'K': { static const double v[] = {1.0, 2.5, 1e-3}; return v[rint_(r, 3)]; }
  case 'v': { static const double v[] = {1000.0, 1.0, 1e-3, 0.1}; return v[rint_(r, 4)]; }
  case 'u': { static const double v[] = {0.0, 0.0, 0.01, -0.01, 1e-4}; return v[rint_(r, 5)]; }
  case 'f': { static const double v[] = {10.0, 1e7, -5.0, 0.0, 1.0}; return v[rint_(r, 5)]; }
  case 'G': { static const double v[] = {0.0, 0.0, 1e10, 1e9}; return v[rint_(r, 4)]; }
  case 'l': { static const double v[] = {0.0, 0.0, 1.0, 0.1}; return v[rint_(r, 4)]; }
  case 'a': { static const double v[] = {1.0, 0.5, 0.25, 2.0, 0.0, -0.5, 1.0}; return v[rint_(r, 7)]; }
  case 'y': { static const double v[] = {0.0, 0.1, 0.3, 0.5, 1.0, -0.0}; return v[rint_(r, 6)]; }
  case 'd': { static const double v[] = {1e-6, 0.01, 0.1, 0.0, 1e-3}; return v[rint_(r, 5)]; }
  case 'e': { static const double v[] = {0.3, 0.1, 0.05, 0.5, 0.2, 1e-3}; return v[rint_(r, 6)]; }
  case 'X': { static const double v[] = {0.0, 0.0, 0.5, 1.0, -1.0, 0.25}; return v[rint_(r, 6)]; }
  case 'r': { static const double v[] = {1.0, 2.0, 0.5, 0.25, 1.5, 0.7071067811865476}; return v[rint_(r, 6)]; }
  default: return runif(r);
  }
}

static int enum_max(char role) {
  switch (role) {
  case 'C': case 'L': case 'T': case 'x': case 'Z': return 1;
  case 'K': return 2; /* (a 3D component: x, y, z) */
  case 'M': return 3;
  case 'O': case 'P': return 2; /* (P: strain, stress, axisymmetric) */
  default: return 1;
  }
}

static int pick_tag(rng_t *r, const ctx_t *cx) { return cx->ntags ? cx->tags[rint_(r, cx->ntags)] : rrange(r, 1, 4); }
static int pick_body(rng_t *r, const ctx_t *cx) { return cx->nbodies ? cx->bodies[rint_(r, cx->nbodies)] : rrange(r, 1, 2); }
static int pick_node(rng_t *r, const ctx_t *cx) { return cx->base + (cx->nn ? rint_(r, cx->nn) : rint_(r, 4)); }
static int pick_hnode(rng_t *r, const ctx_t *cx) { return cx->nh && chance(r, 0.95) ? cx->hids[rint_(r, cx->nh)] : rrange(r, -2, 40); }

static int plausible_int(rng_t *r, char role, const ctx_t *cx) {
  switch (role) {
  case 'n': return pick_node(r, cx);
  case 't': return pick_tag(r, cx);
  case 'b': return pick_body(r, cx);
  case 'B': return cx->base;
  case 'c': return rrange(r, 0, 4);
  case 'f': return chance(r, 0.6) ? G_VALID : rint_(r, NGMSH);
  case 'V': return chance(r, 0.6) ? VP_FILE : rint_(r, NVTU);
  case 'm': return chance(r, 0.8) ? 50 : rrange(r, 1, 5);
  case 'w': return rint_(r, 3);
  case 'q': return chance(r, 0.8) ? 0 : rrange(r, -1, 2);
  case 'h': return (int[]){0, 1, 2, 1}[rint_(r, 4)];
  case 's': return rint_(r, cx->nsides > 1 ? cx->nsides : 2);
  case 'R': return (int[]){0, 0, 1, 1, 1, 1, 2, 2, 3, 4}[rint_(r, 10)];
  case 'D': return chance(r, 0.9) ? 0 : (int[]){-1, 1, -2, 7}[rint_(r, 4)];
  case 'k': return rint_(r, 1000);
  case 'S': return chance(r, 0.6) ? 0 : rint_(r, 6);
  case 'A': return rint_(r, 6);
  case 'g': return rint_(r, 4);
  case 'W': return chance(r, 0.6) ? TFEM_CONTACT_WEIGHTING_MORTAR : chance(r, 0.5) ? TFEM_CONTACT_WEIGHTING_STRIP
                                                                     : TFEM_CONTACT_WEIGHTING_AUTO;
  case 'Y': return chance(r, 0.8) ? rrange(r, 1, 4) : rrange(r, 5, 6);
  case 'N': return (int[]){200, 500, 2000, 5000, 20000, 2000}[rint_(r, 6)];
  case 'P': return chance(r, 0.8) ? rint_(r, 2) : TFEM_PLANE_MODE_AXISYMMETRIC;
  case 'F': return chance(r, 0.6) ? SG_VALID : rint_(r, NSG);
  case 'Q': return chance(r, 0.8) ? 0 : rrange(r, -1, 2);
  case 'e': return cx->hbase + rint_(r, cx->nsides > 1 ? cx->nsides : 2);
  default: return rint_(r, enum_max(role) + 1);
  }
}

/* v + d and v * m without signed overflow (UB; -O2 wraps INT_MIN - 1 to
 * INT_MAX, a count the arrays were never sized for), clamped to int. */
static int sat_int(long long v) { return v < INT_MIN ? INT_MIN : v > INT_MAX ? INT_MAX : (int)v; }
/* max_unknowns of tfem_solve_adaptive from its int (role N). */
static int64_t adapt_max_unknowns(int v) { return v == INT_MAX ? INT64_MAX : v == INT_MIN ? INT64_MIN : (int64_t)v; }
static int64_t sat_inc64(int64_t v) { return v == INT64_MAX ? v : v + 1; }

static int wild_int(rng_t *r, char role, int v, const ctx_t *cx) {
  /* Threads: negative, or a few more than the cores. (Not INT_MAX: the
   * library would start threads until the system refuses, for minutes;
   * see c_tests/README.md.) */
  if (role == 'h') return (int[]){-1, INT_MIN, -7, 3, 8, 0}[rint_(r, 6)];
  /* The contact weighting: not 0, 1 or 2 (refused, the model unchanged). */
  if (role == 'W') return (int[]){-1, 3, INT_MAX, INT_MIN}[rint_(r, 4)];
  /* The adaptive solve's limits: never both large (max_cycles stays at 6
   * or below: a tolerance of 1e-300 refines until a limit stops it). */
  if (role == 'Y') return (int[]){0, -1, INT_MIN, 1, 6}[rint_(r, 5)];
  if (role == 'N') return (int[]){0, -1, 1, 50, INT_MAX, INT_MIN}[rint_(r, 6)];
  switch (rint_(r, 8)) {
  case 0: return -1;
  case 1: return INT_MIN;
  case 2: return role == 'm' ? 1000 : INT_MAX;
  case 3: return sat_int((long long)v + 1);
  case 4: return sat_int((long long)v - 1);
  case 5:
    if (role == 'n') return cx->nn + cx->base;
    if (role == 'f' || role == 'V' || role == 'F') return -1;
    return enum_max(role) + 1;
  case 6: return role == 'n' ? sat_int((long long)v + (cx->base ? -1 : 1)) : 99;
  default: return 0;
  }
}

/* Keeps the input arrays consistent with the counts (a count larger than an
 * array would be the caller's error, not the library's). */
static void fix_arrays(rng_t *r, call_t *c, const ctx_t *cx) {
  int need[MAXIN] = {-1, -1, -1, -1};
  switch (c->fn) {
  case F_SET_MESH:
    need[0] = c->iv[0] >= 0 && c->iv[0] < 100000 ? 2 * c->iv[0] : -1;
    need[1] = c->iv[1] >= 0 && c->iv[1] < 100000 ? 3 * c->iv[1] : -1;
    need[2] = c->iv[1] >= 0 && c->iv[1] < 100000 ? c->iv[1] : -1;
    break;
  case F_SET_BOUNDARY_EDGES: case F_ADD_BOUNDARY_EDGES:
    need[0] = c->iv[0] >= 0 && c->iv[0] < 100000 ? 2 * c->iv[0] : -1;
    need[1] = c->iv[0] >= 0 && c->iv[0] < 100000 ? c->iv[0] : -1;
    break;
  case F_ADD_CONTACT_PAIR_WITH_MESH: need[0] = c->iv[2] >= 0 ? 3 * c->iv[2] : -1; break;
  case F_ELEMENT_STIFFNESS: case F_LAPLACIAN_STIFFNESS: need[0] = 6; break;
  case F_CONTACT_ADD_SIDE:
    need[0] = c->iv[3] >= 0 && c->iv[3] < 100000 ? c->iv[3] : -1;
    need[1] = need[0] >= 0 ? 2 * need[0] : -1;
    need[2] = need[1];
    need[3] = c->iv[4] >= 0 && c->iv[4] < 100000 ? 2 * c->iv[4] : -1;
    break;
  case F_CONTACT_ADD_PAIR_WITH_MESH: need[0] = c->iv[2] >= 0 && c->iv[2] < 100000 ? 3 * c->iv[2] : -1; break;
  case F_ADD_CONTACT_PAIRS_AUTO: need[0] = c->iv[0] >= 0 && c->iv[0] < 100000 ? c->iv[0] : -1; break;
  case F_S_SET_MESH:
    need[0] = c->iv[0] >= 0 && c->iv[0] < 100000 ? 3 * c->iv[0] : -1;
    need[1] = c->iv[1] >= 0 && c->iv[1] < 100000 ? 4 * c->iv[1] : -1;
    need[2] = c->iv[1] >= 0 && c->iv[1] < 100000 ? c->iv[1] : -1;
    break;
  case F_S_SET_FACES: case F_S_ADD_FACES:
    need[0] = c->iv[0] >= 0 && c->iv[0] < 100000 ? 3 * c->iv[0] : -1;
    need[1] = c->iv[0] >= 0 && c->iv[0] < 100000 ? c->iv[0] : -1;
    break;
  case F_SC_ADD_SIDE:
    need[0] = c->iv[2] >= 0 && c->iv[2] < 100000 ? c->iv[2] : -1;
    need[1] = need[0] >= 0 ? 3 * need[0] : -1;
    need[2] = need[1];
    need[3] = c->iv[3] >= 0 && c->iv[3] < 100000 ? 3 * c->iv[3] : -1;
    break;
  default: return;
  }
  for (int j = 0; j < fn_nin(c->fn); ++j) {
    if (need[j] < 0 || need[j] == c->in[j].n) continue;
    size_t el = in_el(c->fn, j);
    void *p = xmalloc((size_t)need[j] * el + 1);
    int keep = c->in[j].n < need[j] ? c->in[j].n : need[j];
    if (keep > 0) memcpy(p, c->in[j].p, (size_t)keep * el);
    for (int k = keep; k < need[j]; ++k) {
      char role = FN[c->fn].ink[j];
      if (role == 'x') {
        ((double *)p)[k] = rint_(r, 5) * 0.5;
      } else if (role == 'q') {
        ((int64_t *)p)[k] = rrange(r, cx->hbase - 1, cx->hbase + 40);
      } else if (role == 'h') {
        ((int *)p)[k] = pick_hnode(r, cx);
      } else {
        int v = role == 'n' ? pick_node(r, cx) : role == 'b' ? pick_body(r, cx) : pick_tag(r, cx);
        ((int *)p)[k] = v;
      }
    }
    free(c->in[j].p);
    c->in[j].p = p;
    c->in[j].n = need[j];
  }
}

/* ------------------------------------------------------------------------ */
/* Scenes                                                                    */
/* ------------------------------------------------------------------------ */

static void set_mesh_call(case_t *cs, const mesh_t *m, int base) {
  call_t *c = add_call(cs, F_SET_MESH);
  c->iv[0] = m->nn;
  c->iv[1] = m->nt;
  c->iv[2] = base;
  in_set(c, 0, m->xy, 2 * m->nn, sizeof(double));
  in_set(c, 1, NULL, 3 * m->nt, sizeof(int));
  for (int k = 0; k < 3 * m->nt; ++k) ((int *)c->in[1].p)[k] = m->tri[k] + base;
  in_set(c, 2, m->body, m->nt, sizeof(int));
}
static void edges_call(case_t *cs, const mesh_t *m, int base) {
  call_t *c = add_call(cs, F_SET_BOUNDARY_EDGES);
  c->iv[0] = m->ne;
  in_set(c, 0, NULL, 2 * m->ne, sizeof(int));
  for (int k = 0; k < 2 * m->ne; ++k) ((int *)c->in[0].p)[k] = m->edge[k] + base;
  in_set(c, 1, m->tag, m->ne, sizeof(int));
}
/* One group of boundary edges (those tagged `tag`), given the tag `as_tag`,
 * through `fn` (tfem_set_boundary_edges or tfem_add_boundary_edges). */
static call_t *group_call(case_t *cs, const mesh_t *m, int base, int fn, int tag, int as_tag) {
  call_t *c = add_call(cs, fn);
  int n = 0;
  for (int e = 0; e < m->ne; ++e) n += m->tag[e] == tag;
  c->iv[0] = n;
  in_set(c, 0, NULL, 2 * n, sizeof(int));
  in_set(c, 1, NULL, n, sizeof(int));
  for (int e = 0, k = 0; e < m->ne; ++e)
    if (m->tag[e] == tag) {
      ((int *)c->in[0].p)[2 * k] = m->edge[2 * e] + base;
      ((int *)c->in[0].p)[2 * k + 1] = m->edge[2 * e + 1] + base;
      ((int *)c->in[1].p)[k++] = as_tag;
    }
  return c;
}
/* The distinct tags of a mesh's edges, ascending (at most 16). */
static int mesh_tags(const mesh_t *m, int *tags) {
  int n = 0;
  for (int e = 0; e < m->ne; ++e) {
    int k = 0;
    while (k < n && tags[k] != m->tag[e]) ++k;
    if (k == n && n < 16) tags[n++] = m->tag[e];
  }
  for (int i = 1; i < n; ++i)
    for (int j = i; j > 0 && tags[j - 1] > tags[j]; --j) {
      int t = tags[j];
      tags[j] = tags[j - 1];
      tags[j - 1] = t;
    }
  return n;
}
/* The boundary edges of a scene: one tfem_set_boundary_edges (60%), or one
 * group (tag) at a time: tfem_set_boundary_edges with the first group and
 * tfem_add_boundary_edges for each other (20%), or tfem_add_boundary_edges
 * only (20%). */
static void edges_calls(rng_t *r, case_t *cs, const mesh_t *m, int base) {
  int v = rint_(r, 10), tags[16], nt = mesh_tags(m, tags);
  if (v < 6 || nt == 0) {
    edges_call(cs, m, base);
    return;
  }
  for (int k = 0; k < nt; ++k)
    group_call(cs, m, base, k == 0 && v < 8 ? F_SET_BOUNDARY_EDGES : F_ADD_BOUNDARY_EDGES, tags[k], tags[k]);
}
static call_t *call_i(case_t *cs, int fn, int a, int b) {
  call_t *c = add_call(cs, fn);
  c->iv[0] = a;
  c->iv[1] = b;
  return c;
}
static void material(case_t *cs, int body, double e, double nu, int plane) {
  call_t *c = call_i(cs, F_SET_MATERIAL, body, plane);
  c->dv[0] = e;
  c->dv[1] = nu;
}
static void fixc(case_t *cs, int fn, int what, int comp, double v) {
  call_t *c = call_i(cs, fn, what, comp);
  c->dv[0] = v;
}
static void load2(case_t *cs, int fn, int what, double a, double b) {
  call_t *c = call_i(cs, fn, what, 0);
  c->dv[0] = a;
  c->dv[1] = b;
}
static void solve_contact_call(case_t *cs, int law, int test, int maxit, int refac, double ec, double lam) {
  call_t *c = add_call(cs, F_SOLVE_CONTACT);
  c->iv[0] = law;
  c->iv[1] = test;
  c->iv[2] = maxit;
  c->iv[3] = refac;
  c->dv[0] = ec;
  c->dv[1] = lam;
}
static void result_getters(rng_t *r, case_t *cs, int contact) {
  add_call(cs, F_GET_SIZES);
  add_call(cs, F_GET_DISPLACEMENTS);
  if (chance(r, 0.7)) add_call(cs, F_GET_REACTIONS);
  if (chance(r, 0.5)) add_call(cs, F_GET_STRAINS);
  if (chance(r, 0.5)) add_call(cs, F_GET_STRESSES);
  if (chance(r, 0.3)) add_call(cs, F_GET_JACOBIANS);
  if (chance(r, 0.3)) add_call(cs, F_GET_OUT_OF_PLANE);
  if (chance(r, 0.5)) add_call(cs, F_GET_MATRIX_SIZE);
  if (chance(r, 0.5)) add_call(cs, F_GET_MATRIX);
  if (chance(r, 0.4)) add_call(cs, F_GET_EXTERNAL_WORK);
  if (chance(r, 0.15)) add_call(cs, F_GET_THREADS);
  if (contact) {
    add_call(cs, F_GET_CONTACT_ACTIVE);
    if (chance(r, 0.7)) add_call(cs, F_GET_CONTACT_PRESSURE);
    if (chance(r, 0.5)) add_call(cs, F_GET_CONTACT_ELEMENTS);
    if (chance(r, 0.5)) add_call(cs, F_GET_CONTACT_REPORT);
    if (chance(r, 0.6)) add_call(cs, F_GET_CONTACT_FORCES);
    if (chance(r, 0.5)) add_call(cs, F_GET_CONTACT_GAPS);
    if (chance(r, 0.4)) add_call(cs, F_GET_CONTACT_NODAL_PRESSURES);
    if (chance(r, 0.3)) add_call(cs, F_GET_CONTACT_PAIR_NODAL_PRESSURES);
    if (chance(r, 0.2)) add_call(cs, F_GET_CONTACT_SHEAR);
    if (chance(r, 0.2)) add_call(cs, F_GET_CONTACT_FRICTION_STATE);
    if (chance(r, 0.2)) add_call(cs, F_GET_CONTACT_DISSIPATION);
    if (chance(r, 0.25)) add_call(cs, F_GET_CONTACT_MESH_SIZE);
    if (chance(r, 0.25)) add_call(cs, F_GET_CONTACT_MESH);
    if (chance(r, 0.2)) add_call(cs, F_GET_CONTACT_ELEMENT_PAIRS);
    if (chance(r, 0.2)) add_call(cs, F_GET_CONTACT_ELEMENT_APEXES);
    if (chance(r, 0.2)) call_i(cs, F_GET_CONTACT_PAIR_BODIES, 0, 0);
    if (chance(r, 0.1)) add_call(cs, F_GET_CONTACT_SLAVE_NODES); /* (after a strip solve: refused) */
    if (chance(r, 0.05)) add_call(cs, F_GET_CONTACT_WEIGHTING);
  } else if (chance(r, 0.1)) {
    add_call(cs, chance(r, 0.5) ? F_GET_CONTACT_MESH_SIZE : F_GET_CONTACT_FORCES);
  }
  if (chance(r, 0.3)) add_call(cs, F_WARNING_COUNT);
  if (chance(r, 0.2)) call_i(cs, F_GET_WARNING, 0, 0)->out[0] = (out_spec){LS_FIXED, 512, 0, 0, 0, 0};
  if (chance(r, 0.2)) call_i(cs, F_GET_WARNING_SIZE, rint_(r, 2), 0);
  if (chance(r, 0.15)) call_i(cs, F_WRITE_VTU, chance(r, 0.8) ? VP_FILE : rint_(r, NVTU), 0);
  if (chance(r, 0.2)) add_call(cs, F_LAST_ERROR)->out[0] = (out_spec){LS_FIXED, 512, 0, 0, 0, 0};
}

/* A unit square of nx × ny cells, body `body`, clamped on the left (u = 0,
 * v = 0 at the lower-left corner) and pulled on the right by a traction 10:
 * u = 10 x / E exactly (plane stress). Tags 1 left, 2 right, 3 bottom, 4 top. */
static void scene_square(rng_t *r, case_t *cs, ctx_t *cx, mesh_t *m, int clockwise, int oracle) {
  /* (Given clockwise, every element has J = -1/n² < 0 < Jmin = h³/λ, with
   * h = √2/n and λ = 1: tempered, each is |J|/Jmin = n/(2√2) times too
   * stiff: 2.8, 5.7 or 11.3 times for n = 8, 16, 32.) */
  int nc = (int[]){8, 16, 32}[rint_(r, 3)];
  int nx = oracle ? nc : rrange(r, 1, 8), ny = oracle ? nc : rrange(r, 1, 8);
  int body = (int[]){1, 7, -3, 100}[rint_(r, 4)];
  int base = rint_(r, 2);
  double xs[40], ys[40];
  for (int i = 0; i <= nx; ++i) xs[i] = (double)i / nx;
  for (int j = 0; j <= ny; ++j) ys[j] = (double)j / ny;
  int rows[40 * 40];
  add_grid(m, xs, nx + 1, ys, ny + 1, body, NAN, rows);
  if (clockwise)
    for (int t = 0; t < m->nt; ++t) {
      int a = m->tri[3 * t + 1];
      m->tri[3 * t + 1] = m->tri[3 * t + 2];
      m->tri[3 * t + 2] = a;
    }
  int *be, nb = boundary_edges(m, &be);
  for (int e = 0; e < nb; ++e) {
    const double *p = &m->xy[2 * be[2 * e]], *q = &m->xy[2 * be[2 * e + 1]];
    int tag = p[0] == 0 && q[0] == 0 ? 1 : p[0] == 1 && q[0] == 1 ? 2 : p[1] == 0 && q[1] == 0 ? 3 : 4;
    mesh_edge(m, be[2 * e], be[2 * e + 1], tag);
  }
  free(be);
  *cx = (ctx_t){m->nn, m->nt, base, {1, 2, 3, 4}, 4, {body}, 1, m, 0, 0, 0, {0}};
  set_mesh_call(cs, m, base);
  edges_calls(r, cs, m, base);
  material(cs, body, 1000.0, 0.25, TFEM_PLANE_MODE_STRESS);
  int temper = clockwise ? 0 : rint_(r, 3);
  if (temper == 1) call_i(cs, F_SET_TEMPERING, TFEM_TEMPERING_MODE_LAMBDA, 0)->dv[0] = 1000.0;
  if (temper == 2) call_i(cs, F_SET_TEMPERING, TFEM_TEMPERING_MODE_OFF, 0);
  if (chance(r, 0.3)) call_i(cs, F_SET_ORDERING, rint_(r, 3), rint_(r, 2));
  fixc(cs, F_FIX_EDGES, 1, TFEM_COMPONENT_X, 0.0);
  fixc(cs, F_FIX, rows[0] + base, TFEM_COMPONENT_Y, 0.0);
  load2(cs, F_ADD_TRACTION, 2, 10.0, 0.0);
  add_call(cs, F_SOLVE);
  call_t *d = NULL;
  result_getters(r, cs, 0);
  for (int i = 0; i < cs->n; ++i)
    if (cs->c[i].fn == F_GET_DISPLACEMENTS) d = &cs->c[i];
  /* Exact for P1 unless tempering softens the (counter-clockwise) elements:
   * Jmin = min(h³/λ, h²/10) with λ = 1 (auto) against J = hx·hy. */
  double hx = 1.0 / nx, hy = 1.0 / ny, h = sqrt(hx * hx + hy * hy);
  int exact = temper != 0 || hx * hy >= fmin(h * h * h, 0.1 * h * h);
  if (d && (oracle || exact)) {
    d->oracle = 1;
    d->or_node = rows[ny * (nx + 1) + nx];
    d->or_comp = 0;
    d->or_expect = 10.0 / 1000.0;
    d->or_rtol = 1e-6;
  }
}

/* The seed's two blocks (scenes.rs): Ω1 = [0,1]×[-0.25,0] (body 1, E 1e10)
 * supported over 2C, Ω2 = [0,1]×[gap,gap+0.25] (body 2, E 1e11) pressed by
 * 1e7 over 2C, u = 0 on x = 1/2. Tags 1 support, 2 lower contact side,
 * 3 upper contact side, 4 load. Variant 1 (user_mesh): the contact mesh
 * is given; 2: the literal-test cycle at h = 1/32; 3 (curved): every node
 * raised by BOW 4x(1-x) (a shear of the plane, the triangles keep their
 * orientation), so that the contact sides are arcs: the upper block's
 * nodes along x differ from the lower one's in number (a spacing of 1.5h,
 * 0.6h or 2.5h, the first whose count differs) or (30%) are the same at
 * no gap (the sides coincide); 40% of them have the interface cut at
 * x = 1/2 into two pairs, (2, 3) left and (5, 6) right, which share the
 * node at x = 1/2 on either side (one interface of bodies 1 and 2: one
 * slave side, one weighted gap at the shared slave node); 4 (cut): the
 * straight blocks, their nodes chosen so, the interface always cut.
 * Returns the family the automatic weighting gives the pairs (the header):
 * FAM_STRIP on straight sides or nodes that face each other, FAM_MORTAR
 * on the curved non-matching sides. With probability 1/2 a twin model
 * (F_TWIN mode 4) checks that, pristine: the automatic weighting's results
 * are those of that family forced, bit for bit; in a straight cut
 * interface, with probability 1/2, another (F_TWIN mode 5) that the two
 * pairs are the interface as one pair: the same displacements and nodal
 * pressures within 1e-9 of the largest. (Not on the curved ones: there
 * each pair's end node takes its own side's end normal, where one pair
 * has the mean of two edges' normals, so the two discretisations differ
 * at the cut by the turn of the edges: 5e-6 of u and 4e-4 of the strip's
 * nodal pressure seen.) */
#define BOW 0.04
static int scene_two_blocks(rng_t *r, case_t *cs, ctx_t *cx, mesh_t *m, int variant) {
  static const double hs[] = {0.25, 0.125, 0.0625};
  static const double cc[] = {0.1, 0.2, 0.3};
  double h = hs[rint_(r, 3)], c = cc[rint_(r, 3)];
  int user_mesh = variant == 1, literal = variant == 2, curved = variant == 3, cut = variant == 4;
  int split = cut || (curved && chance(r, 0.4));
  if (literal) {
    h = 1.0 / 32.0;
    c = 0.3;
  }
  double gap = (user_mesh && chance(r, 0.7)) || chance(r, 0.15) ? 0.05 * h : 0.0;
  double h_up = (!user_mesh && !literal && chance(r, 0.2)) ? 1.5 * h : h;
  double mid = 0.5, stops[2] = {mid - c, mid + c};
  static __thread double xs[4096], xs2[4096], ys1[4096], ys2[4096];
  int nx = subdivide_symmetric(0, 1, stops, 2, h, xs);
  int nx2 = subdivide_symmetric(0, 1, stops, 2, h_up, xs2);
  int fam = FAM_STRIP;
  if (curved || cut) {
    /* the upper side's nodes as many as the lower's only where they
     * coincide (no gap); else another count (contact/mesh.rs matching:
     * not node for node, so the automatic weighting takes the mortar's) */
    h_up = h;
    if (!chance(r, 0.3))
      for (int k = 0; k < 3; ++k) {
        double f = (double[]){1.5, 0.6, 2.5}[k];
        if (subdivide_symmetric(0, 1, stops, 2, f * h, xs2) != nx) {
          h_up = f * h;
          break;
        }
      }
    nx2 = subdivide_symmetric(0, 1, stops, 2, h_up, xs2);
    if (nx2 == nx) gap = 0.0;
    else if (curved) fam = FAM_MORTAR;
  }
  int ny1 = subdivide(-0.25, 0, NULL, 0, h, ys1);
  int ny2 = subdivide(0, 0.25, NULL, 0, h_up, ys2);
  for (int j = 0; j < ny2; ++j) ys2[j] += gap;
  int *lower = xmalloc(sizeof(int) * (size_t)(nx * ny1)), *upper = xmalloc(sizeof(int) * (size_t)(nx2 * ny2));
  add_grid(m, xs, nx, ys1, ny1, 1, mid, lower);
  int n_lower = m->nn;
  add_grid(m, xs2, nx2, ys2, ny2, 2, mid, upper);
  int *be, nb = boundary_edges(m, &be);
  for (int e = 0; e < nb; ++e) {
    int a = be[2 * e], b = be[2 * e + 1];
    const double *p = &m->xy[2 * a], *q = &m->xy[2 * b];
    int in_lower = a < n_lower;
    int loaded = p[0] >= mid - c && p[0] <= mid + c && q[0] >= mid - c && q[0] <= mid + c;
    int tag = 0;
    if (in_lower && p[1] == -0.25 && q[1] == -0.25 && loaded) tag = 1;
    else if (in_lower && p[1] == 0.0 && q[1] == 0.0) tag = split && p[0] + q[0] > 2 * mid ? 5 : 2;
    else if (!in_lower && p[1] == ys2[0] && q[1] == ys2[0]) tag = split && p[0] + q[0] > 2 * mid ? 6 : 3;
    else if (!in_lower && p[1] == ys2[ny2 - 1] && q[1] == p[1] && loaded) tag = 4;
    if (tag) mesh_edge(m, a, b, tag);
  }
  free(be);
  if (curved) /* (after the tags, which read the straight coordinates) */
    for (int i = 0; i < m->nn; ++i) m->xy[2 * i + 1] += BOW * 4.0 * m->xy[2 * i] * (1.0 - m->xy[2 * i]);
  int base = rint_(r, 2);
  *cx = split ? (ctx_t){m->nn, m->nt, base, {1, 2, 3, 4, 5, 6}, 6, {1, 2}, 2, m, 0, 0, 0, {0}}
              : (ctx_t){m->nn, m->nt, base, {1, 2, 3, 4}, 4, {1, 2}, 2, m, 0, 0, 0, {0}};
  set_mesh_call(cs, m, base);
  edges_calls(r, cs, m, base);
  for (int i = 0; i < cs->n && split; ++i) /* (the twin of mode 5: the interface uncut) */
    if (cs->c[i].fn == F_SET_BOUNDARY_EDGES || cs->c[i].fn == F_ADD_BOUNDARY_EDGES) cs->c[i].tw = 4;
  int plane = chance(r, 0.8) ? TFEM_PLANE_MODE_STRAIN : TFEM_PLANE_MODE_STRESS;
  material(cs, 1, 1e10, 0.3, plane);
  material(cs, 2, 1e11, 0.3, plane);
  if (chance(r, 0.2)) call_i(cs, F_SET_TEMPERING, TFEM_TEMPERING_MODE_AUTO, 0);
  int imid = 0, imid2 = 0;
  for (int i = 0; i < nx; ++i)
    if (xs[i] == mid) imid = i;
  for (int i = 0; i < nx2; ++i)
    if (xs2[i] == mid) imid2 = i;
  for (int j = 0; j < ny1; ++j) fixc(cs, F_FIX, lower[j * nx + imid] + base, TFEM_COMPONENT_X, 0.0);
  for (int j = 0; j < ny2; ++j) fixc(cs, F_FIX, upper[j * nx2 + imid2] + base, TFEM_COMPONENT_X, 0.0);
  fixc(cs, F_FIX_EDGES, 1, TFEM_COMPONENT_Y, 0.0);
  call_i(cs, F_ADD_PRESSURE, 4, 0)->dv[0] = 1e7;
  if (user_mesh) {
    call_t *p = add_call(cs, F_ADD_CONTACT_PAIR_WITH_MESH);
    p->iv[0] = 2;
    p->iv[1] = 3;
    p->iv[2] = 2 * (nx - 1);
    in_set(p, 0, NULL, 6 * (nx - 1), sizeof(int));
    int *t = p->in[0].p, flip = chance(r, 0.3);
    for (int i = 0; i + 1 < nx; ++i) {
      int a0 = lower[(ny1 - 1) * nx + i], a1 = lower[(ny1 - 1) * nx + i + 1];
      int b0 = upper[i], b1 = upper[i + 1];
      int tri[6] = {a0, a1, b0, a1, b1, b0};
      if (flip && (i % 2)) {
        tri[1] = b0;
        tri[2] = a1;
      }
      for (int k = 0; k < 6; ++k) t[6 * i + k] = tri[k] + base;
    }
  } else {
    call_i(cs, F_ADD_CONTACT_PAIR, 2, 3);
    if (split) call_i(cs, F_ADD_CONTACT_PAIR, 5, 6)->tw = 1;
  }
  if (chance(r, 0.5)) {
    /* the contact mesh B, before any solve */
    if (chance(r, 0.5)) add_call(cs, F_GET_CONTACT_MESH_SIZE);
    add_call(cs, F_GET_CONTACT_MESH);
    if (chance(r, 0.5)) add_call(cs, F_GET_CONTACT_ELEMENT_PAIRS);
    if (chance(r, 0.5)) add_call(cs, F_GET_CONTACT_ELEMENT_APEXES);
    if (chance(r, 0.5)) call_i(cs, F_GET_CONTACT_PAIR_BODIES, 0, 0);
  }
  if (chance(r, 0.2)) call_i(cs, F_SET_ORDERING, rint_(r, 3), rint_(r, 2));
  if (literal) {
    int refac = rint_(r, 2);
    solve_contact_call(cs, 0, 1, chance(r, 0.3) ? 2 : 50, refac, 0, 0);
    if (chance(r, 0.5)) result_getters(r, cs, 1);
    solve_contact_call(cs, 0, 1, 50, 1 - refac, 0, 0);
  } else if (chance(r, 0.15)) {
    add_call(cs, F_SOLVE_CONTACT)->in[0].null_ = 1;
  } else {
    int law = chance(r, 0.15), test = chance(r, 0.15), refac = chance(r, 0.3);
    solve_contact_call(cs, law, test, 50, refac, chance(r, 0.1) ? 1e9 : 0, chance(r, 0.1) ? 0.5 : 0);
  }
  result_getters(r, cs, 1);
  if (chance(r, 0.5)) call_i(cs, F_TWIN, 4, 0); /* (pristine: the automatic weighting = its family forced) */
  if (cut && chance(r, 0.5)) call_i(cs, F_TWIN, 5, nx2 == nx); /* (pristine: the interface cut = uncut; nodes matching) */
  free(lower);
  free(upper);
  return fam;
}

/* Axisymmetric bodies (TFEM_PLANE_MODE_AXISYMMETRIC): the section
 * [x0, x0 + 1] x [0, 1] of a ring (x the radius, y the axis), nx x ny
 * cells, E 1000, nu 0.3, tempering off, u_z = 0 on the bottom (tag 3),
 * pulled along the axis by a traction p = 10 on the top (tag 4): the
 * uniform stress sigma_zz = p, u_z = p y / E, u_r = -nu p r / E and a hoop
 * stress of 0, exact for the ring element (linear fields). 30% of the
 * solid and hollow ones are two bodies (x beyond x0 + 1/2: body 2, the
 * same material), and then body 2 made plane strain is refused (a model is
 * axisymmetric in every body or in none). Variants: 0 solid (x0 = 0) with
 * u_r = 0 on the axis (tag 1): OK, the closed form; 1 hollow (x0 = 1/2):
 * OK, the closed form; 2 solid, the axis left free: the solve refused
 * (INVALID_ARGUMENT); 3 solid, u_r = 1e-3 on the axis: refused alike; 4
 * across the axis (x0 = -1/4): tfem_set_material after the mesh refused
 * (INVALID_MATERIAL; the body then has no material), or before it accepted
 * and the solve refused (INVALID_MATERIAL). The material comes before the
 * mesh in 30% of the cases. The solve is tfem_solve or (40%)
 * tfem_solve_adaptive (a uniform stress: the estimate is round-off, one
 * cycle, the mesh kept), refused alike. */
static void scene_axisym(rng_t *r, case_t *cs, ctx_t *cx, mesh_t *m) {
  int variant = (int[]){0, 0, 0, 1, 1, 2, 2, 3, 4, 4}[rint_(r, 10)];
  double x0 = variant == 1 ? 0.5 : variant == 4 ? -0.25 : 0.0, p = 10.0, e = 1000.0, nu = 0.3;
  int nx = rrange(r, 1, 6), ny = rrange(r, 1, 6), base = rint_(r, 2);
  int two = variant <= 1 && chance(r, 0.3), before = chance(r, 0.3);
  double xs[8], ys[8];
  for (int i = 0; i <= nx; ++i) xs[i] = i == nx ? x0 + 1.0 : x0 + (double)i / nx;
  for (int j = 0; j <= ny; ++j) ys[j] = (double)j / ny;
  int rows[64];
  add_grid(m, xs, nx + 1, ys, ny + 1, 1, NAN, rows);
  if (two)
    for (int t = 0; t < m->nt; ++t) {
      const int *v = &m->tri[3 * t];
      if (m->xy[2 * v[0]] + m->xy[2 * v[1]] + m->xy[2 * v[2]] > 3.0 * (x0 + 0.5)) m->body[t] = 2;
    }
  int *be, nb = boundary_edges(m, &be);
  for (int k = 0; k < nb; ++k) {
    const double *a = &m->xy[2 * be[2 * k]], *b = &m->xy[2 * be[2 * k + 1]];
    int tag = a[0] == x0 && b[0] == x0 ? 1 : a[0] == x0 + 1.0 && b[0] == x0 + 1.0 ? 2 : a[1] == 0 && b[1] == 0 ? 3 : 4;
    mesh_edge(m, be[2 * k], be[2 * k + 1], tag);
  }
  free(be);
  *cx = (ctx_t){m->nn, m->nt, base, {1, 2, 3, 4}, 4, {1, 2}, two ? 2 : 1, m, 0, 0, 0, {0}};
  int want_mat = variant == 4 && !before ? TFEM_STATUS_INVALID_MATERIAL : TFEM_STATUS_OK;
  for (int b = 1; b <= 1 + two && before; ++b) {
    call_t *c = call_i(cs, F_SET_MATERIAL, b, TFEM_PLANE_MODE_AXISYMMETRIC);
    c->dv[0] = e, c->dv[1] = nu;
  }
  set_mesh_call(cs, m, base);
  edges_calls(r, cs, m, base);
  for (int b = 1; b <= 1 + two && !before; ++b) {
    call_t *c = call_i(cs, F_SET_MATERIAL, b, TFEM_PLANE_MODE_AXISYMMETRIC);
    c->dv[0] = e, c->dv[1] = nu, c->want = 1 + want_mat;
  }
  if (two && chance(r, 0.5)) { /* a plane body among axisymmetric ones */
    call_t *c = call_i(cs, F_SET_MATERIAL, 2, chance(r, 0.5) ? TFEM_PLANE_MODE_STRAIN : TFEM_PLANE_MODE_STRESS);
    c->dv[0] = e, c->dv[1] = nu, c->want = 1 + TFEM_STATUS_INVALID_MATERIAL;
  }
  call_i(cs, F_SET_TEMPERING, TFEM_TEMPERING_MODE_OFF, 0);
  fixc(cs, F_FIX_EDGES, 3, TFEM_COMPONENT_Y, 0.0);
  if (variant == 0 || variant == 4) fixc(cs, F_FIX_EDGES, 1, TFEM_COMPONENT_X, 0.0);
  if (variant == 3) fixc(cs, F_FIX_EDGES, 1, TFEM_COMPONENT_X, 1e-3);
  load2(cs, F_ADD_TRACTION, 4, 0.0, p);
  int ok = variant <= 1;
  call_t *sv;
  if (chance(r, 0.4)) {
    sv = add_call(cs, F_SOLVE_ADAPTIVE);
    sv->in[0].null_ = 1;
    sv->iv[4] = rint_(r, 2);
    sv->iv[5] = rrange(r, 1, 3);
    sv->iv[6] = 2000;
    sv->dv[2] = (double[]){0.05, 0.1, 1e-3}[rint_(r, 3)];
    sv->expect = 1; /* (one cycle: the estimate of a uniform stress is round-off) */
  } else {
    sv = add_call(cs, F_SOLVE);
  }
  sv->want = 1 + (ok ? TFEM_STATUS_OK : variant == 4 ? TFEM_STATUS_INVALID_MATERIAL : TFEM_STATUS_INVALID_ARGUMENT);
  result_getters(r, cs, 0);
  int corner = rows[ny * (nx + 1) + nx];
  for (int k = 0; k < 2; ++k) {
    call_t *d = add_call(cs, F_GET_DISPLACEMENTS);
    d->want = 1 + (ok ? TFEM_STATUS_OK : TFEM_STATUS_INVALID_STATE);
    d->oracle = ok;
    d->or_node = corner;
    d->or_comp = k == 0 ? TFEM_COMPONENT_Y : TFEM_COMPONENT_X;
    d->or_expect = k == 0 ? p / e : -nu * p * (x0 + 1.0) / e;
    d->or_rtol = 1e-6;
  }
  call_t *h = add_call(cs, F_GET_OUT_OF_PLANE);
  h->want = 1 + (ok ? TFEM_STATUS_OK : TFEM_STATUS_INVALID_STATE);
  h->oracle = ok ? 2 : 0;
  h->or_expect = p;
  h->or_rtol = 1e-9;
  if (chance(r, 0.3)) { /* the ring element of a triangle of the section */
    call_t *k = add_call(cs, F_ELEMENT_STIFFNESS);
    k->iv[0] = TFEM_PLANE_MODE_AXISYMMETRIC;
    k->dv[0] = e, k->dv[1] = nu, k->dv[2] = chance(r, 0.5) ? 0.0 : 1e-3;
    double xy[6];
    for (int q = 0; q < 3; ++q) xy[2 * q] = m->xy[2 * m->tri[q]], xy[2 * q + 1] = m->xy[2 * m->tri[q] + 1];
    in_set(k, 0, xy, 6, sizeof(double));
    k->want = 1 + (x0 < 0 ? TFEM_STATUS_INVALID_ARGUMENT : TFEM_STATUS_OK);
  }
  if (chance(r, 0.2)) add_call(cs, F_GET_CONTACT_WEIGHTING);
  if (chance(r, 0.2)) call_i(cs, F_SET_CONTACT_WEIGHTING, TFEM_CONTACT_WEIGHTING_MORTAR, 0)->want =
      1 + (variant == 4 && !before ? TFEM_STATUS_OK : TFEM_STATUS_INVALID_ARGUMENT);
}

/* The adaptive solve (tfem_solve_adaptive, tfem_get_adapt_cycles) on the
 * unit square of scene_square (a uniform field: when its exact solution is
 * checked, one cycle, the mesh kept) or, 60% of the squares, with a force
 * at the loaded corner too (refined), or on the seed's two blocks (each
 * cycle a contact solve, the pair carried over to the refined mesh): the
 * scene's first solve made adaptive, its limits cheap (max_unknowns 300 to
 * 3000, 1 to 4 cycles). Before it, sometimes, refused calls (a tolerance
 * of 0, -1, NaN, Inf; goal 2 or -1; max_unknowns 0 or -5; max_cycles 0 or
 * -1: INVALID_ARGUMENT, the model unchanged) and tfem_get_adapt_cycles
 * (INVALID_STATE); after it the cycles (the exact length, one short:
 * BUFFER_TOO_SMALL, columns NULL), the sizes, sometimes refused calls
 * again and the cycles (kept), the warnings and the scene's getters; then
 * sometimes a second adaptive solve, a plain solve of the refined mesh,
 * the first mesh set again (the cycles are kept), or, on the blocks, a
 * second adaptive solve that fails (lambda = 1e-200) and the cycles and
 * results of the first read (kept). */
/* A refused tfem_solve_adaptive: the arguments of `keep` with one made
 * bad (INVALID_ARGUMENT, the model unchanged). */
static void bad_adaptive_call(rng_t *r, case_t *cs, const call_t *keep) {
  call_t *b = add_call(cs, F_SOLVE_ADAPTIVE);
  *b = *keep;
  for (int j = 0; j < MAXIN; ++j) b->in[j].p = NULL, b->in[j].n = 0;
  for (int j = 0; j <= MAXOUT; ++j) b->saved[j] = NULL, b->saved_n[j] = 0;
  b->expect = 0;
  b->want = 1 + TFEM_STATUS_INVALID_ARGUMENT;
  switch (rint_(r, 4)) {
  case 0: b->dv[2] = (double[]){0.0, -1.0, NAN, INFINITY, -0.0}[rint_(r, 5)]; break;
  case 1: b->iv[4] = chance(r, 0.5) ? 2 : -1; break;
  case 2: b->iv[6] = chance(r, 0.5) ? 0 : -5; break;
  default: b->iv[5] = chance(r, 0.5) ? 0 : -1; break;
  }
}

static void scene_adaptive(rng_t *r, case_t *cs, ctx_t *cx, mesh_t *m) {
  int blocks = chance(r, 0.4), corner = !blocks && chance(r, 0.6);
  if (blocks) scene_two_blocks(r, cs, cx, m, 0);
  else scene_square(r, cs, cx, m, 0, 0);
  int si = -1;
  for (int i = cs->n - 1; i >= 0; --i) {
    if (cs->c[i].fn == F_TWIN) case_delete(cs, i);
    else if (cs->c[i].fn == F_SOLVE || cs->c[i].fn == F_SOLVE_CONTACT) si = i;
  }
  if (si < 0) return;
  int uniform = 0;
  for (int i = 0; i < cs->n; ++i) {
    uniform |= cs->c[i].oracle == 1;
    if (corner) cs->c[i].oracle = 0;
  }
  uniform &= !corner;
  if (corner) { /* a force at the loaded corner (node 1 up from the last, whatever the base: the grid's last) */
    case_t one = {0};
    call_t *f = call_i(&one, F_ADD_NODAL_FORCE, cx->base + m->nn - 1, 0);
    f->dv[0] = 0.0, f->dv[1] = 5.0;
    case_insert_copy(cs, si, f);
    case_free(&one);
    ++si;
  }
  call_t *a = &cs->c[si];
  int was = a->fn;
  a->fn = F_SOLVE_ADAPTIVE;
  if (was == F_SOLVE) a->in[0].null_ = 1;
  a->iv[4] = chance(r, 0.7) ? TFEM_ADAPT_GOAL_ENERGY : TFEM_ADAPT_GOAL_COMPLIANCE;
  a->iv[5] = rrange(r, 1, 4);
  a->iv[6] = (int[]){300, 1000, 3000}[rint_(r, 3)];
  a->dv[2] = (double[]){0.2, 0.1, 0.05, 1e-3, 1e-300}[rint_(r, 5)];
  /* The blocks' contact options with the literal inversion test: the
   * header (TFEM_INVERSION_TEST_LITERAL) says its second-order term "can
   * exceed the penalty penetration on fine meshes and make the loop
   * cycle", and the refinement makes finer meshes, so the adaptive solve
   * may be NOT_CONVERGED (the model then as it was given, no cycles): no
   * status is demanded of it, nor of the calls whose status follows from
   * it (oracle_adapt and oracle_adapt_cycles still check them against
   * what it did), as of the frictional steps that may cycle. */
  int may_cycle = blocks && !a->in[0].null_ && a->iv[1] == TFEM_INVERSION_TEST_LITERAL;
  int ok_after = may_cycle ? 0 : 1 + TFEM_STATUS_OK;
  a->want = ok_after;
  a->expect = uniform && a->dv[2] >= 1e-3 ? 1 : 0;
  call_t keep = *a; /* (its scalar arguments, for the calls made from it) */
  /* after it (inserted in order at si + 1) */
  case_t after = {0};
  call_t *c = add_call(&after, F_GET_ADAPT_CYCLES);
  c->want = ok_after;
  if (chance(r, 0.3)) {
    c = add_call(&after, F_GET_ADAPT_CYCLES);
    for (int j = 0; j < 3; ++j) c->out[j].null_ = chance(r, 0.4);
    if (chance(r, 0.5)) {
      c->out[0] = (out_spec){LS_REL, -1, c->out[0].null_, 0, 0, 0};
      c->want = may_cycle ? 0 : 1 + TFEM_STATUS_BUFFER_TOO_SMALL;
    }
  }
  add_call(&after, F_GET_SIZES);
  if (chance(r, 0.4)) { /* refused after it: the cycles stay */
    for (int k = rrange(r, 1, 2); k > 0; --k) bad_adaptive_call(r, &after, &keep);
    add_call(&after, F_GET_ADAPT_CYCLES)->want = ok_after;
  }
  if (chance(r, 0.5)) add_call(&after, F_WARNING_COUNT);
  if (chance(r, 0.3)) call_i(&after, F_GET_WARNING, 0, 0)->out[0] = (out_spec){LS_FIXED, 512, 0, 0, 0, 0};
  for (int i = 0; i < after.n; ++i) case_insert_copy(cs, si + 1 + i, &after.c[i]);
  case_free(&after);
  /* before it: refusals, and no cycles yet */
  case_t pre = {0};
  if (chance(r, 0.3)) add_call(&pre, F_GET_ADAPT_CYCLES)->want = 1 + TFEM_STATUS_INVALID_STATE;
  for (int k = chance(r, 0.4) ? rrange(r, 1, 2) : 0; k > 0; --k) bad_adaptive_call(r, &pre, &keep);
  for (int i = 0; i < pre.n; ++i) case_insert_copy(cs, si + i, &pre.c[i]);
  case_free(&pre);
  /* then */
  int v = rint_(r, 10);
  if (v < 3) { /* a second adaptive solve, from the refined mesh */
    c = add_call(cs, F_SOLVE_ADAPTIVE);
    *c = keep;
    for (int j = 0; j < MAXIN; ++j) c->in[j].p = NULL, c->in[j].n = 0;
    for (int j = 0; j <= MAXOUT; ++j) c->saved[j] = NULL;
    c->iv[4] = 1 - keep.iv[4];
    c->iv[5] = rrange(r, 1, 2);
    c->dv[2] = 0.1;
    c->expect = keep.expect;
    add_call(cs, F_GET_ADAPT_CYCLES);
    result_getters(r, cs, blocks);
  } else if (v < 5) { /* a plain solve of the refined mesh */
    c = add_call(cs, blocks ? F_SOLVE_CONTACT : F_SOLVE);
    c->in[0].null_ = 1;
    c->want = 1 + TFEM_STATUS_OK;
    add_call(cs, F_GET_DISPLACEMENTS);
    if (chance(r, 0.5)) add_call(cs, F_GET_OUT_OF_PLANE);
    add_call(cs, F_GET_ADAPT_CYCLES)->want = ok_after;
  } else if (v < 6) { /* the first mesh again: the cycles stay */
    set_mesh_call(cs, m, cx->base);
    add_call(cs, F_GET_SIZES);
    add_call(cs, F_GET_ADAPT_CYCLES)->want = ok_after;
  } else if (v < 7 && blocks) {
    /* a second adaptive solve that fails (lambda = 1e-200: SINGULAR, seen
     * on these blocks): the cycles and results of the first stay (a failed
     * call leaves the model as it was) */
    c = add_call(cs, F_SOLVE_ADAPTIVE);
    *c = keep;
    for (int j = 0; j < MAXIN; ++j) c->in[j].p = NULL, c->in[j].n = 0;
    for (int j = 0; j <= MAXOUT; ++j) c->saved[j] = NULL, c->saved_n[j] = 0;
    c->in[0].null_ = 0;
    c->iv[0] = c->iv[1] = c->iv[3] = 0, c->iv[2] = 50, c->dv[0] = 0.0, c->dv[1] = 1e-200;
    c->want = c->expect = 0;
    add_call(cs, F_GET_ADAPT_CYCLES);
    add_call(cs, F_GET_DISPLACEMENTS);
    if (chance(r, 0.5)) add_call(cs, F_GET_CONTACT_PRESSURE);
    if (chance(r, 0.5)) add_call(cs, F_WARNING_COUNT);
  }
}

/* A circle for tfem_set_boundary_circle on the edges tagged `tag` of a
 * scene's mesh (0-based), as (x, y, radius): the circumcircle of the tag's
 * first edge and its first node not in line with it (the circle of an arc:
 * accepted), else a circle through the first edge's ends, its centre on
 * their bisector at the edge's midpoint (a chord through the centre), 0.5,
 * 2 or 1e3 lengths away, or so far (1e8, 1e160) that every node of the tag
 * is within its tolerance of 1e-6 of the radius; then sometimes the radius
 * off by 5e-7 of it (accepted) or 2e-6 (refused). 0 if no edge has the tag. */
static int circle_of_tag(rng_t *r, const mesh_t *m, int tag, double out[3]) {
  int e0 = -1;
  for (int e = 0; e < m->ne && e0 < 0; ++e)
    if (m->tag[e] == tag) e0 = e;
  if (e0 < 0) return 0;
  const double *a = &m->xy[2 * m->edge[2 * e0]], *b = &m->xy[2 * m->edge[2 * e0 + 1]];
  double ab[2] = {b[0] - a[0], b[1] - a[1]}, l2 = ab[0] * ab[0] + ab[1] * ab[1];
  int third = -1;
  for (int e = 0; e < m->ne && third < 0; ++e)
    for (int k = 0; k < 2 && m->tag[e] == tag && third < 0; ++k) {
      const double *c = &m->xy[2 * m->edge[2 * e + k]];
      if (fabs(ab[0] * (c[1] - a[1]) - ab[1] * (c[0] - a[0])) > 1e-9 * l2) third = m->edge[2 * e + k];
    }
  if (third >= 0 && chance(r, 0.85)) {
    const double *c = &m->xy[2 * third];
    double bx = b[0] - a[0], by = b[1] - a[1], cx = c[0] - a[0], cy = c[1] - a[1];
    double d = 2.0 * (bx * cy - by * cx), b2 = bx * bx + by * by, c2 = cx * cx + cy * cy;
    out[0] = a[0] + (cy * b2 - by * c2) / d;
    out[1] = a[1] + (bx * c2 - cx * b2) / d;
  } else {
    double t = (double[]){0.0, 0.5, 2.0, 1e3, 1e8, 1e160}[rint_(r, 6)] * (chance(r, 0.5) ? 1 : -1);
    out[0] = 0.5 * (a[0] + b[0]) - t * ab[1];
    out[1] = 0.5 * (a[1] + b[1]) + t * ab[0];
  }
  out[2] = hypot(a[0] - out[0], a[1] - out[1]);
  int v = rint_(r, 10);
  if (v == 0) out[2] *= 1.0 + 5e-7;
  else if (v == 1) out[2] *= 1.0 + 2e-6;
  return 1;
}

/* tfem_set_boundary_circle of a scene, the status it must return plus 1
 * (0: not checked). */
static call_t *circle_call(case_t *cs, int tag, double x, double y, double radius, int want) {
  call_t *c = add_call(cs, F_SET_BOUNDARY_CIRCLE);
  c->iv[0] = tag;
  c->dv[0] = x, c->dv[1] = y, c->dv[2] = radius;
  c->want = want;
  return c;
}

/* A quarter of a ring about (x0, y0), r1 <= r <= r1 + w, the angle from 0
 * to 90 degrees in na cells and the radius in nr, body 1 (plane strain or
 * stress), x = x0 (tag 1, u_x = 0), y = y0 (tag 2, u_y = 0), the outer arc
 * tag 3, the inner arc tag 4 pressed by 10. The arcs' circles are declared
 * (each 80%; the inner one 20% of those 5e-7 of its radius off: accepted),
 * and refused around them as the header says: a circle before the mesh
 * (INVALID_STATE) or before the edges, on a tag of no edge, with a centre
 * or radius not finite, a radius <= 0, the radius off by 2e-6 of it or the
 * centre by 1e-2 of it, the outer circle on the inner arc, a circle on a
 * straight side (INVALID_ARGUMENT); a straight side of one edge sometimes on a
 * circle through its ends (its centre maybe far away: accepted). Then a
 * plain solve (50%) with a circle declared after it (the results kept),
 * and an adaptive solve: the nodes it adds on a declared arc lie on its
 * circle (oracle_circle_nodes), its report and its mesh as the other
 * adaptive scenes'; sometimes a second one (the circles carried to the
 * refined mesh). */
static void scene_ring(rng_t *r, case_t *cs, ctx_t *cx, mesh_t *m) {
  static const double centres[][2] = {{0.0, 0.0}, {0.5, -0.25}, {-3.0, 7.0}, {1e3, 1e3}};
  const double *o = centres[rint_(r, 4)];
  double r1 = (double[]){1.0, 0.5, 2.0}[rint_(r, 3)], w = (double[]){1.0, 0.5}[rint_(r, 2)];
  int na = rrange(r, 1, 6), nr = rrange(r, 1, 3), base = rint_(r, 2);
  int plane = chance(r, 0.7) ? TFEM_PLANE_MODE_STRAIN : TFEM_PLANE_MODE_STRESS;
  for (int j = 0; j <= na; ++j)
    for (int i = 0; i <= nr; ++i) {
      double rad = r1 + w * i / nr, a = 0.5 * M_PI * j / na;
      mesh_node(m, j == na ? o[0] : o[0] + rad * cos(a), j == 0 ? o[1] : o[1] + rad * sin(a));
    }
#define RID(i, j) ((j) * (nr + 1) + (i))
  for (int j = 0; j < na; ++j)
    for (int i = 0; i < nr; ++i) {
      mesh_tri(m, RID(i, j), RID(i + 1, j), RID(i + 1, j + 1), 1);
      mesh_tri(m, RID(i, j), RID(i + 1, j + 1), RID(i, j + 1), 1);
    }
  for (int i = nr; i > 0; --i) mesh_edge(m, RID(i, na), RID(i - 1, na), 1);
  for (int i = 0; i < nr; ++i) mesh_edge(m, RID(i, 0), RID(i + 1, 0), 2);
  for (int j = 0; j < na; ++j) {
    mesh_edge(m, RID(nr, j), RID(nr, j + 1), 3);
    mesh_edge(m, RID(0, j + 1), RID(0, j), 4);
  }
#undef RID
  *cx = (ctx_t){m->nn, m->nt, base, {1, 2, 3, 4}, 4, {1}, 1, m, 0, 0, 0, {0}};
  const int ok = 1 + TFEM_STATUS_OK, refused = 1 + TFEM_STATUS_INVALID_ARGUMENT;
  double r2 = r1 + w;
  if (chance(r, 0.15)) circle_call(cs, 3, o[0], o[1], r2, 1 + TFEM_STATUS_INVALID_STATE);
  set_mesh_call(cs, m, base);
  if (chance(r, 0.2)) circle_call(cs, 4, o[0], o[1], r1, refused); /* (no edge yet) */
  edges_calls(r, cs, m, base);
  material(cs, 1, 1000.0, 0.3, plane);
  fixc(cs, F_FIX_EDGES, 1, TFEM_COMPONENT_X, 0.0);
  fixc(cs, F_FIX_EDGES, 2, TFEM_COMPONENT_Y, 0.0);
  call_i(cs, F_ADD_PRESSURE, 4, 0)->dv[0] = 10.0;
  int outer = chance(r, 0.8), inner = chance(r, 0.8);
  /* refusals, before and after the declarations */
  int nbad = chance(r, 0.6) ? rrange(r, 1, 4) : 0, at_bad = rint_(r, 2);
  for (int pass = 0; pass < 2; ++pass) {
    if (pass == 1) {
      if (outer) circle_call(cs, 3, o[0], o[1], r2, ok);
      if (inner) circle_call(cs, 4, o[0], o[1], chance(r, 0.2) ? r1 * (1.0 + 1e-6 * 0.5) : r1, ok);
    }
    if (pass != at_bad) continue;
    for (int k = 0; k < nbad; ++k) {
      int tag = chance(r, 0.5) ? 3 : 4;
      double x = o[0], y = o[1], rad = tag == 3 ? r2 : r1;
      switch (rint_(r, 7)) {
      case 0:
        if (chance(r, 0.5)) x = (double[]){NAN, INFINITY, -INFINITY}[rint_(r, 3)];
        else y = (double[]){NAN, INFINITY, -INFINITY}[rint_(r, 3)];
        break;
      case 1: rad = (double[]){0.0, -0.0, -rad, NAN, INFINITY, -INFINITY, -DBL_MAX}[rint_(r, 7)]; break;
      case 2: rad *= 1.0 + (chance(r, 0.5) ? 2e-6 : -2e-6); break;
      case 3: tag = 4, rad = r2; break;
      case 4: tag = (int[]){99, 0, -1, INT_MIN, 5}[rint_(r, 5)]; break;
      case 5: tag = rrange(r, 1, 2); break;
      default: x += 0.01 * rad; break;
      }
      circle_call(cs, tag, x, y, rad, refused);
    }
  }
  if (nr == 1 && chance(r, 0.25)) { /* a straight side of one edge on a circle through its ends (circle_of_tag) */
    double q[3];
    int tag = rrange(r, 1, 2);
    if (circle_of_tag(r, m, tag, q)) circle_call(cs, tag, q[0], q[1], q[2], 0);
  }
  if (chance(r, 0.5)) {
    add_call(cs, F_SOLVE)->want = ok;
    add_call(cs, F_GET_DISPLACEMENTS);
    if (chance(r, 0.5)) add_call(cs, F_GET_STRESSES);
    circle_call(cs, chance(r, 0.5) ? 3 : 4, o[0], o[1], chance(r, 0.5) ? r2 : r1, 0); /* (either arc: either status) */
    if (chance(r, 0.3)) circle_call(cs, 3, o[0], o[1], -1.0, refused);
    add_call(cs, F_GET_DISPLACEMENTS)->want = ok; /* (kept, bit for bit: the results_kept oracle) */
    if (chance(r, 0.5)) add_call(cs, F_GET_MATRIX);
  }
  call_t *a = add_call(cs, F_SOLVE_ADAPTIVE);
  a->in[0].null_ = 1;
  a->iv[4] = chance(r, 0.7) ? TFEM_ADAPT_GOAL_ENERGY : TFEM_ADAPT_GOAL_COMPLIANCE;
  a->iv[5] = rrange(r, 1, 4);
  a->iv[6] = (int[]){2000, 20000}[rint_(r, 2)];
  a->dv[2] = (double[]){0.1, 0.02, 1e-3}[rint_(r, 3)];
  add_call(cs, F_GET_ADAPT_CYCLES);
  result_getters(r, cs, 0);
  if (chance(r, 0.3)) { /* again, from the refined mesh */
    if (chance(r, 0.5)) circle_call(cs, 3, o[0], o[1], r2, 0);
    call_t *b = add_call(cs, F_SOLVE_ADAPTIVE);
    b->in[0].null_ = 1;
    b->iv[4] = TFEM_ADAPT_GOAL_ENERGY, b->iv[5] = rrange(r, 1, 2), b->iv[6] = 20000, b->dv[2] = 1e-3;
    add_call(cs, F_GET_SIZES);
    add_call(cs, F_GET_DISPLACEMENTS);
  }
}

/* A unit square whose middle row of nodes is lowered onto the row below:
 * a band of flat (zero-area) and inverted triangles, legal in TFEM. */
static void scene_degenerate(rng_t *r, case_t *cs, ctx_t *cx, mesh_t *m) {
  int n = 2 * rrange(r, 1, 3);
  double xs[8], ys[8];
  for (int i = 0; i <= n; ++i) xs[i] = ys[i] = (double)i / n;
  int rows[64];
  add_grid(m, xs, n + 1, ys, n + 1, 1, NAN, rows);
  double drop = (double[]){1.0, 1.0, 1.5, 0.999999}[rint_(r, 4)] / n;
  for (int i = 0; i <= n; ++i) m->xy[2 * rows[(n / 2) * (n + 1) + i] + 1] -= drop;
  int *be, nb = boundary_edges(m, &be);
  for (int e = 0; e < nb; ++e) {
    const double *p = &m->xy[2 * be[2 * e]], *q = &m->xy[2 * be[2 * e + 1]];
    int tag = p[1] == 0 && q[1] == 0 ? 3 : p[1] == 1 && q[1] == 1 ? 4 : p[0] == 0 && q[0] == 0 ? 1 : 2;
    mesh_edge(m, be[2 * e], be[2 * e + 1], tag);
  }
  free(be);
  int base = rint_(r, 2);
  *cx = (ctx_t){m->nn, m->nt, base, {1, 2, 3, 4}, 4, {1}, 1, m, 0, 0, 0, {0}};
  set_mesh_call(cs, m, base);
  edges_calls(r, cs, m, base);
  material(cs, 1, 1000.0, 0.3, rint_(r, 2));
  int mode = rint_(r, 4);
  call_i(cs, F_SET_TEMPERING, mode, 0)->dv[0] = mode == 1 ? 1.0 : mode == 2 ? (chance(r, 0.5) ? 1e-300 : 1e-3) : 0.0;
  fixc(cs, F_FIX_EDGES, 3, TFEM_COMPONENT_X, 0.0);
  fixc(cs, F_FIX_EDGES, 3, TFEM_COMPONENT_Y, 0.0);
  if (chance(r, 0.5)) load2(cs, F_ADD_TRACTION, 4, 0.0, -10.0);
  else call_i(cs, F_ADD_PRESSURE, 4, 0)->dv[0] = 10.0;
  if (chance(r, 0.4)) load2(cs, F_SET_BODY_FORCE, 1, 0.0, -1.0);
  add_call(cs, F_SOLVE);
  result_getters(r, cs, 0);
}

/* The unit square of the valid Gmsh file: tags 1 left, 2 right, 3 bottom, 4 top. */
static void scene_gmsh(rng_t *r, case_t *cs, ctx_t *cx) {
  int base = rint_(r, 2);
  *cx = (ctx_t){9, 8, base, {1, 2, 3, 4}, 4, {1}, 1, NULL, 0, 0, 0, {0}};
  call_i(cs, F_LOAD_GMSH, chance(r, 0.7) ? G_VALID : G_CLOCKWISE, base);
  material(cs, 1, 1000.0, 0.25, TFEM_PLANE_MODE_STRESS);
  call_i(cs, F_SET_TEMPERING, TFEM_TEMPERING_MODE_LAMBDA, 0)->dv[0] = 1000.0;
  fixc(cs, F_FIX_EDGES, 1, TFEM_COMPONENT_X, 0.0);
  fixc(cs, F_FIX_EDGES, 3, TFEM_COMPONENT_Y, 0.0);
  load2(cs, F_ADD_TRACTION, 2, 10.0, 0.0);
  add_call(cs, F_SOLVE);
  result_getters(r, cs, 0);
}

/* A random small mesh: random points on a coarse lattice (coincident ones
 * possible), random triangles (repeated or unused nodes possible). */

/* A call inserted at position `at` of the case (zeroed arguments). */
static call_t *insert_call(case_t *cs, int at, int fn) {
  case_t one = {0};
  add_call(&one, fn);
  for (int j = 0; j < MAXOUT; ++j) one.c[0].out[j].ls = LS_EXACT;
  case_insert_copy(cs, at, &one.c[0]);
  case_free(&one);
  return &cs->c[at];
}
static int find_call(const case_t *cs, int fn, int from) {
  for (int i = from; i < cs->n; ++i)
    if (cs->c[i].fn == fn) return i;
  return -1;
}
static call_t *friction_call(case_t *cs, int at, int pair, double mu) {
  call_t *c = insert_call(cs, at, F_SET_FRICTION);
  c->iv[0] = pair;
  c->dv[0] = mu;
  return c;
}
static void friction_getters(rng_t *r, case_t *cs) {
  add_call(cs, F_GET_CONTACT_SHEAR);
  add_call(cs, F_GET_CONTACT_FRICTION_STATE);
  add_call(cs, F_GET_CONTACT_DISSIPATION);
  if (chance(r, 0.5)) add_call(cs, F_GET_CONTACT_PRESSURE);
  if (chance(r, 0.3)) add_call(cs, F_GET_CONTACT_FORCES);
}
/* The solve_contact call of a two-blocks scene made frictionless-law (the
 * Coulomb oracle is for the frictionless law with mu per pair). */
static int frictionless_law(case_t *cs) {
  int i = find_call(cs, F_SOLVE_CONTACT, 0);
  if (i >= 0 && !cs->c[i].in[0].null_) cs->c[i].iv[0] = TFEM_CONTACT_LAW_FRICTIONLESS;
  return i;
}

/* Roles of calls in the value oracles of the step and host scenes (call_t.tag). */
enum { T_NONE, T_REF_STEP, T_REF_DISP, T_CMP_STEP, T_CMP_DISP };

static call_t *step_call(case_t *cs, double factor, int opts, int tag) {
  call_t *c = add_call(cs, F_STEP);
  c->iv[0] = TFEM_CONTACT_LAW_FRICTIONLESS;
  c->iv[1] = TFEM_INVERSION_TEST_LINEARISED;
  c->iv[2] = 50;
  c->iv[3] = 0;
  c->dv[2] = factor;
  c->in[0].null_ = !opts;
  c->tag = tag;
  return c;
}

/* A load step expected OK in a pristine scene (call_t.want), with the
 * options (opts) and refactorize set in them (refac). */
static call_t *stepc(case_t *cs, double factor, int opts, int refac, int tag) {
  call_t *c = step_call(cs, factor, opts, tag);
  if (opts) c->iv[3] = refac;
  c->want = 1 + TFEM_STATUS_OK;
  return c;
}

/* Load steps on the two blocks, under the strip weighting or (30%,
 * "mortar_steps") the mortar one (its steps frictionless, on the pairs'
 * own sides: no friction, no user contact mesh; its solve frictionless and
 * linearised): a history of steps, one repeated after tfem_revert_step and
 * after tfem_set_contact_state of the state saved before it (both must
 * give the same results bit for bit; under the mortar weighting too since
 * 56d2e1d, its state over the slave nodes' set), the state saved given to
 * a fresh model of the same problem whose first step must be that step,
 * bit for bit (F_TWIN mode 3), the state refused under the other
 * weighting (another contact mesh) and taken back under its own (the step
 * again, bit for bit), loads changed between steps, a state that is not
 * one, other options. Options with refactorize set (30% of those given),
 * accepted under both weightings since 56d2e1d (before: INVALID_ARGUMENT
 * under the strip's, "a load history condenses the contact interface"):
 * each step a contact solve from the step before's state, repeated bit for
 * bit all the same. 15% lock the interface (both contact sides wholly
 * prescribed, a contact that couples no free unknown: before 56d2e1d
 * refused by a step, INVALID_ARGUMENT): the contact solve first, and a
 * step at factor 1 must give its displacements to the bit, sometimes
 * reverted (the solve's displacements back, to the bit). 30% end with a
 * step whose field overflows (a pressure of 1e10 more, factor 1e300):
 * NUMERICAL_FAILURE under both weightings since 56d2e1d (the mortar's
 * before), sometimes a factor beyond 1e300 or not finite
 * (INVALID_ARGUMENT), then a small step (OK: the failed ones changed
 * nothing, which the replay checks). The statuses are the scene's
 * expectation when pristine (call_t.want). */
static void scene_steps(rng_t *r, case_t *cs, ctx_t *cx, mesh_t *m) {
  int mortar = chance(r, 0.3);
  if (mortar) cs->kind = "mortar_steps";
  scene_two_blocks(r, cs, cx, m, mortar ? 0 : chance(r, 0.3));
  int user = find_call(cs, F_ADD_CONTACT_PAIR_WITH_MESH, 0) >= 0;
  int locked = chance(r, 0.15);
  int solve = find_call(cs, F_SOLVE_CONTACT, 0);
  if (locked) { /* both contact sides wholly prescribed (0, as on x = 1/2) */
    int at = find_call(cs, F_ADD_PRESSURE, 0);
    for (int k = 0; k < 4 && at >= 0; ++k) {
      call_t *f = insert_call(cs, at++, F_FIX_EDGES);
      f->iv[0] = k < 2 ? 2 : 3;
      f->iv[1] = k % 2 ? TFEM_COMPONENT_Y : TFEM_COMPONENT_X;
      f->dv[0] = 0.0;
    }
    solve = find_call(cs, F_SOLVE_CONTACT, 0);
  }
  if (solve >= 0 && locked) {
    cs->c[solve].in[0].null_ = 1; /* (the options of the step that repeats it) */
  } else if (solve >= 0 && mortar && !cs->c[solve].in[0].null_) {
    cs->c[solve].iv[0] = TFEM_CONTACT_LAW_FRICTIONLESS;
    cs->c[solve].iv[1] = TFEM_INVERSION_TEST_LINEARISED;
  }
  if (!locked && chance(r, 0.6)) /* no contact solve before the steps */
    for (int i = 0; i < cs->n; ++i)
      if (cs->c[i].fn == F_SOLVE_CONTACT) {
        while (cs->n > i) case_delete(cs, cs->n - 1);
        break;
      }
  if (mortar) { /* before the mesh (the model's), or right before the solve or the first step */
    int at = chance(r, 0.5) ? 0 : find_call(cs, F_SOLVE_CONTACT, 0);
    insert_call(cs, at >= 0 ? at : cs->n, F_SET_CONTACT_WEIGHTING)->iv[0] = TFEM_CONTACT_WEIGHTING_MORTAR;
  }
  solve = find_call(cs, F_SOLVE_CONTACT, 0);
  if (locked && solve >= 0) {
    /* the interface couples no free unknown: a step is the contact solve
     * of its scaled loads, at factor 1 the solve's field to the bit */
    cs->c[solve].tag = T_REF_STEP;
    add_call(cs, F_GET_DISPLACEMENTS)->tag = T_REF_DISP;
    stepc(cs, 1.0, 0, 0, T_NONE);
    add_call(cs, F_GET_DISPLACEMENTS)->tag = T_CMP_DISP;
    if (chance(r, 0.5)) { /* reverted as any step: the solve's results back, to the bit */
      add_call(cs, F_REVERT_STEP)->want = 1 + TFEM_STATUS_OK;
      add_call(cs, F_GET_DISPLACEMENTS)->tag = T_CMP_DISP;
    }
  }
  int opts = chance(r, 0.5), refac = opts && chance(r, 0.3);
  double a1 = chance(r, 0.5) ? 0.5 : 0.25, a2 = chance(r, 0.8) ? 1.0 : 2.0;
  int friction = !mortar && chance(r, 0.35);
  if (friction) { /* a frictional history: repeated bit for bit too */
    frictionless_law(cs);
    friction_call(cs, cs->n, 0, (double[]){0.1, 0.3, 0.05}[rint_(r, 3)]);
    if (chance(r, 0.5)) load2(cs, F_ADD_TRACTION, 4, (double[]){1e6, -2e6}[rint_(r, 2)], 0.0);
  }
  stepc(cs, a1, opts, refac, T_NONE);
  if (chance(r, 0.3)) result_getters(r, cs, 1);
  else add_call(cs, F_GET_DISPLACEMENTS);
  add_call(cs, F_GET_CONTACT_STATE_SIZE)->want = 1 + TFEM_STATUS_OK;
  add_call(cs, F_GET_CONTACT_STATE)->want = 1 + TFEM_STATUS_OK;
  stepc(cs, a2, opts, refac, T_REF_STEP);
  add_call(cs, F_GET_DISPLACEMENTS)->tag = T_REF_DISP;
  if (chance(r, 0.5)) /* (per element of B: refused under the mortar weighting) */
    add_call(cs, F_GET_CONTACT_ACTIVE)->want = 1 + (mortar ? TFEM_STATUS_INVALID_STATE : TFEM_STATUS_OK);
  if (chance(r, 0.5)) call_i(cs, F_TWIN, 3, 0); /* the state in a fresh model: the same step */
  add_call(cs, F_REVERT_STEP)->want = 1 + TFEM_STATUS_OK;
  if (chance(r, 0.3)) add_call(cs, F_GET_DISPLACEMENTS);
  stepc(cs, a2, opts, refac, T_CMP_STEP);
  add_call(cs, F_GET_DISPLACEMENTS)->tag = T_CMP_DISP;
  call_t *c = add_call(cs, F_SET_CONTACT_STATE); /* the state after step a1 */
  c->iv[0] = 0;
  c->want = 1 + TFEM_STATUS_OK;
  stepc(cs, a2, opts, refac, T_CMP_STEP);
  add_call(cs, F_GET_DISPLACEMENTS)->tag = T_CMP_DISP;
  if (!user && chance(r, 0.3)) {
    /* under the other family the state belongs to another contact mesh
     * (refused, INVALID_ARGUMENT); under its own again it is taken, and
     * the step from it is the same, bit for bit. The straight blocks'
     * family under the automatic weighting (the default) is the strip's:
     * a state read under one is taken under the other */
    int automatic = chance(r, 0.5);
    int own = mortar ? TFEM_CONTACT_WEIGHTING_MORTAR
                     : automatic ? TFEM_CONTACT_WEIGHTING_AUTO : TFEM_CONTACT_WEIGHTING_STRIP;
    int other = !mortar ? TFEM_CONTACT_WEIGHTING_MORTAR
                        : automatic ? TFEM_CONTACT_WEIGHTING_AUTO : TFEM_CONTACT_WEIGHTING_STRIP;
    /* (a frictional history: the mortar weighting is refused where it is
     * set, naming the pair, since dc75b81; the model unchanged takes the
     * state) */
    int unserved = friction && other == TFEM_CONTACT_WEIGHTING_MORTAR;
    call_i(cs, F_SET_CONTACT_WEIGHTING, other, 0)->want =
        1 + (unserved ? TFEM_STATUS_INVALID_ARGUMENT : TFEM_STATUS_OK);
    c = add_call(cs, F_SET_CONTACT_STATE);
    c->iv[0] = 0;
    c->want = 1 + (unserved ? TFEM_STATUS_OK : TFEM_STATUS_INVALID_ARGUMENT);
    call_i(cs, F_SET_CONTACT_WEIGHTING, own, 0)->want = 1 + TFEM_STATUS_OK;
    c = add_call(cs, F_SET_CONTACT_STATE);
    c->iv[0] = 0;
    c->want = 1 + TFEM_STATUS_OK;
    stepc(cs, a2, opts, refac, T_CMP_STEP);
    add_call(cs, F_GET_DISPLACEMENTS)->tag = T_CMP_DISP;
  }
  if (chance(r, 0.3)) { /* once per step */
    add_call(cs, F_REVERT_STEP)->want = 1 + TFEM_STATUS_OK;
    add_call(cs, F_REVERT_STEP)->want = 1 + TFEM_STATUS_INVALID_STATE;
  }
  if (chance(r, 0.4)) {
    c = add_call(cs, F_SET_CONTACT_STATE); /* not a state, or a damaged one */
    c->iv[0] = rrange(r, 1, 5);
    c->iv[2] = rint_(r, 1000);
    c->want = 1 + TFEM_STATUS_INVALID_ARGUMENT;
  }
  int fx = -1;
  for (int i = 0; i < cs->n; ++i)
    if (cs->c[i].fn == F_FIX && cs->c[i].iv[1] == TFEM_COMPONENT_X) fx = i;
  if (fx >= 0 && chance(r, 0.35)) { /* a non-proportional history: a prescribed value moved */
    fixc(cs, F_SET_PRESCRIBED, cs->c[fx].iv[0], TFEM_COMPONENT_X, (double[]){1e-5, -1e-5, 0.0}[rint_(r, 3)]);
    cs->c[cs->n - 1].want = 1 + TFEM_STATUS_OK;
    if (chance(r, 0.3)) fixc(cs, F_SET_PRESCRIBED, cs->c[fx].iv[0], TFEM_COMPONENT_Y, 1e-5); /* not prescribed */
    stepc(cs, 1.0, opts, refac, T_REF_STEP)->want = friction ? 0 : 1; /* (with friction it may cycle) */
    if (friction) friction_getters(r, cs);
    add_call(cs, F_GET_DISPLACEMENTS)->tag = T_REF_DISP;
    add_call(cs, F_REVERT_STEP)->want = 1 + TFEM_STATUS_OK;
    stepc(cs, 1.0, opts, refac, T_CMP_STEP)->want = friction ? 0 : 1;
    add_call(cs, F_GET_DISPLACEMENTS)->tag = T_CMP_DISP;
  } else if (chance(r, 0.5)) { /* a non-proportional history */
    call_i(cs, F_ADD_PRESSURE, 4, 0)->dv[0] = 5e6;
    double a = chance(r, 0.5) ? 1.5 : -0.5;
    /* (-0.5: a free body, may fail; with friction a new path may cycle) */
    stepc(cs, a, opts, refac, T_NONE)->want = a > 0 && !friction ? 1 + TFEM_STATUS_OK : 0;
  } else {
    stepc(cs, 1.5, !opts, !opts && chance(r, 0.3), T_NONE)->want = friction ? 0 : 1; /* other options: a new history */
  }
  if (chance(r, 0.5)) result_getters(r, cs, 1);
  else add_call(cs, F_GET_DISPLACEMENTS), add_call(cs, F_GET_CONTACT_REPORT);
  if (friction) friction_getters(r, cs);
  add_call(cs, F_GET_CONTACT_STATE_SIZE)->want = 1 + TFEM_STATUS_OK;
  if (chance(r, 0.3)) {
    /* a step whose field would overflow: refused, NUMERICAL_FAILURE, the
     * model unchanged (the replay); a factor beyond 1e300 or not finite:
     * INVALID_ARGUMENT; then a step of the same loads that fits */
    call_i(cs, F_ADD_PRESSURE, 4, 0)->dv[0] = 1e10;
    stepc(cs, 1e300, opts, refac, T_NONE)->want = 1 + TFEM_STATUS_NUMERICAL_FAILURE;
    if (chance(r, 0.5))
      stepc(cs, (double[]){2e300, INFINITY, NAN, -DBL_MAX}[rint_(r, 4)], opts, refac, T_NONE)->want =
          1 + TFEM_STATUS_INVALID_ARGUMENT;
    stepc(cs, 1e-3, opts, refac, T_NONE)->want = friction ? 0 : 1; /* (with friction a new path may cycle) */
    add_call(cs, F_GET_DISPLACEMENTS);
    if (chance(r, 0.5)) add_call(cs, F_GET_CONTACT_REPORT);
  }
}

/* Coulomb friction on the two blocks: tfem_set_friction refused (negative,
 * NaN or infinite mu, an unknown pair) and accepted, sometimes a shear
 * traction on the top so that elements slip; the friction getters after
 * the solve (Coulomb's law per element, oracle_coulomb); mu = 0, or mu set
 * back to 0 and solved again, against a twin model that never heard of
 * friction, bit for bit (the header: "0, the default, is frictionless, bit
 * for bit"). */
static void scene_friction(rng_t *r, case_t *cs, ctx_t *cx, mesh_t *m) {
  scene_two_blocks(r, cs, cx, m, chance(r, 0.3));
  int pair = find_call(cs, F_ADD_CONTACT_PAIR, 0);
  if (pair < 0) pair = find_call(cs, F_ADD_CONTACT_PAIR_WITH_MESH, 0);
  int solve = frictionless_law(cs);
  if (pair < 0 || solve < 0) return;
  static const double mus[] = {0.0, 0.1, 0.3, 0.5, 1.0, 0.05, -0.0, 0.2};
  double mu = mus[rint_(r, 8)];
  int at = pair + 1;
  if (chance(r, 0.5)) { /* refused: nothing may change */
    static const double bad[] = {-0.1, NAN, INFINITY, -INFINITY, -1e-300};
    call_t *c = friction_call(cs, at++, 0, bad[rint_(r, 5)]);
    c->tw = 1;
    if (chance(r, 0.5)) friction_call(cs, at++, (int[]){1, -1, 7, INT_MIN}[rint_(r, 4)], 0.3)->tw = 1;
  }
  friction_call(cs, at++, 0, mu)->tw = 1;
  if (chance(r, 0.3)) friction_call(cs, at++, 0, mu)->tw = 1; /* the same again: nothing changes */
  if (chance(r, 0.5)) { /* a shear on the top: the interface slips where mu is small */
    call_t *t = insert_call(cs, at++, F_ADD_TRACTION);
    t->iv[0] = 4;
    t->dv[0] = (double[]){1e6, 3e6, -2e6}[rint_(r, 3)];
  }
  friction_getters(r, cs);
  if (mu != 0.0 && chance(r, 0.6)) {
    /* back to frictionless: solved again, it is the twin's problem */
    call_t sc = cs->c[find_call(cs, F_SOLVE_CONTACT, 0)];
    friction_call(cs, cs->n, 0, 0.0)->tw = 1;
    call_t *c = add_call(cs, F_SOLVE_CONTACT);
    memcpy(c->iv, sc.iv, sizeof c->iv);
    memcpy(c->dv, sc.dv, sizeof c->dv);
    c->in[0].null_ = sc.in[0].null_;
    add_call(cs, F_GET_DISPLACEMENTS);
    friction_getters(r, cs);
    mu = 0.0;
  }
  if (mu == 0.0) call_i(cs, F_TWIN, 0, 0);
}

/* Automatic pairing on the two blocks: the declared pair (2, 3) replaced
 * by tfem_add_contact_pairs_auto (every tag, or a list with the two sides;
 * a tolerance beyond the gap: one pair expected, (2, 3), bodies 1 and 2;
 * below it: none), refused calls before (negative, NaN, infinite
 * tolerance, an unknown tag, NULL tags with a count, a negative count), a
 * second call (nothing left to pair), or the declared pair kept (nothing to
 * add); the solve against a twin model with the pair declared, bit for
 * bit. */
static void scene_auto_pairs(rng_t *r, case_t *cs, ctx_t *cx, mesh_t *m) {
  scene_two_blocks(r, cs, cx, m, 0);
  int i = find_call(cs, F_ADD_CONTACT_PAIR, 0);
  if (i < 0) return;
  /* the gap of the scene: the lowest y of the upper block's contact side */
  double gap = 0;
  for (int e = 0; e < m->ne; ++e)
    if (m->tag[e] == 3) gap = m->xy[2 * m->edge[2 * e] + 1];
  double h = 1.0, tol;
  for (int e = 0; e < m->ne; ++e)
    if (m->tag[e] == 2) {
      double dx = fabs(m->xy[2 * m->edge[2 * e]] - m->xy[2 * m->edge[2 * e + 1]]);
      if (dx < h) h = dx;
    }
  int expect = 1, keep_declared = chance(r, 0.15);
  if (gap > 0 && chance(r, 0.15)) {
    tol = 0.25 * gap, expect = 0; /* nothing within the tolerance */
  } else {
    tol = gap > 0 ? (double[]){4 * gap, 0.1, h}[rint_(r, 3)] : (double[]){1e-6, 1e-3, 0.1, 0.2}[rint_(r, 4)];
  }
  int at = i + 1;
  if (keep_declared) {
    expect = 0;
  } else {
    case_delete(cs, i);
    at = i;
  }
  if (chance(r, 0.5)) { /* refused: nothing may be added */
    call_t *c = insert_call(cs, at++, F_ADD_CONTACT_PAIRS_AUTO);
    int v = rint_(r, 5);
    c->dv[0] = v == 0 ? (double[]){-1.0, NAN, INFINITY, -1e-300}[rint_(r, 4)] : tol;
    c->iv[0] = v == 4 ? -1 : v == 0 ? 0 : 2;
    if (c->iv[0] == 2) {
      int tg[2] = {2, v == 2 ? 99 : v == 3 ? -3 : 3};
      in_set(c, 0, tg, 2, sizeof(int));
      if (v == 1) c->in[0].null_ = 1; /* NULL tags with a count */
    } else {
      c->in[0].null_ = 1;
    }
    c->expect = -1;
  }
  call_t *c = insert_call(cs, at++, F_ADD_CONTACT_PAIRS_AUTO);
  c->dv[0] = tol;
  c->expect = expect;
  int lists = rint_(r, 5);
  if (lists <= 1) {
    c->iv[0] = 0;
    c->in[0].null_ = lists == 0;
    if (lists == 1) in_set(c, 0, NULL, 0, sizeof(int));
  } else {
    static const int l2[] = {2, 3}, l3[] = {3, 2}, l4[] = {1, 2, 3, 4};
    const int *l = lists == 2 ? l2 : lists == 3 ? l3 : l4;
    c->iv[0] = lists == 4 ? 4 : 2;
    in_set(c, 0, l, c->iv[0], sizeof(int));
  }
  if (chance(r, 0.4)) c->out[0].null_ = 1;
  if (chance(r, 0.2)) c->out[1].null_ = 1;
  if (!keep_declared && expect == 1) {
    c->tw = 3, c->tw_a = 2, c->tw_b = 3;
  } else if (keep_declared) {
    c->tw = 1;
  }
  if (chance(r, 0.3)) { /* again: the pair is declared already */
    call_t *d = insert_call(cs, at++, F_ADD_CONTACT_PAIRS_AUTO);
    d->dv[0] = 0.2;
    d->expect = expect == 1 || keep_declared ? 0 : 1; /* (none within the first tolerance: found now) */
    d->tw = 1;
    d->in[0].null_ = 1;
  }
  if (chance(r, 0.5)) call_i(cs, F_GET_CONTACT_PAIR_BODIES, 0, 0);
  if (expect == 1 || keep_declared) call_i(cs, F_TWIN, 1, 0);
}

/* Prescribed values moved by tfem_set_prescribed on the two blocks: after
 * a contact solve, some of the x DOFs fixed on x = 1/2 (one, the upper
 * block's, or all) are given other values, with refused calls among them
 * (a DOF not prescribed, a node out of range, a component 2, a NaN
 * value), and solved again: the same results as a twin model fixed at
 * those values from the start (tolerance 1e-9 of max |u|). */
static void scene_prescribed(rng_t *r, case_t *cs, ctx_t *cx, mesh_t *m) {
  scene_two_blocks(r, cs, cx, m, chance(r, 0.3));
  int solve = frictionless_law(cs);
  if (solve < 0) return;
  call_t sc = cs->c[solve];
  int fixes[512], nf = 0;
  for (int i = 0; i < cs->n && nf < 512; ++i)
    if (cs->c[i].fn == F_FIX && cs->c[i].iv[1] == TFEM_COMPONENT_X) fixes[nf++] = i;
  if (nf == 0) return;
  int which = rint_(r, 3), k0 = which == 0 ? rint_(r, nf) : which == 1 ? nf / 2 : 0, k1 = which == 0 ? k0 + 1 : nf;
  double v = (double[]){1e-5, -2e-5, 1e-4, 3e-6}[rint_(r, 4)];
  int mixed = chance(r, 0.3);
  if (chance(r, 0.3)) { /* before any solve, too */
    call_t *c = insert_call(cs, solve, F_SET_PRESCRIBED);
    c->iv[0] = cs->c[fixes[k0]].iv[0];
    c->iv[1] = TFEM_COMPONENT_X;
    c->dv[0] = 0.5 * v;
    c->tw = 1;
    for (int k = 0; k < nf; ++k) fixes[k] += fixes[k] >= solve;
  }
  for (int k = k0; k < k1; ++k) {
    call_t *f = &cs->c[fixes[k]];
    double vk = mixed ? v * (1 + k) : v;
    f->tw = 2;
    f->tw_val = vk;
    int node = f->iv[0];
    if (chance(r, 0.15)) { /* refused: nothing may change */
      call_t *c = add_call(cs, F_SET_PRESCRIBED);
      /* (y on x = 1/2: prescribed 0 on the support, so 0 changes nothing,
       * else not prescribed) */
      int bad = rint_(r, 5);
      c->iv[0] = bad == 1 ? cx->nn + cx->base : bad == 3 ? cx->base - 1 : node;
      c->iv[1] = bad == 0 ? TFEM_COMPONENT_Y : bad == 2 ? 2 : TFEM_COMPONENT_X;
      c->dv[0] = bad == 0 ? 0.0 : bad == 4 ? (double[]){NAN, INFINITY, -INFINITY}[rint_(r, 3)] : vk;
      c->tw = 1;
    }
    call_t *c = add_call(cs, F_SET_PRESCRIBED);
    c->iv[0] = node;
    c->iv[1] = TFEM_COMPONENT_X;
    c->dv[0] = vk;
    c->tw = 1;
  }
  if (chance(r, 0.3)) add_call(cs, F_GET_DISPLACEMENTS); /* results gone */
  call_t *c = add_call(cs, F_SOLVE_CONTACT);
  memcpy(c->iv, sc.iv, sizeof c->iv);
  memcpy(c->dv, sc.dv, sizeof c->dv);
  c->in[0].null_ = sc.in[0].null_;
  add_call(cs, F_GET_DISPLACEMENTS);
  if (chance(r, 0.3)) result_getters(r, cs, 1);
  call_i(cs, F_TWIN, 2, 0);
}

/* The mortar weighting on the two blocks (c_tests/mortar_test.c has the
 * patch test): tfem_set_contact_weighting(1) before the mesh (the
 * weighting is the model's), after the pair or right before the solve; the
 * frictionless solve with the linearised test, or one the weighting
 * refuses (the stick law, the literal test); friction set under it (mu > 0
 * refused by tfem_set_friction naming the pair since dc75b81, the model
 * unchanged: the solve then proceeds; mu = +-0 accepted); a pair with its
 * own contact mesh (refused by tfem_add_contact_pair_with_mesh when the
 * weighting was set before it, else tfem_set_contact_weighting(1) is
 * refused naming the pair and the automatic weighting stays: what follows
 * is left to the general oracles); the getters (those per element of B
 * refused); the slave nodes (all four columns, some NULL, a short length);
 * then one of: load steps (a frictionless contact solve of the scaled
 * loads, refactorize accepted) whose results are a
 * step's (slave nodes, no system matrix), their contact state (served
 * since 56d2e1d, over the slave nodes' set: its size and bytes OK, a
 * damaged state refused with INVALID_ARGUMENT; before, all three
 * INVALID_STATE naming "contact states"), then reverted (the results
 * before the last step, once), the last step again from the state brought
 * back (bit for bit), the state read set again (taken) and a step from it,
 * a step unloading to 0 (OK since 56d2e1d: the warm start that finds no
 * contact is tried again from the step's own initial set); a wild
 * weighting (refused, nothing changes), the mortar weighting set again
 * (nothing changes), the strip set back (the results gone; solved again:
 * no slave nodes), the model re-created (the strip again). The statuses
 * are the scene's expectation when pristine (call_t.want). The histories
 * of scene_steps run under the mortar weighting too ("mortar_steps"). */
static void scene_mortar(rng_t *r, case_t *cs, ctx_t *cx, mesh_t *m) {
  int user = chance(r, 0.12);
  int geo = scene_two_blocks(r, cs, cx, m, user ? 1 : chance(r, 0.25) ? 3 : chance(r, 0.15) ? 4 : 0); /* (curved, cut) */
  int solve = find_call(cs, F_SOLVE_CONTACT, 0);
  int pair = find_call(cs, user ? F_ADD_CONTACT_PAIR_WITH_MESH : F_ADD_CONTACT_PAIR, 0);
  if (solve < 0 || pair < 0) return;
  call_t *sc = &cs->c[solve];
  int bad_opts = 0;
  if (!sc->in[0].null_) {
    if (chance(r, 0.85)) sc->iv[0] = TFEM_CONTACT_LAW_FRICTIONLESS, sc->iv[1] = TFEM_INVERSION_TEST_LINEARISED;
    bad_opts = sc->iv[0] == TFEM_CONTACT_LAW_STICK || sc->iv[1] == TFEM_INVERSION_TEST_LITERAL;
  }
  int at = (int[]){0, pair + 1, solve}[rint_(r, 3)];
  insert_call(cs, at, F_SET_CONTACT_WEIGHTING)->iv[0] = TFEM_CONTACT_WEIGHTING_MORTAR;
  ++solve;
  if (chance(r, 0.3)) insert_call(cs, at + 1, F_GET_CONTACT_WEIGHTING)->want = 1, ++solve;
  if (!user && chance(r, 0.15)) { /* refused where it is set (mu > 0): the model unchanged, the solve proceeds */
    double mu = (double[]){0.3, 0.05, 1e-300, 0.0, -0.0}[rint_(r, 5)];
    friction_call(cs, solve++, 0, mu)->want = 1 + (mu > 0 ? TFEM_STATUS_INVALID_ARGUMENT : TFEM_STATUS_OK);
  }
  int refused = user || bad_opts;
  if (!user) cs->c[solve].want = 1 + (refused ? TFEM_STATUS_INVALID_ARGUMENT : TFEM_STATUS_OK);
  int ok = refused ? TFEM_STATUS_INVALID_STATE : TFEM_STATUS_OK; /* (slave nodes: none without results) */
  add_call(cs, F_GET_CONTACT_SLAVE_NODES)->want = 1 + ok;
  if (chance(r, 0.5)) add_call(cs, F_GET_CONTACT_REPORT);
  if (chance(r, 0.5)) { /* some columns NULL */
    call_t *c = add_call(cs, F_GET_CONTACT_SLAVE_NODES);
    for (int j = 0; j < 4; ++j) c->out[j].null_ = chance(r, 0.5);
    c->want = 1 + ok;
  }
  if (chance(r, 0.4)) { /* one column short: all are (one length) */
    call_t *c = add_call(cs, F_GET_CONTACT_SLAVE_NODES);
    c->out[rint_(r, 4)] = (out_spec){LS_REL, chance(r, 0.7) ? -1 : -2, 0, 0, 0, 0};
    c->want = 1 + (refused ? TFEM_STATUS_INVALID_STATE : TFEM_STATUS_BUFFER_TOO_SMALL);
  }
  if (chance(r, 0.4)) add_call(cs, F_GET_CONTACT_NODAL_PRESSURES);
  if (chance(r, 0.3)) { /* one column longer: all are; nothing past n written */
    call_t *c = add_call(cs, F_GET_CONTACT_SLAVE_NODES);
    c->out[rint_(r, 4)] = (out_spec){LS_REL, rrange(r, 1, 3), 0, 0, 0, 0};
    c->want = 1 + ok;
  }
  switch (rint_(r, 5)) {
  case 0: { /* load steps under the mortar weighting, their contact states, then a revert */
    int srefused = user; /* (the step's own options are frictionless, linearised) */
    int sok = srefused ? TFEM_STATUS_INVALID_STATE : TFEM_STATUS_OK; /* slave nodes after the steps */
    int nsteps = chance(r, 0.35) ? 2 : 1, last_opts = 0, last_refac = 0;
    for (int k = 0; k < nsteps; ++k) {
      int opts = chance(r, 0.5), last = k == nsteps - 1;
      call_t *c = step_call(cs, last ? 1.0 : (chance(r, 0.5) ? 0.5 : 0.25), opts, last ? T_REF_STEP : T_NONE);
      if (opts && chance(r, 0.3)) c->iv[3] = 1; /* refactorize: accepted (each step a contact solve) */
      if (!user) c->want = 1 + TFEM_STATUS_OK;
      last_opts = opts, last_refac = c->iv[3];
      add_call(cs, F_GET_CONTACT_SLAVE_NODES)->want = 1 + (srefused ? ok : sok);
      /* (user: the statuses left to the general oracles) */
      int rs = srefused ? TFEM_STATUS_INVALID_STATE : TFEM_STATUS_OK;
      if (chance(r, 0.4)) add_call(cs, F_GET_CONTACT_REPORT)->want = 1 + rs;
      if (last) add_call(cs, F_GET_DISPLACEMENTS)->want = 1 + rs, cs->c[cs->n - 1].tag = T_REF_DISP;
      else if (chance(r, 0.5)) add_call(cs, F_GET_DISPLACEMENTS)->want = 1 + rs;
    }
    if (!srefused) {
      if (chance(r, 0.4)) add_call(cs, F_GET_CONTACT_NODAL_PRESSURES)->want = 1;
      if (chance(r, 0.3)) add_call(cs, F_GET_CONTACT_ACTIVE)->want = 1 + TFEM_STATUS_INVALID_STATE;
      if (chance(r, 0.3)) add_call(cs, F_GET_MATRIX_SIZE)->want = 1 + TFEM_STATUS_INVALID_STATE;
      if (chance(r, 0.3)) result_getters(r, cs, 1);
    }
    /* the contact states: served as the strip's since 56d2e1d (before:
     * INVALID_STATE naming "contact states"), over the slave nodes' set;
     * none without a step (the steps refused) */
    int sst = srefused ? TFEM_STATUS_INVALID_STATE : TFEM_STATUS_OK;
    if (chance(r, 0.5)) add_call(cs, F_GET_CONTACT_STATE_SIZE)->want = 1 + sst;
    int saved = chance(r, 0.6);
    if (saved) add_call(cs, F_GET_CONTACT_STATE)->want = 1 + sst;
    if (chance(r, 0.3)) {
      call_t *c = add_call(cs, F_SET_CONTACT_STATE); /* not a state, or a damaged one */
      c->iv[0] = rrange(r, 1, 5);
      c->iv[2] = rint_(r, 1000);
      if (!user) c->want = 1 + TFEM_STATUS_INVALID_ARGUMENT;
    }
    /* the revert: the results before the last step (those of the steps
     * before, or of the solve); once */
    int before_ok = nsteps == 2 ? sok : ok;
    add_call(cs, F_REVERT_STEP)->want = 1 + (srefused ? TFEM_STATUS_INVALID_STATE : TFEM_STATUS_OK);
    add_call(cs, F_GET_CONTACT_SLAVE_NODES)->want = 1 + (srefused ? ok : before_ok);
    if (chance(r, 0.5)) add_call(cs, F_GET_DISPLACEMENTS);
    if (chance(r, 0.3)) add_call(cs, F_REVERT_STEP)->want = 1 + TFEM_STATUS_INVALID_STATE;
    if (!srefused && chance(r, 0.5)) { /* the last step again, from the state brought back: bit for bit */
      step_call(cs, 1.0, last_opts, T_CMP_STEP)->want = 1;
      cs->c[cs->n - 1].iv[3] = last_refac;
      add_call(cs, F_GET_DISPLACEMENTS)->tag = T_CMP_DISP;
      add_call(cs, F_GET_CONTACT_SLAVE_NODES)->want = 1;
      if (chance(r, 0.5)) add_call(cs, F_GET_CONTACT_REPORT)->want = 1;
    }
    if (!srefused && saved && chance(r, 0.4)) { /* the state after the last step, set again: taken */
      call_t *c = add_call(cs, F_SET_CONTACT_STATE);
      c->iv[0] = 0;
      c->want = 1;
      step_call(cs, 1.0, chance(r, 0.5), T_NONE)->want = 1;
      add_call(cs, F_GET_CONTACT_SLAVE_NODES)->want = 1;
    }
    if (!srefused && chance(r, 0.35)) {
      /* unloading to 0: the warm start leads nowhere (no contact at all,
       * the upper block free), the step is tried again from the initial
       * set of its own loads (since 56d2e1d) and is OK */
      step_call(cs, 0.0, chance(r, 0.5), T_NONE)->want = 1;
      add_call(cs, F_GET_CONTACT_SLAVE_NODES)->want = 1;
      if (chance(r, 0.5)) add_call(cs, F_GET_DISPLACEMENTS)->want = 1;
    }
    break;
  }
  case 1: /* a wild weighting: refused, nothing changes */
    call_i(cs, F_SET_CONTACT_WEIGHTING, (int[]){-1, 3, INT_MAX, INT_MIN}[rint_(r, 4)], 0)->want =
        1 + TFEM_STATUS_INVALID_ARGUMENT;
    add_call(cs, F_GET_CONTACT_WEIGHTING)->want = 1;
    add_call(cs, F_GET_CONTACT_SLAVE_NODES)->want = 1 + ok;
    break;
  case 2: /* the same weighting again: nothing changes */
    call_i(cs, F_SET_CONTACT_WEIGHTING, TFEM_CONTACT_WEIGHTING_MORTAR, 0)->want = 1;
    add_call(cs, F_GET_CONTACT_SLAVE_NODES)->want = 1 + ok;
    if (chance(r, 0.5)) add_call(cs, F_GET_DISPLACEMENTS)->want = 1 + (refused ? TFEM_STATUS_INVALID_STATE : 0);
    break;
  case 3: { /* the strip or the automatic weighting back: the results go; solved again, no slave nodes where
             * every pair gets B (the strip; the automatic one on straight or coinciding sides, on a pair with
             * friction or a mesh of its own), else (the curved non-matching sides) no elements of B */
    int automatic = chance(r, 0.5);
    int fam = !automatic || user ? FAM_STRIP : geo;
    call_i(cs, F_SET_CONTACT_WEIGHTING, automatic ? TFEM_CONTACT_WEIGHTING_AUTO : TFEM_CONTACT_WEIGHTING_STRIP, 0)->want = 1;
    add_call(cs, F_GET_CONTACT_SLAVE_NODES)->want = 1 + TFEM_STATUS_INVALID_STATE;
    add_call(cs, F_GET_DISPLACEMENTS)->want = 1 + TFEM_STATUS_INVALID_STATE;
    add_call(cs, F_SOLVE_CONTACT)->in[0].null_ = 1;
    add_call(cs, F_GET_CONTACT_ACTIVE)->want = 1 + (fam == FAM_MORTAR ? TFEM_STATUS_INVALID_STATE : 0);
    add_call(cs, F_GET_CONTACT_SLAVE_NODES)->want = 1 + (fam == FAM_MORTAR ? TFEM_STATUS_OK : TFEM_STATUS_INVALID_STATE);
    if (chance(r, 0.5)) add_call(cs, F_GET_CONTACT_GAPS);
    if (automatic && chance(r, 0.5)) add_call(cs, F_GET_CONTACT_WEIGHTING)->want = 1;
    break;
  }
  default: /* a new model: the automatic weighting again (the default) */
    add_call(cs, F_RECREATE);
    add_call(cs, F_GET_CONTACT_WEIGHTING)->want = 1;
    break;
  }
  if (user) {
    /* the mortar weighting set before the pair with its own contact mesh:
     * the pair refused (no pair at all after); set after it: the weighting
     * refused naming pair 0, the automatic one stays (the pair gets B).
     * The rest is left to the general oracles. */
    int w = find_call(cs, F_SET_CONTACT_WEIGHTING, 0), p = find_call(cs, F_ADD_CONTACT_PAIR_WITH_MESH, 0);
    for (int i = 0; i < cs->n; ++i) cs->c[i].want = 0;
    if (w >= 0 && p >= 0) {
      cs->c[w].want = 1 + (w < p ? TFEM_STATUS_OK : TFEM_STATUS_INVALID_ARGUMENT);
      cs->c[p].want = 1 + (w < p ? TFEM_STATUS_INVALID_ARGUMENT : TFEM_STATUS_OK);
    }
  }
}

/* The interface of tag `tag` of mesh m as one side of a contact context:
 * host node numbers mul * node + off, equations 2 node + component (in the
 * index base; the x DOFs of the nodes at x = 0.5, fixed in the model, have
 * none). */
static void host_side_call(case_t *cs, const mesh_t *m, int tag, int body, double young, int plane, int base, int mul,
                           int off) {
  int ne = 0, nn = 0, *nodes = xmalloc(sizeof(int) * 2 * (size_t)m->ne + 1);
  for (int e = 0; e < m->ne; ++e)
    if (m->tag[e] == tag) {
      ++ne;
      for (int k = 0; k < 2; ++k) {
        int v = m->edge[2 * e + k], seen = 0;
        for (int i = 0; i < nn && !seen; ++i) seen = nodes[i] == v;
        if (!seen) nodes[nn++] = v;
      }
    }
  call_t *c = add_call(cs, F_CONTACT_ADD_SIDE);
  c->iv[0] = tag;
  c->iv[1] = body;
  c->iv[2] = plane;
  c->iv[3] = nn;
  c->iv[4] = ne;
  c->dv[0] = young;
  c->dv[1] = 0.3;
  in_set(c, 0, NULL, nn, sizeof(int));
  in_set(c, 1, NULL, 2 * nn, sizeof(double));
  in_set(c, 2, NULL, 2 * nn, sizeof(int64_t));
  in_set(c, 3, NULL, 2 * ne, sizeof(int));
  for (int i = 0; i < nn; ++i) {
    int v = nodes[i];
    ((int *)c->in[0].p)[i] = mul * v + off;
    ((double *)c->in[1].p)[2 * i] = m->xy[2 * v];
    ((double *)c->in[1].p)[2 * i + 1] = m->xy[2 * v + 1];
    ((int64_t *)c->in[2].p)[2 * i] = m->xy[2 * v] == 0.5 ? base - 1 : 2 * v + base;
    ((int64_t *)c->in[2].p)[2 * i + 1] = 2 * v + 1 + base;
  }
  for (int e = 0, k = 0; e < m->ne; ++e)
    if (m->tag[e] == tag) {
      ((int *)c->in[3].p)[2 * k] = mul * m->edge[2 * e] + off;
      ((int *)c->in[3].p)[2 * k + 1] = mul * m->edge[2 * e + 1] + off;
      ++k;
    }
  free(nodes);
}

static call_t *rt_call(case_t *cs, int fn, int recipe, int k) {
  call_t *c = add_call(cs, fn);
  c->iv[0] = recipe;
  c->iv[2] = k;
  return c;
}

/* A host code on the two blocks: the model solves them (tfem_solve_contact)
 * and a contact context holds the same interface, its equations those of
 * the model's DOFs (2 node + component), so the model's displacements are
 * the host's solution vector. Every entry point of the context, in the
 * order of a host's active-set loop. */
static void scene_host(rng_t *r, case_t *cs, ctx_t *cx, mesh_t *m) {
  int variant = chance(r, 0.4);
  scene_two_blocks(r, cs, cx, m, variant);
  int base = rint_(r, 2), mul = chance(r, 0.5) ? 1 : 3, off = chance(r, 0.5) ? base : 7;
  cs->coupled = 1;
  cs->hm_mul = mul;
  cs->hm_off = off;
  cs->neq = 2 * m->nn;
  cx->hbase = base;
  cx->nh = 0;
  for (int e = 0; e < m->ne && cx->nh < 64; ++e)
    if (m->tag[e] == 2 || m->tag[e] == 3) cx->hids[cx->nh++] = mul * m->edge[2 * e] + off;
  cx->nsides = 2;
  call_i(cs, F_CONTACT_CREATE, base, 0);
  if (chance(r, 0.3)) {
    call_t *c = add_call(cs, F_CONTACT_SET_OPTIONS);
    c->iv[0] = chance(r, 0.8) ? 0 : 1;
    c->iv[1] = chance(r, 0.8) ? 0 : 1;
    c->iv[2] = chance(r, 0.7) ? 50 : 3;
    c->dv[0] = chance(r, 0.7) ? 0 : 1e9;
    c->dv[1] = chance(r, 0.7) ? 0 : 0.5;
  }
  /* (15% axisymmetric sides: the blocks lie at x >= 0; then, 30%, a plane
   * side after them, refused: a context takes one section) */
  int plane = chance(r, 0.15) ? TFEM_PLANE_MODE_AXISYMMETRIC : chance(r, 0.8) ? TFEM_PLANE_MODE_STRAIN : TFEM_PLANE_MODE_STRESS;
  host_side_call(cs, m, 2, 1, 1e10, plane, base, mul, off);
  host_side_call(cs, m, 3, 2, 1e11, plane, base, mul, off);
  if (plane == TFEM_PLANE_MODE_AXISYMMETRIC && chance(r, 0.3))
    host_side_call(cs, m, 3, 2, 1e11, TFEM_PLANE_MODE_STRAIN, base, mul, off);
  call_t *um = NULL;
  for (int i = 0; i < cs->n && variant; ++i)
    if (cs->c[i].fn == F_ADD_CONTACT_PAIR_WITH_MESH) um = &cs->c[i];
  if (um && um->in[0].p && !um->in[0].null_) {
    call_t *c = add_call(cs, F_CONTACT_ADD_PAIR_WITH_MESH);
    um = NULL;
    for (int i = 0; i < cs->n; ++i)
      if (cs->c[i].fn == F_ADD_CONTACT_PAIR_WITH_MESH) um = &cs->c[i];
    int nt = um->iv[2] > 0 && um->in[0].n >= 3 * um->iv[2] ? um->iv[2] : 0, mb = um->iv[2] >= 0 ? 0 : 0;
    (void)mb;
    c->iv[0] = 0;
    c->iv[1] = 1;
    c->iv[2] = nt;
    in_set(c, 0, NULL, 3 * nt, sizeof(int));
    /* (the model's contact triangles are in the model's index base) */
    int mbase = 0;
    for (int i = 0; i < cs->n; ++i)
      if (cs->c[i].fn == F_SET_MESH) mbase = cs->c[i].iv[2];
    for (int k = 0; k < 3 * nt; ++k) ((int *)c->in[0].p)[k] = mul * (((int *)um->in[0].p)[k] - mbase) + off;
  } else {
    call_i(cs, F_CONTACT_ADD_PAIR, 0, 1);
  }
  add_call(cs, F_CONTACT_SIZES);
  add_call(cs, F_CONTACT_NODES);
  add_call(cs, F_CONTACT_PATTERN);
  if (chance(r, 0.6)) add_call(cs, F_CONTACT_ELEMENT_EQUATIONS);
  if (chance(r, 0.5)) add_call(cs, F_CONTACT_ELEMENT_BLOCKS);
  if (chance(r, 0.5)) add_call(cs, F_CONTACT_ELEMENTS);
  rt_call(cs, F_CONTACT_EVALUATE, 0, rint_(r, 1000)); /* the initial-gap load */
  rt_call(cs, F_CONTACT_GATHER, 2, rint_(r, 1000));   /* the model's displacements */
  rt_call(cs, F_CONTACT_UPDATE, 2, rint_(r, 1000));
  add_call(cs, F_CONTACT_GET_ACTIVE);
  rt_call(cs, F_CONTACT_EVALUATE, 2, rint_(r, 1000));
  rt_call(cs, F_CONTACT_SCATTER_ADD, 1, rint_(r, 1000));
  add_call(cs, F_CONTACT_LENGTH);
  rt_call(cs, F_CONTACT_GAPS, 2, rint_(r, 1000));
  rt_call(cs, F_CONTACT_PRESSURES, 2, rint_(r, 1000));
  rt_call(cs, F_CONTACT_SET_ACTIVE, chance(r, 0.5) ? 3 : 2, rint_(r, 1000));
  add_call(cs, F_CONTACT_GET_ACTIVE);
  if (chance(r, 0.5)) add_call(cs, F_CONTACT_RESTART);
  rt_call(cs, F_CONTACT_UPDATE, chance(r, 0.5) ? 0 : 1, rint_(r, 1000));
  rt_call(cs, F_CONTACT_UPDATE, 2, rint_(r, 1000));
  rt_call(cs, F_CONTACT_PRESSURES, 1, rint_(r, 1000));
  if (chance(r, 0.3)) add_call(cs, F_CONTACT_LAST_ERROR)->out[0] = (out_spec){LS_FIXED, 512, 0, 0, 0, 0};
  if (chance(r, 0.2)) add_call(cs, F_CONTACT_LAST_ERROR_LENGTH);
  if (chance(r, 0.2)) {
    add_call(cs, F_CONTACT_DESTROY);
    add_call(cs, F_CONTACT_LENGTH);
    if (chance(r, 0.5)) add_call(cs, F_CONTACT_LAST_ERROR_LENGTH);
  }
}

static void random_mesh(rng_t *r, mesh_t *m, int nbodies) {
  int nn = rrange(r, 3, 16), nt = rrange(r, 1, 20);
  double scale = chance(r, 0.8) ? 1.0 : wild_double(r);
  for (int i = 0; i < nn; ++i) mesh_node(m, rint_(r, 5) * 0.25 * scale, rint_(r, 5) * 0.25 * scale);
  for (int t = 0; t < nt; ++t) {
    int a = rint_(r, nn), b = rint_(r, nn), c = rint_(r, nn);
    if (chance(r, 0.9)) {
      while (b == a) b = rint_(r, nn);
      while (c == a || c == b) c = rint_(r, nn);
    }
    mesh_tri(m, a, b, c, 1 + rint_(r, nbodies));
  }
  for (int t = 0; t < nt; ++t)
    for (int k = 0; k < 3; ++k)
      if (chance(r, 0.3)) mesh_edge(m, m->tri[3 * t + k], m->tri[3 * t + (k + 1) % 3], rrange(r, 1, 4));
}

/* A random call of any entry point; arguments plausible for the context,
 * each made wild with probability `wild`. */
static void random_call(rng_t *r, case_t *cs, const ctx_t *cx, double wild, int at, int forced) {
  static const int weight[NF] = {
      [F_VERSION] = 1, [F_LAST_ERROR] = 3, [F_LAST_ERROR_LENGTH] = 2, [F_WARNING_COUNT] = 2,
      [F_GET_WARNING] = 2, [F_SET_MESH] = 2, [F_LOAD_GMSH] = 2, [F_SET_BOUNDARY_EDGES] = 3,
      [F_SET_MATERIAL] = 4, [F_SET_TEMPERING] = 3, [F_SET_ORDERING] = 3, [F_FIX] = 4,
      [F_FIX_EDGES] = 4, [F_CLEAR_CONSTRAINTS] = 2, [F_ADD_PRESSURE] = 3, [F_ADD_TRACTION] = 3,
      [F_ADD_NODAL_FORCE] = 3, [F_SET_BODY_FORCE] = 2, [F_CLEAR_LOADS] = 2, [F_SOLVE] = 6,
      [F_GET_SIZES] = 2, [F_GET_DISPLACEMENTS] = 4, [F_GET_STRAINS] = 3, [F_GET_STRESSES] = 3,
      [F_GET_JACOBIANS] = 3, [F_GET_REACTIONS] = 4, [F_GET_MATRIX_SIZE] = 2, [F_GET_MATRIX] = 3,
      [F_ELEMENT_STIFFNESS] = 4, [F_LAPLACIAN_STIFFNESS] = 3, [F_ADD_CONTACT_PAIR] = 3,
      [F_ADD_CONTACT_PAIR_WITH_MESH] = 2, [F_CONTACT_OPTIONS_DEFAULT] = 2, [F_SOLVE_CONTACT] = 5,
      [F_GET_CONTACT_ACTIVE] = 3, [F_GET_CONTACT_PRESSURE] = 3, [F_GET_CONTACT_ELEMENTS] = 2,
      [F_GET_CONTACT_REPORT] = 2, [F_ADD_BOUNDARY_EDGES] = 3, [F_GET_EXTERNAL_WORK] = 3,
      [F_GET_CONTACT_FORCES] = 3, [F_GET_CONTACT_GAPS] = 3, [F_GET_CONTACT_NODAL_PRESSURES] = 2, [F_GET_CONTACT_MESH_SIZE] = 2,
      [F_GET_CONTACT_MESH] = 2, [F_GET_CONTACT_ELEMENT_PAIRS] = 2, [F_GET_CONTACT_ELEMENT_APEXES] = 2,
      [F_GET_CONTACT_PAIR_BODIES] = 2, [F_SET_THREADS] = 2, [F_GET_THREADS] = 2,
      [F_DESTROY_NULL] = 1, [F_RECREATE] = 1,
      [F_STEP] = 4, [F_REVERT_STEP] = 2, [F_GET_CONTACT_STATE_SIZE] = 2, [F_GET_CONTACT_STATE] = 2,
      [F_SET_CONTACT_STATE] = 2, [F_CONTACT_CREATE] = 3, [F_CONTACT_DESTROY] = 1, [F_CONTACT_LAST_ERROR] = 1,
      [F_CONTACT_SET_OPTIONS] = 1, [F_CONTACT_ADD_SIDE] = 3, [F_CONTACT_ADD_PAIR] = 2,
      [F_CONTACT_ADD_PAIR_WITH_MESH] = 1, [F_CONTACT_SIZES] = 1, [F_CONTACT_NODES] = 1, [F_CONTACT_PATTERN] = 1,
      [F_CONTACT_EVALUATE] = 2, [F_CONTACT_GATHER] = 1, [F_CONTACT_SCATTER_ADD] = 1, [F_CONTACT_UPDATE] = 2,
      [F_CONTACT_RESTART] = 1, [F_CONTACT_GET_ACTIVE] = 1, [F_CONTACT_SET_ACTIVE] = 1, [F_CONTACT_GAPS] = 1,
      [F_CONTACT_PRESSURES] = 1, [F_CONTACT_ELEMENTS] = 1, [F_CONTACT_ELEMENT_EQUATIONS] = 1,
      [F_CONTACT_ELEMENT_BLOCKS] = 1, [F_CONTACT_LENGTH] = 1, [F_GET_CONTACT_SHEAR] = 1,
      [F_GET_CONTACT_FRICTION_STATE] = 1, [F_GET_CONTACT_DISSIPATION] = 1, [F_SET_FRICTION] = 2,
      [F_SET_PRESCRIBED] = 2, [F_ADD_CONTACT_PAIRS_AUTO] = 2, [F_GET_CONTACT_PAIR_NODAL_PRESSURES] = 2,
      [F_WRITE_VTU] = 2, [F_GET_WARNING_SIZE] = 2, [F_CONTACT_LAST_ERROR_LENGTH] = 1,
      [F_SET_CONTACT_WEIGHTING] = 3, [F_GET_CONTACT_WEIGHTING] = 1, [F_GET_CONTACT_SLAVE_NODES] = 3,
      [F_GET_OUT_OF_PLANE] = 3, [F_SOLVE_ADAPTIVE] = 2, [F_GET_ADAPT_CYCLES] = 2, [F_SET_BOUNDARY_CIRCLE] = 3};
  int total = 0;
  for (int f = 0; f < NF; ++f) total += weight[f];
  int x = rint_(r, total), fn = 0;
  while (x >= weight[fn]) x -= weight[fn++];
  if (forced >= 0) fn = forced;
  call_t tmp;
  memset(&tmp, 0, sizeof tmp);
  case_t one = {0};
  call_t *c = add_call(&one, fn);
  for (int k = 0; k < fn_ni(fn); ++k) {
    char role = FN[fn].ir[k];
    c->iv[k] = plausible_int(r, role, cx);
    if (chance(r, wild) && role != 'c') c->iv[k] = wild_int(r, role, c->iv[k], cx);
  }
  for (int k = 0; k < fn_nd(fn); ++k)
    c->dv[k] = chance(r, wild) ? wild_double(r) : plausible_double(r, FN[fn].dr[k]);
  switch (fn) {
  case F_SET_MESH: {
    mesh_t rm = {0};
    if (cx->mesh && chance(r, 0.5)) {
      const mesh_t *s = cx->mesh;
      for (int i = 0; i < s->nn; ++i) mesh_node(&rm, s->xy[2 * i], s->xy[2 * i + 1]);
      for (int t = 0; t < s->nt; ++t) mesh_tri(&rm, s->tri[3 * t], s->tri[3 * t + 1], s->tri[3 * t + 2], s->body[t]);
    } else {
      random_mesh(r, &rm, cx->nbodies > 1 ? 2 : 1);
    }
    c->iv[0] = rm.nn;
    c->iv[1] = rm.nt;
    c->iv[2] = cx->base;
    in_set(c, 0, rm.xy, 2 * rm.nn, sizeof(double));
    in_set(c, 1, NULL, 3 * rm.nt, sizeof(int));
    for (int k = 0; k < 3 * rm.nt; ++k) ((int *)c->in[1].p)[k] = rm.tri[k] + cx->base;
    in_set(c, 2, rm.body, rm.nt, sizeof(int));
    mesh_free(&rm);
    break;
  }
  case F_SET_BOUNDARY_EDGES: {
    /* The scene's edges, most kept; sometimes every edge of one tag left
     * out (loads on it then name nothing) or an interior edge (a side of
     * two triangles) given a tag that may carry a load. */
    const mesh_t *sm = cx->mesh;
    int ne = 0, cap = (sm ? sm->ne : 0) + 4, drop_tag = chance(r, 0.35) ? pick_tag(r, cx) : INT_MIN;
    int *en = xmalloc(sizeof(int) * 2 * (size_t)cap), *tg = xmalloc(sizeof(int) * (size_t)cap);
    if (sm) {
      double keep = chance(r, 0.5) ? 1.0 : 0.8;
      for (int e = 0; e < sm->ne; ++e)
        if (sm->tag[e] != drop_tag && chance(r, keep)) {
          en[2 * ne] = sm->edge[2 * e] + cx->base;
          en[2 * ne + 1] = sm->edge[2 * e + 1] + cx->base;
          tg[ne++] = chance(r, 0.9) ? sm->tag[e] : pick_tag(r, cx);
        }
      if (sm->nt > 1 && chance(r, 0.25)) {
        /* an interior side: a side of a triangle that another one shares */
        for (int tries = 0; tries < 20; ++tries) {
          int t = rint_(r, sm->nt), k = rint_(r, 3), n2 = 0;
          int p = sm->tri[3 * t + k], q = sm->tri[3 * t + (k + 1) % 3];
          for (int u = 0; u < sm->nt; ++u)
            for (int kk = 0; kk < 3; ++kk) {
              int a = sm->tri[3 * u + kk], b = sm->tri[3 * u + (kk + 1) % 3];
              n2 += (a == p && b == q) || (a == q && b == p);
            }
          if (n2 == 2) {
            en[2 * ne] = p + cx->base;
            en[2 * ne + 1] = q + cx->base;
            tg[ne++] = pick_tag(r, cx);
            break;
          }
        }
      }
    }
    if (ne == 0 || chance(r, 0.1)) {
      en[2 * ne] = pick_node(r, cx);
      en[2 * ne + 1] = pick_node(r, cx);
      tg[ne++] = pick_tag(r, cx);
    }
    c->iv[0] = ne;
    in_set(c, 0, en, 2 * ne, sizeof(int));
    in_set(c, 1, tg, ne, sizeof(int));
    free(en);
    free(tg);
    break;
  }
  case F_ADD_BOUNDARY_EDGES: {
    /* One group of the scene's edges (a tag), most often as it is (a
     * group given again), or under another tag, sometimes with an
     * interior side (it cannot carry a load) or random nodes. */
    const mesh_t *sm = cx->mesh;
    int ne = 0, cap = (sm ? sm->ne : 0) + 4;
    int *en = xmalloc(sizeof(int) * 2 * (size_t)cap), *tg = xmalloc(sizeof(int) * (size_t)cap);
    if (sm && sm->ne) {
      int tag = sm->tag[rint_(r, sm->ne)];
      int as = chance(r, 0.6) ? tag : chance(r, 0.5) ? 5 : pick_tag(r, cx);
      double keep = chance(r, 0.7) ? 1.0 : 0.6;
      for (int e = 0; e < sm->ne; ++e)
        if (sm->tag[e] == tag && chance(r, keep)) {
          en[2 * ne] = sm->edge[2 * e] + cx->base;
          en[2 * ne + 1] = sm->edge[2 * e + 1] + cx->base;
          tg[ne++] = as;
        }
      if (sm->nt > 1 && chance(r, 0.15)) {
        int t = rint_(r, sm->nt), k = rint_(r, 3);
        en[2 * ne] = sm->tri[3 * t + k] + cx->base;
        en[2 * ne + 1] = sm->tri[3 * t + (k + 1) % 3] + cx->base;
        tg[ne++] = as;
      }
    }
    if (ne == 0 || chance(r, 0.05)) {
      en[2 * ne] = pick_node(r, cx);
      en[2 * ne + 1] = pick_node(r, cx);
      tg[ne++] = pick_tag(r, cx);
    }
    c->iv[0] = ne;
    in_set(c, 0, en, 2 * ne, sizeof(int));
    in_set(c, 1, tg, ne, sizeof(int));
    free(en);
    free(tg);
    break;
  }
  case F_ADD_CONTACT_PAIR_WITH_MESH: {
    int nt = rrange(r, 1, 4);
    c->iv[2] = nt;
    in_set(c, 0, NULL, 3 * nt, sizeof(int));
    for (int k = 0; k < 3 * nt; ++k) ((int *)c->in[0].p)[k] = pick_node(r, cx);
    break;
  }
  case F_ELEMENT_STIFFNESS: case F_LAPLACIAN_STIFFNESS: {
    /* (a ring, axisymmetric: corners at x >= 0 half the time, on the axis
     * sometimes, else some may lie across it) */
    double xy[6] = {0, 0, 1, 0, 0, 1};
    int ring_side = fn == F_ELEMENT_STIFFNESS && c->iv[0] == TFEM_PLANE_MODE_AXISYMMETRIC && chance(r, 0.5);
    if (chance(r, 0.5))
      for (int k = 0; k < 6; ++k)
        xy[k] = chance(r, wild) ? wild_double(r) : ring_side && k % 2 == 0 ? rint_(r, 3) * 0.5 : rint_(r, 5) * 0.5 - 1.0;
    in_set(c, 0, xy, 6, sizeof(double));
    break;
  }
  case F_SOLVE_CONTACT: case F_STEP: case F_SOLVE_ADAPTIVE:
    if (chance(r, 0.2)) c->in[0].null_ = 1;
    break;
  case F_SET_BOUNDARY_CIRCLE: {
    /* most often a circle made for the tag's edges (of the arc they lie
     * on, or through an edge's ends), one of its numbers sometimes wild */
    double circle[3];
    if (cx->mesh && chance(r, 0.6) && circle_of_tag(r, cx->mesh, c->iv[0], circle)) {
      for (int k = 0; k < 3; ++k) c->dv[k] = circle[k];
      if (chance(r, wild)) c->dv[rint_(r, 3)] = wild_double(r);
    }
    break;
  }
  case F_ADD_CONTACT_PAIRS_AUTO:
    /* every tag (NULL or not), or a few (an unknown one sometimes) */
    if (c->iv[0] == 0 && chance(r, 0.5)) c->in[0].null_ = 1;
    else if (c->iv[0] > 0 && chance(r, wild)) {
      fix_arrays(r, c, cx);
      ((int *)c->in[0].p)[rint_(r, c->iv[0])] = (int[]){99, -1, 0, INT_MIN}[rint_(r, 4)];
    }
    break;
  case F_CONTACT_ADD_PAIR_WITH_MESH: {
    int nt = rrange(r, 1, 4);
    c->iv[2] = nt;
    in_set(c, 0, NULL, 3 * nt, sizeof(int));
    for (int k = 0; k < 3 * nt; ++k) ((int *)c->in[0].p)[k] = pick_hnode(r, cx);
    break;
  }
  case F_GET_WARNING: case F_LAST_ERROR: case F_CONTACT_LAST_ERROR:
    c->out[0] = (out_spec){chance(r, 0.7) ? LS_FIXED : LS_EXACT, rint_(r, 3) ? 512 : rint_(r, 40), 0, 0, 0, 0};
    break;
  default: break;
  }
  fix_arrays(r, c, cx);
  if (FN[fn].model && chance(r, wild * 0.2)) c->null_model = 1;
  for (int j = 0; j < fn_nout(fn); ++j) {
    if (chance(r, wild * 0.3)) c->out[j].null_ = 1;
    else if (!FN[fn].scalar_out && FN[fn].req[j] != R_36 && FN[fn].req[j] != R_9 && chance(r, wild * 0.5))
      c->out[j] = (out_spec){LS_REL, chance(r, 0.7) ? -1 : rrange(r, -3, 3), 0, 0, 0, 0};
  }
  c->mutated = 1;
  case_insert_copy(cs, at < 0 ? cs->n : at, c);
  case_free(&one);
  (void)tmp;
}

/* Mutates one argument of call c. */
static void mutate_arg(rng_t *r, call_t *c, const ctx_t *cx) {
  int fn = c->fn;
  c->mutated = 1;
  for (int tries = 0; tries < 8; ++tries) {
    switch (rint_(r, 6)) {
    case 0: /* an int argument */
      if (fn_ni(fn)) {
        int k = rint_(r, fn_ni(fn));
        char role = FN[fn].ir[k];
        if (role == 'c') {
          int v = c->iv[k];
          int opts[6] = {-1, INT_MIN, 0, sat_int((long long)v + 1), sat_int((long long)v - 1), sat_int(2LL * v)};
          c->iv[k] = opts[rint_(r, 6)];
          fix_arrays(r, c, cx);
        } else if (role == 'B') {
          c->iv[k] = (int[]){1 - c->iv[k], 2, -1}[rint_(r, 3)];
        } else if (role == 'f') {
          c->iv[k] = rrange(r, -1, NGMSH - 1);
        } else if (role == 'F') {
          c->iv[k] = rrange(r, -1, NSG - 1);
        } else {
          c->iv[k] = chance(r, 0.3) ? plausible_int(r, role, cx) : wild_int(r, role, c->iv[k], cx);
        }
        return;
      }
      break;
    case 1: /* a double argument */
      if (fn_nd(fn)) {
        c->dv[rint_(r, fn_nd(fn))] = wild_double(r);
        return;
      }
      break;
    case 2: /* an input array: NULL, or one element */
      if (fn_nin(fn)) {
        int j = rint_(r, fn_nin(fn));
        char role = FN[fn].ink[j];
        if ((fn == F_CONTACT_SCATTER_ADD || fn == F_SC_SCATTER_ADD) && j == 1) break; /* (the host vector's content) */
        if (role == 'o' || role == 'r' || in_runtime(fn, j) || chance(r, 0.2) || c->in[j].n == 0) {
          c->in[j].null_ = 1;
        } else if (role == 'q') {
          int64_t *v = &((int64_t *)c->in[j].p)[rint_(r, c->in[j].n)];
          *v = (int64_t[]){-1, -2, INT64_MIN, INT64_MAX, sat_inc64(*v), 1000000}[rint_(r, 6)];
        } else if (role == 'h') {
          int *v = &((int *)c->in[j].p)[rint_(r, c->in[j].n)];
          *v = (int[]){-1, INT_MIN, INT_MAX, sat_int((long long)*v + 1), pick_hnode(r, cx)}[rint_(r, 5)];
        } else if (role == 'x') {
          ((double *)c->in[j].p)[rint_(r, c->in[j].n)] = wild_double(r);
        } else {
          int *v = &((int *)c->in[j].p)[rint_(r, c->in[j].n)];
          *v = role == 'n' ? wild_int(r, 'n', *v, cx) : role == 'b' ? (int[]){0, 99, -1, pick_body(r, cx)}[rint_(r, 4)]
                                                                     : (int[]){0, 99, -1, pick_tag(r, cx)}[rint_(r, 4)];
        }
        return;
      }
      break;
    case 3: /* an output buffer: NULL or the wrong length */
      if (fn_nout(fn)) {
        int j = rint_(r, fn_nout(fn));
        if (FN[fn].scalar_out || FN[fn].req[j] == R_36 || FN[fn].req[j] == R_9 || chance(r, 0.3)) {
          c->out[j].null_ = 1;
        } else {
          long d[] = {-1, -1, -2, 1, 1000};
          c->out[j].ls = chance(r, 0.2) ? LS_FIXED : LS_REL;
          c->out[j].delta = c->out[j].ls == LS_FIXED ? rint_(r, 3) : d[rint_(r, 5)];
        }
        return;
      }
      break;
    case 4: /* the model */
      if (FN[fn].model) {
        c->null_model = 1;
        return;
      }
      break;
    default: /* options of a contact solve */
      if (fn == F_SOLVE_CONTACT || fn == F_STEP || fn == F_CONTACT_SET_OPTIONS || fn == F_SOLVE_ADAPTIVE ||
          fn == F_S_SOLVE_CONTACT || fn == F_S_STEP || fn == F_SC_CREATE) {
        int k = rint_(r, 6);
        if (k < 4) c->iv[k] = chance(r, 0.5) ? plausible_int(r, FN[fn].ir[k], cx) : wild_int(r, FN[fn].ir[k], c->iv[k], cx);
        else c->dv[k - 4] = chance(r, 0.5) ? plausible_double(r, FN[fn].dr[k - 4]) : wild_double(r);
        return;
      }
      break;
    }
  }
}

/* Structural and argument mutations of a scene. */
static void mutate_case(rng_t *r, case_t *cs, const ctx_t *cx) {
  int n_mut = rrange(r, 1, 4);
  for (int k = 0; k < n_mut && cs->n > 0; ++k) {
    int i = rint_(r, cs->n);
    switch (rint_(r, 16)) {
    case 0: case 1: case 2: case 3: mutate_arg(r, &cs->c[i], cx); break;
    case 13: { /* threads set (1, 2, 0 or negative) somewhere, around the solves */
      int at = rint_(r, cs->n + 1);
      case_t one = {0};
      call_t *c = add_call(&one, F_SET_THREADS);
      c->iv[0] = (int[]){1, 2, 0, -1, INT_MIN, 1, 2, 3}[rint_(r, 8)];
      c->mutated = 1;
      case_insert_copy(cs, at, c);
      if (chance(r, 0.5)) {
        case_t two = {0};
        add_call(&two, F_GET_THREADS)->mutated = 1;
        case_insert_copy(cs, at + 1, &two.c[0]);
        case_free(&two);
      }
      case_free(&one);
      break;
    }
    case 14: { /* a group of boundary edges added twice */
      int adds[64], na = 0;
      for (int k2 = 0; k2 < cs->n && na < 64; ++k2)
        if (cs->c[k2].fn == F_ADD_BOUNDARY_EDGES) adds[na++] = k2;
      if (na) {
        int src = adds[rint_(r, na)];
        int at = rrange(r, src + 1, cs->n);
        case_insert_copy(cs, at, &cs->c[src]);
        cs->c[at].mutated = 1;
      } else if (cx->mesh && cx->mesh->ne) {
        int tags[16], nt = mesh_tags(cx->mesh, tags), tag = tags[rint_(r, nt)];
        case_t one = {0};
        call_t *c = group_call(&one, cx->mesh, cx->base, F_ADD_BOUNDARY_EDGES, tag, tag);
        c->mutated = 1;
        case_insert_copy(cs, rint_(r, cs->n + 1), c);
        case_free(&one);
      }
      break;
    }
    case 15: /* a group added late: again, under another tag, or with an interior side */
      random_call(r, cs, cx, 0.0, rrange(r, cs->n / 2, cs->n), F_ADD_BOUNDARY_EDGES);
      break;
    case 11: case 12: { /* an extreme magnitude for a physical value */
      static const double ext[] = {1e300, DBL_MAX, 1e200, 1e155, 1e-300, 4.9406564584124654e-324, 1e-200, 1e30};
      int tries = 0;
      while (tries++ < 40 && !(fn_nd(cs->c[i].fn) > 0 && FN[cs->c[i].fn].model)) i = rint_(r, cs->n);
      call_t *c = &cs->c[i];
      if (fn_nd(c->fn) > 0) {
        int k = rint_(r, fn_nd(c->fn));
        c->dv[k] = ext[rint_(r, 8)] * (c->dv[k] < 0 ? -1 : 1);
        c->mutated = 1;
      }
      break;
    }
    case 10: /* new boundary edges, late: a tag gone or naming an interior edge */
      random_call(r, cs, cx, 0.0, rrange(r, cs->n / 2, cs->n), F_SET_BOUNDARY_EDGES);
      break;
    case 4: random_call(r, cs, cx, 0.3, rint_(r, cs->n + 1), -1); break;
    case 5: if (cs->n > 1) case_delete(cs, i); break;
    case 6: { /* duplicate, maybe mutated, right after or later */
      int at = chance(r, 0.5) ? i + 1 : rrange(r, i + 1, cs->n);
      case_insert_copy(cs, at, &cs->c[i]);
      cs->c[at].mutated = 1;
      if (chance(r, 0.5)) mutate_arg(r, &cs->c[at], cx);
      break;
    }
    case 7: if (i + 1 < cs->n) { /* swap neighbours */
        call_t t = cs->c[i];
        cs->c[i] = cs->c[i + 1];
        cs->c[i + 1] = t;
        cs->c[i].mutated = cs->c[i + 1].mutated = 1;
      }
      break;
    case 8: { /* move a call elsewhere (out of order) */
      call_t t = cs->c[i];
      memmove(&cs->c[i], &cs->c[i + 1], (size_t)(cs->n - 1 - i) * sizeof(call_t));
      int at = rint_(r, cs->n);
      memmove(&cs->c[at + 1], &cs->c[at], (size_t)(cs->n - 1 - at) * sizeof(call_t));
      cs->c[at] = t;
      cs->c[at].mutated = 1;
      break;
    }
    default: { /* a second solve with other options, or a failing one first */
      int at = rint_(r, cs->n + 1);
      call_t sc;
      memset(&sc, 0, sizeof sc);
      case_t one = {0};
      call_t *c = add_call(&one, chance(r, 0.5) ? F_SOLVE_CONTACT : F_SOLVE);
      c->iv[0] = rint_(r, 2);
      c->iv[1] = rint_(r, 2);
      c->iv[2] = chance(r, 0.3) ? 1 : 50;
      c->iv[3] = rint_(r, 2);
      c->mutated = 1;
      case_insert_copy(cs, at, c);
      case_free(&one);
      (void)sc;
      break;
    }
    }
  }
}

/* ------------------------------------------------------------------------ */
/* The 3D model and its contact context: meshes, scenes, random calls        */
/* ------------------------------------------------------------------------ */

/* A share of the cases (SOLID_SHARE, drawn from a stream of their own so
 * that every other case is the one it was) are 3D cases: the runner makes
 * the 3D handles, and the calls are the 3D model's, its contact context's
 * and, given the 3D handles, a few 2D ones. */
#define SOLID_SHARE 0.08
static double g_solid_share = SOLID_SHARE; /* (--solid-share: a campaign of 3D cases, 1 for 3D only) */

typedef struct {
  int nn, nt, nf;
  double *xyz;
  int *tet, *body, *face, *ftag; /* 0-based */
  int capn, capt, capf;
} smesh_t;

static int smesh_node(smesh_t *m, double x, double y, double z) {
  if (m->nn == m->capn) {
    m->capn = m->capn ? 2 * m->capn : 64;
    m->xyz = xrealloc(m->xyz, sizeof(double) * 3 * (size_t)m->capn);
  }
  m->xyz[3 * m->nn] = x;
  m->xyz[3 * m->nn + 1] = y;
  m->xyz[3 * m->nn + 2] = z;
  return m->nn++;
}
static void smesh_tet(smesh_t *m, const int v[4], int body) {
  if (m->nt == m->capt) {
    m->capt = m->capt ? 2 * m->capt : 64;
    m->tet = xrealloc(m->tet, sizeof(int) * 4 * (size_t)m->capt);
    m->body = xrealloc(m->body, sizeof(int) * (size_t)m->capt);
  }
  memcpy(&m->tet[4 * m->nt], v, 4 * sizeof(int));
  m->body[m->nt++] = body;
}
static void smesh_face(smesh_t *m, int a, int b, int c, int tag) {
  if (m->nf == m->capf) {
    m->capf = m->capf ? 2 * m->capf : 64;
    m->face = xrealloc(m->face, sizeof(int) * 3 * (size_t)m->capf);
    m->ftag = xrealloc(m->ftag, sizeof(int) * (size_t)m->capf);
  }
  m->face[3 * m->nf] = a;
  m->face[3 * m->nf + 1] = b;
  m->face[3 * m->nf + 2] = c;
  m->ftag[m->nf++] = tag;
}
static void smesh_free(smesh_t *m) {
  free(m->xyz), free(m->tet), free(m->body), free(m->face), free(m->ftag);
  memset(m, 0, sizeof *m);
}

/* A block [0, 1] x [0, 1] x [z0, z0 + 1] of n x n x n cells of Kuhn's six
 * tetrahedra (c_tests/solid_test.c's cube: the odd orders numbered
 * backwards, J > 0), body `body`, its sides tagged tag0 + 1 .. tag0 + 6
 * (x = 0, x = 1, y = 0, y = 1, z = z0, z = z0 + 1), every face of its
 * tetrahedra on a side. Returns its first node. */
static int kuhn_block(smesh_t *m, int n, double z0, int body, int tag0) {
  static const int orders[6][3] = {{0, 1, 2}, {1, 2, 0}, {2, 0, 1}, {0, 2, 1}, {2, 1, 0}, {1, 0, 2}};
  int first = m->nn, np = n + 1, start = m->nt;
  for (int k = 0; k < np; ++k)
    for (int j = 0; j < np; ++j)
      for (int i = 0; i < np; ++i) smesh_node(m, (double)i / n, (double)j / n, z0 + (double)k / n);
#define KID(i, j, k) (first + (i) + np * ((j) + np * (k)))
  for (int k = 0; k < n; ++k)
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i)
        for (int o = 0; o < 6; ++o) {
          int p[3] = {0, 0, 0}, v[4];
          v[0] = KID(i, j, k);
          for (int s = 0; s < 3; ++s) {
            p[orders[o][s]] = 1;
            v[s + 1] = KID(i + p[0], j + p[1], k + p[2]);
          }
          if (o >= 3) {
            int t = v[2];
            v[2] = v[3];
            v[3] = t;
          }
          smesh_tet(m, v, body);
        }
#undef KID
  for (int e = start; e < m->nt; ++e)
    for (int skip = 0; skip < 4; ++skip) {
      int f[3], nf = 0;
      for (int q = 0; q < 4; ++q)
        if (q != skip) f[nf++] = m->tet[4 * e + q];
      for (int axis = 0; axis < 3; ++axis)
        for (int end = 0; end < 2; ++end) {
          int at = end ? n : 0, on = 1;
          for (int q = 0; q < 3; ++q) {
            int rr = f[q] - first, g[3] = {rr % np, (rr / np) % np, rr / (np * np)};
            on = on && g[axis] == at;
          }
          if (on) smesh_face(m, f[0], f[1], f[2], tag0 + 1 + 2 * axis + end);
        }
    }
  return first;
}

/* The generation context of a 3D case. */
static ctx_t ctx3(const smesh_t *m, int base, int nbodies) {
  ctx_t cx;
  memset(&cx, 0, sizeof cx);
  cx.nn = m ? m->nn : 4;
  cx.nt = m ? m->nt : 0;
  cx.base = base;
  cx.ntags = 0;
  for (int f = 0; m && f < m->nf && cx.ntags < 8; ++f) {
    int k = 0;
    while (k < cx.ntags && cx.tags[k] != m->ftag[f]) ++k;
    if (k == cx.ntags) cx.tags[cx.ntags++] = m->ftag[f];
  }
  if (!cx.ntags) cx.tags[0] = 1, cx.tags[1] = 2, cx.tags[2] = 3, cx.tags[3] = 4, cx.ntags = 4;
  cx.nbodies = nbodies;
  for (int b = 0; b < nbodies && b < 4; ++b) cx.bodies[b] = b + 1;
  return cx;
}

static call_t *s_mesh_call(case_t *cs, const smesh_t *m, int base) {
  call_t *c = add_call(cs, F_S_SET_MESH);
  c->iv[0] = m->nn;
  c->iv[1] = m->nt;
  c->iv[2] = base;
  in_set(c, 0, m->xyz, 3 * m->nn, sizeof(double));
  in_set(c, 1, NULL, 4 * m->nt, sizeof(int));
  for (int k = 0; k < 4 * m->nt; ++k) ((int *)c->in[1].p)[k] = m->tet[k] + base;
  in_set(c, 2, m->body, m->nt, sizeof(int));
  return c;
}
/* The faces of m tagged `tag` (INT_MIN: every one) through fn, given the
 * tag `as_tag` (INT_MIN: their own). */
static call_t *s_faces_call(case_t *cs, const smesh_t *m, int base, int fn, int tag, int as_tag) {
  call_t *c = add_call(cs, fn);
  int n = 0;
  for (int f = 0; f < m->nf; ++f) n += tag == INT_MIN || m->ftag[f] == tag;
  c->iv[0] = n;
  in_set(c, 0, NULL, 3 * n, sizeof(int));
  in_set(c, 1, NULL, n, sizeof(int));
  for (int f = 0, k = 0; f < m->nf; ++f)
    if (tag == INT_MIN || m->ftag[f] == tag) {
      for (int q = 0; q < 3; ++q) ((int *)c->in[0].p)[3 * k + q] = m->face[3 * f + q] + base;
      ((int *)c->in[1].p)[k++] = as_tag == INT_MIN ? m->ftag[f] : as_tag;
    }
  return c;
}
/* The tagged faces of a scene: one tfem_solid_set_boundary_faces (60%),
 * or one group (tag) per call: set for the first and add for the others
 * (20%), or add only (20%). */
static void s_faces_calls(rng_t *r, case_t *cs, const smesh_t *m, int base) {
  int tags[16], nt = 0, v = rint_(r, 10);
  for (int f = 0; f < m->nf; ++f) {
    int k = 0;
    while (k < nt && tags[k] != m->ftag[f]) ++k;
    if (k == nt && nt < 16) tags[nt++] = m->ftag[f];
  }
  if (v < 6 || nt == 0) {
    s_faces_call(cs, m, base, F_S_SET_FACES, INT_MIN, INT_MIN);
    return;
  }
  for (int k = 0; k < nt; ++k) s_faces_call(cs, m, base, k == 0 && v < 8 ? F_S_SET_FACES : F_S_ADD_FACES, tags[k], INT_MIN);
}
static call_t *s_call(case_t *cs, int fn, int a, int b, double x, double y, double z) {
  call_t *c = add_call(cs, fn);
  c->iv[0] = a;
  c->iv[1] = b;
  c->dv[0] = x;
  c->dv[1] = y;
  c->dv[2] = z;
  return c;
}
/* A solve or step with options (law and test 0: frictionless, the 3D
 * test), or none (null_opts). */
static call_t *s_solve_call(case_t *cs, int fn, int maxit, int refac, double ec, double lam, double factor, int null_opts) {
  call_t *c = add_call(cs, fn);
  c->iv[2] = maxit;
  c->iv[3] = refac;
  c->dv[0] = ec;
  c->dv[1] = lam;
  c->dv[2] = factor;
  c->in[0].null_ = null_opts;
  return c;
}
static call_t *want(call_t *c, int status) {
  c->want = status + 1;
  return c;
}
/* Oracles of a pristine 3D scene (call_t.oracle; the closed form's
 * numbers in the getter's dv, which a getter does not pass) and the
 * reference displacements of its steps (call_t.tag; slot tw_a). */
enum { SO_TENSION_U = 10, SO_TENSION_S, SO_TENSION_R, SO_TENSION_W, SO_BLOCKS_S, SO_BLOCKS_AREA, SO_BLOCKS_ACTIVE,
       SO_BLOCKS_R, SO_BLOCKS_P, SO_BLOCKS_F };
enum { ST_REF = 20, ST_CMP };
static call_t *s_oracle(case_t *cs, int fn, int oracle, double load, double young, double nu) {
  call_t *c = add_call(cs, fn);
  c->oracle = oracle;
  c->dv[0] = load;
  c->dv[1] = young;
  c->dv[2] = nu;
  c->want = TFEM_STATUS_OK + 1;
  return c;
}
/* The displacements stored in slot `slot` (ST_REF), or compared with
 * those of the slot times `factor` within rtol of their largest (0: bit
 * for bit) (ST_CMP). */
static call_t *s_disp_tag(case_t *cs, int tag, int slot, double factor, double rtol) {
  call_t *c = add_call(cs, F_S_DISPLACEMENTS);
  c->tag = tag;
  c->tw_a = slot;
  c->dv[0] = factor;
  c->dv[1] = rtol;
  c->want = TFEM_STATUS_OK + 1;
  return c;
}

static void s_result_getters(rng_t *r, case_t *cs, int contact) {
  add_call(cs, F_S_GET_SIZES);
  add_call(cs, F_S_DISPLACEMENTS);
  if (chance(r, 0.6)) add_call(cs, F_S_REACTIONS);
  if (chance(r, 0.5)) add_call(cs, F_S_STRAINS);
  if (chance(r, 0.5)) add_call(cs, F_S_STRESSES);
  if (chance(r, 0.4)) add_call(cs, F_S_WORK);
  if (chance(r, 0.4)) add_call(cs, F_S_SOLVE_INFO);
  if (chance(r, 0.3)) add_call(cs, F_S_ITERATIONS);
  if (contact) {
    add_call(cs, F_S_CONTACT_ACTIVE);
    if (chance(r, 0.6)) add_call(cs, F_S_CONTACT_FORCES);
    if (chance(r, 0.5)) add_call(cs, F_S_NODAL_PRESSURES);
    if (chance(r, 0.5)) add_call(cs, F_S_AREA);
    if (chance(r, 0.4)) s_call(cs, F_S_PAIR_AREA, chance(r, 0.8) ? 0 : rrange(r, -1, 2), 0, 0, 0, 0);
    if (chance(r, 0.4)) add_call(cs, F_S_CONTACT_TETS);
  } else if (chance(r, 0.1)) {
    add_call(cs, chance(r, 0.5) ? F_S_AREA : F_S_CONTACT_FORCES);
  }
  if (chance(r, 0.3)) add_call(cs, F_S_WARNING_COUNT);
  if (chance(r, 0.15)) s_call(cs, F_S_GET_WARNING, 0, 0, 0, 0, 0)->out[0] = (out_spec){LS_FIXED, 512, 0, 0, 0, 0};
  if (chance(r, 0.15)) s_call(cs, F_S_GET_WARNING_SIZE, rint_(r, 2), 0, 0, 0, 0);
  if (chance(r, 0.15)) s_call(cs, F_S_WRITE_VTU, chance(r, 0.8) ? VP_FILE : rint_(r, NVTU), 0, 0, 0, 0);
  if (chance(r, 0.2)) add_call(cs, F_S_FACE_COUNT);
  if (chance(r, 0.2)) add_call(cs, F_S_MESH_NODES);
  if (chance(r, 0.2)) add_call(cs, F_S_MESH_TETS)->out[1].null_ = chance(r, 0.3);
  if (chance(r, 0.2)) add_call(cs, F_S_GET_FACES)->out[1].null_ = chance(r, 0.3);
  if (chance(r, 0.2)) add_call(cs, F_S_LAST_ERROR)->out[0] = (out_spec){LS_FIXED, 512, 0, 0, 0, 0};
  if (chance(r, 0.1)) add_call(cs, F_S_LAST_ERROR_LENGTH);
}

/* A unit cube of n x n x n cells (body 1, E, nu) on rollers (u_x = 0 on
 * x = 0, tag 1; u_y = 0 on y = 0, tag 3; u_z = 0 on z = 0, tag 5) pulled
 * by a traction t on x = 1 (tag 2; or a pressure -t there): uniaxial
 * stress, exactly u = (t x, -nu t y, -nu t z) / E, sigma = (t, 0, ...),
 * the rollers' reactions -t, the work t^2 / E. */
static void scene_solid_tension(rng_t *r, case_t *cs, ctx_t *cx, smesh_t *m) {
  int n = rrange(r, 1, 2), base = rint_(r, 2), k = rint_(r, 3);
  static const double Es[] = {1.0, 1000.0, 210e9}, ts[] = {0.1, 10.0, 1e6}, nus[] = {0.25, 0.3, 0.0};
  double E = Es[k], t = ts[k], nu = nus[rint_(r, 3)];
  kuhn_block(m, n, 0.0, 1, 0);
  *cx = ctx3(m, base, 1);
  int mat_first = chance(r, 0.3);
  if (mat_first) want(s_call(cs, F_S_SET_MATERIAL, 1, 0, E, nu, 0), TFEM_STATUS_OK);
  want(s_mesh_call(cs, m, base), TFEM_STATUS_OK);
  s_faces_calls(r, cs, m, base);
  if (!mat_first) want(s_call(cs, F_S_SET_MATERIAL, 1, 0, E, nu, 0), TFEM_STATUS_OK);
  if (chance(r, 0.3)) want(s_call(cs, F_S_SET_TEMPERING, chance(r, 0.5) ? 0 : 3, 0, 0, 0, 0), TFEM_STATUS_OK);
  int order[3] = {0, 1, 2};
  for (int i = 2; i > 0; --i) {
    int j = rint_(r, i + 1), x = order[i];
    order[i] = order[j], order[j] = x;
  }
  for (int i = 0; i < 3; ++i) want(s_call(cs, F_S_FIX_FACES, 1 + 2 * order[i], order[i], 0.0, 0, 0), TFEM_STATUS_OK);
  if (chance(r, 0.6)) want(s_call(cs, F_S_ADD_TRACTION, 2, 0, t, 0.0, 0.0), TFEM_STATUS_OK);
  else want(s_call(cs, F_S_ADD_PRESSURE, 2, 0, -t, 0, 0), TFEM_STATUS_OK);
  if (chance(r, 0.2)) want(s_call(cs, F_S_SET_ORDERING, rint_(r, 3), 0, 0, 0, 0), TFEM_STATUS_OK);
  if (chance(r, 0.5)) want(add_call(cs, F_S_SOLVE), TFEM_STATUS_OK);
  else want(s_solve_call(cs, F_S_SOLVE_CONTACT, 50, rint_(r, 2), 0, 0, 0, chance(r, 0.5)), TFEM_STATUS_OK);
  s_oracle(cs, F_S_DISPLACEMENTS, SO_TENSION_U, t, E, nu);
  if (chance(r, 0.7)) s_oracle(cs, F_S_STRESSES, SO_TENSION_S, t, E, nu);
  if (chance(r, 0.6)) s_oracle(cs, F_S_REACTIONS, SO_TENSION_R, t, E, nu);
  if (chance(r, 0.5)) s_oracle(cs, F_S_WORK, SO_TENSION_W, t, E, nu);
  if (chance(r, 0.2)) want(s_call(cs, F_S_SET_ORDERING, rint_(r, 3), 0, 0, 0, 0), TFEM_STATUS_OK);
  s_result_getters(r, cs, 0);
}

/* The stacked cubes of c_tests/solid_test.c: two blocks of n x n x n
 * cells, body 1 on z in [-1, 0] and body 2 on z in [gap, 1 + gap] (tags
 * 1..6 and 11..16), on rollers (u_z = 0 under the lower one, u_x = 0 on
 * x = 0 and u_y = 0 on y = 0 of both), pressed into frictionless contact
 * (the lower top, tag 6, and the upper bottom, tag 15, a pair either way
 * round): touching under a pressure p on the upper top (exact: sigma_zz =
 * -p, every tetrahedron of B active, contact area 1, the rollers carry p),
 * or across a gap of 0.01 by u_z = -0.02 prescribed there. Returns p (0
 * with a gap); *upper: the upper block's first node. */
static double solid_blocks_problem(rng_t *r, case_t *cs, ctx_t *cx, smesh_t *m, int gap, int *upper, double *young) {
  int n = rrange(r, 1, 2), base = rint_(r, 2);
  double E = chance(r, 0.5) ? 1.0 : 1000.0, nu = 0.25, p = 0.1 * E;
  kuhn_block(m, n, -1.0, 1, 0);
  *upper = kuhn_block(m, n, gap ? 0.01 : 0.0, 2, 10);
  *young = E;
  *cx = ctx3(m, base, 2);
  want(s_mesh_call(cs, m, base), TFEM_STATUS_OK);
  s_faces_calls(r, cs, m, base);
  want(s_call(cs, F_S_SET_MATERIAL, 1, 0, E, nu, 0), TFEM_STATUS_OK);
  want(s_call(cs, F_S_SET_MATERIAL, 2, 0, E, nu, 0), TFEM_STATUS_OK);
  static const int rollers[5][2] = {{5, TFEM_AXIS_Z}, {1, TFEM_AXIS_X}, {11, TFEM_AXIS_X}, {3, TFEM_AXIS_Y}, {13, TFEM_AXIS_Y}};
  int first = rint_(r, 5);
  for (int i = 0; i < 5; ++i)
    want(s_call(cs, F_S_FIX_FACES, rollers[(first + i) % 5][0], rollers[(first + i) % 5][1], 0.0, 0, 0), TFEM_STATUS_OK);
  if (gap) {
    want(s_call(cs, F_S_FIX_FACES, 16, TFEM_AXIS_Z, -0.02, 0, 0), TFEM_STATUS_OK);
    p = 0;
  } else if (chance(r, 0.7)) {
    want(s_call(cs, F_S_ADD_PRESSURE, 16, 0, p, 0, 0), TFEM_STATUS_OK);
  } else {
    want(s_call(cs, F_S_ADD_TRACTION, 16, 0, 0.0, 0.0, -p), TFEM_STATUS_OK);
  }
  if (chance(r, 0.7)) want(s_call(cs, F_S_ADD_PAIR, 6, 15, 0, 0, 0), TFEM_STATUS_OK);
  else want(s_call(cs, F_S_ADD_PAIR, 15, 6, 0, 0, 0), TFEM_STATUS_OK);
  return p;
}

static void scene_solid_blocks(rng_t *r, case_t *cs, ctx_t *cx, smesh_t *m, int gap) {
  int upper;
  double E, p = solid_blocks_problem(r, cs, cx, m, gap, &upper, &E);
  if (chance(r, 0.2)) want(s_call(cs, F_S_SET_TEMPERING, 0, 0, 0, 0, 0), TFEM_STATUS_OK);
  if (chance(r, 0.3)) want(add_call(cs, F_S_SOLVE), TFEM_STATUS_OK);
  else want(s_solve_call(cs, F_S_SOLVE_CONTACT, 50, rint_(r, 2), 0, 0, 0, chance(r, 0.4)), TFEM_STATUS_OK);
  if (!gap) {
    s_oracle(cs, F_S_STRESSES, SO_BLOCKS_S, p, E, 0.25);
    if (chance(r, 0.6)) s_oracle(cs, F_S_REACTIONS, SO_BLOCKS_R, p, E, 0.25);
    if (chance(r, 0.6)) s_oracle(cs, F_S_NODAL_PRESSURES, SO_BLOCKS_P, p, E, 0.25);
    if (chance(r, 0.6)) s_oracle(cs, F_S_CONTACT_FORCES, SO_BLOCKS_F, p, E, 0.25)->iv[0] = upper;
  }
  s_oracle(cs, F_S_AREA, SO_BLOCKS_AREA, p, E, 0.25);
  if (chance(r, 0.5)) s_oracle(cs, F_S_PAIR_AREA, SO_BLOCKS_AREA, p, E, 0.25);
  s_oracle(cs, F_S_CONTACT_ACTIVE, SO_BLOCKS_ACTIVE, p, E, 0.25);
  s_result_getters(r, cs, 1);
}

/* Load steps on the touching blocks: a step at a factor a is the solve
 * times a (the blocks stay in full contact: linear, within 1e-9 of the
 * largest), reverted to the solve's results bit for bit, once; a step
 * repeated after its revert, bit for bit; a bad factor refused, the
 * results kept; new loads (the pressure doubled) discard the results
 * (a revert refused), and a step at 1 is then twice the solve. */
static void scene_solid_steps(rng_t *r, case_t *cs, ctx_t *cx, smesh_t *m) {
  int upper;
  double E;
  solid_blocks_problem(r, cs, cx, m, 0, &upper, &E);
  double p = E * 0.1, a = (double[]){0.5, 0.25, 2.0, 1.0}[rint_(r, 4)];
  int null_opts = chance(r, 0.5), refac = chance(r, 0.3);
  want(s_solve_call(cs, F_S_SOLVE_CONTACT, 50, refac, 0, 0, 0, chance(r, 0.5)), TFEM_STATUS_OK);
  s_disp_tag(cs, ST_REF, 0, 1.0, 0.0);
  want(s_solve_call(cs, F_S_STEP, 50, refac, 0, 0, a, null_opts), TFEM_STATUS_OK);
  s_disp_tag(cs, ST_CMP, 0, a, 1e-9);
  if (chance(r, 0.5)) s_oracle(cs, F_S_STRESSES, SO_BLOCKS_S, a * p, E, 0.25);
  want(add_call(cs, F_S_REVERT_STEP), TFEM_STATUS_OK);
  s_disp_tag(cs, ST_CMP, 0, 1.0, 0.0);
  want(add_call(cs, F_S_REVERT_STEP), TFEM_STATUS_INVALID_STATE);
  double b = (double[]){0.5, 0.75, 1.5}[rint_(r, 3)];
  want(s_solve_call(cs, F_S_STEP, 50, refac, 0, 0, b, null_opts), TFEM_STATUS_OK);
  s_disp_tag(cs, ST_REF, 1, 1.0, 0.0);
  want(add_call(cs, F_S_REVERT_STEP), TFEM_STATUS_OK);
  want(s_solve_call(cs, F_S_STEP, 50, refac, 0, 0, b, null_opts), TFEM_STATUS_OK);
  s_disp_tag(cs, ST_CMP, 1, 1.0, 0.0);
  if (chance(r, 0.5)) {
    double bad = (double[]){NAN, INFINITY, -INFINITY, 1e301, -1e301}[rint_(r, 5)];
    want(s_solve_call(cs, F_S_STEP, 50, refac, 0, 0, bad, null_opts), TFEM_STATUS_INVALID_ARGUMENT);
    s_disp_tag(cs, ST_CMP, 1, 1.0, 0.0);
  }
  if (chance(r, 0.5)) {
    want(s_call(cs, F_S_ADD_PRESSURE, 16, 0, p, 0, 0), TFEM_STATUS_OK);
    want(add_call(cs, F_S_REVERT_STEP), TFEM_STATUS_INVALID_STATE);
    want(s_solve_call(cs, F_S_STEP, 50, refac, 0, 0, 1.0, null_opts), TFEM_STATUS_OK);
    s_disp_tag(cs, ST_CMP, 0, 2.0, 1e-9);
  }
  s_result_getters(r, cs, 1);
}

/* The interface of tag `tag` of m as one side of a 3D contact context:
 * host node numbers mul * node + off, equations 3 node + component in the
 * index base (none for the DOFs the blocks' rollers fix: u_x on x = 0,
 * u_y on y = 0), triangles counter-clockwise seen from outside (their
 * normal along out_z). */
static call_t *s_side_call(case_t *cs, const smesh_t *m, int tag, int body, double young, int base, int mul, int off,
                           double out_z) {
  int nf = 0, nn = 0, *nodes = xmalloc(sizeof(int) * 3 * (size_t)m->nf + 1);
  for (int f = 0; f < m->nf; ++f)
    if (m->ftag[f] == tag) {
      ++nf;
      for (int q = 0; q < 3; ++q) {
        int v = m->face[3 * f + q], seen = 0;
        for (int i = 0; i < nn && !seen; ++i) seen = nodes[i] == v;
        if (!seen) nodes[nn++] = v;
      }
    }
  call_t *c = add_call(cs, F_SC_ADD_SIDE);
  c->iv[0] = tag;
  c->iv[1] = body;
  c->iv[2] = nn;
  c->iv[3] = nf;
  c->dv[0] = young;
  in_set(c, 0, NULL, nn, sizeof(int));
  in_set(c, 1, NULL, 3 * nn, sizeof(double));
  in_set(c, 2, NULL, 3 * nn, sizeof(int64_t));
  in_set(c, 3, NULL, 3 * nf, sizeof(int));
  for (int i = 0; i < nn; ++i) {
    int v = nodes[i];
    ((int *)c->in[0].p)[i] = mul * v + off;
    for (int k = 0; k < 3; ++k) {
      ((double *)c->in[1].p)[3 * i + k] = m->xyz[3 * v + k];
      ((int64_t *)c->in[2].p)[3 * i + k] = k < 2 && m->xyz[3 * v + k] == 0.0 ? base - 1 : 3 * v + k + base;
    }
  }
  for (int f = 0, k = 0; f < m->nf; ++f)
    if (m->ftag[f] == tag) {
      int t[3] = {m->face[3 * f], m->face[3 * f + 1], m->face[3 * f + 2]};
      const double *a = &m->xyz[3 * t[0]], *b = &m->xyz[3 * t[1]], *d = &m->xyz[3 * t[2]];
      double nz = (b[0] - a[0]) * (d[1] - a[1]) - (b[1] - a[1]) * (d[0] - a[0]);
      if (nz * out_z < 0) {
        int x = t[1];
        t[1] = t[2], t[2] = x;
      }
      for (int q = 0; q < 3; ++q) ((int *)c->in[3].p)[3 * k + q] = mul * t[q] + off;
      ++k;
    }
  free(nodes);
  return c;
}

/* A 3D host code on the blocks: the model solves them, and a 3D contact
 * context holds the same interface, its equations those of the model's
 * DOFs (3 node + component), so that the model's displacements are the
 * host's solution vector. Every entry point of the context, in the order
 * of a host's active-set loop. */
static void scene_solid_host(rng_t *r, case_t *cs, ctx_t *cx, smesh_t *m) {
  int upper;
  double E;
  solid_blocks_problem(r, cs, cx, m, chance(r, 0.2), &upper, &E);
  want(s_solve_call(cs, F_S_SOLVE_CONTACT, 50, 0, 0, 0, 0, 1), TFEM_STATUS_OK);
  add_call(cs, F_S_DISPLACEMENTS);
  int base = rint_(r, 2), mul = chance(r, 0.5) ? 1 : 3, off = chance(r, 0.5) ? base : 7;
  cs->coupled = 2;
  cs->hm_mul = mul;
  cs->hm_off = off;
  cs->neq = 3 * m->nn;
  cx->hbase = base;
  cx->nh = 0;
  for (int f = 0; f < m->nf && cx->nh < 64; ++f)
    if (m->ftag[f] == 6 || m->ftag[f] == 15) cx->hids[cx->nh++] = mul * m->face[3 * f] + off;
  cx->nsides = 2;
  call_t *c = add_call(cs, F_SC_CREATE);
  c->iv[2] = chance(r, 0.8) ? 50 : 3;
  c->iv[4] = base;
  c->dv[0] = chance(r, 0.7) ? 0 : E;
  c->dv[1] = chance(r, 0.7) ? 0 : 1.0;
  c->in[0].null_ = chance(r, 0.5);
  want(c, TFEM_STATUS_OK);
  want(s_side_call(cs, m, 6, 1, E, base, mul, off, 1.0), TFEM_STATUS_OK);
  want(s_side_call(cs, m, 15, 2, E, base, mul, off, -1.0), TFEM_STATUS_OK);
  want(s_call(cs, F_SC_ADD_PAIR, base, base + 1, 0, 0, 0), TFEM_STATUS_OK);
  if (chance(r, 0.5)) want(add_call(cs, F_SC_SETUP), TFEM_STATUS_OK);
  add_call(cs, F_SC_SIZES);
  add_call(cs, F_SC_NODES);
  add_call(cs, F_SC_PATTERN);
  if (chance(r, 0.6)) add_call(cs, F_SC_ELEMENT_EQUATIONS);
  if (chance(r, 0.5)) add_call(cs, F_SC_ELEMENT_BLOCKS);
  if (chance(r, 0.5)) add_call(cs, F_SC_TETS);
  rt_call(cs, F_SC_EVALUATE, 0, rint_(r, 1000)); /* the initial gaps' load */
  rt_call(cs, F_SC_GATHER, 2, rint_(r, 1000));   /* the model's displacements */
  rt_call(cs, F_SC_UPDATE, 2, rint_(r, 1000));
  add_call(cs, F_SC_GET_ACTIVE);
  rt_call(cs, F_SC_EVALUATE, 2, rint_(r, 1000));
  rt_call(cs, F_SC_SCATTER_ADD, 1, rint_(r, 1000));
  add_call(cs, F_SC_AREA);
  rt_call(cs, F_SC_GAPS, 2, rint_(r, 1000));
  rt_call(cs, F_SC_SET_ACTIVE, chance(r, 0.5) ? 3 : 2, rint_(r, 1000));
  add_call(cs, F_SC_GET_ACTIVE);
  if (chance(r, 0.5)) add_call(cs, F_SC_RESTART);
  rt_call(cs, F_SC_UPDATE, chance(r, 0.5) ? 0 : 1, rint_(r, 1000));
  rt_call(cs, F_SC_UPDATE, 2, rint_(r, 1000));
  rt_call(cs, F_SC_GAPS, 1, rint_(r, 1000));
  if (chance(r, 0.3)) add_call(cs, F_SC_LAST_ERROR)->out[0] = (out_spec){LS_FIXED, 512, 0, 0, 0, 0};
  if (chance(r, 0.2)) add_call(cs, F_SC_LAST_ERROR_LENGTH);
  if (chance(r, 0.2)) {
    add_call(cs, F_SC_DESTROY);
    add_call(cs, F_SC_AREA);
    if (chance(r, 0.5)) add_call(cs, F_SC_LAST_ERROR_LENGTH);
  }
}

/* A tetrahedral Gmsh file (SG_VALID 75%: nodes A..E, ABC in groups 10 and
 * 99, BCE in 20), its mesh and faces read back, held (u_z = 0 on ABC, A
 * fixed in x and y, B in y) and pressed on BCE, solved; or a file refused
 * (the model unchanged). */
static void scene_solid_gmsh(rng_t *r, case_t *cs, ctx_t *cx) {
  int base = rint_(r, 2), file = chance(r, 0.75) ? SG_VALID : rint_(r, NSG);
  smesh_t none = {0};
  *cx = ctx3(&none, base, 1);
  cx->nn = 5, cx->tags[0] = 10, cx->tags[1] = 20, cx->tags[2] = 99, cx->ntags = 3;
  call_t *c = s_call(cs, F_S_LOAD_GMSH, file, base, 0, 0, 0);
  if (file == SG_VALID) want(c, TFEM_STATUS_OK);
  if (chance(r, 0.3)) s_call(cs, F_S_LOAD_GMSH, 1 + rint_(r, NSG - 1), base, 0, 0, 0);
  add_call(cs, F_S_GET_SIZES);
  if (chance(r, 0.6)) add_call(cs, F_S_FACE_COUNT);
  if (chance(r, 0.6)) add_call(cs, F_S_MESH_NODES);
  if (chance(r, 0.6)) add_call(cs, F_S_MESH_TETS);
  if (chance(r, 0.6)) add_call(cs, F_S_GET_FACES);
  s_call(cs, F_S_SET_MATERIAL, 1, 0, 1.0, 0.3, 0);
  s_call(cs, F_S_FIX_FACES, 10, TFEM_AXIS_Z, 0.0, 0, 0);
  s_call(cs, F_S_FIX, base, TFEM_AXIS_X, 0.0, 0, 0);
  s_call(cs, F_S_FIX, base, TFEM_AXIS_Y, 0.0, 0, 0);
  s_call(cs, F_S_FIX, base + 1, TFEM_AXIS_Y, 0.0, 0, 0);
  s_call(cs, F_S_ADD_PRESSURE, 20, 0, 0.1, 0, 0);
  if (file == SG_VALID) want(add_call(cs, F_S_SOLVE), TFEM_STATUS_OK);
  else add_call(cs, F_S_SOLVE);
  s_result_getters(r, cs, 0);
}

/* A random tetrahedral mesh: 4..14 nodes on the grid of step 1/2 in the
 * unit cube (20%: scaled by a wild number), 1..12 tetrahedra of random
 * nodes (10% with a node repeated), some of their faces tagged 1..4, a
 * random triangle sometimes. */
static void solid_random_mesh(rng_t *r, smesh_t *m, int nbodies) {
  int nn = rrange(r, 4, 14), nt = rrange(r, 1, 12);
  double scale = chance(r, 0.8) ? 1.0 : wild_double(r);
  for (int i = 0; i < nn; ++i)
    smesh_node(m, rint_(r, 3) * 0.5 * scale, rint_(r, 3) * 0.5 * scale, rint_(r, 3) * 0.5 * scale);
  for (int t = 0; t < nt; ++t) {
    int v[4];
    for (int k = 0; k < 4; ++k) {
      v[k] = rint_(r, nn);
      for (int tries = 0; tries < 20 && chance(r, 0.9); ++tries) {
        int dup = 0;
        for (int q = 0; q < k; ++q) dup |= v[q] == v[k];
        if (!dup) break;
        v[k] = rint_(r, nn);
      }
    }
    smesh_tet(m, v, 1 + rint_(r, nbodies));
  }
  for (int t = 0; t < nt; ++t)
    for (int skip = 0; skip < 4; ++skip)
      if (chance(r, 0.25)) {
        int f[3], k = 0;
        for (int q = 0; q < 4; ++q)
          if (q != skip) f[k++] = m->tet[4 * t + q];
        smesh_face(m, f[0], f[1], f[2], rrange(r, 1, 4));
      }
  if (chance(r, 0.1)) smesh_face(m, rint_(r, nn), rint_(r, nn), rint_(r, nn), rrange(r, 1, 4));
}

/* Whether call c passes a handle (and so can be given another one). */
static int takes_handle(int fn) { return FN[fn].model != 0; }
/* A handle of another kind than fn's, or one of its own destroyed (5). */
static int other_handle(rng_t *r, int fn) {
  int own = FN[fn].model, h;
  do h = rrange(r, 1, 5);
  while (h == own);
  return h;
}

static int huge_count(rng_t *r, call_t *c);
/* A random 3D call (or a 2D one given a 3D handle); arguments plausible
 * for the context, each made wild with probability `wild`. */
static void random_solid_call(rng_t *r, case_t *cs, const ctx_t *cx, const smesh_t *sm, double wild, int at, int forced) {
  static const int weight[NF] = {
      [F_S_LAST_ERROR] = 3, [F_S_LAST_ERROR_LENGTH] = 2, [F_S_WARNING_COUNT] = 2, [F_S_GET_WARNING_SIZE] = 2,
      [F_S_GET_WARNING] = 2, [F_S_SET_MESH] = 3, [F_S_LOAD_GMSH] = 2, [F_S_SET_FACES] = 3, [F_S_ADD_FACES] = 3,
      [F_S_GET_SIZES] = 2, [F_S_FACE_COUNT] = 2, [F_S_MESH_NODES] = 2, [F_S_MESH_TETS] = 2, [F_S_GET_FACES] = 2,
      [F_S_SET_MATERIAL] = 4, [F_S_SET_TEMPERING] = 3, [F_S_SET_ORDERING] = 2, [F_S_FIX] = 4, [F_S_FIX_FACES] = 4,
      [F_S_CLEAR_CONSTRAINTS] = 2, [F_S_ADD_PRESSURE] = 3, [F_S_ADD_TRACTION] = 3, [F_S_ADD_NODAL_FORCE] = 3,
      [F_S_CLEAR_LOADS] = 2, [F_S_ADD_PAIR] = 3, [F_S_CLEAR_PAIRS] = 2, [F_S_SOLVE] = 5, [F_S_SOLVE_CONTACT] = 5,
      [F_S_STEP] = 4, [F_S_REVERT_STEP] = 3, [F_S_SOLVE_INFO] = 2, [F_S_ITERATIONS] = 2, [F_S_DISPLACEMENTS] = 4,
      [F_S_STRAINS] = 2, [F_S_STRESSES] = 3, [F_S_REACTIONS] = 3, [F_S_WORK] = 2, [F_S_CONTACT_TETS] = 2,
      [F_S_CONTACT_ACTIVE] = 3, [F_S_CONTACT_FORCES] = 3, [F_S_NODAL_PRESSURES] = 3, [F_S_AREA] = 2,
      [F_S_PAIR_AREA] = 2, [F_S_WRITE_VTU] = 2, [F_S_DESTROY] = 1, [F_S_RECREATE] = 1,
      [F_SC_CREATE] = 3, [F_SC_DESTROY] = 1, [F_SC_LAST_ERROR] = 2, [F_SC_LAST_ERROR_LENGTH] = 1, [F_SC_ADD_SIDE] = 4,
      [F_SC_ADD_PAIR] = 3, [F_SC_SETUP] = 2, [F_SC_SIZES] = 2, [F_SC_NODES] = 1, [F_SC_TETS] = 1, [F_SC_PATTERN] = 1,
      [F_SC_ELEMENT_EQUATIONS] = 1, [F_SC_ELEMENT_BLOCKS] = 1, [F_SC_EVALUATE] = 2, [F_SC_GATHER] = 2,
      [F_SC_SCATTER_ADD] = 2, [F_SC_UPDATE] = 2, [F_SC_RESTART] = 1, [F_SC_GET_ACTIVE] = 1, [F_SC_SET_ACTIVE] = 1,
      [F_SC_GAPS] = 2, [F_SC_AREA] = 1,
      /* 2D functions, given a 3D handle */
      [F_GET_SIZES] = 1, [F_SOLVE] = 1, [F_SET_MATERIAL] = 1, [F_LAST_ERROR] = 1, [F_LAST_ERROR_LENGTH] = 1,
      [F_GET_DISPLACEMENTS] = 1, [F_CONTACT_SIZES] = 1, [F_CONTACT_LAST_ERROR] = 1, [F_CONTACT_LAST_ERROR_LENGTH] = 1,
      [F_CONTACT_EVALUATE] = 1};
  int total = 0;
  for (int f = 0; f < NF; ++f) total += weight[f];
  int x = rint_(r, total), fn = 0;
  while (x >= weight[fn]) x -= weight[fn++];
  if (forced >= 0) fn = forced;
  case_t one = {0};
  call_t *c = add_call(&one, fn);
  for (int k = 0; k < fn_ni(fn); ++k) {
    char role = FN[fn].ir[k];
    c->iv[k] = plausible_int(r, role, cx);
    if (chance(r, wild) && role != 'c') c->iv[k] = wild_int(r, role, c->iv[k], cx);
  }
  for (int k = 0; k < fn_nd(fn); ++k)
    c->dv[k] = chance(r, wild) ? wild_double(r) : plausible_double(r, FN[fn].dr[k]);
  switch (fn) {
  case F_S_SET_MESH: {
    smesh_t rm = {0};
    const smesh_t *use = sm && sm->nt && chance(r, 0.5) ? sm : (solid_random_mesh(r, &rm, cx->nbodies > 1 ? 2 : 1), &rm);
    c->iv[0] = use->nn;
    c->iv[1] = use->nt;
    c->iv[2] = chance(r, wild) ? wild_int(r, 'B', cx->base, cx) : cx->base;
    in_set(c, 0, use->xyz, 3 * use->nn, sizeof(double));
    in_set(c, 1, NULL, 4 * use->nt, sizeof(int));
    for (int k = 0; k < 4 * use->nt; ++k) ((int *)c->in[1].p)[k] = use->tet[k] + cx->base;
    in_set(c, 2, use->body, use->nt, sizeof(int));
    smesh_free(&rm);
    break;
  }
  case F_S_SET_FACES: case F_S_ADD_FACES: {
    /* the scene's faces (set: most of them; add: one tag's, as it or
     * under another tag), sometimes a face inside the mesh (of two
     * tetrahedra) or random nodes */
    int nf = 0, cap = (sm ? sm->nf : 0) + 4, tag = sm && sm->nf ? sm->ftag[rint_(r, sm->nf)] : 1;
    int as = fn == F_S_ADD_FACES && chance(r, 0.4) ? pick_tag(r, cx) : INT_MIN;
    int *fv = xmalloc(sizeof(int) * 3 * (size_t)cap), *tg = xmalloc(sizeof(int) * (size_t)cap);
    double keep = chance(r, 0.5) ? 1.0 : 0.8;
    for (int f = 0; sm && f < sm->nf; ++f)
      if ((fn == F_S_SET_FACES || sm->ftag[f] == tag) && chance(r, keep)) {
        for (int q = 0; q < 3; ++q) fv[3 * nf + q] = sm->face[3 * f + q] + cx->base;
        tg[nf++] = as != INT_MIN ? as : chance(r, 0.9) ? sm->ftag[f] : pick_tag(r, cx);
      }
    if (sm && sm->nt > 1 && chance(r, 0.2)) { /* a face of a tetrahedron, maybe inside */
      int t = rint_(r, sm->nt), skip = rint_(r, 4), k = 0;
      for (int q = 0; q < 4; ++q)
        if (q != skip) fv[3 * nf + k++] = sm->tet[4 * t + q] + cx->base;
      tg[nf++] = pick_tag(r, cx);
    }
    if (nf == 0 || chance(r, 0.1)) {
      for (int q = 0; q < 3; ++q) fv[3 * nf + q] = pick_node(r, cx);
      tg[nf++] = pick_tag(r, cx);
    }
    c->iv[0] = nf;
    in_set(c, 0, fv, 3 * nf, sizeof(int));
    in_set(c, 1, tg, nf, sizeof(int));
    free(fv), free(tg);
    break;
  }
  case F_SC_ADD_SIDE:
    if (sm && sm->nf && chance(r, 0.7)) {
      /* a side of the scene's interface (tag 6 or 15), in the case's host numbering */
      int tag = chance(r, 0.5) ? 6 : 15, mul = cs->hm_mul > 0 ? cs->hm_mul : 1, off = cs->hm_mul > 0 ? cs->hm_off : cx->hbase;
      case_t tmp = {0};
      call_t *sc = s_side_call(&tmp, sm, tag, tag == 6 ? 1 : 2, chance(r, wild) ? wild_double(r) : 1.0, cx->hbase, mul, off,
                               tag == 6 ? 1.0 : -1.0);
      if (sc->iv[3] > 0) {
        call_t keep_c;
        memset(&keep_c, 0, sizeof keep_c);
        for (int j = 0; j < 4; ++j) in_set(c, j, sc->in[j].p, sc->in[j].n, in_el(F_SC_ADD_SIDE, j));
        c->iv[0] = sc->iv[0], c->iv[1] = sc->iv[1], c->iv[2] = sc->iv[2], c->iv[3] = sc->iv[3], c->dv[0] = sc->dv[0];
        (void)keep_c;
      }
      case_free(&tmp);
    }
    break;
  case F_S_SOLVE_CONTACT: case F_S_STEP: case F_SC_CREATE:
    if (!chance(r, wild)) c->iv[0] = c->iv[1] = 0; /* (frictionless, the 3D test: what 3D takes) */
    if (fn == F_SC_CREATE) c->iv[4] = chance(r, wild) ? wild_int(r, 'B', cx->hbase, cx) : cx->hbase;
    if (chance(r, 0.2)) c->in[0].null_ = 1;
    break;
  case F_S_LAST_ERROR: case F_SC_LAST_ERROR: case F_S_GET_WARNING: case F_LAST_ERROR: case F_CONTACT_LAST_ERROR:
    c->out[0] = (out_spec){chance(r, 0.7) ? LS_FIXED : LS_EXACT, rint_(r, 3) ? 512 : rint_(r, 40), 0, 0, 0, 0};
    break;
  default: break;
  }
  fix_arrays(r, c, cx);
  if (chance(r, wild * 0.1)) huge_count(r, c);
  if (FN[fn].model && chance(r, wild * 0.2)) c->null_model = 1;
  /* a handle of another kind: the 2D functions always get one (the 2D
   * model of a 3D case holds nothing), the 3D ones sometimes */
  if (takes_handle(fn) && (FN[fn].model <= 2 || chance(r, 0.03 + wild * 0.2))) c->handle = other_handle(r, fn);
  if (FN[fn].model <= 2 && c->handle == 5) c->handle = 3 + rint_(r, 2);
  for (int j = 0; j < fn_nout(fn); ++j) {
    if (chance(r, wild * 0.3)) c->out[j].null_ = 1;
    else if (!FN[fn].scalar_out && chance(r, wild * 0.5))
      c->out[j] = (out_spec){LS_REL, chance(r, 0.7) ? -1 : rrange(r, -3, 3), 0, 0, 0, 0};
  }
  c->mutated = 1;
  case_insert_copy(cs, at < 0 ? cs->n : at, c);
  case_free(&one);
}

/* A count of call c made huge (INT_MAX, 2^30, 2^28) with the arrays it
 * sizes NULL: a count larger than its array is the caller's error, but
 * with the array NULL the call must be refused before it reads or
 * reserves anything (no abort, no huge allocation). Returns 0 if c has no
 * count. */
static int huge_count(rng_t *r, call_t *c) {
  int fn = c->fn, ks[4], nk = 0;
  for (int i = 0; i < fn_ni(fn); ++i)
    if (FN[fn].ir[i] == 'c') ks[nk++] = i;
  if (!nk) return 0;
  int k = ks[rint_(r, nk)];
  c->iv[k] = (int[]){INT_MAX, 1 << 30, 1 << 28}[rint_(r, 3)];
  switch (fn) {
  case F_S_SET_MESH:
    if (k == 0) c->in[0].null_ = 1;
    else c->in[1].null_ = c->in[2].null_ = 1;
    break;
  case F_S_SET_FACES: case F_S_ADD_FACES: c->in[0].null_ = c->in[1].null_ = 1; break;
  case F_SC_ADD_SIDE:
    if (k == 2) c->in[0].null_ = c->in[1].null_ = c->in[2].null_ = 1;
    else c->in[3].null_ = 1;
    break;
  default:
    for (int j = 0; j < fn_nin(fn); ++j) c->in[j].null_ = 1;
    break;
  }
  c->mutated = 1;
  return 1;
}

/* Structural and argument mutations of a 3D scene. */
static void solid_mutate_case(rng_t *r, case_t *cs, const ctx_t *cx, const smesh_t *sm) {
  int n_mut = rrange(r, 1, 4);
  for (int k = 0; k < n_mut && cs->n > 0; ++k) {
    int i = rint_(r, cs->n);
    switch (rint_(r, 16)) {
    case 0: case 1: case 2: mutate_arg(r, &cs->c[i], cx); break;
    case 3: { /* an argument, or a count made huge with its arrays NULL */
      int tries = 0;
      if (chance(r, 0.5)) {
        mutate_arg(r, &cs->c[i], cx);
        break;
      }
      while (tries++ < 40 && !strchr(FN[cs->c[i].fn].ir, 'c')) i = rint_(r, cs->n);
      if (!huge_count(r, &cs->c[i])) mutate_arg(r, &cs->c[i], cx);
      break;
    }
    case 4: case 5: random_solid_call(r, cs, cx, sm, 0.3, rint_(r, cs->n + 1), -1); break;
    case 6: if (cs->n > 1) case_delete(cs, i); break;
    case 7: { /* duplicate, maybe mutated, right after or later */
      int at = chance(r, 0.5) ? i + 1 : rrange(r, i + 1, cs->n);
      case_insert_copy(cs, at, &cs->c[i]);
      cs->c[at].mutated = 1;
      if (chance(r, 0.5)) mutate_arg(r, &cs->c[at], cx);
      break;
    }
    case 8: if (i + 1 < cs->n) { /* swap neighbours */
        call_t t = cs->c[i];
        cs->c[i] = cs->c[i + 1];
        cs->c[i + 1] = t;
        cs->c[i].mutated = cs->c[i + 1].mutated = 1;
      }
      break;
    case 9: { /* move a call elsewhere */
      call_t t = cs->c[i];
      memmove(&cs->c[i], &cs->c[i + 1], (size_t)(cs->n - 1 - i) * sizeof(call_t));
      int at = rint_(r, cs->n);
      memmove(&cs->c[at + 1], &cs->c[at], (size_t)(cs->n - 1 - at) * sizeof(call_t));
      cs->c[at] = t;
      cs->c[at].mutated = 1;
      break;
    }
    case 10: { /* a handle of another kind, or destroyed, on a call that takes one */
      int tries = 0;
      while (tries++ < 40 && !takes_handle(cs->c[i].fn)) i = rint_(r, cs->n);
      if (takes_handle(cs->c[i].fn)) {
        cs->c[i].handle = other_handle(r, cs->c[i].fn);
        cs->c[i].mutated = 1;
      }
      break;
    }
    case 11: { /* an extreme magnitude for a physical value */
      static const double ext[] = {1e300, DBL_MAX, 1e200, 1e155, 1e-300, 4.9406564584124654e-324, 1e-200, 1e30};
      int tries = 0;
      while (tries++ < 40 && !(fn_nd(cs->c[i].fn) > 0 && FN[cs->c[i].fn].model)) i = rint_(r, cs->n);
      call_t *c = &cs->c[i];
      if (fn_nd(c->fn) > 0 && FN[c->fn].model) {
        int kk = rint_(r, fn_nd(c->fn));
        c->dv[kk] = ext[rint_(r, 8)] * (c->dv[kk] < 0 ? -1 : 1);
        c->mutated = 1;
      }
      break;
    }
    case 12: { /* another solve or step, with other options */
      case_t one = {0};
      int fn = (int[]){F_S_SOLVE, F_S_SOLVE_CONTACT, F_S_STEP, F_S_REVERT_STEP}[rint_(r, 4)];
      call_t *c = s_solve_call(&one, fn, chance(r, 0.3) ? 1 : 50, rint_(r, 2), chance(r, 0.8) ? 0 : wild_double(r),
                               chance(r, 0.8) ? 0 : 0.5, plausible_double(r, 'a'), chance(r, 0.3));
      c->mutated = 1;
      case_insert_copy(cs, rint_(r, cs->n + 1), c);
      case_free(&one);
      break;
    }
    case 13: { /* the model or the context re-created or destroyed, or a handle destroyed as another kind */
      case_t one = {0};
      int fn = (int[]){F_S_RECREATE, F_S_DESTROY, F_SC_DESTROY, F_SC_CREATE}[rint_(r, 4)];
      call_t *c = add_call(&one, fn);
      if (fn == F_S_DESTROY || (fn == F_SC_DESTROY && chance(r, 0.6))) c->handle = other_handle(r, fn);
      if (fn == F_SC_CREATE) c->iv[2] = 50, c->iv[4] = cx->hbase;
      c->mutated = 1;
      case_insert_copy(cs, rint_(r, cs->n + 1), c);
      case_free(&one);
      break;
    }
    case 14: /* faces given late (while constraints, loads or pairs name them) or again */
      random_solid_call(r, cs, cx, sm, 0.0, rrange(r, cs->n / 2, cs->n), chance(r, 0.5) ? F_S_SET_FACES : F_S_ADD_FACES);
      break;
    default: { /* the ordering (results kept) anywhere */
      case_t one = {0};
      call_t *c = s_call(&one, F_S_SET_ORDERING, chance(r, 0.8) ? rint_(r, 3) : (int[]){-1, 3, INT_MIN}[rint_(r, 3)], 0,
                         0, 0, 0);
      c->mutated = 1;
      case_insert_copy(cs, rint_(r, cs->n + 1), c);
      if (chance(r, 0.5)) {
        case_t two = {0};
        add_call(&two, F_S_DISPLACEMENTS)->mutated = 1;
        case_insert_copy(cs, rint_(r, cs->n + 1), &two.c[0]);
        case_free(&two);
      }
      case_free(&one);
      break;
    }
    }
  }
}

/* Builds a 3D case (valid scenes, mutated or left pristine; random
 * sequences), from the case's own stream r. */
static void gen_solid_case(rng_t *r, case_t *cs) {
  smesh_t sm = {0};
  ctx_t cx;
  memset(&cx, 0, sizeof cx);
  cs->solid = 1;
  if (chance(r, 0.65)) {
    int s = rint_(r, 20);
    if (s < 4) { cs->kind = "solid_tension"; scene_solid_tension(r, cs, &cx, &sm); }
    else if (s < 7) { cs->kind = "solid_blocks"; scene_solid_blocks(r, cs, &cx, &sm, 0); }
    else if (s < 9) { cs->kind = "solid_gap"; scene_solid_blocks(r, cs, &cx, &sm, 1); }
    else if (s < 13) { cs->kind = "solid_steps"; scene_solid_steps(r, cs, &cx, &sm); }
    else if (s < 18) { cs->kind = "solid_host"; scene_solid_host(r, cs, &cx, &sm); }
    else { cs->kind = "solid_gmsh"; scene_solid_gmsh(r, cs, &cx); }
    if (chance(r, 0.25)) cs->pristine = 1;
    else solid_mutate_case(r, cs, &cx, &sm);
  } else {
    cs->kind = "solid_random";
    int nb = rrange(r, 1, 2);
    if (chance(r, 0.3)) {
      int upper;
      double E;
      solid_blocks_problem(r, cs, &cx, &sm, chance(r, 0.3), &upper, &E);
      for (int i = 0; i < cs->n; ++i) cs->c[i].want = 0;
      cx.hbase = rint_(r, 2), cx.nsides = 2;
    } else if (chance(r, 0.8)) {
      solid_random_mesh(r, &sm, nb);
      cx = ctx3(&sm, rint_(r, 2), nb);
      s_mesh_call(cs, &sm, cx.base);
      if (chance(r, 0.8) && sm.nf) s_faces_calls(r, cs, &sm, cx.base);
      for (int b = 1; b <= nb; ++b)
        if (chance(r, 0.8)) s_call(cs, F_S_SET_MATERIAL, b, 0, plausible_double(r, 'E'), plausible_double(r, 'p'), 0);
      if (chance(r, 0.6)) {
        /* three nodes of every tetrahedron held (80%; else half the nodes),
         * loads on the others and on a tag: a solve that may succeed on any
         * geometry (flat, inverted, huge, tiny) */
        int every = chance(r, 0.8);
        char *held = xcalloc((size_t)sm.nn + 1, 1);
        for (int t = 0; t < sm.nt && every; ++t)
          for (int q = 0; q < 3; ++q) held[sm.tet[4 * t + q]] = 1;
        for (int v = 0; v < sm.nn && !every; ++v) held[v] = chance(r, 0.5);
        for (int b = 1; b <= nb; ++b) s_call(cs, F_S_SET_MATERIAL, b, 0, plausible_double(r, 'E'), 0.3, 0);
        for (int v = 0; v < sm.nn; ++v)
          if (held[v])
            for (int k = 0; k < 3; ++k) s_call(cs, F_S_FIX, v + cx.base, k, chance(r, 0.8) ? 0.0 : plausible_double(r, 'u'), 0, 0);
        free(held);
        s_call(cs, F_S_ADD_NODAL_FORCE, rint_(r, sm.nn) + cx.base, 0, plausible_double(r, 'f'), plausible_double(r, 'f'),
               plausible_double(r, 'f'));
        if (sm.nf && chance(r, 0.5)) s_call(cs, F_S_ADD_PRESSURE, sm.ftag[rint_(r, sm.nf)], 0, plausible_double(r, 'f'), 0, 0);
        if (chance(r, 0.5)) add_call(cs, F_S_SOLVE);
        else s_solve_call(cs, F_S_SOLVE_CONTACT, 50, rint_(r, 2), 0, 0, 0, chance(r, 0.5));
        s_result_getters(r, cs, chance(r, 0.3));
      }
    } else {
      cx = ctx3(NULL, rint_(r, 2), 2);
      cx.nn = rrange(r, 0, 6);
    }
    int n = rrange(r, 3, 40);
    double wild = runif(r) * 0.5;
    for (int k = 0; k < n; ++k) random_solid_call(r, cs, &cx, sm.nt ? &sm : NULL, wild, -1, -1);
  }
  smesh_free(&sm);
}

/* Builds case number `index` of `seed`. */
static void gen_case(uint64_t seed, long index, case_t *cs, mesh_t *m) {
  rng_t r = {mix64(seed * 0x9e3779b97f4a7c15ULL + (uint64_t)index)};
  memset(cs, 0, sizeof *cs);
  cs->seed = seed;
  cs->index = index;
  /* (a 3D case, from a stream of its own: the others are as they were) */
  rng_t r3 = {mix64(seed * 0x9e3779b97f4a7c15ULL + (uint64_t)index) ^ 0x3d3d3d3d3d3d3d3dULL};
  if (runif(&r3) < g_solid_share) {
    gen_solid_case(&r3, cs);
    return;
  }
  ctx_t cx = {0};
  int kind = rint_(&r, 100);
  if (kind < 70) {
    /* (a) a valid scene, mutated (10% left pristine) */
    int s = rint_(&r, 137);
    if (s >= 128) {
      if (s < 131) { cs->kind = "axisymmetric"; scene_axisym(&r, cs, &cx, m); }
      else if (s < 134) { cs->kind = "adaptive"; scene_adaptive(&r, cs, &cx, m); }
      else { cs->kind = "ring"; scene_ring(&r, cs, &cx, m); }
    } else if (s >= 100) {
      if (s < 108) { cs->kind = "steps"; scene_steps(&r, cs, &cx, m); }
      else if (s < 116) { cs->kind = "host"; scene_host(&r, cs, &cx, m); }
      else if (s < 120) { cs->kind = "friction"; scene_friction(&r, cs, &cx, m); }
      else if (s < 124) { cs->kind = "auto_pairs"; scene_auto_pairs(&r, cs, &cx, m); }
      else { cs->kind = "prescribed"; scene_prescribed(&r, cs, &cx, m); }
    } else if (s < 22) { cs->kind = "square"; scene_square(&r, cs, &cx, m, 0, 0); }
    else if (s < 30) { cs->kind = "clockwise_square"; scene_square(&r, cs, &cx, m, 1, 1); }
    else if (s < 47) { cs->kind = "two_blocks"; scene_two_blocks(&r, cs, &cx, m, 0); }
    else if (s < 51) { cs->kind = "curved_blocks"; scene_two_blocks(&r, cs, &cx, m, 3); }
    else if (s < 52) { cs->kind = "cut_blocks"; scene_two_blocks(&r, cs, &cx, m, 4); }
    else if (s < 58) { cs->kind = "mortar"; scene_mortar(&r, cs, &cx, m); }
    else if (s < 72) { cs->kind = "user_contact_mesh"; scene_two_blocks(&r, cs, &cx, m, 1); }
    else if (s < 78) { cs->kind = "literal_cycle"; scene_two_blocks(&r, cs, &cx, m, 2); }
    else if (s < 90) { cs->kind = "degenerate"; scene_degenerate(&r, cs, &cx, m); }
    else { cs->kind = "gmsh"; scene_gmsh(&r, cs, &cx); }
    if (chance(&r, 0.15)) {
      /* results kept, bit for bit, by tfem_set_threads and tfem_set_ordering */
      if (chance(&r, 0.6)) call_i(cs, F_SET_THREADS, (int[]){1, 2, 0}[rint_(&r, 3)], 0);
      else call_i(cs, F_SET_ORDERING, rint_(&r, 3), rint_(&r, 2));
      add_call(cs, F_GET_DISPLACEMENTS);
      if (chance(&r, 0.5)) add_call(cs, F_GET_MATRIX);
      if (chance(&r, 0.5)) add_call(cs, F_GET_REACTIONS);
    }
    if (chance(&r, 0.25)) {
      /* the model's own pool (1 or 2 threads) or the process-wide one, set
       * anywhere (results do not depend on it beyond round-off) */
      case_t one = {0};
      call_i(&one, F_SET_THREADS, (int[]){1, 2, 0}[rint_(&r, 3)], 0);
      case_insert_copy(cs, rint_(&r, cs->n + 1), &one.c[0]);
      case_free(&one);
    }
    if (!chance(&r, s >= 116 || (s >= 52 && s < 58) ? 0.45 : s >= 100 || (s >= 47 && s < 52) ? 0.35 : 0.1))
      mutate_case(&r, cs, &cx);
    else cs->pristine = 1;
  } else {
    /* (b) a fully random sequence */
    cs->kind = "random";
    int nb = rrange(&r, 1, 2);
    if (chance(&r, 0.75)) {
      random_mesh(&r, m, nb);
      cx = (ctx_t){m->nn, m->nt, rint_(&r, 2), {1, 2, 3, 4}, 4, {1, 2}, nb, m, 0, 0, 0, {0}};
      set_mesh_call(cs, m, cx.base);
      if (chance(&r, 0.8)) edges_calls(&r, cs, m, cx.base);
      for (int b = 1; b <= nb; ++b)
        if (chance(&r, 0.8)) material(cs, b, plausible_double(&r, 'E'), plausible_double(&r, 'p'), plausible_int(&r, 'P', &cx));
    } else {
      cx = (ctx_t){rrange(&r, 0, 6), 0, rint_(&r, 2), {1, 2, 3, 4}, 4, {1, 2}, 2, NULL, 0, 0, 0, {0}};
    }
    int n = rrange(&r, 3, 40);
    double wild = runif(&r) * 0.5;
    for (int k = 0; k < n; ++k) random_call(&r, cs, &cx, wild, -1, -1);
  }
}

/* ------------------------------------------------------------------------ */
/* Shared state of a run (visible to forked children)                        */
/* ------------------------------------------------------------------------ */

typedef struct {
  int done;
  int term; /* 0 normal; else V_CRASH, V_ABORT or V_HANG */
  long counts[NV];
  long calls;
  long stderr_bytes;
  long status_flips; /* replay: a call OK originally failed (part of state_change) */
  long oracles[NO];
} case_result;

typedef struct {
  int printed[NV]; /* findings printed so far, per class (a print limit) */
  case_result res[];
} shared_t;

static shared_t *g_shared;
static int g_print_limit = 3;
static int g_verbose = 0;

/* ------------------------------------------------------------------------ */
/* Guarded output buffers                                                    */
/* ------------------------------------------------------------------------ */

#define GUARD 64
#define CANARY 0xCB
static const uint64_t PAT_D = 0x7FF4DEADBEEF0001ULL; /* a signalling NaN */
#define PAT_BYTE 0x5A

typedef struct {
  unsigned char *blk, *p;
  size_t n, bytes;
  int kind;
} gbuf;

static void gb_alloc(gbuf *g, int kind, size_t n) {
  g->kind = kind;
  g->n = n;
  g->bytes = n * ksize(kind);
  g->blk = xmalloc(g->bytes + 2 * GUARD);
  g->p = g->blk + GUARD;
  memset(g->blk, CANARY, GUARD);
  memset(g->p + g->bytes, CANARY, GUARD);
  if (kind == K_D || kind == K_T)
    for (size_t i = 0; i < n; ++i) memcpy(g->p + 8 * i, &PAT_D, 8);
  else
    memset(g->p, PAT_BYTE, g->bytes);
}
static int gb_canary_ok(const gbuf *g) {
  for (int i = 0; i < GUARD; ++i)
    if (g->blk[i] != CANARY || g->p[g->bytes + i] != CANARY) return 0;
  return 1;
}
static int gb_is_pattern(const gbuf *g, size_t i) {
  size_t es = ksize(g->kind);
  if (g->kind == K_D || g->kind == K_T) return memcmp(g->p + 8 * i, &PAT_D, 8) == 0;
  for (size_t b = 0; b < es; ++b)
    if (g->p[i * es + b] != PAT_BYTE) return 0;
  return 1;
}
static int gb_untouched(const gbuf *g) {
  for (size_t i = 0; i < g->n; ++i)
    if (!gb_is_pattern(g, i)) return 0;
  return 1;
}

/* ------------------------------------------------------------------------ */
/* The shadow model: what the tester knows the model holds                   */
/* ------------------------------------------------------------------------ */

typedef struct {
  int tag, type; /* 0 pressure, 1 traction */
  double a, b;
} sh_load;

typedef struct {
  int has_mesh; /* a mesh was set (by set_mesh or a Gmsh file) */
  int exact;    /* and it is known here */
  int nn, nt, base;
  double *xy;
  int *tri, *body, *used;
  int ne;
  int *edge, *tag;
  sh_load *load;
  int nl;
  double *nforce; /* 2 per node */
  int bf_body[16];
  double bf[16][2];
  int nbf;
  double *presc; /* 2 per node, NAN: free */
  int presc_nonempty;
  int results; /* 0 none, 1 plain solve, 2 contact solve, 3 load step */
  int pre_results, pre_valid; /* the results before the last step (tfem_revert_step) */
  int pre_res_fam;             /* ... and the families of their pairs (res_fam) */
  /* the displacements of the results before the last step (a hash, known
   * when read since the last change of the results): tfem_revert_step
   * brings them back, bit for bit */
  int pre_disp_ok, pre_disp_idx, disp_reverted;
  uint64_t pre_disp_hash;
  int no_matrix;   /* results of a step: no system matrix */
  int res_unknown; /* results not known here (a step reverted that was not seen) */
  int contact_test; /* inversion test of the last contact solve */
  int matrix_dropped;
  double relres, cond;
  /* contact pairs declared since the mesh (tags; 16 at most kept; INT_MIN:
   * a pair found by tfem_add_contact_pairs_auto whose tags are not known
   * here), their friction coefficients (64 kept), the law of the last
   * contact solve or step (-1 unknown), the results the Coulomb oracle saw */
  int npairs;
  int pair_tag[16][2];
  double pair_mu[64];
  char pair_user[64]; /* the pair was declared with a contact mesh of its own */
  int contact_law;
  long coul_gen;
  /* the contact weighting: pairs declared with a contact mesh of their
   * own (the mortar weighting refuses them, the automatic one gives them
   * B), the families of the pairs of the last contact solve's or load
   * step's results (FAM_* bits, sh_families: FAM_STRIP some pair weighted
   * by B, FAM_MORTAR some by the mortar weighting, FAM_UNKNOWN some not
   * known here; 0 no pair), the families of the last step's pairs
   * (sh_fam_sig, -1 not known: the contact state it leaves names them) */
  int mesh_pairs;
  int res_fam;
  long hist_sig;
  /* The following survive a new mesh (they are the model's). */
  int threads;     /* set by tfem_set_threads (0: the process-wide pool) */
  int weighting;   /* set by tfem_set_contact_weighting (0 strip, 1 mortar, 2 automatic: the default) */
  long prob_gen;   /* changes of the problem */
  long sol_gen;    /* changes of the results (solves, changes of the problem) */
  /* the materials set successfully (16 bodies kept; a new mesh keeps them:
   * the header), and their section: axi, every body axisymmetric (the
   * model takes one section, tfem_set_material refuses a mix) */
  int nmat, axi;
  int mat_body[16], mat_plane[16];
  double mat_young[16], mat_nu[16];
  /* the cycles of the last adaptive solve (the model's, whatever the mesh):
   * 0 none, -1 not known here; their unknowns and estimates (64 kept) and
   * the call that made them */
  long adapt_n;
  int adapt_idx;
  int64_t adapt_unk[64];
  double adapt_est[64];
  /* the circles declared on tags (tfem_set_boundary_circle; a new mesh has
   * none), 16 kept (more: not known here): tag, centre and radius, and
   * whether every edge of the tag is known to lie on it (clean: at its
   * declaration and after an adaptive solve that kept them there, not
   * after new boundary edges); the nodes of the mesh the last adaptive
   * solve left (0: not known) */
  int ncirc;
  int circ_tag[16], circ_clean[16];
  double circ[16][3];
  int refined_nn;
  /* snapshots: the contact mesh B, the contact elements of a contact solve
   * (both in the index base, with the problem generation they belong to),
   * and the displacements (a hash, with the results generation) */
  int *cmesh, *celem;
  long ncmesh, ncelem, cmesh_gen, celem_gen;
  int cmesh_idx, celem_idx;
  uint64_t disp_hash, mat_hash;
  long disp_gen, mat_gen;
  int disp_idx, mat_idx;
} shadow_t;

static void sh_init(shadow_t *s) {
  memset(s, 0, sizeof *s);
  s->relres = NAN;
  s->cmesh_gen = s->celem_gen = s->disp_gen = s->mat_gen = s->coul_gen = -1;
  s->contact_law = -1;
  s->weighting = TFEM_CONTACT_WEIGHTING_AUTO;
  s->hist_sig = -1;
}
/* Forgets the mesh and everything on it; keeps what belongs to the model
 * (threads, generations: a new mesh is a new problem). */
static void sh_clear_mesh(shadow_t *s) {
  free(s->xy);
  free(s->tri);
  free(s->body);
  free(s->used);
  free(s->edge);
  free(s->tag);
  free(s->load);
  free(s->nforce);
  free(s->presc);
  free(s->cmesh);
  free(s->celem);
  int threads = s->threads, weighting = s->weighting;
  long pg = s->prob_gen, sg = s->sol_gen;
  shadow_t keep = *s; /* (the model's materials and adaptive cycles) */
  sh_init(s);
  s->threads = threads;
  s->weighting = weighting;
  s->nmat = keep.nmat, s->axi = keep.axi;
  memcpy(s->mat_body, keep.mat_body, sizeof s->mat_body);
  memcpy(s->mat_plane, keep.mat_plane, sizeof s->mat_plane);
  memcpy(s->mat_young, keep.mat_young, sizeof s->mat_young);
  memcpy(s->mat_nu, keep.mat_nu, sizeof s->mat_nu);
  s->adapt_n = keep.adapt_n, s->adapt_idx = keep.adapt_idx;
  memcpy(s->adapt_unk, keep.adapt_unk, sizeof s->adapt_unk);
  memcpy(s->adapt_est, keep.adapt_est, sizeof s->adapt_est);
  s->prob_gen = pg + 1;
  s->sol_gen = sg + 1;
}
/* The header's orientation rule, written independently of the library:
 * triangles joined by an edge shared by exactly two triangles of one body
 * form regions; the numbering of each region is made consistent (neighbours
 * traverse their shared edge in opposite directions, from the region's
 * first triangle on) and the region is turned if its signed area is
 * negative. Turning swaps the last two nodes. */
typedef struct {
  int lo, hi, t, fwd;
} sh_side;
static int sh_side_cmp(const void *a, const void *b) {
  const sh_side *x = a, *y = b;
  if (x->lo != y->lo) return x->lo < y->lo ? -1 : 1;
  if (x->hi != y->hi) return x->hi < y->hi ? -1 : 1;
  return x->t < y->t ? -1 : x->t > y->t;
}
static double sh_j(const double *xy, const int *v) {
  const double *a = &xy[2 * v[0]], *b = &xy[2 * v[1]], *c = &xy[2 * v[2]];
  return (b[0] - a[0]) * (c[1] - a[1]) - (c[0] - a[0]) * (b[1] - a[1]);
}
static void sh_orient(int nt, int *tri, const int *body, const double *xy) {
  int any = 0;
  for (int t = 0; t < nt && !any; ++t) any = sh_j(xy, &tri[3 * t]) < 0;
  if (!any) return;
  sh_side *sd = xmalloc(sizeof *sd * 3 * (size_t)nt);
  for (int t = 0; t < nt; ++t)
    for (int k = 0; k < 3; ++k) {
      int p = tri[3 * t + k], q = tri[3 * t + (k + 1) % 3];
      sd[3 * t + k] = (sh_side){p < q ? p : q, p < q ? q : p, t, p < q};
    }
  qsort(sd, 3 * (size_t)nt, sizeof *sd, sh_side_cmp);
  int *nb = xmalloc(sizeof(int) * 6 * (size_t)nt), *nnb = xcalloc((size_t)nt, sizeof(int));
  for (size_t i = 0; i < 3 * (size_t)nt;) {
    size_t j = i + 1;
    while (j < 3 * (size_t)nt && sd[j].lo == sd[i].lo && sd[j].hi == sd[i].hi) ++j;
    if (j - i == 2 && body[sd[i].t] == body[sd[i + 1].t]) {
      int a = sd[i].t, b = sd[i + 1].t, same = sd[i].fwd == sd[i + 1].fwd;
      nb[2 * (3 * a + nnb[a])] = b, nb[2 * (3 * a + nnb[a]) + 1] = same, nnb[a]++;
      nb[2 * (3 * b + nnb[b])] = a, nb[2 * (3 * b + nnb[b]) + 1] = same, nnb[b]++;
    }
    i = j;
  }
  int *flip = xcalloc((size_t)nt, sizeof(int)), *seen = xcalloc((size_t)nt, sizeof(int));
  int *queue = xmalloc(sizeof(int) * (size_t)nt);
  for (int root = 0; root < nt; ++root) {
    if (seen[root]) continue;
    int head = 0, tail = 0;
    seen[root] = 1;
    queue[tail++] = root;
    double area = 0;
    while (head < tail) {
      int t = queue[head++];
      area += flip[t] ? -sh_j(xy, &tri[3 * t]) : sh_j(xy, &tri[3 * t]);
      for (int k = 0; k < nnb[t]; ++k) {
        int u = nb[2 * (3 * t + k)];
        if (!seen[u]) {
          seen[u] = 1;
          flip[u] = flip[t] ^ nb[2 * (3 * t + k) + 1];
          queue[tail++] = u;
        }
      }
    }
    if (area < 0)
      for (int k = 0; k < tail; ++k) flip[queue[k]] ^= 1;
  }
  for (int t = 0; t < nt; ++t)
    if (flip[t]) {
      int x = tri[3 * t + 1];
      tri[3 * t + 1] = tri[3 * t + 2];
      tri[3 * t + 2] = x;
    }
  free(sd), free(nb), free(nnb), free(flip), free(seen), free(queue);
}

static void sh_new_mesh(shadow_t *s, int nn, const double *xy, int nt, const int *tri0, const int *body, int base) {
  sh_clear_mesh(s);
  s->has_mesh = s->exact = 1;
  s->nn = nn;
  s->nt = nt;
  s->base = base;
  s->xy = xmalloc(sizeof(double) * 2 * (size_t)nn);
  memcpy(s->xy, xy, sizeof(double) * 2 * (size_t)nn);
  s->tri = xmalloc(sizeof(int) * 3 * (size_t)nt);
  for (int k = 0; k < 3 * nt; ++k) s->tri[k] = tri0[k];
  s->body = xmalloc(sizeof(int) * (size_t)nt);
  memcpy(s->body, body, sizeof(int) * (size_t)nt);
  sh_orient(nt, s->tri, s->body, s->xy);
  s->used = xcalloc((size_t)nn, sizeof(int));
  for (int k = 0; k < 3 * nt; ++k) s->used[s->tri[k]] = 1;
  s->nforce = xcalloc(2 * (size_t)nn, sizeof(double));
  s->presc = xmalloc(sizeof(double) * 2 * (size_t)nn);
  for (int g = 0; g < 2 * nn; ++g) s->presc[g] = NAN;
}
static void sh_set_edges(shadow_t *s, int ne, const int *edge0, const int *tag) {
  free(s->edge);
  free(s->tag);
  s->ne = ne;
  s->edge = xmalloc(sizeof(int) * 2 * (size_t)(ne + 1));
  s->tag = xmalloc(sizeof(int) * (size_t)(ne + 1));
  for (int k = 0; k < 2 * ne; ++k) s->edge[k] = edge0[k];
  for (int k = 0; k < ne; ++k) s->tag[k] = tag[k];
}
/* The unit square of the valid Gmsh file as the library reads it. */
static void sh_gmsh_square(shadow_t *s, int base) {
  double xy[18];
  for (int k = 0; k < 9; ++k) {
    xy[2 * k] = 0.5 * (k % 3);
    xy[2 * k + 1] = 0.5 * (k / 3);
  }
  int tri[24], nt = 0, body[8] = {1, 1, 1, 1, 1, 1, 1, 1};
  for (int j = 0; j < 2; ++j)
    for (int i = 0; i < 2; ++i) {
      int a = i + 3 * j, b = a + 1, c = a + 4, d = a + 3;
      int t[6] = {a, b, c, a, c, d};
      memcpy(&tri[3 * nt], t, sizeof t);
      nt += 2;
    }
  sh_new_mesh(s, 9, xy, 8, tri, body, base);
  int edge[16] = {0, 3, 3, 6, 2, 5, 5, 8, 0, 1, 1, 2, 6, 7, 7, 8}, tag[8] = {1, 1, 2, 2, 3, 3, 4, 4};
  sh_set_edges(s, 8, edge, tag);
}
/* Owner (the single triangle with the edge) and its third node, or -1. */
static int sh_owner(const shadow_t *s, int p, int q, int *third) {
  int owner = -1, count = 0;
  for (int t = 0; t < s->nt; ++t)
    for (int k = 0; k < 3; ++k) {
      int a = s->tri[3 * t + k], b = s->tri[3 * t + (k + 1) % 3];
      if ((a == p && b == q) || (a == q && b == p)) {
        ++count;
        owner = t;
        *third = s->tri[3 * t + (k + 2) % 3];
      }
    }
  return count == 1 ? owner : -1;
}
/* Outward normal of a boundary edge as mesh.rs computes it; 0 if none. */
static int sh_normal(const shadow_t *s, int p, int q, double n[2]) {
  int third = 0, t = sh_owner(s, p, q, &third);
  if (t < 0) return 0;
  const double *a = &s->xy[2 * p], *c = &s->xy[2 * q], *r = &s->xy[2 * third];
  double tv[2] = {c[0] - a[0], c[1] - a[1]}, len = hypot(tv[0], tv[1]);
  if (len == 0.0) return 0;
  double left[2] = {-tv[1] / len, tv[0] / len};
  double side = left[0] * (r[0] - a[0]) + left[1] * (r[1] - a[1]);
  int interior_on_left;
  if (side != 0.0) {
    interior_on_left = side > 0.0;
  } else {
    int k = 0;
    while (k < 3 && s->tri[3 * t + k] != p) ++k;
    interior_on_left = s->tri[3 * t + (k + 1) % 3] == q;
  }
  n[0] = interior_on_left ? -left[0] : left[0];
  n[1] = interior_on_left ? -left[1] : left[1];
  return 1;
}
/* The external nodal forces f (2 per node, zeroed here) as the library
 * assembles them (pressures and tractions split equally between an edge's
 * nodes, point forces, body forces split equally between the corners of
 * each triangle of positive J); 0 if they cannot be known (a pressure on
 * an edge without an outward normal) or are not finite. */
static int sh_nodal_forces(const shadow_t *s, double *f) {
  memset(f, 0, sizeof(double) * 2 * (size_t)s->nn);
  if (s->axi) return 0; /* (axisymmetric: the whole ring's forces, 2 pi r per unit length; not made here) */
  int ok = 1;
  for (int l = 0; l < s->nl && ok; ++l)
    for (int e = 0; e < s->ne; ++e) {
      if (s->tag[e] != s->load[l].tag) continue;
      int p = s->edge[2 * e], q = s->edge[2 * e + 1];
      const double *xp = &s->xy[2 * p], *xq = &s->xy[2 * q];
      double len = hypot(xq[0] - xp[0], xq[1] - xp[1]), t[2], n[2];
      if (s->load[l].type == 1) {
        t[0] = s->load[l].a;
        t[1] = s->load[l].b;
      } else {
        if (!sh_normal(s, p, q, n)) {
          ok = 0;
          break;
        }
        t[0] = -s->load[l].a * n[0];
        t[1] = -s->load[l].a * n[1];
      }
      for (int v = 0; v < 2; ++v) {
        int node = v ? q : p;
        f[2 * node] += 0.5 * len * t[0];
        f[2 * node + 1] += 0.5 * len * t[1];
      }
    }
  for (int g = 0; g < 2 * s->nn; ++g) f[g] += s->nforce[g];
  for (int b = 0; b < s->nbf; ++b)
    for (int t = 0; t < s->nt; ++t) {
      if (s->body[t] != s->bf_body[b]) continue;
      const int *v = &s->tri[3 * t];
      const double *x1 = &s->xy[2 * v[0]], *x2 = &s->xy[2 * v[1]], *x3 = &s->xy[2 * v[2]];
      double j = (x2[0] - x1[0]) * (x3[1] - x1[1]) - (x3[0] - x1[0]) * (x2[1] - x1[1]);
      double area = 0.5 * (j > 0 ? j : 0);
      for (int k = 0; k < 3; ++k) {
        f[2 * v[k]] += s->bf[b][0] * area / 3.0;
        f[2 * v[k] + 1] += s->bf[b][1] * area / 3.0;
      }
    }
  for (int g = 0; g < 2 * s->nn && ok; ++g) ok = isfinite(f[g]);
  return ok;
}
/* Total external force (x, y) on the nodes that carry unknowns or are
 * prescribed, as the reactions must balance it; 0 if it cannot be known. */
static int sh_total_force(const shadow_t *s, double tot[2], double *mag) {
  double *f = xmalloc(sizeof(double) * 2 * (size_t)s->nn + 1);
  int ok = sh_nodal_forces(s, f);
  tot[0] = tot[1] = *mag = 0;
  for (int g = 0; g < 2 * s->nn; ++g)
    if (s->used[g / 2] || !isnan(s->presc[g])) {
      tot[g % 2] += f[g];
      *mag += fabs(f[g]);
    }
  free(f);
  return ok && isfinite(*mag);
}

/* The loads and contact pairs declared, against the shadow's current
 * edges (tfem_set_boundary_edges / tfem_add_boundary_edges must refuse
 * edges that leave one without): a loaded tag needs edges, each a side of
 * exactly one triangle with a length (an outward normal); a pair's tags
 * need edges. Returns 1 and says why when one is left without. */
static int sh_orphan(const shadow_t *s, char *why, size_t cap) {
  for (int l = 0; l < s->nl; ++l) {
    int tag = s->load[l].tag, any = 0;
    for (int e = 0; e < s->ne; ++e) {
      if (s->tag[e] != tag) continue;
      any = 1;
      double n[2];
      if (!sh_normal(s, s->edge[2 * e], s->edge[2 * e + 1], n)) {
        snprintf(why, cap, "the %s on tag %d now acts on edge (%d, %d), interior or of zero length",
                 s->load[l].type ? "traction" : "pressure", tag, s->edge[2 * e] + s->base, s->edge[2 * e + 1] + s->base);
        return 1;
      }
    }
    if (!any) {
      snprintf(why, cap, "the %s on tag %d has no edge left", s->load[l].type ? "traction" : "pressure", tag);
      return 1;
    }
  }
  for (int k = 0; k < s->npairs && k < 16; ++k)
    for (int side = 0; side < 2 && s->pair_tag[k][0] != INT_MIN; ++side) {
      int tag = s->pair_tag[k][side], any = 0;
      for (int e = 0; e < s->ne && !any; ++e) any = s->tag[e] == tag;
      if (!any) {
        snprintf(why, cap, "contact pair %d (tags %d, %d) has no edge tagged %d left", k, s->pair_tag[k][0],
                 s->pair_tag[k][1], tag);
        return 1;
      }
    }
  return 0;
}

/* The first edge (0-based nodes, either direction) given twice with one
 * tag among edges [from, ne) of the shadow, or of [from, ne) against
 * [0, from); -1 if none. */
static int sh_double_edge(const shadow_t *s, int from) {
  for (int e = from; e < s->ne; ++e) {
    int p = s->edge[2 * e], q = s->edge[2 * e + 1];
    int lo = p < q ? p : q, hi = p < q ? q : p;
    for (int f = 0; f < e; ++f) {
      int a = s->edge[2 * f], b = s->edge[2 * f + 1];
      if (s->tag[f] == s->tag[e] && (a < b ? a : b) == lo && (a < b ? b : a) == hi) return e;
    }
  }
  return -1;
}

/* ---- The families of the contact pairs (include/tfem.h,
 * tfem_set_contact_weighting): under the strip weighting (0) every pair is
 * weighted by the elements of B, under the mortar weighting (1) every pair
 * by weighted gaps; under the automatic one (2, the default) a pair with a
 * contact mesh of its own or friction (mu > 0) gets B, and so does a pair
 * whose two sides' nodes face each other (contact/mesh.rs matching: the
 * conforming test, or every node of either side close to the other side
 * at the abscissa of a node of it) or whose two sides are straight
 * (contact/mesh.rs straight); curved sides whose nodes do not match get
 * the mortar weighting. Written here from the header and the rule, on the
 * shadow's mesh; where the rule's round-off or its looser reading of
 * "matching" could go either way the family is FAM_UNKNOWN (the checks
 * that depend on it are then replaced by consistency checks). ---- */

/* The side of tag `tag` chained as contact/mesh.rs chains it: each edge
 * turned so that its outward normal is its left normal (side_of), chained
 * head to tail from the one node that starts an edge and ends none.
 * Returns the number of nodes (edges + 1), written to *out (to free); 0
 * when the edges are not one chain (a branch, a loop, pieces: not
 * straight); -1 when it cannot be known here (no exact mesh, no edge, an
 * edge without an outward normal: such a side makes no pair). */
static int sh_chain(const shadow_t *s, int tag, int **out) {
  *out = NULL;
  if (!s->exact) return -1;
  int ne = 0;
  for (int e = 0; e < s->ne; ++e) ne += s->tag[e] == tag;
  if (ne == 0) return -1;
  int *next = xmalloc(sizeof(int) * (size_t)s->nn + 1);
  char *has_prev = xcalloc((size_t)s->nn + 1, 1);
  for (int v = 0; v < s->nn; ++v) next[v] = -1;
  int verdict = 1;
  for (int e = 0; e < s->ne && verdict == 1; ++e) {
    if (s->tag[e] != tag) continue;
    int p = s->edge[2 * e], q = s->edge[2 * e + 1];
    double n[2];
    if (p < 0 || q < 0 || p >= s->nn || q >= s->nn || !sh_normal(s, p, q, n)) {
      verdict = -1;
      break;
    }
    const double *xp = &s->xy[2 * p], *xq = &s->xy[2 * q];
    double left[2] = {-(xq[1] - xp[1]), xq[0] - xp[0]};
    int a = p, b = q;
    if (!(left[0] * n[0] + left[1] * n[1] >= 0.0)) a = q, b = p;
    if (next[a] != -1) verdict = 0; /* (a branch) */
    next[a] = b;
    has_prev[b] = 1;
  }
  int start = -1, starts = 0;
  for (int v = 0; v < s->nn && verdict == 1; ++v)
    if (next[v] != -1 && !has_prev[v]) start = v, ++starts;
  if (verdict == 1 && starts != 1) verdict = 0; /* (a loop, or pieces) */
  int len = 0;
  if (verdict == 1) {
    *out = xmalloc(sizeof(int) * (size_t)(ne + 2));
    (*out)[len++] = start;
    for (int v = start; next[v] != -1 && len <= ne; v = next[v]) (*out)[len++] = next[v];
    if (len != ne + 1) verdict = 0;
  }
  free(next);
  free(has_prev);
  if (verdict != 1) {
    free(*out);
    *out = NULL;
    return verdict;
  }
  return len;
}

/* Whether the chain ch (n nodes) is straight (contact/mesh.rs straight:
 * every node within 1e-9 L^2 of the line through its ends, |r x d|, L its
 * length): 1 yes, 0 no, -1 within a factor 2 of the tolerance or where the
 * squares leave the doubles' range (not decided here). */
static int sh_straight(const shadow_t *s, const int *ch, int n) {
  const double *p = &s->xy[2 * ch[0]], *q = &s->xy[2 * ch[n - 1]];
  double d[2] = {q[0] - p[0], q[1] - p[1]}, L2 = d[0] * d[0] + d[1] * d[1];
  if (!isfinite(L2) || L2 > 1e250 || L2 < 1e-250) return L2 == 0.0 && d[0] == 0.0 && d[1] == 0.0 ? 0 : -1;
  int verdict = 1;
  for (int k = 0; k < n; ++k) {
    const double *x = &s->xy[2 * ch[k]];
    double cr = fabs((x[0] - p[0]) * d[1] - (x[1] - p[1]) * d[0]);
    if (!isfinite(cr)) return -1;
    if (cr > 2e-9 * L2) return 0;
    if (cr > 0.5e-9 * L2) verdict = -1;
  }
  return verdict;
}

/* Distance from point x to the polyline ch (n nodes). */
static double sh_dist_chain(const shadow_t *s, const double *x, const int *ch, int n) {
  double best = INFINITY;
  for (int k = 0; k + 1 < n; ++k) {
    const double *a = &s->xy[2 * ch[k]], *b = &s->xy[2 * ch[k + 1]];
    double ab[2] = {b[0] - a[0], b[1] - a[1]}, ax[2] = {x[0] - a[0], x[1] - a[1]};
    double l2 = ab[0] * ab[0] + ab[1] * ab[1], t = l2 > 0 ? (ax[0] * ab[0] + ax[1] * ab[1]) / l2 : 0;
    t = t < 0 ? 0 : t > 1 ? 1 : t;
    best = fmin(best, hypot(ax[0] - t * ab[0], ax[1] - t * ab[1]));
  }
  return n == 1 ? hypot(x[0] - s->xy[2 * ch[0]], x[1] - s->xy[2 * ch[0] + 1]) : best;
}

/* Whether every node of chain a (na nodes) is within 0.45 of its shortest
 * edge of chain b, and every node of b of a (contact/mesh.rs matching's
 * "close", within half an edge, with a margin). */
static int sh_all_close(const shadow_t *s, const int *a, int na, const int *b, int nb) {
  for (int side = 0; side < 2; ++side) {
    const int *u = side ? b : a, *w = side ? a : b;
    int nu = side ? nb : na, nw = side ? na : nb;
    for (int i = 0; i < nu; ++i) {
      double h = INFINITY;
      const double *x = &s->xy[2 * u[i]];
      if (i > 0) h = fmin(h, hypot(x[0] - s->xy[2 * u[i - 1]], x[1] - s->xy[2 * u[i - 1] + 1]));
      if (i + 1 < nu) h = fmin(h, hypot(x[0] - s->xy[2 * u[i + 1]], x[1] - s->xy[2 * u[i + 1] + 1]));
      if (!(sh_dist_chain(s, x, w, nw) <= 0.45 * h)) return 0;
    }
  }
  return 1;
}

/* Whether the nodes of chains a and b face each other node for node
 * (contact/mesh.rs matching): 1 when they coincide (as many nodes, each
 * at a node of the other side: the conforming test pairs them), 0 when
 * every node of either side is within 0.45 of its shortest edge of the
 * other side (contact/mesh.rs: "close", within half an edge) and the two
 * sides have different numbers of nodes (then neither the conforming test,
 * which pairs every node, nor the abscissa test, which compares the close
 * nodes of the two sides one for one, can pass), -1 otherwise (not
 * decided here). */
static int sh_matching(const shadow_t *s, const int *a, int na, const int *b, int nb) {
  if (na == nb) {
    int same = 1;
    for (int side = 0; side < 2 && same; ++side) {
      const int *u = side ? b : a, *w = side ? a : b;
      for (int i = 0; i < na && same; ++i) {
        int found = 0;
        for (int j = 0; j < na && !found; ++j)
          found = s->xy[2 * u[i]] == s->xy[2 * w[j]] && s->xy[2 * u[i] + 1] == s->xy[2 * w[j] + 1];
        same = found;
      }
    }
    return same ? 1 : -1;
  }
  return sh_all_close(s, a, na, b, nb) ? 0 : -1;
}

/* The family of contact pair k under the model's weighting (FAM_*). */
static int sh_pair_family(const shadow_t *s, int k) {
  if (s->weighting == TFEM_CONTACT_WEIGHTING_STRIP) return FAM_STRIP;
  /* (axisymmetric bodies take B where the automatic weighting would take
   * the mortar's, which has no ring measure: src/model/problem.rs
   * weighting_in_use) */
  if (s->axi && s->weighting == TFEM_CONTACT_WEIGHTING_AUTO) return FAM_STRIP;
  if (s->weighting == TFEM_CONTACT_WEIGHTING_MORTAR) return FAM_MORTAR;
  if (s->weighting != TFEM_CONTACT_WEIGHTING_AUTO || k >= 64) return FAM_UNKNOWN;
  if (s->pair_user[k] || s->pair_mu[k] > 0.0) return FAM_STRIP;
  if (!s->exact || k >= 16) return FAM_UNKNOWN;
  if (s->pair_tag[k][0] == INT_MIN) {
    /* (a pair found by tfem_add_contact_pairs_auto, its tags not known
     * here: B when every tagged side is straight) */
    int fam = FAM_STRIP;
    for (int e = 0; e < s->ne && fam == FAM_STRIP; ++e) {
      int *ch, n = sh_chain(s, s->tag[e], &ch);
      if (n <= 0 || sh_straight(s, ch, n) != 1) fam = FAM_UNKNOWN;
      free(ch);
    }
    return fam;
  }
  int *ca, *cb, na = sh_chain(s, s->pair_tag[k][0], &ca), nb = sh_chain(s, s->pair_tag[k][1], &cb);
  int fam = FAM_UNKNOWN;
  if (na > 0 && nb > 0) {
    int sa = sh_straight(s, ca, na), sb = sh_straight(s, cb, nb);
    int match = sh_matching(s, ca, na, cb, nb);
    if ((sa == 1 && sb == 1) || match == 1) fam = FAM_STRIP;
    else if (match == 0 && (sa == 0 || sb == 0)) fam = FAM_MORTAR;
  }
  free(ca);
  free(cb);
  return fam;
}

/* The families of the declared pairs (FAM_* bits; 0 without a pair). */
static int sh_families(const shadow_t *s) {
  int fam = 0;
  for (int k = 0; k < s->npairs; ++k) {
    fam |= sh_pair_family(s, k);
    if (k >= 64) break; /* (the others: FAM_UNKNOWN too) */
  }
  return fam;
}

/* The families pair by pair, as a contact state names them (its contact
 * mesh): 16 pairs at most, each FAM_MORTAR or not, and their count; -1
 * when some is not known here. */
static long sh_fam_sig(const shadow_t *s) {
  if (s->npairs > 16) return -1;
  long sig = (long)s->npairs << 20;
  for (int k = 0; k < s->npairs; ++k) {
    int f = sh_pair_family(s, k);
    if (f == FAM_UNKNOWN) return -1;
    if (f == FAM_MORTAR) sig |= 1L << k;
  }
  return sig;
}
/* The body the mortar weighting takes the slave nodes from (include/tfem.h:
 * "one weighted gap per node of each interface's coarser side";
 * src/contact/discretisation.rs: the pairs between the same two bodies
 * together, side a on a tie), where the shadow can tell: every pair
 * declared (tags known) under the mortar weighting, all between the same
 * two bodies, each pair's sides chains whose every node is close to the
 * other side (then every edge faces the other side, contact/mortar.rs
 * facing_edges); the coarser body is the one with fewer edges over the
 * pairs, on a tie the body of the pairs' first sides (the same for all).
 * -1 when not known here. */
static int sh_slave_body(const shadow_t *s) {
  if (!s->exact || s->npairs < 1 || s->npairs > 16) return -1;
  int bodies[2] = {INT_MIN, INT_MIN}, edges[2] = {0, 0}, first = INT_MIN, ok = 1;
  for (int k = 0; k < s->npairs && ok; ++k) {
    if (sh_pair_family(s, k) != FAM_MORTAR || s->pair_tag[k][0] == INT_MIN) return -1;
    int *ca, *cb, na = sh_chain(s, s->pair_tag[k][0], &ca), nb = sh_chain(s, s->pair_tag[k][1], &cb), third;
    ok = na > 1 && nb > 1 && sh_all_close(s, ca, na, cb, nb);
    int ta = ok ? sh_owner(s, ca[0], ca[1], &third) : -1, tb = ok ? sh_owner(s, cb[0], cb[1], &third) : -1;
    ok = ok && ta >= 0 && tb >= 0 && s->body[ta] != s->body[tb];
    if (ok && k == 0) bodies[0] = s->body[ta], bodies[1] = s->body[tb], first = s->body[ta];
    for (int side = 0; side < 2 && ok; ++side) {
      int b = s->body[side ? tb : ta], n = side ? nb : na;
      if (b == bodies[0]) edges[0] += n - 1;
      else if (b == bodies[1]) edges[1] += n - 1;
      else ok = 0;
    }
    ok = ok && s->body[ta] == first; /* (a tie: each pair's own side a) */
    free(ca);
    free(cb);
  }
  if (!ok) return -1;
  return edges[0] < edges[1] ? bodies[0] : edges[1] < edges[0] ? bodies[1] : first;
}

static const char *fam_name(int fam) {
  return fam == 0 ? "no pair" : fam == FAM_STRIP ? "the strip for every pair" : fam == FAM_MORTAR
         ? "the mortar weighting for every pair" : fam == (FAM_STRIP | FAM_MORTAR) ? "the strip and the mortar weighting"
         : "families not known here";
}

/* The body of every node (0-based): INT_MIN unused, INT_MAX on two bodies. */
static int *sh_node_bodies(const shadow_t *s) {
  int *nb = xmalloc(sizeof(int) * (size_t)s->nn + 1);
  for (int i = 0; i < s->nn; ++i) nb[i] = INT_MIN;
  for (int t = 0; t < s->nt; ++t)
    for (int k = 0; k < 3; ++k) {
      int *v = &nb[s->tri[3 * t + k]];
      if (*v == INT_MIN) *v = s->body[t];
      else if (*v != s->body[t]) *v = INT_MAX;
    }
  return nb;
}

/* The contact mesh B (nodes in the index base) and the pair of each of
 * its elements, read with extra calls; the number of elements, or -1. */
static long fetch_contact_mesh(tfem_model *m, int **nodes, int **pairs) {
  int n = -1;
  *nodes = NULL;
  if (pairs) *pairs = NULL;
  if (tfem_get_contact_mesh_size(m, &n) != TFEM_STATUS_OK || n < 0) return -1;
  *nodes = xmalloc(sizeof(int) * 3 * (size_t)n + 1);
  if (tfem_get_contact_mesh(m, *nodes, 3 * (size_t)n) != TFEM_STATUS_OK) {
    free(*nodes);
    *nodes = NULL;
    return -1;
  }
  if (pairs) {
    *pairs = xmalloc(sizeof(int) * (size_t)n + 1);
    if (tfem_get_contact_element_pairs(m, *pairs, (size_t)n) != TFEM_STATUS_OK) {
      free(*nodes);
      free(*pairs);
      *nodes = *pairs = NULL;
      return -1;
    }
  }
  return n;
}

static uint64_t fnv64(const void *p, size_t n) {
  uint64_t h = 1469598103934665603ULL;
  for (size_t i = 0; i < n; ++i) h = (h ^ ((const unsigned char *)p)[i]) * 1099511628211ULL;
  return h;
}

/* What tfem_set_boundary_circle(tag, (x, y), radius) must return, from the
 * shadow (the rules of src/fem/curve.rs and Mesh::set_curve): INVALID_STATE
 * without a mesh; INVALID_ARGUMENT for a centre not finite or a radius not
 * finite or <= 0, a tag of no edge, a node of the tag's edges farther than
 * 1e-6 of the radius from the circle (off[v] set for each such node when
 * off is given); else OK. `why` gets what the message must say. -1 when the
 * shadow does not know the edges, or a node lies within 1e-9 of that bound
 * either way (rounding decides). */
static int circle_expect(const shadow_t *s, int tag, double x, double y, double radius, char *why, size_t cap,
                         unsigned char *off) {
  if (!s->has_mesh) return snprintf(why, cap, "no mesh"), TFEM_STATUS_INVALID_STATE;
  if (!isfinite(x) || !isfinite(y)) return snprintf(why, cap, "centre"), TFEM_STATUS_INVALID_ARGUMENT;
  if (!(isfinite(radius) && radius > 0)) return snprintf(why, cap, "radius"), TFEM_STATUS_INVALID_ARGUMENT;
  if (!s->exact) return -1;
  double tol = 1e-6 * radius;
  int any = 0, out = 0, unsure = 0;
  for (int e = 0; e < s->ne; ++e) {
    if (s->tag[e] != tag) continue;
    any = 1;
    for (int k = 0; k < 2; ++k) {
      int v = s->edge[2 * e + k];
      double d = fabs(hypot(s->xy[2 * v] - x, s->xy[2 * v + 1] - y) - radius);
      if (fabs(d - tol) <= 1e-9 * tol) unsure = 1;
      else if (!(d <= tol)) {
        out = 1;
        if (off) off[v] = 1;
      }
    }
  }
  if (!any) return snprintf(why, cap, "no boundary edge has tag %d", tag), TFEM_STATUS_INVALID_ARGUMENT;
  if (unsure) return -1;
  if (out) return snprintf(why, cap, " of an edge tagged %d lies", tag), TFEM_STATUS_INVALID_ARGUMENT;
  why[0] = 0;
  return TFEM_STATUS_OK;
}

/* ------------------------------------------------------------------------ */
/* The 3D model and its contact context: the shadow and the checks           */
/* ------------------------------------------------------------------------ */

/* What the tester knows the 3D model (and the 3D context) hold. */
typedef struct {
  int tag, type; /* 0 pressure, 1 traction */
  double v[3];
} ss_load;

typedef struct {
  int has_mesh; /* a mesh was set (by set_mesh or a Gmsh file) */
  int exact;    /* and it is known here */
  int nn, nt, base;
  double *xyz;
  int *tet, *body; /* 0-based, as the model holds them (renumbered) */
  int nf, *face, *ftag;
  /* what names the faces (the model refuses new faces while any is declared) */
  int constrained, loaded, npairs;
  int pair_tag[16][2];
  double *presc;  /* 3 per node, NAN: free */
  double *nforce; /* 3 per node */
  ss_load *load;
  int nl;
  /* the results: 0 none, 1 a solve's, 2 a step's; not known here; a step
   * to revert (1 yes, 0 no, -1 not known) and what it would bring back */
  int results, res_unknown, undo, pre_results, pre_unknown;
  long sol_gen;
  uint64_t disp_hash, pre_disp_hash;
  long disp_gen;
  int disp_idx, pre_disp_ok, pre_disp_idx;
  /* the bodies given a material (the model's: a new mesh keeps them; 16
   * kept, more: not known) */
  int nmat, mat_body[16];
  /* the reference displacements of a pristine scene (ST_REF) */
  double *ref[2];
  long nref[2];
  /* the 3D context: made, its index base, sides (bodies), pairs, B built,
   * the interface nodes in the order the sides first gave them (with their
   * coordinates and equations, 0-based, -1 none; more than 512: not known) */
  int sc_live, sc_base, sc_nsides, sc_npairs, sc_built;
  int sc_side_body[64];
  int sc_nn;
  int sc_ids[512];
  double sc_xyz[512][3];
  int64_t sc_eq[512][3];
} sshadow_t;

static void ss_clear_mesh(sshadow_t *s) {
  free(s->xyz), free(s->tet), free(s->body), free(s->face), free(s->ftag), free(s->presc), free(s->nforce),
      free(s->load);
  s->xyz = s->presc = s->nforce = NULL;
  s->tet = s->body = s->face = s->ftag = NULL;
  s->load = NULL;
  s->has_mesh = s->exact = s->nn = s->nt = s->nf = s->nl = 0;
  s->constrained = s->loaded = s->npairs = 0;
  s->results = s->res_unknown = s->undo = 0;
  s->sol_gen++;
}
static void ss_free(sshadow_t *s) {
  ss_clear_mesh(s);
  free(s->ref[0]), free(s->ref[1]);
  s->ref[0] = s->ref[1] = NULL;
}

/* J = det[x1 - x0, x2 - x0, x3 - x0] and the longest edge, as
 * src/fem/tet.rs TetGeometry computes them (the same operations). */
static double ss_j(const double *x0, const double *x1, const double *x2, const double *x3, double *h) {
  const double *x[4] = {x0, x1, x2, x3};
  double e1[3], e2[3], e3[3];
  for (int k = 0; k < 3; ++k) e1[k] = x1[k] - x0[k], e2[k] = x2[k] - x0[k], e3[k] = x3[k] - x0[k];
  double a1[3] = {e2[1] * e3[2] - e2[2] * e3[1], e2[2] * e3[0] - e2[0] * e3[2], e2[0] * e3[1] - e2[1] * e3[0]};
  double hh = 0.0;
  for (int i = 0; i < 4; ++i)
    for (int k = i + 1; k < 4; ++k) {
      double d[3] = {x[i][0] - x[k][0], x[i][1] - x[k][1], x[i][2] - x[k][2]};
      hh = fmax(hh, sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]));
    }
  if (h) *h = hh;
  return e1[0] * a1[0] + e1[1] * a1[1] + e1[2] * a1[2];
}

/* A new mesh (tet0: 0-based as given); a tetrahedron of negative J is
 * renumbered, its last two nodes swapped (src/fem/solid_mesh.rs). */
static void ss_new_mesh(sshadow_t *s, int nn, const double *xyz, int nt, const int *tet0, const int *body, int base) {
  ss_clear_mesh(s);
  s->has_mesh = s->exact = 1;
  s->nn = nn, s->nt = nt, s->base = base;
  s->xyz = xmalloc(sizeof(double) * 3 * (size_t)nn + 1);
  memcpy(s->xyz, xyz, sizeof(double) * 3 * (size_t)nn);
  s->tet = xmalloc(sizeof(int) * 4 * (size_t)nt + 1);
  memcpy(s->tet, tet0, sizeof(int) * 4 * (size_t)nt);
  s->body = xmalloc(sizeof(int) * (size_t)nt + 1);
  memcpy(s->body, body, sizeof(int) * (size_t)nt);
  for (int e = 0; e < nt; ++e) {
    int *t = &s->tet[4 * e];
    if (ss_j(&xyz[3 * t[0]], &xyz[3 * t[1]], &xyz[3 * t[2]], &xyz[3 * t[3]], NULL) < 0.0) {
      int x = t[2];
      t[2] = t[3], t[3] = x;
    }
  }
  s->presc = xmalloc(sizeof(double) * 3 * (size_t)nn + 1);
  for (int k = 0; k < 3 * nn; ++k) s->presc[k] = NAN;
  s->nforce = xcalloc(3 * (size_t)nn + 1, sizeof(double));
}
/* The mesh of SG_VALID (c_tests/solid_test.c's: node i the i-th of the file). */
static void ss_gmsh_valid(sshadow_t *s, int base) {
  static const double xyz[15] = {0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1, 1, 1, 1};
  static const int tet[8] = {0, 1, 2, 3, 1, 2, 3, 4}, body[2] = {1, 1}, face[9] = {0, 1, 2, 0, 1, 2, 1, 2, 4};
  static const int tag[3] = {10, 99, 20};
  ss_new_mesh(s, 5, xyz, 2, tet, body, base);
  s->nf = 3;
  s->face = xmalloc(sizeof face);
  s->ftag = xmalloc(sizeof tag);
  memcpy(s->face, face, sizeof face);
  memcpy(s->ftag, tag, sizeof tag);
}
static void ss_sorted3(const int *f, int *k) {
  k[0] = f[0], k[1] = f[1], k[2] = f[2];
  for (int i = 0; i < 2; ++i)
    for (int j = 0; j < 2 - i; ++j)
      if (k[j] > k[j + 1]) {
        int x = k[j];
        k[j] = k[j + 1], k[j + 1] = x;
      }
}
/* The tetrahedra having face f (0-based nodes): their count, the first. */
static int ss_owners(const sshadow_t *s, const int *f, int *owner) {
  int key[3], n = 0;
  ss_sorted3(f, key);
  for (int e = 0; e < s->nt; ++e)
    for (int skip = 0; skip < 4; ++skip) {
      int g[3], k = 0, gk[3];
      for (int q = 0; q < 4; ++q)
        if (q != skip) g[k++] = s->tet[4 * e + q];
      ss_sorted3(g, gk);
      if (gk[0] == key[0] && gk[1] == key[1] && gk[2] == key[2] && n++ == 0) *owner = e;
    }
  return n;
}
static int ss_tag_faces(const sshadow_t *s, int tag) {
  int n = 0;
  for (int f = 0; f < s->nf; ++f) n += s->ftag[f] == tag;
  return n;
}
static int ss_has_material(const sshadow_t *s, int body) {
  for (int k = 0; k < s->nmat && k < 16; ++k)
    if (s->mat_body[k] == body) return 1;
  return s->nmat > 16 ? -1 : 0;
}
/* A body of the mesh without a material: 1 some (*which), 0 none, -1 not known. */
static int ss_missing_material(const sshadow_t *s, int *which) {
  if (!s->exact) return -1;
  int unknown = 0;
  for (int e = 0; e < s->nt; ++e) {
    int h = ss_has_material(s, s->body[e]);
    if (h == 0) {
      *which = s->body[e];
      return 1;
    }
    unknown |= h < 0;
  }
  return unknown ? -1 : 0;
}
/* The faces (3 node indices each in the index base, tags) a call gives
 * are refused by the header's rules: 1 (why), 0 not, -1 not known here. */
static int ss_faces_refused(const sshadow_t *s, const call_t *c, char *why, size_t cap) {
  int n = c->iv[0], add = c->fn == F_S_ADD_FACES;
  if (!s->has_mesh) return snprintf(why, cap, "no mesh"), 1;
  if (n < 0) return snprintf(why, cap, "n_faces = %d", n), 1;
  if (n > 0 && (c->in[0].null_ || c->in[1].null_)) return snprintf(why, cap, "an array NULL"), 1;
  if (!s->exact) return -1;
  if (s->constrained || s->loaded || s->npairs)
    return snprintf(why, cap, "constraints, loads or contact pairs name the faces"), 1;
  if (n > 0 && (c->in[0].n < 3 * n || c->in[1].n < n)) return -1;
  const int *fv = c->in[0].p, *tg = c->in[1].p;
  for (int f = 0; f < n; ++f) {
    int g[3];
    for (int q = 0; q < 3; ++q) {
      long v = (long)fv[3 * f + q] - s->base;
      if (v < 0 || v >= s->nn) return snprintf(why, cap, "face %d: node %d out of range", f, fv[3 * f + q]), 1;
      g[q] = (int)v;
    }
    int owner = -1, count = ss_owners(s, g, &owner);
    if (count != 1) return snprintf(why, cap, "face %d is a face of %d tetrahedra", f, count), 1;
    double h, j = ss_j(&s->xyz[3 * s->tet[4 * owner]], &s->xyz[3 * s->tet[4 * owner + 1]], &s->xyz[3 * s->tet[4 * owner + 2]],
                       &s->xyz[3 * s->tet[4 * owner + 3]], &h);
    /* (as src/fem/solid_mesh.rs tests it: a J that is NaN is not flat) */
    if (fabs(j) <= 1e-12 * h * h * h) return snprintf(why, cap, "face %d is a face of a flat tetrahedron only", f), 1;
    int key[3];
    ss_sorted3(g, key);
    for (int e = 0; e < (add ? s->nf : 0) + f; ++e) {
      int other[3], ok[3], otag;
      if (add && e < s->nf) {
        memcpy(other, &s->face[3 * e], sizeof other);
        otag = s->ftag[e];
      } else {
        int k = add ? e - s->nf : e;
        for (int q = 0; q < 3; ++q) other[q] = fv[3 * k + q] - s->base;
        otag = tg[k];
      }
      ss_sorted3(other, ok);
      if (otag == tg[f] && ok[0] == key[0] && ok[1] == key[1] && ok[2] == key[2])
        return snprintf(why, cap, "face %d given tag %d twice", f, tg[f]), 1;
    }
  }
  return 0;
}
/* The nodal loads the shadow knows (3 per node): nodal forces, and the
 * pressures and tractions on the faces of their tags (a third of each
 * face's force at each of its nodes; a pressure acts along minus the
 * outward normal, away from the face's tetrahedron). 0 if not known. */
static int ss_loads(const sshadow_t *s, double *f) {
  if (!s->exact) return 0;
  memcpy(f, s->nforce, sizeof(double) * 3 * (size_t)s->nn);
  for (int l = 0; l < s->nl; ++l)
    for (int k = 0; k < s->nf; ++k) {
      if (s->ftag[k] != s->load[l].tag) continue;
      const int *fv = &s->face[3 * k];
      const double *a = &s->xyz[3 * fv[0]], *b = &s->xyz[3 * fv[1]], *c = &s->xyz[3 * fv[2]];
      double u[3] = {b[0] - a[0], b[1] - a[1], b[2] - a[2]}, w[3] = {c[0] - a[0], c[1] - a[1], c[2] - a[2]};
      double n[3] = {u[1] * w[2] - u[2] * w[1], u[2] * w[0] - u[0] * w[2], u[0] * w[1] - u[1] * w[0]};
      int owner = -1;
      if (ss_owners(s, fv, &owner) < 1) return 0;
      int d = -1;
      for (int q = 0; q < 4; ++q) {
        int v = s->tet[4 * owner + q];
        if (v != fv[0] && v != fv[1] && v != fv[2]) d = v;
      }
      if (d < 0) return 0;
      const double *x = &s->xyz[3 * d];
      if (n[0] * (x[0] - a[0]) + n[1] * (x[1] - a[1]) + n[2] * (x[2] - a[2]) > 0)
        for (int q = 0; q < 3; ++q) n[q] = -n[q];
      double area2 = sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
      for (int q = 0; q < 3; ++q)
        for (int comp = 0; comp < 3; ++comp)
          f[3 * fv[q] + comp] += s->load[l].type ? s->load[l].v[comp] * area2 / 6.0 : -s->load[l].v[0] * n[comp] / 6.0;
    }
  return 1;
}

static int solid_result_fn(int fn) {
  switch (fn) {
  case F_S_SOLVE_INFO: case F_S_ITERATIONS: case F_S_DISPLACEMENTS: case F_S_STRAINS: case F_S_STRESSES:
  case F_S_REACTIONS: case F_S_WORK: case F_S_CONTACT_TETS: case F_S_CONTACT_ACTIVE: case F_S_CONTACT_FORCES:
  case F_S_NODAL_PRESSURES: case F_S_AREA: case F_S_PAIR_AREA: case F_S_WRITE_VTU:
    return 1;
  default: return 0;
  }
}
/* Does a successful call of f change the 3D problem (and so discard the results)? */
static int solid_changes_problem(int fn) {
  switch (fn) {
  case F_S_SET_MESH: case F_S_LOAD_GMSH: case F_S_SET_FACES: case F_S_ADD_FACES: case F_S_SET_MATERIAL:
  case F_S_SET_TEMPERING: case F_S_FIX: case F_S_FIX_FACES: case F_S_CLEAR_CONSTRAINTS: case F_S_ADD_PRESSURE:
  case F_S_ADD_TRACTION: case F_S_ADD_NODAL_FORCE: case F_S_CLEAR_LOADS: case F_S_ADD_PAIR: case F_S_CLEAR_PAIRS:
    return 1;
  default: return 0;
  }
}
/* The 3D context's calls that build B (a success means it is built). */
static int sc_builds(int fn) {
  switch (fn) {
  case F_SC_SETUP: case F_SC_SIZES: case F_SC_TETS: case F_SC_PATTERN: case F_SC_ELEMENT_EQUATIONS:
  case F_SC_ELEMENT_BLOCKS: case F_SC_EVALUATE: case F_SC_UPDATE: case F_SC_RESTART: case F_SC_GET_ACTIVE:
  case F_SC_SET_ACTIVE: case F_SC_GAPS: case F_SC_AREA:
    return 1;
  default: return 0;
  }
}
/* The options of a 3D solve, step or context are refused by the header's
 * rules (frictionless, the 3D test, max_iterations >= 1, refactorize 0 or
 * 1, E_c and lambda 0 or finite and > 0). */
static int solid_options_refused(const call_t *c) {
  if (c->in[0].null_) return 0;
  int bad = c->iv[0] != 0 || c->iv[1] != 0 || c->iv[2] < 1 || (c->iv[3] != 0 && c->iv[3] != 1);
  for (int k = 0; k < 2; ++k) bad |= !(c->dv[k] == 0.0 || (isfinite(c->dv[k]) && c->dv[k] > 0));
  return bad;
}
/* ------------------------------------------------------------------------ */
/* The runner: executes a case's calls and checks each                       */
/* ------------------------------------------------------------------------ */

typedef struct {
  tfem_model *m;
  case_t *cs;
  shadow_t sh;
  int phase;     /* 0 original, 1 replay */
  int verbose;
  int full_prefix; /* calls [0, full_prefix) are all the case's first calls (oracles valid) */
  int pristine;
  int mismatch_reported;
  long counts[NV];
  long calls;
  long stderr_bytes;
  long status_flips;
  long oracles[NO];
  FILE *cfile; /* the C reproducer being written (verbose runs) */
  /* the contact context (NULL: none), its index base, B built (a call
   * needing it succeeded) */
  tfem_contact *ctx;
  int cbase, cbuilt;
  int ctx_ring; /* the section of the context's sides: -1 no side yet, 0 plane, 1 axisymmetric */
  /* contact states saved (tfem_get_contact_state): the last, the one before */
  unsigned char *st_last, *st_prev;
  size_t n_last, n_prev;
  /* the reference of the repeated step (report fields, displacements) */
  int ref_ok, ref_disp_ok;
  tfem_contact_report ref_rep;
  uint64_t ref_disp;
  int ref_idx;
  /* the families of the pairs of the step each saved state was read after
   * (sh_fam_sig, -1 not known: a state of other families belongs to another
   * contact mesh) */
  long st_last_w, st_prev_w;
  /* the per-element outputs and the slave nodes of the results of
   * generation fam_gen: -1 not asked, 0 refused, 1 served */
  long fam_gen;
  int seen_elem, seen_slave;
  /* a 3D case: the 3D model (NULL once destroyed), the 3D context (NULL:
   * none), a 2D context (a handle of another kind), the 3D shadow */
  tfem_solid_model *sm;
  tfem_solid_contact *sctx;
  tfem_contact *octx;
  sshadow_t ss;
} runner_t;

static void c_emit_call(FILE *f, const call_t *c, int idx);
static void c_emit_status(FILE *f, const call_t *c, int idx, int st);

static void finding(runner_t *R, int v, int idx, const char *fmt, ...) {
  R->counts[v]++;
  int show = R->verbose;
  if (!show && g_shared) show = __atomic_fetch_add(&g_shared->printed[v], 1, __ATOMIC_RELAXED) < g_print_limit;
  if (!show) return;
  char line[1200];
  int n = snprintf(line, sizeof line, "VIOLATION %s: seed=%" PRIu64 " case=%ld (%s) call #%d %s: ", V_NAME[v],
                   R->cs->seed, R->cs->index, R->cs->kind, idx,
                   idx >= 0 && idx < R->cs->n ? FN[R->cs->c[idx].fn].name : "-");
  va_list ap;
  va_start(ap, fmt);
  if (n < (int)sizeof line) vsnprintf(line + n, sizeof line - (size_t)n, fmt, ap);
  va_end(ap);
  size_t L = strlen(line);
  if (L + 2 > sizeof line) L = sizeof line - 2;
  line[L] = '\n';
  line[L + 1] = 0;
  fputs(line, stdout);
  fflush(stdout);
}

static off_t g_err_claimed; /* stderr bytes already attributed to a call */

static off_t fd_size(int fd) {
  struct stat st;
  if (fstat(fd, &st) != 0 || !S_ISREG(st.st_mode)) return -1;
  return st.st_size;
}

/* A printable excerpt of a message. */
static void excerpt(const char *s, size_t n, char *out, size_t cap) {
  size_t k = 0;
  for (size_t i = 0; i < n && k + 5 < cap; ++i) {
    unsigned char ch = (unsigned char)s[i];
    if (ch == '\n') {
      out[k++] = '\\';
      out[k++] = 'n';
    } else if (ch < 32 || ch == 127) {
      k += (size_t)snprintf(out + k, cap - k, "\\x%02x", ch);
    } else {
      out[k++] = (char)ch;
    }
  }
  out[k] = 0;
}

static int ctx_sizes(runner_t *R, int *nn, int *ne, int64_t *np);
static int ssc_sizes(runner_t *R, int *nn, int *nt, int64_t *np);
static int ssc_nodes(const runner_t *R);
/* The cycles of the model's last adaptive solve (tfem_get_adapt_cycles
 * with no column: OK once the length holds them all): 0 none (refused
 * INVALID_STATE), -1 not known (another refusal, or more than 4096). */
static long probe_cycles(tfem_model *m) {
  int st = tfem_get_adapt_cycles(m, NULL, NULL, NULL, 0);
  if (st == TFEM_STATUS_INVALID_STATE) return 0;
  if (st == TFEM_STATUS_OK) return -1; /* (no cycle, yet an adaptive solve: reported below) */
  if (st != TFEM_STATUS_BUFFER_TOO_SMALL) return -1;
  long lo = 1, hi = 4096; /* the first length that holds them */
  if (tfem_get_adapt_cycles(m, NULL, NULL, NULL, (size_t)hi) != TFEM_STATUS_OK) return -1;
  while (lo < hi) {
    long mid = (lo + hi) / 2;
    if (tfem_get_adapt_cycles(m, NULL, NULL, NULL, (size_t)mid) == TFEM_STATUS_OK) hi = mid;
    else lo = mid + 1;
  }
  return lo;
}
static long required_len(runner_t *R, const call_t *c, int j) {
  int rq = FN[c->fn].req[j];
  int nn = -1, nt = -1, nc = -1;
  int64_t n = -1, nnz = -1;
  switch (rq) {
  case R_SCALAR: return 1;
  case R_36: return 36;
  case R_9: return 9;
  case R_2NN: case R_3NT: case R_NT: case R_NC: case R_3NC: case R_NN:
    if (tfem_get_sizes(R->m, &nn, &nt, &nc) != TFEM_STATUS_OK) return -1;
    return rq == R_2NN ? 2L * nn : rq == R_3NT ? 3L * nt : rq == R_NT ? nt : rq == R_NC ? nc : rq == R_NN ? nn : 3L * nc;
  case R_CM: case R_3CM:
    if (tfem_get_contact_mesh_size(R->m, &nc) != TFEM_STATUS_OK) return -1;
    return rq == R_CM ? nc : 3L * nc;
  case R_N1: case R_NNZ: case R_N:
    if (tfem_get_system_matrix_size(R->m, &n, &nnz) != TFEM_STATUS_OK) return -1;
    return rq == R_N1 ? (long)n + 1 : rq == R_NNZ ? (long)nnz : (long)n;
  case R_MSG: return (long)tfem_last_error_length(c->null_model ? NULL : R->m);
  case R_STATE: {
    size_t z = 0;
    if (c->null_model || tfem_get_contact_state_size(R->m, &z) != TFEM_STATUS_OK) return -1;
    return (long)z;
  }
  case R_CMSG: {
    static __thread char b[65536];
    if (c->null_model || !R->ctx) return -1;
    b[0] = 0;
    tfem_contact_last_error(R->ctx, b, sizeof b);
    return (long)strlen(b) + 1;
  }
  case R_NEQ: return R->cs->coupled ? R->cs->neq : -1;
  case R_CYC: return c->null_model ? -1 : R->sh.adapt_n > 0 ? R->sh.adapt_n : probe_cycles(R->m);
  case R_SLAVE: { /* the slave nodes: the report's elements less those of B (tfem_get_sizes) */
    tfem_contact_report rep;
    int nc = -1;
    if (c->null_model || tfem_get_contact_report(R->m, &rep) != TFEM_STATUS_OK ||
        tfem_get_sizes(R->m, NULL, NULL, &nc) != TFEM_STATUS_OK || nc < 0 || nc > rep.elements)
      return -1;
    return rep.elements - nc;
  }
  case R_CN: case R_2CN: case R_CE: case R_3CE: case R_6CE: case R_36CE: case R_CP: {
    int cn, ce;
    int64_t np;
    if (c->null_model || !ctx_sizes(R, &cn, &ce, &np)) return -1;
    return rq == R_CN ? cn : rq == R_2CN ? 2L * cn : rq == R_CE ? ce : rq == R_3CE ? 3L * ce : rq == R_6CE ? 6L * ce
         : rq == R_36CE ? 36L * ce : (long)np;
  }
  case R_WARN: {
    char b[4096];
    if (tfem_get_warning(R->m, c->iv[0], b, sizeof b) != TFEM_STATUS_OK) return -1;
    return (long)strlen(b) + 1;
  }
  /* the 3D model and its context */
  case R_S3NN: case R_SNN: case R_S6NT: case R_S4NT: case R_SNT: case R_SNC: case R_S4NC:
    if (!R->sm || tfem_solid_get_sizes(R->sm, &nn, &nt, &nc) != TFEM_STATUS_OK) return -1;
    return rq == R_S3NN ? 3L * nn : rq == R_SNN ? nn : rq == R_S6NT ? 6L * nt : rq == R_S4NT ? 4L * nt : rq == R_SNT ? nt
         : rq == R_SNC ? nc : 4L * nc;
  case R_S3NF: case R_SNF:
    if (!R->sm || tfem_solid_get_boundary_face_count(R->sm, &nn) != TFEM_STATUS_OK) return -1;
    return rq == R_S3NF ? 3L * nn : nn;
  case R_SMSG: return c->null_model || c->handle || !R->sm ? -1 : (long)tfem_solid_last_error_length(R->sm);
  case R_SWARN: {
    char b[4096];
    if (!R->sm || tfem_solid_get_warning(R->sm, c->iv[0], b, sizeof b) != TFEM_STATUS_OK) return -1;
    return (long)strlen(b) + 1;
  }
  case R_SCN: case R_S3CN: {
    int cn = ssc_nodes(R);
    return cn < 0 ? -1 : rq == R_SCN ? cn : 3L * cn;
  }
  case R_SCT: case R_S4CT: case R_S12CT: case R_S144CT: case R_SCP: {
    int ce;
    int64_t np;
    if (!ssc_sizes(R, NULL, &ce, &np)) return -1;
    return rq == R_SCT ? ce : rq == R_S4CT ? 4L * ce : rq == R_S12CT ? 12L * ce : rq == R_S144CT ? 144L * ce : (long)np;
  }
  case R_SCMSG: {
    static __thread char b[65536];
    if (c->null_model || c->handle || !R->sctx) return -1;
    b[0] = 0;
    tfem_solid_contact_last_error(R->sctx, b, sizeof b);
    return (long)strlen(b) + 1;
  }
  case R_SNEQ: return R->cs->coupled == 2 ? R->cs->neq : -1;
  default: return -1;
  }
}

static void resolve_outputs(runner_t *R, call_t *c) {
  for (int j = 0; j < fn_nout(c->fn); ++j) {
    out_spec *o = &c->out[j];
    if (o->resolved) continue;
    o->resolved = 1;
    o->req = required_len(R, c, j);
    if (FN[c->fn].scalar_out || FN[c->fn].req[j] == R_36 || FN[c->fn].req[j] == R_9) {
      o->len = 1;
      if (FN[c->fn].req[j] == R_36) o->len = 36;
      if (FN[c->fn].req[j] == R_9) o->len = 9;
      continue;
    }
    long base = o->req >= 0 ? o->req : 16, len;
    if (o->ls == LS_EXACT) len = base;
    else if (o->ls == LS_REL) len = base + o->delta;
    else len = o->delta;
    if (len < 0) len = 0;
    if (len > 50000000) len = 50000000;
    o->len = (size_t)len;
  }
}

static void norm_info(const tfem_solve_info *in, tfem_solve_info *out) {
  memset(out, 0, sizeof *out);
  out->unknowns = in->unknowns;
  out->matrix_nnz = in->matrix_nnz;
  out->factor_nnz = in->factor_nnz;
  out->factorizations = in->factorizations;
  out->interface_unknowns = in->interface_unknowns;
  out->relative_residual = in->relative_residual;
  out->condition_estimate = in->condition_estimate;
  out->memory_bytes = in->memory_bytes;
  out->factorization_bytes = in->factorization_bytes;
}
static void norm_report(const tfem_contact_report *in, tfem_contact_report *out) {
  memset(out, 0, sizeof *out);
  out->iterations = in->iterations;
  out->elements = in->elements;
  out->active = in->active;
  out->contact_length = in->contact_length;
  out->max_penetration = in->max_penetration;
  norm_info(&in->info, &out->info);
}
static void norm_options(const tfem_contact_options *in, tfem_contact_options *out) {
  memset(out, 0, sizeof *out);
  out->law = in->law;
  out->contact_modulus = in->contact_modulus;
  out->lambda = in->lambda;
  out->inversion_test = in->inversion_test;
  out->max_iterations = in->max_iterations;
  out->refactorize = in->refactorize;
}

/* Normalised bytes of output j (structs without padding and timings). */
static unsigned char *out_bytes(const gbuf *g, size_t *n) {
  unsigned char *b;
  if (g->kind == K_SI) {
    b = xmalloc(sizeof(tfem_solve_info));
    norm_info((const tfem_solve_info *)(const void *)g->p, (tfem_solve_info *)(void *)b);
    *n = sizeof(tfem_solve_info);
  } else if (g->kind == K_RE) {
    b = xmalloc(sizeof(tfem_contact_report));
    norm_report((const tfem_contact_report *)(const void *)g->p, (tfem_contact_report *)(void *)b);
    *n = sizeof(tfem_contact_report);
  } else if (g->kind == K_AR) { /* (the seconds left out) */
    const tfem_adapt_report *in = (const tfem_adapt_report *)(const void *)g->p;
    tfem_adapt_report *o = xmalloc(sizeof *o);
    memset(o, 0, sizeof *o);
    o->cycles = in->cycles;
    o->reached = in->reached;
    o->unknowns = in->unknowns;
    o->triangles = in->triangles;
    o->estimate = in->estimate;
    b = (unsigned char *)o;
    *n = sizeof *o;
  } else if (g->kind == K_T) { /* timings: not compared */
    b = xcalloc(1, g->bytes);
    *n = g->bytes;
  } else if (g->kind == K_OP) {
    b = xmalloc(sizeof(tfem_contact_options));
    norm_options((const tfem_contact_options *)(const void *)g->p, (tfem_contact_options *)(void *)b);
    *n = sizeof(tfem_contact_options);
  } else {
    b = xmalloc(g->bytes);
    memcpy(b, g->p, g->bytes);
    *n = g->bytes;
  }
  return b;
}

static int info_bad(const tfem_solve_info *i, char *why, size_t cap) {
  const double d[] = {i->relative_residual, i->condition_estimate, i->time_analysis, i->time_assembly,
                      i->time_factorization, i->time_solve, i->time_interface, i->time_total};
  static const char *const nm[] = {"relative_residual", "condition_estimate", "time_analysis", "time_assembly",
                                   "time_factorization", "time_solve", "time_interface", "time_total"};
  for (int k = 0; k < 8; ++k)
    if (!isfinite(d[k])) {
      snprintf(why, cap, "info.%s = %g", nm[k], d[k]);
      return 1;
    }
  return 0;
}
static int info_insane(const tfem_solve_info *i, char *why, size_t cap) {
  if (i->unknowns < 0 || i->matrix_nnz < 0 || i->factor_nnz < 0 || i->factorizations < 0 ||
      i->interface_unknowns < 0 || i->memory_bytes < 0 || i->factorization_bytes < 0 ||
      i->relative_residual < 0 || i->time_total < 0) {
    snprintf(why, cap, "negative field in solve info (unknowns %" PRId64 ", nnz %" PRId64 ", residual %g)",
             i->unknowns, i->matrix_nnz, i->relative_residual);
    return 1;
  }
  return 0;
}

static const char *fn_name(int fn) { return FN[fn].name; }

/* The outputs (doubles) the library gives as results carrying +0.0 where
 * a computation left -0.0 (src/model/solution.rs PositiveZero, the
 * report's and the slave nodes' values in src/contact/settled.rs), and the
 * host context's contact length (the header: "+0.0 when no element is
 * active"). Not geometry or matrices (jacobians, element matrices, the
 * system matrix, the host's element values). */
static int plus_zero_output(int fn) {
  switch (fn) {
  case F_GET_DISPLACEMENTS: case F_GET_EXTERNAL_WORK: case F_GET_STRAINS: case F_GET_STRESSES: case F_GET_REACTIONS:
  case F_GET_CONTACT_PRESSURE: case F_GET_CONTACT_SHEAR: case F_GET_CONTACT_DISSIPATION: case F_GET_CONTACT_FORCES:
  case F_GET_CONTACT_NODAL_PRESSURES: case F_GET_CONTACT_PAIR_NODAL_PRESSURES: case F_GET_CONTACT_GAPS:
  case F_GET_CONTACT_SLAVE_NODES: case F_CONTACT_LENGTH: case F_GET_OUT_OF_PLANE:
    return 1;
  default: return 0;
  }
}

/* Output j was passed, long enough for everything required. */
static int out_full(const call_t *c, int j) {
  return !c->out[j].null_ && c->out[j].req >= 0 && c->out[j].len >= (size_t)c->out[j].req;
}

/* The round-off of sums of element forces K_e u_e - f0_e over n nodes: the
 * terms are bounded by max |K_ij| (the system matrix of the last solve,
 * contact elements included) times max |u| + the largest initial gap
 * `gap` (the initial-gap loads f0 of the contact elements are of the size
 * of K times the gap), and the forces themselves can be far smaller (a
 * block moving rigidly by 0.0125 to close a gap, E = 1e11, loads of 1 N:
 * sums of 1e-7; no load at all, initial-gap loads cancelling: 1e-7). -1 if
 * it cannot be known. */
static double roundoff_scale(tfem_model *m, int nn, double gap) {
  int64_t n = -1, nnz = -1;
  if (tfem_get_system_matrix_size(m, &n, &nnz) != TFEM_STATUS_OK || n < 0 || nnz < 0) return -1;
  int64_t *cp = xmalloc(sizeof(int64_t) * (size_t)(n + 1)), *ri = xmalloc(sizeof(int64_t) * (size_t)nnz + 1);
  int64_t *dofs = xmalloc(sizeof(int64_t) * (size_t)n + 1);
  double *val = xmalloc(sizeof(double) * (size_t)nnz + 1), *u = xmalloc(sizeof(double) * 2 * (size_t)nn + 1);
  double kmax = 0, umax = 0, scale = -1;
  if (tfem_get_system_matrix(m, cp, (size_t)n + 1, ri, (size_t)nnz, val, (size_t)nnz, dofs, (size_t)n) == TFEM_STATUS_OK &&
      tfem_get_displacements(m, u, 2 * (size_t)nn) == TFEM_STATUS_OK) {
    for (int64_t k = 0; k < nnz; ++k) kmax = fmax(kmax, fabs(val[k]));
    for (int g = 0; g < 2 * nn; ++g) umax = fmax(umax, fabs(u[g]));
    scale = 32 * DBL_EPSILON * nn * kmax * (umax + gap);
  }
  free(cp), free(ri), free(dofs), free(val), free(u);
  return isfinite(scale) ? scale : -1;
}

/* tfem_get_contact_forces (2 per node, after a contact solve): zero off
 * the contact elements; the forces of a pair sum to zero (1e-9 of their
 * magnitude; the whole interface when pairs share nodes); on each body
 * the contact forces, the loads known here and the reactions sum to zero
 * (1e-8 of their magnitudes; an accurate solve, nodes of one body each);
 * both sums give or take the round-off of the element forces
 * (roundoff_scale). Only without prescribed displacements: with them the
 * element forces are not bounded by the loads (a displacement of 1e11
 * prescribed gives sums of 1e4 on forces of 1e7). */
static void oracle_contact_forces(runner_t *R, int idx, const double *fc) {
  shadow_t *s = &R->sh;
  int nn = s->nn, *cm, *cp;
  long ne = fetch_contact_mesh(R->m, &cm, &cp);
  if (ne < 0) return;
  int zero_presc = 1;
  for (int g2 = 0; g2 < 2 * nn; ++g2) zero_presc &= isnan(s->presc[g2]) || s->presc[g2] == 0.0;
  double gap = 0; /* the largest initial gap: height of a contact element over its longest side */
  for (long e = 0; e < ne; ++e) {
    long v[3];
    for (int k = 0; k < 3; ++k) v[k] = (long)cm[3 * e + k] - s->base;
    if (v[0] < 0 || v[1] < 0 || v[2] < 0 || v[0] >= nn || v[1] >= nn || v[2] >= nn) continue;
    int vi[3] = {(int)v[0], (int)v[1], (int)v[2]};
    double L = 0;
    for (int k = 0; k < 3; ++k) {
      const double *a = &s->xy[2 * vi[k]], *b = &s->xy[2 * vi[(k + 1) % 3]];
      L = fmax(L, hypot(b[0] - a[0], b[1] - a[1]));
    }
    if (L > 0) gap = fmax(gap, fabs(sh_j(s->xy, vi)) / L);
  }
  double ro = zero_presc ? roundoff_scale(R->m, nn, gap) : -1;
  zero_presc &= ro >= 0;
  int *pair_of = xmalloc(sizeof(int) * (size_t)nn + 1), shared = 0, npairs = 0, bad = 0;
  for (int v = 0; v < nn; ++v) pair_of[v] = -1;
  for (long e = 0; e < ne && !bad; ++e) {
    if (cp[e] < 0 || cp[e] >= 1000) bad = 1;
    else if (cp[e] + 1 > npairs) npairs = cp[e] + 1;
    for (int k = 0; k < 3 && !bad; ++k) {
      long v = (long)cm[3 * e + k] - s->base;
      if (v < 0 || v >= nn) bad = 1;
      else if (pair_of[v] == -1) pair_of[v] = cp[e];
      else if (pair_of[v] != cp[e]) pair_of[v] = -2, shared = 1;
    }
  }
  for (int v = 0; v < nn && !bad; ++v)
    if (pair_of[v] == -1 && (fc[2 * v] != 0.0 || fc[2 * v + 1] != 0.0)) {
      finding(R, V_CONTACT, idx, "contact force (%g, %g) at node %d, which is in no contact element", fc[2 * v],
              fc[2 * v + 1], v + s->base);
      break;
    }
  for (int k = 0; k < (shared ? 1 : npairs) && !bad && zero_presc; ++k) {
    double sum[2] = {0, 0}, mag = 0;
    for (int v = 0; v < nn; ++v)
      if (shared ? pair_of[v] != -1 : pair_of[v] == k)
        for (int d = 0; d < 2; ++d) sum[d] += fc[2 * v + d], mag += fabs(fc[2 * v + d]);
    R->oracles[O_PAIR_SUM] += isfinite(mag) && mag > 0 && ro < 1e-6 * mag;
    for (int d = 0; d < 2; ++d)
      if (isfinite(mag) && fabs(sum[d]) > 1e-9 * mag + ro) {
        finding(R, V_CONTACT, idx, "the contact forces of %s%d sum to %c = %.6g (of magnitude %.6g): not zero",
                shared ? "the pairs sharing nodes, from pair " : "pair ", k, d ? 'y' : 'x', sum[d], mag + ro);
        break;
      }
  }
  int friction_at_fixed = 0; /* (the known defect above: not checked) */
#if !API_FUZZ_FRICTION_REACTIONS
  int any_mu = s->npairs > 64;
  for (int k = 0; k < s->npairs && k < 64; ++k) any_mu |= s->pair_mu[k] != 0.0;
  for (int v = 0; v < nn && any_mu && !friction_at_fixed; ++v)
    friction_at_fixed = pair_of[v] != -1 && (!isnan(s->presc[2 * v]) || !isnan(s->presc[2 * v + 1]));
#endif
  tfem_contact_report rep;
  if (!bad && zero_presc && !friction_at_fixed && tfem_get_contact_report(R->m, &rep) == TFEM_STATUS_OK &&
      isfinite(rep.info.relative_residual) && rep.info.relative_residual < 1e-10) {
    double *f = xmalloc(sizeof(double) * 2 * (size_t)nn + 1), *re = xmalloc(sizeof(double) * 2 * (size_t)nn + 1);
    int *nb = sh_node_bodies(s), one_body = 1;
    for (int v = 0; v < nn; ++v) one_body &= nb[v] != INT_MAX;
    if (one_body && sh_nodal_forces(s, f) && tfem_get_reactions(R->m, re, 2 * (size_t)nn) == TFEM_STATUS_OK) {
      int bodies[16], nbo = 0;
      for (int t = 0; t < s->nt; ++t) {
        int k = 0;
        while (k < nbo && bodies[k] != s->body[t]) ++k;
        if (k == nbo && nbo < 16) bodies[nbo++] = s->body[t];
      }
      for (int k = 0; k < nbo; ++k) {
        double sum[2] = {0, 0}, mag = 0;
        for (int v = 0; v < nn; ++v)
          if (nb[v] == bodies[k])
            for (int d = 0; d < 2; ++d) {
              sum[d] += f[2 * v + d] + re[2 * v + d] + fc[2 * v + d];
              mag += fabs(f[2 * v + d]) + fabs(re[2 * v + d]) + fabs(fc[2 * v + d]);
            }
        R->oracles[O_BODY_BALANCE] += isfinite(mag) && mag < 1e200 && mag > 0 && ro < 1e-6 * mag;
        for (int d = 0; d < 2; ++d)
          if (isfinite(mag) && mag < 1e200 && fabs(sum[d]) > 1e-8 * mag + ro) {
            finding(R, V_CONTACT, idx,
                    "on body %d, contact forces + loads + reactions sum to %c = %.6g (of magnitude %.6g, round-off "
                    "%.3g; relative residual %.3g): not balanced",
                    bodies[k], d ? 'y' : 'x', sum[d], mag, ro, rep.info.relative_residual);
            k = nbo;
            break;
          }
      }
    }
    free(f);
    free(re);
    free(nb);
  }
  free(pair_of);
  free(cm);
  free(cp);
}

/* The nodes of the current contact mesh: a flag per node (nn + 1 bytes, to
 * free), or NULL when the mesh cannot be read or names a node out of range. */
static char *contact_nodes(runner_t *R) {
  shadow_t *s = &R->sh;
  int *cm;
  long ne = fetch_contact_mesh(R->m, &cm, NULL);
  if (ne < 0) return NULL;
  char *in = xcalloc((size_t)s->nn + 1, 1);
  for (long e = 0; e < 3 * ne; ++e) {
    long v = (long)cm[e] - s->base;
    if (v < 0 || v >= s->nn) {
      free(in);
      in = NULL;
      break;
    }
    in[v] = 1;
  }
  free(cm);
  return in;
}

/* tfem_get_contact_nodal_pressures (per node, after a contact solve):
 * zero off the nodes of the contact elements. */
static void oracle_nodal_pressures(runner_t *R, int idx, const double *p) {
  shadow_t *s = &R->sh;
  char *in = contact_nodes(R);
  for (int v = 0; in && v < s->nn; ++v)
    if (!in[v] && p[v] != 0.0) {
      finding(R, V_CONTACT, idx, "nodal contact pressure %g at node %d, which no contact element touches", p[v],
              v + s->base);
      break;
    }
  free(in);
}

/* tfem_get_contact_pair_nodal_pressures (pair k, after a contact solve):
 * zero off the nodes of pair k's contact elements; at a node on pair k's
 * elements only, tfem_get_contact_nodal_pressures' value to the bit (the
 * same reading of the same elements). */
static void oracle_pair_nodal_pressures(runner_t *R, int idx, int pair, const double *p) {
  shadow_t *s = &R->sh;
  int *cm, *cp;
  long ne = fetch_contact_mesh(R->m, &cm, &cp);
  if (ne < 0) return;
  int nn = s->nn, bad = 0;
  int *pair_of = xmalloc(sizeof(int) * (size_t)nn + 1); /* -1 none, -2 several */
  char *on_k = xcalloc((size_t)nn + 1, 1);
  double *all = xmalloc(sizeof(double) * (size_t)nn + 1);
  for (int v = 0; v < nn; ++v) pair_of[v] = -1;
  for (long e = 0; e < ne && !bad; ++e)
    for (int k = 0; k < 3 && !bad; ++k) {
      long v = (long)cm[3 * e + k] - s->base;
      if (v < 0 || v >= nn) bad = 1;
      else {
        on_k[v] |= cp[e] == pair;
        pair_of[v] = pair_of[v] == -1 || pair_of[v] == cp[e] ? cp[e] : -2;
      }
    }
  if (!bad && tfem_get_contact_nodal_pressures(R->m, all, (size_t)nn) == TFEM_STATUS_OK) {
    R->oracles[O_PAIR_PRESSURE]++;
    for (int v = 0; v < nn; ++v) {
      if (!on_k[v] && p[v] != 0.0) {
        finding(R, V_CONTACT, idx, "pair %d: nodal pressure %g at node %d, on no element of that pair", pair, p[v],
                v + s->base);
        break;
      }
      if (pair_of[v] == pair && memcmp(&p[v], &all[v], sizeof(double)) != 0) {
        finding(R, V_CONTACT, idx, "pair %d: nodal pressure %.17g at node %d, on that pair only, read %.17g with all",
                pair, p[v], v + s->base, all[v]);
        break;
      }
    }
  }
  free(cm);
  free(cp);
  free(pair_of);
  free(on_k);
  free(all);
}

/* tfem_get_contact_gaps (per node, after a contact solve): zero off the
 * contact elements; where the report gives a penetration, the smallest
 * gap is minus it (1e-14 relative: the library computes both from the
 * elements' openings; equal to the bit so far, 8 ulps apart once under the
 * literal test at 6e197). Only with the
 * linearised inversion test: the literal one leaves elements inactive
 * whose linearised opening is negative (its second-order term), so the
 * smallest gap can be below minus the penetration of the active ones
 * (seen: -6e197 against 1e197 with 1e200 prescribed). */
static void oracle_gaps(runner_t *R, int idx, const double *gap) {
  shadow_t *s = &R->sh;
  char *in = contact_nodes(R);
  int bad = in == NULL;
  double mn = INFINITY;
  for (int v = 0; v < s->nn && !bad; ++v) {
    if (!in[v] && gap[v] != 0.0) {
      finding(R, V_CONTACT, idx, "gap %g at node %d, which is in no contact element", gap[v], v + s->base);
      bad = 1;
    }
    if (gap[v] < mn) mn = gap[v];
  }
  tfem_contact_report rep;
  int checked = !bad && s->contact_test == TFEM_INVERSION_TEST_LINEARISED && !(s->res_fam & (FAM_MORTAR | FAM_UNKNOWN)) &&
                tfem_get_contact_report(R->m, &rep) == TFEM_STATUS_OK && rep.max_penetration > 0;
  R->oracles[O_GAP_PEN] += checked;
  if (checked && !(fabs(mn + rep.max_penetration) <= 1e-14 * rep.max_penetration))
    finding(R, V_CONTACT, idx, "smallest gap %.17g, but the report's max_penetration is %.17g (relative difference %.3g)",
            mn, rep.max_penetration, fabs(mn + rep.max_penetration) / rep.max_penetration);
  free(in);
}

/* tfem_get_contact_slave_nodes (OK: after a solve or step with a pair
 * under the mortar weighting), against the report and a read of all four
 * columns at the exact length n = the report's elements less the elements
 * of B (tfem_get_sizes: the header, "the report's `elements` counting
 * elements of B and slave nodes"): the columns the call asked for are
 * those values, bit for bit, and nothing past n is written; nodes in
 * range; tributaries finite and > 0; gaps finite; pressures finite and
 * >= 0, > 0 only where the mean gap is negative (p = -kappa G); the nodes
 * with a pressure are at most the report's active ones; where no pair is
 * weighted by B (no element of B) as many, their tributaries sum to the
 * report's contact length (1e-12 relative) and their largest -gap is its
 * max_penetration (1e-14 relative). Where the shadow knows the interface's
 * coarser side (sh_slave_body: one interface of two bodies, cut into one
 * or more pairs), every slave node is on that body and none is listed
 * twice (a slave node that ends two pairs carries one weighted gap), and
 * tfem_get_contact_nodal_pressures reads each slave node's pressure to the
 * bit (src/model/mod.rs contact_nodal_pressures: "Under the mortar
 * weighting: each slave node's -kappa G_i/m_i"; the brief of 000420e: a
 * slave node shared by two pairs reads one weighted gap). */
#if !API_FUZZ_MORTAR_TENSION
static double max_displacement(tfem_model *m) {
  int nn = -1, nt, nc;
  double mx = NAN;
  if (tfem_get_sizes(m, &nn, &nt, &nc) != TFEM_STATUS_OK || nn < 0) return mx;
  double *u = xmalloc(sizeof(double) * 2 * (size_t)nn + 1);
  if (tfem_get_displacements(m, u, 2 * (size_t)nn) == TFEM_STATUS_OK) {
    mx = 0;
    for (int k = 0; k < 2 * nn; ++k) mx = fmax(mx, fabs(u[k]));
  }
  free(u);
  return mx;
}
#endif
static void oracle_slave_nodes(runner_t *R, int idx, const call_t *c, const gbuf *g) {
  shadow_t *s = &R->sh;
  tfem_contact_report rep;
  if (tfem_get_contact_report(R->m, &rep) != TFEM_STATUS_OK) {
    finding(R, V_WEIGHTING, idx, "slave nodes OK, but tfem_get_contact_report refused");
    return;
  }
  int nc = -1;
  if (tfem_get_sizes(R->m, NULL, NULL, &nc) != TFEM_STATUS_OK || nc < 0 || nc > rep.elements) {
    finding(R, V_WEIGHTING, idx, "slave nodes OK, but %d elements of B (tfem_get_sizes) of the report's %d elements",
            nc, rep.elements);
    return;
  }
  long n = rep.elements - nc;
  if (n < 0 || n > 10000000) return;
  int *node = xmalloc(sizeof(int) * (size_t)n + 1);
  double *col[3];
  for (int k = 0; k < 3; ++k) col[k] = xmalloc(sizeof(double) * (size_t)n + 1);
  int st = tfem_get_contact_slave_nodes(R->m, node, col[0], col[1], col[2], (size_t)n);
  R->oracles[O_SLAVE]++;
  if (st != TFEM_STATUS_OK) {
    finding(R, V_WEIGHTING, idx, "OK, but all four columns at length n = %ld give %s", n, status_name(st));
    goto done;
  }
  for (int j = 0; j < 4; ++j) {
    if (c->out[j].null_) continue;
    const void *mine = j == 0 ? (const void *)node : (const void *)col[j - 1];
    size_t es = ksize(g[j].kind), m = (size_t)n < g[j].n ? (size_t)n : g[j].n;
    if (memcmp(g[j].p, mine, es * m) != 0) {
      finding(R, V_WEIGHTING, idx, "column %d differs from the same column read with all four", j);
      break;
    }
    for (size_t i = (size_t)n; i < g[j].n; ++i)
      if (!gb_is_pattern(&g[j], i)) {
        finding(R, V_WEIGHTING, idx, "column %d element %zu written, past the %ld slave nodes (length %zu)", j, i, n,
                g[j].n);
        break;
      }
  }
  long act = 0;
  double sum = 0, pen = 0;
  for (long i = 0; i < n; ++i) {
    double t = col[0][i], gp = col[1][i], p = col[2][i];
    if (s->exact && (node[i] < s->base || node[i] >= s->base + s->nn)) {
      finding(R, V_WEIGHTING, idx, "slave node %ld is node %d, out of range", i, node[i]);
      goto done;
    }
    int sign_bad = isfinite(p) && isfinite(gp) && (p < 0 || (p > 0 && !(gp < 0)));
#if !API_FUZZ_MORTAR_TENSION
    if (sign_bad && fabs(gp) <= 1e-12 * max_displacement(R->m)) sign_bad = 0; /* (the known round-off above) */
#endif
    if (!(isfinite(t) && t > 0) || !isfinite(gp) || !isfinite(p) || sign_bad) {
      finding(R, V_WEIGHTING, idx, "slave node %ld (node %d): tributary %.17g, gap %.17g, pressure %.17g", i, node[i],
              t, gp, p);
      goto done;
    }
    if (p > 0) ++act, sum += t, pen = fmax(pen, -gp);
  }
  int sb = s->res_fam == FAM_MORTAR ? sh_slave_body(s) : -1;
  if (sb != -1) {
    int *nb = sh_node_bodies(s);
    char *seen = xcalloc((size_t)s->nn + 1, 1);
    R->oracles[O_SLAVE]++;
    for (long i = 0; i < n; ++i) {
      int v = node[i] - s->base, b = nb[v];
      if (b != INT_MAX && b != sb) {
        finding(R, V_WEIGHTING, idx, "slave node %ld (node %d) is on body %d, the interface's coarser side is body %d "
                "(fewer edges over its pairs)", i, node[i], b, sb);
        break;
      }
      if (seen[v]) {
        finding(R, V_WEIGHTING, idx, "node %d is listed twice among the %ld slave nodes of one interface (%d pairs): "
                "one weighted gap per slave node", node[i], n, s->npairs);
        break;
      }
      seen[v] = 1;
    }
    double *np = xmalloc(sizeof(double) * (size_t)s->nn + 1);
    if (tfem_get_contact_nodal_pressures(R->m, np, (size_t)s->nn) == TFEM_STATUS_OK) {
      R->oracles[O_SLAVE]++;
      for (long i = 0; i < n; ++i)
        if (memcmp(&np[node[i] - s->base], &col[2][i], sizeof(double)) != 0) {
          finding(R, V_WEIGHTING, idx, "slave node %ld (node %d): pressure %.17g, but tfem_get_contact_nodal_pressures "
                  "reads %.17g there (%d pairs)", i, node[i], col[2][i], np[node[i] - s->base], s->npairs);
          break;
        }
    }
    free(np);
    free(seen);
    free(nb);
  }
  if (act > rep.active) {
    finding(R, V_WEIGHTING, idx, "%ld slave nodes with a pressure, %d active in the report", act, rep.active);
  } else if (act == rep.active && nc == 0) {
    if (!(fabs(sum - rep.contact_length) <= 1e-12 * fabs(rep.contact_length)))
      finding(R, V_WEIGHTING, idx, "the tributaries of the %ld active slave nodes sum to %.17g, the report's contact "
              "length is %.17g", act, sum, rep.contact_length);
    else if (!(fabs(pen - rep.max_penetration) <= 1e-14 * rep.max_penetration))
      finding(R, V_WEIGHTING, idx, "the largest -gap of the active slave nodes is %.17g, the report's max_penetration "
              "%.17g", pen, rep.max_penetration);
  }
done:
  free(node);
  for (int k = 0; k < 3; ++k) free(col[k]);
}

/* tfem_get_external_work: the sum of f.u over the loads known here and the
 * displacements (relative 1e-10 of the sum of |f.u|). */
static void oracle_work(runner_t *R, int idx, double w) {
  shadow_t *s = &R->sh;
  size_t n2 = 2 * (size_t)s->nn;
  double *f = xmalloc(sizeof(double) * n2 + 1), *u = xmalloc(sizeof(double) * n2 + 1);
  if (sh_nodal_forces(s, f) && tfem_get_displacements(R->m, u, n2) == TFEM_STATUS_OK) {
    double sum = 0, mag = 0;
    for (size_t g = 0; g < n2; ++g) {
      sum += f[g] * u[g];
      mag += fabs(f[g] * u[g]);
    }
    R->oracles[O_WORK] += isfinite(mag) && mag < 1e300 && mag > 0;
    if (isfinite(mag) && mag < 1e300 && !(fabs(w - sum) <= 1e-10 * mag + 1e-290))
      finding(R, V_WORK, idx, "work %.17g, but the sum of f.u over the loads is %.17g (of magnitude %.3g)", w, sum, mag);
  }
  free(f);
  free(u);
}

/* Runs call idx, checks it (original run) or compares it (replay). */

/* ---- friction, prescribed values moved, automatic pairs, twin models ---- */

/* Coulomb's law per contact element, as c_tests/boundary_test.c checks it:
 * open (state 0): no shear and no pressure; stick (1): |tau| <= mu p
 * (1 + 1e-9); slip (2): |tau| = mu p within 1e-9; no dissipation below 0
 * (nor NaN); mu = 0: no shear, no dissipation, and never stick when every
 * element's mu is 0 (the header: "a frictionless solve: 2 where active";
 * a mu = 0 pair beside a frictional one may stick, with no shear); open exactly
 * where the element is inactive (active may be NULL). p is taken as
 * max(p, 0) (an active element in tension, seen at 1e40 with a DOF
 * prescribed 1e30: no shear). tiny, the slack of round-off, is 1e-9 mu
 * times the largest of |p| and smax, the largest stress of the body
 * elements (the stresses' round-off is relative to the largest: a slip
 * seen 4e-11 of mu max |p| off mu p on an element of 1/50 of the largest
 * pressure; 8e-7 of mu p with a DOF prescribed 1e5); dtol the slack of
 * the dissipation's sign (see API_FUZZ_DISSIPATION_SIGN). mu[k] NaN: element k
 * not known here
 * (only its state, dissipation and activity are checked). Returns the
 * first element breaking it (why says how), or -1. */
static long coulomb_check(long n, const double *p, const double *tau, const int *state, const double *d,
                          const int *active, const double *mu, double smax, double dtol, char *why, size_t cap) {
  double pmax = smax;
  int frictionless = 1; /* (every element's mu 0: "a frictionless solve: 2 where active") */
  double dmax = 0;
  for (long k = 0; k < n; ++k) {
    if (fabs(p[k]) > pmax) pmax = fabs(p[k]);
    if (fabs(d[k]) > dmax) dmax = fabs(d[k]);
    frictionless &= mu[k] == 0.0;
  }
  for (long k = 0; k < n; ++k) {
    double mk = mu[k], lim = mk * fmax(p[k], 0.0), tiny = 1e-9 * (isnan(mk) ? 0.0 : mk) * pmax;
    why[0] = 0;
    if (state[k] < 0 || state[k] > 2) snprintf(why, cap, "friction state %d is not 0, 1 or 2", state[k]);
    else if (!(d[k] >= -dtol) || !isfinite(d[k]))
      snprintf(why, cap, "dissipation %.17g (largest |dissipation| %.6g)", d[k], dmax);
    else if (active && (state[k] != 0) != (active[k] != 0))
      snprintf(why, cap, "friction state %d (0 = open) but active flag %d", state[k], active[k]);
    else if (isnan(mk)) continue;
    else if (state[k] == 0 && (tau[k] != 0.0 || p[k] != 0.0))
      snprintf(why, cap, "open, yet shear %.17g, pressure %.17g", tau[k], p[k]);
    else if (mk == 0.0 && (tau[k] != 0.0 || d[k] != 0.0 || (state[k] == 1 && frictionless)))
      snprintf(why, cap, "mu = 0 (frictionless), yet state %d, shear %.17g, dissipation %.17g", state[k], tau[k], d[k]);
    else if (mk != 0.0 && state[k] == 1 && !(fabs(tau[k]) <= lim * (1 + 1e-9) + tiny))
      snprintf(why, cap, "sticks with |shear| %.17g > mu p = %.17g (max pressure %.6g)", fabs(tau[k]), lim, pmax);
    else if (mk != 0.0 && state[k] == 2 && !(fabs(fabs(tau[k]) - lim) <= 1e-9 * fabs(lim) + tiny))
      snprintf(why, cap, "slips with |shear| %.17g, not mu p = %.17g (max pressure %.6g)", fabs(tau[k]), lim, pmax);
    if (why[0]) return k;
  }
  return -1;
}

/* Coulomb's law of the last contact solve or step (frictionless law, mu per
 * pair as set here), from the pressures, shear, friction states,
 * dissipation, active flags and element pairs read with extra calls; once
 * per result. */
static void oracle_coulomb(runner_t *R, int idx) {
  shadow_t *s = &R->sh;
  if (!s->exact || !(s->results == 2 || s->results == 3) || s->res_unknown || s->contact_law != 0 ||
      s->coul_gen == s->sol_gen)
    return;
  s->coul_gen = s->sol_gen;
  int nn, nt, nc, ncm;
  if (tfem_get_sizes(R->m, &nn, &nt, &nc) != TFEM_STATUS_OK || nc <= 0 ||
      tfem_get_contact_mesh_size(R->m, &ncm) != TFEM_STATUS_OK || ncm != nc)
    return;
  size_t n = (size_t)nc;
  double smax = 0, *sig = xmalloc(sizeof(double) * 3 * (size_t)nt + 1);
  if (tfem_get_element_stresses(R->m, sig, 3 * (size_t)nt) == TFEM_STATUS_OK)
    for (size_t k = 0; k < 3 * (size_t)nt; ++k) smax = fmax(smax, fabs(sig[k]));
  free(sig);
  {
    /* The round-off of the stresses has an absolute floor, eps E |u| / h,
     * which the largest stress does not measure when the solution is
     * (nearly) a rigid motion (no load): E from the largest entry of the
     * system matrix, h the shortest edge of the mesh. */
    int64_t mn = 0, mnnz = 0;
    double kmax = 0, umax = 0, hmin = INFINITY;
    if (s->xy && s->tri && tfem_get_system_matrix_size(R->m, &mn, &mnnz) == TFEM_STATUS_OK && mn > 0 && mnnz > 0) {
      int64_t *cp = xmalloc(sizeof(int64_t) * (size_t)(mn + 1)), *ri = xmalloc(sizeof(int64_t) * (size_t)mnnz);
      int64_t *dofs = xmalloc(sizeof(int64_t) * (size_t)mn);
      double *val = xmalloc(sizeof(double) * (size_t)mnnz), *u = xmalloc(sizeof(double) * 2 * (size_t)nn + 1);
      if (tfem_get_system_matrix(R->m, cp, (size_t)mn + 1, ri, (size_t)mnnz, val, (size_t)mnnz, dofs, (size_t)mn) ==
              TFEM_STATUS_OK &&
          tfem_get_displacements(R->m, u, 2 * (size_t)nn) == TFEM_STATUS_OK) {
        for (int64_t k = 0; k < mnnz; ++k) kmax = fmax(kmax, fabs(val[k]));
        for (size_t k = 0; k < 2 * (size_t)nn; ++k) umax = fmax(umax, fabs(u[k]));
        for (int t = 0; t < s->nt; ++t)
          for (int a = 0; a < 3; ++a) {
            int i = s->tri[3 * t + a], j = s->tri[3 * t + (a + 1) % 3];
            if (i < 0 || j < 0 || i >= s->nn || j >= s->nn) continue;
            double h = hypot(s->xy[2 * i] - s->xy[2 * j], s->xy[2 * i + 1] - s->xy[2 * j + 1]);
            if (h > 0) hmin = fmin(hmin, h);
          }
        if (isfinite(hmin) && isfinite(kmax * umax)) smax = fmax(smax, 1e9 * 64 * DBL_EPSILON * kmax * umax / hmin);
      }
      free(cp), free(ri), free(dofs), free(val), free(u);
    }
  }
  double dtol = 0;
#if !API_FUZZ_DISSIPATION_SIGN
  {
    double umax = 0, mumax = 0, pm = 0, *u = xmalloc(sizeof(double) * 2 * (size_t)nn + 1), *pp = xmalloc(sizeof(double) * n);
    if (tfem_get_displacements(R->m, u, 2 * (size_t)nn) == TFEM_STATUS_OK &&
        tfem_get_contact_pressure(R->m, pp, n) == TFEM_STATUS_OK) {
      for (size_t k = 0; k < 2 * (size_t)nn; ++k) umax = fmax(umax, fabs(u[k]));
      for (size_t k = 0; k < n; ++k) pm = fmax(pm, fabs(pp[k]));
      for (int k = 0; k < s->npairs && k < 64; ++k) mumax = fmax(mumax, s->pair_mu[k]);
      dtol = 1e-12 * mumax * pm * umax;
    }
    free(u), free(pp);
  }
#endif
  double *p = xmalloc(sizeof(double) * n), *tau = xmalloc(sizeof(double) * n), *d = xmalloc(sizeof(double) * n);
  double *mu = xmalloc(sizeof(double) * n);
  int *state = xmalloc(sizeof(int) * n), *act = xmalloc(sizeof(int) * n), *pr = xmalloc(sizeof(int) * n);
  const char *failed = tfem_get_contact_pressure(R->m, p, n) != TFEM_STATUS_OK ? "tfem_get_contact_pressure"
                       : tfem_get_contact_shear(R->m, tau, n) != TFEM_STATUS_OK ? "tfem_get_contact_shear"
                       : tfem_get_contact_friction_state(R->m, state, n) != TFEM_STATUS_OK ? "tfem_get_contact_friction_state"
                       : tfem_get_contact_dissipation(R->m, d, n) != TFEM_STATUS_OK ? "tfem_get_contact_dissipation"
                       : tfem_get_contact_active(R->m, act, n) != TFEM_STATUS_OK ? "tfem_get_contact_active"
                       : tfem_get_contact_element_pairs(R->m, pr, n) != TFEM_STATUS_OK ? "tfem_get_contact_element_pairs"
                                                                                       : NULL;
  if (failed) {
    finding(R, V_FRICTION, idx, "%s failed on the results this call read", failed);
  } else {
    for (size_t k = 0; k < n; ++k) mu[k] = pr[k] >= 0 && pr[k] < s->npairs && pr[k] < 64 ? s->pair_mu[pr[k]] : NAN;
    char why[300];
    long k = coulomb_check((long)n, p, tau, state, d, act, mu, smax, dtol, why, sizeof why);
    R->oracles[O_COULOMB]++;
    if (k >= 0)
      finding(R, V_FRICTION, idx, "contact element %ld (pair %d, mu %g, pressure %.6g): %s", k, pr[k], mu[k], p[k], why);
  }
  free(p), free(tau), free(d), free(mu), free(state), free(act), free(pr);
}

/* The number of contact pairs from `from` on, as tfem_get_contact_pair_bodies
 * answers (their bodies in ab, cap kept); the message of the last, failing,
 * call is cleared by a successful tfem_get_threads. */
static int probe_pairs(tfem_model *m, int from, int (*ab)[2], int cap) {
  int k = from;
  while (k >= 0 && k < from + 1000) {
    int a = INT_MIN, b = INT_MIN;
    if (tfem_get_contact_pair_bodies(m, k, &a, &b) != TFEM_STATUS_OK) break;
    if (k - from < cap) ab[k - from][0] = a, ab[k - from][1] = b;
    ++k;
  }
  int t;
  tfem_get_threads(m, &t);
  return k - from;
}

/* Equal values: bit for bit (rtol < 0), or within rtol of the largest
 * magnitude of either. Returns the first index differing, or -1. */
static long same_values(long n, const double *a, const double *b, double rtol) {
  double big = 0;
  for (long k = 0; k < n; ++k) {
    if (fabs(a[k]) > big) big = fabs(a[k]);
    if (fabs(b[k]) > big) big = fabs(b[k]);
  }
  for (long k = 0; k < n; ++k)
    if (rtol < 0 ? memcmp(&a[k], &b[k], sizeof(double)) != 0 : !(fabs(a[k] - b[k]) <= rtol * big)) return k;
  return -1;
}

/* One call of the case on the twin model (the calls that change the
 * problem or the results; getters are left out), changed as call_t.tw says
 * when `apply`. */
static int twin_exec(tfem_model **mp, const call_t *c, int apply) {
  tfem_model *m = *mp;
  const void *in[MAXIN];
  for (int j = 0; j < MAXIN; ++j) in[j] = c->in[j].null_ ? NULL : c->in[j].p;
  tfem_contact_options opts = {c->iv[0], c->dv[0], c->dv[1], c->iv[1], c->iv[2], c->iv[3]};
  const tfem_contact_options *op = c->in[0].null_ ? NULL : &opts;
  double v0 = apply && c->tw == 2 ? c->tw_val : c->dv[0];
  tfem_solve_info info;
  tfem_contact_report rep;
  if (apply && c->tw == 4 && (c->fn == F_SET_BOUNDARY_EDGES || c->fn == F_ADD_BOUNDARY_EDGES) && in[1] &&
      c->in[1].n > 0) {
    int *tags = xmalloc(sizeof(int) * (size_t)c->in[1].n);
    for (int k = 0; k < c->in[1].n; ++k) {
      int t = ((const int *)in[1])[k];
      tags[k] = t == 5 ? 2 : t == 6 ? 3 : t;
    }
    int st = c->fn == F_SET_BOUNDARY_EDGES ? tfem_set_boundary_edges(m, c->iv[0], in[0], tags)
                                           : tfem_add_boundary_edges(m, c->iv[0], in[0], tags);
    free(tags);
    return st;
  }
  switch (c->fn) {
  case F_SET_MESH: return tfem_set_mesh(m, c->iv[0], in[0], c->iv[1], in[1], in[2], c->iv[2]);
  case F_LOAD_GMSH: return tfem_load_gmsh(m, c->iv[0] >= 0 && c->iv[0] < NGMSH ? g_path[c->iv[0]] : NULL, c->iv[1]);
  case F_SET_BOUNDARY_EDGES: return tfem_set_boundary_edges(m, c->iv[0], in[0], in[1]);
  case F_ADD_BOUNDARY_EDGES: return tfem_add_boundary_edges(m, c->iv[0], in[0], in[1]);
  case F_SET_MATERIAL: return tfem_set_material(m, c->iv[0], c->dv[0], c->dv[1], c->iv[1]);
  case F_SET_TEMPERING: return tfem_set_tempering(m, c->iv[0], c->dv[0]);
  case F_SET_ORDERING: return tfem_set_ordering(m, c->iv[0], c->iv[1]);
  case F_FIX: return tfem_fix(m, c->iv[0], c->iv[1], v0);
  case F_FIX_EDGES: return tfem_fix_edges(m, c->iv[0], c->iv[1], v0);
  case F_CLEAR_CONSTRAINTS: return tfem_clear_constraints(m);
  case F_ADD_PRESSURE: return tfem_add_pressure(m, c->iv[0], c->dv[0]);
  case F_ADD_TRACTION: return tfem_add_traction(m, c->iv[0], c->dv[0], c->dv[1]);
  case F_ADD_NODAL_FORCE: return tfem_add_nodal_force(m, c->iv[0], c->dv[0], c->dv[1]);
  case F_SET_BODY_FORCE: return tfem_set_body_force(m, c->iv[0], c->dv[0], c->dv[1]);
  case F_CLEAR_LOADS: return tfem_clear_loads(m);
  case F_SOLVE: return tfem_solve(m, &info);
  case F_ADD_CONTACT_PAIR: return tfem_add_contact_pair(m, c->iv[0], c->iv[1], NULL);
  case F_ADD_CONTACT_PAIR_WITH_MESH: return tfem_add_contact_pair_with_mesh(m, c->iv[0], c->iv[1], c->iv[2], in[0], NULL, NULL);
  case F_SOLVE_CONTACT: return tfem_solve_contact(m, op, &rep);
  case F_SET_THREADS: return tfem_set_threads(m, c->iv[0]);
  case F_STEP: return tfem_step(m, c->dv[2], op, &rep);
  case F_REVERT_STEP: return tfem_revert_step(m);
  case F_SET_CONTACT_STATE: return tfem_set_contact_state(m, in[0], c->in[0].n > 0 ? (size_t)c->in[0].n : 0);
  case F_SET_FRICTION: return tfem_set_friction(m, c->iv[0], v0);
  case F_SET_PRESCRIBED: return tfem_set_prescribed(m, c->iv[0], c->iv[1], v0);
  case F_SET_CONTACT_WEIGHTING: return tfem_set_contact_weighting(m, c->iv[0]);
  case F_SET_BOUNDARY_CIRCLE: return tfem_set_boundary_circle(m, c->iv[0], c->dv[0], c->dv[1], c->dv[2]);
  case F_ADD_CONTACT_PAIRS_AUTO:
    if (apply && c->tw == 3) return tfem_add_contact_pair(m, c->tw_a, c->tw_b, NULL);
    return tfem_add_contact_pairs_auto(m, c->iv[0], in[0], v0, NULL, NULL);
  case F_RECREATE:
    tfem_destroy(m);
    *mp = tfem_create();
    return *mp ? TFEM_STATUS_OK : TFEM_STATUS_OUT_OF_MEMORY;
  default: return TFEM_STATUS_OK;
  }
}

/* The twin-model oracle of a pristine scene (F_TWIN, mode c->iv[0]): the
 * calls before it that succeeded, run on a fresh model with the changes of
 * call_t.tw, give the same displacements (and contact pressures and active
 * flags), bit for bit for mu = 0 never set (0) and the pair declared
 * instead of found (1), within 1e-9 for the DOFs fixed at the values
 * tfem_set_prescribed gave them (2); mode 3, a load step's contact state
 * restored in a fresh model: oracle_twin_restart; mode 4, the automatic
 * weighting (the default, never set in the case) against a twin given the
 * weighting the shadow says it chose for every pair (sh_families: the
 * strip on the straight blocks, the mortar weighting on the curved
 * non-matching ones), bit for bit, the report and the slave nodes too
 * (the same discretisation: src/contact/discretisation.rs). */
static void oracle_twin_restart(runner_t *R, int idx);
static void oracle_twin(runner_t *R, int idx, const call_t *tc) {
  shadow_t *s = &R->sh;
  int mode = tc->iv[0];
  if (mode == 3) {
    oracle_twin_restart(R, idx);
    return;
  }
  if (!s->exact || !s->results || s->res_unknown || s->results == 3 || s->npairs > 64) return;
  int forced = -1; /* (mode 4: the weighting the twin is given) */
  if (mode == 4) {
    if (s->results != 2 || s->weighting != TFEM_CONTACT_WEIGHTING_AUTO ||
        (s->res_fam != FAM_STRIP && s->res_fam != FAM_MORTAR))
      return;
    forced = s->res_fam == FAM_STRIP ? TFEM_CONTACT_WEIGHTING_STRIP : TFEM_CONTACT_WEIGHTING_MORTAR;
  }
  for (int k = 0; k < idx; ++k) {
    const call_t *c = &R->cs->c[k];
    int ok = c->ran && c->status == TFEM_STATUS_OK;
    if (ok && (c->fn == F_STEP || c->fn == F_REVERT_STEP || c->fn == F_SET_CONTACT_STATE)) return;
    if (mode == 4 && ok && (c->fn == F_SET_CONTACT_WEIGHTING || c->fn == F_RECREATE)) return;
    if (mode != 4 && (c->tw == 2 || c->tw == 3 || c->tw == 4) && !ok) return;
    if (mode != 4 && c->tw == 3 && c->got != 1) return;
  }
  if (mode == 0)
    for (int k = 0; k < s->npairs; ++k)
      if (s->pair_mu[k] != 0.0) return;
  size_t nu = 2 * (size_t)s->nn;
  double *u1 = xmalloc(sizeof(double) * nu + 1), *u2 = xmalloc(sizeof(double) * nu + 1);
  if (tfem_get_displacements(R->m, u1, nu) != TFEM_STATUS_OK) {
    free(u1), free(u2);
    return;
  }
  tfem_model *t = tfem_create();
  int bad = -1, bst = 0;
  if (t && forced >= 0 && (bst = tfem_set_contact_weighting(t, forced)) != TFEM_STATUS_OK) bad = idx;
  for (int k = 0; k < idx && t && bad < 0; ++k) {
    const call_t *c = &R->cs->c[k];
    if (!c->ran || c->status != TFEM_STATUS_OK || c->null_model || (c->tw == 1 && mode != 4)) continue;
    int st = twin_exec(&t, c, mode != 4);
    if (st != TFEM_STATUS_OK && bad < 0) bad = k, bst = st;
  }
  char msg[300] = "";
  double rtol = mode == 2 || mode == 5 ? 1e-9 : -1;
  if (!t) {
    finding(R, V_OTHER, idx, "tfem_create() returned NULL (twin)");
  } else if (bad >= 0) {
    tfem_last_error(t, msg, sizeof msg);
    finding(R, V_TWIN, idx, "the twin model's call #%d %s: %s (OK here): \"%s\"", bad,
            bad == idx ? "tfem_set_contact_weighting" : fn_name(R->cs->c[bad].fn), status_name(bst), msg);
  } else {
    int st = tfem_get_displacements(t, u2, nu);
    long k = st == TFEM_STATUS_OK ? same_values((long)nu, u1, u2, rtol) : -1;
    R->oracles[O_TWIN]++;
    if (st != TFEM_STATUS_OK) {
      tfem_last_error(t, msg, sizeof msg);
      finding(R, V_TWIN, idx, "the twin model's displacements: %s \"%s\"", status_name(st), msg);
    } else if (k >= 0) {
      finding(R, V_TWIN, idx, "mode %d: u[%ld] = %.17g, the twin's %.17g (%s)", mode, k, u1[k], u2[k],
              mode == 0 ? "mu = 0 set against never set" : mode == 1 ? "pair found against pair declared"
              : mode == 2 ? "tfem_set_prescribed against fixed at that value"
              : mode == 5 ? "the interface cut into two pairs against one pair"
              : forced ? "the automatic weighting against the mortar weighting forced"
                       : "the automatic weighting against the strip forced");
    } else {
      if (R->verbose) {
        double dmax = 0, umax = 0;
        for (size_t i = 0; i < nu; ++i) {
          if (fabs(u1[i] - u2[i]) > dmax) dmax = fabs(u1[i] - u2[i]);
          if (fabs(u1[i]) > umax) umax = fabs(u1[i]);
        }
        printf("       twin (mode %d): %zu displacements, max |difference| %.3g of max |u| %.3g%s\n", mode, nu, dmax, umax,
               memcmp(u1, u2, sizeof(double) * nu) ? "" : " (bit for bit)");
      }
    }
    if (t && bad < 0 && s->results == 2 && mode == 5 && s->res_fam == FAM_STRIP && !tc->iv[1]) {
      /* (the strip's reading near a pair's end where the nodes do not
       * match: a node takes the other side's reading interpolated, and at
       * the cut that side's reading is of its pair's half tributary: 4e-4
       * of the pressure off the uncut reading at the nodes next to the
       * cut, seen; the header promises exactness for a uniform pressure
       * only. The displacements are checked above.) */
    } else if (t && bad < 0 && s->results == 2 && mode == 5) {
      /* the nodal pressures of the whole interface: those of one pair
       * (the header: a node on several pairs reads "the pressure where
       * two pairs continue one face"; under the mortar weighting one
       * weighted gap at the shared slave node) */
      double *p1 = xmalloc(sizeof(double) * (size_t)s->nn + 1), *p2 = xmalloc(sizeof(double) * (size_t)s->nn + 1);
      int s1 = tfem_get_contact_nodal_pressures(R->m, p1, (size_t)s->nn),
          s2 = tfem_get_contact_nodal_pressures(t, p2, (size_t)s->nn);
      long kp = s1 == TFEM_STATUS_OK && s2 == TFEM_STATUS_OK ? same_values(s->nn, p1, p2, 1e-9) : -1;
      R->oracles[O_TWIN] += s1 == TFEM_STATUS_OK && s2 == TFEM_STATUS_OK;
      if (s1 != s2)
        finding(R, V_TWIN, idx, "mode 5: nodal pressures %s, the twin's (one pair) %s", status_name(s1), status_name(s2));
      else if (kp >= 0)
        finding(R, V_TWIN, idx, "mode 5: nodal pressure at node %ld = %.17g with the interface cut into two pairs (%s), "
                "%.17g as one pair", kp + s->base, p1[kp], fam_name(s->res_fam), p2[kp]);
      for (int v = 0; v < s->nn && R->verbose && kp >= 0; ++v)
        if (p1[v] != p2[v])
          printf("       node %d (%.6g, %.6g): %.17g cut, %.17g one pair\n", v + s->base, s->xy[2 * v], s->xy[2 * v + 1],
                 p1[v], p2[v]);
      free(p1), free(p2);
    } else if (t && bad < 0 && s->results == 2) {
      int nn, nt, nc, nn2, nt2, nc2;
      if (tfem_get_sizes(R->m, &nn, &nt, &nc) == TFEM_STATUS_OK && tfem_get_sizes(t, &nn2, &nt2, &nc2) == TFEM_STATUS_OK) {
        if (nc != nc2) {
          finding(R, V_TWIN, idx, "mode %d: %d contact elements, the twin %d", mode, nc, nc2);
        } else if (nc > 0) {
          double *p1 = xmalloc(sizeof(double) * (size_t)nc), *p2 = xmalloc(sizeof(double) * (size_t)nc);
          int *a1 = xmalloc(sizeof(int) * (size_t)nc), *a2 = xmalloc(sizeof(int) * (size_t)nc);
          if (tfem_get_contact_pressure(R->m, p1, (size_t)nc) == TFEM_STATUS_OK &&
              tfem_get_contact_pressure(t, p2, (size_t)nc) == TFEM_STATUS_OK &&
              tfem_get_contact_active(R->m, a1, (size_t)nc) == TFEM_STATUS_OK &&
              tfem_get_contact_active(t, a2, (size_t)nc) == TFEM_STATUS_OK) {
            long kp = same_values(nc, p1, p2, rtol);
            if (kp >= 0) finding(R, V_TWIN, idx, "mode %d: contact pressure %ld = %.17g, the twin's %.17g", mode, kp, p1[kp], p2[kp]);
            else if (memcmp(a1, a2, sizeof(int) * (size_t)nc) != 0) finding(R, V_TWIN, idx, "mode %d: active flags differ from the twin's", mode);
          }
          free(p1), free(p2), free(a1), free(a2);
        }
      }
      tfem_contact_report r1, r2;
      if (mode == 4 && tfem_get_contact_report(R->m, &r1) == TFEM_STATUS_OK &&
          tfem_get_contact_report(t, &r2) == TFEM_STATUS_OK &&
          (r1.elements != r2.elements || r1.active != r2.active || memcmp(&r1.contact_length, &r2.contact_length, 8) ||
           memcmp(&r1.max_penetration, &r2.max_penetration, 8)))
        finding(R, V_TWIN, idx, "mode 4: report (active %d of %d, length %.17g, penetration %.17g), the twin's (%d of %d, "
                "%.17g, %.17g)", r1.active, r1.elements, r1.contact_length, r1.max_penetration, r2.active, r2.elements,
                r2.contact_length, r2.max_penetration);
      else if (mode == 4 && forced == TFEM_CONTACT_WEIGHTING_MORTAR && tfem_get_contact_report(R->m, &r1) == TFEM_STATUS_OK &&
               r1.elements > 0) {
        size_t n = (size_t)r1.elements;
        int *n1 = xmalloc(sizeof(int) * n), *n2 = xmalloc(sizeof(int) * n);
        double *c1 = xmalloc(sizeof(double) * 3 * n), *c2 = xmalloc(sizeof(double) * 3 * n);
        int s1 = tfem_get_contact_slave_nodes(R->m, n1, c1, c1 + n, c1 + 2 * n, n);
        int s2 = tfem_get_contact_slave_nodes(t, n2, c2, c2 + n, c2 + 2 * n, n);
        if (s1 != s2 || (s1 == TFEM_STATUS_OK && (memcmp(n1, n2, sizeof(int) * n) || memcmp(c1, c2, sizeof(double) * 3 * n))))
          finding(R, V_TWIN, idx, "mode 4: slave nodes (%s) differ from the twin's (%s)", status_name(s1), status_name(s2));
        free(n1), free(n2), free(c1), free(c2);
      }
      R->oracles[O_TWIN] += mode == 4;
    }
  }
  tfem_destroy(t);
  free(u1), free(u2);
}

/* The restart twin (F_TWIN mode 3, a pristine load-step scene): the
 * contact state read (tfem_get_contact_state) before the last load step,
 * given to a fresh model that holds the same problem (the calls before
 * that step that succeeded, without the solves, steps, reverts and states
 * set), makes that model's first step at the same factor and options the
 * original's step, bit for bit: its report and displacements (the
 * header: tfem_set_contact_state "continues the history bit for bit (a
 * restart, in this model or another one holding the same problem)"; under
 * the mortar weighting, from the slave nodes' set, since 56d2e1d). Only
 * getters may come between the state read and the step, and between the
 * step and the oracle. */
static void oracle_twin_restart(runner_t *R, int idx) {
  shadow_t *s = &R->sh;
  const call_t *cs = R->cs->c;
  if (!s->exact || s->results != 3 || s->res_unknown) return;
  int k_step = idx - 1;
  while (k_step >= 0 && reads_only(cs[k_step].fn)) --k_step;
  if (k_step < 0 || cs[k_step].fn != F_STEP || !cs[k_step].ran || cs[k_step].status != TFEM_STATUS_OK ||
      cs[k_step].null_model)
    return;
  int k_state = k_step - 1;
  while (k_state >= 0 && reads_only(cs[k_state].fn) && cs[k_state].fn != F_GET_CONTACT_STATE) --k_state;
  if (k_state < 0 || cs[k_state].fn != F_GET_CONTACT_STATE || cs[k_state].status != TFEM_STATUS_OK ||
      !out_full(&cs[k_state], 0) || !cs[k_state].saved[0] || cs[k_state].saved_n[0] < (size_t)cs[k_state].out[0].req)
    return;
  const call_t *sc = &cs[k_step];
  const unsigned char *bytes = cs[k_state].saved[0];
  size_t nbytes = (size_t)cs[k_state].out[0].req;
  size_t nu = 2 * (size_t)s->nn;
  double *u1 = xmalloc(sizeof(double) * nu + 1), *u2 = xmalloc(sizeof(double) * nu + 1);
  if (tfem_get_displacements(R->m, u1, nu) != TFEM_STATUS_OK) {
    free(u1), free(u2);
    return;
  }
  tfem_model *t = tfem_create();
  int bad = -1, bst = 0;
  for (int k = 0; k < k_state && t; ++k) {
    const call_t *c = &cs[k];
    if (!c->ran || c->status != TFEM_STATUS_OK || c->null_model || c->fn == F_STEP || c->fn == F_REVERT_STEP ||
        c->fn == F_SET_CONTACT_STATE || c->fn == F_SOLVE || c->fn == F_SOLVE_CONTACT)
      continue;
    int st = twin_exec(&t, c, 1);
    if (st != TFEM_STATUS_OK && bad < 0) bad = k, bst = st;
  }
  char msg[300] = "";
  if (!t) {
    finding(R, V_OTHER, idx, "tfem_create() returned NULL (twin)");
  } else if (bad >= 0) {
    tfem_last_error(t, msg, sizeof msg);
    finding(R, V_TWIN, idx, "the restart twin's call #%d %s: %s (OK here): \"%s\"", bad, fn_name(cs[bad].fn),
            status_name(bst), msg);
  } else {
    tfem_contact_options opts = {sc->iv[0], sc->dv[0], sc->dv[1], sc->iv[1], sc->iv[2], sc->iv[3]};
    tfem_contact_report rep;
    int st = tfem_set_contact_state(t, bytes, nbytes), step = -1;
    if (st == TFEM_STATUS_OK) step = (int)tfem_step(t, sc->dv[2], sc->in[0].null_ ? NULL : &opts, &rep);
    int sd = step == TFEM_STATUS_OK ? (int)tfem_get_displacements(t, u2, nu) : -1;
    R->oracles[O_RESTART]++;
    if (st != TFEM_STATUS_OK || step != TFEM_STATUS_OK || sd != TFEM_STATUS_OK) {
      tfem_last_error(t, msg, sizeof msg);
      finding(R, V_TWIN, idx, "restart (%s weighting): the state of call #%d set in a fresh model: %s, its step at %g "
              "(call #%d): %s, displacements %s: \"%s\"", s->weighting ? "mortar" : "strip", k_state, status_name(st),
              sc->dv[2], k_step, step < 0 ? "-" : status_name(step), sd < 0 ? "-" : status_name(sd), msg);
    } else {
      long k = same_values((long)nu, u1, u2, -1);
      tfem_contact_report a;
      int have_rep = !sc->out[0].null_ && sc->saved[0] && sc->saved_n[0] == sizeof a;
      if (have_rep) memcpy(&a, sc->saved[0], sizeof a);
      if (k >= 0)
        finding(R, V_TWIN, idx, "restart (%s weighting): u[%ld] = %.17g after the step of call #%d, %.17g in a fresh "
                "model given the state of call #%d", s->weighting ? "mortar" : "strip", k, u1[k], k_step, u2[k], k_state);
      else if (have_rep && (a.iterations != rep.iterations || a.elements != rep.elements || a.active != rep.active ||
                            memcmp(&a.contact_length, &rep.contact_length, 8) ||
                            memcmp(&a.max_penetration, &rep.max_penetration, 8)))
        finding(R, V_TWIN, idx, "restart (%s weighting): report (iterations %d, active %d of %d, length %.17g, "
                "penetration %.17g) in a fresh model given the state of call #%d, (%d, %d of %d, %.17g, %.17g) at call #%d",
                s->weighting ? "mortar" : "strip", rep.iterations, rep.active, rep.elements, rep.contact_length,
                rep.max_penetration, k_state, a.iterations, a.active, a.elements, a.contact_length, a.max_penetration,
                k_step);
      else if (R->verbose)
        printf("       twin (restart): %zu displacements bit for bit after the state of call #%d and the step of "
               "call #%d\n", nu, k_state, k_step);
    }
  }
  tfem_destroy(t);
  free(u1), free(u2);
}

/* ---- the contact context (a second handle) and load steps ---- */

/* Sizes of the context's contact mesh B, once a call that builds it
 * succeeded (asking earlier would build it: a change the replay, which
 * makes no such call, would not see). */
static int ctx_sizes(runner_t *R, int *nn, int *ne, int64_t *np) {
  int a = -1, b = -1;
  int64_t e = -1;
  if (!R->ctx || !R->cbuilt || tfem_contact_sizes(R->ctx, &a, &b, &e) != TFEM_STATUS_OK || a < 0 || b < 0 || e < 0)
    return 0;
  if (nn) *nn = a;
  if (ne) *ne = b;
  if (np) *np = e;
  return 1;
}

/* The elements of B (3 host nodes each), their equations (6 each) and
 * active flags; NULL if unknown. */
typedef struct {
  int ne, nn;
  int64_t np;
  int *elem, *active, *nodes;
  int64_t *eq;
} ctx_view;
static void cv_free(ctx_view *v) {
  free(v->elem), free(v->active), free(v->eq), free(v->nodes);
  memset(v, 0, sizeof *v);
}
static int ctx_view_get(runner_t *R, ctx_view *v) {
  memset(v, 0, sizeof *v);
  if (!ctx_sizes(R, &v->nn, &v->ne, &v->np)) return 0;
  v->elem = xmalloc(sizeof(int) * 3 * (size_t)v->ne + 1);
  v->active = xmalloc(sizeof(int) * (size_t)v->ne + 1);
  v->nodes = xmalloc(sizeof(int) * (size_t)v->nn + 1);
  v->eq = xmalloc(sizeof(int64_t) * 6 * (size_t)v->ne + 1);
  if (tfem_contact_elements(R->ctx, v->elem, 3 * (size_t)v->ne) != TFEM_STATUS_OK ||
      tfem_contact_get_active(R->ctx, v->active, (size_t)v->ne) != TFEM_STATUS_OK ||
      tfem_contact_nodes(R->ctx, v->nodes, (size_t)v->nn) != TFEM_STATUS_OK ||
      tfem_contact_element_equations(R->ctx, v->eq, 6 * (size_t)v->ne) != TFEM_STATUS_OK) {
    cv_free(v);
    return 0;
  }
  return 1;
}
/* The equation (0-based, -1 none, -2 unknown) of DOF comp of interface node i. */
static int64_t cv_eq(const ctx_view *v, int i, int comp, int base) {
  for (int k = 0; k < v->ne; ++k)
    for (int a = 0; a < 3; ++a)
      if (v->elem[3 * k + a] == v->nodes[i]) {
        int64_t e = v->eq[6 * k + 2 * a + comp];
        return e < base ? -1 : e - base;
      }
  return -2;
}

static void rt_fill(rng_t *q, double *u, int n, int recipe, const double *model_u, int k) {
  for (int i = 0; i < n; ++i) {
    switch (recipe) {
    case 1: u[i] = (runif(q) - 0.5) * 2e-3; break;
    case 2: u[i] = model_u ? model_u[i] : 0.0; break;
    case 3: u[i] = (runif(q) - 0.5) * 2e-3; break;
    case 4: u[i] = (runif(q) - 0.5) * 2e150; break;
    default: u[i] = 0.0; break;
    }
  }
  if (recipe == 3 && n > 0) u[k % n] = (double[]){NAN, INFINITY, -INFINITY, 1e308, -DBL_MAX}[k % 5];
}

/* Makes the runtime inputs of call c (once: the replay passes the same
 * bytes) from its recipe: the int arguments recipe, length offset, seed. */
static void make_inputs(runner_t *R, call_t *c, int idx) {
  int fn = c->fn;
  if (c->in_made) return;
  c->in_made = 1;
  int rec = c->iv[0], dl = c->iv[1], k = c->iv[2] < 0 ? -(c->iv[2] + 1) : c->iv[2];
  if (dl < -100000 || dl > 100000) dl = dl < 0 ? -100000 : 100000;
  rng_t q = {mix64(0x5eedULL + (uint64_t)k * 7919u + (uint64_t)idx)};
  int cn = -1, ce = -1;
  ctx_sizes(R, &cn, &ce, NULL);
  /* the model's displacements, when the case couples the two (host equation = model DOF) */
  int mnn = -1, mnt, mnc;
  double *mu = NULL;
  if (R->cs->coupled && R->m && tfem_get_sizes(R->m, &mnn, &mnt, &mnc) == TFEM_STATUS_OK && mnn > 0) {
    mu = xmalloc(sizeof(double) * 2 * (size_t)mnn);
    if (tfem_get_displacements(R->m, mu, 2 * (size_t)mnn) != TFEM_STATUS_OK) free(mu), mu = NULL;
  }
  for (int j = 0; j < fn_nin(fn); ++j) {
    if (!in_runtime(fn, j)) continue;
    char role = FN[fn].ink[j];
    if (role == 'U') {
      long base;
      double *src = NULL;
      if (fn == F_CONTACT_GATHER) {
        base = R->cs->coupled ? R->cs->neq : 2 + k % 20;
        if (mu && R->cs->neq == 2 * mnn) src = mu;
      } else if (fn == F_CONTACT_SCATTER_ADD && j == 1) {
        base = (long)c->out[0].len;
        dl = 0;
      } else {
        base = cn >= 0 ? 2L * cn : 2 + 2 * (k % 6);
        if (mu && cn >= 0 && R->cs->hm_mul > 0) {
          /* the model's displacements at the interface nodes */
          int *nodes = xmalloc(sizeof(int) * (size_t)cn + 1);
          src = xmalloc(sizeof(double) * 2 * (size_t)cn + 1);
          if (tfem_contact_nodes(R->ctx, nodes, (size_t)cn) == TFEM_STATUS_OK) {
            for (int i = 0; i < cn; ++i) {
              long v = ((long)nodes[i] - R->cs->hm_off) / R->cs->hm_mul;
              int ok = v >= 0 && v < mnn && v * R->cs->hm_mul + R->cs->hm_off == nodes[i];
              src[2 * i] = ok ? mu[2 * v] : 0.0;
              src[2 * i + 1] = ok ? mu[2 * v + 1] : 0.0;
            }
          } else {
            memset(src, 0, sizeof(double) * 2 * (size_t)cn);
          }
          free(nodes);
        }
      }
      long n = base + dl;
      if (n < 0) n = 0;
      if (n > 4000000) n = 4000000;
      double *u = xcalloc((size_t)n + 1, sizeof(double));
      long ns = src ? (fn == F_CONTACT_GATHER ? 2L * mnn : 2L * cn) : 0;
      double *full = xcalloc((size_t)(n > ns ? n : ns) + 1, sizeof(double));
      if (src) memcpy(full, src, sizeof(double) * (size_t)ns);
      rt_fill(&q, u, (int)n, fn == F_CONTACT_SCATTER_ADD && j == 1 ? (rec == 0 ? 0 : 1) : rec, full, k);
      in_set(c, j, u, (int)n, sizeof(double));
      free(u), free(full);
      if (src && src != mu) free(src);
    } else if (role == 'a') {
      long n = (ce >= 0 ? ce : 1 + k % 8) + dl;
      if (n < 0) n = 0;
      if (n > 4000000) n = 4000000;
      int *a = xcalloc((size_t)n + 1, sizeof(int));
      if (rec == 3 && ce >= 0) {
        int *cur = xcalloc((size_t)ce + 1, sizeof(int));
        if (tfem_contact_get_active(R->ctx, cur, (size_t)ce) == TFEM_STATUS_OK)
          for (long i = 0; i < n && i < ce; ++i) a[i] = cur[i];
        free(cur);
      } else {
        for (long i = 0; i < n; ++i) a[i] = rec == 1 ? 1 : (rec == 2 || rec == 4) ? (int)(rnext(&q) & 1) : 0;
        if (rec == 4 && n > 0) a[k % n] = (int[]){2, -1, INT_MIN, INT_MAX}[k % 4];
      }
      in_set(c, j, a, (int)n, sizeof(int));
      free(a);
    } else if (role == 's') {
      /* 0 the state saved last, 1 the one before, 2 the last with a byte
       * changed, 3 bytes that are no state, 4 none, 5 the last cut short */
      const unsigned char *src = rec == 1 ? R->st_prev : R->st_last;
      size_t sn = rec == 1 ? R->n_prev : R->n_last;
      unsigned char *b;
      long n;
      if (rec == 4) {
        n = 0;
        b = xmalloc(1);
      } else if (!src || rec == 3 || rec < 0 || rec > 5) {
        n = k % 300;
        b = xmalloc((size_t)n + 1);
        for (long i = 0; i < n; ++i) b[i] = (unsigned char)rnext(&q);
      } else {
        n = (long)sn + (rec == 5 ? -(long)sn / 2 - 1 : dl);
        if (n < 0) n = 0;
        b = xcalloc((size_t)n + 1, 1);
        memcpy(b, src, (size_t)n < sn ? (size_t)n : sn);
        if (rec == 2 && n > 0) b[k % n] ^= (unsigned char)(1u << (k % 8));
      }
      in_set(c, j, b, (int)n, 1);
      free(b);
    }
  }
  free(mu);
}

/* Value oracles of the contact context (each from the library's own
 * outputs: the element equations, blocks and flags). */
static void oracle_host(runner_t *R, int idx, const call_t *c, gbuf *g) {
  int fn = c->fn;
  ctx_view v;
  if (!ctx_view_get(R, &v)) return;
  int base = R->cbase;
  if (fn == F_CONTACT_PATTERN || fn == F_CONTACT_EVALUATE) {
    /* the pattern: element after element, its DOFs with an equation, row by row */
    const int64_t *rows = fn == F_CONTACT_PATTERN ? (const int64_t *)(const void *)g[0].p : NULL;
    const int64_t *cols = fn == F_CONTACT_PATTERN ? (const int64_t *)(const void *)g[1].p : NULL;
    const double *val = fn == F_CONTACT_EVALUATE && !c->out[0].null_ ? (const double *)(const void *)g[0].p : NULL;
    size_t cap = fn == F_CONTACT_PATTERN ? c->out[0].len : c->out[0].len;
    double *blk = NULL;
    if (val) {
      blk = xmalloc(sizeof(double) * 36 * (size_t)v.ne + 1);
      if (tfem_contact_element_blocks(R->ctx, blk, 36 * (size_t)v.ne) != TFEM_STATUS_OK) {
        free(blk);
        cv_free(&v);
        return;
      }
    }
    int64_t p = 0;
    int bad = 0;
    for (int k = 0; k < v.ne && !bad; ++k)
      for (int a = 0; a < 6 && !bad; ++a) {
        if (v.eq[6 * k + a] < base) continue;
        for (int b = 0; b < 6 && !bad; ++b) {
          if (v.eq[6 * k + b] < base) continue;
          if ((size_t)p < cap) {
            if (rows && (rows[p] != v.eq[6 * k + a] || cols[p] != v.eq[6 * k + b])) {
              finding(R, V_HOST, idx, "pattern entry %" PRId64 " = (%" PRId64 ", %" PRId64 "), element %d's DOFs %d, %d have "
                      "equations %" PRId64 ", %" PRId64, p, rows[p], cols[p], k, a, b, v.eq[6 * k + a], v.eq[6 * k + b]);
              bad = 1;
            }
            if (val && val[p] != blk[36 * k + 6 * a + b] && !(val[p] == 0 && blk[36 * k + 6 * a + b] == 0)) {
              finding(R, V_HOST, idx, "value %" PRId64 " = %.17g, element %d's block (%d, %d) = %.17g (active %d)", p, val[p], k,
                      a, b, blk[36 * k + 6 * a + b], v.active[k]);
              bad = 1;
            }
          }
          ++p;
        }
      }
    if (!bad && p != v.np) finding(R, V_HOST, idx, "%" PRId64 " pattern entries from the element equations, sizes says %" PRId64, p, v.np);
    R->oracles[O_HOST_PATTERN]++;
    free(blk);
  } else if (fn == F_CONTACT_GATHER || fn == F_CONTACT_SCATTER_ADD) {
    /* gather: u of a DOF = its equation's entry (0 without one); scatter:
     * the host vector's entry += the residual of each DOF with that equation */
    const double *in = c->in[0].p;
    size_t neq = fn == F_CONTACT_GATHER ? (size_t)c->in[0].n : c->out[0].len;
    const double *out = (const double *)(const void *)g[0].p, *before = c->in[1].p;
    double *expect = NULL;
    if (fn == F_CONTACT_SCATTER_ADD) {
      expect = xmalloc(sizeof(double) * neq + 1);
      memcpy(expect, before, sizeof(double) * neq);
    }
    int bad = 0, unknown = 0;
    for (int i = 0; i < v.nn && !bad; ++i)
      for (int comp = 0; comp < 2 && !bad; ++comp) {
        int64_t e = cv_eq(&v, i, comp, base);
        if (e == -2) { /* a node on no element of B: its equation is not known here */
          unknown = 1;
          continue;
        }
        if (e >= (int64_t)neq) {
          finding(R, V_HOST, idx, "OK with equation %" PRId64 " of node %d beyond the %zu given", e + base, v.nodes[i], neq);
          bad = 1;
        } else if (fn == F_CONTACT_GATHER) {
          double want = e < 0 ? 0.0 : in[e];
          if (memcmp(&want, &out[2 * i + comp], 8) != 0 && !(want == 0 && out[2 * i + comp] == 0)) {
            finding(R, V_HOST, idx, "u[%d] of node %d = %.17g, its equation %" PRId64 " holds %.17g", 2 * i + comp, v.nodes[i],
                    out[2 * i + comp], e + base, want);
            bad = 1;
          }
        } else if (e >= 0) {
          expect[e] += in[2 * i + comp];
        }
      }
    if (fn == F_CONTACT_SCATTER_ADD && !unknown)
      for (size_t e = 0; e < neq && !bad; ++e)
        if (!(out[e] == expect[e] || fabs(out[e] - expect[e]) <= 1e-13 * fabs(expect[e]) ||
              (isnan(out[e]) && isnan(expect[e])))) {
          finding(R, V_HOST, idx, "host vector entry %zu = %.17g, expected %.17g", e, out[e], expect[e]);
          bad = 1;
        }
    free(expect);
    R->oracles[O_HOST_GATHER]++;
  } else if (fn == F_CONTACT_SET_ACTIVE) {
    const int *a = c->in[0].p;
    for (int k = 0; k < v.ne; ++k)
      if (v.active[k] != a[k]) {
        finding(R, V_HOST, idx, "element %d set to %d, tfem_contact_get_active gives %d", k, a[k], v.active[k]);
        break;
      }
    R->oracles[O_HOST_ACTIVE]++;
  } else if (fn == F_CONTACT_PRESSURES) {
    const double *pr = (const double *)(const void *)g[0].p;
    for (int k = 0; k < v.ne; ++k)
      if (!v.active[k] && pr[k] != 0) {
        finding(R, V_HOST, idx, "pressure %.17g of inactive element %d", pr[k], k);
        break;
      }
    R->oracles[O_HOST_ACTIVE]++;
  } else if (fn == F_CONTACT_LENGTH) {
    double L;
    memcpy(&L, g[0].p, 8);
    int na = 0;
    for (int k = 0; k < v.ne; ++k) na += v.active[k];
    if (L < 0 || (na == 0 && L != 0)) finding(R, V_HOST, idx, "contact length %.17g with %d active elements", L, na);
  }
  cv_free(&v);
}

/* ------------------------------------------------------------------------ */
/* Axisymmetric bodies, out-of-plane stresses, the adaptive solve           */
/* ------------------------------------------------------------------------ */

/* The material the shadow holds for a body (-1: none known). */
static int sh_material(const shadow_t *s, int body) {
  for (int k = 0; k < s->nmat; ++k)
    if (s->mat_body[k] == body) return k;
  return -1;
}

/* The axis of an axisymmetric model (src/model/problem.rs check_axis): a
 * node of a triangle across it (x < 0) or on it (x = 0) with u_r not
 * prescribed to 0 makes a solve refuse. With margins of a hundred times the
 * library's 1e-12 of the mesh's size either way, so that only a node
 * clearly across or clearly on the axis counts. For one body (body !=
 * INT_MIN: what tfem_set_material refuses) only its nodes across the axis
 * that no other body's triangle uses (the library names a node's body by
 * one of its triangles: a node a plane body shares is left to the solve).
 * Returns the node (0-based) and says why, or -1 (none, or the mesh not
 * known here). */
static int sh_axis_violation(const shadow_t *s, int body, char *why, size_t cap) {
  if (!s->exact || s->nn <= 0) return -1;
  double lo[2] = {INFINITY, INFINITY}, hi[2] = {-INFINITY, -INFINITY};
  for (int v = 0; v < s->nn; ++v)
    for (int k = 0; k < 2; ++k) lo[k] = fmin(lo[k], s->xy[2 * v + k]), hi[k] = fmax(hi[k], s->xy[2 * v + k]);
  double size = fmax(hi[0] - lo[0], hi[1] - lo[1]);
  if (!(isfinite(size) && size > 0)) return -1;
  for (int t = 0; t < s->nt; ++t) {
    if (body != INT_MIN && s->body[t] != body) continue;
    for (int k = 0; k < 3; ++k) {
      int v = s->tri[3 * t + k];
      double x = s->xy[2 * v];
      int shared = 0;
      for (int u = 0; u < s->nt && body != INT_MIN && x < -1e-10 * size && !shared; ++u)
        shared = s->body[u] != body && (s->tri[3 * u] == v || s->tri[3 * u + 1] == v || s->tri[3 * u + 2] == v);
      if (x < -1e-10 * size && !shared) {
        snprintf(why, cap, "node %d (body %d) has x = %g < 0", v + s->base, s->body[t], x);
        return v;
      }
      if (body == INT_MIN && fabs(x) <= 1e-14 * size && s->presc[2 * v] != 0.0) {
        snprintf(why, cap, "node %d lies on the axis (x = %g) with u_r %s", v + s->base, x,
                 isnan(s->presc[2 * v]) ? "free" : "prescribed to a value other than 0");
        return v;
      }
    }
  }
  return -1;
}

/* tfem_set_material against the shadow's materials: an axisymmetric body
 * joining a plane one (or the reverse), crossing the axis, or under the
 * mortar weighting forced is refused (INVALID_MATERIAL). */
static void oracle_material(runner_t *R, int idx, const call_t *c, int st, const char *msg) {
  shadow_t *s = &R->sh;
  int body = c->iv[0], plane = c->iv[1], ring = plane == TFEM_PLANE_MODE_AXISYMMETRIC;
  if (plane < 0 || plane > 2) return;
  const char *why = NULL;
  char buf[200];
  for (int k = 0; k < s->nmat && !why; ++k)
    if (s->mat_body[k] != body && (s->mat_plane[k] == TFEM_PLANE_MODE_AXISYMMETRIC) != ring) {
      snprintf(buf, sizeof buf, "body %d is %s", s->mat_body[k], ring ? "plane" : "axisymmetric");
      why = buf;
    }
  if (!why && ring && s->weighting == TFEM_CONTACT_WEIGHTING_MORTAR) why = "the mortar weighting is forced";
  int inmesh = 1;
  if (s->exact) {
    inmesh = 0;
    for (int t = 0; t < s->nt && !inmesh; ++t) inmesh = s->body[t] == body;
  }
  if (!why && ring && inmesh && sh_axis_violation(s, body, buf, sizeof buf) >= 0) why = buf;
  if (!why || !inmesh) return;
  R->oracles[O_AXI]++;
  if (st == TFEM_STATUS_OK)
    finding(R, V_AXI, idx, "tfem_set_material(body %d, plane mode %d) is OK although %s", body, plane, why);
  else if (st != TFEM_STATUS_INVALID_MATERIAL && st != TFEM_STATUS_NULL_POINTER)
    finding(R, V_AXI, idx, "tfem_set_material(body %d, plane mode %d) refused with %s, not INVALID_MATERIAL (%s): "
            "\"%.160s\"", body, plane, status_name(st), why, msg);
}

/* tfem_get_element_out_of_plane_stresses against the strains and the
 * materials: 0 in plane stress, lambda (eps_xx + eps_yy) in plane strain
 * (the header); an axisymmetric body's hoop stress needs the hoop strain,
 * not read here (its pristine scene checks it against the closed form). */
static void oracle_out_of_plane(runner_t *R, int idx, const double *sz) {
  shadow_t *s = &R->sh;
  int nt = s->nt, checked = 0;
  if (!s->exact || nt <= 0) return;
  double *eps = xmalloc(sizeof(double) * 3 * (size_t)nt + 1);
  if (tfem_get_element_strains(R->m, eps, 3 * (size_t)nt) == TFEM_STATUS_OK) {
    for (int t = 0; t < nt; ++t) {
      int k = sh_material(s, s->body[t]);
      if (k < 0) break;
      double e = s->mat_young[k], nu = s->mat_nu[k], want, slack;
      if (s->mat_plane[k] == TFEM_PLANE_MODE_STRESS) {
        want = 0.0, slack = 0.0;
      } else if (s->mat_plane[k] == TFEM_PLANE_MODE_STRAIN) {
        double lam = e * nu / ((1.0 + nu) * (1.0 - 2.0 * nu));
        want = lam * (eps[3 * t] + eps[3 * t + 1]);
        slack = 1e-12 * fabs(lam) * (fabs(eps[3 * t]) + fabs(eps[3 * t + 1]));
      } else {
        continue;
      }
      if (!isfinite(want) || !isfinite(slack)) continue;
      checked = 1;
      if (!(fabs(sz[t] - want) <= slack)) {
        finding(R, V_AXI, idx, "triangle %d (body %d, plane mode %d, E %g, nu %g): out-of-plane stress %.17g, the strains "
                "%.6g %.6g give %.17g", t + s->base, s->body[t], s->mat_plane[k], e, nu, sz[t], eps[3 * t],
                eps[3 * t + 1], want);
        break;
      }
    }
  }
  R->oracles[O_OUT_OF_PLANE] += checked;
  free(eps);
}

/* tfem_element_stiffness (OK): symmetric, no force for a translation
 * along y (along the axis of a ring; also along x for a plane element),
 * and an axisymmetric element has no corner at x < 0 (the header). */
static void oracle_element_stiffness(runner_t *R, int idx, const call_t *c, const double *k) {
  const double *xy = c->in[0].null_ ? NULL : c->in[0].p;
  int ring = c->iv[0] == TFEM_PLANE_MODE_AXISYMMETRIC;
  if (!xy) return;
  if (ring)
    for (int v = 0; v < 3; ++v)
      if (xy[2 * v] < 0) {
        finding(R, V_AXI, idx, "OK for an axisymmetric element with corner %d at x = %g < 0", v + 1, xy[2 * v]);
        return;
      }
  double big = 0;
  for (int i = 0; i < 36; ++i) big = fmax(big, fabs(k[i]));
  if (!isfinite(big) || big < 1e-250 || big > 1e280) return;
  /* (round-off: of the largest entry's size, lambda's as nu -> 1/2, in every sum) */
  R->oracles[O_AXI] += ring;
  for (int i = 0; i < 6; ++i)
    for (int j = 0; j < i; ++j)
      if (fabs(k[6 * i + j] - k[6 * j + i]) > 1e-12 * big) {
        finding(R, ring ? V_AXI : V_OTHER, idx, "plane mode %d: K[%d][%d] = %.17g but K[%d][%d] = %.17g", c->iv[0], i, j,
                k[6 * i + j], j, i, k[6 * j + i]);
        return;
      }
  for (int d = ring ? 1 : 0; d < 2; ++d)
    for (int i = 0; i < 6; ++i) {
      double f = 0, m = 0;
      for (int v = 0; v < 3; ++v) f += k[6 * i + 2 * v + d], m += fabs(k[6 * i + 2 * v + d]);
      if (fabs(f) > 1e-12 * big + 1e-10 * m) {
        finding(R, ring ? V_AXI : V_OTHER, idx, "plane mode %d: a translation along %c gives force %.6g at DOF %d (row "
                "magnitude %.6g)", c->iv[0], d ? 'y' : 'x', f, i, m);
        return;
      }
    }
}

/* tfem_solve_adaptive against the header: a bad argument (goal not 0 or 1,
 * tolerance not finite and > 0, max_unknowns or max_cycles below 1) is
 * refused with INVALID_ARGUMENT (the replay checks that nothing changed);
 * OK: 1 to max_cycles solves, each read back (tfem_get_adapt_cycles: the
 * last one's unknowns and estimate the report's, unknowns growing, a
 * refined mesh's within max_unknowns, no cycle but the last meeting the
 * tolerance), reached exactly when the last estimate meets the tolerance,
 * else a warning saying so (with contact pairs the refinement also locates
 * the contact zones' edges to the tolerance, the header says: there a
 * cycle meeting it may be followed by another, and reached may be 0 with
 * the estimate met, never 1 without), the report's triangles the mesh's, the given
 * nodes kept where they were (tfem_get_mesh_nodes), the mesh unchanged
 * after one cycle. Called before the shadow takes the call. */
static void oracle_adapt(runner_t *R, int idx, const call_t *c, int st, const gbuf *g, const char *msg) {
  shadow_t *s = &R->sh;
  double tol = c->dv[2];
  int goal = c->iv[4], maxc = c->iv[5];
  int64_t maxu = adapt_max_unknowns(c->iv[6]);
  const char *bad = goal != TFEM_ADAPT_GOAL_ENERGY && goal != TFEM_ADAPT_GOAL_COMPLIANCE ? "goal"
                    : !(isfinite(tol) && tol > 0)                                         ? "tolerance"
                    : maxu < 1                                                            ? "max_unknowns"
                    : maxc < 1                                                            ? "max_cycles"
                                                                                          : NULL;
  if (bad) {
    R->oracles[O_ADAPT]++;
    if (st != TFEM_STATUS_INVALID_ARGUMENT)
      finding(R, V_ADAPT, idx, "%s with %s bad (tolerance %g, goal %d, max_unknowns %" PRId64 ", max_cycles %d), not "
              "INVALID_ARGUMENT: \"%.160s\"", status_name(st), bad, tol, goal, maxu, maxc, msg);
    return;
  }
  if (st != TFEM_STATUS_OK) return;
  R->oracles[O_ADAPT]++;
  tfem_adapt_report rep;
  int have = !c->out[0].null_;
  if (have) memcpy(&rep, g[0].p, sizeof rep);
  long n = probe_cycles(R->m);
  s->adapt_n = -1;
  if (n < 1 || n > maxc) {
    finding(R, V_ADAPT, idx, "tfem_get_adapt_cycles holds %ld cycle(s) after an adaptive solve of max_cycles %d", n, maxc);
    return;
  }
  if (have && rep.cycles != n) finding(R, V_ADAPT, idx, "report: %d cycles, tfem_get_adapt_cycles holds %ld", rep.cycles, n);
  if (c->expect > 0 && R->pristine && idx < R->full_prefix && n != c->expect)
    finding(R, V_ADAPT, idx, "%ld cycles, the scene expects %d (a uniform field: the estimate is round-off)", n, c->expect);
  int64_t *un = xmalloc(sizeof(int64_t) * (size_t)n);
  double *es = xmalloc(sizeof(double) * (size_t)n), *sec = xmalloc(sizeof(double) * (size_t)n);
  int gs = tfem_get_adapt_cycles(R->m, un, es, sec, (size_t)n);
  if (gs != TFEM_STATUS_OK) {
    finding(R, V_ADAPT, idx, "tfem_get_adapt_cycles of length %ld (the cycles it holds) gives %s", n, status_name(gs));
  } else {
    int contact = s->npairs != 0, reached = contact && have ? es[n - 1] <= tol && rep.reached : es[n - 1] <= tol;
    s->adapt_n = n;
    s->adapt_idx = idx;
    for (long k = 0; k < n && k < 64; ++k) s->adapt_unk[k] = un[k], s->adapt_est[k] = es[k];
    for (long k = 0; k < n; ++k) {
      if (!isfinite(es[k]) || es[k] < 0 || !isfinite(sec[k]) || sec[k] < 0 || un[k] < 1) {
        finding(R, isfinite(es[k]) && isfinite(sec[k]) ? V_ADAPT : V_NAN_OK, idx, "cycle %ld: %" PRId64
                " unknowns, estimate %g, %g s", k, un[k], es[k], sec[k]);
        break;
      }
      if (k > 0 && un[k] < un[k - 1]) {
        finding(R, V_ADAPT, idx, "cycle %ld has %" PRId64 " unknowns, cycle %ld had %" PRId64 " (a refined mesh has no fewer)",
                k, un[k], k - 1, un[k - 1]);
        break;
      }
      if (k > 0 && un[k] > maxu) {
        finding(R, V_ADAPT, idx, "cycle %ld solved a refined mesh of %" PRId64 " unknowns, beyond max_unknowns %" PRId64
                " (the header: the refinement stops when the next mesh would exceed it)", k, un[k], maxu);
        break;
      }
      if (k + 1 < n && es[k] <= tol && !contact) {
        finding(R, V_ADAPT, idx, "cycle %ld's estimate %g meets the tolerance %g, yet cycle %ld followed", k, es[k], tol,
                k + 1);
        break;
      }
    }
    if (have && (rep.unknowns != un[n - 1] || memcmp(&rep.estimate, &es[n - 1], sizeof(double)) != 0 ||
                 rep.reached != reached))
      finding(R, V_ADAPT, idx, "report: unknowns %" PRId64 ", estimate %.17g, reached %d; the last cycle: %" PRId64
              ", %.17g (tolerance %g)", rep.unknowns, rep.estimate, rep.reached, un[n - 1], es[n - 1], tol);
    if (!reached) { /* a limit stopped it: a warning says so */
      int count = 0, said = 0;
      char w[1024];
      if (tfem_warning_count(R->m, &count) == TFEM_STATUS_OK)
        for (int k = 0; k < count && !said; ++k)
          said = tfem_get_warning(R->m, k, w, sizeof w) == TFEM_STATUS_OK && strstr(w, "adaptive") != NULL;
      if (!said)
        finding(R, V_ADAPT, idx, "the tolerance %g is not met (estimate %g after %ld of %d cycles) and no warning of "
                "the %d says so", tol, es[n - 1], n, maxc, count);
    }
  }
  free(un), free(es), free(sec);
  int nn = -1, nt = -1;
  if (tfem_get_sizes(R->m, &nn, &nt, NULL) != TFEM_STATUS_OK) {
    finding(R, V_ADAPT, idx, "tfem_get_sizes refused after the adaptive solve");
    return;
  }
  if (have && rep.triangles != nt)
    finding(R, V_ADAPT, idx, "report: %" PRId64 " triangles, the model's mesh %d", rep.triangles, nt);
  if (s->exact) {
    if (nn < s->nn || nt < s->nt || (n == 1 && (nn != s->nn || nt != s->nt))) {
      finding(R, V_ADAPT, idx, "%ld cycle(s): the mesh went from %d nodes, %d triangles to %d, %d", n, s->nn, s->nt, nn,
              nt);
    } else {
      double *xy = xmalloc(sizeof(double) * 2 * (size_t)nn + 1);
      if (tfem_get_mesh_nodes(R->m, xy, 2 * (size_t)nn) == TFEM_STATUS_OK &&
          memcmp(xy, s->xy, sizeof(double) * 2 * (size_t)s->nn) != 0) {
        int v = 0;
        while (v < s->nn && !memcmp(&xy[2 * v], &s->xy[2 * v], 2 * sizeof(double))) ++v;
        finding(R, V_ADAPT, idx, "node %d moved from (%g, %g) to (%g, %g) (the header: the given nodes keep their indices)",
                v + s->base, s->xy[2 * v], s->xy[2 * v + 1], xy[2 * v], xy[2 * v + 1]);
      }
      free(xy);
    }
  }
}

/* tfem_get_adapt_cycles: INVALID_STATE before any adaptive solve,
 * BUFFER_TOO_SMALL below the cycles' count, else OK with the cycles of
 * the last adaptive solve, whatever came after it. */
static void oracle_adapt_cycles(runner_t *R, int idx, const call_t *c, int st, const gbuf *g, const char *msg) {
  shadow_t *s = &R->sh;
  long n = s->adapt_n;
  size_t L = c->out[0].len;
  int want = n == 0 ? TFEM_STATUS_INVALID_STATE : n < 0 ? -1 : L < (size_t)n ? TFEM_STATUS_BUFFER_TOO_SMALL : TFEM_STATUS_OK;
  if (want < 0) return;
  R->oracles[O_ADAPT]++;
  if (st != want && n > 0 && st == TFEM_STATUS_INVALID_STATE) {
    finding(R, V_ADAPT, idx, "INVALID_STATE: the %ld cycles of the adaptive solve of call #%d are gone (the calls since "
            "made no adaptive solve; %s expected): \"%.160s\"", n, s->adapt_idx, status_name(want), msg);
    return;
  }
  if (st != want) {
    finding(R, V_ADAPT, idx, "%s for length %zu (%ld cycles of an adaptive solve%s), %s expected: \"%.160s\"",
            status_name(st), L, n, n ? "" : ": none", status_name(want), msg);
    return;
  }
  if (st != TFEM_STATUS_OK) return;
  for (long k = 0; k < n && k < 64; ++k) {
    int64_t u = s->adapt_unk[k];
    double e = s->adapt_est[k];
    if ((!c->out[0].null_ && memcmp(g[0].p + sizeof(int64_t) * (size_t)k, &u, sizeof u)) ||
        (!c->out[1].null_ && memcmp(g[1].p + sizeof(double) * (size_t)k, &e, sizeof e))) {
      finding(R, V_ADAPT, idx, "cycle %ld differs from what the adaptive solve of call #%d left (%" PRId64 " unknowns, "
              "estimate %.17g)", k, s->adapt_idx, u, e);
      return;
    }
  }
}

/* tfem_set_boundary_circle against circle_expect: the status, the message
 * saying why, a node off the circle named as the one that is (in the
 * index base). Called before the shadow takes the call. */
static void oracle_circle(runner_t *R, int idx, const call_t *c, int st, const char *msg) {
  shadow_t *s = &R->sh;
  char why[96];
  unsigned char *off = s->exact && s->has_mesh ? xcalloc((size_t)s->nn + 1, 1) : NULL;
  int tag = c->iv[0], want = circle_expect(s, tag, c->dv[0], c->dv[1], c->dv[2], why, sizeof why, off);
  if (want < 0) {
    if (st != TFEM_STATUS_OK && st != TFEM_STATUS_INVALID_ARGUMENT)
      finding(R, V_CIRCLE, idx, "%s (not OK or INVALID_ARGUMENT) for the circle (%g, %g) of radius %g on tag %d: "
              "\"%.160s\"", status_name(st), c->dv[0], c->dv[1], c->dv[2], tag, msg);
    free(off);
    return;
  }
  R->oracles[O_CIRCLE]++;
  int v = INT_MIN, t = INT_MIN;
  if (st != want) {
    finding(R, V_CIRCLE, idx, "%s for the circle (%.17g, %.17g) of radius %.17g on tag %d, %s expected%s%s: \"%.160s\"",
            status_name(st), c->dv[0], c->dv[1], c->dv[2], tag, status_name(want), why[0] ? ": " : "", why, msg);
  } else if (st != TFEM_STATUS_OK && !strstr(msg, why)) {
    finding(R, V_CIRCLE, idx, "%s for the circle (%g, %g) of radius %g on tag %d without saying \"%s\": \"%.160s\"",
            status_name(st), c->dv[0], c->dv[1], c->dv[2], tag, why, msg);
  } else if (st != TFEM_STATUS_OK && off && strstr(why, "of an edge tagged")) {
    if (sscanf(msg, "node %d of an edge tagged %d", &v, &t) != 2 || t != tag)
      finding(R, V_CIRCLE, idx, "a node of tag %d is off the circle (%g, %g) of radius %g; the message does not name "
              "it as \"node N of an edge tagged %d\": \"%.160s\"", tag, c->dv[0], c->dv[1], c->dv[2], tag, msg);
    else if ((long)v - s->base < 0 || (long)v - s->base >= s->nn || !off[v - s->base])
      finding(R, V_CIRCLE, idx, "the message names node %d, which is not a node of tag %d off the circle (%g, %g) of "
              "radius %g (index base %d): \"%.160s\"", v, tag, c->dv[0], c->dv[1], c->dv[2], s->base, msg);
  }
  free(off);
}

/* After an adaptive solve that succeeded: every node of an edge tagged
 * with a declared circle whose edges all lay on it (clean) lies on it, the
 * nodes it added (numbered from the mesh's count before it, when known)
 * to round-off of the circle's numbers (1e-12 of |centre| + radius), the
 * others within the 1e-6 of the radius they were declared with. Called
 * before the shadow takes the call; leaves the shadow's circles clean as
 * found, and the refined mesh's node count. */
static void oracle_circle_nodes(runner_t *R, int idx) {
  shadow_t *s = &R->sh;
  int nn = -1, ne = -1, before = s->exact ? s->nn : s->refined_nn;
  s->refined_nn = 0;
  if (tfem_get_sizes(R->m, &nn, NULL, NULL) != TFEM_STATUS_OK || nn < 1) return;
  s->refined_nn = nn;
  if (s->ncirc == 0 || s->ncirc > 16) return;
  int clean[16], any = 0;
  char why[96];
  for (int k = 0; k < s->ncirc; ++k) {
    clean[k] = s->exact ? circle_expect(s, s->circ_tag[k], s->circ[k][0], s->circ[k][1], s->circ[k][2], why,
                                        sizeof why, NULL) == TFEM_STATUS_OK
                        : s->circ_clean[k];
    any |= clean[k];
    s->circ_clean[k] = 0;
  }
  if (!any || tfem_get_boundary_edge_count(R->m, &ne) != TFEM_STATUS_OK || ne < 0) return;
  double *xy = xmalloc(sizeof(double) * 2 * (size_t)nn);
  int *edges = xmalloc(sizeof(int) * 2 * (size_t)ne + 1), *tags = xmalloc(sizeof(int) * (size_t)ne + 1);
  if (tfem_get_mesh_nodes(R->m, xy, 2 * (size_t)nn) != TFEM_STATUS_OK ||
      tfem_get_boundary_edges(R->m, edges, 2 * (size_t)ne, tags, (size_t)ne) != TFEM_STATUS_OK) {
    finding(R, V_CIRCLE, idx, "the refined mesh (%d nodes, %d boundary edges) cannot be read back", nn, ne);
    free(xy), free(edges), free(tags);
    return;
  }
  int bad[16] = {0};
  for (int e = 0; e < ne; ++e) {
    int k = 0;
    while (k < s->ncirc && s->circ_tag[k] != tags[e]) ++k;
    if (k == s->ncirc || !clean[k] || bad[k]) continue;
    const double *q = s->circ[k];
    R->oracles[O_CIRCLE]++;
    for (int j = 0; j < 2 && !bad[k]; ++j) {
      long v = (long)edges[2 * e + j] - s->base;
      if (v < 0 || v >= nn) {
        finding(R, V_CIRCLE, idx, "boundary edge %d has node %d, outside the %d nodes (index base %d)", e + s->base,
                edges[2 * e + j], nn, s->base);
        bad[k] = 1;
        break;
      }
      int added = before > 0 && v >= before;
      double d = fabs(hypot(xy[2 * v] - q[0], xy[2 * v + 1] - q[1]) - q[2]);
      double bound = added ? 1e-12 * (q[2] + fabs(q[0]) + fabs(q[1])) : 1e-6 * q[2] * (1.0 + 1e-9);
      if (!(d <= bound)) {
        finding(R, V_CIRCLE, idx, "node %ld (%s) of an edge tagged %d lies %.3g from the circle (%.17g, %.17g) of "
                "radius %.17g declared on the tag (at most %.3g): at (%.17g, %.17g)", v + s->base,
                added ? "added by the refinement" : "given", tags[e], d, q[0], q[1], q[2], bound, xy[2 * v],
                xy[2 * v + 1]);
        bad[k] = 1;
      }
    }
  }
  for (int k = 0; k < s->ncirc; ++k) s->circ_clean[k] = clean[k] && !bad[k];
  free(xy), free(edges), free(tags);
}

/* Whether an accessor of a result tfem_write_vtu writes refuses it with
 * TFEM_STATUS_NUMERICAL_FAILURE and the message `msg`: the header's
 * tfem_write_vtu returns NUMERICAL_FAILURE "when a result it holds cannot
 * be computed as the accessors would refuse it: an overflowing stress, or
 * a load step's field that cannot be recovered to working accuracy, named
 * in the message" (a stress beyond DBL_MAX of finite displacements, e.g.
 * under a traction of DBL_MAX, is one). */
static int vtu_refusal_of_accessor(tfem_model *m, const char *msg) {
  int nn = 0, nt = 0, nc = 0;
  if (tfem_get_sizes(m, &nn, &nt, &nc) != TFEM_STATUS_OK || nn < 0 || nt < 0) return 0;
  size_t cap = 3 * (size_t)(nn > nt ? nn : nt) + (nc > 0 ? (size_t)nc : 0) + 1;
  double *v = xmalloc(sizeof(double) * cap);
  char got[4096]; /* (exec_call reads the message into as many bytes) */
  int seen = 0;
  for (int k = 0; k < 8 && !seen; ++k) {
    int st;
    switch (k) {
    case 0: st = tfem_get_displacements(m, v, 2 * (size_t)nn); break;
    case 1: st = tfem_get_element_strains(m, v, 3 * (size_t)nt); break;
    case 2: st = tfem_get_element_stresses(m, v, 3 * (size_t)nt); break;
    case 3: st = tfem_get_element_out_of_plane_stresses(m, v, (size_t)nt); break;
    case 4: st = tfem_get_contact_nodal_tractions(m, v, 2 * (size_t)nn); break;
    case 5: st = tfem_get_contact_forces(m, v, 2 * (size_t)nn); break;
    case 6: st = tfem_get_contact_gaps(m, v, (size_t)nn); break;
    default: st = nc > 0 ? tfem_get_contact_pressure(m, v, (size_t)nc) : TFEM_STATUS_OK; break;
    }
    got[0] = 0;
    if (st == TFEM_STATUS_NUMERICAL_FAILURE) tfem_last_error(m, got, sizeof got);
    seen = st == TFEM_STATUS_NUMERICAL_FAILURE && strcmp(got, msg) == 0;
  }
  free(v);
  return seen;
}

/* ------------------------------------------------------------------------ */
/* The 3D model and its contact context: handles, inputs, oracles            */
/* ------------------------------------------------------------------------ */

/* The handle call c passes when it names one (c->handle): of another kind
 * (the 2D model, a 2D context, the 3D model, the 3D context: NULL when the
 * case has none), or one of the function's own kind destroyed right
 * before the call (nothing is made between: its address is no live
 * handle's). */
static void *call_handle(runner_t *R, const call_t *c) {
  switch (c->handle) {
  case 1: return R->m;
  case 2: return R->octx;
  case 3: return R->sm;
  case 4: return R->sctx;
  default:
    switch (FN[c->fn].model) {
    case 1: {
      tfem_model *x = tfem_create();
      tfem_destroy(x);
      return x;
    }
    case 2: {
      tfem_contact *x = tfem_contact_create(0);
      tfem_contact_destroy(x);
      return x;
    }
    case 3: {
      tfem_solid_model *x = tfem_solid_create();
      tfem_solid_destroy(x);
      return x;
    }
    default: {
      tfem_solid_contact *x = tfem_solid_contact_create(0, NULL);
      tfem_solid_contact_destroy(x);
      return x;
    }
    }
  }
}
static const char *handle_name(int h) {
  static const char *const n[] = {"its own", "the 2D model", "a 2D context", "the 3D model", "the 3D context",
                                  "a destroyed one"};
  return h >= 0 && h <= 5 ? n[h] : "?";
}
/* The message the *_last_error function of `kind` (1..4) gives for h. */
static int last_error_of(int kind, void *h, char *b, size_t cap) {
  b[0] = 0;
  switch (kind) {
  case 1: return tfem_last_error(h, b, cap);
  case 2: return tfem_contact_last_error(h, b, cap);
  case 3: return tfem_solid_last_error(h, b, cap);
  default: return tfem_solid_contact_last_error(h, b, cap);
  }
}
/* A live handle of the runner that is no longer live: its name, or NULL. */
static const char *handle_gone(runner_t *R) {
  char b[8];
  if (R->m && tfem_last_error(R->m, b, sizeof b) == TFEM_STATUS_INVALID_ARGUMENT) return "the 2D model";
  if (R->ctx && tfem_contact_last_error(R->ctx, b, sizeof b) == TFEM_STATUS_INVALID_ARGUMENT) return "the 2D context";
  if (R->octx && tfem_contact_last_error(R->octx, b, sizeof b) == TFEM_STATUS_INVALID_ARGUMENT) return "a 2D context";
  if (R->sm && tfem_solid_last_error(R->sm, b, sizeof b) == TFEM_STATUS_INVALID_ARGUMENT) return "the 3D model";
  if (R->sctx && tfem_solid_contact_last_error(R->sctx, b, sizeof b) == TFEM_STATUS_INVALID_ARGUMENT)
    return "the 3D context";
  return NULL;
}

/* A call given a handle of another kind, or destroyed (hp; NULL when the
 * case has no handle of that kind): refused with INVALID_ARGUMENT (NULL:
 * NULL_POINTER), the message in the thread's slot saying what the handle
 * is not; the *_last_error functions give INVALID_ARGUMENT with that
 * message in their buffer, *_last_error_length its size; a *_destroy of
 * it is a no-op. (Nothing written and nothing changed: the generic checks
 * and the replay.) */
static void oracle_handle(runner_t *R, int idx, const call_t *c, int st, void *hp, size_t lel, const gbuf *g,
                          const char *msg) {
  int fn = c->fn, kind = FN[fn].model;
  static __thread char full[65536];
  R->oracles[O_HANDLE]++;
  int is_last = fn == F_LAST_ERROR || fn == F_CONTACT_LAST_ERROR || fn == F_S_LAST_ERROR || fn == F_SC_LAST_ERROR;
  int is_len = fn == F_LAST_ERROR_LENGTH || fn == F_CONTACT_LAST_ERROR_LENGTH || fn == F_S_LAST_ERROR_LENGTH ||
               fn == F_SC_LAST_ERROR_LENGTH;
  int is_destroy = fn == F_CONTACT_DESTROY || fn == F_S_DESTROY || fn == F_SC_DESTROY;
  if (is_destroy) {
    const char *gone = handle_gone(R);
    if (gone) finding(R, V_HANDLE, idx, "%s of %s destroyed %s (the header: a no-op)", fn_name(fn), handle_name(c->handle), gone);
    return;
  }
  if (is_last || is_len) {
    int s2 = hp ? last_error_of(kind, hp, full, sizeof full) : TFEM_STATUS_NULL_POINTER;
    if (hp && (s2 != TFEM_STATUS_INVALID_ARGUMENT || (!strstr(full, "is not") && !strstr(full, "destroyed")))) {
      finding(R, V_HANDLE, idx, "given %s: %s, \"%.160s\" (not INVALID_ARGUMENT saying what it is not)",
              handle_name(c->handle), status_name(s2), full);
      return;
    }
    if (is_len) {
      size_t want_len = hp ? strlen(full) + 1 : 1;
      if (lel != want_len)
        finding(R, V_HANDLE, idx, "%zu for %s, the message refusing it has %zu bytes", lel, handle_name(c->handle),
                want_len - 1);
      return;
    }
    if (hp && st != TFEM_STATUS_INVALID_ARGUMENT)
      finding(R, V_HANDLE, idx, "%s for %s (the header: INVALID_ARGUMENT, the message saying so in the buffer)",
              status_name(st), handle_name(c->handle));
    else if (hp && !c->out[0].null_ && c->out[0].len > 0) {
      const char *b = (const char *)g[0].p;
      size_t n = strnlen(b, c->out[0].len);
      if (n == c->out[0].len || strncmp(b, full, n) != 0 || (n < strlen(full) && n + 1 < c->out[0].len))
        finding(R, V_HANDLE, idx, "the buffer of %zu bytes for %s holds \"%.80s\", not the message \"%.160s\" cut to it",
                c->out[0].len, handle_name(c->handle), b, full);
    }
    return;
  }
  if (hp ? st != TFEM_STATUS_INVALID_ARGUMENT : st != TFEM_STATUS_NULL_POINTER)
    finding(R, V_HANDLE, idx, "%s for %s (the header: INVALID_ARGUMENT for a handle that is not live, of its kind): "
            "\"%.160s\"", status_name(st), handle_name(c->handle), msg);
  else if (hp && !strstr(msg, "is not"))
    finding(R, V_HANDLE, idx, "INVALID_ARGUMENT for %s, the thread's message does not say what it is not: \"%.160s\"",
            handle_name(c->handle), msg);
}

/* The 3D context's sizes once B is built (asking builds it). */
static int ssc_sizes(runner_t *R, int *nn, int *nt, int64_t *np) {
  int a = -1, b = -1;
  int64_t e = -1;
  if (!R->sctx || !R->ss.sc_built || tfem_solid_contact_sizes(R->sctx, &a, &b, &e) != TFEM_STATUS_OK || a < 0 ||
      b < 0 || e < 0)
    return 0;
  if (nn) *nn = a;
  if (nt) *nt = b;
  if (np) *np = e;
  return 1;
}
/* The interface nodes of the 3D context the shadow knows (-1: not known). */
static int ssc_nodes(const runner_t *R) { return R->ss.sc_live && R->ss.sc_nn <= 512 ? R->ss.sc_nn : -1; }

/* The runtime inputs of a 3D context's call (make_inputs' recipes): u (3
 * per interface node, or the host's vector), the host vector scatter_add
 * adds to, active flags. */
static void make_solid_inputs(runner_t *R, call_t *c, int idx) {
  int fn = c->fn;
  if (c->in_made) return;
  c->in_made = 1;
  int rec = c->iv[0], dl = c->iv[1], k = c->iv[2] < 0 ? -(c->iv[2] + 1) : c->iv[2];
  if (dl < -100000 || dl > 100000) dl = dl < 0 ? -100000 : 100000;
  rng_t q = {mix64(0x5eedULL + (uint64_t)k * 7919u + (uint64_t)idx)};
  int cn = ssc_nodes(R), ce = -1;
  ssc_sizes(R, NULL, &ce, NULL);
  /* the 3D model's displacements, when the case couples the two (host equation = model DOF) */
  int mnn = -1;
  double *mu = NULL;
  if (R->cs->coupled == 2 && R->sm && tfem_solid_get_sizes(R->sm, &mnn, NULL, NULL) == TFEM_STATUS_OK && mnn > 0) {
    mu = xmalloc(sizeof(double) * 3 * (size_t)mnn);
    if (tfem_solid_get_displacements(R->sm, mu, 3 * (size_t)mnn) != TFEM_STATUS_OK) free(mu), mu = NULL;
  }
  for (int j = 0; j < fn_nin(fn); ++j) {
    if (!in_runtime(fn, j)) continue;
    char role = FN[fn].ink[j];
    if (role == 'U') {
      long base, ns = 0;
      double *src = NULL;
      if (fn == F_SC_GATHER) {
        base = R->cs->coupled == 2 ? R->cs->neq : 3 + k % 20;
        if (mu && R->cs->neq == 3 * mnn) src = mu, ns = 3L * mnn;
      } else if (fn == F_SC_SCATTER_ADD && j == 1) {
        base = (long)c->out[0].len;
        dl = 0;
      } else {
        base = cn >= 0 ? 3L * cn : 3 + 3 * (k % 6);
        if (mu && cn > 0 && R->cs->hm_mul > 0) {
          /* the model's displacements at the interface nodes */
          src = xcalloc(3 * (size_t)cn + 1, sizeof(double));
          ns = 3L * cn;
          for (int i = 0; i < cn; ++i) {
            long v = ((long)R->ss.sc_ids[i] - R->cs->hm_off) / R->cs->hm_mul;
            if (v >= 0 && v < mnn && v * R->cs->hm_mul + R->cs->hm_off == R->ss.sc_ids[i])
              for (int comp = 0; comp < 3; ++comp) src[3 * i + comp] = mu[3 * v + comp];
          }
        }
      }
      long n = base + dl;
      if (n < 0) n = 0;
      if (n > 4000000) n = 4000000;
      double *u = xcalloc((size_t)n + 1, sizeof(double));
      double *full = xcalloc((size_t)(n > ns ? n : ns) + 1, sizeof(double));
      if (src) memcpy(full, src, sizeof(double) * (size_t)ns);
      rt_fill(&q, u, (int)n, fn == F_SC_SCATTER_ADD && j == 1 ? (rec == 0 ? 0 : 1) : rec, full, k);
      in_set(c, j, u, (int)n, sizeof(double));
      free(u), free(full);
      if (src && src != mu) free(src);
    } else if (role == 'a') {
      long n = (ce >= 0 ? ce : 1 + k % 8) + dl;
      if (n < 0) n = 0;
      if (n > 4000000) n = 4000000;
      int *a = xcalloc((size_t)n + 1, sizeof(int));
      if (rec == 3 && ce >= 0) {
        int *cur = xcalloc((size_t)ce + 1, sizeof(int));
        if (tfem_solid_contact_get_active(R->sctx, cur, (size_t)ce) == TFEM_STATUS_OK)
          for (long i = 0; i < n && i < ce; ++i) a[i] = cur[i];
        free(cur);
      } else {
        for (long i = 0; i < n; ++i) a[i] = rec == 1 ? 1 : (rec == 2 || rec == 4) ? (int)(rnext(&q) & 1) : 0;
        if (rec == 4 && n > 0) a[k % n] = (int[]){2, -1, INT_MIN, INT_MAX}[k % 4];
      }
      in_set(c, j, a, (int)n, sizeof(int));
      free(a);
    }
  }
  free(mu);
}

/* Value oracles of the 3D context, from its own outputs: the pattern is,
 * tetrahedron after tetrahedron of B, the pairs of its DOFs with an
 * equation (tfem_solid_contact_element_equations) row by row; evaluate's
 * values are the element blocks' entries in that order; gather gives
 * each DOF its equation's entry (0 without one), scatter_add adds the
 * residual to exactly those; set_active then get_active gives the flags
 * set; update's changed is 0 or 1, 1 exactly when it switched some; the
 * area is +0.0 without an active tetrahedron. */
static void oracle_solid_host(runner_t *R, int idx, const call_t *c, gbuf *g) {
  int fn = c->fn, nn, nt, base = R->ss.sc_base;
  int64_t np;
  if (!ssc_sizes(R, &nn, &nt, &np)) return;
  int64_t *eq = xmalloc(sizeof(int64_t) * 12 * (size_t)nt + 1);
  int *act = xmalloc(sizeof(int) * (size_t)nt + 1), *nodes = xmalloc(sizeof(int) * (size_t)nn + 1);
  int *tets = xmalloc(sizeof(int) * 4 * (size_t)nt + 1);
  if (tfem_solid_contact_element_equations(R->sctx, eq, 12 * (size_t)nt) != TFEM_STATUS_OK ||
      tfem_solid_contact_get_active(R->sctx, act, (size_t)nt) != TFEM_STATUS_OK ||
      tfem_solid_contact_nodes(R->sctx, nodes, (size_t)nn) != TFEM_STATUS_OK ||
      tfem_solid_contact_tetrahedra(R->sctx, tets, 4 * (size_t)nt) != TFEM_STATUS_OK)
    goto done;
  if (fn == F_SC_PATTERN || fn == F_SC_EVALUATE) {
    const int64_t *rows = fn == F_SC_PATTERN ? (const int64_t *)(const void *)g[0].p : NULL;
    const int64_t *cols = fn == F_SC_PATTERN ? (const int64_t *)(const void *)g[1].p : NULL;
    const double *val = fn == F_SC_EVALUATE && !c->out[0].null_ ? (const double *)(const void *)g[0].p : NULL;
    double *blk = NULL;
    if (val) {
      blk = xmalloc(sizeof(double) * 144 * (size_t)nt + 1);
      if (tfem_solid_contact_element_blocks(R->sctx, blk, 144 * (size_t)nt) != TFEM_STATUS_OK) {
        free(blk);
        goto done;
      }
    }
    int64_t p = 0;
    int bad = 0;
    for (int k = 0; k < nt && !bad; ++k)
      for (int a = 0; a < 12 && !bad; ++a) {
        if (eq[12 * k + a] < base) continue;
        for (int b = 0; b < 12 && !bad; ++b) {
          if (eq[12 * k + b] < base) continue;
          if ((size_t)p < c->out[0].len) {
            if (rows && (rows[p] != eq[12 * k + a] || cols[p] != eq[12 * k + b])) {
              finding(R, V_SOLID_HOST, idx, "pattern entry %" PRId64 " = (%" PRId64 ", %" PRId64 "), tetrahedron %d's DOFs "
                      "%d, %d have equations %" PRId64 ", %" PRId64, p, rows[p], cols[p], k, a, b, eq[12 * k + a],
                      eq[12 * k + b]);
              bad = 1;
            }
            double want_v = blk ? blk[144 * k + 12 * a + b] : 0;
            if (val && val[p] != want_v) {
              finding(R, V_SOLID_HOST, idx, "value %" PRId64 " = %.17g, tetrahedron %d's block (%d, %d) = %.17g (active %d)",
                      p, val[p], k, a, b, want_v, act[k]);
              bad = 1;
            }
          }
          ++p;
        }
      }
    if (!bad && p != np)
      finding(R, V_SOLID_HOST, idx, "%" PRId64 " pattern entries from the element equations, sizes says %" PRId64, p, np);
    /* (an inactive tetrahedron's block is zeros) */
    for (int k = 0; blk && k < nt && !bad; ++k)
      for (int i = 0; i < 144 && !act[k]; ++i)
        if (blk[144 * k + i] != 0) {
          finding(R, V_SOLID_HOST, idx, "inactive tetrahedron %d has a block entry %.17g", k, blk[144 * k + i]);
          bad = 1;
          break;
        }
    R->oracles[O_SOLID_HOST]++;
    free(blk);
  } else if (fn == F_SC_GATHER || fn == F_SC_SCATTER_ADD) {
    /* each DOF's equation: from the tetrahedra of B that hold its node */
    const double *in = c->in[0].p;
    size_t neq = fn == F_SC_GATHER ? (size_t)c->in[0].n : c->out[0].len;
    const double *out = (const double *)(const void *)g[0].p, *before = c->in[1].p;
    double *expect = NULL;
    if (fn == F_SC_SCATTER_ADD) {
      expect = xmalloc(sizeof(double) * neq + 1);
      memcpy(expect, before, sizeof(double) * neq);
    }
    int bad = 0, unknown = 0;
    for (int i = 0; i < nn && !bad; ++i)
      for (int comp = 0; comp < 3 && !bad; ++comp) {
        int64_t e = -2;
        for (int k = 0; k < nt && e == -2; ++k)
          for (int a = 0; a < 4; ++a)
            if (tets[4 * k + a] == nodes[i]) {
              e = eq[12 * k + 3 * a + comp] < base ? -1 : eq[12 * k + 3 * a + comp] - base;
              break;
            }
        if (e == -2) { /* a node on no tetrahedron of B: its equation is not known here */
          unknown = 1;
          continue;
        }
        if (e >= (int64_t)neq) {
          finding(R, V_SOLID_HOST, idx, "OK with equation %" PRId64 " of node %d beyond the %zu given", e + base, nodes[i], neq);
          bad = 1;
        } else if (fn == F_SC_GATHER) {
          double want_u = e < 0 ? 0.0 : in[e];
          if (memcmp(&want_u, &out[3 * i + comp], 8) != 0 && !(want_u == 0 && out[3 * i + comp] == 0)) {
            finding(R, V_SOLID_HOST, idx, "u[%d] of node %d = %.17g, its equation %" PRId64 " holds %.17g", 3 * i + comp,
                    nodes[i], out[3 * i + comp], e + base, want_u);
            bad = 1;
          }
        } else if (e >= 0) {
          expect[e] += in[3 * i + comp];
        }
      }
    if (fn == F_SC_SCATTER_ADD && !unknown)
      for (size_t e = 0; e < neq && !bad; ++e)
        if (!(out[e] == expect[e] || fabs(out[e] - expect[e]) <= 1e-13 * fabs(expect[e]))) {
          finding(R, V_SOLID_HOST, idx, "host vector entry %zu = %.17g, expected %.17g", e, out[e], expect[e]);
          bad = 1;
        }
    free(expect);
    R->oracles[O_SOLID_HOST]++;
  } else if (fn == F_SC_SET_ACTIVE) {
    const int *a = c->in[0].p;
    for (int k = 0; k < nt; ++k)
      if (act[k] != a[k]) {
        finding(R, V_SOLID_HOST, idx, "tetrahedron %d set to %d, tfem_solid_contact_get_active gives %d", k, a[k], act[k]);
        break;
      }
    R->oracles[O_SOLID_HOST]++;
  } else if (fn == F_SC_UPDATE && !c->out[0].null_) {
    int ch, on = -1, off = -1;
    memcpy(&ch, g[0].p, sizeof ch);
    if (!c->out[1].null_) memcpy(&on, g[1].p, sizeof on);
    if (!c->out[2].null_) memcpy(&off, g[2].p, sizeof off);
    R->oracles[O_SOLID_HOST]++;
    if (ch != 0 && ch != 1) finding(R, V_SOLID_HOST, idx, "changed = %d", ch);
    else if (on >= 0 && off >= 0 && ch != (on + off > 0))
      finding(R, V_SOLID_HOST, idx, "changed = %d with %d switched on and %d off", ch, on, off);
    else if ((on >= 0 && on > nt) || (off >= 0 && off > nt) || on < -1 || off < -1)
      finding(R, V_SOLID_HOST, idx, "%d switched on and %d off of %d tetrahedra", on, off, nt);
  } else if (fn == F_SC_AREA) {
    double A;
    memcpy(&A, g[0].p, 8);
    int na = 0;
    for (int k = 0; k < nt; ++k) na += act[k];
    R->oracles[O_SOLID_HOST]++;
    /* (-0.0 with nothing active: unlike tfem_contact_length's "+0.0", the
     * 3D header promises no sign of zero) */
    if (A < 0 || (na == 0 && A != 0)) finding(R, V_SOLID_HOST, idx, "contact area %.17g with %d active tetrahedra", A, na);
  }
done:
  free(eq), free(act), free(nodes), free(tets);
}

/* tfem_solid_write_vtu: NULL refused; a file written only where it can
 * be, a grid of the model's points and tetrahedra; an unwritable path
 * refused with TFEM_STATUS_IO once there are results (NUMERICAL_FAILURE
 * for a result that is not finite, nothing written). */
static void solid_vtu_check(runner_t *R, int idx, const call_t *c, int st, const char *path, const char *vtu, size_t vtu_n,
                            int vtu_found, const char *msg) {
  const sshadow_t *s = &R->ss;
  int known = s->has_mesh && s->results && !s->res_unknown;
  if (c->null_model || c->handle) return;
  if (!path && st != TFEM_STATUS_NULL_POINTER) {
    finding(R, V_NULL_ARG, idx, "NULL path gave %s", status_name(st));
  } else if (path && st == TFEM_STATUS_OK && !vtu_writable(c->iv[0])) {
    finding(R, V_SOLID, idx, "OK although the path \"%s\" cannot be written", path);
  } else if (path && st == TFEM_STATUS_OK) {
    int nn = -1, nt = -1;
    char want_p[64], want_c[64];
    if (!vtu_found) {
      finding(R, V_SOLID, idx, "OK but no file at %s", path);
    } else if (tfem_solid_get_sizes(R->sm, &nn, &nt, NULL) == TFEM_STATUS_OK) {
      snprintf(want_p, sizeof want_p, "NumberOfPoints=\"%d\"", nn);
      snprintf(want_c, sizeof want_c, "NumberOfCells=\"%d\"", nt);
      R->oracles[O_VTU]++;
      if (!vtu || !strstr(vtu, "<VTKFile") || !strstr(vtu, "UnstructuredGrid") || !strstr(vtu, want_p) ||
          !strstr(vtu, want_c))
        finding(R, V_SOLID, idx, "the .vtu (%zu bytes) is not a grid of %d points and %d tetrahedra", vtu_n, nn, nt);
    }
  } else if (path && known && st == TFEM_STATUS_NUMERICAL_FAILURE) {
    R->oracles[O_VTU]++;
    if (vtu_found) finding(R, V_SOLID, idx, "NUMERICAL_FAILURE, yet a file is at \"%s\": \"%.160s\"", path, msg);
  } else if (path && known && st != TFEM_STATUS_INVALID_STATE) {
    int want_st = vtu_writable(c->iv[0]) ? TFEM_STATUS_OK : TFEM_STATUS_IO;
    R->oracles[O_VTU]++;
    if (st != want_st)
      finding(R, V_SOLID, idx, "%s (not %s) for the path \"%s\" after a solve: \"%.160s\"", status_name(st),
              status_name(want_st), path, msg);
  }
}

/* A pristine 3D scene's closed form (call_t.oracle, its numbers in dv). */
static void solid_exact(runner_t *R, int idx, const call_t *c, const gbuf *g) {
  const sshadow_t *s = &R->ss;
  const double load = c->dv[0], E = c->dv[1], nu = c->dv[2], tol = 1e-9;
  long n = c->out[0].req;
  const double *v = (const double *)(const void *)g[0].p;
  if (!s->exact || c->out[0].null_ || !R->pristine || idx >= R->full_prefix) return;
  R->oracles[O_SOLID_EXACT]++;
  switch (c->oracle) {
  case SO_TENSION_U: {
    if (n != 3L * s->nn) return;
    double worst = 0, scale = fabs(load) / E;
    for (int i = 0; i < s->nn; ++i) {
      const double *x = &s->xyz[3 * i];
      double want_u[3] = {load * x[0] / E, -nu * load * x[1] / E, -nu * load * x[2] / E};
      for (int k = 0; k < 3; ++k) worst = fmax(worst, fabs(v[3 * i + k] - want_u[k]));
    }
    if (!(worst <= tol * scale))
      finding(R, V_SOLID, idx, "tension of a cube: |u - (t x, -nu t y, -nu t z)/E| up to %.3g, %.3g of t/E (t %g, E %g, nu %g)",
              worst, worst / scale, load, E, nu);
    break;
  }
  case SO_TENSION_S: case SO_BLOCKS_S: {
    if (n != 6L * s->nt) return;
    double worst = 0;
    for (int e = 0; e < s->nt; ++e)
      for (int k = 0; k < 6; ++k) {
        double want_s = c->oracle == SO_TENSION_S ? (k == 0 ? load : 0.0) : (k == 2 ? -load : 0.0);
        worst = fmax(worst, fabs(v[6 * e + k] - want_s));
      }
    if (!(worst <= tol * fabs(load)))
      finding(R, V_SOLID, idx, "%s: the stresses differ from the uniaxial %s = %g by up to %.3g", c->oracle == SO_TENSION_S ?
              "tension of a cube" : "stacked blocks pressed", c->oracle == SO_TENSION_S ? "sigma_xx" : "sigma_zz",
              c->oracle == SO_TENSION_S ? load : -load, worst);
    break;
  }
  case SO_TENSION_R: case SO_BLOCKS_R: {
    if (n != 3L * s->nn) return;
    double sum[3] = {0, 0, 0}, mag = 0;
    for (int i = 0; i < s->nn; ++i)
      for (int k = 0; k < 3; ++k) sum[k] += v[3 * i + k], mag += fabs(v[3 * i + k]);
    double want_r[3] = {c->oracle == SO_TENSION_R ? -load : 0.0, 0.0, c->oracle == SO_BLOCKS_R ? load : 0.0};
    for (int k = 0; k < 3; ++k)
      if (!(fabs(sum[k] - want_r[k]) <= tol * (fabs(load) + mag))) {
        finding(R, V_SOLID, idx, "the reactions sum to %.17g in %c, the load gives %g", sum[k], 'x' + k, want_r[k]);
        break;
      }
    break;
  }
  case SO_TENSION_W: {
    double w;
    memcpy(&w, g[0].p, 8);
    if (!(fabs(w - load * load / E) <= tol * load * load / E))
      finding(R, V_SOLID, idx, "external work %.17g, exactly t^2/E = %.17g for the pulled cube", w, load * load / E);
    break;
  }
  case SO_BLOCKS_AREA: {
    double a;
    memcpy(&a, g[0].p, 8);
    if (!(fabs(a - 1.0) <= 1e-12)) finding(R, V_SOLID, idx, "contact area %.17g of the closed interface of area 1", a);
    break;
  }
  case SO_BLOCKS_ACTIVE: {
    for (long k = 0; k < n; ++k) {
      int a;
      memcpy(&a, g[0].p + sizeof(int) * (size_t)k, sizeof a);
      if (a != 1) {
        finding(R, V_SOLID, idx, "tetrahedron %ld of B is not active (%d), every one is on the closed interface", k, a);
        break;
      }
    }
    if (n < 1) finding(R, V_SOLID, idx, "no tetrahedron of B on the closed interface");
    break;
  }
  case SO_BLOCKS_P: {
    if (n != s->nn) return;
    for (int i = 0; i < s->nn; ++i) {
      double want_p = s->xyz[3 * i + 2] == 0.0 ? load : 0.0;
      if (!(fabs(v[i] - want_p) <= tol * load)) {
        finding(R, V_SOLID, idx, "nodal contact pressure %.17g at node %d (z = %g), exactly %g", v[i], i + s->base,
                s->xyz[3 * i + 2], want_p);
        break;
      }
    }
    break;
  }
  case SO_BLOCKS_F: {
    if (n != 3L * s->nn) return;
    double up = 0;
    for (int i = c->iv[0]; i < s->nn; ++i) up += v[3 * i + 2];
    if (!(fabs(up - load) <= tol * load))
      finding(R, V_SOLID, idx, "the contact holds the upper block up by %.17g, the load is %g", up, load);
    break;
  }
  default: break;
  }
}

/* The checks of a 3D call made with its own handle (or none), and the
 * shadow it updates. */
static void solid_checks(runner_t *R, int idx, call_t *c, int st, gbuf *g, const char *msg) {
  int fn = c->fn;
  sshadow_t *s = &R->ss;
  char why[200] = "";
  if (c->null_model) return;
  /* ---- the 3D model ---- */
  if (FN[fn].model == 3 || fn == F_S_RECREATE) {
    int refused = -1; /* the header refuses the call: 1 yes (why), 0 no (valid), -1 not known */
    switch (fn) {
    case F_S_SET_MESH: {
      int nn = c->iv[0], nt = c->iv[1], base = c->iv[2];
      refused = 0;
      if (base != 0 && base != 1) refused = 1, snprintf(why, sizeof why, "index_base = %d", base);
      else if (nn < 0 || nt < 0) refused = 1, snprintf(why, sizeof why, "a negative count");
      else if ((nn > 0 && c->in[0].null_) || (nt > 0 && (c->in[1].null_ || c->in[2].null_)))
        refused = 1, snprintf(why, sizeof why, "an array NULL");
      else if (c->in[0].n < 3 * nn || c->in[1].n < 4 * nt || c->in[2].n < nt) refused = -1;
      else {
        const double *x = c->in[0].p;
        const int *t = c->in[1].p;
        for (int k = 0; k < 3 * nn && !refused; ++k)
          if (!isfinite(x[k])) refused = 1, snprintf(why, sizeof why, "a coordinate %g", x[k]);
        for (int e = 0; e < nt && !refused; ++e)
          for (int a = 0; a < 4 && !refused; ++a) {
            if ((long)t[4 * e + a] - base < 0 || (long)t[4 * e + a] - base >= nn)
              refused = 1, snprintf(why, sizeof why, "tetrahedron %d: node %d out of range", e, t[4 * e + a]);
            for (int b = a + 1; b < 4 && !refused; ++b)
              if (t[4 * e + a] == t[4 * e + b]) refused = 1, snprintf(why, sizeof why, "tetrahedron %d repeats a node", e);
          }
      }
      break;
    }
    case F_S_LOAD_GMSH:
      refused = c->iv[1] != 0 && c->iv[1] != 1 ? 1 : c->iv[0] == SG_VALID ? 0 : 1;
      snprintf(why, sizeof why, "file %d, index_base %d", c->iv[0], c->iv[1]);
      break;
    case F_S_SET_FACES: case F_S_ADD_FACES: refused = ss_faces_refused(s, c, why, sizeof why); break;
    case F_S_SET_MATERIAL: {
      double E = c->dv[0], nu = c->dv[1];
      refused = !(isfinite(E) && E > 0 && isfinite(nu) && nu > -1.0 && nu < 0.5);
      snprintf(why, sizeof why, "E = %g, nu = %g", E, nu);
      if (refused && st != TFEM_STATUS_OK && st != TFEM_STATUS_INVALID_MATERIAL)
        finding(R, V_SOLID, idx, "a material (%s) refused with %s, not INVALID_MATERIAL", why, status_name(st));
      break;
    }
    case F_S_SET_TEMPERING:
      refused = !(c->iv[0] == 0 || c->iv[0] == 3 || ((c->iv[0] == 1 || c->iv[0] == 2) && isfinite(c->dv[0]) && c->dv[0] > 0));
      snprintf(why, sizeof why, "mode %d, value %g", c->iv[0], c->dv[0]);
      break;
    case F_S_SET_ORDERING:
      refused = c->iv[0] < 0 || c->iv[0] > 2;
      snprintf(why, sizeof why, "ordering %d", c->iv[0]);
      break;
    case F_S_FIX: case F_S_ADD_NODAL_FORCE: {
      long v = (long)c->iv[0] - s->base;
      int finite = fn == F_S_FIX ? isfinite(c->dv[0]) : isfinite(c->dv[0]) && isfinite(c->dv[1]) && isfinite(c->dv[2]);
      refused = !s->has_mesh || (s->exact && (v < 0 || v >= s->nn)) || !finite || (fn == F_S_FIX && (c->iv[1] < 0 || c->iv[1] > 2));
      if (!refused && !s->exact) refused = -1;
      snprintf(why, sizeof why, "%s, node %d, component %d, value %g", s->has_mesh ? "a mesh" : "no mesh", c->iv[0],
               fn == F_S_FIX ? c->iv[1] : -1, c->dv[0]);
      break;
    }
    case F_S_FIX_FACES: case F_S_ADD_PRESSURE: case F_S_ADD_TRACTION: {
      int finite = fn == F_S_ADD_TRACTION ? isfinite(c->dv[0]) && isfinite(c->dv[1]) && isfinite(c->dv[2]) : isfinite(c->dv[0]);
      int comp_bad = fn == F_S_FIX_FACES && (c->iv[1] < 0 || c->iv[1] > 2);
      refused = !s->has_mesh || !finite || comp_bad || (s->exact && !ss_tag_faces(s, c->iv[0]));
      if (!refused && !s->exact) refused = -1;
      snprintf(why, sizeof why, "%s, tag %d (%d faces), value %g", s->has_mesh ? "a mesh" : "no mesh", c->iv[0],
               s->exact ? ss_tag_faces(s, c->iv[0]) : -1, c->dv[0]);
      break;
    }
    case F_S_ADD_PAIR:
      refused = !s->has_mesh || c->iv[0] == c->iv[1] ||
                (s->exact && (!ss_tag_faces(s, c->iv[0]) || !ss_tag_faces(s, c->iv[1])));
      if (!refused && !s->exact) refused = -1;
      snprintf(why, sizeof why, "tags %d and %d", c->iv[0], c->iv[1]);
      break;
    case F_S_CLEAR_CONSTRAINTS: case F_S_CLEAR_LOADS: case F_S_CLEAR_PAIRS:
      refused = 0;
      break;
    case F_S_SOLVE: case F_S_SOLVE_CONTACT: case F_S_STEP: {
      int body = 0, missing = ss_missing_material(s, &body);
      int bad_factor = fn == F_S_STEP && !(isfinite(c->dv[2]) && fabs(c->dv[2]) <= 1e300);
      int bad_opts = fn != F_S_SOLVE && solid_options_refused(c);
      if (!s->has_mesh) refused = 1, snprintf(why, sizeof why, "no mesh");
      else if (bad_opts) refused = 1, snprintf(why, sizeof why, "options %d %d %d %d %g %g", c->iv[0], c->iv[1], c->iv[2],
                                              c->iv[3], c->dv[0], c->dv[1]);
      else if (missing == 1) refused = 1, snprintf(why, sizeof why, "body %d has no material", body);
      else if (bad_factor) refused = 1, snprintf(why, sizeof why, "load_factor = %g", c->dv[2]);
      if (refused == 1 && missing == 1 && !bad_opts && st != TFEM_STATUS_OK && st != TFEM_STATUS_INVALID_MATERIAL)
        finding(R, V_SOLID, idx, "%s refused with %s, not INVALID_MATERIAL: \"%.160s\"", why, status_name(st), msg);
      break;
    }
    case F_S_REVERT_STEP:
      if (s->undo >= 0) refused = !s->undo, snprintf(why, sizeof why, "no load step to revert");
      if (st != TFEM_STATUS_OK && st != TFEM_STATUS_INVALID_STATE)
        finding(R, V_SOLID, idx, "%s (the header: refused with INVALID_STATE only): \"%.160s\"", status_name(st), msg);
      if (s->undo == 1 && st != TFEM_STATUS_OK)
        finding(R, V_SOLID, idx, "refused after a load step that nothing changed since: %s \"%.160s\"", status_name(st), msg);
      break;
    case F_S_PAIR_AREA:
      if (s->has_mesh && s->results && !s->res_unknown) {
        refused = c->iv[0] < 0 || c->iv[0] >= s->npairs;
        snprintf(why, sizeof why, "pair %d of %d", c->iv[0], s->npairs);
      }
      break;
    case F_S_GET_WARNING_SIZE: case F_S_GET_WARNING:
      if (st == TFEM_STATUS_OK || st == TFEM_STATUS_BUFFER_TOO_SMALL) {
        int count = -1;
        if (tfem_solid_warning_count(R->sm, &count) == TFEM_STATUS_OK && (c->iv[0] < 0 || c->iv[0] >= count))
          finding(R, V_SOLID, idx, "%s for warning %d of %d", status_name(st), c->iv[0], count);
      }
      if (fn == F_S_GET_WARNING_SIZE && st == TFEM_STATUS_OK && !c->out[0].null_) {
        size_t z;
        memcpy(&z, g[0].p, sizeof z);
        if (z < 1 || z > ((size_t)1 << 26)) {
          finding(R, V_SOLID, idx, "warning %d has size %zu", c->iv[0], z);
        } else {
          char *w = xmalloc(z + 1);
          int s_short = z > 1 ? tfem_solid_get_warning(R->sm, c->iv[0], w, z - 1) : TFEM_STATUS_BUFFER_TOO_SMALL;
          memset(w, 'x', z + 1);
          int s_full = tfem_solid_get_warning(R->sm, c->iv[0], w, z);
          R->oracles[O_WARNING_SIZE]++;
          if (s_full != TFEM_STATUS_OK || strnlen(w, z) + 1 != z || s_short != TFEM_STATUS_BUFFER_TOO_SMALL)
            finding(R, V_SOLID, idx, "warning %d of size %zu: a buffer of that size gives %s (%zu bytes), one byte less %s",
                    c->iv[0], z, status_name(s_full), strnlen(w, z), status_name(s_short));
          free(w);
        }
      }
      break;
    default: break;
    }
    if (refused >= 0) {
      R->oracles[O_SOLID_ARGS]++;
      if (refused && st == TFEM_STATUS_OK)
        finding(R, V_SOLID, idx, "OK although %s (the header: refused)", why);
      else if (!refused && st != TFEM_STATUS_OK && st != TFEM_STATUS_OUT_OF_MEMORY && !solid_result_fn(fn) &&
               fn != F_S_SOLVE && fn != F_S_SOLVE_CONTACT && fn != F_S_STEP && fn != F_S_REVERT_STEP)
        finding(R, V_SOLID, idx, "%s refused (%s): \"%.160s\"", why[0] ? why : "a valid call", status_name(st), msg);
    }
    /* results kept until a change of the problem, gone after one */
    if (solid_result_fn(fn) && s->has_mesh && !s->res_unknown) {
      R->oracles[O_SOLID_KEPT]++;
      if (st == TFEM_STATUS_INVALID_STATE && s->results)
        finding(R, V_SOLID, idx, "INVALID_STATE although the last %s succeeded and nothing changed the problem since: "
                "\"%.160s\"", s->results == 2 ? "load step" : "solve", msg);
      else if (st == TFEM_STATUS_OK && !s->results)
        finding(R, V_SOLID, idx, "results returned although %s", s->sol_gen > 1 ? "the problem changed since the last solve"
                                                                             : "nothing was solved");
    }
    if (c->want && R->pristine && idx < R->full_prefix && st != c->want - 1)
      finding(R, V_SOLID, idx, "%s, the scene expects %s: \"%.160s\"", status_name(st), status_name(c->want - 1), msg);
    if (st == TFEM_STATUS_OK) {
      /* ---- outputs of a successful call ---- */
      switch (fn) {
      case F_S_GET_SIZES:
        if (s->exact && !c->out[0].null_ && !c->out[1].null_) {
          int nn, nt, nc = -1;
          memcpy(&nn, g[0].p, 4);
          memcpy(&nt, g[1].p, 4);
          if (!c->out[2].null_) memcpy(&nc, g[2].p, 4);
          R->oracles[O_SOLID_MESH]++;
          if (nn != s->nn || nt != s->nt || (!c->out[2].null_ && (nc < 0 || (!s->results && !s->res_unknown && nc != 0))))
            finding(R, V_SOLID, idx, "sizes %d, %d, %d; the mesh has %d nodes and %d tetrahedra%s", nn, nt, nc, s->nn, s->nt,
                    s->results ? "" : ", and there are no results");
        }
        break;
      case F_S_FACE_COUNT:
        if (s->exact) {
          int n;
          memcpy(&n, g[0].p, 4);
          R->oracles[O_SOLID_MESH]++;
          if (n != s->nf) finding(R, V_SOLID, idx, "%d faces, %d were given", n, s->nf);
        }
        break;
      case F_S_MESH_NODES:
        if (s->exact && out_full(c, 0) && c->out[0].req == 3L * s->nn) {
          R->oracles[O_SOLID_MESH]++;
          if (s->nn && memcmp(g[0].p, s->xyz, sizeof(double) * 3 * (size_t)s->nn) != 0)
            finding(R, V_SOLID, idx, "the nodes read back differ from those given");
        }
        break;
      case F_S_MESH_TETS:
        if (s->exact && out_full(c, 0) && c->out[0].req == 4L * s->nt) {
          const int *t = (const int *)(const void *)g[0].p;
          R->oracles[O_SOLID_MESH]++;
          for (int e = 0; e < s->nt; ++e) {
            int same = 1, swapped = 1;
            for (int a = 0; a < 4; ++a) same &= t[4 * e + a] == s->tet[4 * e + a] + s->base;
            for (int a = 0; a < 4; ++a) swapped &= t[4 * e + a] == s->tet[4 * e + (a < 2 ? a : 5 - a)] + s->base;
            /* (a J within round-off of 0 may take either sign: this file's
             * arithmetic may contract into fused multiply-adds, the
             * library's does not) */
            double h, j = ss_j(&s->xyz[3 * s->tet[4 * e]], &s->xyz[3 * s->tet[4 * e + 1]], &s->xyz[3 * s->tet[4 * e + 2]],
                               &s->xyz[3 * s->tet[4 * e + 3]], &h);
            if (!same && swapped && !(fabs(j) > 1e-9 * h * h * h)) same = 1;
            if (!same) {
              finding(R, V_SOLID, idx, "tetrahedron %d reads back as %d %d %d %d, given (renumbered if of negative J) %d %d %d %d",
                      e + s->base, t[4 * e], t[4 * e + 1], t[4 * e + 2], t[4 * e + 3], s->tet[4 * e] + s->base,
                      s->tet[4 * e + 1] + s->base, s->tet[4 * e + 2] + s->base, s->tet[4 * e + 3] + s->base);
              break;
            }
          }
          if (s->nt && out_full(c, 1) && memcmp(g[1].p, s->body, sizeof(int) * (size_t)s->nt) != 0)
            finding(R, V_SOLID, idx, "the bodies read back differ from those given");
        }
        break;
      case F_S_GET_FACES:
        if (s->exact && out_full(c, 0) && c->out[0].req == 3L * s->nf) {
          const int *f = (const int *)(const void *)g[0].p;
          R->oracles[O_SOLID_MESH]++;
          for (int k = 0; k < 3 * s->nf; ++k)
            if (f[k] != s->face[k] + s->base) {
              finding(R, V_SOLID, idx, "face %d reads back with node %d, given %d", k / 3 + s->base, f[k], s->face[k] + s->base);
              break;
            }
          if (s->nf && out_full(c, 1) && memcmp(g[1].p, s->ftag, sizeof(int) * (size_t)s->nf) != 0)
            finding(R, V_SOLID, idx, "the face tags read back differ from those given");
        }
        break;
      case F_S_ADD_PAIR:
        if (!c->out[0].null_) {
          int p;
          memcpy(&p, g[0].p, 4);
          if (s->exact && p != s->npairs) finding(R, V_SOLID, idx, "pair index %d, %d pairs were declared before", p, s->npairs);
        }
        break;
      case F_S_ITERATIONS: {
        int it;
        memcpy(&it, g[0].p, 4);
        if (it < 1) finding(R, V_SOLID, idx, "%d active-set iterations", it);
        break;
      }
      case F_S_DISPLACEMENTS:
        if (out_full(c, 0) && s->results) {
          uint64_t h = fnv64(g[0].p, sizeof(double) * (size_t)c->out[0].req);
          R->oracles[O_SOLID_KEPT] += s->disp_gen == s->sol_gen;
          if (s->disp_gen == s->sol_gen && h != s->disp_hash)
            finding(R, V_SOLID, idx, "displacements differ from those of call #%d, although no solve succeeded and nothing "
                    "changed the problem since", s->disp_idx);
          s->disp_hash = h, s->disp_gen = s->sol_gen, s->disp_idx = idx;
        }
        if (out_full(c, 0) && c->oracle) solid_exact(R, idx, c, g);
        if (out_full(c, 0) && (c->tag == ST_REF || c->tag == ST_CMP) && R->pristine && idx < R->full_prefix) {
          int slot = c->tw_a & 1;
          long n = c->out[0].req;
          const double *u = (const double *)(const void *)g[0].p;
          if (c->tag == ST_REF) {
            free(s->ref[slot]);
            s->ref[slot] = xmalloc(sizeof(double) * (size_t)n + 1);
            memcpy(s->ref[slot], u, sizeof(double) * (size_t)n);
            s->nref[slot] = n;
          } else if (s->ref[slot] && s->nref[slot] == n) {
            double umax = 0, worst = 0;
            long at = -1;
            for (long k = 0; k < n; ++k) umax = fmax(umax, fabs(s->ref[slot][k]));
            for (long k = 0; k < n; ++k) {
              double d = fabs(u[k] - c->dv[0] * s->ref[slot][k]);
              if (c->dv[1] == 0 ? memcmp(&u[k], &s->ref[slot][k], 8) != 0 : d > worst) worst = d, at = k;
            }
            R->oracles[O_SOLID_STEP]++;
            if (c->dv[1] == 0 && at >= 0)
              finding(R, V_SOLID, idx, "u[%ld] = %.17g, %.17g in the results this step repeats or reverts to (bit for bit)",
                      at, u[at], s->ref[slot][at]);
            else if (c->dv[1] > 0 && !(worst <= c->dv[1] * fabs(c->dv[0]) * umax))
              finding(R, V_SOLID, idx, "u differs from %g times the reference by %.3g (u[%ld]; largest |u| %.3g): a step "
                      "at a factor is the solve of the loads times it", c->dv[0], worst, at, umax);
          }
        }
        break;
      case F_S_STRESSES: case F_S_REACTIONS: case F_S_WORK: case F_S_NODAL_PRESSURES:
        if (c->oracle && (fn == F_S_WORK || out_full(c, 0))) solid_exact(R, idx, c, g);
        if (fn == F_S_REACTIONS && out_full(c, 0) && s->exact && c->out[0].req == 3L * s->nn && s->results) {
          /* zero at the components not prescribed */
          const double *v = (const double *)(const void *)g[0].p;
          R->oracles[O_SOLID_CONTACT]++;
          for (int k = 0; k < 3 * s->nn; ++k)
            if (isnan(s->presc[k]) && v[k] != 0.0) {
              finding(R, V_SOLID, idx, "reaction %.17g at component %d of node %d, which is not prescribed", v[k], k % 3,
                      k / 3 + s->base);
              break;
            }
        }
        if (fn == F_S_NODAL_PRESSURES && out_full(c, 0) && s->exact && c->out[0].req == s->nn && s->npairs <= 16) {
          /* zero off the pairs' faces */
          const double *v = (const double *)(const void *)g[0].p;
          char *on = xcalloc((size_t)s->nn + 1, 1);
          for (int f = 0; f < s->nf; ++f)
            for (int p = 0; p < s->npairs; ++p)
              if (s->ftag[f] == s->pair_tag[p][0] || s->ftag[f] == s->pair_tag[p][1])
                on[s->face[3 * f]] = on[s->face[3 * f + 1]] = on[s->face[3 * f + 2]] = 1;
          R->oracles[O_SOLID_CONTACT]++;
          for (int i = 0; i < s->nn; ++i)
            if (!on[i] && v[i] != 0.0) {
              finding(R, V_SOLID, idx, "contact pressure %.17g at node %d, on no face of a contact pair", v[i], i + s->base);
              break;
            }
          free(on);
        }
        if (fn == F_S_WORK && s->exact && s->results == 1 && !s->res_unknown) {
          /* the work of the loads known here over the displacements */
          double w, *f = xmalloc(sizeof(double) * 3 * (size_t)s->nn + 1), *u = xmalloc(sizeof(double) * 3 * (size_t)s->nn + 1);
          memcpy(&w, g[0].p, 8);
          if (ss_loads(s, f) && tfem_solid_get_displacements(R->sm, u, 3 * (size_t)s->nn) == TFEM_STATUS_OK) {
            double sum = 0, mag = 0;
            for (int k = 0; k < 3 * s->nn; ++k) sum += f[k] * u[k], mag += fabs(f[k] * u[k]);
            R->oracles[O_WORK]++;
            if (isfinite(mag) && mag < 1e300 && !(fabs(w - sum) <= 1e-10 * mag + 1e-300))
              finding(R, V_SOLID, idx, "external work %.17g, the sum of f.u over the loads known here %.17g", w, sum);
          }
          free(f), free(u);
        }
        break;
      case F_S_CONTACT_ACTIVE: case F_S_CONTACT_TETS:
        if (out_full(c, 0)) {
          long n = c->out[0].req;
          R->oracles[O_SOLID_CONTACT]++;
          for (long k = 0; k < n; ++k) {
            int v;
            memcpy(&v, g[0].p + sizeof(int) * (size_t)k, sizeof v);
            if (fn == F_S_CONTACT_ACTIVE ? v != 0 && v != 1 : s->exact && (v < s->base || v >= s->base + s->nn)) {
              finding(R, V_SOLID, idx, "%s %ld = %d", fn == F_S_CONTACT_ACTIVE ? "active flag" : "node", k, v);
              break;
            }
          }
          if (c->oracle) solid_exact(R, idx, c, g);
        }
        break;
      case F_S_CONTACT_FORCES:
        if (out_full(c, 0)) {
          /* the forces of a pair sum to zero: all of them too */
          const double *v = (const double *)(const void *)g[0].p;
          long n = c->out[0].req;
          double sum[3] = {0, 0, 0}, mag = 0;
          for (long k = 0; k < n; ++k) sum[k % 3] += v[k], mag += fabs(v[k]);
          R->oracles[O_SOLID_CONTACT]++;
          for (int k = 0; k < 3; ++k)
            if (isfinite(mag) && mag < 1e300 && !(fabs(sum[k]) <= 1e-9 * mag + 1e-300)) {
              finding(R, V_SOLID, idx, "the contact forces sum to %.3g in %c (of %.3g in all)", sum[k], 'x' + k, mag);
              break;
            }
          if (c->oracle) solid_exact(R, idx, c, g);
        }
        break;
      case F_S_AREA: case F_S_PAIR_AREA: {
        double a;
        memcpy(&a, g[0].p, 8);
        R->oracles[O_SOLID_CONTACT]++;
        if (a < 0) finding(R, V_SOLID, idx, "contact area %.17g", a);
        if (c->oracle) solid_exact(R, idx, c, g);
        break;
      }
      default: break;
      }
      /* ---- the shadow ---- */
      switch (fn) {
      case F_S_SET_MESH: {
        int *t0 = xmalloc(sizeof(int) * 4 * (size_t)c->iv[1] + 1);
        for (int k = 0; k < 4 * c->iv[1]; ++k) t0[k] = ((const int *)c->in[1].p)[k] - c->iv[2];
        ss_new_mesh(s, c->iv[0], c->in[0].p, c->iv[1], t0, c->in[2].p, c->iv[2]);
        free(t0);
        break;
      }
      case F_S_LOAD_GMSH:
        if (c->iv[0] == SG_VALID) ss_gmsh_valid(s, c->iv[1]);
        else ss_clear_mesh(s), s->has_mesh = 1, s->base = c->iv[1];
        break;
      case F_S_SET_FACES: case F_S_ADD_FACES:
        if (s->exact && c->in[0].n >= 3 * c->iv[0] && c->in[1].n >= c->iv[0]) {
          int from = fn == F_S_ADD_FACES ? s->nf : 0, n = c->iv[0];
          s->face = xrealloc(s->face, sizeof(int) * 3 * (size_t)(from + n) + 1);
          s->ftag = xrealloc(s->ftag, sizeof(int) * (size_t)(from + n) + 1);
          for (int k = 0; k < 3 * n; ++k) s->face[3 * from + k] = ((const int *)c->in[0].p)[k] - s->base;
          if (n) memcpy(&s->ftag[from], c->in[1].p, sizeof(int) * (size_t)n);
          s->nf = from + n;
        } else {
          s->exact = 0;
        }
        break;
      case F_S_SET_MATERIAL:
        if (ss_has_material(s, c->iv[0]) == 0) {
          if (s->nmat < 16) s->mat_body[s->nmat] = c->iv[0];
          s->nmat++;
        }
        break;
      case F_S_FIX: case F_S_FIX_FACES:
        s->constrained = 1;
        if (s->exact) {
          for (int v = 0; v < s->nn; ++v) {
            int on = fn == F_S_FIX ? v == c->iv[0] - s->base : 0;
            for (int f = 0; f < s->nf && !on && fn == F_S_FIX_FACES; ++f)
              on = s->ftag[f] == c->iv[0] && (s->face[3 * f] == v || s->face[3 * f + 1] == v || s->face[3 * f + 2] == v);
            if (on) s->presc[3 * v + c->iv[1]] = c->dv[0];
          }
        }
        break;
      case F_S_CLEAR_CONSTRAINTS:
        s->constrained = 0;
        for (int k = 0; s->exact && k < 3 * s->nn; ++k) s->presc[k] = NAN;
        break;
      case F_S_ADD_PRESSURE: case F_S_ADD_TRACTION:
        s->loaded = 1;
        s->load = xrealloc(s->load, sizeof(ss_load) * (size_t)(s->nl + 1));
        s->load[s->nl++] = (ss_load){c->iv[0], fn == F_S_ADD_TRACTION, {c->dv[0], c->dv[1], c->dv[2]}};
        break;
      case F_S_ADD_NODAL_FORCE:
        s->loaded = 1;
        if (s->exact)
          for (int k = 0; k < 3; ++k) s->nforce[3 * (c->iv[0] - s->base) + k] += c->dv[k];
        break;
      case F_S_CLEAR_LOADS:
        s->loaded = 0;
        s->nl = 0;
        if (s->exact) memset(s->nforce, 0, sizeof(double) * 3 * (size_t)s->nn);
        break;
      case F_S_ADD_PAIR:
        if (s->npairs < 16) s->pair_tag[s->npairs][0] = c->iv[0], s->pair_tag[s->npairs][1] = c->iv[1];
        s->npairs++;
        break;
      case F_S_CLEAR_PAIRS: s->npairs = 0; break;
      case F_S_SOLVE: case F_S_SOLVE_CONTACT:
        s->results = 1, s->res_unknown = 0, s->undo = 0, s->sol_gen++;
        break;
      case F_S_STEP:
        s->pre_results = s->results, s->pre_unknown = s->res_unknown;
        s->pre_disp_ok = s->results && s->disp_gen == s->sol_gen;
        s->pre_disp_hash = s->disp_hash, s->pre_disp_idx = s->disp_idx;
        s->results = 2, s->res_unknown = 0, s->undo = 1, s->sol_gen++;
        break;
      case F_S_REVERT_STEP:
        /* the results before the step, their displacements bit for bit */
        if (s->undo == 1) {
          s->results = s->pre_results, s->res_unknown = s->pre_unknown;
          s->sol_gen++;
          if (s->pre_disp_ok) s->disp_hash = s->pre_disp_hash, s->disp_gen = s->sol_gen, s->disp_idx = s->pre_disp_idx;
        } else {
          s->res_unknown = 1, s->sol_gen++;
        }
        s->undo = 0;
        break;
      case F_S_RECREATE:
        ss_clear_mesh(s);
        s->nmat = 0;
        break;
      default: break;
      }
      if (solid_changes_problem(fn)) s->results = 0, s->res_unknown = 0, s->undo = 0, s->sol_gen++;
    }
    if (fn == F_S_DESTROY && !c->handle) {
      ss_clear_mesh(s);
      s->nmat = 0;
    }
    return;
  }
  /* ---- the 3D context ---- */
  if (fn == F_SC_CREATE) {
    int base = c->iv[4], valid = (base == 0 || base == 1) && !solid_options_refused(c);
    R->oracles[O_SOLID_HOST]++;
    if ((st == TFEM_STATUS_OK) != valid)
      finding(R, V_SOLID_HOST, idx, "tfem_solid_contact_create(%d, %s) %s", base, c->in[0].null_ ? "NULL" : "options",
              st ? "returned NULL" : "made a context although its arguments are refused");
    if (st == TFEM_STATUS_OK) {
      s->sc_live = 1, s->sc_base = base, s->sc_nsides = s->sc_npairs = s->sc_built = s->sc_nn = 0;
    }
    return;
  }
  if (FN[fn].model != 4 || !s->sc_live) return;
  int refused = -1;
  if (fn == F_SC_ADD_SIDE) {
    int nn = c->iv[2], nt = c->iv[3], base = s->sc_base;
    const int64_t most = (int64_t)(PTRDIFF_MAX / 8);
    refused = 0;
    if (s->sc_built) refused = 1, snprintf(why, sizeof why, "B is built");
    else if (nn < 0 || nt < 0) refused = 1, snprintf(why, sizeof why, "a negative count");
    else if ((nn > 0 && (c->in[0].null_ || c->in[1].null_ || c->in[2].null_)) || (nt > 0 && c->in[3].null_))
      refused = 1, snprintf(why, sizeof why, "an array NULL");
    else if (!(isfinite(c->dv[0]) && c->dv[0] > 0)) refused = 1, snprintf(why, sizeof why, "Young's modulus %g", c->dv[0]);
    else if (c->in[0].n < nn || c->in[1].n < 3 * nn || c->in[2].n < 3 * nn || c->in[3].n < 3 * nt || s->sc_nn > 512)
      refused = -1;
    else {
      const int *ids = c->in[0].p, *tri = c->in[3].p;
      const double *x = c->in[1].p;
      const int64_t *eq = c->in[2].p;
      for (int i = 0; i < nn && refused == 0; ++i) {
        if (ids[i] < base) {
          refused = 1, snprintf(why, sizeof why, "node %d below the index base", ids[i]);
          break;
        }
        for (int k = 0; k < 3; ++k)
          if (!isfinite(x[3 * i + k])) refused = 1, snprintf(why, sizeof why, "node %d at a non-finite coordinate", ids[i]);
        for (int k = 0; k < 3; ++k)
          if (eq[3 * i + k] >= (int64_t)base + most) refused = 1, snprintf(why, sizeof why, "an equation beyond any vector");
        if (refused) break;
        for (int v = 0; v < s->sc_nn; ++v)
          if (s->sc_ids[v] == ids[i]) {
            int same = 1;
            for (int k = 0; k < 3; ++k)
              same &= x[3 * i + k] == s->sc_xyz[v][k] && (eq[3 * i + k] < base ? -1 : eq[3 * i + k] - base) == s->sc_eq[v][k];
            if (!same) refused = 1, snprintf(why, sizeof why, "node %d given before with other coordinates or equations", ids[i]);
          }
        for (int j = 0; j < i && refused == 0; ++j)
          if (ids[j] == ids[i]) {
            int same = 1;
            for (int k = 0; k < 3; ++k)
              same &= x[3 * i + k] == x[3 * j + k] &&
                      (eq[3 * i + k] < base ? -1 : eq[3 * i + k] - base) == (eq[3 * j + k] < base ? -1 : eq[3 * j + k] - base);
            if (!same) refused = 1, snprintf(why, sizeof why, "node %d given twice with other coordinates or equations", ids[i]);
          }
      }
      for (int k = 0; k < 3 * nt && refused == 0; ++k) {
        int found = 0;
        for (int i = 0; i < nn && !found; ++i) found = ids[i] == tri[k];
        if (!found) refused = 1, snprintf(why, sizeof why, "a triangle over node %d, which the side does not give", tri[k]);
      }
      if (refused == 0 && nt == 0) refused = 1, snprintf(why, sizeof why, "no triangle");
    }
    if (st == TFEM_STATUS_OK && !c->out[0].null_) {
      int side;
      memcpy(&side, g[0].p, 4);
      if (side != s->sc_nsides + s->sc_base)
        finding(R, V_SOLID_HOST, idx, "side number %d, %d sides were added before (index base %d)", side, s->sc_nsides, s->sc_base);
    }
    if (st == TFEM_STATUS_OK) {
      if (s->sc_nsides < 64) s->sc_side_body[s->sc_nsides] = c->iv[1];
      s->sc_nsides++;
      const int *ids = c->in[0].p;
      const double *x = c->in[1].p;
      const int64_t *eq = c->in[2].p;
      for (int i = 0; i < nn && c->in[0].n >= nn && c->in[1].n >= 3 * nn && c->in[2].n >= 3 * nn && s->sc_nn <= 512; ++i) {
        int known = 0;
        for (int v = 0; v < s->sc_nn && !known; ++v) known = s->sc_ids[v] == ids[i];
        if (known) continue;
        if (s->sc_nn == 512) {
          s->sc_nn++;
          break;
        }
        int v = s->sc_nn++;
        s->sc_ids[v] = ids[i];
        for (int k = 0; k < 3; ++k) s->sc_xyz[v][k] = x[3 * i + k], s->sc_eq[v][k] = eq[3 * i + k] < s->sc_base ? -1 : eq[3 * i + k] - s->sc_base;
      }
    }
  } else if (fn == F_SC_ADD_PAIR) {
    long a = (long)c->iv[0] - s->sc_base, b = (long)c->iv[1] - s->sc_base;
    refused = s->sc_built || a < 0 || b < 0 || a >= s->sc_nsides || b >= s->sc_nsides ||
              (a < 64 && b < 64 && s->sc_side_body[a] == s->sc_side_body[b]);
    if (s->sc_nsides > 64) refused = -1;
    snprintf(why, sizeof why, "sides %d and %d of %d%s", c->iv[0], c->iv[1], s->sc_nsides, s->sc_built ? ", B built" : "");
    if (st == TFEM_STATUS_OK && !c->out[0].null_) {
      int p;
      memcpy(&p, g[0].p, 4);
      if (p != s->sc_npairs + s->sc_base)
        finding(R, V_SOLID_HOST, idx, "pair number %d, %d pairs were added before (index base %d)", p, s->sc_npairs, s->sc_base);
    }
    if (st == TFEM_STATUS_OK) s->sc_npairs++;
  } else if (sc_builds(fn) && s->sc_npairs == 0) {
    refused = 1, snprintf(why, sizeof why, "no contact pair");
    if (st != TFEM_STATUS_OK && st != TFEM_STATUS_INVALID_STATE && st != TFEM_STATUS_NULL_POINTER &&
        st != TFEM_STATUS_INVALID_ARGUMENT && st != TFEM_STATUS_BUFFER_TOO_SMALL)
      finding(R, V_SOLID_HOST, idx, "%s without a pair: \"%.160s\"", status_name(st), msg);
  }
  if (refused >= 0) {
    R->oracles[O_SOLID_HOST]++;
    if (refused && st == TFEM_STATUS_OK) finding(R, V_SOLID_HOST, idx, "OK although %s (the header: refused)", why);
    else if (!refused && st != TFEM_STATUS_OK && st != TFEM_STATUS_OUT_OF_MEMORY)
      finding(R, V_SOLID_HOST, idx, "%s refused (%s): \"%.160s\"", why[0] ? why : "a valid call", status_name(st), msg);
  }
  if (c->want && R->pristine && idx < R->full_prefix && st != c->want - 1)
    finding(R, V_SOLID_HOST, idx, "%s, the scene expects %s: \"%.160s\"", status_name(st), status_name(c->want - 1), msg);
  if (st != TFEM_STATUS_OK) return;
  if (sc_builds(fn)) s->sc_built = 1;
  if (fn == F_SC_SIZES && !c->out[0].null_ && ssc_nodes(R) >= 0) {
    int n;
    memcpy(&n, g[0].p, 4);
    R->oracles[O_SOLID_HOST]++;
    if (n != ssc_nodes(R)) finding(R, V_SOLID_HOST, idx, "%d interface nodes, the sides gave %d", n, ssc_nodes(R));
  }
  if (fn == F_SC_NODES && out_full(c, 0) && ssc_nodes(R) >= 0 && c->out[0].req == ssc_nodes(R)) {
    R->oracles[O_SOLID_HOST]++;
    if (memcmp(g[0].p, s->sc_ids, sizeof(int) * (size_t)ssc_nodes(R)) != 0)
      finding(R, V_SOLID_HOST, idx, "the interface nodes are not in the order the sides first gave them");
  }
  if (fn == F_SC_GET_ACTIVE && out_full(c, 0))
    for (long k = 0; k < c->out[0].req; ++k) {
      int v;
      memcpy(&v, g[0].p + sizeof(int) * (size_t)k, sizeof v);
      if (v != 0 && v != 1) {
        finding(R, V_SOLID_HOST, idx, "active flag %ld = %d", k, v);
        break;
      }
    }
  int full0 = out_full(c, 0);
  if ((fn == F_SC_PATTERN && full0 && out_full(c, 1)) || (fn == F_SC_EVALUATE && full0) ||
      ((fn == F_SC_GATHER || fn == F_SC_SCATTER_ADD) && full0 && !c->in[0].null_) ||
      (fn == F_SC_SET_ACTIVE && !c->in[0].null_) || fn == F_SC_UPDATE || (fn == F_SC_AREA && !c->out[0].null_))
    oracle_solid_host(R, idx, c, g);
  if (fn == F_SC_DESTROY && !c->handle) s->sc_live = 0;
}
/* Keeps the outputs of an OK call for the replay; frees the buffers. */
static void keep_outputs(call_t *c, int st, int nout, const char *ver, gbuf *g) {
  if (st == TFEM_STATUS_OK) {
    if (c->fn == F_VERSION && ver) {
      c->saved[0] = (unsigned char *)strdup(ver);
    } else {
      for (int j = 0; j < nout; ++j)
        if (!c->out[j].null_) c->saved[j] = out_bytes(&g[j], &c->saved_n[j]);
    }
  }
  for (int j = 0; j < nout; ++j) free(g[j].blk);
}

static void exec_call(runner_t *R, int idx) {
  call_t *c = &R->cs->c[idx];
  int fn = c->fn;
  if (fn == F_TWIN) { /* not a call of the library: the twin oracle (original run only) */
    if (R->phase == 0) {
      c->status = TFEM_STATUS_OK;
      c->ran = 1;
      if (R->cfile) fprintf(R->cfile, "  /* #%d: api_fuzz compares with a twin model here (mode %d) */\n", idx, c->iv[0]);
      if (R->verbose) printf("  #%-3d %-34s -> (oracle)\n", idx, fn_name(fn));
      if (R->pristine && idx < R->full_prefix) oracle_twin(R, idx, c);
    }
    return;
  }
  /* (a context's call without a context passes NULL; so does a 3D call
   * once the 3D model is destroyed; a handle of the call's own kind is its
   * own) */
  if (R->phase == 0 && c->handle == FN[fn].model) c->handle = 0;
  if (R->phase == 0 && ((c->handle == 1 && !R->m) || (c->handle == 2 && !R->octx) || (c->handle == 3 && !R->sm) ||
                        (c->handle == 4 && !R->sctx)))
    c->handle = 0, c->null_model = 1; /* (no handle of that kind: NULL) */
  if (R->phase == 0 && !c->handle &&
      ((FN[fn].model == 2 && !R->ctx) || (FN[fn].model == 3 && !R->sm) || (FN[fn].model == 4 && !R->sctx)))
    c->null_model = 1;
  tfem_model *m = c->null_model ? NULL : R->m;
  tfem_contact *hc = c->null_model ? NULL : R->ctx;
  tfem_solid_model *sm = c->null_model ? NULL : R->sm;
  tfem_solid_contact *sx = c->null_model ? NULL : R->sctx;
  if (R->phase == 0) {
    resolve_outputs(R, c);
    if (fn == F_CONTACT_PATTERN || fn == F_SC_PATTERN) c->out[1].len = c->out[0].len; /* (one length for both) */
    if (fn == F_GET_CONTACT_SLAVE_NODES) { /* (one length for the four: the last one not exact, else the first's) */
      size_t L = c->out[0].len;
      for (int j = 0; j < 4; ++j)
        if (c->out[j].ls != LS_EXACT) L = c->out[j].len;
      for (int j = 0; j < 4; ++j) c->out[j].len = L;
    }
    if (fn == F_GET_ADAPT_CYCLES) { /* (one length for the three, as for the slave nodes) */
      size_t L = c->out[0].len;
      for (int j = 0; j < 3; ++j)
        if (c->out[j].ls != LS_EXACT) L = c->out[j].len;
      for (int j = 0; j < 3; ++j) c->out[j].len = L;
    }
    if (FN[fn].model == 4) make_solid_inputs(R, c, idx);
    else make_inputs(R, c, idx);
  }
  const void *in[MAXIN];
  for (int j = 0; j < MAXIN; ++j) in[j] = c->in[j].null_ ? NULL : c->in[j].p;
  tfem_contact_options opts = {c->iv[0], c->dv[0], c->dv[1], c->iv[1], c->iv[2], c->iv[3]};
  gbuf g[MAXOUT];
  void *o[MAXOUT] = {0};
  int nout = fn_nout(fn);
  for (int j = 0; j < nout; ++j) {
    gb_alloc(&g[j], out_kind(fn, j), c->out[j].len);
    o[j] = c->out[j].null_ ? NULL : g[j].p;
  }
  /* tfem_contact_scatter_add adds to the host's vector: it starts with the values made for it */
  if ((fn == F_CONTACT_SCATTER_ADD || fn == F_SC_SCATTER_ADD) && c->in[1].p && g[0].n <= (size_t)c->in[1].n)
    memcpy(g[0].p, c->in[1].p, sizeof(double) * g[0].n);
  size_t ulen = c->in[0].n > 0 ? (size_t)c->in[0].n : 0;
  size_t lel = 0;
  const char *ver = NULL;
  const char *path = NULL;
  if (fn == F_LOAD_GMSH && c->iv[0] >= 0 && c->iv[0] < NGMSH) path = g_path[c->iv[0]];
  if (fn == F_S_LOAD_GMSH && c->iv[0] >= 0 && c->iv[0] < NSG) path = sg_path[c->iv[0]];
  char vbuf[600];
  if (fn == F_WRITE_VTU || fn == F_S_WRITE_VTU) {
    path = vtu_path(c->iv[0], R->cs->index, idx, vbuf, sizeof vbuf);
    if (vtu_writable(c->iv[0])) unlink(path); /* (left by a child that died) */
  }
  if (R->cfile && R->phase == 0) {
    c_emit_call(R->cfile, c, idx);
    fflush(R->cfile);
  }
  if (R->verbose && R->phase == 0) {
    printf("  #%-3d %-34s", idx, fn_name(fn));
    fflush(stdout);
  }
  /* a handle of another kind, or destroyed (made last: nothing is made
   * between its destruction and the call) */
  void *hp = NULL;
  if (c->handle && !c->null_model && FN[fn].model) {
    hp = call_handle(R, c);
    m = hp, hc = hp, sm = hp, sx = hp;
  }
  off_t e0 = fd_size(2);
  int st = TFEM_STATUS_OK;
  switch (fn) {
  case F_VERSION: ver = tfem_version(); break;
  case F_LAST_ERROR: st = tfem_last_error(m, o[0], c->out[0].len); break;
  case F_LAST_ERROR_LENGTH: lel = tfem_last_error_length(m); break;
  case F_WARNING_COUNT: st = tfem_warning_count(m, o[0]); break;
  case F_GET_WARNING: st = tfem_get_warning(m, c->iv[0], o[0], c->out[0].len); break;
  case F_SET_MESH: st = tfem_set_mesh(m, c->iv[0], in[0], c->iv[1], in[1], in[2], c->iv[2]); break;
  case F_LOAD_GMSH: st = tfem_load_gmsh(m, path, c->iv[1]); break;
  case F_SET_BOUNDARY_EDGES: st = tfem_set_boundary_edges(m, c->iv[0], in[0], in[1]); break;
  case F_SET_MATERIAL: st = tfem_set_material(m, c->iv[0], c->dv[0], c->dv[1], c->iv[1]); break;
  case F_SET_TEMPERING: st = tfem_set_tempering(m, c->iv[0], c->dv[0]); break;
  case F_SET_ORDERING: st = tfem_set_ordering(m, c->iv[0], c->iv[1]); break;
  case F_FIX: st = tfem_fix(m, c->iv[0], c->iv[1], c->dv[0]); break;
  case F_FIX_EDGES: st = tfem_fix_edges(m, c->iv[0], c->iv[1], c->dv[0]); break;
  case F_CLEAR_CONSTRAINTS: st = tfem_clear_constraints(m); break;
  case F_ADD_PRESSURE: st = tfem_add_pressure(m, c->iv[0], c->dv[0]); break;
  case F_ADD_TRACTION: st = tfem_add_traction(m, c->iv[0], c->dv[0], c->dv[1]); break;
  case F_ADD_NODAL_FORCE: st = tfem_add_nodal_force(m, c->iv[0], c->dv[0], c->dv[1]); break;
  case F_SET_BODY_FORCE: st = tfem_set_body_force(m, c->iv[0], c->dv[0], c->dv[1]); break;
  case F_CLEAR_LOADS: st = tfem_clear_loads(m); break;
  case F_SOLVE: st = tfem_solve(m, o[0]); break;
  case F_GET_SIZES: st = tfem_get_sizes(m, o[0], o[1], o[2]); break;
  case F_GET_DISPLACEMENTS: st = tfem_get_displacements(m, o[0], c->out[0].len); break;
  case F_GET_STRAINS: st = tfem_get_element_strains(m, o[0], c->out[0].len); break;
  case F_GET_STRESSES: st = tfem_get_element_stresses(m, o[0], c->out[0].len); break;
  case F_GET_JACOBIANS: st = tfem_get_element_jacobians(m, o[0], c->out[0].len); break;
  case F_GET_REACTIONS: st = tfem_get_reactions(m, o[0], c->out[0].len); break;
  case F_GET_MATRIX_SIZE: st = tfem_get_system_matrix_size(m, o[0], o[1]); break;
  case F_GET_MATRIX:
    st = tfem_get_system_matrix(m, o[0], c->out[0].len, o[1], c->out[1].len, o[2], c->out[2].len, o[3],
                                c->out[3].len);
    break;
  case F_ELEMENT_STIFFNESS: st = tfem_element_stiffness(in[0], c->dv[0], c->dv[1], c->iv[0], c->dv[2], o[0]); break;
  case F_LAPLACIAN_STIFFNESS: st = tfem_laplacian_stiffness(in[0], c->dv[0], c->dv[1], o[0]); break;
  case F_ADD_CONTACT_PAIR: st = tfem_add_contact_pair(m, c->iv[0], c->iv[1], o[0]); break;
  case F_ADD_CONTACT_PAIR_WITH_MESH:
    st = tfem_add_contact_pair_with_mesh(m, c->iv[0], c->iv[1], c->iv[2], in[0], o[0], o[1]);
    break;
  case F_CONTACT_OPTIONS_DEFAULT: st = tfem_contact_options_default(o[0]); break;
  case F_SOLVE_CONTACT: st = tfem_solve_contact(m, c->in[0].null_ ? NULL : &opts, o[0]); break;
  case F_GET_CONTACT_ACTIVE: st = tfem_get_contact_active(m, o[0], c->out[0].len); break;
  case F_GET_CONTACT_PRESSURE: st = tfem_get_contact_pressure(m, o[0], c->out[0].len); break;
  case F_GET_CONTACT_ELEMENTS: st = tfem_get_contact_elements(m, o[0], c->out[0].len); break;
  case F_GET_CONTACT_REPORT: st = tfem_get_contact_report(m, o[0]); break;
  case F_ADD_BOUNDARY_EDGES: st = tfem_add_boundary_edges(m, c->iv[0], in[0], in[1]); break;
  case F_GET_EXTERNAL_WORK: st = tfem_get_external_work(m, o[0]); break;
  case F_GET_CONTACT_FORCES: st = tfem_get_contact_forces(m, o[0], c->out[0].len); break;
  case F_GET_CONTACT_GAPS: st = tfem_get_contact_gaps(m, o[0], c->out[0].len); break;
  case F_GET_CONTACT_NODAL_PRESSURES: st = tfem_get_contact_nodal_pressures(m, o[0], c->out[0].len); break;
  case F_GET_CONTACT_PAIR_NODAL_PRESSURES:
    st = tfem_get_contact_pair_nodal_pressures(m, c->iv[0], o[0], c->out[0].len);
    break;
  case F_GET_CONTACT_MESH_SIZE: st = tfem_get_contact_mesh_size(m, o[0]); break;
  case F_GET_CONTACT_MESH: st = tfem_get_contact_mesh(m, o[0], c->out[0].len); break;
  case F_GET_CONTACT_ELEMENT_PAIRS: st = tfem_get_contact_element_pairs(m, o[0], c->out[0].len); break;
  case F_GET_CONTACT_ELEMENT_APEXES: st = tfem_get_contact_element_apexes(m, o[0], c->out[0].len); break;
  case F_GET_CONTACT_PAIR_BODIES: st = tfem_get_contact_pair_bodies(m, c->iv[0], o[0], o[1]); break;
  case F_SET_THREADS: st = tfem_set_threads(m, c->iv[0]); break;
  case F_GET_THREADS: st = tfem_get_threads(m, o[0]); break;
  case F_STEP: st = tfem_step(m, c->dv[2], c->in[0].null_ ? NULL : &opts, o[0]); break;
  case F_REVERT_STEP: st = tfem_revert_step(m); break;
  case F_GET_CONTACT_STATE_SIZE: st = tfem_get_contact_state_size(m, o[0]); break;
  case F_GET_CONTACT_STATE: st = tfem_get_contact_state(m, o[0], c->out[0].len); break;
  case F_SET_CONTACT_STATE: st = tfem_set_contact_state(m, in[0], ulen); break;
  case F_CONTACT_CREATE: {
    tfem_contact *nc = tfem_contact_create(c->iv[0]);
    if (nc) {
      tfem_contact_destroy(R->ctx);
      R->ctx = nc;
      R->cbase = c->iv[0];
      R->cbuilt = 0;
      R->ctx_ring = -1;
    } else {
      st = TFEM_STATUS_INVALID_ARGUMENT; /* (NULL: the message is the thread's) */
    }
    break;
  }
  case F_CONTACT_DESTROY:
    tfem_contact_destroy(hc);
    if (hc && !c->handle) R->ctx = NULL, R->cbuilt = 0;
    break;
  case F_CONTACT_LAST_ERROR: st = tfem_contact_last_error(hc, o[0], c->out[0].len); break;
  case F_CONTACT_SET_OPTIONS: st = tfem_contact_set_options(hc, c->in[0].null_ ? NULL : &opts); break;
  case F_CONTACT_ADD_SIDE:
    st = tfem_contact_add_side(hc, c->iv[0], c->iv[1], c->dv[0], c->dv[1], c->iv[2], c->iv[3], in[0], in[1], in[2],
                               c->iv[4], in[3], o[0]);
    break;
  case F_CONTACT_ADD_PAIR: st = tfem_contact_add_pair(hc, c->iv[0], c->iv[1], o[0]); break;
  case F_CONTACT_ADD_PAIR_WITH_MESH: st = tfem_contact_add_pair_with_mesh(hc, c->iv[0], c->iv[1], c->iv[2], in[0], o[0]); break;
  case F_CONTACT_SIZES: st = tfem_contact_sizes(hc, o[0], o[1], o[2]); break;
  case F_CONTACT_NODES: st = tfem_contact_nodes(hc, o[0], c->out[0].len); break;
  case F_CONTACT_PATTERN: st = tfem_contact_pattern(hc, o[0], o[1], c->out[0].len); break;
  case F_CONTACT_EVALUATE:
    st = tfem_contact_evaluate(hc, in[0], ulen, o[0], c->out[0].len, o[1], c->out[1].len);
    break;
  case F_CONTACT_GATHER: st = tfem_contact_gather(hc, in[0], ulen, o[0], c->out[0].len); break;
  case F_CONTACT_SCATTER_ADD: st = tfem_contact_scatter_add(hc, in[0], ulen, o[0], c->out[0].len); break;
  case F_CONTACT_UPDATE: st = tfem_contact_update(hc, in[0], ulen, o[0]); break;
  case F_CONTACT_RESTART: st = tfem_contact_restart(hc); break;
  case F_CONTACT_GET_ACTIVE: st = tfem_contact_get_active(hc, o[0], c->out[0].len); break;
  case F_CONTACT_SET_ACTIVE: st = tfem_contact_set_active(hc, in[0], ulen); break;
  case F_CONTACT_GAPS: st = tfem_contact_gaps(hc, in[0], ulen, o[0], c->out[0].len); break;
  case F_CONTACT_PRESSURES: st = tfem_contact_pressures(hc, in[0], ulen, o[0], c->out[0].len); break;
  case F_CONTACT_ELEMENTS: st = tfem_contact_elements(hc, o[0], c->out[0].len); break;
  case F_CONTACT_ELEMENT_EQUATIONS: st = tfem_contact_element_equations(hc, o[0], c->out[0].len); break;
  case F_CONTACT_ELEMENT_BLOCKS: st = tfem_contact_element_blocks(hc, o[0], c->out[0].len); break;
  case F_CONTACT_LENGTH: st = tfem_contact_length(hc, o[0]); break;
  case F_GET_CONTACT_SHEAR: st = tfem_get_contact_shear(m, o[0], c->out[0].len); break;
  case F_GET_CONTACT_FRICTION_STATE: st = tfem_get_contact_friction_state(m, o[0], c->out[0].len); break;
  case F_GET_CONTACT_DISSIPATION: st = tfem_get_contact_dissipation(m, o[0], c->out[0].len); break;
  case F_SET_FRICTION: st = tfem_set_friction(m, c->iv[0], c->dv[0]); break;
  case F_SET_PRESCRIBED: st = tfem_set_prescribed(m, c->iv[0], c->iv[1], c->dv[0]); break;
  case F_ADD_CONTACT_PAIRS_AUTO: st = tfem_add_contact_pairs_auto(m, c->iv[0], in[0], c->dv[0], o[0], o[1]); break;
  case F_WRITE_VTU: st = tfem_write_vtu(m, path); break;
  case F_GET_WARNING_SIZE: st = tfem_get_warning_size(m, c->iv[0], o[0]); break;
  case F_CONTACT_LAST_ERROR_LENGTH: lel = tfem_contact_last_error_length(hc); break;
  case F_SET_CONTACT_WEIGHTING: st = tfem_set_contact_weighting(m, c->iv[0]); break;
  case F_GET_CONTACT_WEIGHTING: st = tfem_get_contact_weighting(m, o[0]); break;
  case F_GET_CONTACT_SLAVE_NODES:
    st = tfem_get_contact_slave_nodes(m, o[0], o[1], o[2], o[3], c->out[0].len);
    break;
  case F_GET_OUT_OF_PLANE: st = tfem_get_element_out_of_plane_stresses(m, o[0], c->out[0].len); break;
  case F_SOLVE_ADAPTIVE:
    st = tfem_solve_adaptive(m, c->dv[2], c->iv[4], adapt_max_unknowns(c->iv[6]), c->iv[5], c->in[0].null_ ? NULL : &opts,
                             o[0]);
    break;
  case F_GET_ADAPT_CYCLES: st = tfem_get_adapt_cycles(m, o[0], o[1], o[2], c->out[0].len); break;
  case F_SET_BOUNDARY_CIRCLE: st = tfem_set_boundary_circle(m, c->iv[0], c->dv[0], c->dv[1], c->dv[2]); break;
  /* the 3D model */
  case F_S_LAST_ERROR: st = tfem_solid_last_error(sm, o[0], c->out[0].len); break;
  case F_S_LAST_ERROR_LENGTH: lel = tfem_solid_last_error_length(sm); break;
  case F_S_WARNING_COUNT: st = tfem_solid_warning_count(sm, o[0]); break;
  case F_S_GET_WARNING_SIZE: st = tfem_solid_get_warning_size(sm, c->iv[0], o[0]); break;
  case F_S_GET_WARNING: st = tfem_solid_get_warning(sm, c->iv[0], o[0], c->out[0].len); break;
  case F_S_SET_MESH: st = tfem_solid_set_mesh(sm, c->iv[0], in[0], c->iv[1], in[1], in[2], c->iv[2]); break;
  case F_S_LOAD_GMSH: st = tfem_solid_load_gmsh(sm, path, c->iv[1]); break;
  case F_S_SET_FACES: st = tfem_solid_set_boundary_faces(sm, c->iv[0], in[0], in[1]); break;
  case F_S_ADD_FACES: st = tfem_solid_add_boundary_faces(sm, c->iv[0], in[0], in[1]); break;
  case F_S_GET_SIZES: st = tfem_solid_get_sizes(sm, o[0], o[1], o[2]); break;
  case F_S_FACE_COUNT: st = tfem_solid_get_boundary_face_count(sm, o[0]); break;
  case F_S_MESH_NODES: st = tfem_solid_get_mesh_nodes(sm, o[0], c->out[0].len); break;
  case F_S_MESH_TETS: st = tfem_solid_get_mesh_tetrahedra(sm, o[0], c->out[0].len, o[1], c->out[1].len); break;
  case F_S_GET_FACES: st = tfem_solid_get_boundary_faces(sm, o[0], c->out[0].len, o[1], c->out[1].len); break;
  case F_S_SET_MATERIAL: st = tfem_solid_set_material(sm, c->iv[0], c->dv[0], c->dv[1]); break;
  case F_S_SET_TEMPERING: st = tfem_solid_set_tempering(sm, c->iv[0], c->dv[0]); break;
  case F_S_SET_ORDERING: st = tfem_solid_set_ordering(sm, c->iv[0]); break;
  case F_S_FIX: st = tfem_solid_fix(sm, c->iv[0], c->iv[1], c->dv[0]); break;
  case F_S_FIX_FACES: st = tfem_solid_fix_faces(sm, c->iv[0], c->iv[1], c->dv[0]); break;
  case F_S_CLEAR_CONSTRAINTS: st = tfem_solid_clear_constraints(sm); break;
  case F_S_ADD_PRESSURE: st = tfem_solid_add_pressure(sm, c->iv[0], c->dv[0]); break;
  case F_S_ADD_TRACTION: st = tfem_solid_add_traction(sm, c->iv[0], c->dv[0], c->dv[1], c->dv[2]); break;
  case F_S_ADD_NODAL_FORCE: st = tfem_solid_add_nodal_force(sm, c->iv[0], c->dv[0], c->dv[1], c->dv[2]); break;
  case F_S_CLEAR_LOADS: st = tfem_solid_clear_loads(sm); break;
  case F_S_ADD_PAIR: st = tfem_solid_add_contact_pair(sm, c->iv[0], c->iv[1], o[0]); break;
  case F_S_CLEAR_PAIRS: st = tfem_solid_clear_contact_pairs(sm); break;
  case F_S_SOLVE: st = tfem_solid_solve(sm, o[0]); break;
  case F_S_SOLVE_CONTACT: st = tfem_solid_solve_contact(sm, c->in[0].null_ ? NULL : &opts, o[0]); break;
  case F_S_STEP: st = tfem_solid_step(sm, c->dv[2], c->in[0].null_ ? NULL : &opts, o[0]); break;
  case F_S_REVERT_STEP: st = tfem_solid_revert_step(sm); break;
  case F_S_SOLVE_INFO: st = tfem_solid_get_solve_info(sm, o[0]); break;
  case F_S_ITERATIONS: st = tfem_solid_get_iterations(sm, o[0]); break;
  case F_S_DISPLACEMENTS: st = tfem_solid_get_displacements(sm, o[0], c->out[0].len); break;
  case F_S_STRAINS: st = tfem_solid_get_element_strains(sm, o[0], c->out[0].len); break;
  case F_S_STRESSES: st = tfem_solid_get_element_stresses(sm, o[0], c->out[0].len); break;
  case F_S_REACTIONS: st = tfem_solid_get_reactions(sm, o[0], c->out[0].len); break;
  case F_S_WORK: st = tfem_solid_get_external_work(sm, o[0]); break;
  case F_S_CONTACT_TETS: st = tfem_solid_get_contact_tetrahedra(sm, o[0], c->out[0].len); break;
  case F_S_CONTACT_ACTIVE: st = tfem_solid_get_contact_active(sm, o[0], c->out[0].len); break;
  case F_S_CONTACT_FORCES: st = tfem_solid_get_contact_forces(sm, o[0], c->out[0].len); break;
  case F_S_NODAL_PRESSURES: st = tfem_solid_get_contact_nodal_pressures(sm, o[0], c->out[0].len); break;
  case F_S_AREA: st = tfem_solid_get_contact_area(sm, o[0]); break;
  case F_S_PAIR_AREA: st = tfem_solid_get_contact_pair_area(sm, c->iv[0], o[0]); break;
  case F_S_WRITE_VTU: st = tfem_solid_write_vtu(sm, path); break;
  case F_S_DESTROY:
    tfem_solid_destroy(sm);
    if (sm && !c->handle) R->sm = NULL;
    break;
  case F_S_RECREATE:
    tfem_solid_destroy(R->sm);
    R->sm = tfem_solid_create();
    break;
  /* the 3D contact context */
  case F_SC_CREATE: {
    tfem_solid_contact *nc = tfem_solid_contact_create(c->iv[4], c->in[0].null_ ? NULL : &opts);
    if (nc) {
      tfem_solid_contact_destroy(R->sctx);
      R->sctx = nc;
    } else {
      st = TFEM_STATUS_INVALID_ARGUMENT; /* (NULL: the message is the thread's) */
    }
    break;
  }
  case F_SC_DESTROY:
    tfem_solid_contact_destroy(sx);
    if (sx && !c->handle) R->sctx = NULL;
    break;
  case F_SC_LAST_ERROR: st = tfem_solid_contact_last_error(sx, o[0], c->out[0].len); break;
  case F_SC_LAST_ERROR_LENGTH: lel = tfem_solid_contact_last_error_length(sx); break;
  case F_SC_ADD_SIDE:
    st = tfem_solid_contact_add_side(sx, c->iv[0], c->iv[1], c->dv[0], c->iv[2], in[0], in[1], in[2], c->iv[3], in[3], o[0]);
    break;
  case F_SC_ADD_PAIR: st = tfem_solid_contact_add_pair(sx, c->iv[0], c->iv[1], o[0]); break;
  case F_SC_SETUP: st = tfem_solid_contact_setup(sx); break;
  case F_SC_SIZES: st = tfem_solid_contact_sizes(sx, o[0], o[1], o[2]); break;
  case F_SC_NODES: st = tfem_solid_contact_nodes(sx, o[0], c->out[0].len); break;
  case F_SC_TETS: st = tfem_solid_contact_tetrahedra(sx, o[0], c->out[0].len); break;
  case F_SC_PATTERN: st = tfem_solid_contact_pattern(sx, o[0], o[1], c->out[0].len); break;
  case F_SC_ELEMENT_EQUATIONS: st = tfem_solid_contact_element_equations(sx, o[0], c->out[0].len); break;
  case F_SC_ELEMENT_BLOCKS: st = tfem_solid_contact_element_blocks(sx, o[0], c->out[0].len); break;
  case F_SC_EVALUATE:
    st = tfem_solid_contact_evaluate(sx, in[0], ulen, o[0], c->out[0].len, o[1], c->out[1].len);
    break;
  case F_SC_GATHER: st = tfem_solid_contact_gather(sx, in[0], ulen, o[0], c->out[0].len); break;
  case F_SC_SCATTER_ADD: st = tfem_solid_contact_scatter_add(sx, in[0], ulen, o[0], c->out[0].len); break;
  case F_SC_UPDATE: st = tfem_solid_contact_update(sx, in[0], ulen, o[0], o[1], o[2]); break;
  case F_SC_RESTART: st = tfem_solid_contact_restart(sx); break;
  case F_SC_GET_ACTIVE: st = tfem_solid_contact_get_active(sx, o[0], c->out[0].len); break;
  case F_SC_SET_ACTIVE: st = tfem_solid_contact_set_active(sx, in[0], ulen); break;
  case F_SC_GAPS: st = tfem_solid_contact_gaps(sx, in[0], ulen, o[0], c->out[0].len); break;
  case F_SC_AREA: st = tfem_solid_contact_area(sx, o[0]); break;
  case F_DESTROY_NULL: tfem_destroy(NULL); break;
  case F_RECREATE:
    tfem_destroy(R->m);
    R->m = tfem_create();
    break;
  default: break;
  }
  off_t e1 = fd_size(2);
  /* The .vtu written: read (original run) and removed at once. */
  char *vtu = NULL;
  size_t vtu_n = 0;
  int vtu_found = 0;
  if ((fn == F_WRITE_VTU || fn == F_S_WRITE_VTU) && path && vtu_writable(c->iv[0])) {
    FILE *vf = fopen(path, "rb");
    if (vf) {
      vtu_found = 1;
      if (R->phase == 0) {
        size_t cap = 1 << 16;
        vtu = xmalloc(cap + 1);
        size_t k;
        while ((k = fread(vtu + vtu_n, 1, cap - vtu_n, vf)) > 0) {
          vtu_n += k;
          if (vtu_n == cap && cap < ((size_t)1 << 26)) vtu = xrealloc(vtu, (cap *= 2) + 1);
          else if (vtu_n == cap) break;
        }
        vtu[vtu_n] = 0;
      }
      fclose(vf);
    }
    unlink(path);
  }

  if (R->phase == 1) {
    /* Replay: the same call must succeed again with the same outputs. */
    int v = V_NONDET, known = 0;
    for (int k = 0; k < idx; ++k) {
      if (R->cs->c[k].status != TFEM_STATUS_OK) v = V_STATE;
      known |= !API_FUZZ_ADAPT_FAILURE_RESTORES && R->cs->c[k].fn == F_SOLVE_ADAPTIVE && R->cs->c[k].ran &&
               !R->cs->c[k].null_model && R->cs->c[k].status != TFEM_STATUS_OK &&
               (R->cs->c[k].status != TFEM_STATUS_INVALID_ARGUMENT ||
                R->cs->c[k].refine_refused); /* (the defect above, when not checked) */
    }
    if (known) {
      for (int j = 0; j < nout; ++j) free(g[j].blk);
      free(vtu);
      return;
    }
    char why[400] = "";
    if (st != TFEM_STATUS_OK) {
      char msg[300] = "";
      if (c->handle) tfem_last_error(NULL, msg, sizeof msg);
      else if (FN[fn].model == 2 && hc) tfem_contact_last_error(hc, msg, sizeof msg);
      else if (FN[fn].model == 3 && sm) tfem_solid_last_error(sm, msg, sizeof msg);
      else if (FN[fn].model == 4 && sx) tfem_solid_contact_last_error(sx, msg, sizeof msg);
      else tfem_last_error(FN[fn].model == 1 && !c->null_model ? R->m : NULL, msg, sizeof msg);
      snprintf(why, sizeof why, "OK originally, %s (%d) on replay without the failed calls: %s", status_name(st), st, msg);
      R->status_flips++;
    } else if (fn == F_VERSION) {
      if (!ver || strcmp(ver, (const char *)c->saved[0]) != 0) snprintf(why, sizeof why, "version string differs");
    } else if (fn != F_LAST_ERROR && fn != F_LAST_ERROR_LENGTH) {
      for (int j = 0; j < nout && !why[0]; ++j) {
        if (c->out[j].null_) continue;
        size_t nb;
        unsigned char *b = out_bytes(&g[j], &nb);
        if (nb != c->saved_n[j] || memcmp(b, c->saved[j], nb) != 0) {
          size_t first = 0, es = ksize(g[j].kind);
          while (first < nb && b[first] == c->saved[j][first]) ++first;
          if (g[j].kind == K_D) {
            size_t e = first / 8;
            double a, bb;
            memcpy(&a, c->saved[j] + 8 * e, 8);
            memcpy(&bb, b + 8 * e, 8);
            snprintf(why, sizeof why, "output %d differs at element %zu: %.17g originally, %.17g on replay", j, e, a, bb);
          } else {
            snprintf(why, sizeof why, "output %d differs at byte %zu (element %zu)", j, first, first / es);
          }
        }
        free(b);
      }
    }
    if (why[0]) {
      /* Counted once per case; the verbose run shows every difference. */
      if (!R->mismatch_reported) {
        finding(R, v, idx, "%s", why);
      } else if (R->verbose) {
        finding(R, v, idx, "%s", why);
        R->counts[v]--;
      }
      R->mismatch_reported = 1;
    }
    for (int j = 0; j < nout; ++j) free(g[j].blk);
    free(vtu);
    return;
  }

  /* ---- original run: checks ---- */
  if (R->cfile) {
    c_emit_status(R->cfile, c, idx, st);
    fflush(R->cfile);
  }
  c->status = st;
  c->ran = 1;
  R->calls++;
  /* (the message of a call given another handle is the thread's) */
  const tfem_model *slot = (FN[fn].model == 1 && !c->null_model && !c->handle) ? R->m : NULL;
  int hslot = FN[fn].model == 2 && hc && !c->handle; /* the message is the context's */
  tfem_solid_model *sslot = FN[fn].model == 3 && !c->handle ? sm : NULL;         /* ... the 3D model's */
  tfem_solid_contact *scslot = FN[fn].model == 4 && !c->handle ? sx : NULL;      /* ... the 3D context's */
  int msg_fn = fn != F_LAST_ERROR && fn != F_LAST_ERROR_LENGTH && fn != F_VERSION && fn != F_DESTROY_NULL &&
               fn != F_RECREATE && fn != F_CONTACT_LAST_ERROR && fn != F_CONTACT_DESTROY &&
               fn != F_CONTACT_LAST_ERROR_LENGTH && fn != F_S_LAST_ERROR && fn != F_S_LAST_ERROR_LENGTH &&
               fn != F_S_DESTROY && fn != F_S_RECREATE && fn != F_SC_LAST_ERROR && fn != F_SC_LAST_ERROR_LENGTH &&
               fn != F_SC_DESTROY;
  static __thread char msg[65536];
  msg[0] = 0;
  if (msg_fn && hslot) tfem_contact_last_error(hc, msg, sizeof msg);
  else if (msg_fn && sslot) tfem_solid_last_error(sslot, msg, 4096);
  else if (msg_fn && scslot) tfem_solid_contact_last_error(scslot, msg, 4096);
  else if (msg_fn) tfem_last_error(slot, msg, 4096);
  c->refine_refused = fn == F_SOLVE_ADAPTIVE && st == TFEM_STATUS_INVALID_ARGUMENT && strstr(msg, "curve") != NULL;
  if (R->verbose) {
    char ex[600];
    excerpt(msg, strlen(msg), ex, sizeof ex);
    printf(" -> %s%s%s\n", status_name(st), st ? ": " : "", st ? ex : "");
    if (fn == F_SOLVE_ADAPTIVE && st == TFEM_STATUS_OK && !c->out[0].null_) {
      const tfem_adapt_report *ar = (const tfem_adapt_report *)(const void *)g[0].p;
      printf("       (%d cycle(s) of at most %d, reached %d, %" PRId64 " unknowns, %" PRId64 " triangles, estimate %.3g, "
             "tolerance %g)\n", ar->cycles, c->iv[5], ar->reached, ar->unknowns, ar->triangles, ar->estimate, c->dv[2]);
    }
  }
  if (e0 >= 0 && e1 > e0) {
    /* Bytes are claimed once: with threads, other calls may overlap. */
    off_t from = __atomic_load_n(&g_err_claimed, __ATOMIC_RELAXED);
    while (from < e1 && !__atomic_compare_exchange_n(&g_err_claimed, &from, e1, 0, __ATOMIC_RELAXED, __ATOMIC_RELAXED)) {
    }
    if (from > e0) e0 = from;
  }
  if (e0 >= 0 && e1 > e0) {
    char text[400] = "", ex[800];
    ssize_t k = pread(2, text, sizeof text - 1 < (size_t)(e1 - e0) ? sizeof text - 1 : (size_t)(e1 - e0), e0);
    if (k < 0) k = 0;
    excerpt(text, (size_t)k, ex, sizeof ex);
    R->stderr_bytes += (long)(e1 - e0);
    finding(R, V_STDERR, idx, "%ld bytes on stderr (status %s): \"%s\"", (long)(e1 - e0), status_name(st), ex);
  }
  if (st < 0 || st > 14) finding(R, V_BAD_STATUS, idx, "status %d is not a tfem_status", st);
  int known_panic = 0;
#if !API_FUZZ_FRICTION_PANIC
  if (st == TFEM_STATUS_INTERNAL && (fn == F_SOLVE_CONTACT || fn == F_STEP) && strstr(msg, "index out of bounds")) {
    for (int k = 0; k < R->sh.npairs && k < 64; ++k) known_panic |= R->sh.pair_mu[k] != 0.0;
    known_panic |= R->sh.npairs > 64;
    if (known_panic) R->sh.res_unknown = 1; /* (what a panic leaves is not known here: matrix dropped, seed 15 case 9800) */
  }
#endif
  if (st == TFEM_STATUS_INTERNAL && !known_panic) {
    char ex[600];
    excerpt(msg, strlen(msg), ex, sizeof ex);
    finding(R, V_INTERNAL, idx, "TFEM_STATUS_INTERNAL: \"%s\"", ex);
  }
  for (int j = 0; j < nout; ++j)
    if (!c->out[j].null_ && !gb_canary_ok(&g[j]))
      finding(R, V_CANARY, idx, "output %d (declared length %zu) has a canary overwritten", j, c->out[j].len);
  if (st != TFEM_STATUS_OK && !may_write_on_failure(fn, st))
    for (int j = 0; j < nout; ++j)
      if (!c->out[j].null_ && (fn == F_CONTACT_SCATTER_ADD || fn == F_SC_SCATTER_ADD ? c->in[1].p && g[0].n <= (size_t)c->in[1].n &&
                                                              memcmp(g[0].p, c->in[1].p, sizeof(double) * g[0].n) != 0
                                                        : !gb_untouched(&g[j])))
        finding(R, V_WRITE_ON_FAIL, idx, "output %d written although the status is %s", j, status_name(st));
  if (c->null_model && FN[fn].model && fn != F_LAST_ERROR && fn != F_LAST_ERROR_LENGTH && fn != F_CONTACT_DESTROY &&
      fn != F_CONTACT_LAST_ERROR_LENGTH && fn != F_S_LAST_ERROR_LENGTH && fn != F_SC_LAST_ERROR_LENGTH &&
      fn != F_S_DESTROY && fn != F_SC_DESTROY && st != TFEM_STATUS_NULL_POINTER)
    finding(R, V_OTHER, idx, "NULL model gave %s, not NULL_POINTER", status_name(st));
  /* NULL pointers other than the model: a required one must be refused, an
   * optional one ("may be NULL") accepted. (An input array of no element
   * may be NULL.) */
  if (FN[fn].model && !c->null_model && !c->handle && fn != F_LAST_ERROR && fn != F_CONTACT_LAST_ERROR &&
      fn != F_S_LAST_ERROR && fn != F_SC_LAST_ERROR) {
    int req_null = -1, opt_null = -1;
    for (int j = 0; j < nout; ++j)
      if (c->out[j].null_) *(out_nullable(fn, j) ? &opt_null : &req_null) = j;
    for (int j = 0; j < fn_nin(fn); ++j)
      if (c->in[j].null_ && (FN[fn].ink[j] == 'o' || FN[fn].ink[j] == 'r' || c->in[j].n > 0) &&
          !((fn == F_CONTACT_SCATTER_ADD || fn == F_SC_SCATTER_ADD) && j == 1))
        *(FN[fn].ink[j] == 'o' ? &opt_null : &req_null) = 10 + j;
    if (req_null >= 0 && st == TFEM_STATUS_OK)
      finding(R, V_NULL_ARG, idx, "OK although %s %d is NULL", req_null >= 10 ? "input" : "output", req_null % 10);
    if (opt_null >= 0 && req_null < 0 && st == TFEM_STATUS_NULL_POINTER)
      finding(R, V_NULL_ARG, idx, "NULL_POINTER although only %s %d, which may be NULL, is NULL: \"%.160s\"",
              opt_null >= 10 ? "input" : "output", opt_null % 10, msg);
  }

  /* Messages. */
  if (msg_fn) {
    size_t sl = strlen(msg), L = hslot     ? sl + 1
                                 : sslot   ? tfem_solid_last_error_length(sslot)
                                 : scslot  ? tfem_solid_contact_last_error_length(scslot)
                                           : tfem_last_error_length(slot);
    if (st != TFEM_STATUS_OK) {
      if (sl == 0)
        finding(R, V_EMPTY_MSG, idx, "status %s without a message (%s slot)", status_name(st),
                slot ? "model" : sslot ? "3D model" : scslot ? "3D context" : "thread");
      if (L > MAX_MSG + 1) {
        char ex[200];
        excerpt(msg, sl < 120 ? sl : 120, ex, sizeof ex);
        finding(R, V_LONG_MSG, idx, "message of %zu bytes (status %s): \"%s...\"", L - 1, status_name(st), ex);
      }
      if (L <= 4096 && L != sl + 1)
        finding(R, V_LASTERR, idx, "tfem_last_error_length = %zu but the message has %zu bytes", L, sl);
    } else if ((slot || hslot || sslot || scslot) && sl != 0) {
      finding(R, V_LASTERR, idx, "the model's message is not empty after a successful call: \"%.80s\"", msg);
    } else if (!slot && !hslot && !sslot && !scslot && sl != 0 && !FN[fn].model) {
      char ex[200];
      excerpt(msg, sl < 100 ? sl : 100, ex, sizeof ex);
      finding(R, V_SLOT, idx, "tfem_last_error(NULL) still gives \"%s\" after this successful model-free call", ex);
    }
  }

  /* The last-error calls themselves. */
  if (!c->handle && (fn == F_LAST_ERROR || (fn == F_CONTACT_LAST_ERROR && hc) || (fn == F_S_LAST_ERROR && sm) ||
                      (fn == F_SC_LAST_ERROR && sx))) {
    size_t L = fn == F_LAST_ERROR ? tfem_last_error_length(m) : 0;
    if (fn == F_CONTACT_LAST_ERROR || fn == F_S_LAST_ERROR || fn == F_SC_LAST_ERROR) {
      static __thread char b[65536];
      b[0] = 0;
      if (fn == F_CONTACT_LAST_ERROR) tfem_contact_last_error(hc, b, sizeof b);
      else if (fn == F_S_LAST_ERROR) tfem_solid_last_error(sm, b, sizeof b);
      else tfem_solid_contact_last_error(sx, b, sizeof b);
      L = strlen(b) + 1;
      if (fn == F_S_LAST_ERROR && tfem_solid_last_error_length(sm) != L)
        finding(R, V_LASTERR, idx, "tfem_solid_last_error_length = %zu, the message has %zu bytes", tfem_solid_last_error_length(sm),
                L - 1);
      if (fn == F_SC_LAST_ERROR && tfem_solid_contact_last_error_length(sx) != L)
        finding(R, V_LASTERR, idx, "tfem_solid_contact_last_error_length = %zu, the message has %zu bytes",
                tfem_solid_contact_last_error_length(sx), L - 1);
    }
    size_t len = c->out[0].len;
    if (!o[0]) {
      if (st != TFEM_STATUS_NULL_POINTER) finding(R, V_LASTERR, idx, "NULL buffer gave %s", status_name(st));
    } else if (len == 0) {
      if (st != TFEM_STATUS_BUFFER_TOO_SMALL || !gb_untouched(&g[0]))
        finding(R, V_LASTERR, idx, "zero-length buffer gave %s (or was written)", status_name(st));
    } else {
      size_t sl = strnlen((const char *)g[0].p, len);
      if (sl == len) finding(R, V_LASTERR, idx, "buffer of %zu bytes not NUL-terminated", len);
      else if (L <= len && (st != TFEM_STATUS_OK || sl + 1 != L))
        finding(R, V_LASTERR, idx, "message of %zu bytes in a %zu-byte buffer: %s, %zu copied", L - 1, len, status_name(st), sl);
      else if (L > len && st != TFEM_STATUS_BUFFER_TOO_SMALL)
        finding(R, V_LASTERR, idx, "message of %zu bytes truncated to %zu without BUFFER_TOO_SMALL", L - 1, len);
    }
  }
  if (fn == F_CONTACT_CREATE && (st == TFEM_STATUS_OK) != (c->iv[0] == 0 || c->iv[0] == 1))
    finding(R, V_OTHER, idx, "tfem_contact_create(%d) %s", c->iv[0], st ? "returned NULL" : "made a context");
  if (fn == F_LAST_ERROR_LENGTH && lel < 1) finding(R, V_LASTERR, idx, "tfem_last_error_length = 0");
  if ((fn == F_S_LAST_ERROR_LENGTH || fn == F_SC_LAST_ERROR_LENGTH) && !c->handle) {
    /* 1 for NULL; else the message the *_last_error function gives, with its NUL */
    static __thread char b[65536];
    b[0] = 0;
    if (fn == F_S_LAST_ERROR_LENGTH && sm) tfem_solid_last_error(sm, b, sizeof b);
    if (fn == F_SC_LAST_ERROR_LENGTH && sx) tfem_solid_contact_last_error(sx, b, sizeof b);
    if (lel != strlen(b) + 1)
      finding(R, V_LASTERR, idx, "%s = %zu, the message (%s) has %zu bytes", fn_name(fn), lel,
              c->null_model ? "NULL handle" : "live", strlen(b));
  }
  if (fn == F_CONTACT_LAST_ERROR_LENGTH) {
    /* 1 for NULL; else the message tfem_contact_last_error gives, with its NUL */
    static __thread char b[65536];
    b[0] = 0;
    if (hc) tfem_contact_last_error(hc, b, sizeof b);
    if (lel != strlen(b) + 1)
      finding(R, V_LASTERR, idx, "tfem_contact_last_error_length = %zu, the message (%s context) has %zu bytes", lel,
              hc ? "live" : "NULL", strlen(b));
  }
  /* tfem_get_warning_size: an index in range, and a buffer of the size
   * given holds the whole warning, one byte less truncates it. (The call
   * that fails comes first: the model's message is then cleared by the
   * one that succeeds, as by the call checked.) */
  if (fn == F_GET_WARNING_SIZE && st == TFEM_STATUS_OK && m && !c->out[0].null_) {
    size_t z;
    int count = -1;
    memcpy(&z, g[0].p, sizeof z);
    if (tfem_warning_count(m, &count) == TFEM_STATUS_OK && (c->iv[0] < 0 || c->iv[0] >= count))
      finding(R, V_OTHER, idx, "OK for warning %d of %d", c->iv[0], count);
    if (z < 1 || z > ((size_t)1 << 26)) {
      finding(R, V_OTHER, idx, "warning %d has size %zu", c->iv[0], z);
    } else {
      char *w = xmalloc(z + 1);
      int s_short = z > 1 ? tfem_get_warning(m, c->iv[0], w, z - 1) : TFEM_STATUS_BUFFER_TOO_SMALL;
      memset(w, 'x', z + 1);
      int s_full = tfem_get_warning(m, c->iv[0], w, z);
      R->oracles[O_WARNING_SIZE]++;
      if (s_full != TFEM_STATUS_OK || strnlen(w, z) + 1 != z)
        finding(R, V_OTHER, idx, "warning %d of size %zu: a buffer of that size gives %s, %zu bytes", c->iv[0], z,
                status_name(s_full), strnlen(w, z));
      else if (s_short != TFEM_STATUS_BUFFER_TOO_SMALL)
        finding(R, V_OTHER, idx, "warning %d of size %zu: a buffer of %zu bytes gives %s", c->iv[0], z, z - 1,
                status_name(s_short));
      free(w);
    }
  }
  /* tfem_write_vtu: NULL refused; a file written only where it can be,
   * holding the grid of the model's points and cells; an unwritable path
   * refused with TFEM_STATUS_IO once there are results; NUMERICAL_FAILURE
   * only as an accessor of what it writes refuses it, nothing written. */
  if (fn == F_S_WRITE_VTU) solid_vtu_check(R, idx, c, st, path, vtu, vtu_n, vtu_found, msg);
  if (fn == F_WRITE_VTU && !c->null_model && !c->handle) {
    const shadow_t *sv = &R->sh;
    int known = sv->has_mesh && sv->results && !sv->res_unknown;
    if (!path && st != TFEM_STATUS_NULL_POINTER) {
      finding(R, V_NULL_ARG, idx, "NULL path gave %s", status_name(st));
    } else if (path && st == TFEM_STATUS_OK && !vtu_writable(c->iv[0])) {
      finding(R, V_OTHER, idx, "OK although the path \"%s\" cannot be written", path);
    } else if (path && st == TFEM_STATUS_OK) {
      int nn = -1, nt = -1, nc = -1;
      char want[64];
      const char *cells = vtu ? strstr(vtu, "NumberOfCells=\"") : NULL;
      long ncells = cells ? strtol(cells + strlen("NumberOfCells=\""), NULL, 10) : -1;
      if (!vtu_found) {
        finding(R, V_OTHER, idx, "OK but no file at %s", path);
      } else if (tfem_get_sizes(m, &nn, &nt, &nc) == TFEM_STATUS_OK) {
        snprintf(want, sizeof want, "NumberOfPoints=\"%d\"", nn);
        R->oracles[O_VTU]++;
        if (!vtu || !strstr(vtu, "<VTKFile") || !strstr(vtu, "UnstructuredGrid") || !strstr(vtu, want) ||
            ncells < nt || ncells > (long)nt + (nc > 0 ? nc : 0))
          finding(R, V_OTHER, idx, "the .vtu (%zu bytes) is not a grid of %d points and %d (+ %d contact) cells: "
                  "NumberOfCells %ld", vtu_n, nn, nt, nc, ncells);
      }
    } else if (path && known && st == TFEM_STATUS_NUMERICAL_FAILURE) {
      /* A result the file would hold that its accessor refuses (a stress
       * beyond DBL_MAX): the header's NUMERICAL_FAILURE, nothing written,
       * the item named as that accessor names it (vtu_refusal_of_accessor) */
      R->oracles[O_VTU]++;
      if (vtu_found)
        finding(R, V_OTHER, idx, "NUMERICAL_FAILURE, yet a file is at \"%s\" (the header: nothing is written): "
                "\"%.160s\"", path, msg);
      else if (!vtu_refusal_of_accessor(m, msg))
        finding(R, V_OTHER, idx, "NUMERICAL_FAILURE for the path \"%s\" after a solve, yet no accessor of the "
                "results it writes refuses them so: \"%.160s\"", path, msg);
    } else if (path && known && st != TFEM_STATUS_INVALID_STATE) {
      /* (INVALID_STATE with results: the results_lost oracle below) */
      int want_st = vtu_writable(c->iv[0]) ? TFEM_STATUS_OK : TFEM_STATUS_IO;
      R->oracles[O_VTU]++;
      if (st != want_st)
        finding(R, V_OTHER, idx, "%s (not %s) for the path \"%s\" after a solve: \"%.160s\"", status_name(st),
                status_name(want_st), path, msg);
    }
  }
  free(vtu);
  if (fn == F_VERSION) {
    int a, b, cc, n = 0;
    if (!ver || sscanf(ver, "%d.%d.%d%n", &a, &b, &cc, &n) != 3 || ver[n] != 0)
      finding(R, V_OTHER, idx, "tfem_version() = \"%s\" is not major.minor.patch", ver ? ver : "(null)");
  }

  /* Outputs of a successful call. */
  if (st == TFEM_STATUS_OK) {
    for (int j = 0; j < nout; ++j) {
      if (c->out[j].null_) continue;
      const gbuf *b = &g[j];
      char why[200] = "";
      /* (scatter_add adds to the host's own vector: a non-finite value
       * already in it stays; gather and scatter_add refuse one they read) */
      int passed_through = 0;
      if ((fn == F_CONTACT_SCATTER_ADD || fn == F_SC_SCATTER_ADD) && c->in[1].p)
        for (int i = 0; i < c->in[1].n && !passed_through; ++i) passed_through = !isfinite(((const double *)c->in[1].p)[i]);
      if (b->kind == K_D && !passed_through) {
        for (size_t i = 0; i < b->n; ++i) {
          double v;
          memcpy(&v, b->p + 8 * i, 8);
          if (!gb_is_pattern(b, i) && !isfinite(v)) {
            size_t bad = 0;
            for (size_t k = i; k < b->n; ++k) {
              double w;
              memcpy(&w, b->p + 8 * k, 8);
              bad += !gb_is_pattern(b, k) && !isfinite(w);
            }
            finding(R, V_NAN_OK, idx, "output %d element %zu = %g (%zu non-finite of %zu)", j, i, v, bad, b->n);
            break;
          }
        }
        /* results carry +0.0, never -0.0 (src/model/solution.rs
         * PositiveZero; the header's tfem_contact_length: "+0.0 when no
         * element is active") */
        for (size_t i = 0; i < b->n && plus_zero_output(fn); ++i) {
          double v;
          memcpy(&v, b->p + 8 * i, 8);
          if (!gb_is_pattern(b, i) && v == 0.0 && signbit(v)) {
            finding(R, V_NEG_ZERO, idx, "output %d element %zu is -0.0", j, i);
            break;
          }
        }
      } else if (b->kind == K_SI) {
        if (info_bad((const tfem_solve_info *)(const void *)b->p, why, sizeof why)) finding(R, V_NAN_OK, idx, "%s", why);
        else if (info_insane((const tfem_solve_info *)(const void *)b->p, why, sizeof why)) finding(R, V_OTHER, idx, "%s", why);
      } else if (b->kind == K_RE) {
        const tfem_contact_report *rp = (const tfem_contact_report *)(const void *)b->p;
        if (!isfinite(rp->contact_length) || !isfinite(rp->max_penetration))
          finding(R, V_NAN_OK, idx, "report contact_length = %g, max_penetration = %g", rp->contact_length, rp->max_penetration);
        else if ((rp->contact_length == 0.0 && signbit(rp->contact_length)) ||
                 (rp->max_penetration == 0.0 && signbit(rp->max_penetration)))
          finding(R, V_NEG_ZERO, idx, "report contact_length = %g, max_penetration = %g (a -0.0)", rp->contact_length,
                  rp->max_penetration);
        else if (info_bad(&rp->info, why, sizeof why)) finding(R, V_NAN_OK, idx, "report %s", why);
        else if (rp->iterations < 1 || rp->active < 0 || rp->active > rp->elements || rp->contact_length < 0 ||
                 rp->max_penetration < 0 || info_insane(&rp->info, why, sizeof why))
          finding(R, V_OTHER, idx, "report: iterations %d, active %d of %d, length %g, penetration %g %s", rp->iterations,
                  rp->active, rp->elements, rp->contact_length, rp->max_penetration, why);
      } else if (b->kind == K_OP) {
        const tfem_contact_options *op = (const tfem_contact_options *)(const void *)b->p;
        if (!isfinite(op->contact_modulus) || !isfinite(op->lambda)) finding(R, V_NAN_OK, idx, "default options not finite");
        else if (op->law != 0 || op->inversion_test != 0 || op->max_iterations != 50 || op->refactorize != 0)
          finding(R, V_OTHER, idx, "default options %d %d %d %d differ from the header's", op->law, op->inversion_test,
                  op->max_iterations, op->refactorize);
      } else if (b->kind == K_T) {
        for (size_t i = 0; i < b->n; ++i) {
          double v;
          memcpy(&v, b->p + 8 * i, 8);
          if (!gb_is_pattern(b, i) && !(isfinite(v) && v >= 0)) {
            finding(R, isfinite(v) ? V_OTHER : V_NAN_OK, idx, "output %d element %zu = %g seconds", j, i, v);
            break;
          }
        }
      } else if (b->kind == K_AR) {
        const tfem_adapt_report *ar = (const tfem_adapt_report *)(const void *)b->p;
        if (!isfinite(ar->estimate) || !isfinite(ar->seconds))
          finding(R, V_NAN_OK, idx, "adapt report estimate = %g, seconds = %g", ar->estimate, ar->seconds);
        else if (ar->cycles < 1 || (ar->reached != 0 && ar->reached != 1) || ar->unknowns < 0 || ar->triangles < 1 ||
                 ar->estimate < 0 || ar->seconds < 0)
          finding(R, V_ADAPT, idx, "adapt report: cycles %d, reached %d, unknowns %" PRId64 ", triangles %" PRId64
                  ", estimate %g, seconds %g", ar->cycles, ar->reached, ar->unknowns, ar->triangles, ar->estimate,
                  ar->seconds);
      }
      /* Everything required written. */
      /* (a state's bytes, like a message's, may be the pattern's) */
      if (!FN[fn].scalar_out && b->kind != K_C && b->kind != K_U8 && c->out[j].req >= 0 && (size_t)c->out[j].req <= b->n) {
        for (size_t i = 0; i < (size_t)c->out[j].req; ++i)
          if (gb_is_pattern(b, i)) {
            finding(R, V_OTHER, idx, "OK but output %d element %zu of %ld not written", j, i, c->out[j].req);
            break;
          }
      }
      /* (tfem_contact_scatter_add: n_equations need only cover the
       * equations the sides use, fewer than the model's 2 n_nodes when the
       * last nodes are off the interface; seed 11 case 17609) */
      if (!FN[fn].scalar_out && b->kind != K_C && c->out[j].req >= 0 && (size_t)c->out[j].req > b->n &&
          fn != F_CONTACT_SCATTER_ADD && fn != F_SC_SCATTER_ADD)
        finding(R, V_OTHER, idx, "OK with output %d of length %zu where %ld are needed", j, b->n, c->out[j].req);
    }
    /* Structure of the system matrix. */
    if (fn == F_GET_MATRIX && !c->out[0].null_ && c->out[0].req >= 1) {
      const int64_t *cp = (const int64_t *)(const void *)g[0].p, *ri = (const int64_t *)(const void *)g[1].p;
      const int64_t *dofs = (const int64_t *)(const void *)g[3].p;
      int64_t n = c->out[0].req - 1, b = R->sh.has_mesh ? R->sh.base : cp[0];
      int bad = cp[0] != b;
      for (int64_t j = 0; j < n && !bad; ++j) {
        bad |= cp[j + 1] < cp[j];
        for (int64_t p = cp[j] - b; p < cp[j + 1] - b && !bad; ++p)
          bad |= p < 0 || (size_t)p >= g[1].n || ri[p] - b < 0 || ri[p] - b > j || (p > cp[j] - b && ri[p] <= ri[p - 1]);
        bad |= dofs[j] < b;
      }
      if (bad) finding(R, V_OTHER, idx, "system matrix is not an upper-triangular CSC in the index base");
    }
    if (fn == F_CONTACT_UPDATE && o[0]) {
      int v;
      memcpy(&v, g[0].p, 4);
      if (v != 0 && v != 1) finding(R, V_OTHER, idx, "changed = %d", v);
    }
    if ((fn == F_GET_CONTACT_ACTIVE || fn == F_CONTACT_GET_ACTIVE) && o[0])
      for (size_t i = 0; i < g[0].n && c->out[0].req >= 0 && i < (size_t)c->out[0].req; ++i) {
        int v;
        memcpy(&v, g[0].p + 4 * i, 4);
        if (v != 0 && v != 1) {
          finding(R, V_OTHER, idx, "active flag %zu = %d", i, v);
          break;
        }
      }
    if (fn == F_GET_CONTACT_ELEMENTS && o[0] && R->sh.exact)
      for (size_t i = 0; c->out[0].req >= 0 && i < (size_t)c->out[0].req && i < g[0].n; ++i) {
        int v;
        memcpy(&v, g[0].p + 4 * i, 4);
        if (v < R->sh.base || v >= R->sh.base + R->sh.nn) {
          finding(R, V_OTHER, idx, "contact element node %d out of range", v);
          break;
        }
      }
    if (fn == F_GET_SIZES && R->sh.exact && o[0] && o[1]) {
      int nn, nt;
      memcpy(&nn, g[0].p, 4);
      memcpy(&nt, g[1].p, 4);
      if (nn != R->sh.nn || nt != R->sh.nt) finding(R, V_OTHER, idx, "sizes %d, %d; the mesh has %d, %d", nn, nt, R->sh.nn, R->sh.nt);
    }
    if (c->null_model && FN[fn].model && fn != F_LAST_ERROR && fn != F_LAST_ERROR_LENGTH && fn != F_CONTACT_DESTROY &&
        fn != F_CONTACT_LAST_ERROR_LENGTH && fn != F_S_LAST_ERROR_LENGTH && fn != F_SC_LAST_ERROR_LENGTH &&
        fn != F_S_DESTROY && fn != F_SC_DESTROY)
      finding(R, V_OTHER, idx, "OK with a NULL model");
  }

  /* ---- the 3D model and context, and calls given a handle of another kind ---- */
  if (c->handle || FN[fn].model >= 3 || fn == F_S_RECREATE || fn == F_SC_CREATE) {
    if (c->handle && !c->null_model) oracle_handle(R, idx, c, st, hp, lel, g, msg);
    else solid_checks(R, idx, c, st, g, msg);
    keep_outputs(c, st, nout, ver, g);
    return;
  }

  /* ---- the contact context and load steps ---- */
  if (st == TFEM_STATUS_OK && !c->null_model && FN[fn].model == 2 && fn != F_CONTACT_DESTROY &&
      fn != F_CONTACT_LAST_ERROR && fn != F_CONTACT_LAST_ERROR_LENGTH && fn != F_CONTACT_SET_OPTIONS && fn != F_CONTACT_ADD_SIDE &&
      fn != F_CONTACT_ADD_PAIR && fn != F_CONTACT_ADD_PAIR_WITH_MESH)
    R->cbuilt = 1; /* (a call that needs the contact mesh B succeeded) */
  if (st == TFEM_STATUS_OK && hc) {
    int full0 = out_full(c, 0);
    if ((fn == F_CONTACT_PATTERN && full0 && out_full(c, 1)) || (fn == F_CONTACT_EVALUATE && full0) ||
        ((fn == F_CONTACT_GATHER || fn == F_CONTACT_SCATTER_ADD) && full0 && !c->in[0].null_) ||
        (fn == F_CONTACT_SET_ACTIVE && !c->in[0].null_) || (fn == F_CONTACT_PRESSURES && full0) ||
        (fn == F_CONTACT_LENGTH && !c->out[0].null_))
      oracle_host(R, idx, c, g);
  }
  if (st == TFEM_STATUS_OK && !c->null_model && fn == F_GET_CONTACT_STATE && out_full(c, 0)) {
    free(R->st_prev);
    R->st_prev = R->st_last, R->n_prev = R->n_last, R->st_prev_w = R->st_last_w;
    R->st_last_w = R->sh.hist_sig;
    R->n_last = (size_t)c->out[0].req;
    R->st_last = xmalloc(R->n_last + 1);
    memcpy(R->st_last, g[0].p, R->n_last);
  }
  if (c->tag != T_NONE && R->pristine && idx < R->full_prefix) {
    /* a step repeated after tfem_revert_step or tfem_set_contact_state of
     * the state before it: the same results, bit for bit (all the calls
     * since the reference successful, but those that only read the model
     * and those refused as the scene expects: the replay shows that a
     * failed call changed nothing) */
    int all_ok = st == TFEM_STATUS_OK;
    for (int k = R->ref_idx; k < idx && all_ok && (c->tag == T_CMP_STEP || c->tag == T_CMP_DISP); ++k) {
      const call_t *ck = &R->cs->c[k];
      all_ok = ck->status == TFEM_STATUS_OK || reads_only(ck->fn) || (ck->want && ck->status == ck->want - 1);
    }
    if (c->tag == T_REF_STEP) {
      R->ref_ok = all_ok && !c->out[0].null_;
      R->ref_idx = idx;
      R->ref_disp_ok = 0;
      if (R->ref_ok) memcpy(&R->ref_rep, g[0].p, sizeof R->ref_rep);
    } else if (c->tag == T_REF_DISP && all_ok && out_full(c, 0)) {
      R->ref_disp = fnv64(g[0].p, sizeof(double) * (size_t)c->out[0].req);
      R->ref_disp_ok = 1;
    } else if (c->tag == T_CMP_STEP && all_ok && R->ref_ok && !c->out[0].null_) {
      tfem_contact_report b;
      const tfem_contact_report *a = &R->ref_rep;
      memcpy(&b, g[0].p, sizeof b);
      R->oracles[O_STEP_REPEAT]++;
      if (a->iterations != b.iterations || a->elements != b.elements || a->active != b.active ||
          memcmp(&a->contact_length, &b.contact_length, 8) || memcmp(&a->max_penetration, &b.max_penetration, 8))
        finding(R, V_STEP, idx, "report (iterations %d, active %d of %d, length %.17g, penetration %.17g), call #%d gave "
                "(%d, %d of %d, %.17g, %.17g)", b.iterations, b.active, b.elements, b.contact_length, b.max_penetration,
                R->ref_idx, a->iterations, a->active, a->elements, a->contact_length, a->max_penetration);
    } else if (c->tag == T_CMP_DISP && all_ok && R->ref_disp_ok && out_full(c, 0)) {
      R->oracles[O_STEP_REPEAT]++;
      if (fnv64(g[0].p, sizeof(double) * (size_t)c->out[0].req) != R->ref_disp)
        finding(R, V_STEP, idx, "displacements differ from those after the step of call #%d", R->ref_idx);
    }
  }

  /* ---- the shadow model and the semantic oracles ---- */
  shadow_t *s = &R->sh;
  int need_results = fn == F_GET_DISPLACEMENTS || fn == F_GET_STRAINS || fn == F_GET_STRESSES ||
                     fn == F_GET_REACTIONS || fn == F_GET_MATRIX_SIZE || fn == F_GET_MATRIX ||
                     fn == F_GET_EXTERNAL_WORK || fn == F_WRITE_VTU || fn == F_GET_OUT_OF_PLANE;
  /* ---- axisymmetric bodies, the ring element, the adaptive solve ---- */
  if (!c->null_model && fn == F_SET_MATERIAL) oracle_material(R, idx, c, st, msg);
  if (hc && fn == F_CONTACT_ADD_SIDE && c->iv[2] >= 0 && c->iv[2] <= 2) {
    /* a context is axisymmetric in every side or in none, an axisymmetric
     * side at x >= 0 (src/contact/host.rs check_section) */
    int ring = c->iv[2] == TFEM_PLANE_MODE_AXISYMMETRIC, across = -1;
    const double *xy = c->in[1].null_ ? NULL : c->in[1].p;
    for (int i = 0; ring && xy && i < c->iv[3] && 2 * i + 1 < c->in[1].n && across < 0; ++i)
      if (xy[2 * i] < 0) across = i;
    int mixed = R->ctx_ring >= 0 && R->ctx_ring != ring;
    R->oracles[O_AXI] += mixed || across >= 0;
    if (st == TFEM_STATUS_OK && (mixed || across >= 0))
      finding(R, V_AXI, idx, "tfem_contact_add_side (plane mode %d) is OK although %s", c->iv[2],
              mixed ? "the context's sides before it are of the other section" : "a node is at x < 0");
    if (st == TFEM_STATUS_OK) R->ctx_ring = ring;
  }
  if (fn == F_ELEMENT_STIFFNESS && st == TFEM_STATUS_OK && !c->out[0].null_)
    oracle_element_stiffness(R, idx, c, (const double *)(const void *)g[0].p);
  if (!c->null_model && fn == F_SOLVE_ADAPTIVE) oracle_adapt(R, idx, c, st, g, msg);
  if (!c->null_model && fn == F_GET_ADAPT_CYCLES) oracle_adapt_cycles(R, idx, c, st, g, msg);
  if (!c->null_model && fn == F_SET_BOUNDARY_CIRCLE) oracle_circle(R, idx, c, st, msg);
  if (!c->null_model && fn == F_SOLVE_ADAPTIVE && st == TFEM_STATUS_OK) oracle_circle_nodes(R, idx);
  if (!c->null_model && st == TFEM_STATUS_OK && s->axi &&
      (fn == F_SOLVE || fn == F_SOLVE_CONTACT || fn == F_STEP || fn == F_SOLVE_ADAPTIVE)) {
    /* an axisymmetric model's solve: no body across the axis, u_r = 0 on it */
    char why[200];
    R->oracles[O_AXI] += s->exact;
    if (sh_axis_violation(s, INT_MIN, why, sizeof why) >= 0)
      finding(R, V_AXI, idx, "OK for an axisymmetric model although %s (the header: refused by the solve)", why);
  }
  int need_contact = fn == F_GET_CONTACT_ACTIVE || fn == F_GET_CONTACT_PRESSURE || fn == F_GET_CONTACT_ELEMENTS ||
                     fn == F_GET_CONTACT_REPORT || fn == F_GET_CONTACT_FORCES || fn == F_GET_CONTACT_GAPS ||
                     fn == F_GET_CONTACT_NODAL_PRESSURES || fn == F_GET_CONTACT_PAIR_NODAL_PRESSURES ||
                     fn == F_GET_CONTACT_SHEAR || fn == F_GET_CONTACT_FRICTION_STATE ||
                     fn == F_GET_CONTACT_DISSIPATION;
  /* the outputs per element of B, refused when every pair is under the
   * mortar weighting (they cover the pairs weighted by B), and the slave
   * nodes, refused when no pair is (they cover the others): what the
   * families of the results' pairs (res_fam) say, each known served,
   * known refused, or neither (a family not known here) */
  int per_element = fn == F_GET_CONTACT_ACTIVE || fn == F_GET_CONTACT_PRESSURE || fn == F_GET_CONTACT_SHEAR ||
                    fn == F_GET_CONTACT_FRICTION_STATE || fn == F_GET_CONTACT_DISSIPATION ||
                    fn == F_GET_CONTACT_ELEMENTS;
  int fam = s->res_fam;
  int elem_served = (fam & FAM_STRIP) || !(fam & (FAM_MORTAR | FAM_UNKNOWN)), elem_refused = fam == FAM_MORTAR;
  int slave_served = (fam & FAM_MORTAR) != 0, slave_refused = !(fam & (FAM_MORTAR | FAM_UNKNOWN));
  if (st != TFEM_STATUS_OK && st != TFEM_STATUS_NULL_POINTER && !c->null_model && fn == F_GET_CONTACT_PAIR_BODIES &&
      s->has_mesh && c->iv[0] >= 0 && c->iv[0] < s->npairs)
    finding(R, V_CONTACT, idx, "%s for pair %d of the %d declared: \"%.160s\"", status_name(st), c->iv[0], s->npairs, msg);
  if (!c->null_model && s->has_mesh && st == TFEM_STATUS_INVALID_STATE && !s->res_unknown) {
    int matrix = fn == F_GET_MATRIX_SIZE || fn == F_GET_MATRIX;
    if (matrix && s->no_matrix) {
      /* (the system matrix of a step is not available) */
    } else if (need_results && s->results) {
      if (matrix && s->matrix_dropped)
        finding(R, V_MATRIX_DROPPED, idx, "no matrix after a failed solve, while the displacements of the solve before it are kept: \"%.160s\"", msg);
      else
        finding(R, V_RESULTS_LOST, idx, "INVALID_STATE although the last %s solve succeeded and nothing changed the problem since: \"%.160s\"",
                s->results == 2 ? "contact" : s->results == 3 ? "load step" : "plain", msg);
    } else if (need_contact && (s->results == 2 || (s->results == 3 && fam == FAM_MORTAR)) &&
               !(per_element && !elem_served)) {
      finding(R, V_RESULTS_LOST, idx, "contact results gone although nothing changed the problem since the contact solve: \"%.160s\"", msg);
    }
  }
  if (!c->null_model && st == TFEM_STATUS_OK && (need_results || need_contact) && !s->results && s->has_mesh &&
      !s->res_unknown)
    finding(R, V_OTHER, idx, "results returned although the problem changed since the last solve");
  if (!c->null_model && st == TFEM_STATUS_OK && (fn == F_GET_MATRIX_SIZE || fn == F_GET_MATRIX) && s->has_mesh &&
      !s->res_unknown && s->results == 3)
    finding(R, V_OTHER, idx, "OK after a load step%s (the header: the system matrix of a step is not available)",
            fam & FAM_MORTAR ? " under the mortar weighting" : "");
  if (!c->null_model && s->exact && (fn == F_SET_BOUNDARY_EDGES || fn == F_ADD_BOUNDARY_EDGES) && c->iv[0] >= 0 &&
      (c->iv[0] == 0 || (!c->in[0].null_ && !c->in[1].null_ && c->in[0].n >= 2 * c->iv[0] && c->in[1].n >= c->iv[0]))) {
    /* The edges the call asks for (set replaces, add appends), and the
     * header's refusals: an edge given a tag it already has, a load or a
     * pair left without edges. OK: the shadow takes them, and a refusal
     * missed is a finding; refused: counted when the edges were otherwise
     * valid. */
    int from = fn == F_ADD_BOUNDARY_EDGES ? s->ne : 0, n = c->iv[0], valid = 1, in_range = 1;
    const int *en = c->in[0].p, *tg = c->in[1].p;
    int *e0 = xmalloc(sizeof(int) * 2 * (size_t)(from + n) + 1), *t0 = xmalloc(sizeof(int) * (size_t)(from + n) + 1);
    if (from) {
      memcpy(e0, s->edge, sizeof(int) * 2 * (size_t)from);
      memcpy(t0, s->tag, sizeof(int) * (size_t)from);
    }
    for (int k = 0; k < n; ++k) {
      long pl = (long)en[2 * k] - s->base, ql = (long)en[2 * k + 1] - s->base;
      if (pl < 0 || ql < 0 || pl >= s->nn || ql >= s->nn || pl == ql) {
        valid = in_range = 0;
        if (st == TFEM_STATUS_OK) finding(R, V_OTHER, idx, "OK with edge %d (nodes %d, %d): out of range or both ends equal", k, en[2 * k], en[2 * k + 1]);
        break;
      }
      int p = (int)pl, q = (int)ql, side = 0;
      for (int t = 0; t < s->nt && !side; ++t)
        for (int kk = 0; kk < 3; ++kk) {
          int a = s->tri[3 * t + kk], b = s->tri[3 * t + (kk + 1) % 3];
          side |= (a == p && b == q) || (a == q && b == p);
        }
      valid &= side;
      e0[2 * (from + k)] = p;
      e0[2 * (from + k) + 1] = q;
      t0[from + k] = tg[k];
    }
    if (valid || (st == TFEM_STATUS_OK && in_range)) {
      int old_ne = s->ne, *old_e = s->edge, *old_t = s->tag;
      s->edge = e0, s->tag = t0, s->ne = from + n;
      int d = sh_double_edge(s, from);
      char why[300];
      int orphan = sh_orphan(s, why, sizeof why);
      if (st == TFEM_STATUS_OK) {
        if (d >= 0)
          finding(R, V_DOUBLE_EDGE, idx, "edge (%d, %d) given tag %d %s: OK", s->edge[2 * d] + s->base,
                  s->edge[2 * d + 1] + s->base, s->tag[d], fn == F_SET_BOUNDARY_EDGES ? "twice" : "again");
        if (orphan) finding(R, V_DROPPED_LOAD, idx, "%s, yet the call is OK (the header: refused, naming the tag)", why);
        free(old_e), free(old_t);
        e0 = t0 = NULL;
      } else {
        R->oracles[O_EDGES_REFUSED] += d >= 0 || orphan;
        s->edge = old_e, s->tag = old_t, s->ne = old_ne;
      }
    }
    free(e0);
    free(t0);
  }
  if (!c->null_model && s->exact && st != TFEM_STATUS_OK && (fn == F_FIX || fn == F_FIX_EDGES) && isfinite(c->dv[0]) &&
      (c->iv[1] == 0 || c->iv[1] == 1)) {
    /* a different value for a prescribed DOF: refused, as required */
    int conflict = 0;
    for (int e = 0; e < (fn == F_FIX ? 1 : s->ne) && !conflict; ++e) {
      if (fn == F_FIX_EDGES && s->tag[e] != c->iv[0]) continue;
      for (int k = 0; k < 2; ++k) {
        long node = fn == F_FIX ? (long)c->iv[0] - s->base : s->edge[2 * e + k];
        if (node < 0 || node >= s->nn) break;
        double pv = s->presc[2 * node + c->iv[1]];
        conflict |= !isnan(pv) && pv != c->dv[0];
      }
    }
    R->oracles[O_FIX_REFUSED] += conflict;
  }
  if (!c->null_model && fn == F_SET_FRICTION) {
    /* the header: a negative or non-finite mu, or an unknown pair, refused
     * with INVALID_ARGUMENT; else accepted, except mu > 0 while the mortar
     * weighting is forced (frictionless: refused by this call since
     * dc75b81, INVALID_ARGUMENT naming the pair, the model unchanged; the
     * doc of tfem_set_contact_weighting in src/ffi/entry.rs) */
    int pair = c->iv[0];
    double mu = c->dv[0];
    int valid = pair >= 0 && pair < s->npairs && isfinite(mu) && mu >= 0;
    int unserved = valid && mu > 0.0 && s->weighting == TFEM_CONTACT_WEIGHTING_MORTAR;
    char named[48];
    snprintf(named, sizeof named, "contact pair %d", pair);
    R->oracles[O_FRICTION_ARGS]++;
    R->oracles[O_WEIGHTING] += unserved;
    if (st == TFEM_STATUS_OK && unserved)
      finding(R, V_WEIGHTING, idx, "tfem_set_friction(pair %d, mu %g) is OK under the mortar weighting (refused where it "
              "is set since dc75b81)", pair, mu);
    else if (st == TFEM_STATUS_OK && !valid)
      finding(R, V_FRICTION, idx, "tfem_set_friction(pair %d, mu %g) is OK with %d pair(s) declared", pair, mu, s->npairs);
    else if (unserved && (st != TFEM_STATUS_INVALID_ARGUMENT || !strstr(msg, named) || !strstr(msg, "friction")))
      finding(R, V_WEIGHTING, idx, "tfem_set_friction(pair %d, mu %g) under the mortar weighting: %s, not "
              "INVALID_ARGUMENT naming \"%s\" and friction: \"%.160s\"", pair, mu, status_name(st), named, msg);
    else if (st != TFEM_STATUS_OK && valid && !unserved)
      finding(R, V_FRICTION, idx, "tfem_set_friction(pair %d of %d, mu %g) refused: %s \"%.160s\"", pair, s->npairs, mu,
              status_name(st), msg);
    else if (st != TFEM_STATUS_OK && st != TFEM_STATUS_INVALID_ARGUMENT)
      finding(R, V_FRICTION, idx, "tfem_set_friction(pair %d, mu %g) refused with %s, not INVALID_ARGUMENT", pair, mu,
              status_name(st));
  }
  if (!c->null_model && fn == F_ADD_CONTACT_PAIR_WITH_MESH && s->has_mesh) {
    /* a pair's own contact mesh under the forced mortar weighting (which
     * makes no B): refused by this call since dc75b81, INVALID_ARGUMENT
     * naming it (other refusals may come first: the triangles' indices,
     * the tags, no triangles); under the other weightings never refused
     * for that */
    int mortar = s->weighting == TFEM_CONTACT_WEIGHTING_MORTAR, own = strstr(msg, "contact mesh of its own") != NULL;
    R->oracles[O_WEIGHTING] += mortar;
    if (mortar && st == TFEM_STATUS_OK)
      finding(R, V_WEIGHTING, idx, "tfem_add_contact_pair_with_mesh is OK under the mortar weighting (refused since "
              "dc75b81: the mortar weighting uses no mesh B)");
    else if (own && st != TFEM_STATUS_INVALID_ARGUMENT)
      finding(R, V_WEIGHTING, idx, "tfem_add_contact_pair_with_mesh refused for its own contact mesh with %s, not "
              "INVALID_ARGUMENT: \"%.160s\"", status_name(st), msg);
    else if (!mortar && st != TFEM_STATUS_OK && own)
      finding(R, V_WEIGHTING, idx, "tfem_add_contact_pair_with_mesh refused for its own mesh under weighting %d (only the "
              "mortar weighting refuses it): \"%.160s\"", s->weighting, msg);
  }
  if (!c->null_model && fn == F_SET_PRESCRIBED && (s->exact || !s->has_mesh)) {
    /* accepted exactly for a component prescribed before and a finite value */
    long node = (long)c->iv[0] - s->base;
    int comp = c->iv[1];
    int valid = s->has_mesh && node >= 0 && node < s->nn && (comp == 0 || comp == 1) && isfinite(c->dv[0]) &&
                !isnan(s->presc[2 * node + comp]);
    R->oracles[O_PRESCRIBED]++;
    if (st == TFEM_STATUS_OK && !valid)
      finding(R, V_PRESCRIBED, idx, "tfem_set_prescribed(node %d, component %d, %g) is OK: %s", c->iv[0], comp, c->dv[0],
              !s->has_mesh ? "no mesh" : node < 0 || node >= s->nn ? "no such node" : comp != 0 && comp != 1
              ? "no such component" : !isfinite(c->dv[0]) ? "value not finite" : "not prescribed before");
    else if (st != TFEM_STATUS_OK && valid)
      finding(R, V_PRESCRIBED, idx, "tfem_set_prescribed(node %d, component %d, %g) refused although prescribed (%g): %s \"%.160s\"",
              c->iv[0], comp, c->dv[0], s->presc[2 * node + comp], status_name(st), msg);
  }
  if (!c->null_model && fn == F_ADD_CONTACT_PAIRS_AUTO && st != TFEM_STATUS_OK && s->has_mesh && c->iv[0] >= 0 &&
      (c->iv[0] == 0 || !c->in[0].null_) && !(isfinite(c->dv[0]) && c->dv[0] >= 0) && st != TFEM_STATUS_INVALID_ARGUMENT)
    finding(R, V_AUTO_PAIRS, idx, "tolerance %g refused with %s, not INVALID_ARGUMENT", c->dv[0], status_name(st));
  /* ---- the mortar weighting (tfem_set_contact_weighting) ---- */
  int known_revert = 0; /* (the defect above, when not checked) */
#if !API_FUZZ_REVERT_AFRESH
  known_revert = fn == F_REVERT_STEP && st == TFEM_STATUS_INVALID_ARGUMENT && strstr(msg, "0 contact parts");
#endif
  if (fn == F_REVERT_STEP && !c->null_model && st != TFEM_STATUS_OK && st != TFEM_STATUS_INVALID_STATE && !known_revert)
    finding(R, V_STEP, idx, "%s (the header: refused with INVALID_STATE only, when there is no step to revert or the "
            "contact mesh changed since): \"%.160s\"", status_name(st), msg);
  if (c->want && R->pristine && idx < R->full_prefix && st != c->want - 1 && !known_revert &&
      !(fn == F_GET_ADAPT_CYCLES && s->adapt_n < 0)) /* (cycles not known here: the switch above) */
    finding(R, strcmp(R->cs->kind, "axisymmetric") == 0 ? V_AXI
               : strcmp(R->cs->kind, "adaptive") == 0   ? V_ADAPT
               : strcmp(R->cs->kind, "ring") == 0       ? V_CIRCLE
               : strcmp(R->cs->kind, "mortar") == 0 || fn == F_SET_CONTACT_WEIGHTING || fn == F_GET_CONTACT_WEIGHTING
                   ? V_WEIGHTING : V_STEP,
            idx, "%s, the scene expects %s (weighting %d): \"%.160s\"", status_name(st), status_name(c->want - 1),
            s->weighting, msg);
  if (!c->null_model && fn == F_SET_CONTACT_WEIGHTING) {
    /* 0, 1 or 2 accepted, anything else INVALID_ARGUMENT naming
     * "weighting = N" (the replay checks that a refusal changed nothing;
     * get_weighting that the shadow's is kept). The mortar weighting
     * forced where a pair has friction or a contact mesh of its own is
     * refused since dc75b81, INVALID_ARGUMENT naming the first such pair
     * (the doc of tfem_set_contact_weighting in src/ffi/entry.rs; the
     * model unchanged). unserved: that pair, -1 none, -2 not known here */
    int w = c->iv[0], valid = w == TFEM_CONTACT_WEIGHTING_STRIP || w == TFEM_CONTACT_WEIGHTING_MORTAR ||
                              w == TFEM_CONTACT_WEIGHTING_AUTO;
    int unserved = -1;
    if (w == TFEM_CONTACT_WEIGHTING_MORTAR && s->has_mesh) {
      if (s->npairs > 64) unserved = -2;
      for (int k = 0; k < s->npairs && k < 64 && unserved == -1; ++k)
        if (s->pair_mu[k] > 0.0 || s->pair_user[k]) unserved = k;
    }
    char named[48], pnamed[48];
    snprintf(named, sizeof named, "weighting = %d", w);
    snprintf(pnamed, sizeof pnamed, "contact pair %d has", unserved);
    R->oracles[O_WEIGHTING]++;
    if (w == TFEM_CONTACT_WEIGHTING_MORTAR && s->axi) {
      /* (axisymmetric bodies take B: the mortar weighting refused,
       * INVALID_ARGUMENT, src/model/problem.rs set_contact_weighting) */
      R->oracles[O_AXI]++;
      if (st != TFEM_STATUS_INVALID_ARGUMENT)
        finding(R, V_AXI, idx, "tfem_set_contact_weighting(1) with axisymmetric bodies: %s, not INVALID_ARGUMENT: "
                "\"%.160s\"", status_name(st), msg);
    } else if (unserved >= 0 && st == TFEM_STATUS_OK)
      finding(R, V_WEIGHTING, idx, "tfem_set_contact_weighting(1) is OK with pair %d %s (refused since dc75b81)",
              unserved, s->pair_user[unserved] ? "declared with a contact mesh of its own" : "frictional");
    else if (unserved >= 0 && (st != TFEM_STATUS_INVALID_ARGUMENT || !strstr(msg, pnamed)))
      finding(R, V_WEIGHTING, idx, "tfem_set_contact_weighting(1) with pair %d %s: %s, not INVALID_ARGUMENT naming "
              "\"%s\": \"%.160s\"", unserved, s->pair_user[unserved] ? "declared with a contact mesh of its own"
              : "frictional", status_name(st), pnamed, msg);
    else if (unserved != -1)
      ;
    else if (st == TFEM_STATUS_OK && !valid)
      finding(R, V_WEIGHTING, idx, "tfem_set_contact_weighting(%d) is OK (0 strip, 1 mortar, 2 automatic only)", w);
    else if (st != TFEM_STATUS_OK && valid)
      finding(R, V_WEIGHTING, idx, "tfem_set_contact_weighting(%d) refused: %s \"%.160s\"", w, status_name(st), msg);
    else if (st != TFEM_STATUS_OK && st != TFEM_STATUS_INVALID_ARGUMENT)
      finding(R, V_WEIGHTING, idx, "tfem_set_contact_weighting(%d) refused with %s, not INVALID_ARGUMENT", w,
              status_name(st));
    else if (st == TFEM_STATUS_INVALID_ARGUMENT && !strstr(msg, named))
      finding(R, V_WEIGHTING, idx, "tfem_set_contact_weighting(%d) refused without naming \"%s\": \"%.160s\"", w, named,
              msg);
  }
  if (!c->null_model && fn == F_GET_CONTACT_WEIGHTING && !c->out[0].null_) {
    int w = INT_MIN;
    if (st == TFEM_STATUS_OK) memcpy(&w, g[0].p, sizeof w);
    R->oracles[O_WEIGHTING]++;
    if (st != TFEM_STATUS_OK)
      finding(R, V_WEIGHTING, idx, "tfem_get_contact_weighting refused: %s \"%.160s\"", status_name(st), msg);
    else if (w != s->weighting)
      finding(R, V_WEIGHTING, idx, "weighting %d, but the last one set successfully is %d (2, automatic, the default)", w,
              s->weighting);
  }
  int contact_results = s->has_mesh && !s->res_unknown && (s->results == 2 || s->results == 3);
  if (!c->null_model && fn == F_GET_CONTACT_SLAVE_NODES && s->has_mesh && !s->res_unknown) {
    /* after a contact solve or step where some pair is under the mortar
     * weighting: OK, BUFFER_TOO_SMALL for length < n; else (no contact
     * results, or no such pair) INVALID_STATE, after a solve naming the
     * strip weighting for every pair */
    int served = contact_results && slave_served, refused = !contact_results || slave_refused;
    long n = c->out[0].req;
    R->oracles[O_WEIGHTING] += served || refused;
    if (refused && st != TFEM_STATUS_INVALID_STATE)
      finding(R, V_WEIGHTING, idx, "%s %s: \"%.160s\"", status_name(st),
              !contact_results  ? "without contact results"
              : s->results == 2 ? "after a contact solve with no pair under the mortar weighting"
                                : "after a load step with no pair under the mortar weighting",
              msg);
    else if (refused && contact_results && !strstr(msg, "strip weighting for every pair"))
      finding(R, V_WEIGHTING, idx, "INVALID_STATE with no pair under the mortar weighting (%s), the message does not "
              "say the strip weighting for every pair: \"%.160s\"", fam_name(fam), msg);
    else if (served && n >= 0 && c->out[0].len < (size_t)n && st != TFEM_STATUS_BUFFER_TOO_SMALL)
      finding(R, V_WEIGHTING, idx, "%s with length %zu for %ld slave nodes: \"%.160s\"", status_name(st), c->out[0].len,
              n, msg);
    else if (served && n >= 0 && c->out[0].len >= (size_t)n && st != TFEM_STATUS_OK)
      finding(R, V_WEIGHTING, idx, "%s after a solve or step with %s, length %zu for %ld slave nodes: \"%.160s\"",
              status_name(st), fam_name(fam), c->out[0].len, n, msg);
  }
  if (!c->null_model && st == TFEM_STATUS_OK && fn == F_GET_CONTACT_SLAVE_NODES) oracle_slave_nodes(R, idx, c, g);
  if (!c->null_model && per_element && contact_results && elem_refused) {
    R->oracles[O_WEIGHTING]++;
    if (st != TFEM_STATUS_INVALID_STATE && !(st == TFEM_STATUS_NULL_POINTER && c->out[0].null_))
      finding(R, V_WEIGHTING, idx, "%s after a %s with the mortar weighting for every pair (the header: refused, "
              "INVALID_STATE)", status_name(st), s->results == 3 ? "load step" : "solve");
    else if (st == TFEM_STATUS_INVALID_STATE && !strstr(msg, "mortar weighting for every pair"))
      finding(R, V_WEIGHTING, idx, "INVALID_STATE with the mortar weighting for every pair, the message does not say "
              "so: \"%.160s\"", msg);
  }
  if (!c->null_model && contact_results && (per_element || fn == F_GET_CONTACT_SLAVE_NODES)) {
    /* Whatever the families: one of the two kinds of output is served
     * after a contact solve or step (a pair is weighted by B or by weighted
     * gaps), each answer kept until the results change, and a refusal
     * names the other family (the families not known here included) */
    int slave = fn == F_GET_CONTACT_SLAVE_NODES, seen = -1;
    if (st == TFEM_STATUS_OK || st == TFEM_STATUS_BUFFER_TOO_SMALL) seen = 1;
    else if (st == TFEM_STATUS_INVALID_STATE &&
             strstr(msg, slave ? "strip weighting for every pair" : "mortar weighting for every pair"))
      seen = 0;
    if (R->fam_gen != s->sol_gen) R->fam_gen = s->sol_gen, R->seen_elem = R->seen_slave = -1;
    int *mine = slave ? &R->seen_slave : &R->seen_elem, other = slave ? R->seen_elem : R->seen_slave;
    if (seen >= 0) {
      R->oracles[O_WEIGHTING]++;
      if (*mine >= 0 && *mine != seen)
        finding(R, V_WEIGHTING, idx, "%s %s, %s before on the same results", slave ? "slave nodes" : "per-element output",
                seen ? "served" : "refused", seen ? "refused" : "served");
      else if (seen == 0 && other == 0)
        finding(R, V_WEIGHTING, idx, "refused, and so were the %s on the same results (%d pairs): neither family",
                slave ? "per-element outputs" : "slave nodes", s->npairs);
      *mine = seen;
    }
  }
  if (!c->null_model && fn == F_SET_CONTACT_STATE && s->has_mesh && !c->in[0].null_ && s->npairs > 0) {
    /* the contact states are served whatever the weighting (since
     * 56d2e1d; before, INVALID_STATE naming "contact states" under the
     * mortar one), each naming its contact mesh: the elements of B of the
     * pairs weighted by B and the slave nodes' weighted gaps of the others
     * (src/model/restart.rs fingerprint_of). A state read (its bytes
     * intact) while the pairs' families were others (sh_fam_sig: another
     * weighting, or friction that takes a pair to B under the automatic
     * one) belongs to another contact mesh: refused, INVALID_ARGUMENT
     * saying so (a pair with its own contact mesh, which the mortar
     * weighting does not serve, may be refused otherwise; so may a state
     * whose contact mesh the mortar weighting cannot make:
     * INVALID_CONTACT, an interface in pieces). The same families under
     * another weighting value (the automatic weighting giving the strip's
     * B on straight sides) are the same contact mesh: no expectation. */
    size_t n = (size_t)c->in[0].n;
    long w = -1, now = sh_fam_sig(s);
    if (R->st_last && n == R->n_last && memcmp(c->in[0].p, R->st_last, n) == 0) w = R->st_last_w;
    else if (R->st_prev && n == R->n_prev && memcmp(c->in[0].p, R->st_prev, n) == 0) w = R->st_prev_w;
    if (w >= 0 && now >= 0 && w >> 20 == now >> 20 && w != now) {
      R->oracles[O_WEIGHTING]++;
      if (st == TFEM_STATUS_OK)
        finding(R, V_WEIGHTING, idx, "OK with a contact state read with the mortar weighting on pairs %#lx, now on %#lx "
                "(weighting %d; the header: a state of another contact mesh is refused)", w & 0xfffff, now & 0xfffff,
                s->weighting);
      else if (st == TFEM_STATUS_INVALID_ARGUMENT && !s->mesh_pairs && !strstr(msg, "another contact mesh"))
        finding(R, V_WEIGHTING, idx, "INVALID_ARGUMENT for a contact state read with the mortar weighting on pairs %#lx, "
                "now on %#lx, not naming another contact mesh: \"%.160s\"", w & 0xfffff, now & 0xfffff, msg);
    }
  }
  if (!c->null_model && fn == F_STEP && st == TFEM_STATUS_OK && !(isfinite(c->dv[2]) && fabs(c->dv[2]) <= 1e300))
    finding(R, V_STEP, idx, "OK with load_factor = %.17g (the header: finite, at most 1e300 in magnitude)", c->dv[2]);
  if (!c->null_model && (fn == F_SOLVE_CONTACT || fn == F_STEP) && s->has_mesh && s->npairs <= 64) {
    /* where some pair is under the mortar weighting, on the pairs' own
     * sides (refactorize, interfaces too large to condense and interfaces
     * of no free unknown are accepted by steps under either weighting
     * since 56d2e1d: each step a contact solve of its scaled loads): the
     * stick law and the literal test refused whenever one is. Friction and
     * a pair's own contact mesh are refused where they are set since
     * dc75b81 (tfem_set_friction, tfem_set_contact_weighting,
     * tfem_add_contact_pair_with_mesh; checked above): no such pair is
     * under the mortar weighting at a solve (under the automatic weighting
     * those pairs get B), and the solve is not refused for them. No pair,
     * no refusal (the strip's B is empty: nothing the weighting does not
     * serve). */
    int some = 0;
    for (int k = 0; k < s->npairs; ++k) some |= sh_pair_family(s, k) == FAM_MORTAR;
    int stick = !c->in[0].null_ && c->iv[0] == TFEM_CONTACT_LAW_STICK;
    int literal = !c->in[0].null_ && c->iv[1] == TFEM_INVERSION_TEST_LITERAL;
    const char *why = !some ? NULL : stick ? "the stick law" : literal ? "the literal inversion test" : NULL;
    R->oracles[O_WEIGHTING] += why != NULL;
    if (!why && some && st == TFEM_STATUS_INVALID_ARGUMENT &&
        (strstr(msg, "has friction") || strstr(msg, "contact mesh of its own")))
      finding(R, V_WEIGHTING, idx, "refused at the solve for friction or an own contact mesh under the mortar weighting "
              "(refused where they are set since dc75b81, never by the solve): \"%.160s\"", msg);
    if (why && st == TFEM_STATUS_OK)
      finding(R, V_WEIGHTING, idx, "OK with %s under the mortar weighting (weighting %d: %s)", why, s->weighting,
              fam_name(sh_families(s)));
  }

  if (st == TFEM_STATUS_OK && !c->null_model) {
    switch (fn) {
    case F_SET_MESH: {
      int base = c->iv[2];
      int *tri0 = xmalloc(sizeof(int) * 3 * (size_t)c->iv[1] + 1);
      for (int k = 0; k < 3 * c->iv[1]; ++k) tri0[k] = ((const int *)c->in[1].p)[k] - base;
      sh_new_mesh(s, c->iv[0], c->in[0].p, c->iv[1], tri0, c->in[2].p, base);
      free(tri0);
      break;
    }
    case F_LOAD_GMSH:
      if (c->iv[0] == G_VALID || c->iv[0] == G_CLOCKWISE) {
        sh_gmsh_square(s, c->iv[1]);
      } else {
        sh_clear_mesh(s);
        s->has_mesh = 1;
      }
      break;
    case F_SET_BOUNDARY_EDGES: case F_ADD_BOUNDARY_EDGES:
      for (int k = 0; k < s->ncirc && k < 16; ++k) s->circ_clean[k] = 0; /* (a circle's tag may have other edges) */
      break; /* (the shadow's edges: below) */
    case F_SET_BOUNDARY_CIRCLE: {
      /* a circle replaces the one declared on its tag; nothing of a solve changes */
      int k = 0;
      while (k < s->ncirc && k < 16 && s->circ_tag[k] != c->iv[0]) ++k;
      if (k == s->ncirc) s->ncirc++;
      if (k < 16) {
        s->circ_tag[k] = c->iv[0];
        s->circ[k][0] = c->dv[0], s->circ[k][1] = c->dv[1], s->circ[k][2] = c->dv[2];
        s->circ_clean[k] = 1;
      }
      goto keep_results;
    }
    case F_SET_MATERIAL: {
      int k = sh_material(s, c->iv[0]);
      if (k < 0 && s->nmat < 16) k = s->nmat++;
      if (k >= 0) {
        s->mat_body[k] = c->iv[0];
        s->mat_plane[k] = c->iv[1];
        s->mat_young[k] = c->dv[0];
        s->mat_nu[k] = c->dv[1];
      }
      s->axi = c->iv[1] == TFEM_PLANE_MODE_AXISYMMETRIC; /* (one section for all: a mix is refused) */
      break;
    }
    case F_FIX: case F_FIX_EDGES:
      if (s->exact) {
        int comp = c->iv[1], reported = 0, nodes[2];
        double v = c->dv[0];
        for (int e = 0; e < (fn == F_FIX ? 1 : s->ne); ++e) {
          if (fn == F_FIX_EDGES && s->tag[e] != c->iv[0]) continue;
          int nk = fn == F_FIX ? 1 : 2;
          nodes[0] = fn == F_FIX ? c->iv[0] - s->base : s->edge[2 * e];
          nodes[1] = fn == F_FIX ? nodes[0] : s->edge[2 * e + 1];
          for (int k = 0; k < nk; ++k) {
            double *p = &s->presc[2 * nodes[k] + comp];
            if (!isnan(*p) && *p != v && !reported) {
              finding(R, V_DOUBLE_FIX, idx, "component %d of node %d was prescribed to %g and is now set to %g: OK",
                      comp, nodes[k] + s->base, *p, v);
              reported = 1;
            }
            *p = v;
          }
        }
      }
      s->presc_nonempty = 1;
      break;
    case F_CLEAR_CONSTRAINTS:
      if (s->exact)
        for (int g2 = 0; g2 < 2 * s->nn; ++g2) s->presc[g2] = NAN;
      if (!s->presc_nonempty) goto keep_results;
      s->presc_nonempty = 0;
      break;
    case F_ADD_PRESSURE: case F_ADD_TRACTION:
      if (s->exact) {
        s->load = xrealloc(s->load, sizeof(sh_load) * (size_t)(s->nl + 1));
        s->load[s->nl++] = (sh_load){c->iv[0], fn == F_ADD_TRACTION, c->dv[0], c->dv[1]};
      }
      break;
    case F_ADD_NODAL_FORCE:
      if (s->exact) {
        s->nforce[2 * (c->iv[0] - s->base)] += c->dv[0];
        s->nforce[2 * (c->iv[0] - s->base) + 1] += c->dv[1];
      }
      break;
    case F_SET_BODY_FORCE: {
      int b = 0;
      while (b < s->nbf && s->bf_body[b] != c->iv[0]) ++b;
      if (b < 16) {
        if (b == s->nbf) s->nbf++;
        s->bf_body[b] = c->iv[0];
        s->bf[b][0] = c->dv[0];
        s->bf[b][1] = c->dv[1];
      }
      break;
    }
    case F_CLEAR_LOADS:
      s->nl = 0;
      s->nbf = 0;
      if (s->exact) memset(s->nforce, 0, sizeof(double) * 2 * (size_t)s->nn);
      break;
    case F_ADD_CONTACT_PAIR: case F_ADD_CONTACT_PAIR_WITH_MESH:
      if (!c->out[0].null_) {
        int pr;
        memcpy(&pr, g[0].p, sizeof pr);
        if (pr != s->npairs) finding(R, V_CONTACT, idx, "pair index %d, but %d pairs were declared before", pr, s->npairs);
      }
      if (s->npairs < 16) {
        s->pair_tag[s->npairs][0] = c->iv[0];
        s->pair_tag[s->npairs][1] = c->iv[1];
      }
      if (s->npairs < 64) s->pair_mu[s->npairs] = 0.0, s->pair_user[s->npairs] = fn == F_ADD_CONTACT_PAIR_WITH_MESH;
      s->npairs++;
      s->mesh_pairs += fn == F_ADD_CONTACT_PAIR_WITH_MESH;
      break;
    case F_SET_CONTACT_WEIGHTING:
      if (c->iv[0] == s->weighting) goto keep_results; /* the same: nothing changes */
      s->weighting = c->iv[0];
      break; /* a change discards the results */
    case F_SET_THREADS:
      if (c->iv[0] < 0) finding(R, V_THREADS, idx, "tfem_set_threads(%d) is OK", c->iv[0]);
      s->threads = c->iv[0];
      goto keep_results;
    case F_GET_THREADS:
      if (!c->out[0].null_) {
        int n;
        memcpy(&n, g[0].p, sizeof n);
        if (n < 1 || (s->threads >= 1 && n != s->threads))
          finding(R, V_THREADS, idx, "%d threads, after tfem_set_threads(%d)", n, s->threads);
        R->oracles[O_THREADS] += s->threads >= 1;
      }
      goto keep_results;
    case F_GET_CONTACT_PAIR_BODIES:
      if (s->has_mesh && (c->iv[0] < 0 || c->iv[0] >= s->npairs)) {
        finding(R, V_CONTACT, idx, "OK for pair %d, but %d pairs were declared", c->iv[0], s->npairs);
      } else if (s->exact && c->iv[0] < 16 && s->pair_tag[c->iv[0]][0] != INT_MIN) {
        /* a pair's body is that of the triangles owning its tag's edges */
        for (int side = 0; side < 2; ++side) {
          if (c->out[side].null_) continue;
          int b, found = 0, owned = 0, third;
          memcpy(&b, g[side].p, sizeof b);
          for (int e = 0; e < s->ne && !found; ++e) {
            if (s->tag[e] != s->pair_tag[c->iv[0]][side]) continue;
            int t = sh_owner(s, s->edge[2 * e], s->edge[2 * e + 1], &third);
            if (t >= 0) owned = 1, found = s->body[t] == b;
          }
          if (owned && !found)
            finding(R, V_CONTACT, idx, "body_%c = %d, but no edge tagged %d is on that body", 'a' + side, b,
                    s->pair_tag[c->iv[0]][side]);
        }
      }
      goto keep_results;
    case F_GET_CONTACT_MESH_SIZE:
      if (s->exact && s->npairs == 0 && !c->out[0].null_) {
        int n;
        memcpy(&n, g[0].p, sizeof n);
        if (n != 0) finding(R, V_CONTACT, idx, "%d contact elements without any contact pair", n);
      }
      goto keep_results;
    case F_GET_CONTACT_MESH: case F_GET_CONTACT_ELEMENTS:
      if (out_full(c, 0) && s->exact) {
        /* the contact mesh before a solve is the contact elements after it */
        long n = c->out[0].req;
        const int *v = (const int *)(const void *)g[0].p;
        for (long k = 0; k < n && fn == F_GET_CONTACT_MESH; ++k)
          if (v[k] < s->base || v[k] >= s->base + s->nn) {
            finding(R, V_CONTACT, idx, "contact element node %d out of range", v[k]);
            break;
          }
        int mesh = fn == F_GET_CONTACT_MESH;
        /* (the contact elements cover the pairs weighted by B only) */
        if (!mesh && (s->results != 2 || (s->res_fam & (FAM_MORTAR | FAM_UNKNOWN)))) goto keep_results;
        int *other = mesh ? s->celem : s->cmesh;
        long no = mesh ? s->ncelem : s->ncmesh, og = mesh ? s->celem_gen : s->cmesh_gen;
        R->oracles[O_MESH_EQ] += og == s->prob_gen;
        if (og == s->prob_gen && (no != n || (n && memcmp(other, v, sizeof(int) * (size_t)n) != 0))) {
          long k = 0;
          while (k < n && k < no && other[k] == v[k]) ++k;
          finding(R, V_CONTACT, idx, "%ld contact element nodes, %ld %s of call #%d (first difference at %ld)", n, no,
                  mesh ? "in the contact elements" : "in the contact mesh", mesh ? s->celem_idx : s->cmesh_idx, k);
        }
        int **mine = mesh ? &s->cmesh : &s->celem;
        free(*mine);
        *mine = xmalloc(sizeof(int) * (size_t)n + 1);
        if (n) memcpy(*mine, v, sizeof(int) * (size_t)n);
        if (mesh) s->ncmesh = n, s->cmesh_gen = s->prob_gen, s->cmesh_idx = idx;
        else s->ncelem = n, s->celem_gen = s->prob_gen, s->celem_idx = idx;
      }
      goto keep_results;
    case F_GET_CONTACT_ELEMENT_PAIRS:
      if (out_full(c, 0) && s->has_mesh)
        for (long k = 0; k < c->out[0].req; ++k) {
          int v;
          memcpy(&v, g[0].p + sizeof(int) * (size_t)k, sizeof v);
          if (v < 0 || v >= s->npairs) {
            finding(R, V_CONTACT, idx, "element %ld belongs to pair %d, but %d pairs were declared", k, v, s->npairs);
            break;
          }
        }
      goto keep_results;
    case F_GET_CONTACT_ELEMENT_APEXES:
      if (out_full(c, 0) && s->exact) {
        int *cm;
        long ne = fetch_contact_mesh(R->m, &cm, NULL);
        R->oracles[O_APEX] += ne > 0;
        for (long k = 0; k < ne && k < c->out[0].req; ++k) {
          int v;
          memcpy(&v, g[0].p + sizeof(int) * (size_t)k, sizeof v);
          if (v != cm[3 * k] && v != cm[3 * k + 1] && v != cm[3 * k + 2]) {
            finding(R, V_CONTACT, idx, "apex %d of element %ld is not one of its nodes %d %d %d", v, k, cm[3 * k],
                    cm[3 * k + 1], cm[3 * k + 2]);
            break;
          }
        }
        free(cm);
      }
      goto keep_results;
    case F_GET_CONTACT_FORCES:
      if (out_full(c, 0) && s->exact && s->results == 2 && c->out[0].req == 2L * s->nn)
        oracle_contact_forces(R, idx, (const double *)(const void *)g[0].p);
      goto keep_results;
    case F_GET_CONTACT_GAPS:
      if (out_full(c, 0) && s->exact && s->results == 2 && c->out[0].req == s->nn)
        oracle_gaps(R, idx, (const double *)(const void *)g[0].p);
      goto keep_results;
    case F_GET_CONTACT_NODAL_PRESSURES:
      if (out_full(c, 0) && s->exact && s->results == 2 && c->out[0].req == s->nn)
        oracle_nodal_pressures(R, idx, (const double *)(const void *)g[0].p);
      goto keep_results;
    case F_GET_CONTACT_PAIR_NODAL_PRESSURES:
      if (s->has_mesh && (c->iv[0] < 0 || c->iv[0] >= s->npairs))
        finding(R, V_CONTACT, idx, "OK for contact pair %d of the %d declared", c->iv[0], s->npairs);
      else if (out_full(c, 0) && s->exact && s->results == 2 && c->out[0].req == s->nn &&
               (API_FUZZ_MORTAR_CUT_READING || !(s->res_fam & (FAM_MORTAR | FAM_UNKNOWN)) || s->npairs < 2))
        oracle_pair_nodal_pressures(R, idx, c->iv[0], (const double *)(const void *)g[0].p);
      goto keep_results;
    case F_GET_EXTERNAL_WORK:
      if (!c->out[0].null_ && s->exact && s->results && s->results != 3) { /* (a step's loads are scaled) */
        double w;
        memcpy(&w, g[0].p, sizeof w);
        oracle_work(R, idx, w);
      }
      goto keep_results;
    case F_STEP:
      /* a step's results (where a pair is under the mortar weighting, a
       * frictionless step of the linearised test: its pairs per slave node) */
      s->contact_law = c->in[0].null_ ? TFEM_CONTACT_LAW_FRICTIONLESS : c->iv[0];
      s->pre_results = s->results;
      s->pre_res_fam = s->res_fam;
      s->pre_valid = !s->res_unknown;
      s->pre_disp_ok = s->pre_valid && s->results && s->disp_gen == s->sol_gen;
      s->pre_disp_hash = s->disp_hash;
      s->pre_disp_idx = s->disp_idx;
      s->results = 3;
      s->res_fam = sh_families(s);
      s->hist_sig = sh_fam_sig(s);
      if (s->res_fam & FAM_MORTAR) s->contact_test = TFEM_INVERSION_TEST_LINEARISED;
      s->no_matrix = 1;
      s->res_unknown = 0;
      s->sol_gen++;
      goto keep_results;
    case F_REVERT_STEP:
      /* the results before the step (unknown if the step is not known
       * here), their displacements bit for bit if they were read */
      if (s->pre_valid) s->results = s->pre_results, s->res_fam = s->pre_res_fam;
      else s->res_unknown = 1;
      s->contact_law = -1; /* (the law of the results before the step: not kept here) */
      s->sol_gen++;
      if (s->pre_valid && s->pre_disp_ok) {
        s->disp_hash = s->pre_disp_hash;
        s->disp_gen = s->sol_gen;
        s->disp_idx = s->pre_disp_idx;
        s->disp_reverted = 1;
      }
      s->pre_valid = s->pre_disp_ok = 0;
      goto keep_results;
    case F_SOLVE: case F_SOLVE_CONTACT: case F_SOLVE_ADAPTIVE: {
      /* (an adaptive solve: a contact solve when the model has pairs; a
       * refined mesh is not known here: the shadow's mesh stops being exact,
       * its contact mesh is another) */
      int contact = fn == F_SOLVE_CONTACT || (fn == F_SOLVE_ADAPTIVE && s->npairs > 0), was_exact = s->exact;
      if (fn == F_SOLVE_ADAPTIVE) {
        int nn = -1, nt = -1;
        if (tfem_get_sizes(R->m, &nn, &nt, NULL) != TFEM_STATUS_OK || !s->exact || nn != s->nn || nt != s->nt) {
          s->exact = 0;
          s->prob_gen++;
        }
      }
      s->results = contact ? 2 : 1;
      s->no_matrix = 0;
      s->res_unknown = 0;
      s->pre_valid = s->pre_disp_ok = 0;
      s->matrix_dropped = 0;
      s->sol_gen++;
      s->contact_test = contact && !c->in[0].null_ ? c->iv[1] : TFEM_INVERSION_TEST_LINEARISED;
      s->res_fam = contact ? sh_families(s) : 0;
      s->contact_law = contact && !c->in[0].null_ ? c->iv[0] : TFEM_CONTACT_LAW_FRICTIONLESS;
      s->relres = NAN;
      if (!c->out[0].null_ && fn != F_SOLVE_ADAPTIVE) {
        const tfem_solve_info *inf = fn == F_SOLVE ? (const tfem_solve_info *)(const void *)g[0].p
                                                   : &((const tfem_contact_report *)(const void *)g[0].p)->info;
        s->relres = inf->relative_residual;
        s->cond = inf->condition_estimate;
      }
      if (was_exact)
        for (int l = 0; l < s->nl; ++l) {
          int found = 0;
          for (int e = 0; e < s->ne && !found; ++e) found = s->tag[e] == s->load[l].tag;
          if (!found) {
            finding(R, V_DROPPED_LOAD, idx, "the %s on tag %d is ignored: no boundary edge has that tag any more",
                    s->load[l].type ? "traction" : "pressure", s->load[l].tag);
            break;
          }
        }
      goto keep_results;
    }
    case F_GET_DISPLACEMENTS:
      if (c->oracle && R->pristine && idx < R->full_prefix && o[0]) {
        double u;
        memcpy(&u, g[0].p + 8 * (size_t)(2 * c->or_node + c->or_comp), 8);
        if (!(fabs(u - c->or_expect) <= c->or_rtol * fabs(c->or_expect)))
          finding(R, V_ORACLE, idx, "u%c of node %d = %.6g, exact %.6g (ratio %.3g); status OK, %s", c->or_comp ? 'y' : 'x',
                  c->or_node + s->base, u, c->or_expect, u / c->or_expect,
                  strcmp(R->cs->kind, "clockwise_square") == 0 ? "mesh given clockwise" : "counter-clockwise mesh");
      }
      if (out_full(c, 0) && s->results) {
        /* results are kept, bit for bit, until a solve succeeds or the
         * problem changes (tfem_set_threads, tfem_set_ordering and failed
         * solves keep them) */
        uint64_t h = fnv64(g[0].p, sizeof(double) * (size_t)c->out[0].req);
        R->oracles[O_DISP_KEPT] += s->disp_gen == s->sol_gen;
        if (s->disp_gen == s->sol_gen && h != s->disp_hash)
          finding(R, V_RESULTS_CHANGED, idx, "displacements differ from those of call #%d, although no solve succeeded "
                  "and nothing changed the problem since%s", s->disp_idx,
                  s->disp_reverted ? " but a tfem_revert_step of the step after it" : "");
        s->disp_reverted = 0;
        s->disp_hash = h;
        s->disp_gen = s->sol_gen;
        s->disp_idx = idx;
      }
      goto keep_results;
    case F_GET_REACTIONS:
      if (s->exact && s->results == 1 && o[0] && isfinite(s->relres) && s->relres < 1e-9 && s->cond < 1e10 &&
          c->out[0].len >= 2 * (size_t)s->nn) {
        /* (Only for plain solves without prescribed displacements: with
         * them, or with the initial-gap loads of contact elements, the
         * internal forces, and their round-off, are not bounded by the
         * loads.) */
        double tot[2], mag, rs[2] = {0, 0}, rmag = 0;
        int zero_presc = 1;
        for (int g2 = 0; g2 < 2 * s->nn; ++g2) zero_presc &= isnan(s->presc[g2]) || s->presc[g2] == 0.0;
        if (zero_presc && sh_total_force(s, tot, &mag)) {
          for (int g2 = 0; g2 < 2 * s->nn; ++g2) {
            double v;
            memcpy(&v, g[0].p + 8 * (size_t)g2, 8);
            rs[g2 % 2] += v;
            rmag += fabs(v);
          }
          for (int k = 0; k < 2; ++k)
            if (fabs(rs[k] + tot[k]) > 1e-6 * (mag + rmag) && isfinite(rmag) && mag > 1e-200 && mag < 1e200)
              finding(R, V_EQUILIBRIUM, idx, "sum of reactions %c = %.9g, applied loads %.9g (imbalance %.3g of %.3g)",
                      k ? 'y' : 'x', rs[k], tot[k], rs[k] + tot[k], mag + rmag);
        }
      }
      goto keep_results;
    case F_GET_MATRIX:
      if (out_full(c, 0) && out_full(c, 1) && out_full(c, 2) && out_full(c, 3) && s->results) {
        /* the matrix too is kept, bit for bit (a failed solve rebuilds it) */
        uint64_t h = 0;
        for (int j = 0; j < 4; ++j) h = h * 31 + fnv64(g[j].p, ksize(g[j].kind) * (size_t)c->out[j].req);
        R->oracles[O_DISP_KEPT] += s->mat_gen == s->sol_gen;
        if (s->mat_gen == s->sol_gen && h != s->mat_hash)
          finding(R, V_RESULTS_CHANGED, idx, "system matrix differs from that of call #%d, although no solve succeeded "
                  "and nothing changed the problem since", s->mat_idx);
        s->mat_hash = h;
        s->mat_gen = s->sol_gen;
        s->mat_idx = idx;
      }
      goto keep_results;
    case F_RECREATE:
      sh_clear_mesh(s);
      s->threads = 0;
      s->weighting = TFEM_CONTACT_WEIGHTING_AUTO;
      s->nmat = s->axi = 0;
      s->adapt_n = 0;
      goto keep_results;
    case F_GET_OUT_OF_PLANE:
      if (c->oracle == 2 && R->pristine && idx < R->full_prefix && out_full(c, 0)) {
        /* a pristine scene's closed form: every value within or_rtol of or_expect's magnitude of 0 */
        const double *v = (const double *)(const void *)g[0].p;
        for (long t = 0; t < c->out[0].req; ++t)
          if (!(fabs(v[t]) <= c->or_rtol * fabs(c->or_expect))) {
            finding(R, V_AXI, idx, "triangle %ld: out-of-plane (hoop) stress %.6g, exactly 0 for the uniform axial "
                    "stress %g of this scene", t + s->base, v[t], c->or_expect);
            break;
          }
      }
      if (out_full(c, 0) && s->exact && s->results && !s->res_unknown && c->out[0].req == s->nt)
        oracle_out_of_plane(R, idx, (const double *)(const void *)g[0].p);
      goto keep_results;
    case F_SET_CONTACT_STATE: {
#if !API_FUZZ_FRICTION_STATE_RESULTS
      int any_mu = s->npairs > 64;
      for (int k = 0; k < s->npairs && k < 64; ++k) any_mu |= s->pair_mu[k] != 0.0;
      if (any_mu && s->results == 3) s->res_unknown = 1; /* (the known defect above) */
#endif
      goto keep_results;
    }
    case F_GET_CONTACT_SHEAR: case F_GET_CONTACT_FRICTION_STATE: case F_GET_CONTACT_DISSIPATION:
      if (out_full(c, 0)) oracle_coulomb(R, idx);
      goto keep_results;
    case F_SET_FRICTION:
      if (c->iv[0] < 0 || c->iv[0] >= 64) { /* (not known here) */
        s->res_unknown = 1;
        goto keep_results;
      }
      if (memcmp(&s->pair_mu[c->iv[0]], &c->dv[0], sizeof(double)) == 0) goto keep_results; /* no change */
      s->pair_mu[c->iv[0]] = c->dv[0];
      break;
    case F_SET_PRESCRIBED:
      if (s->exact) {
        long node = (long)c->iv[0] - s->base;
        if (node < 0 || node >= s->nn || c->iv[1] < 0 || c->iv[1] > 1) goto keep_results; /* (a finding above) */
        double *pv = &s->presc[2 * node + c->iv[1]];
        if (memcmp(pv, &c->dv[0], sizeof(double)) == 0) goto keep_results; /* the same value: no change */
        *pv = c->dv[0];
      }
      break;
    case F_ADD_CONTACT_PAIRS_AUTO: {
      /* first = the pairs declared before, count = the pairs that
       * tfem_get_contact_pair_bodies then knows beyond them, bodies
       * different; the scene's expectation when pristine */
      int first = INT_MIN, count = INT_MIN, ab[64][2];
      if (!c->out[0].null_) memcpy(&first, g[0].p, sizeof first);
      if (!c->out[1].null_) memcpy(&count, g[1].p, sizeof count);
      if (c->iv[0] < 0 || !(isfinite(c->dv[0]) && c->dv[0] >= 0))
        finding(R, V_AUTO_PAIRS, idx, "OK with n_tags %d, tolerance %g", c->iv[0], c->dv[0]);
      for (int k = 0; s->exact && c->iv[0] > 0 && !c->in[0].null_ && k < c->iv[0] && k < c->in[0].n; ++k) {
        int tag = ((const int *)c->in[0].p)[k], any = 0;
        for (int e = 0; e < s->ne && !any; ++e) any = s->tag[e] == tag;
        if (!any) {
          finding(R, V_AUTO_PAIRS, idx, "OK with tag %d, which names no boundary edge", tag);
          break;
        }
      }
      if (first != INT_MIN && first != s->npairs)
        finding(R, V_AUTO_PAIRS, idx, "first = %d, but %d pair(s) were declared before", first, s->npairs);
      int from = first != INT_MIN ? first : s->npairs, n = probe_pairs(R->m, from, ab, 64);
      R->oracles[O_AUTO_PAIRS]++;
      if (count != INT_MIN && count != n)
        finding(R, V_AUTO_PAIRS, idx, "count = %d, but tfem_get_contact_pair_bodies knows %d pair(s) from %d on", count, n, from);
      for (int k = 0; k < n && k < 64; ++k)
        if (ab[k][0] == ab[k][1]) {
          finding(R, V_AUTO_PAIRS, idx, "pair %d joins two tags of body %d", from + k, ab[k][0]);
          break;
        }
      if (c->expect >= 0 && R->pristine && idx < R->full_prefix && n != c->expect)
        finding(R, V_AUTO_PAIRS, idx, "%d pair(s) added (tags %s, tolerance %g), the scene expects %d (tags 2 and 3 face "
                "each other within the gap)", n, c->iv[0] ? "given" : "all", c->dv[0], c->expect);
      c->got = n;
      int known = c->tw == 3 && n == 1 && c->expect == 1 && R->pristine && idx < R->full_prefix;
      for (int k = s->npairs; k < s->npairs + n; ++k) {
        if (k < 16) s->pair_tag[k][0] = known ? c->tw_a : INT_MIN, s->pair_tag[k][1] = known ? c->tw_b : INT_MIN;
        if (k < 64) s->pair_mu[k] = 0.0, s->pair_user[k] = 0;
      }
      s->npairs += n;
      if (n == 0) goto keep_results;
      break;
    }
    default:
      if (!changes_problem(fn)) goto keep_results;
      break;
    }
    s->results = 0; /* a change of the problem discards the results */
    s->res_unknown = 0;
    s->pre_valid = s->pre_disp_ok = 0;
    s->matrix_dropped = 0;
    s->prob_gen++;
    s->sol_gen++;
  keep_results:;
  }
  if (st != TFEM_STATUS_OK && !c->null_model && (fn == F_SOLVE || fn == F_SOLVE_CONTACT || fn == F_SOLVE_ADAPTIVE))
    s->matrix_dropped = 1;
  if (!API_FUZZ_ADAPT_FAILURE_RESTORES && st != TFEM_STATUS_OK && !c->null_model && fn == F_SOLVE_ADAPTIVE) {
    /* (the defects above, when not checked) */
    s->adapt_n = -1;
    if (st != TFEM_STATUS_INVALID_ARGUMENT || c->refine_refused) s->res_unknown = 1;
  }

  /* Keep the outputs for the replay. */
  keep_outputs(c, st, nout, ver, g);
}

/* ------------------------------------------------------------------------ */
/* The C reproducer                                                          */
/* ------------------------------------------------------------------------ */

static void c_str(FILE *f, const char *s, size_t n) {
  fputc('"', f);
  int col = 0;
  for (size_t i = 0; i < n; ++i) {
    unsigned char ch = (unsigned char)s[i];
    if (ch == '\n') {
      fputs("\\n\"\n      \"", f);
      col = 0;
      continue;
    }
    if (ch >= 32 && ch < 127 && ch != '"' && ch != '\\' && ch != '?') {
      fputc(ch, f);
      ++col;
    } else {
      fprintf(f, "\\%03o", ch);
      col += 4;
    }
    if (col > 90) {
      fputs("\"\n      \"", f);
      col = 0;
    }
  }
  fputc('"', f);
}

static const char *c_type(int kind) {
  switch (kind) {
  case K_D: return "double";
  case K_I: return "int";
  case K_L: return "int64_t";
  case K_C: return "char";
  case K_Z: return "size_t";
  case K_U8: return "uint8_t";
  case K_SI: return "tfem_solve_info";
  case K_RE: return "tfem_contact_report";
  case K_AR: return "tfem_adapt_report";
  case K_T: return "double";
  default: return "tfem_contact_options";
  }
}

static const char *G_REPRO[NGMSH];

static void c_emit_header(FILE *f, const case_t *cs) {
  fprintf(f,
          "/* Reproducer of api_fuzz --seed %" PRIu64 " --replay-case %ld (%s scene).\n"
          " * Build: gcc -std=c11 repro.c -Iinclude -Ltarget/release -ltfem -lm\n"
          " * Run:   LD_LIBRARY_PATH=target/release ./a.out\n"
          " * Run A makes every call; run B, on a fresh model, only those that\n"
          " * succeeded in run A: a difference between the A and B lines of a\n"
          " * call that succeeded in both means a failed call changed the model. */\n"
          "#include <math.h>\n#include <stdint.h>\n#include <stdio.h>\n#include <string.h>\n"
          "#include <sys/stat.h>\n#include \"tfem.h\"\n\n"
          "#define REPRO_DIR \"/tmp/api_fuzz_repro\"\n"
          "static const char *L = \"A\";\nstatic int skip(int k);\n"
          "static inline void show(const tfem_model *m, int k, const char *fn, tfem_status s) {\n"
          "  char b[4096] = \"\";\n  if (s != TFEM_STATUS_OK) tfem_last_error(m, b, sizeof b);\n"
          "  printf(\"%%s #%%d %%s -> %%d %%s\\n\", L, k, fn, (int)s, b);\n}\n"
          "static inline void show_c(const tfem_contact *c, int k, const char *fn, tfem_status s) {\n"
          "  char b[4096] = \"\";\n  if (s != TFEM_STATUS_OK) {\n    if (c) tfem_contact_last_error(c, b, sizeof b);\n"
          "    else tfem_last_error(NULL, b, sizeof b);\n  }\n"
          "  printf(\"%%s #%%d %%s -> %%d %%s\\n\", L, k, fn, (int)s, b);\n}\n"
          "static inline void show_s(const tfem_solid_model *m, int k, const char *fn, tfem_status s) {\n"
          "  char b[4096] = \"\";\n  if (s != TFEM_STATUS_OK) {\n    if (m) tfem_solid_last_error(m, b, sizeof b);\n"
          "    else tfem_last_error(NULL, b, sizeof b);\n  }\n"
          "  printf(\"%%s #%%d %%s -> %%d %%s\\n\", L, k, fn, (int)s, b);\n}\n"
          "static inline void show_sc(const tfem_solid_contact *c, int k, const char *fn, tfem_status s) {\n"
          "  char b[4096] = \"\";\n  if (s != TFEM_STATUS_OK) {\n    if (c) tfem_solid_contact_last_error(c, b, sizeof b);\n"
          "    else tfem_last_error(NULL, b, sizeof b);\n  }\n"
          "  printf(\"%%s #%%d %%s -> %%d %%s\\n\", L, k, fn, (int)s, b);\n}\n"
          "static inline unsigned long long fnv(const void *p, size_t n) {\n"
          "  unsigned long long h = 1469598103934665603ULL;\n"
          "  for (size_t i = 0; i < n; ++i) h = (h ^ ((const unsigned char *)p)[i]) * 1099511628211ULL;\n"
          "  return h;\n}\n"
          "static inline void dump_d(int k, const char *w, const double *v, size_t n) {\n"
          "  size_t bad = 0;\n  for (size_t i = 0; i < n; ++i) bad += !isfinite(v[i]);\n"
          "  printf(\"%%s #%%d %%s: %%zu values, %%zu not finite, hash %%016llx:\", L, k, w, n, bad, fnv(v, n * sizeof *v));\n"
          "  for (size_t i = 0; i < n && i < 4; ++i) printf(\" %%.17g\", v[i]);\n  printf(\"\\n\");\n}\n"
          "static inline void dump_i(int k, const char *w, const int *v, size_t n) {\n"
          "  printf(\"%%s #%%d %%s: %%zu values, hash %%016llx:\", L, k, w, n, fnv(v, n * sizeof *v));\n"
          "  for (size_t i = 0; i < n && i < 6; ++i) printf(\" %%d\", v[i]);\n  printf(\"\\n\");\n}\n"
          "static inline void dump_l(int k, const char *w, const int64_t *v, size_t n) {\n"
          "  printf(\"%%s #%%d %%s: %%zu values, hash %%016llx:\", L, k, w, n, fnv(v, n * sizeof *v));\n"
          "  for (size_t i = 0; i < n && i < 6; ++i) printf(\" %%lld\", (long long)v[i]);\n  printf(\"\\n\");\n}\n"
          "static inline void dump_info(int k, const tfem_solve_info *i) {\n"
          "  printf(\"%%s #%%d info: unknowns %%lld nnz %%lld factorizations %%lld relative_residual %%.17g condition %%.17g\\n\",\n"
          "         L, k, (long long)i->unknowns, (long long)i->matrix_nnz, (long long)i->factorizations,\n"
          "         i->relative_residual, i->condition_estimate);\n}\n"
          "static inline void dump_report(int k, const tfem_contact_report *r) {\n"
          "  printf(\"%%s #%%d report: iterations %%d elements %%d active %%d contact_length %%.17g max_penetration %%.17g\\n\",\n"
          "         L, k, r->iterations, r->elements, r->active, r->contact_length, r->max_penetration);\n"
          "  dump_info(k, &r->info);\n}\n"
          "static inline void write_file(const char *path, const char *text, size_t n) {\n"
          "  mkdir(REPRO_DIR, 0700);\n  FILE *f = fopen(path, \"wb\");\n"
          "  if (f) {\n    fwrite(text, 1, n, f);\n    fclose(f);\n  }\n}\n\n"
          "static void run(void) {\n  tfem_model *m = tfem_create();\n  tfem_contact *cx = NULL;\n  tfem_status s;\n  (void)s;\n",
          cs->seed, cs->index, cs->kind);
  if (cs->solid)
    fprintf(f, "  tfem_solid_model *sm = tfem_solid_create();\n  tfem_solid_contact *scx = NULL;\n"
               "  tfem_contact *ocx = tfem_contact_create(0); /* (a handle of another kind) */\n"
               "  (void)sm, (void)scx, (void)ocx;\n");
}

static void c_emit_call(FILE *f, const call_t *c, int idx) {
  int fn = c->fn;
  char b1[64];
  const char *M = c->null_model ? "NULL" : "m";
  fprintf(f, "  if (!skip(%d)) {\n", idx);
  /* the handle of another kind the call is given, or one destroyed just before */
  static const char *const KT[5] = {"", "tfem_model", "tfem_contact", "tfem_solid_model", "tfem_solid_contact"};
  static const char *const HV[5] = {"", "m", "ocx", "sm", "scx"};
  char hx[96] = "";
  int kind = FN[fn].model;
  if (c->handle && !c->null_model && kind) {
    if (c->handle == 5) {
      static const char *const mk[5] = {"", "tfem_create()", "tfem_contact_create(0)", "tfem_solid_create()",
                                        "tfem_solid_contact_create(0, NULL)"};
      static const char *const rm[5] = {"", "tfem_destroy", "tfem_contact_destroy", "tfem_solid_destroy",
                                         "tfem_solid_contact_destroy"};
      fprintf(f, "    %s *dead = %s;\n    %s(dead); /* (a destroyed handle) */\n", KT[kind], mk[kind], rm[kind]);
      snprintf(hx, sizeof hx, "dead");
    } else {
      snprintf(hx, sizeof hx, "(%s *)%s", KT[kind], HV[c->handle]);
    }
    M = hx;
  }
  for (int j = 0; j < fn_nin(fn); ++j) {
    char role = FN[fn].ink[j];
    if (role == 'o' || role == 'r' || c->in[j].null_ || (fn == F_CONTACT_SCATTER_ADD && j == 1 && c->out[0].null_)) continue;
    if (role == 'q' || role == 's') {
      fprintf(f, "    static const %s a%d[%d] = {", role == 'q' ? "int64_t" : "uint8_t", j, c->in[j].n > 0 ? c->in[j].n : 1);
      for (int k = 0; k < c->in[j].n; ++k)
        fprintf(f, "%s%s%lld", k ? "," : "", k && k % 12 == 0 ? "\n      " : (k ? " " : ""),
                role == 'q' ? (long long)((int64_t *)c->in[j].p)[k] : (long long)((unsigned char *)c->in[j].p)[k]);
      if (c->in[j].n == 0) fprintf(f, "0");
    } else if (role == 'x' || role == 'U') {
      fprintf(f, "    static const double a%d[%d] = {", j, c->in[j].n > 0 ? c->in[j].n : 1);
      for (int k = 0; k < c->in[j].n; ++k)
        fprintf(f, "%s%s%s", k ? "," : "", k && k % 6 == 0 ? "\n      " : (k ? " " : ""), cdbl(((double *)c->in[j].p)[k], b1));
      if (c->in[j].n == 0) fprintf(f, "0");
    } else {
      fprintf(f, "    static const int a%d[%d] = {", j, c->in[j].n > 0 ? c->in[j].n : 1);
      for (int k = 0; k < c->in[j].n; ++k)
        fprintf(f, "%s%s%d", k ? "," : "", k && k % 12 == 0 ? "\n      " : (k ? " " : ""), ((int *)c->in[j].p)[k]);
      if (c->in[j].n == 0) fprintf(f, "0");
    }
    fprintf(f, "};\n");
  }
  for (int j = 0; j < fn_nout(fn); ++j) {
    if (c->out[j].null_) continue;
    int k = out_kind(fn, j);
    if (FN[fn].scalar_out) fprintf(f, "    %s o%d;\n    memset(&o%d, 0x5a, sizeof o%d);\n", c_type(k), j, j, j);
    else fprintf(f, "    static %s o%d[%zu];\n", c_type(k), j, c->out[j].len ? c->out[j].len : 1);
  }
  char a[MAXIN][8], o[MAXOUT][8];
  for (int j = 0; j < MAXIN; ++j) snprintf(a[j], sizeof a[j], c->in[j].null_ ? "NULL" : "a%d", j);
  for (int j = 0; j < MAXOUT; ++j)
    snprintf(o[j], sizeof o[j], c->out[j].null_ ? "NULL" : FN[fn].scalar_out ? "&o%d" : "o%d", j);
  char d[MAXD][64];
  for (int k = 0; k < MAXD; ++k) cdbl(c->dv[k], d[k]);
  const int *I = c->iv;
  size_t *len = (size_t[]){c->out[0].len, c->out[1].len, c->out[2].len, c->out[3].len};
  const char *sl = FN[fn].model == 1 && !hx[0] ? M : "NULL";
  const char *H = hx[0] ? hx : c->null_model ? "NULL" : "cx";
  const char *SM = hx[0] ? hx : c->null_model ? "NULL" : "sm", *SX = hx[0] ? hx : c->null_model ? "NULL" : "scx";
  size_t ul = c->in[0].n > 0 ? (size_t)c->in[0].n : 0;
  switch (fn) {
  case F_VERSION: fprintf(f, "    printf(\"%%s #%d version %%s\\n\", L, tfem_version());\n", idx); break;
  case F_LAST_ERROR: fprintf(f, "    s = tfem_last_error(%s, %s, %zu);\n", M, o[0], len[0]); break;
  case F_LAST_ERROR_LENGTH: fprintf(f, "    printf(\"%%s #%d length %%zu\\n\", L, tfem_last_error_length(%s));\n", idx, M); break;
  case F_WARNING_COUNT: fprintf(f, "    s = tfem_warning_count(%s, %s);\n", M, o[0]); break;
  case F_GET_WARNING: fprintf(f, "    s = tfem_get_warning(%s, %d, %s, %zu);\n", M, I[0], o[0], len[0]); break;
  case F_SET_MESH: fprintf(f, "    s = tfem_set_mesh(%s, %d, %s, %d, %s, %s, %d);\n", M, I[0], a[0], I[1], a[1], a[2], I[2]); break;
  case F_LOAD_GMSH:
    if (I[0] < 0 || I[0] >= NGMSH) {
      fprintf(f, "    s = tfem_load_gmsh(%s, NULL, %d);\n", M, I[1]);
    } else {
      if (g_text[I[0]] && I[0] != G_DIRECTORY && I[0] != G_NONEXISTENT && I[0] != G_BAD_UTF8) {
        fprintf(f, "    write_file(%s, ", G_REPRO[I[0]]);
        c_str(f, g_text[I[0]], g_len[I[0]]);
        fprintf(f, ", %zu);\n", g_len[I[0]]);
      }
      if (I[0] == G_DIRECTORY) fprintf(f, "    mkdir(REPRO_DIR, 0700);\n");
      fprintf(f, "    s = tfem_load_gmsh(%s, %s, %d);\n", M, G_REPRO[I[0]], I[1]);
    }
    break;
  case F_SET_BOUNDARY_EDGES: fprintf(f, "    s = tfem_set_boundary_edges(%s, %d, %s, %s);\n", M, I[0], a[0], a[1]); break;
  case F_SET_MATERIAL: fprintf(f, "    s = tfem_set_material(%s, %d, %s, %s, %d);\n", M, I[0], d[0], d[1], I[1]); break;
  case F_SET_TEMPERING: fprintf(f, "    s = tfem_set_tempering(%s, %d, %s);\n", M, I[0], d[0]); break;
  case F_SET_ORDERING: fprintf(f, "    s = tfem_set_ordering(%s, %d, %d);\n", M, I[0], I[1]); break;
  case F_FIX: fprintf(f, "    s = tfem_fix(%s, %d, %d, %s);\n", M, I[0], I[1], d[0]); break;
  case F_FIX_EDGES: fprintf(f, "    s = tfem_fix_edges(%s, %d, %d, %s);\n", M, I[0], I[1], d[0]); break;
  case F_CLEAR_CONSTRAINTS: fprintf(f, "    s = tfem_clear_constraints(%s);\n", M); break;
  case F_ADD_PRESSURE: fprintf(f, "    s = tfem_add_pressure(%s, %d, %s);\n", M, I[0], d[0]); break;
  case F_ADD_TRACTION: fprintf(f, "    s = tfem_add_traction(%s, %d, %s, %s);\n", M, I[0], d[0], d[1]); break;
  case F_ADD_NODAL_FORCE: fprintf(f, "    s = tfem_add_nodal_force(%s, %d, %s, %s);\n", M, I[0], d[0], d[1]); break;
  case F_SET_BODY_FORCE: fprintf(f, "    s = tfem_set_body_force(%s, %d, %s, %s);\n", M, I[0], d[0], d[1]); break;
  case F_CLEAR_LOADS: fprintf(f, "    s = tfem_clear_loads(%s);\n", M); break;
  case F_SOLVE: fprintf(f, "    s = tfem_solve(%s, %s);\n", M, o[0]); break;
  case F_GET_SIZES: fprintf(f, "    s = tfem_get_sizes(%s, %s, %s, %s);\n", M, o[0], o[1], o[2]); break;
  case F_GET_DISPLACEMENTS: fprintf(f, "    s = tfem_get_displacements(%s, %s, %zu);\n", M, o[0], len[0]); break;
  case F_GET_STRAINS: fprintf(f, "    s = tfem_get_element_strains(%s, %s, %zu);\n", M, o[0], len[0]); break;
  case F_GET_STRESSES: fprintf(f, "    s = tfem_get_element_stresses(%s, %s, %zu);\n", M, o[0], len[0]); break;
  case F_GET_JACOBIANS: fprintf(f, "    s = tfem_get_element_jacobians(%s, %s, %zu);\n", M, o[0], len[0]); break;
  case F_GET_REACTIONS: fprintf(f, "    s = tfem_get_reactions(%s, %s, %zu);\n", M, o[0], len[0]); break;
  case F_GET_MATRIX_SIZE: fprintf(f, "    s = tfem_get_system_matrix_size(%s, %s, %s);\n", M, o[0], o[1]); break;
  case F_GET_MATRIX:
    fprintf(f, "    s = tfem_get_system_matrix(%s, %s, %zu, %s, %zu, %s, %zu, %s, %zu);\n", M, o[0], len[0], o[1], len[1], o[2],
            len[2], o[3], len[3]);
    break;
  case F_ELEMENT_STIFFNESS: fprintf(f, "    s = tfem_element_stiffness(%s, %s, %s, %d, %s, %s);\n", a[0], d[0], d[1], I[0], d[2], o[0]); break;
  case F_LAPLACIAN_STIFFNESS: fprintf(f, "    s = tfem_laplacian_stiffness(%s, %s, %s, %s);\n", a[0], d[0], d[1], o[0]); break;
  case F_ADD_CONTACT_PAIR: fprintf(f, "    s = tfem_add_contact_pair(%s, %d, %d, %s);\n", M, I[0], I[1], o[0]); break;
  case F_ADD_CONTACT_PAIR_WITH_MESH:
    fprintf(f, "    s = tfem_add_contact_pair_with_mesh(%s, %d, %d, %d, %s, %s, %s);\n", M, I[0], I[1], I[2], a[0], o[0], o[1]);
    break;
  case F_CONTACT_OPTIONS_DEFAULT: fprintf(f, "    s = tfem_contact_options_default(%s);\n", o[0]); break;
  case F_SOLVE_CONTACT:
    if (c->in[0].null_) {
      fprintf(f, "    s = tfem_solve_contact(%s, NULL, %s);\n", M, o[0]);
    } else {
      fprintf(f, "    tfem_contact_options opt = {%d, %s, %s, %d, %d, %d};\n", I[0], d[0], d[1], I[1], I[2], I[3]);
      fprintf(f, "    s = tfem_solve_contact(%s, &opt, %s);\n", M, o[0]);
    }
    break;
  case F_GET_CONTACT_ACTIVE: fprintf(f, "    s = tfem_get_contact_active(%s, %s, %zu);\n", M, o[0], len[0]); break;
  case F_GET_CONTACT_PRESSURE: fprintf(f, "    s = tfem_get_contact_pressure(%s, %s, %zu);\n", M, o[0], len[0]); break;
  case F_GET_CONTACT_ELEMENTS: fprintf(f, "    s = tfem_get_contact_elements(%s, %s, %zu);\n", M, o[0], len[0]); break;
  case F_GET_CONTACT_REPORT: fprintf(f, "    s = tfem_get_contact_report(%s, %s);\n", M, o[0]); break;
  case F_ADD_BOUNDARY_EDGES: fprintf(f, "    s = tfem_add_boundary_edges(%s, %d, %s, %s);\n", M, I[0], a[0], a[1]); break;
  case F_GET_EXTERNAL_WORK: fprintf(f, "    s = tfem_get_external_work(%s, %s);\n", M, o[0]); break;
  case F_GET_CONTACT_FORCES: fprintf(f, "    s = tfem_get_contact_forces(%s, %s, %zu);\n", M, o[0], len[0]); break;
  case F_GET_CONTACT_GAPS: fprintf(f, "    s = tfem_get_contact_gaps(%s, %s, %zu);\n", M, o[0], len[0]); break;
  case F_GET_CONTACT_NODAL_PRESSURES:
    fprintf(f, "    s = tfem_get_contact_nodal_pressures(%s, %s, %zu);\n", M, o[0], len[0]);
    break;
  case F_GET_CONTACT_PAIR_NODAL_PRESSURES:
    fprintf(f, "    s = tfem_get_contact_pair_nodal_pressures(%s, %d, %s, %zu);\n", M, I[0], o[0], len[0]);
    break;
  case F_GET_CONTACT_MESH_SIZE: fprintf(f, "    s = tfem_get_contact_mesh_size(%s, %s);\n", M, o[0]); break;
  case F_GET_CONTACT_MESH: fprintf(f, "    s = tfem_get_contact_mesh(%s, %s, %zu);\n", M, o[0], len[0]); break;
  case F_GET_CONTACT_ELEMENT_PAIRS:
    fprintf(f, "    s = tfem_get_contact_element_pairs(%s, %s, %zu);\n", M, o[0], len[0]);
    break;
  case F_GET_CONTACT_ELEMENT_APEXES:
    fprintf(f, "    s = tfem_get_contact_element_apexes(%s, %s, %zu);\n", M, o[0], len[0]);
    break;
  case F_GET_CONTACT_PAIR_BODIES:
    fprintf(f, "    s = tfem_get_contact_pair_bodies(%s, %d, %s, %s);\n", M, I[0], o[0], o[1]);
    break;
  case F_SET_THREADS: fprintf(f, "    s = tfem_set_threads(%s, %d);\n", M, I[0]); break;
  case F_GET_THREADS: fprintf(f, "    s = tfem_get_threads(%s, %s);\n", M, o[0]); break;
  case F_STEP:
    if (c->in[0].null_) {
      fprintf(f, "    s = tfem_step(%s, %s, NULL, %s);\n", M, d[2], o[0]);
    } else {
      fprintf(f, "    tfem_contact_options opt = {%d, %s, %s, %d, %d, %d};\n", I[0], d[0], d[1], I[1], I[2], I[3]);
      fprintf(f, "    s = tfem_step(%s, %s, &opt, %s);\n", M, d[2], o[0]);
    }
    break;
  case F_REVERT_STEP: fprintf(f, "    s = tfem_revert_step(%s);\n", M); break;
  case F_GET_CONTACT_STATE_SIZE: fprintf(f, "    s = tfem_get_contact_state_size(%s, %s);\n", M, o[0]); break;
  case F_GET_CONTACT_STATE: fprintf(f, "    s = tfem_get_contact_state(%s, (uint8_t *)%s, %zu);\n", M, o[0], len[0]); break;
  case F_SET_CONTACT_STATE: fprintf(f, "    s = tfem_set_contact_state(%s, %s, %zu);\n", M, a[0], ul); break;
  case F_CONTACT_CREATE:
    fprintf(f, "    tfem_contact *nc = tfem_contact_create(%d);\n    s = nc ? TFEM_STATUS_OK : TFEM_STATUS_INVALID_ARGUMENT;\n"
               "    if (nc) {\n      tfem_contact_destroy(cx);\n      cx = nc;\n    }\n", I[0]);
    break;
  case F_CONTACT_DESTROY:
    fprintf(f, "    tfem_contact_destroy(%s);\n", H);
    if (!c->null_model) fprintf(f, "    cx = NULL;\n");
    break;
  case F_CONTACT_LAST_ERROR: fprintf(f, "    s = tfem_contact_last_error(%s, %s, %zu);\n", H, o[0], len[0]); break;
  case F_CONTACT_SET_OPTIONS:
    if (c->in[0].null_) {
      fprintf(f, "    s = tfem_contact_set_options(%s, NULL);\n", H);
    } else {
      fprintf(f, "    tfem_contact_options opt = {%d, %s, %s, %d, %d, %d};\n", I[0], d[0], d[1], I[1], I[2], I[3]);
      fprintf(f, "    s = tfem_contact_set_options(%s, &opt);\n", H);
    }
    break;
  case F_CONTACT_ADD_SIDE:
    fprintf(f, "    s = tfem_contact_add_side(%s, %d, %d, %s, %s, %d, %d, %s, %s, %s, %d, %s, %s);\n", H, I[0], I[1], d[0], d[1],
            I[2], I[3], a[0], a[1], a[2], I[4], a[3], o[0]);
    break;
  case F_CONTACT_ADD_PAIR: fprintf(f, "    s = tfem_contact_add_pair(%s, %d, %d, %s);\n", H, I[0], I[1], o[0]); break;
  case F_CONTACT_ADD_PAIR_WITH_MESH:
    fprintf(f, "    s = tfem_contact_add_pair_with_mesh(%s, %d, %d, %d, %s, %s);\n", H, I[0], I[1], I[2], a[0], o[0]);
    break;
  case F_CONTACT_SIZES: fprintf(f, "    s = tfem_contact_sizes(%s, %s, %s, %s);\n", H, o[0], o[1], o[2]); break;
  case F_CONTACT_NODES: fprintf(f, "    s = tfem_contact_nodes(%s, %s, %zu);\n", H, o[0], len[0]); break;
  case F_CONTACT_PATTERN: fprintf(f, "    s = tfem_contact_pattern(%s, %s, %s, %zu);\n", H, o[0], o[1], len[0]); break;
  case F_CONTACT_EVALUATE:
    fprintf(f, "    s = tfem_contact_evaluate(%s, %s, %zu, %s, %zu, %s, %zu);\n", H, a[0], ul, o[0], len[0], o[1], len[1]);
    break;
  case F_CONTACT_GATHER: fprintf(f, "    s = tfem_contact_gather(%s, %s, %zu, %s, %zu);\n", H, a[0], ul, o[0], len[0]); break;
  case F_CONTACT_SCATTER_ADD:
    if (!c->out[0].null_) fprintf(f, "    memcpy(o0, a1, sizeof o0);\n");
    fprintf(f, "    s = tfem_contact_scatter_add(%s, %s, %zu, %s, %zu);\n", H, a[0], ul, o[0], len[0]);
    break;
  case F_CONTACT_UPDATE: fprintf(f, "    s = tfem_contact_update(%s, %s, %zu, %s);\n", H, a[0], ul, o[0]); break;
  case F_CONTACT_RESTART: fprintf(f, "    s = tfem_contact_restart(%s);\n", H); break;
  case F_CONTACT_GET_ACTIVE: fprintf(f, "    s = tfem_contact_get_active(%s, %s, %zu);\n", H, o[0], len[0]); break;
  case F_CONTACT_SET_ACTIVE: fprintf(f, "    s = tfem_contact_set_active(%s, %s, %zu);\n", H, a[0], ul); break;
  case F_CONTACT_GAPS: fprintf(f, "    s = tfem_contact_gaps(%s, %s, %zu, %s, %zu);\n", H, a[0], ul, o[0], len[0]); break;
  case F_CONTACT_PRESSURES: fprintf(f, "    s = tfem_contact_pressures(%s, %s, %zu, %s, %zu);\n", H, a[0], ul, o[0], len[0]); break;
  case F_CONTACT_ELEMENTS: fprintf(f, "    s = tfem_contact_elements(%s, %s, %zu);\n", H, o[0], len[0]); break;
  case F_CONTACT_ELEMENT_EQUATIONS: fprintf(f, "    s = tfem_contact_element_equations(%s, %s, %zu);\n", H, o[0], len[0]); break;
  case F_CONTACT_ELEMENT_BLOCKS: fprintf(f, "    s = tfem_contact_element_blocks(%s, %s, %zu);\n", H, o[0], len[0]); break;
  case F_CONTACT_LENGTH: fprintf(f, "    s = tfem_contact_length(%s, %s);\n", H, o[0]); break;
  case F_GET_CONTACT_SHEAR: fprintf(f, "    s = tfem_get_contact_shear(%s, %s, %zu);\n", M, o[0], len[0]); break;
  case F_GET_CONTACT_FRICTION_STATE:
    fprintf(f, "    s = tfem_get_contact_friction_state(%s, %s, %zu);\n", M, o[0], len[0]);
    break;
  case F_GET_CONTACT_DISSIPATION:
    fprintf(f, "    s = tfem_get_contact_dissipation(%s, %s, %zu);\n", M, o[0], len[0]);
    break;
  case F_SET_FRICTION: fprintf(f, "    s = tfem_set_friction(%s, %d, %s);\n", M, I[0], d[0]); break;
  case F_SET_PRESCRIBED: fprintf(f, "    s = tfem_set_prescribed(%s, %d, %d, %s);\n", M, I[0], I[1], d[0]); break;
  case F_ADD_CONTACT_PAIRS_AUTO:
    fprintf(f, "    s = tfem_add_contact_pairs_auto(%s, %d, %s, %s, %s, %s);\n", M, I[0], a[0], d[0], o[0], o[1]);
    break;
  case F_WRITE_VTU: {
    static const char *const vp[NVTU] = {"REPRO_DIR \"/out.vtu\"", "REPRO_DIR \"/\\377\\376.vtu\"",
                                         "REPRO_DIR \"/no_such_dir/out.vtu\"", "REPRO_DIR", "\"\""};
    int k = I[0];
    if (k >= 0 && k < NVTU && k != VP_NO_DIR && k != VP_EMPTY) fprintf(f, "    mkdir(REPRO_DIR, 0700);\n");
    fprintf(f, "    s = tfem_write_vtu(%s, %s);\n", M, k >= 0 && k < NVTU ? vp[k] : "NULL");
    break;
  }
  case F_GET_WARNING_SIZE: fprintf(f, "    s = tfem_get_warning_size(%s, %d, %s);\n", M, I[0], o[0]); break;
  case F_CONTACT_LAST_ERROR_LENGTH:
    fprintf(f, "    printf(\"%%s #%d length %%zu\\n\", L, tfem_contact_last_error_length(%s));\n", idx, H);
    break;
  case F_SET_CONTACT_WEIGHTING: fprintf(f, "    s = tfem_set_contact_weighting(%s, %d);\n", M, I[0]); break;
  case F_GET_CONTACT_WEIGHTING: fprintf(f, "    s = tfem_get_contact_weighting(%s, %s);\n", M, o[0]); break;
  case F_GET_CONTACT_SLAVE_NODES:
    fprintf(f, "    s = tfem_get_contact_slave_nodes(%s, %s, %s, %s, %s, %zu);\n", M, o[0], o[1], o[2], o[3], len[0]);
    break;
  case F_GET_OUT_OF_PLANE:
    fprintf(f, "    s = tfem_get_element_out_of_plane_stresses(%s, %s, %zu);\n", M, o[0], len[0]);
    break;
  case F_SOLVE_ADAPTIVE: {
    char mu[32];
    int64_t u = adapt_max_unknowns(I[6]);
    if (u == INT64_MAX) snprintf(mu, sizeof mu, "INT64_MAX");
    else if (u == INT64_MIN) snprintf(mu, sizeof mu, "INT64_MIN");
    else snprintf(mu, sizeof mu, "%" PRId64, u);
    if (!c->in[0].null_)
      fprintf(f, "    tfem_contact_options opt = {%d, %s, %s, %d, %d, %d};\n", I[0], d[0], d[1], I[1], I[2], I[3]);
    fprintf(f, "    s = tfem_solve_adaptive(%s, %s, %d, %s, %d, %s, %s);\n", M, d[2], I[4], mu, I[5],
            c->in[0].null_ ? "NULL" : "&opt", o[0]);
    break;
  }
  case F_GET_ADAPT_CYCLES:
    fprintf(f, "    s = tfem_get_adapt_cycles(%s, %s, %s, %s, %zu);\n", M, o[0], o[1], o[2], len[0]);
    break;
  case F_SET_BOUNDARY_CIRCLE:
    fprintf(f, "    s = tfem_set_boundary_circle(%s, %d, %s, %s, %s);\n", M, I[0], d[0], d[1], d[2]);
    break;
  case F_DESTROY_NULL: fprintf(f, "    tfem_destroy(NULL);\n"); break;
  case F_RECREATE: fprintf(f, "    tfem_destroy(m);\n    m = tfem_create();\n"); break;
  /* the 3D model */
  case F_S_LAST_ERROR: fprintf(f, "    s = tfem_solid_last_error(%s, %s, %zu);\n", SM, o[0], len[0]); break;
  case F_S_LAST_ERROR_LENGTH:
    fprintf(f, "    printf(\"%%s #%d length %%zu\\n\", L, tfem_solid_last_error_length(%s));\n", idx, SM);
    break;
  case F_S_WARNING_COUNT: fprintf(f, "    s = tfem_solid_warning_count(%s, %s);\n", SM, o[0]); break;
  case F_S_GET_WARNING_SIZE: fprintf(f, "    s = tfem_solid_get_warning_size(%s, %d, %s);\n", SM, I[0], o[0]); break;
  case F_S_GET_WARNING: fprintf(f, "    s = tfem_solid_get_warning(%s, %d, %s, %zu);\n", SM, I[0], o[0], len[0]); break;
  case F_S_SET_MESH:
    fprintf(f, "    s = tfem_solid_set_mesh(%s, %d, %s, %d, %s, %s, %d);\n", SM, I[0], a[0], I[1], a[1], a[2], I[2]);
    break;
  case F_S_LOAD_GMSH:
    if (I[0] < 0 || I[0] >= NSG) {
      fprintf(f, "    s = tfem_solid_load_gmsh(%s, NULL, %d);\n", SM, I[1]);
    } else if (SG_2D_FILE[I[0]] >= 0) {
      int g2 = SG_2D_FILE[I[0]];
      if (g_text[g2] && g2 != G_DIRECTORY && g2 != G_NONEXISTENT && g2 != G_BAD_UTF8) {
        fprintf(f, "    write_file(%s, ", G_REPRO[g2]);
        c_str(f, g_text[g2], g_len[g2]);
        fprintf(f, ", %zu);\n", g_len[g2]);
      }
      if (g2 == G_DIRECTORY) fprintf(f, "    mkdir(REPRO_DIR, 0700);\n");
      fprintf(f, "    s = tfem_solid_load_gmsh(%s, %s, %d);\n", SM, G_REPRO[g2], I[1]);
    } else {
      fprintf(f, "    write_file(REPRO_DIR \"/%s.msh\", ", SG_NAME[I[0]]);
      c_str(f, sg_text[I[0]], sg_len[I[0]]);
      fprintf(f, ", %zu);\n    s = tfem_solid_load_gmsh(%s, REPRO_DIR \"/%s.msh\", %d);\n", sg_len[I[0]], SM, SG_NAME[I[0]], I[1]);
    }
    break;
  case F_S_SET_FACES: fprintf(f, "    s = tfem_solid_set_boundary_faces(%s, %d, %s, %s);\n", SM, I[0], a[0], a[1]); break;
  case F_S_ADD_FACES: fprintf(f, "    s = tfem_solid_add_boundary_faces(%s, %d, %s, %s);\n", SM, I[0], a[0], a[1]); break;
  case F_S_GET_SIZES: fprintf(f, "    s = tfem_solid_get_sizes(%s, %s, %s, %s);\n", SM, o[0], o[1], o[2]); break;
  case F_S_FACE_COUNT: fprintf(f, "    s = tfem_solid_get_boundary_face_count(%s, %s);\n", SM, o[0]); break;
  case F_S_MESH_NODES: fprintf(f, "    s = tfem_solid_get_mesh_nodes(%s, %s, %zu);\n", SM, o[0], len[0]); break;
  case F_S_MESH_TETS:
    fprintf(f, "    s = tfem_solid_get_mesh_tetrahedra(%s, %s, %zu, %s, %zu);\n", SM, o[0], len[0], o[1], len[1]);
    break;
  case F_S_GET_FACES:
    fprintf(f, "    s = tfem_solid_get_boundary_faces(%s, %s, %zu, %s, %zu);\n", SM, o[0], len[0], o[1], len[1]);
    break;
  case F_S_SET_MATERIAL: fprintf(f, "    s = tfem_solid_set_material(%s, %d, %s, %s);\n", SM, I[0], d[0], d[1]); break;
  case F_S_SET_TEMPERING: fprintf(f, "    s = tfem_solid_set_tempering(%s, %d, %s);\n", SM, I[0], d[0]); break;
  case F_S_SET_ORDERING: fprintf(f, "    s = tfem_solid_set_ordering(%s, %d);\n", SM, I[0]); break;
  case F_S_FIX: fprintf(f, "    s = tfem_solid_fix(%s, %d, %d, %s);\n", SM, I[0], I[1], d[0]); break;
  case F_S_FIX_FACES: fprintf(f, "    s = tfem_solid_fix_faces(%s, %d, %d, %s);\n", SM, I[0], I[1], d[0]); break;
  case F_S_CLEAR_CONSTRAINTS: fprintf(f, "    s = tfem_solid_clear_constraints(%s);\n", SM); break;
  case F_S_ADD_PRESSURE: fprintf(f, "    s = tfem_solid_add_pressure(%s, %d, %s);\n", SM, I[0], d[0]); break;
  case F_S_ADD_TRACTION:
    fprintf(f, "    s = tfem_solid_add_traction(%s, %d, %s, %s, %s);\n", SM, I[0], d[0], d[1], d[2]);
    break;
  case F_S_ADD_NODAL_FORCE:
    fprintf(f, "    s = tfem_solid_add_nodal_force(%s, %d, %s, %s, %s);\n", SM, I[0], d[0], d[1], d[2]);
    break;
  case F_S_CLEAR_LOADS: fprintf(f, "    s = tfem_solid_clear_loads(%s);\n", SM); break;
  case F_S_ADD_PAIR: fprintf(f, "    s = tfem_solid_add_contact_pair(%s, %d, %d, %s);\n", SM, I[0], I[1], o[0]); break;
  case F_S_CLEAR_PAIRS: fprintf(f, "    s = tfem_solid_clear_contact_pairs(%s);\n", SM); break;
  case F_S_SOLVE: fprintf(f, "    s = tfem_solid_solve(%s, %s);\n", SM, o[0]); break;
  case F_S_SOLVE_CONTACT: case F_S_STEP:
    if (!c->in[0].null_)
      fprintf(f, "    tfem_contact_options opt = {%d, %s, %s, %d, %d, %d};\n", I[0], d[0], d[1], I[1], I[2], I[3]);
    if (fn == F_S_STEP)
      fprintf(f, "    s = tfem_solid_step(%s, %s, %s, %s);\n", SM, d[2], c->in[0].null_ ? "NULL" : "&opt", o[0]);
    else fprintf(f, "    s = tfem_solid_solve_contact(%s, %s, %s);\n", SM, c->in[0].null_ ? "NULL" : "&opt", o[0]);
    break;
  case F_S_REVERT_STEP: fprintf(f, "    s = tfem_solid_revert_step(%s);\n", SM); break;
  case F_S_SOLVE_INFO: fprintf(f, "    s = tfem_solid_get_solve_info(%s, %s);\n", SM, o[0]); break;
  case F_S_ITERATIONS: fprintf(f, "    s = tfem_solid_get_iterations(%s, %s);\n", SM, o[0]); break;
  case F_S_DISPLACEMENTS: fprintf(f, "    s = tfem_solid_get_displacements(%s, %s, %zu);\n", SM, o[0], len[0]); break;
  case F_S_STRAINS: fprintf(f, "    s = tfem_solid_get_element_strains(%s, %s, %zu);\n", SM, o[0], len[0]); break;
  case F_S_STRESSES: fprintf(f, "    s = tfem_solid_get_element_stresses(%s, %s, %zu);\n", SM, o[0], len[0]); break;
  case F_S_REACTIONS: fprintf(f, "    s = tfem_solid_get_reactions(%s, %s, %zu);\n", SM, o[0], len[0]); break;
  case F_S_WORK: fprintf(f, "    s = tfem_solid_get_external_work(%s, %s);\n", SM, o[0]); break;
  case F_S_CONTACT_TETS: fprintf(f, "    s = tfem_solid_get_contact_tetrahedra(%s, %s, %zu);\n", SM, o[0], len[0]); break;
  case F_S_CONTACT_ACTIVE: fprintf(f, "    s = tfem_solid_get_contact_active(%s, %s, %zu);\n", SM, o[0], len[0]); break;
  case F_S_CONTACT_FORCES: fprintf(f, "    s = tfem_solid_get_contact_forces(%s, %s, %zu);\n", SM, o[0], len[0]); break;
  case F_S_NODAL_PRESSURES:
    fprintf(f, "    s = tfem_solid_get_contact_nodal_pressures(%s, %s, %zu);\n", SM, o[0], len[0]);
    break;
  case F_S_AREA: fprintf(f, "    s = tfem_solid_get_contact_area(%s, %s);\n", SM, o[0]); break;
  case F_S_PAIR_AREA: fprintf(f, "    s = tfem_solid_get_contact_pair_area(%s, %d, %s);\n", SM, I[0], o[0]); break;
  case F_S_WRITE_VTU: {
    static const char *const vp[NVTU] = {"REPRO_DIR \"/out.vtu\"", "REPRO_DIR \"/\\377\\376.vtu\"",
                                         "REPRO_DIR \"/no_such_dir/out.vtu\"", "REPRO_DIR", "\"\""};
    int k = I[0];
    if (k >= 0 && k < NVTU && k != VP_NO_DIR && k != VP_EMPTY) fprintf(f, "    mkdir(REPRO_DIR, 0700);\n");
    fprintf(f, "    s = tfem_solid_write_vtu(%s, %s);\n", SM, k >= 0 && k < NVTU ? vp[k] : "NULL");
    break;
  }
  case F_S_DESTROY:
    fprintf(f, "    tfem_solid_destroy(%s);\n", SM);
    if (!c->null_model && !hx[0]) fprintf(f, "    sm = NULL;\n");
    break;
  case F_S_RECREATE: fprintf(f, "    tfem_solid_destroy(sm);\n    sm = tfem_solid_create();\n"); break;
  /* the 3D contact context */
  case F_SC_CREATE:
    if (!c->in[0].null_)
      fprintf(f, "    tfem_contact_options opt = {%d, %s, %s, %d, %d, %d};\n", I[0], d[0], d[1], I[1], I[2], I[3]);
    fprintf(f, "    tfem_solid_contact *nc = tfem_solid_contact_create(%d, %s);\n"
               "    s = nc ? TFEM_STATUS_OK : TFEM_STATUS_INVALID_ARGUMENT;\n"
               "    if (nc) {\n      tfem_solid_contact_destroy(scx);\n      scx = nc;\n    }\n",
            I[4], c->in[0].null_ ? "NULL" : "&opt");
    break;
  case F_SC_DESTROY:
    fprintf(f, "    tfem_solid_contact_destroy(%s);\n", SX);
    if (!c->null_model && !hx[0]) fprintf(f, "    scx = NULL;\n");
    break;
  case F_SC_LAST_ERROR: fprintf(f, "    s = tfem_solid_contact_last_error(%s, %s, %zu);\n", SX, o[0], len[0]); break;
  case F_SC_LAST_ERROR_LENGTH:
    fprintf(f, "    printf(\"%%s #%d length %%zu\\n\", L, tfem_solid_contact_last_error_length(%s));\n", idx, SX);
    break;
  case F_SC_ADD_SIDE:
    fprintf(f, "    s = tfem_solid_contact_add_side(%s, %d, %d, %s, %d, %s, %s, %s, %d, %s, %s);\n", SX, I[0], I[1], d[0], I[2],
            a[0], a[1], a[2], I[3], a[3], o[0]);
    break;
  case F_SC_ADD_PAIR: fprintf(f, "    s = tfem_solid_contact_add_pair(%s, %d, %d, %s);\n", SX, I[0], I[1], o[0]); break;
  case F_SC_SETUP: fprintf(f, "    s = tfem_solid_contact_setup(%s);\n", SX); break;
  case F_SC_SIZES: fprintf(f, "    s = tfem_solid_contact_sizes(%s, %s, %s, %s);\n", SX, o[0], o[1], o[2]); break;
  case F_SC_NODES: fprintf(f, "    s = tfem_solid_contact_nodes(%s, %s, %zu);\n", SX, o[0], len[0]); break;
  case F_SC_TETS: fprintf(f, "    s = tfem_solid_contact_tetrahedra(%s, %s, %zu);\n", SX, o[0], len[0]); break;
  case F_SC_PATTERN: fprintf(f, "    s = tfem_solid_contact_pattern(%s, %s, %s, %zu);\n", SX, o[0], o[1], len[0]); break;
  case F_SC_ELEMENT_EQUATIONS:
    fprintf(f, "    s = tfem_solid_contact_element_equations(%s, %s, %zu);\n", SX, o[0], len[0]);
    break;
  case F_SC_ELEMENT_BLOCKS: fprintf(f, "    s = tfem_solid_contact_element_blocks(%s, %s, %zu);\n", SX, o[0], len[0]); break;
  case F_SC_EVALUATE:
    fprintf(f, "    s = tfem_solid_contact_evaluate(%s, %s, %zu, %s, %zu, %s, %zu);\n", SX, a[0], ul, o[0], len[0], o[1], len[1]);
    break;
  case F_SC_GATHER: fprintf(f, "    s = tfem_solid_contact_gather(%s, %s, %zu, %s, %zu);\n", SX, a[0], ul, o[0], len[0]); break;
  case F_SC_SCATTER_ADD:
    if (!c->out[0].null_) fprintf(f, "    memcpy(o0, a1, sizeof o0);\n");
    fprintf(f, "    s = tfem_solid_contact_scatter_add(%s, %s, %zu, %s, %zu);\n", SX, a[0], ul, o[0], len[0]);
    break;
  case F_SC_UPDATE:
    fprintf(f, "    s = tfem_solid_contact_update(%s, %s, %zu, %s, %s, %s);\n", SX, a[0], ul, o[0], o[1], o[2]);
    break;
  case F_SC_RESTART: fprintf(f, "    s = tfem_solid_contact_restart(%s);\n", SX); break;
  case F_SC_GET_ACTIVE: fprintf(f, "    s = tfem_solid_contact_get_active(%s, %s, %zu);\n", SX, o[0], len[0]); break;
  case F_SC_SET_ACTIVE: fprintf(f, "    s = tfem_solid_contact_set_active(%s, %s, %zu);\n", SX, a[0], ul); break;
  case F_SC_GAPS: fprintf(f, "    s = tfem_solid_contact_gaps(%s, %s, %zu, %s, %zu);\n", SX, a[0], ul, o[0], len[0]); break;
  case F_SC_AREA: fprintf(f, "    s = tfem_solid_contact_area(%s, %s);\n", SX, o[0]); break;
  default: break;
  }
  if (fn != F_VERSION && fn != F_LAST_ERROR_LENGTH && fn != F_DESTROY_NULL && fn != F_RECREATE && fn != F_CONTACT_DESTROY &&
      fn != F_CONTACT_LAST_ERROR_LENGTH && fn != F_S_LAST_ERROR_LENGTH && fn != F_S_DESTROY && fn != F_S_RECREATE &&
      fn != F_SC_DESTROY && fn != F_SC_LAST_ERROR_LENGTH) {
    int own3 = !hx[0] && fn != F_S_LAST_ERROR && fn != F_SC_LAST_ERROR;
    if (FN[fn].model == 2 && fn != F_CONTACT_LAST_ERROR) fprintf(f, "    show_c(%s, %d, \"%s\", s);\n", hx[0] ? "NULL" : H, idx, fn_name(fn));
    else if (FN[fn].model == 3) fprintf(f, "    show_s(%s, %d, \"%s\", s);\n", own3 ? SM : "NULL", idx, fn_name(fn));
    else if (FN[fn].model == 4) fprintf(f, "    show_sc(%s, %d, \"%s\", s);\n", own3 ? SX : "NULL", idx, fn_name(fn));
    else fprintf(f, "    show(%s, %d, \"%s\", s);\n", fn == F_LAST_ERROR || fn == F_CONTACT_LAST_ERROR ? "NULL" : sl, idx, fn_name(fn));
    if (fn == F_LAST_ERROR) fprintf(f, "    (void)0; /* (the message shown is the thread's) */\n");
    int any = 0;
    for (int j = 0; j < fn_nout(fn); ++j) any |= !c->out[j].null_;
    if (any) {
      fprintf(f, "    if (s == TFEM_STATUS_OK) {\n");
      for (int j = 0; j < fn_nout(fn); ++j) {
        if (c->out[j].null_) continue;
        int k = out_kind(fn, j);
        const char *p = FN[fn].scalar_out ? "&" : "";
        size_t n = FN[fn].scalar_out ? 1 : c->out[j].len;
        switch (k) {
        case K_D: fprintf(f, "      dump_d(%d, \"o%d\", %so%d, %zu);\n", idx, j, p, j, n); break;
        case K_I: fprintf(f, "      dump_i(%d, \"o%d\", %so%d, %zu);\n", idx, j, p, j, n); break;
        case K_L: fprintf(f, "      dump_l(%d, \"o%d\", %so%d, %zu);\n", idx, j, p, j, n); break;
        case K_C: fprintf(f, "      printf(\"%%s #%d text: %%s\\n\", L, o%d);\n", idx, j); break;
        case K_Z: fprintf(f, "      printf(\"%%s #%d size %%zu\\n\", L, o%d);\n", idx, j); break;
        case K_U8: fprintf(f, "      printf(\"%%s #%d bytes hash %%016llx\\n\", L, fnv(o%d, %zu));\n", idx, j, n); break;
        case K_SI: fprintf(f, "      dump_info(%d, &o%d);\n", idx, j); break;
        case K_RE: fprintf(f, "      dump_report(%d, &o%d);\n", idx, j); break;
        case K_T: fprintf(f, "      dump_d(%d, \"o%d (seconds)\", %so%d, %zu);\n", idx, j, p, j, n); break;
        case K_AR:
          fprintf(f, "      printf(\"%%s #%d adapt report: cycles %%d reached %%d unknowns %%lld triangles %%lld estimate "
                     "%%.17g seconds %%g\\n\", L, o%d.cycles, o%d.reached, (long long)o%d.unknowns, (long long)o%d.triangles, "
                     "o%d.estimate, o%d.seconds);\n",
                  idx, j, j, j, j, j, j);
          break;
        default:
          fprintf(f, "      printf(\"%%s #%d options %%d %%g %%g %%d %%d %%d\\n\", L, o%d.law, o%d.contact_modulus, o%d.lambda, "
                     "o%d.inversion_test, o%d.max_iterations, o%d.refactorize);\n",
                  idx, j, j, j, j, j, j);
          break;
        }
      }
      fprintf(f, "    }\n");
    }
  }
}

static void c_emit_status(FILE *f, const call_t *c, int idx, int st) {
  (void)c;
  fprintf(f, "  } /* #%d -> %s */\n", idx, status_name(st));
}

static void c_emit_tail(FILE *f, const case_t *cs, int died) {
  if (cs->solid) fprintf(f, "  tfem_solid_destroy(sm);\n  tfem_solid_contact_destroy(scx);\n  tfem_contact_destroy(ocx);\n");
  fprintf(f, "  tfem_destroy(m);\n  tfem_contact_destroy(cx);\n}\n\n");
  if (died) fprintf(f, "/* The process died in the last call above. */\n");
  fprintf(f, "static int skip_failed = 0;\nstatic int skip(int k) {\n  static const int failed[] = {");
  int nf = 0;
  for (int i = 0; i < cs->n; ++i)
    if (!died && cs->c[i].ran && cs->c[i].status != TFEM_STATUS_OK) fprintf(f, "%s%d", nf++ ? ", " : "", i);
  if (!nf) fprintf(f, "-1");
  fprintf(f, "};\n  if (!skip_failed) return 0;\n"
             "  for (size_t i = 0; i < sizeof failed / sizeof *failed; ++i)\n    if (failed[i] == k) return 1;\n  return 0;\n}\n\n"
             "int main(void) {\n  L = \"A\";\n  run();\n");
  if (nf) fprintf(f, "  L = \"B\";\n  skip_failed = 1;\n  run();\n");
  fprintf(f, "  return 0;\n}\n");
}

/* ------------------------------------------------------------------------ */
/* Running a case: original run, checks, replay                              */
/* ------------------------------------------------------------------------ */

static unsigned char *g_keep; /* calls kept (minimisation); NULL: all */
static int g_nkeep;
static FILE *g_cfile;         /* reproducer stream of a verbose run */

static void run_case(uint64_t seed, long index, int verbose, case_result *res) {
  mesh_t mesh = {0};
  case_t cs;
  gen_case(seed, index, &cs, &mesh);
  int full_prefix = cs.n;
  if (g_keep) {
    for (int i = 0; i < cs.n && i < g_nkeep; ++i)
      if (!g_keep[i] && full_prefix == cs.n) full_prefix = i;
    for (int i = (cs.n < g_nkeep ? cs.n : g_nkeep) - 1; i >= 0; --i)
      if (!g_keep[i]) case_delete(&cs, i);
    if (full_prefix > cs.n) full_prefix = cs.n;
  }
  runner_t R;
  memset(&R, 0, sizeof R);
  R.fam_gen = -1;
  R.cs = &cs;
  R.verbose = verbose;
  R.pristine = cs.pristine;
  R.full_prefix = full_prefix;
  sh_init(&R.sh);
  R.cfile = verbose ? g_cfile : NULL;
  if (verbose) {
    printf("case %ld of seed %" PRIu64 ": %s scene%s, %d calls\n", index, seed, cs.kind,
           cs.pristine ? " (pristine)" : cs.index < 0 ? "" : " (mutated)", cs.n);
    if (R.cfile) c_emit_header(R.cfile, &cs);
  }
  R.m = tfem_create();
  if (!R.m) finding(&R, V_OTHER, -1, "tfem_create() returned NULL");
  if (cs.solid) {
    /* (a 3D case: the 3D model, and a 2D context as a handle of another kind) */
    R.sm = tfem_solid_create();
    R.octx = tfem_contact_create(0);
    if (!R.sm || !R.octx) finding(&R, V_OTHER, -1, "tfem_solid_create() or tfem_contact_create(0) returned NULL");
  }
  for (int i = 0; i < cs.n && R.m; ++i) exec_call(&R, i);
  tfem_destroy(R.m);
  tfem_contact_destroy(R.ctx);
  R.ctx = NULL;
  R.cbuilt = 0;
  tfem_solid_destroy(R.sm);
  tfem_solid_contact_destroy(R.sctx);
  tfem_contact_destroy(R.octx);
  R.sm = NULL, R.sctx = NULL, R.octx = NULL;
  ss_free(&R.ss);
  if (R.cfile) {
    c_emit_tail(R.cfile, &cs, 0);
    fflush(R.cfile);
  }
  sh_clear_mesh(&R.sh);
  /* Replay on a fresh model without the calls that failed. */
  R.phase = 1;
  R.m = tfem_create();
  if (cs.solid) R.sm = tfem_solid_create(), R.octx = tfem_contact_create(0);
  if (verbose) {
    int nf = 0;
    for (int i = 0; i < cs.n; ++i) nf += cs.c[i].status != TFEM_STATUS_OK;
    printf("replay without the %d failed call(s) on a fresh model: ", nf);
  }
  long before = 0;
  for (int v = 0; v < NV; ++v) before += R.counts[v];
  /* (The message calls are left out: what they read is the failed calls'.) */
  for (int i = 0; i < cs.n && R.m; ++i)
    if (cs.c[i].ran && cs.c[i].status == TFEM_STATUS_OK && cs.c[i].fn != F_LAST_ERROR &&
        cs.c[i].fn != F_LAST_ERROR_LENGTH && cs.c[i].fn != F_CONTACT_LAST_ERROR &&
        cs.c[i].fn != F_CONTACT_LAST_ERROR_LENGTH && cs.c[i].fn != F_S_LAST_ERROR &&
        cs.c[i].fn != F_S_LAST_ERROR_LENGTH && cs.c[i].fn != F_SC_LAST_ERROR && cs.c[i].fn != F_SC_LAST_ERROR_LENGTH)
      exec_call(&R, i);
  tfem_destroy(R.m);
  tfem_contact_destroy(R.ctx);
  R.ctx = NULL;
  tfem_solid_destroy(R.sm);
  tfem_solid_contact_destroy(R.sctx);
  tfem_contact_destroy(R.octx);
  R.sm = NULL, R.sctx = NULL, R.octx = NULL;
  free(R.st_last), free(R.st_prev);
  if (verbose) {
    long after = 0;
    for (int v = 0; v < NV; ++v) after += R.counts[v];
    printf("%s\n", after == before ? "identical" : "DIFFERS (see above)");
  }
  res->calls = R.calls;
  res->stderr_bytes = R.stderr_bytes;
  res->status_flips = R.status_flips;
  for (int o = 0; o < NO; ++o) res->oracles[o] = R.oracles[o];
  for (int v = 0; v < NV; ++v) res->counts[v] = R.counts[v];
  res->done = 1;
  case_free(&cs);
  mesh_free(&mesh);
}

/* ------------------------------------------------------------------------ */
/* Processes: batches in forked children, bisection of the ones that die     */
/* ------------------------------------------------------------------------ */

typedef struct {
  uint64_t seed;
  int threads;
  double timeout;
  int no_fork;
} opts_t;

static opts_t g_opt;
static long g_first; /* case number of batch position 0 */
static const int *g_pos;
static int g_npos, g_next;
static int g_errfd = -1;
static char g_errpath[300];

/* Each case runs on a thread of its own, so that it starts with an empty
 * thread error slot whatever ran before it on the same worker. */
static void *case_thread(void *arg) {
  int k = *(int *)arg;
  run_case(g_opt.seed, g_first + g_pos[k], g_verbose, &g_shared->res[g_pos[k]]);
  return NULL;
}

static void *worker(void *arg) {
  (void)arg;
  for (;;) {
    int k = __atomic_fetch_add(&g_next, 1, __ATOMIC_RELAXED);
    if (k >= g_npos) return NULL;
    pthread_t th;
    pthread_attr_t at;
    pthread_attr_init(&at);
    pthread_attr_setstacksize(&at, 8u << 20);
    if (pthread_create(&th, &at, case_thread, &k) == 0) {
      pthread_join(th, NULL);
    } else {
      case_thread(&k);
    }
    pthread_attr_destroy(&at);
  }
}

static void run_list(const int *pos, int n, int threads) {
  g_pos = pos;
  g_npos = n;
  g_next = 0;
  if (threads <= 1 || n <= 1) {
    worker(NULL);
    return;
  }
  pthread_t th[64];
  int nt = threads < 64 ? threads : 64;
  for (int t = 0; t < nt; ++t) pthread_create(&th[t], NULL, worker, NULL);
  for (int t = 0; t < nt; ++t) pthread_join(th[t], NULL);
}

/* Runs the batch positions pos[] in a child; returns 0 if it ended
 * normally, else V_CRASH, V_ABORT or V_HANG (with a description). */
static int spawn(const int *pos, int n, int threads, char *how, size_t cap) {
  for (int i = 0; i < n; ++i) memset(&g_shared->res[pos[i]], 0, sizeof(case_result));
  how[0] = 0;
  if (g_opt.no_fork) {
    run_list(pos, n, threads);
    return 0;
  }
  if (ftruncate(g_errfd, 0) != 0) { /* ignore */
  }
  fflush(stdout);
  pid_t pid = fork();
  if (pid < 0) {
    perror("fork");
    exit(3);
  }
  if (pid == 0) {
    g_err_claimed = 0;
    sigset_t none;
    sigemptyset(&none);
    sigprocmask(SIG_SETMASK, &none, NULL);
    dup2(g_errfd, 2);
    run_list(pos, n, threads);
    fflush(stdout);
    if (g_cfile) fflush(g_cfile);
    _exit(0);
  }
  double t0 = now_s();
  int status = 0;
  sigset_t chld;
  sigemptyset(&chld);
  sigaddset(&chld, SIGCHLD);
  for (;;) {
    pid_t w = waitpid(pid, &status, WNOHANG);
    if (w == pid) break;
    if (w < 0 && errno != EINTR) {
      perror("waitpid");
      exit(3);
    }
    double left = g_opt.timeout - (now_s() - t0);
    if (left <= 0) {
      kill(pid, SIGKILL);
      waitpid(pid, &status, 0);
      snprintf(how, cap, "no result after %.0f s (killed)", g_opt.timeout);
      return V_HANG;
    }
    /* SIGCHLD is blocked: wait for it (or the next second) */
    struct timespec ts = {left > 1 ? 1 : 0, left > 1 ? 0 : (long)(left * 1e9)};
    sigtimedwait(&chld, NULL, &ts);
  }
  if (WIFEXITED(status) && WEXITSTATUS(status) == 0) return 0;
  if (WIFSIGNALED(status)) {
    int sig = WTERMSIG(status);
    snprintf(how, cap, "killed by signal %d (%s)", sig, strsignal(sig));
    return sig == SIGABRT ? V_ABORT : V_CRASH;
  }
  snprintf(how, cap, "exited with status %d", WEXITSTATUS(status));
  return V_CRASH;
}

static void print_stderr_tail(void) {
  off_t sz = fd_size(g_errfd);
  if (sz <= 0) return;
  char buf[2049];
  off_t from = sz > 2048 ? sz - 2048 : 0;
  ssize_t k = pread(g_errfd, buf, 2048, from);
  if (k <= 0) return;
  buf[k] = 0;
  printf("    its stderr%s:\n", from ? " (last 2048 bytes)" : "");
  for (char *line = strtok(buf, "\n"); line; line = strtok(NULL, "\n")) printf("    | %s\n", line);
}

/* Reruns the positions that did not finish, halving, down to the cases that
 * kill a process alone. */
static void bisect(const int *pos, int n) {
  char how[200];
  int t = spawn(pos, n, 1, how, sizeof how);
  if (t == 0) return;
  int *left = xmalloc(sizeof(int) * (size_t)n), nl = 0;
  for (int i = 0; i < n; ++i)
    if (!g_shared->res[pos[i]].done) left[nl++] = pos[i];
  if (n == 1 || nl == 0) {
    int p = nl ? left[0] : pos[n - 1];
    case_result *r = &g_shared->res[p];
    memset(r, 0, sizeof *r);
    r->done = 1;
    r->term = t;
    r->counts[t] = 1;
    mesh_t mesh = {0};
    case_t cs;
    gen_case(g_opt.seed, g_first + p, &cs, &mesh);
    printf("VIOLATION %s: seed=%" PRIu64 " case=%ld (%s): the process was %s; rerun: api_fuzz --seed %" PRIu64
           " --replay-case %ld\n",
           V_NAME[t], g_opt.seed, g_first + p, cs.kind, how, g_opt.seed, g_first + p);
    print_stderr_tail();
    fflush(stdout);
    case_free(&cs);
    mesh_free(&mesh);
  } else if (nl == 1) {
    bisect(left, 1);
  } else {
    bisect(left, nl / 2);
    bisect(left + nl / 2, nl - nl / 2);
  }
  free(left);
}

static void run_batch(long first, int n) {
  g_first = first;
  int *pos = xmalloc(sizeof(int) * (size_t)n);
  for (int i = 0; i < n; ++i) pos[i] = i;
  char how[200];
  int t = spawn(pos, n, g_opt.threads, how, sizeof how);
  if (t != 0) {
    int nl = 0;
    for (int i = 0; i < n; ++i)
      if (!g_shared->res[i].done) pos[nl++] = i;
    if (g_verbose) printf("batch from case %ld %s: bisecting %d unfinished case(s)\n", first, how, nl);
    if (nl) bisect(pos, nl);
  }
  free(pos);
}

/* ------------------------------------------------------------------------ */
/* Minimisation of one case (--replay-case K --minimize)                     */
/* ------------------------------------------------------------------------ */

static int case_shows(long index, int target) {
  int pos = 0;
  char how[200];
  g_first = index;
  int t = spawn(&pos, 1, 1, how, sizeof how);
  if (target == V_CRASH || target == V_ABORT || target == V_HANG) return t == target;
  if (target == NV) return t == 0 && g_shared->res[0].status_flips > 0; /* state_change_status */
  return t == 0 && g_shared->res[0].counts[target] > 0;
}

static void minimize(long index, int target, int ncalls) {
  g_nkeep = ncalls;
  g_keep = xmalloc((size_t)ncalls);
  memset(g_keep, 1, (size_t)ncalls);
  unsigned char *trial = xmalloc((size_t)ncalls);
  int runs = 0;
  for (int chunks = 2;;) {
    int kept = 0;
    for (int i = 0; i < ncalls; ++i) kept += g_keep[i];
    if (kept <= 1) break;
    int size = (kept + chunks - 1) / chunks, reduced = 0;
    for (int start = 0; start < kept && !reduced; start += size) {
      memcpy(trial, g_keep, (size_t)ncalls);
      for (int i = 0, k = 0; i < ncalls; ++i)
        if (g_keep[i]) {
          if (k >= start && k < start + size) trial[i] = 0;
          ++k;
        }
      unsigned char *save = g_keep;
      g_keep = trial;
      int shows = case_shows(index, target);
      g_keep = save;
      ++runs;
      if (shows) {
        memcpy(g_keep, trial, (size_t)ncalls);
        chunks = chunks > 2 ? chunks - 1 : 2;
        reduced = 1;
      }
    }
    if (!reduced) {
      if (chunks >= kept) break;
      chunks = 2 * chunks < kept ? 2 * chunks : kept;
    }
  }
  int kept = 0;
  for (int i = 0; i < ncalls; ++i) kept += g_keep[i];
  printf("minimised to %d of %d calls in %d runs (still showing %s)\n", kept, ncalls, runs,
         target == NV ? "state_change_status" : V_NAME[target]);
  free(trial);
}

/* ------------------------------------------------------------------------ */
/* Self-test of the checkers (no library call)                              */
/* ------------------------------------------------------------------------ */

static int self_test(void) {
  int bad = 0;
#define ST(cond)                                           \
  do {                                                     \
    if (!(cond)) {                                         \
      printf("self-test failed: %s (line %d)\n", #cond, __LINE__); \
      ++bad;                                               \
    }                                                      \
  } while (0)
  for (int kind = K_D; kind <= K_OP; ++kind) {
    gbuf g;
    gb_alloc(&g, kind, 4);
    ST(gb_canary_ok(&g) && gb_untouched(&g));
    g.p[g.bytes] ^= 1; /* one byte beyond the declared length */
    ST(!gb_canary_ok(&g));
    g.p[g.bytes] ^= 1;
    g.p[-1] ^= 1; /* one byte before */
    ST(!gb_canary_ok(&g));
    g.p[-1] ^= 1;
    ST(gb_canary_ok(&g));
    g.p[g.bytes - 1] ^= 1; /* inside: a write, not a canary violation */
    ST(gb_canary_ok(&g) && !gb_untouched(&g));
    free(g.blk);
  }
  gbuf d;
  gb_alloc(&d, K_D, 2);
  double qnan = NAN, inf = INFINITY;
  memcpy(d.p, &qnan, 8);
  memcpy(d.p + 8, &inf, 8);
  ST(!gb_is_pattern(&d, 0) && !gb_is_pattern(&d, 1)); /* a NaN written is not the fill pattern */
  free(d.blk);
  gbuf z;
  gb_alloc(&z, K_D, 0);
  ST(gb_canary_ok(&z) && gb_untouched(&z));
  z.p[0] ^= 1;
  ST(!gb_canary_ok(&z));
  free(z.blk);
  tfem_solve_info a, b;
  memset(&a, 0x11, sizeof a);
  memset(&b, 0x22, sizeof b);
  a.time_total = 1;
  b = a;
  b.time_total = 2;
  tfem_solve_info na, nb;
  norm_info(&a, &na);
  norm_info(&b, &nb);
  ST(memcmp(&na, &nb, sizeof na) == 0); /* timings are not compared */
  b.relative_residual = 3;
  norm_info(&b, &nb);
  ST(memcmp(&na, &nb, sizeof na) != 0);
  char c[64];
  ST(!strcmp(cdbl(-0.0, c), "(-0.0)") && !strcmp(cdbl(1.0, c), "1.0") && !strcmp(cdbl(NAN, c), "NAN"));
  ST(strtod(cdbl(4.9406564584124654e-324, c), NULL) == 4.9406564584124654e-324);
  /* The shadow's boundary-edge rules: a unit square of two triangles, a
   * pressure on tag 1 (the bottom edge 0-1). */
  {
    shadow_t sh;
    sh_init(&sh);
    double xy[8] = {0, 0, 1, 0, 1, 1, 0, 1};
    int tri[6] = {0, 1, 2, 0, 2, 3}, body[2] = {1, 1};
    sh_new_mesh(&sh, 4, xy, 2, tri, body, 0);
    int e1[4] = {0, 1, 1, 2}, t1[2] = {1, 2};
    sh_set_edges(&sh, 2, e1, t1);
    sh.load = xmalloc(sizeof(sh_load));
    sh.load[sh.nl++] = (sh_load){1, 0, 1.0, 0.0};
    char why[300];
    ST(!sh_orphan(&sh, why, sizeof why) && sh_double_edge(&sh, 0) < 0);
    int e2[6] = {0, 1, 1, 2, 1, 0}, t2[3] = {1, 2, 1}; /* 0-1 tagged 1 twice */
    sh_set_edges(&sh, 3, e2, t2);
    ST(sh_double_edge(&sh, 0) == 2 && sh_double_edge(&sh, 3) < 0);
    int e3[4] = {1, 2, 0, 2}, t3[2] = {2, 1}; /* tag 1 only on the diagonal, interior */
    sh_set_edges(&sh, 2, e3, t3);
    ST(sh_orphan(&sh, why, sizeof why) && strstr(why, "interior"));
    int e4[2] = {1, 2}, t4[1] = {2}; /* tag 1 gone */
    sh_set_edges(&sh, 1, e4, t4);
    ST(sh_orphan(&sh, why, sizeof why) && strstr(why, "no edge left"));
    double f[8];
    sh_set_edges(&sh, 2, e1, t1);
    ST(sh_nodal_forces(&sh, f) && f[1] == 0.5 && f[3] == 0.5 && f[0] == 0.0); /* pressure 1 on y = 0 pushes up */
    sh.threads = 3;
    sh_clear_mesh(&sh);
    ST(sh.threads == 3 && sh.nn == 0 && sh.cmesh_gen == -1);
    sh_clear_mesh(&sh);
  }
  /* Coulomb's law (oracle_coulomb): a frictional result that keeps it,
   * then one planted breach per rule, each caught at its element. */
  {
    double p[5] = {0, 2e7, 1e7, 3e7, 5e6}, tau[5] = {0, 1e6, -3e6, 0, 0}, d[5] = {0, 0, 4.5, 0, 0};
    double mu[5] = {0.3, 0.3, 0.3, 0.0, NAN};
    int state[5] = {0, 1, 2, 2, 1}, act[5] = {0, 1, 1, 1, 1};
    char why[300];
    ST(coulomb_check(5, p, tau, state, d, act, mu, 0, 0, why, sizeof why) < 0);
    tau[1] = 6.1e6; /* sticks beyond mu p = 6e6 */
    ST(coulomb_check(5, p, tau, state, d, act, mu, 0, 0, why, sizeof why) == 1 && strstr(why, "sticks"));
    tau[1] = 6e6 * (1 + 1e-10); /* within the 1e-9 of boundary_test.c */
    ST(coulomb_check(5, p, tau, state, d, act, mu, 0, 0, why, sizeof why) < 0);
    tau[2] = -2.9e6; /* slips below mu p = 3e6 */
    ST(coulomb_check(5, p, tau, state, d, act, mu, 0, 0, why, sizeof why) == 2 && strstr(why, "slips"));
    tau[2] = -3e6;
    d[2] = -1e-30; /* negative dissipation */
    ST(coulomb_check(5, p, tau, state, d, act, mu, 0, 0, why, sizeof why) == 2 && strstr(why, "dissipation"));
    d[2] = 4.5;
    tau[3] = 1e-9; /* shear with mu = 0 */
    ST(coulomb_check(5, p, tau, state, d, act, mu, 0, 0, why, sizeof why) == 3 && strstr(why, "mu = 0"));
    tau[3] = 0;
    tau[0] = 1.0; /* shear on an open element */
    ST(coulomb_check(5, p, tau, state, d, act, mu, 0, 0, why, sizeof why) == 0 && strstr(why, "open"));
    tau[0] = 0;
    act[4] = 0; /* state 1 on an inactive element (mu unknown: still checked) */
    ST(coulomb_check(5, p, tau, state, d, act, mu, 0, 0, why, sizeof why) == 4 && strstr(why, "active"));
    act[4] = 1;
    state[1] = 3;
    ST(coulomb_check(5, p, tau, state, d, act, mu, 0, 0, why, sizeof why) == 1);
    state[1] = 1;
    ST(coulomb_check(5, p, tau, state, d, NULL, mu, 0, 0, why, sizeof why) < 0);
    double z[5] = {0, 0, 0, 0, 0}, t0[5] = {0, 0, 0, 0, 0}, d0[5] = {0, 0, 0, 0, 0};
    int st1[5] = {0, 2, 2, 1, 2}; /* a stick in a frictionless solve */
    ST(coulomb_check(5, p, t0, st1, d0, act, z, 0, 0, why, sizeof why) == 3);
    st1[3] = 2;
    ST(coulomb_check(5, p, t0, st1, d0, act, z, 0, 0, why, sizeof why) < 0);
    p[4] = -1e6, mu[4] = 0.3, state[4] = 2; /* slipping in tension: no shear */
    ST(coulomb_check(5, p, tau, state, d, act, mu, 0, 0, why, sizeof why) < 0);
    tau[4] = 1e-3 * 0.3 * 3e7; /* shear in tension beyond the round-off of the largest pressure */
    ST(coulomb_check(5, p, tau, state, d, act, mu, 0, 0, why, sizeof why) == 4);
    /* the twin comparison: one ulp caught bit for bit, not within 1e-9 */
    double a[3] = {1.0, -2.0, 0.5}, b[3] = {1.0, -2.0, 0.5};
    ST(same_values(3, a, b, -1) < 0);
    b[1] = nextafter(-2.0, 0.0);
    ST(same_values(3, a, b, -1) == 1 && same_values(3, a, b, 1e-9) < 0);
    b[2] = 0.5 + 1e-6;
    ST(same_values(3, a, b, 1e-9) == 2);
    b[2] = NAN;
    ST(same_values(3, a, b, 1e-9) == 2);
    b[2] = -0.0 + 0.5;
    a[0] = 0.0, b[0] = -0.0; /* -0 against 0: a difference bit for bit only */
    ST(same_values(3, a, b, -1) == 0 && same_values(1, a, b, 1e-9) < 0);
  }
  /* The families of the contact pairs (sh_pair_family) on the two
   * blocks, straight and curved, against what scene_two_blocks builds
   * them for: the strip under the automatic weighting on straight sides
   * and on coinciding curved ones, the mortar weighting on the curved
   * non-matching ones (both met); the forced weightings; friction and a
   * mesh of its own take B; the state's signature; a side that branches
   * or a curved side whose nodes are not all close to the other side is
   * not decided here. */
  {
    int met[10] = {0};
    for (int k = 0; k < 120; ++k) {
      rng_t r = {mix64(0x5eedULL + (uint64_t)k)};
      case_t cs;
      memset(&cs, 0, sizeof cs);
      mesh_t m = {0};
      ctx_t cx = {0};
      int variant = (int[]){0, 3, 3, 4}[k % 4], fam = scene_two_blocks(&r, &cs, &cx, &m, variant);
      shadow_t sh;
      sh_init(&sh);
      sh_new_mesh(&sh, m.nn, m.xy, m.nt, m.tri, m.body, 0);
      sh_set_edges(&sh, m.ne, m.edge, m.tag);
      int split = 0, lower = 0, upper = 0; /* (the interface cut into pairs (2, 3) and (5, 6)) */
      for (int e = 0; e < m.ne; ++e) {
        split |= m.tag[e] == 5;
        lower += m.tag[e] == 2 || m.tag[e] == 5;
        upper += m.tag[e] == 3 || m.tag[e] == 6;
      }
      sh.npairs = 1 + split, sh.pair_tag[0][0] = 2, sh.pair_tag[0][1] = 3, sh.pair_tag[1][0] = 5, sh.pair_tag[1][1] = 6;
      ST(sh.weighting == TFEM_CONTACT_WEIGHTING_AUTO && sh_pair_family(&sh, 0) == fam && sh_families(&sh) == fam);
      ST(sh_slave_body(&sh) == (fam == FAM_MORTAR ? (upper < lower ? 2 : 1) : -1));
      met[variant == 4 ? 8 + (fam == FAM_MORTAR) : variant + (fam == FAM_MORTAR)] = 1; /* (straight 0-1, curved 3-4, cut 8-9) */
      met[variant == 4 ? 5 : 6 + split] = 1;
      int *ch, n = sh_chain(&sh, 2, &ch);
      ST(n > 2 && sh_straight(&sh, ch, n) == (variant != 3));
      free(ch);
      ST(sh_fam_sig(&sh) == ((long)sh.npairs << 20 | (fam == FAM_MORTAR ? (split ? 3 : 1) : 0)));
      sh.pair_mu[0] = 0.05;
      ST(sh_pair_family(&sh, 0) == FAM_STRIP);
      sh.pair_mu[0] = -0.0, sh.pair_user[0] = 1;
      ST(sh_pair_family(&sh, 0) == FAM_STRIP);
      sh.pair_user[0] = 0;
      sh.weighting = TFEM_CONTACT_WEIGHTING_STRIP;
      ST(sh_pair_family(&sh, 0) == FAM_STRIP);
      sh.weighting = TFEM_CONTACT_WEIGHTING_MORTAR;
      ST(sh_pair_family(&sh, 0) == FAM_MORTAR && sh_fam_sig(&sh) == ((long)sh.npairs << 20 | (split ? 3 : 1)));
      ST(sh_slave_body(&sh) == (upper < lower ? 2 : 1)); /* (a tie: side a, the lower block's) */
      sh.weighting = TFEM_CONTACT_WEIGHTING_AUTO;
      if (fam == FAM_MORTAR) { /* the upper block (body 2) lifted by 0.6: its nodes no longer close */
        int *nb = sh_node_bodies(&sh);
        for (int i = 0; i < sh.nn; ++i)
          if (nb[i] == 2) sh.xy[2 * i + 1] += 0.6;
        free(nb);
        ST(sh_pair_family(&sh, 0) == FAM_UNKNOWN && sh_fam_sig(&sh) == -1);
      }
      sh_clear_mesh(&sh);
      case_free(&cs);
      mesh_free(&m);
    }
    ST(met[0] && !met[1] && met[3] && met[4] && met[5] && met[6] && met[7] && met[8] && !met[9]);
    /* a side that branches at node 1 (0-1 and 1-2 of triangle 0-1-2,
     * 1-3 of triangle 1-3-4, which touches it at node 1): no chain; an
     * unknown tag: not known here; 0-1-3 along y = 0: straight, node 1
     * raised by 2e-9 (|r x d| = 4e-9 of L^2 = 4: within a factor 2 of the
     * tolerance), by 1e-7: not straight */
    shadow_t sh;
    sh_init(&sh);
    double xy[10] = {0, 0, 1, 0, 0, 1, 2, 0, 2, 1};
    int tri[6] = {0, 1, 2, 1, 3, 4}, body[2] = {1, 1}, e[6] = {0, 1, 1, 3, 1, 2}, t[3] = {5, 5, 5};
    sh_new_mesh(&sh, 5, xy, 2, tri, body, 0);
    sh_set_edges(&sh, 3, e, t);
    int *ch;
    ST(sh_chain(&sh, 5, &ch) == 0 && sh_chain(&sh, 6, &ch) == -1);
    sh_set_edges(&sh, 2, e, t);
    ST(sh_chain(&sh, 5, &ch) == 3);
    if (ch) {
      ST(sh_straight(&sh, ch, 3) == 1);
      sh.xy[3] = 2e-9;
      ST(sh_straight(&sh, ch, 3) == -1);
      sh.xy[3] = 1e-7;
      ST(sh_straight(&sh, ch, 3) == 0);
      free(ch);
    }
    sh_clear_mesh(&sh);
    ST(plus_zero_output(F_GET_CONTACT_GAPS) && plus_zero_output(F_GET_DISPLACEMENTS) && !plus_zero_output(F_GET_JACOBIANS) &&
       !plus_zero_output(F_GET_MATRIX));
  }
  /* The adaptive solve and axisymmetric bodies (2026-11-29). */
  ST(adapt_max_unknowns(INT_MAX) == INT64_MAX && adapt_max_unknowns(INT_MIN) == INT64_MIN && adapt_max_unknowns(300) == 300);
  ST(enum_max('P') == TFEM_PLANE_MODE_AXISYMMETRIC && plus_zero_output(F_GET_OUT_OF_PLANE) && reads_only(F_GET_ADAPT_CYCLES));
  {
    /* the adaptive limits stay cheap: max_cycles never above 6 */
    rng_t q = {99};
    ctx_t cx0;
    memset(&cx0, 0, sizeof cx0);
    int ok = 1;
    for (int k = 0; k < 2000; ++k) {
      int w = wild_int(&q, 'Y', 3, &cx0), p = plausible_int(&q, 'Y', &cx0);
      ok &= w <= 6 && p >= 1 && p <= 6;
    }
    ST(ok);
  }
  {
    /* a report's seconds and the cycles' timings are left out of the
     * replay's comparison, the rest not */
    gbuf a, b;
    gb_alloc(&a, K_AR, 1);
    gb_alloc(&b, K_AR, 1);
    tfem_adapt_report x = {3, 1, 100, 50, 0.01, 1.5}, y = x;
    y.seconds = 2.5;
    memcpy(a.p, &x, sizeof x);
    memcpy(b.p, &y, sizeof y);
    size_t na, nb;
    unsigned char *ba = out_bytes(&a, &na), *bb = out_bytes(&b, &nb);
    ST(na == nb && !memcmp(ba, bb, na));
    free(bb);
    y.estimate = nextafter(0.01, 1.0);
    memcpy(b.p, &y, sizeof y);
    bb = out_bytes(&b, &nb);
    ST(na == nb && memcmp(ba, bb, na) != 0);
    free(ba), free(bb), free(a.blk), free(b.blk);
    gb_alloc(&a, K_T, 2);
    ST(gb_is_pattern(&a, 0) && gb_untouched(&a));
    double t = 0.25;
    memcpy(a.p, &t, 8);
    ST(!gb_is_pattern(&a, 0));
    ba = out_bytes(&a, &na);
    ST(na == 16 && ba[0] == 0 && ba[15] == 0);
    free(ba), free(a.blk);
  }
  {
    /* the axis of an axisymmetric model, on the shadow's unit square */
    shadow_t sh;
    sh_init(&sh);
    double xy[8] = {0, 0, 1, 0, 1, 1, 0, 1};
    int tri[6] = {0, 1, 2, 0, 2, 3}, body[2] = {1, 1};
    char why[200];
    sh_new_mesh(&sh, 4, xy, 2, tri, body, 0);
    ST(sh_axis_violation(&sh, INT_MIN, why, sizeof why) == 0); /* node 0 on the axis, u_r free */
    sh.presc[0] = 0.0;
    ST(sh_axis_violation(&sh, INT_MIN, why, sizeof why) == 3);
    sh.presc[6] = 1e-3; /* u_r prescribed, not to 0 */
    ST(sh_axis_violation(&sh, INT_MIN, why, sizeof why) == 3);
    sh.presc[6] = 0.0;
    ST(sh_axis_violation(&sh, INT_MIN, why, sizeof why) == -1 && sh_axis_violation(&sh, 1, why, sizeof why) == -1);
    sh.xy[6] = -1e-14; /* within the library's 1e-12 of the size: on the axis, not across */
    ST(sh_axis_violation(&sh, 1, why, sizeof why) == -1);
    sh.xy[6] = -1e-3; /* across */
    ST(sh_axis_violation(&sh, 1, why, sizeof why) == 3 && sh_axis_violation(&sh, INT_MIN, why, sizeof why) == 3);
    ST(sh_axis_violation(&sh, 2, why, sizeof why) == -1);
    sh.axi = 1, sh.nmat = 1, sh.mat_body[0] = 1, sh.mat_plane[0] = TFEM_PLANE_MODE_AXISYMMETRIC;
    double f[8];
    ST(!sh_nodal_forces(&sh, f)); /* (the ring's forces are not made here) */
    sh.adapt_n = 2;
    sh_clear_mesh(&sh); /* (the materials and the cycles are the model's) */
    ST(sh.axi == 1 && sh.nmat == 1 && sh_material(&sh, 1) == 0 && sh.adapt_n == 2 && !sh.has_mesh);
    sh_clear_mesh(&sh);
  }
  {
    /* the ring element's oracle: K = v v^T with v off the y DOFs is
     * symmetric and gives no force for an axial translation; a breach of
     * either, or a corner at x < 0, is a finding */
    runner_t R0;
    case_t cs0;
    memset(&R0, 0, sizeof R0);
    memset(&cs0, 0, sizeof cs0);
    cs0.kind = "self-test";
    R0.cs = &cs0;
    sh_init(&R0.sh);
    call_t c0;
    memset(&c0, 0, sizeof c0);
    c0.fn = F_ELEMENT_STIFFNESS;
    c0.iv[0] = TFEM_PLANE_MODE_AXISYMMETRIC;
    double xy[6] = {0, 0, 1, 0, 0, 1}, v[6] = {1, 0, 2, 0, 3, 0}, k[36];
    in_set(&c0, 0, xy, 6, sizeof(double));
    for (int i = 0; i < 36; ++i) k[i] = v[i / 6] * v[i % 6];
    oracle_element_stiffness(&R0, 0, &c0, k);
    ST(R0.counts[V_AXI] == 0);
    k[1] += 1e-3; /* K[0][1] != K[1][0] */
    oracle_element_stiffness(&R0, 0, &c0, k);
    ST(R0.counts[V_AXI] == 1);
    k[1] -= 1e-3, k[7] += 1.0; /* symmetric, but K t_y != 0 */
    oracle_element_stiffness(&R0, 0, &c0, k);
    ST(R0.counts[V_AXI] == 2);
    k[7] -= 1.0, ((double *)c0.in[0].p)[2] = -0.5; /* corner 2 across the axis */
    oracle_element_stiffness(&R0, 0, &c0, k);
    ST(R0.counts[V_AXI] == 3);
    call_free(&c0);
    /* tfem_get_adapt_cycles against the shadow's cycles */
    gbuf g3[3];
    memset(&c0, 0, sizeof c0);
    c0.fn = F_GET_ADAPT_CYCLES;
    c0.out[0].len = 2;
    gb_alloc(&g3[0], K_L, 2), gb_alloc(&g3[1], K_D, 2), gb_alloc(&g3[2], K_T, 2);
    int64_t un[2] = {100, 250};
    double es[2] = {0.3, 0.1};
    memcpy(g3[0].p, un, sizeof un), memcpy(g3[1].p, es, sizeof es);
    oracle_adapt_cycles(&R0, 0, &c0, TFEM_STATUS_INVALID_STATE, g3, ""); /* none yet: INVALID_STATE */
    ST(R0.counts[V_ADAPT] == 0);
    oracle_adapt_cycles(&R0, 0, &c0, TFEM_STATUS_OK, g3, "");
    ST(R0.counts[V_ADAPT] == 1);
    R0.sh.adapt_n = 2, R0.sh.adapt_unk[0] = 100, R0.sh.adapt_unk[1] = 250, R0.sh.adapt_est[0] = 0.3, R0.sh.adapt_est[1] = 0.1;
    oracle_adapt_cycles(&R0, 0, &c0, TFEM_STATUS_OK, g3, "");
    ST(R0.counts[V_ADAPT] == 1);
    R0.sh.adapt_est[1] = nextafter(0.1, 1.0); /* a cycle changed since */
    oracle_adapt_cycles(&R0, 0, &c0, TFEM_STATUS_OK, g3, "");
    ST(R0.counts[V_ADAPT] == 2);
    c0.out[0].len = 1; /* one short */
    oracle_adapt_cycles(&R0, 0, &c0, TFEM_STATUS_OK, g3, "");
    oracle_adapt_cycles(&R0, 0, &c0, TFEM_STATUS_BUFFER_TOO_SMALL, g3, "");
    ST(R0.counts[V_ADAPT] == 3);
    /* tfem_solve_adaptive: a bad argument accepted is a finding (no library call on that path) */
    c0.fn = F_SOLVE_ADAPTIVE;
    c0.iv[4] = 0, c0.iv[5] = 2, c0.iv[6] = 300, c0.dv[2] = NAN;
    oracle_adapt(&R0, 0, &c0, TFEM_STATUS_OK, g3, "");
    oracle_adapt(&R0, 0, &c0, TFEM_STATUS_INVALID_ARGUMENT, g3, "");
    c0.dv[2] = 0.1, c0.iv[6] = INT_MIN; /* max_unknowns INT64_MIN */
    oracle_adapt(&R0, 0, &c0, TFEM_STATUS_NOT_CONVERGED, g3, "");
    ST(R0.counts[V_ADAPT] == 5);
    for (int j = 0; j < 3; ++j) free(g3[j].blk);
  }
  {
    /* tfem_set_boundary_circle's expected status (circle_expect) and its
     * oracle: nodes 0..2 on the unit circle, node 3 inside it; tag 3 joins
     * 0-1-2, tag 4 joins 2 and 3 */
    runner_t R0;
    case_t cs0;
    memset(&R0, 0, sizeof R0);
    memset(&cs0, 0, sizeof cs0);
    cs0.kind = "self-test";
    R0.cs = &cs0;
    sh_init(&R0.sh);
    shadow_t *sh = &R0.sh;
    char why[96];
    unsigned char off[4] = {0};
    ST(circle_expect(sh, 3, 0, 0, 1, why, sizeof why, NULL) == TFEM_STATUS_INVALID_STATE && strstr(why, "no mesh"));
    double xy[8] = {1, 0, 0, 1, -1, 0, 0.5, 0.5};
    int tri[6] = {0, 1, 3, 1, 2, 3}, body[2] = {1, 1}, edge[6] = {0, 1, 1, 2, 2, 3}, tag[3] = {3, 3, 4};
    sh_new_mesh(sh, 4, xy, 2, tri, body, 1);
    sh_set_edges(sh, 3, edge, tag);
    ST(circle_expect(sh, 3, NAN, 0, 1, why, sizeof why, NULL) == TFEM_STATUS_INVALID_ARGUMENT && !strcmp(why, "centre"));
    ST(circle_expect(sh, 3, 0, -INFINITY, 1, why, sizeof why, NULL) == TFEM_STATUS_INVALID_ARGUMENT);
    for (int k = 0; k < 5; ++k)
      ST(circle_expect(sh, 3, 0, 0, (double[]){0.0, -0.0, -1.0, NAN, INFINITY}[k], why, sizeof why, NULL) ==
             TFEM_STATUS_INVALID_ARGUMENT && !strcmp(why, "radius"));
    ST(circle_expect(sh, 99, 0, 0, 1, why, sizeof why, NULL) == TFEM_STATUS_INVALID_ARGUMENT &&
       !strcmp(why, "no boundary edge has tag 99"));
    ST(circle_expect(sh, 3, 0, 0, 1, why, sizeof why, NULL) == TFEM_STATUS_OK);
    ST(circle_expect(sh, 3, 0, 0, 1 + 5e-7, why, sizeof why, NULL) == TFEM_STATUS_OK);
    ST(circle_expect(sh, 3, 0, 0, 1 + 2e-6, why, sizeof why, off) == TFEM_STATUS_INVALID_ARGUMENT && off[0] && off[1] &&
       off[2] && !off[3]);
    ST(circle_expect(sh, 3, 0, 0, 1 / (1 - 1e-6), why, sizeof why, NULL) == -1); /* (on the bound: rounding decides) */
    memset(off, 0, sizeof off);
    ST(circle_expect(sh, 4, 0, 0, 1, why, sizeof why, off) == TFEM_STATUS_INVALID_ARGUMENT && !off[2] && off[3] &&
       strstr(why, " of an edge tagged 4 lies"));
    call_t c0;
    memset(&c0, 0, sizeof c0);
    c0.fn = F_SET_BOUNDARY_CIRCLE;
    c0.iv[0] = 4, c0.dv[2] = 1.0;
    oracle_circle(&R0, 0, &c0, TFEM_STATUS_INVALID_ARGUMENT, "node 4 of an edge tagged 4 lies 2.9e-1 from the curve");
    ST(R0.counts[V_CIRCLE] == 0);
    oracle_circle(&R0, 0, &c0, TFEM_STATUS_INVALID_ARGUMENT, "node 3 of an edge tagged 4 lies 0 from the curve");
    ST(R0.counts[V_CIRCLE] == 1); /* (node 3, base 1, is on the circle) */
    oracle_circle(&R0, 0, &c0, TFEM_STATUS_OK, "");
    ST(R0.counts[V_CIRCLE] == 2);
    c0.iv[0] = 3;
    oracle_circle(&R0, 0, &c0, TFEM_STATUS_OK, "");
    oracle_circle(&R0, 0, &c0, TFEM_STATUS_INVALID_STATE, "no mesh");
    ST(R0.counts[V_CIRCLE] == 3);
    sh->exact = 0; /* (a refined mesh: only the circle itself is known) */
    oracle_circle(&R0, 0, &c0, TFEM_STATUS_INVALID_ARGUMENT, "node 1 of an edge tagged 3 lies");
    ST(R0.counts[V_CIRCLE] == 3 && circle_expect(sh, 3, 0, 0, 1, why, sizeof why, NULL) == -1);
    sh_clear_mesh(sh);
  }
  /* The 3D checkers: the Kuhn blocks, the shadow's J, faces and loads, the
   * options refused, what a failed 3D message copy may write. */
  {
    smesh_t m = {0};
    int lower = kuhn_block(&m, 2, -1.0, 1, 0), upper = kuhn_block(&m, 2, 0.0, 2, 10);
    ST(lower == 0 && upper == 27 && m.nn == 54 && m.nt == 96 && m.nf == 2 * 6 * 8);
    int positive = 1, per_tag[17] = {0};
    for (int e = 0; e < m.nt; ++e)
      positive &= ss_j(&m.xyz[3 * m.tet[4 * e]], &m.xyz[3 * m.tet[4 * e + 1]], &m.xyz[3 * m.tet[4 * e + 2]],
                       &m.xyz[3 * m.tet[4 * e + 3]], NULL) > 0;
    for (int f = 0; f < m.nf; ++f) per_tag[m.ftag[f] < 17 ? m.ftag[f] : 0]++;
    ST(positive && per_tag[1] == 8 && per_tag[6] == 8 && per_tag[15] == 8 && per_tag[16] == 8 && per_tag[7] == 0 &&
       per_tag[0] == 0);
    sshadow_t sh;
    memset(&sh, 0, sizeof sh);
    int swapped[4 * 96];
    memcpy(swapped, m.tet, sizeof swapped);
    swapped[2] = m.tet[3], swapped[3] = m.tet[2]; /* tetrahedron 0 given with negative J: renumbered */
    ss_new_mesh(&sh, m.nn, m.xyz, m.nt, swapped, m.body, 1);
    ST(!memcmp(sh.tet, m.tet, sizeof swapped) && sh.base == 1 && sh.exact);
    case_t cs;
    memset(&cs, 0, sizeof cs);
    char why[200];
    call_t *c = s_faces_call(&cs, &m, 1, F_S_SET_FACES, INT_MIN, INT_MIN);
    ST(ss_faces_refused(&sh, c, why, sizeof why) == 0);
    int inner[3] = {m.tet[0] + 1, m.tet[1] + 1, m.tet[2] + 1}, owner = -1, g0[3] = {m.tet[0], m.tet[1], m.tet[2]};
    int shared = ss_owners(&sh, g0, &owner) == 2;
    c = s_call(&cs, F_S_ADD_FACES, 1, 0, 0, 0, 0);
    in_set(c, 0, inner, 3, sizeof(int));
    in_set(c, 1, (int[]){7}, 1, sizeof(int));
    ST(!shared || (ss_faces_refused(&sh, c, why, sizeof why) == 1 && strstr(why, "2 tetrahedra")));
    c = s_faces_call(&cs, &m, 1, F_S_SET_FACES, 16, INT_MIN);
    case_insert_copy(&cs, cs.n, c);
    c = &cs.c[cs.n - 1];
    sh.nf = 0;
    ST(ss_faces_refused(&sh, c, why, sizeof why) == 0);
    int *both = xmalloc(sizeof(int) * 6 * 8), *tags = xmalloc(sizeof(int) * 16);
    memcpy(both, c->in[0].p, sizeof(int) * 24), memcpy(both + 24, c->in[0].p, sizeof(int) * 24);
    for (int k = 0; k < 16; ++k) tags[k] = 16;
    in_set(c, 0, both, 48, sizeof(int)), in_set(c, 1, tags, 16, sizeof(int));
    c->iv[0] = 16;
    ST(ss_faces_refused(&sh, c, why, sizeof why) == 1 && strstr(why, "twice")); /* (a face given twice with one tag) */
    tags[15] = 17;
    for (int k = 8; k < 16; ++k) tags[k] = 17;
    in_set(c, 1, tags, 16, sizeof(int));
    ST(ss_faces_refused(&sh, c, why, sizeof why) == 0); /* (the same faces under another tag) */
    sh.loaded = 1;
    ST(ss_faces_refused(&sh, c, why, sizeof why) == 1 && strstr(why, "name the faces"));
    sh.loaded = 0;
    free(both), free(tags);
    /* the loads on the upper top (tag 16, area 1, outward +z): a pressure
     * 2 pushes down by 2 in all, a traction (1, 0, 3) pulls by (1, 0, 3) */
    sh.nf = m.nf;
    sh.face = xmalloc(sizeof(int) * 3 * (size_t)m.nf), sh.ftag = xmalloc(sizeof(int) * (size_t)m.nf);
    memcpy(sh.face, m.face, sizeof(int) * 3 * (size_t)m.nf), memcpy(sh.ftag, m.ftag, sizeof(int) * (size_t)m.nf);
    sh.load = xmalloc(2 * sizeof(ss_load));
    sh.load[0] = (ss_load){16, 0, {2.0, 0, 0}}, sh.load[1] = (ss_load){16, 1, {1.0, 0.0, 3.0}}, sh.nl = 2;
    double f[3 * 54], tot[3] = {0, 0, 0};
    ST(ss_loads(&sh, f));
    for (int k = 0; k < 3 * 54; ++k) tot[k % 3] += f[k];
    ST(fabs(tot[0] - 1.0) < 1e-14 && fabs(tot[1]) < 1e-14 && fabs(tot[2] - 1.0) < 1e-14);
    /* a flat tetrahedron (four nodes of one plane): its face refused */
    double flat_xyz[12] = {0, 0, 0, 1, 0, 0, 0, 1, 0, 1, 1, 0};
    int flat_tet[4] = {0, 1, 2, 3}, flat_body[1] = {1}, flat_face[3] = {0, 1, 2}, flat_tag[1] = {1};
    ss_new_mesh(&sh, 4, flat_xyz, 1, flat_tet, flat_body, 0);
    c = s_call(&cs, F_S_SET_FACES, 1, 0, 0, 0, 0);
    in_set(c, 0, flat_face, 3, sizeof(int)), in_set(c, 1, flat_tag, 1, sizeof(int));
    ST(ss_faces_refused(&sh, c, why, sizeof why) == 1 && strstr(why, "flat"));
    ss_free(&sh);
    /* the options: frictionless, the 3D test, max_iterations >= 1, refactorize 0 or 1, E_c and lambda 0 or > 0 */
    c = s_solve_call(&cs, F_S_SOLVE_CONTACT, 50, 1, 0.0, 2.0, 0, 0);
    ST(!solid_options_refused(c));
    c->iv[0] = 1;
    ST(solid_options_refused(c));
    c->iv[0] = 0, c->dv[1] = -0.0;
    ST(!solid_options_refused(c));
    c->dv[1] = NAN;
    ST(solid_options_refused(c));
    c->dv[1] = 0, c->iv[2] = 0;
    ST(solid_options_refused(c));
    c->in[0].null_ = 1;
    ST(!solid_options_refused(c));
    ST(!may_write_on_failure(F_S_GET_WARNING, TFEM_STATUS_INVALID_ARGUMENT) &&
       may_write_on_failure(F_S_GET_WARNING, TFEM_STATUS_BUFFER_TOO_SMALL) &&
       may_write_on_failure(F_SC_LAST_ERROR, TFEM_STATUS_INVALID_ARGUMENT) &&
       !may_write_on_failure(F_S_LAST_ERROR, TFEM_STATUS_NULL_POINTER) && may_write_on_failure(F_GET_WARNING, 2));
    ST(solid_changes_problem(F_S_FIX) && !solid_changes_problem(F_S_SET_ORDERING) && sc_builds(F_SC_AREA) &&
       !sc_builds(F_SC_GATHER) && solid_result_fn(F_S_WRITE_VTU));
    case_free(&cs);
    smesh_free(&m);
  }
  /* 3D cases: a share of the cases (from a stream of their own: the
   * others are the cases they were without it), every kind met, each
   * generated the same from (seed, case). */
  {
    static const char *const kinds[7] = {"solid_tension", "solid_blocks", "solid_gap", "solid_steps", "solid_host",
                                         "solid_gmsh", "solid_random"};
    int met[7] = {0}, n3 = 0, same_2d = 1;
    double keep = g_solid_share;
    for (long k = 0; k < 2000; ++k) {
      mesh_t m1 = {0}, m2 = {0};
      case_t c1, c2;
      g_solid_share = keep;
      gen_case(13, k, &c1, &m1);
      g_solid_share = 0.0;
      gen_case(13, k, &c2, &m2);
      n3 += c1.solid;
      for (int i = 0; i < 7 && c1.solid; ++i) met[i] |= !strcmp(c1.kind, kinds[i]);
      if (!c1.solid) {
        same_2d &= c1.n == c2.n && !strcmp(c1.kind, c2.kind);
        for (int i = 0; same_2d && i < c1.n; ++i) same_2d = c1.c[i].fn == c2.c[i].fn && !memcmp(c1.c[i].iv, c2.c[i].iv, sizeof c1.c[i].iv);
      }
      case_free(&c1), case_free(&c2), mesh_free(&m1), mesh_free(&m2);
    }
    g_solid_share = keep;
    ST(n3 > 0.5 * SOLID_SHARE * 2000 && n3 < 1.5 * SOLID_SHARE * 2000 && same_2d);
    for (int i = 0; i < 7; ++i) ST(met[i]);
  }
  /* Case generation is a pure function of (seed, case). */
  for (long k = 0; k < 200; ++k) {
    mesh_t m1 = {0}, m2 = {0};
    case_t c1, c2;
    gen_case(7, k, &c1, &m1);
    gen_case(7, k, &c2, &m2);
    int same = c1.n == c2.n;
    for (int i = 0; same && i < c1.n; ++i) {
      same = c1.c[i].fn == c2.c[i].fn && !memcmp(c1.c[i].iv, c2.c[i].iv, sizeof c1.c[i].iv) &&
             !memcmp(c1.c[i].dv, c2.c[i].dv, sizeof c1.c[i].dv);
      for (int j = 0; same && j < MAXIN; ++j)
        same = c1.c[i].in[j].n == c2.c[i].in[j].n &&
               (!c1.c[i].in[j].n || !memcmp(c1.c[i].in[j].p, c2.c[i].in[j].p, (size_t)c1.c[i].in[j].n * in_el(c1.c[i].fn, j)));
    }
    ST(same);
    case_free(&c1);
    case_free(&c2);
    mesh_free(&m1);
    mesh_free(&m2);
  }
#undef ST
  printf("api_fuzz self-test: %s\n", bad ? "FAILED" : "passed");
  return bad ? 1 : 0;
}

/* ------------------------------------------------------------------------ */
/* main                                                                      */
/* ------------------------------------------------------------------------ */

static void usage(void) {
  printf("usage: api_fuzz [--seed S] [--cases N] [--first K] [--threads T] [--long] [--seconds S]\n"
         "                [--batch B] [--timeout S] [--print-limit P] [--verbose] [--no-fork] [--solid-share F]\n"
         "       api_fuzz --seed S --replay-case K [--minimize [--class NAME]] [--c-file PATH]\n"
         "         (--class state_change_status: a call OK originally fails on the replay)\n"
         "       api_fuzz --self-test   (checks the checkers, no library call)\n"
         "Defaults: seed 1, %d cases from case 0 (about a minute on 2 cores), 1 thread, batches of 25 cases\n"
         "per forked child, 120 s per batch. --long runs 500 times as many cases (hours);\n"
         "--seconds stops starting new batches after that many seconds. --solid-share sets the share of 3D\n"
         "cases (default %.2f; 1: only 3D; give it to --replay-case too). Exit status 1 if any\n"
         "violation was found. Classes:",
         20000, SOLID_SHARE);
  for (int v = 0; v < NV; ++v) printf("%s %s", v ? "," : "", V_NAME[v]);
  printf("\n");
}

int main(int argc, char **argv) {
  long cases = 20000, replay = -1, first_case = 0;
  int batch = 25, long_mode = 0, do_min = 0, target = -1;
  double seconds = 0;
  const char *cpath = NULL;
  g_opt = (opts_t){1, 1, 120.0, 0};
  for (int i = 1; i < argc; ++i) {
    const char *a = argv[i];
    const char *v = i + 1 < argc ? argv[i + 1] : NULL;
    if (!strcmp(a, "--seed") && v) g_opt.seed = strtoull(v, NULL, 0), ++i;
    else if (!strcmp(a, "--cases") && v) cases = strtol(v, NULL, 0), ++i;
    else if (!strcmp(a, "--first") && v) first_case = strtol(v, NULL, 0), ++i;
    else if (!strcmp(a, "--threads") && v) g_opt.threads = atoi(v), ++i;
    else if (!strcmp(a, "--batch") && v) batch = atoi(v), ++i;
    else if (!strcmp(a, "--timeout") && v) g_opt.timeout = atof(v), ++i;
    else if (!strcmp(a, "--seconds") && v) seconds = atof(v), ++i;
    else if (!strcmp(a, "--print-limit") && v) g_print_limit = atoi(v), ++i;
    else if (!strcmp(a, "--replay-case") && v) replay = strtol(v, NULL, 0), ++i;
    else if (!strcmp(a, "--c-file") && v) cpath = v, ++i;
    else if (!strcmp(a, "--solid-share") && v) g_solid_share = atof(v), ++i;
    else if (!strcmp(a, "--class") && v) {
      for (int k = 0; k < NV; ++k)
        if (!strcmp(v, V_NAME[k])) target = k;
      if (!strcmp(v, "state_change_status")) target = NV; /* a status flip on replay */
      if (target < 0) {
        usage();
        return 2;
      }
      ++i;
    } else if (!strcmp(a, "--long")) long_mode = 1;
    else if (!strcmp(a, "--minimize")) do_min = 1;
    else if (!strcmp(a, "--verbose")) g_verbose = 1;
    else if (!strcmp(a, "--no-fork")) g_opt.no_fork = 1;
    else if (!strcmp(a, "--self-test")) {
      gmsh_files_init();
      int rc = self_test();
      gmsh_files_cleanup();
      return rc;
    }
    else {
      usage();
      return !strcmp(a, "--help") ? 0 : 2;
    }
  }
  if (long_mode) cases *= 500;
  if (batch < 1) batch = 1;
  if (g_opt.threads < 1) g_opt.threads = 1;
  setvbuf(stdout, NULL, _IOLBF, 0);
  sigset_t chld;
  sigemptyset(&chld);
  sigaddset(&chld, SIGCHLD);
  sigprocmask(SIG_BLOCK, &chld, NULL);

  gmsh_files_init();
  static const char *repro_name[NGMSH];
  char rb[NGMSH][96];
  for (int g = 0; g < NGMSH; ++g) {
    if (g == G_DIRECTORY) snprintf(rb[g], sizeof rb[g], "REPRO_DIR");
    else if (g == G_BAD_UTF8) snprintf(rb[g], sizeof rb[g], "REPRO_DIR \"/\\377\\376.msh\"");
    else if (g == G_NONEXISTENT) snprintf(rb[g], sizeof rb[g], "REPRO_DIR \"/does_not_exist.msh\"");
    else snprintf(rb[g], sizeof rb[g], "REPRO_DIR \"/%s.msh\"", G_NAME[g]);
    repro_name[g] = rb[g];
    G_REPRO[g] = repro_name[g];
  }
  snprintf(g_errpath, sizeof g_errpath, "%s/stderr", g_dir);
  g_errfd = open(g_errpath, O_RDWR | O_CREAT | O_TRUNC | O_APPEND, 0600);
  if (g_errfd < 0) {
    perror(g_errpath);
    return 3;
  }
  size_t shsize = sizeof(shared_t) + sizeof(case_result) * (size_t)(batch > 1 ? batch : 1);
  g_shared = mmap(NULL, shsize, PROT_READ | PROT_WRITE, MAP_SHARED | MAP_ANONYMOUS, -1, 0);
  if (g_shared == MAP_FAILED) {
    perror("mmap");
    return 3;
  }
  memset(g_shared, 0, shsize);
  if (g_opt.no_fork) dup2(g_errfd, 2);

  if (replay >= 0) {
    /* One case, verbosely, with its C reproducer. */
    int pos = 0;
    char how[200];
    mesh_t mesh = {0};
    case_t cs;
    gen_case(g_opt.seed, replay, &cs, &mesh);
    int ncalls = cs.n;
    case_free(&cs);
    mesh_free(&mesh);
    if (do_min) {
      g_first = replay;
      int t = spawn(&pos, 1, 1, how, sizeof how);
      if (target < 0) {
        if (t) target = t;
        else
          for (int v = 0; v < NV && target < 0; ++v)
            if (g_shared->res[0].counts[v] > 0) target = v;
      }
      if (target < 0) {
        printf("case %ld shows no violation: nothing to minimise\n", replay);
      } else {
        printf("minimising case %ld (%d calls) on %s\n", replay, ncalls, target == NV ? "state_change_status" : V_NAME[target]);
        minimize(replay, target, ncalls);
      }
    }
    char path[400];
    snprintf(path, sizeof path, "%s", cpath ? cpath : "");
    if (!cpath) snprintf(path, sizeof path, "%s/repro.c", g_dir);
    g_cfile = fopen(path, "w+");
    if (!g_cfile) {
      perror(path);
      return 3;
    }
    g_verbose = 1;
    g_first = replay;
    int t = spawn(&pos, 1, 1, how, sizeof how);
    if (t) {
      /* The child died: close the program it was writing. */
      fseek(g_cfile, 0, SEEK_END);
      fprintf(g_cfile, "  } /* the process died here */\n");
      mesh_t m2 = {0};
      case_t c2;
      gen_case(g_opt.seed, replay, &c2, &m2);
      c_emit_tail(g_cfile, &c2, 1);
      case_free(&c2);
      mesh_free(&m2);
      printf("\nVIOLATION %s: the process was %s\n", V_NAME[t], how);
      print_stderr_tail();
    }
    fflush(g_cfile);
    printf("\n/* ---------------- C reproducer (%s) ---------------- */\n", cpath ? cpath : "printed only");
    rewind(g_cfile);
    char buf[4096];
    size_t k;
    while ((k = fread(buf, 1, sizeof buf, g_cfile)) > 0) fwrite(buf, 1, k, stdout);
    fclose(g_cfile);
    if (!cpath) unlink(path);
    long total = t ? 1 : 0;
    for (int v = 0; v < NV; ++v) total += g_shared->res[0].counts[v];
    close(g_errfd);
    unlink(g_errpath);
    gmsh_files_cleanup();
    return total ? 1 : 0;
  }

  double t0 = now_s(), t_progress = t0;
  long totals[NV] = {0}, ncases[NV] = {0}, firsts[NV][5], calls = 0, done = 0, stderr_bytes = 0, oracles[NO] = {0};
  for (long first = first_case; first < first_case + cases; first += batch) {
    int n = (int)(first_case + cases - first < batch ? first_case + cases - first : batch);
    run_batch(first, n);
    for (int i = 0; i < n; ++i) {
      case_result *r = &g_shared->res[i];
      if (!r->done) continue;
      ++done;
      calls += r->calls;
      stderr_bytes += r->stderr_bytes;
      for (int o = 0; o < NO; ++o) oracles[o] += r->oracles[o];
      for (int v = 0; v < NV; ++v)
        if (r->counts[v] > 0) {
          if (ncases[v] < 5) firsts[v][ncases[v]] = first + i;
          ncases[v]++;
          totals[v] += r->counts[v];
        }
    }
    if (now_s() - t_progress > 60) {
      long v = 0;
      for (int k = 0; k < NV; ++k) v += totals[k];
      printf("progress: %ld of %ld cases, %ld calls, %ld violations, %.0f s\n", done, cases, calls, v, now_s() - t0);
      t_progress = now_s();
    }
    if (seconds > 0 && now_s() - t0 > seconds) {
      printf("time limit of %.0f s reached after %ld cases\n", seconds, done);
      break;
    }
  }
  double dt = now_s() - t0;
  /* (tfem_version is a static string: calling it here starts no thread.) */
  printf("\napi_fuzz: libtfem %s, seed %" PRIu64 ", %ld cases, %ld calls in %.1f s (%d thread%s per child)\n",
         tfem_version(), g_opt.seed, done, calls, dt, g_opt.threads, g_opt.threads > 1 ? "s" : "");
  printf("  %-15s %7s %11s  %s\n", "class", "cases", "occurrences", "first cases (rerun with --replay-case K)");
  long other = 0, any = 0;
  for (int v = 0; v < NV; ++v) {
    any += totals[v];
    if (v != V_CRASH && v != V_ABORT && v != V_HANG && v != V_NAN_OK && v != V_CANARY && v != V_STATE &&
        v != V_STDERR && v != V_LONG_MSG)
      other += totals[v];
    if (!totals[v]) continue;
    printf("  %-15s %7ld %11ld  ", V_NAME[v], ncases[v], totals[v]);
    for (long k = 0; k < ncases[v] && k < 5; ++k) printf("%s%ld", k ? " " : "", firsts[v][k]);
    printf("   %s\n", V_DESC[v]);
  }
  printf("  oracles checked:");
  for (int o = 0; o < NO; ++o) printf(" %s=%ld", O_NAME[o], oracles[o]);
  printf("\n");
  printf("SUMMARY cases=%ld calls=%ld crashes=%ld aborts=%ld hangs=%ld nan_inf_ok=%ld canary=%ld state_changes=%ld "
         "stderr_bytes=%ld long_messages=%ld other_violations=%ld -> %s\n",
         done, calls, totals[V_CRASH], totals[V_ABORT], totals[V_HANG], totals[V_NAN_OK], totals[V_CANARY],
         totals[V_STATE], stderr_bytes, totals[V_LONG_MSG], other, any ? "FAIL" : "PASS");
  close(g_errfd);
  unlink(g_errpath);
  gmsh_files_cleanup();
  return any ? 1 : 0;
}
