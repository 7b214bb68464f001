! The 3D model (tfem_solid_*) from Fortran 2008 (-std=f2008), with index_base = 1
! and the mesh and results in rank-2 arrays (xyz(3, nn), tets(4, nt),
! faces(3, nf), u(3, nn), s(6, nt)) where the C API takes flat buffers.
!
! The scene is the contact patch test of c_tests/solid_test.c: two unit cubes
! stacked along z (body 1 on [-1, 0], body 2 on [0, 1]), each one cell of
! Kuhn's six tetrahedra, sides tagged 1..6 and 11..16 (x = min, x = max,
! y = min, y = max, z = min, z = max); rollers under the lower cube and on
! x = 0, y = 0; a pressure p on the upper top; a frictionless contact pair
! between tag 6 (the lower top, planar) and tag 15 (the upper bottom). Exact:
! sigma_zz = -p in every tetrahedron, contact area 1, reactions summing to p.
program fortran_solid_f2008_test
  use, intrinsic :: iso_c_binding
  use tfem
  implicit none
  integer, parameter :: dp = c_double
  integer, parameter :: NC = 1, NP = NC + 1, NPER = NP**3, NN = 2 * NPER
  integer, parameter :: NT = 2 * 6 * NC**3, NF = 2 * 6 * 2 * NC**2, NCT = 3 * 2 * NC**2
  real(dp), parameter :: P = 0.1_dp, E = 1.0_dp, NU = 0.25_dp, TOL = 1.0e-9_dp
  real(c_double) :: xyz(3, NN), u(3, NN), r(3, NN), s(6, NT), xyz_back(3, NN)
  real(c_double) :: u_flat(3 * NN), pressure(NN), area, work, worst
  integer(c_int) :: tets(4, NT), body(NT), faces(3, NF), tags(NF), tets_back(4, NT)
  integer(c_int) :: active(NCT)
  integer(c_int) :: status, pair, n_nodes, n_tets, n_contact, iterations, nt_done, nf_done
  integer :: passed = 0, failed = 0
  type(c_ptr) :: m
  type(tfem_contact_options) :: options
  type(tfem_solve_info) :: info

  nt_done = 0
  nf_done = 0
  call cube(0, -1.0_dp, 1, 0)
  call cube(NPER, 0.0_dp, 2, 10)
  call expect(nt_done == NT .and. nf_done == NF, 'mesh built')

  m = tfem_solid_create()
  call ok(tfem_solid_set_mesh(m, int(NN, c_int), xyz, int(NT, c_int), tets, body, 1_c_int), &
      'tfem_solid_set_mesh')
  call ok(tfem_solid_set_boundary_faces(m, int(NF, c_int), faces, tags), 'boundary faces')
  call ok(tfem_solid_set_material(m, 1_c_int, E, NU), 'material 1')
  call ok(tfem_solid_set_material(m, 2_c_int, E, NU), 'material 2')
  call ok(tfem_solid_fix_faces(m, 5_c_int, TFEM_AXIS_Z, 0.0_dp), 'rollers under')
  call ok(tfem_solid_fix_faces(m, 1_c_int, TFEM_AXIS_X, 0.0_dp), 'lower x = 0')
  call ok(tfem_solid_fix_faces(m, 11_c_int, TFEM_AXIS_X, 0.0_dp), 'upper x = 0')
  call ok(tfem_solid_fix_faces(m, 3_c_int, TFEM_AXIS_Y, 0.0_dp), 'lower y = 0')
  call ok(tfem_solid_fix_faces(m, 13_c_int, TFEM_AXIS_Y, 0.0_dp), 'upper y = 0')
  call ok(tfem_solid_add_pressure(m, 16_c_int, P), 'pressure')
  call ok(tfem_solid_add_contact_pair(m, 6_c_int, 15_c_int, pair), 'contact pair')
  call expect(pair == 0, 'pair numbers are 0-based')
  call ok(tfem_contact_options_default(options), 'contact options')
  call ok(tfem_solid_solve_contact(m, options, info), 'contact solve')
  call expect(info%unknowns == 3 * NN - 5 * NP**2, 'unknowns: three per node less the rollers')
  call ok(tfem_solid_get_iterations(m, iterations), 'iterations')
  call expect(iterations >= 1 .and. info%factorizations >= 1, 'iterations and factorizations')
  call ok(tfem_solid_get_sizes(m, n_nodes, n_tets, n_contact), 'sizes')
  call expect(n_nodes == NN .and. n_tets == NT .and. n_contact == NCT, 'sizes as meshed')

  ! The mesh reads back as given, 1-based.
  call ok(tfem_solid_get_mesh_nodes(m, xyz_back, int(3 * NN, c_size_t)), 'mesh nodes')
  call expect(all(xyz_back == xyz), 'nodes read back')
  call ok(tfem_solid_get_mesh_tetrahedra(m, tets_back, int(4 * NT, c_size_t), body, int(NT, c_size_t)), &
      'mesh tetrahedra')
  call expect(all(tets_back == tets), 'tetrahedra read back')

  ! The whole interface in contact; uniaxial stress everywhere.
  call ok(tfem_solid_get_contact_active(m, active, int(NCT, c_size_t)), 'contact active')
  call expect(all(active == 1), 'every tetrahedron of B active')
  call ok(tfem_solid_get_contact_area(m, area), 'contact area')
  call expect(abs(area - 1) <= 1.0e-12_dp, 'contact area = interface area')
  call ok(tfem_solid_get_element_stresses(m, s, int(6 * NT, c_size_t)), 'stresses')
  worst = maxval(abs(s(1:2, :))) + maxval(abs(s(3, :) + P)) + maxval(abs(s(4:6, :)))
  call expect(worst <= TOL * P, 'sigma_zz = -p, every other component 0')

  ! Displacements linear; reactions carry p A; nodal pressure p on the interface.
  call ok(tfem_solid_get_displacements(m, u, int(3 * NN, c_size_t)), 'displacements')
  worst = maxval(abs(u(1, :) - NU * P / E * xyz(1, :))) + maxval(abs(u(2, :) - NU * P / E * xyz(2, :))) &
      + maxval(abs(u(3, 1:NPER) + P / E * (xyz(3, 1:NPER) + 1))) &
      + maxval(abs(u(3, NPER + 1:) - u(3, NPER + 1) + P / E * xyz(3, NPER + 1:)))
  call expect(worst <= TOL * P / E, 'linear displacements')
  call ok(tfem_solid_get_reactions(m, r, int(3 * NN, c_size_t)), 'reactions')
  call expect(abs(sum(r(3, :)) - P) <= 1.0e-12_dp .and. maxval(abs(r(1:2, :))) <= TOL * P, &
      'reactions balance p A')
  call ok(tfem_solid_get_contact_nodal_pressures(m, pressure, int(NN, c_size_t)), 'nodal pressures')
  call expect(maxval(abs(pressure - merge(P, 0.0_dp, xyz(3, :) == 0))) <= TOL * P, 'nodal pressure p')
  call ok(tfem_solid_get_external_work(m, work), 'external work')
  call expect(abs(work + P * u(3, NN)) <= TOL * work, 'work = compliance of the pressure')

  ! The same numbers through a rank-1 array, and a buffer one value short.
  call ok(tfem_solid_get_displacements(m, u_flat, int(size(u_flat), c_size_t)), 'flat displacements')
  call expect(all(u_flat == reshape(u, [3 * NN])), 'flat displacements the same')
  status = tfem_solid_get_displacements(m, u, int(3 * NN - 1, c_size_t))
  call expect(status == TFEM_STATUS_BUFFER_TOO_SMALL, 'rank-2 buffer too short')

  ! Refusals name the item in the 1-based numbering, and change nothing.
  status = tfem_solid_fix(m, 0_c_int, TFEM_AXIS_X, 0.0_dp)
  call expect(status == TFEM_STATUS_INVALID_ARGUMENT, 'node 0 refused with index base 1')
  call expect(index(tfem_solid_error_message(m), 'node 0 is out of range') > 0 .and. &
      index(tfem_solid_error_message(m), 'index base 1') > 0, 'the message names node 0')
  status = tfem_solid_fix(m, int(NN + 1, c_int), TFEM_AXIS_Z, 0.0_dp)
  call expect(status == TFEM_STATUS_INVALID_ARGUMENT .and. &
      index(tfem_solid_error_message(m), 'node 17') > 0, 'node NN + 1 refused, named')
  status = tfem_solid_fix(m, 1_c_int, 3_c_int, 0.0_dp)
  call expect(status == TFEM_STATUS_INVALID_ARGUMENT .and. &
      index(tfem_solid_error_message(m), 'component = 3') > 0, 'component 3 refused')
  status = tfem_solid_get_contact_pair_area(m, 1_c_int, area)
  call expect(status == TFEM_STATUS_INVALID_ARGUMENT .and. abs(area - 1) <= 1.0e-12_dp, &
      'pair 1 refused (0-based), area kept')
  options%law = 1
  status = tfem_solid_solve_contact(m, options, info)
  call expect(status == TFEM_STATUS_INVALID_ARGUMENT .and. &
      index(tfem_solid_error_message(m), 'frictionless') > 0, 'the stick law refused')
  call ok(tfem_solid_get_displacements(m, u_flat, int(size(u_flat), c_size_t)), 'displacements kept')
  call expect(all(u_flat == reshape(u, [3 * NN])), 'results unchanged by the refusals')
  call expect(len(tfem_solid_error_message(m)) == 0, 'a success clears the message')
  call tfem_solid_destroy(m)

  ! A body without material.
  m = tfem_solid_create()
  call ok(tfem_solid_set_mesh(m, int(NN, c_int), xyz, int(NT, c_int), tets, body, 1_c_int), 'mesh again')
  call ok(tfem_solid_set_material(m, 1_c_int, E, NU), 'material 1 only')
  call ok(tfem_solid_fix(m, 1_c_int, TFEM_AXIS_X, 0.0_dp), 'a support')
  status = tfem_solid_solve(m, info)
  call expect(status == TFEM_STATUS_INVALID_MATERIAL .and. &
      index(tfem_solid_error_message(m), 'body 2 has no material') > 0, 'body 2 without material')
  call tfem_solid_destroy(m)

  print '(a, i0, a, i0, a)', 'fortran_solid_f2008_test: ', passed, ' passed, ', failed, ' failed'
  if (failed > 0) stop 1

