! The Fortran interface of tfem, 1-based: a tension test solved exactly,
! and error paths reported with messages in the user's numbering.
program fortran_api_test
  use, intrinsic :: iso_c_binding
  use tfem
  implicit none
  integer, parameter :: dp = c_double
  integer :: passed = 0, failed = 0
  type(c_ptr) :: m, ctx
  ! A 2 x 1 rectangle of 4 triangles (nodes 1..6), body 7; left edge tag 1,
  ! right edge tag 2.
  real(dp) :: xy(12) = [0._dp, 0._dp, 1._dp, 0._dp, 2._dp, 0._dp, 0._dp, 1._dp, 1._dp, 1._dp, 2._dp, 1._dp]
  integer(c_int) :: conn(12) = [1, 2, 5, 1, 5, 4, 2, 3, 6, 2, 6, 5]
  integer(c_int) :: body(4) = 7
  integer(c_int) :: edges(4) = [1, 4, 3, 6], tags(2) = [1, 2]
  real(dp) :: u(12), r(12), err
  integer(c_int) :: status, bad(12), pair
  type(tfem_solve_info) :: info
  character(len=:), allocatable :: msg
  integer :: i, j
  integer(c_int64_t) :: n, nnz, p
  integer(c_int64_t), allocatable :: col_ptr(:), row_idx(:), dofs(:)
  real(dp), allocatable :: kval(:), x(:), ku(:), f(:)

  call expect(len(tfem_version_string()) > 0, 'version')
  m = tfem_create()
  status = tfem_solve(m, info)
  call expect(status == TFEM_STATUS_INVALID_STATE, 'solve before mesh')
  bad = conn
  bad(6) = 7
  status = tfem_set_mesh(m, 6_c_int, xy, 4_c_int, bad, body, 1_c_int)
  msg = tfem_error_message(m)
  call expect(status == TFEM_STATUS_INVALID_MESH .and. index(msg, 'triangle 2') > 0 .and. index(msg, '7') > 0, &
      'out-of-range node named 1-based: '//msg)
  call expect(tfem_set_mesh(m, 6_c_int, xy, 4_c_int, conn, body, 1_c_int) == TFEM_STATUS_OK, 'set mesh')
  call expect(tfem_set_boundary_edges(m, 2_c_int, edges, tags) == TFEM_STATUS_OK, 'edges')
  status = tfem_set_material(m, 7_c_int, -1._dp, 0.25_dp, TFEM_PLANE_MODE_STRESS)
  call expect(status == TFEM_STATUS_INVALID_MATERIAL .and. index(tfem_error_message(m), 'body 7') > 0, 'bad E')
  call expect(tfem_set_material(m, 7_c_int, 1000._dp, 0.25_dp, TFEM_PLANE_MODE_STRESS) == TFEM_STATUS_OK, 'material')
  call expect(tfem_set_tempering(m, TFEM_TEMPERING_MODE_LAMBDA, 1000._dp) == TFEM_STATUS_OK, 'tempering')
  status = tfem_fix(m, 0_c_int, TFEM_COMPONENT_X, 0._dp)
  call expect(status == TFEM_STATUS_INVALID_ARGUMENT .and. index(tfem_error_message(m), 'index base 1') > 0, &
      'node 0 is out of range in 1-based numbering')
  call expect(tfem_fix_edges(m, 1_c_int, TFEM_COMPONENT_X, 0._dp) == TFEM_STATUS_OK, 'fix edges')
  call expect(tfem_fix(m, 1_c_int, TFEM_COMPONENT_Y, 0._dp) == TFEM_STATUS_OK, 'fix')
  call expect(tfem_add_traction(m, 2_c_int, 10._dp, 0._dp) == TFEM_STATUS_OK, 'traction')
  status = tfem_set_ordering(m, 7_c_int, 1_c_int)
  call expect(status == TFEM_STATUS_INVALID_ARGUMENT .and. index(tfem_error_message(m), 'ordering = 7') > 0, &
      'bad ordering named')
  call expect(tfem_set_ordering(m, TFEM_ORDERING_MODE_AMD, 1_c_int) == TFEM_STATUS_OK, 'AMD ordering')
  call expect(tfem_solve(m, info) == TFEM_STATUS_OK, 'solve: '//tfem_error_message(m))
  call expect(info%unknowns == 9 .and. info%relative_residual < 1e-12_dp, 'solve info')
  call expect(tfem_get_displacements(m, u, int(size(u), c_size_t)) == TFEM_STATUS_OK, 'displacements')
  err = 0
  do i = 1, 6
    err = max(err, abs(u(2 * i - 1) - 10 * xy(2 * i - 1) / 1000), abs(u(2 * i) + 0.25_dp * 10 * xy(2 * i) / 1000))
  end do
  call expect(err < 1e-14_dp, 'exact uniaxial tension')
  call expect(tfem_get_reactions(m, r, int(size(r), c_size_t)) == TFEM_STATUS_OK, 'reactions')
  call expect(abs(r(1) + r(7) + 10) < 1e-12_dp, 'reactions balance the load')
  ! The solve's matrix, 1-based: K u = f on the unknowns, f the traction's
  ! nodal forces (5 in x at nodes 3 and 6: positions 5 and 11 of u).
  call expect(tfem_get_system_matrix_size(m, n, nnz) == TFEM_STATUS_OK .and. n == 9, 'matrix size')
  allocate (col_ptr(n + 1), row_idx(nnz), kval(nnz), dofs(n), x(n), ku(n), f(12))
  call expect(tfem_get_system_matrix(m, col_ptr, size(col_ptr, kind=c_size_t), row_idx, size(row_idx, kind=c_size_t), &
      kval, size(kval, kind=c_size_t), dofs, size(dofs, kind=c_size_t)) == TFEM_STATUS_OK, 'matrix')
  call expect(col_ptr(1) == 1 .and. col_ptr(n + 1) == nnz + 1, 'matrix 1-based')
  x = u(dofs)
  ku = 0
  do j = 1, int(n)
    do p = col_ptr(j), col_ptr(j + 1) - 1
      ku(row_idx(p)) = ku(row_idx(p)) + kval(p) * x(j)
      if (row_idx(p) /= j) ku(j) = ku(j) + kval(p) * x(row_idx(p))
    end do
  end do
  f = 0
  f([5, 11]) = 5
  call expect(maxval(abs(ku - f(dofs))) < 1e-12_dp, 'K u = f through the matrix')
  status = tfem_get_displacements(m, u, 11_c_size_t)
  call expect(status == TFEM_STATUS_BUFFER_TOO_SMALL, 'short buffer')
  ! Friction and moved prescribed values: pairs are 0-based, nodes 1-based.
  status = tfem_set_friction(m, 0_c_int, 0.3_dp)
  call expect(status == TFEM_STATUS_INVALID_ARGUMENT .and. index(tfem_error_message(m), 'pair 0') > 0, &
      'friction of a pair that does not exist')
  status = tfem_set_prescribed(m, 3_c_int, TFEM_COMPONENT_Y, 1._dp)
  call expect(status == TFEM_STATUS_INVALID_ARGUMENT .and. index(tfem_error_message(m), 'node 3') > 0, &
      'moving a value that is not prescribed, named 1-based')
  call expect(tfem_set_prescribed(m, 1_c_int, TFEM_COMPONENT_Y, 1e-3_dp) == TFEM_STATUS_OK, 'move a prescribed value')
  call expect(tfem_solve(m, info) == TFEM_STATUS_OK, 'solve after the move')
  call expect(tfem_get_displacements(m, u, int(size(u), c_size_t)) == TFEM_STATUS_OK, 'moved displacements')
  call expect(abs(u(2) - 1e-3_dp) < 1e-15_dp, 'the moved value holds')

  ! A contact context keeps its own messages, read as a Fortran string; a
  ! model given as a context (type(c_ptr) does not tell them apart) is
  ! refused, and says so.
  ctx = tfem_contact_create(1_c_int)
  status = tfem_contact_add_pair(ctx, 0_c_int, 1_c_int, pair)
  call expect(status == TFEM_STATUS_INVALID_ARGUMENT .and. len(tfem_contact_error_message(ctx)) > 0 &
      .and. index(tfem_contact_error_message(ctx), 'side') > 0, 'a contact context''s message: ' &
      //tfem_contact_error_message(ctx))
  call expect(index(tfem_contact_error_message(m), 'is not a contact context') > 0, &
      'a model given as a context: '//tfem_contact_error_message(m))
  call expect(index(tfem_error_message(ctx), 'is not a model') > 0, &
      'a context given as a model: '//tfem_error_message(ctx))
  ! The helper sizes its buffer by the message's length (it copied through
  ! 4096 bytes): the whole message comes, the length counting the NUL.
  call expect(int(tfem_contact_last_error_length(ctx)) == len(tfem_contact_error_message(ctx)) + 1, &
      'a contact context''s message length')
  call expect(int(tfem_contact_last_error_length(m)) == len(tfem_contact_error_message(m)) + 1, &
      'the length of the message of a model given as a context')
  call tfem_contact_destroy(ctx)
  call tfem_destroy(m)

  write (*, '(a, i0, a, i0, a)') 'fortran_api_test: ', passed, ' passed, ', failed, ' failed'
  write (*, '(i0, a, i0, a)') passed, ' passed, ', failed, ' failed'
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
end program fortran_api_test
