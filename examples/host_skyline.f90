! A legacy FE host with tfem's contact: the seed scene (two blocks in
! frictionless contact, canonical parameters of docs/method.md section 4)
! solved by a program that keeps its own everything, as a 1985 code would:
! plane-strain P1 elements (B^T D B * area), an ID array numbering the free
! DOFs 1..NEQ (fixed DOFs eliminated), column heights, a skyline (profile)
! matrix, LDL^T factorisation and solve, its own load vector and its own
! active-set loop. tfem contributes only the contact, through the
! tfem_contact_* entry points with index_base = 1: the contact mesh B
! between the two interface sides, the fixed pattern of its contributions
! in the host's equations, their values at each active set, and the
! inversion test that updates the set.
!
! The same mesh is then solved by tfem's built-in contact solve
! (tfem_solve_contact, as examples/two_blocks.f90 does) and the two are
! compared: the largest nodal displacement difference relative to the
! largest displacement must be <= 1e-10 and the active sets the same, else
! the program stops with exit code 1.
!
!   gfortran -O2 include/tfem.f90 examples/host_skyline.f90 -Ltarget/release -ltfem \
!            -Wl,-rpath,$PWD/target/release -o host_skyline && ./host_skyline [2C/L [N [R]]]
!
! 2C/L is the width of the support and of the load relative to L (default
! 0.2), N the number of cells per unit length (h = 1/N, default 32), R the
! steps of iterative refinement after each skyline solve (default 1).
!
! Why refine: the profile LDL^T in the natural (row by row) order is less
! accurate than tfem's sparse Cholesky as the band widens. Against the
! exact solution of the same discrete system (refined with quad-precision
! residuals), 2C/L = 0.2: at h = 1/128 the plain skyline is off by 1.7e-11
! of the largest displacement and tfem by 9.0e-12; at h = 1/256, 2.1e-10
! and 1.8e-11, so the plain skyline misses the 1e-10 agreement there. One
! refinement step (residual in double, with the unfactored matrix: the
! bodies' profile plus the contact values) brings the skyline to 3e-13 at
! h = 1/128, and the difference from tfem at h = 1/256 to 2.2e-11 (tfem's).
! The unrefined difference is printed too (R = 0 checks it).
program host_skyline
  use, intrinsic :: iso_c_binding
  use, intrinsic :: iso_fortran_env, only: int64
  use tfem
  implicit none
  integer, parameter :: dp = c_double
  real(dp), parameter :: L = 1.0_dp, H1 = 0.25_dp, H2 = 0.25_dp, P = 1.0e7_dp
  real(dp), parameter :: E1 = 1.0e10_dp, E2 = 1.0e11_dp, NU = 0.3_dp
  real(dp), parameter :: TOLERANCE = 1.0e-10_dp

  ! -- the mesh (as examples/two_blocks.f90) ---------------------------------
  real(dp) :: C, H, ratio, mid
  real(dp), allocatable :: xs(:), ys1(:), ys2(:), xy(:)
  integer(c_int), allocatable :: conn(:), body(:), edges(:), tags(:)
  integer :: nx, ny1, ny2, n_nodes, n_tri, n_edges, n_cells, i, j, k, t, imid
  integer :: lower_offset, upper_offset, corner_lower, corner_upper, top_center

  ! -- the host: ID array, profile, matrix, load, solution ----------------------
  integer, allocatable :: id(:, :), jh(:), jh_body(:), ptr(:)
  integer :: neq, nwk, nwk_body, raised, lm(6), e, bad, n_refine
  real(dp), allocatable :: a_body(:), a(:), f_body(:), f(:), x(:), x_plain(:), dx(:), u_host(:)
  real(dp) :: ke(6, 6), dmat(3, 3)

  ! -- the contact context ----------------------------------------------------
  type(c_ptr) :: ctx
  type(tfem_contact_options) :: copts
  integer(c_int) :: side_lower, side_upper, pair, n_if, n_b, changed
  integer(c_int64_t) :: n_entries
  integer(c_int), allocatable :: s_nodes(:), s_edges(:), active_host(:), b_host(:)
  integer(c_int64_t), allocatable :: s_eq(:), rows(:), cols(:)
  real(dp), allocatable :: s_xy(:), values(:), r0(:), u_zero(:), u_if(:), gaps(:)
  integer :: iterations, outside

  ! -- tfem's built-in solve -----------------------------------------------------
  type(c_ptr) :: model
  type(tfem_contact_options) :: options
  type(tfem_contact_report) :: report
  integer(c_int) :: n_b_model
  integer(c_int), allocatable :: active_tfem(:), b_tfem(:)
  real(dp), allocatable :: u_tfem(:)

  ! -- results ----------------------------------------------------------------------
  real(dp) :: lc_host, pen_host, diff, scale, rel, res_host, res_tfem, res_plain, diff_plain
  real(dp) :: t_assembly, t_factor, t_solve, t_host, t_tfem
  integer(int64) :: clock0, clock1, clock_all, rate
  logical :: same_order, same_active
  character(len=64) :: arg

  model = c_null_ptr
  ratio = 0.2_dp
  n_cells = 32
  n_refine = 1
  if (command_argument_count() >= 1) then
    call get_command_argument(1, arg)
    read (arg, *) ratio
  end if
  if (command_argument_count() >= 2) then
    call get_command_argument(2, arg)
    read (arg, *) n_cells
  end if
  if (command_argument_count() >= 3) then
    call get_command_argument(3, arg)
    read (arg, *) n_refine
  end if
  C = 0.5_dp * ratio * L
  H = 1.0_dp / real(n_cells, dp)
  call system_clock(count_rate=rate)

  ! =========================================================================
  ! The mesh: two structured blocks, lower (body 1) and upper (body 2), whose
  ! interface rows coincide at y = 0 (separate nodes), 1-based numbering row
  ! by row, lower block first.
  ! =========================================================================
  mid = 0.5_dp * L
  call symmetric_points(0.0_dp, L, mid - C, H, xs)
  call points(-H1, 0.0_dp, H, ys1)
  call points(0.0_dp, H2, H, ys2)
  nx = size(xs); ny1 = size(ys1); ny2 = size(ys2)
  n_nodes = nx * (ny1 + ny2)
  n_tri = 2 * (nx - 1) * (ny1 - 1 + ny2 - 1)
  allocate(xy(2 * n_nodes), conn(3 * n_tri), body(n_tri))
  lower_offset = 0
  upper_offset = nx * ny1
  k = 0
  do j = 1, ny1
    do i = 1, nx
      xy(2 * k + 1) = xs(i); xy(2 * k + 2) = ys1(j); k = k + 1
    end do
  end do
  do j = 1, ny2
    do i = 1, nx
      xy(2 * k + 1) = xs(i); xy(2 * k + 2) = ys2(j); k = k + 1
    end do
  end do
  t = 0
  call grid_triangles(lower_offset, ny1, 1)
  call grid_triangles(upper_offset, ny2, 2)

  ! Tagged edges: 1 support (bottom of the lower block over 2C), 2 lower
  ! interface, 3 upper interface, 4 loaded segment (top of the upper block).
  allocate(edges(2 * 4 * nx), tags(4 * nx))
  n_edges = 0
  do i = 1, nx - 1
    if (xs(i) >= mid - C .and. xs(i + 1) <= mid + C) call add_edge(node(lower_offset, 1, i), &
        node(lower_offset, 1, i + 1), 1)
    call add_edge(node(lower_offset, ny1, i), node(lower_offset, ny1, i + 1), 2)
    call add_edge(node(upper_offset, 1, i), node(upper_offset, 1, i + 1), 3)
    if (xs(i) >= mid - C .and. xs(i + 1) <= mid + C) call add_edge(node(upper_offset, ny2, i), &
        node(upper_offset, ny2, i + 1), 4)
  end do
  imid = minloc(abs(xs - mid), 1)
  corner_lower = node(lower_offset, ny1, 1)
  corner_upper = node(upper_offset, 1, 1)
  top_center = node(upper_offset, ny2, imid)

  write (*, '(a, f6.3, a, i0, a, i0, a, i0)') 'case 2C/L = ', ratio, ', h = 1/', n_cells, &
      ', nodes ', n_nodes, ', triangles ', n_tri

  call system_clock(clock_all)
  ! =========================================================================
  ! HOST. Boundary conditions and equation numbers (the ID array): u = 0 on
  ! the centre column of both blocks (symmetry), v = 0 on the support.
  ! =========================================================================
  allocate(id(2, n_nodes))
  id = 1
  do j = 1, ny1
    id(1, node(lower_offset, j, imid)) = 0
  end do
  do j = 1, ny2
    id(1, node(upper_offset, j, imid)) = 0
  end do
  do e = 1, n_edges
    if (tags(e) == 1) then
      id(2, edges(2 * e - 1)) = 0
      id(2, edges(2 * e)) = 0
    end if
  end do
  neq = 0
  do i = 1, n_nodes
    do k = 1, 2
      if (id(k, i) /= 0) then
        neq = neq + 1
        id(k, i) = neq
      end if
    end do
  end do

  ! =========================================================================
  ! CONTACT DEFINITION. One side per block: its interface nodes (host
  ! numbers, ascending), their coordinates, their two equations (0: fixed),
  ! and its edges with the body on the left: the lower block lies below its
  ! top row, so its edges run right to left; the upper block above its
  ! bottom row, so its edges run left to right.
  ! =========================================================================
  ctx = tfem_contact_create(1_c_int)
  if (.not. c_associated(ctx)) then
    write (*, '(2a)') 'tfem_contact_create: ', tfem_error_message()
    stop 1
  end if
  call check(tfem_contact_options_default(copts))
  ! The built-in solve takes lambda from the mesh's bounding box, the
  ! context from the interface nodes' box: give the mesh's, as tfem does.
  copts%lambda = max(L, H1 + H2)
  call ccheck(tfem_contact_set_options(ctx, copts), 'tfem_contact_set_options')
  allocate(s_nodes(nx), s_xy(2 * nx), s_eq(2 * nx), s_edges(2 * (nx - 1)))
  call interface_side(lower_offset, ny1, .true.)
  call ccheck(tfem_contact_add_side(ctx, 2_c_int, 1_c_int, E1, NU, TFEM_PLANE_MODE_STRAIN, &
      int(nx, c_int), s_nodes, s_xy, s_eq, int(nx - 1, c_int), s_edges, side_lower), &
      'tfem_contact_add_side (lower)')
  call interface_side(upper_offset, 1, .false.)
  call ccheck(tfem_contact_add_side(ctx, 3_c_int, 2_c_int, E2, NU, TFEM_PLANE_MODE_STRAIN, &
      int(nx, c_int), s_nodes, s_xy, s_eq, int(nx - 1, c_int), s_edges, side_upper), &
      'tfem_contact_add_side (upper)')
  call ccheck(tfem_contact_add_pair(ctx, side_lower, side_upper, pair), 'tfem_contact_add_pair')
  call ccheck(tfem_contact_sizes(ctx, n_if, n_b, n_entries), 'tfem_contact_sizes')
  allocate(rows(n_entries), cols(n_entries), values(n_entries))
  ! The module declares `rows` a scalar, intent(out) (its generator takes a
  ! pointer neither const nor followed by a length for one output value),
  ! so an array does not match: pass its first element, from which the C
  ! function writes the n_entries values.
  call ccheck(tfem_contact_pattern(ctx, rows, cols, int(n_entries, c_size_t)), &
      'tfem_contact_pattern')

  ! =========================================================================
  ! PROFILE. Column heights from the element connectivity (COLHT), then
  ! raised by the contact pattern where it couples equations outside the
  ! bodies' profile (here: the two interface rows, on different bodies).
  ! =========================================================================
  allocate(jh(neq), jh_body(neq), ptr(neq + 1))
  jh = 0
  do e = 1, n_tri
    call element_equations(e, lm)
    call column_heights(lm)
  end do
  nwk_body = profile_size()
  jh_body = jh
  outside = 0
  do e = 1, int(n_entries)
    i = int(min(rows(e), cols(e)))
    j = int(max(rows(e), cols(e)))
    if (j - i > jh_body(j)) outside = outside + 1
    jh(j) = max(jh(j), j - i)
  end do
  raised = count(jh > jh_body)
  nwk = profile_size()
  ptr(1) = 1
  do j = 1, neq
    ptr(j + 1) = ptr(j) + jh(j) + 1
  end do
  write (*, '(a, i0)') 'host_equations ', neq
  write (*, '(a, i0, a, i0, a)') 'host_profile ', nwk_body, ' entries from the bodies, ', nwk, &
      ' with the contact'
  write (*, '(a, i0, a, i0, a)') 'outside_body_profile ', outside, ' pattern entries, ', raised, &
      ' columns raised'
  write (*, '(a, i0, a, i0, a, i0, a)') 'contact_b ', n_b, ' elements, ', n_if, &
      ' interface nodes, ', n_entries, ' pattern entries'
  ! Every pattern entry (i, j), j >= i, must now have its place.
  do e = 1, int(n_entries)
    if (cols(e) >= rows(e)) then
      if (cols(e) - rows(e) > jh(cols(e))) then
        write (*, '(a, i0)') 'profile misses pattern entry ', e
        stop 1
      end if
    end if
  end do

  ! =========================================================================
  ! ASSEMBLY of the bodies (once) and of the load: the pressure P on the
  ! loaded segment, P * length / 2 at each end node of an edge, downwards.
  ! =========================================================================
  call system_clock(clock0)
  allocate(a_body(nwk), a(nwk), f_body(neq), f(neq), x(neq), x_plain(neq), dx(neq))
  a_body = 0.0_dp
  f_body = 0.0_dp
  do e = 1, n_tri
    if (body(e) == 1) then
      call plane_strain(E1, NU, dmat)
    else
      call plane_strain(E2, NU, dmat)
    end if
    call p1_stiffness(e, dmat, ke)
    call element_equations(e, lm)
    call add_element(ke, lm)
  end do
  do e = 1, n_edges
    if (tags(e) == 4) then
      do k = 0, 1
        i = id(2, edges(2 * e - 1 + k))
        if (i /= 0) f_body(i) = f_body(i) - 0.5_dp * P * edge_length(edges(2 * e - 1), edges(2 * e))
      end do
    end if
  end do
  call system_clock(clock1)
  t_assembly = real(clock1 - clock0, dp) / real(rate, dp)

  ! =========================================================================
  ! ACTIVE-SET LOOP. Linear host: K + K_c(active) and f - r_c(u = 0), both
  ! from tfem_contact_evaluate; factorise, solve, gather the interface
  ! displacements, and let tfem_contact_update switch the inverted elements
  ! on and the others off, until the set settles.
  ! =========================================================================
  allocate(r0(2 * n_if), u_zero(2 * n_if), u_if(2 * n_if))
  u_zero = 0.0_dp
  iterations = 0
  t_factor = 0.0_dp
  t_solve = 0.0_dp
  do
    iterations = iterations + 1
    call ccheck(tfem_contact_evaluate(ctx, u_zero, size(u_zero), values, size(values), r0, &
        size(r0)), 'tfem_contact_evaluate')
    a = a_body
    call add_contact(a)
    f = f_body
    call ccheck(tfem_contact_scatter_add(ctx, -r0, size(r0), f, size(f)), &
        'tfem_contact_scatter_add')
    call system_clock(clock0)
    call skyline_factor(neq, ptr, a, bad)
    call system_clock(clock1)
    t_factor = t_factor + real(clock1 - clock0, dp) / real(rate, dp)
    if (bad /= 0) then
      write (*, '(a, i0, a, i0)') 'skyline: zero or negative pivot at equation ', bad, &
          ', active-set iteration ', iterations
      stop 1
    end if
    call system_clock(clock0)
    x = f
    call skyline_solve(neq, ptr, a, x)
    x_plain = x
    ! Iterative refinement against the unfactored matrix (body profile plus
    ! the contact values in the pattern): the profile LDL^T in the natural
    ! order loses digits as the band widens (see the header).
    do k = 1, n_refine
      call host_residual(x, dx)
      call skyline_solve(neq, ptr, a, dx)
      x = x + dx
    end do
    call system_clock(clock1)
    t_solve = t_solve + real(clock1 - clock0, dp) / real(rate, dp)
    call ccheck(tfem_contact_gather(ctx, x, size(x), u_if, size(u_if)), 'tfem_contact_gather')
    call ccheck(tfem_contact_update(ctx, u_if, size(u_if), changed), 'tfem_contact_update')
    if (changed == 0) exit
  end do
  call system_clock(clock1)
  t_host = real(clock1 - clock_all, dp) / real(rate, dp)

  ! The host's results: nodal displacements, contact length (half the
  ! summed interface-edge length of the active elements), penetration.
  allocate(u_host(2 * n_nodes), active_host(n_b), b_host(3 * n_b), gaps(n_if))
  do i = 1, n_nodes
    do k = 1, 2
      u_host(2 * (i - 1) + k) = 0.0_dp
      if (id(k, i) /= 0) u_host(2 * (i - 1) + k) = x(id(k, i))
    end do
  end do
  call ccheck(tfem_contact_get_active(ctx, active_host, size(active_host)), &
      'tfem_contact_get_active')
  call ccheck(tfem_contact_elements(ctx, b_host, size(b_host)), 'tfem_contact_elements')
  call ccheck(tfem_contact_gaps(ctx, u_if, size(u_if), gaps, size(gaps)), 'tfem_contact_gaps')
  lc_host = 0.0_dp
  do e = 1, n_b
    if (active_host(e) /= 0) lc_host = lc_host + 0.5_dp * interface_edge(b_host(3 * e - 2:3 * e))
  end do
  pen_host = max(0.0_dp, -minval(gaps))

  ! =========================================================================
  ! TFEM'S BUILT-IN SOLVE of the same mesh (examples/two_blocks.f90).
  ! =========================================================================
  model = tfem_create()
  call check(tfem_set_mesh(model, int(n_nodes, c_int), xy, int(n_tri, c_int), conn, body, 1_c_int))
  call check(tfem_set_boundary_edges(model, int(n_edges, c_int), edges, tags))
  call check(tfem_set_material(model, 1_c_int, E1, NU, TFEM_PLANE_MODE_STRAIN))
  call check(tfem_set_material(model, 2_c_int, E2, NU, TFEM_PLANE_MODE_STRAIN))
  do j = 1, ny1
    call check(tfem_fix(model, int(node(lower_offset, j, imid), c_int), TFEM_COMPONENT_X, 0.0_dp))
  end do
  do j = 1, ny2
    call check(tfem_fix(model, int(node(upper_offset, j, imid), c_int), TFEM_COMPONENT_X, 0.0_dp))
  end do
  call check(tfem_fix_edges(model, 1_c_int, TFEM_COMPONENT_Y, 0.0_dp))
  call check(tfem_add_pressure(model, 4_c_int, P))
  call check(tfem_add_contact_pair(model, 2_c_int, 3_c_int, k))
  call check(tfem_contact_options_default(options))
  call system_clock(clock0)
  call check(tfem_solve_contact(model, options, report))
  call system_clock(clock1)
  t_tfem = real(clock1 - clock0, dp) / real(rate, dp)
  allocate(u_tfem(2 * n_nodes))
  call check(tfem_get_displacements(model, u_tfem, size(u_tfem)))
  call check(tfem_get_sizes(model, n_contact_elements=n_b_model))
  allocate(active_tfem(n_b_model), b_tfem(3 * n_b_model))
  call check(tfem_get_contact_active(model, active_tfem, size(active_tfem)))
  call check(tfem_get_contact_elements(model, b_tfem, size(b_tfem)))

  ! =========================================================================
  ! COMPARISON.
  ! =========================================================================
  ! tfem's solution in the host's equations.
  do i = 1, n_nodes
    do k = 1, 2
      if (id(k, i) /= 0) x(id(k, i)) = u_tfem(2 * (i - 1) + k)
    end do
  end do
  call host_residual(x, dx)
  res_tfem = norm2(dx) / norm2(f)
  do i = 1, n_nodes
    do k = 1, 2
      if (id(k, i) /= 0) x(id(k, i)) = u_host(2 * (i - 1) + k)
    end do
  end do
  call host_residual(x, dx)
  res_host = norm2(dx) / norm2(f)
  call host_residual(x_plain, dx)
  res_plain = norm2(dx) / norm2(f)
  diff = maxval(abs(u_host - u_tfem))
  scale = maxval(abs(u_tfem))
  rel = diff / scale
  diff_plain = 0.0_dp
  do i = 1, n_nodes
    do k = 1, 2
      if (id(k, i) /= 0) diff_plain = max(diff_plain, abs(x_plain(id(k, i)) - u_tfem(2 * (i - 1) + k)))
    end do
  end do
  same_order = n_b_model == n_b
  if (same_order) same_order = all(b_host == b_tfem)
  if (same_order) then
    same_active = all(active_host == active_tfem)
  else
    ! Another element order: compare the active elements as node triples.
    same_active = same_sets(b_host, active_host, b_tfem, active_tfem)
  end if

  write (*, '(a)') '                          host (skyline)           tfem (built-in)'
  write (*, '(a, 2es25.16)') 'lc              ', lc_host, report%contact_length
  write (*, '(a, 2es25.16)') 'gap_edge        ', u_host(2 * corner_upper) - u_host(2 * corner_lower), &
      u_tfem(2 * corner_upper) - u_tfem(2 * corner_lower)
  write (*, '(a, 2es25.16)') 'v_top           ', u_host(2 * top_center), u_tfem(2 * top_center)
  write (*, '(a, 2es25.16)') 'max_penetration ', pen_host, report%max_penetration
  write (*, '(a, 2i25)') 'iterations      ', iterations, report%iterations
  write (*, '(a, 2i25)') 'active          ', count(active_host /= 0), report%active
  write (*, '(a, 2i25)') 'unknowns        ', neq, report%info%unknowns
  write (*, '(a, es10.3, a, es10.3, a, i0, a, es10.3, a)') 'time_host ', t_host, &
      ' s (assembly ', t_assembly, ' s, ', iterations, ' skyline factorisations ', t_factor, ' s)'
  write (*, '(a, es10.3)') 'time_host_factor ', t_factor
  write (*, '(a, es10.3)') 'time_host_solve ', t_solve
  write (*, '(a, es10.3, a, es10.3, a, i0, a, es10.3, a)') 'time_tfem ', t_tfem, &
      ' s (report total ', report%info%time_total, ' s, ', report%info%factorizations, &
      ' factorisations ', report%info%time_factorization, ' s)'
  write (*, '(a, es10.3)') 'time_tfem_factor ', report%info%time_factorization
  ! ||(K + K_c) u - (f - r_c(0))|| / ||f - r_c(0)|| in the host's settled system
  write (*, '(a, 2es25.16)') 'residual        ', res_host, res_tfem
  write (*, '(a, i0)') 'refinement_steps ', n_refine
  write (*, '(a, es24.16)') 'residual_unrefined ', res_plain
  write (*, '(a, es24.16)') 'relative_difference_unrefined ', diff_plain / scale
  write (*, '(a, es24.16)') 'max_displacement ', scale
  write (*, '(a, es24.16)') 'max_difference ', diff
  write (*, '(a, es24.16)') 'relative_difference ', rel
  write (*, '(a, l1)') 'same_element_order ', same_order
  write (*, '(a, l1)') 'same_active_set ', same_active

  call tfem_destroy(model)
  call tfem_contact_destroy(ctx)
  if (.not. (rel <= TOLERANCE) .or. .not. same_active .or. iterations /= report%iterations) then
    write (*, '(a)') 'FAILED: the host does not reproduce the built-in solve'
    stop 1
  end if
  write (*, '(a)') 'agreement ok'

contains

  !> 1-based node number of grid point (row j, column i) of a grid.
  integer function node(offset, j, i)
    integer, intent(in) :: offset, j, i
    node = offset + (j - 1) * nx + i
  end function node

  subroutine check(status)
    integer(c_int), intent(in) :: status
    if (status /= TFEM_STATUS_OK) then
      write (*, '(a, i0, 2a)') 'tfem error ', status, ': ', tfem_error_message(model)
      stop 1
    end if
  end subroutine check

  !> Stops with the context's message if a tfem_contact_* call failed.
  subroutine ccheck(status, what)
    integer(c_int), intent(in) :: status
    character(len=*), intent(in) :: what
    if (status == TFEM_STATUS_OK) return
    write (*, '(2a, i0, 2a)') what, ': tfem error ', status, ': ', tfem_contact_error_message(ctx)
    stop 1
  end subroutine ccheck

  subroutine add_edge(p, q, tag)
    integer, intent(in) :: p, q, tag
    edges(2 * n_edges + 1) = p; edges(2 * n_edges + 2) = q
    n_edges = n_edges + 1
    tags(n_edges) = tag
  end subroutine add_edge

  real(dp) function edge_length(p, q)
    integer, intent(in) :: p, q
    edge_length = hypot(xy(2 * q - 1) - xy(2 * p - 1), xy(2 * q) - xy(2 * p))
  end function edge_length

  !> The interface row `row` of the block at `offset` as a contact side in
  !> s_nodes, s_xy, s_eq, s_edges; `reverse`: edges right to left (the body
  !> lies below the row).
  subroutine interface_side(offset, row, reverse)
    integer, intent(in) :: offset, row
    logical, intent(in) :: reverse
    integer :: ii, v
    do ii = 1, nx
      v = node(offset, row, ii)
      s_nodes(ii) = v
      s_xy(2 * ii - 1:2 * ii) = xy(2 * v - 1:2 * v)
      s_eq(2 * ii - 1) = int(id(1, v), c_int64_t)
      s_eq(2 * ii) = int(id(2, v), c_int64_t)
    end do
    do ii = 1, nx - 1
      if (reverse) then
        s_edges(2 * ii - 1:2 * ii) = [node(offset, row, ii + 1), node(offset, row, ii)]
      else
        s_edges(2 * ii - 1:2 * ii) = [node(offset, row, ii), node(offset, row, ii + 1)]
      end if
    end do
  end subroutine interface_side

  !> The length of the interface edge of a contact element (nodes `tri`):
  !> the two of its nodes on the same block.
  real(dp) function interface_edge(tri)
    integer(c_int), intent(in) :: tri(3)
    logical :: lower(3)
    lower = tri <= upper_offset
    if (lower(1) .eqv. lower(2)) then
      interface_edge = edge_length(tri(1), tri(2))
    else if (lower(2) .eqv. lower(3)) then
      interface_edge = edge_length(tri(2), tri(3))
    else
      interface_edge = edge_length(tri(3), tri(1))
    end if
  end function interface_edge

  !> Whether the active elements of two contact meshes (node triples in
  !> any order and rotation) are the same set.
  logical function same_sets(b1, a1, b2, a2)
    integer(c_int), intent(in) :: b1(:), a1(:), b2(:), a2(:)
    integer :: p, q
    logical :: found
    same_sets = count(a1 /= 0) == count(a2 /= 0)
    do p = 1, size(a1)
      if (a1(p) == 0 .or. .not. same_sets) cycle
      found = .false.
      do q = 1, size(a2)
        if (a2(q) /= 0 .and. same_triple(b1(3 * p - 2:3 * p), b2(3 * q - 2:3 * q))) found = .true.
      end do
      same_sets = found
    end do
  end function same_sets

  logical function same_triple(s, r)
    integer(c_int), intent(in) :: s(3), r(3)
    same_triple = all([any(r == s(1)), any(r == s(2)), any(r == s(3))])
  end function same_triple

  !> Splits every cell along "/" left of x = L/2 and "\" right of it.
  subroutine grid_triangles(offset, ny, tag)
    integer, intent(in) :: offset, ny, tag
    integer :: na, nb, nc, nd, jj, ii
    do jj = 1, ny - 1
      do ii = 1, nx - 1
        na = node(offset, jj, ii); nb = node(offset, jj, ii + 1)
        nc = node(offset, jj + 1, ii + 1); nd = node(offset, jj + 1, ii)
        if (0.5_dp * (xs(ii) + xs(ii + 1)) < mid) then
          conn(3 * t + 1:3 * t + 6) = [na, nb, nc, na, nc, nd]
        else
          conn(3 * t + 1:3 * t + 6) = [na, nb, nd, nb, nc, nd]
        end if
        body(t + 1:t + 2) = tag
        t = t + 2
      end do
    end do
  end subroutine grid_triangles

  !> Points from a to b with spacing at most h.
  subroutine points(pa, pb, h, out)
    real(dp), intent(in) :: pa, pb, h
    real(dp), allocatable, intent(out) :: out(:)
    call knots_points([pa, pb], h, out)
  end subroutine points

  subroutine knots_points(knots, h, out)
    real(dp), intent(in) :: knots(:), h
    real(dp), allocatable, intent(out) :: out(:)
    integer :: w, n, kk, m
    m = 1
    do w = 1, size(knots) - 1
      m = m + max(1, ceiling((knots(w + 1) - knots(w)) / h - 1.0e-9_dp))
    end do
    allocate(out(m))
    out(1) = knots(1)
    m = 1
    do w = 1, size(knots) - 1
      n = max(1, ceiling((knots(w + 1) - knots(w)) / h - 1.0e-9_dp))
      do kk = 1, n
        m = m + 1
        if (kk == n) then
          out(m) = knots(w + 1)
        else
          out(m) = knots(w) + (knots(w + 1) - knots(w)) * real(kk, dp) / real(n, dp)
        end if
      end do
    end do
  end subroutine knots_points

  !> Points from a to b through stop and b - (stop - a), mirror-symmetric
  !> about (a + b) / 2.
  subroutine symmetric_points(pa, pb, stop_left, h, out)
    real(dp), intent(in) :: pa, pb, stop_left, h
    real(dp), allocatable, intent(out) :: out(:)
    real(dp), allocatable :: half(:)
    real(dp) :: m
    integer :: n, q
    m = 0.5_dp * (pa + pb)
    call knots_points([pa, stop_left, m], h, half)
    n = size(half)
    allocate(out(2 * n - 1))
    out(1:n) = half
    do q = 1, n - 1
      out(n + q) = m + (m - half(n - q))
    end do
    out(2 * n - 1) = pb
  end subroutine symmetric_points

  ! ---------------------------------------------------------------------------
  ! The host's finite elements and its skyline solver.
  ! ---------------------------------------------------------------------------

  !> Plane-strain elasticity matrix (Lame form), strains (exx, eyy, gxy).
  subroutine plane_strain(young, poisson, d)
    real(dp), intent(in) :: young, poisson
    real(dp), intent(out) :: d(3, 3)
    real(dp) :: mu, lambda
    mu = young / (2.0_dp * (1.0_dp + poisson))
    lambda = young * poisson / ((1.0_dp + poisson) * (1.0_dp - 2.0_dp * poisson))
    d = 0.0_dp
    d(1, 1) = lambda + 2.0_dp * mu; d(1, 2) = lambda
    d(2, 1) = lambda; d(2, 2) = lambda + 2.0_dp * mu
    d(3, 3) = mu
  end subroutine plane_strain

  !> The stiffness of P1 triangle `el`: B^T D B * area, DOFs (u1 v1 u2 v2 u3 v3).
  subroutine p1_stiffness(el, d, s)
    integer, intent(in) :: el
    real(dp), intent(in) :: d(3, 3)
    real(dp), intent(out) :: s(6, 6)
    real(dp) :: px(3), py(3), bx(3), by(3), twice_area, bm(3, 6)
    integer :: q
    do q = 1, 3
      px(q) = xy(2 * conn(3 * (el - 1) + q) - 1)
      py(q) = xy(2 * conn(3 * (el - 1) + q))
    end do
    twice_area = (px(2) - px(1)) * (py(3) - py(1)) - (px(3) - px(1)) * (py(2) - py(1))
    if (.not. twice_area > 0.0_dp) then
      write (*, '(a, i0, a)') 'triangle ', el, ' is degenerate or clockwise'
      stop 1
    end if
    bx = [py(2) - py(3), py(3) - py(1), py(1) - py(2)] / twice_area
    by = [px(3) - px(2), px(1) - px(3), px(2) - px(1)] / twice_area
    bm = 0.0_dp
    do q = 1, 3
      bm(1, 2 * q - 1) = bx(q)
      bm(2, 2 * q) = by(q)
      bm(3, 2 * q - 1) = by(q)
      bm(3, 2 * q) = bx(q)
    end do
    s = 0.5_dp * twice_area * matmul(transpose(bm), matmul(d, bm))
  end subroutine p1_stiffness

  !> The equations of the six DOFs of triangle `el` (0: fixed).
  subroutine element_equations(el, eqs)
    integer, intent(in) :: el
    integer, intent(out) :: eqs(6)
    integer :: q
    do q = 1, 3
      eqs(2 * q - 1) = id(1, conn(3 * (el - 1) + q))
      eqs(2 * q) = id(2, conn(3 * (el - 1) + q))
    end do
  end subroutine element_equations

  !> Raises the column heights jh by an element's equations (COLHT).
  subroutine column_heights(eqs)
    integer, intent(in) :: eqs(:)
    integer :: q, lowest
    lowest = huge(lowest)
    do q = 1, size(eqs)
      if (eqs(q) /= 0) lowest = min(lowest, eqs(q))
    end do
    do q = 1, size(eqs)
      if (eqs(q) /= 0) jh(eqs(q)) = max(jh(eqs(q)), eqs(q) - lowest)
    end do
  end subroutine column_heights

  !> The number of stored entries of the profile of heights jh.
  integer function profile_size()
    integer(int64) :: total
    total = sum(int(jh, int64)) + int(neq, int64)
    if (total > huge(profile_size)) then
      write (*, '(a, i0, a)') 'profile of ', total, ' entries is too large'
      stop 1
    end if
    profile_size = int(total)
  end function profile_size

  !> Adds an element matrix to the body profile (ADDBAN): its upper triangle.
  subroutine add_element(s, eqs)
    real(dp), intent(in) :: s(6, 6)
    integer, intent(in) :: eqs(6)
    integer :: p, q, ii, jj
    do q = 1, 6
      jj = eqs(q)
      if (jj == 0) cycle
      do p = 1, 6
        ii = eqs(p)
        if (ii == 0 .or. ii > jj) cycle
        a_body(ptr(jj + 1) - 1 - (jj - ii)) = a_body(ptr(jj + 1) - 1 - (jj - ii)) + s(p, q)
      end do
    end do
  end subroutine add_element

  !> Adds the contact values of the pattern's upper triangle (j >= i) to
  !> the profile matrix `s`; the lower triangle mirrors it.
  subroutine add_contact(s)
    real(dp), intent(inout) :: s(:)
    integer :: q, ii, jj
    do q = 1, int(n_entries)
      if (cols(q) >= rows(q)) then
        ii = int(rows(q)); jj = int(cols(q))
        s(ptr(jj + 1) - 1 - (jj - ii)) = s(ptr(jj + 1) - 1 - (jj - ii)) + values(q)
      end if
    end do
  end subroutine add_contact

  !> r = f - (K + K_c) z with the unfactored matrix: the bodies' profile
  !> a_body (upper triangle, symmetric) and the contact values in the
  !> pattern (both triangles, as given).
  subroutine host_residual(z, r)
    real(dp), intent(in) :: z(:)
    real(dp), intent(out) :: r(:)
    integer :: jj, dj, top_j, q
    r = f
    do jj = 1, neq
      dj = ptr(jj + 1) - 1
      top_j = jj - (dj - ptr(jj))
      r(jj) = r(jj) - a_body(dj) * z(jj)
      if (top_j < jj) then
        r(top_j:jj - 1) = r(top_j:jj - 1) - a_body(ptr(jj):dj - 1) * z(jj)
        r(jj) = r(jj) - dot_product(a_body(ptr(jj):dj - 1), z(top_j:jj - 1))
      end if
    end do
    do q = 1, int(n_entries)
      r(rows(q)) = r(rows(q)) - values(q) * z(cols(q))
    end do
  end subroutine host_residual

  !> LDL^T of the symmetric profile matrix `s` in place. Column j holds
  !> rows j - h_j .. j at s(ptr(j) : ptr(j + 1) - 1), the diagonal last;
  !> on return the unit upper factor U = L^T above the diagonal, D on it.
  !> `failed`: the equation of the first pivot that is not positive, or 0.
  subroutine skyline_factor(n, ptr, s, failed)
    integer, intent(in) :: n, ptr(:)
    real(dp), intent(inout) :: s(:)
    integer, intent(out) :: failed
    integer :: jj, ii, top_j, top_i, k0, dj, di
    real(dp) :: g, u, d
    failed = 0
    do jj = 1, n
      dj = ptr(jj + 1) - 1
      top_j = jj - (dj - ptr(jj))
      ! g(i, j) = a(i, j) - sum_k U(k, i) g(k, j), top to bottom
      do ii = top_j + 1, jj - 1
        di = ptr(ii + 1) - 1
        top_i = ii - (di - ptr(ii))
        k0 = max(top_i, top_j)
        if (k0 < ii) s(dj - (jj - ii)) = s(dj - (jj - ii)) - &
            dot_product(s(di - (ii - k0):di - 1), s(dj - (jj - k0):dj - (jj - ii) - 1))
      end do
      ! U(i, j) = g(i, j) / d(i), d(j) = a(j, j) - sum_i U(i, j) g(i, j)
      d = s(dj)
      do ii = top_j, jj - 1
        g = s(dj - (jj - ii))
        u = g / s(ptr(ii + 1) - 1)
        s(dj - (jj - ii)) = u
        d = d - u * g
      end do
      if (.not. d > 0.0_dp) then
        failed = jj
        return
      end if
      s(dj) = d
    end do
  end subroutine skyline_factor

  !> Solves (U^T D U) z = b with the factor of skyline_factor, z over b.
  subroutine skyline_solve(n, ptr, s, z)
    integer, intent(in) :: n, ptr(:)
    real(dp), intent(in) :: s(:)
    real(dp), intent(inout) :: z(:)
    integer :: jj, dj, top_j
    do jj = 1, n
      dj = ptr(jj + 1) - 1
      top_j = jj - (dj - ptr(jj))
      if (top_j < jj) z(jj) = z(jj) - dot_product(s(ptr(jj):dj - 1), z(top_j:jj - 1))
    end do
    do jj = 1, n
      z(jj) = z(jj) / s(ptr(jj + 1) - 1)
    end do
    do jj = n, 1, -1
      dj = ptr(jj + 1) - 1
      top_j = jj - (dj - ptr(jj))
      if (top_j < jj) z(top_j:jj - 1) = z(top_j:jj - 1) - s(ptr(jj):dj - 1) * z(jj)
    end do
  end subroutine skyline_solve
end program host_skyline