contains

  ! A unit cube from z0 to z0 + 1, body b, sides tagged tag0 + 1 .. tag0 + 6, its
  ! nodes from first + 1: Kuhn's six tetrahedra per cell (paths from corner
  ! (0,0,0) to (1,1,1) in every order of the axes, the odd orders numbered
  ! backwards to keep J > 0), and every face of them on a side.
  subroutine cube(first, z0, b, tag0)
    integer, intent(in) :: first, b, tag0
    real(dp), intent(in) :: z0
    integer, parameter :: orders(3, 6) = reshape([1, 2, 3, 2, 3, 1, 3, 1, 2, 1, 3, 2, 3, 2, 1, 2, 1, 3], [3, 6])
    integer :: i, j, k, o, st, q, e, skip, axis, side, at, start, f(3), g(3), step(3), c(4)
    do k = 0, NC
      do j = 0, NC
        do i = 0, NC
          xyz(:, node(first, i, j, k)) = [real(i, dp) / NC, real(j, dp) / NC, z0 + real(k, dp) / NC]
        end do
      end do
    end do
    start = nt_done + 1
    do k = 0, NC - 1
      do j = 0, NC - 1
        do i = 0, NC - 1
          do o = 1, 6
            step = 0
            c(1) = node(first, i, j, k)
            do st = 1, 3
              step(orders(st, o)) = 1
              c(st + 1) = node(first, i + step(1), j + step(2), k + step(3))
            end do
            if (o > 3) c([3, 4]) = c([4, 3])
            nt_done = nt_done + 1
            tets(:, nt_done) = c
            body(nt_done) = b
          end do
        end do
      end do
    end do
    do e = start, nt_done
      do skip = 1, 4
        f = pack(tets(:, e), [(q /= skip, q = 1, 4)])
        do axis = 1, 3
          do side = 0, 1
            at = side * NC
            do q = 1, 3
              g(q) = grid(first, f(q), axis)
            end do
            if (all(g == at)) then
              nf_done = nf_done + 1
              faces(:, nf_done) = f
              tags(nf_done) = tag0 + 2 * axis - 1 + side
            end if
          end do
        end do
      end do
    end do
  end subroutine cube

  ! The 1-based number of node (i, j, k) of the cube whose nodes follow first.
  pure integer function node(first, i, j, k)
    integer, intent(in) :: first, i, j, k
    node = first + 1 + i + NP * (j + NP * k)
  end function node

  ! Grid coordinate axis (1..3) of node v of the cube whose nodes follow first.
  pure integer function grid(first, v, axis)
    integer, intent(in) :: first, v, axis
    integer :: rest
    rest = v - first - 1
    select case (axis)
    case (1)
      grid = mod(rest, NP)
    case (2)
      grid = mod(rest / NP, NP)
    case default
      grid = rest / (NP * NP)
    end select
  end function grid

  subroutine ok(st, what)
    integer(c_int), intent(in) :: st
    character(len=*), intent(in) :: what
    if (st == TFEM_STATUS_OK) then
      passed = passed + 1
    else
      failed = failed + 1
      print '(a, a, a, i0, a, a)', 'FAIL ', what, ': status ', st, ': ', tfem_solid_error_message(m)
    end if
  end subroutine ok

  subroutine expect(cond, what)
    logical, intent(in) :: cond
    character(len=*), intent(in) :: what
    if (cond) then
      passed = passed + 1
    else
      failed = failed + 1
      print '(a, a)', 'FAIL ', what
    end if
  end subroutine expect
end program fortran_solid_f2008_test
