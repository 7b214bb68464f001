! Generated from include/tfem.h by tests/fortran.rs. Do not edit:
! regenerate with `TFEM_BLESS=1 cargo test --test fortran`.
!
! Fortran interface to tfem (ISO_C_BINDING): every function of tfem.h with its whole
! documentation, the enums as named constants, the structs as bind(C) types, and
! string helpers. From tfem.h:
!
! tfem -- the Tempered Finite Element Method for elasticity and contact
! in 2D (frictionless or with Coulomb friction) and 3D (frictionless).
! C ABI.
!
! Overview
! - Two objects. A tfem_model holds a whole problem: the mesh and its
!   bodies, materials, loads and constraints, contact pairs, and the
!   results of its last solve or load step. A tfem_contact is the contact
!   context of a host code that keeps its own elements and solver: it
!   gives back contact stiffness and forces to add to the host's system.
!   A tfem_solid_model holds a problem in space (tetrahedra, tagged
!   boundary faces, frictionless contact between tagged surfaces): its
!   functions, tfem_solid_*, follow the same phases and conventions, and
!   one is used by one thread at a time like a tfem_model. A
!   tfem_solid_contact is the contact context of a 3D host code, the
!   tfem_contact of tetrahedral meshes (tfem_solid_contact_*).
! - Phases of a model: describe it (mesh, materials, loads and
!   constraints, contact pairs), solve it (tfem_solve, tfem_solve_contact,
!   or a load history of tfem_step), read the results (computed when
!   asked). Any change to the description discards the results.
! - The entry points below stand in groups, in that order, each under a
!   head: lifecycle, mesh, materials, loads and constraints, contact pairs,
!   solve, results, contact results, load history, utilities, the host
!   codes' contact context, the 3D model, and the 3D host codes' contact
!   context.
!
! Conventions
! - Every function returns a tfem_status; TFEM_STATUS_OK (0) is success.
!   Status numbers are fixed forever and never reused. tfem_last_error()
!   gives the message of the last failed call, naming the offending node,
!   triangle, edge, body or argument.
! - Indices (nodes, triangles, edges) use the index_base given to
!   tfem_set_mesh (0 for C, 1 for Fortran) in every later call and in
!   every message. Counts are int; buffer lengths are size_t, in elements.
! - Output buffers are owned by the caller. Their length is checked and
!   nothing is written when it is too short (TFEM_STATUS_BUFFER_TOO_SMALL).
! - A call that returns an error writes none of its outputs: every buffer,
!   and every value or struct given back through a pointer (a size, count
!   or index, a tfem_solve_info, a tfem_contact_report, the host vector of
!   tfem_contact_scatter_add and tfem_solid_contact_scatter_add), keeps the
!   bytes it held, whatever the error (a handle or argument refused, a
!   wrong state, one of several buffers too short or NULL, a solve that
!   fails). The only exceptions are the message copies: tfem_last_error,
!   tfem_contact_last_error and tfem_get_warning (and the 3D handles'
!   tfem_solid_last_error, tfem_solid_get_warning and
!   tfem_solid_contact_last_error) write the message cut to the buffer
!   (NUL-terminated) with TFEM_STATUS_BUFFER_TOO_SMALL, and the
!   *_last_error functions write the message refusing a handle that is
!   not live with TFEM_STATUS_INVALID_ARGUMENT.
! - A failed call leaves the model as it was, its results included. Any
!   change to the problem (mesh, boundary edges, materials, constraints,
!   loads, contact pairs, tempering) discards previous results; settings
!   that change nothing physical (tfem_set_ordering, tfem_set_threads)
!   keep them. Results are computed when asked for, and do not depend on
!   the calls that failed before.
! - Units are the caller's: lengths, forces and moduli in one consistent
!   system (SI: m, N, Pa). The model is 2D with unit thickness: moduli,
!   stresses, pressures and tractions are forces per unit area (Pa);
!   nodal forces, reactions and contact forces are forces per unit
!   thickness (N/m); body forces are forces per unit volume (N/m^3); work
!   is per unit thickness (J/m).
! - No NaN or Inf is ever returned as a result with TFEM_STATUS_OK: an
!   overflow gives TFEM_STATUS_NUMERICAL_FAILURE naming the item.
! - Nothing is ever printed on stdout or stderr: messages, warnings and
!   internal failures are read with tfem_last_error and tfem_get_warning.
! - Handles are checked before use: a destroyed model or context, or a
!   handle of the other kind (a Fortran type(c_ptr) does not tell them
!   apart), is refused with TFEM_STATUS_INVALID_ARGUMENT (its message in
!   the thread's slot, or in the buffer of the *_last_error functions),
!   and destroying it is a no-op. (A destroyed
!   handle whose address a new handle has taken reaches the new one.)
!
! Thread contract
! - A tfem_model must be used by one thread at a time (no internal
!   locking); different models may be used concurrently from different
!   threads. The solver itself runs on a thread pool: the process-wide one
!   (as many threads as cores, or RAYON_NUM_THREADS), or the model's own
!   with tfem_set_threads (1 for a host that runs its own threads).
! - tfem_version, tfem_element_stiffness, tfem_laplacian_stiffness and
!   tfem_contact_options_default are pure and thread-safe; their errors go
!   to a per-thread slot read with tfem_last_error(NULL, ...), which their
!   next success clears.
! - No panic crosses the boundary: an internal failure returns
!   TFEM_STATUS_INTERNAL (its message read with tfem_last_error).
!
! In Fortran (`use tfem`), where it differs from the C conventions above
! - The model handle is a type(c_ptr) from tfem_create, passed by value.
! - Functions returning a tfem_status return an integer(c_int): compare it with the
!   TFEM_STATUS_* parameters below. tfem_error_message([model]) returns the last error as a
!   Fortran string (model omitted: the calling thread's model-free calls);
!   tfem_contact_error_message(context) that of a contact context;
!   tfem_solid_error_message(model) that of a 3D model (from tfem_solid_create);
!   tfem_solid_contact_error_message(context) that of a 3D contact context;
!   tfem_warning_message(model, index), tfem_solid_warning_message(model, index) and
!   tfem_version_string() return strings too.
! - Indices: pass index_base = 1 to tfem_set_mesh (or tfem_load_gmsh; for a 3D model
!   tfem_solid_set_mesh or tfem_solid_load_gmsh; for a contact context tfem_contact_create or
!   tfem_solid_contact_create) and every node, triangle, tetrahedron, edge and face number of
!   later calls and messages is 1-based, like Fortran arrays. Numbers that a function documents
!   as 0-based stay 0-based.
! - NULL: a pointer argument that the C documentation says may be NULL is OPTIONAL: omit it (by
!   keyword, or at the end of the list) and the library receives NULL. A nullable model handle
!   is passed by value: its generic has a specific without it instead (tfem_last_error(buffer,
!   length), tfem_last_error_length()).
! - Kinds: C int is integer(c_int), the default integer of gfortran, ifx, flang and nvfortran
!   (unless built with -fdefault-integer-8 or -i8), so default integer counts, indices and
!   index arrays are passed as they are; double is real(c_double), int64_t integer(c_int64_t).
!   Buffer lengths (size_t) accept default integers too: see the generic interfaces below.
! - Arrays: a numeric array that the C function takes as a flat buffer may have rank 1 or 2,
!   each array of a call its own: xy(2, n_nodes), triangles(3, n_triangles), u(2, n_nodes),
!   stresses(3, n_triangles). The library reads and writes the array's elements in array
!   element order, in place (a contiguous array is not copied).
! - Character buffers are character(kind=c_char) arrays or strings; a path is NUL-terminated:
!   append c_null_char.
!
! Fortran 2008
! This file compiles under -std=f2008 (and -std=f2018). It holds three modules, in this order:
! - tfem_c, the C API as it is: every function as a bind(C) interface under its C name with its
!   whole C documentation, every argument required (a nullable pointer too: pass a variable),
!   arrays assumed-size (any rank, or an element as the start of a buffer), size_t lengths
!   integer(c_size_t); the enums as named constants, the structs as bind(C) types. It is the
!   module as it was before the generic interfaces.
! - tfem_specifics, the module procedures behind the generic interfaces of tfem: not for direct
!   use (their names and number may change). They are apart from tfem because a procedure has at
!   most one explicit interface in a scoping unit: here a C name is tfem_c's bind(C) interface,
!   called directly, or one that takes the nullable pointers as type(c_ptr).
! - tfem, the module to use: tfem_c's constants, types and the interfaces of the functions that
!   need nothing converted, and a generic interface for every other function.
!
! Generic interfaces
! A function with a size_t length, a nullable pointer or a nullable model handle is a generic
! interface named like the C function. Its specifics take every combination of
! - lengths as integer(c_size_t) (the kind of integer(c_int64_t) on 64-bit platforms) or as
!   integer(tfem_length_kind) (c_int where size_t is wider, so default integers and literals;
!   c_int64_t where size_t is c_int), all the lengths of one call of one kind; a negative
!   length is passed as 0, so that the call fails with TFEM_STATUS_BUFFER_TOO_SMALL;
! - each numeric array with rank 1 or 2: generic resolution matches ranks, so a rank-1 dummy
!   alone would refuse the rank-2 arrays that sequence association passes to the assumed-size
!   dummy of a bind(C) interface. The specific takes a rank-2 array as an assumed-size x(1, *)
!   and passes it on to the C function's x(*) by sequence association, without a copy;
! - character buffers as character(kind=c_char) arrays or as character(len=*) strings;
! - a nullable model handle given or omitted (c_null_ptr is passed).
! The specifics are named after the C function with suffixes: _opt (nullable pointers), _no_<arg>
! (handle omitted), _str (strings), _i (tfem_length_kind lengths), _r<ranks> (a digit per numeric
! array, when one has rank 2). Ranks above 2, and an array element as the start of a buffer
! (u(1)), match no specific (a scalar dummy cannot be passed on as the start of an array): use
! tfem_c's interface for them.
! A function without a nullable pointer also keeps tfem_c's bind(C) interface among its specifics
! (every argument, integer(c_size_t) lengths, rank-1 arrays), so that such calls, procedure actual
! arguments and c_funloc reach it under the C name as before.
! A function with a nullable pointer cannot. Fortran 2008 forbids OPTIONAL dummies in bind(C)
! interfaces (Fortran 2018 allows them, from TS 29113), so the omitted arguments need a module
! procedure; one whose OPTIONAL dummies have the types of the bind(C) interface's arguments is
! indistinguishable from it (an OPTIONAL dummy tells no specifics apart), and specifics that leave
! arguments out cannot tell two of one type apart when either is omitted by keyword
! (tfem_get_sizes(m, n_triangles=n) and tfem_get_sizes(m, n_nodes=n)). Keeping the bind(C)
! interface under the C name would thus lose omitted arguments that compiled before; tfem keeps
! them, and its generic for such a function holds module procedures only. They pass an absent
! argument as a null type(c_ptr) and a given one as its address (a zero-length array as that of a
! private one-element array, so that the C function sees a buffer of length 0, not NULL). A
! nullable array of rank 2 is a required argument of its specifics, the rank of an OPTIONAL dummy
! telling none apart: given, it may have rank 1 or 2; omitted, it is absent. What these names lose
! in tfem is the bind(C) procedure itself: for c_funloc or a procedure actual argument, take it
! from tfem_c under another local name (use tfem_c, only: c_tfem_solve => tfem_solve). These
! functions are:
!   tfem_get_sizes, tfem_get_mesh_triangles, tfem_get_boundary_edges, tfem_add_contact_pair,
!   tfem_add_contact_pair_with_mesh, tfem_add_contact_pairs_auto, tfem_get_contact_pair_bodies,
!   tfem_solve, tfem_solve_contact, tfem_solve_adaptive, tfem_get_adapt_cycles,
!   tfem_get_contact_slave_nodes, tfem_step, tfem_get_system_matrix_size, tfem_contact_add_side,
!   tfem_contact_add_pair, tfem_contact_add_pair_with_mesh, tfem_contact_sizes,
!   tfem_contact_evaluate, tfem_contact_update, tfem_solid_get_sizes,
!   tfem_solid_get_mesh_tetrahedra, tfem_solid_get_boundary_faces, tfem_solid_add_contact_pair,
!   tfem_solid_solve, tfem_solid_solve_contact, tfem_solid_step, tfem_solid_contact_create,
!   tfem_solid_contact_add_side, tfem_solid_contact_add_pair, tfem_solid_contact_sizes,
!   tfem_solid_contact_evaluate, tfem_solid_contact_update

! The C API as it is (see "Fortran 2008" above).
module tfem_c
  use, intrinsic :: iso_c_binding
  implicit none

  ! enum tfem_status: Outcome of a call. The numbers are part of the C ABI and are fixed forever: a
  ! code is never renumbered or reused, new codes are appended.
  !> Success.
  integer(c_int), parameter :: TFEM_STATUS_OK = 0
  !> A required pointer argument was NULL.
  integer(c_int), parameter :: TFEM_STATUS_NULL_POINTER = 1
  !> An argument is out of its documented range (the message names it).
  integer(c_int), parameter :: TFEM_STATUS_INVALID_ARGUMENT = 2
  !> The mesh is invalid (the message names the node, triangle or edge).
  integer(c_int), parameter :: TFEM_STATUS_INVALID_MESH = 3
  !> A material is invalid or missing (the message names the body).
  integer(c_int), parameter :: TFEM_STATUS_INVALID_MATERIAL = 4
  !> The call is not allowed in the model's current state (e.g. a solve before a mesh was given,
  !! results before a solve).
  integer(c_int), parameter :: TFEM_STATUS_INVALID_STATE = 5
  !> A caller-owned output buffer is shorter than required.
  integer(c_int), parameter :: TFEM_STATUS_BUFFER_TOO_SMALL = 6
  !> The stiffness matrix is singular or indefinite: some body is not restrained (the message names
  !! it).
  integer(c_int), parameter :: TFEM_STATUS_SINGULAR = 7
  !> The contact active-set loop did not converge (the message gives the history).
  integer(c_int), parameter :: TFEM_STATUS_NOT_CONVERGED = 8
  !> A degenerate element cannot be integrated (zero Jacobian with tempering off); the message names
  !! it.
  integer(c_int), parameter :: TFEM_STATUS_DEGENERATE_ELEMENT = 9
  !> A contact pair or contact mesh is invalid (the message names it).
  integer(c_int), parameter :: TFEM_STATUS_INVALID_CONTACT = 10
  !> A computed result is not finite (overflow), or a solve could not reach working accuracy even
  !! with a factorisation of its own matrix (the message says which); nothing was returned.
  integer(c_int), parameter :: TFEM_STATUS_NUMERICAL_FAILURE = 11
  !> An internal error (a caught panic): please report it.
  integer(c_int), parameter :: TFEM_STATUS_INTERNAL = 12
  !> Memory could not be allocated (the message names what for): the library's copy of a caller's
  !! array and the structures a mesh or a contact side derives from it; every stage of a solve, a
  !! load step or a step's recovery, checked before the stage starts (set-up, ordering,
  !! factorisation, vectors, the threads and their dense kernels' buffers). The bounds checked are
  !! conservative: a call may be refused a little before memory is truly exhausted. Other
  !! allocations (declarations, results read after a solve, files) are small beside these and not
  !! checked: where they fail, the process aborts.
  integer(c_int), parameter :: TFEM_STATUS_OUT_OF_MEMORY = 13
  !> A file could not be read or written (the message names it).
  integer(c_int), parameter :: TFEM_STATUS_IO = 14

  ! enum tfem_tempering_mode: How Jmin is chosen (argument `mode` of `tfem_set_tempering`).
  !> Jmin = min(h³/λ, h²/10), λ = larger side of the mesh's bounding box (default): an element whose
  !! apex stands at least a tenth of its longest edge h above it is never softened.
  integer(c_int), parameter :: TFEM_TEMPERING_MODE_AUTO = 0
  !> Jmin = h³/λ with λ = `value` (a length in model units).
  integer(c_int), parameter :: TFEM_TEMPERING_MODE_LAMBDA = 1
  !> Jmin = `value` for every element (length²).
  integer(c_int), parameter :: TFEM_TEMPERING_MODE_FIXED_JMIN = 2
  !> Plain FEM (no tempering); zero-Jacobian elements are an error.
  integer(c_int), parameter :: TFEM_TEMPERING_MODE_OFF = 3

  ! enum tfem_ordering_mode: The fill-reducing ordering of the factorisation (argument `ordering` of
  ! `tfem_set_ordering`).
  !> Nested dissection from 10 000 unknowns, AMD below (default).
  integer(c_int), parameter :: TFEM_ORDERING_MODE_AUTO = 0
  !> faer's approximate minimum degree.
  integer(c_int), parameter :: TFEM_ORDERING_MODE_AMD = 1
  !> Geometric nested dissection on the node coordinates.
  integer(c_int), parameter :: TFEM_ORDERING_MODE_NESTED_DISSECTION = 2

  ! enum tfem_contact_weighting: How the contact pairs' energy is weighted along their interfaces
  ! (argument `weighting` of `tfem_set_contact_weighting`).
  !> The elements of the contact mesh B (the seed's method) for every pair.
  integer(c_int), parameter :: TFEM_CONTACT_WEIGHTING_STRIP = 0
  !> The sampled mortar weighting for every pair: one weighted gap per node of each interface's
  !! coarser side; frictionless.
  integer(c_int), parameter :: TFEM_CONTACT_WEIGHTING_MORTAR = 1
  !> Each pair what is right for its interface (the default): B where the two sides' nodes match,
  !! the mortar weighting where they do not, B for a pair with friction or a contact mesh of its
  !! own.
  integer(c_int), parameter :: TFEM_CONTACT_WEIGHTING_AUTO = 2

  ! enum tfem_contact_law: The constitutive law of the contact elements.
  !> Only the normal strain is penalised: D_c = E_c m mᵀ with m = [n_x², n_y², n_x n_y]. Tangential
  !! slip is free.
  integer(c_int), parameter :: TFEM_CONTACT_LAW_FRICTIONLESS = 0
  !> Tempered isotropic elasticity in B (E_c, ν of the softer body) on the element flattened onto
  !! its interface line (`contact::law_geometry`): a normal and a tangential spring on the jump
  !! between the surfaces, so it also resists slip and ties them (sticking contact). Flattened
  !! because, across an initial gap or overlap, the element itself would also read the bodies'
  !! tangential stretching, and its Poisson stress broke the patch test (docs/method.md §6.4).
  integer(c_int), parameter :: TFEM_CONTACT_LAW_STICK = 1

  ! enum tfem_inversion_test: How an element of B is found inverted.
  !> J linearised about the initial configuration, J0 + Σ g_i·u_i < 0 (consistent with small strain;
  !! for a flat conforming element, the node-pair normal gap). Under the frictionless law, only its
  !! normal part J0 + Σ (n·g_i)(n·u_i) — the element's normal opening: the node-to-segment gap at
  !! its apex times its interface edge, the very quantity the law penalises — so that an active
  !! element always pushes. The two differ by J0·ε_tt (the interface stretching times the initial
  !! gap): nothing on touching surfaces, but on a curved gap, where the bodies strain by a percent,
  !! enough to activate elements that then pull. The default.
  integer(c_int), parameter :: TFEM_INVERSION_TEST_LINEARISED = 0
  !> The seed's literal test, J(X + u) < 0. Its second-order term (slope times slip) can exceed the
  !! penalty penetration on fine meshes and make the loop cycle.
  integer(c_int), parameter :: TFEM_INVERSION_TEST_LITERAL = 1

  ! enum tfem_plane_mode: The 2D idealisation of the out-of-plane direction.
  !> ε_zz = 0 (thick bodies; the seed's setting).
  integer(c_int), parameter :: TFEM_PLANE_MODE_STRAIN = 0
  !> σ_zz = 0 (thin plates).
  integer(c_int), parameter :: TFEM_PLANE_MODE_STRESS = 1
  !> Bodies of revolution about the axis x = 0: x is the radius r ≥ 0, y the axial coordinate z, and
  !! the hoop strain ε_θθ = u_r/r. Every force and stiffness is that of the whole ring (2π radians):
  !! docs/method.md §7.
  integer(c_int), parameter :: TFEM_PLANE_MODE_AXISYMMETRIC = 2

  ! enum tfem_component: A displacement component.
  !> Horizontal (u).
  integer(c_int), parameter :: TFEM_COMPONENT_X = 0
  !> Vertical (v).
  integer(c_int), parameter :: TFEM_COMPONENT_Y = 1

  ! enum tfem_adapt_goal: What the tolerance of `tfem_solve_adaptive` bounds (argument `goal`).
  !> The relative error in the energy norm.
  integer(c_int), parameter :: TFEM_ADAPT_GOAL_ENERGY = 0
  !> The relative error of the compliance (f·u), the square of the energy's.
  integer(c_int), parameter :: TFEM_ADAPT_GOAL_COMPLIANCE = 1

  ! enum tfem_axis: A displacement component in space (argument `comp` of `tfem_solid_fix` and
  ! `tfem_solid_fix_faces`): the 2D `tfem_component` has no z, and its values must keep their
  ! meaning, so 3D has its own.
  !> u_x.
  integer(c_int), parameter :: TFEM_AXIS_X = 0
  !> u_y.
  integer(c_int), parameter :: TFEM_AXIS_Y = 1
  !> u_z.
  integer(c_int), parameter :: TFEM_AXIS_Z = 2

  !> Options of `tfem_solve_contact`. Fill with `tfem_contact_options_default` and change what you
  !! need.
  type, bind(C) :: tfem_contact_options
    !> A `ContactLaw` value: 0 = frictionless (default), 1 = stick.
    integer(c_int) :: law
    !> E_c of the contact elements; 0 = the smaller E of the two bodies, or where one side of a pair
    !! has every DOF of its contact nodes prescribed (a rigid tool) the other body's E, so that a
    !! rigid tool's nominal E does not set the penalty. The host contact context
    !! (`tfem_contact_set_options`) still takes the smaller E of its two sides: give a rigid side
    !! its neighbour's E, or set `contact_modulus`.
    real(c_double) :: contact_modulus
    !> λ of the contact elements (Jmin = h³/λ), model length units; 0 = the larger side of the
    !! mesh's bounding box.
    real(c_double) :: lambda
    !> An `InversionTest` value: 0 = linearised J (default), 1 = literal J.
    integer(c_int) :: inversion_test
    !> Cap on active-set iterations (default 50).
    integer(c_int) :: max_iterations
    !> 1 = refactorise the matrix at every active-set iteration; 0 (default) = condense the changes
    !! on the contact interface (faster, exact).
    integer(c_int) :: refactorize
  end type tfem_contact_options

  !> Statistics of a solve. Times are wall-clock seconds.
  type, bind(C) :: tfem_solve_info
    !> Unknowns after Dirichlet elimination.
    integer(c_int64_t) :: unknowns
    !> Stored entries of the matrix's upper triangle.
    integer(c_int64_t) :: matrix_nnz
    !> Stored entries of the Cholesky factor.
    integer(c_int64_t) :: factor_nnz
    !> Numeric factorisations performed.
    integer(c_int64_t) :: factorizations
    !> Unknowns of the condensed contact interface (0 if not condensed).
    integer(c_int64_t) :: interface_unknowns
    !> ‖K u − f‖ / ‖f‖ of the final system.
    real(c_double) :: relative_residual
    !> Condition estimate of the Jacobi-scaled final matrix.
    real(c_double) :: condition_estimate
    !> Bytes held by pattern, matrix values, factor and dense interface.
    integer(c_int64_t) :: memory_bytes
    !> Bytes one numeric factorisation needs at its peak (factor, symbolic structure, workspace).
    integer(c_int64_t) :: factorization_bytes
    !> Pattern and symbolic analysis (0 when reused).
    real(c_double) :: time_analysis
    !> Element matrices and scatter-add.
    real(c_double) :: time_assembly
    !> Numeric factorisations, including the singularity check.
    real(c_double) :: time_factorization
    !> Triangular solves.
    real(c_double) :: time_solve
    !> Dense work on the condensed contact interface.
    real(c_double) :: time_interface
    !> The whole call.
    real(c_double) :: time_total
  end type tfem_solve_info

  !> Report of `tfem_solve_contact`.
  type, bind(C) :: tfem_contact_report
    !> Active-set iterations (solves).
    integer(c_int) :: iterations
    !> Elements of the contact mesh B (under the mortar weighting, `tfem_set_contact_weighting`:
    !! slave nodes).
    integer(c_int) :: elements
    !> Active elements at convergence (under the mortar weighting: slave nodes).
    integer(c_int) :: active
    !> Contact length ℓc, model length units: the summed interface-edge length of the active
    !! elements, each as far as it faces the other side, of one of B's two families (edges on one
    !! side or on the other) in each contact zone (a pair's active elements connected through shared
    !! nodes), the one active over the longer length. (Not their mean, which counts half the width
    !! of a contact carried by one family alone; docs/method.md §6.8.) Under the mortar weighting:
    !! the active slave nodes' summed tributaries.
    real(c_double) :: contact_length
    !> Largest normal interpenetration, model length units (under the mortar weighting: of an active
    !! slave node's mean gap).
    real(c_double) :: max_penetration
    !> Solver statistics.
    type(tfem_solve_info) :: info
  end type tfem_contact_report

  !> Report of `tfem_solve_adaptive`.
  type, bind(C) :: tfem_adapt_report
    !> Solves made (cycles); each cycle's numbers from `tfem_get_adapt_cycles`.
    integer(c_int) :: cycles
    !> 1 if the last estimate meets the tolerance (and, with contact, the contact zones' edges are
    !! located to it), 0 if a limit stopped the refinement first (a warning then says what was
    !! reached).
    integer(c_int) :: reached
    !> Unknowns of the last solve.
    integer(c_int64_t) :: unknowns
    !> Triangles of the refined mesh.
    integer(c_int64_t) :: triangles
    !> The last estimate of the goal's relative error.
    real(c_double) :: estimate
    !> Seconds of the whole adaptive solve, refinements included.
    real(c_double) :: seconds
  end type tfem_adapt_report

  interface
    ! ==============================================================================================
    ! Lifecycle, errors and warnings: a model is created, used from one thread at a time, and
    ! destroyed; every call returns a tfem_status, the message of the last failed one is
    ! tfem_last_error's, and warnings (something really wrong that did not stop the call) are kept
    ! until the next solve or change.
    ! ==============================================================================================

    !> The library version as a static NUL-terminated string ("major.minor.patch"). Thread-safe;
    !! never NULL; do not free.
    function tfem_version() &
        bind(C, name="tfem_version") result(res)
      import
      type(c_ptr) :: res
    end function tfem_version

    !> Creates an empty model. Returns NULL only if memory is exhausted. Free it with
    !! `tfem_destroy`.
    function tfem_create() &
        bind(C, name="tfem_create") result(res)
      import
      type(c_ptr) :: res
    end function tfem_create

    !> Destroys a model and everything it owns. NULL is a no-op, and so is a pointer that is not a
    !! live model (destroyed already, or a contact context). A destroyed handle given to any
    !! function is refused (TFEM_STATUS_INVALID_ARGUMENT), as is a handle of the other kind — unless
    !! its address has since been reused by a new handle, which it then reaches: do not use a handle
    !! after destroying it.
    subroutine tfem_destroy(model) &
        bind(C, name="tfem_destroy")
      import
      type(c_ptr), value :: model
    end subroutine tfem_destroy

    !> Copies the message of the last failed call on `model` (empty after a successful call) into
    !! `buffer` (`length` bytes including the final NUL). With `model` NULL, gives the calling
    !! thread's last error from calls that have no model (or were given a NULL one). A message
    !! longer than the buffer is truncated (still NUL-terminated) and TFEM_STATUS_BUFFER_TOO_SMALL
    !! is returned; `tfem_last_error_length` gives the size needed. A `model` that is not a live
    !! model gives TFEM_STATUS_INVALID_ARGUMENT with the message saying so in `buffer`. (These, with
    !! `tfem_contact_last_error` and `tfem_get_warning`, are the only failed calls that write an
    !! output: see the conventions at the top.)
    function tfem_last_error(model, buffer, length) &
        bind(C, name="tfem_last_error") result(status)
      import
      type(c_ptr), value :: model
      character(kind=c_char), intent(inout) :: buffer(*)
      integer(c_size_t), value :: length
      integer(c_int) :: status
    end function tfem_last_error

    !> Size in bytes (including the final NUL) of the message `tfem_last_error` would give. `model`
    !! may be NULL (thread's last error).
    function tfem_last_error_length(model) &
        bind(C, name="tfem_last_error_length") result(res)
      import
      type(c_ptr), value :: model
      integer(c_size_t) :: res
    end function tfem_last_error_length

    !> Number of warnings: mesh validation (unused or coincident nodes, inverted or clockwise
    !! triangles), what `tfem_add_contact_pairs_auto` left out (a tag whose edges bound several
    !! bodies, an interface found again under other tags: kept until the pairs are cleared, the
    !! boundary edges set anew or the mesh replaced) and the last solve or load step (tempering of
    !! well-shaped elements, an ill-conditioned system, contact pressures with fewer than six
    !! correct digits: a penalty E_c so stiff that its overlaps approach the rounding of the
    !! displacements; after `tfem_solve` or `tfem_solve_contact`, a body's reactions with fewer than
    !! six correct digits: a "rigid" body modelled with a huge Young's modulus; a one-sided contact
    !! zone). The pairing warnings outlive solves.
    function tfem_warning_count(model, count) &
        bind(C, name="tfem_warning_count") result(status)
      import
      type(c_ptr), value :: model
      integer(c_int), intent(inout) :: count
      integer(c_int) :: status
    end function tfem_warning_count

    !> Writes to `size` the size in bytes (including the final NUL) of warning number `index`
    !! (0-based, whatever the index base): a buffer of this size holds all of it in
    !! `tfem_get_warning`. An index out of range is refused (TFEM_STATUS_INVALID_ARGUMENT), `size`
    !! unchanged.
    function tfem_get_warning_size(model, index, size) &
        bind(C, name="tfem_get_warning_size") result(status)
      import
      type(c_ptr), value :: model
      integer(c_int), value :: index
      integer(c_size_t), intent(inout) :: size
      integer(c_int) :: status
    end function tfem_get_warning_size

    !> Copies warning number `index` (0-based, whatever the index base) into `buffer` of `length`
    !! bytes, truncating like `tfem_last_error` (`tfem_get_warning_size` gives the size needed): the
    !! truncated warning is written with TFEM_STATUS_BUFFER_TOO_SMALL; on any other error (an index
    !! out of range) `buffer` is unchanged.
    function tfem_get_warning(model, index, buffer, length) &
        bind(C, name="tfem_get_warning") result(status)
      import
      type(c_ptr), value :: model
      integer(c_int), value :: index
      character(kind=c_char), intent(inout) :: buffer(*)
      integer(c_size_t), value :: length
      integer(c_int) :: status
    end function tfem_get_warning

    !> Sets the number of threads the model's solves run on: 1 <= `threads` <= 1024 gives the model
    !! a pool of its own (1: no parallelism at all, for a host that runs its own OpenMP or MPI
    !! threads); 0 (the default) uses the process-wide pool, with as many threads as cores or the
    !! environment variable RAYON_NUM_THREADS. Results do not depend on it beyond round-off, and are
    !! kept.
    function tfem_set_threads(model, threads) &
        bind(C, name="tfem_set_threads") result(status)
      import
      type(c_ptr), value :: model
      integer(c_int), value :: threads
      integer(c_int) :: status
    end function tfem_set_threads

    !> Writes the number of threads the model's solves run on (see `tfem_set_threads`).
    function tfem_get_threads(model, threads) &
        bind(C, name="tfem_get_threads") result(status)
      import
      type(c_ptr), value :: model
      integer(c_int), intent(inout) :: threads
      integer(c_int) :: status
    end function tfem_get_threads

    ! ==============================================================================================
    ! Mesh: nodes, triangles and their bodies (tfem_set_mesh, or a Gmsh file), and the tagged
    ! boundary edges that loads, constraints and contact pairs name.
    ! ==============================================================================================

    !> Sets the mesh: `n_nodes` nodes with coordinates `xy` (2·n_nodes values, x0 y0 x1 y1 …),
    !! `n_triangles` P1 triangles with `connectivity` (3·n_triangles node indices) and a body tag
    !! per triangle in `body_of_triangle`. `index_base` is 0 (C) or 1 (Fortran) and applies to every
    !! index of every later call. Orientation: triangles may be numbered clockwise,
    !! counter-clockwise, or both; each connected region of a body is numbered consistently across
    !! its shared edges and turned counter-clockwise by area (a warning counts the triangles turned;
    !! every later output refers to the turned triangles). A triangle still clockwise then is a fold
    !! of the mesh, an inverted element, which TFEM tempers (a warning counts them). Degenerate
    !! triangles are legal. Coordinates whose products overflow double precision are refused.
    !! Replacing a mesh discards constraints, loads, contact pairs and results; materials and
    !! tempering are kept.
    function tfem_set_mesh(model, n_nodes, xy, n_triangles, connectivity, body_of_triangle, index_base) &
        bind(C, name="tfem_set_mesh") result(status)
      import
      type(c_ptr), value :: model
      integer(c_int), value :: n_nodes
      real(c_double), intent(in) :: xy(*)
      integer(c_int), value :: n_triangles
      integer(c_int), intent(in) :: connectivity(*)
      integer(c_int), intent(in) :: body_of_triangle(*)
      integer(c_int), value :: index_base
      integer(c_int) :: status
    end function tfem_set_mesh

    !> Loads a Gmsh MSH 4.1 mesh (ASCII or binary) from the file `path` (NUL-terminated; on Unix any
    !! bytes, as the file system takes them, elsewhere UTF-8): physical surfaces become bodies (tag
    !! = body), physical curves become boundary-edge tags (a curve in several groups under each of
    !! their tags; a surface in several is the body of the first, and physical points are not used:
    !! a warning names both); only 3-node triangles and 2-node lines, in the plane z = 0. Replaces
    !! the mesh like `tfem_set_mesh` with the given `index_base` for later calls: node i is the i-th
    !! node of the file's `$Nodes` section, whatever its Gmsh tag (`tfem_get_mesh_nodes`,
    !! `tfem_get_mesh_triangles` and `tfem_get_boundary_edges` read the mesh back). Returns
    !! TFEM_STATUS_IO for an unreadable or malformed file, TFEM_STATUS_INVALID_MESH for unsupported
    !! content: another version of the format (MSH 2.2, 4.0, …; the message says how to convert the
    !! file: `gmsh old.msh -save -format msh41 -o new.msh`; TFEM_STATUS_IO in earlier versions), an
    !! element type other than those above, a node off the plane, a triangle with a repeated node
    !! (an error about an element or a node names its entity and physical group: tag, and name from
    !! `$PhysicalNames`); TFEM_STATUS_INVALID_ARGUMENT if the library was built without the `gmsh`
    !! feature. On error the model is unchanged.
    function tfem_load_gmsh(model, path, index_base) &
        bind(C, name="tfem_load_gmsh") result(status)
      import
      type(c_ptr), value :: model
      character(kind=c_char), intent(in) :: path(*)
      integer(c_int), value :: index_base
      integer(c_int) :: status
    end function tfem_load_gmsh

    !> Sets the tagged boundary edges: `n_edges` edges given by `edge_nodes` (2·n_edges node
    !! indices) with a tag each in `tags`. Tags name the edges for loads, constraints and contact
    !! pairs. Replaces previous edges (use `tfem_add_boundary_edges` to add one group at a time).
    !! Refused, naming the tag, when a load or contact pair already declared would lose its edges or
    !! find them interior (an edge shared by two triangles can carry a constraint, not a load or a
    !! contact interface); on any error nothing changes.
    function tfem_set_boundary_edges(model, n_edges, edge_nodes, tags) &
        bind(C, name="tfem_set_boundary_edges") result(status)
      import
      type(c_ptr), value :: model
      integer(c_int), value :: n_edges
      integer(c_int), intent(in) :: edge_nodes(*)
      integer(c_int), intent(in) :: tags(*)
      integer(c_int) :: status
    end function tfem_set_boundary_edges

    !> Adds tagged boundary edges to those already set (see `tfem_set_boundary_edges`): `n_edges`
    !! edges given by `edge_nodes` (2·n_edges node indices) with a tag each in `tags`, for instance
    !! one call per boundary group. An edge given again with a tag it already has is refused (its
    !! loads would count twice); on any error nothing changes.
    function tfem_add_boundary_edges(model, n_edges, edge_nodes, tags) &
        bind(C, name="tfem_add_boundary_edges") result(status)
      import
      type(c_ptr), value :: model
      integer(c_int), value :: n_edges
      integer(c_int), intent(in) :: edge_nodes(*)
      integer(c_int), intent(in) :: tags(*)
      integer(c_int) :: status
    end function tfem_add_boundary_edges

    !> Sizes: nodes, triangles, and elements of the contact mesh of the last contact solve (0
    !! otherwise). Any pointer may be NULL.
    function tfem_get_sizes(model, n_nodes, n_triangles, n_contact_elements) &
        bind(C, name="tfem_get_sizes") result(status)
      import
      type(c_ptr), value :: model
      integer(c_int), intent(inout) :: n_nodes
      integer(c_int), intent(inout) :: n_triangles
      integer(c_int), intent(inout) :: n_contact_elements
      integer(c_int) :: status
    end function tfem_get_sizes

    !> Number of boundary edges the model holds (each with its tag), from `tfem_set_boundary_edges`
    !! / `tfem_add_boundary_edges` or a Gmsh file's physical lines; see `tfem_get_boundary_edges`.
    function tfem_get_boundary_edge_count(model, count) &
        bind(C, name="tfem_get_boundary_edge_count") result(status)
      import
      type(c_ptr), value :: model
      integer(c_int), intent(inout) :: count
      integer(c_int) :: status
    end function tfem_get_boundary_edge_count

    !> Copies the node coordinates the model holds (x0 y0 x1 y1 …, 2·n_nodes values, n_nodes from
    !! `tfem_get_sizes`) into `xy` of `length` values. After `tfem_load_gmsh` node i (in the model's
    !! index base) is the i-th node of the file's `$Nodes` section, whatever its Gmsh tag.
    function tfem_get_mesh_nodes(model, xy, length) &
        bind(C, name="tfem_get_mesh_nodes") result(status)
      import
      type(c_ptr), value :: model
      real(c_double), intent(inout) :: xy(*)
      integer(c_size_t), value :: length
      integer(c_int) :: status
    end function tfem_get_mesh_nodes

    !> Copies the triangles the model holds (3·n_triangles node indices in the model's index base,
    !! n_triangles from `tfem_get_sizes`) into `triangles` of `length` values and each triangle's
    !! body tag into `bodies` of `bodies_length` values; `bodies` may be NULL. Triangles given
    !! clockwise are held (and copied) counter-clockwise. Nothing is written unless both buffers are
    !! large enough.
    function tfem_get_mesh_triangles(model, triangles, length, bodies, bodies_length) &
        bind(C, name="tfem_get_mesh_triangles") result(status)
      import
      type(c_ptr), value :: model
      integer(c_int), intent(inout) :: triangles(*)
      integer(c_size_t), value :: length
      integer(c_int), intent(inout) :: bodies(*)
      integer(c_size_t), value :: bodies_length
      integer(c_int) :: status
    end function tfem_get_mesh_triangles

    !> Copies the boundary edges the model holds (2·count node indices in the model's index base,
    !! count from `tfem_get_boundary_edge_count`) into `edges` of `length` values and each edge's
    !! tag into `tags` of `tags_length` values, in the order they were given (a Gmsh file's: its
    !! line elements, by physical group); `tags` may be NULL. Nothing is written unless both buffers
    !! are large enough.
    function tfem_get_boundary_edges(model, edges, length, tags, tags_length) &
        bind(C, name="tfem_get_boundary_edges") result(status)
      import
      type(c_ptr), value :: model
      integer(c_int), intent(inout) :: edges(*)
      integer(c_size_t), value :: length
      integer(c_int), intent(inout) :: tags(*)
      integer(c_size_t), value :: tags_length
      integer(c_int) :: status
    end function tfem_get_boundary_edges

    ! ==============================================================================================
    ! Materials, tempering and ordering: one material per body; the tempering of degenerate
    ! triangles; the fill-reducing ordering.
    ! ==============================================================================================

    !> Sets the material of body `body`: Young's modulus `young` (> 0), Poisson ratio `poisson` (in
    !! (-1, 0.5) for plane strain and axisymmetric bodies, (-1, 0.5] for plane stress) and `plane`
    !! (a `PlaneMode`: 0 strain, 1 stress, 2 axisymmetric). Axisymmetric bodies (x the radius, y the
    !! axis) do not mix with plane ones, lie at x >= 0, need u_r = 0 fixed on nodes on the axis
    !! (checked by the solve) and take the whole ring's forces: nodal forces and reactions are
    !! totals around the circumference, pressures and tractions per unit area (docs/method.md §7).
    function tfem_set_material(model, body, young, poisson, plane_mode) &
        bind(C, name="tfem_set_material") result(status)
      import
      type(c_ptr), value :: model
      integer(c_int), value :: body
      real(c_double), value :: young
      real(c_double), value :: poisson
      integer(c_int), value :: plane_mode
      integer(c_int) :: status
    end function tfem_set_material

    !> Chooses Jmin: `mode` is a `TemperingMode` (0 auto, 1 lambda = `value`, 2 fixed Jmin =
    !! `value`, 3 off); `value` is ignored for 0 and 3.
    function tfem_set_tempering(model, mode, value) &
        bind(C, name="tfem_set_tempering") result(status)
      import
      type(c_ptr), value :: model
      integer(c_int), value :: mode
      real(c_double), value :: value
      integer(c_int) :: status
    end function tfem_set_tempering

    !> Chooses the fill-reducing ordering: `ordering` is an `OrderingMode` (0 auto, 1 AMD, 2 nested
    !! dissection); `parallel_subtrees` = 1 (default) factorises the two subtrees of a nested
    !! dissection concurrently, 0 as one tree. Results do not depend on either beyond round-off: the
    !! results of the last solve (all of them, the matrix included) are kept, and the next solve
    !! analyses the matrix anew.
    function tfem_set_ordering(model, ordering, parallel_subtrees) &
        bind(C, name="tfem_set_ordering") result(status)
      import
      type(c_ptr), value :: model
      integer(c_int), value :: ordering
      integer(c_int), value :: parallel_subtrees
      integer(c_int) :: status
    end function tfem_set_ordering

    ! ==============================================================================================
    ! Loads and constraints: prescribed displacements per node or per tag, and their values changed
    ! along a load history; pressures, tractions, nodal and body forces.
    ! ==============================================================================================

    !> Prescribes displacement component `component` (0 x, 1 y) of `node` to `value` (model length
    !! units). A component already prescribed a different value is refused
    !! (TFEM_STATUS_INVALID_ARGUMENT naming the node): one of the two would silently win. Call
    !! `tfem_clear_constraints` to change prescribed values.
    function tfem_fix(model, node, comp, value) &
        bind(C, name="tfem_fix") result(status)
      import
      type(c_ptr), value :: model
      integer(c_int), value :: node
      integer(c_int), value :: comp
      real(c_double), value :: value
      integer(c_int) :: status
    end function tfem_fix

    !> Prescribes component `component` to `value` on every node of the boundary edges tagged `tag`
    !! (interior edges too). All or nothing: a node already prescribed a different value (see
    !! `tfem_fix`) refuses the whole call.
    function tfem_fix_edges(model, tag, comp, value) &
        bind(C, name="tfem_fix_edges") result(status)
      import
      type(c_ptr), value :: model
      integer(c_int), value :: tag
      integer(c_int), value :: comp
      real(c_double), value :: value
      integer(c_int) :: status
    end function tfem_fix_edges

    !> Changes the value of displacement component `comp` (0 x, 1 y) of `node`, prescribed before by
    !! `tfem_fix` or `tfem_fix_edges`: the loads of a non-proportional load history, which goes on
    !! with the same factorisation (the set of prescribed DOFs is unchanged). A node not prescribed
    !! in that component is refused, naming it.
    function tfem_set_prescribed(model, node, comp, value) &
        bind(C, name="tfem_set_prescribed") result(status)
      import
      type(c_ptr), value :: model
      integer(c_int), value :: node
      integer(c_int), value :: comp
      real(c_double), value :: value
      integer(c_int) :: status
    end function tfem_set_prescribed

    !> Changes the value of displacement component `comp` (0 x, 1 y) on every node of the boundary
    !! edges tagged `tag`, each prescribed before by `tfem_fix_edges` or `tfem_fix`:
    !! `tfem_set_prescribed` for a whole tag, the loads of a load history given as `tfem_fix_edges`
    !! gives them (the factorisation is kept). All or nothing: an unknown tag, a value that is not
    !! finite or a node not prescribed in that component is refused (TFEM_STATUS_INVALID_ARGUMENT
    !! naming it) and the model is unchanged.
    function tfem_set_prescribed_edges(model, tag, comp, value) &
        bind(C, name="tfem_set_prescribed_edges") result(status)
      import
      type(c_ptr), value :: model
      integer(c_int), value :: tag
      integer(c_int), value :: comp
      real(c_double), value :: value
      integer(c_int) :: status
    end function tfem_set_prescribed_edges

    !> Removes every prescribed displacement.
    function tfem_clear_constraints(model) &
        bind(C, name="tfem_clear_constraints") result(status)
      import
      type(c_ptr), value :: model
      integer(c_int) :: status
    end function tfem_clear_constraints

    !> Declares that the boundary edges tagged `tag` lie on the circle of centre (`center_x`,
    !! `center_y`) and radius `radius` (> 0), so that `tfem_solve_adaptive` puts the nodes it adds
    !! on those edges on the circle rather than at the chords' midpoints: the refined boundary then
    !! converges to the circle (a cylinder's contact, a ring's bore). It replaces a curve declared
    !! on the tag before and changes nothing of a solve. Refused, nothing changed, if the circle is
    !! ill defined, no edge has the tag, or a node of its edges lies farther than 1e-6·radius from
    !! the circle (the message names the node).
    function tfem_set_boundary_circle(model, tag, center_x, center_y, radius) &
        bind(C, name="tfem_set_boundary_circle") result(status)
      import
      type(c_ptr), value :: model
      integer(c_int), value :: tag
      real(c_double), value :: center_x
      real(c_double), value :: center_y
      real(c_double), value :: radius
      integer(c_int) :: status
    end function tfem_set_boundary_circle

    !> Applies pressure `pressure` on the boundary edges tagged `tag`: a stress (force per unit
    !! area, Pa in SI), positive pushing into the body; with the 2D convention of unit thickness, an
    !! edge of length ℓ carries the force ℓ·pressure per unit thickness (axisymmetric bodies: the
    !! whole ring's, ∫ pressure·2πr ds). Loads add up.
    function tfem_add_pressure(model, tag, pressure) &
        bind(C, name="tfem_add_pressure") result(status)
      import
      type(c_ptr), value :: model
      integer(c_int), value :: tag
      real(c_double), value :: pressure
      integer(c_int) :: status
    end function tfem_add_pressure

    !> Applies the traction (tx, ty) on the boundary edges tagged `tag`: a stress vector (force per
    !! unit area, Pa in SI); an edge of length ℓ carries ℓ·(tx, ty) per unit thickness (axisymmetric
    !! bodies: the whole ring's, ∫ (tx, ty)·2πr ds). Loads add up.
    function tfem_add_traction(model, tag, tx, ty) &
        bind(C, name="tfem_add_traction") result(status)
      import
      type(c_ptr), value :: model
      integer(c_int), value :: tag
      real(c_double), value :: tx
      real(c_double), value :: ty
      integer(c_int) :: status
    end function tfem_add_traction

    !> Adds the point force (fx, fy) at `node`: force per unit thickness (N/m in SI; axisymmetric
    !! bodies: the total force on the node's ring, N). Loads add up.
    function tfem_add_nodal_force(model, node, fx, fy) &
        bind(C, name="tfem_add_nodal_force") result(status)
      import
      type(c_ptr), value :: model
      integer(c_int), value :: node
      real(c_double), value :: fx
      real(c_double), value :: fy
      integer(c_int) :: status
    end function tfem_add_nodal_force

    !> Sets the body force (bx, by) of body `body`: force per unit volume (ρg, N/m³ in SI), acting
    !! on each unit area of the mesh per unit thickness (axisymmetric bodies: on the whole ring's
    !! volume).
    function tfem_set_body_force(model, body, bx, by) &
        bind(C, name="tfem_set_body_force") result(status)
      import
      type(c_ptr), value :: model
      integer(c_int), value :: body
      real(c_double), value :: bx
      real(c_double), value :: by
      integer(c_int) :: status
    end function tfem_set_body_force

    !> Removes every load.
    function tfem_clear_loads(model) &
        bind(C, name="tfem_clear_loads") result(status)
      import
      type(c_ptr), value :: model
      integer(c_int) :: status
    end function tfem_clear_loads

    ! ==============================================================================================
    ! Contact pairs: the interfaces between bodies (declared, or found by
    ! tfem_add_contact_pairs_auto), their friction and weighting, and the contact mesh B the strip
    ! weighting makes. These are the model's own contact pairs, solved by tfem_solve_contact and
    ! tfem_step; a host code with its own elements and solver uses the contact context
    ! (tfem_contact_*) at the end of the header instead.
    ! ==============================================================================================

    !> Declares a potential contact interface between the boundary edges tagged `tag_a` (one body)
    !! and `tag_b` (another body). The contact mesh B is built from matching nodes when they match
    !! (a small normal gap is allowed), else by triangulating the strip between the two interfaces
    !! (each must be one open chain of edges). Writes the pair's index (0-based) to `pair` (may be
    !! NULL). A pair declared already, or one whose tags share boundary edges with both tags of a
    !! declared pair (the same interface under other tags, which would count twice), is refused with
    !! TFEM_STATUS_INVALID_CONTACT.
    function tfem_add_contact_pair(model, tag_a, tag_b, pair) &
        bind(C, name="tfem_add_contact_pair") result(status)
      import
      type(c_ptr), value :: model
      integer(c_int), value :: tag_a
      integer(c_int), value :: tag_b
      integer(c_int), intent(inout) :: pair
      integer(c_int) :: status
    end function tfem_add_contact_pair

    !> Declares a contact pair with a user-made contact mesh B: `n_triangles` triangles in
    !! `connectivity` (3 per triangle) over nodes of the two interfaces. Wrongly oriented triangles
    !! are flipped; their number goes to `flipped` (may be NULL), the pair's index to `pair` (may be
    !! NULL). A triangle given twice (the same three nodes, in any order) is refused with
    !! TFEM_STATUS_INVALID_CONTACT naming both triangles. The triangles are the contact: a pair of
    !! tags declared already, or sharing edges with a declared pair, is not refused here (several
    !! meshes may cover parts of one interface), so do not give a part twice.
    function tfem_add_contact_pair_with_mesh(model, tag_a, tag_b, n_triangles, connectivity, pair, &
        flipped) &
        bind(C, name="tfem_add_contact_pair_with_mesh") result(status)
      import
      type(c_ptr), value :: model
      integer(c_int), value :: tag_a
      integer(c_int), value :: tag_b
      integer(c_int), value :: n_triangles
      integer(c_int), intent(in) :: connectivity(*)
      integer(c_int), intent(inout) :: pair
      integer(c_int), intent(inout) :: flipped
      integer(c_int) :: status
    end function tfem_add_contact_pair_with_mesh

    !> Declares a contact pair for every two boundary tags of different bodies whose edges face each
    !! other within `tolerance` (model length units: some edge of the one within `tolerance` of some
    !! edge of the other, outward normals opposed within 30°, each in front of the other,
    !! overlapping along the interface, no third body between them; a gap of exactly `tolerance`
    !! pairs; docs/method.md §6.16). `tags` (`n_tags` values) restricts the search to those tags;
    !! with `n_tags` = 0 every tag that can be a contact side is considered, and `tags` may be NULL.
    !! Pairs already declared are skipped, tags of one body never pair, and an interface found again
    !! under tags that share its edges with a pair kept (a "whole boundary" group beside the faces)
    !! is skipped: the pair of tags with the fewest edges is kept (to pair an interface under other
    !! tags, declare that pair by hand instead). What is left out without an error — with `n_tags` =
    !! 0, a tag whose edges bound several bodies; an interface found again under other tags — is
    !! named in a warning (`tfem_warning_count`, `tfem_get_warning`). The pairs added get
    !! consecutive indices: writes the first to `first` (may be NULL) and their number, 0 when
    !! nothing faces within the tolerance, to `count` (may be NULL). A negative or non-finite
    !! tolerance, an unknown tag or an interface whose contact mesh cannot be built is refused,
    !! naming it, and nothing is added.
    function tfem_add_contact_pairs_auto(model, n_tags, tags, tolerance, first, count) &
        bind(C, name="tfem_add_contact_pairs_auto") result(status)
      import
      type(c_ptr), value :: model
      integer(c_int), value :: n_tags
      integer(c_int), intent(in) :: tags(*)
      real(c_double), value :: tolerance
      integer(c_int), intent(inout) :: first
      integer(c_int), intent(inout) :: count
      integer(c_int) :: status
    end function tfem_add_contact_pairs_auto

    !> Sets Coulomb's friction coefficient μ ≥ 0 of contact pair `pair` (0-based, from
    !! `tfem_add_contact_pair`): stick while the shear stays within μ times the pressure, slip
    !! against the slip of the step beyond (docs/method.md §6.15). 0, the default, is frictionless,
    !! bit for bit. A negative or non-finite μ, or an unknown pair, is refused
    !! (TFEM_STATUS_INVALID_ARGUMENT naming it). Changing μ starts a new load history. Frictional or
    !! not, the elements of a pair's contact mesh measure every point of the interface along the
    !! first side's normal there, so that a frictionless interface transmits no tangential traction.
    function tfem_set_friction(model, pair, mu) &
        bind(C, name="tfem_set_friction") result(status)
      import
      type(c_ptr), value :: model
      integer(c_int), value :: pair
      real(c_double), value :: mu
      integer(c_int) :: status
    end function tfem_set_friction

    !> Chooses how the contact pairs' energy is weighted along their interfaces: `weighting` is a
    !! `ContactWeightingMode`. 2 automatic, the default: each pair what is right for it — the
    !! elements of the contact mesh B (the seed's method) where the two sides' nodes match, one
    !! weighted gap per node of the interface's coarser side where they do not (exact on the contact
    !! patch test whatever the meshes, converging on curved interfaces where B reads one side only),
    !! B for a pair with friction or a contact mesh of its own. 0 strip and 1 mortar force one
    !! weighting on every pair (an expert's override). A change discards the results, like any
    !! change of the contact pairs. The mortar weighting is frictionless and makes no mesh B:
    !! forcing it with a pair that has friction or a contact mesh of its own, or giving such a pair
    !! under it, is refused by that call (TFEM_ERR_ARGUMENT, naming the pair); a solve under it with
    !! the stick law or the literal inversion test is refused too. The per-element outputs
    !! (`tfem_get_contact_active`, `tfem_get_contact_pressure`, `tfem_get_contact_elements`, shear,
    !! friction state, dissipation; `tfem_get_sizes`' contact elements) cover the pairs weighted by
    !! B, and are refused when no pair is (`tfem_get_contact_mesh` still gives the B the pairs would
    !! make); the state of the others is per slave node (`tfem_get_contact_slave_nodes`). Nodal
    !! pressures, gaps and forces, reactions and the report cover every pair, the report's
    !! `elements` counting elements of B and slave nodes.
    function tfem_set_contact_weighting(model, weighting) &
        bind(C, name="tfem_set_contact_weighting") result(status)
      import
      type(c_ptr), value :: model
      integer(c_int), value :: weighting
      integer(c_int) :: status
    end function tfem_set_contact_weighting

    !> Writes the contact weighting (a `ContactWeightingMode`: 0 strip, 1 mortar, 2 automatic, the
    !! default) into `*weighting`.
    function tfem_get_contact_weighting(model, weighting) &
        bind(C, name="tfem_get_contact_weighting") result(status)
      import
      type(c_ptr), value :: model
      integer(c_int), intent(inout) :: weighting
      integer(c_int) :: status
    end function tfem_get_contact_weighting

    !> Writes the number of elements of the contact mesh B of the declared contact pairs, available
    !! before any solve (0 without pairs).
    function tfem_get_contact_mesh_size(model, n_elements) &
        bind(C, name="tfem_get_contact_mesh_size") result(status)
      import
      type(c_ptr), value :: model
      integer(c_int), intent(inout) :: n_elements
      integer(c_int) :: status
    end function tfem_get_contact_mesh_size

    !> Copies the nodes of every element of the contact mesh B of the declared contact pairs (3 per
    !! element, in the model's index base, oriented so that J > 0 when the gap opens), available
    !! before any solve: the same elements, in the same order, as `tfem_get_contact_elements` gives
    !! after a contact solve.
    function tfem_get_contact_mesh(model, out, length) &
        bind(C, name="tfem_get_contact_mesh") result(status)
      import
      type(c_ptr), value :: model
      integer(c_int), intent(inout) :: out(*)
      integer(c_size_t), value :: length
      integer(c_int) :: status
    end function tfem_get_contact_mesh

    !> Copies, for every element of the contact mesh B (see `tfem_get_contact_mesh`), the index of
    !! its contact pair (0-based, as returned by `tfem_add_contact_pair`, whatever the index base).
    function tfem_get_contact_element_pairs(model, out, length) &
        bind(C, name="tfem_get_contact_element_pairs") result(status)
      import
      type(c_ptr), value :: model
      integer(c_int), intent(inout) :: out(*)
      integer(c_size_t), value :: length
      integer(c_int) :: status
    end function tfem_get_contact_element_pairs

    !> Copies, for every element of the contact mesh B (see `tfem_get_contact_mesh`), its apex: the
    !! node (in the model's index base) alone on its side of the interface, whose distance from the
    !! element's interface edge is the element's gap.
    function tfem_get_contact_element_apexes(model, out, length) &
        bind(C, name="tfem_get_contact_element_apexes") result(status)
      import
      type(c_ptr), value :: model
      integer(c_int), intent(inout) :: out(*)
      integer(c_size_t), value :: length
      integer(c_int) :: status
    end function tfem_get_contact_element_apexes

    !> Writes the bodies of contact pair `pair` (0-based, as returned by `tfem_add_contact_pair`):
    !! `body_a` carries the pair's first tag, `body_b` its second. Either pointer may be NULL.
    function tfem_get_contact_pair_bodies(model, pair, body_a, body_b) &
        bind(C, name="tfem_get_contact_pair_bodies") result(status)
      import
      type(c_ptr), value :: model
      integer(c_int), value :: pair
      integer(c_int), intent(inout) :: body_a
      integer(c_int), intent(inout) :: body_b
      integer(c_int) :: status
    end function tfem_get_contact_pair_bodies

    ! ==============================================================================================
    ! Solve: without contact (tfem_solve) or with it (tfem_solve_contact, one load; tfem_step for a
    ! load history, below).
    ! ==============================================================================================

    !> Fills `options` with the defaults: frictionless law, E_c and λ derived from the model,
    !! linearised inversion test, 50 iterations.
    function tfem_contact_options_default(options) &
        bind(C, name="tfem_contact_options_default") result(status)
      import
      type(tfem_contact_options), intent(inout) :: options
      integer(c_int) :: status
    end function tfem_contact_options_default

    !> Solves a scene without contact. `info` may be NULL. A body that is not restrained gives
    !! TFEM_STATUS_SINGULAR naming it. A model with every DOF prescribed has nothing to solve:
    !! TFEM_STATUS_INVALID_STATE; so also `tfem_solve_contact` and `tfem_step`.
    function tfem_solve(model, info) &
        bind(C, name="tfem_solve") result(status)
      import
      type(c_ptr), value :: model
      type(tfem_solve_info), intent(inout) :: info
      integer(c_int) :: status
    end function tfem_solve

    !> Solves the contact problem by the active-set loop over inverted contact elements (under the
    !! mortar weighting, `tfem_set_contact_weighting`, over the slave nodes whose weighted gap is
    !! negative). `options` may be NULL (defaults); `report` may be NULL. TFEM_STATUS_NOT_CONVERGED
    !! (cycle or iteration cap) gives the history in the message; the model is then unchanged. Every
    !! DOF prescribed: TFEM_STATUS_INVALID_STATE.
    function tfem_solve_contact(model, options, report) &
        bind(C, name="tfem_solve_contact") result(status)
      import
      type(c_ptr), value :: model
      type(tfem_contact_options), intent(in) :: options
      type(tfem_contact_report), intent(inout) :: report
      integer(c_int) :: status
    end function tfem_solve_contact

    !> Solves to a tolerance (docs/method.md §8): solve (a contact solve with the `contact` options
    !! when the model has pairs), estimate the error by stress recovery, refine the triangles
    !! holding half of it by newest-vertex bisection, and again, until the estimated relative error
    !! of `goal` (an `AdaptGoal`: 0 energy norm, 1 compliance) is at most `tolerance` (> 0) — and,
    !! with contact, the edges of the contact zones are located to `tolerance` of the contact length
    !! (the interface edges pressed at one end only refined until shorter) — or the next mesh would
    !! exceed `max_unknowns`, or `max_cycles` solves are done (either is a warning with the estimate
    !! reached, `tfem_get_warning`, and TFEM_STATUS_OK). The model keeps the refined mesh — the
    !! given nodes keep their indices, new ones follow; read it back with `tfem_get_sizes`,
    !! `tfem_get_mesh_nodes`, `tfem_get_mesh_triangles` and `tfem_get_boundary_edges` — its loads,
    !! constraints and pairs carried over, and the last solve's results. New nodes on edges whose
    !! tag has a circle (`tfem_set_boundary_circle`) go on the circle, and a curved interface's
    !! facing edges are bisected together. `contact` may be NULL (the default options); `report` may
    !! be NULL. Bad arguments change nothing; a failed solve restores the model as it was given.
    function tfem_solve_adaptive(model, tolerance, goal, max_unknowns, max_cycles, contact, report) &
        bind(C, name="tfem_solve_adaptive") result(status)
      import
      type(c_ptr), value :: model
      real(c_double), value :: tolerance
      integer(c_int), value :: goal
      integer(c_int64_t), value :: max_unknowns
      integer(c_int), value :: max_cycles
      type(tfem_contact_options), intent(in) :: contact
      type(tfem_adapt_report), intent(inout) :: report
      integer(c_int) :: status
    end function tfem_solve_adaptive

    !> Copies each cycle of the last successful `tfem_solve_adaptive` (`cycles` of its report): its
    !! unknowns, its estimated relative error and its seconds (solve and estimate), into arrays of
    !! `length` values each: `unknowns` may be NULL, `estimates` may be NULL, `seconds` may be NULL.
    !! Nothing is written unless `length` holds every cycle.
    function tfem_get_adapt_cycles(model, unknowns, estimates, seconds, length) &
        bind(C, name="tfem_get_adapt_cycles") result(status)
      import
      type(c_ptr), value :: model
      integer(c_int64_t), intent(inout) :: unknowns
      real(c_double), intent(inout) :: estimates
      real(c_double), intent(inout) :: seconds(*)
      integer(c_size_t), value :: length
      integer(c_int) :: status
    end function tfem_get_adapt_cycles

    ! ==============================================================================================
    ! Results of the last solve or step: displacements, strains, stresses, reactions, external work,
    ! and the VTU file.
    ! ==============================================================================================

    !> Copies the nodal displacements (u0 v0 u1 v1 …, 2·n_nodes values) of the last solve into `out`
    !! of `length` values.
    function tfem_get_displacements(model, out, length) &
        bind(C, name="tfem_get_displacements") result(status)
      import
      type(c_ptr), value :: model
      real(c_double), intent(inout) :: out(*)
      integer(c_size_t), value :: length
      integer(c_int) :: status
    end function tfem_get_displacements

    !> Copies element strains (ε_xx ε_yy γ_xy per triangle, engineering shear, 3·n_triangles
    !! values), computed on request.
    function tfem_get_element_strains(model, out, length) &
        bind(C, name="tfem_get_element_strains") result(status)
      import
      type(c_ptr), value :: model
      real(c_double), intent(inout) :: out(*)
      integer(c_size_t), value :: length
      integer(c_int) :: status
    end function tfem_get_element_strains

    !> Copies element stresses (σ_xx σ_yy σ_xy per triangle, 3·n_triangles values; force per unit
    !! area, Pa in SI), computed on request. An overflow gives TFEM_STATUS_NUMERICAL_FAILURE naming
    !! the triangle.
    function tfem_get_element_stresses(model, out, length) &
        bind(C, name="tfem_get_element_stresses") result(status)
      import
      type(c_ptr), value :: model
      real(c_double), intent(inout) :: out(*)
      integer(c_size_t), value :: length
      integer(c_int) :: status
    end function tfem_get_element_stresses

    !> Copies each triangle's stress normal to the mesh's plane (n_triangles values), computed on
    !! request: the hoop stress σ_θθ of axisymmetric bodies, σ_zz = λ(ε_xx + ε_yy) in plane strain,
    !! 0 in plane stress.
    function tfem_get_element_out_of_plane_stresses(model, out, length) &
        bind(C, name="tfem_get_element_out_of_plane_stresses") result(status)
      import
      type(c_ptr), value :: model
      real(c_double), intent(inout) :: out(*)
      integer(c_size_t), value :: length
      integer(c_int) :: status
    end function tfem_get_element_out_of_plane_stresses

    !> Copies J (twice the signed area, initial configuration) of every triangle as stored, that is
    !! after the turning of triangles numbered clockwise (see `tfem_set_mesh`): negative only for
    !! the mesh's folds (n_triangles values). Needs only a mesh.
    function tfem_get_element_jacobians(model, out, length) &
        bind(C, name="tfem_get_element_jacobians") result(status)
      import
      type(c_ptr), value :: model
      real(c_double), intent(inout) :: out(*)
      integer(c_size_t), value :: length
      integer(c_int) :: status
    end function tfem_get_element_jacobians

    !> Copies reaction forces (Rx Ry per node, 2·n_nodes values; force per unit thickness, N/m in
    !! SI; zero at DOFs that are not prescribed), computed on request. `tfem_solve` and
    !! `tfem_solve_contact` bound their rounding per body and warn (`tfem_get_warning`), naming the
    !! body, where its reactions may carry fewer than six correct digits (a "rigid" body given a
    !! huge Young's modulus: prescribe its motion with a modulus like its neighbours' instead).
    function tfem_get_reactions(model, out, length) &
        bind(C, name="tfem_get_reactions") result(status)
      import
      type(c_ptr), value :: model
      real(c_double), intent(inout) :: out(*)
      integer(c_size_t), value :: length
      integer(c_int) :: status
    end function tfem_get_reactions

    !> Writes the work of the external loads of the last solve, Σ f·u over every node (force ×
    !! length per unit thickness, J/m in SI; axisymmetric bodies: the whole ring's, J): for a
    !! pressure load, the compliance ∫ p (−u·n) ds.
    function tfem_get_external_work(model, work) &
        bind(C, name="tfem_get_external_work") result(status)
      import
      type(c_ptr), value :: model
      real(c_double), intent(inout) :: work
      integer(c_int) :: status
    end function tfem_get_external_work

    !> Writes the solved model to the file `path` (NUL-terminated; on Unix any bytes, as for
    !! `tfem_load_gmsh`) as a VTK XML unstructured grid (`.vtu`, read by ParaView, VTK and meshio;
    !! binary: raw appended data, little-endian, UInt64 block headers, no compression): the mesh in
    !! its initial configuration (z = 0) with - point data `displacement` ([u, v, 0]) and, after a
    !! contact solve or load step under either weighting, `contact_pressure` (the nodal pressure of
    !! `tfem_get_contact_nodal_pressures`), `contact_shear` (the nodal shear of
    !! `tfem_get_contact_nodal_tractions`), `contact_force` ([f_x, f_y, 0],
    !! `tfem_get_contact_forces`) and `contact_gap` (`tfem_get_contact_gaps`); none of them after a
    !! solve without contact; - cell data `body` (the body tag), `J` (twice the signed area),
    !! `strain` [ε_xx, ε_yy, γ_xy] and `stress` [σ_xx, σ_yy, σ_xy]; - for the pairs weighted by B,
    !! its elements appended after the body triangles as cells of body −1 (zero strain and stress),
    !! with cell data `contact_element_active` (UInt8, 1 where active) and
    !! `contact_element_pressure` (`tfem_get_contact_active`, `tfem_get_contact_pressure`; 0 on the
    !! body triangles). Pairs under the mortar weighting have no B: their contact is in the nodal
    !! arrays. (Earlier versions named the last two `contact_active` and `contact_pressure`, wrote
    !! them as zeros under the mortar weighting, and wrote no nodal contact array.) Returns
    !! TFEM_STATUS_INVALID_STATE before a solve (nothing is written), TFEM_STATUS_IO when the file
    !! cannot be written (the message names it and the reason), TFEM_STATUS_INVALID_ARGUMENT if the
    !! library was built without the `vtu` feature, and TFEM_STATUS_NUMERICAL_FAILURE (nothing is
    !! written) when a result it holds cannot be computed as the accessors would refuse it: an
    !! overflowing stress, or a load step's field that cannot be recovered to working accuracy,
    !! named in the message. The model is never changed.
    function tfem_write_vtu(model, path) &
        bind(C, name="tfem_write_vtu") result(status)
      import
      type(c_ptr), value :: model
      character(kind=c_char), intent(in) :: path(*)
      integer(c_int) :: status
    end function tfem_write_vtu

    ! ==============================================================================================
    ! Contact results of the last solve or step. Per node, for every pair: forces, pressures and
    ! tractions, gaps. Per element of the contact mesh B (tfem_get_contact_active ... dissipation;
    ! pairs weighted by B): element values at each element's apex. Per slave node (pairs under the
    ! mortar weighting): tfem_get_contact_slave_nodes.
    ! ==============================================================================================

    !> Writes the report of the last contact solve to `report`.
    function tfem_get_contact_report(model, report) &
        bind(C, name="tfem_get_contact_report") result(status)
      import
      type(c_ptr), value :: model
      type(tfem_contact_report), intent(inout) :: report
      integer(c_int) :: status
    end function tfem_get_contact_report

    !> Copies the force the contact exerts on every node in the last contact solve (fx fy per node,
    !! 2·n_nodes values; force per unit thickness, N/m in SI, or the whole ring's for axisymmetric
    !! bodies; zero off the contact interfaces), computed on request. The forces of one pair sum to
    !! zero; on a body they balance its loads and reactions.
    function tfem_get_contact_forces(model, out, length) &
        bind(C, name="tfem_get_contact_forces") result(status)
      import
      type(c_ptr), value :: model
      real(c_double), intent(inout) :: out(*)
      integer(c_size_t), value :: length
      integer(c_int) :: status
    end function tfem_get_contact_forces

    !> Copies the contact pressure at every node in the last contact solve (n_nodes values; force
    !! per unit area, Pa in SI, positive in compression; zero off the contact interfaces), computed
    !! on request: the traction read from both sides of the interface (the mean of a node's normal
    !! contact force over its tributary — the integral of its hat over its interface edges as far as
    !! they face the other side, half its edges where they face it whole — and the other side's
    !! forces over their tributaries near it); where the other side is more than 1.8 times coarser,
    !! a node takes the other side's reading there, interpolated (the coarser side's reading is the
    !! closer to the traction), blended with its own from 1.2 times. Exact for a uniform pressure on
    !! matching and non-matching interfaces alike. Each pair is read with its own forces; a node on
    !! several pairs (where three bodies meet) gets their normal forces over their tributaries
    !! together: the pressure where two pairs continue one face, the tributary-weighted mean of its
    !! faces' pressures at a corner.
    function tfem_get_contact_nodal_pressures(model, out, length) &
        bind(C, name="tfem_get_contact_nodal_pressures") result(status)
      import
      type(c_ptr), value :: model
      real(c_double), intent(inout) :: out(*)
      integer(c_size_t), value :: length
      integer(c_int) :: status
    end function tfem_get_contact_nodal_pressures

    !> Copies the contact traction at every node in the last contact solve or step, as (p, τ) per
    !! node (2·n_nodes values; force per unit area, Pa in SI; zero off the contact interfaces),
    !! computed on request. p is the pressure of `tfem_get_contact_nodal_pressures`, positive in
    !! compression. τ is the tangential traction the other body exerts on the node's body, along t =
    !! (−n_y, n_x) with n the body's outward normal (the direction of travel along a
    !! counter-clockwise boundary), so that both sides of an interface read one traction with one
    !! sign; the vector traction on the node's body is τ t − p n. Each part is the contact law's
    !! own, read along the normal the contact mesh measures the point along (one per point of the
    !! interface: its first side's): a frictionless interface reads τ = 0 to round-off, curved or
    !! not, and a frictional one its Coulomb shear. Pairs under the mortar weighting (frictionless)
    !! read τ = 0. Before a contact solve, or after a change, there are no results
    !! (TFEM_STATUS_INVALID_STATE).
    function tfem_get_contact_nodal_tractions(model, out, length) &
        bind(C, name="tfem_get_contact_nodal_tractions") result(status)
      import
      type(c_ptr), value :: model
      real(c_double), intent(inout) :: out(*)
      integer(c_size_t), value :: length
      integer(c_int) :: status
    end function tfem_get_contact_nodal_tractions

    !> Copies the contact pressure of contact pair `pair` (0-based, from `tfem_add_contact_pair` or
    !! `tfem_add_contact_pairs_auto`) alone at every node in the last contact solve (n_nodes values,
    !! as `tfem_get_contact_nodal_pressures`; zero off that pair's contact mesh), computed on
    !! request from that pair's forces over that pair's tributaries: a node where three bodies meet
    !! reads each face on its own (at a block's corner, the bed's pressure on the bed pair and the
    !! head joint's on the head pair), where `tfem_get_contact_nodal_pressures` gives their
    !! tributary-weighted mean. As there, where one side ends inside an edge of the other, the first
    !! node of the other side past that end reads the other side's pressure near that end. An
    !! unknown pair is refused (TFEM_STATUS_INVALID_ARGUMENT naming it); before a contact solve, or
    !! after a change (declaring a pair is one), there are no results (TFEM_STATUS_INVALID_STATE).
    function tfem_get_contact_pair_nodal_pressures(model, pair, out, length) &
        bind(C, name="tfem_get_contact_pair_nodal_pressures") result(status)
      import
      type(c_ptr), value :: model
      integer(c_int), value :: pair
      real(c_double), intent(inout) :: out(*)
      integer(c_size_t), value :: length
      integer(c_int) :: status
    end function tfem_get_contact_pair_nodal_pressures

    !> `tfem_get_contact_nodal_tractions` of contact pair `pair` (0-based) alone, read over that
    !! pair's forces and tributaries as `tfem_get_contact_pair_nodal_pressures` reads its pressures
    !! (2·n_nodes values). An unknown pair is refused (TFEM_STATUS_INVALID_ARGUMENT naming it).
    function tfem_get_contact_pair_nodal_tractions(model, pair, out, length) &
        bind(C, name="tfem_get_contact_pair_nodal_tractions") result(status)
      import
      type(c_ptr), value :: model
      integer(c_int), value :: pair
      real(c_double), intent(inout) :: out(*)
      integer(c_size_t), value :: length
      integer(c_int) :: status
    end function tfem_get_contact_pair_nodal_tractions

    !> Copies the normal gap at every node in the last contact solve (n_nodes values, model length
    !! units; zero off the contact interfaces), computed on request: the smallest, over the contact
    !! elements at the node, of the distance of an element's apex from its interface edge in the
    !! deformed configuration (linearised). Positive: open; negative: the bodies interpenetrate (by
    !! O(h²), the penalty of the contact elements).
    function tfem_get_contact_gaps(model, out, length) &
        bind(C, name="tfem_get_contact_gaps") result(status)
      import
      type(c_ptr), value :: model
      real(c_double), intent(inout) :: out(*)
      integer(c_size_t), value :: length
      integer(c_int) :: status
    end function tfem_get_contact_gaps

    !> Copies the active flag (1 active, 0 not) of every contact element of the last contact solve
    !! (n_contact_elements values, see `tfem_get_sizes`).
    function tfem_get_contact_active(model, out, length) &
        bind(C, name="tfem_get_contact_active") result(status)
      import
      type(c_ptr), value :: model
      integer(c_int), intent(inout) :: out(*)
      integer(c_size_t), value :: length
      integer(c_int) :: status
    end function tfem_get_contact_active

    !> Copies the contact pressure of every contact element (n_contact_elements values): the normal
    !! stress −n·σ·n in the element (force per unit area, Pa in SI), positive in compression, 0 when
    !! inactive. It is the traction at the element's apex (the interface point it measures: on
    !! matching meshes the apex node), times the share of its edge that faces the other side; each
    !! point is measured by two elements, one with its edge on either side. For the traction at the
    !! interface nodes, read `tfem_get_contact_nodal_tractions` (on a non-matching interface one
    !! family's element values read up to twice the traction).
    function tfem_get_contact_pressure(model, out, length) &
        bind(C, name="tfem_get_contact_pressure") result(status)
      import
      type(c_ptr), value :: model
      real(c_double), intent(inout) :: out(*)
      integer(c_size_t), value :: length
      integer(c_int) :: status
    end function tfem_get_contact_pressure

    !> Copies the nodes of every contact element (3·n_contact_elements indices, in the model's index
    !! base), oriented so that J > 0 when the gap opens. Refused (TFEM_STATUS_INVALID_STATE) after a
    !! solve under the mortar weighting, which uses no B.
    function tfem_get_contact_elements(model, out, length) &
        bind(C, name="tfem_get_contact_elements") result(status)
      import
      type(c_ptr), value :: model
      integer(c_int), intent(inout) :: out(*)
      integer(c_size_t), value :: length
      integer(c_int) :: status
    end function tfem_get_contact_elements

    !> Copies the shear traction τ = n·σ·t (Pa in SI; t = (−n_y, n_x), n the element's normal, see
    !! `tfem_get_contact_mesh`) of every contact element of the last contact solve or step
    !! (n_contact_elements values): 0 when open, |τ| ≤ μp when sticking, μp when slipping; all 0
    !! when frictionless. An element value at its apex, as `tfem_get_contact_pressure`; the shear at
    !! the interface nodes is `tfem_get_contact_nodal_tractions`'.
    function tfem_get_contact_shear(model, out, length) &
        bind(C, name="tfem_get_contact_shear") result(status)
      import
      type(c_ptr), value :: model
      real(c_double), intent(inout) :: out(*)
      integer(c_size_t), value :: length
      integer(c_int) :: status
    end function tfem_get_contact_shear

    !> Copies the frictional state of every contact element of the last contact solve or step
    !! (n_contact_elements values): 0 open, 1 stick, 2 slip (a frictionless solve: 2 where active).
    function tfem_get_contact_friction_state(model, out, length) &
        bind(C, name="tfem_get_contact_friction_state") result(status)
      import
      type(c_ptr), value :: model
      integer(c_int), intent(inout) :: out(*)
      integer(c_size_t), value :: length
      integer(c_int) :: status
    end function tfem_get_contact_friction_state

    !> Copies the energy dissipated by slip in the last step (or solve) at every contact element
    !! (n_contact_elements values, J per unit thickness in SI; for axisymmetric bodies per unit
    !! length of the element's ring, 2πr̄ times less than the whole ring's): ½ τ Δγ_p ≥ 0; all 0
    !! when frictionless.
    function tfem_get_contact_dissipation(model, out, length) &
        bind(C, name="tfem_get_contact_dissipation") result(status)
      import
      type(c_ptr), value :: model
      real(c_double), intent(inout) :: out(*)
      integer(c_size_t), value :: length
      integer(c_int) :: status
    end function tfem_get_contact_dissipation

    !> Copies the state of every slave node after a contact solve under the mortar weighting, n =
    !! the report's `elements`, in the order of the pairs: `node` (n values: the slave node, in the
    !! model's index base), `tributary` (n values: m_i, the length its hat covers where it faces the
    !! other side), `gap` (n values: the mean gap G_i/m_i, negative where the bodies overlap) and
    !! `pressure` (n values: −κG_i/m_i, positive in compression, 0 when inactive; an active node
    !! whose weighted gap is at the round-off of the displacements, as where the bodies touch
    !! without load, can read a pressure of that round-off of either sign). Any pointer may be NULL
    !! (that column is not written); `length` (>= n) is the size of each buffer given. Refused after
    !! a solve under the strip weighting.
    function tfem_get_contact_slave_nodes(model, node, tributary, gap, pressure, length) &
        bind(C, name="tfem_get_contact_slave_nodes") result(status)
      import
      type(c_ptr), value :: model
      integer(c_int), intent(inout) :: node(*)
      real(c_double), intent(inout) :: tributary(*)
      real(c_double), intent(inout) :: gap(*)
      real(c_double), intent(inout) :: pressure(*)
      integer(c_size_t), value :: length
      integer(c_int) :: status
    end function tfem_get_contact_slave_nodes

    ! ==============================================================================================
    ! Load history: steps on one factorisation, revert, and the contact state saved and restored
    ! (restarts).
    ! ==============================================================================================

    !> One quasi-static load step: the contact problem with the loads and prescribed displacements
    !! as set, scaled by `load_factor`, warm-started from the contact state of the last step (the
    !! initial set of a contact solve for the first, or a state given by `tfem_set_contact_state`).
    !! One factorisation serves every step while the stiffness (mesh, constraints, materials,
    !! tempering, contact pairs) and the contact options (`options` may be NULL: defaults;
    !! `max_iterations` may change) are unchanged: a step is dense work on the contact interface,
    !! plus one sparse solve when the loads changed since the last step (a non-proportional
    !! history). Its displacements, and everything computed from them, are recovered on first
    !! request (one sparse solve, or, where that cannot reach working accuracy on a very
    !! non-matching interface, a factorisation of the step's own matrix, made and dropped at that
    !! request); the system matrix of a step is not available. The step is accepted as it is:
    !! `tfem_revert_step` undoes it. `report` may be NULL. Where the contact interface is not
    !! condensed (options with `refactorize` set, an interface too large to condense — see
    !! `TfemContactOptions` —, or a contact that couples no free unknown) each step is a contact
    !! solve of its scaled loads started from the state of the step before. A warm start that leads
    !! nowhere (a body left free: unloading to zero from a loaded set passes through no contact at
    !! all; a cycle) is tried again from the initial set of the step's own loads. `load_factor` must
    !! be finite, at most 1e300 in magnitude, and a step whose field would overflow is refused
    !! (TFEM_STATUS_NUMERICAL_FAILURE). On error the model is unchanged. A frictional history goes
    !! on from the slip state it reached across a change of materials, options or prescribed DOFs
    !! between steps (with friction the answer depends on the path). Every DOF prescribed:
    !! TFEM_STATUS_INVALID_STATE. Under the mortar weighting (`tfem_set_contact_weighting`,
    !! frictionless) a step is the same history over the slave nodes' weighted gaps.
    function tfem_step(model, load_factor, options, report) &
        bind(C, name="tfem_step") result(status)
      import
      type(c_ptr), value :: model
      real(c_double), value :: load_factor
      type(tfem_contact_options), intent(in) :: options
      type(tfem_contact_report), intent(inout) :: report
      integer(c_int) :: status
    end function tfem_step

    !> Undoes the last load step: its results, and the contact state the next step starts from, go
    !! back to what they were before it. Once per step. Refused with TFEM_STATUS_INVALID_STATE, the
    !! model unchanged, once the mesh, its boundary edges, the contact pairs, friction on/off or the
    !! contact weighting have changed since that step: they remake the contact mesh, and its contact
    !! state belongs to the one before; the message names the change. Fixing or clearing prescribed
    !! DOFs does not block it: like new materials, it changes the stiffness, not the contact mesh.
    !! The state brought back is the next step's start even if that step starts a new history (new
    !! materials, options or prescribed DOFs), with that problem's own interface factor.
    function tfem_revert_step(model) &
        bind(C, name="tfem_revert_step") result(status)
      import
      type(c_ptr), value :: model
      integer(c_int) :: status
    end function tfem_revert_step

    !> Writes to `size` the number of bytes of the contact state of the last load step (see
    !! `tfem_get_contact_state`).
    function tfem_get_contact_state_size(model, size) &
        bind(C, name="tfem_get_contact_state_size") result(status)
      import
      type(c_ptr), value :: model
      integer(c_size_t), intent(inout) :: size
      integer(c_int) :: status
    end function tfem_get_contact_state_size

    !> Copies the contact state of the last load step into `buffer` (`length` bytes, at least
    !! `tfem_get_contact_state_size`): the active set and the factor of the condensed interface
    !! system, so that `tfem_set_contact_state` continues the history bit for bit (a restart, in
    !! this model or another one holding the same problem). Under the mortar weighting the set is
    !! the slave nodes'.
    function tfem_get_contact_state(model, buffer, length) &
        bind(C, name="tfem_get_contact_state") result(status)
      import
      type(c_ptr), value :: model
      integer(c_int8_t), intent(inout) :: buffer(*)
      integer(c_size_t), value :: length
      integer(c_int) :: status
    end function tfem_get_contact_state

    !> Continues the load history from a contact state (`length` bytes from
    !! `tfem_get_contact_state`): the next `tfem_step` starts from it. Refused, naming why, if the
    !! bytes are not such a state, belong to another contact mesh, or are frictional where no pair
    !! has friction; the model is then unchanged. From a history of the same problem (the same
    !! geometry, materials, constraints and options) the steps go on bit for bit; from one whose
    !! interface system differs (the same contact mesh, another shape or stiffness), from its active
    !! set and slip state, with the interface factor of this problem; so also when the next step
    !! starts a new history (new materials, options or prescribed DOFs). If the mesh, its boundary
    !! edges, the pairs or friction on/off change before the next step (they remake the contact
    !! mesh), that step starts afresh and warns; a change of the prescribed DOFs keeps it. A
    !! frictional state waiting for a step under the stick law is refused by that step
    !! (TFEM_STATUS_INVALID_ARGUMENT) until another state is set.
    function tfem_set_contact_state(model, buffer, length) &
        bind(C, name="tfem_set_contact_state") result(status)
      import
      type(c_ptr), value :: model
      integer(c_int8_t), intent(in) :: buffer(*)
      integer(c_size_t), value :: length
      integer(c_int) :: status
    end function tfem_set_contact_state

    ! ==============================================================================================
    ! Utilities: the assembled system matrix, and element stiffness matrices for codes that assemble
    ! their own.
    ! ==============================================================================================

    !> Sizes of the stiffness matrix of the last solve (see `tfem_get_system_matrix`): `n` unknowns
    !! and `nnz` stored entries of its upper triangle. Either pointer may be NULL.
    function tfem_get_system_matrix_size(model, n, nnz) &
        bind(C, name="tfem_get_system_matrix_size") result(status)
      import
      type(c_ptr), value :: model
      integer(c_int64_t), intent(inout) :: n
      integer(c_int64_t), intent(inout) :: nnz
      integer(c_int) :: status
    end function tfem_get_system_matrix_size

    !> Copies the stiffness matrix K of the last solve on its unknowns (the DOFs left after
    !! Dirichlet elimination), the system K u = f whose solution `tfem_get_displacements` returns;
    !! for a contact solve it holds the contact elements active at convergence. Upper triangle in
    !! compressed sparse columns, rows ascending within each column: `col_ptr` (n + 1 values),
    !! `row_idx` and `values` (nnz values each), indices in the model's index base (`col_ptr[0]` =
    !! base). `dofs` (n values) gives each unknown's position in the array of
    !! `tfem_get_displacements`, in the index base (2·node + component for base 0). Every buffer is
    !! checked before any is written. Like every result it outlives a failed solve (which rebuilds
    !! it bit for bit) and is discarded by a change of the problem (TFEM_STATUS_INVALID_STATE).
    function tfem_get_system_matrix(model, col_ptr, col_ptr_length, row_idx, row_idx_length, values, &
        values_length, dofs, dofs_length) &
        bind(C, name="tfem_get_system_matrix") result(status)
      import
      type(c_ptr), value :: model
      integer(c_int64_t), intent(inout) :: col_ptr(*)
      integer(c_size_t), value :: col_ptr_length
      integer(c_int64_t), intent(inout) :: row_idx(*)
      integer(c_size_t), value :: row_idx_length
      real(c_double), intent(inout) :: values(*)
      integer(c_size_t), value :: values_length
      integer(c_int64_t), intent(inout) :: dofs(*)
      integer(c_size_t), value :: dofs_length
      integer(c_int) :: status
    end function tfem_get_system_matrix

    !> Tempered elasticity stiffness of one P1 triangle with corners `xy` (x1 y1 x2 y2 x3 y3): K =
    !! B̂ᵀ D B̂ / (2·max(J, jmin)), written row-major into `out` (36 values, DOFs u1 v1 u2 v2 u3
    !! v3). For `TFEM_PLANE_MODE_AXISYMMETRIC` (x the radius, corners with x ≥ 0) the whole ring's K
    !! = 2πx̄ (B̂ + J H)ᵀ D₄ (B̂ + J H) / (2·max(J, jmin)), H the hoop row 1/(3x̄) on each u_r
    !! (docs/method.md §7). `jmin` > 0 tempers; `jmin` = 0 is plain FEM (divides by |J|, fails for J
    !! = 0). Pure and thread-safe; errors go to the thread's `tfem_last_error(NULL, …)`.
    function tfem_element_stiffness(xy, young, poisson, plane_mode, jmin, out) &
        bind(C, name="tfem_element_stiffness") result(status)
      import
      real(c_double), intent(in) :: xy(*)
      real(c_double), value :: young
      real(c_double), value :: poisson
      integer(c_int), value :: plane_mode
      real(c_double), value :: jmin
      real(c_double), intent(inout) :: out(*)
      integer(c_int) :: status
    end function tfem_element_stiffness

    !> Tempered Laplacian stiffness of one P1 triangle: K_ij = κ g_i·g_j / (2·max(J, jmin)),
    !! row-major into `out` (9 values). `jmin` as in `tfem_element_stiffness`. Pure and thread-safe.
    function tfem_laplacian_stiffness(xy, kappa, jmin, out) &
        bind(C, name="tfem_laplacian_stiffness") result(status)
      import
      real(c_double), intent(in) :: xy(*)
      real(c_double), value :: kappa
      real(c_double), value :: jmin
      real(c_double), intent(inout) :: out(*)
      integer(c_int) :: status
    end function tfem_laplacian_stiffness

    ! ==============================================================================================
    ! Contact for host codes (tfem_contact_*): a contact context for a code that keeps its own
    ! elements and solver. It takes the host's nodes, displacements and contact sides, and gives
    ! back the contact's stiffness and forces to add to the host's system, and the contact state per
    ! element of B (tfem_contact_get_active, tfem_contact_pressures; not the model's
    ! tfem_get_contact_*).
    ! ==============================================================================================

    !> Creates a contact context for a host code that keeps its own elements, assembly, solver and
    !! Newton loop: node numbers and equation numbers in `index_base` (0 for C, 1 for Fortran).
    !! Returns NULL if `index_base` is not 0 or 1 (message in `tfem_last_error(NULL, …)`) or memory
    !! is exhausted. The host then adds the sides of its contact interfaces
    !! (`tfem_contact_add_side`) and the pairs (`tfem_contact_add_pair`); the first call that needs
    !! the contact mesh B builds it, after which sides and pairs are fixed.
    function tfem_contact_create(index_base) &
        bind(C, name="tfem_contact_create") result(res)
      import
      integer(c_int), value :: index_base
      type(c_ptr) :: res
    end function tfem_contact_create

    !> Destroys a contact context. NULL is a no-op, and so is a pointer that is not a live context
    !! (destroyed already, or a model).
    subroutine tfem_contact_destroy(context) &
        bind(C, name="tfem_contact_destroy")
      import
      type(c_ptr), value :: context
    end subroutine tfem_contact_destroy

    !> Copies the message of the last failed call on `context` (empty after a successful call) into
    !! `buffer` (`length` bytes including the final NUL), truncating like `tfem_last_error`. A
    !! `context` that is not a live contact context gives TFEM_STATUS_INVALID_ARGUMENT with the
    !! message saying so in `buffer`.
    function tfem_contact_last_error(context, buffer, length) &
        bind(C, name="tfem_contact_last_error") result(status)
      import
      type(c_ptr), value :: context
      character(kind=c_char), intent(inout) :: buffer(*)
      integer(c_size_t), value :: length
      integer(c_int) :: status
    end function tfem_contact_last_error

    !> Size in bytes (including the final NUL) of the message `tfem_contact_last_error` would give
    !! for `context` (a buffer of this size holds all of it): 1 after a successful call; for a
    !! handle that is not a live contact context (destroyed, or a model), the size of the message
    !! saying so. `context` may be NULL: 1 (it has no message).
    function tfem_contact_last_error_length(context) &
        bind(C, name="tfem_contact_last_error_length") result(res)
      import
      type(c_ptr), value :: context
      integer(c_size_t) :: res
    end function tfem_contact_last_error_length

    !> Sets the contact options (law, E_c, λ, inversion test, and `max_iterations`: the number of
    !! `tfem_contact_update` calls of one loop before it counts as not converged; `refactorize` is
    !! ignored). Only before the contact mesh is built. Defaults: `tfem_contact_options_default`,
    !! with λ the larger side of the interface nodes' bounding box.
    function tfem_contact_set_options(context, options) &
        bind(C, name="tfem_contact_set_options") result(status)
      import
      type(c_ptr), value :: context
      type(tfem_contact_options), intent(in) :: options
      integer(c_int) :: status
    end function tfem_contact_set_options

    !> Adds one side of a contact interface, of body `body` (Young's modulus `young`, Poisson ratio
    !! `poisson`, `plane_mode` a `PlaneMode`: the softer side's E is the default E_c, the stick law
    !! takes its ν): `n_nodes` interface nodes `nodes` (the host's node numbers) with their
    !! coordinates `xy` (2 per node) and the equations of their x and y unknowns `equations` (2 per
    !! node, in the index base; a value below the base marks a fixed DOF without an equation), and
    !! `n_edges` edges `edges` (2 host node numbers each), each given with its body on its left (the
    !! counter-clockwise boundary orientation); an edge that runs against its neighbour is refused
    !! (TFEM_STATUS_INVALID_CONTACT, naming it). A node of two sides must come with the same
    !! coordinates and equations. A node number below the index base is refused
    !! (TFEM_STATUS_INVALID_ARGUMENT naming the side, the node's entry and the number), and so is an
    !! equation that no host vector can hold (from index_base + PTRDIFF_MAX / 8 on: no array of
    !! doubles spans more bytes), naming the node and the equation. The host's system size is not
    !! known here: `tfem_contact_gather` and `tfem_contact_scatter_add` check every equation against
    !! the vector they are given. Writes the side's index (0-based) to `side` (may be NULL). On
    !! error nothing changes.
    function tfem_contact_add_side(context, tag, body, young, poisson, plane_mode, n_nodes, nodes, xy, &
        equations, n_edges, edges, side) &
        bind(C, name="tfem_contact_add_side") result(status)
      import
      type(c_ptr), value :: context
      integer(c_int), value :: tag
      integer(c_int), value :: body
      real(c_double), value :: young
      real(c_double), value :: poisson
      integer(c_int), value :: plane_mode
      integer(c_int), value :: n_nodes
      integer(c_int), intent(in) :: nodes(*)
      real(c_double), intent(in) :: xy(*)
      integer(c_int64_t), intent(in) :: equations(*)
      integer(c_int), value :: n_edges
      integer(c_int), intent(in) :: edges(*)
      integer(c_int), intent(inout) :: side
      integer(c_int) :: status
    end function tfem_contact_add_side

    !> Declares sides `side_a` and `side_b` (on different bodies) a contact pair: the contact mesh B
    !! is built from their matching nodes, or by triangulating the strip between them. Two sides
    !! whose outward normals point the same way (one of them given clockwise) are refused with
    !! TFEM_STATUS_INVALID_CONTACT naming both. A pair of two sides already paired (either way
    !! round) is refused with TFEM_STATUS_INVALID_CONTACT naming it: it would double their contact.
    !! Messages name a side by its index and tag ("side 0 (tag 101)") and nodes by the host's
    !! numbers. Writes the pair's index (0-based) to `pair` (may be NULL).
    function tfem_contact_add_pair(context, side_a, side_b, pair) &
        bind(C, name="tfem_contact_add_pair") result(status)
      import
      type(c_ptr), value :: context
      integer(c_int), value :: side_a
      integer(c_int), value :: side_b
      integer(c_int), intent(inout) :: pair
      integer(c_int) :: status
    end function tfem_contact_add_pair

    !> Declares a pair with the host's own contact mesh B: `n_triangles` triangles `connectivity` (3
    !! host node numbers each) over the interface nodes of the two sides; wrongly oriented ones are
    !! turned. A triangle given twice (the same three nodes) is refused (TFEM_STATUS_INVALID_CONTACT
    !! naming both triangles), and so is a pair already declared, as by `tfem_contact_add_pair`. A
    !! node number below the index base is refused (TFEM_STATUS_INVALID_ARGUMENT naming the pair,
    !! the triangle, the node's place in it and the number). Writes the pair's index (0-based) to
    !! `pair` (may be NULL).
    function tfem_contact_add_pair_with_mesh(context, side_a, side_b, n_triangles, connectivity, pair) &
        bind(C, name="tfem_contact_add_pair_with_mesh") result(status)
      import
      type(c_ptr), value :: context
      integer(c_int), value :: side_a
      integer(c_int), value :: side_b
      integer(c_int), value :: n_triangles
      integer(c_int), intent(in) :: connectivity(*)
      integer(c_int), intent(inout) :: pair
      integer(c_int) :: status
    end function tfem_contact_add_pair_with_mesh

    !> Builds the contact mesh B (if not yet) and writes the sizes: interface nodes (the length of
    !! every per-node array: 2 values per node for displacements and residuals), elements of B, and
    !! entries of the pattern. Any pointer may be NULL.
    function tfem_contact_sizes(context, n_nodes, n_elements, n_entries) &
        bind(C, name="tfem_contact_sizes") result(status)
      import
      type(c_ptr), value :: context
      integer(c_int), intent(inout) :: n_nodes
      integer(c_int), intent(inout) :: n_elements
      integer(c_int64_t), intent(inout) :: n_entries
      integer(c_int) :: status
    end function tfem_contact_sizes

    !> Copies the interface nodes (host numbers, n_nodes values), in the order of every per-node
    !! array.
    function tfem_contact_nodes(context, out, length) &
        bind(C, name="tfem_contact_nodes") result(status)
      import
      type(c_ptr), value :: context
      integer(c_int), intent(inout) :: out(*)
      integer(c_size_t), value :: length
      integer(c_int) :: status
    end function tfem_contact_nodes

    !> Copies the fixed pattern of the contact contributions into `rows` (n_entries values) and
    !! `cols` (n_entries values), in the host's equation numbering and index base: element after
    !! element of B, each element's 6×6 block row by row over its DOFs (x then y of its first,
    !! second and third node), the DOFs without an equation left out; both triangles of each block.
    !! Entries repeat where elements share a DOF pair: the host sums them.
    function tfem_contact_pattern(context, rows, cols, length) &
        bind(C, name="tfem_contact_pattern") result(status)
      import
      type(c_ptr), value :: context
      integer(c_int64_t), intent(inout) :: rows(*)
      integer(c_int64_t), intent(inout) :: cols(*)
      integer(c_size_t), value :: length
      integer(c_int) :: status
    end function tfem_contact_pattern

    !> The contact contributions at the displacements `u` of the interface nodes (2 per node,
    !! `u_length` = 2·n_nodes): the tangent's values in the pattern's order into `values` (n_entries
    !! values, zeros for inactive elements), and the contact residual Σ (K_e u_e − f0_e) of the
    !! active elements, 2 per interface node, into `residual`. `values` may be NULL; `residual` may
    !! be NULL. A linear host adds the values to its matrix and minus the residual at u = 0 (the
    !! load of initial gaps) to its right-hand side; a Newton host adds the values to its tangent
    !! and the residual at its current u to its residual. The contact law is linear in u for a given
    !! active set: the values depend on the active set only, not on `u`, and change only when
    !! `tfem_contact_update` or `tfem_contact_set_active` changes the set. A non-finite value in `u`
    !! is refused (TFEM_STATUS_INVALID_ARGUMENT naming the node and the value); a result that
    !! overflows is TFEM_STATUS_NUMERICAL_FAILURE; either way the buffers are unchanged. Allocates
    !! nothing.
    function tfem_contact_evaluate(context, u, u_length, values, values_length, residual, residual_length) &
        bind(C, name="tfem_contact_evaluate") result(status)
      import
      type(c_ptr), value :: context
      real(c_double), intent(in) :: u(*)
      integer(c_size_t), value :: u_length
      real(c_double), intent(inout) :: values(*)
      integer(c_size_t), value :: values_length
      real(c_double), intent(inout) :: residual(*)
      integer(c_size_t), value :: residual_length
      integer(c_int) :: status
    end function tfem_contact_evaluate

    !> Copies into `u` (2 per interface node) the displacements of the interface nodes from the
    !! host's solution vector `u_equations` (`n_equations` values; entry i is equation i +
    !! index_base); a DOF without an equation counts as fixed at zero. A non-finite entry at an
    !! interface node's equation is refused (TFEM_STATUS_INVALID_ARGUMENT naming the node and the
    !! equation); `u` is then unchanged.
    function tfem_contact_gather(context, u_equations, n_equations, u, u_length) &
        bind(C, name="tfem_contact_gather") result(status)
      import
      type(c_ptr), value :: context
      real(c_double), intent(in) :: u_equations(*)
      integer(c_size_t), value :: n_equations
      real(c_double), intent(inout) :: u(*)
      integer(c_size_t), value :: u_length
      integer(c_int) :: status
    end function tfem_contact_gather

    !> Adds per-node values `residual` (2 per interface node, as `tfem_contact_evaluate` writes
    !! them) into the host's vector `host_vector` (`n_equations` values, entry i is equation i +
    !! index_base); DOFs without an equation are left out. A non-finite value in `residual` is
    !! refused (TFEM_STATUS_INVALID_ARGUMENT naming the node), and so is a sum that would not be
    !! finite: an entry of `host_vector` that is not finite already (TFEM_STATUS_INVALID_ARGUMENT),
    !! or an overflow (TFEM_STATUS_NUMERICAL_FAILURE), naming the node and the equation.
    !! `host_vector` is then unchanged.
    function tfem_contact_scatter_add(context, residual, residual_length, host_vector, n_equations) &
        bind(C, name="tfem_contact_scatter_add") result(status)
      import
      type(c_ptr), value :: context
      real(c_double), intent(in) :: residual(*)
      integer(c_size_t), value :: residual_length
      real(c_double), intent(inout) :: host_vector(*)
      integer(c_size_t), value :: n_equations
      integer(c_int) :: status
    end function tfem_contact_scatter_add

    !> The inversion test at the displacements `u` (2 per interface node) of a solve with the
    !! current active set: the elements found inverted are switched on, the others off; `changed`
    !! (may be NULL) is set to 1 if the set changed, 0 if it settled. The same test and cycle
    !! detection as tfem's own loop: a set visited before, or more calls than the options'
    !! `max_iterations` since the last `tfem_contact_restart`, gives TFEM_STATUS_NOT_CONVERGED with
    !! the history, the set unchanged. Call it with converged displacements of the host's problem
    !! for the current set (after its Newton loop, not at every Newton iteration): the test judges
    !! the solution, and a mid-Newton iterate may switch elements that the converged state would
    !! not. A non-finite value in `u` is refused (TFEM_STATUS_INVALID_ARGUMENT naming the node and
    !! the value).
    function tfem_contact_update(context, u, u_length, changed) &
        bind(C, name="tfem_contact_update") result(status)
      import
      type(c_ptr), value :: context
      real(c_double), intent(in) :: u(*)
      integer(c_size_t), value :: u_length
      integer(c_int), intent(inout) :: changed
      integer(c_int) :: status
    end function tfem_contact_update

    !> Starts a new active-set loop from the current flags (a new load step): the history and the
    !! sets visited are forgotten.
    function tfem_contact_restart(context) &
        bind(C, name="tfem_contact_restart") result(status)
      import
      type(c_ptr), value :: context
      integer(c_int) :: status
    end function tfem_contact_restart

    !> Copies the active flag (1 active, 0 not) of every element of B.
    function tfem_contact_get_active(context, out, length) &
        bind(C, name="tfem_contact_get_active") result(status)
      import
      type(c_ptr), value :: context
      integer(c_int), intent(inout) :: out(*)
      integer(c_size_t), value :: length
      integer(c_int) :: status
    end function tfem_contact_get_active

    !> Sets the active flags of the elements of B (n_elements values, 0 or 1): a warm start or a
    !! restored state; starts a new loop.
    function tfem_contact_set_active(context, active, length) &
        bind(C, name="tfem_contact_set_active") result(status)
      import
      type(c_ptr), value :: context
      integer(c_int), intent(in) :: active(*)
      integer(c_size_t), value :: length
      integer(c_int) :: status
    end function tfem_contact_set_active

    !> Copies the normal gap at every interface node (n_nodes values, model length units) for the
    !! displacements `u` (2 per interface node): the smallest, over the elements of B at the node,
    !! of the distance of an element's apex from its interface edge (linearised; negative:
    !! interpenetration). A node in no element of B (on a part of its side that faces nothing of the
    !! other, beyond the other side's end) has no gap and reads 0, as if touching: it is not in
    !! contact, and no contact force acts there; tell such nodes by their absence from
    !! `tfem_contact_elements`. A non-finite value in `u` is refused (TFEM_STATUS_INVALID_ARGUMENT
    !! naming the node and the value).
    function tfem_contact_gaps(context, u, u_length, out, length) &
        bind(C, name="tfem_contact_gaps") result(status)
      import
      type(c_ptr), value :: context
      real(c_double), intent(in) :: u(*)
      integer(c_size_t), value :: u_length
      real(c_double), intent(inout) :: out(*)
      integer(c_size_t), value :: length
      integer(c_int) :: status
    end function tfem_contact_gaps

    !> Copies the contact pressure of every element of B (n_elements values; a stress, positive in
    !! compression, zero when inactive) for the displacements `u` (2 per interface node). A
    !! non-finite value in `u` is refused (TFEM_STATUS_INVALID_ARGUMENT naming the node and the
    !! value).
    function tfem_contact_pressures(context, u, u_length, out, length) &
        bind(C, name="tfem_contact_pressures") result(status)
      import
      type(c_ptr), value :: context
      real(c_double), intent(in) :: u(*)
      integer(c_size_t), value :: u_length
      real(c_double), intent(inout) :: out(*)
      integer(c_size_t), value :: length
      integer(c_int) :: status
    end function tfem_contact_pressures

    !> Copies the nodes of every element of B (3 host node numbers each, oriented so that J > 0 when
    !! the gap opens).
    function tfem_contact_elements(context, out, length) &
        bind(C, name="tfem_contact_elements") result(status)
      import
      type(c_ptr), value :: context
      integer(c_int), intent(inout) :: out(*)
      integer(c_size_t), value :: length
      integer(c_int) :: status
    end function tfem_contact_elements

    !> Copies the equations of every element's six DOFs (6 per element, x then y of each node, in
    !! the index base; index_base − 1 marks a DOF without an equation): with
    !! `tfem_contact_element_blocks`, the contributions as unassembled element blocks.
    function tfem_contact_element_equations(context, out, length) &
        bind(C, name="tfem_contact_element_equations") result(status)
      import
      type(c_ptr), value :: context
      integer(c_int64_t), intent(inout) :: out(*)
      integer(c_size_t), value :: length
      integer(c_int) :: status
    end function tfem_contact_element_equations

    !> Copies every element's 6×6 tangent block (36 values per element, row-major over its DOFs as
    !! in `tfem_contact_element_equations`): its stiffness when active, zeros when not.
    function tfem_contact_element_blocks(context, out, length) &
        bind(C, name="tfem_contact_element_blocks") result(status)
      import
      type(c_ptr), value :: context
      real(c_double), intent(inout) :: out(*)
      integer(c_size_t), value :: length
      integer(c_int) :: status
    end function tfem_contact_element_blocks

    !> Writes the contact length of the current active set to `length`, model length units: per
    !! contact zone (a pair's active elements of B connected through shared nodes), the summed
    !! interface-edge length of the active elements (each as far as it faces the other side) of the
    !! family — edges on one side, or on the other: each covers the interface once — active over the
    !! longer length; +0.0 when no element is active. (Their mean would count half the width where
    !! one family alone carries a contact.)
    function tfem_contact_length(context, length) &
        bind(C, name="tfem_contact_length") result(status)
      import
      type(c_ptr), value :: context
      real(c_double), intent(inout) :: length
      integer(c_int) :: status
    end function tfem_contact_length

    ! ==============================================================================================
    ! The 3D model (tfem_solid_*): a handle of its own, tfem_solid_model, with the conventions of
    ! tfem_model. Tetrahedra and tagged boundary faces, one isotropic material per body, constraints
    ! and loads per node or per face tag, frictionless contact pairs between tagged surfaces (a
    ! planar side facing a matching one, docs/method.md §9), a solve, and its results per node, per
    ! tetrahedron and per tetrahedron of the contact layer B.
    ! ==============================================================================================

    !> Creates an empty 3D model. Returns NULL only if memory is exhausted. Free it with
    !! `tfem_solid_destroy`. A 3D model is its own handle: the 2D functions (`tfem_*` without
    !! `solid`) refuse it, and the 3D ones refuse a 2D model.
    function tfem_solid_create() &
        bind(C, name="tfem_solid_create") result(res)
      import
      type(c_ptr) :: res
    end function tfem_solid_create

    !> Destroys a 3D model and everything it owns. NULL is a no-op, and so is a pointer that is not
    !! a live 3D model (destroyed already, or another kind of handle): do not use a handle after
    !! destroying it.
    subroutine tfem_solid_destroy(model) &
        bind(C, name="tfem_solid_destroy")
      import
      type(c_ptr), value :: model
    end subroutine tfem_solid_destroy

    !> Copies the message of the last failed call on `model` (empty after a successful call) into
    !! `buffer` (`length` bytes including the final NUL), truncating like `tfem_last_error`
    !! (TFEM_STATUS_BUFFER_TOO_SMALL; `tfem_solid_last_error_length` gives the size needed). A 3D
    !! model keeps its own messages; calls given no handle at all leave theirs in the thread's slot,
    !! read with `tfem_last_error(NULL, …)`. A `model` that is not a live 3D model gives
    !! TFEM_STATUS_INVALID_ARGUMENT with the message saying so in `buffer`.
    function tfem_solid_last_error(model, buffer, length) &
        bind(C, name="tfem_solid_last_error") result(status)
      import
      type(c_ptr), value :: model
      character(kind=c_char), intent(inout) :: buffer(*)
      integer(c_size_t), value :: length
      integer(c_int) :: status
    end function tfem_solid_last_error

    !> Size in bytes (including the final NUL) of the message `tfem_solid_last_error` would give for
    !! `model`, so that a buffer of this size holds all of it: 1 after a successful call; for a
    !! handle that is not a live 3D model, the size of the message saying so. `model` may be NULL: 1
    !! (it has no message).
    function tfem_solid_last_error_length(model) &
        bind(C, name="tfem_solid_last_error_length") result(res)
      import
      type(c_ptr), value :: model
      integer(c_size_t) :: res
    end function tfem_solid_last_error_length

    !> Number of warnings: what the mesh noticed (tetrahedra numbered with negative volume and
    !! renumbered, nodes used by no tetrahedron) and what the last solve noticed but did not refuse
    !! (an ill-conditioned system). They are kept until the next solve or mesh.
    function tfem_solid_warning_count(model, count) &
        bind(C, name="tfem_solid_warning_count") result(status)
      import
      type(c_ptr), value :: model
      integer(c_int), intent(inout) :: count
      integer(c_int) :: status
    end function tfem_solid_warning_count

    !> Writes to `size` the size in bytes (including the final NUL) of warning number `index`
    !! (0-based, whatever the index base), so that a buffer of this size holds all of it in
    !! `tfem_solid_get_warning`. An index out of range is refused (TFEM_STATUS_INVALID_ARGUMENT),
    !! `size` unchanged.
    function tfem_solid_get_warning_size(model, index, size) &
        bind(C, name="tfem_solid_get_warning_size") result(status)
      import
      type(c_ptr), value :: model
      integer(c_int), value :: index
      integer(c_size_t), intent(inout) :: size
      integer(c_int) :: status
    end function tfem_solid_get_warning_size

    !> Copies warning number `index` (0-based, whatever the index base) into `buffer` of `length`
    !! bytes, truncating like `tfem_get_warning`: the truncated warning is written with
    !! TFEM_STATUS_BUFFER_TOO_SMALL; on any other error `buffer` is unchanged.
    function tfem_solid_get_warning(model, index, buffer, length) &
        bind(C, name="tfem_solid_get_warning") result(status)
      import
      type(c_ptr), value :: model
      integer(c_int), value :: index
      character(kind=c_char), intent(inout) :: buffer(*)
      integer(c_size_t), value :: length
      integer(c_int) :: status
    end function tfem_solid_get_warning

    !> Sets the mesh: `n_nodes` nodes with coordinates `xyz` (3·n_nodes values, x0 y0 z0 x1 …),
    !! `n_tetrahedra` linear tetrahedra with `connectivity` (4·n_tetrahedra node indices) and a body
    !! tag per tetrahedron in `body_of_tetrahedron`. `index_base` is 0 (C) or 1 (Fortran) and
    !! applies to every index of every later call and message, as `tfem_set_mesh`'s. A tetrahedron
    !! numbered with negative volume is renumbered (its last two nodes swapped; a warning counts
    !! them, and every output refers to the renumbered ones); flat ones are legal (tempered). The
    !! mesh has no tagged faces yet: give them with `tfem_solid_set_boundary_faces`. Replacing a
    !! mesh discards constraints, loads, contact pairs and results; materials and tempering are
    !! kept. Refused, naming the tetrahedron or node, for a node index out of range, a node repeated
    !! in a tetrahedron or a coordinate that is not finite (TFEM_STATUS_INVALID_MESH).
    function tfem_solid_set_mesh(model, n_nodes, xyz, n_tetrahedra, connectivity, body_of_tetrahedron, &
        index_base) &
        bind(C, name="tfem_solid_set_mesh") result(status)
      import
      type(c_ptr), value :: model
      integer(c_int), value :: n_nodes
      real(c_double), intent(in) :: xyz(*)
      integer(c_int), value :: n_tetrahedra
      integer(c_int), intent(in) :: connectivity(*)
      integer(c_int), intent(in) :: body_of_tetrahedron(*)
      integer(c_int), value :: index_base
      integer(c_int) :: status
    end function tfem_solid_set_mesh

    !> Loads a Gmsh MSH 4.1 mesh (ASCII or binary) of tetrahedra from the file `path`
    !! (NUL-terminated; on Unix any bytes, as for `tfem_load_gmsh`): physical volumes become bodies
    !! (tag = body), the triangles of physical surfaces become tagged boundary faces (tag = the
    !! physical surface's), node i being the i-th node of the file's `$Nodes` section. Replaces the
    !! mesh like `tfem_solid_set_mesh` with the given `index_base`. Returns TFEM_STATUS_IO for an
    !! unreadable or malformed file, TFEM_STATUS_INVALID_MESH for content a tetrahedral mesh cannot
    !! take (another version of the format, no tetrahedra in a physical volume as in a 2D file,
    !! elements of higher order, a tagged triangle that is not the face of exactly one tetrahedron;
    !! named by the file's tags and physical groups), TFEM_STATUS_INVALID_ARGUMENT if the library
    !! was built without the `gmsh` feature. On error the model is unchanged.
    function tfem_solid_load_gmsh(model, path, index_base) &
        bind(C, name="tfem_solid_load_gmsh") result(status)
      import
      type(c_ptr), value :: model
      character(kind=c_char), intent(in) :: path(*)
      integer(c_int), value :: index_base
      integer(c_int) :: status
    end function tfem_solid_load_gmsh

    !> Sets the tagged boundary faces: `n_faces` triangles given by `face_nodes` (3·n_faces node
    !! indices, in any order: the outward side is away from the tetrahedron the face belongs to)
    !! with a tag each in `tags`. Tags name the faces for constraints, loads and contact pairs.
    !! Replaces previous faces (`tfem_solid_add_boundary_faces` adds one group at a time). Each must
    !! be a face of exactly one tetrahedron, and a face given twice with one tag is refused (its
    !! loads would count twice): TFEM_STATUS_INVALID_MESH naming the face. Faces are given before
    !! the constraints, loads and contact pairs that name them: while any is declared the call is
    !! refused (TFEM_STATUS_INVALID_STATE). Discards the results. On any error nothing changes.
    function tfem_solid_set_boundary_faces(model, n_faces, face_nodes, tags) &
        bind(C, name="tfem_solid_set_boundary_faces") result(status)
      import
      type(c_ptr), value :: model
      integer(c_int), value :: n_faces
      integer(c_int), intent(in) :: face_nodes(*)
      integer(c_int), intent(in) :: tags(*)
      integer(c_int) :: status
    end function tfem_solid_set_boundary_faces

    !> Adds tagged boundary faces to those already set, checked as `tfem_solid_set_boundary_faces`
    !! checks them (a face already holding the tag is refused): for instance one call per physical
    !! surface.
    function tfem_solid_add_boundary_faces(model, n_faces, face_nodes, tags) &
        bind(C, name="tfem_solid_add_boundary_faces") result(status)
      import
      type(c_ptr), value :: model
      integer(c_int), value :: n_faces
      integer(c_int), intent(in) :: face_nodes(*)
      integer(c_int), intent(in) :: tags(*)
      integer(c_int) :: status
    end function tfem_solid_add_boundary_faces

    !> Sizes: nodes, tetrahedra, and tetrahedra of the contact layer B of the last solve (0 before a
    !! solve, or without contact pairs), which size the buffers of the getters. Any pointer may be
    !! NULL.
    function tfem_solid_get_sizes(model, n_nodes, n_tetrahedra, n_contact_tetrahedra) &
        bind(C, name="tfem_solid_get_sizes") result(status)
      import
      type(c_ptr), value :: model
      integer(c_int), intent(inout) :: n_nodes
      integer(c_int), intent(inout) :: n_tetrahedra
      integer(c_int), intent(inout) :: n_contact_tetrahedra
      integer(c_int) :: status
    end function tfem_solid_get_sizes

    !> Number of tagged boundary faces the model holds, from `tfem_solid_set_boundary_faces` /
    !! `tfem_solid_add_boundary_faces` or a Gmsh file's physical surfaces; see
    !! `tfem_solid_get_boundary_faces`.
    function tfem_solid_get_boundary_face_count(model, count) &
        bind(C, name="tfem_solid_get_boundary_face_count") result(status)
      import
      type(c_ptr), value :: model
      integer(c_int), intent(inout) :: count
      integer(c_int) :: status
    end function tfem_solid_get_boundary_face_count

    !> Copies the node coordinates the model holds (x0 y0 z0 x1 …, 3·n_nodes values) into `xyz` of
    !! `length` values: after `tfem_solid_load_gmsh`, the mesh the file gave.
    function tfem_solid_get_mesh_nodes(model, xyz, length) &
        bind(C, name="tfem_solid_get_mesh_nodes") result(status)
      import
      type(c_ptr), value :: model
      real(c_double), intent(inout) :: xyz(*)
      integer(c_size_t), value :: length
      integer(c_int) :: status
    end function tfem_solid_get_mesh_nodes

    !> Copies the tetrahedra the model holds (4·n_tetrahedra node indices in the model's index base,
    !! those given with negative volume renumbered) into `tetrahedra` of `length` values and each
    !! one's body tag into `bodies` of `bodies_length` values; `bodies` may be NULL. Nothing is
    !! written unless both buffers are large enough.
    function tfem_solid_get_mesh_tetrahedra(model, tetrahedra, length, bodies, bodies_length) &
        bind(C, name="tfem_solid_get_mesh_tetrahedra") result(status)
      import
      type(c_ptr), value :: model
      integer(c_int), intent(inout) :: tetrahedra(*)
      integer(c_size_t), value :: length
      integer(c_int), intent(inout) :: bodies(*)
      integer(c_size_t), value :: bodies_length
      integer(c_int) :: status
    end function tfem_solid_get_mesh_tetrahedra

    !> Copies the tagged boundary faces the model holds (3·count node indices in the model's index
    !! base, count from `tfem_solid_get_boundary_face_count`) into `faces` of `length` values and
    !! each face's tag into `tags` of `tags_length` values, in the order they were given; `tags` may
    !! be NULL. Nothing is written unless both buffers are large enough.
    function tfem_solid_get_boundary_faces(model, faces, length, tags, tags_length) &
        bind(C, name="tfem_solid_get_boundary_faces") result(status)
      import
      type(c_ptr), value :: model
      integer(c_int), intent(inout) :: faces(*)
      integer(c_size_t), value :: length
      integer(c_int), intent(inout) :: tags(*)
      integer(c_size_t), value :: tags_length
      integer(c_int) :: status
    end function tfem_solid_get_boundary_faces

    !> Sets the isotropic material of body `body`: Young's modulus `young` (finite, > 0) and
    !! Poisson's ratio `poisson` (in (-1, 0.5)); a body may be given its material before or after
    !! the mesh. Refused with TFEM_STATUS_INVALID_MATERIAL naming the body. Every body of the mesh
    !! needs one before a solve.
    function tfem_solid_set_material(model, body, young, poisson) &
        bind(C, name="tfem_solid_set_material") result(status)
      import
      type(c_ptr), value :: model
      integer(c_int), value :: body
      real(c_double), value :: young
      real(c_double), value :: poisson
      integer(c_int) :: status
    end function tfem_solid_set_material

    !> Chooses Jmin, the floor of the tempered tetrahedra's Jacobian, with `tfem_set_tempering`'s
    !! encoding (a `tfem_tempering_mode`): 0 auto, Jmin = min(h⁴/λ, h³/10) with λ the larger side of
    !! the mesh's bounding box (h the element's longest edge); 1 the same h⁴/λ with λ = `value` (a
    !! length); 2 Jmin = `value` for every tetrahedron (length³; J is six times the volume); 3 off,
    !! plain FEM (a flat tetrahedron is then an error). `value` is ignored for 0 and 3, and must be
    !! finite and > 0 for 1 and 2.
    function tfem_solid_set_tempering(model, mode, value) &
        bind(C, name="tfem_solid_set_tempering") result(status)
      import
      type(c_ptr), value :: model
      integer(c_int), value :: mode
      real(c_double), value :: value
      integer(c_int) :: status
    end function tfem_solid_set_tempering

    !> Chooses the fill-reducing ordering of the factorisation (a `tfem_ordering_mode`: 0 auto, 1
    !! AMD, 2 nested dissection). Results do not depend on it beyond round-off, and are kept.
    function tfem_solid_set_ordering(model, ordering) &
        bind(C, name="tfem_solid_set_ordering") result(status)
      import
      type(c_ptr), value :: model
      integer(c_int), value :: ordering
      integer(c_int) :: status
    end function tfem_solid_set_ordering

    !> Prescribes displacement component `comp` (a `tfem_axis`: 0 x, 1 y, 2 z) of `node` to `value`
    !! (model length units). A component prescribed again takes the new value (unlike `tfem_fix`,
    !! which refuses a different one). Refused, naming it, for a node out of range, a component
    !! other than 0, 1, 2 or a value that is not finite.
    function tfem_solid_fix(model, node, comp, value) &
        bind(C, name="tfem_solid_fix") result(status)
      import
      type(c_ptr), value :: model
      integer(c_int), value :: node
      integer(c_int), value :: comp
      real(c_double), value :: value
      integer(c_int) :: status
    end function tfem_solid_fix

    !> Prescribes component `comp` (0 x, 1 y, 2 z) to `value` on every node of the boundary faces
    !! tagged `tag`, as they are when called (faces are fixed before constraints: see
    !! `tfem_solid_set_boundary_faces`). An unknown tag is refused, naming it.
    function tfem_solid_fix_faces(model, tag, comp, value) &
        bind(C, name="tfem_solid_fix_faces") result(status)
      import
      type(c_ptr), value :: model
      integer(c_int), value :: tag
      integer(c_int), value :: comp
      real(c_double), value :: value
      integer(c_int) :: status
    end function tfem_solid_fix_faces

    !> Removes every prescribed displacement (and so lets the boundary faces change again, once
    !! loads and pairs are cleared too).
    function tfem_solid_clear_constraints(model) &
        bind(C, name="tfem_solid_clear_constraints") result(status)
      import
      type(c_ptr), value :: model
      integer(c_int) :: status
    end function tfem_solid_clear_constraints

    !> Applies pressure `pressure` on the boundary faces tagged `tag`: a stress (force per unit
    !! area, Pa in SI), positive pushing into the body, along each face's outward normal. Loads add
    !! up.
    function tfem_solid_add_pressure(model, tag, pressure) &
        bind(C, name="tfem_solid_add_pressure") result(status)
      import
      type(c_ptr), value :: model
      integer(c_int), value :: tag
      real(c_double), value :: pressure
      integer(c_int) :: status
    end function tfem_solid_add_pressure

    !> Applies the traction (tx, ty, tz) on the boundary faces tagged `tag`: a stress vector (force
    !! per unit area, Pa in SI) whatever the faces' orientation. Loads add up.
    function tfem_solid_add_traction(model, tag, tx, ty, tz) &
        bind(C, name="tfem_solid_add_traction") result(status)
      import
      type(c_ptr), value :: model
      integer(c_int), value :: tag
      real(c_double), value :: tx
      real(c_double), value :: ty
      real(c_double), value :: tz
      integer(c_int) :: status
    end function tfem_solid_add_traction

    !> Adds the point force (fx, fy, fz) at `node` (N in SI). Loads add up.
    function tfem_solid_add_nodal_force(model, node, fx, fy, fz) &
        bind(C, name="tfem_solid_add_nodal_force") result(status)
      import
      type(c_ptr), value :: model
      integer(c_int), value :: node
      real(c_double), value :: fx
      real(c_double), value :: fy
      real(c_double), value :: fz
      integer(c_int) :: status
    end function tfem_solid_add_nodal_force

    !> Removes every load.
    function tfem_solid_clear_loads(model) &
        bind(C, name="tfem_solid_clear_loads") result(status)
      import
      type(c_ptr), value :: model
      integer(c_int) :: status
    end function tfem_solid_clear_loads

    !> Declares a frictionless contact interface between the boundary faces tagged `tag_a` and those
    !! tagged `tag_b`, on two bodies. Side a must be planar: its outward normal is the direction
    !! that opens the gap, and the contact layer B is a layer of flat tetrahedra built across that
    !! plane (docs/method.md §9). Side b must face side a node to node (matching meshes); that, the
    !! planarity and the two bodies are checked by the solve, which names the pair and its tags.
    !! Writes the pair's index (0-based, whatever the index base) to `pair` (may be NULL). Two equal
    !! tags or a tag without faces are refused here, naming the tag.
    function tfem_solid_add_contact_pair(model, tag_a, tag_b, pair) &
        bind(C, name="tfem_solid_add_contact_pair") result(status)
      import
      type(c_ptr), value :: model
      integer(c_int), value :: tag_a
      integer(c_int), value :: tag_b
      integer(c_int), intent(inout) :: pair
      integer(c_int) :: status
    end function tfem_solid_add_contact_pair

    !> Removes every contact pair.
    function tfem_solid_clear_contact_pairs(model) &
        bind(C, name="tfem_solid_clear_contact_pairs") result(status)
      import
      type(c_ptr), value :: model
      integer(c_int) :: status
    end function tfem_solid_clear_contact_pairs

    !> Solves the model with the default contact options (as `tfem_solid_solve_contact` without
    !! options), the call for a model without contact pairs: one linear solve then. `info` may be
    !! NULL.
    function tfem_solid_solve(model, info) &
        bind(C, name="tfem_solid_solve") result(status)
      import
      type(c_ptr), value :: model
      type(tfem_solve_info), intent(inout) :: info
      integer(c_int) :: status
    end function tfem_solid_solve

    !> Solves the model: where it has contact pairs, the tetrahedra of B are switched on where they
    !! would invert, by the active-set loop of the 2D contact solve. `options` may be NULL
    !! (defaults: see `tfem_contact_options_default`); 3D contact is frictionless with its own
    !! inversion test, so `law` must be 0 and `inversion_test` 0 (TFEM_STATUS_INVALID_ARGUMENT
    !! saying so otherwise); `contact_modulus` and `lambda` (0: the smaller E of the pair's bodies,
    !! the other body's for a rigid tool; the mesh's size), `max_iterations` and `refactorize` are
    !! read. `info` may be NULL. A body without material gives TFEM_STATUS_INVALID_MATERIAL naming
    !! it, a body not restrained TFEM_STATUS_SINGULAR naming it, a pair whose sides do not fit (side
    !! a not planar, sides not matching node to node, both on one body) an error naming the pair and
    !! its tags. On error the model is unchanged, its previous results included.
    function tfem_solid_solve_contact(model, options, info) &
        bind(C, name="tfem_solid_solve_contact") result(status)
      import
      type(c_ptr), value :: model
      type(tfem_contact_options), intent(in) :: options
      type(tfem_solve_info), intent(inout) :: info
      integer(c_int) :: status
    end function tfem_solid_solve_contact

    !> One quasi-static load step: the model's loads and prescribed displacements times
    !! `load_factor` (finite; initial gaps as they are), started from the active set of the last
    !! solve or step, on the structure, pattern and symbolic analysis the first solve derived, so
    !! that a load history repeats neither the analysis nor the active-set iterations a cold start
    !! would. Frictionless contact has no memory: a step's answer is that of a solve at its factor,
    !! and the loads may change between steps (a non-proportional history). `options` may be NULL
    !! (defaults; refused as by `tfem_solid_solve_contact`); `info` may be NULL.
    !! `tfem_solid_revert_step` takes the step back. On error the model is unchanged.
    function tfem_solid_step(model, load_factor, options, info) &
        bind(C, name="tfem_solid_step") result(status)
      import
      type(c_ptr), value :: model
      real(c_double), value :: load_factor
      type(tfem_contact_options), intent(in) :: options
      type(tfem_solve_info), intent(inout) :: info
      integer(c_int) :: status
    end function tfem_solid_step

    !> Takes back the last load step: its results, and the active set the next step starts from, are
    !! those before it. Once per step, and not after a change of the model (which discards the
    !! results): refused then with TFEM_STATUS_INVALID_STATE, the model unchanged.
    function tfem_solid_revert_step(model) &
        bind(C, name="tfem_solid_revert_step") result(status)
      import
      type(c_ptr), value :: model
      integer(c_int) :: status
    end function tfem_solid_revert_step

    !> Writes the statistics of the last solve (unknowns, factorisations, interface unknowns,
    !! residual, times) to `info`.
    function tfem_solid_get_solve_info(model, info) &
        bind(C, name="tfem_solid_get_solve_info") result(status)
      import
      type(c_ptr), value :: model
      type(tfem_solve_info), intent(inout) :: info
      integer(c_int) :: status
    end function tfem_solid_get_solve_info

    !> Writes the active-set iterations of the last solve (1 without contact) to `iterations`.
    function tfem_solid_get_iterations(model, iterations) &
        bind(C, name="tfem_solid_get_iterations") result(status)
      import
      type(c_ptr), value :: model
      integer(c_int), intent(inout) :: iterations
      integer(c_int) :: status
    end function tfem_solid_get_iterations

    !> Copies the nodal displacements (ux0 uy0 uz0 ux1 …, 3·n_nodes values) of the last solve into
    !! `out` of `length` values.
    function tfem_solid_get_displacements(model, out, length) &
        bind(C, name="tfem_solid_get_displacements") result(status)
      import
      type(c_ptr), value :: model
      real(c_double), intent(inout) :: out(*)
      integer(c_size_t), value :: length
      integer(c_int) :: status
    end function tfem_solid_get_displacements

    !> Copies element strains (ε_xx ε_yy ε_zz γ_yz γ_xz γ_xy per tetrahedron, engineering shears,
    !! 6·n_tetrahedra values), computed on request and tempered below Jmin as the stiffness is.
    function tfem_solid_get_element_strains(model, out, length) &
        bind(C, name="tfem_solid_get_element_strains") result(status)
      import
      type(c_ptr), value :: model
      real(c_double), intent(inout) :: out(*)
      integer(c_size_t), value :: length
      integer(c_int) :: status
    end function tfem_solid_get_element_strains

    !> Copies element stresses (σ_xx σ_yy σ_zz σ_yz σ_xz σ_xy per tetrahedron, 6·n_tetrahedra
    !! values, the order of the strains; force per unit area, Pa in SI), computed on request. An
    !! overflow gives TFEM_STATUS_NUMERICAL_FAILURE naming the tetrahedron.
    function tfem_solid_get_element_stresses(model, out, length) &
        bind(C, name="tfem_solid_get_element_stresses") result(status)
      import
      type(c_ptr), value :: model
      real(c_double), intent(inout) :: out(*)
      integer(c_size_t), value :: length
      integer(c_int) :: status
    end function tfem_solid_get_element_stresses

    !> Copies reaction forces (Rx Ry Rz per node, 3·n_nodes values, N in SI; zero at components that
    !! are not prescribed), computed on request: with the loads and the contact forces they balance
    !! every body.
    function tfem_solid_get_reactions(model, out, length) &
        bind(C, name="tfem_solid_get_reactions") result(status)
      import
      type(c_ptr), value :: model
      real(c_double), intent(inout) :: out(*)
      integer(c_size_t), value :: length
      integer(c_int) :: status
    end function tfem_solid_get_reactions

    !> Writes the work of the external loads of the last solve, Σ f·u over every node (J in SI): for
    !! a pressure load, the compliance.
    function tfem_solid_get_external_work(model, work) &
        bind(C, name="tfem_solid_get_external_work") result(status)
      import
      type(c_ptr), value :: model
      real(c_double), intent(inout) :: work
      integer(c_int) :: status
    end function tfem_solid_get_external_work

    !> Copies the nodes of every tetrahedron of the contact layer B of the last solve
    !! (4·n_contact_tetrahedra indices in the model's index base, pair by pair, numbered so that
    !! opening the gap makes J positive).
    function tfem_solid_get_contact_tetrahedra(model, out, length) &
        bind(C, name="tfem_solid_get_contact_tetrahedra") result(status)
      import
      type(c_ptr), value :: model
      integer(c_int), intent(inout) :: out(*)
      integer(c_size_t), value :: length
      integer(c_int) :: status
    end function tfem_solid_get_contact_tetrahedra

    !> Copies the active flag (1 pressed, 0 open) of every tetrahedron of B in the last solve
    !! (n_contact_tetrahedra values, see `tfem_solid_get_sizes`).
    function tfem_solid_get_contact_active(model, out, length) &
        bind(C, name="tfem_solid_get_contact_active") result(status)
      import
      type(c_ptr), value :: model
      integer(c_int), intent(inout) :: out(*)
      integer(c_size_t), value :: length
      integer(c_int) :: status
    end function tfem_solid_get_contact_active

    !> Copies the force the contact exerts on every node in the last solve (fx fy fz per node,
    !! 3·n_nodes values, N in SI; zero off the contact interfaces), computed on request: the forces
    !! of one pair sum to zero.
    function tfem_solid_get_contact_forces(model, out, length) &
        bind(C, name="tfem_solid_get_contact_forces") result(status)
      import
      type(c_ptr), value :: model
      real(c_double), intent(inout) :: out(*)
      integer(c_size_t), value :: length
      integer(c_int) :: status
    end function tfem_solid_get_contact_forces

    !> Copies the contact pressure at every node in the last solve (n_nodes values; force per unit
    !! area, Pa in SI, positive in compression; zero off the pairs' faces), computed on request: the
    !! normal force B exerts on the node over its tributary area, a third of each of its faces.
    function tfem_solid_get_contact_nodal_pressures(model, out, length) &
        bind(C, name="tfem_solid_get_contact_nodal_pressures") result(status)
      import
      type(c_ptr), value :: model
      real(c_double), intent(inout) :: out(*)
      integer(c_size_t), value :: length
      integer(c_int) :: status
    end function tfem_solid_get_contact_nodal_pressures

    !> Writes the area in contact in the last solve, every pair together (model length units
    !! squared): each active tetrahedron of B stands for a third of the facing triangle of its
    !! prism, so a closed interface reads its whole area.
    function tfem_solid_get_contact_area(model, area) &
        bind(C, name="tfem_solid_get_contact_area") result(status)
      import
      type(c_ptr), value :: model
      real(c_double), intent(inout) :: area
      integer(c_int) :: status
    end function tfem_solid_get_contact_area

    !> Writes the area in contact of contact pair `pair` alone (0-based, as
    !! `tfem_solid_add_contact_pair` returned it, whatever the index base) in the last solve. An
    !! unknown pair is refused (TFEM_STATUS_INVALID_ARGUMENT naming it).
    function tfem_solid_get_contact_pair_area(model, pair, area) &
        bind(C, name="tfem_solid_get_contact_pair_area") result(status)
      import
      type(c_ptr), value :: model
      integer(c_int), value :: pair
      real(c_double), intent(inout) :: area
      integer(c_int) :: status
    end function tfem_solid_get_contact_pair_area

    !> Writes the solved model to the file `path` (NUL-terminated; on Unix any bytes, as for
    !! `tfem_load_gmsh`) as a VTK XML unstructured grid (`.vtu`, binary appended data, read by
    !! ParaView, VTK and meshio): the tetrahedra in their initial configuration with point data
    !! `displacement` ([u_x, u_y, u_z]) and, when the model has contact pairs, `contact_pressure`
    !! (`tfem_solid_get_contact_nodal_pressures`); cell data `body`, `J` (six times the signed
    !! volume) and `stress` (VTK's order of a symmetric tensor, [σ_xx, σ_yy, σ_zz, σ_xy, σ_yz,
    !! σ_xz], so that its tensor filters read it; not the Voigt order of
    !! `tfem_solid_get_element_stresses`). Returns TFEM_STATUS_INVALID_STATE before a solve,
    !! TFEM_STATUS_NUMERICAL_FAILURE for a result that is not finite (nothing is written then),
    !! TFEM_STATUS_IO when the file cannot be written (the message names it and the reason), and
    !! TFEM_STATUS_INVALID_ARGUMENT if the library was built without the `vtu` feature. The model is
    !! never changed.
    function tfem_solid_write_vtu(model, path) &
        bind(C, name="tfem_solid_write_vtu") result(status)
      import
      type(c_ptr), value :: model
      character(kind=c_char), intent(in) :: path(*)
      integer(c_int) :: status
    end function tfem_solid_write_vtu

    ! ==============================================================================================
    ! Contact for 3D host codes (tfem_solid_contact_*): the contact context of tfem_contact_* for a
    ! code with its own tetrahedral elements and solver, a handle of its own, tfem_solid_contact.
    ! The host gives each side's nodes, coordinates, equations (x, y, z) and triangles,
    ! counter-clockwise seen from outside its body; it gets back B's stiffness and forces in its
    ! equations, in a pattern fixed once, the verdict of the active-set loop, and the state per
    ! tetrahedron of B. Side, pair and tetrahedron numbers are in the context's index base.
    ! ==============================================================================================

    !> Creates a 3D contact context for a host code that keeps its own elements, assembly, solver
    !! and Newton loop: node numbers, equation numbers, and side, pair and contact-tetrahedron
    !! numbers in `index_base` (0 for C, 1 for Fortran). `options` may be NULL (the defaults of
    !! `tfem_contact_options_default`); they are fixed here, as B is built from them once:
    !! `contact_modulus` (0: the smaller Young's modulus of a pair's two sides), `lambda` (0: the
    !! larger side of the interface nodes' bounding box) and `max_iterations` (the number of
    !! `tfem_solid_contact_update` calls of one loop before it counts as not converged) are read,
    !! `refactorize` is ignored; 3D contact is frictionless with its own inversion test, so `law`
    !! and `inversion_test` must be 0. Returns NULL if `index_base` is not 0 or 1 or an option is
    !! refused (message in `tfem_last_error(NULL, …)`), or memory is exhausted. The host then adds
    !! the sides (`tfem_solid_contact_add_side`) and pairs (`tfem_solid_contact_add_pair`); the
    !! first call that needs B builds it, after which sides and pairs are fixed. A 3D context is its
    !! own handle: the 2D `tfem_contact_*` functions refuse it, and these refuse a 2D context or a
    !! model.
    function tfem_solid_contact_create(index_base, options) &
        bind(C, name="tfem_solid_contact_create") result(res)
      import
      integer(c_int), value :: index_base
      type(tfem_contact_options), intent(in) :: options
      type(c_ptr) :: res
    end function tfem_solid_contact_create

    !> Destroys a 3D contact context. NULL is a no-op, and so is a pointer that is not a live 3D
    !! context (destroyed already, or another kind of handle): do not use a handle after destroying
    !! it.
    subroutine tfem_solid_contact_destroy(context) &
        bind(C, name="tfem_solid_contact_destroy")
      import
      type(c_ptr), value :: context
    end subroutine tfem_solid_contact_destroy

    !> Copies the message of the last failed call on `context` (empty after a successful call) into
    !! `buffer` (`length` bytes including the final NUL), truncating like `tfem_last_error`
    !! (TFEM_STATUS_BUFFER_TOO_SMALL; `tfem_solid_contact_last_error_length` gives the size needed).
    !! A 3D context keeps its own messages. A `context` that is not a live 3D contact context gives
    !! TFEM_STATUS_INVALID_ARGUMENT with the message saying so in `buffer`.
    function tfem_solid_contact_last_error(context, buffer, length) &
        bind(C, name="tfem_solid_contact_last_error") result(status)
      import
      type(c_ptr), value :: context
      character(kind=c_char), intent(inout) :: buffer(*)
      integer(c_size_t), value :: length
      integer(c_int) :: status
    end function tfem_solid_contact_last_error

    !> Size in bytes (including the final NUL) of the message `tfem_solid_contact_last_error` would
    !! give for `context`, so that a buffer of this size holds all of it: 1 after a successful call;
    !! for a handle that is not a live 3D contact context (destroyed, or another kind), the size of
    !! the message saying so. `context` may be NULL: 1 (it has no message).
    function tfem_solid_contact_last_error_length(context) &
        bind(C, name="tfem_solid_contact_last_error_length") result(res)
      import
      type(c_ptr), value :: context
      integer(c_size_t) :: res
    end function tfem_solid_contact_last_error_length

    !> Adds one side of a contact interface, of body `body` (Young's modulus `young`, finite and >
    !! 0: the softer side's is the default E_c): `n_nodes` interface nodes `nodes` (the host's node
    !! numbers) with their coordinates `xyz` (3 per node) and the equations of their x, y and z
    !! unknowns `equations` (3 per node, in the index base; a value below the base marks a fixed DOF
    !! without an equation), and `n_triangles` triangles `triangles` (3 host node numbers each)
    !! numbered counter-clockwise seen from outside the body, so that the two sides of a pair face
    !! each other. A node of two sides, or given twice in one, must come with the same coordinates
    !! and equations. Refused with TFEM_STATUS_INVALID_ARGUMENT, naming the side (by its number in
    !! the index base and its tag), the node or the triangle: a node number below the index base, a
    !! coordinate that is not finite, an equation no host vector can hold (from index_base +
    !! PTRDIFF_MAX / 8 on), a triangle over a node the side does not give, a side without triangles;
    !! TFEM_STATUS_INVALID_STATE once B is built. The host's system size is not known here:
    !! `tfem_solid_contact_gather` and `tfem_solid_contact_scatter_add` check every equation against
    !! the vector they are given. Writes the side's number (in the index base) to `side` (may be
    !! NULL). On error nothing changes.
    function tfem_solid_contact_add_side(context, tag, body, young, n_nodes, nodes, xyz, equations, &
        n_triangles, triangles, side) &
        bind(C, name="tfem_solid_contact_add_side") result(status)
      import
      type(c_ptr), value :: context
      integer(c_int), value :: tag
      integer(c_int), value :: body
      real(c_double), value :: young
      integer(c_int), value :: n_nodes
      integer(c_int), intent(in) :: nodes(*)
      real(c_double), intent(in) :: xyz(*)
      integer(c_int64_t), intent(in) :: equations(*)
      integer(c_int), value :: n_triangles
      integer(c_int), intent(in) :: triangles(*)
      integer(c_int), intent(inout) :: side
      integer(c_int) :: status
    end function tfem_solid_contact_add_side

    !> Declares sides `side_a` and `side_b` (their numbers in the index base, of two different
    !! bodies) a contact pair: side a must be planar (its outward normal opens the gap) and side b
    !! face it node to node; B, a layer of flat tetrahedra over the prisms between the facing
    !! triangles, is built from them (docs/method.md §9). A side that does not exist, or two sides
    !! of one body, are refused with TFEM_STATUS_INVALID_ARGUMENT naming them; sides that do not fit
    !! (side a not planar, sides not facing each other or not matching) are refused by the call that
    !! builds B, naming the pair and its sides. Writes the pair's number (in the index base) to
    !! `pair` (may be NULL).
    function tfem_solid_contact_add_pair(context, side_a, side_b, pair) &
        bind(C, name="tfem_solid_contact_add_pair") result(status)
      import
      type(c_ptr), value :: context
      integer(c_int), value :: side_a
      integer(c_int), value :: side_b
      integer(c_int), intent(inout) :: pair
      integer(c_int) :: status
    end function tfem_solid_contact_add_pair

    !> Builds B of every pair and the pattern now, so that a host learns of sides that do not fit
    !! where it declares them rather than at its first evaluation (every call that needs B builds it
    !! otherwise). Sides and pairs are fixed from then on; the active set starts from the tetrahedra
    !! touching or overlapping at rest. Without a pair, TFEM_STATUS_INVALID_STATE. Calling it again
    !! does nothing.
    function tfem_solid_contact_setup(context) &
        bind(C, name="tfem_solid_contact_setup") result(status)
      import
      type(c_ptr), value :: context
      integer(c_int) :: status
    end function tfem_solid_contact_setup

    !> Builds B (if not yet) and writes the sizes: interface nodes (3 values per node in every
    !! per-node array: displacements and residuals), tetrahedra of B (the length of the
    !! per-tetrahedron arrays), and entries of the pattern. Any pointer may be NULL.
    function tfem_solid_contact_sizes(context, n_nodes, n_tetrahedra, n_entries) &
        bind(C, name="tfem_solid_contact_sizes") result(status)
      import
      type(c_ptr), value :: context
      integer(c_int), intent(inout) :: n_nodes
      integer(c_int), intent(inout) :: n_tetrahedra
      integer(c_int64_t), intent(inout) :: n_entries
      integer(c_int) :: status
    end function tfem_solid_contact_sizes

    !> Copies the interface nodes (host numbers, n_nodes values), in the order of every per-node
    !! array: the order in which the sides first gave them.
    function tfem_solid_contact_nodes(context, out, length) &
        bind(C, name="tfem_solid_contact_nodes") result(status)
      import
      type(c_ptr), value :: context
      integer(c_int), intent(inout) :: out(*)
      integer(c_size_t), value :: length
      integer(c_int) :: status
    end function tfem_solid_contact_nodes

    !> Copies the nodes of every tetrahedron of B (4 host node numbers each, numbered so that J
    !! grows as the gap opens), pair by pair: with the per-tetrahedron arrays (active flags, gaps),
    !! where the contact is.
    function tfem_solid_contact_tetrahedra(context, out, length) &
        bind(C, name="tfem_solid_contact_tetrahedra") result(status)
      import
      type(c_ptr), value :: context
      integer(c_int), intent(inout) :: out(*)
      integer(c_size_t), value :: length
      integer(c_int) :: status
    end function tfem_solid_contact_tetrahedra

    !> Copies the fixed pattern of the contact contributions into `rows` (n_entries values) and
    !! `cols` (n_entries values), in the host's equation numbering and index base: tetrahedron after
    !! tetrahedron of B, each one's 12×12 block row by row over its DOFs (x, y, z of its first node,
    !! then of its second …), the DOFs without an equation left out; both triangles of each block.
    !! Entries repeat where tetrahedra share a DOF pair: the host sums them. B's topology never
    !! changes, so a host sets up its sparse matrix once.
    function tfem_solid_contact_pattern(context, rows, cols, length) &
        bind(C, name="tfem_solid_contact_pattern") result(status)
      import
      type(c_ptr), value :: context
      integer(c_int64_t), intent(inout) :: rows(*)
      integer(c_int64_t), intent(inout) :: cols(*)
      integer(c_size_t), value :: length
      integer(c_int) :: status
    end function tfem_solid_contact_pattern

    !> Copies the equations of every tetrahedron's twelve DOFs (12 per tetrahedron, x, y, z of each
    !! node, in the index base; index_base − 1 marks a DOF without an equation): with
    !! `tfem_solid_contact_element_blocks`, the contributions as unassembled element blocks, for a
    !! host that assembles elements rather than a pattern.
    function tfem_solid_contact_element_equations(context, out, length) &
        bind(C, name="tfem_solid_contact_element_equations") result(status)
      import
      type(c_ptr), value :: context
      integer(c_int64_t), intent(inout) :: out(*)
      integer(c_size_t), value :: length
      integer(c_int) :: status
    end function tfem_solid_contact_element_equations

    !> Copies every tetrahedron's 12×12 tangent block (144 values per tetrahedron, row-major over
    !! its DOFs as in `tfem_solid_contact_element_equations`): its stiffness when active, zeros when
    !! not.
    function tfem_solid_contact_element_blocks(context, out, length) &
        bind(C, name="tfem_solid_contact_element_blocks") result(status)
      import
      type(c_ptr), value :: context
      real(c_double), intent(inout) :: out(*)
      integer(c_size_t), value :: length
      integer(c_int) :: status
    end function tfem_solid_contact_element_blocks

    !> The contact contributions at the displacements `u` of the interface nodes (3 per node,
    !! `u_length` = 3·n_nodes): the tangent's values in the pattern's order into `values` (n_entries
    !! values, zeros for inactive tetrahedra), and the contact residual Σ (K_e u_e − f0_e) of the
    !! active tetrahedra, 3 per interface node, into `residual`. `values` may be NULL; `residual`
    !! may be NULL. A linear host adds the values to its matrix and minus the residual at u₀ to its
    !! right-hand side, u₀ zero at DOFs with an equation and the prescribed value at those without
    !! (a rigid tool pressed by δ: `tfem_solid_contact_gather` reads such DOFs as 0, so set them in
    !! `u` itself, here and for `tfem_solid_contact_update`); that is the load of the initial gaps
    !! and of the prescribed values. A Newton host adds the values to its tangent and the residual
    !! at its current u to its residual. The law is linear in u for a given active set: the values
    !! depend on the active set only, and change only when `tfem_solid_contact_update` or
    !! `tfem_solid_contact_set_active` changes it. A non-finite value in `u` is refused
    !! (TFEM_STATUS_INVALID_ARGUMENT naming the node); a residual that overflows is
    !! TFEM_STATUS_NUMERICAL_FAILURE naming the node; either way the buffers are unchanged.
    function tfem_solid_contact_evaluate(context, u, u_length, values, values_length, residual, &
        residual_length) &
        bind(C, name="tfem_solid_contact_evaluate") result(status)
      import
      type(c_ptr), value :: context
      real(c_double), intent(in) :: u(*)
      integer(c_size_t), value :: u_length
      real(c_double), intent(inout) :: values(*)
      integer(c_size_t), value :: values_length
      real(c_double), intent(inout) :: residual(*)
      integer(c_size_t), value :: residual_length
      integer(c_int) :: status
    end function tfem_solid_contact_evaluate

    !> Copies into `u` (3 per interface node) the displacements of the interface nodes from the
    !! host's solution vector `u_equations` (`n_equations` values; entry i is equation i +
    !! index_base); a DOF without an equation counts as fixed at zero. An interface node's equation
    !! beyond `n_equations`, or a non-finite entry there, is refused (TFEM_STATUS_INVALID_ARGUMENT
    !! naming the node and the equation); `u` is then unchanged.
    function tfem_solid_contact_gather(context, u_equations, n_equations, u, u_length) &
        bind(C, name="tfem_solid_contact_gather") result(status)
      import
      type(c_ptr), value :: context
      real(c_double), intent(in) :: u_equations(*)
      integer(c_size_t), value :: n_equations
      real(c_double), intent(inout) :: u(*)
      integer(c_size_t), value :: u_length
      integer(c_int) :: status
    end function tfem_solid_contact_gather

    !> Adds per-node values `residual` (3 per interface node, as `tfem_solid_contact_evaluate`
    !! writes them) into the host's vector `host_vector` (`n_equations` values, entry i is equation
    !! i + index_base); DOFs without an equation are left out. A non-finite value in `residual` is
    !! refused (TFEM_STATUS_INVALID_ARGUMENT naming the node), and so is a sum that would not be
    !! finite: an entry of `host_vector` that is not finite already (TFEM_STATUS_INVALID_ARGUMENT),
    !! or an overflow (TFEM_STATUS_NUMERICAL_FAILURE), naming the node and the equation; an equation
    !! beyond `n_equations` is refused naming the node. `host_vector` is then unchanged.
    function tfem_solid_contact_scatter_add(context, residual, residual_length, host_vector, n_equations) &
        bind(C, name="tfem_solid_contact_scatter_add") result(status)
      import
      type(c_ptr), value :: context
      real(c_double), intent(in) :: residual(*)
      integer(c_size_t), value :: residual_length
      real(c_double), intent(inout) :: host_vector(*)
      integer(c_size_t), value :: n_equations
      integer(c_int) :: status
    end function tfem_solid_contact_scatter_add

    !> The inversion test at the displacements `u` (3 per interface node) of a solve with the
    !! current active set: the tetrahedra of B whose gap is not positive (pressed, or touching) are
    !! switched on, the others off. `changed` (may be NULL) is set to 1 if the set changed, 0 if it
    !! settled; `switched_on` (may be NULL) and `switched_off` (may be NULL) to the number of
    !! tetrahedra switched each way. The same test and cycle detection as tfem's own loop: a set
    !! visited before, or more calls than the options' `max_iterations` since the last
    !! `tfem_solid_contact_restart`, gives TFEM_STATUS_NOT_CONVERGED with the history, the set
    !! unchanged. Call it with converged displacements of the host's problem for the current set
    !! (after its Newton loop, not at every Newton iteration): the test judges the solution. A
    !! non-finite value in `u` is refused (TFEM_STATUS_INVALID_ARGUMENT naming the node).
    function tfem_solid_contact_update(context, u, u_length, changed, switched_on, switched_off) &
        bind(C, name="tfem_solid_contact_update") result(status)
      import
      type(c_ptr), value :: context
      real(c_double), intent(in) :: u(*)
      integer(c_size_t), value :: u_length
      integer(c_int), intent(inout) :: changed
      integer(c_int), intent(inout) :: switched_on
      integer(c_int), intent(inout) :: switched_off
      integer(c_int) :: status
    end function tfem_solid_contact_update

    !> Starts a new active-set loop from the current flags (a new load step): the history and the
    !! sets visited are forgotten, so that a set met in an earlier step is no cycle.
    function tfem_solid_contact_restart(context) &
        bind(C, name="tfem_solid_contact_restart") result(status)
      import
      type(c_ptr), value :: context
      integer(c_int) :: status
    end function tfem_solid_contact_restart

    !> Copies the active flag (1 active, 0 not) of every tetrahedron of B (n_tetrahedra values): the
    !! state a host saves to restore with `tfem_solid_contact_set_active`.
    function tfem_solid_contact_get_active(context, out, length) &
        bind(C, name="tfem_solid_contact_get_active") result(status)
      import
      type(c_ptr), value :: context
      integer(c_int), intent(inout) :: out(*)
      integer(c_size_t), value :: length
      integer(c_int) :: status
    end function tfem_solid_contact_get_active

    !> Sets the active flags of the tetrahedra of B (n_tetrahedra values, 0 or 1): a warm start or a
    !! restored state; starts a new loop. A value other than 0 or 1, or another count, is refused
    !! (TFEM_STATUS_INVALID_ARGUMENT), the flags unchanged.
    function tfem_solid_contact_set_active(context, active, length) &
        bind(C, name="tfem_solid_contact_set_active") result(status)
      import
      type(c_ptr), value :: context
      integer(c_int), intent(in) :: active(*)
      integer(c_size_t), value :: length
      integer(c_int) :: status
    end function tfem_solid_contact_set_active

    !> Copies the opening of every tetrahedron of B (n_tetrahedra values, model length units) at the
    !! displacements `u` (3 per interface node): its linearised gap over its facing area, the
    !! distance across the interface (negative: an overlap). Per tetrahedron rather than per node as
    !! in 2D: in space a node's tetrahedra may face different triangles. A non-finite value in `u`
    !! is refused (TFEM_STATUS_INVALID_ARGUMENT naming the node), a gap that overflows is
    !! TFEM_STATUS_NUMERICAL_FAILURE naming the tetrahedron; `out` is then unchanged.
    function tfem_solid_contact_gaps(context, u, u_length, out, length) &
        bind(C, name="tfem_solid_contact_gaps") result(status)
      import
      type(c_ptr), value :: context
      real(c_double), intent(in) :: u(*)
      integer(c_size_t), value :: u_length
      real(c_double), intent(inout) :: out(*)
      integer(c_size_t), value :: length
      integer(c_int) :: status
    end function tfem_solid_contact_gaps

    !> Writes the area in contact of the current active set to `area` (model length units squared):
    !! each active tetrahedron of B stands for a third of its prism's facing triangle, so that a
    !! closed interface reads its whole area. A sum that overflows is TFEM_STATUS_NUMERICAL_FAILURE.
    function tfem_solid_contact_area(context, area) &
        bind(C, name="tfem_solid_contact_area") result(status)
      import
      type(c_ptr), value :: context
      real(c_double), intent(inout) :: area
      integer(c_int) :: status
    end function tfem_solid_contact_area
  end interface
end module tfem_c

! The module procedures behind the generic interfaces of module tfem (see "Generic
! interfaces" above); not for direct use.
module tfem_specifics
  use, intrinsic :: iso_c_binding
  use tfem_c, only: tfem_contact_options, tfem_solve_info, tfem_contact_report, tfem_adapt_report, &
        tfem_last_error, tfem_last_error_length, tfem_get_warning, tfem_get_mesh_nodes, &
        tfem_get_contact_mesh, tfem_get_contact_element_pairs, tfem_get_contact_element_apexes, &
        tfem_get_displacements, tfem_get_element_strains, tfem_get_element_stresses, &
        tfem_get_element_out_of_plane_stresses, tfem_get_element_jacobians, tfem_get_reactions, &
        tfem_get_contact_forces, tfem_get_contact_nodal_pressures, tfem_get_contact_nodal_tractions, &
        tfem_get_contact_pair_nodal_pressures, tfem_get_contact_pair_nodal_tractions, &
        tfem_get_contact_gaps, tfem_get_contact_active, tfem_get_contact_pressure, &
        tfem_get_contact_elements, tfem_get_contact_shear, tfem_get_contact_friction_state, &
        tfem_get_contact_dissipation, tfem_get_contact_state, tfem_set_contact_state, &
        tfem_get_system_matrix, tfem_contact_last_error, tfem_contact_last_error_length, &
        tfem_contact_nodes, tfem_contact_pattern, tfem_contact_gather, tfem_contact_scatter_add, &
        tfem_contact_get_active, tfem_contact_set_active, tfem_contact_gaps, tfem_contact_pressures, &
        tfem_contact_elements, tfem_contact_element_equations, tfem_contact_element_blocks, &
        tfem_solid_last_error, tfem_solid_last_error_length, tfem_solid_get_warning, &
        tfem_solid_get_mesh_nodes, tfem_solid_get_displacements, tfem_solid_get_element_strains, &
        tfem_solid_get_element_stresses, tfem_solid_get_reactions, tfem_solid_get_contact_tetrahedra, &
        tfem_solid_get_contact_active, tfem_solid_get_contact_forces, &
        tfem_solid_get_contact_nodal_pressures, tfem_solid_contact_last_error, &
        tfem_solid_contact_last_error_length, tfem_solid_contact_nodes, tfem_solid_contact_tetrahedra, &
        tfem_solid_contact_pattern, tfem_solid_contact_element_equations, &
        tfem_solid_contact_element_blocks, tfem_solid_contact_gather, tfem_solid_contact_scatter_add, &
        tfem_solid_contact_get_active, tfem_solid_contact_set_active, tfem_solid_contact_gaps
  implicit none
  private
  public :: tfem_length_kind
  public :: tfem_last_error_i, tfem_last_error_str, tfem_last_error_str_i, tfem_last_error_no_model
  public :: tfem_last_error_no_model_i, tfem_last_error_no_model_str, tfem_last_error_no_model_str_i
  public :: tfem_last_error_length_no_model, tfem_get_warning_i, tfem_get_warning_str
  public :: tfem_get_warning_str_i, tfem_get_sizes_opt, tfem_get_mesh_nodes_r2
  public :: tfem_get_mesh_nodes_i, tfem_get_mesh_nodes_i_r2, tfem_get_mesh_triangles_opt
  public :: tfem_get_mesh_triangles_opt_r21, tfem_get_mesh_triangles_opt_r12
  public :: tfem_get_mesh_triangles_opt_r22, tfem_get_mesh_triangles_opt_i
  public :: tfem_get_mesh_triangles_opt_i_r21, tfem_get_mesh_triangles_opt_i_r12
  public :: tfem_get_mesh_triangles_opt_i_r22, tfem_get_boundary_edges_opt
  public :: tfem_get_boundary_edges_opt_r21, tfem_get_boundary_edges_opt_r12
  public :: tfem_get_boundary_edges_opt_r22, tfem_get_boundary_edges_opt_i
  public :: tfem_get_boundary_edges_opt_i_r21, tfem_get_boundary_edges_opt_i_r12
  public :: tfem_get_boundary_edges_opt_i_r22, tfem_add_contact_pair_opt
  public :: tfem_add_contact_pair_with_mesh_opt, tfem_add_contact_pair_with_mesh_opt_r2
  public :: tfem_add_contact_pairs_auto_opt, tfem_add_contact_pairs_auto_opt_r2
  public :: tfem_get_contact_mesh_r2, tfem_get_contact_mesh_i, tfem_get_contact_mesh_i_r2
  public :: tfem_get_contact_element_pairs_r2, tfem_get_contact_element_pairs_i
  public :: tfem_get_contact_element_pairs_i_r2, tfem_get_contact_element_apexes_r2
  public :: tfem_get_contact_element_apexes_i, tfem_get_contact_element_apexes_i_r2
  public :: tfem_get_contact_pair_bodies_opt, tfem_solve_opt, tfem_solve_contact_opt
  public :: tfem_solve_adaptive_opt, tfem_get_adapt_cycles_opt, tfem_get_adapt_cycles_opt_r2
  public :: tfem_get_adapt_cycles_opt_i, tfem_get_adapt_cycles_opt_i_r2, tfem_get_displacements_r2
  public :: tfem_get_displacements_i, tfem_get_displacements_i_r2, tfem_get_element_strains_r2
  public :: tfem_get_element_strains_i, tfem_get_element_strains_i_r2, tfem_get_element_stresses_r2
  public :: tfem_get_element_stresses_i, tfem_get_element_stresses_i_r2
  public :: tfem_get_element_out_of_plane_stresses_r2, tfem_get_element_out_of_plane_stresses_i
  public :: tfem_get_element_out_of_plane_stresses_i_r2, tfem_get_element_jacobians_r2
  public :: tfem_get_element_jacobians_i, tfem_get_element_jacobians_i_r2, tfem_get_reactions_r2
  public :: tfem_get_reactions_i, tfem_get_reactions_i_r2, tfem_get_contact_forces_r2
  public :: tfem_get_contact_forces_i, tfem_get_contact_forces_i_r2
  public :: tfem_get_contact_nodal_pressures_r2, tfem_get_contact_nodal_pressures_i
  public :: tfem_get_contact_nodal_pressures_i_r2, tfem_get_contact_nodal_tractions_r2
  public :: tfem_get_contact_nodal_tractions_i, tfem_get_contact_nodal_tractions_i_r2
  public :: tfem_get_contact_pair_nodal_pressures_r2, tfem_get_contact_pair_nodal_pressures_i
  public :: tfem_get_contact_pair_nodal_pressures_i_r2, tfem_get_contact_pair_nodal_tractions_r2
  public :: tfem_get_contact_pair_nodal_tractions_i, tfem_get_contact_pair_nodal_tractions_i_r2
  public :: tfem_get_contact_gaps_r2, tfem_get_contact_gaps_i, tfem_get_contact_gaps_i_r2
  public :: tfem_get_contact_active_r2, tfem_get_contact_active_i, tfem_get_contact_active_i_r2
  public :: tfem_get_contact_pressure_r2, tfem_get_contact_pressure_i
  public :: tfem_get_contact_pressure_i_r2, tfem_get_contact_elements_r2
  public :: tfem_get_contact_elements_i, tfem_get_contact_elements_i_r2, tfem_get_contact_shear_r2
  public :: tfem_get_contact_shear_i, tfem_get_contact_shear_i_r2
  public :: tfem_get_contact_friction_state_r2, tfem_get_contact_friction_state_i
  public :: tfem_get_contact_friction_state_i_r2, tfem_get_contact_dissipation_r2
  public :: tfem_get_contact_dissipation_i, tfem_get_contact_dissipation_i_r2
  public :: tfem_get_contact_slave_nodes_opt, tfem_get_contact_slave_nodes_opt_r2111
  public :: tfem_get_contact_slave_nodes_opt_r1211, tfem_get_contact_slave_nodes_opt_r2211
  public :: tfem_get_contact_slave_nodes_opt_r1121, tfem_get_contact_slave_nodes_opt_r2121
  public :: tfem_get_contact_slave_nodes_opt_r1221, tfem_get_contact_slave_nodes_opt_r2221
  public :: tfem_get_contact_slave_nodes_opt_r1112, tfem_get_contact_slave_nodes_opt_r2112
  public :: tfem_get_contact_slave_nodes_opt_r1212, tfem_get_contact_slave_nodes_opt_r2212
  public :: tfem_get_contact_slave_nodes_opt_r1122, tfem_get_contact_slave_nodes_opt_r2122
  public :: tfem_get_contact_slave_nodes_opt_r1222, tfem_get_contact_slave_nodes_opt_r2222
  public :: tfem_get_contact_slave_nodes_opt_i, tfem_get_contact_slave_nodes_opt_i_r2111
  public :: tfem_get_contact_slave_nodes_opt_i_r1211, tfem_get_contact_slave_nodes_opt_i_r2211
  public :: tfem_get_contact_slave_nodes_opt_i_r1121, tfem_get_contact_slave_nodes_opt_i_r2121
  public :: tfem_get_contact_slave_nodes_opt_i_r1221, tfem_get_contact_slave_nodes_opt_i_r2221
  public :: tfem_get_contact_slave_nodes_opt_i_r1112, tfem_get_contact_slave_nodes_opt_i_r2112
  public :: tfem_get_contact_slave_nodes_opt_i_r1212, tfem_get_contact_slave_nodes_opt_i_r2212
  public :: tfem_get_contact_slave_nodes_opt_i_r1122, tfem_get_contact_slave_nodes_opt_i_r2122
  public :: tfem_get_contact_slave_nodes_opt_i_r1222, tfem_get_contact_slave_nodes_opt_i_r2222
  public :: tfem_step_opt, tfem_get_contact_state_r2, tfem_get_contact_state_i
  public :: tfem_get_contact_state_i_r2, tfem_set_contact_state_r2, tfem_set_contact_state_i
  public :: tfem_set_contact_state_i_r2, tfem_get_system_matrix_size_opt
  public :: tfem_get_system_matrix_r2111, tfem_get_system_matrix_r1211, tfem_get_system_matrix_r2211
  public :: tfem_get_system_matrix_r1121, tfem_get_system_matrix_r2121, tfem_get_system_matrix_r1221
  public :: tfem_get_system_matrix_r2221, tfem_get_system_matrix_r1112, tfem_get_system_matrix_r2112
  public :: tfem_get_system_matrix_r1212, tfem_get_system_matrix_r2212, tfem_get_system_matrix_r1122
  public :: tfem_get_system_matrix_r2122, tfem_get_system_matrix_r1222, tfem_get_system_matrix_r2222
  public :: tfem_get_system_matrix_i, tfem_get_system_matrix_i_r2111, tfem_get_system_matrix_i_r1211
  public :: tfem_get_system_matrix_i_r2211, tfem_get_system_matrix_i_r1121
  public :: tfem_get_system_matrix_i_r2121, tfem_get_system_matrix_i_r1221
  public :: tfem_get_system_matrix_i_r2221, tfem_get_system_matrix_i_r1112
  public :: tfem_get_system_matrix_i_r2112, tfem_get_system_matrix_i_r1212
  public :: tfem_get_system_matrix_i_r2212, tfem_get_system_matrix_i_r1122
  public :: tfem_get_system_matrix_i_r2122, tfem_get_system_matrix_i_r1222
  public :: tfem_get_system_matrix_i_r2222, tfem_contact_last_error_i, tfem_contact_last_error_str
  public :: tfem_contact_last_error_str_i, tfem_contact_last_error_length_no_context
  public :: tfem_contact_add_side_opt, tfem_contact_add_side_opt_r2111
  public :: tfem_contact_add_side_opt_r1211, tfem_contact_add_side_opt_r2211
  public :: tfem_contact_add_side_opt_r1121, tfem_contact_add_side_opt_r2121
  public :: tfem_contact_add_side_opt_r1221, tfem_contact_add_side_opt_r2221
  public :: tfem_contact_add_side_opt_r1112, tfem_contact_add_side_opt_r2112
  public :: tfem_contact_add_side_opt_r1212, tfem_contact_add_side_opt_r2212
  public :: tfem_contact_add_side_opt_r1122, tfem_contact_add_side_opt_r2122
  public :: tfem_contact_add_side_opt_r1222, tfem_contact_add_side_opt_r2222
  public :: tfem_contact_add_pair_opt, tfem_contact_add_pair_with_mesh_opt
  public :: tfem_contact_add_pair_with_mesh_opt_r2, tfem_contact_sizes_opt, tfem_contact_nodes_r2
  public :: tfem_contact_nodes_i, tfem_contact_nodes_i_r2, tfem_contact_pattern_r21
  public :: tfem_contact_pattern_r12, tfem_contact_pattern_r22, tfem_contact_pattern_i
  public :: tfem_contact_pattern_i_r21, tfem_contact_pattern_i_r12, tfem_contact_pattern_i_r22
  public :: tfem_contact_evaluate_opt, tfem_contact_evaluate_opt_r211
  public :: tfem_contact_evaluate_opt_r121, tfem_contact_evaluate_opt_r221
  public :: tfem_contact_evaluate_opt_r112, tfem_contact_evaluate_opt_r212
  public :: tfem_contact_evaluate_opt_r122, tfem_contact_evaluate_opt_r222
  public :: tfem_contact_evaluate_opt_i, tfem_contact_evaluate_opt_i_r211
  public :: tfem_contact_evaluate_opt_i_r121, tfem_contact_evaluate_opt_i_r221
  public :: tfem_contact_evaluate_opt_i_r112, tfem_contact_evaluate_opt_i_r212
  public :: tfem_contact_evaluate_opt_i_r122, tfem_contact_evaluate_opt_i_r222
  public :: tfem_contact_gather_r21, tfem_contact_gather_r12, tfem_contact_gather_r22
  public :: tfem_contact_gather_i, tfem_contact_gather_i_r21, tfem_contact_gather_i_r12
  public :: tfem_contact_gather_i_r22, tfem_contact_scatter_add_r21, tfem_contact_scatter_add_r12
  public :: tfem_contact_scatter_add_r22, tfem_contact_scatter_add_i, tfem_contact_scatter_add_i_r21
  public :: tfem_contact_scatter_add_i_r12, tfem_contact_scatter_add_i_r22, tfem_contact_update_opt
  public :: tfem_contact_update_opt_r2, tfem_contact_update_opt_i, tfem_contact_update_opt_i_r2
  public :: tfem_contact_get_active_r2, tfem_contact_get_active_i, tfem_contact_get_active_i_r2
  public :: tfem_contact_set_active_r2, tfem_contact_set_active_i, tfem_contact_set_active_i_r2
  public :: tfem_contact_gaps_r21, tfem_contact_gaps_r12, tfem_contact_gaps_r22, tfem_contact_gaps_i
  public :: tfem_contact_gaps_i_r21, tfem_contact_gaps_i_r12, tfem_contact_gaps_i_r22
  public :: tfem_contact_pressures_r21, tfem_contact_pressures_r12, tfem_contact_pressures_r22
  public :: tfem_contact_pressures_i, tfem_contact_pressures_i_r21, tfem_contact_pressures_i_r12
  public :: tfem_contact_pressures_i_r22, tfem_contact_elements_r2, tfem_contact_elements_i
  public :: tfem_contact_elements_i_r2, tfem_contact_element_equations_r2
  public :: tfem_contact_element_equations_i, tfem_contact_element_equations_i_r2
  public :: tfem_contact_element_blocks_r2, tfem_contact_element_blocks_i
  public :: tfem_contact_element_blocks_i_r2, tfem_solid_last_error_i, tfem_solid_last_error_str
  public :: tfem_solid_last_error_str_i, tfem_solid_last_error_length_no_model
  public :: tfem_solid_get_warning_i, tfem_solid_get_warning_str, tfem_solid_get_warning_str_i
  public :: tfem_solid_get_sizes_opt, tfem_solid_get_mesh_nodes_r2, tfem_solid_get_mesh_nodes_i
  public :: tfem_solid_get_mesh_nodes_i_r2, tfem_solid_get_mesh_tetrahedra_opt
  public :: tfem_solid_get_mesh_tetrahedra_opt_r21, tfem_solid_get_mesh_tetrahedra_opt_r12
  public :: tfem_solid_get_mesh_tetrahedra_opt_r22, tfem_solid_get_mesh_tetrahedra_opt_i
  public :: tfem_solid_get_mesh_tetrahedra_opt_i_r21, tfem_solid_get_mesh_tetrahedra_opt_i_r12
  public :: tfem_solid_get_mesh_tetrahedra_opt_i_r22, tfem_solid_get_boundary_faces_opt
  public :: tfem_solid_get_boundary_faces_opt_r21, tfem_solid_get_boundary_faces_opt_r12
  public :: tfem_solid_get_boundary_faces_opt_r22, tfem_solid_get_boundary_faces_opt_i
  public :: tfem_solid_get_boundary_faces_opt_i_r21, tfem_solid_get_boundary_faces_opt_i_r12
  public :: tfem_solid_get_boundary_faces_opt_i_r22, tfem_solid_add_contact_pair_opt
  public :: tfem_solid_solve_opt, tfem_solid_solve_contact_opt, tfem_solid_step_opt
  public :: tfem_solid_get_displacements_r2, tfem_solid_get_displacements_i
  public :: tfem_solid_get_displacements_i_r2, tfem_solid_get_element_strains_r2
  public :: tfem_solid_get_element_strains_i, tfem_solid_get_element_strains_i_r2
  public :: tfem_solid_get_element_stresses_r2, tfem_solid_get_element_stresses_i
  public :: tfem_solid_get_element_stresses_i_r2, tfem_solid_get_reactions_r2
  public :: tfem_solid_get_reactions_i, tfem_solid_get_reactions_i_r2
  public :: tfem_solid_get_contact_tetrahedra_r2, tfem_solid_get_contact_tetrahedra_i
  public :: tfem_solid_get_contact_tetrahedra_i_r2, tfem_solid_get_contact_active_r2
  public :: tfem_solid_get_contact_active_i, tfem_solid_get_contact_active_i_r2
  public :: tfem_solid_get_contact_forces_r2, tfem_solid_get_contact_forces_i
  public :: tfem_solid_get_contact_forces_i_r2, tfem_solid_get_contact_nodal_pressures_r2
  public :: tfem_solid_get_contact_nodal_pressures_i, tfem_solid_get_contact_nodal_pressures_i_r2
  public :: tfem_solid_contact_create_opt, tfem_solid_contact_last_error_i
  public :: tfem_solid_contact_last_error_str, tfem_solid_contact_last_error_str_i
  public :: tfem_solid_contact_last_error_length_no_context, tfem_solid_contact_add_side_opt
  public :: tfem_solid_contact_add_side_opt_r2111, tfem_solid_contact_add_side_opt_r1211
  public :: tfem_solid_contact_add_side_opt_r2211, tfem_solid_contact_add_side_opt_r1121
  public :: tfem_solid_contact_add_side_opt_r2121, tfem_solid_contact_add_side_opt_r1221
  public :: tfem_solid_contact_add_side_opt_r2221, tfem_solid_contact_add_side_opt_r1112
  public :: tfem_solid_contact_add_side_opt_r2112, tfem_solid_contact_add_side_opt_r1212
  public :: tfem_solid_contact_add_side_opt_r2212, tfem_solid_contact_add_side_opt_r1122
  public :: tfem_solid_contact_add_side_opt_r2122, tfem_solid_contact_add_side_opt_r1222
  public :: tfem_solid_contact_add_side_opt_r2222, tfem_solid_contact_add_pair_opt
  public :: tfem_solid_contact_sizes_opt, tfem_solid_contact_nodes_r2, tfem_solid_contact_nodes_i
  public :: tfem_solid_contact_nodes_i_r2, tfem_solid_contact_tetrahedra_r2
  public :: tfem_solid_contact_tetrahedra_i, tfem_solid_contact_tetrahedra_i_r2
  public :: tfem_solid_contact_pattern_r21, tfem_solid_contact_pattern_r12
  public :: tfem_solid_contact_pattern_r22, tfem_solid_contact_pattern_i
  public :: tfem_solid_contact_pattern_i_r21, tfem_solid_contact_pattern_i_r12
  public :: tfem_solid_contact_pattern_i_r22, tfem_solid_contact_element_equations_r2
  public :: tfem_solid_contact_element_equations_i, tfem_solid_contact_element_equations_i_r2
  public :: tfem_solid_contact_element_blocks_r2, tfem_solid_contact_element_blocks_i
  public :: tfem_solid_contact_element_blocks_i_r2, tfem_solid_contact_evaluate_opt
  public :: tfem_solid_contact_evaluate_opt_r211, tfem_solid_contact_evaluate_opt_r121
  public :: tfem_solid_contact_evaluate_opt_r221, tfem_solid_contact_evaluate_opt_r112
  public :: tfem_solid_contact_evaluate_opt_r212, tfem_solid_contact_evaluate_opt_r122
  public :: tfem_solid_contact_evaluate_opt_r222, tfem_solid_contact_evaluate_opt_i
  public :: tfem_solid_contact_evaluate_opt_i_r211, tfem_solid_contact_evaluate_opt_i_r121
  public :: tfem_solid_contact_evaluate_opt_i_r221, tfem_solid_contact_evaluate_opt_i_r112
  public :: tfem_solid_contact_evaluate_opt_i_r212, tfem_solid_contact_evaluate_opt_i_r122
  public :: tfem_solid_contact_evaluate_opt_i_r222, tfem_solid_contact_gather_r21
  public :: tfem_solid_contact_gather_r12, tfem_solid_contact_gather_r22
  public :: tfem_solid_contact_gather_i, tfem_solid_contact_gather_i_r21
  public :: tfem_solid_contact_gather_i_r12, tfem_solid_contact_gather_i_r22
  public :: tfem_solid_contact_scatter_add_r21, tfem_solid_contact_scatter_add_r12
  public :: tfem_solid_contact_scatter_add_r22, tfem_solid_contact_scatter_add_i
  public :: tfem_solid_contact_scatter_add_i_r21, tfem_solid_contact_scatter_add_i_r12
  public :: tfem_solid_contact_scatter_add_i_r22, tfem_solid_contact_update_opt
  public :: tfem_solid_contact_update_opt_r2, tfem_solid_contact_update_opt_i
  public :: tfem_solid_contact_update_opt_i_r2, tfem_solid_contact_get_active_r2
  public :: tfem_solid_contact_get_active_i, tfem_solid_contact_get_active_i_r2
  public :: tfem_solid_contact_set_active_r2, tfem_solid_contact_set_active_i
  public :: tfem_solid_contact_set_active_i_r2, tfem_solid_contact_gaps_r21
  public :: tfem_solid_contact_gaps_r12, tfem_solid_contact_gaps_r22, tfem_solid_contact_gaps_i
  public :: tfem_solid_contact_gaps_i_r21, tfem_solid_contact_gaps_i_r12
  public :: tfem_solid_contact_gaps_i_r22

  !> The kind of the lengths the generic interfaces accept besides integer(c_size_t): c_int (the
  !! default integer) where size_t is wider, else c_int64_t.
  integer, parameter :: tfem_length_kind = merge(c_int, c_int64_t, c_size_t /= c_int)

  ! The buffer passed for a given zero-length c_double array: never read or written.
  real(c_double), target, save :: tfem_empty_c_double(1)
  ! The buffer passed for a given zero-length c_int array: never read or written.
  integer(c_int), target, save :: tfem_empty_c_int(1)

  interface
    function tfem_get_sizes_by_address(model, n_nodes, n_triangles, n_contact_elements) &
        bind(C, name="tfem_get_sizes") result(status)
      import
      type(c_ptr), value :: model
      type(c_ptr), value :: n_nodes
      type(c_ptr), value :: n_triangles
      type(c_ptr), value :: n_contact_elements
      integer(c_int) :: status
    end function tfem_get_sizes_by_address

    function tfem_get_mesh_triangles_by_address(model, triangles, length, bodies, bodies_length) &
        bind(C, name="tfem_get_mesh_triangles") result(status)
      import
      type(c_ptr), value :: model
      integer(c_int), intent(inout) :: triangles(*)
      integer(c_size_t), value :: length
      type(c_ptr), value :: bodies
      integer(c_size_t), value :: bodies_length
      integer(c_int) :: status
    end function tfem_get_mesh_triangles_by_address

    function tfem_get_boundary_edges_by_address(model, edges, length, tags, tags_length) &
        bind(C, name="tfem_get_boundary_edges") result(status)
      import
      type(c_ptr), value :: model
      integer(c_int), intent(inout) :: edges(*)
      integer(c_size_t), value :: length
      type(c_ptr), value :: tags
      integer(c_size_t), value :: tags_length
      integer(c_int) :: status
    end function tfem_get_boundary_edges_by_address

    function tfem_add_contact_pair_by_address(model, tag_a, tag_b, pair) &
        bind(C, name="tfem_add_contact_pair") result(status)
      import
      type(c_ptr), value :: model
      integer(c_int), value :: tag_a
      integer(c_int), value :: tag_b
      type(c_ptr), value :: pair
      integer(c_int) :: status
    end function tfem_add_contact_pair_by_address

    function tfem_add_contact_pair_with_mesh_by_address(model, tag_a, tag_b, n_triangles, connectivity, &
        pair, flipped) &
        bind(C, name="tfem_add_contact_pair_with_mesh") result(status)
      import
      type(c_ptr), value :: model
      integer(c_int), value :: tag_a
      integer(c_int), value :: tag_b
      integer(c_int), value :: n_triangles
      integer(c_int), intent(in) :: connectivity(*)
      type(c_ptr), value :: pair
      type(c_ptr), value :: flipped
      integer(c_int) :: status
    end function tfem_add_contact_pair_with_mesh_by_address

    function tfem_add_contact_pairs_auto_by_address(model, n_tags, tags, tolerance, first, count) &
        bind(C, name="tfem_add_contact_pairs_auto") result(status)
      import
      type(c_ptr), value :: model
      integer(c_int), value :: n_tags
      type(c_ptr), value :: tags
      real(c_double), value :: tolerance
      type(c_ptr), value :: first
      type(c_ptr), value :: count
      integer(c_int) :: status
    end function tfem_add_contact_pairs_auto_by_address

    function tfem_get_contact_pair_bodies_by_address(model, pair, body_a, body_b) &
        bind(C, name="tfem_get_contact_pair_bodies") result(status)
      import
      type(c_ptr), value :: model
      integer(c_int), value :: pair
      type(c_ptr), value :: body_a
      type(c_ptr), value :: body_b
      integer(c_int) :: status
    end function tfem_get_contact_pair_bodies_by_address

    function tfem_solve_by_address(model, info) &
        bind(C, name="tfem_solve") result(status)
      import
      type(c_ptr), value :: model
      type(c_ptr), value :: info
      integer(c_int) :: status
    end function tfem_solve_by_address

    function tfem_solve_contact_by_address(model, options, report) &
        bind(C, name="tfem_solve_contact") result(status)
      import
      type(c_ptr), value :: model
      type(c_ptr), value :: options
      type(c_ptr), value :: report
      integer(c_int) :: status
    end function tfem_solve_contact_by_address

    function tfem_solve_adaptive_by_address(model, tolerance, goal, max_unknowns, max_cycles, contact, &
        report) &
        bind(C, name="tfem_solve_adaptive") result(status)
      import
      type(c_ptr), value :: model
      real(c_double), value :: tolerance
      integer(c_int), value :: goal
      integer(c_int64_t), value :: max_unknowns
      integer(c_int), value :: max_cycles
      type(c_ptr), value :: contact
      type(c_ptr), value :: report
      integer(c_int) :: status
    end function tfem_solve_adaptive_by_address

    function tfem_get_adapt_cycles_by_address(model, unknowns, estimates, seconds, length) &
        bind(C, name="tfem_get_adapt_cycles") result(status)
      import
      type(c_ptr), value :: model
      type(c_ptr), value :: unknowns
      type(c_ptr), value :: estimates
      type(c_ptr), value :: seconds
      integer(c_size_t), value :: length
      integer(c_int) :: status
    end function tfem_get_adapt_cycles_by_address

    function tfem_get_contact_slave_nodes_by_address(model, node, tributary, gap, pressure, length) &
        bind(C, name="tfem_get_contact_slave_nodes") result(status)
      import
      type(c_ptr), value :: model
      type(c_ptr), value :: node
      type(c_ptr), value :: tributary
      type(c_ptr), value :: gap
      type(c_ptr), value :: pressure
      integer(c_size_t), value :: length
      integer(c_int) :: status
    end function tfem_get_contact_slave_nodes_by_address

    function tfem_step_by_address(model, load_factor, options, report) &
        bind(C, name="tfem_step") result(status)
      import
      type(c_ptr), value :: model
      real(c_double), value :: load_factor
      type(c_ptr), value :: options
      type(c_ptr), value :: report
      integer(c_int) :: status
    end function tfem_step_by_address

    function tfem_get_system_matrix_size_by_address(model, n, nnz) &
        bind(C, name="tfem_get_system_matrix_size") result(status)
      import
      type(c_ptr), value :: model
      type(c_ptr), value :: n
      type(c_ptr), value :: nnz
      integer(c_int) :: status
    end function tfem_get_system_matrix_size_by_address

    function tfem_contact_add_side_by_address(context, tag, body, young, poisson, plane_mode, n_nodes, &
        nodes, xy, equations, n_edges, edges, side) &
        bind(C, name="tfem_contact_add_side") result(status)
      import
      type(c_ptr), value :: context
      integer(c_int), value :: tag
      integer(c_int), value :: body
      real(c_double), value :: young
      real(c_double), value :: poisson
      integer(c_int), value :: plane_mode
      integer(c_int), value :: n_nodes
      integer(c_int), intent(in) :: nodes(*)
      real(c_double), intent(in) :: xy(*)
      integer(c_int64_t), intent(in) :: equations(*)
      integer(c_int), value :: n_edges
      integer(c_int), intent(in) :: edges(*)
      type(c_ptr), value :: side
      integer(c_int) :: status
    end function tfem_contact_add_side_by_address

    function tfem_contact_add_pair_by_address(context, side_a, side_b, pair) &
        bind(C, name="tfem_contact_add_pair") result(status)
      import
      type(c_ptr), value :: context
      integer(c_int), value :: side_a
      integer(c_int), value :: side_b
      type(c_ptr), value :: pair
      integer(c_int) :: status
    end function tfem_contact_add_pair_by_address

    function tfem_contact_add_pair_with_mesh_by_address(context, side_a, side_b, n_triangles, &
        connectivity, pair) &
        bind(C, name="tfem_contact_add_pair_with_mesh") result(status)
      import
      type(c_ptr), value :: context
      integer(c_int), value :: side_a
      integer(c_int), value :: side_b
      integer(c_int), value :: n_triangles
      integer(c_int), intent(in) :: connectivity(*)
      type(c_ptr), value :: pair
      integer(c_int) :: status
    end function tfem_contact_add_pair_with_mesh_by_address

    function tfem_contact_sizes_by_address(context, n_nodes, n_elements, n_entries) &
        bind(C, name="tfem_contact_sizes") result(status)
      import
      type(c_ptr), value :: context
      type(c_ptr), value :: n_nodes
      type(c_ptr), value :: n_elements
      type(c_ptr), value :: n_entries
      integer(c_int) :: status
    end function tfem_contact_sizes_by_address

    function tfem_contact_evaluate_by_address(context, u, u_length, values, values_length, residual, &
        residual_length) &
        bind(C, name="tfem_contact_evaluate") result(status)
      import
      type(c_ptr), value :: context
      real(c_double), intent(in) :: u(*)
      integer(c_size_t), value :: u_length
      type(c_ptr), value :: values
      integer(c_size_t), value :: values_length
      type(c_ptr), value :: residual
      integer(c_size_t), value :: residual_length
      integer(c_int) :: status
    end function tfem_contact_evaluate_by_address

    function tfem_contact_update_by_address(context, u, u_length, changed) &
        bind(C, name="tfem_contact_update") result(status)
      import
      type(c_ptr), value :: context
      real(c_double), intent(in) :: u(*)
      integer(c_size_t), value :: u_length
      type(c_ptr), value :: changed
      integer(c_int) :: status
    end function tfem_contact_update_by_address

    function tfem_solid_get_sizes_by_address(model, n_nodes, n_tetrahedra, n_contact_tetrahedra) &
        bind(C, name="tfem_solid_get_sizes") result(status)
      import
      type(c_ptr), value :: model
      type(c_ptr), value :: n_nodes
      type(c_ptr), value :: n_tetrahedra
      type(c_ptr), value :: n_contact_tetrahedra
      integer(c_int) :: status
    end function tfem_solid_get_sizes_by_address

    function tfem_solid_get_mesh_tetrahedra_by_address(model, tetrahedra, length, bodies, bodies_length) &
        bind(C, name="tfem_solid_get_mesh_tetrahedra") result(status)
      import
      type(c_ptr), value :: model
      integer(c_int), intent(inout) :: tetrahedra(*)
      integer(c_size_t), value :: length
      type(c_ptr), value :: bodies
      integer(c_size_t), value :: bodies_length
      integer(c_int) :: status
    end function tfem_solid_get_mesh_tetrahedra_by_address

    function tfem_solid_get_boundary_faces_by_address(model, faces, length, tags, tags_length) &
        bind(C, name="tfem_solid_get_boundary_faces") result(status)
      import
      type(c_ptr), value :: model
      integer(c_int), intent(inout) :: faces(*)
      integer(c_size_t), value :: length
      type(c_ptr), value :: tags
      integer(c_size_t), value :: tags_length
      integer(c_int) :: status
    end function tfem_solid_get_boundary_faces_by_address

    function tfem_solid_add_contact_pair_by_address(model, tag_a, tag_b, pair) &
        bind(C, name="tfem_solid_add_contact_pair") result(status)
      import
      type(c_ptr), value :: model
      integer(c_int), value :: tag_a
      integer(c_int), value :: tag_b
      type(c_ptr), value :: pair
      integer(c_int) :: status
    end function tfem_solid_add_contact_pair_by_address

    function tfem_solid_solve_by_address(model, info) &
        bind(C, name="tfem_solid_solve") result(status)
      import
      type(c_ptr), value :: model
      type(c_ptr), value :: info
      integer(c_int) :: status
    end function tfem_solid_solve_by_address

    function tfem_solid_solve_contact_by_address(model, options, info) &
        bind(C, name="tfem_solid_solve_contact") result(status)
      import
      type(c_ptr), value :: model
      type(c_ptr), value :: options
      type(c_ptr), value :: info
      integer(c_int) :: status
    end function tfem_solid_solve_contact_by_address

    function tfem_solid_step_by_address(model, load_factor, options, info) &
        bind(C, name="tfem_solid_step") result(status)
      import
      type(c_ptr), value :: model
      real(c_double), value :: load_factor
      type(c_ptr), value :: options
      type(c_ptr), value :: info
      integer(c_int) :: status
    end function tfem_solid_step_by_address

    function tfem_solid_contact_create_by_address(index_base, options) &
        bind(C, name="tfem_solid_contact_create") result(res)
      import
      integer(c_int), value :: index_base
      type(c_ptr), value :: options
      type(c_ptr) :: res
    end function tfem_solid_contact_create_by_address

    function tfem_solid_contact_add_side_by_address(context, tag, body, young, n_nodes, nodes, xyz, &
        equations, n_triangles, triangles, side) &
        bind(C, name="tfem_solid_contact_add_side") result(status)
      import
      type(c_ptr), value :: context
      integer(c_int), value :: tag
      integer(c_int), value :: body
      real(c_double), value :: young
      integer(c_int), value :: n_nodes
      integer(c_int), intent(in) :: nodes(*)
      real(c_double), intent(in) :: xyz(*)
      integer(c_int64_t), intent(in) :: equations(*)
      integer(c_int), value :: n_triangles
      integer(c_int), intent(in) :: triangles(*)
      type(c_ptr), value :: side
      integer(c_int) :: status
    end function tfem_solid_contact_add_side_by_address

    function tfem_solid_contact_add_pair_by_address(context, side_a, side_b, pair) &
        bind(C, name="tfem_solid_contact_add_pair") result(status)
      import
      type(c_ptr), value :: context
      integer(c_int), value :: side_a
      integer(c_int), value :: side_b
      type(c_ptr), value :: pair
      integer(c_int) :: status
    end function tfem_solid_contact_add_pair_by_address

    function tfem_solid_contact_sizes_by_address(context, n_nodes, n_tetrahedra, n_entries) &
        bind(C, name="tfem_solid_contact_sizes") result(status)
      import
      type(c_ptr), value :: context
      type(c_ptr), value :: n_nodes
      type(c_ptr), value :: n_tetrahedra
      type(c_ptr), value :: n_entries
      integer(c_int) :: status
    end function tfem_solid_contact_sizes_by_address

    function tfem_solid_contact_evaluate_by_address(context, u, u_length, values, values_length, residual, &
        residual_length) &
        bind(C, name="tfem_solid_contact_evaluate") result(status)
      import
      type(c_ptr), value :: context
      real(c_double), intent(in) :: u(*)
      integer(c_size_t), value :: u_length
      type(c_ptr), value :: values
      integer(c_size_t), value :: values_length
      type(c_ptr), value :: residual
      integer(c_size_t), value :: residual_length
      integer(c_int) :: status
    end function tfem_solid_contact_evaluate_by_address

    function tfem_solid_contact_update_by_address(context, u, u_length, changed, switched_on, &
        switched_off) &
        bind(C, name="tfem_solid_contact_update") result(status)
      import
      type(c_ptr), value :: context
      real(c_double), intent(in) :: u(*)
      integer(c_size_t), value :: u_length
      type(c_ptr), value :: changed
      type(c_ptr), value :: switched_on
      type(c_ptr), value :: switched_off
      integer(c_int) :: status
    end function tfem_solid_contact_update_by_address
  end interface

contains

  !> A length of kind tfem_length_kind as integer(c_size_t). A negative length becomes 0, so
  !! that the library reports TFEM_STATUS_BUFFER_TOO_SMALL instead of reading a huge size_t.
  elemental function tfem_to_size_t(n) result(s)
    integer(tfem_length_kind), intent(in) :: n
    integer(c_size_t) :: s
    if (n <= 0) then
      s = 0
    else if (n >= huge(s)) then
      s = huge(s)
    else
      s = int(n, c_size_t)
    end if
  end function tfem_to_size_t

  !> The address to pass for the nullable c_double array x: NULL when absent, that of
  !! tfem_empty_c_double when its buffer is empty (c_loc needs a nonzero size).
  function tfem_address_c_double(x, nonempty) result(address)
    real(c_double), intent(in), optional, target :: x(*)
    logical, intent(in) :: nonempty
    type(c_ptr) :: address
    address = c_null_ptr
    if (.not. present(x)) return
    address = c_loc(tfem_empty_c_double)
    if (nonempty) address = c_loc(x)
  end function tfem_address_c_double

  !> The address to pass for the nullable c_int array x: NULL when absent, that of
  !! tfem_empty_c_int when its buffer is empty (c_loc needs a nonzero size).
  function tfem_address_c_int(x, nonempty) result(address)
    integer(c_int), intent(in), optional, target :: x(*)
    logical, intent(in) :: nonempty
    type(c_ptr) :: address
    address = c_null_ptr
    if (.not. present(x)) return
    address = c_loc(tfem_empty_c_int)
    if (nonempty) address = c_loc(x)
  end function tfem_address_c_int

  function tfem_last_error_i(model, buffer, length) result(status)
    type(c_ptr), value :: model
    character(kind=c_char), intent(inout) :: buffer(*)
    integer(tfem_length_kind), intent(in) :: length
    integer(c_int) :: status
    status = tfem_last_error(model, buffer, tfem_to_size_t(length))
  end function tfem_last_error_i

  function tfem_last_error_str(model, buffer, length) result(status)
    type(c_ptr), value :: model
    character(kind=c_char, len=*), intent(inout) :: buffer
    integer(c_size_t), intent(in) :: length
    integer(c_int) :: status
    status = tfem_last_error(model, buffer, length)
  end function tfem_last_error_str

  function tfem_last_error_str_i(model, buffer, length) result(status)
    type(c_ptr), value :: model
    character(kind=c_char, len=*), intent(inout) :: buffer
    integer(tfem_length_kind), intent(in) :: length
    integer(c_int) :: status
    status = tfem_last_error(model, buffer, tfem_to_size_t(length))
  end function tfem_last_error_str_i

  function tfem_last_error_no_model(buffer, length) result(status)
    character(kind=c_char), intent(inout) :: buffer(*)
    integer(c_size_t), intent(in) :: length
    integer(c_int) :: status
    status = tfem_last_error(c_null_ptr, buffer, length)
  end function tfem_last_error_no_model

  function tfem_last_error_no_model_i(buffer, length) result(status)
    character(kind=c_char), intent(inout) :: buffer(*)
    integer(tfem_length_kind), intent(in) :: length
    integer(c_int) :: status
    status = tfem_last_error(c_null_ptr, buffer, tfem_to_size_t(length))
  end function tfem_last_error_no_model_i

  function tfem_last_error_no_model_str(buffer, length) result(status)
    character(kind=c_char, len=*), intent(inout) :: buffer
    integer(c_size_t), intent(in) :: length
    integer(c_int) :: status
    status = tfem_last_error(c_null_ptr, buffer, length)
  end function tfem_last_error_no_model_str

  function tfem_last_error_no_model_str_i(buffer, length) result(status)
    character(kind=c_char, len=*), intent(inout) :: buffer
    integer(tfem_length_kind), intent(in) :: length
    integer(c_int) :: status
    status = tfem_last_error(c_null_ptr, buffer, tfem_to_size_t(length))
  end function tfem_last_error_no_model_str_i

  function tfem_last_error_length_no_model() result(res)
    integer(c_size_t) :: res
    res = tfem_last_error_length(c_null_ptr)
  end function tfem_last_error_length_no_model

  function tfem_get_warning_i(model, index, buffer, length) result(status)
    type(c_ptr), value :: model
    integer(c_int), value :: index
    character(kind=c_char), intent(inout) :: buffer(*)
    integer(tfem_length_kind), intent(in) :: length
    integer(c_int) :: status
    status = tfem_get_warning(model, index, buffer, tfem_to_size_t(length))
  end function tfem_get_warning_i

  function tfem_get_warning_str(model, index, buffer, length) result(status)
    type(c_ptr), value :: model
    integer(c_int), value :: index
    character(kind=c_char, len=*), intent(inout) :: buffer
    integer(c_size_t), intent(in) :: length
    integer(c_int) :: status
    status = tfem_get_warning(model, index, buffer, length)
  end function tfem_get_warning_str

  function tfem_get_warning_str_i(model, index, buffer, length) result(status)
    type(c_ptr), value :: model
    integer(c_int), value :: index
    character(kind=c_char, len=*), intent(inout) :: buffer
    integer(tfem_length_kind), intent(in) :: length
    integer(c_int) :: status
    status = tfem_get_warning(model, index, buffer, tfem_to_size_t(length))
  end function tfem_get_warning_str_i

  function tfem_get_sizes_opt(model, n_nodes, n_triangles, n_contact_elements) result(status)
    type(c_ptr), value :: model
    integer(c_int), intent(inout), optional, target :: n_nodes
    integer(c_int), intent(inout), optional, target :: n_triangles
    integer(c_int), intent(inout), optional, target :: n_contact_elements
    integer(c_int) :: status
    type(c_ptr) :: n_nodes_address
    type(c_ptr) :: n_triangles_address
    type(c_ptr) :: n_contact_elements_address
    n_nodes_address = c_null_ptr
    if (present(n_nodes)) n_nodes_address = c_loc(n_nodes)
    n_triangles_address = c_null_ptr
    if (present(n_triangles)) n_triangles_address = c_loc(n_triangles)
    n_contact_elements_address = c_null_ptr
    if (present(n_contact_elements)) n_contact_elements_address = c_loc(n_contact_elements)
    status = tfem_get_sizes_by_address(model, n_nodes_address, n_triangles_address, &
        n_contact_elements_address)
  end function tfem_get_sizes_opt

  function tfem_get_mesh_nodes_r2(model, xy, length) result(status)
    type(c_ptr), value :: model
    real(c_double), intent(inout) :: xy(1, *)
    integer(c_size_t), intent(in) :: length
    integer(c_int) :: status
    status = tfem_get_mesh_nodes(model, xy, length)
  end function tfem_get_mesh_nodes_r2

  function tfem_get_mesh_nodes_i(model, xy, length) result(status)
    type(c_ptr), value :: model
    real(c_double), intent(inout) :: xy(*)
    integer(tfem_length_kind), intent(in) :: length
    integer(c_int) :: status
    status = tfem_get_mesh_nodes(model, xy, tfem_to_size_t(length))
  end function tfem_get_mesh_nodes_i

  function tfem_get_mesh_nodes_i_r2(model, xy, length) result(status)
    type(c_ptr), value :: model
    real(c_double), intent(inout) :: xy(1, *)
    integer(tfem_length_kind), intent(in) :: length
    integer(c_int) :: status
    status = tfem_get_mesh_nodes(model, xy, tfem_to_size_t(length))
  end function tfem_get_mesh_nodes_i_r2

  function tfem_get_mesh_triangles_opt(model, triangles, length, bodies, bodies_length) result(status)
    type(c_ptr), value :: model
    integer(c_int), intent(inout) :: triangles(*)
    integer(c_size_t), intent(in) :: length
    integer(c_int), intent(inout), optional, target :: bodies(*)
    integer(c_size_t), intent(in) :: bodies_length
    integer(c_int) :: status
    type(c_ptr) :: bodies_address
    bodies_address = tfem_address_c_int(bodies, bodies_length /= 0)
    status = tfem_get_mesh_triangles_by_address(model, triangles, length, bodies_address, &
        bodies_length)
  end function tfem_get_mesh_triangles_opt

  function tfem_get_mesh_triangles_opt_r21(model, triangles, length, bodies, &
        bodies_length) result(status)
    type(c_ptr), value :: model
    integer(c_int), intent(inout) :: triangles(1, *)
    integer(c_size_t), intent(in) :: length
    integer(c_int), intent(inout), optional, target :: bodies(*)
    integer(c_size_t), intent(in) :: bodies_length
    integer(c_int) :: status
    type(c_ptr) :: bodies_address
    bodies_address = tfem_address_c_int(bodies, bodies_length /= 0)
    status = tfem_get_mesh_triangles_by_address(model, triangles, length, bodies_address, &
        bodies_length)
  end function tfem_get_mesh_triangles_opt_r21

  function tfem_get_mesh_triangles_opt_r12(model, triangles, length, bodies, &
        bodies_length) result(status)
    type(c_ptr), value :: model
    integer(c_int), intent(inout) :: triangles(*)
    integer(c_size_t), intent(in) :: length
    integer(c_int), intent(inout), target :: bodies(1, *)
    integer(c_size_t), intent(in) :: bodies_length
    integer(c_int) :: status
    type(c_ptr) :: bodies_address
    bodies_address = tfem_address_c_int(bodies, bodies_length /= 0)
    status = tfem_get_mesh_triangles_by_address(model, triangles, length, bodies_address, &
        bodies_length)
  end function tfem_get_mesh_triangles_opt_r12

  function tfem_get_mesh_triangles_opt_r22(model, triangles, length, bodies, &
        bodies_length) result(status)
    type(c_ptr), value :: model
    integer(c_int), intent(inout) :: triangles(1, *)
    integer(c_size_t), intent(in) :: length
    integer(c_int), intent(inout), target :: bodies(1, *)
    integer(c_size_t), intent(in) :: bodies_length
    integer(c_int) :: status
    type(c_ptr) :: bodies_address
    bodies_address = tfem_address_c_int(bodies, bodies_length /= 0)
    status = tfem_get_mesh_triangles_by_address(model, triangles, length, bodies_address, &
        bodies_length)
  end function tfem_get_mesh_triangles_opt_r22

  function tfem_get_mesh_triangles_opt_i(model, triangles, length, bodies, &
        bodies_length) result(status)
    type(c_ptr), value :: model
    integer(c_int), intent(inout) :: triangles(*)
    integer(tfem_length_kind), intent(in) :: length
    integer(c_int), intent(inout), optional, target :: bodies(*)
    integer(tfem_length_kind), intent(in) :: bodies_length
    integer(c_int) :: status
    type(c_ptr) :: bodies_address
    bodies_address = tfem_address_c_int(bodies, bodies_length > 0)
    status = tfem_get_mesh_triangles_by_address(model, triangles, tfem_to_size_t(length), &
        bodies_address, tfem_to_size_t(bodies_length))
  end function tfem_get_mesh_triangles_opt_i

  function tfem_get_mesh_triangles_opt_i_r21(model, triangles, length, bodies, &
        bodies_length) result(status)
    type(c_ptr), value :: model
    integer(c_int), intent(inout) :: triangles(1, *)
    integer(tfem_length_kind), intent(in) :: length
    integer(c_int), intent(inout), optional, target :: bodies(*)
    integer(tfem_length_kind), intent(in) :: bodies_length
    integer(c_int) :: status
    type(c_ptr) :: bodies_address
    bodies_address = tfem_address_c_int(bodies, bodies_length > 0)
    status = tfem_get_mesh_triangles_by_address(model, triangles, tfem_to_size_t(length), &
        bodies_address, tfem_to_size_t(bodies_length))
  end function tfem_get_mesh_triangles_opt_i_r21

  function tfem_get_mesh_triangles_opt_i_r12(model, triangles, length, bodies, &
        bodies_length) result(status)
    type(c_ptr), value :: model
    integer(c_int), intent(inout) :: triangles(*)
    integer(tfem_length_kind), intent(in) :: length
    integer(c_int), intent(inout), target :: bodies(1, *)
    integer(tfem_length_kind), intent(in) :: bodies_length
    integer(c_int) :: status
    type(c_ptr) :: bodies_address
    bodies_address = tfem_address_c_int(bodies, bodies_length > 0)
    status = tfem_get_mesh_triangles_by_address(model, triangles, tfem_to_size_t(length), &
        bodies_address, tfem_to_size_t(bodies_length))
  end function tfem_get_mesh_triangles_opt_i_r12

  function tfem_get_mesh_triangles_opt_i_r22(model, triangles, length, bodies, &
        bodies_length) result(status)
    type(c_ptr), value :: model
    integer(c_int), intent(inout) :: triangles(1, *)
    integer(tfem_length_kind), intent(in) :: length
    integer(c_int), intent(inout), target :: bodies(1, *)
    integer(tfem_length_kind), intent(in) :: bodies_length
    integer(c_int) :: status
    type(c_ptr) :: bodies_address
    bodies_address = tfem_address_c_int(bodies, bodies_length > 0)
    status = tfem_get_mesh_triangles_by_address(model, triangles, tfem_to_size_t(length), &
        bodies_address, tfem_to_size_t(bodies_length))
  end function tfem_get_mesh_triangles_opt_i_r22

  function tfem_get_boundary_edges_opt(model, edges, length, tags, tags_length) result(status)
    type(c_ptr), value :: model
    integer(c_int), intent(inout) :: edges(*)
    integer(c_size_t), intent(in) :: length
    integer(c_int), intent(inout), optional, target :: tags(*)
    integer(c_size_t), intent(in) :: tags_length
    integer(c_int) :: status
    type(c_ptr) :: tags_address
    tags_address = tfem_address_c_int(tags, tags_length /= 0)
    status = tfem_get_boundary_edges_by_address(model, edges, length, tags_address, tags_length)
  end function tfem_get_boundary_edges_opt

  function tfem_get_boundary_edges_opt_r21(model, edges, length, tags, tags_length) result(status)
    type(c_ptr), value :: model
    integer(c_int), intent(inout) :: edges(1, *)
    integer(c_size_t), intent(in) :: length
    integer(c_int), intent(inout), optional, target :: tags(*)
    integer(c_size_t), intent(in) :: tags_length
    integer(c_int) :: status
    type(c_ptr) :: tags_address
    tags_address = tfem_address_c_int(tags, tags_length /= 0)
    status = tfem_get_boundary_edges_by_address(model, edges, length, tags_address, tags_length)
  end function tfem_get_boundary_edges_opt_r21

  function tfem_get_boundary_edges_opt_r12(model, edges, length, tags, tags_length) result(status)
    type(c_ptr), value :: model
    integer(c_int), intent(inout) :: edges(*)
    integer(c_size_t), intent(in) :: length
    integer(c_int), intent(inout), target :: tags(1, *)
    integer(c_size_t), intent(in) :: tags_length
    integer(c_int) :: status
    type(c_ptr) :: tags_address
    tags_address = tfem_address_c_int(tags, tags_length /= 0)
    status = tfem_get_boundary_edges_by_address(model, edges, length, tags_address, tags_length)
  end function tfem_get_boundary_edges_opt_r12

  function tfem_get_boundary_edges_opt_r22(model, edges, length, tags, tags_length) result(status)
    type(c_ptr), value :: model
    integer(c_int), intent(inout) :: edges(1, *)
    integer(c_size_t), intent(in) :: length
    integer(c_int), intent(inout), target :: tags(1, *)
    integer(c_size_t), intent(in) :: tags_length
    integer(c_int) :: status
    type(c_ptr) :: tags_address
    tags_address = tfem_address_c_int(tags, tags_length /= 0)
    status = tfem_get_boundary_edges_by_address(model, edges, length, tags_address, tags_length)
  end function tfem_get_boundary_edges_opt_r22

  function tfem_get_boundary_edges_opt_i(model, edges, length, tags, tags_length) result(status)
    type(c_ptr), value :: model
    integer(c_int), intent(inout) :: edges(*)
    integer(tfem_length_kind), intent(in) :: length
    integer(c_int), intent(inout), optional, target :: tags(*)
    integer(tfem_length_kind), intent(in) :: tags_length
    integer(c_int) :: status
    type(c_ptr) :: tags_address
    tags_address = tfem_address_c_int(tags, tags_length > 0)
    status = tfem_get_boundary_edges_by_address(model, edges, tfem_to_size_t(length), tags_address, &
        tfem_to_size_t(tags_length))
  end function tfem_get_boundary_edges_opt_i

  function tfem_get_boundary_edges_opt_i_r21(model, edges, length, tags, tags_length) result(status)
    type(c_ptr), value :: model
    integer(c_int), intent(inout) :: edges(1, *)
    integer(tfem_length_kind), intent(in) :: length
    integer(c_int), intent(inout), optional, target :: tags(*)
    integer(tfem_length_kind), intent(in) :: tags_length
    integer(c_int) :: status
    type(c_ptr) :: tags_address
    tags_address = tfem_address_c_int(tags, tags_length > 0)
    status = tfem_get_boundary_edges_by_address(model, edges, tfem_to_size_t(length), tags_address, &
        tfem_to_size_t(tags_length))
  end function tfem_get_boundary_edges_opt_i_r21

  function tfem_get_boundary_edges_opt_i_r12(model, edges, length, tags, tags_length) result(status)
    type(c_ptr), value :: model
    integer(c_int), intent(inout) :: edges(*)
    integer(tfem_length_kind), intent(in) :: length
    integer(c_int), intent(inout), target :: tags(1, *)
    integer(tfem_length_kind), intent(in) :: tags_length
    integer(c_int) :: status
    type(c_ptr) :: tags_address
    tags_address = tfem_address_c_int(tags, tags_length > 0)
    status = tfem_get_boundary_edges_by_address(model, edges, tfem_to_size_t(length), tags_address, &
        tfem_to_size_t(tags_length))
  end function tfem_get_boundary_edges_opt_i_r12

  function tfem_get_boundary_edges_opt_i_r22(model, edges, length, tags, tags_length) result(status)
    type(c_ptr), value :: model
    integer(c_int), intent(inout) :: edges(1, *)
    integer(tfem_length_kind), intent(in) :: length
    integer(c_int), intent(inout), target :: tags(1, *)
    integer(tfem_length_kind), intent(in) :: tags_length
    integer(c_int) :: status
    type(c_ptr) :: tags_address
    tags_address = tfem_address_c_int(tags, tags_length > 0)
    status = tfem_get_boundary_edges_by_address(model, edges, tfem_to_size_t(length), tags_address, &
        tfem_to_size_t(tags_length))
  end function tfem_get_boundary_edges_opt_i_r22

  function tfem_add_contact_pair_opt(model, tag_a, tag_b, pair) result(status)
    type(c_ptr), value :: model
    integer(c_int), value :: tag_a
    integer(c_int), value :: tag_b
    integer(c_int), intent(inout), optional, target :: pair
    integer(c_int) :: status
    type(c_ptr) :: pair_address
    pair_address = c_null_ptr
    if (present(pair)) pair_address = c_loc(pair)
    status = tfem_add_contact_pair_by_address(model, tag_a, tag_b, pair_address)
  end function tfem_add_contact_pair_opt

  function tfem_add_contact_pair_with_mesh_opt(model, tag_a, tag_b, n_triangles, &
        connectivity, pair, flipped) result(status)
    type(c_ptr), value :: model
    integer(c_int), value :: tag_a
    integer(c_int), value :: tag_b
    integer(c_int), value :: n_triangles
    integer(c_int), intent(in) :: connectivity(*)
    integer(c_int), intent(inout), optional, target :: pair
    integer(c_int), intent(inout), optional, target :: flipped
    integer(c_int) :: status
    type(c_ptr) :: pair_address
    type(c_ptr) :: flipped_address
    pair_address = c_null_ptr
    if (present(pair)) pair_address = c_loc(pair)
    flipped_address = c_null_ptr
    if (present(flipped)) flipped_address = c_loc(flipped)
    status = tfem_add_contact_pair_with_mesh_by_address(model, tag_a, tag_b, n_triangles, &
        connectivity, pair_address, flipped_address)
  end function tfem_add_contact_pair_with_mesh_opt

  function tfem_add_contact_pair_with_mesh_opt_r2(model, tag_a, tag_b, n_triangles, &
        connectivity, pair, flipped) result(status)
    type(c_ptr), value :: model
    integer(c_int), value :: tag_a
    integer(c_int), value :: tag_b
    integer(c_int), value :: n_triangles
    integer(c_int), intent(in) :: connectivity(1, *)
    integer(c_int), intent(inout), optional, target :: pair
    integer(c_int), intent(inout), optional, target :: flipped
    integer(c_int) :: status
    type(c_ptr) :: pair_address
    type(c_ptr) :: flipped_address
    pair_address = c_null_ptr
    if (present(pair)) pair_address = c_loc(pair)
    flipped_address = c_null_ptr
    if (present(flipped)) flipped_address = c_loc(flipped)
    status = tfem_add_contact_pair_with_mesh_by_address(model, tag_a, tag_b, n_triangles, &
        connectivity, pair_address, flipped_address)
  end function tfem_add_contact_pair_with_mesh_opt_r2

  function tfem_add_contact_pairs_auto_opt(model, n_tags, tags, tolerance, first, &
        count) result(status)
    type(c_ptr), value :: model
    integer(c_int), value :: n_tags
    integer(c_int), intent(in), optional, target :: tags(*)
    real(c_double), value :: tolerance
    integer(c_int), intent(inout), optional, target :: first
    integer(c_int), intent(inout), optional, target :: count
    integer(c_int) :: status
    type(c_ptr) :: tags_address
    type(c_ptr) :: first_address
    type(c_ptr) :: count_address
    tags_address = tfem_address_c_int(tags, n_tags > 0)
    first_address = c_null_ptr
    if (present(first)) first_address = c_loc(first)
    count_address = c_null_ptr
    if (present(count)) count_address = c_loc(count)
    status = tfem_add_contact_pairs_auto_by_address(model, n_tags, tags_address, tolerance, &
        first_address, count_address)
  end function tfem_add_contact_pairs_auto_opt

  function tfem_add_contact_pairs_auto_opt_r2(model, n_tags, tags, tolerance, first, &
        count) result(status)
    type(c_ptr), value :: model
    integer(c_int), value :: n_tags
    integer(c_int), intent(in), target :: tags(1, *)
    real(c_double), value :: tolerance
    integer(c_int), intent(inout), optional, target :: first
    integer(c_int), intent(inout), optional, target :: count
    integer(c_int) :: status
    type(c_ptr) :: tags_address
    type(c_ptr) :: first_address
    type(c_ptr) :: count_address
    tags_address = tfem_address_c_int(tags, n_tags > 0)
    first_address = c_null_ptr
    if (present(first)) first_address = c_loc(first)
    count_address = c_null_ptr
    if (present(count)) count_address = c_loc(count)
    status = tfem_add_contact_pairs_auto_by_address(model, n_tags, tags_address, tolerance, &
        first_address, count_address)
  end function tfem_add_contact_pairs_auto_opt_r2

  function tfem_get_contact_mesh_r2(model, out, length) result(status)
    type(c_ptr), value :: model
    integer(c_int), intent(inout) :: out(1, *)
    integer(c_size_t), intent(in) :: length
    integer(c_int) :: status
    status = tfem_get_contact_mesh(model, out, length)
  end function tfem_get_contact_mesh_r2

  function tfem_get_contact_mesh_i(model, out, length) result(status)
    type(c_ptr), value :: model
    integer(c_int), intent(inout) :: out(*)
    integer(tfem_length_kind), intent(in) :: length
    integer(c_int) :: status
    status = tfem_get_contact_mesh(model, out, tfem_to_size_t(length))
  end function tfem_get_contact_mesh_i

  function tfem_get_contact_mesh_i_r2(model, out, length) result(status)
    type(c_ptr), value :: model
    integer(c_int), intent(inout) :: out(1, *)
    integer(tfem_length_kind), intent(in) :: length
    integer(c_int) :: status
    status = tfem_get_contact_mesh(model, out, tfem_to_size_t(length))
  end function tfem_get_contact_mesh_i_r2

  function tfem_get_contact_element_pairs_r2(model, out, length) result(status)
    type(c_ptr), value :: model
    integer(c_int), intent(inout) :: out(1, *)
    integer(c_size_t), intent(in) :: length
    integer(c_int) :: status
    status = tfem_get_contact_element_pairs(model, out, length)
  end function tfem_get_contact_element_pairs_r2

  function tfem_get_contact_element_pairs_i(model, out, length) result(status)
    type(c_ptr), value :: model
    integer(c_int), intent(inout) :: out(*)
    integer(tfem_length_kind), intent(in) :: length
    integer(c_int) :: status
    status = tfem_get_contact_element_pairs(model, out, tfem_to_size_t(length))
  end function tfem_get_contact_element_pairs_i

  function tfem_get_contact_element_pairs_i_r2(model, out, length) result(status)
    type(c_ptr), value :: model
    integer(c_int), intent(inout) :: out(1, *)
    integer(tfem_length_kind), intent(in) :: length
    integer(c_int) :: status
    status = tfem_get_contact_element_pairs(model, out, tfem_to_size_t(length))
  end function tfem_get_contact_element_pairs_i_r2

  function tfem_get_contact_element_apexes_r2(model, out, length) result(status)
    type(c_ptr), value :: model
    integer(c_int), intent(inout) :: out(1, *)
    integer(c_size_t), intent(in) :: length
    integer(c_int) :: status
    status = tfem_get_contact_element_apexes(model, out, length)
  end function tfem_get_contact_element_apexes_r2

  function tfem_get_contact_element_apexes_i(model, out, length) result(status)
    type(c_ptr), value :: model
    integer(c_int), intent(inout) :: out(*)
    integer(tfem_length_kind), intent(in) :: length
    integer(c_int) :: status
    status = tfem_get_contact_element_apexes(model, out, tfem_to_size_t(length))
  end function tfem_get_contact_element_apexes_i

  function tfem_get_contact_element_apexes_i_r2(model, out, length) result(status)
    type(c_ptr), value :: model
    integer(c_int), intent(inout) :: out(1, *)
    integer(tfem_length_kind), intent(in) :: length
    integer(c_int) :: status
    status = tfem_get_contact_element_apexes(model, out, tfem_to_size_t(length))
  end function tfem_get_contact_element_apexes_i_r2

  function tfem_get_contact_pair_bodies_opt(model, pair, body_a, body_b) result(status)
    type(c_ptr), value :: model
    integer(c_int), value :: pair
    integer(c_int), intent(inout), optional, target :: body_a
    integer(c_int), intent(inout), optional, target :: body_b
    integer(c_int) :: status
    type(c_ptr) :: body_a_address
    type(c_ptr) :: body_b_address
    body_a_address = c_null_ptr
    if (present(body_a)) body_a_address = c_loc(body_a)
    body_b_address = c_null_ptr
    if (present(body_b)) body_b_address = c_loc(body_b)
    status = tfem_get_contact_pair_bodies_by_address(model, pair, body_a_address, body_b_address)
  end function tfem_get_contact_pair_bodies_opt

  function tfem_solve_opt(model, info) result(status)
    type(c_ptr), value :: model
    type(tfem_solve_info), intent(inout), optional, target :: info
    integer(c_int) :: status
    type(c_ptr) :: info_address
    info_address = c_null_ptr
    if (present(info)) info_address = c_loc(info)
    status = tfem_solve_by_address(model, info_address)
  end function tfem_solve_opt

  function tfem_solve_contact_opt(model, options, report) result(status)
    type(c_ptr), value :: model
    type(tfem_contact_options), intent(in), optional, target :: options
    type(tfem_contact_report), intent(inout), optional, target :: report
    integer(c_int) :: status
    type(c_ptr) :: options_address
    type(c_ptr) :: report_address
    options_address = c_null_ptr
    if (present(options)) options_address = c_loc(options)
    report_address = c_null_ptr
    if (present(report)) report_address = c_loc(report)
    status = tfem_solve_contact_by_address(model, options_address, report_address)
  end function tfem_solve_contact_opt

  function tfem_solve_adaptive_opt(model, tolerance, goal, max_unknowns, max_cycles, &
        contact, report) result(status)
    type(c_ptr), value :: model
    real(c_double), value :: tolerance
    integer(c_int), value :: goal
    integer(c_int64_t), value :: max_unknowns
    integer(c_int), value :: max_cycles
    type(tfem_contact_options), intent(in), optional, target :: contact
    type(tfem_adapt_report), intent(inout), optional, target :: report
    integer(c_int) :: status
    type(c_ptr) :: contact_address
    type(c_ptr) :: report_address
    contact_address = c_null_ptr
    if (present(contact)) contact_address = c_loc(contact)
    report_address = c_null_ptr
    if (present(report)) report_address = c_loc(report)
    status = tfem_solve_adaptive_by_address(model, tolerance, goal, max_unknowns, max_cycles, &
        contact_address, report_address)
  end function tfem_solve_adaptive_opt

  function tfem_get_adapt_cycles_opt(model, unknowns, estimates, seconds, length) result(status)
    type(c_ptr), value :: model
    integer(c_int64_t), intent(inout), optional, target :: unknowns
    real(c_double), intent(inout), optional, target :: estimates
    real(c_double), intent(inout), optional, target :: seconds(*)
    integer(c_size_t), intent(in) :: length
    integer(c_int) :: status
    type(c_ptr) :: unknowns_address
    type(c_ptr) :: estimates_address
    type(c_ptr) :: seconds_address
    unknowns_address = c_null_ptr
    if (present(unknowns)) unknowns_address = c_loc(unknowns)
    estimates_address = c_null_ptr
    if (present(estimates)) estimates_address = c_loc(estimates)
    seconds_address = tfem_address_c_double(seconds, length /= 0)
    status = tfem_get_adapt_cycles_by_address(model, unknowns_address, estimates_address, &
        seconds_address, length)
  end function tfem_get_adapt_cycles_opt

  function tfem_get_adapt_cycles_opt_r2(model, unknowns, estimates, seconds, length) result(status)
    type(c_ptr), value :: model
    integer(c_int64_t), intent(inout), optional, target :: unknowns
    real(c_double), intent(inout), optional, target :: estimates
    real(c_double), intent(inout), target :: seconds(1, *)
    integer(c_size_t), intent(in) :: length
    integer(c_int) :: status
    type(c_ptr) :: unknowns_address
    type(c_ptr) :: estimates_address
    type(c_ptr) :: seconds_address
    unknowns_address = c_null_ptr
    if (present(unknowns)) unknowns_address = c_loc(unknowns)
    estimates_address = c_null_ptr
    if (present(estimates)) estimates_address = c_loc(estimates)
    seconds_address = tfem_address_c_double(seconds, length /= 0)
    status = tfem_get_adapt_cycles_by_address(model, unknowns_address, estimates_address, &
        seconds_address, length)
  end function tfem_get_adapt_cycles_opt_r2

  function tfem_get_adapt_cycles_opt_i(model, unknowns, estimates, seconds, length) result(status)
    type(c_ptr), value :: model
    integer(c_int64_t), intent(inout), optional, target :: unknowns
    real(c_double), intent(inout), optional, target :: estimates
    real(c_double), intent(inout), optional, target :: seconds(*)
    integer(tfem_length_kind), intent(in) :: length
    integer(c_int) :: status
    type(c_ptr) :: unknowns_address
    type(c_ptr) :: estimates_address
    type(c_ptr) :: seconds_address
    unknowns_address = c_null_ptr
    if (present(unknowns)) unknowns_address = c_loc(unknowns)
    estimates_address = c_null_ptr
    if (present(estimates)) estimates_address = c_loc(estimates)
    seconds_address = tfem_address_c_double(seconds, length > 0)
    status = tfem_get_adapt_cycles_by_address(model, unknowns_address, estimates_address, &
        seconds_address, tfem_to_size_t(length))
  end function tfem_get_adapt_cycles_opt_i

  function tfem_get_adapt_cycles_opt_i_r2(model, unknowns, estimates, seconds, length) result(status)
    type(c_ptr), value :: model
    integer(c_int64_t), intent(inout), optional, target :: unknowns
    real(c_double), intent(inout), optional, target :: estimates
    real(c_double), intent(inout), target :: seconds(1, *)
    integer(tfem_length_kind), intent(in) :: length
    integer(c_int) :: status
    type(c_ptr) :: unknowns_address
    type(c_ptr) :: estimates_address
    type(c_ptr) :: seconds_address
    unknowns_address = c_null_ptr
    if (present(unknowns)) unknowns_address = c_loc(unknowns)
    estimates_address = c_null_ptr
    if (present(estimates)) estimates_address = c_loc(estimates)
    seconds_address = tfem_address_c_double(seconds, length > 0)
    status = tfem_get_adapt_cycles_by_address(model, unknowns_address, estimates_address, &
        seconds_address, tfem_to_size_t(length))
  end function tfem_get_adapt_cycles_opt_i_r2

  function tfem_get_displacements_r2(model, out, length) result(status)
    type(c_ptr), value :: model
    real(c_double), intent(inout) :: out(1, *)
    integer(c_size_t), intent(in) :: length
    integer(c_int) :: status
    status = tfem_get_displacements(model, out, length)
  end function tfem_get_displacements_r2

  function tfem_get_displacements_i(model, out, length) result(status)
    type(c_ptr), value :: model
    real(c_double), intent(inout) :: out(*)
    integer(tfem_length_kind), intent(in) :: length
    integer(c_int) :: status
    status = tfem_get_displacements(model, out, tfem_to_size_t(length))
  end function tfem_get_displacements_i

  function tfem_get_displacements_i_r2(model, out, length) result(status)
    type(c_ptr), value :: model
    real(c_double), intent(inout) :: out(1, *)
    integer(tfem_length_kind), intent(in) :: length
    integer(c_int) :: status
    status = tfem_get_displacements(model, out, tfem_to_size_t(length))
  end function tfem_get_displacements_i_r2

  function tfem_get_element_strains_r2(model, out, length) result(status)
    type(c_ptr), value :: model
    real(c_double), intent(inout) :: out(1, *)
    integer(c_size_t), intent(in) :: length
    integer(c_int) :: status
    status = tfem_get_element_strains(model, out, length)
  end function tfem_get_element_strains_r2

  function tfem_get_element_strains_i(model, out, length) result(status)
    type(c_ptr), value :: model
    real(c_double), intent(inout) :: out(*)
    integer(tfem_length_kind), intent(in) :: length
    integer(c_int) :: status
    status = tfem_get_element_strains(model, out, tfem_to_size_t(length))
  end function tfem_get_element_strains_i

  function tfem_get_element_strains_i_r2(model, out, length) result(status)
    type(c_ptr), value :: model
    real(c_double), intent(inout) :: out(1, *)
    integer(tfem_length_kind), intent(in) :: length
    integer(c_int) :: status
    status = tfem_get_element_strains(model, out, tfem_to_size_t(length))
  end function tfem_get_element_strains_i_r2

  function tfem_get_element_stresses_r2(model, out, length) result(status)
    type(c_ptr), value :: model
    real(c_double), intent(inout) :: out(1, *)
    integer(c_size_t), intent(in) :: length
    integer(c_int) :: status
    status = tfem_get_element_stresses(model, out, length)
  end function tfem_get_element_stresses_r2

  function tfem_get_element_stresses_i(model, out, length) result(status)
    type(c_ptr), value :: model
    real(c_double), intent(inout) :: out(*)
    integer(tfem_length_kind), intent(in) :: length
    integer(c_int) :: status
    status = tfem_get_element_stresses(model, out, tfem_to_size_t(length))
  end function tfem_get_element_stresses_i

  function tfem_get_element_stresses_i_r2(model, out, length) result(status)
    type(c_ptr), value :: model
    real(c_double), intent(inout) :: out(1, *)
    integer(tfem_length_kind), intent(in) :: length
    integer(c_int) :: status
    status = tfem_get_element_stresses(model, out, tfem_to_size_t(length))
  end function tfem_get_element_stresses_i_r2

  function tfem_get_element_out_of_plane_stresses_r2(model, out, length) result(status)
    type(c_ptr), value :: model
    real(c_double), intent(inout) :: out(1, *)
    integer(c_size_t), intent(in) :: length
    integer(c_int) :: status
    status = tfem_get_element_out_of_plane_stresses(model, out, length)
  end function tfem_get_element_out_of_plane_stresses_r2

  function tfem_get_element_out_of_plane_stresses_i(model, out, length) result(status)
    type(c_ptr), value :: model
    real(c_double), intent(inout) :: out(*)
    integer(tfem_length_kind), intent(in) :: length
    integer(c_int) :: status
    status = tfem_get_element_out_of_plane_stresses(model, out, tfem_to_size_t(length))
  end function tfem_get_element_out_of_plane_stresses_i

  function tfem_get_element_out_of_plane_stresses_i_r2(model, out, length) result(status)
    type(c_ptr), value :: model
    real(c_double), intent(inout) :: out(1, *)
    integer(tfem_length_kind), intent(in) :: length
    integer(c_int) :: status
    status = tfem_get_element_out_of_plane_stresses(model, out, tfem_to_size_t(length))
  end function tfem_get_element_out_of_plane_stresses_i_r2

  function tfem_get_element_jacobians_r2(model, out, length) result(status)
    type(c_ptr), value :: model
    real(c_double), intent(inout) :: out(1, *)
    integer(c_size_t), intent(in) :: length
    integer(c_int) :: status
    status = tfem_get_element_jacobians(model, out, length)
  end function tfem_get_element_jacobians_r2

  function tfem_get_element_jacobians_i(model, out, length) result(status)
    type(c_ptr), value :: model
    real(c_double), intent(inout) :: out(*)
    integer(tfem_length_kind), intent(in) :: length
    integer(c_int) :: status
    status = tfem_get_element_jacobians(model, out, tfem_to_size_t(length))
  end function tfem_get_element_jacobians_i

  function tfem_get_element_jacobians_i_r2(model, out, length) result(status)
    type(c_ptr), value :: model
    real(c_double), intent(inout) :: out(1, *)
    integer(tfem_length_kind), intent(in) :: length
    integer(c_int) :: status
    status = tfem_get_element_jacobians(model, out, tfem_to_size_t(length))
  end function tfem_get_element_jacobians_i_r2

  function tfem_get_reactions_r2(model, out, length) result(status)
    type(c_ptr), value :: model
    real(c_double), intent(inout) :: out(1, *)
    integer(c_size_t), intent(in) :: length
    integer(c_int) :: status
    status = tfem_get_reactions(model, out, length)
  end function tfem_get_reactions_r2

  function tfem_get_reactions_i(model, out, length) result(status)
    type(c_ptr), value :: model
    real(c_double), intent(inout) :: out(*)
    integer(tfem_length_kind), intent(in) :: length
    integer(c_int) :: status
    status = tfem_get_reactions(model, out, tfem_to_size_t(length))
  end function tfem_get_reactions_i

  function tfem_get_reactions_i_r2(model, out, length) result(status)
    type(c_ptr), value :: model
    real(c_double), intent(inout) :: out(1, *)
    integer(tfem_length_kind), intent(in) :: length
    integer(c_int) :: status
    status = tfem_get_reactions(model, out, tfem_to_size_t(length))
  end function tfem_get_reactions_i_r2

  function tfem_get_contact_forces_r2(model, out, length) result(status)
    type(c_ptr), value :: model
    real(c_double), intent(inout) :: out(1, *)
    integer(c_size_t), intent(in) :: length
    integer(c_int) :: status
    status = tfem_get_contact_forces(model, out, length)
  end function tfem_get_contact_forces_r2

  function tfem_get_contact_forces_i(model, out, length) result(status)
    type(c_ptr), value :: model
    real(c_double), intent(inout) :: out(*)
    integer(tfem_length_kind), intent(in) :: length
    integer(c_int) :: status
    status = tfem_get_contact_forces(model, out, tfem_to_size_t(length))
  end function tfem_get_contact_forces_i

  function tfem_get_contact_forces_i_r2(model, out, length) result(status)
    type(c_ptr), value :: model
    real(c_double), intent(inout) :: out(1, *)
    integer(tfem_length_kind), intent(in) :: length
    integer(c_int) :: status
    status = tfem_get_contact_forces(model, out, tfem_to_size_t(length))
  end function tfem_get_contact_forces_i_r2

  function tfem_get_contact_nodal_pressures_r2(model, out, length) result(status)
    type(c_ptr), value :: model
    real(c_double), intent(inout) :: out(1, *)
    integer(c_size_t), intent(in) :: length
    integer(c_int) :: status
    status = tfem_get_contact_nodal_pressures(model, out, length)
  end function tfem_get_contact_nodal_pressures_r2

  function tfem_get_contact_nodal_pressures_i(model, out, length) result(status)
    type(c_ptr), value :: model
    real(c_double), intent(inout) :: out(*)
    integer(tfem_length_kind), intent(in) :: length
    integer(c_int) :: status
    status = tfem_get_contact_nodal_pressures(model, out, tfem_to_size_t(length))
  end function tfem_get_contact_nodal_pressures_i

  function tfem_get_contact_nodal_pressures_i_r2(model, out, length) result(status)
    type(c_ptr), value :: model
    real(c_double), intent(inout) :: out(1, *)
    integer(tfem_length_kind), intent(in) :: length
    integer(c_int) :: status
    status = tfem_get_contact_nodal_pressures(model, out, tfem_to_size_t(length))
  end function tfem_get_contact_nodal_pressures_i_r2

  function tfem_get_contact_nodal_tractions_r2(model, out, length) result(status)
    type(c_ptr), value :: model
    real(c_double), intent(inout) :: out(1, *)
    integer(c_size_t), intent(in) :: length
    integer(c_int) :: status
    status = tfem_get_contact_nodal_tractions(model, out, length)
  end function tfem_get_contact_nodal_tractions_r2

  function tfem_get_contact_nodal_tractions_i(model, out, length) result(status)
    type(c_ptr), value :: model
    real(c_double), intent(inout) :: out(*)
    integer(tfem_length_kind), intent(in) :: length
    integer(c_int) :: status
    status = tfem_get_contact_nodal_tractions(model, out, tfem_to_size_t(length))
  end function tfem_get_contact_nodal_tractions_i

  function tfem_get_contact_nodal_tractions_i_r2(model, out, length) result(status)
    type(c_ptr), value :: model
    real(c_double), intent(inout) :: out(1, *)
    integer(tfem_length_kind), intent(in) :: length
    integer(c_int) :: status
    status = tfem_get_contact_nodal_tractions(model, out, tfem_to_size_t(length))
  end function tfem_get_contact_nodal_tractions_i_r2

  function tfem_get_contact_pair_nodal_pressures_r2(model, pair, out, length) result(status)
    type(c_ptr), value :: model
    integer(c_int), value :: pair
    real(c_double), intent(inout) :: out(1, *)
    integer(c_size_t), intent(in) :: length
    integer(c_int) :: status
    status = tfem_get_contact_pair_nodal_pressures(model, pair, out, length)
  end function tfem_get_contact_pair_nodal_pressures_r2

  function tfem_get_contact_pair_nodal_pressures_i(model, pair, out, length) result(status)
    type(c_ptr), value :: model
    integer(c_int), value :: pair
    real(c_double), intent(inout) :: out(*)
    integer(tfem_length_kind), intent(in) :: length
    integer(c_int) :: status
    status = tfem_get_contact_pair_nodal_pressures(model, pair, out, tfem_to_size_t(length))
  end function tfem_get_contact_pair_nodal_pressures_i

  function tfem_get_contact_pair_nodal_pressures_i_r2(model, pair, out, length) result(status)
    type(c_ptr), value :: model
    integer(c_int), value :: pair
    real(c_double), intent(inout) :: out(1, *)
    integer(tfem_length_kind), intent(in) :: length
    integer(c_int) :: status
    status = tfem_get_contact_pair_nodal_pressures(model, pair, out, tfem_to_size_t(length))
  end function tfem_get_contact_pair_nodal_pressures_i_r2

  function tfem_get_contact_pair_nodal_tractions_r2(model, pair, out, length) result(status)
    type(c_ptr), value :: model
    integer(c_int), value :: pair
    real(c_double), intent(inout) :: out(1, *)
    integer(c_size_t), intent(in) :: length
    integer(c_int) :: status
    status = tfem_get_contact_pair_nodal_tractions(model, pair, out, length)
  end function tfem_get_contact_pair_nodal_tractions_r2

  function tfem_get_contact_pair_nodal_tractions_i(model, pair, out, length) result(status)
    type(c_ptr), value :: model
    integer(c_int), value :: pair
    real(c_double), intent(inout) :: out(*)
    integer(tfem_length_kind), intent(in) :: length
    integer(c_int) :: status
    status = tfem_get_contact_pair_nodal_tractions(model, pair, out, tfem_to_size_t(length))
  end function tfem_get_contact_pair_nodal_tractions_i

  function tfem_get_contact_pair_nodal_tractions_i_r2(model, pair, out, length) result(status)
    type(c_ptr), value :: model
    integer(c_int), value :: pair
    real(c_double), intent(inout) :: out(1, *)
    integer(tfem_length_kind), intent(in) :: length
    integer(c_int) :: status
    status = tfem_get_contact_pair_nodal_tractions(model, pair, out, tfem_to_size_t(length))
  end function tfem_get_contact_pair_nodal_tractions_i_r2

  function tfem_get_contact_gaps_r2(model, out, length) result(status)
    type(c_ptr), value :: model
    real(c_double), intent(inout) :: out(1, *)
    integer(c_size_t), intent(in) :: length
    integer(c_int) :: status
    status = tfem_get_contact_gaps(model, out, length)
  end function tfem_get_contact_gaps_r2

  function tfem_get_contact_gaps_i(model, out, length) result(status)
    type(c_ptr), value :: model
    real(c_double), intent(inout) :: out(*)
    integer(tfem_length_kind), intent(in) :: length
    integer(c_int) :: status
    status = tfem_get_contact_gaps(model, out, tfem_to_size_t(length))
  end function tfem_get_contact_gaps_i

  function tfem_get_contact_gaps_i_r2(model, out, length) result(status)
    type(c_ptr), value :: model
    real(c_double), intent(inout) :: out(1, *)
    integer(tfem_length_kind), intent(in) :: length
    integer(c_int) :: status
    status = tfem_get_contact_gaps(model, out, tfem_to_size_t(length))
  end function tfem_get_contact_gaps_i_r2

  function tfem_get_contact_active_r2(model, out, length) result(status)
    type(c_ptr), value :: model
    integer(c_int), intent(inout) :: out(1, *)
    integer(c_size_t), intent(in) :: length
    integer(c_int) :: status
    status = tfem_get_contact_active(model, out, length)
  end function tfem_get_contact_active_r2

  function tfem_get_contact_active_i(model, out, length) result(status)
    type(c_ptr), value :: model
    integer(c_int), intent(inout) :: out(*)
    integer(tfem_length_kind), intent(in) :: length
    integer(c_int) :: status
    status = tfem_get_contact_active(model, out, tfem_to_size_t(length))
  end function tfem_get_contact_active_i

  function tfem_get_contact_active_i_r2(model, out, length) result(status)
    type(c_ptr), value :: model
    integer(c_int), intent(inout) :: out(1, *)
    integer(tfem_length_kind), intent(in) :: length
    integer(c_int) :: status
    status = tfem_get_contact_active(model, out, tfem_to_size_t(length))
  end function tfem_get_contact_active_i_r2

  function tfem_get_contact_pressure_r2(model, out, length) result(status)
    type(c_ptr), value :: model
    real(c_double), intent(inout) :: out(1, *)
    integer(c_size_t), intent(in) :: length
    integer(c_int) :: status
    status = tfem_get_contact_pressure(model, out, length)
  end function tfem_get_contact_pressure_r2

  function tfem_get_contact_pressure_i(model, out, length) result(status)
    type(c_ptr), value :: model
    real(c_double), intent(inout) :: out(*)
    integer(tfem_length_kind), intent(in) :: length
    integer(c_int) :: status
    status = tfem_get_contact_pressure(model, out, tfem_to_size_t(length))
  end function tfem_get_contact_pressure_i

  function tfem_get_contact_pressure_i_r2(model, out, length) result(status)
    type(c_ptr), value :: model
    real(c_double), intent(inout) :: out(1, *)
    integer(tfem_length_kind), intent(in) :: length
    integer(c_int) :: status
    status = tfem_get_contact_pressure(model, out, tfem_to_size_t(length))
  end function tfem_get_contact_pressure_i_r2

  function tfem_get_contact_elements_r2(model, out, length) result(status)
    type(c_ptr), value :: model
    integer(c_int), intent(inout) :: out(1, *)
    integer(c_size_t), intent(in) :: length
    integer(c_int) :: status
    status = tfem_get_contact_elements(model, out, length)
  end function tfem_get_contact_elements_r2

  function tfem_get_contact_elements_i(model, out, length) result(status)
    type(c_ptr), value :: model
    integer(c_int), intent(inout) :: out(*)
    integer(tfem_length_kind), intent(in) :: length
    integer(c_int) :: status
    status = tfem_get_contact_elements(model, out, tfem_to_size_t(length))
  end function tfem_get_contact_elements_i

  function tfem_get_contact_elements_i_r2(model, out, length) result(status)
    type(c_ptr), value :: model
    integer(c_int), intent(inout) :: out(1, *)
    integer(tfem_length_kind), intent(in) :: length
    integer(c_int) :: status
    status = tfem_get_contact_elements(model, out, tfem_to_size_t(length))
  end function tfem_get_contact_elements_i_r2

  function tfem_get_contact_shear_r2(model, out, length) result(status)
    type(c_ptr), value :: model
    real(c_double), intent(inout) :: out(1, *)
    integer(c_size_t), intent(in) :: length
    integer(c_int) :: status
    status = tfem_get_contact_shear(model, out, length)
  end function tfem_get_contact_shear_r2

  function tfem_get_contact_shear_i(model, out, length) result(status)
    type(c_ptr), value :: model
    real(c_double), intent(inout) :: out(*)
    integer(tfem_length_kind), intent(in) :: length
    integer(c_int) :: status
    status = tfem_get_contact_shear(model, out, tfem_to_size_t(length))
  end function tfem_get_contact_shear_i

  function tfem_get_contact_shear_i_r2(model, out, length) result(status)
    type(c_ptr), value :: model
    real(c_double), intent(inout) :: out(1, *)
    integer(tfem_length_kind), intent(in) :: length
    integer(c_int) :: status
    status = tfem_get_contact_shear(model, out, tfem_to_size_t(length))
  end function tfem_get_contact_shear_i_r2

  function tfem_get_contact_friction_state_r2(model, out, length) result(status)
    type(c_ptr), value :: model
    integer(c_int), intent(inout) :: out(1, *)
    integer(c_size_t), intent(in) :: length
    integer(c_int) :: status
    status = tfem_get_contact_friction_state(model, out, length)
  end function tfem_get_contact_friction_state_r2

  function tfem_get_contact_friction_state_i(model, out, length) result(status)
    type(c_ptr), value :: model
    integer(c_int), intent(inout) :: out(*)
    integer(tfem_length_kind), intent(in) :: length
    integer(c_int) :: status
    status = tfem_get_contact_friction_state(model, out, tfem_to_size_t(length))
  end function tfem_get_contact_friction_state_i

  function tfem_get_contact_friction_state_i_r2(model, out, length) result(status)
    type(c_ptr), value :: model
    integer(c_int), intent(inout) :: out(1, *)
    integer(tfem_length_kind), intent(in) :: length
    integer(c_int) :: status
    status = tfem_get_contact_friction_state(model, out, tfem_to_size_t(length))
  end function tfem_get_contact_friction_state_i_r2

  function tfem_get_contact_dissipation_r2(model, out, length) result(status)
    type(c_ptr), value :: model
    real(c_double), intent(inout) :: out(1, *)
    integer(c_size_t), intent(in) :: length
    integer(c_int) :: status
    status = tfem_get_contact_dissipation(model, out, length)
  end function tfem_get_contact_dissipation_r2

  function tfem_get_contact_dissipation_i(model, out, length) result(status)
    type(c_ptr), value :: model
    real(c_double), intent(inout) :: out(*)
    integer(tfem_length_kind), intent(in) :: length
    integer(c_int) :: status
    status = tfem_get_contact_dissipation(model, out, tfem_to_size_t(length))
  end function tfem_get_contact_dissipation_i

  function tfem_get_contact_dissipation_i_r2(model, out, length) result(status)
    type(c_ptr), value :: model
    real(c_double), intent(inout) :: out(1, *)
    integer(tfem_length_kind), intent(in) :: length
    integer(c_int) :: status
    status = tfem_get_contact_dissipation(model, out, tfem_to_size_t(length))
  end function tfem_get_contact_dissipation_i_r2

  function tfem_get_contact_slave_nodes_opt(model, node, tributary, gap, pressure, &
        length) result(status)
    type(c_ptr), value :: model
    integer(c_int), intent(inout), optional, target :: node(*)
    real(c_double), intent(inout), optional, target :: tributary(*)
    real(c_double), intent(inout), optional, target :: gap(*)
    real(c_double), intent(inout), optional, target :: pressure(*)
    integer(c_size_t), intent(in) :: length
    integer(c_int) :: status
    type(c_ptr) :: node_address
    type(c_ptr) :: tributary_address
    type(c_ptr) :: gap_address
    type(c_ptr) :: pressure_address
    node_address = tfem_address_c_int(node, length /= 0)
    tributary_address = tfem_address_c_double(tributary, length /= 0)
    gap_address = tfem_address_c_double(gap, length /= 0)
    pressure_address = tfem_address_c_double(pressure, length /= 0)
    status = tfem_get_contact_slave_nodes_by_address(model, node_address, tributary_address, &
        gap_address, pressure_address, length)
  end function tfem_get_contact_slave_nodes_opt

  function tfem_get_contact_slave_nodes_opt_r2111(model, node, tributary, gap, &
        pressure, length) result(status)
    type(c_ptr), value :: model
    integer(c_int), intent(inout), target :: node(1, *)
    real(c_double), intent(inout), optional, target :: tributary(*)
    real(c_double), intent(inout), optional, target :: gap(*)
    real(c_double), intent(inout), optional, target :: pressure(*)
    integer(c_size_t), intent(in) :: length
    integer(c_int) :: status
    type(c_ptr) :: node_address
    type(c_ptr) :: tributary_address
    type(c_ptr) :: gap_address
    type(c_ptr) :: pressure_address
    node_address = tfem_address_c_int(node, length /= 0)
    tributary_address = tfem_address_c_double(tributary, length /= 0)
    gap_address = tfem_address_c_double(gap, length /= 0)
    pressure_address = tfem_address_c_double(pressure, length /= 0)
    status = tfem_get_contact_slave_nodes_by_address(model, node_address, tributary_address, &
        gap_address, pressure_address, length)
  end function tfem_get_contact_slave_nodes_opt_r2111

  function tfem_get_contact_slave_nodes_opt_r1211(model, node, tributary, gap, &
        pressure, length) result(status)
    type(c_ptr), value :: model
    integer(c_int), intent(inout), optional, target :: node(*)
    real(c_double), intent(inout), target :: tributary(1, *)
    real(c_double), intent(inout), optional, target :: gap(*)
    real(c_double), intent(inout), optional, target :: pressure(*)
    integer(c_size_t), intent(in) :: length
    integer(c_int) :: status
    type(c_ptr) :: node_address
    type(c_ptr) :: tributary_address
    type(c_ptr) :: gap_address
    type(c_ptr) :: pressure_address
    node_address = tfem_address_c_int(node, length /= 0)
    tributary_address = tfem_address_c_double(tributary, length /= 0)
    gap_address = tfem_address_c_double(gap, length /= 0)
    pressure_address = tfem_address_c_double(pressure, length /= 0)
    status = tfem_get_contact_slave_nodes_by_address(model, node_address, tributary_address, &
        gap_address, pressure_address, length)
  end function tfem_get_contact_slave_nodes_opt_r1211

  function tfem_get_contact_slave_nodes_opt_r2211(model, node, tributary, gap, &
        pressure, length) result(status)
    type(c_ptr), value :: model
    integer(c_int), intent(inout), target :: node(1, *)
    real(c_double), intent(inout), target :: tributary(1, *)
    real(c_double), intent(inout), optional, target :: gap(*)
    real(c_double), intent(inout), optional, target :: pressure(*)
    integer(c_size_t), intent(in) :: length
    integer(c_int) :: status
    type(c_ptr) :: node_address
    type(c_ptr) :: tributary_address
    type(c_ptr) :: gap_address
    type(c_ptr) :: pressure_address
    node_address = tfem_address_c_int(node, length /= 0)
    tributary_address = tfem_address_c_double(tributary, length /= 0)
    gap_address = tfem_address_c_double(gap, length /= 0)
    pressure_address = tfem_address_c_double(pressure, length /= 0)
    status = tfem_get_contact_slave_nodes_by_address(model, node_address, tributary_address, &
        gap_address, pressure_address, length)
  end function tfem_get_contact_slave_nodes_opt_r2211

  function tfem_get_contact_slave_nodes_opt_r1121(model, node, tributary, gap, &
        pressure, length) result(status)
    type(c_ptr), value :: model
    integer(c_int), intent(inout), optional, target :: node(*)
    real(c_double), intent(inout), optional, target :: tributary(*)
    real(c_double), intent(inout), target :: gap(1, *)
    real(c_double), intent(inout), optional, target :: pressure(*)
    integer(c_size_t), intent(in) :: length
    integer(c_int) :: status
    type(c_ptr) :: node_address
    type(c_ptr) :: tributary_address
    type(c_ptr) :: gap_address
    type(c_ptr) :: pressure_address
    node_address = tfem_address_c_int(node, length /= 0)
    tributary_address = tfem_address_c_double(tributary, length /= 0)
    gap_address = tfem_address_c_double(gap, length /= 0)
    pressure_address = tfem_address_c_double(pressure, length /= 0)
    status = tfem_get_contact_slave_nodes_by_address(model, node_address, tributary_address, &
        gap_address, pressure_address, length)
  end function tfem_get_contact_slave_nodes_opt_r1121

  function tfem_get_contact_slave_nodes_opt_r2121(model, node, tributary, gap, &
        pressure, length) result(status)
    type(c_ptr), value :: model
    integer(c_int), intent(inout), target :: node(1, *)
    real(c_double), intent(inout), optional, target :: tributary(*)
    real(c_double), intent(inout), target :: gap(1, *)
    real(c_double), intent(inout), optional, target :: pressure(*)
    integer(c_size_t), intent(in) :: length
    integer(c_int) :: status
    type(c_ptr) :: node_address
    type(c_ptr) :: tributary_address
    type(c_ptr) :: gap_address
    type(c_ptr) :: pressure_address
    node_address = tfem_address_c_int(node, length /= 0)
    tributary_address = tfem_address_c_double(tributary, length /= 0)
    gap_address = tfem_address_c_double(gap, length /= 0)
    pressure_address = tfem_address_c_double(pressure, length /= 0)
    status = tfem_get_contact_slave_nodes_by_address(model, node_address, tributary_address, &
        gap_address, pressure_address, length)
  end function tfem_get_contact_slave_nodes_opt_r2121

  function tfem_get_contact_slave_nodes_opt_r1221(model, node, tributary, gap, &
        pressure, length) result(status)
    type(c_ptr), value :: model
    integer(c_int), intent(inout), optional, target :: node(*)
    real(c_double), intent(inout), target :: tributary(1, *)
    real(c_double), intent(inout), target :: gap(1, *)
    real(c_double), intent(inout), optional, target :: pressure(*)
    integer(c_size_t), intent(in) :: length
    integer(c_int) :: status
    type(c_ptr) :: node_address
    type(c_ptr) :: tributary_address
    type(c_ptr) :: gap_address
    type(c_ptr) :: pressure_address
    node_address = tfem_address_c_int(node, length /= 0)
    tributary_address = tfem_address_c_double(tributary, length /= 0)
    gap_address = tfem_address_c_double(gap, length /= 0)
    pressure_address = tfem_address_c_double(pressure, length /= 0)
    status = tfem_get_contact_slave_nodes_by_address(model, node_address, tributary_address, &
        gap_address, pressure_address, length)
  end function tfem_get_contact_slave_nodes_opt_r1221

  function tfem_get_contact_slave_nodes_opt_r2221(model, node, tributary, gap, &
        pressure, length) result(status)
    type(c_ptr), value :: model
    integer(c_int), intent(inout), target :: node(1, *)
    real(c_double), intent(inout), target :: tributary(1, *)
    real(c_double), intent(inout), target :: gap(1, *)
    real(c_double), intent(inout), optional, target :: pressure(*)
    integer(c_size_t), intent(in) :: length
    integer(c_int) :: status
    type(c_ptr) :: node_address
    type(c_ptr) :: tributary_address
    type(c_ptr) :: gap_address
    type(c_ptr) :: pressure_address
    node_address = tfem_address_c_int(node, length /= 0)
    tributary_address = tfem_address_c_double(tributary, length /= 0)
    gap_address = tfem_address_c_double(gap, length /= 0)
    pressure_address = tfem_address_c_double(pressure, length /= 0)
    status = tfem_get_contact_slave_nodes_by_address(model, node_address, tributary_address, &
        gap_address, pressure_address, length)
  end function tfem_get_contact_slave_nodes_opt_r2221

  function tfem_get_contact_slave_nodes_opt_r1112(model, node, tributary, gap, &
        pressure, length) result(status)
    type(c_ptr), value :: model
    integer(c_int), intent(inout), optional, target :: node(*)
    real(c_double), intent(inout), optional, target :: tributary(*)
    real(c_double), intent(inout), optional, target :: gap(*)
    real(c_double), intent(inout), target :: pressure(1, *)
    integer(c_size_t), intent(in) :: length
    integer(c_int) :: status
    type(c_ptr) :: node_address
    type(c_ptr) :: tributary_address
    type(c_ptr) :: gap_address
    type(c_ptr) :: pressure_address
    node_address = tfem_address_c_int(node, length /= 0)
    tributary_address = tfem_address_c_double(tributary, length /= 0)
    gap_address = tfem_address_c_double(gap, length /= 0)
    pressure_address = tfem_address_c_double(pressure, length /= 0)
    status = tfem_get_contact_slave_nodes_by_address(model, node_address, tributary_address, &
        gap_address, pressure_address, length)
  end function tfem_get_contact_slave_nodes_opt_r1112

  function tfem_get_contact_slave_nodes_opt_r2112(model, node, tributary, gap, &
        pressure, length) result(status)
    type(c_ptr), value :: model
    integer(c_int), intent(inout), target :: node(1, *)
    real(c_double), intent(inout), optional, target :: tributary(*)
    real(c_double), intent(inout), optional, target :: gap(*)
    real(c_double), intent(inout), target :: pressure(1, *)
    integer(c_size_t), intent(in) :: length
    integer(c_int) :: status
    type(c_ptr) :: node_address
    type(c_ptr) :: tributary_address
    type(c_ptr) :: gap_address
    type(c_ptr) :: pressure_address
    node_address = tfem_address_c_int(node, length /= 0)
    tributary_address = tfem_address_c_double(tributary, length /= 0)
    gap_address = tfem_address_c_double(gap, length /= 0)
    pressure_address = tfem_address_c_double(pressure, length /= 0)
    status = tfem_get_contact_slave_nodes_by_address(model, node_address, tributary_address, &
        gap_address, pressure_address, length)
  end function tfem_get_contact_slave_nodes_opt_r2112

  function tfem_get_contact_slave_nodes_opt_r1212(model, node, tributary, gap, &
        pressure, length) result(status)
    type(c_ptr), value :: model
    integer(c_int), intent(inout), optional, target :: node(*)
    real(c_double), intent(inout), target :: tributary(1, *)
    real(c_double), intent(inout), optional, target :: gap(*)
    real(c_double), intent(inout), target :: pressure(1, *)
    integer(c_size_t), intent(in) :: length
    integer(c_int) :: status
    type(c_ptr) :: node_address
    type(c_ptr) :: tributary_address
    type(c_ptr) :: gap_address
    type(c_ptr) :: pressure_address
    node_address = tfem_address_c_int(node, length /= 0)
    tributary_address = tfem_address_c_double(tributary, length /= 0)
    gap_address = tfem_address_c_double(gap, length /= 0)
    pressure_address = tfem_address_c_double(pressure, length /= 0)
    status = tfem_get_contact_slave_nodes_by_address(model, node_address, tributary_address, &
        gap_address, pressure_address, length)
  end function tfem_get_contact_slave_nodes_opt_r1212

  function tfem_get_contact_slave_nodes_opt_r2212(model, node, tributary, gap, &
        pressure, length) result(status)
    type(c_ptr), value :: model
    integer(c_int), intent(inout), target :: node(1, *)
    real(c_double), intent(inout), target :: tributary(1, *)
    real(c_double), intent(inout), optional, target :: gap(*)
    real(c_double), intent(inout), target :: pressure(1, *)
    integer(c_size_t), intent(in) :: length
    integer(c_int) :: status
    type(c_ptr) :: node_address
    type(c_ptr) :: tributary_address
    type(c_ptr) :: gap_address
    type(c_ptr) :: pressure_address
    node_address = tfem_address_c_int(node, length /= 0)
    tributary_address = tfem_address_c_double(tributary, length /= 0)
    gap_address = tfem_address_c_double(gap, length /= 0)
    pressure_address = tfem_address_c_double(pressure, length /= 0)
    status = tfem_get_contact_slave_nodes_by_address(model, node_address, tributary_address, &
        gap_address, pressure_address, length)
  end function tfem_get_contact_slave_nodes_opt_r2212

  function tfem_get_contact_slave_nodes_opt_r1122(model, node, tributary, gap, &
        pressure, length) result(status)
    type(c_ptr), value :: model
    integer(c_int), intent(inout), optional, target :: node(*)
    real(c_double), intent(inout), optional, target :: tributary(*)
    real(c_double), intent(inout), target :: gap(1, *)
    real(c_double), intent(inout), target :: pressure(1, *)
    integer(c_size_t), intent(in) :: length
    integer(c_int) :: status
    type(c_ptr) :: node_address
    type(c_ptr) :: tributary_address
    type(c_ptr) :: gap_address
    type(c_ptr) :: pressure_address
    node_address = tfem_address_c_int(node, length /= 0)
    tributary_address = tfem_address_c_double(tributary, length /= 0)
    gap_address = tfem_address_c_double(gap, length /= 0)
    pressure_address = tfem_address_c_double(pressure, length /= 0)
    status = tfem_get_contact_slave_nodes_by_address(model, node_address, tributary_address, &
        gap_address, pressure_address, length)
  end function tfem_get_contact_slave_nodes_opt_r1122

  function tfem_get_contact_slave_nodes_opt_r2122(model, node, tributary, gap, &
        pressure, length) result(status)
    type(c_ptr), value :: model
    integer(c_int), intent(inout), target :: node(1, *)
    real(c_double), intent(inout), optional, target :: tributary(*)
    real(c_double), intent(inout), target :: gap(1, *)
    real(c_double), intent(inout), target :: pressure(1, *)
    integer(c_size_t), intent(in) :: length
    integer(c_int) :: status
    type(c_ptr) :: node_address
    type(c_ptr) :: tributary_address
    type(c_ptr) :: gap_address
    type(c_ptr) :: pressure_address
    node_address = tfem_address_c_int(node, length /= 0)
    tributary_address = tfem_address_c_double(tributary, length /= 0)
    gap_address = tfem_address_c_double(gap, length /= 0)
    pressure_address = tfem_address_c_double(pressure, length /= 0)
    status = tfem_get_contact_slave_nodes_by_address(model, node_address, tributary_address, &
        gap_address, pressure_address, length)
  end function tfem_get_contact_slave_nodes_opt_r2122

  function tfem_get_contact_slave_nodes_opt_r1222(model, node, tributary, gap, &
        pressure, length) result(status)
    type(c_ptr), value :: model
    integer(c_int), intent(inout), optional, target :: node(*)
    real(c_double), intent(inout), target :: tributary(1, *)
    real(c_double), intent(inout), target :: gap(1, *)
    real(c_double), intent(inout), target :: pressure(1, *)
    integer(c_size_t), intent(in) :: length
    integer(c_int) :: status
    type(c_ptr) :: node_address
    type(c_ptr) :: tributary_address
    type(c_ptr) :: gap_address
    type(c_ptr) :: pressure_address
    node_address = tfem_address_c_int(node, length /= 0)
    tributary_address = tfem_address_c_double(tributary, length /= 0)
    gap_address = tfem_address_c_double(gap, length /= 0)
    pressure_address = tfem_address_c_double(pressure, length /= 0)
    status = tfem_get_contact_slave_nodes_by_address(model, node_address, tributary_address, &
        gap_address, pressure_address, length)
  end function tfem_get_contact_slave_nodes_opt_r1222

  function tfem_get_contact_slave_nodes_opt_r2222(model, node, tributary, gap, &
        pressure, length) result(status)
    type(c_ptr), value :: model
    integer(c_int), intent(inout), target :: node(1, *)
    real(c_double), intent(inout), target :: tributary(1, *)
    real(c_double), intent(inout), target :: gap(1, *)
    real(c_double), intent(inout), target :: pressure(1, *)
    integer(c_size_t), intent(in) :: length
    integer(c_int) :: status
    type(c_ptr) :: node_address
    type(c_ptr) :: tributary_address
    type(c_ptr) :: gap_address
    type(c_ptr) :: pressure_address
    node_address = tfem_address_c_int(node, length /= 0)
    tributary_address = tfem_address_c_double(tributary, length /= 0)
    gap_address = tfem_address_c_double(gap, length /= 0)
    pressure_address = tfem_address_c_double(pressure, length /= 0)
    status = tfem_get_contact_slave_nodes_by_address(model, node_address, tributary_address, &
        gap_address, pressure_address, length)
  end function tfem_get_contact_slave_nodes_opt_r2222

  function tfem_get_contact_slave_nodes_opt_i(model, node, tributary, gap, pressure, &
        length) result(status)
    type(c_ptr), value :: model
    integer(c_int), intent(inout), optional, target :: node(*)
    real(c_double), intent(inout), optional, target :: tributary(*)
    real(c_double), intent(inout), optional, target :: gap(*)
    real(c_double), intent(inout), optional, target :: pressure(*)
    integer(tfem_length_kind), intent(in) :: length
    integer(c_int) :: status
    type(c_ptr) :: node_address
    type(c_ptr) :: tributary_address
    type(c_ptr) :: gap_address
    type(c_ptr) :: pressure_address
    node_address = tfem_address_c_int(node, length > 0)
    tributary_address = tfem_address_c_double(tributary, length > 0)
    gap_address = tfem_address_c_double(gap, length > 0)
    pressure_address = tfem_address_c_double(pressure, length > 0)
    status = tfem_get_contact_slave_nodes_by_address(model, node_address, tributary_address, &
        gap_address, pressure_address, tfem_to_size_t(length))
  end function tfem_get_contact_slave_nodes_opt_i

  function tfem_get_contact_slave_nodes_opt_i_r2111(model, node, tributary, gap, &
        pressure, length) result(status)
    type(c_ptr), value :: model
    integer(c_int), intent(inout), target :: node(1, *)
    real(c_double), intent(inout), optional, target :: tributary(*)
    real(c_double), intent(inout), optional, target :: gap(*)
    real(c_double), intent(inout), optional, target :: pressure(*)
    integer(tfem_length_kind), intent(in) :: length
    integer(c_int) :: status
    type(c_ptr) :: node_address
    type(c_ptr) :: tributary_address
    type(c_ptr) :: gap_address
    type(c_ptr) :: pressure_address
    node_address = tfem_address_c_int(node, length > 0)
    tributary_address = tfem_address_c_double(tributary, length > 0)
    gap_address = tfem_address_c_double(gap, length > 0)
    pressure_address = tfem_address_c_double(pressure, length > 0)
    status = tfem_get_contact_slave_nodes_by_address(model, node_address, tributary_address, &
        gap_address, pressure_address, tfem_to_size_t(length))
  end function tfem_get_contact_slave_nodes_opt_i_r2111

  function tfem_get_contact_slave_nodes_opt_i_r1211(model, node, tributary, gap, &
        pressure, length) result(status)
    type(c_ptr), value :: model
    integer(c_int), intent(inout), optional, target :: node(*)
    real(c_double), intent(inout), target :: tributary(1, *)
    real(c_double), intent(inout), optional, target :: gap(*)
    real(c_double), intent(inout), optional, target :: pressure(*)
    integer(tfem_length_kind), intent(in) :: length
    integer(c_int) :: status
    type(c_ptr) :: node_address
    type(c_ptr) :: tributary_address
    type(c_ptr) :: gap_address
    type(c_ptr) :: pressure_address
    node_address = tfem_address_c_int(node, length > 0)
    tributary_address = tfem_address_c_double(tributary, length > 0)
    gap_address = tfem_address_c_double(gap, length > 0)
    pressure_address = tfem_address_c_double(pressure, length > 0)
    status = tfem_get_contact_slave_nodes_by_address(model, node_address, tributary_address, &
        gap_address, pressure_address, tfem_to_size_t(length))
  end function tfem_get_contact_slave_nodes_opt_i_r1211

  function tfem_get_contact_slave_nodes_opt_i_r2211(model, node, tributary, gap, &
        pressure, length) result(status)
    type(c_ptr), value :: model
    integer(c_int), intent(inout), target :: node(1, *)
    real(c_double), intent(inout), target :: tributary(1, *)
    real(c_double), intent(inout), optional, target :: gap(*)
    real(c_double), intent(inout), optional, target :: pressure(*)
    integer(tfem_length_kind), intent(in) :: length
    integer(c_int) :: status
    type(c_ptr) :: node_address
    type(c_ptr) :: tributary_address
    type(c_ptr) :: gap_address
    type(c_ptr) :: pressure_address
    node_address = tfem_address_c_int(node, length > 0)
    tributary_address = tfem_address_c_double(tributary, length > 0)
    gap_address = tfem_address_c_double(gap, length > 0)
    pressure_address = tfem_address_c_double(pressure, length > 0)
    status = tfem_get_contact_slave_nodes_by_address(model, node_address, tributary_address, &
        gap_address, pressure_address, tfem_to_size_t(length))
  end function tfem_get_contact_slave_nodes_opt_i_r2211

  function tfem_get_contact_slave_nodes_opt_i_r1121(model, node, tributary, gap, &
        pressure, length) result(status)
    type(c_ptr), value :: model
    integer(c_int), intent(inout), optional, target :: node(*)
    real(c_double), intent(inout), optional, target :: tributary(*)
    real(c_double), intent(inout), target :: gap(1, *)
    real(c_double), intent(inout), optional, target :: pressure(*)
    integer(tfem_length_kind), intent(in) :: length
    integer(c_int) :: status
    type(c_ptr) :: node_address
    type(c_ptr) :: tributary_address
    type(c_ptr) :: gap_address
    type(c_ptr) :: pressure_address
    node_address = tfem_address_c_int(node, length > 0)
    tributary_address = tfem_address_c_double(tributary, length > 0)
    gap_address = tfem_address_c_double(gap, length > 0)
    pressure_address = tfem_address_c_double(pressure, length > 0)
    status = tfem_get_contact_slave_nodes_by_address(model, node_address, tributary_address, &
        gap_address, pressure_address, tfem_to_size_t(length))
  end function tfem_get_contact_slave_nodes_opt_i_r1121

  function tfem_get_contact_slave_nodes_opt_i_r2121(model, node, tributary, gap, &
        pressure, length) result(status)
    type(c_ptr), value :: model
    integer(c_int), intent(inout), target :: node(1, *)
    real(c_double), intent(inout), optional, target :: tributary(*)
    real(c_double), intent(inout), target :: gap(1, *)
    real(c_double), intent(inout), optional, target :: pressure(*)
    integer(tfem_length_kind), intent(in) :: length
    integer(c_int) :: status
    type(c_ptr) :: node_address
    type(c_ptr) :: tributary_address
    type(c_ptr) :: gap_address
    type(c_ptr) :: pressure_address
    node_address = tfem_address_c_int(node, length > 0)
    tributary_address = tfem_address_c_double(tributary, length > 0)
    gap_address = tfem_address_c_double(gap, length > 0)
    pressure_address = tfem_address_c_double(pressure, length > 0)
    status = tfem_get_contact_slave_nodes_by_address(model, node_address, tributary_address, &
        gap_address, pressure_address, tfem_to_size_t(length))
  end function tfem_get_contact_slave_nodes_opt_i_r2121

  function tfem_get_contact_slave_nodes_opt_i_r1221(model, node, tributary, gap, &
        pressure, length) result(status)
    type(c_ptr), value :: model
    integer(c_int), intent(inout), optional, target :: node(*)
    real(c_double), intent(inout), target :: tributary(1, *)
    real(c_double), intent(inout), target :: gap(1, *)
    real(c_double), intent(inout), optional, target :: pressure(*)
    integer(tfem_length_kind), intent(in) :: length
    integer(c_int) :: status
    type(c_ptr) :: node_address
    type(c_ptr) :: tributary_address
    type(c_ptr) :: gap_address
    type(c_ptr) :: pressure_address
    node_address = tfem_address_c_int(node, length > 0)
    tributary_address = tfem_address_c_double(tributary, length > 0)
    gap_address = tfem_address_c_double(gap, length > 0)
    pressure_address = tfem_address_c_double(pressure, length > 0)
    status = tfem_get_contact_slave_nodes_by_address(model, node_address, tributary_address, &
        gap_address, pressure_address, tfem_to_size_t(length))
  end function tfem_get_contact_slave_nodes_opt_i_r1221

  function tfem_get_contact_slave_nodes_opt_i_r2221(model, node, tributary, gap, &
        pressure, length) result(status)
    type(c_ptr), value :: model
    integer(c_int), intent(inout), target :: node(1, *)
    real(c_double), intent(inout), target :: tributary(1, *)
    real(c_double), intent(inout), target :: gap(1, *)
    real(c_double), intent(inout), optional, target :: pressure(*)
    integer(tfem_length_kind), intent(in) :: length
    integer(c_int) :: status
    type(c_ptr) :: node_address
    type(c_ptr) :: tributary_address
    type(c_ptr) :: gap_address
    type(c_ptr) :: pressure_address
    node_address = tfem_address_c_int(node, length > 0)
    tributary_address = tfem_address_c_double(tributary, length > 0)
    gap_address = tfem_address_c_double(gap, length > 0)
    pressure_address = tfem_address_c_double(pressure, length > 0)
    status = tfem_get_contact_slave_nodes_by_address(model, node_address, tributary_address, &
        gap_address, pressure_address, tfem_to_size_t(length))
  end function tfem_get_contact_slave_nodes_opt_i_r2221

  function tfem_get_contact_slave_nodes_opt_i_r1112(model, node, tributary, gap, &
        pressure, length) result(status)
    type(c_ptr), value :: model
    integer(c_int), intent(inout), optional, target :: node(*)
    real(c_double), intent(inout), optional, target :: tributary(*)
    real(c_double), intent(inout), optional, target :: gap(*)
    real(c_double), intent(inout), target :: pressure(1, *)
    integer(tfem_length_kind), intent(in) :: length
    integer(c_int) :: status
    type(c_ptr) :: node_address
    type(c_ptr) :: tributary_address
    type(c_ptr) :: gap_address
    type(c_ptr) :: pressure_address
    node_address = tfem_address_c_int(node, length > 0)
    tributary_address = tfem_address_c_double(tributary, length > 0)
    gap_address = tfem_address_c_double(gap, length > 0)
    pressure_address = tfem_address_c_double(pressure, length > 0)
    status = tfem_get_contact_slave_nodes_by_address(model, node_address, tributary_address, &
        gap_address, pressure_address, tfem_to_size_t(length))
  end function tfem_get_contact_slave_nodes_opt_i_r1112

  function tfem_get_contact_slave_nodes_opt_i_r2112(model, node, tributary, gap, &
        pressure, length) result(status)
    type(c_ptr), value :: model
    integer(c_int), intent(inout), target :: node(1, *)
    real(c_double), intent(inout), optional, target :: tributary(*)
    real(c_double), intent(inout), optional, target :: gap(*)
    real(c_double), intent(inout), target :: pressure(1, *)
    integer(tfem_length_kind), intent(in) :: length
    integer(c_int) :: status
    type(c_ptr) :: node_address
    type(c_ptr) :: tributary_address
    type(c_ptr) :: gap_address
    type(c_ptr) :: pressure_address
    node_address = tfem_address_c_int(node, length > 0)
    tributary_address = tfem_address_c_double(tributary, length > 0)
    gap_address = tfem_address_c_double(gap, length > 0)
    pressure_address = tfem_address_c_double(pressure, length > 0)
    status = tfem_get_contact_slave_nodes_by_address(model, node_address, tributary_address, &
        gap_address, pressure_address, tfem_to_size_t(length))
  end function tfem_get_contact_slave_nodes_opt_i_r2112

  function tfem_get_contact_slave_nodes_opt_i_r1212(model, node, tributary, gap, &
        pressure, length) result(status)
    type(c_ptr), value :: model
    integer(c_int), intent(inout), optional, target :: node(*)
    real(c_double), intent(inout), target :: tributary(1, *)
    real(c_double), intent(inout), optional, target :: gap(*)
    real(c_double), intent(inout), target :: pressure(1, *)
    integer(tfem_length_kind), intent(in) :: length
    integer(c_int) :: status
    type(c_ptr) :: node_address
    type(c_ptr) :: tributary_address
    type(c_ptr) :: gap_address
    type(c_ptr) :: pressure_address
    node_address = tfem_address_c_int(node, length > 0)
    tributary_address = tfem_address_c_double(tributary, length > 0)
    gap_address = tfem_address_c_double(gap, length > 0)
    pressure_address = tfem_address_c_double(pressure, length > 0)
    status = tfem_get_contact_slave_nodes_by_address(model, node_address, tributary_address, &
        gap_address, pressure_address, tfem_to_size_t(length))
  end function tfem_get_contact_slave_nodes_opt_i_r1212

  function tfem_get_contact_slave_nodes_opt_i_r2212(model, node, tributary, gap, &
        pressure, length) result(status)
    type(c_ptr), value :: model
    integer(c_int), intent(inout), target :: node(1, *)
    real(c_double), intent(inout), target :: tributary(1, *)
    real(c_double), intent(inout), optional, target :: gap(*)
    real(c_double), intent(inout), target :: pressure(1, *)
    integer(tfem_length_kind), intent(in) :: length
    integer(c_int) :: status
    type(c_ptr) :: node_address
    type(c_ptr) :: tributary_address
    type(c_ptr) :: gap_address
    type(c_ptr) :: pressure_address
    node_address = tfem_address_c_int(node, length > 0)
    tributary_address = tfem_address_c_double(tributary, length > 0)
    gap_address = tfem_address_c_double(gap, length > 0)
    pressure_address = tfem_address_c_double(pressure, length > 0)
    status = tfem_get_contact_slave_nodes_by_address(model, node_address, tributary_address, &
        gap_address, pressure_address, tfem_to_size_t(length))
  end function tfem_get_contact_slave_nodes_opt_i_r2212

  function tfem_get_contact_slave_nodes_opt_i_r1122(model, node, tributary, gap, &
        pressure, length) result(status)
    type(c_ptr), value :: model
    integer(c_int), intent(inout), optional, target :: node(*)
    real(c_double), intent(inout), optional, target :: tributary(*)
    real(c_double), intent(inout), target :: gap(1, *)
    real(c_double), intent(inout), target :: pressure(1, *)
    integer(tfem_length_kind), intent(in) :: length
    integer(c_int) :: status
    type(c_ptr) :: node_address
    type(c_ptr) :: tributary_address
    type(c_ptr) :: gap_address
    type(c_ptr) :: pressure_address
    node_address = tfem_address_c_int(node, length > 0)
    tributary_address = tfem_address_c_double(tributary, length > 0)
    gap_address = tfem_address_c_double(gap, length > 0)
    pressure_address = tfem_address_c_double(pressure, length > 0)
    status = tfem_get_contact_slave_nodes_by_address(model, node_address, tributary_address, &
        gap_address, pressure_address, tfem_to_size_t(length))
  end function tfem_get_contact_slave_nodes_opt_i_r1122

  function tfem_get_contact_slave_nodes_opt_i_r2122(model, node, tributary, gap, &
        pressure, length) result(status)
    type(c_ptr), value :: model
    integer(c_int), intent(inout), target :: node(1, *)
    real(c_double), intent(inout), optional, target :: tributary(*)
    real(c_double), intent(inout), target :: gap(1, *)
    real(c_double), intent(inout), target :: pressure(1, *)
    integer(tfem_length_kind), intent(in) :: length
    integer(c_int) :: status
    type(c_ptr) :: node_address
    type(c_ptr) :: tributary_address
    type(c_ptr) :: gap_address
    type(c_ptr) :: pressure_address
    node_address = tfem_address_c_int(node, length > 0)
    tributary_address = tfem_address_c_double(tributary, length > 0)
    gap_address = tfem_address_c_double(gap, length > 0)
    pressure_address = tfem_address_c_double(pressure, length > 0)
    status = tfem_get_contact_slave_nodes_by_address(model, node_address, tributary_address, &
        gap_address, pressure_address, tfem_to_size_t(length))
  end function tfem_get_contact_slave_nodes_opt_i_r2122

  function tfem_get_contact_slave_nodes_opt_i_r1222(model, node, tributary, gap, &
        pressure, length) result(status)
    type(c_ptr), value :: model
    integer(c_int), intent(inout), optional, target :: node(*)
    real(c_double), intent(inout), target :: tributary(1, *)
    real(c_double), intent(inout), target :: gap(1, *)
    real(c_double), intent(inout), target :: pressure(1, *)
    integer(tfem_length_kind), intent(in) :: length
    integer(c_int) :: status
    type(c_ptr) :: node_address
    type(c_ptr) :: tributary_address
    type(c_ptr) :: gap_address
    type(c_ptr) :: pressure_address
    node_address = tfem_address_c_int(node, length > 0)
    tributary_address = tfem_address_c_double(tributary, length > 0)
    gap_address = tfem_address_c_double(gap, length > 0)
    pressure_address = tfem_address_c_double(pressure, length > 0)
    status = tfem_get_contact_slave_nodes_by_address(model, node_address, tributary_address, &
        gap_address, pressure_address, tfem_to_size_t(length))
  end function tfem_get_contact_slave_nodes_opt_i_r1222

  function tfem_get_contact_slave_nodes_opt_i_r2222(model, node, tributary, gap, &
        pressure, length) result(status)
    type(c_ptr), value :: model
    integer(c_int), intent(inout), target :: node(1, *)
    real(c_double), intent(inout), target :: tributary(1, *)
    real(c_double), intent(inout), target :: gap(1, *)
    real(c_double), intent(inout), target :: pressure(1, *)
    integer(tfem_length_kind), intent(in) :: length
    integer(c_int) :: status
    type(c_ptr) :: node_address
    type(c_ptr) :: tributary_address
    type(c_ptr) :: gap_address
    type(c_ptr) :: pressure_address
    node_address = tfem_address_c_int(node, length > 0)
    tributary_address = tfem_address_c_double(tributary, length > 0)
    gap_address = tfem_address_c_double(gap, length > 0)
    pressure_address = tfem_address_c_double(pressure, length > 0)
    status = tfem_get_contact_slave_nodes_by_address(model, node_address, tributary_address, &
        gap_address, pressure_address, tfem_to_size_t(length))
  end function tfem_get_contact_slave_nodes_opt_i_r2222

  function tfem_step_opt(model, load_factor, options, report) result(status)
    type(c_ptr), value :: model
    real(c_double), value :: load_factor
    type(tfem_contact_options), intent(in), optional, target :: options
    type(tfem_contact_report), intent(inout), optional, target :: report
    integer(c_int) :: status
    type(c_ptr) :: options_address
    type(c_ptr) :: report_address
    options_address = c_null_ptr
    if (present(options)) options_address = c_loc(options)
    report_address = c_null_ptr
    if (present(report)) report_address = c_loc(report)
    status = tfem_step_by_address(model, load_factor, options_address, report_address)
  end function tfem_step_opt

  function tfem_get_contact_state_r2(model, buffer, length) result(status)
    type(c_ptr), value :: model
    integer(c_int8_t), intent(inout) :: buffer(1, *)
    integer(c_size_t), intent(in) :: length
    integer(c_int) :: status
    status = tfem_get_contact_state(model, buffer, length)
  end function tfem_get_contact_state_r2

  function tfem_get_contact_state_i(model, buffer, length) result(status)
    type(c_ptr), value :: model
    integer(c_int8_t), intent(inout) :: buffer(*)
    integer(tfem_length_kind), intent(in) :: length
    integer(c_int) :: status
    status = tfem_get_contact_state(model, buffer, tfem_to_size_t(length))
  end function tfem_get_contact_state_i

  function tfem_get_contact_state_i_r2(model, buffer, length) result(status)
    type(c_ptr), value :: model
    integer(c_int8_t), intent(inout) :: buffer(1, *)
    integer(tfem_length_kind), intent(in) :: length
    integer(c_int) :: status
    status = tfem_get_contact_state(model, buffer, tfem_to_size_t(length))
  end function tfem_get_contact_state_i_r2

  function tfem_set_contact_state_r2(model, buffer, length) result(status)
    type(c_ptr), value :: model
    integer(c_int8_t), intent(in) :: buffer(1, *)
    integer(c_size_t), intent(in) :: length
    integer(c_int) :: status
    status = tfem_set_contact_state(model, buffer, length)
  end function tfem_set_contact_state_r2

  function tfem_set_contact_state_i(model, buffer, length) result(status)
    type(c_ptr), value :: model
    integer(c_int8_t), intent(in) :: buffer(*)
    integer(tfem_length_kind), intent(in) :: length
    integer(c_int) :: status
    status = tfem_set_contact_state(model, buffer, tfem_to_size_t(length))
  end function tfem_set_contact_state_i

  function tfem_set_contact_state_i_r2(model, buffer, length) result(status)
    type(c_ptr), value :: model
    integer(c_int8_t), intent(in) :: buffer(1, *)
    integer(tfem_length_kind), intent(in) :: length
    integer(c_int) :: status
    status = tfem_set_contact_state(model, buffer, tfem_to_size_t(length))
  end function tfem_set_contact_state_i_r2

  function tfem_get_system_matrix_size_opt(model, n, nnz) result(status)
    type(c_ptr), value :: model
    integer(c_int64_t), intent(inout), optional, target :: n
    integer(c_int64_t), intent(inout), optional, target :: nnz
    integer(c_int) :: status
    type(c_ptr) :: n_address
    type(c_ptr) :: nnz_address
    n_address = c_null_ptr
    if (present(n)) n_address = c_loc(n)
    nnz_address = c_null_ptr
    if (present(nnz)) nnz_address = c_loc(nnz)
    status = tfem_get_system_matrix_size_by_address(model, n_address, nnz_address)
  end function tfem_get_system_matrix_size_opt

  function tfem_get_system_matrix_r2111(model, col_ptr, col_ptr_length, row_idx, &
        row_idx_length, values, values_length, dofs, dofs_length) result(status)
    type(c_ptr), value :: model
    integer(c_int64_t), intent(inout) :: col_ptr(1, *)
    integer(c_size_t), intent(in) :: col_ptr_length
    integer(c_int64_t), intent(inout) :: row_idx(*)
    integer(c_size_t), intent(in) :: row_idx_length
    real(c_double), intent(inout) :: values(*)
    integer(c_size_t), intent(in) :: values_length
    integer(c_int64_t), intent(inout) :: dofs(*)
    integer(c_size_t), intent(in) :: dofs_length
    integer(c_int) :: status
    status = tfem_get_system_matrix(model, col_ptr, col_ptr_length, row_idx, row_idx_length, values, &
        values_length, dofs, dofs_length)
  end function tfem_get_system_matrix_r2111

  function tfem_get_system_matrix_r1211(model, col_ptr, col_ptr_length, row_idx, &
        row_idx_length, values, values_length, dofs, dofs_length) result(status)
    type(c_ptr), value :: model
    integer(c_int64_t), intent(inout) :: col_ptr(*)
    integer(c_size_t), intent(in) :: col_ptr_length
    integer(c_int64_t), intent(inout) :: row_idx(1, *)
    integer(c_size_t), intent(in) :: row_idx_length
    real(c_double), intent(inout) :: values(*)
    integer(c_size_t), intent(in) :: values_length
    integer(c_int64_t), intent(inout) :: dofs(*)
    integer(c_size_t), intent(in) :: dofs_length
    integer(c_int) :: status
    status = tfem_get_system_matrix(model, col_ptr, col_ptr_length, row_idx, row_idx_length, values, &
        values_length, dofs, dofs_length)
  end function tfem_get_system_matrix_r1211

  function tfem_get_system_matrix_r2211(model, col_ptr, col_ptr_length, row_idx, &
        row_idx_length, values, values_length, dofs, dofs_length) result(status)
    type(c_ptr), value :: model
    integer(c_int64_t), intent(inout) :: col_ptr(1, *)
    integer(c_size_t), intent(in) :: col_ptr_length
    integer(c_int64_t), intent(inout) :: row_idx(1, *)
    integer(c_size_t), intent(in) :: row_idx_length
    real(c_double), intent(inout) :: values(*)
    integer(c_size_t), intent(in) :: values_length
    integer(c_int64_t), intent(inout) :: dofs(*)
    integer(c_size_t), intent(in) :: dofs_length
    integer(c_int) :: status
    status = tfem_get_system_matrix(model, col_ptr, col_ptr_length, row_idx, row_idx_length, values, &
        values_length, dofs, dofs_length)
  end function tfem_get_system_matrix_r2211

  function tfem_get_system_matrix_r1121(model, col_ptr, col_ptr_length, row_idx, &
        row_idx_length, values, values_length, dofs, dofs_length) result(status)
    type(c_ptr), value :: model
    integer(c_int64_t), intent(inout) :: col_ptr(*)
    integer(c_size_t), intent(in) :: col_ptr_length
    integer(c_int64_t), intent(inout) :: row_idx(*)
    integer(c_size_t), intent(in) :: row_idx_length
    real(c_double), intent(inout) :: values(1, *)
    integer(c_size_t), intent(in) :: values_length
    integer(c_int64_t), intent(inout) :: dofs(*)
    integer(c_size_t), intent(in) :: dofs_length
    integer(c_int) :: status
    status = tfem_get_system_matrix(model, col_ptr, col_ptr_length, row_idx, row_idx_length, values, &
        values_length, dofs, dofs_length)
  end function tfem_get_system_matrix_r1121

  function tfem_get_system_matrix_r2121(model, col_ptr, col_ptr_length, row_idx, &
        row_idx_length, values, values_length, dofs, dofs_length) result(status)
    type(c_ptr), value :: model
    integer(c_int64_t), intent(inout) :: col_ptr(1, *)
    integer(c_size_t), intent(in) :: col_ptr_length
    integer(c_int64_t), intent(inout) :: row_idx(*)
    integer(c_size_t), intent(in) :: row_idx_length
    real(c_double), intent(inout) :: values(1, *)
    integer(c_size_t), intent(in) :: values_length
    integer(c_int64_t), intent(inout) :: dofs(*)
    integer(c_size_t), intent(in) :: dofs_length
    integer(c_int) :: status
    status = tfem_get_system_matrix(model, col_ptr, col_ptr_length, row_idx, row_idx_length, values, &
        values_length, dofs, dofs_length)
  end function tfem_get_system_matrix_r2121

  function tfem_get_system_matrix_r1221(model, col_ptr, col_ptr_length, row_idx, &
        row_idx_length, values, values_length, dofs, dofs_length) result(status)
    type(c_ptr), value :: model
    integer(c_int64_t), intent(inout) :: col_ptr(*)
    integer(c_size_t), intent(in) :: col_ptr_length
    integer(c_int64_t), intent(inout) :: row_idx(1, *)
    integer(c_size_t), intent(in) :: row_idx_length
    real(c_double), intent(inout) :: values(1, *)
    integer(c_size_t), intent(in) :: values_length
    integer(c_int64_t), intent(inout) :: dofs(*)
    integer(c_size_t), intent(in) :: dofs_length
    integer(c_int) :: status
    status = tfem_get_system_matrix(model, col_ptr, col_ptr_length, row_idx, row_idx_length, values, &
        values_length, dofs, dofs_length)
  end function tfem_get_system_matrix_r1221

  function tfem_get_system_matrix_r2221(model, col_ptr, col_ptr_length, row_idx, &
        row_idx_length, values, values_length, dofs, dofs_length) result(status)
    type(c_ptr), value :: model
    integer(c_int64_t), intent(inout) :: col_ptr(1, *)
    integer(c_size_t), intent(in) :: col_ptr_length
    integer(c_int64_t), intent(inout) :: row_idx(1, *)
    integer(c_size_t), intent(in) :: row_idx_length
    real(c_double), intent(inout) :: values(1, *)
    integer(c_size_t), intent(in) :: values_length
    integer(c_int64_t), intent(inout) :: dofs(*)
    integer(c_size_t), intent(in) :: dofs_length
    integer(c_int) :: status
    status = tfem_get_system_matrix(model, col_ptr, col_ptr_length, row_idx, row_idx_length, values, &
        values_length, dofs, dofs_length)
  end function tfem_get_system_matrix_r2221

  function tfem_get_system_matrix_r1112(model, col_ptr, col_ptr_length, row_idx, &
        row_idx_length, values, values_length, dofs, dofs_length) result(status)
    type(c_ptr), value :: model
    integer(c_int64_t), intent(inout) :: col_ptr(*)
    integer(c_size_t), intent(in) :: col_ptr_length
    integer(c_int64_t), intent(inout) :: row_idx(*)
    integer(c_size_t), intent(in) :: row_idx_length
    real(c_double), intent(inout) :: values(*)
    integer(c_size_t), intent(in) :: values_length
    integer(c_int64_t), intent(inout) :: dofs(1, *)
    integer(c_size_t), intent(in) :: dofs_length
    integer(c_int) :: status
    status = tfem_get_system_matrix(model, col_ptr, col_ptr_length, row_idx, row_idx_length, values, &
        values_length, dofs, dofs_length)
  end function tfem_get_system_matrix_r1112

  function tfem_get_system_matrix_r2112(model, col_ptr, col_ptr_length, row_idx, &
        row_idx_length, values, values_length, dofs, dofs_length) result(status)
    type(c_ptr), value :: model
    integer(c_int64_t), intent(inout) :: col_ptr(1, *)
    integer(c_size_t), intent(in) :: col_ptr_length
    integer(c_int64_t), intent(inout) :: row_idx(*)
    integer(c_size_t), intent(in) :: row_idx_length
    real(c_double), intent(inout) :: values(*)
    integer(c_size_t), intent(in) :: values_length
    integer(c_int64_t), intent(inout) :: dofs(1, *)
    integer(c_size_t), intent(in) :: dofs_length
    integer(c_int) :: status
    status = tfem_get_system_matrix(model, col_ptr, col_ptr_length, row_idx, row_idx_length, values, &
        values_length, dofs, dofs_length)
  end function tfem_get_system_matrix_r2112

  function tfem_get_system_matrix_r1212(model, col_ptr, col_ptr_length, row_idx, &
        row_idx_length, values, values_length, dofs, dofs_length) result(status)
    type(c_ptr), value :: model
    integer(c_int64_t), intent(inout) :: col_ptr(*)
    integer(c_size_t), intent(in) :: col_ptr_length
    integer(c_int64_t), intent(inout) :: row_idx(1, *)
    integer(c_size_t), intent(in) :: row_idx_length
    real(c_double), intent(inout) :: values(*)
    integer(c_size_t), intent(in) :: values_length
    integer(c_int64_t), intent(inout) :: dofs(1, *)
    integer(c_size_t), intent(in) :: dofs_length
    integer(c_int) :: status
    status = tfem_get_system_matrix(model, col_ptr, col_ptr_length, row_idx, row_idx_length, values, &
        values_length, dofs, dofs_length)
  end function tfem_get_system_matrix_r1212

  function tfem_get_system_matrix_r2212(model, col_ptr, col_ptr_length, row_idx, &
        row_idx_length, values, values_length, dofs, dofs_length) result(status)
    type(c_ptr), value :: model
    integer(c_int64_t), intent(inout) :: col_ptr(1, *)
    integer(c_size_t), intent(in) :: col_ptr_length
    integer(c_int64_t), intent(inout) :: row_idx(1, *)
    integer(c_size_t), intent(in) :: row_idx_length
    real(c_double), intent(inout) :: values(*)
    integer(c_size_t), intent(in) :: values_length
    integer(c_int64_t), intent(inout) :: dofs(1, *)
    integer(c_size_t), intent(in) :: dofs_length
    integer(c_int) :: status
    status = tfem_get_system_matrix(model, col_ptr, col_ptr_length, row_idx, row_idx_length, values, &
        values_length, dofs, dofs_length)
  end function tfem_get_system_matrix_r2212

  function tfem_get_system_matrix_r1122(model, col_ptr, col_ptr_length, row_idx, &
        row_idx_length, values, values_length, dofs, dofs_length) result(status)
    type(c_ptr), value :: model
    integer(c_int64_t), intent(inout) :: col_ptr(*)
    integer(c_size_t), intent(in) :: col_ptr_length
    integer(c_int64_t), intent(inout) :: row_idx(*)
    integer(c_size_t), intent(in) :: row_idx_length
    real(c_double), intent(inout) :: values(1, *)
    integer(c_size_t), intent(in) :: values_length
    integer(c_int64_t), intent(inout) :: dofs(1, *)
    integer(c_size_t), intent(in) :: dofs_length
    integer(c_int) :: status
    status = tfem_get_system_matrix(model, col_ptr, col_ptr_length, row_idx, row_idx_length, values, &
        values_length, dofs, dofs_length)
  end function tfem_get_system_matrix_r1122

  function tfem_get_system_matrix_r2122(model, col_ptr, col_ptr_length, row_idx, &
        row_idx_length, values, values_length, dofs, dofs_length) result(status)
    type(c_ptr), value :: model
    integer(c_int64_t), intent(inout) :: col_ptr(1, *)
    integer(c_size_t), intent(in) :: col_ptr_length
    integer(c_int64_t), intent(inout) :: row_idx(*)
    integer(c_size_t), intent(in) :: row_idx_length
    real(c_double), intent(inout) :: values(1, *)
    integer(c_size_t), intent(in) :: values_length
    integer(c_int64_t), intent(inout) :: dofs(1, *)
    integer(c_size_t), intent(in) :: dofs_length
    integer(c_int) :: status
    status = tfem_get_system_matrix(model, col_ptr, col_ptr_length, row_idx, row_idx_length, values, &
        values_length, dofs, dofs_length)
  end function tfem_get_system_matrix_r2122

  function tfem_get_system_matrix_r1222(model, col_ptr, col_ptr_length, row_idx, &
        row_idx_length, values, values_length, dofs, dofs_length) result(status)
    type(c_ptr), value :: model
    integer(c_int64_t), intent(inout) :: col_ptr(*)
    integer(c_size_t), intent(in) :: col_ptr_length
    integer(c_int64_t), intent(inout) :: row_idx(1, *)
    integer(c_size_t), intent(in) :: row_idx_length
    real(c_double), intent(inout) :: values(1, *)
    integer(c_size_t), intent(in) :: values_length
    integer(c_int64_t), intent(inout) :: dofs(1, *)
    integer(c_size_t), intent(in) :: dofs_length
    integer(c_int) :: status
    status = tfem_get_system_matrix(model, col_ptr, col_ptr_length, row_idx, row_idx_length, values, &
        values_length, dofs, dofs_length)
  end function tfem_get_system_matrix_r1222

  function tfem_get_system_matrix_r2222(model, col_ptr, col_ptr_length, row_idx, &
        row_idx_length, values, values_length, dofs, dofs_length) result(status)
    type(c_ptr), value :: model
    integer(c_int64_t), intent(inout) :: col_ptr(1, *)
    integer(c_size_t), intent(in) :: col_ptr_length
    integer(c_int64_t), intent(inout) :: row_idx(1, *)
    integer(c_size_t), intent(in) :: row_idx_length
    real(c_double), intent(inout) :: values(1, *)
    integer(c_size_t), intent(in) :: values_length
    integer(c_int64_t), intent(inout) :: dofs(1, *)
    integer(c_size_t), intent(in) :: dofs_length
    integer(c_int) :: status
    status = tfem_get_system_matrix(model, col_ptr, col_ptr_length, row_idx, row_idx_length, values, &
        values_length, dofs, dofs_length)
  end function tfem_get_system_matrix_r2222

  function tfem_get_system_matrix_i(model, col_ptr, col_ptr_length, row_idx, &
        row_idx_length, values, values_length, dofs, dofs_length) result(status)
    type(c_ptr), value :: model
    integer(c_int64_t), intent(inout) :: col_ptr(*)
    integer(tfem_length_kind), intent(in) :: col_ptr_length
    integer(c_int64_t), intent(inout) :: row_idx(*)
    integer(tfem_length_kind), intent(in) :: row_idx_length
    real(c_double), intent(inout) :: values(*)
    integer(tfem_length_kind), intent(in) :: values_length
    integer(c_int64_t), intent(inout) :: dofs(*)
    integer(tfem_length_kind), intent(in) :: dofs_length
    integer(c_int) :: status
    status = tfem_get_system_matrix(model, col_ptr, tfem_to_size_t(col_ptr_length), row_idx, &
        tfem_to_size_t(row_idx_length), values, tfem_to_size_t(values_length), dofs, &
        tfem_to_size_t(dofs_length))
  end function tfem_get_system_matrix_i

  function tfem_get_system_matrix_i_r2111(model, col_ptr, col_ptr_length, row_idx, &
        row_idx_length, values, values_length, dofs, dofs_length) result(status)
    type(c_ptr), value :: model
    integer(c_int64_t), intent(inout) :: col_ptr(1, *)
    integer(tfem_length_kind), intent(in) :: col_ptr_length
    integer(c_int64_t), intent(inout) :: row_idx(*)
    integer(tfem_length_kind), intent(in) :: row_idx_length
    real(c_double), intent(inout) :: values(*)
    integer(tfem_length_kind), intent(in) :: values_length
    integer(c_int64_t), intent(inout) :: dofs(*)
    integer(tfem_length_kind), intent(in) :: dofs_length
    integer(c_int) :: status
    status = tfem_get_system_matrix(model, col_ptr, tfem_to_size_t(col_ptr_length), row_idx, &
        tfem_to_size_t(row_idx_length), values, tfem_to_size_t(values_length), dofs, &
        tfem_to_size_t(dofs_length))
  end function tfem_get_system_matrix_i_r2111

  function tfem_get_system_matrix_i_r1211(model, col_ptr, col_ptr_length, row_idx, &
        row_idx_length, values, values_length, dofs, dofs_length) result(status)
    type(c_ptr), value :: model
    integer(c_int64_t), intent(inout) :: col_ptr(*)
    integer(tfem_length_kind), intent(in) :: col_ptr_length
    integer(c_int64_t), intent(inout) :: row_idx(1, *)
    integer(tfem_length_kind), intent(in) :: row_idx_length
    real(c_double), intent(inout) :: values(*)
    integer(tfem_length_kind), intent(in) :: values_length
    integer(c_int64_t), intent(inout) :: dofs(*)
    integer(tfem_length_kind), intent(in) :: dofs_length
    integer(c_int) :: status
    status = tfem_get_system_matrix(model, col_ptr, tfem_to_size_t(col_ptr_length), row_idx, &
        tfem_to_size_t(row_idx_length), values, tfem_to_size_t(values_length), dofs, &
        tfem_to_size_t(dofs_length))
  end function tfem_get_system_matrix_i_r1211

  function tfem_get_system_matrix_i_r2211(model, col_ptr, col_ptr_length, row_idx, &
        row_idx_length, values, values_length, dofs, dofs_length) result(status)
    type(c_ptr), value :: model
    integer(c_int64_t), intent(inout) :: col_ptr(1, *)
    integer(tfem_length_kind), intent(in) :: col_ptr_length
    integer(c_int64_t), intent(inout) :: row_idx(1, *)
    integer(tfem_length_kind), intent(in) :: row_idx_length
    real(c_double), intent(inout) :: values(*)
    integer(tfem_length_kind), intent(in) :: values_length
    integer(c_int64_t), intent(inout) :: dofs(*)
    integer(tfem_length_kind), intent(in) :: dofs_length
    integer(c_int) :: status
    status = tfem_get_system_matrix(model, col_ptr, tfem_to_size_t(col_ptr_length), row_idx, &
        tfem_to_size_t(row_idx_length), values, tfem_to_size_t(values_length), dofs, &
        tfem_to_size_t(dofs_length))
  end function tfem_get_system_matrix_i_r2211

  function tfem_get_system_matrix_i_r1121(model, col_ptr, col_ptr_length, row_idx, &
        row_idx_length, values, values_length, dofs, dofs_length) result(status)
    type(c_ptr), value :: model
    integer(c_int64_t), intent(inout) :: col_ptr(*)
    integer(tfem_length_kind), intent(in) :: col_ptr_length
    integer(c_int64_t), intent(inout) :: row_idx(*)
    integer(tfem_length_kind), intent(in) :: row_idx_length
    real(c_double), intent(inout) :: values(1, *)
    integer(tfem_length_kind), intent(in) :: values_length
    integer(c_int64_t), intent(inout) :: dofs(*)
    integer(tfem_length_kind), intent(in) :: dofs_length
    integer(c_int) :: status
    status = tfem_get_system_matrix(model, col_ptr, tfem_to_size_t(col_ptr_length), row_idx, &
        tfem_to_size_t(row_idx_length), values, tfem_to_size_t(values_length), dofs, &
        tfem_to_size_t(dofs_length))
  end function tfem_get_system_matrix_i_r1121

  function tfem_get_system_matrix_i_r2121(model, col_ptr, col_ptr_length, row_idx, &
        row_idx_length, values, values_length, dofs, dofs_length) result(status)
    type(c_ptr), value :: model
    integer(c_int64_t), intent(inout) :: col_ptr(1, *)
    integer(tfem_length_kind), intent(in) :: col_ptr_length
    integer(c_int64_t), intent(inout) :: row_idx(*)
    integer(tfem_length_kind), intent(in) :: row_idx_length
    real(c_double), intent(inout) :: values(1, *)
    integer(tfem_length_kind), intent(in) :: values_length
    integer(c_int64_t), intent(inout) :: dofs(*)
    integer(tfem_length_kind), intent(in) :: dofs_length
    integer(c_int) :: status
    status = tfem_get_system_matrix(model, col_ptr, tfem_to_size_t(col_ptr_length), row_idx, &
        tfem_to_size_t(row_idx_length), values, tfem_to_size_t(values_length), dofs, &
        tfem_to_size_t(dofs_length))
  end function tfem_get_system_matrix_i_r2121

  function tfem_get_system_matrix_i_r1221(model, col_ptr, col_ptr_length, row_idx, &
        row_idx_length, values, values_length, dofs, dofs_length) result(status)
    type(c_ptr), value :: model
    integer(c_int64_t), intent(inout) :: col_ptr(*)
    integer(tfem_length_kind), intent(in) :: col_ptr_length
    integer(c_int64_t), intent(inout) :: row_idx(1, *)
    integer(tfem_length_kind), intent(in) :: row_idx_length
    real(c_double), intent(inout) :: values(1, *)
    integer(tfem_length_kind), intent(in) :: values_length
    integer(c_int64_t), intent(inout) :: dofs(*)
    integer(tfem_length_kind), intent(in) :: dofs_length
    integer(c_int) :: status
    status = tfem_get_system_matrix(model, col_ptr, tfem_to_size_t(col_ptr_length), row_idx, &
        tfem_to_size_t(row_idx_length), values, tfem_to_size_t(values_length), dofs, &
        tfem_to_size_t(dofs_length))
  end function tfem_get_system_matrix_i_r1221

  function tfem_get_system_matrix_i_r2221(model, col_ptr, col_ptr_length, row_idx, &
        row_idx_length, values, values_length, dofs, dofs_length) result(status)
    type(c_ptr), value :: model
    integer(c_int64_t), intent(inout) :: col_ptr(1, *)
    integer(tfem_length_kind), intent(in) :: col_ptr_length
    integer(c_int64_t), intent(inout) :: row_idx(1, *)
    integer(tfem_length_kind), intent(in) :: row_idx_length
    real(c_double), intent(inout) :: values(1, *)
    integer(tfem_length_kind), intent(in) :: values_length
    integer(c_int64_t), intent(inout) :: dofs(*)
    integer(tfem_length_kind), intent(in) :: dofs_length
    integer(c_int) :: status
    status = tfem_get_system_matrix(model, col_ptr, tfem_to_size_t(col_ptr_length), row_idx, &
        tfem_to_size_t(row_idx_length), values, tfem_to_size_t(values_length), dofs, &
        tfem_to_size_t(dofs_length))
  end function tfem_get_system_matrix_i_r2221

  function tfem_get_system_matrix_i_r1112(model, col_ptr, col_ptr_length, row_idx, &
        row_idx_length, values, values_length, dofs, dofs_length) result(status)
    type(c_ptr), value :: model
    integer(c_int64_t), intent(inout) :: col_ptr(*)
    integer(tfem_length_kind), intent(in) :: col_ptr_length
    integer(c_int64_t), intent(inout) :: row_idx(*)
    integer(tfem_length_kind), intent(in) :: row_idx_length
    real(c_double), intent(inout) :: values(*)
    integer(tfem_length_kind), intent(in) :: values_length
    integer(c_int64_t), intent(inout) :: dofs(1, *)
    integer(tfem_length_kind), intent(in) :: dofs_length
    integer(c_int) :: status
    status = tfem_get_system_matrix(model, col_ptr, tfem_to_size_t(col_ptr_length), row_idx, &
        tfem_to_size_t(row_idx_length), values, tfem_to_size_t(values_length), dofs, &
        tfem_to_size_t(dofs_length))
  end function tfem_get_system_matrix_i_r1112

  function tfem_get_system_matrix_i_r2112(model, col_ptr, col_ptr_length, row_idx, &
        row_idx_length, values, values_length, dofs, dofs_length) result(status)
    type(c_ptr), value :: model
    integer(c_int64_t), intent(inout) :: col_ptr(1, *)
    integer(tfem_length_kind), intent(in) :: col_ptr_length
    integer(c_int64_t), intent(inout) :: row_idx(*)
    integer(tfem_length_kind), intent(in) :: row_idx_length
    real(c_double), intent(inout) :: values(*)
    integer(tfem_length_kind), intent(in) :: values_length
    integer(c_int64_t), intent(inout) :: dofs(1, *)
    integer(tfem_length_kind), intent(in) :: dofs_length
    integer(c_int) :: status
    status = tfem_get_system_matrix(model, col_ptr, tfem_to_size_t(col_ptr_length), row_idx, &
        tfem_to_size_t(row_idx_length), values, tfem_to_size_t(values_length), dofs, &
        tfem_to_size_t(dofs_length))
  end function tfem_get_system_matrix_i_r2112

  function tfem_get_system_matrix_i_r1212(model, col_ptr, col_ptr_length, row_idx, &
        row_idx_length, values, values_length, dofs, dofs_length) result(status)
    type(c_ptr), value :: model
    integer(c_int64_t), intent(inout) :: col_ptr(*)
    integer(tfem_length_kind), intent(in) :: col_ptr_length
    integer(c_int64_t), intent(inout) :: row_idx(1, *)
    integer(tfem_length_kind), intent(in) :: row_idx_length
    real(c_double), intent(inout) :: values(*)
    integer(tfem_length_kind), intent(in) :: values_length
    integer(c_int64_t), intent(inout) :: dofs(1, *)
    integer(tfem_length_kind), intent(in) :: dofs_length
    integer(c_int) :: status
    status = tfem_get_system_matrix(model, col_ptr, tfem_to_size_t(col_ptr_length), row_idx, &
        tfem_to_size_t(row_idx_length), values, tfem_to_size_t(values_length), dofs, &
        tfem_to_size_t(dofs_length))
  end function tfem_get_system_matrix_i_r1212

  function tfem_get_system_matrix_i_r2212(model, col_ptr, col_ptr_length, row_idx, &
        row_idx_length, values, values_length, dofs, dofs_length) result(status)
    type(c_ptr), value :: model
    integer(c_int64_t), intent(inout) :: col_ptr(1, *)
    integer(tfem_length_kind), intent(in) :: col_ptr_length
    integer(c_int64_t), intent(inout) :: row_idx(1, *)
    integer(tfem_length_kind), intent(in) :: row_idx_length
    real(c_double), intent(inout) :: values(*)
    integer(tfem_length_kind), intent(in) :: values_length
    integer(c_int64_t), intent(inout) :: dofs(1, *)
    integer(tfem_length_kind), intent(in) :: dofs_length
    integer(c_int) :: status
    status = tfem_get_system_matrix(model, col_ptr, tfem_to_size_t(col_ptr_length), row_idx, &
        tfem_to_size_t(row_idx_length), values, tfem_to_size_t(values_length), dofs, &
        tfem_to_size_t(dofs_length))
  end function tfem_get_system_matrix_i_r2212

  function tfem_get_system_matrix_i_r1122(model, col_ptr, col_ptr_length, row_idx, &
        row_idx_length, values, values_length, dofs, dofs_length) result(status)
    type(c_ptr), value :: model
    integer(c_int64_t), intent(inout) :: col_ptr(*)
    integer(tfem_length_kind), intent(in) :: col_ptr_length
    integer(c_int64_t), intent(inout) :: row_idx(*)
    integer(tfem_length_kind), intent(in) :: row_idx_length
    real(c_double), intent(inout) :: values(1, *)
    integer(tfem_length_kind), intent(in) :: values_length
    integer(c_int64_t), intent(inout) :: dofs(1, *)
    integer(tfem_length_kind), intent(in) :: dofs_length
    integer(c_int) :: status
    status = tfem_get_system_matrix(model, col_ptr, tfem_to_size_t(col_ptr_length), row_idx, &
        tfem_to_size_t(row_idx_length), values, tfem_to_size_t(values_length), dofs, &
        tfem_to_size_t(dofs_length))
  end function tfem_get_system_matrix_i_r1122

  function tfem_get_system_matrix_i_r2122(model, col_ptr, col_ptr_length, row_idx, &
        row_idx_length, values, values_length, dofs, dofs_length) result(status)
    type(c_ptr), value :: model
    integer(c_int64_t), intent(inout) :: col_ptr(1, *)
    integer(tfem_length_kind), intent(in) :: col_ptr_length
    integer(c_int64_t), intent(inout) :: row_idx(*)
    integer(tfem_length_kind), intent(in) :: row_idx_length
    real(c_double), intent(inout) :: values(1, *)
    integer(tfem_length_kind), intent(in) :: values_length
    integer(c_int64_t), intent(inout) :: dofs(1, *)
    integer(tfem_length_kind), intent(in) :: dofs_length
    integer(c_int) :: status
    status = tfem_get_system_matrix(model, col_ptr, tfem_to_size_t(col_ptr_length), row_idx, &
        tfem_to_size_t(row_idx_length), values, tfem_to_size_t(values_length), dofs, &
        tfem_to_size_t(dofs_length))
  end function tfem_get_system_matrix_i_r2122

  function tfem_get_system_matrix_i_r1222(model, col_ptr, col_ptr_length, row_idx, &
        row_idx_length, values, values_length, dofs, dofs_length) result(status)
    type(c_ptr), value :: model
    integer(c_int64_t), intent(inout) :: col_ptr(*)
    integer(tfem_length_kind), intent(in) :: col_ptr_length
    integer(c_int64_t), intent(inout) :: row_idx(1, *)
    integer(tfem_length_kind), intent(in) :: row_idx_length
    real(c_double), intent(inout) :: values(1, *)
    integer(tfem_length_kind), intent(in) :: values_length
    integer(c_int64_t), intent(inout) :: dofs(1, *)
    integer(tfem_length_kind), intent(in) :: dofs_length
    integer(c_int) :: status
    status = tfem_get_system_matrix(model, col_ptr, tfem_to_size_t(col_ptr_length), row_idx, &
        tfem_to_size_t(row_idx_length), values, tfem_to_size_t(values_length), dofs, &
        tfem_to_size_t(dofs_length))
  end function tfem_get_system_matrix_i_r1222

  function tfem_get_system_matrix_i_r2222(model, col_ptr, col_ptr_length, row_idx, &
        row_idx_length, values, values_length, dofs, dofs_length) result(status)
    type(c_ptr), value :: model
    integer(c_int64_t), intent(inout) :: col_ptr(1, *)
    integer(tfem_length_kind), intent(in) :: col_ptr_length
    integer(c_int64_t), intent(inout) :: row_idx(1, *)
    integer(tfem_length_kind), intent(in) :: row_idx_length
    real(c_double), intent(inout) :: values(1, *)
    integer(tfem_length_kind), intent(in) :: values_length
    integer(c_int64_t), intent(inout) :: dofs(1, *)
    integer(tfem_length_kind), intent(in) :: dofs_length
    integer(c_int) :: status
    status = tfem_get_system_matrix(model, col_ptr, tfem_to_size_t(col_ptr_length), row_idx, &
        tfem_to_size_t(row_idx_length), values, tfem_to_size_t(values_length), dofs, &
        tfem_to_size_t(dofs_length))
  end function tfem_get_system_matrix_i_r2222

  function tfem_contact_last_error_i(context, buffer, length) result(status)
    type(c_ptr), value :: context
    character(kind=c_char), intent(inout) :: buffer(*)
    integer(tfem_length_kind), intent(in) :: length
    integer(c_int) :: status
    status = tfem_contact_last_error(context, buffer, tfem_to_size_t(length))
  end function tfem_contact_last_error_i

  function tfem_contact_last_error_str(context, buffer, length) result(status)
    type(c_ptr), value :: context
    character(kind=c_char, len=*), intent(inout) :: buffer
    integer(c_size_t), intent(in) :: length
    integer(c_int) :: status
    status = tfem_contact_last_error(context, buffer, length)
  end function tfem_contact_last_error_str

  function tfem_contact_last_error_str_i(context, buffer, length) result(status)
    type(c_ptr), value :: context
    character(kind=c_char, len=*), intent(inout) :: buffer
    integer(tfem_length_kind), intent(in) :: length
    integer(c_int) :: status
    status = tfem_contact_last_error(context, buffer, tfem_to_size_t(length))
  end function tfem_contact_last_error_str_i

  function tfem_contact_last_error_length_no_context() result(res)
    integer(c_size_t) :: res
    res = tfem_contact_last_error_length(c_null_ptr)
  end function tfem_contact_last_error_length_no_context

  function tfem_contact_add_side_opt(context, tag, body, young, poisson, plane_mode, &
        n_nodes, nodes, xy, equations, n_edges, edges, side) result(status)
    type(c_ptr), value :: context
    integer(c_int), value :: tag
    integer(c_int), value :: body
    real(c_double), value :: young
    real(c_double), value :: poisson
    integer(c_int), value :: plane_mode
    integer(c_int), value :: n_nodes
    integer(c_int), intent(in) :: nodes(*)
    real(c_double), intent(in) :: xy(*)
    integer(c_int64_t), intent(in) :: equations(*)
    integer(c_int), value :: n_edges
    integer(c_int), intent(in) :: edges(*)
    integer(c_int), intent(inout), optional, target :: side
    integer(c_int) :: status
    type(c_ptr) :: side_address
    side_address = c_null_ptr
    if (present(side)) side_address = c_loc(side)
    status = tfem_contact_add_side_by_address(context, tag, body, young, poisson, plane_mode, n_nodes, &
        nodes, xy, equations, n_edges, edges, side_address)
  end function tfem_contact_add_side_opt

  function tfem_contact_add_side_opt_r2111(context, tag, body, young, poisson, &
        plane_mode, n_nodes, nodes, xy, equations, n_edges, edges, side) result(status)
    type(c_ptr), value :: context
    integer(c_int), value :: tag
    integer(c_int), value :: body
    real(c_double), value :: young
    real(c_double), value :: poisson
    integer(c_int), value :: plane_mode
    integer(c_int), value :: n_nodes
    integer(c_int), intent(in) :: nodes(1, *)
    real(c_double), intent(in) :: xy(*)
    integer(c_int64_t), intent(in) :: equations(*)
    integer(c_int), value :: n_edges
    integer(c_int), intent(in) :: edges(*)
    integer(c_int), intent(inout), optional, target :: side
    integer(c_int) :: status
    type(c_ptr) :: side_address
    side_address = c_null_ptr
    if (present(side)) side_address = c_loc(side)
    status = tfem_contact_add_side_by_address(context, tag, body, young, poisson, plane_mode, n_nodes, &
        nodes, xy, equations, n_edges, edges, side_address)
  end function tfem_contact_add_side_opt_r2111

  function tfem_contact_add_side_opt_r1211(context, tag, body, young, poisson, &
        plane_mode, n_nodes, nodes, xy, equations, n_edges, edges, side) result(status)
    type(c_ptr), value :: context
    integer(c_int), value :: tag
    integer(c_int), value :: body
    real(c_double), value :: young
    real(c_double), value :: poisson
    integer(c_int), value :: plane_mode
    integer(c_int), value :: n_nodes
    integer(c_int), intent(in) :: nodes(*)
    real(c_double), intent(in) :: xy(1, *)
    integer(c_int64_t), intent(in) :: equations(*)
    integer(c_int), value :: n_edges
    integer(c_int), intent(in) :: edges(*)
    integer(c_int), intent(inout), optional, target :: side
    integer(c_int) :: status
    type(c_ptr) :: side_address
    side_address = c_null_ptr
    if (present(side)) side_address = c_loc(side)
    status = tfem_contact_add_side_by_address(context, tag, body, young, poisson, plane_mode, n_nodes, &
        nodes, xy, equations, n_edges, edges, side_address)
  end function tfem_contact_add_side_opt_r1211

  function tfem_contact_add_side_opt_r2211(context, tag, body, young, poisson, &
        plane_mode, n_nodes, nodes, xy, equations, n_edges, edges, side) result(status)
    type(c_ptr), value :: context
    integer(c_int), value :: tag
    integer(c_int), value :: body
    real(c_double), value :: young
    real(c_double), value :: poisson
    integer(c_int), value :: plane_mode
    integer(c_int), value :: n_nodes
    integer(c_int), intent(in) :: nodes(1, *)
    real(c_double), intent(in) :: xy(1, *)
    integer(c_int64_t), intent(in) :: equations(*)
    integer(c_int), value :: n_edges
    integer(c_int), intent(in) :: edges(*)
    integer(c_int), intent(inout), optional, target :: side
    integer(c_int) :: status
    type(c_ptr) :: side_address
    side_address = c_null_ptr
    if (present(side)) side_address = c_loc(side)
    status = tfem_contact_add_side_by_address(context, tag, body, young, poisson, plane_mode, n_nodes, &
        nodes, xy, equations, n_edges, edges, side_address)
  end function tfem_contact_add_side_opt_r2211

  function tfem_contact_add_side_opt_r1121(context, tag, body, young, poisson, &
        plane_mode, n_nodes, nodes, xy, equations, n_edges, edges, side) result(status)
    type(c_ptr), value :: context
    integer(c_int), value :: tag
    integer(c_int), value :: body
    real(c_double), value :: young
    real(c_double), value :: poisson
    integer(c_int), value :: plane_mode
    integer(c_int), value :: n_nodes
    integer(c_int), intent(in) :: nodes(*)
    real(c_double), intent(in) :: xy(*)
    integer(c_int64_t), intent(in) :: equations(1, *)
    integer(c_int), value :: n_edges
    integer(c_int), intent(in) :: edges(*)
    integer(c_int), intent(inout), optional, target :: side
    integer(c_int) :: status
    type(c_ptr) :: side_address
    side_address = c_null_ptr
    if (present(side)) side_address = c_loc(side)
    status = tfem_contact_add_side_by_address(context, tag, body, young, poisson, plane_mode, n_nodes, &
        nodes, xy, equations, n_edges, edges, side_address)
  end function tfem_contact_add_side_opt_r1121

  function tfem_contact_add_side_opt_r2121(context, tag, body, young, poisson, &
        plane_mode, n_nodes, nodes, xy, equations, n_edges, edges, side) result(status)
    type(c_ptr), value :: context
    integer(c_int), value :: tag
    integer(c_int), value :: body
    real(c_double), value :: young
    real(c_double), value :: poisson
    integer(c_int), value :: plane_mode
    integer(c_int), value :: n_nodes
    integer(c_int), intent(in) :: nodes(1, *)
    real(c_double), intent(in) :: xy(*)
    integer(c_int64_t), intent(in) :: equations(1, *)
    integer(c_int), value :: n_edges
    integer(c_int), intent(in) :: edges(*)
    integer(c_int), intent(inout), optional, target :: side
    integer(c_int) :: status
    type(c_ptr) :: side_address
    side_address = c_null_ptr
    if (present(side)) side_address = c_loc(side)
    status = tfem_contact_add_side_by_address(context, tag, body, young, poisson, plane_mode, n_nodes, &
        nodes, xy, equations, n_edges, edges, side_address)
  end function tfem_contact_add_side_opt_r2121

  function tfem_contact_add_side_opt_r1221(context, tag, body, young, poisson, &
        plane_mode, n_nodes, nodes, xy, equations, n_edges, edges, side) result(status)
    type(c_ptr), value :: context
    integer(c_int), value :: tag
    integer(c_int), value :: body
    real(c_double), value :: young
    real(c_double), value :: poisson
    integer(c_int), value :: plane_mode
    integer(c_int), value :: n_nodes
    integer(c_int), intent(in) :: nodes(*)
    real(c_double), intent(in) :: xy(1, *)
    integer(c_int64_t), intent(in) :: equations(1, *)
    integer(c_int), value :: n_edges
    integer(c_int), intent(in) :: edges(*)
    integer(c_int), intent(inout), optional, target :: side
    integer(c_int) :: status
    type(c_ptr) :: side_address
    side_address = c_null_ptr
    if (present(side)) side_address = c_loc(side)
    status = tfem_contact_add_side_by_address(context, tag, body, young, poisson, plane_mode, n_nodes, &
        nodes, xy, equations, n_edges, edges, side_address)
  end function tfem_contact_add_side_opt_r1221

  function tfem_contact_add_side_opt_r2221(context, tag, body, young, poisson, &
        plane_mode, n_nodes, nodes, xy, equations, n_edges, edges, side) result(status)
    type(c_ptr), value :: context
    integer(c_int), value :: tag
    integer(c_int), value :: body
    real(c_double), value :: young
    real(c_double), value :: poisson
    integer(c_int), value :: plane_mode
    integer(c_int), value :: n_nodes
    integer(c_int), intent(in) :: nodes(1, *)
    real(c_double), intent(in) :: xy(1, *)
    integer(c_int64_t), intent(in) :: equations(1, *)
    integer(c_int), value :: n_edges
    integer(c_int), intent(in) :: edges(*)
    integer(c_int), intent(inout), optional, target :: side
    integer(c_int) :: status
    type(c_ptr) :: side_address
    side_address = c_null_ptr
    if (present(side)) side_address = c_loc(side)
    status = tfem_contact_add_side_by_address(context, tag, body, young, poisson, plane_mode, n_nodes, &
        nodes, xy, equations, n_edges, edges, side_address)
  end function tfem_contact_add_side_opt_r2221

  function tfem_contact_add_side_opt_r1112(context, tag, body, young, poisson, &
        plane_mode, n_nodes, nodes, xy, equations, n_edges, edges, side) result(status)
    type(c_ptr), value :: context
    integer(c_int), value :: tag
    integer(c_int), value :: body
    real(c_double), value :: young
    real(c_double), value :: poisson
    integer(c_int), value :: plane_mode
    integer(c_int), value :: n_nodes
    integer(c_int), intent(in) :: nodes(*)
    real(c_double), intent(in) :: xy(*)
    integer(c_int64_t), intent(in) :: equations(*)
    integer(c_int), value :: n_edges
    integer(c_int), intent(in) :: edges(1, *)
    integer(c_int), intent(inout), optional, target :: side
    integer(c_int) :: status
    type(c_ptr) :: side_address
    side_address = c_null_ptr
    if (present(side)) side_address = c_loc(side)
    status = tfem_contact_add_side_by_address(context, tag, body, young, poisson, plane_mode, n_nodes, &
        nodes, xy, equations, n_edges, edges, side_address)
  end function tfem_contact_add_side_opt_r1112

  function tfem_contact_add_side_opt_r2112(context, tag, body, young, poisson, &
        plane_mode, n_nodes, nodes, xy, equations, n_edges, edges, side) result(status)
    type(c_ptr), value :: context
    integer(c_int), value :: tag
    integer(c_int), value :: body
    real(c_double), value :: young
    real(c_double), value :: poisson
    integer(c_int), value :: plane_mode
    integer(c_int), value :: n_nodes
    integer(c_int), intent(in) :: nodes(1, *)
    real(c_double), intent(in) :: xy(*)
    integer(c_int64_t), intent(in) :: equations(*)
    integer(c_int), value :: n_edges
    integer(c_int), intent(in) :: edges(1, *)
    integer(c_int), intent(inout), optional, target :: side
    integer(c_int) :: status
    type(c_ptr) :: side_address
    side_address = c_null_ptr
    if (present(side)) side_address = c_loc(side)
    status = tfem_contact_add_side_by_address(context, tag, body, young, poisson, plane_mode, n_nodes, &
        nodes, xy, equations, n_edges, edges, side_address)
  end function tfem_contact_add_side_opt_r2112

  function tfem_contact_add_side_opt_r1212(context, tag, body, young, poisson, &
        plane_mode, n_nodes, nodes, xy, equations, n_edges, edges, side) result(status)
    type(c_ptr), value :: context
    integer(c_int), value :: tag
    integer(c_int), value :: body
    real(c_double), value :: young
    real(c_double), value :: poisson
    integer(c_int), value :: plane_mode
    integer(c_int), value :: n_nodes
    integer(c_int), intent(in) :: nodes(*)
    real(c_double), intent(in) :: xy(1, *)
    integer(c_int64_t), intent(in) :: equations(*)
    integer(c_int), value :: n_edges
    integer(c_int), intent(in) :: edges(1, *)
    integer(c_int), intent(inout), optional, target :: side
    integer(c_int) :: status
    type(c_ptr) :: side_address
    side_address = c_null_ptr
    if (present(side)) side_address = c_loc(side)
    status = tfem_contact_add_side_by_address(context, tag, body, young, poisson, plane_mode, n_nodes, &
        nodes, xy, equations, n_edges, edges, side_address)
  end function tfem_contact_add_side_opt_r1212

  function tfem_contact_add_side_opt_r2212(context, tag, body, young, poisson, &
        plane_mode, n_nodes, nodes, xy, equations, n_edges, edges, side) result(status)
    type(c_ptr), value :: context
    integer(c_int), value :: tag
    integer(c_int), value :: body
    real(c_double), value :: young
    real(c_double), value :: poisson
    integer(c_int), value :: plane_mode
    integer(c_int), value :: n_nodes
    integer(c_int), intent(in) :: nodes(1, *)
    real(c_double), intent(in) :: xy(1, *)
    integer(c_int64_t), intent(in) :: equations(*)
    integer(c_int), value :: n_edges
    integer(c_int), intent(in) :: edges(1, *)
    integer(c_int), intent(inout), optional, target :: side
    integer(c_int) :: status
    type(c_ptr) :: side_address
    side_address = c_null_ptr
    if (present(side)) side_address = c_loc(side)
    status = tfem_contact_add_side_by_address(context, tag, body, young, poisson, plane_mode, n_nodes, &
        nodes, xy, equations, n_edges, edges, side_address)
  end function tfem_contact_add_side_opt_r2212

  function tfem_contact_add_side_opt_r1122(context, tag, body, young, poisson, &
        plane_mode, n_nodes, nodes, xy, equations, n_edges, edges, side) result(status)
    type(c_ptr), value :: context
    integer(c_int), value :: tag
    integer(c_int), value :: body
    real(c_double), value :: young
    real(c_double), value :: poisson
    integer(c_int), value :: plane_mode
    integer(c_int), value :: n_nodes
    integer(c_int), intent(in) :: nodes(*)
    real(c_double), intent(in) :: xy(*)
    integer(c_int64_t), intent(in) :: equations(1, *)
    integer(c_int), value :: n_edges
    integer(c_int), intent(in) :: edges(1, *)
    integer(c_int), intent(inout), optional, target :: side
    integer(c_int) :: status
    type(c_ptr) :: side_address
    side_address = c_null_ptr
    if (present(side)) side_address = c_loc(side)
    status = tfem_contact_add_side_by_address(context, tag, body, young, poisson, plane_mode, n_nodes, &
        nodes, xy, equations, n_edges, edges, side_address)
  end function tfem_contact_add_side_opt_r1122

  function tfem_contact_add_side_opt_r2122(context, tag, body, young, poisson, &
        plane_mode, n_nodes, nodes, xy, equations, n_edges, edges, side) result(status)
    type(c_ptr), value :: context
    integer(c_int), value :: tag
    integer(c_int), value :: body
    real(c_double), value :: young
    real(c_double), value :: poisson
    integer(c_int), value :: plane_mode
    integer(c_int), value :: n_nodes
    integer(c_int), intent(in) :: nodes(1, *)
    real(c_double), intent(in) :: xy(*)
    integer(c_int64_t), intent(in) :: equations(1, *)
    integer(c_int), value :: n_edges
    integer(c_int), intent(in) :: edges(1, *)
    integer(c_int), intent(inout), optional, target :: side
    integer(c_int) :: status
    type(c_ptr) :: side_address
    side_address = c_null_ptr
    if (present(side)) side_address = c_loc(side)
    status = tfem_contact_add_side_by_address(context, tag, body, young, poisson, plane_mode, n_nodes, &
        nodes, xy, equations, n_edges, edges, side_address)
  end function tfem_contact_add_side_opt_r2122

  function tfem_contact_add_side_opt_r1222(context, tag, body, young, poisson, &
        plane_mode, n_nodes, nodes, xy, equations, n_edges, edges, side) result(status)
    type(c_ptr), value :: context
    integer(c_int), value :: tag
    integer(c_int), value :: body
    real(c_double), value :: young
    real(c_double), value :: poisson
    integer(c_int), value :: plane_mode
    integer(c_int), value :: n_nodes
    integer(c_int), intent(in) :: nodes(*)
    real(c_double), intent(in) :: xy(1, *)
    integer(c_int64_t), intent(in) :: equations(1, *)
    integer(c_int), value :: n_edges
    integer(c_int), intent(in) :: edges(1, *)
    integer(c_int), intent(inout), optional, target :: side
    integer(c_int) :: status
    type(c_ptr) :: side_address
    side_address = c_null_ptr
    if (present(side)) side_address = c_loc(side)
    status = tfem_contact_add_side_by_address(context, tag, body, young, poisson, plane_mode, n_nodes, &
        nodes, xy, equations, n_edges, edges, side_address)
  end function tfem_contact_add_side_opt_r1222

  function tfem_contact_add_side_opt_r2222(context, tag, body, young, poisson, &
        plane_mode, n_nodes, nodes, xy, equations, n_edges, edges, side) result(status)
    type(c_ptr), value :: context
    integer(c_int), value :: tag
    integer(c_int), value :: body
    real(c_double), value :: young
    real(c_double), value :: poisson
    integer(c_int), value :: plane_mode
    integer(c_int), value :: n_nodes
    integer(c_int), intent(in) :: nodes(1, *)
    real(c_double), intent(in) :: xy(1, *)
    integer(c_int64_t), intent(in) :: equations(1, *)
    integer(c_int), value :: n_edges
    integer(c_int), intent(in) :: edges(1, *)
    integer(c_int), intent(inout), optional, target :: side
    integer(c_int) :: status
    type(c_ptr) :: side_address
    side_address = c_null_ptr
    if (present(side)) side_address = c_loc(side)
    status = tfem_contact_add_side_by_address(context, tag, body, young, poisson, plane_mode, n_nodes, &
        nodes, xy, equations, n_edges, edges, side_address)
  end function tfem_contact_add_side_opt_r2222

  function tfem_contact_add_pair_opt(context, side_a, side_b, pair) result(status)
    type(c_ptr), value :: context
    integer(c_int), value :: side_a
    integer(c_int), value :: side_b
    integer(c_int), intent(inout), optional, target :: pair
    integer(c_int) :: status
    type(c_ptr) :: pair_address
    pair_address = c_null_ptr
    if (present(pair)) pair_address = c_loc(pair)
    status = tfem_contact_add_pair_by_address(context, side_a, side_b, pair_address)
  end function tfem_contact_add_pair_opt

  function tfem_contact_add_pair_with_mesh_opt(context, side_a, side_b, n_triangles, &
        connectivity, pair) result(status)
    type(c_ptr), value :: context
    integer(c_int), value :: side_a
    integer(c_int), value :: side_b
    integer(c_int), value :: n_triangles
    integer(c_int), intent(in) :: connectivity(*)
    integer(c_int), intent(inout), optional, target :: pair
    integer(c_int) :: status
    type(c_ptr) :: pair_address
    pair_address = c_null_ptr
    if (present(pair)) pair_address = c_loc(pair)
    status = tfem_contact_add_pair_with_mesh_by_address(context, side_a, side_b, n_triangles, &
        connectivity, pair_address)
  end function tfem_contact_add_pair_with_mesh_opt

  function tfem_contact_add_pair_with_mesh_opt_r2(context, side_a, side_b, n_triangles, &
        connectivity, pair) result(status)
    type(c_ptr), value :: context
    integer(c_int), value :: side_a
    integer(c_int), value :: side_b
    integer(c_int), value :: n_triangles
    integer(c_int), intent(in) :: connectivity(1, *)
    integer(c_int), intent(inout), optional, target :: pair
    integer(c_int) :: status
    type(c_ptr) :: pair_address
    pair_address = c_null_ptr
    if (present(pair)) pair_address = c_loc(pair)
    status = tfem_contact_add_pair_with_mesh_by_address(context, side_a, side_b, n_triangles, &
        connectivity, pair_address)
  end function tfem_contact_add_pair_with_mesh_opt_r2

  function tfem_contact_sizes_opt(context, n_nodes, n_elements, n_entries) result(status)
    type(c_ptr), value :: context
    integer(c_int), intent(inout), optional, target :: n_nodes
    integer(c_int), intent(inout), optional, target :: n_elements
    integer(c_int64_t), intent(inout), optional, target :: n_entries
    integer(c_int) :: status
    type(c_ptr) :: n_nodes_address
    type(c_ptr) :: n_elements_address
    type(c_ptr) :: n_entries_address
    n_nodes_address = c_null_ptr
    if (present(n_nodes)) n_nodes_address = c_loc(n_nodes)
    n_elements_address = c_null_ptr
    if (present(n_elements)) n_elements_address = c_loc(n_elements)
    n_entries_address = c_null_ptr
    if (present(n_entries)) n_entries_address = c_loc(n_entries)
    status = tfem_contact_sizes_by_address(context, n_nodes_address, n_elements_address, &
        n_entries_address)
  end function tfem_contact_sizes_opt

  function tfem_contact_nodes_r2(context, out, length) result(status)
    type(c_ptr), value :: context
    integer(c_int), intent(inout) :: out(1, *)
    integer(c_size_t), intent(in) :: length
    integer(c_int) :: status
    status = tfem_contact_nodes(context, out, length)
  end function tfem_contact_nodes_r2

  function tfem_contact_nodes_i(context, out, length) result(status)
    type(c_ptr), value :: context
    integer(c_int), intent(inout) :: out(*)
    integer(tfem_length_kind), intent(in) :: length
    integer(c_int) :: status
    status = tfem_contact_nodes(context, out, tfem_to_size_t(length))
  end function tfem_contact_nodes_i

  function tfem_contact_nodes_i_r2(context, out, length) result(status)
    type(c_ptr), value :: context
    integer(c_int), intent(inout) :: out(1, *)
    integer(tfem_length_kind), intent(in) :: length
    integer(c_int) :: status
    status = tfem_contact_nodes(context, out, tfem_to_size_t(length))
  end function tfem_contact_nodes_i_r2

  function tfem_contact_pattern_r21(context, rows, cols, length) result(status)
    type(c_ptr), value :: context
    integer(c_int64_t), intent(inout) :: rows(1, *)
    integer(c_int64_t), intent(inout) :: cols(*)
    integer(c_size_t), intent(in) :: length
    integer(c_int) :: status
    status = tfem_contact_pattern(context, rows, cols, length)
  end function tfem_contact_pattern_r21

  function tfem_contact_pattern_r12(context, rows, cols, length) result(status)
    type(c_ptr), value :: context
    integer(c_int64_t), intent(inout) :: rows(*)
    integer(c_int64_t), intent(inout) :: cols(1, *)
    integer(c_size_t), intent(in) :: length
    integer(c_int) :: status
    status = tfem_contact_pattern(context, rows, cols, length)
  end function tfem_contact_pattern_r12

  function tfem_contact_pattern_r22(context, rows, cols, length) result(status)
    type(c_ptr), value :: context
    integer(c_int64_t), intent(inout) :: rows(1, *)
    integer(c_int64_t), intent(inout) :: cols(1, *)
    integer(c_size_t), intent(in) :: length
    integer(c_int) :: status
    status = tfem_contact_pattern(context, rows, cols, length)
  end function tfem_contact_pattern_r22

  function tfem_contact_pattern_i(context, rows, cols, length) result(status)
    type(c_ptr), value :: context
    integer(c_int64_t), intent(inout) :: rows(*)
    integer(c_int64_t), intent(inout) :: cols(*)
    integer(tfem_length_kind), intent(in) :: length
    integer(c_int) :: status
    status = tfem_contact_pattern(context, rows, cols, tfem_to_size_t(length))
  end function tfem_contact_pattern_i

  function tfem_contact_pattern_i_r21(context, rows, cols, length) result(status)
    type(c_ptr), value :: context
    integer(c_int64_t), intent(inout) :: rows(1, *)
    integer(c_int64_t), intent(inout) :: cols(*)
    integer(tfem_length_kind), intent(in) :: length
    integer(c_int) :: status
    status = tfem_contact_pattern(context, rows, cols, tfem_to_size_t(length))
  end function tfem_contact_pattern_i_r21

  function tfem_contact_pattern_i_r12(context, rows, cols, length) result(status)
    type(c_ptr), value :: context
    integer(c_int64_t), intent(inout) :: rows(*)
    integer(c_int64_t), intent(inout) :: cols(1, *)
    integer(tfem_length_kind), intent(in) :: length
    integer(c_int) :: status
    status = tfem_contact_pattern(context, rows, cols, tfem_to_size_t(length))
  end function tfem_contact_pattern_i_r12

  function tfem_contact_pattern_i_r22(context, rows, cols, length) result(status)
    type(c_ptr), value :: context
    integer(c_int64_t), intent(inout) :: rows(1, *)
    integer(c_int64_t), intent(inout) :: cols(1, *)
    integer(tfem_length_kind), intent(in) :: length
    integer(c_int) :: status
    status = tfem_contact_pattern(context, rows, cols, tfem_to_size_t(length))
  end function tfem_contact_pattern_i_r22

  function tfem_contact_evaluate_opt(context, u, u_length, values, values_length, &
        residual, residual_length) result(status)
    type(c_ptr), value :: context
    real(c_double), intent(in) :: u(*)
    integer(c_size_t), intent(in) :: u_length
    real(c_double), intent(inout), optional, target :: values(*)
    integer(c_size_t), intent(in) :: values_length
    real(c_double), intent(inout), optional, target :: residual(*)
    integer(c_size_t), intent(in) :: residual_length
    integer(c_int) :: status
    type(c_ptr) :: values_address
    type(c_ptr) :: residual_address
    values_address = tfem_address_c_double(values, values_length /= 0)
    residual_address = tfem_address_c_double(residual, residual_length /= 0)
    status = tfem_contact_evaluate_by_address(context, u, u_length, values_address, values_length, &
        residual_address, residual_length)
  end function tfem_contact_evaluate_opt

  function tfem_contact_evaluate_opt_r211(context, u, u_length, values, values_length, &
        residual, residual_length) result(status)
    type(c_ptr), value :: context
    real(c_double), intent(in) :: u(1, *)
    integer(c_size_t), intent(in) :: u_length
    real(c_double), intent(inout), optional, target :: values(*)
    integer(c_size_t), intent(in) :: values_length
    real(c_double), intent(inout), optional, target :: residual(*)
    integer(c_size_t), intent(in) :: residual_length
    integer(c_int) :: status
    type(c_ptr) :: values_address
    type(c_ptr) :: residual_address
    values_address = tfem_address_c_double(values, values_length /= 0)
    residual_address = tfem_address_c_double(residual, residual_length /= 0)
    status = tfem_contact_evaluate_by_address(context, u, u_length, values_address, values_length, &
        residual_address, residual_length)
  end function tfem_contact_evaluate_opt_r211

  function tfem_contact_evaluate_opt_r121(context, u, u_length, values, values_length, &
        residual, residual_length) result(status)
    type(c_ptr), value :: context
    real(c_double), intent(in) :: u(*)
    integer(c_size_t), intent(in) :: u_length
    real(c_double), intent(inout), target :: values(1, *)
    integer(c_size_t), intent(in) :: values_length
    real(c_double), intent(inout), optional, target :: residual(*)
    integer(c_size_t), intent(in) :: residual_length
    integer(c_int) :: status
    type(c_ptr) :: values_address
    type(c_ptr) :: residual_address
    values_address = tfem_address_c_double(values, values_length /= 0)
    residual_address = tfem_address_c_double(residual, residual_length /= 0)
    status = tfem_contact_evaluate_by_address(context, u, u_length, values_address, values_length, &
        residual_address, residual_length)
  end function tfem_contact_evaluate_opt_r121

  function tfem_contact_evaluate_opt_r221(context, u, u_length, values, values_length, &
        residual, residual_length) result(status)
    type(c_ptr), value :: context
    real(c_double), intent(in) :: u(1, *)
    integer(c_size_t), intent(in) :: u_length
    real(c_double), intent(inout), target :: values(1, *)
    integer(c_size_t), intent(in) :: values_length
    real(c_double), intent(inout), optional, target :: residual(*)
    integer(c_size_t), intent(in) :: residual_length
    integer(c_int) :: status
    type(c_ptr) :: values_address
    type(c_ptr) :: residual_address
    values_address = tfem_address_c_double(values, values_length /= 0)
    residual_address = tfem_address_c_double(residual, residual_length /= 0)
    status = tfem_contact_evaluate_by_address(context, u, u_length, values_address, values_length, &
        residual_address, residual_length)
  end function tfem_contact_evaluate_opt_r221

  function tfem_contact_evaluate_opt_r112(context, u, u_length, values, values_length, &
        residual, residual_length) result(status)
    type(c_ptr), value :: context
    real(c_double), intent(in) :: u(*)
    integer(c_size_t), intent(in) :: u_length
    real(c_double), intent(inout), optional, target :: values(*)
    integer(c_size_t), intent(in) :: values_length
    real(c_double), intent(inout), target :: residual(1, *)
    integer(c_size_t), intent(in) :: residual_length
    integer(c_int) :: status
    type(c_ptr) :: values_address
    type(c_ptr) :: residual_address
    values_address = tfem_address_c_double(values, values_length /= 0)
    residual_address = tfem_address_c_double(residual, residual_length /= 0)
    status = tfem_contact_evaluate_by_address(context, u, u_length, values_address, values_length, &
        residual_address, residual_length)
  end function tfem_contact_evaluate_opt_r112

  function tfem_contact_evaluate_opt_r212(context, u, u_length, values, values_length, &
        residual, residual_length) result(status)
    type(c_ptr), value :: context
    real(c_double), intent(in) :: u(1, *)
    integer(c_size_t), intent(in) :: u_length
    real(c_double), intent(inout), optional, target :: values(*)
    integer(c_size_t), intent(in) :: values_length
    real(c_double), intent(inout), target :: residual(1, *)
    integer(c_size_t), intent(in) :: residual_length
    integer(c_int) :: status
    type(c_ptr) :: values_address
    type(c_ptr) :: residual_address
    values_address = tfem_address_c_double(values, values_length /= 0)
    residual_address = tfem_address_c_double(residual, residual_length /= 0)
    status = tfem_contact_evaluate_by_address(context, u, u_length, values_address, values_length, &
        residual_address, residual_length)
  end function tfem_contact_evaluate_opt_r212

  function tfem_contact_evaluate_opt_r122(context, u, u_length, values, values_length, &
        residual, residual_length) result(status)
    type(c_ptr), value :: context
    real(c_double), intent(in) :: u(*)
    integer(c_size_t), intent(in) :: u_length
    real(c_double), intent(inout), target :: values(1, *)
    integer(c_size_t), intent(in) :: values_length
    real(c_double), intent(inout), target :: residual(1, *)
    integer(c_size_t), intent(in) :: residual_length
    integer(c_int) :: status
    type(c_ptr) :: values_address
    type(c_ptr) :: residual_address
    values_address = tfem_address_c_double(values, values_length /= 0)
    residual_address = tfem_address_c_double(residual, residual_length /= 0)
    status = tfem_contact_evaluate_by_address(context, u, u_length, values_address, values_length, &
        residual_address, residual_length)
  end function tfem_contact_evaluate_opt_r122

  function tfem_contact_evaluate_opt_r222(context, u, u_length, values, values_length, &
        residual, residual_length) result(status)
    type(c_ptr), value :: context
    real(c_double), intent(in) :: u(1, *)
    integer(c_size_t), intent(in) :: u_length
    real(c_double), intent(inout), target :: values(1, *)
    integer(c_size_t), intent(in) :: values_length
    real(c_double), intent(inout), target :: residual(1, *)
    integer(c_size_t), intent(in) :: residual_length
    integer(c_int) :: status
    type(c_ptr) :: values_address
    type(c_ptr) :: residual_address
    values_address = tfem_address_c_double(values, values_length /= 0)
    residual_address = tfem_address_c_double(residual, residual_length /= 0)
    status = tfem_contact_evaluate_by_address(context, u, u_length, values_address, values_length, &
        residual_address, residual_length)
  end function tfem_contact_evaluate_opt_r222

  function tfem_contact_evaluate_opt_i(context, u, u_length, values, values_length, &
        residual, residual_length) result(status)
    type(c_ptr), value :: context
    real(c_double), intent(in) :: u(*)
    integer(tfem_length_kind), intent(in) :: u_length
    real(c_double), intent(inout), optional, target :: values(*)
    integer(tfem_length_kind), intent(in) :: values_length
    real(c_double), intent(inout), optional, target :: residual(*)
    integer(tfem_length_kind), intent(in) :: residual_length
    integer(c_int) :: status
    type(c_ptr) :: values_address
    type(c_ptr) :: residual_address
    values_address = tfem_address_c_double(values, values_length > 0)
    residual_address = tfem_address_c_double(residual, residual_length > 0)
    status = tfem_contact_evaluate_by_address(context, u, tfem_to_size_t(u_length), values_address, &
        tfem_to_size_t(values_length), residual_address, tfem_to_size_t(residual_length))
  end function tfem_contact_evaluate_opt_i

  function tfem_contact_evaluate_opt_i_r211(context, u, u_length, values, &
        values_length, residual, residual_length) result(status)
    type(c_ptr), value :: context
    real(c_double), intent(in) :: u(1, *)
    integer(tfem_length_kind), intent(in) :: u_length
    real(c_double), intent(inout), optional, target :: values(*)
    integer(tfem_length_kind), intent(in) :: values_length
    real(c_double), intent(inout), optional, target :: residual(*)
    integer(tfem_length_kind), intent(in) :: residual_length
    integer(c_int) :: status
    type(c_ptr) :: values_address
    type(c_ptr) :: residual_address
    values_address = tfem_address_c_double(values, values_length > 0)
    residual_address = tfem_address_c_double(residual, residual_length > 0)
    status = tfem_contact_evaluate_by_address(context, u, tfem_to_size_t(u_length), values_address, &
        tfem_to_size_t(values_length), residual_address, tfem_to_size_t(residual_length))
  end function tfem_contact_evaluate_opt_i_r211

  function tfem_contact_evaluate_opt_i_r121(context, u, u_length, values, &
        values_length, residual, residual_length) result(status)
    type(c_ptr), value :: context
    real(c_double), intent(in) :: u(*)
    integer(tfem_length_kind), intent(in) :: u_length
    real(c_double), intent(inout), target :: values(1, *)
    integer(tfem_length_kind), intent(in) :: values_length
    real(c_double), intent(inout), optional, target :: residual(*)
    integer(tfem_length_kind), intent(in) :: residual_length
    integer(c_int) :: status
    type(c_ptr) :: values_address
    type(c_ptr) :: residual_address
    values_address = tfem_address_c_double(values, values_length > 0)
    residual_address = tfem_address_c_double(residual, residual_length > 0)
    status = tfem_contact_evaluate_by_address(context, u, tfem_to_size_t(u_length), values_address, &
        tfem_to_size_t(values_length), residual_address, tfem_to_size_t(residual_length))
  end function tfem_contact_evaluate_opt_i_r121

  function tfem_contact_evaluate_opt_i_r221(context, u, u_length, values, &
        values_length, residual, residual_length) result(status)
    type(c_ptr), value :: context
    real(c_double), intent(in) :: u(1, *)
    integer(tfem_length_kind), intent(in) :: u_length
    real(c_double), intent(inout), target :: values(1, *)
    integer(tfem_length_kind), intent(in) :: values_length
    real(c_double), intent(inout), optional, target :: residual(*)
    integer(tfem_length_kind), intent(in) :: residual_length
    integer(c_int) :: status
    type(c_ptr) :: values_address
    type(c_ptr) :: residual_address
    values_address = tfem_address_c_double(values, values_length > 0)
    residual_address = tfem_address_c_double(residual, residual_length > 0)
    status = tfem_contact_evaluate_by_address(context, u, tfem_to_size_t(u_length), values_address, &
        tfem_to_size_t(values_length), residual_address, tfem_to_size_t(residual_length))
  end function tfem_contact_evaluate_opt_i_r221

  function tfem_contact_evaluate_opt_i_r112(context, u, u_length, values, &
        values_length, residual, residual_length) result(status)
    type(c_ptr), value :: context
    real(c_double), intent(in) :: u(*)
    integer(tfem_length_kind), intent(in) :: u_length
    real(c_double), intent(inout), optional, target :: values(*)
    integer(tfem_length_kind), intent(in) :: values_length
    real(c_double), intent(inout), target :: residual(1, *)
    integer(tfem_length_kind), intent(in) :: residual_length
    integer(c_int) :: status
    type(c_ptr) :: values_address
    type(c_ptr) :: residual_address
    values_address = tfem_address_c_double(values, values_length > 0)
    residual_address = tfem_address_c_double(residual, residual_length > 0)
    status = tfem_contact_evaluate_by_address(context, u, tfem_to_size_t(u_length), values_address, &
        tfem_to_size_t(values_length), residual_address, tfem_to_size_t(residual_length))
  end function tfem_contact_evaluate_opt_i_r112

  function tfem_contact_evaluate_opt_i_r212(context, u, u_length, values, &
        values_length, residual, residual_length) result(status)
    type(c_ptr), value :: context
    real(c_double), intent(in) :: u(1, *)
    integer(tfem_length_kind), intent(in) :: u_length
    real(c_double), intent(inout), optional, target :: values(*)
    integer(tfem_length_kind), intent(in) :: values_length
    real(c_double), intent(inout), target :: residual(1, *)
    integer(tfem_length_kind), intent(in) :: residual_length
    integer(c_int) :: status
    type(c_ptr) :: values_address
    type(c_ptr) :: residual_address
    values_address = tfem_address_c_double(values, values_length > 0)
    residual_address = tfem_address_c_double(residual, residual_length > 0)
    status = tfem_contact_evaluate_by_address(context, u, tfem_to_size_t(u_length), values_address, &
        tfem_to_size_t(values_length), residual_address, tfem_to_size_t(residual_length))
  end function tfem_contact_evaluate_opt_i_r212

  function tfem_contact_evaluate_opt_i_r122(context, u, u_length, values, &
        values_length, residual, residual_length) result(status)
    type(c_ptr), value :: context
    real(c_double), intent(in) :: u(*)
    integer(tfem_length_kind), intent(in) :: u_length
    real(c_double), intent(inout), target :: values(1, *)
    integer(tfem_length_kind), intent(in) :: values_length
    real(c_double), intent(inout), target :: residual(1, *)
    integer(tfem_length_kind), intent(in) :: residual_length
    integer(c_int) :: status
    type(c_ptr) :: values_address
    type(c_ptr) :: residual_address
    values_address = tfem_address_c_double(values, values_length > 0)
    residual_address = tfem_address_c_double(residual, residual_length > 0)
    status = tfem_contact_evaluate_by_address(context, u, tfem_to_size_t(u_length), values_address, &
        tfem_to_size_t(values_length), residual_address, tfem_to_size_t(residual_length))
  end function tfem_contact_evaluate_opt_i_r122

  function tfem_contact_evaluate_opt_i_r222(context, u, u_length, values, &
        values_length, residual, residual_length) result(status)
    type(c_ptr), value :: context
    real(c_double), intent(in) :: u(1, *)
    integer(tfem_length_kind), intent(in) :: u_length
    real(c_double), intent(inout), target :: values(1, *)
    integer(tfem_length_kind), intent(in) :: values_length
    real(c_double), intent(inout), target :: residual(1, *)
    integer(tfem_length_kind), intent(in) :: residual_length
    integer(c_int) :: status
    type(c_ptr) :: values_address
    type(c_ptr) :: residual_address
    values_address = tfem_address_c_double(values, values_length > 0)
    residual_address = tfem_address_c_double(residual, residual_length > 0)
    status = tfem_contact_evaluate_by_address(context, u, tfem_to_size_t(u_length), values_address, &
        tfem_to_size_t(values_length), residual_address, tfem_to_size_t(residual_length))
  end function tfem_contact_evaluate_opt_i_r222

  function tfem_contact_gather_r21(context, u_equations, n_equations, u, u_length) result(status)
    type(c_ptr), value :: context
    real(c_double), intent(in) :: u_equations(1, *)
    integer(c_size_t), intent(in) :: n_equations
    real(c_double), intent(inout) :: u(*)
    integer(c_size_t), intent(in) :: u_length
    integer(c_int) :: status
    status = tfem_contact_gather(context, u_equations, n_equations, u, u_length)
  end function tfem_contact_gather_r21

  function tfem_contact_gather_r12(context, u_equations, n_equations, u, u_length) result(status)
    type(c_ptr), value :: context
    real(c_double), intent(in) :: u_equations(*)
    integer(c_size_t), intent(in) :: n_equations
    real(c_double), intent(inout) :: u(1, *)
    integer(c_size_t), intent(in) :: u_length
    integer(c_int) :: status
    status = tfem_contact_gather(context, u_equations, n_equations, u, u_length)
  end function tfem_contact_gather_r12

  function tfem_contact_gather_r22(context, u_equations, n_equations, u, u_length) result(status)
    type(c_ptr), value :: context
    real(c_double), intent(in) :: u_equations(1, *)
    integer(c_size_t), intent(in) :: n_equations
    real(c_double), intent(inout) :: u(1, *)
    integer(c_size_t), intent(in) :: u_length
    integer(c_int) :: status
    status = tfem_contact_gather(context, u_equations, n_equations, u, u_length)
  end function tfem_contact_gather_r22

  function tfem_contact_gather_i(context, u_equations, n_equations, u, u_length) result(status)
    type(c_ptr), value :: context
    real(c_double), intent(in) :: u_equations(*)
    integer(tfem_length_kind), intent(in) :: n_equations
    real(c_double), intent(inout) :: u(*)
    integer(tfem_length_kind), intent(in) :: u_length
    integer(c_int) :: status
    status = tfem_contact_gather(context, u_equations, tfem_to_size_t(n_equations), u, &
        tfem_to_size_t(u_length))
  end function tfem_contact_gather_i

  function tfem_contact_gather_i_r21(context, u_equations, n_equations, u, u_length) result(status)
    type(c_ptr), value :: context
    real(c_double), intent(in) :: u_equations(1, *)
    integer(tfem_length_kind), intent(in) :: n_equations
    real(c_double), intent(inout) :: u(*)
    integer(tfem_length_kind), intent(in) :: u_length
    integer(c_int) :: status
    status = tfem_contact_gather(context, u_equations, tfem_to_size_t(n_equations), u, &
        tfem_to_size_t(u_length))
  end function tfem_contact_gather_i_r21

  function tfem_contact_gather_i_r12(context, u_equations, n_equations, u, u_length) result(status)
    type(c_ptr), value :: context
    real(c_double), intent(in) :: u_equations(*)
    integer(tfem_length_kind), intent(in) :: n_equations
    real(c_double), intent(inout) :: u(1, *)
    integer(tfem_length_kind), intent(in) :: u_length
    integer(c_int) :: status
    status = tfem_contact_gather(context, u_equations, tfem_to_size_t(n_equations), u, &
        tfem_to_size_t(u_length))
  end function tfem_contact_gather_i_r12

  function tfem_contact_gather_i_r22(context, u_equations, n_equations, u, u_length) result(status)
    type(c_ptr), value :: context
    real(c_double), intent(in) :: u_equations(1, *)
    integer(tfem_length_kind), intent(in) :: n_equations
    real(c_double), intent(inout) :: u(1, *)
    integer(tfem_length_kind), intent(in) :: u_length
    integer(c_int) :: status
    status = tfem_contact_gather(context, u_equations, tfem_to_size_t(n_equations), u, &
        tfem_to_size_t(u_length))
  end function tfem_contact_gather_i_r22

  function tfem_contact_scatter_add_r21(context, residual, residual_length, &
        host_vector, n_equations) result(status)
    type(c_ptr), value :: context
    real(c_double), intent(in) :: residual(1, *)
    integer(c_size_t), intent(in) :: residual_length
    real(c_double), intent(inout) :: host_vector(*)
    integer(c_size_t), intent(in) :: n_equations
    integer(c_int) :: status
    status = tfem_contact_scatter_add(context, residual, residual_length, host_vector, n_equations)
  end function tfem_contact_scatter_add_r21

  function tfem_contact_scatter_add_r12(context, residual, residual_length, &
        host_vector, n_equations) result(status)
    type(c_ptr), value :: context
    real(c_double), intent(in) :: residual(*)
    integer(c_size_t), intent(in) :: residual_length
    real(c_double), intent(inout) :: host_vector(1, *)
    integer(c_size_t), intent(in) :: n_equations
    integer(c_int) :: status
    status = tfem_contact_scatter_add(context, residual, residual_length, host_vector, n_equations)
  end function tfem_contact_scatter_add_r12

  function tfem_contact_scatter_add_r22(context, residual, residual_length, &
        host_vector, n_equations) result(status)
    type(c_ptr), value :: context
    real(c_double), intent(in) :: residual(1, *)
    integer(c_size_t), intent(in) :: residual_length
    real(c_double), intent(inout) :: host_vector(1, *)
    integer(c_size_t), intent(in) :: n_equations
    integer(c_int) :: status
    status = tfem_contact_scatter_add(context, residual, residual_length, host_vector, n_equations)
  end function tfem_contact_scatter_add_r22

  function tfem_contact_scatter_add_i(context, residual, residual_length, host_vector, &
        n_equations) result(status)
    type(c_ptr), value :: context
    real(c_double), intent(in) :: residual(*)
    integer(tfem_length_kind), intent(in) :: residual_length
    real(c_double), intent(inout) :: host_vector(*)
    integer(tfem_length_kind), intent(in) :: n_equations
    integer(c_int) :: status
    status = tfem_contact_scatter_add(context, residual, tfem_to_size_t(residual_length), host_vector, &
        tfem_to_size_t(n_equations))
  end function tfem_contact_scatter_add_i

  function tfem_contact_scatter_add_i_r21(context, residual, residual_length, &
        host_vector, n_equations) result(status)
    type(c_ptr), value :: context
    real(c_double), intent(in) :: residual(1, *)
    integer(tfem_length_kind), intent(in) :: residual_length
    real(c_double), intent(inout) :: host_vector(*)
    integer(tfem_length_kind), intent(in) :: n_equations
    integer(c_int) :: status
    status = tfem_contact_scatter_add(context, residual, tfem_to_size_t(residual_length), host_vector, &
        tfem_to_size_t(n_equations))
  end function tfem_contact_scatter_add_i_r21

  function tfem_contact_scatter_add_i_r12(context, residual, residual_length, &
        host_vector, n_equations) result(status)
    type(c_ptr), value :: context
    real(c_double), intent(in) :: residual(*)
    integer(tfem_length_kind), intent(in) :: residual_length
    real(c_double), intent(inout) :: host_vector(1, *)
    integer(tfem_length_kind), intent(in) :: n_equations
    integer(c_int) :: status
    status = tfem_contact_scatter_add(context, residual, tfem_to_size_t(residual_length), host_vector, &
        tfem_to_size_t(n_equations))
  end function tfem_contact_scatter_add_i_r12

  function tfem_contact_scatter_add_i_r22(context, residual, residual_length, &
        host_vector, n_equations) result(status)
    type(c_ptr), value :: context
    real(c_double), intent(in) :: residual(1, *)
    integer(tfem_length_kind), intent(in) :: residual_length
    real(c_double), intent(inout) :: host_vector(1, *)
    integer(tfem_length_kind), intent(in) :: n_equations
    integer(c_int) :: status
    status = tfem_contact_scatter_add(context, residual, tfem_to_size_t(residual_length), host_vector, &
        tfem_to_size_t(n_equations))
  end function tfem_contact_scatter_add_i_r22

  function tfem_contact_update_opt(context, u, u_length, changed) result(status)
    type(c_ptr), value :: context
    real(c_double), intent(in) :: u(*)
    integer(c_size_t), intent(in) :: u_length
    integer(c_int), intent(inout), optional, target :: changed
    integer(c_int) :: status
    type(c_ptr) :: changed_address
    changed_address = c_null_ptr
    if (present(changed)) changed_address = c_loc(changed)
    status = tfem_contact_update_by_address(context, u, u_length, changed_address)
  end function tfem_contact_update_opt

  function tfem_contact_update_opt_r2(context, u, u_length, changed) result(status)
    type(c_ptr), value :: context
    real(c_double), intent(in) :: u(1, *)
    integer(c_size_t), intent(in) :: u_length
    integer(c_int), intent(inout), optional, target :: changed
    integer(c_int) :: status
    type(c_ptr) :: changed_address
    changed_address = c_null_ptr
    if (present(changed)) changed_address = c_loc(changed)
    status = tfem_contact_update_by_address(context, u, u_length, changed_address)
  end function tfem_contact_update_opt_r2

  function tfem_contact_update_opt_i(context, u, u_length, changed) result(status)
    type(c_ptr), value :: context
    real(c_double), intent(in) :: u(*)
    integer(tfem_length_kind), intent(in) :: u_length
    integer(c_int), intent(inout), optional, target :: changed
    integer(c_int) :: status
    type(c_ptr) :: changed_address
    changed_address = c_null_ptr
    if (present(changed)) changed_address = c_loc(changed)
    status = tfem_contact_update_by_address(context, u, tfem_to_size_t(u_length), changed_address)
  end function tfem_contact_update_opt_i

  function tfem_contact_update_opt_i_r2(context, u, u_length, changed) result(status)
    type(c_ptr), value :: context
    real(c_double), intent(in) :: u(1, *)
    integer(tfem_length_kind), intent(in) :: u_length
    integer(c_int), intent(inout), optional, target :: changed
    integer(c_int) :: status
    type(c_ptr) :: changed_address
    changed_address = c_null_ptr
    if (present(changed)) changed_address = c_loc(changed)
    status = tfem_contact_update_by_address(context, u, tfem_to_size_t(u_length), changed_address)
  end function tfem_contact_update_opt_i_r2

  function tfem_contact_get_active_r2(context, out, length) result(status)
    type(c_ptr), value :: context
    integer(c_int), intent(inout) :: out(1, *)
    integer(c_size_t), intent(in) :: length
    integer(c_int) :: status
    status = tfem_contact_get_active(context, out, length)
  end function tfem_contact_get_active_r2

  function tfem_contact_get_active_i(context, out, length) result(status)
    type(c_ptr), value :: context
    integer(c_int), intent(inout) :: out(*)
    integer(tfem_length_kind), intent(in) :: length
    integer(c_int) :: status
    status = tfem_contact_get_active(context, out, tfem_to_size_t(length))
  end function tfem_contact_get_active_i

  function tfem_contact_get_active_i_r2(context, out, length) result(status)
    type(c_ptr), value :: context
    integer(c_int), intent(inout) :: out(1, *)
    integer(tfem_length_kind), intent(in) :: length
    integer(c_int) :: status
    status = tfem_contact_get_active(context, out, tfem_to_size_t(length))
  end function tfem_contact_get_active_i_r2

  function tfem_contact_set_active_r2(context, active, length) result(status)
    type(c_ptr), value :: context
    integer(c_int), intent(in) :: active(1, *)
    integer(c_size_t), intent(in) :: length
    integer(c_int) :: status
    status = tfem_contact_set_active(context, active, length)
  end function tfem_contact_set_active_r2

  function tfem_contact_set_active_i(context, active, length) result(status)
    type(c_ptr), value :: context
    integer(c_int), intent(in) :: active(*)
    integer(tfem_length_kind), intent(in) :: length
    integer(c_int) :: status
    status = tfem_contact_set_active(context, active, tfem_to_size_t(length))
  end function tfem_contact_set_active_i

  function tfem_contact_set_active_i_r2(context, active, length) result(status)
    type(c_ptr), value :: context
    integer(c_int), intent(in) :: active(1, *)
    integer(tfem_length_kind), intent(in) :: length
    integer(c_int) :: status
    status = tfem_contact_set_active(context, active, tfem_to_size_t(length))
  end function tfem_contact_set_active_i_r2

  function tfem_contact_gaps_r21(context, u, u_length, out, length) result(status)
    type(c_ptr), value :: context
    real(c_double), intent(in) :: u(1, *)
    integer(c_size_t), intent(in) :: u_length
    real(c_double), intent(inout) :: out(*)
    integer(c_size_t), intent(in) :: length
    integer(c_int) :: status
    status = tfem_contact_gaps(context, u, u_length, out, length)
  end function tfem_contact_gaps_r21

  function tfem_contact_gaps_r12(context, u, u_length, out, length) result(status)
    type(c_ptr), value :: context
    real(c_double), intent(in) :: u(*)
    integer(c_size_t), intent(in) :: u_length
    real(c_double), intent(inout) :: out(1, *)
    integer(c_size_t), intent(in) :: length
    integer(c_int) :: status
    status = tfem_contact_gaps(context, u, u_length, out, length)
  end function tfem_contact_gaps_r12

  function tfem_contact_gaps_r22(context, u, u_length, out, length) result(status)
    type(c_ptr), value :: context
    real(c_double), intent(in) :: u(1, *)
    integer(c_size_t), intent(in) :: u_length
    real(c_double), intent(inout) :: out(1, *)
    integer(c_size_t), intent(in) :: length
    integer(c_int) :: status
    status = tfem_contact_gaps(context, u, u_length, out, length)
  end function tfem_contact_gaps_r22

  function tfem_contact_gaps_i(context, u, u_length, out, length) result(status)
    type(c_ptr), value :: context
    real(c_double), intent(in) :: u(*)
    integer(tfem_length_kind), intent(in) :: u_length
    real(c_double), intent(inout) :: out(*)
    integer(tfem_length_kind), intent(in) :: length
    integer(c_int) :: status
    status = tfem_contact_gaps(context, u, tfem_to_size_t(u_length), out, tfem_to_size_t(length))
  end function tfem_contact_gaps_i

  function tfem_contact_gaps_i_r21(context, u, u_length, out, length) result(status)
    type(c_ptr), value :: context
    real(c_double), intent(in) :: u(1, *)
    integer(tfem_length_kind), intent(in) :: u_length
    real(c_double), intent(inout) :: out(*)
    integer(tfem_length_kind), intent(in) :: length
    integer(c_int) :: status
    status = tfem_contact_gaps(context, u, tfem_to_size_t(u_length), out, tfem_to_size_t(length))
  end function tfem_contact_gaps_i_r21

  function tfem_contact_gaps_i_r12(context, u, u_length, out, length) result(status)
    type(c_ptr), value :: context
    real(c_double), intent(in) :: u(*)
    integer(tfem_length_kind), intent(in) :: u_length
    real(c_double), intent(inout) :: out(1, *)
    integer(tfem_length_kind), intent(in) :: length
    integer(c_int) :: status
    status = tfem_contact_gaps(context, u, tfem_to_size_t(u_length), out, tfem_to_size_t(length))
  end function tfem_contact_gaps_i_r12

  function tfem_contact_gaps_i_r22(context, u, u_length, out, length) result(status)
    type(c_ptr), value :: context
    real(c_double), intent(in) :: u(1, *)
    integer(tfem_length_kind), intent(in) :: u_length
    real(c_double), intent(inout) :: out(1, *)
    integer(tfem_length_kind), intent(in) :: length
    integer(c_int) :: status
    status = tfem_contact_gaps(context, u, tfem_to_size_t(u_length), out, tfem_to_size_t(length))
  end function tfem_contact_gaps_i_r22

  function tfem_contact_pressures_r21(context, u, u_length, out, length) result(status)
    type(c_ptr), value :: context
    real(c_double), intent(in) :: u(1, *)
    integer(c_size_t), intent(in) :: u_length
    real(c_double), intent(inout) :: out(*)
    integer(c_size_t), intent(in) :: length
    integer(c_int) :: status
    status = tfem_contact_pressures(context, u, u_length, out, length)
  end function tfem_contact_pressures_r21

  function tfem_contact_pressures_r12(context, u, u_length, out, length) result(status)
    type(c_ptr), value :: context
    real(c_double), intent(in) :: u(*)
    integer(c_size_t), intent(in) :: u_length
    real(c_double), intent(inout) :: out(1, *)
    integer(c_size_t), intent(in) :: length
    integer(c_int) :: status
    status = tfem_contact_pressures(context, u, u_length, out, length)
  end function tfem_contact_pressures_r12

  function tfem_contact_pressures_r22(context, u, u_length, out, length) result(status)
    type(c_ptr), value :: context
    real(c_double), intent(in) :: u(1, *)
    integer(c_size_t), intent(in) :: u_length
    real(c_double), intent(inout) :: out(1, *)
    integer(c_size_t), intent(in) :: length
    integer(c_int) :: status
    status = tfem_contact_pressures(context, u, u_length, out, length)
  end function tfem_contact_pressures_r22

  function tfem_contact_pressures_i(context, u, u_length, out, length) result(status)
    type(c_ptr), value :: context
    real(c_double), intent(in) :: u(*)
    integer(tfem_length_kind), intent(in) :: u_length
    real(c_double), intent(inout) :: out(*)
    integer(tfem_length_kind), intent(in) :: length
    integer(c_int) :: status
    status = tfem_contact_pressures(context, u, tfem_to_size_t(u_length), out, tfem_to_size_t(length))
  end function tfem_contact_pressures_i

  function tfem_contact_pressures_i_r21(context, u, u_length, out, length) result(status)
    type(c_ptr), value :: context
    real(c_double), intent(in) :: u(1, *)
    integer(tfem_length_kind), intent(in) :: u_length
    real(c_double), intent(inout) :: out(*)
    integer(tfem_length_kind), intent(in) :: length
    integer(c_int) :: status
    status = tfem_contact_pressures(context, u, tfem_to_size_t(u_length), out, tfem_to_size_t(length))
  end function tfem_contact_pressures_i_r21

  function tfem_contact_pressures_i_r12(context, u, u_length, out, length) result(status)
    type(c_ptr), value :: context
    real(c_double), intent(in) :: u(*)
    integer(tfem_length_kind), intent(in) :: u_length
    real(c_double), intent(inout) :: out(1, *)
    integer(tfem_length_kind), intent(in) :: length
    integer(c_int) :: status
    status = tfem_contact_pressures(context, u, tfem_to_size_t(u_length), out, tfem_to_size_t(length))
  end function tfem_contact_pressures_i_r12

  function tfem_contact_pressures_i_r22(context, u, u_length, out, length) result(status)
    type(c_ptr), value :: context
    real(c_double), intent(in) :: u(1, *)
    integer(tfem_length_kind), intent(in) :: u_length
    real(c_double), intent(inout) :: out(1, *)
    integer(tfem_length_kind), intent(in) :: length
    integer(c_int) :: status
    status = tfem_contact_pressures(context, u, tfem_to_size_t(u_length), out, tfem_to_size_t(length))
  end function tfem_contact_pressures_i_r22

  function tfem_contact_elements_r2(context, out, length) result(status)
    type(c_ptr), value :: context
    integer(c_int), intent(inout) :: out(1, *)
    integer(c_size_t), intent(in) :: length
    integer(c_int) :: status
    status = tfem_contact_elements(context, out, length)
  end function tfem_contact_elements_r2

  function tfem_contact_elements_i(context, out, length) result(status)
    type(c_ptr), value :: context
    integer(c_int), intent(inout) :: out(*)
    integer(tfem_length_kind), intent(in) :: length
    integer(c_int) :: status
    status = tfem_contact_elements(context, out, tfem_to_size_t(length))
  end function tfem_contact_elements_i

  function tfem_contact_elements_i_r2(context, out, length) result(status)
    type(c_ptr), value :: context
    integer(c_int), intent(inout) :: out(1, *)
    integer(tfem_length_kind), intent(in) :: length
    integer(c_int) :: status
    status = tfem_contact_elements(context, out, tfem_to_size_t(length))
  end function tfem_contact_elements_i_r2

  function tfem_contact_element_equations_r2(context, out, length) result(status)
    type(c_ptr), value :: context
    integer(c_int64_t), intent(inout) :: out(1, *)
    integer(c_size_t), intent(in) :: length
    integer(c_int) :: status
    status = tfem_contact_element_equations(context, out, length)
  end function tfem_contact_element_equations_r2

  function tfem_contact_element_equations_i(context, out, length) result(status)
    type(c_ptr), value :: context
    integer(c_int64_t), intent(inout) :: out(*)
    integer(tfem_length_kind), intent(in) :: length
    integer(c_int) :: status
    status = tfem_contact_element_equations(context, out, tfem_to_size_t(length))
  end function tfem_contact_element_equations_i

  function tfem_contact_element_equations_i_r2(context, out, length) result(status)
    type(c_ptr), value :: context
    integer(c_int64_t), intent(inout) :: out(1, *)
    integer(tfem_length_kind), intent(in) :: length
    integer(c_int) :: status
    status = tfem_contact_element_equations(context, out, tfem_to_size_t(length))
  end function tfem_contact_element_equations_i_r2

  function tfem_contact_element_blocks_r2(context, out, length) result(status)
    type(c_ptr), value :: context
    real(c_double), intent(inout) :: out(1, *)
    integer(c_size_t), intent(in) :: length
    integer(c_int) :: status
    status = tfem_contact_element_blocks(context, out, length)
  end function tfem_contact_element_blocks_r2

  function tfem_contact_element_blocks_i(context, out, length) result(status)
    type(c_ptr), value :: context
    real(c_double), intent(inout) :: out(*)
    integer(tfem_length_kind), intent(in) :: length
    integer(c_int) :: status
    status = tfem_contact_element_blocks(context, out, tfem_to_size_t(length))
  end function tfem_contact_element_blocks_i

  function tfem_contact_element_blocks_i_r2(context, out, length) result(status)
    type(c_ptr), value :: context
    real(c_double), intent(inout) :: out(1, *)
    integer(tfem_length_kind), intent(in) :: length
    integer(c_int) :: status
    status = tfem_contact_element_blocks(context, out, tfem_to_size_t(length))
  end function tfem_contact_element_blocks_i_r2

  function tfem_solid_last_error_i(model, buffer, length) result(status)
    type(c_ptr), value :: model
    character(kind=c_char), intent(inout) :: buffer(*)
    integer(tfem_length_kind), intent(in) :: length
    integer(c_int) :: status
    status = tfem_solid_last_error(model, buffer, tfem_to_size_t(length))
  end function tfem_solid_last_error_i

  function tfem_solid_last_error_str(model, buffer, length) result(status)
    type(c_ptr), value :: model
    character(kind=c_char, len=*), intent(inout) :: buffer
    integer(c_size_t), intent(in) :: length
    integer(c_int) :: status
    status = tfem_solid_last_error(model, buffer, length)
  end function tfem_solid_last_error_str

  function tfem_solid_last_error_str_i(model, buffer, length) result(status)
    type(c_ptr), value :: model
    character(kind=c_char, len=*), intent(inout) :: buffer
    integer(tfem_length_kind), intent(in) :: length
    integer(c_int) :: status
    status = tfem_solid_last_error(model, buffer, tfem_to_size_t(length))
  end function tfem_solid_last_error_str_i

  function tfem_solid_last_error_length_no_model() result(res)
    integer(c_size_t) :: res
    res = tfem_solid_last_error_length(c_null_ptr)
  end function tfem_solid_last_error_length_no_model

  function tfem_solid_get_warning_i(model, index, buffer, length) result(status)
    type(c_ptr), value :: model
    integer(c_int), value :: index
    character(kind=c_char), intent(inout) :: buffer(*)
    integer(tfem_length_kind), intent(in) :: length
    integer(c_int) :: status
    status = tfem_solid_get_warning(model, index, buffer, tfem_to_size_t(length))
  end function tfem_solid_get_warning_i

  function tfem_solid_get_warning_str(model, index, buffer, length) result(status)
    type(c_ptr), value :: model
    integer(c_int), value :: index
    character(kind=c_char, len=*), intent(inout) :: buffer
    integer(c_size_t), intent(in) :: length
    integer(c_int) :: status
    status = tfem_solid_get_warning(model, index, buffer, length)
  end function tfem_solid_get_warning_str

  function tfem_solid_get_warning_str_i(model, index, buffer, length) result(status)
    type(c_ptr), value :: model
    integer(c_int), value :: index
    character(kind=c_char, len=*), intent(inout) :: buffer
    integer(tfem_length_kind), intent(in) :: length
    integer(c_int) :: status
    status = tfem_solid_get_warning(model, index, buffer, tfem_to_size_t(length))
  end function tfem_solid_get_warning_str_i

  function tfem_solid_get_sizes_opt(model, n_nodes, n_tetrahedra, n_contact_tetrahedra) result(status)
    type(c_ptr), value :: model
    integer(c_int), intent(inout), optional, target :: n_nodes
    integer(c_int), intent(inout), optional, target :: n_tetrahedra
    integer(c_int), intent(inout), optional, target :: n_contact_tetrahedra
    integer(c_int) :: status
    type(c_ptr) :: n_nodes_address
    type(c_ptr) :: n_tetrahedra_address
    type(c_ptr) :: n_contact_tetrahedra_address
    n_nodes_address = c_null_ptr
    if (present(n_nodes)) n_nodes_address = c_loc(n_nodes)
    n_tetrahedra_address = c_null_ptr
    if (present(n_tetrahedra)) n_tetrahedra_address = c_loc(n_tetrahedra)
    n_contact_tetrahedra_address = c_null_ptr
    if (present(n_contact_tetrahedra)) n_contact_tetrahedra_address = c_loc(n_contact_tetrahedra)
    status = tfem_solid_get_sizes_by_address(model, n_nodes_address, n_tetrahedra_address, &
        n_contact_tetrahedra_address)
  end function tfem_solid_get_sizes_opt

  function tfem_solid_get_mesh_nodes_r2(model, xyz, length) result(status)
    type(c_ptr), value :: model
    real(c_double), intent(inout) :: xyz(1, *)
    integer(c_size_t), intent(in) :: length
    integer(c_int) :: status
    status = tfem_solid_get_mesh_nodes(model, xyz, length)
  end function tfem_solid_get_mesh_nodes_r2

  function tfem_solid_get_mesh_nodes_i(model, xyz, length) result(status)
    type(c_ptr), value :: model
    real(c_double), intent(inout) :: xyz(*)
    integer(tfem_length_kind), intent(in) :: length
    integer(c_int) :: status
    status = tfem_solid_get_mesh_nodes(model, xyz, tfem_to_size_t(length))
  end function tfem_solid_get_mesh_nodes_i

  function tfem_solid_get_mesh_nodes_i_r2(model, xyz, length) result(status)
    type(c_ptr), value :: model
    real(c_double), intent(inout) :: xyz(1, *)
    integer(tfem_length_kind), intent(in) :: length
    integer(c_int) :: status
    status = tfem_solid_get_mesh_nodes(model, xyz, tfem_to_size_t(length))
  end function tfem_solid_get_mesh_nodes_i_r2

  function tfem_solid_get_mesh_tetrahedra_opt(model, tetrahedra, length, bodies, &
        bodies_length) result(status)
    type(c_ptr), value :: model
    integer(c_int), intent(inout) :: tetrahedra(*)
    integer(c_size_t), intent(in) :: length
    integer(c_int), intent(inout), optional, target :: bodies(*)
    integer(c_size_t), intent(in) :: bodies_length
    integer(c_int) :: status
    type(c_ptr) :: bodies_address
    bodies_address = tfem_address_c_int(bodies, bodies_length /= 0)
    status = tfem_solid_get_mesh_tetrahedra_by_address(model, tetrahedra, length, bodies_address, &
        bodies_length)
  end function tfem_solid_get_mesh_tetrahedra_opt

  function tfem_solid_get_mesh_tetrahedra_opt_r21(model, tetrahedra, length, bodies, &
        bodies_length) result(status)
    type(c_ptr), value :: model
    integer(c_int), intent(inout) :: tetrahedra(1, *)
    integer(c_size_t), intent(in) :: length
    integer(c_int), intent(inout), optional, target :: bodies(*)
    integer(c_size_t), intent(in) :: bodies_length
    integer(c_int) :: status
    type(c_ptr) :: bodies_address
    bodies_address = tfem_address_c_int(bodies, bodies_length /= 0)
    status = tfem_solid_get_mesh_tetrahedra_by_address(model, tetrahedra, length, bodies_address, &
        bodies_length)
  end function tfem_solid_get_mesh_tetrahedra_opt_r21

  function tfem_solid_get_mesh_tetrahedra_opt_r12(model, tetrahedra, length, bodies, &
        bodies_length) result(status)
    type(c_ptr), value :: model
    integer(c_int), intent(inout) :: tetrahedra(*)
    integer(c_size_t), intent(in) :: length
    integer(c_int), intent(inout), target :: bodies(1, *)
    integer(c_size_t), intent(in) :: bodies_length
    integer(c_int) :: status
    type(c_ptr) :: bodies_address
    bodies_address = tfem_address_c_int(bodies, bodies_length /= 0)
    status = tfem_solid_get_mesh_tetrahedra_by_address(model, tetrahedra, length, bodies_address, &
        bodies_length)
  end function tfem_solid_get_mesh_tetrahedra_opt_r12

  function tfem_solid_get_mesh_tetrahedra_opt_r22(model, tetrahedra, length, bodies, &
        bodies_length) result(status)
    type(c_ptr), value :: model
    integer(c_int), intent(inout) :: tetrahedra(1, *)
    integer(c_size_t), intent(in) :: length
    integer(c_int), intent(inout), target :: bodies(1, *)
    integer(c_size_t), intent(in) :: bodies_length
    integer(c_int) :: status
    type(c_ptr) :: bodies_address
    bodies_address = tfem_address_c_int(bodies, bodies_length /= 0)
    status = tfem_solid_get_mesh_tetrahedra_by_address(model, tetrahedra, length, bodies_address, &
        bodies_length)
  end function tfem_solid_get_mesh_tetrahedra_opt_r22

  function tfem_solid_get_mesh_tetrahedra_opt_i(model, tetrahedra, length, bodies, &
        bodies_length) result(status)
    type(c_ptr), value :: model
    integer(c_int), intent(inout) :: tetrahedra(*)
    integer(tfem_length_kind), intent(in) :: length
    integer(c_int), intent(inout), optional, target :: bodies(*)
    integer(tfem_length_kind), intent(in) :: bodies_length
    integer(c_int) :: status
    type(c_ptr) :: bodies_address
    bodies_address = tfem_address_c_int(bodies, bodies_length > 0)
    status = tfem_solid_get_mesh_tetrahedra_by_address(model, tetrahedra, tfem_to_size_t(length), &
        bodies_address, tfem_to_size_t(bodies_length))
  end function tfem_solid_get_mesh_tetrahedra_opt_i

  function tfem_solid_get_mesh_tetrahedra_opt_i_r21(model, tetrahedra, length, bodies, &
        bodies_length) result(status)
    type(c_ptr), value :: model
    integer(c_int), intent(inout) :: tetrahedra(1, *)
    integer(tfem_length_kind), intent(in) :: length
    integer(c_int), intent(inout), optional, target :: bodies(*)
    integer(tfem_length_kind), intent(in) :: bodies_length
    integer(c_int) :: status
    type(c_ptr) :: bodies_address
    bodies_address = tfem_address_c_int(bodies, bodies_length > 0)
    status = tfem_solid_get_mesh_tetrahedra_by_address(model, tetrahedra, tfem_to_size_t(length), &
        bodies_address, tfem_to_size_t(bodies_length))
  end function tfem_solid_get_mesh_tetrahedra_opt_i_r21

  function tfem_solid_get_mesh_tetrahedra_opt_i_r12(model, tetrahedra, length, bodies, &
        bodies_length) result(status)
    type(c_ptr), value :: model
    integer(c_int), intent(inout) :: tetrahedra(*)
    integer(tfem_length_kind), intent(in) :: length
    integer(c_int), intent(inout), target :: bodies(1, *)
    integer(tfem_length_kind), intent(in) :: bodies_length
    integer(c_int) :: status
    type(c_ptr) :: bodies_address
    bodies_address = tfem_address_c_int(bodies, bodies_length > 0)
    status = tfem_solid_get_mesh_tetrahedra_by_address(model, tetrahedra, tfem_to_size_t(length), &
        bodies_address, tfem_to_size_t(bodies_length))
  end function tfem_solid_get_mesh_tetrahedra_opt_i_r12

  function tfem_solid_get_mesh_tetrahedra_opt_i_r22(model, tetrahedra, length, bodies, &
        bodies_length) result(status)
    type(c_ptr), value :: model
    integer(c_int), intent(inout) :: tetrahedra(1, *)
    integer(tfem_length_kind), intent(in) :: length
    integer(c_int), intent(inout), target :: bodies(1, *)
    integer(tfem_length_kind), intent(in) :: bodies_length
    integer(c_int) :: status
    type(c_ptr) :: bodies_address
    bodies_address = tfem_address_c_int(bodies, bodies_length > 0)
    status = tfem_solid_get_mesh_tetrahedra_by_address(model, tetrahedra, tfem_to_size_t(length), &
        bodies_address, tfem_to_size_t(bodies_length))
  end function tfem_solid_get_mesh_tetrahedra_opt_i_r22

  function tfem_solid_get_boundary_faces_opt(model, faces, length, tags, tags_length) result(status)
    type(c_ptr), value :: model
    integer(c_int), intent(inout) :: faces(*)
    integer(c_size_t), intent(in) :: length
    integer(c_int), intent(inout), optional, target :: tags(*)
    integer(c_size_t), intent(in) :: tags_length
    integer(c_int) :: status
    type(c_ptr) :: tags_address
    tags_address = tfem_address_c_int(tags, tags_length /= 0)
    status = tfem_solid_get_boundary_faces_by_address(model, faces, length, tags_address, tags_length)
  end function tfem_solid_get_boundary_faces_opt

  function tfem_solid_get_boundary_faces_opt_r21(model, faces, length, tags, &
        tags_length) result(status)
    type(c_ptr), value :: model
    integer(c_int), intent(inout) :: faces(1, *)
    integer(c_size_t), intent(in) :: length
    integer(c_int), intent(inout), optional, target :: tags(*)
    integer(c_size_t), intent(in) :: tags_length
    integer(c_int) :: status
    type(c_ptr) :: tags_address
    tags_address = tfem_address_c_int(tags, tags_length /= 0)
    status = tfem_solid_get_boundary_faces_by_address(model, faces, length, tags_address, tags_length)
  end function tfem_solid_get_boundary_faces_opt_r21

  function tfem_solid_get_boundary_faces_opt_r12(model, faces, length, tags, &
        tags_length) result(status)
    type(c_ptr), value :: model
    integer(c_int), intent(inout) :: faces(*)
    integer(c_size_t), intent(in) :: length
    integer(c_int), intent(inout), target :: tags(1, *)
    integer(c_size_t), intent(in) :: tags_length
    integer(c_int) :: status
    type(c_ptr) :: tags_address
    tags_address = tfem_address_c_int(tags, tags_length /= 0)
    status = tfem_solid_get_boundary_faces_by_address(model, faces, length, tags_address, tags_length)
  end function tfem_solid_get_boundary_faces_opt_r12

  function tfem_solid_get_boundary_faces_opt_r22(model, faces, length, tags, &
        tags_length) result(status)
    type(c_ptr), value :: model
    integer(c_int), intent(inout) :: faces(1, *)
    integer(c_size_t), intent(in) :: length
    integer(c_int), intent(inout), target :: tags(1, *)
    integer(c_size_t), intent(in) :: tags_length
    integer(c_int) :: status
    type(c_ptr) :: tags_address
    tags_address = tfem_address_c_int(tags, tags_length /= 0)
    status = tfem_solid_get_boundary_faces_by_address(model, faces, length, tags_address, tags_length)
  end function tfem_solid_get_boundary_faces_opt_r22

  function tfem_solid_get_boundary_faces_opt_i(model, faces, length, tags, tags_length) result(status)
    type(c_ptr), value :: model
    integer(c_int), intent(inout) :: faces(*)
    integer(tfem_length_kind), intent(in) :: length
    integer(c_int), intent(inout), optional, target :: tags(*)
    integer(tfem_length_kind), intent(in) :: tags_length
    integer(c_int) :: status
    type(c_ptr) :: tags_address
    tags_address = tfem_address_c_int(tags, tags_length > 0)
    status = tfem_solid_get_boundary_faces_by_address(model, faces, tfem_to_size_t(length), &
        tags_address, tfem_to_size_t(tags_length))
  end function tfem_solid_get_boundary_faces_opt_i

  function tfem_solid_get_boundary_faces_opt_i_r21(model, faces, length, tags, &
        tags_length) result(status)
    type(c_ptr), value :: model
    integer(c_int), intent(inout) :: faces(1, *)
    integer(tfem_length_kind), intent(in) :: length
    integer(c_int), intent(inout), optional, target :: tags(*)
    integer(tfem_length_kind), intent(in) :: tags_length
    integer(c_int) :: status
    type(c_ptr) :: tags_address
    tags_address = tfem_address_c_int(tags, tags_length > 0)
    status = tfem_solid_get_boundary_faces_by_address(model, faces, tfem_to_size_t(length), &
        tags_address, tfem_to_size_t(tags_length))
  end function tfem_solid_get_boundary_faces_opt_i_r21

  function tfem_solid_get_boundary_faces_opt_i_r12(model, faces, length, tags, &
        tags_length) result(status)
    type(c_ptr), value :: model
    integer(c_int), intent(inout) :: faces(*)
    integer(tfem_length_kind), intent(in) :: length
    integer(c_int), intent(inout), target :: tags(1, *)
    integer(tfem_length_kind), intent(in) :: tags_length
    integer(c_int) :: status
    type(c_ptr) :: tags_address
    tags_address = tfem_address_c_int(tags, tags_length > 0)
    status = tfem_solid_get_boundary_faces_by_address(model, faces, tfem_to_size_t(length), &
        tags_address, tfem_to_size_t(tags_length))
  end function tfem_solid_get_boundary_faces_opt_i_r12

  function tfem_solid_get_boundary_faces_opt_i_r22(model, faces, length, tags, &
        tags_length) result(status)
    type(c_ptr), value :: model
    integer(c_int), intent(inout) :: faces(1, *)
    integer(tfem_length_kind), intent(in) :: length
    integer(c_int), intent(inout), target :: tags(1, *)
    integer(tfem_length_kind), intent(in) :: tags_length
    integer(c_int) :: status
    type(c_ptr) :: tags_address
    tags_address = tfem_address_c_int(tags, tags_length > 0)
    status = tfem_solid_get_boundary_faces_by_address(model, faces, tfem_to_size_t(length), &
        tags_address, tfem_to_size_t(tags_length))
  end function tfem_solid_get_boundary_faces_opt_i_r22

  function tfem_solid_add_contact_pair_opt(model, tag_a, tag_b, pair) result(status)
    type(c_ptr), value :: model
    integer(c_int), value :: tag_a
    integer(c_int), value :: tag_b
    integer(c_int), intent(inout), optional, target :: pair
    integer(c_int) :: status
    type(c_ptr) :: pair_address
    pair_address = c_null_ptr
    if (present(pair)) pair_address = c_loc(pair)
    status = tfem_solid_add_contact_pair_by_address(model, tag_a, tag_b, pair_address)
  end function tfem_solid_add_contact_pair_opt

  function tfem_solid_solve_opt(model, info) result(status)
    type(c_ptr), value :: model
    type(tfem_solve_info), intent(inout), optional, target :: info
    integer(c_int) :: status
    type(c_ptr) :: info_address
    info_address = c_null_ptr
    if (present(info)) info_address = c_loc(info)
    status = tfem_solid_solve_by_address(model, info_address)
  end function tfem_solid_solve_opt

  function tfem_solid_solve_contact_opt(model, options, info) result(status)
    type(c_ptr), value :: model
    type(tfem_contact_options), intent(in), optional, target :: options
    type(tfem_solve_info), intent(inout), optional, target :: info
    integer(c_int) :: status
    type(c_ptr) :: options_address
    type(c_ptr) :: info_address
    options_address = c_null_ptr
    if (present(options)) options_address = c_loc(options)
    info_address = c_null_ptr
    if (present(info)) info_address = c_loc(info)
    status = tfem_solid_solve_contact_by_address(model, options_address, info_address)
  end function tfem_solid_solve_contact_opt

  function tfem_solid_step_opt(model, load_factor, options, info) result(status)
    type(c_ptr), value :: model
    real(c_double), value :: load_factor
    type(tfem_contact_options), intent(in), optional, target :: options
    type(tfem_solve_info), intent(inout), optional, target :: info
    integer(c_int) :: status
    type(c_ptr) :: options_address
    type(c_ptr) :: info_address
    options_address = c_null_ptr
    if (present(options)) options_address = c_loc(options)
    info_address = c_null_ptr
    if (present(info)) info_address = c_loc(info)
    status = tfem_solid_step_by_address(model, load_factor, options_address, info_address)
  end function tfem_solid_step_opt

  function tfem_solid_get_displacements_r2(model, out, length) result(status)
    type(c_ptr), value :: model
    real(c_double), intent(inout) :: out(1, *)
    integer(c_size_t), intent(in) :: length
    integer(c_int) :: status
    status = tfem_solid_get_displacements(model, out, length)
  end function tfem_solid_get_displacements_r2

  function tfem_solid_get_displacements_i(model, out, length) result(status)
    type(c_ptr), value :: model
    real(c_double), intent(inout) :: out(*)
    integer(tfem_length_kind), intent(in) :: length
    integer(c_int) :: status
    status = tfem_solid_get_displacements(model, out, tfem_to_size_t(length))
  end function tfem_solid_get_displacements_i

  function tfem_solid_get_displacements_i_r2(model, out, length) result(status)
    type(c_ptr), value :: model
    real(c_double), intent(inout) :: out(1, *)
    integer(tfem_length_kind), intent(in) :: length
    integer(c_int) :: status
    status = tfem_solid_get_displacements(model, out, tfem_to_size_t(length))
  end function tfem_solid_get_displacements_i_r2

  function tfem_solid_get_element_strains_r2(model, out, length) result(status)
    type(c_ptr), value :: model
    real(c_double), intent(inout) :: out(1, *)
    integer(c_size_t), intent(in) :: length
    integer(c_int) :: status
    status = tfem_solid_get_element_strains(model, out, length)
  end function tfem_solid_get_element_strains_r2

  function tfem_solid_get_element_strains_i(model, out, length) result(status)
    type(c_ptr), value :: model
    real(c_double), intent(inout) :: out(*)
    integer(tfem_length_kind), intent(in) :: length
    integer(c_int) :: status
    status = tfem_solid_get_element_strains(model, out, tfem_to_size_t(length))
  end function tfem_solid_get_element_strains_i

  function tfem_solid_get_element_strains_i_r2(model, out, length) result(status)
    type(c_ptr), value :: model
    real(c_double), intent(inout) :: out(1, *)
    integer(tfem_length_kind), intent(in) :: length
    integer(c_int) :: status
    status = tfem_solid_get_element_strains(model, out, tfem_to_size_t(length))
  end function tfem_solid_get_element_strains_i_r2

  function tfem_solid_get_element_stresses_r2(model, out, length) result(status)
    type(c_ptr), value :: model
    real(c_double), intent(inout) :: out(1, *)
    integer(c_size_t), intent(in) :: length
    integer(c_int) :: status
    status = tfem_solid_get_element_stresses(model, out, length)
  end function tfem_solid_get_element_stresses_r2

  function tfem_solid_get_element_stresses_i(model, out, length) result(status)
    type(c_ptr), value :: model
    real(c_double), intent(inout) :: out(*)
    integer(tfem_length_kind), intent(in) :: length
    integer(c_int) :: status
    status = tfem_solid_get_element_stresses(model, out, tfem_to_size_t(length))
  end function tfem_solid_get_element_stresses_i

  function tfem_solid_get_element_stresses_i_r2(model, out, length) result(status)
    type(c_ptr), value :: model
    real(c_double), intent(inout) :: out(1, *)
    integer(tfem_length_kind), intent(in) :: length
    integer(c_int) :: status
    status = tfem_solid_get_element_stresses(model, out, tfem_to_size_t(length))
  end function tfem_solid_get_element_stresses_i_r2

  function tfem_solid_get_reactions_r2(model, out, length) result(status)
    type(c_ptr), value :: model
    real(c_double), intent(inout) :: out(1, *)
    integer(c_size_t), intent(in) :: length
    integer(c_int) :: status
    status = tfem_solid_get_reactions(model, out, length)
  end function tfem_solid_get_reactions_r2

  function tfem_solid_get_reactions_i(model, out, length) result(status)
    type(c_ptr), value :: model
    real(c_double), intent(inout) :: out(*)
    integer(tfem_length_kind), intent(in) :: length
    integer(c_int) :: status
    status = tfem_solid_get_reactions(model, out, tfem_to_size_t(length))
  end function tfem_solid_get_reactions_i

  function tfem_solid_get_reactions_i_r2(model, out, length) result(status)
    type(c_ptr), value :: model
    real(c_double), intent(inout) :: out(1, *)
    integer(tfem_length_kind), intent(in) :: length
    integer(c_int) :: status
    status = tfem_solid_get_reactions(model, out, tfem_to_size_t(length))
  end function tfem_solid_get_reactions_i_r2

  function tfem_solid_get_contact_tetrahedra_r2(model, out, length) result(status)
    type(c_ptr), value :: model
    integer(c_int), intent(inout) :: out(1, *)
    integer(c_size_t), intent(in) :: length
    integer(c_int) :: status
    status = tfem_solid_get_contact_tetrahedra(model, out, length)
  end function tfem_solid_get_contact_tetrahedra_r2

  function tfem_solid_get_contact_tetrahedra_i(model, out, length) result(status)
    type(c_ptr), value :: model
    integer(c_int), intent(inout) :: out(*)
    integer(tfem_length_kind), intent(in) :: length
    integer(c_int) :: status
    status = tfem_solid_get_contact_tetrahedra(model, out, tfem_to_size_t(length))
  end function tfem_solid_get_contact_tetrahedra_i

  function tfem_solid_get_contact_tetrahedra_i_r2(model, out, length) result(status)
    type(c_ptr), value :: model
    integer(c_int), intent(inout) :: out(1, *)
    integer(tfem_length_kind), intent(in) :: length
    integer(c_int) :: status
    status = tfem_solid_get_contact_tetrahedra(model, out, tfem_to_size_t(length))
  end function tfem_solid_get_contact_tetrahedra_i_r2

  function tfem_solid_get_contact_active_r2(model, out, length) result(status)
    type(c_ptr), value :: model
    integer(c_int), intent(inout) :: out(1, *)
    integer(c_size_t), intent(in) :: length
    integer(c_int) :: status
    status = tfem_solid_get_contact_active(model, out, length)
  end function tfem_solid_get_contact_active_r2

  function tfem_solid_get_contact_active_i(model, out, length) result(status)
    type(c_ptr), value :: model
    integer(c_int), intent(inout) :: out(*)
    integer(tfem_length_kind), intent(in) :: length
    integer(c_int) :: status
    status = tfem_solid_get_contact_active(model, out, tfem_to_size_t(length))
  end function tfem_solid_get_contact_active_i

  function tfem_solid_get_contact_active_i_r2(model, out, length) result(status)
    type(c_ptr), value :: model
    integer(c_int), intent(inout) :: out(1, *)
    integer(tfem_length_kind), intent(in) :: length
    integer(c_int) :: status
    status = tfem_solid_get_contact_active(model, out, tfem_to_size_t(length))
  end function tfem_solid_get_contact_active_i_r2

  function tfem_solid_get_contact_forces_r2(model, out, length) result(status)
    type(c_ptr), value :: model
    real(c_double), intent(inout) :: out(1, *)
    integer(c_size_t), intent(in) :: length
    integer(c_int) :: status
    status = tfem_solid_get_contact_forces(model, out, length)
  end function tfem_solid_get_contact_forces_r2

  function tfem_solid_get_contact_forces_i(model, out, length) result(status)
    type(c_ptr), value :: model
    real(c_double), intent(inout) :: out(*)
    integer(tfem_length_kind), intent(in) :: length
    integer(c_int) :: status
    status = tfem_solid_get_contact_forces(model, out, tfem_to_size_t(length))
  end function tfem_solid_get_contact_forces_i

  function tfem_solid_get_contact_forces_i_r2(model, out, length) result(status)
    type(c_ptr), value :: model
    real(c_double), intent(inout) :: out(1, *)
    integer(tfem_length_kind), intent(in) :: length
    integer(c_int) :: status
    status = tfem_solid_get_contact_forces(model, out, tfem_to_size_t(length))
  end function tfem_solid_get_contact_forces_i_r2

  function tfem_solid_get_contact_nodal_pressures_r2(model, out, length) result(status)
    type(c_ptr), value :: model
    real(c_double), intent(inout) :: out(1, *)
    integer(c_size_t), intent(in) :: length
    integer(c_int) :: status
    status = tfem_solid_get_contact_nodal_pressures(model, out, length)
  end function tfem_solid_get_contact_nodal_pressures_r2

  function tfem_solid_get_contact_nodal_pressures_i(model, out, length) result(status)
    type(c_ptr), value :: model
    real(c_double), intent(inout) :: out(*)
    integer(tfem_length_kind), intent(in) :: length
    integer(c_int) :: status
    status = tfem_solid_get_contact_nodal_pressures(model, out, tfem_to_size_t(length))
  end function tfem_solid_get_contact_nodal_pressures_i

  function tfem_solid_get_contact_nodal_pressures_i_r2(model, out, length) result(status)
    type(c_ptr), value :: model
    real(c_double), intent(inout) :: out(1, *)
    integer(tfem_length_kind), intent(in) :: length
    integer(c_int) :: status
    status = tfem_solid_get_contact_nodal_pressures(model, out, tfem_to_size_t(length))
  end function tfem_solid_get_contact_nodal_pressures_i_r2

  function tfem_solid_contact_create_opt(index_base, options) result(res)
    integer(c_int), value :: index_base
    type(tfem_contact_options), intent(in), optional, target :: options
    type(c_ptr) :: res
    type(c_ptr) :: options_address
    options_address = c_null_ptr
    if (present(options)) options_address = c_loc(options)
    res = tfem_solid_contact_create_by_address(index_base, options_address)
  end function tfem_solid_contact_create_opt

  function tfem_solid_contact_last_error_i(context, buffer, length) result(status)
    type(c_ptr), value :: context
    character(kind=c_char), intent(inout) :: buffer(*)
    integer(tfem_length_kind), intent(in) :: length
    integer(c_int) :: status
    status = tfem_solid_contact_last_error(context, buffer, tfem_to_size_t(length))
  end function tfem_solid_contact_last_error_i

  function tfem_solid_contact_last_error_str(context, buffer, length) result(status)
    type(c_ptr), value :: context
    character(kind=c_char, len=*), intent(inout) :: buffer
    integer(c_size_t), intent(in) :: length
    integer(c_int) :: status
    status = tfem_solid_contact_last_error(context, buffer, length)
  end function tfem_solid_contact_last_error_str

  function tfem_solid_contact_last_error_str_i(context, buffer, length) result(status)
    type(c_ptr), value :: context
    character(kind=c_char, len=*), intent(inout) :: buffer
    integer(tfem_length_kind), intent(in) :: length
    integer(c_int) :: status
    status = tfem_solid_contact_last_error(context, buffer, tfem_to_size_t(length))
  end function tfem_solid_contact_last_error_str_i

  function tfem_solid_contact_last_error_length_no_context() result(res)
    integer(c_size_t) :: res
    res = tfem_solid_contact_last_error_length(c_null_ptr)
  end function tfem_solid_contact_last_error_length_no_context

  function tfem_solid_contact_add_side_opt(context, tag, body, young, n_nodes, nodes, &
        xyz, equations, n_triangles, triangles, side) result(status)
    type(c_ptr), value :: context
    integer(c_int), value :: tag
    integer(c_int), value :: body
    real(c_double), value :: young
    integer(c_int), value :: n_nodes
    integer(c_int), intent(in) :: nodes(*)
    real(c_double), intent(in) :: xyz(*)
    integer(c_int64_t), intent(in) :: equations(*)
    integer(c_int), value :: n_triangles
    integer(c_int), intent(in) :: triangles(*)
    integer(c_int), intent(inout), optional, target :: side
    integer(c_int) :: status
    type(c_ptr) :: side_address
    side_address = c_null_ptr
    if (present(side)) side_address = c_loc(side)
    status = tfem_solid_contact_add_side_by_address(context, tag, body, young, n_nodes, nodes, xyz, &
        equations, n_triangles, triangles, side_address)
  end function tfem_solid_contact_add_side_opt

  function tfem_solid_contact_add_side_opt_r2111(context, tag, body, young, n_nodes, &
        nodes, xyz, equations, n_triangles, triangles, side) result(status)
    type(c_ptr), value :: context
    integer(c_int), value :: tag
    integer(c_int), value :: body
    real(c_double), value :: young
    integer(c_int), value :: n_nodes
    integer(c_int), intent(in) :: nodes(1, *)
    real(c_double), intent(in) :: xyz(*)
    integer(c_int64_t), intent(in) :: equations(*)
    integer(c_int), value :: n_triangles
    integer(c_int), intent(in) :: triangles(*)
    integer(c_int), intent(inout), optional, target :: side
    integer(c_int) :: status
    type(c_ptr) :: side_address
    side_address = c_null_ptr
    if (present(side)) side_address = c_loc(side)
    status = tfem_solid_contact_add_side_by_address(context, tag, body, young, n_nodes, nodes, xyz, &
        equations, n_triangles, triangles, side_address)
  end function tfem_solid_contact_add_side_opt_r2111

  function tfem_solid_contact_add_side_opt_r1211(context, tag, body, young, n_nodes, &
        nodes, xyz, equations, n_triangles, triangles, side) result(status)
    type(c_ptr), value :: context
    integer(c_int), value :: tag
    integer(c_int), value :: body
    real(c_double), value :: young
    integer(c_int), value :: n_nodes
    integer(c_int), intent(in) :: nodes(*)
    real(c_double), intent(in) :: xyz(1, *)
    integer(c_int64_t), intent(in) :: equations(*)
    integer(c_int), value :: n_triangles
    integer(c_int), intent(in) :: triangles(*)
    integer(c_int), intent(inout), optional, target :: side
    integer(c_int) :: status
    type(c_ptr) :: side_address
    side_address = c_null_ptr
    if (present(side)) side_address = c_loc(side)
    status = tfem_solid_contact_add_side_by_address(context, tag, body, young, n_nodes, nodes, xyz, &
        equations, n_triangles, triangles, side_address)
  end function tfem_solid_contact_add_side_opt_r1211

  function tfem_solid_contact_add_side_opt_r2211(context, tag, body, young, n_nodes, &
        nodes, xyz, equations, n_triangles, triangles, side) result(status)
    type(c_ptr), value :: context
    integer(c_int), value :: tag
    integer(c_int), value :: body
    real(c_double), value :: young
    integer(c_int), value :: n_nodes
    integer(c_int), intent(in) :: nodes(1, *)
    real(c_double), intent(in) :: xyz(1, *)
    integer(c_int64_t), intent(in) :: equations(*)
    integer(c_int), value :: n_triangles
    integer(c_int), intent(in) :: triangles(*)
    integer(c_int), intent(inout), optional, target :: side
    integer(c_int) :: status
    type(c_ptr) :: side_address
    side_address = c_null_ptr
    if (present(side)) side_address = c_loc(side)
    status = tfem_solid_contact_add_side_by_address(context, tag, body, young, n_nodes, nodes, xyz, &
        equations, n_triangles, triangles, side_address)
  end function tfem_solid_contact_add_side_opt_r2211

  function tfem_solid_contact_add_side_opt_r1121(context, tag, body, young, n_nodes, &
        nodes, xyz, equations, n_triangles, triangles, side) result(status)
    type(c_ptr), value :: context
    integer(c_int), value :: tag
    integer(c_int), value :: body
    real(c_double), value :: young
    integer(c_int), value :: n_nodes
    integer(c_int), intent(in) :: nodes(*)
    real(c_double), intent(in) :: xyz(*)
    integer(c_int64_t), intent(in) :: equations(1, *)
    integer(c_int), value :: n_triangles
    integer(c_int), intent(in) :: triangles(*)
    integer(c_int), intent(inout), optional, target :: side
    integer(c_int) :: status
    type(c_ptr) :: side_address
    side_address = c_null_ptr
    if (present(side)) side_address = c_loc(side)
    status = tfem_solid_contact_add_side_by_address(context, tag, body, young, n_nodes, nodes, xyz, &
        equations, n_triangles, triangles, side_address)
  end function tfem_solid_contact_add_side_opt_r1121

  function tfem_solid_contact_add_side_opt_r2121(context, tag, body, young, n_nodes, &
        nodes, xyz, equations, n_triangles, triangles, side) result(status)
    type(c_ptr), value :: context
    integer(c_int), value :: tag
    integer(c_int), value :: body
    real(c_double), value :: young
    integer(c_int), value :: n_nodes
    integer(c_int), intent(in) :: nodes(1, *)
    real(c_double), intent(in) :: xyz(*)
    integer(c_int64_t), intent(in) :: equations(1, *)
    integer(c_int), value :: n_triangles
    integer(c_int), intent(in) :: triangles(*)
    integer(c_int), intent(inout), optional, target :: side
    integer(c_int) :: status
    type(c_ptr) :: side_address
    side_address = c_null_ptr
    if (present(side)) side_address = c_loc(side)
    status = tfem_solid_contact_add_side_by_address(context, tag, body, young, n_nodes, nodes, xyz, &
        equations, n_triangles, triangles, side_address)
  end function tfem_solid_contact_add_side_opt_r2121

  function tfem_solid_contact_add_side_opt_r1221(context, tag, body, young, n_nodes, &
        nodes, xyz, equations, n_triangles, triangles, side) result(status)
    type(c_ptr), value :: context
    integer(c_int), value :: tag
    integer(c_int), value :: body
    real(c_double), value :: young
    integer(c_int), value :: n_nodes
    integer(c_int), intent(in) :: nodes(*)
    real(c_double), intent(in) :: xyz(1, *)
    integer(c_int64_t), intent(in) :: equations(1, *)
    integer(c_int), value :: n_triangles
    integer(c_int), intent(in) :: triangles(*)
    integer(c_int), intent(inout), optional, target :: side
    integer(c_int) :: status
    type(c_ptr) :: side_address
    side_address = c_null_ptr
    if (present(side)) side_address = c_loc(side)
    status = tfem_solid_contact_add_side_by_address(context, tag, body, young, n_nodes, nodes, xyz, &
        equations, n_triangles, triangles, side_address)
  end function tfem_solid_contact_add_side_opt_r1221

  function tfem_solid_contact_add_side_opt_r2221(context, tag, body, young, n_nodes, &
        nodes, xyz, equations, n_triangles, triangles, side) result(status)
    type(c_ptr), value :: context
    integer(c_int), value :: tag
    integer(c_int), value :: body
    real(c_double), value :: young
    integer(c_int), value :: n_nodes
    integer(c_int), intent(in) :: nodes(1, *)
    real(c_double), intent(in) :: xyz(1, *)
    integer(c_int64_t), intent(in) :: equations(1, *)
    integer(c_int), value :: n_triangles
    integer(c_int), intent(in) :: triangles(*)
    integer(c_int), intent(inout), optional, target :: side
    integer(c_int) :: status
    type(c_ptr) :: side_address
    side_address = c_null_ptr
    if (present(side)) side_address = c_loc(side)
    status = tfem_solid_contact_add_side_by_address(context, tag, body, young, n_nodes, nodes, xyz, &
        equations, n_triangles, triangles, side_address)
  end function tfem_solid_contact_add_side_opt_r2221

  function tfem_solid_contact_add_side_opt_r1112(context, tag, body, young, n_nodes, &
        nodes, xyz, equations, n_triangles, triangles, side) result(status)
    type(c_ptr), value :: context
    integer(c_int), value :: tag
    integer(c_int), value :: body
    real(c_double), value :: young
    integer(c_int), value :: n_nodes
    integer(c_int), intent(in) :: nodes(*)
    real(c_double), intent(in) :: xyz(*)
    integer(c_int64_t), intent(in) :: equations(*)
    integer(c_int), value :: n_triangles
    integer(c_int), intent(in) :: triangles(1, *)
    integer(c_int), intent(inout), optional, target :: side
    integer(c_int) :: status
    type(c_ptr) :: side_address
    side_address = c_null_ptr
    if (present(side)) side_address = c_loc(side)
    status = tfem_solid_contact_add_side_by_address(context, tag, body, young, n_nodes, nodes, xyz, &
        equations, n_triangles, triangles, side_address)
  end function tfem_solid_contact_add_side_opt_r1112

  function tfem_solid_contact_add_side_opt_r2112(context, tag, body, young, n_nodes, &
        nodes, xyz, equations, n_triangles, triangles, side) result(status)
    type(c_ptr), value :: context
    integer(c_int), value :: tag
    integer(c_int), value :: body
    real(c_double), value :: young
    integer(c_int), value :: n_nodes
    integer(c_int), intent(in) :: nodes(1, *)
    real(c_double), intent(in) :: xyz(*)
    integer(c_int64_t), intent(in) :: equations(*)
    integer(c_int), value :: n_triangles
    integer(c_int), intent(in) :: triangles(1, *)
    integer(c_int), intent(inout), optional, target :: side
    integer(c_int) :: status
    type(c_ptr) :: side_address
    side_address = c_null_ptr
    if (present(side)) side_address = c_loc(side)
    status = tfem_solid_contact_add_side_by_address(context, tag, body, young, n_nodes, nodes, xyz, &
        equations, n_triangles, triangles, side_address)
  end function tfem_solid_contact_add_side_opt_r2112

  function tfem_solid_contact_add_side_opt_r1212(context, tag, body, young, n_nodes, &
        nodes, xyz, equations, n_triangles, triangles, side) result(status)
    type(c_ptr), value :: context
    integer(c_int), value :: tag
    integer(c_int), value :: body
    real(c_double), value :: young
    integer(c_int), value :: n_nodes
    integer(c_int), intent(in) :: nodes(*)
    real(c_double), intent(in) :: xyz(1, *)
    integer(c_int64_t), intent(in) :: equations(*)
    integer(c_int), value :: n_triangles
    integer(c_int), intent(in) :: triangles(1, *)
    integer(c_int), intent(inout), optional, target :: side
    integer(c_int) :: status
    type(c_ptr) :: side_address
    side_address = c_null_ptr
    if (present(side)) side_address = c_loc(side)
    status = tfem_solid_contact_add_side_by_address(context, tag, body, young, n_nodes, nodes, xyz, &
        equations, n_triangles, triangles, side_address)
  end function tfem_solid_contact_add_side_opt_r1212

  function tfem_solid_contact_add_side_opt_r2212(context, tag, body, young, n_nodes, &
        nodes, xyz, equations, n_triangles, triangles, side) result(status)
    type(c_ptr), value :: context
    integer(c_int), value :: tag
    integer(c_int), value :: body
    real(c_double), value :: young
    integer(c_int), value :: n_nodes
    integer(c_int), intent(in) :: nodes(1, *)
    real(c_double), intent(in) :: xyz(1, *)
    integer(c_int64_t), intent(in) :: equations(*)
    integer(c_int), value :: n_triangles
    integer(c_int), intent(in) :: triangles(1, *)
    integer(c_int), intent(inout), optional, target :: side
    integer(c_int) :: status
    type(c_ptr) :: side_address
    side_address = c_null_ptr
    if (present(side)) side_address = c_loc(side)
    status = tfem_solid_contact_add_side_by_address(context, tag, body, young, n_nodes, nodes, xyz, &
        equations, n_triangles, triangles, side_address)
  end function tfem_solid_contact_add_side_opt_r2212

  function tfem_solid_contact_add_side_opt_r1122(context, tag, body, young, n_nodes, &
        nodes, xyz, equations, n_triangles, triangles, side) result(status)
    type(c_ptr), value :: context
    integer(c_int), value :: tag
    integer(c_int), value :: body
    real(c_double), value :: young
    integer(c_int), value :: n_nodes
    integer(c_int), intent(in) :: nodes(*)
    real(c_double), intent(in) :: xyz(*)
    integer(c_int64_t), intent(in) :: equations(1, *)
    integer(c_int), value :: n_triangles
    integer(c_int), intent(in) :: triangles(1, *)
    integer(c_int), intent(inout), optional, target :: side
    integer(c_int) :: status
    type(c_ptr) :: side_address
    side_address = c_null_ptr
    if (present(side)) side_address = c_loc(side)
    status = tfem_solid_contact_add_side_by_address(context, tag, body, young, n_nodes, nodes, xyz, &
        equations, n_triangles, triangles, side_address)
  end function tfem_solid_contact_add_side_opt_r1122

  function tfem_solid_contact_add_side_opt_r2122(context, tag, body, young, n_nodes, &
        nodes, xyz, equations, n_triangles, triangles, side) result(status)
    type(c_ptr), value :: context
    integer(c_int), value :: tag
    integer(c_int), value :: body
    real(c_double), value :: young
    integer(c_int), value :: n_nodes
    integer(c_int), intent(in) :: nodes(1, *)
    real(c_double), intent(in) :: xyz(*)
    integer(c_int64_t), intent(in) :: equations(1, *)
    integer(c_int), value :: n_triangles
    integer(c_int), intent(in) :: triangles(1, *)
    integer(c_int), intent(inout), optional, target :: side
    integer(c_int) :: status
    type(c_ptr) :: side_address
    side_address = c_null_ptr
    if (present(side)) side_address = c_loc(side)
    status = tfem_solid_contact_add_side_by_address(context, tag, body, young, n_nodes, nodes, xyz, &
        equations, n_triangles, triangles, side_address)
  end function tfem_solid_contact_add_side_opt_r2122

  function tfem_solid_contact_add_side_opt_r1222(context, tag, body, young, n_nodes, &
        nodes, xyz, equations, n_triangles, triangles, side) result(status)
    type(c_ptr), value :: context
    integer(c_int), value :: tag
    integer(c_int), value :: body
    real(c_double), value :: young
    integer(c_int), value :: n_nodes
    integer(c_int), intent(in) :: nodes(*)
    real(c_double), intent(in) :: xyz(1, *)
    integer(c_int64_t), intent(in) :: equations(1, *)
    integer(c_int), value :: n_triangles
    integer(c_int), intent(in) :: triangles(1, *)
    integer(c_int), intent(inout), optional, target :: side
    integer(c_int) :: status
    type(c_ptr) :: side_address
    side_address = c_null_ptr
    if (present(side)) side_address = c_loc(side)
    status = tfem_solid_contact_add_side_by_address(context, tag, body, young, n_nodes, nodes, xyz, &
        equations, n_triangles, triangles, side_address)
  end function tfem_solid_contact_add_side_opt_r1222

  function tfem_solid_contact_add_side_opt_r2222(context, tag, body, young, n_nodes, &
        nodes, xyz, equations, n_triangles, triangles, side) result(status)
    type(c_ptr), value :: context
    integer(c_int), value :: tag
    integer(c_int), value :: body
    real(c_double), value :: young
    integer(c_int), value :: n_nodes
    integer(c_int), intent(in) :: nodes(1, *)
    real(c_double), intent(in) :: xyz(1, *)
    integer(c_int64_t), intent(in) :: equations(1, *)
    integer(c_int), value :: n_triangles
    integer(c_int), intent(in) :: triangles(1, *)
    integer(c_int), intent(inout), optional, target :: side
    integer(c_int) :: status
    type(c_ptr) :: side_address
    side_address = c_null_ptr
    if (present(side)) side_address = c_loc(side)
    status = tfem_solid_contact_add_side_by_address(context, tag, body, young, n_nodes, nodes, xyz, &
        equations, n_triangles, triangles, side_address)
  end function tfem_solid_contact_add_side_opt_r2222

  function tfem_solid_contact_add_pair_opt(context, side_a, side_b, pair) result(status)
    type(c_ptr), value :: context
    integer(c_int), value :: side_a
    integer(c_int), value :: side_b
    integer(c_int), intent(inout), optional, target :: pair
    integer(c_int) :: status
    type(c_ptr) :: pair_address
    pair_address = c_null_ptr
    if (present(pair)) pair_address = c_loc(pair)
    status = tfem_solid_contact_add_pair_by_address(context, side_a, side_b, pair_address)
  end function tfem_solid_contact_add_pair_opt

  function tfem_solid_contact_sizes_opt(context, n_nodes, n_tetrahedra, n_entries) result(status)
    type(c_ptr), value :: context
    integer(c_int), intent(inout), optional, target :: n_nodes
    integer(c_int), intent(inout), optional, target :: n_tetrahedra
    integer(c_int64_t), intent(inout), optional, target :: n_entries
    integer(c_int) :: status
    type(c_ptr) :: n_nodes_address
    type(c_ptr) :: n_tetrahedra_address
    type(c_ptr) :: n_entries_address
    n_nodes_address = c_null_ptr
    if (present(n_nodes)) n_nodes_address = c_loc(n_nodes)
    n_tetrahedra_address = c_null_ptr
    if (present(n_tetrahedra)) n_tetrahedra_address = c_loc(n_tetrahedra)
    n_entries_address = c_null_ptr
    if (present(n_entries)) n_entries_address = c_loc(n_entries)
    status = tfem_solid_contact_sizes_by_address(context, n_nodes_address, n_tetrahedra_address, &
        n_entries_address)
  end function tfem_solid_contact_sizes_opt

  function tfem_solid_contact_nodes_r2(context, out, length) result(status)
    type(c_ptr), value :: context
    integer(c_int), intent(inout) :: out(1, *)
    integer(c_size_t), intent(in) :: length
    integer(c_int) :: status
    status = tfem_solid_contact_nodes(context, out, length)
  end function tfem_solid_contact_nodes_r2

  function tfem_solid_contact_nodes_i(context, out, length) result(status)
    type(c_ptr), value :: context
    integer(c_int), intent(inout) :: out(*)
    integer(tfem_length_kind), intent(in) :: length
    integer(c_int) :: status
    status = tfem_solid_contact_nodes(context, out, tfem_to_size_t(length))
  end function tfem_solid_contact_nodes_i

  function tfem_solid_contact_nodes_i_r2(context, out, length) result(status)
    type(c_ptr), value :: context
    integer(c_int), intent(inout) :: out(1, *)
    integer(tfem_length_kind), intent(in) :: length
    integer(c_int) :: status
    status = tfem_solid_contact_nodes(context, out, tfem_to_size_t(length))
  end function tfem_solid_contact_nodes_i_r2

  function tfem_solid_contact_tetrahedra_r2(context, out, length) result(status)
    type(c_ptr), value :: context
    integer(c_int), intent(inout) :: out(1, *)
    integer(c_size_t), intent(in) :: length
    integer(c_int) :: status
    status = tfem_solid_contact_tetrahedra(context, out, length)
  end function tfem_solid_contact_tetrahedra_r2

  function tfem_solid_contact_tetrahedra_i(context, out, length) result(status)
    type(c_ptr), value :: context
    integer(c_int), intent(inout) :: out(*)
    integer(tfem_length_kind), intent(in) :: length
    integer(c_int) :: status
    status = tfem_solid_contact_tetrahedra(context, out, tfem_to_size_t(length))
  end function tfem_solid_contact_tetrahedra_i

  function tfem_solid_contact_tetrahedra_i_r2(context, out, length) result(status)
    type(c_ptr), value :: context
    integer(c_int), intent(inout) :: out(1, *)
    integer(tfem_length_kind), intent(in) :: length
    integer(c_int) :: status
    status = tfem_solid_contact_tetrahedra(context, out, tfem_to_size_t(length))
  end function tfem_solid_contact_tetrahedra_i_r2

  function tfem_solid_contact_pattern_r21(context, rows, cols, length) result(status)
    type(c_ptr), value :: context
    integer(c_int64_t), intent(inout) :: rows(1, *)
    integer(c_int64_t), intent(inout) :: cols(*)
    integer(c_size_t), intent(in) :: length
    integer(c_int) :: status
    status = tfem_solid_contact_pattern(context, rows, cols, length)
  end function tfem_solid_contact_pattern_r21

  function tfem_solid_contact_pattern_r12(context, rows, cols, length) result(status)
    type(c_ptr), value :: context
    integer(c_int64_t), intent(inout) :: rows(*)
    integer(c_int64_t), intent(inout) :: cols(1, *)
    integer(c_size_t), intent(in) :: length
    integer(c_int) :: status
    status = tfem_solid_contact_pattern(context, rows, cols, length)
  end function tfem_solid_contact_pattern_r12

  function tfem_solid_contact_pattern_r22(context, rows, cols, length) result(status)
    type(c_ptr), value :: context
    integer(c_int64_t), intent(inout) :: rows(1, *)
    integer(c_int64_t), intent(inout) :: cols(1, *)
    integer(c_size_t), intent(in) :: length
    integer(c_int) :: status
    status = tfem_solid_contact_pattern(context, rows, cols, length)
  end function tfem_solid_contact_pattern_r22

  function tfem_solid_contact_pattern_i(context, rows, cols, length) result(status)
    type(c_ptr), value :: context
    integer(c_int64_t), intent(inout) :: rows(*)
    integer(c_int64_t), intent(inout) :: cols(*)
    integer(tfem_length_kind), intent(in) :: length
    integer(c_int) :: status
    status = tfem_solid_contact_pattern(context, rows, cols, tfem_to_size_t(length))
  end function tfem_solid_contact_pattern_i

  function tfem_solid_contact_pattern_i_r21(context, rows, cols, length) result(status)
    type(c_ptr), value :: context
    integer(c_int64_t), intent(inout) :: rows(1, *)
    integer(c_int64_t), intent(inout) :: cols(*)
    integer(tfem_length_kind), intent(in) :: length
    integer(c_int) :: status
    status = tfem_solid_contact_pattern(context, rows, cols, tfem_to_size_t(length))
  end function tfem_solid_contact_pattern_i_r21

  function tfem_solid_contact_pattern_i_r12(context, rows, cols, length) result(status)
    type(c_ptr), value :: context
    integer(c_int64_t), intent(inout) :: rows(*)
    integer(c_int64_t), intent(inout) :: cols(1, *)
    integer(tfem_length_kind), intent(in) :: length
    integer(c_int) :: status
    status = tfem_solid_contact_pattern(context, rows, cols, tfem_to_size_t(length))
  end function tfem_solid_contact_pattern_i_r12

  function tfem_solid_contact_pattern_i_r22(context, rows, cols, length) result(status)
    type(c_ptr), value :: context
    integer(c_int64_t), intent(inout) :: rows(1, *)
    integer(c_int64_t), intent(inout) :: cols(1, *)
    integer(tfem_length_kind), intent(in) :: length
    integer(c_int) :: status
    status = tfem_solid_contact_pattern(context, rows, cols, tfem_to_size_t(length))
  end function tfem_solid_contact_pattern_i_r22

  function tfem_solid_contact_element_equations_r2(context, out, length) result(status)
    type(c_ptr), value :: context
    integer(c_int64_t), intent(inout) :: out(1, *)
    integer(c_size_t), intent(in) :: length
    integer(c_int) :: status
    status = tfem_solid_contact_element_equations(context, out, length)
  end function tfem_solid_contact_element_equations_r2

  function tfem_solid_contact_element_equations_i(context, out, length) result(status)
    type(c_ptr), value :: context
    integer(c_int64_t), intent(inout) :: out(*)
    integer(tfem_length_kind), intent(in) :: length
    integer(c_int) :: status
    status = tfem_solid_contact_element_equations(context, out, tfem_to_size_t(length))
  end function tfem_solid_contact_element_equations_i

  function tfem_solid_contact_element_equations_i_r2(context, out, length) result(status)
    type(c_ptr), value :: context
    integer(c_int64_t), intent(inout) :: out(1, *)
    integer(tfem_length_kind), intent(in) :: length
    integer(c_int) :: status
    status = tfem_solid_contact_element_equations(context, out, tfem_to_size_t(length))
  end function tfem_solid_contact_element_equations_i_r2

  function tfem_solid_contact_element_blocks_r2(context, out, length) result(status)
    type(c_ptr), value :: context
    real(c_double), intent(inout) :: out(1, *)
    integer(c_size_t), intent(in) :: length
    integer(c_int) :: status
    status = tfem_solid_contact_element_blocks(context, out, length)
  end function tfem_solid_contact_element_blocks_r2

  function tfem_solid_contact_element_blocks_i(context, out, length) result(status)
    type(c_ptr), value :: context
    real(c_double), intent(inout) :: out(*)
    integer(tfem_length_kind), intent(in) :: length
    integer(c_int) :: status
    status = tfem_solid_contact_element_blocks(context, out, tfem_to_size_t(length))
  end function tfem_solid_contact_element_blocks_i

  function tfem_solid_contact_element_blocks_i_r2(context, out, length) result(status)
    type(c_ptr), value :: context
    real(c_double), intent(inout) :: out(1, *)
    integer(tfem_length_kind), intent(in) :: length
    integer(c_int) :: status
    status = tfem_solid_contact_element_blocks(context, out, tfem_to_size_t(length))
  end function tfem_solid_contact_element_blocks_i_r2

  function tfem_solid_contact_evaluate_opt(context, u, u_length, values, values_length, &
        residual, residual_length) result(status)
    type(c_ptr), value :: context
    real(c_double), intent(in) :: u(*)
    integer(c_size_t), intent(in) :: u_length
    real(c_double), intent(inout), optional, target :: values(*)
    integer(c_size_t), intent(in) :: values_length
    real(c_double), intent(inout), optional, target :: residual(*)
    integer(c_size_t), intent(in) :: residual_length
    integer(c_int) :: status
    type(c_ptr) :: values_address
    type(c_ptr) :: residual_address
    values_address = tfem_address_c_double(values, values_length /= 0)
    residual_address = tfem_address_c_double(residual, residual_length /= 0)
    status = tfem_solid_contact_evaluate_by_address(context, u, u_length, values_address, &
        values_length, residual_address, residual_length)
  end function tfem_solid_contact_evaluate_opt

  function tfem_solid_contact_evaluate_opt_r211(context, u, u_length, values, &
        values_length, residual, residual_length) result(status)
    type(c_ptr), value :: context
    real(c_double), intent(in) :: u(1, *)
    integer(c_size_t), intent(in) :: u_length
    real(c_double), intent(inout), optional, target :: values(*)
    integer(c_size_t), intent(in) :: values_length
    real(c_double), intent(inout), optional, target :: residual(*)
    integer(c_size_t), intent(in) :: residual_length
    integer(c_int) :: status
    type(c_ptr) :: values_address
    type(c_ptr) :: residual_address
    values_address = tfem_address_c_double(values, values_length /= 0)
    residual_address = tfem_address_c_double(residual, residual_length /= 0)
    status = tfem_solid_contact_evaluate_by_address(context, u, u_length, values_address, &
        values_length, residual_address, residual_length)
  end function tfem_solid_contact_evaluate_opt_r211

  function tfem_solid_contact_evaluate_opt_r121(context, u, u_length, values, &
        values_length, residual, residual_length) result(status)
    type(c_ptr), value :: context
    real(c_double), intent(in) :: u(*)
    integer(c_size_t), intent(in) :: u_length
    real(c_double), intent(inout), target :: values(1, *)
    integer(c_size_t), intent(in) :: values_length
    real(c_double), intent(inout), optional, target :: residual(*)
    integer(c_size_t), intent(in) :: residual_length
    integer(c_int) :: status
    type(c_ptr) :: values_address
    type(c_ptr) :: residual_address
    values_address = tfem_address_c_double(values, values_length /= 0)
    residual_address = tfem_address_c_double(residual, residual_length /= 0)
    status = tfem_solid_contact_evaluate_by_address(context, u, u_length, values_address, &
        values_length, residual_address, residual_length)
  end function tfem_solid_contact_evaluate_opt_r121

  function tfem_solid_contact_evaluate_opt_r221(context, u, u_length, values, &
        values_length, residual, residual_length) result(status)
    type(c_ptr), value :: context
    real(c_double), intent(in) :: u(1, *)
    integer(c_size_t), intent(in) :: u_length
    real(c_double), intent(inout), target :: values(1, *)
    integer(c_size_t), intent(in) :: values_length
    real(c_double), intent(inout), optional, target :: residual(*)
    integer(c_size_t), intent(in) :: residual_length
    integer(c_int) :: status
    type(c_ptr) :: values_address
    type(c_ptr) :: residual_address
    values_address = tfem_address_c_double(values, values_length /= 0)
    residual_address = tfem_address_c_double(residual, residual_length /= 0)
    status = tfem_solid_contact_evaluate_by_address(context, u, u_length, values_address, &
        values_length, residual_address, residual_length)
  end function tfem_solid_contact_evaluate_opt_r221

  function tfem_solid_contact_evaluate_opt_r112(context, u, u_length, values, &
        values_length, residual, residual_length) result(status)
    type(c_ptr), value :: context
    real(c_double), intent(in) :: u(*)
    integer(c_size_t), intent(in) :: u_length
    real(c_double), intent(inout), optional, target :: values(*)
    integer(c_size_t), intent(in) :: values_length
    real(c_double), intent(inout), target :: residual(1, *)
    integer(c_size_t), intent(in) :: residual_length
    integer(c_int) :: status
    type(c_ptr) :: values_address
    type(c_ptr) :: residual_address
    values_address = tfem_address_c_double(values, values_length /= 0)
    residual_address = tfem_address_c_double(residual, residual_length /= 0)
    status = tfem_solid_contact_evaluate_by_address(context, u, u_length, values_address, &
        values_length, residual_address, residual_length)
  end function tfem_solid_contact_evaluate_opt_r112

  function tfem_solid_contact_evaluate_opt_r212(context, u, u_length, values, &
        values_length, residual, residual_length) result(status)
    type(c_ptr), value :: context
    real(c_double), intent(in) :: u(1, *)
    integer(c_size_t), intent(in) :: u_length
    real(c_double), intent(inout), optional, target :: values(*)
    integer(c_size_t), intent(in) :: values_length
    real(c_double), intent(inout), target :: residual(1, *)
    integer(c_size_t), intent(in) :: residual_length
    integer(c_int) :: status
    type(c_ptr) :: values_address
    type(c_ptr) :: residual_address
    values_address = tfem_address_c_double(values, values_length /= 0)
    residual_address = tfem_address_c_double(residual, residual_length /= 0)
    status = tfem_solid_contact_evaluate_by_address(context, u, u_length, values_address, &
        values_length, residual_address, residual_length)
  end function tfem_solid_contact_evaluate_opt_r212

  function tfem_solid_contact_evaluate_opt_r122(context, u, u_length, values, &
        values_length, residual, residual_length) result(status)
    type(c_ptr), value :: context
    real(c_double), intent(in) :: u(*)
    integer(c_size_t), intent(in) :: u_length
    real(c_double), intent(inout), target :: values(1, *)
    integer(c_size_t), intent(in) :: values_length
    real(c_double), intent(inout), target :: residual(1, *)
    integer(c_size_t), intent(in) :: residual_length
    integer(c_int) :: status
    type(c_ptr) :: values_address
    type(c_ptr) :: residual_address
    values_address = tfem_address_c_double(values, values_length /= 0)
    residual_address = tfem_address_c_double(residual, residual_length /= 0)
    status = tfem_solid_contact_evaluate_by_address(context, u, u_length, values_address, &
        values_length, residual_address, residual_length)
  end function tfem_solid_contact_evaluate_opt_r122

  function tfem_solid_contact_evaluate_opt_r222(context, u, u_length, values, &
        values_length, residual, residual_length) result(status)
    type(c_ptr), value :: context
    real(c_double), intent(in) :: u(1, *)
    integer(c_size_t), intent(in) :: u_length
    real(c_double), intent(inout), target :: values(1, *)
    integer(c_size_t), intent(in) :: values_length
    real(c_double), intent(inout), target :: residual(1, *)
    integer(c_size_t), intent(in) :: residual_length
    integer(c_int) :: status
    type(c_ptr) :: values_address
    type(c_ptr) :: residual_address
    values_address = tfem_address_c_double(values, values_length /= 0)
    residual_address = tfem_address_c_double(residual, residual_length /= 0)
    status = tfem_solid_contact_evaluate_by_address(context, u, u_length, values_address, &
        values_length, residual_address, residual_length)
  end function tfem_solid_contact_evaluate_opt_r222

  function tfem_solid_contact_evaluate_opt_i(context, u, u_length, values, &
        values_length, residual, residual_length) result(status)
    type(c_ptr), value :: context
    real(c_double), intent(in) :: u(*)
    integer(tfem_length_kind), intent(in) :: u_length
    real(c_double), intent(inout), optional, target :: values(*)
    integer(tfem_length_kind), intent(in) :: values_length
    real(c_double), intent(inout), optional, target :: residual(*)
    integer(tfem_length_kind), intent(in) :: residual_length
    integer(c_int) :: status
    type(c_ptr) :: values_address
    type(c_ptr) :: residual_address
    values_address = tfem_address_c_double(values, values_length > 0)
    residual_address = tfem_address_c_double(residual, residual_length > 0)
    status = tfem_solid_contact_evaluate_by_address(context, u, tfem_to_size_t(u_length), &
        values_address, tfem_to_size_t(values_length), residual_address, &
        tfem_to_size_t(residual_length))
  end function tfem_solid_contact_evaluate_opt_i

  function tfem_solid_contact_evaluate_opt_i_r211(context, u, u_length, values, &
        values_length, residual, residual_length) result(status)
    type(c_ptr), value :: context
    real(c_double), intent(in) :: u(1, *)
    integer(tfem_length_kind), intent(in) :: u_length
    real(c_double), intent(inout), optional, target :: values(*)
    integer(tfem_length_kind), intent(in) :: values_length
    real(c_double), intent(inout), optional, target :: residual(*)
    integer(tfem_length_kind), intent(in) :: residual_length
    integer(c_int) :: status
    type(c_ptr) :: values_address
    type(c_ptr) :: residual_address
    values_address = tfem_address_c_double(values, values_length > 0)
    residual_address = tfem_address_c_double(residual, residual_length > 0)
    status = tfem_solid_contact_evaluate_by_address(context, u, tfem_to_size_t(u_length), &
        values_address, tfem_to_size_t(values_length), residual_address, &
        tfem_to_size_t(residual_length))
  end function tfem_solid_contact_evaluate_opt_i_r211

  function tfem_solid_contact_evaluate_opt_i_r121(context, u, u_length, values, &
        values_length, residual, residual_length) result(status)
    type(c_ptr), value :: context
    real(c_double), intent(in) :: u(*)
    integer(tfem_length_kind), intent(in) :: u_length
    real(c_double), intent(inout), target :: values(1, *)
    integer(tfem_length_kind), intent(in) :: values_length
    real(c_double), intent(inout), optional, target :: residual(*)
    integer(tfem_length_kind), intent(in) :: residual_length
    integer(c_int) :: status
    type(c_ptr) :: values_address
    type(c_ptr) :: residual_address
    values_address = tfem_address_c_double(values, values_length > 0)
    residual_address = tfem_address_c_double(residual, residual_length > 0)
    status = tfem_solid_contact_evaluate_by_address(context, u, tfem_to_size_t(u_length), &
        values_address, tfem_to_size_t(values_length), residual_address, &
        tfem_to_size_t(residual_length))
  end function tfem_solid_contact_evaluate_opt_i_r121

  function tfem_solid_contact_evaluate_opt_i_r221(context, u, u_length, values, &
        values_length, residual, residual_length) result(status)
    type(c_ptr), value :: context
    real(c_double), intent(in) :: u(1, *)
    integer(tfem_length_kind), intent(in) :: u_length
    real(c_double), intent(inout), target :: values(1, *)
    integer(tfem_length_kind), intent(in) :: values_length
    real(c_double), intent(inout), optional, target :: residual(*)
    integer(tfem_length_kind), intent(in) :: residual_length
    integer(c_int) :: status
    type(c_ptr) :: values_address
    type(c_ptr) :: residual_address
    values_address = tfem_address_c_double(values, values_length > 0)
    residual_address = tfem_address_c_double(residual, residual_length > 0)
    status = tfem_solid_contact_evaluate_by_address(context, u, tfem_to_size_t(u_length), &
        values_address, tfem_to_size_t(values_length), residual_address, &
        tfem_to_size_t(residual_length))
  end function tfem_solid_contact_evaluate_opt_i_r221

  function tfem_solid_contact_evaluate_opt_i_r112(context, u, u_length, values, &
        values_length, residual, residual_length) result(status)
    type(c_ptr), value :: context
    real(c_double), intent(in) :: u(*)
    integer(tfem_length_kind), intent(in) :: u_length
    real(c_double), intent(inout), optional, target :: values(*)
    integer(tfem_length_kind), intent(in) :: values_length
    real(c_double), intent(inout), target :: residual(1, *)
    integer(tfem_length_kind), intent(in) :: residual_length
    integer(c_int) :: status
    type(c_ptr) :: values_address
    type(c_ptr) :: residual_address
    values_address = tfem_address_c_double(values, values_length > 0)
    residual_address = tfem_address_c_double(residual, residual_length > 0)
    status = tfem_solid_contact_evaluate_by_address(context, u, tfem_to_size_t(u_length), &
        values_address, tfem_to_size_t(values_length), residual_address, &
        tfem_to_size_t(residual_length))
  end function tfem_solid_contact_evaluate_opt_i_r112

  function tfem_solid_contact_evaluate_opt_i_r212(context, u, u_length, values, &
        values_length, residual, residual_length) result(status)
    type(c_ptr), value :: context
    real(c_double), intent(in) :: u(1, *)
    integer(tfem_length_kind), intent(in) :: u_length
    real(c_double), intent(inout), optional, target :: values(*)
    integer(tfem_length_kind), intent(in) :: values_length
    real(c_double), intent(inout), target :: residual(1, *)
    integer(tfem_length_kind), intent(in) :: residual_length
    integer(c_int) :: status
    type(c_ptr) :: values_address
    type(c_ptr) :: residual_address
    values_address = tfem_address_c_double(values, values_length > 0)
    residual_address = tfem_address_c_double(residual, residual_length > 0)
    status = tfem_solid_contact_evaluate_by_address(context, u, tfem_to_size_t(u_length), &
        values_address, tfem_to_size_t(values_length), residual_address, &
        tfem_to_size_t(residual_length))
  end function tfem_solid_contact_evaluate_opt_i_r212

  function tfem_solid_contact_evaluate_opt_i_r122(context, u, u_length, values, &
        values_length, residual, residual_length) result(status)
    type(c_ptr), value :: context
    real(c_double), intent(in) :: u(*)
    integer(tfem_length_kind), intent(in) :: u_length
    real(c_double), intent(inout), target :: values(1, *)
    integer(tfem_length_kind), intent(in) :: values_length
    real(c_double), intent(inout), target :: residual(1, *)
    integer(tfem_length_kind), intent(in) :: residual_length
    integer(c_int) :: status
    type(c_ptr) :: values_address
    type(c_ptr) :: residual_address
    values_address = tfem_address_c_double(values, values_length > 0)
    residual_address = tfem_address_c_double(residual, residual_length > 0)
    status = tfem_solid_contact_evaluate_by_address(context, u, tfem_to_size_t(u_length), &
        values_address, tfem_to_size_t(values_length), residual_address, &
        tfem_to_size_t(residual_length))
  end function tfem_solid_contact_evaluate_opt_i_r122

  function tfem_solid_contact_evaluate_opt_i_r222(context, u, u_length, values, &
        values_length, residual, residual_length) result(status)
    type(c_ptr), value :: context
    real(c_double), intent(in) :: u(1, *)
    integer(tfem_length_kind), intent(in) :: u_length
    real(c_double), intent(inout), target :: values(1, *)
    integer(tfem_length_kind), intent(in) :: values_length
    real(c_double), intent(inout), target :: residual(1, *)
    integer(tfem_length_kind), intent(in) :: residual_length
    integer(c_int) :: status
    type(c_ptr) :: values_address
    type(c_ptr) :: residual_address
    values_address = tfem_address_c_double(values, values_length > 0)
    residual_address = tfem_address_c_double(residual, residual_length > 0)
    status = tfem_solid_contact_evaluate_by_address(context, u, tfem_to_size_t(u_length), &
        values_address, tfem_to_size_t(values_length), residual_address, &
        tfem_to_size_t(residual_length))
  end function tfem_solid_contact_evaluate_opt_i_r222

  function tfem_solid_contact_gather_r21(context, u_equations, n_equations, u, &
        u_length) result(status)
    type(c_ptr), value :: context
    real(c_double), intent(in) :: u_equations(1, *)
    integer(c_size_t), intent(in) :: n_equations
    real(c_double), intent(inout) :: u(*)
    integer(c_size_t), intent(in) :: u_length
    integer(c_int) :: status
    status = tfem_solid_contact_gather(context, u_equations, n_equations, u, u_length)
  end function tfem_solid_contact_gather_r21

  function tfem_solid_contact_gather_r12(context, u_equations, n_equations, u, &
        u_length) result(status)
    type(c_ptr), value :: context
    real(c_double), intent(in) :: u_equations(*)
    integer(c_size_t), intent(in) :: n_equations
    real(c_double), intent(inout) :: u(1, *)
    integer(c_size_t), intent(in) :: u_length
    integer(c_int) :: status
    status = tfem_solid_contact_gather(context, u_equations, n_equations, u, u_length)
  end function tfem_solid_contact_gather_r12

  function tfem_solid_contact_gather_r22(context, u_equations, n_equations, u, &
        u_length) result(status)
    type(c_ptr), value :: context
    real(c_double), intent(in) :: u_equations(1, *)
    integer(c_size_t), intent(in) :: n_equations
    real(c_double), intent(inout) :: u(1, *)
    integer(c_size_t), intent(in) :: u_length
    integer(c_int) :: status
    status = tfem_solid_contact_gather(context, u_equations, n_equations, u, u_length)
  end function tfem_solid_contact_gather_r22

  function tfem_solid_contact_gather_i(context, u_equations, n_equations, u, u_length) result(status)
    type(c_ptr), value :: context
    real(c_double), intent(in) :: u_equations(*)
    integer(tfem_length_kind), intent(in) :: n_equations
    real(c_double), intent(inout) :: u(*)
    integer(tfem_length_kind), intent(in) :: u_length
    integer(c_int) :: status
    status = tfem_solid_contact_gather(context, u_equations, tfem_to_size_t(n_equations), u, &
        tfem_to_size_t(u_length))
  end function tfem_solid_contact_gather_i

  function tfem_solid_contact_gather_i_r21(context, u_equations, n_equations, u, &
        u_length) result(status)
    type(c_ptr), value :: context
    real(c_double), intent(in) :: u_equations(1, *)
    integer(tfem_length_kind), intent(in) :: n_equations
    real(c_double), intent(inout) :: u(*)
    integer(tfem_length_kind), intent(in) :: u_length
    integer(c_int) :: status
    status = tfem_solid_contact_gather(context, u_equations, tfem_to_size_t(n_equations), u, &
        tfem_to_size_t(u_length))
  end function tfem_solid_contact_gather_i_r21

  function tfem_solid_contact_gather_i_r12(context, u_equations, n_equations, u, &
        u_length) result(status)
    type(c_ptr), value :: context
    real(c_double), intent(in) :: u_equations(*)
    integer(tfem_length_kind), intent(in) :: n_equations
    real(c_double), intent(inout) :: u(1, *)
    integer(tfem_length_kind), intent(in) :: u_length
    integer(c_int) :: status
    status = tfem_solid_contact_gather(context, u_equations, tfem_to_size_t(n_equations), u, &
        tfem_to_size_t(u_length))
  end function tfem_solid_contact_gather_i_r12

  function tfem_solid_contact_gather_i_r22(context, u_equations, n_equations, u, &
        u_length) result(status)
    type(c_ptr), value :: context
    real(c_double), intent(in) :: u_equations(1, *)
    integer(tfem_length_kind), intent(in) :: n_equations
    real(c_double), intent(inout) :: u(1, *)
    integer(tfem_length_kind), intent(in) :: u_length
    integer(c_int) :: status
    status = tfem_solid_contact_gather(context, u_equations, tfem_to_size_t(n_equations), u, &
        tfem_to_size_t(u_length))
  end function tfem_solid_contact_gather_i_r22

  function tfem_solid_contact_scatter_add_r21(context, residual, residual_length, &
        host_vector, n_equations) result(status)
    type(c_ptr), value :: context
    real(c_double), intent(in) :: residual(1, *)
    integer(c_size_t), intent(in) :: residual_length
    real(c_double), intent(inout) :: host_vector(*)
    integer(c_size_t), intent(in) :: n_equations
    integer(c_int) :: status
    status = tfem_solid_contact_scatter_add(context, residual, residual_length, host_vector, &
        n_equations)
  end function tfem_solid_contact_scatter_add_r21

  function tfem_solid_contact_scatter_add_r12(context, residual, residual_length, &
        host_vector, n_equations) result(status)
    type(c_ptr), value :: context
    real(c_double), intent(in) :: residual(*)
    integer(c_size_t), intent(in) :: residual_length
    real(c_double), intent(inout) :: host_vector(1, *)
    integer(c_size_t), intent(in) :: n_equations
    integer(c_int) :: status
    status = tfem_solid_contact_scatter_add(context, residual, residual_length, host_vector, &
        n_equations)
  end function tfem_solid_contact_scatter_add_r12

  function tfem_solid_contact_scatter_add_r22(context, residual, residual_length, &
        host_vector, n_equations) result(status)
    type(c_ptr), value :: context
    real(c_double), intent(in) :: residual(1, *)
    integer(c_size_t), intent(in) :: residual_length
    real(c_double), intent(inout) :: host_vector(1, *)
    integer(c_size_t), intent(in) :: n_equations
    integer(c_int) :: status
    status = tfem_solid_contact_scatter_add(context, residual, residual_length, host_vector, &
        n_equations)
  end function tfem_solid_contact_scatter_add_r22

  function tfem_solid_contact_scatter_add_i(context, residual, residual_length, &
        host_vector, n_equations) result(status)
    type(c_ptr), value :: context
    real(c_double), intent(in) :: residual(*)
    integer(tfem_length_kind), intent(in) :: residual_length
    real(c_double), intent(inout) :: host_vector(*)
    integer(tfem_length_kind), intent(in) :: n_equations
    integer(c_int) :: status
    status = tfem_solid_contact_scatter_add(context, residual, tfem_to_size_t(residual_length), &
        host_vector, tfem_to_size_t(n_equations))
  end function tfem_solid_contact_scatter_add_i

  function tfem_solid_contact_scatter_add_i_r21(context, residual, residual_length, &
        host_vector, n_equations) result(status)
    type(c_ptr), value :: context
    real(c_double), intent(in) :: residual(1, *)
    integer(tfem_length_kind), intent(in) :: residual_length
    real(c_double), intent(inout) :: host_vector(*)
    integer(tfem_length_kind), intent(in) :: n_equations
    integer(c_int) :: status
    status = tfem_solid_contact_scatter_add(context, residual, tfem_to_size_t(residual_length), &
        host_vector, tfem_to_size_t(n_equations))
  end function tfem_solid_contact_scatter_add_i_r21

  function tfem_solid_contact_scatter_add_i_r12(context, residual, residual_length, &
        host_vector, n_equations) result(status)
    type(c_ptr), value :: context
    real(c_double), intent(in) :: residual(*)
    integer(tfem_length_kind), intent(in) :: residual_length
    real(c_double), intent(inout) :: host_vector(1, *)
    integer(tfem_length_kind), intent(in) :: n_equations
    integer(c_int) :: status
    status = tfem_solid_contact_scatter_add(context, residual, tfem_to_size_t(residual_length), &
        host_vector, tfem_to_size_t(n_equations))
  end function tfem_solid_contact_scatter_add_i_r12

  function tfem_solid_contact_scatter_add_i_r22(context, residual, residual_length, &
        host_vector, n_equations) result(status)
    type(c_ptr), value :: context
    real(c_double), intent(in) :: residual(1, *)
    integer(tfem_length_kind), intent(in) :: residual_length
    real(c_double), intent(inout) :: host_vector(1, *)
    integer(tfem_length_kind), intent(in) :: n_equations
    integer(c_int) :: status
    status = tfem_solid_contact_scatter_add(context, residual, tfem_to_size_t(residual_length), &
        host_vector, tfem_to_size_t(n_equations))
  end function tfem_solid_contact_scatter_add_i_r22

  function tfem_solid_contact_update_opt(context, u, u_length, changed, switched_on, &
        switched_off) result(status)
    type(c_ptr), value :: context
    real(c_double), intent(in) :: u(*)
    integer(c_size_t), intent(in) :: u_length
    integer(c_int), intent(inout), optional, target :: changed
    integer(c_int), intent(inout), optional, target :: switched_on
    integer(c_int), intent(inout), optional, target :: switched_off
    integer(c_int) :: status
    type(c_ptr) :: changed_address
    type(c_ptr) :: switched_on_address
    type(c_ptr) :: switched_off_address
    changed_address = c_null_ptr
    if (present(changed)) changed_address = c_loc(changed)
    switched_on_address = c_null_ptr
    if (present(switched_on)) switched_on_address = c_loc(switched_on)
    switched_off_address = c_null_ptr
    if (present(switched_off)) switched_off_address = c_loc(switched_off)
    status = tfem_solid_contact_update_by_address(context, u, u_length, changed_address, &
        switched_on_address, switched_off_address)
  end function tfem_solid_contact_update_opt

  function tfem_solid_contact_update_opt_r2(context, u, u_length, changed, switched_on, &
        switched_off) result(status)
    type(c_ptr), value :: context
    real(c_double), intent(in) :: u(1, *)
    integer(c_size_t), intent(in) :: u_length
    integer(c_int), intent(inout), optional, target :: changed
    integer(c_int), intent(inout), optional, target :: switched_on
    integer(c_int), intent(inout), optional, target :: switched_off
    integer(c_int) :: status
    type(c_ptr) :: changed_address
    type(c_ptr) :: switched_on_address
    type(c_ptr) :: switched_off_address
    changed_address = c_null_ptr
    if (present(changed)) changed_address = c_loc(changed)
    switched_on_address = c_null_ptr
    if (present(switched_on)) switched_on_address = c_loc(switched_on)
    switched_off_address = c_null_ptr
    if (present(switched_off)) switched_off_address = c_loc(switched_off)
    status = tfem_solid_contact_update_by_address(context, u, u_length, changed_address, &
        switched_on_address, switched_off_address)
  end function tfem_solid_contact_update_opt_r2

  function tfem_solid_contact_update_opt_i(context, u, u_length, changed, switched_on, &
        switched_off) result(status)
    type(c_ptr), value :: context
    real(c_double), intent(in) :: u(*)
    integer(tfem_length_kind), intent(in) :: u_length
    integer(c_int), intent(inout), optional, target :: changed
    integer(c_int), intent(inout), optional, target :: switched_on
    integer(c_int), intent(inout), optional, target :: switched_off
    integer(c_int) :: status
    type(c_ptr) :: changed_address
    type(c_ptr) :: switched_on_address
    type(c_ptr) :: switched_off_address
    changed_address = c_null_ptr
    if (present(changed)) changed_address = c_loc(changed)
    switched_on_address = c_null_ptr
    if (present(switched_on)) switched_on_address = c_loc(switched_on)
    switched_off_address = c_null_ptr
    if (present(switched_off)) switched_off_address = c_loc(switched_off)
    status = tfem_solid_contact_update_by_address(context, u, tfem_to_size_t(u_length), &
        changed_address, switched_on_address, switched_off_address)
  end function tfem_solid_contact_update_opt_i

  function tfem_solid_contact_update_opt_i_r2(context, u, u_length, changed, &
        switched_on, switched_off) result(status)
    type(c_ptr), value :: context
    real(c_double), intent(in) :: u(1, *)
    integer(tfem_length_kind), intent(in) :: u_length
    integer(c_int), intent(inout), optional, target :: changed
    integer(c_int), intent(inout), optional, target :: switched_on
    integer(c_int), intent(inout), optional, target :: switched_off
    integer(c_int) :: status
    type(c_ptr) :: changed_address
    type(c_ptr) :: switched_on_address
    type(c_ptr) :: switched_off_address
    changed_address = c_null_ptr
    if (present(changed)) changed_address = c_loc(changed)
    switched_on_address = c_null_ptr
    if (present(switched_on)) switched_on_address = c_loc(switched_on)
    switched_off_address = c_null_ptr
    if (present(switched_off)) switched_off_address = c_loc(switched_off)
    status = tfem_solid_contact_update_by_address(context, u, tfem_to_size_t(u_length), &
        changed_address, switched_on_address, switched_off_address)
  end function tfem_solid_contact_update_opt_i_r2

  function tfem_solid_contact_get_active_r2(context, out, length) result(status)
    type(c_ptr), value :: context
    integer(c_int), intent(inout) :: out(1, *)
    integer(c_size_t), intent(in) :: length
    integer(c_int) :: status
    status = tfem_solid_contact_get_active(context, out, length)
  end function tfem_solid_contact_get_active_r2

  function tfem_solid_contact_get_active_i(context, out, length) result(status)
    type(c_ptr), value :: context
    integer(c_int), intent(inout) :: out(*)
    integer(tfem_length_kind), intent(in) :: length
    integer(c_int) :: status
    status = tfem_solid_contact_get_active(context, out, tfem_to_size_t(length))
  end function tfem_solid_contact_get_active_i

  function tfem_solid_contact_get_active_i_r2(context, out, length) result(status)
    type(c_ptr), value :: context
    integer(c_int), intent(inout) :: out(1, *)
    integer(tfem_length_kind), intent(in) :: length
    integer(c_int) :: status
    status = tfem_solid_contact_get_active(context, out, tfem_to_size_t(length))
  end function tfem_solid_contact_get_active_i_r2

  function tfem_solid_contact_set_active_r2(context, active, length) result(status)
    type(c_ptr), value :: context
    integer(c_int), intent(in) :: active(1, *)
    integer(c_size_t), intent(in) :: length
    integer(c_int) :: status
    status = tfem_solid_contact_set_active(context, active, length)
  end function tfem_solid_contact_set_active_r2

  function tfem_solid_contact_set_active_i(context, active, length) result(status)
    type(c_ptr), value :: context
    integer(c_int), intent(in) :: active(*)
    integer(tfem_length_kind), intent(in) :: length
    integer(c_int) :: status
    status = tfem_solid_contact_set_active(context, active, tfem_to_size_t(length))
  end function tfem_solid_contact_set_active_i

  function tfem_solid_contact_set_active_i_r2(context, active, length) result(status)
    type(c_ptr), value :: context
    integer(c_int), intent(in) :: active(1, *)
    integer(tfem_length_kind), intent(in) :: length
    integer(c_int) :: status
    status = tfem_solid_contact_set_active(context, active, tfem_to_size_t(length))
  end function tfem_solid_contact_set_active_i_r2

  function tfem_solid_contact_gaps_r21(context, u, u_length, out, length) result(status)
    type(c_ptr), value :: context
    real(c_double), intent(in) :: u(1, *)
    integer(c_size_t), intent(in) :: u_length
    real(c_double), intent(inout) :: out(*)
    integer(c_size_t), intent(in) :: length
    integer(c_int) :: status
    status = tfem_solid_contact_gaps(context, u, u_length, out, length)
  end function tfem_solid_contact_gaps_r21

  function tfem_solid_contact_gaps_r12(context, u, u_length, out, length) result(status)
    type(c_ptr), value :: context
    real(c_double), intent(in) :: u(*)
    integer(c_size_t), intent(in) :: u_length
    real(c_double), intent(inout) :: out(1, *)
    integer(c_size_t), intent(in) :: length
    integer(c_int) :: status
    status = tfem_solid_contact_gaps(context, u, u_length, out, length)
  end function tfem_solid_contact_gaps_r12

  function tfem_solid_contact_gaps_r22(context, u, u_length, out, length) result(status)
    type(c_ptr), value :: context
    real(c_double), intent(in) :: u(1, *)
    integer(c_size_t), intent(in) :: u_length
    real(c_double), intent(inout) :: out(1, *)
    integer(c_size_t), intent(in) :: length
    integer(c_int) :: status
    status = tfem_solid_contact_gaps(context, u, u_length, out, length)
  end function tfem_solid_contact_gaps_r22

  function tfem_solid_contact_gaps_i(context, u, u_length, out, length) result(status)
    type(c_ptr), value :: context
    real(c_double), intent(in) :: u(*)
    integer(tfem_length_kind), intent(in) :: u_length
    real(c_double), intent(inout) :: out(*)
    integer(tfem_length_kind), intent(in) :: length
    integer(c_int) :: status
    status = tfem_solid_contact_gaps(context, u, tfem_to_size_t(u_length), out, &
        tfem_to_size_t(length))
  end function tfem_solid_contact_gaps_i

  function tfem_solid_contact_gaps_i_r21(context, u, u_length, out, length) result(status)
    type(c_ptr), value :: context
    real(c_double), intent(in) :: u(1, *)
    integer(tfem_length_kind), intent(in) :: u_length
    real(c_double), intent(inout) :: out(*)
    integer(tfem_length_kind), intent(in) :: length
    integer(c_int) :: status
    status = tfem_solid_contact_gaps(context, u, tfem_to_size_t(u_length), out, &
        tfem_to_size_t(length))
  end function tfem_solid_contact_gaps_i_r21

  function tfem_solid_contact_gaps_i_r12(context, u, u_length, out, length) result(status)
    type(c_ptr), value :: context
    real(c_double), intent(in) :: u(*)
    integer(tfem_length_kind), intent(in) :: u_length
    real(c_double), intent(inout) :: out(1, *)
    integer(tfem_length_kind), intent(in) :: length
    integer(c_int) :: status
    status = tfem_solid_contact_gaps(context, u, tfem_to_size_t(u_length), out, &
        tfem_to_size_t(length))
  end function tfem_solid_contact_gaps_i_r12

  function tfem_solid_contact_gaps_i_r22(context, u, u_length, out, length) result(status)
    type(c_ptr), value :: context
    real(c_double), intent(in) :: u(1, *)
    integer(tfem_length_kind), intent(in) :: u_length
    real(c_double), intent(inout) :: out(1, *)
    integer(tfem_length_kind), intent(in) :: length
    integer(c_int) :: status
    status = tfem_solid_contact_gaps(context, u, tfem_to_size_t(u_length), out, &
        tfem_to_size_t(length))
  end function tfem_solid_contact_gaps_i_r22

end module tfem_specifics

! The module to use: tfem_c's constants and types, its interfaces where nothing is
! converted, and the generic interfaces.
module tfem
  use, intrinsic :: iso_c_binding
  use tfem_c, only: TFEM_STATUS_OK, TFEM_STATUS_NULL_POINTER, TFEM_STATUS_INVALID_ARGUMENT, &
        TFEM_STATUS_INVALID_MESH, TFEM_STATUS_INVALID_MATERIAL, TFEM_STATUS_INVALID_STATE, &
        TFEM_STATUS_BUFFER_TOO_SMALL, TFEM_STATUS_SINGULAR, TFEM_STATUS_NOT_CONVERGED, &
        TFEM_STATUS_DEGENERATE_ELEMENT, TFEM_STATUS_INVALID_CONTACT, TFEM_STATUS_NUMERICAL_FAILURE, &
        TFEM_STATUS_INTERNAL, TFEM_STATUS_OUT_OF_MEMORY, TFEM_STATUS_IO, TFEM_TEMPERING_MODE_AUTO, &
        TFEM_TEMPERING_MODE_LAMBDA, TFEM_TEMPERING_MODE_FIXED_JMIN, TFEM_TEMPERING_MODE_OFF, &
        TFEM_ORDERING_MODE_AUTO, TFEM_ORDERING_MODE_AMD, TFEM_ORDERING_MODE_NESTED_DISSECTION, &
        TFEM_CONTACT_WEIGHTING_STRIP, TFEM_CONTACT_WEIGHTING_MORTAR, TFEM_CONTACT_WEIGHTING_AUTO, &
        TFEM_CONTACT_LAW_FRICTIONLESS, TFEM_CONTACT_LAW_STICK, TFEM_INVERSION_TEST_LINEARISED, &
        TFEM_INVERSION_TEST_LITERAL, TFEM_PLANE_MODE_STRAIN, TFEM_PLANE_MODE_STRESS, &
        TFEM_PLANE_MODE_AXISYMMETRIC, TFEM_COMPONENT_X, TFEM_COMPONENT_Y, TFEM_ADAPT_GOAL_ENERGY, &
        TFEM_ADAPT_GOAL_COMPLIANCE, TFEM_AXIS_X, TFEM_AXIS_Y, TFEM_AXIS_Z, tfem_contact_options, &
        tfem_solve_info, tfem_contact_report, tfem_adapt_report, tfem_version, tfem_create, &
        tfem_destroy, tfem_warning_count, tfem_get_warning_size, tfem_set_threads, tfem_get_threads, &
        tfem_set_mesh, tfem_load_gmsh, tfem_set_boundary_edges, tfem_add_boundary_edges, &
        tfem_get_boundary_edge_count, tfem_set_material, tfem_set_tempering, tfem_set_ordering, &
        tfem_fix, tfem_fix_edges, tfem_set_prescribed, tfem_set_prescribed_edges, &
        tfem_clear_constraints, tfem_set_boundary_circle, tfem_add_pressure, tfem_add_traction, &
        tfem_add_nodal_force, tfem_set_body_force, tfem_clear_loads, tfem_set_friction, &
        tfem_set_contact_weighting, tfem_get_contact_weighting, tfem_get_contact_mesh_size, &
        tfem_contact_options_default, tfem_get_external_work, tfem_write_vtu, tfem_get_contact_report, &
        tfem_revert_step, tfem_get_contact_state_size, tfem_element_stiffness, &
        tfem_laplacian_stiffness, tfem_contact_create, tfem_contact_destroy, tfem_contact_set_options, &
        tfem_contact_restart, tfem_contact_length, tfem_solid_create, tfem_solid_destroy, &
        tfem_solid_warning_count, tfem_solid_get_warning_size, tfem_solid_set_mesh, &
        tfem_solid_load_gmsh, tfem_solid_set_boundary_faces, tfem_solid_add_boundary_faces, &
        tfem_solid_get_boundary_face_count, tfem_solid_set_material, tfem_solid_set_tempering, &
        tfem_solid_set_ordering, tfem_solid_fix, tfem_solid_fix_faces, tfem_solid_clear_constraints, &
        tfem_solid_add_pressure, tfem_solid_add_traction, tfem_solid_add_nodal_force, &
        tfem_solid_clear_loads, tfem_solid_clear_contact_pairs, tfem_solid_revert_step, &
        tfem_solid_get_solve_info, tfem_solid_get_iterations, tfem_solid_get_external_work, &
        tfem_solid_get_contact_area, tfem_solid_get_contact_pair_area, tfem_solid_write_vtu, &
        tfem_solid_contact_destroy, tfem_solid_contact_setup, tfem_solid_contact_restart, &
        tfem_solid_contact_area, tfem_last_error, tfem_last_error_length, tfem_get_warning, &
        tfem_get_mesh_nodes, tfem_get_contact_mesh, tfem_get_contact_element_pairs, &
        tfem_get_contact_element_apexes, tfem_get_displacements, tfem_get_element_strains, &
        tfem_get_element_stresses, tfem_get_element_out_of_plane_stresses, tfem_get_element_jacobians, &
        tfem_get_reactions, tfem_get_contact_forces, tfem_get_contact_nodal_pressures, &
        tfem_get_contact_nodal_tractions, tfem_get_contact_pair_nodal_pressures, &
        tfem_get_contact_pair_nodal_tractions, tfem_get_contact_gaps, tfem_get_contact_active, &
        tfem_get_contact_pressure, tfem_get_contact_elements, tfem_get_contact_shear, &
        tfem_get_contact_friction_state, tfem_get_contact_dissipation, tfem_get_contact_state, &
        tfem_set_contact_state, tfem_get_system_matrix, tfem_contact_last_error, &
        tfem_contact_last_error_length, tfem_contact_nodes, tfem_contact_pattern, tfem_contact_gather, &
        tfem_contact_scatter_add, tfem_contact_get_active, tfem_contact_set_active, tfem_contact_gaps, &
        tfem_contact_pressures, tfem_contact_elements, tfem_contact_element_equations, &
        tfem_contact_element_blocks, tfem_solid_last_error, tfem_solid_last_error_length, &
        tfem_solid_get_warning, tfem_solid_get_mesh_nodes, tfem_solid_get_displacements, &
        tfem_solid_get_element_strains, tfem_solid_get_element_stresses, tfem_solid_get_reactions, &
        tfem_solid_get_contact_tetrahedra, tfem_solid_get_contact_active, &
        tfem_solid_get_contact_forces, tfem_solid_get_contact_nodal_pressures, &
        tfem_solid_contact_last_error, tfem_solid_contact_last_error_length, tfem_solid_contact_nodes, &
        tfem_solid_contact_tetrahedra, tfem_solid_contact_pattern, &
        tfem_solid_contact_element_equations, tfem_solid_contact_element_blocks, &
        tfem_solid_contact_gather, tfem_solid_contact_scatter_add, tfem_solid_contact_get_active, &
        tfem_solid_contact_set_active, tfem_solid_contact_gaps
  use tfem_specifics
  implicit none
  private :: c_strlen
  private :: tfem_last_error_i, tfem_last_error_str, tfem_last_error_str_i, tfem_last_error_no_model
  private :: tfem_last_error_no_model_i, tfem_last_error_no_model_str
  private :: tfem_last_error_no_model_str_i, tfem_last_error_length_no_model, tfem_get_warning_i
  private :: tfem_get_warning_str, tfem_get_warning_str_i, tfem_get_sizes_opt
  private :: tfem_get_mesh_nodes_r2, tfem_get_mesh_nodes_i, tfem_get_mesh_nodes_i_r2
  private :: tfem_get_mesh_triangles_opt, tfem_get_mesh_triangles_opt_r21
  private :: tfem_get_mesh_triangles_opt_r12, tfem_get_mesh_triangles_opt_r22
  private :: tfem_get_mesh_triangles_opt_i, tfem_get_mesh_triangles_opt_i_r21
  private :: tfem_get_mesh_triangles_opt_i_r12, tfem_get_mesh_triangles_opt_i_r22
  private :: tfem_get_boundary_edges_opt, tfem_get_boundary_edges_opt_r21
  private :: tfem_get_boundary_edges_opt_r12, tfem_get_boundary_edges_opt_r22
  private :: tfem_get_boundary_edges_opt_i, tfem_get_boundary_edges_opt_i_r21
  private :: tfem_get_boundary_edges_opt_i_r12, tfem_get_boundary_edges_opt_i_r22
  private :: tfem_add_contact_pair_opt, tfem_add_contact_pair_with_mesh_opt
  private :: tfem_add_contact_pair_with_mesh_opt_r2, tfem_add_contact_pairs_auto_opt
  private :: tfem_add_contact_pairs_auto_opt_r2, tfem_get_contact_mesh_r2, tfem_get_contact_mesh_i
  private :: tfem_get_contact_mesh_i_r2, tfem_get_contact_element_pairs_r2
  private :: tfem_get_contact_element_pairs_i, tfem_get_contact_element_pairs_i_r2
  private :: tfem_get_contact_element_apexes_r2, tfem_get_contact_element_apexes_i
  private :: tfem_get_contact_element_apexes_i_r2, tfem_get_contact_pair_bodies_opt, tfem_solve_opt
  private :: tfem_solve_contact_opt, tfem_solve_adaptive_opt, tfem_get_adapt_cycles_opt
  private :: tfem_get_adapt_cycles_opt_r2, tfem_get_adapt_cycles_opt_i
  private :: tfem_get_adapt_cycles_opt_i_r2, tfem_get_displacements_r2, tfem_get_displacements_i
  private :: tfem_get_displacements_i_r2, tfem_get_element_strains_r2, tfem_get_element_strains_i
  private :: tfem_get_element_strains_i_r2, tfem_get_element_stresses_r2
  private :: tfem_get_element_stresses_i, tfem_get_element_stresses_i_r2
  private :: tfem_get_element_out_of_plane_stresses_r2, tfem_get_element_out_of_plane_stresses_i
  private :: tfem_get_element_out_of_plane_stresses_i_r2, tfem_get_element_jacobians_r2
  private :: tfem_get_element_jacobians_i, tfem_get_element_jacobians_i_r2, tfem_get_reactions_r2
  private :: tfem_get_reactions_i, tfem_get_reactions_i_r2, tfem_get_contact_forces_r2
  private :: tfem_get_contact_forces_i, tfem_get_contact_forces_i_r2
  private :: tfem_get_contact_nodal_pressures_r2, tfem_get_contact_nodal_pressures_i
  private :: tfem_get_contact_nodal_pressures_i_r2, tfem_get_contact_nodal_tractions_r2
  private :: tfem_get_contact_nodal_tractions_i, tfem_get_contact_nodal_tractions_i_r2
  private :: tfem_get_contact_pair_nodal_pressures_r2, tfem_get_contact_pair_nodal_pressures_i
  private :: tfem_get_contact_pair_nodal_pressures_i_r2, tfem_get_contact_pair_nodal_tractions_r2
  private :: tfem_get_contact_pair_nodal_tractions_i, tfem_get_contact_pair_nodal_tractions_i_r2
  private :: tfem_get_contact_gaps_r2, tfem_get_contact_gaps_i, tfem_get_contact_gaps_i_r2
  private :: tfem_get_contact_active_r2, tfem_get_contact_active_i, tfem_get_contact_active_i_r2
  private :: tfem_get_contact_pressure_r2, tfem_get_contact_pressure_i
  private :: tfem_get_contact_pressure_i_r2, tfem_get_contact_elements_r2
  private :: tfem_get_contact_elements_i, tfem_get_contact_elements_i_r2, tfem_get_contact_shear_r2
  private :: tfem_get_contact_shear_i, tfem_get_contact_shear_i_r2
  private :: tfem_get_contact_friction_state_r2, tfem_get_contact_friction_state_i
  private :: tfem_get_contact_friction_state_i_r2, tfem_get_contact_dissipation_r2
  private :: tfem_get_contact_dissipation_i, tfem_get_contact_dissipation_i_r2
  private :: tfem_get_contact_slave_nodes_opt, tfem_get_contact_slave_nodes_opt_r2111
  private :: tfem_get_contact_slave_nodes_opt_r1211, tfem_get_contact_slave_nodes_opt_r2211
  private :: tfem_get_contact_slave_nodes_opt_r1121, tfem_get_contact_slave_nodes_opt_r2121
  private :: tfem_get_contact_slave_nodes_opt_r1221, tfem_get_contact_slave_nodes_opt_r2221
  private :: tfem_get_contact_slave_nodes_opt_r1112, tfem_get_contact_slave_nodes_opt_r2112
  private :: tfem_get_contact_slave_nodes_opt_r1212, tfem_get_contact_slave_nodes_opt_r2212
  private :: tfem_get_contact_slave_nodes_opt_r1122, tfem_get_contact_slave_nodes_opt_r2122
  private :: tfem_get_contact_slave_nodes_opt_r1222, tfem_get_contact_slave_nodes_opt_r2222
  private :: tfem_get_contact_slave_nodes_opt_i, tfem_get_contact_slave_nodes_opt_i_r2111
  private :: tfem_get_contact_slave_nodes_opt_i_r1211, tfem_get_contact_slave_nodes_opt_i_r2211
  private :: tfem_get_contact_slave_nodes_opt_i_r1121, tfem_get_contact_slave_nodes_opt_i_r2121
  private :: tfem_get_contact_slave_nodes_opt_i_r1221, tfem_get_contact_slave_nodes_opt_i_r2221
  private :: tfem_get_contact_slave_nodes_opt_i_r1112, tfem_get_contact_slave_nodes_opt_i_r2112
  private :: tfem_get_contact_slave_nodes_opt_i_r1212, tfem_get_contact_slave_nodes_opt_i_r2212
  private :: tfem_get_contact_slave_nodes_opt_i_r1122, tfem_get_contact_slave_nodes_opt_i_r2122
  private :: tfem_get_contact_slave_nodes_opt_i_r1222, tfem_get_contact_slave_nodes_opt_i_r2222
  private :: tfem_step_opt, tfem_get_contact_state_r2, tfem_get_contact_state_i
  private :: tfem_get_contact_state_i_r2, tfem_set_contact_state_r2, tfem_set_contact_state_i
  private :: tfem_set_contact_state_i_r2, tfem_get_system_matrix_size_opt
  private :: tfem_get_system_matrix_r2111, tfem_get_system_matrix_r1211
  private :: tfem_get_system_matrix_r2211, tfem_get_system_matrix_r1121
  private :: tfem_get_system_matrix_r2121, tfem_get_system_matrix_r1221
  private :: tfem_get_system_matrix_r2221, tfem_get_system_matrix_r1112
  private :: tfem_get_system_matrix_r2112, tfem_get_system_matrix_r1212
  private :: tfem_get_system_matrix_r2212, tfem_get_system_matrix_r1122
  private :: tfem_get_system_matrix_r2122, tfem_get_system_matrix_r1222
  private :: tfem_get_system_matrix_r2222, tfem_get_system_matrix_i, tfem_get_system_matrix_i_r2111
  private :: tfem_get_system_matrix_i_r1211, tfem_get_system_matrix_i_r2211
  private :: tfem_get_system_matrix_i_r1121, tfem_get_system_matrix_i_r2121
  private :: tfem_get_system_matrix_i_r1221, tfem_get_system_matrix_i_r2221
  private :: tfem_get_system_matrix_i_r1112, tfem_get_system_matrix_i_r2112
  private :: tfem_get_system_matrix_i_r1212, tfem_get_system_matrix_i_r2212
  private :: tfem_get_system_matrix_i_r1122, tfem_get_system_matrix_i_r2122
  private :: tfem_get_system_matrix_i_r1222, tfem_get_system_matrix_i_r2222
  private :: tfem_contact_last_error_i, tfem_contact_last_error_str, tfem_contact_last_error_str_i
  private :: tfem_contact_last_error_length_no_context, tfem_contact_add_side_opt
  private :: tfem_contact_add_side_opt_r2111, tfem_contact_add_side_opt_r1211
  private :: tfem_contact_add_side_opt_r2211, tfem_contact_add_side_opt_r1121
  private :: tfem_contact_add_side_opt_r2121, tfem_contact_add_side_opt_r1221
  private :: tfem_contact_add_side_opt_r2221, tfem_contact_add_side_opt_r1112
  private :: tfem_contact_add_side_opt_r2112, tfem_contact_add_side_opt_r1212
  private :: tfem_contact_add_side_opt_r2212, tfem_contact_add_side_opt_r1122
  private :: tfem_contact_add_side_opt_r2122, tfem_contact_add_side_opt_r1222
  private :: tfem_contact_add_side_opt_r2222, tfem_contact_add_pair_opt
  private :: tfem_contact_add_pair_with_mesh_opt, tfem_contact_add_pair_with_mesh_opt_r2
  private :: tfem_contact_sizes_opt, tfem_contact_nodes_r2, tfem_contact_nodes_i
  private :: tfem_contact_nodes_i_r2, tfem_contact_pattern_r21, tfem_contact_pattern_r12
  private :: tfem_contact_pattern_r22, tfem_contact_pattern_i, tfem_contact_pattern_i_r21
  private :: tfem_contact_pattern_i_r12, tfem_contact_pattern_i_r22, tfem_contact_evaluate_opt
  private :: tfem_contact_evaluate_opt_r211, tfem_contact_evaluate_opt_r121
  private :: tfem_contact_evaluate_opt_r221, tfem_contact_evaluate_opt_r112
  private :: tfem_contact_evaluate_opt_r212, tfem_contact_evaluate_opt_r122
  private :: tfem_contact_evaluate_opt_r222, tfem_contact_evaluate_opt_i
  private :: tfem_contact_evaluate_opt_i_r211, tfem_contact_evaluate_opt_i_r121
  private :: tfem_contact_evaluate_opt_i_r221, tfem_contact_evaluate_opt_i_r112
  private :: tfem_contact_evaluate_opt_i_r212, tfem_contact_evaluate_opt_i_r122
  private :: tfem_contact_evaluate_opt_i_r222, tfem_contact_gather_r21, tfem_contact_gather_r12
  private :: tfem_contact_gather_r22, tfem_contact_gather_i, tfem_contact_gather_i_r21
  private :: tfem_contact_gather_i_r12, tfem_contact_gather_i_r22, tfem_contact_scatter_add_r21
  private :: tfem_contact_scatter_add_r12, tfem_contact_scatter_add_r22, tfem_contact_scatter_add_i
  private :: tfem_contact_scatter_add_i_r21, tfem_contact_scatter_add_i_r12
  private :: tfem_contact_scatter_add_i_r22, tfem_contact_update_opt, tfem_contact_update_opt_r2
  private :: tfem_contact_update_opt_i, tfem_contact_update_opt_i_r2, tfem_contact_get_active_r2
  private :: tfem_contact_get_active_i, tfem_contact_get_active_i_r2, tfem_contact_set_active_r2
  private :: tfem_contact_set_active_i, tfem_contact_set_active_i_r2, tfem_contact_gaps_r21
  private :: tfem_contact_gaps_r12, tfem_contact_gaps_r22, tfem_contact_gaps_i
  private :: tfem_contact_gaps_i_r21, tfem_contact_gaps_i_r12, tfem_contact_gaps_i_r22
  private :: tfem_contact_pressures_r21, tfem_contact_pressures_r12, tfem_contact_pressures_r22
  private :: tfem_contact_pressures_i, tfem_contact_pressures_i_r21, tfem_contact_pressures_i_r12
  private :: tfem_contact_pressures_i_r22, tfem_contact_elements_r2, tfem_contact_elements_i
  private :: tfem_contact_elements_i_r2, tfem_contact_element_equations_r2
  private :: tfem_contact_element_equations_i, tfem_contact_element_equations_i_r2
  private :: tfem_contact_element_blocks_r2, tfem_contact_element_blocks_i
  private :: tfem_contact_element_blocks_i_r2, tfem_solid_last_error_i, tfem_solid_last_error_str
  private :: tfem_solid_last_error_str_i, tfem_solid_last_error_length_no_model
  private :: tfem_solid_get_warning_i, tfem_solid_get_warning_str, tfem_solid_get_warning_str_i
  private :: tfem_solid_get_sizes_opt, tfem_solid_get_mesh_nodes_r2, tfem_solid_get_mesh_nodes_i
  private :: tfem_solid_get_mesh_nodes_i_r2, tfem_solid_get_mesh_tetrahedra_opt
  private :: tfem_solid_get_mesh_tetrahedra_opt_r21, tfem_solid_get_mesh_tetrahedra_opt_r12
  private :: tfem_solid_get_mesh_tetrahedra_opt_r22, tfem_solid_get_mesh_tetrahedra_opt_i
  private :: tfem_solid_get_mesh_tetrahedra_opt_i_r21, tfem_solid_get_mesh_tetrahedra_opt_i_r12
  private :: tfem_solid_get_mesh_tetrahedra_opt_i_r22, tfem_solid_get_boundary_faces_opt
  private :: tfem_solid_get_boundary_faces_opt_r21, tfem_solid_get_boundary_faces_opt_r12
  private :: tfem_solid_get_boundary_faces_opt_r22, tfem_solid_get_boundary_faces_opt_i
  private :: tfem_solid_get_boundary_faces_opt_i_r21, tfem_solid_get_boundary_faces_opt_i_r12
  private :: tfem_solid_get_boundary_faces_opt_i_r22, tfem_solid_add_contact_pair_opt
  private :: tfem_solid_solve_opt, tfem_solid_solve_contact_opt, tfem_solid_step_opt
  private :: tfem_solid_get_displacements_r2, tfem_solid_get_displacements_i
  private :: tfem_solid_get_displacements_i_r2, tfem_solid_get_element_strains_r2
  private :: tfem_solid_get_element_strains_i, tfem_solid_get_element_strains_i_r2
  private :: tfem_solid_get_element_stresses_r2, tfem_solid_get_element_stresses_i
  private :: tfem_solid_get_element_stresses_i_r2, tfem_solid_get_reactions_r2
  private :: tfem_solid_get_reactions_i, tfem_solid_get_reactions_i_r2
  private :: tfem_solid_get_contact_tetrahedra_r2, tfem_solid_get_contact_tetrahedra_i
  private :: tfem_solid_get_contact_tetrahedra_i_r2, tfem_solid_get_contact_active_r2
  private :: tfem_solid_get_contact_active_i, tfem_solid_get_contact_active_i_r2
  private :: tfem_solid_get_contact_forces_r2, tfem_solid_get_contact_forces_i
  private :: tfem_solid_get_contact_forces_i_r2, tfem_solid_get_contact_nodal_pressures_r2
  private :: tfem_solid_get_contact_nodal_pressures_i, tfem_solid_get_contact_nodal_pressures_i_r2
  private :: tfem_solid_contact_create_opt, tfem_solid_contact_last_error_i
  private :: tfem_solid_contact_last_error_str, tfem_solid_contact_last_error_str_i
  private :: tfem_solid_contact_last_error_length_no_context, tfem_solid_contact_add_side_opt
  private :: tfem_solid_contact_add_side_opt_r2111, tfem_solid_contact_add_side_opt_r1211
  private :: tfem_solid_contact_add_side_opt_r2211, tfem_solid_contact_add_side_opt_r1121
  private :: tfem_solid_contact_add_side_opt_r2121, tfem_solid_contact_add_side_opt_r1221
  private :: tfem_solid_contact_add_side_opt_r2221, tfem_solid_contact_add_side_opt_r1112
  private :: tfem_solid_contact_add_side_opt_r2112, tfem_solid_contact_add_side_opt_r1212
  private :: tfem_solid_contact_add_side_opt_r2212, tfem_solid_contact_add_side_opt_r1122
  private :: tfem_solid_contact_add_side_opt_r2122, tfem_solid_contact_add_side_opt_r1222
  private :: tfem_solid_contact_add_side_opt_r2222, tfem_solid_contact_add_pair_opt
  private :: tfem_solid_contact_sizes_opt, tfem_solid_contact_nodes_r2, tfem_solid_contact_nodes_i
  private :: tfem_solid_contact_nodes_i_r2, tfem_solid_contact_tetrahedra_r2
  private :: tfem_solid_contact_tetrahedra_i, tfem_solid_contact_tetrahedra_i_r2
  private :: tfem_solid_contact_pattern_r21, tfem_solid_contact_pattern_r12
  private :: tfem_solid_contact_pattern_r22, tfem_solid_contact_pattern_i
  private :: tfem_solid_contact_pattern_i_r21, tfem_solid_contact_pattern_i_r12
  private :: tfem_solid_contact_pattern_i_r22, tfem_solid_contact_element_equations_r2
  private :: tfem_solid_contact_element_equations_i, tfem_solid_contact_element_equations_i_r2
  private :: tfem_solid_contact_element_blocks_r2, tfem_solid_contact_element_blocks_i
  private :: tfem_solid_contact_element_blocks_i_r2, tfem_solid_contact_evaluate_opt
  private :: tfem_solid_contact_evaluate_opt_r211, tfem_solid_contact_evaluate_opt_r121
  private :: tfem_solid_contact_evaluate_opt_r221, tfem_solid_contact_evaluate_opt_r112
  private :: tfem_solid_contact_evaluate_opt_r212, tfem_solid_contact_evaluate_opt_r122
  private :: tfem_solid_contact_evaluate_opt_r222, tfem_solid_contact_evaluate_opt_i
  private :: tfem_solid_contact_evaluate_opt_i_r211, tfem_solid_contact_evaluate_opt_i_r121
  private :: tfem_solid_contact_evaluate_opt_i_r221, tfem_solid_contact_evaluate_opt_i_r112
  private :: tfem_solid_contact_evaluate_opt_i_r212, tfem_solid_contact_evaluate_opt_i_r122
  private :: tfem_solid_contact_evaluate_opt_i_r222, tfem_solid_contact_gather_r21
  private :: tfem_solid_contact_gather_r12, tfem_solid_contact_gather_r22
  private :: tfem_solid_contact_gather_i, tfem_solid_contact_gather_i_r21
  private :: tfem_solid_contact_gather_i_r12, tfem_solid_contact_gather_i_r22
  private :: tfem_solid_contact_scatter_add_r21, tfem_solid_contact_scatter_add_r12
  private :: tfem_solid_contact_scatter_add_r22, tfem_solid_contact_scatter_add_i
  private :: tfem_solid_contact_scatter_add_i_r21, tfem_solid_contact_scatter_add_i_r12
  private :: tfem_solid_contact_scatter_add_i_r22, tfem_solid_contact_update_opt
  private :: tfem_solid_contact_update_opt_r2, tfem_solid_contact_update_opt_i
  private :: tfem_solid_contact_update_opt_i_r2, tfem_solid_contact_get_active_r2
  private :: tfem_solid_contact_get_active_i, tfem_solid_contact_get_active_i_r2
  private :: tfem_solid_contact_set_active_r2, tfem_solid_contact_set_active_i
  private :: tfem_solid_contact_set_active_i_r2, tfem_solid_contact_gaps_r21
  private :: tfem_solid_contact_gaps_r12, tfem_solid_contact_gaps_r22, tfem_solid_contact_gaps_i
  private :: tfem_solid_contact_gaps_i_r21, tfem_solid_contact_gaps_i_r12
  private :: tfem_solid_contact_gaps_i_r22

  !> Fortran: tfem_last_error (documented in module tfem_c). `model` may be omitted (NULL is
  !! passed). `length` takes an integer(c_size_t) or a default integer (kind tfem_length_kind); a
  !! negative length is passed as 0. `buffer` may also be a character string.
  interface tfem_last_error
    procedure tfem_last_error
    procedure tfem_last_error_i
    procedure tfem_last_error_str
    procedure tfem_last_error_str_i
    procedure tfem_last_error_no_model
    procedure tfem_last_error_no_model_i
    procedure tfem_last_error_no_model_str
    procedure tfem_last_error_no_model_str_i
  end interface tfem_last_error

  !> Fortran: tfem_last_error_length (documented in module tfem_c). `model` may be omitted (NULL is
  !! passed).
  interface tfem_last_error_length
    procedure tfem_last_error_length
    procedure tfem_last_error_length_no_model
  end interface tfem_last_error_length

  !> Fortran: tfem_get_warning (documented in module tfem_c). `length` takes an integer(c_size_t) or
  !! a default integer (kind tfem_length_kind); a negative length is passed as 0. `buffer` may also
  !! be a character string.
  interface tfem_get_warning
    procedure tfem_get_warning
    procedure tfem_get_warning_i
    procedure tfem_get_warning_str
    procedure tfem_get_warning_str_i
  end interface tfem_get_warning

  !> Fortran: tfem_get_sizes (documented in module tfem_c). `n_nodes`, `n_triangles` and
  !! `n_contact_elements` are OPTIONAL: omit them to pass NULL. The name is no bind(C) procedure
  !! here (for c_funloc: module tfem_c).
  interface tfem_get_sizes
    procedure tfem_get_sizes_opt
  end interface tfem_get_sizes

  !> Fortran: tfem_get_mesh_nodes (documented in module tfem_c). `length` takes an integer(c_size_t)
  !! or a default integer (kind tfem_length_kind); a negative length is passed as 0. `xy` may have
  !! rank 1 or 2.
  interface tfem_get_mesh_nodes
    procedure tfem_get_mesh_nodes
    procedure tfem_get_mesh_nodes_r2
    procedure tfem_get_mesh_nodes_i
    procedure tfem_get_mesh_nodes_i_r2
  end interface tfem_get_mesh_nodes

  !> Fortran: tfem_get_mesh_triangles (documented in module tfem_c). `bodies` is OPTIONAL: omit it
  !! to pass NULL. `length` and `bodies_length` take integer(c_size_t) or default integers (kind
  !! tfem_length_kind), all of one kind; a negative length is passed as 0. `triangles` and `bodies`
  !! may each have rank 1 or 2. The name is no bind(C) procedure here (for c_funloc: module tfem_c).
  interface tfem_get_mesh_triangles
    procedure tfem_get_mesh_triangles_opt
    procedure tfem_get_mesh_triangles_opt_r21
    procedure tfem_get_mesh_triangles_opt_r12
    procedure tfem_get_mesh_triangles_opt_r22
    procedure tfem_get_mesh_triangles_opt_i
    procedure tfem_get_mesh_triangles_opt_i_r21
    procedure tfem_get_mesh_triangles_opt_i_r12
    procedure tfem_get_mesh_triangles_opt_i_r22
  end interface tfem_get_mesh_triangles

  !> Fortran: tfem_get_boundary_edges (documented in module tfem_c). `tags` is OPTIONAL: omit it to
  !! pass NULL. `length` and `tags_length` take integer(c_size_t) or default integers (kind
  !! tfem_length_kind), all of one kind; a negative length is passed as 0. `edges` and `tags` may
  !! each have rank 1 or 2. The name is no bind(C) procedure here (for c_funloc: module tfem_c).
  interface tfem_get_boundary_edges
    procedure tfem_get_boundary_edges_opt
    procedure tfem_get_boundary_edges_opt_r21
    procedure tfem_get_boundary_edges_opt_r12
    procedure tfem_get_boundary_edges_opt_r22
    procedure tfem_get_boundary_edges_opt_i
    procedure tfem_get_boundary_edges_opt_i_r21
    procedure tfem_get_boundary_edges_opt_i_r12
    procedure tfem_get_boundary_edges_opt_i_r22
  end interface tfem_get_boundary_edges

  !> Fortran: tfem_add_contact_pair (documented in module tfem_c). `pair` is OPTIONAL: omit it to
  !! pass NULL. The name is no bind(C) procedure here (for c_funloc: module tfem_c).
  interface tfem_add_contact_pair
    procedure tfem_add_contact_pair_opt
  end interface tfem_add_contact_pair

  !> Fortran: tfem_add_contact_pair_with_mesh (documented in module tfem_c). `pair` and `flipped`
  !! are OPTIONAL: omit them to pass NULL. `connectivity` may have rank 1 or 2. The name is no
  !! bind(C) procedure here (for c_funloc: module tfem_c).
  interface tfem_add_contact_pair_with_mesh
    procedure tfem_add_contact_pair_with_mesh_opt
    procedure tfem_add_contact_pair_with_mesh_opt_r2
  end interface tfem_add_contact_pair_with_mesh

  !> Fortran: tfem_add_contact_pairs_auto (documented in module tfem_c). `tags`, `first` and `count`
  !! are OPTIONAL: omit them to pass NULL. `tags` may have rank 1 or 2. The name is no bind(C)
  !! procedure here (for c_funloc: module tfem_c).
  interface tfem_add_contact_pairs_auto
    procedure tfem_add_contact_pairs_auto_opt
    procedure tfem_add_contact_pairs_auto_opt_r2
  end interface tfem_add_contact_pairs_auto

  !> Fortran: tfem_get_contact_mesh (documented in module tfem_c). `length` takes an
  !! integer(c_size_t) or a default integer (kind tfem_length_kind); a negative length is passed as
  !! 0. `out` may have rank 1 or 2.
  interface tfem_get_contact_mesh
    procedure tfem_get_contact_mesh
    procedure tfem_get_contact_mesh_r2
    procedure tfem_get_contact_mesh_i
    procedure tfem_get_contact_mesh_i_r2
  end interface tfem_get_contact_mesh

  !> Fortran: tfem_get_contact_element_pairs (documented in module tfem_c). `length` takes an
  !! integer(c_size_t) or a default integer (kind tfem_length_kind); a negative length is passed as
  !! 0. `out` may have rank 1 or 2.
  interface tfem_get_contact_element_pairs
    procedure tfem_get_contact_element_pairs
    procedure tfem_get_contact_element_pairs_r2
    procedure tfem_get_contact_element_pairs_i
    procedure tfem_get_contact_element_pairs_i_r2
  end interface tfem_get_contact_element_pairs

  !> Fortran: tfem_get_contact_element_apexes (documented in module tfem_c). `length` takes an
  !! integer(c_size_t) or a default integer (kind tfem_length_kind); a negative length is passed as
  !! 0. `out` may have rank 1 or 2.
  interface tfem_get_contact_element_apexes
    procedure tfem_get_contact_element_apexes
    procedure tfem_get_contact_element_apexes_r2
    procedure tfem_get_contact_element_apexes_i
    procedure tfem_get_contact_element_apexes_i_r2
  end interface tfem_get_contact_element_apexes

  !> Fortran: tfem_get_contact_pair_bodies (documented in module tfem_c). `body_a` and `body_b` are
  !! OPTIONAL: omit them to pass NULL. The name is no bind(C) procedure here (for c_funloc: module
  !! tfem_c).
  interface tfem_get_contact_pair_bodies
    procedure tfem_get_contact_pair_bodies_opt
  end interface tfem_get_contact_pair_bodies

  !> Fortran: tfem_solve (documented in module tfem_c). `info` is OPTIONAL: omit it to pass NULL.
  !! The name is no bind(C) procedure here (for c_funloc: module tfem_c).
  interface tfem_solve
    procedure tfem_solve_opt
  end interface tfem_solve

  !> Fortran: tfem_solve_contact (documented in module tfem_c). `options` and `report` are OPTIONAL:
  !! omit them to pass NULL. The name is no bind(C) procedure here (for c_funloc: module tfem_c).
  interface tfem_solve_contact
    procedure tfem_solve_contact_opt
  end interface tfem_solve_contact

  !> Fortran: tfem_solve_adaptive (documented in module tfem_c). `contact` and `report` are
  !! OPTIONAL: omit them to pass NULL. The name is no bind(C) procedure here (for c_funloc: module
  !! tfem_c).
  interface tfem_solve_adaptive
    procedure tfem_solve_adaptive_opt
  end interface tfem_solve_adaptive

  !> Fortran: tfem_get_adapt_cycles (documented in module tfem_c). `unknowns`, `estimates` and
  !! `seconds` are OPTIONAL: omit them to pass NULL. `length` takes an integer(c_size_t) or a
  !! default integer (kind tfem_length_kind); a negative length is passed as 0. `seconds` may have
  !! rank 1 or 2. The name is no bind(C) procedure here (for c_funloc: module tfem_c).
  interface tfem_get_adapt_cycles
    procedure tfem_get_adapt_cycles_opt
    procedure tfem_get_adapt_cycles_opt_r2
    procedure tfem_get_adapt_cycles_opt_i
    procedure tfem_get_adapt_cycles_opt_i_r2
  end interface tfem_get_adapt_cycles

  !> Fortran: tfem_get_displacements (documented in module tfem_c). `length` takes an
  !! integer(c_size_t) or a default integer (kind tfem_length_kind); a negative length is passed as
  !! 0. `out` may have rank 1 or 2.
  interface tfem_get_displacements
    procedure tfem_get_displacements
    procedure tfem_get_displacements_r2
    procedure tfem_get_displacements_i
    procedure tfem_get_displacements_i_r2
  end interface tfem_get_displacements

  !> Fortran: tfem_get_element_strains (documented in module tfem_c). `length` takes an
  !! integer(c_size_t) or a default integer (kind tfem_length_kind); a negative length is passed as
  !! 0. `out` may have rank 1 or 2.
  interface tfem_get_element_strains
    procedure tfem_get_element_strains
    procedure tfem_get_element_strains_r2
    procedure tfem_get_element_strains_i
    procedure tfem_get_element_strains_i_r2
  end interface tfem_get_element_strains

  !> Fortran: tfem_get_element_stresses (documented in module tfem_c). `length` takes an
  !! integer(c_size_t) or a default integer (kind tfem_length_kind); a negative length is passed as
  !! 0. `out` may have rank 1 or 2.
  interface tfem_get_element_stresses
    procedure tfem_get_element_stresses
    procedure tfem_get_element_stresses_r2
    procedure tfem_get_element_stresses_i
    procedure tfem_get_element_stresses_i_r2
  end interface tfem_get_element_stresses

  !> Fortran: tfem_get_element_out_of_plane_stresses (documented in module tfem_c). `length` takes
  !! an integer(c_size_t) or a default integer (kind tfem_length_kind); a negative length is passed
  !! as 0. `out` may have rank 1 or 2.
  interface tfem_get_element_out_of_plane_stresses
    procedure tfem_get_element_out_of_plane_stresses
    procedure tfem_get_element_out_of_plane_stresses_r2
    procedure tfem_get_element_out_of_plane_stresses_i
    procedure tfem_get_element_out_of_plane_stresses_i_r2
  end interface tfem_get_element_out_of_plane_stresses

  !> Fortran: tfem_get_element_jacobians (documented in module tfem_c). `length` takes an
  !! integer(c_size_t) or a default integer (kind tfem_length_kind); a negative length is passed as
  !! 0. `out` may have rank 1 or 2.
  interface tfem_get_element_jacobians
    procedure tfem_get_element_jacobians
    procedure tfem_get_element_jacobians_r2
    procedure tfem_get_element_jacobians_i
    procedure tfem_get_element_jacobians_i_r2
  end interface tfem_get_element_jacobians

  !> Fortran: tfem_get_reactions (documented in module tfem_c). `length` takes an integer(c_size_t)
  !! or a default integer (kind tfem_length_kind); a negative length is passed as 0. `out` may have
  !! rank 1 or 2.
  interface tfem_get_reactions
    procedure tfem_get_reactions
    procedure tfem_get_reactions_r2
    procedure tfem_get_reactions_i
    procedure tfem_get_reactions_i_r2
  end interface tfem_get_reactions

  !> Fortran: tfem_get_contact_forces (documented in module tfem_c). `length` takes an
  !! integer(c_size_t) or a default integer (kind tfem_length_kind); a negative length is passed as
  !! 0. `out` may have rank 1 or 2.
  interface tfem_get_contact_forces
    procedure tfem_get_contact_forces
    procedure tfem_get_contact_forces_r2
    procedure tfem_get_contact_forces_i
    procedure tfem_get_contact_forces_i_r2
  end interface tfem_get_contact_forces

  !> Fortran: tfem_get_contact_nodal_pressures (documented in module tfem_c). `length` takes an
  !! integer(c_size_t) or a default integer (kind tfem_length_kind); a negative length is passed as
  !! 0. `out` may have rank 1 or 2.
  interface tfem_get_contact_nodal_pressures
    procedure tfem_get_contact_nodal_pressures
    procedure tfem_get_contact_nodal_pressures_r2
    procedure tfem_get_contact_nodal_pressures_i
    procedure tfem_get_contact_nodal_pressures_i_r2
  end interface tfem_get_contact_nodal_pressures

  !> Fortran: tfem_get_contact_nodal_tractions (documented in module tfem_c). `length` takes an
  !! integer(c_size_t) or a default integer (kind tfem_length_kind); a negative length is passed as
  !! 0. `out` may have rank 1 or 2.
  interface tfem_get_contact_nodal_tractions
    procedure tfem_get_contact_nodal_tractions
    procedure tfem_get_contact_nodal_tractions_r2
    procedure tfem_get_contact_nodal_tractions_i
    procedure tfem_get_contact_nodal_tractions_i_r2
  end interface tfem_get_contact_nodal_tractions

  !> Fortran: tfem_get_contact_pair_nodal_pressures (documented in module tfem_c). `length` takes an
  !! integer(c_size_t) or a default integer (kind tfem_length_kind); a negative length is passed as
  !! 0. `out` may have rank 1 or 2.
  interface tfem_get_contact_pair_nodal_pressures
    procedure tfem_get_contact_pair_nodal_pressures
    procedure tfem_get_contact_pair_nodal_pressures_r2
    procedure tfem_get_contact_pair_nodal_pressures_i
    procedure tfem_get_contact_pair_nodal_pressures_i_r2
  end interface tfem_get_contact_pair_nodal_pressures

  !> Fortran: tfem_get_contact_pair_nodal_tractions (documented in module tfem_c). `length` takes an
  !! integer(c_size_t) or a default integer (kind tfem_length_kind); a negative length is passed as
  !! 0. `out` may have rank 1 or 2.
  interface tfem_get_contact_pair_nodal_tractions
    procedure tfem_get_contact_pair_nodal_tractions
    procedure tfem_get_contact_pair_nodal_tractions_r2
    procedure tfem_get_contact_pair_nodal_tractions_i
    procedure tfem_get_contact_pair_nodal_tractions_i_r2
  end interface tfem_get_contact_pair_nodal_tractions

  !> Fortran: tfem_get_contact_gaps (documented in module tfem_c). `length` takes an
  !! integer(c_size_t) or a default integer (kind tfem_length_kind); a negative length is passed as
  !! 0. `out` may have rank 1 or 2.
  interface tfem_get_contact_gaps
    procedure tfem_get_contact_gaps
    procedure tfem_get_contact_gaps_r2
    procedure tfem_get_contact_gaps_i
    procedure tfem_get_contact_gaps_i_r2
  end interface tfem_get_contact_gaps

  !> Fortran: tfem_get_contact_active (documented in module tfem_c). `length` takes an
  !! integer(c_size_t) or a default integer (kind tfem_length_kind); a negative length is passed as
  !! 0. `out` may have rank 1 or 2.
  interface tfem_get_contact_active
    procedure tfem_get_contact_active
    procedure tfem_get_contact_active_r2
    procedure tfem_get_contact_active_i
    procedure tfem_get_contact_active_i_r2
  end interface tfem_get_contact_active

  !> Fortran: tfem_get_contact_pressure (documented in module tfem_c). `length` takes an
  !! integer(c_size_t) or a default integer (kind tfem_length_kind); a negative length is passed as
  !! 0. `out` may have rank 1 or 2.
  interface tfem_get_contact_pressure
    procedure tfem_get_contact_pressure
    procedure tfem_get_contact_pressure_r2
    procedure tfem_get_contact_pressure_i
    procedure tfem_get_contact_pressure_i_r2
  end interface tfem_get_contact_pressure

  !> Fortran: tfem_get_contact_elements (documented in module tfem_c). `length` takes an
  !! integer(c_size_t) or a default integer (kind tfem_length_kind); a negative length is passed as
  !! 0. `out` may have rank 1 or 2.
  interface tfem_get_contact_elements
    procedure tfem_get_contact_elements
    procedure tfem_get_contact_elements_r2
    procedure tfem_get_contact_elements_i
    procedure tfem_get_contact_elements_i_r2
  end interface tfem_get_contact_elements

  !> Fortran: tfem_get_contact_shear (documented in module tfem_c). `length` takes an
  !! integer(c_size_t) or a default integer (kind tfem_length_kind); a negative length is passed as
  !! 0. `out` may have rank 1 or 2.
  interface tfem_get_contact_shear
    procedure tfem_get_contact_shear
    procedure tfem_get_contact_shear_r2
    procedure tfem_get_contact_shear_i
    procedure tfem_get_contact_shear_i_r2
  end interface tfem_get_contact_shear

  !> Fortran: tfem_get_contact_friction_state (documented in module tfem_c). `length` takes an
  !! integer(c_size_t) or a default integer (kind tfem_length_kind); a negative length is passed as
  !! 0. `out` may have rank 1 or 2.
  interface tfem_get_contact_friction_state
    procedure tfem_get_contact_friction_state
    procedure tfem_get_contact_friction_state_r2
    procedure tfem_get_contact_friction_state_i
    procedure tfem_get_contact_friction_state_i_r2
  end interface tfem_get_contact_friction_state

  !> Fortran: tfem_get_contact_dissipation (documented in module tfem_c). `length` takes an
  !! integer(c_size_t) or a default integer (kind tfem_length_kind); a negative length is passed as
  !! 0. `out` may have rank 1 or 2.
  interface tfem_get_contact_dissipation
    procedure tfem_get_contact_dissipation
    procedure tfem_get_contact_dissipation_r2
    procedure tfem_get_contact_dissipation_i
    procedure tfem_get_contact_dissipation_i_r2
  end interface tfem_get_contact_dissipation

  !> Fortran: tfem_get_contact_slave_nodes (documented in module tfem_c). `node`, `tributary`, `gap`
  !! and `pressure` are OPTIONAL: omit them to pass NULL. `length` takes an integer(c_size_t) or a
  !! default integer (kind tfem_length_kind); a negative length is passed as 0. `node`, `tributary`,
  !! `gap` and `pressure` may each have rank 1 or 2. The name is no bind(C) procedure here (for
  !! c_funloc: module tfem_c).
  interface tfem_get_contact_slave_nodes
    procedure tfem_get_contact_slave_nodes_opt
    procedure tfem_get_contact_slave_nodes_opt_r2111
    procedure tfem_get_contact_slave_nodes_opt_r1211
    procedure tfem_get_contact_slave_nodes_opt_r2211
    procedure tfem_get_contact_slave_nodes_opt_r1121
    procedure tfem_get_contact_slave_nodes_opt_r2121
    procedure tfem_get_contact_slave_nodes_opt_r1221
    procedure tfem_get_contact_slave_nodes_opt_r2221
    procedure tfem_get_contact_slave_nodes_opt_r1112
    procedure tfem_get_contact_slave_nodes_opt_r2112
    procedure tfem_get_contact_slave_nodes_opt_r1212
    procedure tfem_get_contact_slave_nodes_opt_r2212
    procedure tfem_get_contact_slave_nodes_opt_r1122
    procedure tfem_get_contact_slave_nodes_opt_r2122
    procedure tfem_get_contact_slave_nodes_opt_r1222
    procedure tfem_get_contact_slave_nodes_opt_r2222
    procedure tfem_get_contact_slave_nodes_opt_i
    procedure tfem_get_contact_slave_nodes_opt_i_r2111
    procedure tfem_get_contact_slave_nodes_opt_i_r1211
    procedure tfem_get_contact_slave_nodes_opt_i_r2211
    procedure tfem_get_contact_slave_nodes_opt_i_r1121
    procedure tfem_get_contact_slave_nodes_opt_i_r2121
    procedure tfem_get_contact_slave_nodes_opt_i_r1221
    procedure tfem_get_contact_slave_nodes_opt_i_r2221
    procedure tfem_get_contact_slave_nodes_opt_i_r1112
    procedure tfem_get_contact_slave_nodes_opt_i_r2112
    procedure tfem_get_contact_slave_nodes_opt_i_r1212
    procedure tfem_get_contact_slave_nodes_opt_i_r2212
    procedure tfem_get_contact_slave_nodes_opt_i_r1122
    procedure tfem_get_contact_slave_nodes_opt_i_r2122
    procedure tfem_get_contact_slave_nodes_opt_i_r1222
    procedure tfem_get_contact_slave_nodes_opt_i_r2222
  end interface tfem_get_contact_slave_nodes

  !> Fortran: tfem_step (documented in module tfem_c). `options` and `report` are OPTIONAL: omit
  !! them to pass NULL. The name is no bind(C) procedure here (for c_funloc: module tfem_c).
  interface tfem_step
    procedure tfem_step_opt
  end interface tfem_step

  !> Fortran: tfem_get_contact_state (documented in module tfem_c). `length` takes an
  !! integer(c_size_t) or a default integer (kind tfem_length_kind); a negative length is passed as
  !! 0. `buffer` may have rank 1 or 2.
  interface tfem_get_contact_state
    procedure tfem_get_contact_state
    procedure tfem_get_contact_state_r2
    procedure tfem_get_contact_state_i
    procedure tfem_get_contact_state_i_r2
  end interface tfem_get_contact_state

  !> Fortran: tfem_set_contact_state (documented in module tfem_c). `length` takes an
  !! integer(c_size_t) or a default integer (kind tfem_length_kind); a negative length is passed as
  !! 0. `buffer` may have rank 1 or 2.
  interface tfem_set_contact_state
    procedure tfem_set_contact_state
    procedure tfem_set_contact_state_r2
    procedure tfem_set_contact_state_i
    procedure tfem_set_contact_state_i_r2
  end interface tfem_set_contact_state

  !> Fortran: tfem_get_system_matrix_size (documented in module tfem_c). `n` and `nnz` are OPTIONAL:
  !! omit them to pass NULL. The name is no bind(C) procedure here (for c_funloc: module tfem_c).
  interface tfem_get_system_matrix_size
    procedure tfem_get_system_matrix_size_opt
  end interface tfem_get_system_matrix_size

  !> Fortran: tfem_get_system_matrix (documented in module tfem_c). `col_ptr_length`,
  !! `row_idx_length`, `values_length` and `dofs_length` take integer(c_size_t) or default integers
  !! (kind tfem_length_kind), all of one kind; a negative length is passed as 0. `col_ptr`,
  !! `row_idx`, `values` and `dofs` may each have rank 1 or 2.
  interface tfem_get_system_matrix
    procedure tfem_get_system_matrix
    procedure tfem_get_system_matrix_r2111
    procedure tfem_get_system_matrix_r1211
    procedure tfem_get_system_matrix_r2211
    procedure tfem_get_system_matrix_r1121
    procedure tfem_get_system_matrix_r2121
    procedure tfem_get_system_matrix_r1221
    procedure tfem_get_system_matrix_r2221
    procedure tfem_get_system_matrix_r1112
    procedure tfem_get_system_matrix_r2112
    procedure tfem_get_system_matrix_r1212
    procedure tfem_get_system_matrix_r2212
    procedure tfem_get_system_matrix_r1122
    procedure tfem_get_system_matrix_r2122
    procedure tfem_get_system_matrix_r1222
    procedure tfem_get_system_matrix_r2222
    procedure tfem_get_system_matrix_i
    procedure tfem_get_system_matrix_i_r2111
    procedure tfem_get_system_matrix_i_r1211
    procedure tfem_get_system_matrix_i_r2211
    procedure tfem_get_system_matrix_i_r1121
    procedure tfem_get_system_matrix_i_r2121
    procedure tfem_get_system_matrix_i_r1221
    procedure tfem_get_system_matrix_i_r2221
    procedure tfem_get_system_matrix_i_r1112
    procedure tfem_get_system_matrix_i_r2112
    procedure tfem_get_system_matrix_i_r1212
    procedure tfem_get_system_matrix_i_r2212
    procedure tfem_get_system_matrix_i_r1122
    procedure tfem_get_system_matrix_i_r2122
    procedure tfem_get_system_matrix_i_r1222
    procedure tfem_get_system_matrix_i_r2222
  end interface tfem_get_system_matrix

  !> Fortran: tfem_contact_last_error (documented in module tfem_c). `length` takes an
  !! integer(c_size_t) or a default integer (kind tfem_length_kind); a negative length is passed as
  !! 0. `buffer` may also be a character string.
  interface tfem_contact_last_error
    procedure tfem_contact_last_error
    procedure tfem_contact_last_error_i
    procedure tfem_contact_last_error_str
    procedure tfem_contact_last_error_str_i
  end interface tfem_contact_last_error

  !> Fortran: tfem_contact_last_error_length (documented in module tfem_c). `context` may be omitted
  !! (NULL is passed).
  interface tfem_contact_last_error_length
    procedure tfem_contact_last_error_length
    procedure tfem_contact_last_error_length_no_context
  end interface tfem_contact_last_error_length

  !> Fortran: tfem_contact_add_side (documented in module tfem_c). `side` is OPTIONAL: omit it to
  !! pass NULL. `nodes`, `xy`, `equations` and `edges` may each have rank 1 or 2. The name is no
  !! bind(C) procedure here (for c_funloc: module tfem_c).
  interface tfem_contact_add_side
    procedure tfem_contact_add_side_opt
    procedure tfem_contact_add_side_opt_r2111
    procedure tfem_contact_add_side_opt_r1211
    procedure tfem_contact_add_side_opt_r2211
    procedure tfem_contact_add_side_opt_r1121
    procedure tfem_contact_add_side_opt_r2121
    procedure tfem_contact_add_side_opt_r1221
    procedure tfem_contact_add_side_opt_r2221
    procedure tfem_contact_add_side_opt_r1112
    procedure tfem_contact_add_side_opt_r2112
    procedure tfem_contact_add_side_opt_r1212
    procedure tfem_contact_add_side_opt_r2212
    procedure tfem_contact_add_side_opt_r1122
    procedure tfem_contact_add_side_opt_r2122
    procedure tfem_contact_add_side_opt_r1222
    procedure tfem_contact_add_side_opt_r2222
  end interface tfem_contact_add_side

  !> Fortran: tfem_contact_add_pair (documented in module tfem_c). `pair` is OPTIONAL: omit it to
  !! pass NULL. The name is no bind(C) procedure here (for c_funloc: module tfem_c).
  interface tfem_contact_add_pair
    procedure tfem_contact_add_pair_opt
  end interface tfem_contact_add_pair

  !> Fortran: tfem_contact_add_pair_with_mesh (documented in module tfem_c). `pair` is OPTIONAL:
  !! omit it to pass NULL. `connectivity` may have rank 1 or 2. The name is no bind(C) procedure
  !! here (for c_funloc: module tfem_c).
  interface tfem_contact_add_pair_with_mesh
    procedure tfem_contact_add_pair_with_mesh_opt
    procedure tfem_contact_add_pair_with_mesh_opt_r2
  end interface tfem_contact_add_pair_with_mesh

  !> Fortran: tfem_contact_sizes (documented in module tfem_c). `n_nodes`, `n_elements` and
  !! `n_entries` are OPTIONAL: omit them to pass NULL. The name is no bind(C) procedure here (for
  !! c_funloc: module tfem_c).
  interface tfem_contact_sizes
    procedure tfem_contact_sizes_opt
  end interface tfem_contact_sizes

  !> Fortran: tfem_contact_nodes (documented in module tfem_c). `length` takes an integer(c_size_t)
  !! or a default integer (kind tfem_length_kind); a negative length is passed as 0. `out` may have
  !! rank 1 or 2.
  interface tfem_contact_nodes
    procedure tfem_contact_nodes
    procedure tfem_contact_nodes_r2
    procedure tfem_contact_nodes_i
    procedure tfem_contact_nodes_i_r2
  end interface tfem_contact_nodes

  !> Fortran: tfem_contact_pattern (documented in module tfem_c). `length` takes an
  !! integer(c_size_t) or a default integer (kind tfem_length_kind); a negative length is passed as
  !! 0. `rows` and `cols` may each have rank 1 or 2.
  interface tfem_contact_pattern
    procedure tfem_contact_pattern
    procedure tfem_contact_pattern_r21
    procedure tfem_contact_pattern_r12
    procedure tfem_contact_pattern_r22
    procedure tfem_contact_pattern_i
    procedure tfem_contact_pattern_i_r21
    procedure tfem_contact_pattern_i_r12
    procedure tfem_contact_pattern_i_r22
  end interface tfem_contact_pattern

  !> Fortran: tfem_contact_evaluate (documented in module tfem_c). `values` and `residual` are
  !! OPTIONAL: omit them to pass NULL. `u_length`, `values_length` and `residual_length` take
  !! integer(c_size_t) or default integers (kind tfem_length_kind), all of one kind; a negative
  !! length is passed as 0. `u`, `values` and `residual` may each have rank 1 or 2. The name is no
  !! bind(C) procedure here (for c_funloc: module tfem_c).
  interface tfem_contact_evaluate
    procedure tfem_contact_evaluate_opt
    procedure tfem_contact_evaluate_opt_r211
    procedure tfem_contact_evaluate_opt_r121
    procedure tfem_contact_evaluate_opt_r221
    procedure tfem_contact_evaluate_opt_r112
    procedure tfem_contact_evaluate_opt_r212
    procedure tfem_contact_evaluate_opt_r122
    procedure tfem_contact_evaluate_opt_r222
    procedure tfem_contact_evaluate_opt_i
    procedure tfem_contact_evaluate_opt_i_r211
    procedure tfem_contact_evaluate_opt_i_r121
    procedure tfem_contact_evaluate_opt_i_r221
    procedure tfem_contact_evaluate_opt_i_r112
    procedure tfem_contact_evaluate_opt_i_r212
    procedure tfem_contact_evaluate_opt_i_r122
    procedure tfem_contact_evaluate_opt_i_r222
  end interface tfem_contact_evaluate

  !> Fortran: tfem_contact_gather (documented in module tfem_c). `n_equations` and `u_length` take
  !! integer(c_size_t) or default integers (kind tfem_length_kind), all of one kind; a negative
  !! length is passed as 0. `u_equations` and `u` may each have rank 1 or 2.
  interface tfem_contact_gather
    procedure tfem_contact_gather
    procedure tfem_contact_gather_r21
    procedure tfem_contact_gather_r12
    procedure tfem_contact_gather_r22
    procedure tfem_contact_gather_i
    procedure tfem_contact_gather_i_r21
    procedure tfem_contact_gather_i_r12
    procedure tfem_contact_gather_i_r22
  end interface tfem_contact_gather

  !> Fortran: tfem_contact_scatter_add (documented in module tfem_c). `residual_length` and
  !! `n_equations` take integer(c_size_t) or default integers (kind tfem_length_kind), all of one
  !! kind; a negative length is passed as 0. `residual` and `host_vector` may each have rank 1 or 2.
  interface tfem_contact_scatter_add
    procedure tfem_contact_scatter_add
    procedure tfem_contact_scatter_add_r21
    procedure tfem_contact_scatter_add_r12
    procedure tfem_contact_scatter_add_r22
    procedure tfem_contact_scatter_add_i
    procedure tfem_contact_scatter_add_i_r21
    procedure tfem_contact_scatter_add_i_r12
    procedure tfem_contact_scatter_add_i_r22
  end interface tfem_contact_scatter_add

  !> Fortran: tfem_contact_update (documented in module tfem_c). `changed` is OPTIONAL: omit it to
  !! pass NULL. `u_length` takes an integer(c_size_t) or a default integer (kind tfem_length_kind);
  !! a negative length is passed as 0. `u` may have rank 1 or 2. The name is no bind(C) procedure
  !! here (for c_funloc: module tfem_c).
  interface tfem_contact_update
    procedure tfem_contact_update_opt
    procedure tfem_contact_update_opt_r2
    procedure tfem_contact_update_opt_i
    procedure tfem_contact_update_opt_i_r2
  end interface tfem_contact_update

  !> Fortran: tfem_contact_get_active (documented in module tfem_c). `length` takes an
  !! integer(c_size_t) or a default integer (kind tfem_length_kind); a negative length is passed as
  !! 0. `out` may have rank 1 or 2.
  interface tfem_contact_get_active
    procedure tfem_contact_get_active
    procedure tfem_contact_get_active_r2
    procedure tfem_contact_get_active_i
    procedure tfem_contact_get_active_i_r2
  end interface tfem_contact_get_active

  !> Fortran: tfem_contact_set_active (documented in module tfem_c). `length` takes an
  !! integer(c_size_t) or a default integer (kind tfem_length_kind); a negative length is passed as
  !! 0. `active` may have rank 1 or 2.
  interface tfem_contact_set_active
    procedure tfem_contact_set_active
    procedure tfem_contact_set_active_r2
    procedure tfem_contact_set_active_i
    procedure tfem_contact_set_active_i_r2
  end interface tfem_contact_set_active

  !> Fortran: tfem_contact_gaps (documented in module tfem_c). `u_length` and `length` take
  !! integer(c_size_t) or default integers (kind tfem_length_kind), all of one kind; a negative
  !! length is passed as 0. `u` and `out` may each have rank 1 or 2.
  interface tfem_contact_gaps
    procedure tfem_contact_gaps
    procedure tfem_contact_gaps_r21
    procedure tfem_contact_gaps_r12
    procedure tfem_contact_gaps_r22
    procedure tfem_contact_gaps_i
    procedure tfem_contact_gaps_i_r21
    procedure tfem_contact_gaps_i_r12
    procedure tfem_contact_gaps_i_r22
  end interface tfem_contact_gaps

  !> Fortran: tfem_contact_pressures (documented in module tfem_c). `u_length` and `length` take
  !! integer(c_size_t) or default integers (kind tfem_length_kind), all of one kind; a negative
  !! length is passed as 0. `u` and `out` may each have rank 1 or 2.
  interface tfem_contact_pressures
    procedure tfem_contact_pressures
    procedure tfem_contact_pressures_r21
    procedure tfem_contact_pressures_r12
    procedure tfem_contact_pressures_r22
    procedure tfem_contact_pressures_i
    procedure tfem_contact_pressures_i_r21
    procedure tfem_contact_pressures_i_r12
    procedure tfem_contact_pressures_i_r22
  end interface tfem_contact_pressures

  !> Fortran: tfem_contact_elements (documented in module tfem_c). `length` takes an
  !! integer(c_size_t) or a default integer (kind tfem_length_kind); a negative length is passed as
  !! 0. `out` may have rank 1 or 2.
  interface tfem_contact_elements
    procedure tfem_contact_elements
    procedure tfem_contact_elements_r2
    procedure tfem_contact_elements_i
    procedure tfem_contact_elements_i_r2
  end interface tfem_contact_elements

  !> Fortran: tfem_contact_element_equations (documented in module tfem_c). `length` takes an
  !! integer(c_size_t) or a default integer (kind tfem_length_kind); a negative length is passed as
  !! 0. `out` may have rank 1 or 2.
  interface tfem_contact_element_equations
    procedure tfem_contact_element_equations
    procedure tfem_contact_element_equations_r2
    procedure tfem_contact_element_equations_i
    procedure tfem_contact_element_equations_i_r2
  end interface tfem_contact_element_equations

  !> Fortran: tfem_contact_element_blocks (documented in module tfem_c). `length` takes an
  !! integer(c_size_t) or a default integer (kind tfem_length_kind); a negative length is passed as
  !! 0. `out` may have rank 1 or 2.
  interface tfem_contact_element_blocks
    procedure tfem_contact_element_blocks
    procedure tfem_contact_element_blocks_r2
    procedure tfem_contact_element_blocks_i
    procedure tfem_contact_element_blocks_i_r2
  end interface tfem_contact_element_blocks

  !> Fortran: tfem_solid_last_error (documented in module tfem_c). `length` takes an
  !! integer(c_size_t) or a default integer (kind tfem_length_kind); a negative length is passed as
  !! 0. `buffer` may also be a character string.
  interface tfem_solid_last_error
    procedure tfem_solid_last_error
    procedure tfem_solid_last_error_i
    procedure tfem_solid_last_error_str
    procedure tfem_solid_last_error_str_i
  end interface tfem_solid_last_error

  !> Fortran: tfem_solid_last_error_length (documented in module tfem_c). `model` may be omitted
  !! (NULL is passed).
  interface tfem_solid_last_error_length
    procedure tfem_solid_last_error_length
    procedure tfem_solid_last_error_length_no_model
  end interface tfem_solid_last_error_length

  !> Fortran: tfem_solid_get_warning (documented in module tfem_c). `length` takes an
  !! integer(c_size_t) or a default integer (kind tfem_length_kind); a negative length is passed as
  !! 0. `buffer` may also be a character string.
  interface tfem_solid_get_warning
    procedure tfem_solid_get_warning
    procedure tfem_solid_get_warning_i
    procedure tfem_solid_get_warning_str
    procedure tfem_solid_get_warning_str_i
  end interface tfem_solid_get_warning

  !> Fortran: tfem_solid_get_sizes (documented in module tfem_c). `n_nodes`, `n_tetrahedra` and
  !! `n_contact_tetrahedra` are OPTIONAL: omit them to pass NULL. The name is no bind(C) procedure
  !! here (for c_funloc: module tfem_c).
  interface tfem_solid_get_sizes
    procedure tfem_solid_get_sizes_opt
  end interface tfem_solid_get_sizes

  !> Fortran: tfem_solid_get_mesh_nodes (documented in module tfem_c). `length` takes an
  !! integer(c_size_t) or a default integer (kind tfem_length_kind); a negative length is passed as
  !! 0. `xyz` may have rank 1 or 2.
  interface tfem_solid_get_mesh_nodes
    procedure tfem_solid_get_mesh_nodes
    procedure tfem_solid_get_mesh_nodes_r2
    procedure tfem_solid_get_mesh_nodes_i
    procedure tfem_solid_get_mesh_nodes_i_r2
  end interface tfem_solid_get_mesh_nodes

  !> Fortran: tfem_solid_get_mesh_tetrahedra (documented in module tfem_c). `bodies` is OPTIONAL:
  !! omit it to pass NULL. `length` and `bodies_length` take integer(c_size_t) or default integers
  !! (kind tfem_length_kind), all of one kind; a negative length is passed as 0. `tetrahedra` and
  !! `bodies` may each have rank 1 or 2. The name is no bind(C) procedure here (for c_funloc: module
  !! tfem_c).
  interface tfem_solid_get_mesh_tetrahedra
    procedure tfem_solid_get_mesh_tetrahedra_opt
    procedure tfem_solid_get_mesh_tetrahedra_opt_r21
    procedure tfem_solid_get_mesh_tetrahedra_opt_r12
    procedure tfem_solid_get_mesh_tetrahedra_opt_r22
    procedure tfem_solid_get_mesh_tetrahedra_opt_i
    procedure tfem_solid_get_mesh_tetrahedra_opt_i_r21
    procedure tfem_solid_get_mesh_tetrahedra_opt_i_r12
    procedure tfem_solid_get_mesh_tetrahedra_opt_i_r22
  end interface tfem_solid_get_mesh_tetrahedra

  !> Fortran: tfem_solid_get_boundary_faces (documented in module tfem_c). `tags` is OPTIONAL: omit
  !! it to pass NULL. `length` and `tags_length` take integer(c_size_t) or default integers (kind
  !! tfem_length_kind), all of one kind; a negative length is passed as 0. `faces` and `tags` may
  !! each have rank 1 or 2. The name is no bind(C) procedure here (for c_funloc: module tfem_c).
  interface tfem_solid_get_boundary_faces
    procedure tfem_solid_get_boundary_faces_opt
    procedure tfem_solid_get_boundary_faces_opt_r21
    procedure tfem_solid_get_boundary_faces_opt_r12
    procedure tfem_solid_get_boundary_faces_opt_r22
    procedure tfem_solid_get_boundary_faces_opt_i
    procedure tfem_solid_get_boundary_faces_opt_i_r21
    procedure tfem_solid_get_boundary_faces_opt_i_r12
    procedure tfem_solid_get_boundary_faces_opt_i_r22
  end interface tfem_solid_get_boundary_faces

  !> Fortran: tfem_solid_add_contact_pair (documented in module tfem_c). `pair` is OPTIONAL: omit it
  !! to pass NULL. The name is no bind(C) procedure here (for c_funloc: module tfem_c).
  interface tfem_solid_add_contact_pair
    procedure tfem_solid_add_contact_pair_opt
  end interface tfem_solid_add_contact_pair

  !> Fortran: tfem_solid_solve (documented in module tfem_c). `info` is OPTIONAL: omit it to pass
  !! NULL. The name is no bind(C) procedure here (for c_funloc: module tfem_c).
  interface tfem_solid_solve
    procedure tfem_solid_solve_opt
  end interface tfem_solid_solve

  !> Fortran: tfem_solid_solve_contact (documented in module tfem_c). `options` and `info` are
  !! OPTIONAL: omit them to pass NULL. The name is no bind(C) procedure here (for c_funloc: module
  !! tfem_c).
  interface tfem_solid_solve_contact
    procedure tfem_solid_solve_contact_opt
  end interface tfem_solid_solve_contact

  !> Fortran: tfem_solid_step (documented in module tfem_c). `options` and `info` are OPTIONAL: omit
  !! them to pass NULL. The name is no bind(C) procedure here (for c_funloc: module tfem_c).
  interface tfem_solid_step
    procedure tfem_solid_step_opt
  end interface tfem_solid_step

  !> Fortran: tfem_solid_get_displacements (documented in module tfem_c). `length` takes an
  !! integer(c_size_t) or a default integer (kind tfem_length_kind); a negative length is passed as
  !! 0. `out` may have rank 1 or 2.
  interface tfem_solid_get_displacements
    procedure tfem_solid_get_displacements
    procedure tfem_solid_get_displacements_r2
    procedure tfem_solid_get_displacements_i
    procedure tfem_solid_get_displacements_i_r2
  end interface tfem_solid_get_displacements

  !> Fortran: tfem_solid_get_element_strains (documented in module tfem_c). `length` takes an
  !! integer(c_size_t) or a default integer (kind tfem_length_kind); a negative length is passed as
  !! 0. `out` may have rank 1 or 2.
  interface tfem_solid_get_element_strains
    procedure tfem_solid_get_element_strains
    procedure tfem_solid_get_element_strains_r2
    procedure tfem_solid_get_element_strains_i
    procedure tfem_solid_get_element_strains_i_r2
  end interface tfem_solid_get_element_strains

  !> Fortran: tfem_solid_get_element_stresses (documented in module tfem_c). `length` takes an
  !! integer(c_size_t) or a default integer (kind tfem_length_kind); a negative length is passed as
  !! 0. `out` may have rank 1 or 2.
  interface tfem_solid_get_element_stresses
    procedure tfem_solid_get_element_stresses
    procedure tfem_solid_get_element_stresses_r2
    procedure tfem_solid_get_element_stresses_i
    procedure tfem_solid_get_element_stresses_i_r2
  end interface tfem_solid_get_element_stresses

  !> Fortran: tfem_solid_get_reactions (documented in module tfem_c). `length` takes an
  !! integer(c_size_t) or a default integer (kind tfem_length_kind); a negative length is passed as
  !! 0. `out` may have rank 1 or 2.
  interface tfem_solid_get_reactions
    procedure tfem_solid_get_reactions
    procedure tfem_solid_get_reactions_r2
    procedure tfem_solid_get_reactions_i
    procedure tfem_solid_get_reactions_i_r2
  end interface tfem_solid_get_reactions

  !> Fortran: tfem_solid_get_contact_tetrahedra (documented in module tfem_c). `length` takes an
  !! integer(c_size_t) or a default integer (kind tfem_length_kind); a negative length is passed as
  !! 0. `out` may have rank 1 or 2.
  interface tfem_solid_get_contact_tetrahedra
    procedure tfem_solid_get_contact_tetrahedra
    procedure tfem_solid_get_contact_tetrahedra_r2
    procedure tfem_solid_get_contact_tetrahedra_i
    procedure tfem_solid_get_contact_tetrahedra_i_r2
  end interface tfem_solid_get_contact_tetrahedra

  !> Fortran: tfem_solid_get_contact_active (documented in module tfem_c). `length` takes an
  !! integer(c_size_t) or a default integer (kind tfem_length_kind); a negative length is passed as
  !! 0. `out` may have rank 1 or 2.
  interface tfem_solid_get_contact_active
    procedure tfem_solid_get_contact_active
    procedure tfem_solid_get_contact_active_r2
    procedure tfem_solid_get_contact_active_i
    procedure tfem_solid_get_contact_active_i_r2
  end interface tfem_solid_get_contact_active

  !> Fortran: tfem_solid_get_contact_forces (documented in module tfem_c). `length` takes an
  !! integer(c_size_t) or a default integer (kind tfem_length_kind); a negative length is passed as
  !! 0. `out` may have rank 1 or 2.
  interface tfem_solid_get_contact_forces
    procedure tfem_solid_get_contact_forces
    procedure tfem_solid_get_contact_forces_r2
    procedure tfem_solid_get_contact_forces_i
    procedure tfem_solid_get_contact_forces_i_r2
  end interface tfem_solid_get_contact_forces

  !> Fortran: tfem_solid_get_contact_nodal_pressures (documented in module tfem_c). `length` takes
  !! an integer(c_size_t) or a default integer (kind tfem_length_kind); a negative length is passed
  !! as 0. `out` may have rank 1 or 2.
  interface tfem_solid_get_contact_nodal_pressures
    procedure tfem_solid_get_contact_nodal_pressures
    procedure tfem_solid_get_contact_nodal_pressures_r2
    procedure tfem_solid_get_contact_nodal_pressures_i
    procedure tfem_solid_get_contact_nodal_pressures_i_r2
  end interface tfem_solid_get_contact_nodal_pressures

  !> Fortran: tfem_solid_contact_create (documented in module tfem_c). `options` is OPTIONAL: omit
  !! it to pass NULL. The name is no bind(C) procedure here (for c_funloc: module tfem_c).
  interface tfem_solid_contact_create
    procedure tfem_solid_contact_create_opt
  end interface tfem_solid_contact_create

  !> Fortran: tfem_solid_contact_last_error (documented in module tfem_c). `length` takes an
  !! integer(c_size_t) or a default integer (kind tfem_length_kind); a negative length is passed as
  !! 0. `buffer` may also be a character string.
  interface tfem_solid_contact_last_error
    procedure tfem_solid_contact_last_error
    procedure tfem_solid_contact_last_error_i
    procedure tfem_solid_contact_last_error_str
    procedure tfem_solid_contact_last_error_str_i
  end interface tfem_solid_contact_last_error

  !> Fortran: tfem_solid_contact_last_error_length (documented in module tfem_c). `context` may be
  !! omitted (NULL is passed).
  interface tfem_solid_contact_last_error_length
    procedure tfem_solid_contact_last_error_length
    procedure tfem_solid_contact_last_error_length_no_context
  end interface tfem_solid_contact_last_error_length

  !> Fortran: tfem_solid_contact_add_side (documented in module tfem_c). `side` is OPTIONAL: omit it
  !! to pass NULL. `nodes`, `xyz`, `equations` and `triangles` may each have rank 1 or 2. The name
  !! is no bind(C) procedure here (for c_funloc: module tfem_c).
  interface tfem_solid_contact_add_side
    procedure tfem_solid_contact_add_side_opt
    procedure tfem_solid_contact_add_side_opt_r2111
    procedure tfem_solid_contact_add_side_opt_r1211
    procedure tfem_solid_contact_add_side_opt_r2211
    procedure tfem_solid_contact_add_side_opt_r1121
    procedure tfem_solid_contact_add_side_opt_r2121
    procedure tfem_solid_contact_add_side_opt_r1221
    procedure tfem_solid_contact_add_side_opt_r2221
    procedure tfem_solid_contact_add_side_opt_r1112
    procedure tfem_solid_contact_add_side_opt_r2112
    procedure tfem_solid_contact_add_side_opt_r1212
    procedure tfem_solid_contact_add_side_opt_r2212
    procedure tfem_solid_contact_add_side_opt_r1122
    procedure tfem_solid_contact_add_side_opt_r2122
    procedure tfem_solid_contact_add_side_opt_r1222
    procedure tfem_solid_contact_add_side_opt_r2222
  end interface tfem_solid_contact_add_side

  !> Fortran: tfem_solid_contact_add_pair (documented in module tfem_c). `pair` is OPTIONAL: omit it
  !! to pass NULL. The name is no bind(C) procedure here (for c_funloc: module tfem_c).
  interface tfem_solid_contact_add_pair
    procedure tfem_solid_contact_add_pair_opt
  end interface tfem_solid_contact_add_pair

  !> Fortran: tfem_solid_contact_sizes (documented in module tfem_c). `n_nodes`, `n_tetrahedra` and
  !! `n_entries` are OPTIONAL: omit them to pass NULL. The name is no bind(C) procedure here (for
  !! c_funloc: module tfem_c).
  interface tfem_solid_contact_sizes
    procedure tfem_solid_contact_sizes_opt
  end interface tfem_solid_contact_sizes

  !> Fortran: tfem_solid_contact_nodes (documented in module tfem_c). `length` takes an
  !! integer(c_size_t) or a default integer (kind tfem_length_kind); a negative length is passed as
  !! 0. `out` may have rank 1 or 2.
  interface tfem_solid_contact_nodes
    procedure tfem_solid_contact_nodes
    procedure tfem_solid_contact_nodes_r2
    procedure tfem_solid_contact_nodes_i
    procedure tfem_solid_contact_nodes_i_r2
  end interface tfem_solid_contact_nodes

  !> Fortran: tfem_solid_contact_tetrahedra (documented in module tfem_c). `length` takes an
  !! integer(c_size_t) or a default integer (kind tfem_length_kind); a negative length is passed as
  !! 0. `out` may have rank 1 or 2.
  interface tfem_solid_contact_tetrahedra
    procedure tfem_solid_contact_tetrahedra
    procedure tfem_solid_contact_tetrahedra_r2
    procedure tfem_solid_contact_tetrahedra_i
    procedure tfem_solid_contact_tetrahedra_i_r2
  end interface tfem_solid_contact_tetrahedra

  !> Fortran: tfem_solid_contact_pattern (documented in module tfem_c). `length` takes an
  !! integer(c_size_t) or a default integer (kind tfem_length_kind); a negative length is passed as
  !! 0. `rows` and `cols` may each have rank 1 or 2.
  interface tfem_solid_contact_pattern
    procedure tfem_solid_contact_pattern
    procedure tfem_solid_contact_pattern_r21
    procedure tfem_solid_contact_pattern_r12
    procedure tfem_solid_contact_pattern_r22
    procedure tfem_solid_contact_pattern_i
    procedure tfem_solid_contact_pattern_i_r21
    procedure tfem_solid_contact_pattern_i_r12
    procedure tfem_solid_contact_pattern_i_r22
  end interface tfem_solid_contact_pattern

  !> Fortran: tfem_solid_contact_element_equations (documented in module tfem_c). `length` takes an
  !! integer(c_size_t) or a default integer (kind tfem_length_kind); a negative length is passed as
  !! 0. `out` may have rank 1 or 2.
  interface tfem_solid_contact_element_equations
    procedure tfem_solid_contact_element_equations
    procedure tfem_solid_contact_element_equations_r2
    procedure tfem_solid_contact_element_equations_i
    procedure tfem_solid_contact_element_equations_i_r2
  end interface tfem_solid_contact_element_equations

  !> Fortran: tfem_solid_contact_element_blocks (documented in module tfem_c). `length` takes an
  !! integer(c_size_t) or a default integer (kind tfem_length_kind); a negative length is passed as
  !! 0. `out` may have rank 1 or 2.
  interface tfem_solid_contact_element_blocks
    procedure tfem_solid_contact_element_blocks
    procedure tfem_solid_contact_element_blocks_r2
    procedure tfem_solid_contact_element_blocks_i
    procedure tfem_solid_contact_element_blocks_i_r2
  end interface tfem_solid_contact_element_blocks

  !> Fortran: tfem_solid_contact_evaluate (documented in module tfem_c). `values` and `residual` are
  !! OPTIONAL: omit them to pass NULL. `u_length`, `values_length` and `residual_length` take
  !! integer(c_size_t) or default integers (kind tfem_length_kind), all of one kind; a negative
  !! length is passed as 0. `u`, `values` and `residual` may each have rank 1 or 2. The name is no
  !! bind(C) procedure here (for c_funloc: module tfem_c).
  interface tfem_solid_contact_evaluate
    procedure tfem_solid_contact_evaluate_opt
    procedure tfem_solid_contact_evaluate_opt_r211
    procedure tfem_solid_contact_evaluate_opt_r121
    procedure tfem_solid_contact_evaluate_opt_r221
    procedure tfem_solid_contact_evaluate_opt_r112
    procedure tfem_solid_contact_evaluate_opt_r212
    procedure tfem_solid_contact_evaluate_opt_r122
    procedure tfem_solid_contact_evaluate_opt_r222
    procedure tfem_solid_contact_evaluate_opt_i
    procedure tfem_solid_contact_evaluate_opt_i_r211
    procedure tfem_solid_contact_evaluate_opt_i_r121
    procedure tfem_solid_contact_evaluate_opt_i_r221
    procedure tfem_solid_contact_evaluate_opt_i_r112
    procedure tfem_solid_contact_evaluate_opt_i_r212
    procedure tfem_solid_contact_evaluate_opt_i_r122
    procedure tfem_solid_contact_evaluate_opt_i_r222
  end interface tfem_solid_contact_evaluate

  !> Fortran: tfem_solid_contact_gather (documented in module tfem_c). `n_equations` and `u_length`
  !! take integer(c_size_t) or default integers (kind tfem_length_kind), all of one kind; a negative
  !! length is passed as 0. `u_equations` and `u` may each have rank 1 or 2.
  interface tfem_solid_contact_gather
    procedure tfem_solid_contact_gather
    procedure tfem_solid_contact_gather_r21
    procedure tfem_solid_contact_gather_r12
    procedure tfem_solid_contact_gather_r22
    procedure tfem_solid_contact_gather_i
    procedure tfem_solid_contact_gather_i_r21
    procedure tfem_solid_contact_gather_i_r12
    procedure tfem_solid_contact_gather_i_r22
  end interface tfem_solid_contact_gather

  !> Fortran: tfem_solid_contact_scatter_add (documented in module tfem_c). `residual_length` and
  !! `n_equations` take integer(c_size_t) or default integers (kind tfem_length_kind), all of one
  !! kind; a negative length is passed as 0. `residual` and `host_vector` may each have rank 1 or 2.
  interface tfem_solid_contact_scatter_add
    procedure tfem_solid_contact_scatter_add
    procedure tfem_solid_contact_scatter_add_r21
    procedure tfem_solid_contact_scatter_add_r12
    procedure tfem_solid_contact_scatter_add_r22
    procedure tfem_solid_contact_scatter_add_i
    procedure tfem_solid_contact_scatter_add_i_r21
    procedure tfem_solid_contact_scatter_add_i_r12
    procedure tfem_solid_contact_scatter_add_i_r22
  end interface tfem_solid_contact_scatter_add

  !> Fortran: tfem_solid_contact_update (documented in module tfem_c). `changed`, `switched_on` and
  !! `switched_off` are OPTIONAL: omit them to pass NULL. `u_length` takes an integer(c_size_t) or a
  !! default integer (kind tfem_length_kind); a negative length is passed as 0. `u` may have rank 1
  !! or 2. The name is no bind(C) procedure here (for c_funloc: module tfem_c).
  interface tfem_solid_contact_update
    procedure tfem_solid_contact_update_opt
    procedure tfem_solid_contact_update_opt_r2
    procedure tfem_solid_contact_update_opt_i
    procedure tfem_solid_contact_update_opt_i_r2
  end interface tfem_solid_contact_update

  !> Fortran: tfem_solid_contact_get_active (documented in module tfem_c). `length` takes an
  !! integer(c_size_t) or a default integer (kind tfem_length_kind); a negative length is passed as
  !! 0. `out` may have rank 1 or 2.
  interface tfem_solid_contact_get_active
    procedure tfem_solid_contact_get_active
    procedure tfem_solid_contact_get_active_r2
    procedure tfem_solid_contact_get_active_i
    procedure tfem_solid_contact_get_active_i_r2
  end interface tfem_solid_contact_get_active

  !> Fortran: tfem_solid_contact_set_active (documented in module tfem_c). `length` takes an
  !! integer(c_size_t) or a default integer (kind tfem_length_kind); a negative length is passed as
  !! 0. `active` may have rank 1 or 2.
  interface tfem_solid_contact_set_active
    procedure tfem_solid_contact_set_active
    procedure tfem_solid_contact_set_active_r2
    procedure tfem_solid_contact_set_active_i
    procedure tfem_solid_contact_set_active_i_r2
  end interface tfem_solid_contact_set_active

  !> Fortran: tfem_solid_contact_gaps (documented in module tfem_c). `u_length` and `length` take
  !! integer(c_size_t) or default integers (kind tfem_length_kind), all of one kind; a negative
  !! length is passed as 0. `u` and `out` may each have rank 1 or 2.
  interface tfem_solid_contact_gaps
    procedure tfem_solid_contact_gaps
    procedure tfem_solid_contact_gaps_r21
    procedure tfem_solid_contact_gaps_r12
    procedure tfem_solid_contact_gaps_r22
    procedure tfem_solid_contact_gaps_i
    procedure tfem_solid_contact_gaps_i_r21
    procedure tfem_solid_contact_gaps_i_r12
    procedure tfem_solid_contact_gaps_i_r22
  end interface tfem_solid_contact_gaps

contains

  pure function c_strlen(buf) result(n)
    character(kind=c_char), intent(in) :: buf(:)
    integer :: n
    n = 0
    do while (n < size(buf))
      if (buf(n + 1) == c_null_char) exit
      n = n + 1
    end do
  end function c_strlen

  !> The message of the last failed call on model (omitted or c_null_ptr: this thread's
  !! model-free calls), as a Fortran string.
  function tfem_error_message(model) result(msg)
    type(c_ptr), intent(in), optional :: model
    character(len=:), allocatable :: msg
    character(kind=c_char), allocatable :: buf(:)
    type(c_ptr) :: handle
    integer(c_int) :: status
    integer :: i, n
    handle = c_null_ptr
    if (present(model)) handle = model
    allocate(buf(tfem_last_error_length(handle)))
    status = tfem_last_error(handle, buf, size(buf, kind=c_size_t))
    n = c_strlen(buf)
    allocate(character(len=n) :: msg)
    do i = 1, n
      msg(i:i) = buf(i)
    end do
  end function tfem_error_message

  !> The message of the last failed call on the contact context (from
  !! tfem_contact_create), as a Fortran string: a context keeps its own messages,
  !! which tfem_error_message, reading a model's, does not see.
  !! The buffer is sized by tfem_contact_last_error_length, so that a message of any length
  !! comes whole.
  function tfem_contact_error_message(context) result(msg)
    type(c_ptr), intent(in) :: context
    character(len=:), allocatable :: msg
    character(kind=c_char), allocatable :: buf(:)
    integer(c_int) :: status
    integer :: i, n
    allocate(buf(tfem_contact_last_error_length(context)))
    buf(1) = c_null_char
    status = tfem_contact_last_error(context, buf, size(buf, kind=c_size_t))
    n = c_strlen(buf)
    if (status == TFEM_STATUS_NULL_POINTER) n = 0
    allocate(character(len=n) :: msg)
    do i = 1, n
      msg(i:i) = buf(i)
    end do
  end function tfem_contact_error_message

  !> The message of the last failed call on the 3D model (from tfem_solid_create), as a
  !! Fortran string: a 3D model keeps its own messages, which tfem_error_message, reading a
  !! 2D model's, does not see. The buffer is sized by tfem_solid_last_error_length, so that
  !! a message of any length comes whole.
  function tfem_solid_error_message(model) result(msg)
    type(c_ptr), intent(in) :: model
    character(len=:), allocatable :: msg
    character(kind=c_char), allocatable :: buf(:)
    integer(c_int) :: status
    integer :: i, n
    allocate(buf(tfem_solid_last_error_length(model)))
    buf(1) = c_null_char
    status = tfem_solid_last_error(model, buf, size(buf, kind=c_size_t))
    n = c_strlen(buf)
    if (status == TFEM_STATUS_NULL_POINTER) n = 0
    allocate(character(len=n) :: msg)
    do i = 1, n
      msg(i:i) = buf(i)
    end do
  end function tfem_solid_error_message

  !> The message of the last failed call on the 3D contact context (from
  !! tfem_solid_contact_create), as a Fortran string: a context keeps its own messages,
  !! which tfem_error_message and tfem_contact_error_message do not see. The buffer is
  !! sized by tfem_solid_contact_last_error_length, so that a message of any length comes
  !! whole.
  function tfem_solid_contact_error_message(context) result(msg)
    type(c_ptr), intent(in) :: context
    character(len=:), allocatable :: msg
    character(kind=c_char), allocatable :: buf(:)
    integer(c_int) :: status
    integer :: i, n
    allocate(buf(tfem_solid_contact_last_error_length(context)))
    buf(1) = c_null_char
    status = tfem_solid_contact_last_error(context, buf, size(buf, kind=c_size_t))
    n = c_strlen(buf)
    if (status == TFEM_STATUS_NULL_POINTER) n = 0
    allocate(character(len=n) :: msg)
    do i = 1, n
      msg(i:i) = buf(i)
    end do
  end function tfem_solid_contact_error_message

  !> Warning number index (0-based) of the 3D model, as a Fortran string. The buffer is
  !! sized by tfem_solid_get_warning_size, so that a warning of any length comes whole.
  function tfem_solid_warning_message(model, index) result(msg)
    type(c_ptr), intent(in) :: model
    integer, intent(in) :: index
    character(len=:), allocatable :: msg
    character(kind=c_char), allocatable :: buf(:)
    integer(c_size_t) :: bytes
    integer(c_int) :: status
    integer :: i, n
    bytes = 1
    if (tfem_solid_get_warning_size(model, int(index, c_int), bytes) /= TFEM_STATUS_OK) bytes = 1
    allocate(buf(bytes))
    buf(1) = c_null_char
    status = tfem_solid_get_warning(model, int(index, c_int), buf, size(buf, kind=c_size_t))
    n = c_strlen(buf)
    if (status /= TFEM_STATUS_OK .and. status /= TFEM_STATUS_BUFFER_TOO_SMALL) n = 0
    allocate(character(len=n) :: msg)
    do i = 1, n
      msg(i:i) = buf(i)
    end do
  end function tfem_solid_warning_message

  !> Warning number index (0-based) of model, as a Fortran string. The buffer is sized by
  !! tfem_get_warning_size, so that a warning of any length comes whole.
  function tfem_warning_message(model, index) result(msg)
    type(c_ptr), intent(in) :: model
    integer, intent(in) :: index
    character(len=:), allocatable :: msg
    character(kind=c_char), allocatable :: buf(:)
    integer(c_size_t) :: bytes
    integer(c_int) :: status
    integer :: i, n
    bytes = 1
    if (tfem_get_warning_size(model, int(index, c_int), bytes) /= TFEM_STATUS_OK) bytes = 1
    allocate(buf(bytes))
    buf(1) = c_null_char
    status = tfem_get_warning(model, int(index, c_int), buf, size(buf, kind=c_size_t))
    n = c_strlen(buf)
    if (status /= TFEM_STATUS_OK .and. status /= TFEM_STATUS_BUFFER_TOO_SMALL) n = 0
    allocate(character(len=n) :: msg)
    do i = 1, n
      msg(i:i) = buf(i)
    end do
  end function tfem_warning_message

  !> The library version as a Fortran string.
  function tfem_version_string() result(v)
    character(len=:), allocatable :: v
    character(kind=c_char), pointer :: p(:)
    integer :: i, n
    call c_f_pointer(tfem_version(), p, [64])
    n = c_strlen(p)
    allocate(character(len=n) :: v)
    do i = 1, n
      v(i:i) = p(i)
    end do
  end function tfem_version_string

end module tfem
