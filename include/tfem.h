/*
 * tfem -- the Tempered Finite Element Method for elasticity and contact
 * in 2D (frictionless or with Coulomb friction) and 3D (frictionless).
 * C ABI.
 *
 * Overview
 * - Two objects. A tfem_model holds a whole problem: the mesh and its
 *   bodies, materials, loads and constraints, contact pairs, and the
 *   results of its last solve or load step. A tfem_contact is the contact
 *   context of a host code that keeps its own elements and solver: it
 *   gives back contact stiffness and forces to add to the host's system.
 *   A tfem_solid_model holds a problem in space (tetrahedra, tagged
 *   boundary faces, frictionless contact between tagged surfaces): its
 *   functions, tfem_solid_*, follow the same phases and conventions, and
 *   one is used by one thread at a time like a tfem_model. A
 *   tfem_solid_contact is the contact context of a 3D host code, the
 *   tfem_contact of tetrahedral meshes (tfem_solid_contact_*).
 * - Phases of a model: describe it (mesh, materials, loads and
 *   constraints, contact pairs), solve it (tfem_solve, tfem_solve_contact,
 *   or a load history of tfem_step), read the results (computed when
 *   asked). Any change to the description discards the results.
 * - The entry points below stand in groups, in that order, each under a
 *   head: lifecycle, mesh, materials, loads and constraints, contact pairs,
 *   solve, results, contact results, load history, utilities, the host
 *   codes' contact context, the 3D model, and the 3D host codes' contact
 *   context.
 *
 * Conventions
 * - Every function returns a tfem_status; TFEM_STATUS_OK (0) is success.
 *   Status numbers are fixed forever and never reused. tfem_last_error()
 *   gives the message of the last failed call, naming the offending node,
 *   triangle, edge, body or argument.
 * - Indices (nodes, triangles, edges) use the index_base given to
 *   tfem_set_mesh (0 for C, 1 for Fortran) in every later call and in
 *   every message. Counts are int; buffer lengths are size_t, in elements.
 * - Output buffers are owned by the caller. Their length is checked and
 *   nothing is written when it is too short (TFEM_STATUS_BUFFER_TOO_SMALL).
 * - A call that returns an error writes none of its outputs: every buffer,
 *   and every value or struct given back through a pointer (a size, count
 *   or index, a tfem_solve_info, a tfem_contact_report, the host vector of
 *   tfem_contact_scatter_add and tfem_solid_contact_scatter_add), keeps the
 *   bytes it held, whatever the error (a handle or argument refused, a
 *   wrong state, one of several buffers too short or NULL, a solve that
 *   fails). The only exceptions are the message copies: tfem_last_error,
 *   tfem_contact_last_error and tfem_get_warning (and the 3D handles'
 *   tfem_solid_last_error, tfem_solid_get_warning and
 *   tfem_solid_contact_last_error) write the message cut to the buffer
 *   (NUL-terminated) with TFEM_STATUS_BUFFER_TOO_SMALL, and the
 *   *_last_error functions write the message refusing a handle that is
 *   not live with TFEM_STATUS_INVALID_ARGUMENT.
 * - A failed call leaves the model as it was, its results included. Any
 *   change to the problem (mesh, boundary edges, materials, constraints,
 *   loads, contact pairs, tempering) discards previous results; settings
 *   that change nothing physical (tfem_set_ordering, tfem_set_threads)
 *   keep them. Results are computed when asked for, and do not depend on
 *   the calls that failed before.
 * - Units are the caller's: lengths, forces and moduli in one consistent
 *   system (SI: m, N, Pa). The model is 2D with unit thickness: moduli,
 *   stresses, pressures and tractions are forces per unit area (Pa);
 *   nodal forces, reactions and contact forces are forces per unit
 *   thickness (N/m); body forces are forces per unit volume (N/m^3); work
 *   is per unit thickness (J/m).
 * - No NaN or Inf is ever returned as a result with TFEM_STATUS_OK: an
 *   overflow gives TFEM_STATUS_NUMERICAL_FAILURE naming the item.
 * - Nothing is ever printed on stdout or stderr: messages, warnings and
 *   internal failures are read with tfem_last_error and tfem_get_warning.
 * - Handles are checked before use: a destroyed model or context, or a
 *   handle of the other kind (a Fortran type(c_ptr) does not tell them
 *   apart), is refused with TFEM_STATUS_INVALID_ARGUMENT (its message in
 *   the thread's slot, or in the buffer of the *_last_error functions),
 *   and destroying it is a no-op. (A destroyed
 *   handle whose address a new handle has taken reaches the new one.)
 *
 * Thread contract
 * - A tfem_model must be used by one thread at a time (no internal
 *   locking); different models may be used concurrently from different
 *   threads. The solver itself runs on a thread pool: the process-wide one
 *   (as many threads as cores, or RAYON_NUM_THREADS), or the model's own
 *   with tfem_set_threads (1 for a host that runs its own threads).
 * - tfem_version, tfem_element_stiffness, tfem_laplacian_stiffness and
 *   tfem_contact_options_default are pure and thread-safe; their errors go
 *   to a per-thread slot read with tfem_last_error(NULL, ...), which their
 *   next success clears.
 * - No panic crosses the boundary: an internal failure returns
 *   TFEM_STATUS_INTERNAL (its message read with tfem_last_error).
 */


#ifndef TFEM_H
#define TFEM_H

/* Generated by cbindgen from the Rust sources of tfem. Do not edit. */

#include <stddef.h>
#include <stdint.h>

/**
 * Outcome of a call. The numbers are part of the C ABI and are fixed
 * forever: a code is never renumbered or reused, new codes are appended.
 */
typedef enum tfem_status {
  /**
   * Success.
   */
  TFEM_STATUS_OK = 0,
  /**
   * A required pointer argument was NULL.
   */
  TFEM_STATUS_NULL_POINTER = 1,
  /**
   * An argument is out of its documented range (the message names it).
   */
  TFEM_STATUS_INVALID_ARGUMENT = 2,
  /**
   * The mesh is invalid (the message names the node, triangle or edge).
   */
  TFEM_STATUS_INVALID_MESH = 3,
  /**
   * A material is invalid or missing (the message names the body).
   */
  TFEM_STATUS_INVALID_MATERIAL = 4,
  /**
   * The call is not allowed in the model's current state (e.g. a solve
   * before a mesh was given, results before a solve).
   */
  TFEM_STATUS_INVALID_STATE = 5,
  /**
   * A caller-owned output buffer is shorter than required.
   */
  TFEM_STATUS_BUFFER_TOO_SMALL = 6,
  /**
   * The stiffness matrix is singular or indefinite: some body is not
   * restrained (the message names it).
   */
  TFEM_STATUS_SINGULAR = 7,
  /**
   * The contact active-set loop did not converge (the message gives the
   * history).
   */
  TFEM_STATUS_NOT_CONVERGED = 8,
  /**
   * A degenerate element cannot be integrated (zero Jacobian with
   * tempering off); the message names it.
   */
  TFEM_STATUS_DEGENERATE_ELEMENT = 9,
  /**
   * A contact pair or contact mesh is invalid (the message names it).
   */
  TFEM_STATUS_INVALID_CONTACT = 10,
  /**
   * A computed result is not finite (overflow), or a solve could not
   * reach working accuracy even with a factorisation of its own matrix
   * (the message says which); nothing was returned.
   */
  TFEM_STATUS_NUMERICAL_FAILURE = 11,
  /**
   * An internal error (a caught panic): please report it.
   */
  TFEM_STATUS_INTERNAL = 12,
  /**
   * Memory could not be allocated (the message names what for): the
   * library's copy of a caller's array and the structures a mesh or a
   * contact side derives from it; every stage of a solve, a load step
   * or a step's recovery, checked before the stage starts (set-up,
   * ordering, factorisation, vectors, the threads and their dense
   * kernels' buffers). The bounds checked are conservative: a call may
   * be refused a little before memory is truly exhausted. Other
   * allocations (declarations, results read after a solve, files) are
   * small beside these and not checked: where they fail, the process
   * aborts.
   */
  TFEM_STATUS_OUT_OF_MEMORY = 13,
  /**
   * A file could not be read or written (the message names it).
   */
  TFEM_STATUS_IO = 14,
} tfem_status;

/**
 * How Jmin is chosen (argument `mode` of `tfem_set_tempering`).
 */
typedef enum tfem_tempering_mode {
  /**
   * Jmin = min(h³/λ, h²/10), λ = larger side of the mesh's bounding box
   * (default): an element whose apex stands at least a tenth of its
   * longest edge h above it is never softened.
   */
  TFEM_TEMPERING_MODE_AUTO = 0,
  /**
   * Jmin = h³/λ with λ = `value` (a length in model units).
   */
  TFEM_TEMPERING_MODE_LAMBDA = 1,
  /**
   * Jmin = `value` for every element (length²).
   */
  TFEM_TEMPERING_MODE_FIXED_JMIN = 2,
  /**
   * Plain FEM (no tempering); zero-Jacobian elements are an error.
   */
  TFEM_TEMPERING_MODE_OFF = 3,
} tfem_tempering_mode;

/**
 * The fill-reducing ordering of the factorisation (argument `ordering` of
 * `tfem_set_ordering`).
 */
typedef enum tfem_ordering_mode {
  /**
   * Nested dissection from 10 000 unknowns, AMD below (default).
   */
  TFEM_ORDERING_MODE_AUTO = 0,
  /**
   * faer's approximate minimum degree.
   */
  TFEM_ORDERING_MODE_AMD = 1,
  /**
   * Geometric nested dissection on the node coordinates.
   */
  TFEM_ORDERING_MODE_NESTED_DISSECTION = 2,
} tfem_ordering_mode;

/**
 * How the contact pairs' energy is weighted along their interfaces
 * (argument `weighting` of `tfem_set_contact_weighting`).
 */
typedef enum tfem_contact_weighting {
  /**
   * The elements of the contact mesh B (the seed's method) for every
   * pair.
   */
  TFEM_CONTACT_WEIGHTING_STRIP = 0,
  /**
   * The sampled mortar weighting for every pair: one weighted gap per
   * node of each interface's coarser side; frictionless.
   */
  TFEM_CONTACT_WEIGHTING_MORTAR = 1,
  /**
   * Each pair what is right for its interface (the default): B where
   * the two sides' nodes match, the mortar weighting where they do not,
   * B for a pair with friction or a contact mesh of its own.
   */
  TFEM_CONTACT_WEIGHTING_AUTO = 2,
} tfem_contact_weighting;

/**
 * The constitutive law of the contact elements.
 */
typedef enum tfem_contact_law {
  /**
   * Only the normal strain is penalised: D_c = E_c m mᵀ with
   * m = [n_x², n_y², n_x n_y]. Tangential slip is free.
   */
  TFEM_CONTACT_LAW_FRICTIONLESS = 0,
  /**
   * Tempered isotropic elasticity in B (E_c, ν of the softer body) on the
   * element flattened onto its interface line
   * (`contact::law_geometry`): a normal and a
   * tangential spring on the jump between the surfaces, so it also
   * resists slip and ties them (sticking contact). Flattened because,
   * across an initial gap or overlap, the element itself would also
   * read the bodies' tangential stretching, and its Poisson stress
   * broke the patch test (docs/method.md §6.4).
   */
  TFEM_CONTACT_LAW_STICK = 1,
} tfem_contact_law;

/**
 * How an element of B is found inverted.
 */
typedef enum tfem_inversion_test {
  /**
   * J linearised about the initial configuration, J0 + Σ g_i·u_i < 0
   * (consistent with small strain; for a flat conforming element, the
   * node-pair normal gap). Under the frictionless law, only its normal
   * part J0 + Σ (n·g_i)(n·u_i) — the element's normal opening: the
   * node-to-segment gap at its apex times its interface edge, the very
   * quantity the law penalises — so that an active element always pushes.
   * The two differ by J0·ε_tt (the interface stretching times the initial
   * gap): nothing on touching surfaces, but on a curved gap, where the
   * bodies strain by a percent, enough to activate elements that then
   * pull. The default.
   */
  TFEM_INVERSION_TEST_LINEARISED = 0,
  /**
   * The seed's literal test, J(X + u) < 0. Its second-order term (slope
   * times slip) can exceed the penalty penetration on fine meshes and make
   * the loop cycle.
   */
  TFEM_INVERSION_TEST_LITERAL = 1,
} tfem_inversion_test;

/**
 * The 2D idealisation of the out-of-plane direction.
 */
typedef enum tfem_plane_mode {
  /**
   * ε_zz = 0 (thick bodies; the seed's setting).
   */
  TFEM_PLANE_MODE_STRAIN = 0,
  /**
   * σ_zz = 0 (thin plates).
   */
  TFEM_PLANE_MODE_STRESS = 1,
  /**
   * Bodies of revolution about the axis x = 0: x is the radius r ≥ 0,
   * y the axial coordinate z, and the hoop strain ε_θθ = u_r/r. Every
   * force and stiffness is that of the whole ring (2π radians):
   * docs/method.md §7.
   */
  TFEM_PLANE_MODE_AXISYMMETRIC = 2,
} tfem_plane_mode;

/**
 * A displacement component.
 */
typedef enum tfem_component {
  /**
   * Horizontal (u).
   */
  TFEM_COMPONENT_X = 0,
  /**
   * Vertical (v).
   */
  TFEM_COMPONENT_Y = 1,
} tfem_component;

/**
 * What the tolerance of `tfem_solve_adaptive` bounds (argument `goal`).
 */
typedef enum tfem_adapt_goal {
  /**
   * The relative error in the energy norm.
   */
  TFEM_ADAPT_GOAL_ENERGY = 0,
  /**
   * The relative error of the compliance (f·u), the square of the
   * energy's.
   */
  TFEM_ADAPT_GOAL_COMPLIANCE = 1,
} tfem_adapt_goal;

/**
 * A displacement component in space (argument `comp` of `tfem_solid_fix`
 * and `tfem_solid_fix_faces`): the 2D `tfem_component` has no z, and its
 * values must keep their meaning, so 3D has its own.
 */
typedef enum tfem_axis {
  /**
   * u_x.
   */
  TFEM_AXIS_X = 0,
  /**
   * u_y.
   */
  TFEM_AXIS_Y = 1,
  /**
   * u_z.
   */
  TFEM_AXIS_Z = 2,
} tfem_axis;

/**
 * Opaque handle to a contact context for a host code. Create with
 * `tfem_contact_create`, free with `tfem_contact_destroy`.
 */
typedef struct tfem_contact tfem_contact;

/**
 * Opaque handle to a model. Create with `tfem_create`, free with
 * `tfem_destroy`.
 */
typedef struct tfem_model tfem_model;

/**
 * Opaque handle to a 3D contact context for a host code. Create with
 * `tfem_solid_contact_create`, free with `tfem_solid_contact_destroy`.
 */
typedef struct tfem_solid_contact tfem_solid_contact;

/**
 * Opaque handle to a 3D model. Create with `tfem_solid_create`, free with
 * `tfem_solid_destroy`.
 */
