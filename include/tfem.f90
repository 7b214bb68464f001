! Generated from include/tfem.h by tests/fortran.rs. Do not edit:
! regenerate with `TFEM_BLESS=1 cargo test --test fortran`.
!
! Fortran interface to tfem (ISO_C_BINDING). Every function returns an
! integer(c_int) status (TFEM_STATUS_OK = 0). Pass index_base = 1 to
! tfem_set_mesh to use 1-based node, triangle and edge numbers in every
! call and message. The model handle is a type(c_ptr). See tfem.h for
! units, sizes and the thread contract; tfem_error_message(model) returns
! the last error as a Fortran string.
module tfem
  use, intrinsic :: iso_c_binding
  implicit none
  private :: c_strlen

  ! tfem_status
  integer(c_int), parameter :: TFEM_STATUS_OK = 0
  integer(c_int), parameter :: TFEM_STATUS_NULL_POINTER = 1
  integer(c_int), parameter :: TFEM_STATUS_INVALID_ARGUMENT = 2
  integer(c_int), parameter :: TFEM_STATUS_INVALID_MESH = 3
  integer(c_int), parameter :: TFEM_STATUS_INVALID_MATERIAL = 4
  integer(c_int), parameter :: TFEM_STATUS_INVALID_STATE = 5
  integer(c_int), parameter :: TFEM_STATUS_BUFFER_TOO_SMALL = 6
  integer(c_int), parameter :: TFEM_STATUS_SINGULAR = 7
  integer(c_int), parameter :: TFEM_STATUS_NOT_CONVERGED = 8
  integer(c_int), parameter :: TFEM_STATUS_DEGENERATE_ELEMENT = 9
  integer(c_int), parameter :: TFEM_STATUS_INVALID_CONTACT = 10
  integer(c_int), parameter :: TFEM_STATUS_NUMERICAL_FAILURE = 11
  integer(c_int), parameter :: TFEM_STATUS_INTERNAL = 12
  integer(c_int), parameter :: TFEM_STATUS_OUT_OF_MEMORY = 13
  integer(c_int), parameter :: TFEM_STATUS_IO = 14

  ! tfem_tempering_mode
  integer(c_int), parameter :: TFEM_TEMPERING_MODE_AUTO = 0
  integer(c_int), parameter :: TFEM_TEMPERING_MODE_LAMBDA = 1
  integer(c_int), parameter :: TFEM_TEMPERING_MODE_FIXED_JMIN = 2
  integer(c_int), parameter :: TFEM_TEMPERING_MODE_OFF = 3

  ! tfem_ordering_mode
  integer(c_int), parameter :: TFEM_ORDERING_MODE_AUTO = 0
  integer(c_int), parameter :: TFEM_ORDERING_MODE_AMD = 1
  integer(c_int), parameter :: TFEM_ORDERING_MODE_NESTED_DISSECTION = 2

  ! tfem_contact_law
  integer(c_int), parameter :: TFEM_CONTACT_LAW_FRICTIONLESS = 0
  integer(c_int), parameter :: TFEM_CONTACT_LAW_STICK = 1

  ! tfem_inversion_test
  integer(c_int), parameter :: TFEM_INVERSION_TEST_LINEARISED = 0
  integer(c_int), parameter :: TFEM_INVERSION_TEST_LITERAL = 1

  ! tfem_plane_mode
  integer(c_int), parameter :: TFEM_PLANE_MODE_STRAIN = 0
  integer(c_int), parameter :: TFEM_PLANE_MODE_STRESS = 1

  ! tfem_component
  integer(c_int), parameter :: TFEM_COMPONENT_X = 0
  integer(c_int), parameter :: TFEM_COMPONENT_Y = 1

  type, bind(C) :: tfem_solve_info
    integer(c_int64_t) :: unknowns
    integer(c_int64_t) :: matrix_nnz
    integer(c_int64_t) :: factor_nnz
    integer(c_int64_t) :: factorizations
    integer(c_int64_t) :: interface_unknowns
    real(c_double) :: relative_residual
    real(c_double) :: condition_estimate
    integer(c_int64_t) :: memory_bytes
    integer(c_int64_t) :: factorization_bytes
    real(c_double) :: time_analysis
    real(c_double) :: time_assembly
    real(c_double) :: time_factorization
    real(c_double) :: time_solve
    real(c_double) :: time_interface
    real(c_double) :: time_total
  end type tfem_solve_info

  type, bind(C) :: tfem_contact_options
    integer(c_int) :: law
    real(c_double) :: contact_modulus
    real(c_double) :: lambda
    integer(c_int) :: inversion_test
    integer(c_int) :: max_iterations
    integer(c_int) :: refactorize
  end type tfem_contact_options

  type, bind(C) :: tfem_contact_report
    integer(c_int) :: iterations
    integer(c_int) :: elements
    integer(c_int) :: active
    real(c_double) :: contact_length
    real(c_double) :: max_penetration
    type(tfem_solve_info) :: info
  end type tfem_contact_report

  interface
  !> The library version as a static NUL-terminated string ("major.minor.patch")
    function tfem_version() &
        bind(C, name="tfem_version") result(res)
      import
      type(c_ptr) :: res
    end function tfem_version

  !> Creates an empty model
    function tfem_create() &
        bind(C, name="tfem_create") result(res)
      import
      type(c_ptr) :: res
    end function tfem_create

  !> Destroys a model and everything it owns
    subroutine tfem_destroy(model) &
        bind(C, name="tfem_destroy")
      import
      type(c_ptr), value :: model
    end subroutine tfem_destroy

  !> Copies the message of the last failed call on `model` (empty after a successful call) into
  !! `buffer` (`length` bytes including the final NUL)
    function tfem_last_error(model, buffer, length) &
        bind(C, name="tfem_last_error") result(status)
      import
      type(c_ptr), value :: model
      character(kind=c_char), intent(inout) :: buffer(*)
      integer(c_size_t), value :: length
      integer(c_int) :: status
    end function tfem_last_error

  !> Size in bytes (including the final NUL) of the message `tfem_last_error` would give
    function tfem_last_error_length(model) &
        bind(C, name="tfem_last_error_length") result(res)
      import
      type(c_ptr), value :: model
      integer(c_size_t) :: res
    end function tfem_last_error_length

  !> Number of warnings: mesh validation (unused or coincident nodes, inverted or clockwise
  !! triangles) and the last solve (tempering of well-shaped elements)
    function tfem_warning_count(model, count) &
        bind(C, name="tfem_warning_count") result(status)
      import
      type(c_ptr), value :: model
      integer(c_int), intent(out) :: count
      integer(c_int) :: status
    end function tfem_warning_count

  !> Copies warning number `index` (0-based, whatever the index base) into `buffer` of `length`
  !! bytes, truncating like `tfem_last_error`
    function tfem_get_warning(model, index, buffer, length) &
        bind(C, name="tfem_get_warning") result(status)
      import
      type(c_ptr), value :: model
      integer(c_int), value :: index
      character(kind=c_char), intent(inout) :: buffer(*)
      integer(c_size_t), value :: length
      integer(c_int) :: status
    end function tfem_get_warning

  !> Sets the mesh: `n_nodes` nodes with coordinates `xy` (2·n_nodes values, x0 y0 x1 y1 …),
  !! `n_triangles` P1 triangles with `connectivity` (3·n_triangles node indices, counter-clockwise)
  !! and a body tag per triangle in `body_of_triangle`
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

  !> Loads a Gmsh MSH 4.1 mesh (ASCII or binary) from the file `path` (NUL-terminated UTF-8):
  !! physical surfaces become bodies (tag = body), physical curves become boundary-edge tags; only
  !! 3-node triangles and 2-node lines, in the plane z = 0
    function tfem_load_gmsh(model, path, index_base) &
        bind(C, name="tfem_load_gmsh") result(status)
      import
      type(c_ptr), value :: model
      character(kind=c_char), intent(in) :: path(*)
      integer(c_int), value :: index_base
      integer(c_int) :: status
    end function tfem_load_gmsh

  !> Sets the tagged boundary edges: `n_edges` edges given by `edge_nodes` (2·n_edges node indices)
  !! with a tag each in `tags`
    function tfem_set_boundary_edges(model, n_edges, edge_nodes, tags) &
        bind(C, name="tfem_set_boundary_edges") result(status)
      import
      type(c_ptr), value :: model
      integer(c_int), value :: n_edges
      integer(c_int), intent(in) :: edge_nodes(*)
      integer(c_int), intent(in) :: tags(*)
      integer(c_int) :: status
    end function tfem_set_boundary_edges

  !> Sets the material of body `body`: Young's modulus `young` (> 0), Poisson ratio `poisson` (in
  !! (-1, 0.5) for plane strain, (-1, 0.5] for plane stress) and `plane` (a `PlaneMode`: 0 strain, 1
  !! stress)
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

  !> Chooses Jmin: `mode` is a `TemperingMode` (0 auto, 1 lambda = `value`, 2 fixed Jmin = `value`, 3
  !! off); `value` is ignored for 0 and 3
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
  !! dissection concurrently, 0 as one tree
    function tfem_set_ordering(model, ordering, parallel_subtrees) &
        bind(C, name="tfem_set_ordering") result(status)
      import
      type(c_ptr), value :: model
      integer(c_int), value :: ordering
      integer(c_int), value :: parallel_subtrees
      integer(c_int) :: status
    end function tfem_set_ordering

  !> Prescribes displacement component `component` (0 x, 1 y) of `node` to `value` (model length
  !! units)
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
    function tfem_fix_edges(model, tag, comp, value) &
        bind(C, name="tfem_fix_edges") result(status)
      import
      type(c_ptr), value :: model
      integer(c_int), value :: tag
      integer(c_int), value :: comp
      real(c_double), value :: value
      integer(c_int) :: status
    end function tfem_fix_edges

  !> Removes every prescribed displacement
    function tfem_clear_constraints(model) &
        bind(C, name="tfem_clear_constraints") result(status)
      import
      type(c_ptr), value :: model
      integer(c_int) :: status
    end function tfem_clear_constraints

  !> Applies pressure `pressure` (force per unit length, positive pushing into the body) on the
  !! boundary edges tagged `tag`
    function tfem_add_pressure(model, tag, pressure) &
        bind(C, name="tfem_add_pressure") result(status)
      import
      type(c_ptr), value :: model
      integer(c_int), value :: tag
      real(c_double), value :: pressure
      integer(c_int) :: status
    end function tfem_add_pressure

  !> Applies the traction (tx, ty) (force per unit length) on the boundary edges tagged `tag`
    function tfem_add_traction(model, tag, tx, ty) &
        bind(C, name="tfem_add_traction") result(status)
      import
      type(c_ptr), value :: model
      integer(c_int), value :: tag
      real(c_double), value :: tx
      real(c_double), value :: ty
      integer(c_int) :: status
    end function tfem_add_traction

  !> Adds the point force (fx, fy) at `node`
    function tfem_add_nodal_force(model, node, fx, fy) &
        bind(C, name="tfem_add_nodal_force") result(status)
      import
      type(c_ptr), value :: model
      integer(c_int), value :: node
      real(c_double), value :: fx
      real(c_double), value :: fy
      integer(c_int) :: status
    end function tfem_add_nodal_force

  !> Sets the body force (bx, by) (force per unit area) of body `body`
    function tfem_set_body_force(model, body, bx, by) &
        bind(C, name="tfem_set_body_force") result(status)
      import
      type(c_ptr), value :: model
      integer(c_int), value :: body
      real(c_double), value :: bx
      real(c_double), value :: by
      integer(c_int) :: status
    end function tfem_set_body_force

  !> Removes every load
    function tfem_clear_loads(model) &
        bind(C, name="tfem_clear_loads") result(status)
      import
      type(c_ptr), value :: model
      integer(c_int) :: status
    end function tfem_clear_loads

  !> Solves a scene without contact
    function tfem_solve(model, info) &
        bind(C, name="tfem_solve") result(status)
      import
      type(c_ptr), value :: model
      type(tfem_solve_info), intent(inout) :: info
      integer(c_int) :: status
    end function tfem_solve

  !> Sizes: nodes, triangles, and elements of the contact mesh of the last contact solve (0
  !! otherwise)
    function tfem_get_sizes(model, n_nodes, n_triangles, n_contact_elements) &
        bind(C, name="tfem_get_sizes") result(status)
      import
      type(c_ptr), value :: model
      integer(c_int), intent(out) :: n_nodes
      integer(c_int), intent(out) :: n_triangles
      integer(c_int), intent(out) :: n_contact_elements
      integer(c_int) :: status
    end function tfem_get_sizes

  !> Copies the nodal displacements (u0 v0 u1 v1 …, 2·n_nodes values) of the last solve into `out`
  !! of `length` values
    function tfem_get_displacements(model, out, length) &
        bind(C, name="tfem_get_displacements") result(status)
      import
      type(c_ptr), value :: model
      real(c_double), intent(inout) :: out(*)
      integer(c_size_t), value :: length
      integer(c_int) :: status
    end function tfem_get_displacements

  !> Copies element strains (ε_xx ε_yy γ_xy per triangle, engineering shear, 3·n_triangles
  !! values), computed on request
    function tfem_get_element_strains(model, out, length) &
        bind(C, name="tfem_get_element_strains") result(status)
      import
      type(c_ptr), value :: model
      real(c_double), intent(inout) :: out(*)
      integer(c_size_t), value :: length
      integer(c_int) :: status
    end function tfem_get_element_strains

  !> Copies element stresses (σ_xx σ_yy σ_xy per triangle, 3·n_triangles values), computed on
  !! request
    function tfem_get_element_stresses(model, out, length) &
        bind(C, name="tfem_get_element_stresses") result(status)
      import
      type(c_ptr), value :: model
      real(c_double), intent(inout) :: out(*)
      integer(c_size_t), value :: length
      integer(c_int) :: status
    end function tfem_get_element_stresses

  !> Copies J (twice the signed area, initial configuration) of every triangle (n_triangles values)
    function tfem_get_element_jacobians(model, out, length) &
        bind(C, name="tfem_get_element_jacobians") result(status)
      import
      type(c_ptr), value :: model
      real(c_double), intent(inout) :: out(*)
      integer(c_size_t), value :: length
      integer(c_int) :: status
    end function tfem_get_element_jacobians

  !> Copies reaction forces (Rx Ry per node, 2·n_nodes values; zero at DOFs that are not
  !! prescribed), computed on request
    function tfem_get_reactions(model, out, length) &
        bind(C, name="tfem_get_reactions") result(status)
      import
      type(c_ptr), value :: model
      real(c_double), intent(inout) :: out(*)
      integer(c_size_t), value :: length
      integer(c_int) :: status
    end function tfem_get_reactions

  !> Sizes of the stiffness matrix of the last solve (see `tfem_get_system_matrix`): `n` unknowns and
  !! `nnz` stored entries of its upper triangle
    function tfem_get_system_matrix_size(model, n, nnz) &
        bind(C, name="tfem_get_system_matrix_size") result(status)
      import
      type(c_ptr), value :: model
      integer(c_int64_t), intent(out) :: n
      integer(c_int64_t), intent(out) :: nnz
      integer(c_int) :: status
    end function tfem_get_system_matrix_size

  !> Copies the stiffness matrix K of the last solve on its unknowns (the DOFs left after Dirichlet
  !! elimination), the system K u = f whose solution `tfem_get_displacements` returns; for a contact
  !! solve it holds the contact elements active at convergence
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
  !! v3)
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
  !! row-major into `out` (9 values)
    function tfem_laplacian_stiffness(xy, kappa, jmin, out) &
        bind(C, name="tfem_laplacian_stiffness") result(status)
      import
      real(c_double), intent(in) :: xy(*)
      real(c_double), value :: kappa
      real(c_double), value :: jmin
      real(c_double), intent(inout) :: out(*)
      integer(c_int) :: status
    end function tfem_laplacian_stiffness

  !> Declares a potential contact interface between the boundary edges tagged `tag_a` (one body) and
  !! `tag_b` (another body)
    function tfem_add_contact_pair(model, tag_a, tag_b, pair) &
        bind(C, name="tfem_add_contact_pair") result(status)
      import
      type(c_ptr), value :: model
      integer(c_int), value :: tag_a
      integer(c_int), value :: tag_b
      integer(c_int), intent(out) :: pair
      integer(c_int) :: status
    end function tfem_add_contact_pair

  !> Declares a contact pair with a user-made contact mesh B: `n_triangles` triangles in
  !! `connectivity` (3 per triangle) over nodes of the two interfaces
    function tfem_add_contact_pair_with_mesh(model, tag_a, tag_b, n_triangles, connectivity, pair, &
        flipped) &
        bind(C, name="tfem_add_contact_pair_with_mesh") result(status)
      import
      type(c_ptr), value :: model
      integer(c_int), value :: tag_a
      integer(c_int), value :: tag_b
      integer(c_int), value :: n_triangles
      integer(c_int), intent(in) :: connectivity(*)
      integer(c_int), intent(out) :: pair
      integer(c_int), intent(out) :: flipped
      integer(c_int) :: status
    end function tfem_add_contact_pair_with_mesh

  !> Fills `options` with the defaults: frictionless law, E_c and λ derived from the model,
  !! linearised inversion test, 50 iterations
    function tfem_contact_options_default(options) &
        bind(C, name="tfem_contact_options_default") result(status)
      import
      type(tfem_contact_options), intent(inout) :: options
      integer(c_int) :: status
    end function tfem_contact_options_default

  !> Solves the contact problem by the active-set loop over inverted contact elements
    function tfem_solve_contact(model, options, report) &
        bind(C, name="tfem_solve_contact") result(status)
      import
      type(c_ptr), value :: model
      type(tfem_contact_options), intent(in) :: options
      type(tfem_contact_report), intent(inout) :: report
      integer(c_int) :: status
    end function tfem_solve_contact

  !> Copies the active flag (1 active, 0 not) of every contact element of the last contact solve
  !! (n_contact_elements values, see `tfem_get_sizes`)
    function tfem_get_contact_active(model, out, length) &
        bind(C, name="tfem_get_contact_active") result(status)
      import
      type(c_ptr), value :: model
      integer(c_int), intent(inout) :: out(*)
      integer(c_size_t), value :: length
      integer(c_int) :: status
    end function tfem_get_contact_active

  !> Copies the contact pressure (positive in compression, 0 when inactive) of every contact element
  !! (n_contact_elements values)
    function tfem_get_contact_pressure(model, out, length) &
        bind(C, name="tfem_get_contact_pressure") result(status)
      import
      type(c_ptr), value :: model
      real(c_double), intent(inout) :: out(*)
      integer(c_size_t), value :: length
      integer(c_int) :: status
    end function tfem_get_contact_pressure

  !> Copies the nodes of every contact element (3·n_contact_elements indices, in the model's index
  !! base), oriented so that J > 0 when the gap opens
    function tfem_get_contact_elements(model, out, length) &
        bind(C, name="tfem_get_contact_elements") result(status)
      import
      type(c_ptr), value :: model
      integer(c_int), intent(inout) :: out(*)
      integer(c_size_t), value :: length
      integer(c_int) :: status
    end function tfem_get_contact_elements

  !> Writes the report of the last contact solve to `report`
    function tfem_get_contact_report(model, report) &
        bind(C, name="tfem_get_contact_report") result(status)
      import
      type(c_ptr), value :: model
      type(tfem_contact_report), intent(inout) :: report
      integer(c_int) :: status
    end function tfem_get_contact_report

  end interface

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

  !> The message of the last failed call on model (c_null_ptr: this thread's
  !! model-free calls), as a Fortran string.
  function tfem_error_message(model) result(msg)
    type(c_ptr), intent(in) :: model
    character(len=:), allocatable :: msg
    character(kind=c_char), allocatable :: buf(:)
    integer(c_int) :: status
    integer :: i, n
    allocate(buf(tfem_last_error_length(model)))
    status = tfem_last_error(model, buf, int(size(buf), c_size_t))
    n = c_strlen(buf)
    allocate(character(len=n) :: msg)
    do i = 1, n
      msg(i:i) = buf(i)
    end do
  end function tfem_error_message

  !> Warning number index (0-based) of model, as a Fortran string.
  function tfem_warning_message(model, index) result(msg)
    type(c_ptr), intent(in) :: model
    integer, intent(in) :: index
    character(len=:), allocatable :: msg
    character(kind=c_char) :: buf(4096)
    integer(c_int) :: status
    integer :: i, n
    status = tfem_get_warning(model, int(index, c_int), buf, int(size(buf), c_size_t))
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
