! A legacy client, built with -std=f2008 against the installed module: written
! the way the bind(C) interfaces were used before the generic interfaces, with
! every argument given, integer(c_size_t) lengths and the mesh and results in
! rank-2 arrays (xy(2, nn), tri(3, nt), u(2, nn), s(3, nt)) where the C API
! takes flat buffers.
!
! The scene is the contact patch test: two blocks of different moduli, the
! upper meshed 3:2 finer than the lower, so the interface nodes do not match,
! pressed together by a uniform pressure p on top, the lower standing on
! rollers. Frictionless contact leaves each block in uniaxial stress, known
! in closed form (plane strain): sigma_yy = -p, sigma_xx = sigma_xy = 0,
! eps_xx = nu (1 + nu) p / E, eps_yy = -(1 - nu^2) p / E, displacements linear
! in x and y. Every result is checked against it, and read again into rank-1
! arrays: the same numbers, bit for bit.
program fortran_legacy_f2008_test
  use, intrinsic :: iso_c_binding
  use tfem
  implicit none
  integer, parameter :: dp = c_double
  real(dp), parameter :: L = 1.0_dp, H1 = 0.5_dp, H2 = 0.5_dp, P = 2.0e6_dp, NU = 0.3_dp
  real(dp), parameter :: E1 = 1.0e9_dp, E2 = 3.0e9_dp, TOL = 1.0e-9_dp
  integer, parameter :: NX1 = 4, NY1 = 2, NX2 = 6, NY2 = 3
  integer, parameter :: NN1 = (NX1 + 1) * (NY1 + 1), NN = NN1 + (NX2 + 1) * (NY2 + 1)
  integer, parameter :: NT1 = 2 * NX1 * NY1, NT = NT1 + 2 * NX2 * NY2, NE = 2 * (NX1 + NX2)
  real(c_double) :: xy(2, NN), u(2, NN), r(2, NN), s(3, NT), e(3, NT), xy_back(2, NN)
  real(c_double) :: u_flat(2 * NN), s_flat(3 * NT), ex, ey, young, worst
  real(c_double), allocatable :: pressure(:)
  integer(c_int) :: tri(3, NT), body(NT), edges(2, NE), tags(NE), tri_back(3, NT), body_back(NT)
  integer(c_int), allocatable :: active(:)
  integer(c_int) :: status, pair, n_nodes, n_triangles, n_contact, i, j, k, t
  integer :: passed = 0, failed = 0
  character(kind=c_char) :: buffer(256)
  type(c_ptr) :: m
  type(tfem_contact_options) :: options
  type(tfem_contact_report) :: report

  ! Nodes row by row, lower block (1..NN1) then upper; two counter-clockwise
  ! triangles per cell; boundary edges counter-clockwise around each block:
  ! 1 lower bottom, 2 lower top, 3 upper bottom, 4 upper top.
  k = 0
  do j = 0, NY1
    do i = 0, NX1
      k = k + 1
      xy(:, k) = [L * i / NX1, H1 * j / NY1]
    end do
  end do
  do j = 0, NY2
    do i = 0, NX2
      k = k + 1
      xy(:, k) = [L * i / NX2, H1 + H2 * j / NY2]
    end do
  end do
  t = 0
  call cells(0, NX1, NY1, 1)
  call cells(NN1, NX2, NY2, 2)
  k = 0
  do i = 0, NX1 - 1
    call edge(lower(i, 0), lower(i + 1, 0), 1)
    call edge(lower(i + 1, NY1), lower(i, NY1), 2)
  end do
  do i = 0, NX2 - 1
    call edge(upper(i, 0), upper(i + 1, 0), 3)
    call edge(upper(i + 1, NY2), upper(i, NY2), 4)
  end do

  m = tfem_create()
  call ok(tfem_set_mesh(m, int(NN, c_int), xy, int(NT, c_int), tri, body, 1_c_int), 'tfem_set_mesh')
  call ok(tfem_set_boundary_edges(m, int(NE, c_int), edges, tags), 'tfem_set_boundary_edges')
  call ok(tfem_set_material(m, 1_c_int, E1, NU, TFEM_PLANE_MODE_STRAIN), 'material 1')
  call ok(tfem_set_material(m, 2_c_int, E2, NU, TFEM_PLANE_MODE_STRAIN), 'material 2')
  call ok(tfem_fix_edges(m, 1_c_int, TFEM_COMPONENT_Y, 0.0_dp), 'rollers')
  call ok(tfem_fix(m, int(lower(0, 0), c_int), TFEM_COMPONENT_X, 0.0_dp), 'lower block at x = 0')
  call ok(tfem_fix(m, int(upper(0, NY2), c_int), TFEM_COMPONENT_X, 0.0_dp), 'upper block at x = 0')
  call ok(tfem_add_pressure(m, 4_c_int, P), 'pressure')
  call ok(tfem_add_contact_pair(m, 2_c_int, 3_c_int, pair), 'contact pair')
  call ok(tfem_contact_options_default(options), 'contact options')
  call ok(tfem_solve_contact(m, options, report), 'contact solve')
  call expect(report%active > 0, 'contact closed')
  call ok(tfem_get_sizes(m, n_nodes, n_triangles, n_contact), 'sizes')
  call expect(n_nodes == NN .and. n_triangles == NT .and. n_contact > 0, 'sizes as meshed')

  ! The mesh reads back as given.
  call ok(tfem_get_mesh_nodes(m, xy_back, int(2 * NN, c_size_t)), 'mesh nodes')
  call expect(all(xy_back == xy), 'nodes read back')
  call ok(tfem_get_mesh_triangles(m, tri_back, int(3 * NT, c_size_t), body_back, int(NT, c_size_t)), &
      'mesh triangles')
  call expect(all(tri_back == tri) .and. all(body_back == body), 'triangles and bodies read back')

  ! Uniaxial stress and its strains in every triangle.
  call ok(tfem_get_element_stresses(m, s, int(3 * NT, c_size_t)), 'stresses')
  worst = maxval(abs(s(1, :))) + maxval(abs(s(2, :) + P)) + maxval(abs(s(3, :)))
  call expect(worst <= TOL * P, 'sigma_yy = -p, sigma_xx = sigma_xy = 0')
  call ok(tfem_get_element_strains(m, e, int(3 * NT, c_size_t)), 'strains')
  worst = 0
  do t = 1, NT
    young = merge(E1, E2, body(t) == 1)
    worst = max(worst, abs(e(1, t) - NU * (1 + NU) * P / young), abs(e(2, t) + (1 - NU**2) * P / young), &
        abs(e(3, t)))
  end do
  call expect(worst <= TOL * (1 - NU**2) * P / E1, 'plane-strain uniaxial strains')

  ! Displacements: linear in each block; the upper block's vertical one up to
  ! the rigid shift that the contact penalty leaves at the interface.
  call ok(tfem_get_displacements(m, u, int(2 * NN, c_size_t)), 'displacements')
  worst = 0
  do k = 1, NN
    if (k <= NN1) then
      ex = NU * (1 + NU) * P / E1 * xy(1, k)
      ey = -(1 - NU**2) * P / E1 * xy(2, k)
    else
      ex = NU * (1 + NU) * P / E2 * xy(1, k)
      ey = u(2, upper(0, 0)) - (1 - NU**2) * P / E2 * (xy(2, k) - H1)
    end if
    worst = max(worst, abs(u(1, k) - ex), abs(u(2, k) - ey))
  end do
  call expect(worst <= TOL * (1 - NU**2) * P / E1 * (H1 + H2), 'linear displacements')
  call expect(u(2, upper(0, 0)) < -(1 - NU**2) * P / E1 * H1 + TOL * P / E1, 'blocks pressed into contact')

  ! The rollers carry the load; the contact pressure is p where active.
  call ok(tfem_get_reactions(m, r, int(2 * NN, c_size_t)), 'reactions')
  call expect(abs(sum(r(2, :)) - P * L) <= TOL * P * L .and. maxval(abs(r(1, :))) <= TOL * P * L, &
      'reactions balance p L')
  allocate (pressure(n_contact), active(n_contact))
  call ok(tfem_get_contact_active(m, active, int(n_contact, c_size_t)), 'contact active')
  call ok(tfem_get_contact_pressure(m, pressure, int(n_contact, c_size_t)), 'contact pressure')
  call expect(all(active == 0 .or. abs(pressure - P) <= TOL * P), 'contact pressure p')

  ! The same numbers through rank-1 arrays, and a buffer one value short.
  call ok(tfem_get_displacements(m, u_flat, int(size(u_flat), c_size_t)), 'flat displacements')
  call expect(all(u_flat == reshape(u, [2 * NN])), 'flat displacements the same')
  call ok(tfem_get_element_stresses(m, s_flat, int(size(s_flat), c_size_t)), 'flat stresses')
  call expect(all(s_flat == reshape(s, [3 * NT])), 'flat stresses the same')
  status = tfem_get_displacements(m, u, int(2 * NN - 1, c_size_t))
  call expect(status == TFEM_STATUS_BUFFER_TOO_SMALL, 'rank-2 buffer too short')

  ! A refused call's message, into a character array.
  status = tfem_fix(m, 0_c_int, TFEM_COMPONENT_X, 0.0_dp)
  call expect(status == TFEM_STATUS_INVALID_ARGUMENT, 'node 0 refused with index base 1')
  call ok(tfem_last_error(m, buffer, int(size(buffer), c_size_t)), 'last error')
  call expect(index(tfem_error_message(m), 'index base 1') > 0 .and. buffer(1) /= c_null_char, &
      'the message names the index base: '//tfem_error_message(m))
  call tfem_destroy(m)

  write (*, '(a, i0, a, i0, a)') 'fortran_legacy_f2008_test: ', passed, ' passed, ', failed, ' failed'
  if (failed > 0) stop 1

contains

  integer function lower(i, j)
    integer, intent(in) :: i, j
    lower = j * (NX1 + 1) + i + 1
  end function lower

  integer function upper(i, j)
    integer, intent(in) :: i, j
    upper = NN1 + j * (NX2 + 1) + i + 1
  end function upper

  subroutine cells(offset, nx, ny, b)
    integer, intent(in) :: offset, nx, ny, b
    integer :: i, j, a
    do j = 0, ny - 1
      do i = 0, nx - 1
        a = offset + j * (nx + 1) + i + 1
        t = t + 1
        tri(:, t) = [a, a + 1, a + nx + 2]
        body(t) = b
        t = t + 1
        tri(:, t) = [a, a + nx + 2, a + nx + 1]
        body(t) = b
      end do
    end do
  end subroutine cells

  subroutine edge(a, b, tag)
    integer, intent(in) :: a, b, tag
    k = k + 1
    edges(:, k) = [a, b]
    tags(k) = tag
  end subroutine edge

  subroutine ok(status, what)
    integer(c_int), intent(in) :: status
    character(len=*), intent(in) :: what
    call expect(status == TFEM_STATUS_OK, what)
    if (status /= TFEM_STATUS_OK) write (*, '(2a)') '  ', tfem_error_message(m)
  end subroutine ok

  subroutine expect(condition, what)
    logical, intent(in) :: condition
    character(len=*), intent(in) :: what
    if (condition) then
      passed = passed + 1
    else
      failed = failed + 1
      write (*, '(2a)') 'FAIL ', what
    end if
  end subroutine expect
end program fortran_legacy_f2008_test