typedef struct tfem_solid_model tfem_solid_model;

/**
 * Options of `tfem_solve_contact`. Fill with `tfem_contact_options_default`
 * and change what you need.
 */
typedef struct tfem_contact_options {
  /**
   * A `ContactLaw` value: 0 = frictionless (default), 1 = stick.
   */
  int law;
  /**
   * E_c of the contact elements; 0 = the smaller E of the two bodies, or
   * where one side of a pair has every DOF of its contact nodes prescribed
   * (a rigid tool) the other body's E, so that a rigid tool's nominal E
   * does not set the penalty. The
   * host contact context (`tfem_contact_set_options`) still takes the
   * smaller E of its two sides: give a rigid side its neighbour's E, or
   * set `contact_modulus`.
   */
  double contact_modulus;
  /**
   * λ of the contact elements (Jmin = h³/λ), model length units; 0 = the
   * larger side of the mesh's bounding box.
   */
  double lambda;
  /**
   * An `InversionTest` value: 0 = linearised J (default), 1 = literal J.
   */
  int inversion_test;
  /**
   * Cap on active-set iterations (default 50).
   */
  int max_iterations;
  /**
   * 1 = refactorise the matrix at every active-set iteration; 0 (default)
   * = condense the changes on the contact interface (faster, exact).
   */
  int refactorize;
} tfem_contact_options;

/**
 * Statistics of a solve. Times are wall-clock seconds.
 */
typedef struct tfem_solve_info {
  /**
   * Unknowns after Dirichlet elimination.
   */
  int64_t unknowns;
  /**
   * Stored entries of the matrix's upper triangle.
   */
  int64_t matrix_nnz;
  /**
   * Stored entries of the Cholesky factor.
   */
  int64_t factor_nnz;
  /**
   * Numeric factorisations performed.
   */
  int64_t factorizations;
  /**
   * Unknowns of the condensed contact interface (0 if not condensed).
   */
  int64_t interface_unknowns;
  /**
   * ‖K u − f‖ / ‖f‖ of the final system.
   */
  double relative_residual;
  /**
   * Condition estimate of the Jacobi-scaled final matrix.
   */
  double condition_estimate;
  /**
   * Bytes held by pattern, matrix values, factor and dense interface.
   */
  int64_t memory_bytes;
  /**
   * Bytes one numeric factorisation needs at its peak (factor, symbolic
   * structure, workspace).
   */
  int64_t factorization_bytes;
  /**
   * Pattern and symbolic analysis (0 when reused).
   */
  double time_analysis;
  /**
   * Element matrices and scatter-add.
   */
  double time_assembly;
  /**
   * Numeric factorisations, including the singularity check.
   */
  double time_factorization;
  /**
   * Triangular solves.
   */
  double time_solve;
  /**
   * Dense work on the condensed contact interface.
   */
  double time_interface;
  /**
   * The whole call.
   */
  double time_total;
} tfem_solve_info;

/**
 * Report of `tfem_solve_contact`.
 */
typedef struct tfem_contact_report {
  /**
   * Active-set iterations (solves).
   */
  int iterations;
  /**
   * Elements of the contact mesh B (under the mortar weighting,
   * `tfem_set_contact_weighting`: slave nodes).
   */
  int elements;
  /**
   * Active elements at convergence (under the mortar weighting: slave
   * nodes).
   */
  int active;
  /**
   * Contact length ℓc, model length units: the summed interface-edge
   * length of the active elements, each as far as it faces the other
   * side, of one of B's two families (edges on one side or on the other)
   * in each contact zone (a pair's active elements connected through
   * shared nodes), the one active over the longer length.
   * (Not their mean, which counts half the width of a contact carried by
   * one family alone; docs/method.md §6.8.) Under the
   * mortar weighting: the active slave nodes' summed tributaries.
   */
  double contact_length;
  /**
   * Largest normal interpenetration, model length units (under the
   * mortar weighting: of an active slave node's mean gap).
   */
  double max_penetration;
  /**
   * Solver statistics.
   */
  struct tfem_solve_info info;
} tfem_contact_report;

/**
 * Report of `tfem_solve_adaptive`.
 */
typedef struct tfem_adapt_report {
  /**
   * Solves made (cycles); each cycle's numbers from
   * `tfem_get_adapt_cycles`.
   */
  int cycles;
  /**
   * 1 if the last estimate meets the tolerance (and, with contact, the
   * contact zones' edges are located to it), 0 if a limit stopped the
   * refinement first (a warning then says what was reached).
   */
  int reached;
  /**
   * Unknowns of the last solve.
   */
  int64_t unknowns;
  /**
   * Triangles of the refined mesh.
   */
  int64_t triangles;
  /**
   * The last estimate of the goal's relative error.
   */
  double estimate;
  /**
   * Seconds of the whole adaptive solve, refinements included.
   */
  double seconds;
} tfem_adapt_report;

