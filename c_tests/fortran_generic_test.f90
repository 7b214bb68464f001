! The generic interfaces and OPTIONAL arguments of the Fortran module: buffer
! lengths as default-integer literals and variables (no int(n, c_size_t)),
! nullable pointer arguments omitted, strings as message buffers, the error
! of model-free calls read without a model. 1-based throughout.
program fortran_generic_test
  use, intrinsic :: iso_c_binding
  use tfem
  implicit none
  integer, parameter :: dp = c_double
  integer :: passed = 0, failed = 0
  type(c_ptr) :: m, c
  ! A 2 x 1 rectangle of 4 triangles (nodes 1..6), body 7; left edge tag 1,
  ! right edge tag 2. Default integers: integer(c_int) is the default kind.
  real(dp) :: xy(12) = [0._dp, 0._dp, 1._dp, 0._dp, 2._dp, 0._dp, 0._dp, 1._dp, 1._dp, 1._dp, 2._dp, 1._dp]
  integer :: conn(12) = [1, 2, 5, 1, 5, 4, 2, 3, 6, 2, 6, 5]
  integer :: body(4) = 7, edges(4) = [1, 4, 3, 6], tags(2) = [1, 2]
  ! Two unit squares, one on the other (nodes 1..4 lower body 1, 5..8 upper
  ! body 2, interface nodes coincident): lower bottom tag 1, lower top tag 2,
  ! upper bottom tag 3, upper top tag 4.
  real(dp) :: xy2(16) = [0._dp, 0._dp, 1._dp, 0._dp, 1._dp, 1._dp, 0._dp, 1._dp, &
      0._dp, 1._dp, 1._dp, 1._dp, 1._dp, 2._dp, 0._dp, 2._dp]
  integer :: conn2(12) = [1, 2, 3, 1, 3, 4, 5, 6, 7, 5, 7, 8], body2(4) = [1, 1, 2, 2]
  integer :: edges2(8) = [1, 2, 4, 3, 5, 6, 8, 7], tags2(4) = [1, 2, 3, 4]
  real(dp) :: u(12), r(12), jac(4), stiff(36), err, pressure(8), nodal(8), alone(8)
  integer :: status, n_tri, n_con, pair, flipped, flipped_ccw, i, active(8), n_warnings, n12 = 12
  integer(c_int64_t) :: n, nnz, n_only, nnz_only
  integer(c_size_t) :: bytes
  integer(c_int64_t), allocatable :: col_ptr(:), row_idx(:), dofs(:)
  real(dp), allocatable :: kval(:)
  character(kind=c_char) :: buf(256)
  character(len=256) :: text
  character(len=:), allocatable :: msg
  type(tfem_contact_report) :: report
  type(tfem_adapt_report) :: adapt
  type(tfem_contact_options) :: options
  ! A quarter of the ring 1 <= r <= 2 in two cells of 45 degrees (nodes 1..6, r = 1 at odd
  ! nodes, 2 at even ones): x = 0 tag 1 (from the outer node inwards), y = 0 tag 2, the outer
  ! arc tag 3, the inner arc tag 4.
  real(dp), parameter :: c45 = 0.70710678118654752_dp
  real(dp) :: xy3(12) = [1._dp, 0._dp, 2._dp, 0._dp, c45, c45, 2 * c45, 2 * c45, 0._dp, 1._dp, 0._dp, 2._dp]
  integer :: conn3(12) = [1, 2, 4, 1, 4, 3, 3, 4, 6, 3, 6, 5], body3(4) = 1
  integer :: edges3(12) = [6, 5, 1, 2, 2, 4, 4, 6, 3, 1, 5, 3], tags3(6) = [1, 2, 3, 3, 4, 4]
  integer :: n_ring, ne_ring, on_arc
  real(dp), allocatable :: xy_ring(:)
  integer, allocatable :: edges_ring(:), tags_ring(:)

  call expect(kind(0) == c_int, 'default integer is integer(c_int)')
  m = tfem_create()
  call expect(tfem_set_mesh(m, 6, xy, 4, conn, body, 1) == TFEM_STATUS_OK, 'set mesh, default integers')
  call expect(tfem_set_boundary_edges(m, 2, edges, tags) == TFEM_STATUS_OK, 'edges')
  call expect(tfem_set_material(m, 7, 1000._dp, 0.25_dp, TFEM_PLANE_MODE_STRESS) == TFEM_STATUS_OK, 'material')
  call expect(tfem_fix_edges(m, 1, TFEM_COMPONENT_X, 0._dp) == TFEM_STATUS_OK, 'fix edges')
  call expect(tfem_fix(m, 1, TFEM_COMPONENT_Y, 0._dp) == TFEM_STATUS_OK, 'fix')
  call expect(tfem_add_traction(m, 2, 10._dp, 0._dp) == TFEM_STATUS_OK, 'traction')
  call expect(tfem_set_tempering(m, TFEM_TEMPERING_MODE_OFF, 0._dp) == TFEM_STATUS_OK, 'plain FEM')
  ! `info` omitted: NULL.
  call expect(tfem_solve(m) == TFEM_STATUS_OK, 'solve without info: '//tfem_error_message(m))
  ! Only some of the sizes.
  n_tri = -1
  status = tfem_get_sizes(m, n_triangles=n_tri)
  call expect(status == TFEM_STATUS_OK .and. n_tri == 4, 'one size')
  call expect(tfem_get_sizes(m) == TFEM_STATUS_OK, 'no size at all')
  ! Lengths: a literal, a default-integer variable, size(), integer(c_int64_t), c_size_t.
  u = -1
  call expect(tfem_get_displacements(m, u, 12) == TFEM_STATUS_OK, 'displacements, literal length')
  err = 0
  do i = 1, 6
    err = max(err, abs(u(2 * i - 1) - 10 * xy(2 * i - 1) / 1000), abs(u(2 * i) + 0.25_dp * 10 * xy(2 * i) / 1000))
  end do
  call expect(err < 1e-14_dp, 'exact uniaxial tension')
  call expect(tfem_get_displacements(m, u, n12) == TFEM_STATUS_OK, 'displacements, variable length')
  call expect(tfem_get_displacements(m, length=size(u), out=u) == TFEM_STATUS_OK, 'displacements, keywords')
  call expect(tfem_get_displacements(m, u, 11) == TFEM_STATUS_BUFFER_TOO_SMALL, 'short buffer')
  call expect(tfem_get_displacements(m, u, -1) == TFEM_STATUS_BUFFER_TOO_SMALL, 'negative length is 0')
  call expect(tfem_get_displacements(m, u, 12_c_int64_t) == TFEM_STATUS_OK, 'c_int64_t length')
  call expect(tfem_get_displacements(m, u, 12_c_size_t) == TFEM_STATUS_OK, 'c_size_t length')
  status = tfem_get_reactions(m, r, size(r))
  call expect(status == TFEM_STATUS_OK .and. abs(r(1) + r(7) + 10) < 1e-12_dp, 'reactions')
  status = tfem_get_element_jacobians(m, jac, 4)
  call expect(status == TFEM_STATUS_OK .and. all(abs(jac - 1) < 1e-14_dp), 'jacobians')
  ! The matrix sizes one at a time, then the matrix with default-integer lengths.
  status = tfem_get_system_matrix_size(m, n, nnz)
  call expect(status == TFEM_STATUS_OK .and. n == 9, 'matrix size')
  n_only = -1
  nnz_only = -1
  status = tfem_get_system_matrix_size(m, n_only)
  call expect(status == TFEM_STATUS_OK .and. n_only == n, 'n alone')
  status = tfem_get_system_matrix_size(m, nnz=nnz_only)
  call expect(status == TFEM_STATUS_OK .and. nnz_only == nnz, 'nnz alone')
  allocate (col_ptr(n + 1), row_idx(nnz), kval(nnz), dofs(n))
  call expect(tfem_get_system_matrix(m, col_ptr, size(col_ptr), row_idx, size(row_idx), kval, size(kval), &
      dofs, size(dofs)) == TFEM_STATUS_OK, 'matrix, default-integer lengths')
  call expect(col_ptr(1) == 1 .and. col_ptr(n + 1) == nnz + 1, 'matrix 1-based')
  call expect(tfem_get_system_matrix(m, col_ptr, size(col_ptr), row_idx, size(row_idx), kval, size(kval), &
      dofs, 0) == TFEM_STATUS_BUFFER_TOO_SMALL, 'matrix, short dofs')

  ! Messages into an array or a string, with default-integer lengths.
  status = tfem_fix(m, 0, TFEM_COMPONENT_X, 0._dp)
  call expect(status == TFEM_STATUS_INVALID_ARGUMENT, 'node 0 refused')
  status = tfem_last_error(m, buf, size(buf))
  call expect(status == TFEM_STATUS_OK .and. index(chars(buf), 'index base 1') > 0, &
      'last error into an array: '//chars(buf))
  text = ''
  status = tfem_last_error(m, text, len(text))
  call expect(status == TFEM_STATUS_OK .and. index(text, 'index base 1') > 0, &
      'last error into a string: '//trim(text))
  status = tfem_last_error(m, text, 5)
  call expect(status == TFEM_STATUS_BUFFER_TOO_SMALL .and. text(5:5) == c_null_char, 'last error truncated')
  call expect(tfem_last_error(m, buf, 256_c_size_t) == TFEM_STATUS_OK, 'last error, c_size_t length')
  call expect(int(tfem_last_error_length(m)) == len(tfem_error_message(m)) + 1, 'last error length')

  ! A model-free call fails: its error is read without a model.
  xy(1:6) = [0._dp, 0._dp, 1._dp, 0._dp, 0._dp, 1._dp]
  status = tfem_element_stiffness(xy, -1._dp, 0.25_dp, TFEM_PLANE_MODE_STRAIN, 0._dp, stiff)
  call expect(status /= TFEM_STATUS_OK, 'bad element modulus')
  msg = tfem_error_message()
  call expect(len(msg) > 0 .and. msg == tfem_error_message(c_null_ptr), 'thread error, helper: '//msg)
  call expect(int(tfem_last_error_length()) == len(msg) + 1, 'thread error length without model')
  buf = 'x'
  status = tfem_last_error(buf, size(buf))
  call expect(status == TFEM_STATUS_OK .and. chars(buf) == msg, 'thread error, array')
  text = ''
  status = tfem_last_error(text, len(text))
  call expect(status == TFEM_STATUS_OK .and. text(1:len(msg)) == msg, 'thread error, string')
  status = tfem_last_error(length=256_c_size_t, buffer=buf)
  call expect(status == TFEM_STATUS_OK .and. chars(buf) == msg, 'thread error, keywords and c_size_t')

  ! The axisymmetric ring element (x the radius): an axial translation
  ! costs nothing (row-major K, u = (0, 1, 0, 1, 0, 1)); across the axis it
  ! is refused.
  xy(1:6) = [1._dp, 0._dp, 2._dp, 0._dp, 1.5_dp, 1._dp]
  status = tfem_element_stiffness(xy, 1._dp, 0.3_dp, TFEM_PLANE_MODE_AXISYMMETRIC, 1e-3_dp, stiff)
  call expect(status == TFEM_STATUS_OK, 'ring element')
  err = 0._dp
  do i = 1, 6
    err = max(err, abs(stiff(6*(i-1)+2) + stiff(6*(i-1)+4) + stiff(6*(i-1)+6)))
  end do
  call expect(err <= 1e-12_dp * maxval(abs(stiff)), 'ring element: an axial translation is free')
  xy(1) = -0.1_dp
  status = tfem_element_stiffness(xy, 1._dp, 0.3_dp, TFEM_PLANE_MODE_AXISYMMETRIC, 1e-3_dp, stiff)
  call expect(status == TFEM_STATUS_INVALID_ARGUMENT .and. index(tfem_error_message(), 'corner 1') > 0, &
      'ring element across the axis')
  call tfem_destroy(m)

  ! Warnings (node 4 is unused), read with default integers and a string.
  m = tfem_create()
  call expect(tfem_set_mesh(m, 4, xy2, 1, conn2, body2, 1) == TFEM_STATUS_OK, 'mesh with an unused node')
  status = tfem_warning_count(m, n_warnings)
  call expect(status == TFEM_STATUS_OK .and. n_warnings >= 1, 'warning count')
  text = ''
  status = tfem_get_warning(m, 0, text, len(text))
  call expect(status == TFEM_STATUS_OK .and. index(text, '4') > 0, 'warning into a string: '//trim(text))
  status = tfem_get_warning(m, 0, buf, size(buf))
  call expect(status == TFEM_STATUS_OK .and. chars(buf) == tfem_warning_message(m, 0), &
      'warning into an array')
  ! The helper sizes its buffer by the warning's size (it copied through
  ! 4096 bytes), which counts the NUL.
  call expect(tfem_get_warning_size(m, 0, bytes) == TFEM_STATUS_OK .and. &
      int(bytes) == len(tfem_warning_message(m, 0)) + 1, 'warning size')
  call tfem_destroy(m)

  ! Contact: pair index, options and report omitted, then read.
  c = tfem_create()
  call expect(tfem_set_mesh(c, 8, xy2, 4, conn2, body2, 1) == TFEM_STATUS_OK, 'two blocks')
  call expect(tfem_set_boundary_edges(c, 4, edges2, tags2) == TFEM_STATUS_OK, 'two blocks edges')
  call expect(tfem_set_material(c, 1, 1000._dp, 0.3_dp, TFEM_PLANE_MODE_STRAIN) == TFEM_STATUS_OK, 'material 1')
  call expect(tfem_set_material(c, 2, 1000._dp, 0.3_dp, TFEM_PLANE_MODE_STRAIN) == TFEM_STATUS_OK, 'material 2')
  call expect(tfem_fix_edges(c, 1, TFEM_COMPONENT_X, 0._dp) == TFEM_STATUS_OK, 'support x')
  call expect(tfem_fix_edges(c, 1, TFEM_COMPONENT_Y, 0._dp) == TFEM_STATUS_OK, 'support y')
  call expect(tfem_fix(c, 5, TFEM_COMPONENT_X, 0._dp) == TFEM_STATUS_OK, 'upper x')
  call expect(tfem_fix(c, 8, TFEM_COMPONENT_X, 0._dp) == TFEM_STATUS_OK, 'upper x')
  call expect(tfem_add_pressure(c, 4, 1._dp) == TFEM_STATUS_OK, 'pressure')
  status = tfem_add_contact_pair(c, 2, 3)
  call expect(status == TFEM_STATUS_OK, 'contact pair, index omitted: '//tfem_error_message(c))
  status = tfem_solve_contact(c)
  call expect(status == TFEM_STATUS_OK, 'contact solve, options and report omitted: '//tfem_error_message(c))
  status = tfem_get_contact_report(c, report)
  call expect(status == TFEM_STATUS_OK .and. report%iterations >= 1 .and. report%active >= 1, &
      'contact report')
  call expect(tfem_contact_options_default(options) == TFEM_STATUS_OK, 'options')
  call expect(tfem_solve_contact(c, options) == TFEM_STATUS_OK, 'contact solve, report omitted')
  status = tfem_solve_contact(c, report=report)
  call expect(status == TFEM_STATUS_OK .and. report%active >= 1, 'contact solve, options omitted')
  n_con = -1
  status = tfem_get_sizes(c, n_contact_elements=n_con)
  call expect(status == TFEM_STATUS_OK .and. n_con == report%elements, 'contact elements count')
  status = tfem_get_contact_active(c, active, n_con)
  call expect(status == TFEM_STATUS_OK .and. count_active() == report%active, &
      'contact active flags, default-integer length')
  status = tfem_get_contact_pressure(c, pressure, n_con)
  call expect(status == TFEM_STATUS_OK .and. maxval(pressure(1:n_con)) > 0, 'contact pressure')
  ! At the interface (y = 1, nodes 3, 4 below facing 6, 5 above): facing nodes read one
  ! value and the two carry the load 1 over the unit width (the clamped bottom makes the
  ! stress non-uniform); zero elsewhere.
  status = tfem_get_contact_nodal_pressures(c, nodal, 8)
  call expect(status == TFEM_STATUS_OK .and. all(nodal([1, 2, 7, 8]) == 0._dp) .and. &
      abs(nodal(3) - nodal(6)) < 1e-12_dp .and. abs(nodal(4) - nodal(5)) < 1e-12_dp .and. &
      abs(0.5_dp * (nodal(3) + nodal(4)) - 1._dp) < 1e-9_dp, 'nodal contact pressures')
  ! One pair: read alone (0-based pair index) it is the same reading.
  status = tfem_get_contact_pair_nodal_pressures(c, 0, alone, 8)
  call expect(status == TFEM_STATUS_OK .and. all(alone == nodal), 'nodal pressures of pair 0')
  call expect(tfem_get_contact_pair_nodal_pressures(c, 1, alone, 8) == TFEM_STATUS_INVALID_ARGUMENT, &
      'nodal pressures of an unknown pair')
  ! Adaptive: options omitted, then the report; the given nodes stay first.
  status = tfem_solve_adaptive(c, 1e-2_dp, TFEM_ADAPT_GOAL_ENERGY, 100000_c_int64_t, 3)
  call expect(status == TFEM_STATUS_OK, 'adaptive solve, options and report omitted: '//tfem_error_message(c))
  status = tfem_solve_adaptive(c, 1e-2_dp, TFEM_ADAPT_GOAL_ENERGY, 100000_c_int64_t, 3, report=adapt)
  call expect(status == TFEM_STATUS_OK .and. adapt%cycles == 3 .and. adapt%estimate > 0._dp, 'adaptive report')
  status = tfem_get_sizes(c, n_nodes=n_tri)
  call expect(status == TFEM_STATUS_OK .and. n_tri > 8, 'adaptive: refined nodes')
  status = tfem_solve_adaptive(c, -1._dp, TFEM_ADAPT_GOAL_ENERGY, 100000_c_int64_t, 3)
  call expect(status == TFEM_STATUS_INVALID_ARGUMENT .and. index(tfem_error_message(c), 'tolerance') > 0, &
      'adaptive: bad tolerance')
  call tfem_destroy(c)

  ! A contact pair with a user mesh across a gap: pair index kept, flip count omitted.
  xy2(10:16:2) = xy2(10:16:2) + 0.01_dp
  c = tfem_create()
  call expect(tfem_set_mesh(c, 8, xy2, 4, conn2, body2, 1) == TFEM_STATUS_OK, 'two blocks with a gap')
  call expect(tfem_set_boundary_edges(c, 4, edges2, tags2) == TFEM_STATUS_OK, 'edges')
  pair = -1
  status = tfem_add_contact_pair_with_mesh(c, 2, 3, 2, [4, 3, 6, 4, 6, 5], pair)
  call expect(status == TFEM_STATUS_OK .and. pair == 0, 'user contact mesh, flipped omitted: '//tfem_error_message(c))
  flipped = -1
  status = tfem_add_contact_pair_with_mesh(c, 2, 3, 2, [4, 6, 3, 4, 5, 6], flipped=flipped)
  call expect(status == TFEM_STATUS_OK, 'user contact mesh, pair omitted: '//tfem_error_message(c))
  flipped_ccw = -1
  status = tfem_add_contact_pair_with_mesh(c, 2, 3, 2, [4, 3, 6, 4, 6, 5], pair, flipped_ccw)
  call expect(status == TFEM_STATUS_OK .and. pair == 2 .and. flipped + flipped_ccw == 2, &
      'user contact mesh, both outputs')
  call tfem_destroy(c)

  ! A boundary circle: a radius of -1 refused (INVALID_ARGUMENT), a circle off a node of the tag
  ! naming it in index base 1, the outer arc's circle accepted; an adaptive solve then puts the
  ! nodes it adds on the outer arc on that circle. (The status is taken before the message.)
  m = tfem_create()
  call expect(tfem_set_mesh(m, 6, xy3, 4, conn3, body3, 1) == TFEM_STATUS_OK, 'quarter ring')
  call expect(tfem_set_boundary_edges(m, 6, edges3, tags3) == TFEM_STATUS_OK, 'quarter ring edges')
  status = tfem_set_boundary_circle(m, 3, 0._dp, 0._dp, -1._dp)
  msg = tfem_error_message(m)
  call expect(status == TFEM_STATUS_INVALID_ARGUMENT .and. index(msg, 'radius') > 0, 'circle of radius -1: '//msg)
  status = tfem_set_boundary_circle(m, 1, 0._dp, 0._dp, 2._dp)
  msg = tfem_error_message(m)
  call expect(status == TFEM_STATUS_INVALID_ARGUMENT .and. index(msg, 'node 5 of an edge tagged 1') > 0, &
      'circle off node 5: '//msg)
  status = tfem_set_boundary_circle(m, 3, 0._dp, 0._dp, 2._dp)
  msg = tfem_error_message(m)
  call expect(status == TFEM_STATUS_OK, 'circle of the outer arc: '//msg)
  call expect(tfem_set_material(m, 1, 1000._dp, 0.3_dp, TFEM_PLANE_MODE_STRAIN) == TFEM_STATUS_OK, 'ring material')
  call expect(tfem_fix_edges(m, 1, TFEM_COMPONENT_X, 0._dp) == TFEM_STATUS_OK, 'ring x = 0')
  call expect(tfem_fix_edges(m, 2, TFEM_COMPONENT_Y, 0._dp) == TFEM_STATUS_OK, 'ring y = 0')
  call expect(tfem_add_pressure(m, 4, 10._dp) == TFEM_STATUS_OK, 'ring pressure')
  status = tfem_solve_adaptive(m, 1e-3_dp, TFEM_ADAPT_GOAL_ENERGY, 100000_c_int64_t, 4)
  msg = tfem_error_message(m)
  call expect(status == TFEM_STATUS_OK, 'ring adaptive solve: '//msg)
  status = tfem_get_sizes(m, n_nodes=n_ring)
  call expect(status == TFEM_STATUS_OK .and. n_ring > 6, 'ring refined')
  status = tfem_get_boundary_edge_count(m, ne_ring)
  call expect(status == TFEM_STATUS_OK .and. ne_ring > 6, 'ring edges refined')
  allocate (xy_ring(2 * n_ring), edges_ring(2 * ne_ring), tags_ring(ne_ring))
  call expect(tfem_get_mesh_nodes(m, xy_ring, size(xy_ring)) == TFEM_STATUS_OK, 'ring nodes')
  call expect(tfem_get_boundary_edges(m, edges_ring, size(edges_ring), tags_ring, size(tags_ring)) == &
      TFEM_STATUS_OK, 'ring boundary edges')
  err = 0._dp
  on_arc = 0
  do i = 1, ne_ring
    if (tags_ring(i) /= 3) cycle
    on_arc = on_arc + 1
    err = max(err, abs(hypot(xy_ring(2 * edges_ring(2 * i - 1) - 1), xy_ring(2 * edges_ring(2 * i - 1))) - 2), &
        abs(hypot(xy_ring(2 * edges_ring(2 * i) - 1), xy_ring(2 * edges_ring(2 * i))) - 2))
  end do
  call expect(on_arc > 2 .and. err <= 1e-12_dp, 'new nodes of the outer arc on its circle')
  call tfem_destroy(m)

  write (*, '(a, i0, a, i0, a)') 'fortran_generic_test: ', passed, ' passed, ', failed, ' failed'
  if (failed > 0) stop 1

contains

  subroutine expect(ok, what)
    logical, intent(in) :: ok
    character(len=*), intent(in) :: what
    if (ok) then
      passed = passed + 1
    else
      failed = failed + 1
      write (*, '(2a)') 'FAIL ', what
    end if
  end subroutine expect

  !> A NUL-terminated character array as a string.
  function chars(a) result(s)
    character(kind=c_char), intent(in) :: a(:)
    character(len=:), allocatable :: s
    integer :: k
    k = 0
    do while (k < size(a))
      if (a(k + 1) == c_null_char) exit
      k = k + 1
    end do
    allocate (character(len=k) :: s)
    s = transfer(a(1:k), s)
  end function chars

  integer function count_active()
    count_active = count(active(1:n_con) == 1)
  end function count_active
end program fortran_generic_test
