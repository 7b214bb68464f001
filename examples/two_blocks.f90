! The seed scene from Fortran: two blocks in frictionless contact, canonical
! parameters (docs/method.md section 4), 2C/L = 0.2, h = 1/32, meshed here with
! the same structured triangulation as the Rust example, 1-based indices.
!
!   gfortran include/tfem.f90 examples/two_blocks.f90 -Ltarget/release -ltfem \
!            -Wl,-rpath,$PWD/target/release -o two_blocks_f90 && ./two_blocks_f90
program two_blocks
  use, intrinsic :: iso_c_binding
  use tfem
  implicit none
  integer, parameter :: dp = c_double
  real(dp), parameter :: L = 1.0_dp, H1 = 0.25_dp, H2 = 0.25_dp, C = 0.1_dp, P = 1.0e7_dp
  real(dp), parameter :: E1 = 1.0e10_dp, E2 = 1.0e11_dp, NU = 0.3_dp, H = 1.0_dp / 32.0_dp
  real(dp), allocatable :: xs(:), ys1(:), ys2(:), xy(:), u(:)
  integer(c_int), allocatable :: conn(:), body(:), edges(:), tags(:)
  integer :: nx, ny1, ny2, n_nodes, n_tri, n_edges, i, j, k, t, imid, lower_offset, upper_offset
  integer :: corner_lower, corner_upper, top_center
  real(dp) :: mid
  type(c_ptr) :: model
  type(tfem_contact_options) :: options
  type(tfem_contact_report) :: report

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

  model = tfem_create()
  call check(tfem_set_mesh(model, int(n_nodes, c_int), xy, int(n_tri, c_int), conn, body, 1_c_int))
  call check(tfem_set_boundary_edges(model, int(n_edges, c_int), edges, tags))
  call check(tfem_set_material(model, 1_c_int, E1, NU, TFEM_PLANE_MODE_STRAIN))
  call check(tfem_set_material(model, 2_c_int, E2, NU, TFEM_PLANE_MODE_STRAIN))
  imid = minloc(abs(xs - mid), 1)
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
  call check(tfem_solve_contact(model, options, report))

  allocate(u(2 * n_nodes))
  call check(tfem_get_displacements(model, u, int(size(u), c_size_t)))
  corner_lower = node(lower_offset, ny1, 1)
  corner_upper = node(upper_offset, 1, 1)
  top_center = node(upper_offset, ny2, imid)
  write (*, '(a, es24.16)') 'lc ', report%contact_length
  write (*, '(a, es24.16)') 'gap_edge ', u(2 * corner_upper) - u(2 * corner_lower)
  write (*, '(a, es24.16)') 'v_top ', u(2 * top_center)
  write (*, '(a, es24.16)') 'max_penetration ', report%max_penetration
  write (*, '(a, i0)') 'iterations ', report%iterations
  write (*, '(a, i0)') 'unknowns ', report%info%unknowns
  call tfem_destroy(model)

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

  subroutine add_edge(a, b, tag)
    integer, intent(in) :: a, b, tag
    edges(2 * n_edges + 1) = a; edges(2 * n_edges + 2) = b
    n_edges = n_edges + 1
    tags(n_edges) = tag
  end subroutine add_edge

  !> Splits every cell along "/" left of x = L/2 and "\" right of it.
  subroutine grid_triangles(offset, ny, tag)
    integer, intent(in) :: offset, ny, tag
    integer :: a, b, cc, d, jj, ii
    do jj = 1, ny - 1
      do ii = 1, nx - 1
        a = node(offset, jj, ii); b = node(offset, jj, ii + 1)
        cc = node(offset, jj + 1, ii + 1); d = node(offset, jj + 1, ii)
        if (0.5_dp * (xs(ii) + xs(ii + 1)) < mid) then
          conn(3 * t + 1:3 * t + 6) = [a, b, cc, a, cc, d]
        else
          conn(3 * t + 1:3 * t + 6) = [a, b, d, b, cc, d]
        end if
        body(t + 1:t + 2) = tag
        t = t + 2
      end do
    end do
  end subroutine grid_triangles

  !> Points from a to b with spacing at most h.
  subroutine points(a, b, h, out)
    real(dp), intent(in) :: a, b, h
    real(dp), allocatable, intent(out) :: out(:)
    call knots_points([a, b], h, out)
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
  subroutine symmetric_points(a, b, stop_left, h, out)
    real(dp), intent(in) :: a, b, stop_left, h
    real(dp), allocatable, intent(out) :: out(:)
    real(dp), allocatable :: half(:)
    real(dp) :: m
    integer :: n, q
    m = 0.5_dp * (a + b)
    call knots_points([a, stop_left, m], h, half)
    n = size(half)
    allocate(out(2 * n - 1))
    out(1:n) = half
    do q = 1, n - 1
      out(n + q) = m + (m - half(n - q))
    end do
    out(2 * n - 1) = b
  end subroutine symmetric_points
end program two_blocks
