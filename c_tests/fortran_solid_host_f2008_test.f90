! The 3D contact context for host codes (tfem_solid_contact_*) from Fortran 2008
! (-std=f2008), with index_base = 1 and rank-2 arrays (xyz(3, n), equations(3, n),
! triangles(3, n), u(3, n)) where the C API takes flat buffers.
!
! The host of c_tests/solid_host_test.c, one cube cell each: two unit cubes stacked
! along z (body 1 on [-1, 0], body 2 on [0, 1]) of Kuhn's six tetrahedra, the host's
! own plain linear tetrahedra (E = 1, nu = 0.25) in its own dense matrix, rollers on
! x = 0 and y = 0, the lower bottom fixed in z, a pressure p on the upper top. The
! interface sides (side 1 the lower top, side 2 the upper bottom, triangles
! counter-clockwise seen from outside each body) go to tfem in the host's 1-based
! numbers; the host solves with its own Cholesky factorisation and asks
! tfem_solid_contact_update for the verdict until the active set stands. Exact:
! sigma_zz = -p in every tetrahedron (from the host's own displacements), every
! tetrahedron of B active, contact area 1. Then refusals named in 1-based numbers.
program fortran_solid_host_f2008_test
  use, intrinsic :: iso_c_binding
  use, intrinsic :: ieee_arithmetic, only: ieee_value, ieee_quiet_nan
  use tfem
  implicit none
  integer, parameter :: dp = c_double
  integer, parameter :: NC = 1, NP = NC + 1, NPER = NP**3, NN = 2 * NPER
  integer, parameter :: NT = 2 * 6 * NC**3, NF = 2 * 6 * 2 * NC**2
  integer, parameter :: SN = NP**2, ST = 2 * NC**2, NIF = 2 * SN, NCT = 3 * ST
  real(dp), parameter :: P = 0.1_dp, E = 1.0_dp, NU = 0.25_dp, TOL = 1.0e-9_dp
  real(c_double) :: xyz(3, NN), u(3, NN), d(6, 6)
  integer(c_int) :: tets(4, NT), faces(3, NF), tags(NF)
  integer :: eq(3, NN), neq, nt_done, nf_done
  real(dp), allocatable :: k(:, :), kt(:, :), f(:), x(:)
  ! The sides as the host gives them.
  integer(c_int) :: nodes_a(SN), nodes_b(SN), tris_a(3, ST), tris_b(3, ST), bad_tris(3, ST)
  real(c_double) :: xyz_a(3, SN), xyz_b(3, SN)
  integer(c_int64_t) :: eq_a(3, SN), eq_b(3, SN)
  ! What tfem gives back.
  integer(c_int64_t), allocatable :: rows(:), cols(:)
  real(c_double), allocatable :: values(:)
  real(c_double) :: u_if(3, NIF), zero(3, NIF), r0(3, NIF), gaps(NCT), area, worst, saved(3, NIF)
  integer(c_int) :: active(NCT), if_nodes(NIF), contact_tets(4, NCT)
  integer(c_int) :: status, side_a, side_b, pair, n_if, n_tets, changed, on, off, sentinel
  integer(c_int64_t) :: n_entries
  integer :: passed = 0, failed = 0, iteration, el, i
  type(c_ptr) :: ctx, other

  nt_done = 0
  nf_done = 0
  call cube(0, -1.0_dp, 0)
  call cube(NPER, 0.0_dp, 10)
  call expect(nt_done == NT .and. nf_done == NF, 'mesh built')
  call elasticity(d)
  call number_equations()
  call expect(neq == 3 * NN - 5 * NP**2, 'equations: three per node less the rollers')
  allocate(k(neq, neq), kt(neq, neq), f(neq), x(neq))
  call assemble()

  ! The context, 1-based; the sides and their pair, numbered from 1.
  ctx = tfem_solid_contact_create(1_c_int)
  call expect(c_associated(ctx), 'tfem_solid_contact_create')
  call side_of(6, 1.0_dp, nodes_a, xyz_a, eq_a, tris_a)
  call side_of(15, -1.0_dp, nodes_b, xyz_b, eq_b, tris_b)
  call ok(tfem_solid_contact_add_side(ctx, 6_c_int, 1_c_int, E, int(SN, c_int), nodes_a, xyz_a, &
      eq_a, int(ST, c_int), tris_a, side_a), 'side a')
  call ok(tfem_solid_contact_add_side(ctx, 15_c_int, 2_c_int, E, int(SN, c_int), nodes_b, xyz_b, &
      eq_b, int(ST, c_int), tris_b, side_b), 'side b')
  call expect(side_a == 1 .and. side_b == 2, 'side numbers are 1-based')

  ! Refusals while declaring, named in 1-based numbers; nothing written.
  sentinel = -7
  status = tfem_solid_contact_add_pair(ctx, 0_c_int, side_b, sentinel)
  call expect(status == TFEM_STATUS_INVALID_ARGUMENT .and. sentinel == -7 .and. &
      index(tfem_solid_contact_error_message(ctx), 'side_a = 0 is below the index base 1') > 0, &
      'side 0 refused with index base 1')
  status = tfem_solid_contact_add_pair(ctx, side_a, 3_c_int, sentinel)
  call expect(status == TFEM_STATUS_INVALID_ARGUMENT .and. sentinel == -7 .and. &
      index(tfem_solid_contact_error_message(ctx), 'side 3 does not exist') > 0, &
      'side 3 refused, named')
  bad_tris = tris_b
  bad_tris(2, 1) = 99
  status = tfem_solid_contact_add_side(ctx, 15_c_int, 2_c_int, E, int(SN, c_int), nodes_b, xyz_b, &
      eq_b, int(ST, c_int), bad_tris, sentinel)
  call expect(status == TFEM_STATUS_INVALID_ARGUMENT .and. sentinel == -7 .and. &
      index(tfem_solid_contact_error_message(ctx), &
      'side 3 (tag 15): triangle 1 uses node 99, which the side does not give') > 0, &
      'a triangle over a node the side does not give')

  call ok(tfem_solid_contact_add_pair(ctx, side_a, side_b, pair), 'pair')
  call expect(pair == 1, 'pair numbers are 1-based')
  call ok(tfem_solid_contact_sizes(ctx, n_if, n_tets, n_entries), 'sizes')
  call expect(n_if == NIF .and. n_tets == NCT .and. n_entries > 0, 'sizes of B')
  allocate(rows(n_entries), cols(n_entries), values(n_entries))
  call ok(tfem_solid_contact_pattern(ctx, rows, cols, size(rows)), 'pattern')
  call expect(minval(rows) >= 1 .and. maxval(rows) <= neq .and. minval(cols) >= 1 .and. &
      maxval(cols) <= neq, 'the pattern in the host''s 1-based equations')

  ! The host's loop.
  zero = 0
  changed = 1
  iteration = 0
  do while (changed /= 0 .and. iteration < 20)
    iteration = iteration + 1
    call ok(tfem_solid_contact_evaluate(ctx, zero, size(zero), values, size(values), r0, size(r0)), &
        'evaluate')
    kt = k
    do el = 1, int(n_entries)
      kt(rows(el), cols(el)) = kt(rows(el), cols(el)) + values(el)
    end do
    x = f
    call ok(tfem_solid_contact_scatter_add(ctx, -r0, size(r0), x, size(x)), 'scatter_add')
    call cholesky_solve(kt, x)
    call ok(tfem_solid_contact_gather(ctx, x, size(x), u_if, size(u_if)), 'gather')
    call ok(tfem_solid_contact_update(ctx, u_if, size(u_if), changed, on, off), 'update')
    call expect(changed == merge(1, 0, on + off > 0), 'changed as switched')
  end do
  call expect(changed == 0, 'the host''s loop settled')

  ! Exact: uniaxial stress from the host's own displacements; B closed.
  do i = 1, NN
    u(:, i) = merge(x(max(eq(:, i), 1)), 0.0_dp, eq(:, i) > 0)
  end do
  worst = 0
  do el = 1, NT
    worst = max(worst, stress_error(el))
  end do
  print '(a, i0, a, es9.2)', 'host loop: ', iteration, ' iterations, worst stress error ', worst
  call expect(worst <= TOL * P, 'sigma_zz = -p, every other component 0')
  call ok(tfem_solid_contact_get_active(ctx, active, size(active)), 'active flags')
  call expect(all(active == 1), 'every tetrahedron of B active')
  call ok(tfem_solid_contact_area(ctx, area), 'contact area')
  call expect(abs(area - 1) <= 1.0e-12_dp, 'contact area 1')
  call ok(tfem_solid_contact_nodes(ctx, if_nodes, size(if_nodes)), 'interface nodes')
  call expect(all(if_nodes(1:SN) == nodes_a) .and. all(if_nodes(SN + 1:) == nodes_b), &
      'interface nodes in the order given')
  call ok(tfem_solid_contact_tetrahedra(ctx, contact_tets, size(contact_tets)), 'tetrahedra of B')
  call expect(all(xyz(3, reshape(contact_tets, [4 * NCT])) == 0), 'B on the interface, 1-based host nodes')
  call ok(tfem_solid_contact_gaps(ctx, u_if, size(u_if), gaps, size(gaps)), 'gaps')
  call expect(maxval(abs(gaps - (u(3, NPER + 1) - u(3, NPER)))) <= TOL * P / E .and. &
      all(gaps < 0), 'gaps: the uniform penetration')

  ! Refusals after the build: a wrong length, a NaN, a short buffer; nothing written.
  saved = u_if
  status = tfem_solid_contact_gather(ctx, x, size(x), u_if, size(u_if) - 1)
  call expect(status == TFEM_STATUS_BUFFER_TOO_SMALL .and. all(u_if == saved), 'gather: short buffer')
  status = tfem_solid_contact_evaluate(ctx, u_if, size(u_if) - 1, values, size(values), &
      residual_length=0)
  call expect(status == TFEM_STATUS_INVALID_ARGUMENT .and. &
      index(tfem_solid_contact_error_message(ctx), '`u` holds 23 values') > 0, 'evaluate: u too short')
  u_if(3, 2) = ieee_value(1.0_dp, ieee_quiet_nan)
  changed = -7
  status = tfem_solid_contact_update(ctx, u_if, size(u_if), changed)
  call expect(status == TFEM_STATUS_INVALID_ARGUMENT .and. changed == -7 .and. &
      index(tfem_solid_contact_error_message(ctx), 'not finite') > 0, 'update: a NaN refused')
  u_if = saved
  call ok(tfem_solid_contact_update(ctx, u_if, size(u_if), changed), 'update again')
  call expect(len(tfem_solid_contact_error_message(ctx)) == 0, 'a success clears the message')

  ! Handles of other kinds, and a destroyed one.
  other = tfem_contact_create(1_c_int)
  status = tfem_solid_contact_setup(other)
  call expect(status == TFEM_STATUS_INVALID_ARGUMENT .and. &
      index(tfem_error_message(), 'it is a contact context (from tfem_contact_create)') > 0, &
      'a 2D context refused')
  status = tfem_contact_restart(ctx)
  call expect(status == TFEM_STATUS_INVALID_ARGUMENT .and. &
      index(tfem_error_message(), 'it is a 3D contact context') > 0, 'the 3D context refused in 2D')
  call tfem_contact_destroy(other)
  call tfem_solid_contact_destroy(ctx)
  status = tfem_solid_contact_setup(ctx)
  call expect(status == TFEM_STATUS_INVALID_ARGUMENT .and. &
      index(tfem_error_message(), 'destroyed') > 0, 'a destroyed context refused')
  ctx = tfem_solid_contact_create(2_c_int)
  call expect(.not. c_associated(ctx) .and. index(tfem_error_message(), 'index_base = 2') > 0, &
      'index base 2 refused')

  print '(a, i0, a, i0, a)', 'fortran_solid_host_f2008_test: ', passed, ' passed, ', failed, ' failed'
  if (failed > 0) stop 1

contains

  ! A unit cube from z0 to z0 + 1, sides tagged tag0 + 1 .. tag0 + 6 (x = min, x = max,
  ! y = min, y = max, z = min, z = max), its nodes from first + 1: Kuhn's six
  ! tetrahedra per cell, the odd orders numbered backwards to keep J > 0.
  subroutine cube(first, z0, tag0)
    integer, intent(in) :: first, tag0
    real(dp), intent(in) :: z0
    integer, parameter :: orders(3, 6) = reshape([1, 2, 3, 2, 3, 1, 3, 1, 2, 1, 3, 2, 3, 2, 1, 2, 1, 3], [3, 6])
    integer :: i, j, kk, o, st, q, el, skip, axis, side, start, fc(3), g(3), step(3), c(4)
    do kk = 0, NC
      do j = 0, NC
        do i = 0, NC
          xyz(:, node(first, i, j, kk)) = [real(i, dp) / NC, real(j, dp) / NC, z0 + real(kk, dp) / NC]
        end do
      end do
    end do
    start = nt_done + 1
    do kk = 0, NC - 1
      do j = 0, NC - 1
        do i = 0, NC - 1
          do o = 1, 6
            step = 0
            c(1) = node(first, i, j, kk)
            do st = 1, 3
              step(orders(st, o)) = 1
              c(st + 1) = node(first, i + step(1), j + step(2), kk + step(3))
            end do
            if (o > 3) c([3, 4]) = c([4, 3])
            nt_done = nt_done + 1
            tets(:, nt_done) = c
          end do
        end do
      end do
    end do
    do el = start, nt_done
      do skip = 1, 4
        fc = pack(tets(:, el), [(q /= skip, q = 1, 4)])
        do axis = 1, 3
          do side = 0, 1
            do q = 1, 3
              g(q) = grid(first, fc(q), axis)
            end do
            if (all(g == side * NC)) then
              nf_done = nf_done + 1
              faces(:, nf_done) = fc
              tags(nf_done) = tag0 + 2 * axis - 1 + side
            end if
          end do
        end do
      end do
    end do
  end subroutine cube

  pure integer function node(first, i, j, kk)
    integer, intent(in) :: first, i, j, kk
    node = first + 1 + i + NP * (j + NP * kk)
  end function node

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

  ! The host's equations (1-based; 0: fixed): rollers on x = 0 and y = 0, the lower
  ! bottom fixed in z.
  subroutine number_equations()
    integer :: v, c
    logical :: fixed(3)
    neq = 0
    do v = 1, NN
      fixed = [xyz(1, v) == 0, xyz(2, v) == 0, xyz(3, v) == -1]
      do c = 1, 3
        if (fixed(c)) then
          eq(c, v) = 0
        else
          neq = neq + 1
          eq(c, v) = neq
        end if
      end do
    end do
  end subroutine number_equations

  ! Isotropic elasticity in Voigt order xx yy zz yz xz xy (engineering shears).
  subroutine elasticity(dd)
    real(dp), intent(out) :: dd(6, 6)
    real(dp) :: lambda, mu
    integer :: i
    lambda = E * NU / ((1 + NU) * (1 - 2 * NU))
    mu = E / (2 * (1 + NU))
    dd = 0
    dd(1:3, 1:3) = lambda
    do i = 1, 3
      dd(i, i) = dd(i, i) + 2 * mu
      dd(i + 3, i + 3) = mu
    end do
  end subroutine elasticity

  ! Tetrahedron e's strain-displacement matrix and volume: the host's own element.
  subroutine strain_matrix(el, b, volume)
    integer, intent(in) :: el
    real(dp), intent(out) :: b(6, 12), volume
    real(dp) :: m(3, 3), g(3, 3), grad(3, 4), det
    integer :: a
    do a = 1, 3
      m(:, a) = xyz(:, tets(a + 1, el)) - xyz(:, tets(1, el))
    end do
    det = m(1, 1) * (m(2, 2) * m(3, 3) - m(2, 3) * m(3, 2)) &
        - m(1, 2) * (m(2, 1) * m(3, 3) - m(2, 3) * m(3, 1)) &
        + m(1, 3) * (m(2, 1) * m(3, 2) - m(2, 2) * m(3, 1))
    ! g = m^-1: g(a, j) = d xi_a / d x_j.
    g(1, :) = [m(2, 2) * m(3, 3) - m(2, 3) * m(3, 2), m(1, 3) * m(3, 2) - m(1, 2) * m(3, 3), &
        m(1, 2) * m(2, 3) - m(1, 3) * m(2, 2)] / det
    g(2, :) = [m(2, 3) * m(3, 1) - m(2, 1) * m(3, 3), m(1, 1) * m(3, 3) - m(1, 3) * m(3, 1), &
        m(1, 3) * m(2, 1) - m(1, 1) * m(2, 3)] / det
    g(3, :) = [m(2, 1) * m(3, 2) - m(2, 2) * m(3, 1), m(1, 2) * m(3, 1) - m(1, 1) * m(3, 2), &
        m(1, 1) * m(2, 2) - m(1, 2) * m(2, 1)] / det
    grad(:, 1) = -(g(1, :) + g(2, :) + g(3, :))
    do a = 1, 3
      grad(:, a + 1) = g(a, :)
    end do
    b = 0
    do a = 1, 4
      b(1, 3 * a - 2) = grad(1, a)
      b(2, 3 * a - 1) = grad(2, a)
      b(3, 3 * a) = grad(3, a)
      b(4, 3 * a - 1) = grad(3, a)
      b(4, 3 * a) = grad(2, a)
      b(5, 3 * a - 2) = grad(3, a)
      b(5, 3 * a) = grad(1, a)
      b(6, 3 * a - 2) = grad(2, a)
      b(6, 3 * a - 1) = grad(1, a)
    end do
    volume = abs(det) / 6
  end subroutine strain_matrix

  ! The host's matrix and the pressure's load (p A / 3 down at each corner of the top).
  subroutine assemble()
    real(dp) :: b(6, 12), ke(12, 12), volume, n(3)
    integer :: el, r, c, er, ec, fc, q
    ! The node and the axis of each of a tetrahedron's twelve DOFs.
    integer, parameter :: DOF_NODE(12) = [1, 1, 1, 2, 2, 2, 3, 3, 3, 4, 4, 4]
    integer, parameter :: DOF_AXIS(12) = [1, 2, 3, 1, 2, 3, 1, 2, 3, 1, 2, 3]
    k = 0
    f = 0
    do el = 1, NT
      call strain_matrix(el, b, volume)
      ke = volume * matmul(transpose(b), matmul(d, b))
      do r = 1, 12
        er = eq(DOF_AXIS(r), tets(DOF_NODE(r), el))
        if (er == 0) cycle
        do c = 1, 12
          ec = eq(DOF_AXIS(c), tets(DOF_NODE(c), el))
          if (ec > 0) k(er, ec) = k(er, ec) + ke(r, c)
        end do
      end do
    end do
    do fc = 1, NF
      if (tags(fc) /= 16) cycle
      n = normal(faces(:, fc))
      do q = 1, 3
        er = eq(3, faces(q, fc))
        if (er > 0) f(er) = f(er) - P * 0.5_dp * norm2(n) / 3
      end do
    end do
  end subroutine assemble

  ! Face fc's normal, twice its area long.
  function normal(fc) result(n)
    integer(c_int), intent(in) :: fc(3)
    real(dp) :: n(3), a(3), b(3)
    a = xyz(:, fc(2)) - xyz(:, fc(1))
    b = xyz(:, fc(3)) - xyz(:, fc(1))
    n = [a(2) * b(3) - a(3) * b(2), a(3) * b(1) - a(1) * b(3), a(1) * b(2) - a(2) * b(1)]
  end function normal

  ! The faces tagged tag turned counter-clockwise seen from outside (outward normal
  ! along out_z), with their nodes' coordinates and 1-based equations (0: fixed).
  subroutine side_of(tag, out_z, nodes, sxyz, seq, tris)
    integer, intent(in) :: tag
    real(dp), intent(in) :: out_z
    integer(c_int), intent(out) :: nodes(SN), tris(3, ST)
    real(c_double), intent(out) :: sxyz(3, SN)
    integer(c_int64_t), intent(out) :: seq(3, SN)
    integer :: fc, q, nn_, nt_
    integer(c_int) :: t(3)
    real(dp) :: n(3)
    nn_ = 0
    nt_ = 0
    do fc = 1, NF
      if (tags(fc) /= tag) cycle
      t = faces(:, fc)
      n = normal(t)
      if (n(3) * out_z < 0) t([2, 3]) = t([3, 2])
      nt_ = nt_ + 1
      tris(:, nt_) = t
      do q = 1, 3
        if (any(nodes(1:nn_) == t(q))) cycle
        nn_ = nn_ + 1
        nodes(nn_) = t(q)
        sxyz(:, nn_) = xyz(:, t(q))
        seq(:, nn_) = int(eq(:, t(q)), c_int64_t)
      end do
    end do
  end subroutine side_of

  ! Solves a x = rhs in place (a overwritten by its Cholesky factor).
  subroutine cholesky_solve(a, rhs)
    real(dp), intent(inout) :: a(:, :), rhs(:)
    integer :: i, j, n
    n = size(rhs)
    do j = 1, n
      a(j, j) = sqrt(a(j, j) - dot_product(a(j, 1:j - 1), a(j, 1:j - 1)))
      do i = j + 1, n
        a(i, j) = (a(i, j) - dot_product(a(i, 1:j - 1), a(j, 1:j - 1))) / a(j, j)
      end do
    end do
    do i = 1, n
      rhs(i) = (rhs(i) - dot_product(a(i, 1:i - 1), rhs(1:i - 1))) / a(i, i)
    end do
    do i = n, 1, -1
      rhs(i) = (rhs(i) - dot_product(a(i + 1:n, i), rhs(i + 1:n))) / a(i, i)
    end do
  end subroutine cholesky_solve

  ! The largest deviation of tetrahedron e's stress from sigma_zz = -p.
  real(dp) function stress_error(el)
    integer, intent(in) :: el
    real(dp) :: b(6, 12), volume, ue(12), s(6)
    integer :: a
    call strain_matrix(el, b, volume)
    do a = 1, 4
      ue(3 * a - 2:3 * a) = u(:, tets(a, el))
    end do
    s = matmul(d, matmul(b, ue))
    s(3) = s(3) + P
    stress_error = maxval(abs(s))
  end function stress_error

  subroutine ok(st, what)
    integer(c_int), intent(in) :: st
    character(len=*), intent(in) :: what
    if (st == TFEM_STATUS_OK) then
      passed = passed + 1
    else
      failed = failed + 1
      print '(a, a, a, i0, a, a)', 'FAIL ', what, ': status ', st, ': ', tfem_solid_contact_error_message(ctx)
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
end program fortran_solid_host_f2008_test