#ifdef __cplusplus
extern "C" {
#endif // __cplusplus

/****************************************************************************
 * Lifecycle, errors and warnings: a model is created, used from one thread
 * at a time, and destroyed; every call returns a tfem_status, the message of
 * the last failed one is tfem_last_error's, and warnings (something really
 * wrong that did not stop the call) are kept until the next solve or change.
 ***************************************************************************/

/**
 * The library version as a static NUL-terminated string ("major.minor.patch").
 * Thread-safe; never NULL; do not free.
 */
const char *tfem_version(void);

/**
 * Creates an empty model. Returns NULL only if memory is exhausted.
 * Free it with `tfem_destroy`.
 */
struct tfem_model *tfem_create(void);

/**
 * Destroys a model and everything it owns. NULL is a no-op, and so is a
 * pointer that is not a live model (destroyed already, or a contact
 * context). A destroyed handle given to any function is refused
 * (TFEM_STATUS_INVALID_ARGUMENT), as is a handle of the other kind —
 * unless its address has since been reused by a new handle, which it
 * then reaches: do not use a handle after destroying it.
 */
void tfem_destroy(struct tfem_model *model);

/**
 * Copies the message of the last failed call on `model` (empty after a
 * successful call) into `buffer` (`length` bytes including the final NUL).
 * With `model` NULL, gives the calling thread's last error from calls that
 * have no model (or were given a NULL one). A message longer than the buffer
 * is truncated (still NUL-terminated) and TFEM_STATUS_BUFFER_TOO_SMALL is
 * returned; `tfem_last_error_length` gives the size needed. A `model`
 * that is not a live model gives TFEM_STATUS_INVALID_ARGUMENT with the
 * message saying so in `buffer`. (These, with `tfem_contact_last_error`
 * and `tfem_get_warning`, are the only failed calls that write an
 * output: see the conventions at the top.)
 */
enum tfem_status tfem_last_error(const struct tfem_model *model, char *buffer, size_t length);

/**
 * Size in bytes (including the final NUL) of the message `tfem_last_error`
 * would give. `model` may be NULL (thread's last error).
 */
size_t tfem_last_error_length(const struct tfem_model *model);

/**
 * Number of warnings: mesh validation (unused or coincident nodes,
 * inverted or clockwise triangles), what `tfem_add_contact_pairs_auto`
 * left out (a tag whose edges bound several bodies, an interface found
 * again under other tags: kept until the pairs are cleared, the boundary
 * edges set anew or the mesh replaced) and the last solve or load step (tempering of well-shaped
 * elements, an ill-conditioned system, contact pressures with fewer than
 * six correct digits: a penalty E_c so stiff that its overlaps approach
 * the rounding of the displacements; after `tfem_solve` or
 * `tfem_solve_contact`, a body's reactions with fewer than six correct
 * digits: a "rigid" body modelled with a huge Young's modulus; a
 * one-sided contact zone). The pairing warnings outlive solves.
 */
enum tfem_status tfem_warning_count(struct tfem_model *model, int *count);

/**
 * Writes to `size` the size in bytes (including the final NUL) of
 * warning number `index` (0-based, whatever the index base): a buffer
 * of this size holds all of it in `tfem_get_warning`. An index out of
 * range is refused (TFEM_STATUS_INVALID_ARGUMENT), `size` unchanged.
 */
enum tfem_status tfem_get_warning_size(struct tfem_model *model, int index, size_t *size);

/**
 * Copies warning number `index` (0-based, whatever the index base) into
 * `buffer` of `length` bytes, truncating like `tfem_last_error`
 * (`tfem_get_warning_size` gives the size needed): the truncated warning
 * is written with TFEM_STATUS_BUFFER_TOO_SMALL; on any other error
 * (an index out of range) `buffer` is unchanged.
 */
enum tfem_status tfem_get_warning(struct tfem_model *model, int index, char *buffer, size_t length);

/**
 * Sets the number of threads the model's solves run on: 1 <= `threads`
 * <= 1024 gives the model a pool of its own (1: no parallelism at all, for a
 * host that runs its own OpenMP or MPI threads); 0 (the default) uses
 * the process-wide pool, with as many threads as cores or the
 * environment variable RAYON_NUM_THREADS. Results do not depend on it
 * beyond round-off, and are kept.
 */
enum tfem_status tfem_set_threads(struct tfem_model *model, int threads);

/**
 * Writes the number of threads the model's solves run on (see
 * `tfem_set_threads`).
 */
enum tfem_status tfem_get_threads(struct tfem_model *model, int *threads);

/****************************************************************************
 * Mesh: nodes, triangles and their bodies (tfem_set_mesh, or a Gmsh file),
 * and the tagged boundary edges that loads, constraints and contact pairs
 * name.
 ***************************************************************************/

/**
 * Sets the mesh: `n_nodes` nodes with coordinates `xy` (2·n_nodes values,
 * x0 y0 x1 y1 …), `n_triangles` P1 triangles with `connectivity`
 * (3·n_triangles node indices) and a body tag per triangle in
 * `body_of_triangle`. `index_base` is 0 (C) or 1 (Fortran) and applies to
 * every index of every later call. Orientation: triangles may be numbered
 * clockwise, counter-clockwise, or both; each connected region of a body
 * is numbered consistently across its shared edges and turned
 * counter-clockwise by area (a warning counts the triangles turned; every
 * later output refers to the turned triangles). A triangle still
 * clockwise then is a fold of the mesh, an inverted element, which TFEM
 * tempers (a warning counts them). Degenerate triangles are legal.
 * Coordinates whose products overflow double precision are refused.
 * Replacing a mesh discards constraints, loads, contact pairs and
 * results; materials and tempering are kept.
 */
enum tfem_status tfem_set_mesh(struct tfem_model *model,
                               int n_nodes,
                               const double *xy,
                               int n_triangles,
                               const int *connectivity,
                               const int *body_of_triangle,
                               int index_base);

/**
 * Loads a Gmsh MSH 4.1 mesh (ASCII or binary) from the file `path`
 * (NUL-terminated; on Unix any bytes, as the file system takes them,
 * elsewhere UTF-8): physical surfaces become bodies (tag = body),
 * physical curves become boundary-edge tags (a curve in several groups
 * under each of their tags; a surface in several is the body of the first,
 * and physical points are not used: a warning names both); only
 * 3-node triangles and 2-node lines, in the plane z = 0. Replaces the
 * mesh like `tfem_set_mesh` with the given `index_base` for later calls:
 * node i is the i-th node of the file's `$Nodes` section, whatever its
 * Gmsh tag (`tfem_get_mesh_nodes`, `tfem_get_mesh_triangles` and
 * `tfem_get_boundary_edges` read the mesh back).
 * Returns TFEM_STATUS_IO for an unreadable or malformed file,
 * TFEM_STATUS_INVALID_MESH for unsupported content: another version of
 * the format (MSH 2.2, 4.0, …; the message says how to convert the file:
 * `gmsh old.msh -save -format msh41 -o new.msh`; TFEM_STATUS_IO in
 * earlier versions), an element type other
 * than those above, a node off the plane, a triangle with a repeated
 * node (an error about an element or a node names its entity and
 * physical group: tag, and name from `$PhysicalNames`);
 * TFEM_STATUS_INVALID_ARGUMENT if the library was built without the
 * `gmsh` feature. On error the model is unchanged.
 */
enum tfem_status tfem_load_gmsh(struct tfem_model *model, const char *path, int index_base);

/**
 * Sets the tagged boundary edges: `n_edges` edges given by `edge_nodes`
 * (2·n_edges node indices) with a tag each in `tags`. Tags name the edges
 * for loads, constraints and contact pairs. Replaces previous edges (use
 * `tfem_add_boundary_edges` to add one group at a time). Refused, naming
 * the tag, when a load or contact pair already declared would lose its
 * edges or find them interior (an edge shared by two triangles can carry
 * a constraint, not a load or a contact interface); on any error nothing
 * changes.
 */
enum tfem_status tfem_set_boundary_edges(struct tfem_model *model,
                                         int n_edges,
                                         const int *edge_nodes,
                                         const int *tags);

/**
 * Adds tagged boundary edges to those already set (see
 * `tfem_set_boundary_edges`): `n_edges` edges given by `edge_nodes`
 * (2·n_edges node indices) with a tag each in `tags`, for instance one
 * call per boundary group. An edge given again with a tag it already has
 * is refused (its loads would count twice); on any error nothing changes.
 */
enum tfem_status tfem_add_boundary_edges(struct tfem_model *model,
                                         int n_edges,
                                         const int *edge_nodes,
                                         const int *tags);

/**
 * Sizes: nodes, triangles, and elements of the contact mesh of the last
 * contact solve (0 otherwise). Any pointer may be NULL.
 */
enum tfem_status tfem_get_sizes(struct tfem_model *model,
                                int *n_nodes,
                                int *n_triangles,
                                int *n_contact_elements);

/**
 * Number of boundary edges the model holds (each with its tag), from
 * `tfem_set_boundary_edges` / `tfem_add_boundary_edges` or a Gmsh file's
 * physical lines; see `tfem_get_boundary_edges`.
 */
enum tfem_status tfem_get_boundary_edge_count(struct tfem_model *model, int *count);

/**
 * Copies the node coordinates the model holds (x0 y0 x1 y1 …, 2·n_nodes
 * values, n_nodes from `tfem_get_sizes`) into `xy` of `length` values.
 * After `tfem_load_gmsh` node i (in the model's index base) is the i-th
 * node of the file's `$Nodes` section, whatever its Gmsh tag.
 */
enum tfem_status tfem_get_mesh_nodes(struct tfem_model *model, double *xy, size_t length);

/**
 * Copies the triangles the model holds (3·n_triangles node indices in the
 * model's index base, n_triangles from `tfem_get_sizes`) into `triangles`
 * of `length` values and each triangle's body tag into `bodies` of
 * `bodies_length` values; `bodies` may be NULL. Triangles given clockwise
 * are held (and copied) counter-clockwise. Nothing is written unless both
 * buffers are large enough.
 */
enum tfem_status tfem_get_mesh_triangles(struct tfem_model *model,
                                         int *triangles,
                                         size_t length,
                                         int *bodies,
                                         size_t bodies_length);

/**
 * Copies the boundary edges the model holds (2·count node indices in the
 * model's index base, count from `tfem_get_boundary_edge_count`) into
 * `edges` of `length` values and each edge's tag into `tags` of
 * `tags_length` values, in the order they were given (a Gmsh file's: its
 * line elements, by physical group); `tags` may be NULL. Nothing is
 * written unless both buffers are large enough.
 */
enum tfem_status tfem_get_boundary_edges(struct tfem_model *model,
                                         int *edges,
                                         size_t length,
                                         int *tags,
                                         size_t tags_length);

/****************************************************************************
 * Materials, tempering and ordering: one material per body; the tempering of
 * degenerate triangles; the fill-reducing ordering.
 ***************************************************************************/

/**
 * Sets the material of body `body`: Young's modulus `young` (> 0), Poisson
 * ratio `poisson` (in (-1, 0.5) for plane strain and axisymmetric bodies,
 * (-1, 0.5] for plane stress) and `plane` (a `PlaneMode`: 0 strain, 1
 * stress, 2 axisymmetric). Axisymmetric bodies (x the radius, y the axis)
 * do not mix with plane ones, lie at x >= 0, need u_r = 0 fixed on nodes
 * on the axis (checked by the solve) and take the whole ring's forces:
 * nodal forces and reactions are totals around the circumference,
 * pressures and tractions per unit area (docs/method.md §7).
 */
enum tfem_status tfem_set_material(struct tfem_model *model,
                                   int body,
                                   double young,
                                   double poisson,
                                   int plane_mode);

/**
 * Chooses Jmin: `mode` is a `TemperingMode` (0 auto, 1 lambda = `value`,
 * 2 fixed Jmin = `value`, 3 off); `value` is ignored for 0 and 3.
 */
enum tfem_status tfem_set_tempering(struct tfem_model *model, int mode, double value);

/**
 * Chooses the fill-reducing ordering: `ordering` is an `OrderingMode`
 * (0 auto, 1 AMD, 2 nested dissection); `parallel_subtrees` = 1 (default)
 * factorises the two subtrees of a nested dissection concurrently, 0 as
 * one tree. Results do not depend on either beyond round-off: the results
 * of the last solve (all of them, the matrix included) are kept, and the
 * next solve analyses the matrix anew.
 */
enum tfem_status tfem_set_ordering(struct tfem_model *model, int ordering, int parallel_subtrees);

/****************************************************************************
 * Loads and constraints: prescribed displacements per node or per tag, and
 * their values changed along a load history; pressures, tractions, nodal and
 * body forces.
 ***************************************************************************/

/**
 * Prescribes displacement component `component` (0 x, 1 y) of `node` to
 * `value` (model length units). A component already prescribed a
 * different value is refused (TFEM_STATUS_INVALID_ARGUMENT naming the
 * node): one of the two would silently win. Call `tfem_clear_constraints`
 * to change prescribed values.
 */
enum tfem_status tfem_fix(struct tfem_model *model, int node, int comp, double value);

/**
 * Prescribes component `component` to `value` on every node of the
 * boundary edges tagged `tag` (interior edges too). All or nothing: a node
 * already prescribed a different value (see `tfem_fix`) refuses the
 * whole call.
 */
enum tfem_status tfem_fix_edges(struct tfem_model *model, int tag, int comp, double value);

/**
 * Changes the value of displacement component `comp` (0 x, 1 y) of
 * `node`, prescribed before by `tfem_fix` or `tfem_fix_edges`: the loads of
 * a non-proportional load history, which goes on with the same
 * factorisation (the set of prescribed DOFs is unchanged). A node not
 * prescribed in that component is refused, naming it.
 */
enum tfem_status tfem_set_prescribed(struct tfem_model *model, int node, int comp, double value);

/**
 * Changes the value of displacement component `comp` (0 x, 1 y) on every
 * node of the boundary edges tagged `tag`, each prescribed before by
 * `tfem_fix_edges` or `tfem_fix`: `tfem_set_prescribed` for a whole tag,
 * the loads of a load history given as `tfem_fix_edges` gives them (the
 * factorisation is kept). All or nothing: an unknown tag, a value that is
 * not finite or a node not prescribed in that component is refused
 * (TFEM_STATUS_INVALID_ARGUMENT naming it) and the model is unchanged.
 */
enum tfem_status tfem_set_prescribed_edges(struct tfem_model *model,
                                           int tag,
                                           int comp,
                                           double value);

/**
 * Removes every prescribed displacement.
 */
enum tfem_status tfem_clear_constraints(struct tfem_model *model);

/**
 * Declares that the boundary edges tagged `tag` lie on the circle of
 * centre (`center_x`, `center_y`) and radius `radius` (> 0), so that
 * `tfem_solve_adaptive` puts the nodes it adds on those edges on the
 * circle rather than at the chords' midpoints: the refined boundary then
 * converges to the circle (a cylinder's contact, a ring's bore). It
 * replaces a curve declared on the tag before and changes nothing of a
 * solve. Refused, nothing changed, if the circle is ill defined, no edge
 * has the tag, or a node of its edges lies farther than 1e-6·radius from
 * the circle (the message names the node).
 */
enum tfem_status tfem_set_boundary_circle(struct tfem_model *model,
                                          int tag,
                                          double center_x,
                                          double center_y,
                                          double radius);

/**
 * Applies pressure `pressure` on the boundary edges tagged `tag`: a
 * stress (force per unit area, Pa in SI), positive pushing into the body;
 * with the 2D convention of unit thickness, an edge of length ℓ carries
 * the force ℓ·pressure per unit thickness (axisymmetric bodies: the
 * whole ring's, ∫ pressure·2πr ds). Loads add up.
 */
enum tfem_status tfem_add_pressure(struct tfem_model *model, int tag, double pressure);

/**
 * Applies the traction (tx, ty) on the boundary edges tagged `tag`: a
 * stress vector (force per unit area, Pa in SI); an edge of length ℓ
 * carries ℓ·(tx, ty) per unit thickness (axisymmetric bodies: the whole
 * ring's, ∫ (tx, ty)·2πr ds). Loads add up.
 */
enum tfem_status tfem_add_traction(struct tfem_model *model, int tag, double tx, double ty);

/**
 * Adds the point force (fx, fy) at `node`: force per unit thickness (N/m
 * in SI; axisymmetric bodies: the total force on the node's ring, N).
 * Loads add up.
 */
enum tfem_status tfem_add_nodal_force(struct tfem_model *model, int node, double fx, double fy);

/**
 * Sets the body force (bx, by) of body `body`: force per unit volume (ρg,
 * N/m³ in SI), acting on each unit area of the mesh per unit thickness
 * (axisymmetric bodies: on the whole ring's volume).
 */
enum tfem_status tfem_set_body_force(struct tfem_model *model, int body, double bx, double by);

/**
 * Removes every load.
 */
enum tfem_status tfem_clear_loads(struct tfem_model *model);

/****************************************************************************
 * Contact pairs: the interfaces between bodies (declared, or found by
 * tfem_add_contact_pairs_auto), their friction and weighting, and the
 * contact mesh B the strip weighting makes. These are the model's own
 * contact pairs, solved by tfem_solve_contact and tfem_step; a host code
 * with its own elements and solver uses the contact context (tfem_contact_*)
 * at the end of the header instead.
 ***************************************************************************/

/**
 * Declares a potential contact interface between the boundary edges tagged
 * `tag_a` (one body) and `tag_b` (another body). The contact mesh B is
 * built from matching nodes when they match (a small normal gap is
 * allowed), else by triangulating the strip between the two interfaces
 * (each must be one open chain of edges). Writes the pair's index
 * (0-based) to `pair` (may be NULL). A pair declared already, or one
 * whose tags share boundary edges with both tags of a declared pair (the
 * same interface under other tags, which would count twice), is refused
 * with TFEM_STATUS_INVALID_CONTACT.
 */
enum tfem_status tfem_add_contact_pair(struct tfem_model *model, int tag_a, int tag_b, int *pair);

/**
 * Declares a contact pair with a user-made contact mesh B: `n_triangles`
 * triangles in `connectivity` (3 per triangle) over nodes of the two
 * interfaces. Wrongly oriented triangles are flipped; their number goes to
 * `flipped` (may be NULL), the pair's index to `pair` (may be NULL). A
 * triangle given twice (the same three nodes, in any order) is refused
 * with TFEM_STATUS_INVALID_CONTACT naming both triangles. The triangles
 * are the contact: a pair of tags declared already, or sharing edges with
 * a declared pair, is not refused here (several meshes may cover parts of
 * one interface), so do not give a part twice.
 */
enum tfem_status tfem_add_contact_pair_with_mesh(struct tfem_model *model,
                                                 int tag_a,
                                                 int tag_b,
                                                 int n_triangles,
                                                 const int *connectivity,
                                                 int *pair,
                                                 int *flipped);

/**
 * Declares a contact pair for every two boundary tags of different bodies
 * whose edges face each other within `tolerance` (model length units: some
 * edge of the one within `tolerance` of some edge of the other, outward
 * normals opposed within 30°, each in front of the other, overlapping
 * along the interface, no third body between them; a gap of exactly
 * `tolerance` pairs; docs/method.md §6.16). `tags` (`n_tags` values) restricts the search to
 * those tags; with `n_tags` = 0 every tag that can be a contact side is
 * considered, and `tags` may be NULL. Pairs already declared are skipped,
 * tags of one body never pair, and an interface found again under tags
 * that share its edges with a pair kept (a "whole boundary" group beside
 * the faces) is skipped: the pair of tags with the fewest edges is kept
 * (to pair an interface under other tags, declare that pair by hand
 * instead). What is left out without an error — with `n_tags` = 0, a tag
 * whose edges bound several bodies; an interface found again under other
 * tags — is named in a warning (`tfem_warning_count`, `tfem_get_warning`).
 * The pairs added get consecutive indices:
 * writes the first to `first` (may be NULL) and their number, 0 when
 * nothing faces within the tolerance, to `count` (may be NULL). A negative
 * or non-finite tolerance, an unknown tag or an interface whose contact
 * mesh cannot be built is refused, naming it, and nothing is added.
 */
enum tfem_status tfem_add_contact_pairs_auto(struct tfem_model *model,
                                             int n_tags,
                                             const int *tags,
                                             double tolerance,
                                             int *first,
                                             int *count);

/**
 * Sets Coulomb's friction coefficient μ ≥ 0 of contact pair `pair`
 * (0-based, from `tfem_add_contact_pair`): stick while the shear stays
 * within μ times the pressure, slip against the slip of the step beyond
 * (docs/method.md §6.15). 0, the default, is frictionless, bit for bit.
 * A negative or non-finite μ, or an unknown pair, is refused
 * (TFEM_STATUS_INVALID_ARGUMENT naming it). Changing μ starts a new load
 * history. Frictional or not, the elements of a pair's contact mesh
 * measure every point of the interface along the first side's normal
 * there, so that a frictionless interface transmits no tangential
 * traction.
 */
enum tfem_status tfem_set_friction(struct tfem_model *model, int pair, double mu);

/**
 * Chooses how the contact pairs' energy is weighted along their
 * interfaces: `weighting` is a `ContactWeightingMode`. 2 automatic, the
 * default: each pair what is right for it — the elements of the contact
 * mesh B (the seed's method) where the two sides' nodes match, one
 * weighted gap per node of the interface's coarser side where they do not
 * (exact on the contact patch test whatever the meshes, converging on
 * curved interfaces where B reads one side only), B for a pair with
 * friction or a contact mesh of its own. 0 strip and 1 mortar force one
 * weighting on every pair (an expert's override). A change discards the
 * results, like any change of the contact pairs. The mortar weighting is
 * frictionless and makes no mesh B: forcing it with a pair that has
 * friction or a contact mesh of its own, or giving such a pair under it,
 * is refused by that call (TFEM_ERR_ARGUMENT, naming the pair); a solve
 * under it with the stick law or the literal inversion test is refused
 * too. The per-element outputs (`tfem_get_contact_active`,
 * `tfem_get_contact_pressure`, `tfem_get_contact_elements`, shear,
 * friction state, dissipation; `tfem_get_sizes`' contact elements) cover
 * the pairs weighted by B, and are refused when no pair is
 * (`tfem_get_contact_mesh` still gives the B the pairs would make); the
 * state of the others is per slave node (`tfem_get_contact_slave_nodes`).
 * Nodal pressures, gaps and forces, reactions and the report cover every
 * pair, the report's `elements` counting elements of B and slave nodes.
 */
enum tfem_status tfem_set_contact_weighting(struct tfem_model *model, int weighting);

/**
 * Writes the contact weighting (a `ContactWeightingMode`: 0 strip, 1
 * mortar, 2 automatic, the default) into `*weighting`.
 */
enum tfem_status tfem_get_contact_weighting(struct tfem_model *model, int *weighting);

/**
 * Writes the number of elements of the contact mesh B of the declared
 * contact pairs, available before any solve (0 without pairs).
 */
enum tfem_status tfem_get_contact_mesh_size(struct tfem_model *model, int *n_elements);

/**
 * Copies the nodes of every element of the contact mesh B of the declared
 * contact pairs (3 per element, in the model's index base, oriented so
 * that J > 0 when the gap opens), available before any solve: the same
 * elements, in the same order, as `tfem_get_contact_elements` gives after
 * a contact solve.
 */
enum tfem_status tfem_get_contact_mesh(struct tfem_model *model, int *out, size_t length);

/**
 * Copies, for every element of the contact mesh B (see
 * `tfem_get_contact_mesh`), the index of its contact pair (0-based, as
 * returned by `tfem_add_contact_pair`, whatever the index base).
 */
enum tfem_status tfem_get_contact_element_pairs(struct tfem_model *model, int *out, size_t length);

/**
 * Copies, for every element of the contact mesh B (see
 * `tfem_get_contact_mesh`), its apex: the node (in the model's index
 * base) alone on its side of the interface, whose distance from the
 * element's interface edge is the element's gap.
 */
enum tfem_status tfem_get_contact_element_apexes(struct tfem_model *model, int *out, size_t length);

/**
 * Writes the bodies of contact pair `pair` (0-based, as returned by
 * `tfem_add_contact_pair`): `body_a` carries the pair's first tag,
 * `body_b` its second. Either pointer may be NULL.
 */
enum tfem_status tfem_get_contact_pair_bodies(struct tfem_model *model,
                                              int pair,
                                              int *body_a,
                                              int *body_b);

/****************************************************************************
 * Solve: without contact (tfem_solve) or with it (tfem_solve_contact, one
 * load; tfem_step for a load history, below).
 ***************************************************************************/

/**
 * Fills `options` with the defaults: frictionless law, E_c and λ derived
 * from the model, linearised inversion test, 50 iterations.
 */
enum tfem_status tfem_contact_options_default(struct tfem_contact_options *options);

/**
 * Solves a scene without contact. `info` may be NULL. A body that is not
 * restrained gives TFEM_STATUS_SINGULAR naming it. A model with every
 * DOF prescribed has nothing to solve: TFEM_STATUS_INVALID_STATE; so also
 * `tfem_solve_contact` and `tfem_step`.
 */
enum tfem_status tfem_solve(struct tfem_model *model, struct tfem_solve_info *info);

/**
 * Solves the contact problem by the active-set loop over inverted contact
 * elements (under the mortar weighting, `tfem_set_contact_weighting`, over
 * the slave nodes whose weighted gap is negative). `options` may be NULL (defaults); `report` may be NULL.
 * TFEM_STATUS_NOT_CONVERGED (cycle or iteration cap) gives the history in
 * the message; the model is then unchanged. Every DOF prescribed:
 * TFEM_STATUS_INVALID_STATE.
 */
enum tfem_status tfem_solve_contact(struct tfem_model *model,
                                    const struct tfem_contact_options *options,
                                    struct tfem_contact_report *report);

/**
 * Solves to a tolerance (docs/method.md §8): solve (a contact solve with
 * the `contact` options when the model has pairs),
 * estimate the error by stress recovery, refine the triangles holding
 * half of it by newest-vertex bisection, and again, until the estimated
 * relative error of `goal` (an `AdaptGoal`: 0 energy norm, 1 compliance)
 * is at most `tolerance` (> 0) — and, with contact, the edges of the
 * contact zones are located to `tolerance` of the contact length (the
 * interface edges pressed at one end only refined until shorter) — or
 * the next mesh would exceed
 * `max_unknowns`, or `max_cycles` solves are done (either is a warning
 * with the estimate reached, `tfem_get_warning`, and TFEM_STATUS_OK).
 * The model keeps the refined mesh — the given nodes keep their indices,
 * new ones follow; read it back with `tfem_get_sizes`,
 * `tfem_get_mesh_nodes`, `tfem_get_mesh_triangles` and
 * `tfem_get_boundary_edges` — its loads, constraints and pairs carried
 * over, and the last solve's results. New nodes on edges whose tag has
 * a circle (`tfem_set_boundary_circle`) go on the circle, and a curved
 * interface's facing edges are bisected together. `contact` may be NULL (the default
 * options); `report` may be NULL. Bad arguments change nothing; a failed
 * solve restores the model as it was given.
 */
enum tfem_status tfem_solve_adaptive(struct tfem_model *model,
                                     double tolerance,
                                     int goal,
                                     int64_t max_unknowns,
                                     int max_cycles,
                                     const struct tfem_contact_options *contact,
                                     struct tfem_adapt_report *report);

/**
 * Copies each cycle of the last successful `tfem_solve_adaptive`
 * (`cycles` of its report): its unknowns, its estimated relative error and its seconds
 * (solve and estimate), into arrays of `length` values each: `unknowns`
 * may be NULL, `estimates` may be NULL, `seconds` may be NULL. Nothing is
 * written unless `length` holds every cycle.
 */
enum tfem_status tfem_get_adapt_cycles(struct tfem_model *model,
                                       int64_t *unknowns,
                                       double *estimates,
                                       double *seconds,
                                       size_t length);

/****************************************************************************
 * Results of the last solve or step: displacements, strains, stresses,
 * reactions, external work, and the VTU file.
 ***************************************************************************/

/**
 * Copies the nodal displacements (u0 v0 u1 v1 …, 2·n_nodes values) of the
 * last solve into `out` of `length` values.
 */
enum tfem_status tfem_get_displacements(struct tfem_model *model, double *out, size_t length);

/**
 * Copies element strains (ε_xx ε_yy γ_xy per triangle, engineering shear,
 * 3·n_triangles values), computed on request.
 */
enum tfem_status tfem_get_element_strains(struct tfem_model *model, double *out, size_t length);

/**
 * Copies element stresses (σ_xx σ_yy σ_xy per triangle, 3·n_triangles
 * values; force per unit area, Pa in SI), computed on request. An
 * overflow gives TFEM_STATUS_NUMERICAL_FAILURE naming the triangle.
 */
enum tfem_status tfem_get_element_stresses(struct tfem_model *model, double *out, size_t length);

/**
 * Copies each triangle's stress normal to the mesh's plane (n_triangles
 * values), computed on request: the hoop stress σ_θθ of axisymmetric
 * bodies, σ_zz = λ(ε_xx + ε_yy) in plane strain, 0 in plane stress.
 */
enum tfem_status tfem_get_element_out_of_plane_stresses(struct tfem_model *model,
                                                        double *out,
                                                        size_t length);

/**
 * Copies J (twice the signed area, initial configuration) of every
 * triangle as stored, that is after the turning of triangles numbered
 * clockwise (see `tfem_set_mesh`): negative only for the mesh's folds
 * (n_triangles values). Needs only a mesh.
 */
enum tfem_status tfem_get_element_jacobians(struct tfem_model *model, double *out, size_t length);

/**
 * Copies reaction forces (Rx Ry per node, 2·n_nodes values; force per
 * unit thickness, N/m in SI; zero at DOFs that are not prescribed),
 * computed on request. `tfem_solve` and `tfem_solve_contact` bound their
 * rounding per body and warn (`tfem_get_warning`), naming the body, where
 * its reactions may carry fewer than six correct digits (a "rigid" body
 * given a huge Young's modulus: prescribe its motion with a modulus like
 * its neighbours' instead).
 */
enum tfem_status tfem_get_reactions(struct tfem_model *model, double *out, size_t length);

/**
 * Writes the work of the external loads of the last solve, Σ f·u over
 * every node (force × length per unit thickness, J/m in SI; axisymmetric
 * bodies: the whole ring's, J): for a pressure load, the compliance
 * ∫ p (−u·n) ds.
 */
enum tfem_status tfem_get_external_work(struct tfem_model *model, double *work);

/**
 * Writes the solved model to the file `path` (NUL-terminated; on Unix any
 * bytes, as for `tfem_load_gmsh`) as a VTK XML unstructured grid (`.vtu`,
 * read by ParaView, VTK and meshio; binary: raw appended data,
 * little-endian, UInt64 block headers, no compression):
 * the mesh in its initial configuration (z = 0) with
 * - point data `displacement` ([u, v, 0]) and, after a contact solve or
 *   load step under either weighting, `contact_pressure` (the nodal
 *   pressure of `tfem_get_contact_nodal_pressures`), `contact_shear`
 *   (the nodal shear of `tfem_get_contact_nodal_tractions`),
 *   `contact_force` ([f_x, f_y, 0], `tfem_get_contact_forces`) and
 *   `contact_gap` (`tfem_get_contact_gaps`); none of them after a solve
 *   without contact;
 * - cell data `body` (the body tag), `J` (twice the signed area), `strain`
 *   [ε_xx, ε_yy, γ_xy] and `stress` [σ_xx, σ_yy, σ_xy];
 * - for the pairs weighted by B, its elements
 *   appended after the body triangles as cells of body −1 (zero strain
 *   and stress), with cell data `contact_element_active` (UInt8, 1 where
 *   active) and `contact_element_pressure` (`tfem_get_contact_active`,
 *   `tfem_get_contact_pressure`; 0 on the body triangles). Pairs under
 *   the mortar weighting have no B: their contact is in the nodal arrays.
 *
 * (Earlier versions named the last two `contact_active` and
 * `contact_pressure`, wrote them as zeros under the mortar weighting,
 * and wrote no nodal contact array.)
 * Returns TFEM_STATUS_INVALID_STATE before a solve (nothing is written),
 * TFEM_STATUS_IO when the file cannot be written (the message names it
 * and the reason), TFEM_STATUS_INVALID_ARGUMENT if the library was built
 * without the `vtu` feature, and TFEM_STATUS_NUMERICAL_FAILURE (nothing
 * is written) when a result it holds cannot be computed as the accessors
 * would refuse it: an overflowing stress, or a load step's field that
 * cannot be recovered to working accuracy, named in the message. The
 * model is never changed.
 */
enum tfem_status tfem_write_vtu(struct tfem_model *model, const char *path);

/****************************************************************************
 * Contact results of the last solve or step. Per node, for every pair:
 * forces, pressures and tractions, gaps. Per element of the contact mesh B
 * (tfem_get_contact_active ... dissipation; pairs weighted by B): element
 * values at each element's apex. Per slave node (pairs under the mortar
 * weighting): tfem_get_contact_slave_nodes.
 ***************************************************************************/

/**
 * Writes the report of the last contact solve to `report`.
 */
enum tfem_status tfem_get_contact_report(struct tfem_model *model,
                                         struct tfem_contact_report *report);

/**
 * Copies the force the contact exerts on every node in the last contact
 * solve (fx fy per node, 2·n_nodes values; force per unit thickness, N/m
 * in SI, or the whole ring's for axisymmetric bodies; zero off the
 * contact interfaces), computed on request. The
 * forces of one pair sum to zero; on a body they balance its loads and
 * reactions.
 */
enum tfem_status tfem_get_contact_forces(struct tfem_model *model, double *out, size_t length);

/**
 * Copies the contact pressure at every node in the last contact solve
 * (n_nodes values; force per unit area, Pa in SI, positive in compression;
 * zero off the contact interfaces), computed on request: the traction
 * read from both sides of the interface (the mean of a node's normal
 * contact force over its tributary — the integral of its hat over its
 * interface edges as far as they face the other side, half its edges
 * where they face it whole — and the other side's forces over their
 * tributaries near it); where the other side is more than 1.8 times
 * coarser, a node takes the other side's reading there, interpolated
 * (the coarser side's reading is the closer to the traction), blended
 * with its own from 1.2 times. Exact for a
 * uniform pressure on matching and non-matching interfaces alike. Each
 * pair is read with its own forces; a node on several pairs (where three
 * bodies meet) gets their normal
 * forces over their tributaries together: the pressure where two pairs
 * continue one face, the tributary-weighted mean of its faces' pressures
 * at a corner.
 */
enum tfem_status tfem_get_contact_nodal_pressures(struct tfem_model *model,
                                                  double *out,
                                                  size_t length);

/**
 * Copies the contact traction at every node in the last contact solve or
 * step, as (p, τ) per node (2·n_nodes values; force per unit area, Pa in
 * SI; zero off the contact interfaces), computed on request. p is the
 * pressure of `tfem_get_contact_nodal_pressures`, positive in
 * compression. τ is the tangential traction the other body exerts on the
 * node's body, along t = (−n_y, n_x) with n the body's outward normal
 * (the direction of travel along a counter-clockwise boundary), so that
 * both sides of an interface read one traction with one sign; the vector
 * traction on the node's body is τ t − p n. Each part is the contact
 * law's own, read along the normal the contact mesh measures the point
 * along (one per point of the interface: its first side's): a
 * frictionless interface reads τ = 0 to round-off, curved or not, and a
 * frictional one its Coulomb shear. Pairs under the mortar weighting
 * (frictionless) read τ = 0. Before a contact solve, or after a change,
 * there are no results (TFEM_STATUS_INVALID_STATE).
 */
enum tfem_status tfem_get_contact_nodal_tractions(struct tfem_model *model,
                                                  double *out,
                                                  size_t length);

/**
 * Copies the contact pressure of contact pair `pair` (0-based, from
 * `tfem_add_contact_pair` or `tfem_add_contact_pairs_auto`) alone at every
 * node in the last contact solve (n_nodes values, as
 * `tfem_get_contact_nodal_pressures`; zero off that pair's contact
 * mesh), computed on request from that pair's forces over that pair's
 * tributaries: a node where three bodies meet reads each face on its own
 * (at a block's corner, the bed's pressure on the bed pair and the head
 * joint's on the head pair), where `tfem_get_contact_nodal_pressures`
 * gives their tributary-weighted mean. As there, where one side ends
 * inside an edge of the other, the first node of the other side past
 * that end reads the other side's pressure near that end.
 * An unknown pair is refused (TFEM_STATUS_INVALID_ARGUMENT naming it);
 * before a contact solve, or after a change (declaring a pair is one),
 * there are no results (TFEM_STATUS_INVALID_STATE).
 */
enum tfem_status tfem_get_contact_pair_nodal_pressures(struct tfem_model *model,
                                                       int pair,
                                                       double *out,
                                                       size_t length);

/**
 * `tfem_get_contact_nodal_tractions` of contact pair `pair` (0-based)
 * alone, read over that pair's forces and tributaries as
 * `tfem_get_contact_pair_nodal_pressures` reads its pressures (2·n_nodes
 * values). An unknown pair is refused (TFEM_STATUS_INVALID_ARGUMENT
 * naming it).
 */
enum tfem_status tfem_get_contact_pair_nodal_tractions(struct tfem_model *model,
                                                       int pair,
                                                       double *out,
                                                       size_t length);

/**
 * Copies the normal gap at every node in the last contact solve
 * (n_nodes values, model length units; zero off the contact interfaces),
 * computed on request: the smallest, over the contact elements at the
 * node, of the distance of an element's apex from its interface edge in
 * the deformed configuration (linearised). Positive: open; negative: the
 * bodies interpenetrate (by O(h²), the penalty of the contact elements).
 */
enum tfem_status tfem_get_contact_gaps(struct tfem_model *model, double *out, size_t length);

/**
 * Copies the active flag (1 active, 0 not) of every contact element of
 * the last contact solve (n_contact_elements values, see `tfem_get_sizes`).
 */
enum tfem_status tfem_get_contact_active(struct tfem_model *model, int *out, size_t length);

/**
 * Copies the contact pressure of every contact element (n_contact_elements
 * values): the normal stress −n·σ·n in the element (force per unit area,
 * Pa in SI), positive in compression, 0 when inactive. It is the
 * traction at the element's apex (the interface point it measures:
 * on matching meshes the apex node), times the share of its edge that
 * faces the other side; each point is measured by two elements, one
 * with its edge on either side. For the traction at the interface
 * nodes, read `tfem_get_contact_nodal_tractions` (on a non-matching
 * interface one family's element values read up to twice the traction).
 */
enum tfem_status tfem_get_contact_pressure(struct tfem_model *model, double *out, size_t length);

/**
 * Copies the nodes of every contact element (3·n_contact_elements
 * indices, in the model's index base), oriented so that J > 0 when the gap
 * opens. Refused (TFEM_STATUS_INVALID_STATE) after a solve under
 * the mortar weighting, which uses no B.
 */
enum tfem_status tfem_get_contact_elements(struct tfem_model *model, int *out, size_t length);

/**
 * Copies the shear traction τ = n·σ·t (Pa in SI; t = (−n_y, n_x), n the
 * element's normal, see `tfem_get_contact_mesh`) of every contact element
 * of the last contact solve or step (n_contact_elements values): 0 when
 * open, |τ| ≤ μp when sticking, μp when slipping; all 0 when frictionless.
 * An element value at its apex, as `tfem_get_contact_pressure`; the
 * shear at the interface nodes is `tfem_get_contact_nodal_tractions`'.
 */
enum tfem_status tfem_get_contact_shear(struct tfem_model *model, double *out, size_t length);

/**
 * Copies the frictional state of every contact element of the last
 * contact solve or step (n_contact_elements values): 0 open, 1 stick,
 * 2 slip (a frictionless solve: 2 where active).
 */
enum tfem_status tfem_get_contact_friction_state(struct tfem_model *model, int *out, size_t length);

/**
 * Copies the energy dissipated by slip in the last step (or solve) at
 * every contact element (n_contact_elements values, J per unit thickness
 * in SI; for axisymmetric bodies per unit length of the element's ring,
 * 2πr̄ times less than the whole ring's): ½ τ Δγ_p ≥ 0; all 0 when frictionless.
 */
enum tfem_status tfem_get_contact_dissipation(struct tfem_model *model, double *out, size_t length);

/**
 * Copies the state of every slave node after a contact solve under the
 * mortar weighting, n = the report's `elements`, in the order of the
 * pairs: `node` (n values: the slave node, in the model's index base),
 * `tributary` (n values: m_i, the length its hat covers where it faces
 * the other side), `gap` (n values: the mean gap G_i/m_i, negative where
 * the bodies overlap) and `pressure` (n values: −κG_i/m_i, positive in
 * compression, 0 when inactive; an active node whose weighted gap is at
 * the round-off of the displacements, as where the bodies touch without
 * load, can read a pressure of that round-off of either sign). Any pointer may be NULL (that column is
 * not written); `length` (>= n) is the size of each buffer given. Refused
 * after a solve under the strip weighting.
 */
enum tfem_status tfem_get_contact_slave_nodes(struct tfem_model *model,
                                              int *node,
                                              double *tributary,
                                              double *gap,
                                              double *pressure,
                                              size_t length);

/****************************************************************************
 * Load history: steps on one factorisation, revert, and the contact state
 * saved and restored (restarts).
 ***************************************************************************/

/**
 * One quasi-static load step: the contact problem with the loads and
 * prescribed displacements as set, scaled by `load_factor`, warm-started
 * from the contact state of the last step (the initial set of a contact
 * solve for the first, or a state given by `tfem_set_contact_state`).
 * One factorisation serves every step while the stiffness (mesh,
 * constraints, materials, tempering, contact pairs) and the contact
 * options (`options` may be NULL: defaults; `max_iterations` may change)
 * are unchanged: a step is dense work on the contact interface, plus one
 * sparse solve when the loads changed since the last step (a
 * non-proportional history). Its displacements, and everything computed
 * from them, are recovered on first request (one sparse solve, or, where
 * that cannot reach working accuracy on a very non-matching interface, a
 * factorisation of the step's own matrix, made and dropped at that
 * request); the system matrix of a step is not available. The step is
 * accepted as it is: `tfem_revert_step` undoes it. `report` may be NULL.
 * Where the contact interface is not condensed (options with
 * `refactorize` set, an interface too large to condense — see
 * `TfemContactOptions` —, or a contact that couples no free unknown)
 * each step is a contact solve of its scaled loads started from the state
 * of the step before. A warm start that leads nowhere (a body left free:
 * unloading to zero from a loaded set passes through no contact at all;
 * a cycle) is tried again from the initial set of the step's own loads.
 * `load_factor` must be finite, at most 1e300 in magnitude, and a step
 * whose field would overflow is refused (TFEM_STATUS_NUMERICAL_FAILURE).
 * On error the model is unchanged. A frictional history goes on from the
 * slip state it reached across a change of materials, options or
 * prescribed DOFs between steps (with friction the answer depends on the
 * path). Every DOF prescribed: TFEM_STATUS_INVALID_STATE. Under the
 * mortar weighting (`tfem_set_contact_weighting`, frictionless) a step is
 * the same history over the slave nodes' weighted gaps.
 */
enum tfem_status tfem_step(struct tfem_model *model,
                           double load_factor,
                           const struct tfem_contact_options *options,
                           struct tfem_contact_report *report);

/**
 * Undoes the last load step: its results, and the contact state the next
 * step starts from, go back to what they were before it. Once per step.
 * Refused with TFEM_STATUS_INVALID_STATE, the model unchanged, once the
 * mesh, its boundary edges, the contact pairs, friction on/off or the
 * contact weighting have changed since that step: they remake the
 * contact mesh, and its contact state belongs to the one before; the
 * message names the change. Fixing
 * or clearing prescribed DOFs does not block it: like new materials, it
 * changes the stiffness, not the contact mesh. The state brought back is
 * the next step's start even if that step starts a new history (new
 * materials, options or prescribed DOFs), with that problem's own
 * interface factor.
 */
enum tfem_status tfem_revert_step(struct tfem_model *model);

/**
 * Writes to `size` the number of bytes of the contact state of the last
 * load step (see `tfem_get_contact_state`).
 */
enum tfem_status tfem_get_contact_state_size(struct tfem_model *model, size_t *size);

/**
 * Copies the contact state of the last load step into `buffer` (`length`
 * bytes, at least `tfem_get_contact_state_size`): the active set and the
 * factor of the condensed interface system, so that
 * `tfem_set_contact_state` continues the history bit for bit (a restart,
 * in this model or another one holding the same problem). Under the mortar
 * weighting the set is the slave nodes'.
 */
enum tfem_status tfem_get_contact_state(struct tfem_model *model, uint8_t *buffer, size_t length);

/**
 * Continues the load history from a contact state (`length` bytes from
 * `tfem_get_contact_state`): the next `tfem_step` starts from it. Refused,
 * naming why, if the bytes are not such a state, belong to another
 * contact mesh, or are frictional where no pair has friction; the model
 * is then unchanged. From a history of the same problem (the same
 * geometry, materials, constraints and options) the steps go on bit for
 * bit; from one whose interface system differs (the same contact mesh,
 * another shape or stiffness), from its active set and slip state, with
 * the interface factor of this problem; so also when the next step
 * starts a new history (new materials, options or prescribed DOFs). If
 * the mesh, its boundary edges, the pairs or friction on/off change
 * before the next step (they remake the contact mesh), that step starts
 * afresh and warns; a change of the prescribed DOFs keeps it. A
 * frictional state waiting for a step under the stick law is refused by
 * that step (TFEM_STATUS_INVALID_ARGUMENT) until another state is set.
 */
enum tfem_status tfem_set_contact_state(struct tfem_model *model,
                                        const uint8_t *buffer,
                                        size_t length);

/****************************************************************************
 * Utilities: the assembled system matrix, and element stiffness matrices for
 * codes that assemble their own.
 ***************************************************************************/

/**
 * Sizes of the stiffness matrix of the last solve (see
 * `tfem_get_system_matrix`): `n` unknowns and `nnz` stored entries of its
 * upper triangle. Either pointer may be NULL.
 */
enum tfem_status tfem_get_system_matrix_size(struct tfem_model *model, int64_t *n, int64_t *nnz);

/**
 * Copies the stiffness matrix K of the last solve on its unknowns (the
 * DOFs left after Dirichlet elimination), the system K u = f whose
 * solution `tfem_get_displacements` returns; for a contact solve it holds
 * the contact elements active at convergence. Upper triangle in
 * compressed sparse columns, rows ascending within each column:
 * `col_ptr` (n + 1 values), `row_idx` and `values` (nnz values each),
 * indices in the model's index base (`col_ptr[0]` = base). `dofs` (n
 * values) gives each unknown's position in the array of
 * `tfem_get_displacements`, in the index base (2·node + component for
 * base 0). Every buffer is checked before any is written. Like every
 * result it outlives a failed solve (which rebuilds it bit for bit) and
 * is discarded by a change of the problem (TFEM_STATUS_INVALID_STATE).
 */
enum tfem_status tfem_get_system_matrix(struct tfem_model *model,
                                        int64_t *col_ptr,
                                        size_t col_ptr_length,
                                        int64_t *row_idx,
                                        size_t row_idx_length,
                                        double *values,
                                        size_t values_length,
                                        int64_t *dofs,
                                        size_t dofs_length);

/**
 * Tempered elasticity stiffness of one P1 triangle with corners `xy`
 * (x1 y1 x2 y2 x3 y3): K = B̂ᵀ D B̂ / (2·max(J, jmin)), written row-major
 * into `out` (36 values, DOFs u1 v1 u2 v2 u3 v3). For
 * `TFEM_PLANE_MODE_AXISYMMETRIC` (x the radius, corners with x ≥ 0) the
 * whole ring's K = 2πx̄ (B̂ + J H)ᵀ D₄ (B̂ + J H) / (2·max(J, jmin)), H
 * the hoop row 1/(3x̄) on each u_r (docs/method.md §7). `jmin` > 0
 * tempers; `jmin` = 0 is plain FEM (divides by |J|, fails for J = 0).
 * Pure and thread-safe; errors go to the thread's `tfem_last_error(NULL,
 * …)`.
 */
enum tfem_status tfem_element_stiffness(const double *xy,
                                        double young,
                                        double poisson,
                                        int plane_mode,
                                        double jmin,
                                        double *out);

/**
 * Tempered Laplacian stiffness of one P1 triangle: K_ij = κ g_i·g_j /
 * (2·max(J, jmin)), row-major into `out` (9 values). `jmin` as in
 * `tfem_element_stiffness`. Pure and thread-safe.
 */
enum tfem_status tfem_laplacian_stiffness(const double *xy, double kappa, double jmin, double *out);

/****************************************************************************
 * Contact for host codes (tfem_contact_*): a contact context for a code that
 * keeps its own elements and solver. It takes the host's nodes,
 * displacements and contact sides, and gives back the contact's stiffness
 * and forces to add to the host's system, and the contact state per element
 * of B (tfem_contact_get_active, tfem_contact_pressures; not the model's
 * tfem_get_contact_*).
 ***************************************************************************/

/**
 * Creates a contact context for a host code that keeps its own elements,
 * assembly, solver and Newton loop: node numbers and equation numbers in
 * `index_base` (0 for C, 1 for Fortran). Returns NULL if `index_base` is
 * not 0 or 1 (message in `tfem_last_error(NULL, …)`) or memory is
 * exhausted. The host then adds the sides of its contact interfaces
 * (`tfem_contact_add_side`) and the pairs (`tfem_contact_add_pair`); the
 * first call that needs the contact mesh B builds it, after which sides
 * and pairs are fixed.
 */
struct tfem_contact *tfem_contact_create(int index_base);

/**
 * Destroys a contact context. NULL is a no-op, and so is a pointer that
 * is not a live context (destroyed already, or a model).
 */
void tfem_contact_destroy(struct tfem_contact *context);

/**
 * Copies the message of the last failed call on `context` (empty after a
 * successful call) into `buffer` (`length` bytes including the final NUL),
 * truncating like `tfem_last_error`. A `context` that is not a live
 * contact context gives TFEM_STATUS_INVALID_ARGUMENT with the message
 * saying so in `buffer`.
 */
enum tfem_status tfem_contact_last_error(const struct tfem_contact *context,
                                         char *buffer,
                                         size_t length);

/**
 * Size in bytes (including the final NUL) of the message
 * `tfem_contact_last_error` would give for `context` (a buffer of this
 * size holds all of it): 1 after a successful call; for a handle that is
 * not a live contact context (destroyed, or a model), the size of the
 * message saying so. `context` may be NULL: 1 (it has no message).
 */
size_t tfem_contact_last_error_length(const struct tfem_contact *context);

/**
 * Sets the contact options (law, E_c, λ, inversion test, and
 * `max_iterations`: the number of `tfem_contact_update` calls of one loop
 * before it counts as not converged; `refactorize` is ignored). Only
 * before the contact mesh is built. Defaults: `tfem_contact_options_default`,
 * with λ the larger side of the interface nodes' bounding box.
 */
enum tfem_status tfem_contact_set_options(struct tfem_contact *context,
                                          const struct tfem_contact_options *options);

/**
 * Adds one side of a contact interface, of body `body` (Young's modulus
 * `young`, Poisson ratio `poisson`, `plane_mode` a `PlaneMode`: the
 * softer side's E is the default E_c, the stick law takes its ν):
 * `n_nodes` interface nodes `nodes` (the host's node numbers) with their
 * coordinates `xy` (2 per node) and the equations of their x and y
 * unknowns `equations` (2 per node, in the index base; a value below the
 * base marks a fixed DOF without an equation), and `n_edges` edges
 * `edges` (2 host node numbers each), each given with its body on its
 * left (the counter-clockwise boundary orientation); an edge that runs
 * against its neighbour is refused (TFEM_STATUS_INVALID_CONTACT, naming
 * it). A node of two sides must come with the same coordinates and
 * equations. A node number below the index base is refused
 * (TFEM_STATUS_INVALID_ARGUMENT naming the side, the node's entry and the
 * number), and so is an equation that no host vector can hold (from
 * index_base + PTRDIFF_MAX / 8 on: no array of doubles spans more bytes),
 * naming the node and the equation. The host's system size is not known
 * here: `tfem_contact_gather` and `tfem_contact_scatter_add` check every
 * equation against the vector they are given. Writes the side's
 * index (0-based) to `side` (may be NULL). On error nothing changes.
 */
enum tfem_status tfem_contact_add_side(struct tfem_contact *context,
                                       int tag,
                                       int body,
                                       double young,
                                       double poisson,
                                       int plane_mode,
                                       int n_nodes,
                                       const int *nodes,
                                       const double *xy,
                                       const int64_t *equations,
                                       int n_edges,
                                       const int *edges,
                                       int *side);

/**
 * Declares sides `side_a` and `side_b` (on different bodies) a contact
 * pair: the contact mesh B is built from their matching nodes, or by
 * triangulating the strip between them. Two sides whose outward normals
 * point the same way (one of them given clockwise) are refused with
 * TFEM_STATUS_INVALID_CONTACT naming both. A pair of two sides already
 * paired (either way round) is refused with TFEM_STATUS_INVALID_CONTACT
 * naming it: it would double their contact. Messages name a side by its
 * index and tag ("side 0 (tag 101)") and nodes by the host's numbers.
 * Writes the pair's index (0-based) to `pair` (may be NULL).
 */
enum tfem_status tfem_contact_add_pair(struct tfem_contact *context,
                                       int side_a,
                                       int side_b,
                                       int *pair);

/**
 * Declares a pair with the host's own contact mesh B: `n_triangles`
 * triangles `connectivity` (3 host node numbers each) over the interface
 * nodes of the two sides; wrongly oriented ones are turned. A triangle
 * given twice (the same three nodes) is refused
 * (TFEM_STATUS_INVALID_CONTACT naming both triangles), and so is a pair
 * already declared, as by `tfem_contact_add_pair`. A node number below
 * the index base is refused (TFEM_STATUS_INVALID_ARGUMENT naming the
 * pair, the triangle, the node's place in it and the number). Writes the pair's
 * index (0-based) to `pair` (may be NULL).
 */
enum tfem_status tfem_contact_add_pair_with_mesh(struct tfem_contact *context,
                                                 int side_a,
                                                 int side_b,
                                                 int n_triangles,
                                                 const int *connectivity,
                                                 int *pair);

/**
 * Builds the contact mesh B (if not yet) and writes the sizes: interface
 * nodes (the length of every per-node array: 2 values per node for
 * displacements and residuals), elements of B, and entries of the
 * pattern. Any pointer may be NULL.
 */
enum tfem_status tfem_contact_sizes(struct tfem_contact *context,
                                    int *n_nodes,
                                    int *n_elements,
                                    int64_t *n_entries);

/**
 * Copies the interface nodes (host numbers, n_nodes values), in the
 * order of every per-node array.
 */
enum tfem_status tfem_contact_nodes(struct tfem_contact *context, int *out, size_t length);

/**
 * Copies the fixed pattern of the contact contributions into `rows`
 * (n_entries values) and `cols` (n_entries values), in the host's
 * equation numbering and index base: element
 * after element of B, each element's 6×6 block row by row over its DOFs
 * (x then y of its first, second and third node), the DOFs without an
 * equation left out; both triangles of each block. Entries repeat where
 * elements share a DOF pair: the host sums them.
 */
enum tfem_status tfem_contact_pattern(struct tfem_contact *context,
                                      int64_t *rows,
                                      int64_t *cols,
                                      size_t length);

/**
 * The contact contributions at the displacements `u` of the interface
 * nodes (2 per node, `u_length` = 2·n_nodes): the tangent's values in the
 * pattern's order into `values` (n_entries values, zeros for inactive
 * elements), and the contact residual Σ (K_e u_e − f0_e) of the active
 * elements, 2 per interface node, into `residual`. `values` may be NULL;
 * `residual` may be NULL. A linear host adds the values to its matrix and minus the
 * residual at u = 0 (the load of initial gaps) to its right-hand side; a
 * Newton host adds the values to its tangent and the residual at its
 * current u to its residual. The contact law is linear in u for a given
 * active set: the values depend on the active set only, not on `u`, and
 * change only when `tfem_contact_update` or `tfem_contact_set_active`
 * changes the set. A non-finite value in `u` is refused
 * (TFEM_STATUS_INVALID_ARGUMENT naming the node and the value); a result
 * that overflows is TFEM_STATUS_NUMERICAL_FAILURE; either way the buffers
 * are unchanged. Allocates nothing.
 */
enum tfem_status tfem_contact_evaluate(struct tfem_contact *context,
                                       const double *u,
                                       size_t u_length,
                                       double *values,
                                       size_t values_length,
                                       double *residual,
                                       size_t residual_length);

/**
 * Copies into `u` (2 per interface node) the displacements of the
 * interface nodes from the host's solution vector `u_equations`
 * (`n_equations` values; entry i is equation i + index_base); a DOF
 * without an equation counts as fixed at zero. A non-finite entry at an
 * interface node's equation is refused (TFEM_STATUS_INVALID_ARGUMENT
 * naming the node and the equation); `u` is then unchanged.
 */
enum tfem_status tfem_contact_gather(struct tfem_contact *context,
                                     const double *u_equations,
                                     size_t n_equations,
                                     double *u,
                                     size_t u_length);

/**
 * Adds per-node values `residual` (2 per interface node, as
 * `tfem_contact_evaluate` writes them) into the host's vector
 * `host_vector` (`n_equations` values, entry i is equation i +
 * index_base); DOFs without an equation are left out. A non-finite value
 * in `residual` is refused (TFEM_STATUS_INVALID_ARGUMENT naming the node),
 * and so is a sum that would not be finite: an entry of `host_vector`
 * that is not finite already (TFEM_STATUS_INVALID_ARGUMENT), or an
 * overflow (TFEM_STATUS_NUMERICAL_FAILURE), naming the node and the
 * equation. `host_vector` is then unchanged.
 */
enum tfem_status tfem_contact_scatter_add(struct tfem_contact *context,
                                          const double *residual,
                                          size_t residual_length,
                                          double *host_vector,
                                          size_t n_equations);

/**
 * The inversion test at the displacements `u` (2 per interface node) of
 * a solve with the current active set: the elements found inverted are
 * switched on, the others off; `changed` (may be NULL) is set to 1 if the
 * set changed, 0 if it settled. The same test and cycle detection as
 * tfem's own loop: a set visited before, or more calls than the options'
 * `max_iterations` since the last `tfem_contact_restart`, gives
 * TFEM_STATUS_NOT_CONVERGED with the history, the set unchanged. Call
 * it with converged displacements of the host's problem for the current
 * set (after its Newton loop, not at every Newton iteration): the test
 * judges the solution, and a mid-Newton iterate may switch elements that
 * the converged state would not. A non-finite value in `u` is refused
 * (TFEM_STATUS_INVALID_ARGUMENT naming the node and the value).
 */
enum tfem_status tfem_contact_update(struct tfem_contact *context,
                                     const double *u,
                                     size_t u_length,
                                     int *changed);

/**
 * Starts a new active-set loop from the current flags (a new load step):
 * the history and the sets visited are forgotten.
 */
enum tfem_status tfem_contact_restart(struct tfem_contact *context);

/**
 * Copies the active flag (1 active, 0 not) of every element of B.
 */
enum tfem_status tfem_contact_get_active(struct tfem_contact *context, int *out, size_t length);

/**
 * Sets the active flags of the elements of B (n_elements values, 0 or
 * 1): a warm start or a restored state; starts a new loop.
 */
enum tfem_status tfem_contact_set_active(struct tfem_contact *context,
                                         const int *active,
                                         size_t length);

/**
 * Copies the normal gap at every interface node (n_nodes values, model
 * length units) for the displacements `u` (2 per interface node): the
 * smallest, over the elements of B at the node, of the distance of an
 * element's apex from its interface edge (linearised; negative:
 * interpenetration). A node in no element of B (on a part of its side
 * that faces nothing of the other, beyond the other side's end) has no
 * gap and reads 0, as if touching: it is not in contact, and no contact
 * force acts there; tell such nodes by their absence from
 * `tfem_contact_elements`. A non-finite value in `u` is refused
 * (TFEM_STATUS_INVALID_ARGUMENT naming the node and the value).
 */
enum tfem_status tfem_contact_gaps(struct tfem_contact *context,
                                   const double *u,
                                   size_t u_length,
                                   double *out,
                                   size_t length);

/**
 * Copies the contact pressure of every element of B (n_elements values;
 * a stress, positive in compression, zero when inactive) for the
 * displacements `u` (2 per interface node). A non-finite value in `u` is
 * refused (TFEM_STATUS_INVALID_ARGUMENT naming the node and the value).
 */
enum tfem_status tfem_contact_pressures(struct tfem_contact *context,
                                        const double *u,
                                        size_t u_length,
                                        double *out,
                                        size_t length);

/**
 * Copies the nodes of every element of B (3 host node numbers each,
 * oriented so that J > 0 when the gap opens).
 */
enum tfem_status tfem_contact_elements(struct tfem_contact *context, int *out, size_t length);

/**
 * Copies the equations of every element's six DOFs (6 per element, x
 * then y of each node, in the index base; index_base − 1 marks a DOF
 * without an equation): with `tfem_contact_element_blocks`, the
 * contributions as unassembled element blocks.
 */
enum tfem_status tfem_contact_element_equations(struct tfem_contact *context,
                                                int64_t *out,
                                                size_t length);

/**
 * Copies every element's 6×6 tangent block (36 values per element,
 * row-major over its DOFs as in `tfem_contact_element_equations`): its
 * stiffness when active, zeros when not.
 */
enum tfem_status tfem_contact_element_blocks(struct tfem_contact *context,
                                             double *out,
                                             size_t length);

/**
 * Writes the contact length of the current active set to `length`, model
 * length units: per contact zone (a pair's active elements of B connected
 * through shared nodes), the summed interface-edge length
 * of the active elements (each as far as it faces the other side) of the
 * family — edges on one side, or on the other: each covers the interface
 * once — active over the longer length; +0.0 when no element is active.
 * (Their mean would count half the width where one family alone carries
 * a contact.)
 */
enum tfem_status tfem_contact_length(struct tfem_contact *context, double *length);

/****************************************************************************
 * The 3D model (tfem_solid_*): a handle of its own, tfem_solid_model, with
 * the conventions of tfem_model. Tetrahedra and tagged boundary faces, one
 * isotropic material per body, constraints and loads per node or per face
 * tag, frictionless contact pairs between tagged surfaces (a planar side
 * facing a matching one, docs/method.md §9), a solve, and its results per
 * node, per tetrahedron and per tetrahedron of the contact layer B.
 ***************************************************************************/

/**
 * Creates an empty 3D model. Returns NULL only if memory is exhausted.
 * Free it with `tfem_solid_destroy`. A 3D model is its own handle: the
 * 2D functions (`tfem_*` without `solid`) refuse it, and the 3D ones
 * refuse a 2D model.
 */
struct tfem_solid_model *tfem_solid_create(void);

/**
 * Destroys a 3D model and everything it owns. NULL is a no-op, and so is
 * a pointer that is not a live 3D model (destroyed already, or another
 * kind of handle): do not use a handle after destroying it.
 */
void tfem_solid_destroy(struct tfem_solid_model *model);

/**
 * Copies the message of the last failed call on `model` (empty after a
 * successful call) into `buffer` (`length` bytes including the final
 * NUL), truncating like `tfem_last_error` (TFEM_STATUS_BUFFER_TOO_SMALL;
 * `tfem_solid_last_error_length` gives the size needed). A 3D model keeps
 * its own messages; calls given no handle at all leave theirs in the
 * thread's slot, read with `tfem_last_error(NULL, …)`. A `model` that is
 * not a live 3D model gives TFEM_STATUS_INVALID_ARGUMENT with the message
 * saying so in `buffer`.
 */
enum tfem_status tfem_solid_last_error(const struct tfem_solid_model *model,
                                       char *buffer,
                                       size_t length);

/**
 * Size in bytes (including the final NUL) of the message
 * `tfem_solid_last_error` would give for `model`, so that a buffer of
 * this size holds all of it: 1 after a successful call; for a handle
 * that is not a live 3D model, the size of the message saying so.
 * `model` may be NULL: 1 (it has no message).
 */
size_t tfem_solid_last_error_length(const struct tfem_solid_model *model);

/**
 * Number of warnings: what the mesh noticed (tetrahedra numbered with
 * negative volume and renumbered, nodes used by no tetrahedron) and what
 * the last solve noticed but did not refuse (an ill-conditioned system).
 * They are kept until the next solve or mesh.
 */
enum tfem_status tfem_solid_warning_count(struct tfem_solid_model *model, int *count);

/**
 * Writes to `size` the size in bytes (including the final NUL) of
 * warning number `index` (0-based, whatever the index base), so that a
 * buffer of this size holds all of it in `tfem_solid_get_warning`. An
 * index out of range is refused (TFEM_STATUS_INVALID_ARGUMENT), `size`
 * unchanged.
 */
enum tfem_status tfem_solid_get_warning_size(struct tfem_solid_model *model,
                                             int index,
                                             size_t *size);

/**
 * Copies warning number `index` (0-based, whatever the index base) into
 * `buffer` of `length` bytes, truncating like `tfem_get_warning`: the
 * truncated warning is written with TFEM_STATUS_BUFFER_TOO_SMALL; on any
 * other error `buffer` is unchanged.
 */
enum tfem_status tfem_solid_get_warning(struct tfem_solid_model *model,
                                        int index,
                                        char *buffer,
                                        size_t length);

/**
 * Sets the mesh: `n_nodes` nodes with coordinates `xyz` (3·n_nodes
 * values, x0 y0 z0 x1 …), `n_tetrahedra` linear tetrahedra with
 * `connectivity` (4·n_tetrahedra node indices) and a body tag per
 * tetrahedron in `body_of_tetrahedron`. `index_base` is 0 (C) or 1
 * (Fortran) and applies to every index of every later call and message,
 * as `tfem_set_mesh`'s. A tetrahedron numbered with negative volume is
 * renumbered (its last two nodes swapped; a warning counts them, and
 * every output refers to the renumbered ones); flat ones are legal
 * (tempered). The mesh has no tagged faces yet: give them with
 * `tfem_solid_set_boundary_faces`. Replacing a mesh discards
 * constraints, loads, contact pairs and results; materials and
 * tempering are kept. Refused, naming the tetrahedron or node, for a
 * node index out of range, a node repeated in a tetrahedron or a
 * coordinate that is not finite (TFEM_STATUS_INVALID_MESH).
 */
enum tfem_status tfem_solid_set_mesh(struct tfem_solid_model *model,
                                     int n_nodes,
                                     const double *xyz,
                                     int n_tetrahedra,
                                     const int *connectivity,
                                     const int *body_of_tetrahedron,
                                     int index_base);

/**
 * Loads a Gmsh MSH 4.1 mesh (ASCII or binary) of tetrahedra from the file
 * `path` (NUL-terminated; on Unix any bytes, as for `tfem_load_gmsh`):
 * physical volumes become bodies (tag = body), the triangles of physical
 * surfaces become tagged boundary faces (tag = the physical surface's),
 * node i being the i-th node of the file's `$Nodes` section. Replaces the
 * mesh like `tfem_solid_set_mesh` with the given `index_base`. Returns
 * TFEM_STATUS_IO for an unreadable or malformed file,
 * TFEM_STATUS_INVALID_MESH for content a tetrahedral mesh cannot take
 * (another version of the format, no tetrahedra in a physical volume as
 * in a 2D file, elements of higher order, a tagged triangle that is not
 * the face of exactly one tetrahedron; named by the file's tags and
 * physical groups), TFEM_STATUS_INVALID_ARGUMENT if the library was built
 * without the `gmsh` feature. On error the model is unchanged.
 */
enum tfem_status tfem_solid_load_gmsh(struct tfem_solid_model *model,
                                      const char *path,
                                      int index_base);

/**
 * Sets the tagged boundary faces: `n_faces` triangles given by
 * `face_nodes` (3·n_faces node indices, in any order: the outward side is
 * away from the tetrahedron the face belongs to) with a tag each in
 * `tags`. Tags name the faces for constraints, loads and contact pairs.
 * Replaces previous faces (`tfem_solid_add_boundary_faces` adds one group
 * at a time). Each must be a face of exactly one tetrahedron, and a face
 * given twice with one tag is refused (its loads would count twice):
 * TFEM_STATUS_INVALID_MESH naming the face. Faces are given before the
 * constraints, loads and contact pairs that name them: while any is
 * declared the call is refused (TFEM_STATUS_INVALID_STATE). Discards the
 * results. On any error nothing changes.
 */
enum tfem_status tfem_solid_set_boundary_faces(struct tfem_solid_model *model,
                                               int n_faces,
                                               const int *face_nodes,
                                               const int *tags);

/**
 * Adds tagged boundary faces to those already set, checked as
 * `tfem_solid_set_boundary_faces` checks them (a face already holding
 * the tag is refused): for instance one call per physical surface.
 */
enum tfem_status tfem_solid_add_boundary_faces(struct tfem_solid_model *model,
                                               int n_faces,
                                               const int *face_nodes,
                                               const int *tags);

/**
 * Sizes: nodes, tetrahedra, and tetrahedra of the contact layer B of the
 * last solve (0 before a solve, or without contact pairs), which size the
 * buffers of the getters. Any pointer may be NULL.
 */
enum tfem_status tfem_solid_get_sizes(struct tfem_solid_model *model,
                                      int *n_nodes,
                                      int *n_tetrahedra,
                                      int *n_contact_tetrahedra);

/**
 * Number of tagged boundary faces the model holds, from
 * `tfem_solid_set_boundary_faces` / `tfem_solid_add_boundary_faces` or a
 * Gmsh file's physical surfaces; see `tfem_solid_get_boundary_faces`.
 */
enum tfem_status tfem_solid_get_boundary_face_count(struct tfem_solid_model *model, int *count);

/**
 * Copies the node coordinates the model holds (x0 y0 z0 x1 …, 3·n_nodes
 * values) into `xyz` of `length` values: after `tfem_solid_load_gmsh`,
 * the mesh the file gave.
 */
enum tfem_status tfem_solid_get_mesh_nodes(struct tfem_solid_model *model,
                                           double *xyz,
                                           size_t length);

/**
 * Copies the tetrahedra the model holds (4·n_tetrahedra node indices in
 * the model's index base, those given with negative volume renumbered)
 * into `tetrahedra` of `length` values and each one's body tag into
 * `bodies` of `bodies_length` values; `bodies` may be NULL. Nothing is
 * written unless both buffers are large enough.
 */
enum tfem_status tfem_solid_get_mesh_tetrahedra(struct tfem_solid_model *model,
                                                int *tetrahedra,
                                                size_t length,
                                                int *bodies,
                                                size_t bodies_length);

/**
 * Copies the tagged boundary faces the model holds (3·count node indices
 * in the model's index base, count from
 * `tfem_solid_get_boundary_face_count`) into `faces` of `length` values
 * and each face's tag into `tags` of `tags_length` values, in the order
 * they were given; `tags` may be NULL. Nothing is written unless both
 * buffers are large enough.
 */
enum tfem_status tfem_solid_get_boundary_faces(struct tfem_solid_model *model,
                                               int *faces,
                                               size_t length,
                                               int *tags,
                                               size_t tags_length);

/**
 * Sets the isotropic material of body `body`: Young's modulus `young`
 * (finite, > 0) and Poisson's ratio `poisson` (in (-1, 0.5)); a body may
 * be given its material before or after the mesh. Refused with
 * TFEM_STATUS_INVALID_MATERIAL naming the body. Every body of the mesh
 * needs one before a solve.
 */
enum tfem_status tfem_solid_set_material(struct tfem_solid_model *model,
                                         int body,
                                         double young,
                                         double poisson);

/**
 * Chooses Jmin, the floor of the tempered tetrahedra's Jacobian, with
 * `tfem_set_tempering`'s encoding (a `tfem_tempering_mode`): 0 auto,
 * Jmin = min(h⁴/λ, h³/10) with λ the larger side of the mesh's bounding
 * box (h the element's longest edge); 1 the same h⁴/λ with λ = `value`
 * (a length); 2 Jmin = `value` for every tetrahedron (length³; J is six
 * times the volume); 3 off, plain FEM (a flat tetrahedron is then an
 * error). `value` is ignored for 0 and 3, and must be finite and > 0 for
 * 1 and 2.
 */
enum tfem_status tfem_solid_set_tempering(struct tfem_solid_model *model, int mode, double value);

/**
 * Chooses the fill-reducing ordering of the factorisation (a
 * `tfem_ordering_mode`: 0 auto, 1 AMD, 2 nested dissection). Results do
 * not depend on it beyond round-off, and are kept.
 */
enum tfem_status tfem_solid_set_ordering(struct tfem_solid_model *model, int ordering);

/**
 * Prescribes displacement component `comp` (a `tfem_axis`: 0 x, 1 y,
 * 2 z) of `node` to `value` (model length units). A component prescribed
 * again takes the new value (unlike `tfem_fix`, which refuses a different
 * one). Refused, naming it, for a node out of range, a component other
 * than 0, 1, 2 or a value that is not finite.
 */
enum tfem_status tfem_solid_fix(struct tfem_solid_model *model, int node, int comp, double value);

/**
 * Prescribes component `comp` (0 x, 1 y, 2 z) to `value` on every node of
 * the boundary faces tagged `tag`, as they are when called (faces are
 * fixed before constraints: see `tfem_solid_set_boundary_faces`). An
 * unknown tag is refused, naming it.
 */
enum tfem_status tfem_solid_fix_faces(struct tfem_solid_model *model,
                                      int tag,
                                      int comp,
                                      double value);

/**
 * Removes every prescribed displacement (and so lets the boundary faces
 * change again, once loads and pairs are cleared too).
 */
enum tfem_status tfem_solid_clear_constraints(struct tfem_solid_model *model);

/**
 * Applies pressure `pressure` on the boundary faces tagged `tag`: a
 * stress (force per unit area, Pa in SI), positive pushing into the body,
 * along each face's outward normal. Loads add up.
 */
enum tfem_status tfem_solid_add_pressure(struct tfem_solid_model *model, int tag, double pressure);

/**
 * Applies the traction (tx, ty, tz) on the boundary faces tagged `tag`: a
 * stress vector (force per unit area, Pa in SI) whatever the faces'
 * orientation. Loads add up.
 */
enum tfem_status tfem_solid_add_traction(struct tfem_solid_model *model,
                                         int tag,
                                         double tx,
                                         double ty,
                                         double tz);

/**
 * Adds the point force (fx, fy, fz) at `node` (N in SI). Loads add up.
 */
enum tfem_status tfem_solid_add_nodal_force(struct tfem_solid_model *model,
                                            int node,
                                            double fx,
                                            double fy,
                                            double fz);

/**
 * Removes every load.
 */
enum tfem_status tfem_solid_clear_loads(struct tfem_solid_model *model);

/**
 * Declares a frictionless contact interface between the boundary faces
 * tagged `tag_a` and those tagged `tag_b`, on two bodies. Side a must be
 * planar: its outward normal is the direction that opens the gap, and the
 * contact layer B is a layer of flat tetrahedra built across that plane
 * (docs/method.md §9). Side b must face side a node to node (matching
 * meshes); that, the planarity and the two bodies are checked by the
 * solve, which names the pair and its tags. Writes the pair's index
 * (0-based, whatever the index base) to `pair` (may be NULL). Two equal
 * tags or a tag without faces are refused here, naming the tag.
 */
enum tfem_status tfem_solid_add_contact_pair(struct tfem_solid_model *model,
                                             int tag_a,
                                             int tag_b,
                                             int *pair);

/**
 * Removes every contact pair.
 */
enum tfem_status tfem_solid_clear_contact_pairs(struct tfem_solid_model *model);

/**
 * Solves the model with the default contact options (as
 * `tfem_solid_solve_contact` without options), the call for a model
 * without contact pairs: one linear solve then. `info` may be NULL.
 */
enum tfem_status tfem_solid_solve(struct tfem_solid_model *model, struct tfem_solve_info *info);

/**
 * Solves the model: where it has contact pairs, the tetrahedra of B are
 * switched on where they would invert, by the active-set loop of the 2D
 * contact solve. `options` may be NULL (defaults: see
 * `tfem_contact_options_default`); 3D contact is frictionless with its
 * own inversion test, so `law` must be 0 and `inversion_test` 0
 * (TFEM_STATUS_INVALID_ARGUMENT saying so otherwise); `contact_modulus`
 * and `lambda` (0: the smaller E of the pair's bodies, the other body's
 * for a rigid tool; the mesh's size), `max_iterations` and `refactorize`
 * are read. `info` may be NULL. A body without material gives
 * TFEM_STATUS_INVALID_MATERIAL naming it, a body not restrained
 * TFEM_STATUS_SINGULAR naming it, a pair whose sides do not fit (side a
 * not planar, sides not matching node to node, both on one body) an
 * error naming the pair and its tags. On error the model is unchanged,
 * its previous results included.
 */
enum tfem_status tfem_solid_solve_contact(struct tfem_solid_model *model,
                                          const struct tfem_contact_options *options,
                                          struct tfem_solve_info *info);

/**
 * One quasi-static load step: the model's loads and prescribed
 * displacements times `load_factor` (finite; initial gaps as they are),
 * started from the active set of the last solve or step, on the
 * structure, pattern and symbolic analysis the first solve derived, so
 * that a load history repeats neither the analysis nor the active-set
 * iterations a cold start would. Frictionless contact has no memory: a
 * step's answer is that of a solve at its factor, and the loads may
 * change between steps (a non-proportional history). `options` may be
 * NULL (defaults; refused as by `tfem_solid_solve_contact`); `info` may be
 * NULL. `tfem_solid_revert_step` takes the step back. On error the model
 * is unchanged.
 */
enum tfem_status tfem_solid_step(struct tfem_solid_model *model,
                                 double load_factor,
                                 const struct tfem_contact_options *options,
                                 struct tfem_solve_info *info);

/**
 * Takes back the last load step: its results, and the active set the
 * next step starts from, are those before it. Once per step, and not
 * after a change of the model (which discards the results): refused then
 * with TFEM_STATUS_INVALID_STATE, the model unchanged.
 */
enum tfem_status tfem_solid_revert_step(struct tfem_solid_model *model);

/**
 * Writes the statistics of the last solve (unknowns, factorisations,
 * interface unknowns, residual, times) to `info`.
 */
enum tfem_status tfem_solid_get_solve_info(struct tfem_solid_model *model,
                                           struct tfem_solve_info *info);

/**
 * Writes the active-set iterations of the last solve (1 without contact)
 * to `iterations`.
 */
enum tfem_status tfem_solid_get_iterations(struct tfem_solid_model *model, int *iterations);

/**
 * Copies the nodal displacements (ux0 uy0 uz0 ux1 …, 3·n_nodes values)
 * of the last solve into `out` of `length` values.
 */
enum tfem_status tfem_solid_get_displacements(struct tfem_solid_model *model,
                                              double *out,
                                              size_t length);

/**
 * Copies element strains (ε_xx ε_yy ε_zz γ_yz γ_xz γ_xy per tetrahedron,
 * engineering shears, 6·n_tetrahedra values), computed on request and
 * tempered below Jmin as the stiffness is.
 */
enum tfem_status tfem_solid_get_element_strains(struct tfem_solid_model *model,
                                                double *out,
                                                size_t length);

/**
 * Copies element stresses (σ_xx σ_yy σ_zz σ_yz σ_xz σ_xy per tetrahedron,
 * 6·n_tetrahedra values, the order of the strains; force per unit area,
 * Pa in SI), computed on request. An overflow gives
 * TFEM_STATUS_NUMERICAL_FAILURE naming the tetrahedron.
 */
enum tfem_status tfem_solid_get_element_stresses(struct tfem_solid_model *model,
                                                 double *out,
                                                 size_t length);

/**
 * Copies reaction forces (Rx Ry Rz per node, 3·n_nodes values, N in SI;
 * zero at components that are not prescribed), computed on request: with
 * the loads and the contact forces they balance every body.
 */
enum tfem_status tfem_solid_get_reactions(struct tfem_solid_model *model,
                                          double *out,
                                          size_t length);

/**
 * Writes the work of the external loads of the last solve, Σ f·u over
 * every node (J in SI): for a pressure load, the compliance.
 */
enum tfem_status tfem_solid_get_external_work(struct tfem_solid_model *model, double *work);

/**
 * Copies the nodes of every tetrahedron of the contact layer B of the
 * last solve (4·n_contact_tetrahedra indices in the model's index base,
 * pair by pair, numbered so that opening the gap makes J positive).
 */
enum tfem_status tfem_solid_get_contact_tetrahedra(struct tfem_solid_model *model,
                                                   int *out,
                                                   size_t length);

/**
 * Copies the active flag (1 pressed, 0 open) of every tetrahedron of B
 * in the last solve (n_contact_tetrahedra values, see
 * `tfem_solid_get_sizes`).
 */
enum tfem_status tfem_solid_get_contact_active(struct tfem_solid_model *model,
                                               int *out,
                                               size_t length);

/**
 * Copies the force the contact exerts on every node in the last solve
 * (fx fy fz per node, 3·n_nodes values, N in SI; zero off the contact
 * interfaces), computed on request: the forces of one pair sum to zero.
 */
enum tfem_status tfem_solid_get_contact_forces(struct tfem_solid_model *model,
                                               double *out,
                                               size_t length);

/**
 * Copies the contact pressure at every node in the last solve (n_nodes
 * values; force per unit area, Pa in SI, positive in compression; zero
 * off the pairs' faces), computed on request: the normal force B exerts
 * on the node over its tributary area, a third of each of its faces.
 */
enum tfem_status tfem_solid_get_contact_nodal_pressures(struct tfem_solid_model *model,
                                                        double *out,
                                                        size_t length);

/**
 * Writes the area in contact in the last solve, every pair together
 * (model length units squared): each active tetrahedron of B stands for
 * a third of the facing triangle of its prism, so a closed interface
 * reads its whole area.
 */
enum tfem_status tfem_solid_get_contact_area(struct tfem_solid_model *model, double *area);

/**
 * Writes the area in contact of contact pair `pair` alone (0-based, as
 * `tfem_solid_add_contact_pair` returned it, whatever the index base) in
 * the last solve. An unknown pair is refused (TFEM_STATUS_INVALID_ARGUMENT
 * naming it).
 */
enum tfem_status tfem_solid_get_contact_pair_area(struct tfem_solid_model *model,
                                                  int pair,
                                                  double *area);

/**
 * Writes the solved model to the file `path` (NUL-terminated; on Unix any
 * bytes, as for `tfem_load_gmsh`) as a VTK XML unstructured grid (`.vtu`,
 * binary appended data, read by ParaView, VTK and meshio): the
 * tetrahedra in their initial configuration with point data
 * `displacement` ([u_x, u_y, u_z]) and, when the model has contact pairs,
 * `contact_pressure` (`tfem_solid_get_contact_nodal_pressures`); cell
 * data `body`, `J` (six times the signed volume) and `stress` (VTK's
 * order of a symmetric tensor, [σ_xx, σ_yy, σ_zz, σ_xy, σ_yz, σ_xz], so
 * that its tensor filters read it; not the Voigt order of
 * `tfem_solid_get_element_stresses`). Returns TFEM_STATUS_INVALID_STATE
 * before a solve, TFEM_STATUS_NUMERICAL_FAILURE for a result that is not
 * finite (nothing is written then), TFEM_STATUS_IO when the file cannot
 * be written (the message names it and the reason), and
 * TFEM_STATUS_INVALID_ARGUMENT if the library was built without the `vtu`
 * feature. The model is never changed.
 */
enum tfem_status tfem_solid_write_vtu(struct tfem_solid_model *model, const char *path);

/****************************************************************************
 * Contact for 3D host codes (tfem_solid_contact_*): the contact context of
 * tfem_contact_* for a code with its own tetrahedral elements and solver, a
 * handle of its own, tfem_solid_contact. The host gives each side's nodes,
 * coordinates, equations (x, y, z) and triangles, counter-clockwise seen
 * from outside its body; it gets back B's stiffness and forces in its
 * equations, in a pattern fixed once, the verdict of the active-set loop,
 * and the state per tetrahedron of B. Side, pair and tetrahedron numbers are
 * in the context's index base.
 ***************************************************************************/

/**
 * Creates a 3D contact context for a host code that keeps its own
 * elements, assembly, solver and Newton loop: node numbers, equation
 * numbers, and side, pair and contact-tetrahedron numbers in
 * `index_base` (0 for C, 1 for Fortran). `options` may be NULL (the
 * defaults of `tfem_contact_options_default`); they are fixed here, as B
 * is built from them once: `contact_modulus` (0: the smaller Young's
 * modulus of a pair's two sides), `lambda` (0: the larger side of the
 * interface nodes' bounding box) and `max_iterations` (the number of
 * `tfem_solid_contact_update` calls of one loop before it counts as not
 * converged) are read, `refactorize` is ignored; 3D contact is
 * frictionless with its own inversion test, so `law` and
 * `inversion_test` must be 0. Returns NULL if `index_base` is not 0 or 1
 * or an option is refused (message in `tfem_last_error(NULL, …)`), or
 * memory is exhausted. The host then adds the sides
 * (`tfem_solid_contact_add_side`) and pairs
 * (`tfem_solid_contact_add_pair`); the first call that needs B builds it,
 * after which sides and pairs are fixed. A 3D context is its own handle:
 * the 2D `tfem_contact_*` functions refuse it, and these refuse a 2D
 * context or a model.
 */
struct tfem_solid_contact *tfem_solid_contact_create(int index_base,
                                                     const struct tfem_contact_options *options);

/**
 * Destroys a 3D contact context. NULL is a no-op, and so is a pointer
 * that is not a live 3D context (destroyed already, or another kind of
 * handle): do not use a handle after destroying it.
 */
void tfem_solid_contact_destroy(struct tfem_solid_contact *context);

/**
 * Copies the message of the last failed call on `context` (empty after a
 * successful call) into `buffer` (`length` bytes including the final NUL),
 * truncating like `tfem_last_error` (TFEM_STATUS_BUFFER_TOO_SMALL;
 * `tfem_solid_contact_last_error_length` gives the size needed). A 3D
 * context keeps its own messages. A `context` that is not a live 3D
 * contact context gives TFEM_STATUS_INVALID_ARGUMENT with the message
 * saying so in `buffer`.
 */
enum tfem_status tfem_solid_contact_last_error(const struct tfem_solid_contact *context,
                                               char *buffer,
                                               size_t length);

/**
 * Size in bytes (including the final NUL) of the message
 * `tfem_solid_contact_last_error` would give for `context`, so that a
 * buffer of this size holds all of it: 1 after a successful call; for a
 * handle that is not a live 3D contact context (destroyed, or another
 * kind), the size of the message saying so. `context` may be NULL: 1 (it
 * has no message).
 */
size_t tfem_solid_contact_last_error_length(const struct tfem_solid_contact *context);

/**
 * Adds one side of a contact interface, of body `body` (Young's modulus
 * `young`, finite and > 0: the softer side's is the default E_c):
 * `n_nodes` interface nodes `nodes` (the host's node numbers) with their
 * coordinates `xyz` (3 per node) and the equations of their x, y and z
 * unknowns `equations` (3 per node, in the index base; a value below the
 * base marks a fixed DOF without an equation), and `n_triangles`
 * triangles `triangles` (3 host node numbers each) numbered
 * counter-clockwise seen from outside the body, so that the two sides of
 * a pair face each other. A node of two sides, or given twice in one,
 * must come with the same coordinates and equations. Refused with TFEM_STATUS_INVALID_ARGUMENT,
 * naming the side (by its number in the index base and its tag), the node
 * or the triangle: a node number below the index base, a coordinate that
 * is not finite, an equation no host vector can hold (from index_base +
 * PTRDIFF_MAX / 8 on), a triangle over a node the side does not give, a
 * side without triangles; TFEM_STATUS_INVALID_STATE once B is built. The
 * host's system size is not known here: `tfem_solid_contact_gather` and
 * `tfem_solid_contact_scatter_add` check every equation against the
 * vector they are given. Writes the side's number (in the index base) to
 * `side` (may be NULL). On error nothing changes.
 */
enum tfem_status tfem_solid_contact_add_side(struct tfem_solid_contact *context,
                                             int tag,
                                             int body,
                                             double young,
                                             int n_nodes,
                                             const int *nodes,
                                             const double *xyz,
                                             const int64_t *equations,
                                             int n_triangles,
                                             const int *triangles,
                                             int *side);

/**
 * Declares sides `side_a` and `side_b` (their numbers in the index base,
 * of two different bodies) a contact pair: side a must be planar (its
 * outward normal opens the gap) and side b face it node to node; B, a
 * layer of flat tetrahedra over the prisms between the facing triangles,
 * is built from them (docs/method.md §9). A side that does not exist, or
 * two sides of one body, are refused with TFEM_STATUS_INVALID_ARGUMENT
 * naming them; sides that do not fit (side a not planar, sides not facing
 * each other or not matching) are refused by the call that builds B,
 * naming the pair and its sides. Writes the pair's number (in the index
 * base) to `pair` (may be NULL).
 */
enum tfem_status tfem_solid_contact_add_pair(struct tfem_solid_contact *context,
                                             int side_a,
                                             int side_b,
                                             int *pair);

/**
 * Builds B of every pair and the pattern now, so that a host learns of
 * sides that do not fit where it declares them rather than at its first
 * evaluation (every call that needs B builds it otherwise). Sides and
 * pairs are fixed from then on; the active set starts from the
 * tetrahedra touching or overlapping at rest. Without a pair,
 * TFEM_STATUS_INVALID_STATE. Calling it again does nothing.
 */
enum tfem_status tfem_solid_contact_setup(struct tfem_solid_contact *context);

/**
 * Builds B (if not yet) and writes the sizes: interface nodes (3 values
 * per node in every per-node array: displacements and residuals),
 * tetrahedra of B (the length of the per-tetrahedron arrays), and entries
 * of the pattern. Any pointer may be NULL.
 */
enum tfem_status tfem_solid_contact_sizes(struct tfem_solid_contact *context,
                                          int *n_nodes,
                                          int *n_tetrahedra,
                                          int64_t *n_entries);

/**
 * Copies the interface nodes (host numbers, n_nodes values), in the
 * order of every per-node array: the order in which the sides first gave
 * them.
 */
enum tfem_status tfem_solid_contact_nodes(struct tfem_solid_contact *context,
                                          int *out,
                                          size_t length);

/**
 * Copies the nodes of every tetrahedron of B (4 host node numbers each,
 * numbered so that J grows as the gap opens), pair by pair: with the
 * per-tetrahedron arrays (active flags, gaps), where the contact is.
 */
enum tfem_status tfem_solid_contact_tetrahedra(struct tfem_solid_contact *context,
                                               int *out,
                                               size_t length);

/**
 * Copies the fixed pattern of the contact contributions into `rows`
 * (n_entries values) and `cols` (n_entries values), in the host's
 * equation numbering and index base: tetrahedron after tetrahedron of B,
 * each one's 12×12 block row by row over its DOFs (x, y, z of its first
 * node, then of its second …), the DOFs without an equation left out;
 * both triangles of each block. Entries repeat where tetrahedra share a
 * DOF pair: the host sums them. B's topology never changes, so a host
 * sets up its sparse matrix once.
 */
enum tfem_status tfem_solid_contact_pattern(struct tfem_solid_contact *context,
                                            int64_t *rows,
                                            int64_t *cols,
                                            size_t length);

/**
 * Copies the equations of every tetrahedron's twelve DOFs (12 per
 * tetrahedron, x, y, z of each node, in the index base; index_base − 1
 * marks a DOF without an equation): with
 * `tfem_solid_contact_element_blocks`, the contributions as unassembled
 * element blocks, for a host that assembles elements rather than a
 * pattern.
 */
enum tfem_status tfem_solid_contact_element_equations(struct tfem_solid_contact *context,
                                                      int64_t *out,
                                                      size_t length);

/**
 * Copies every tetrahedron's 12×12 tangent block (144 values per
 * tetrahedron, row-major over its DOFs as in
 * `tfem_solid_contact_element_equations`): its stiffness when active,
 * zeros when not.
 */
enum tfem_status tfem_solid_contact_element_blocks(struct tfem_solid_contact *context,
                                                   double *out,
                                                   size_t length);

/**
 * The contact contributions at the displacements `u` of the interface
 * nodes (3 per node, `u_length` = 3·n_nodes): the tangent's values in the
 * pattern's order into `values` (n_entries values, zeros for inactive
 * tetrahedra), and the contact residual Σ (K_e u_e − f0_e) of the active
 * tetrahedra, 3 per interface node, into `residual`. `values` may be
 * NULL; `residual` may be NULL. A linear host adds the values to its
 * matrix and minus the residual at u₀ to its right-hand side, u₀ zero at
 * DOFs with an equation and the prescribed value at those without (a
 * rigid tool pressed by δ: `tfem_solid_contact_gather` reads such DOFs
 * as 0, so set them in `u` itself, here and for
 * `tfem_solid_contact_update`); that is the load of the initial gaps and
 * of the prescribed values. A Newton host adds the values to its tangent and
 * the residual at its current u to its residual. The law is linear in u
 * for a given active set: the values depend on the active set only, and
 * change only when `tfem_solid_contact_update` or
 * `tfem_solid_contact_set_active` changes it. A non-finite value in `u`
 * is refused (TFEM_STATUS_INVALID_ARGUMENT naming the node); a residual
 * that overflows is TFEM_STATUS_NUMERICAL_FAILURE naming the node;
 * either way the buffers are unchanged.
 */
enum tfem_status tfem_solid_contact_evaluate(struct tfem_solid_contact *context,
                                             const double *u,
                                             size_t u_length,
                                             double *values,
                                             size_t values_length,
                                             double *residual,
                                             size_t residual_length);

/**
 * Copies into `u` (3 per interface node) the displacements of the
 * interface nodes from the host's solution vector `u_equations`
 * (`n_equations` values; entry i is equation i + index_base); a DOF
 * without an equation counts as fixed at zero. An interface node's
 * equation beyond `n_equations`, or a non-finite entry there, is refused
 * (TFEM_STATUS_INVALID_ARGUMENT naming the node and the equation); `u` is
 * then unchanged.
 */
enum tfem_status tfem_solid_contact_gather(struct tfem_solid_contact *context,
                                           const double *u_equations,
                                           size_t n_equations,
                                           double *u,
                                           size_t u_length);

/**
 * Adds per-node values `residual` (3 per interface node, as
 * `tfem_solid_contact_evaluate` writes them) into the host's vector
 * `host_vector` (`n_equations` values, entry i is equation i +
 * index_base); DOFs without an equation are left out. A non-finite value
 * in `residual` is refused (TFEM_STATUS_INVALID_ARGUMENT naming the
 * node), and so is a sum that would not be finite: an entry of
 * `host_vector` that is not finite already (TFEM_STATUS_INVALID_ARGUMENT),
 * or an overflow (TFEM_STATUS_NUMERICAL_FAILURE), naming the node and the
 * equation; an equation beyond `n_equations` is refused naming the node.
 * `host_vector` is then unchanged.
 */
enum tfem_status tfem_solid_contact_scatter_add(struct tfem_solid_contact *context,
                                                const double *residual,
                                                size_t residual_length,
                                                double *host_vector,
                                                size_t n_equations);

/**
 * The inversion test at the displacements `u` (3 per interface node) of
 * a solve with the current active set: the tetrahedra of B whose gap is
 * not positive (pressed, or touching) are switched on, the others off.
 * `changed` (may be NULL) is set to 1 if the set changed, 0 if it
 * settled; `switched_on` (may be NULL) and `switched_off` (may be NULL)
 * to the number of tetrahedra switched each way. The same test and cycle
 * detection as tfem's own loop: a set visited before, or more calls than
 * the options' `max_iterations` since the last
 * `tfem_solid_contact_restart`, gives TFEM_STATUS_NOT_CONVERGED with the
 * history, the set unchanged. Call it with converged displacements of
 * the host's problem for the current set (after its Newton loop, not at
 * every Newton iteration): the test judges the solution. A non-finite
 * value in `u` is refused (TFEM_STATUS_INVALID_ARGUMENT naming the node).
 */
enum tfem_status tfem_solid_contact_update(struct tfem_solid_contact *context,
                                           const double *u,
                                           size_t u_length,
                                           int *changed,
                                           int *switched_on,
                                           int *switched_off);

/**
 * Starts a new active-set loop from the current flags (a new load step):
 * the history and the sets visited are forgotten, so that a set met in
 * an earlier step is no cycle.
 */
enum tfem_status tfem_solid_contact_restart(struct tfem_solid_contact *context);

/**
 * Copies the active flag (1 active, 0 not) of every tetrahedron of B
 * (n_tetrahedra values): the state a host saves to restore with
 * `tfem_solid_contact_set_active`.
 */
enum tfem_status tfem_solid_contact_get_active(struct tfem_solid_contact *context,
                                               int *out,
                                               size_t length);

/**
 * Sets the active flags of the tetrahedra of B (n_tetrahedra values, 0
 * or 1): a warm start or a restored state; starts a new loop. A value
 * other than 0 or 1, or another count, is refused
 * (TFEM_STATUS_INVALID_ARGUMENT), the flags unchanged.
 */
enum tfem_status tfem_solid_contact_set_active(struct tfem_solid_contact *context,
                                               const int *active,
                                               size_t length);

/**
 * Copies the opening of every tetrahedron of B (n_tetrahedra values,
 * model length units) at the displacements `u` (3 per interface node):
 * its linearised gap over its facing area, the distance across the
 * interface (negative: an overlap). Per tetrahedron rather than per node
 * as in 2D: in space a node's tetrahedra may face different triangles. A
 * non-finite value in `u` is refused (TFEM_STATUS_INVALID_ARGUMENT naming
 * the node), a gap that overflows is TFEM_STATUS_NUMERICAL_FAILURE naming
 * the tetrahedron; `out` is then unchanged.
 */
enum tfem_status tfem_solid_contact_gaps(struct tfem_solid_contact *context,
                                         const double *u,
                                         size_t u_length,
                                         double *out,
                                         size_t length);

/**
 * Writes the area in contact of the current active set to `area` (model
 * length units squared): each active tetrahedron of B stands for a third
 * of its prism's facing triangle, so that a closed interface reads its
 * whole area. A sum that overflows is TFEM_STATUS_NUMERICAL_FAILURE.
 */
enum tfem_status tfem_solid_contact_area(struct tfem_solid_contact *context, double *area);

#ifdef __cplusplus
}  // extern "C"
#endif  // __cplusplus

#endif  /* TFEM_H */
