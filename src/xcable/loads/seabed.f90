!> The seabed (&seabed): a plane z = -depth + slope_x x + slope_y y that pushes
!> back on the part of a cell below it, with damping and Coulomb friction.
!>
!> With n the plane's unit normal (up) and d(r) the depth of a point r below
!> the plane along n, a straight cell with its ends at x -+ e ds / 2 has the
!> penetrations d1 = dm + delta and d2 = dm - delta, dm = d(x) and
!> delta = (ds/2) n.e. Per unstretched length the cell takes
!>
!>     contact    N n,  N = k P,  P = mean of max(d, 0) along the straight cell
!>                (dm where both ends are in, 0 where both are out, (dm + |delta|)^2
!>                / (4 |delta|) across the bottom: continuous with continuous first
!>                derivatives, so a node touching down gives no jump),
!>     damping    -c phi (n.w) n,  phi the fraction of the cell below the plane,
!>     friction   -N [mu_a g(w_a) + mu_l g(w_l)],  g(v) = v / sqrt(|v|^2 + v_s^2),
!>                w_a the cell's velocity along the line's direction in the plane,
!>                w_l the rest of its velocity in the plane,
!>     static friction (statics only, static_friction = 'end_a' or 'end_b')
!>                s mu_a N r(eps) a,  a the line's direction in the plane (from end a
!>                towards end b), s = -1 towards end a, +1 towards end b, eps = |e| - 1
!>                the cell's strain and r(eps) = eps / sqrt(eps^2 + eps_r^2): full towards
!>                the anchor on a stretched cell, none at zero strain, and the other way
!>                on a compressed one (static friction holds the line whichever way it
!>                would slide, up to mu N; where the friction has taken all the tension
!>                the line lies at zero strain, held, not slack and undetermined),
!>
!> with k = stiffness d and c = damping d (MoorDyn's kBot and cBot on the
!> diameter d), the cell's velocity w and v_s the slip_velocity. In 2-D there is
!> no lateral direction. The contact and the friction are booked as work in the
!> ledger, as every load's is. The length on the bottom (the sum of ds phi) is
!> the load's measure.
module xcable_loads_seabed
   use xcable_core_kinds, only: dp
   use xcable_core_strings, only: quantity
   use xcable_io_config, only: case_config
   use xcable_loads_load, only: cable_load
   use xcable_numerics_vector3, only: outer
   use xcable_numerics_facets, only: facet_at
   implicit none
   private
   public :: seabed_load, seabed_from_case

   !> The strain eps_r over which the static friction fades to none at zero strain
   !> (r(eps_r) = 0.71), smooth for Newton: the larger of static_friction_strain and
   !> fade_cells ds mu_a w / EA, the strain that fade_cells cells' full friction would take
   !> from the line (ds the cell's unstretched length, w the line's weight in the fluid, EA its
   !> axial stiffness near zero strain). Where the friction takes all the tension, the tension
   !> then falls to zero over a few cells instead of a point (resolved by the grid, so Newton
   !> converges); where the tension stays above EA eps_r the friction is full to within
   !> (eps_r / eps)^2 / 2. The effect on the statics is measured in docs/theory/seabed.md.
   real(dp), parameter, public :: static_friction_strain = 1.0e-8_dp, fade_cells = 4

   !> A seabed.
   type, extends(cable_load) :: seabed_load
      !> Depth under z = 0 at the origin (m) and slopes dz/dx, dz/dy.
      real(dp) :: depth = 0, slope_x = 0, slope_y = 0
      !> A bathymetry (in place of the plane): grid lines along x and y (m) and the bottom's
      !> height z on them (m), as flat facets (numerics/facets.f90); a cell takes the facet
      !> under its middle. Not allocated: the plane.
      real(dp), allocatable :: grid_x(:), grid_y(:), grid_z(:, :)
      !> Contact stiffness (N/m^2) and damping (N s/m^2) per unstretched length.
      real(dp) :: stiffness = 0, damping = 0
      !> Friction coefficients along and across the line; slip speed of the regularisation, m/s.
      real(dp) :: mu_axial = 0, mu_lateral = 0, slip_velocity = 1.0e-2_dp
      !> The statics' friction: towards end a (-1), towards end b (+1) or none (0); whether the
      !> statics evaluates the load now (set_statics).
      integer :: static_towards = 0
      logical :: in_statics = .false.
      !> The least strain over which the static friction fades (static_friction_strain), and the
      !> line's axial stiffness (N) and weight in the fluid (N/m) the statics gave (set_statics).
      real(dp) :: static_strain = static_friction_strain, line_stiffness = 0, line_weight = 0
      !> The share of mu_axial the static friction takes (the statics' continuation: 1 at the end).
      real(dp) :: static_share = 1
   contains
      procedure :: name => seabed_name
      procedure :: cell_force => seabed_cell_force
      procedure :: has_3d => seabed_has_3d
      procedure :: cell_force3 => seabed_cell_force3
      procedure :: has_skew => seabed_has_skew
      procedure :: cell_skew => seabed_cell_skew
      procedure :: measure_name => seabed_measure_name
      procedure :: cell_measure => seabed_cell_measure
      procedure :: measure_note => seabed_measure_note
      !> Height of the bottom under a horizontal point (x) or (x, y), m.
      procedure :: bottom => seabed_bottom
      !> The bottom is a floor (the statics' note on a line too long to be taut).
      procedure :: floor => seabed_bottom
      procedure :: set_statics => seabed_set_statics
      procedure :: static_form => seabed_static_form
   end type seabed_load

contains

   !> The seabed of a case (&seabed depth > 0 or a bathymetry_file), none otherwise.
   subroutine seabed_from_case(config, area, load)
      !> Validated case.
      type(case_config), intent(in) :: config
      !> Unstretched cross-section of the cable, m^2 (unused).
      real(dp), intent(in) :: area
      !> The seabed, or unallocated.
      class(cable_load), allocatable, intent(out) :: load
      if (.not. config%has_seabed()) return
      allocate (load, source=seabed_load(depth=config%seabed_depth, slope_x=config%seabed_slope_x, &
                                         slope_y=config%seabed_slope_y, &
                                         stiffness=config%seabed_stiffness*config%diameter, &
                                         damping=config%seabed_damping*config%diameter, mu_axial=config%mu_axial, &
                                         mu_lateral=config%mu_lateral, slip_velocity=config%slip_velocity))
      select type (load)
      type is (seabed_load)
         if (allocated(config%bathymetry_x)) then
            load%grid_x = config%bathymetry_x
            load%grid_y = config%bathymetry_y
            load%grid_z = -config%bathymetry_depth
         end if
         if (trim(config%static_friction) == 'end_a') load%static_towards = -1
         if (trim(config%static_friction) == 'end_b') load%static_towards = 1
      end select
   end subroutine seabed_from_case

   !> The seabed acts otherwise in the statics when it has a static friction.
   pure logical function seabed_static_form(self)
      class(seabed_load), intent(in) :: self
      seabed_static_form = self%static_towards /= 0 .and. self%mu_axial > 0
   end function seabed_static_form

   !> The statics' friction acts while the statics evaluates the load.
   subroutine seabed_set_statics(self, on, stiffness, weight, share)
      class(seabed_load), intent(inout) :: self
      logical, intent(in) :: on
      !> The line's axial stiffness near zero strain (N) and weight in the fluid (N/m); the share of
      !> the friction coefficient the static friction takes.
      real(dp), intent(in) :: stiffness, weight, share
      self%static_share = share
      self%in_statics = on .and. self%static_form()
      self%line_stiffness = stiffness
      self%line_weight = weight
   end subroutine seabed_set_statics

   pure function seabed_name(self) result(name)
      class(seabed_load), intent(in) :: self
      character(:), allocatable :: name
      name = 'seabed'
   end function seabed_name

   pure logical function seabed_has_3d(self)
      class(seabed_load), intent(in) :: self
      seabed_has_3d = .true.
   end function seabed_has_3d

   pure real(dp) function seabed_bottom(self, p)
      class(seabed_load), intent(in) :: self
      real(dp), intent(in) :: p(:)
      real(dp) :: depth, sx, sy
      call local_plane(self, [p, 0.0_dp], depth, sx, sy)
      seabed_bottom = -depth + sx*p(1)
      if (size(p) >= 2) seabed_bottom = seabed_bottom + sy*p(2)
   end function seabed_bottom

   !> The plane of the bottom at the horizontal point of x (x, z or x, y, z): the seabed's own,
   !> or the bathymetry's facet under it, as z = -depth + sx x + sy y.
   pure subroutine local_plane(self, x, depth, sx, sy)
      class(seabed_load), intent(in) :: self
      real(dp), intent(in) :: x(:)
      real(dp), intent(out) :: depth, sx, sy
      real(dp) :: px, py, z0
      if (.not. allocated(self%grid_z)) then
         depth = self%depth
         sx = self%slope_x
         sy = self%slope_y
         return
      end if
      px = x(1)
      py = 0
      if (size(x) >= 3) py = x(2)
      call facet_at(self%grid_x, self%grid_y, self%grid_z, px, py, z0, sx, sy)
      if (size(x) < 3) sy = 0
      depth = -(z0 - sx*px - sy*py)
   end subroutine local_plane

   !> The plane's unit normal (up) in dimension nd (2: x, z; 3: x, y, z) and the depth of the
   !> origin's projection: d(r) = offset - n.r; at the point x (a cell's middle: a bathymetry's
   !> facet under it).
   pure subroutine plane(self, nd, n, offset, x)
      class(seabed_load), intent(in) :: self
      integer, intent(in) :: nd
      real(dp), intent(out) :: n(nd), offset
      real(dp), intent(in) :: x(nd)
      real(dp) :: nu, depth, sx, sy
      call local_plane(self, x, depth, sx, sy)
      if (nd == 2) then
         nu = sqrt(1 + sx**2)
         n = [-sx, 1.0_dp]/nu
      else
         nu = sqrt(1 + sx**2 + sy**2)
         n = [-sx, -sy, 1.0_dp]/nu
      end if
      offset = -depth/nu
   end subroutine plane

   !> Mean penetration P and contact fraction phi of a straight cell with its ends' penetrations
   !> dm + delta and dm - delta, and their derivatives with respect to dm and delta.
   pure subroutine penetration(dm, delta, p, dp_dm, dp_dd, phi, dphi_dm, dphi_dd)
      real(dp), intent(in) :: dm, delta
      real(dp), intent(out) :: p, dp_dm, dp_dd, phi, dphi_dm, dphi_dd
      real(dp) :: a, s
      a = abs(delta)
      s = sign(1.0_dp, delta)
      dp_dd = 0
      dphi_dm = 0
      dphi_dd = 0
      if (dm >= a) then
         p = dm
         dp_dm = 1
         phi = 1
         if (dm == 0) phi = 0.5_dp
      else if (dm <= -a) then
         p = 0
         dp_dm = 0
         phi = 0
      else
         p = (dm + a)**2/(4*a)
         dp_dm = (dm + a)/(2*a)
         dp_dd = s*(dp_dm - p/a)
         phi = (dm + a)/(2*a)
         dphi_dm = 1/(2*a)
         dphi_dd = s*(1/(2*a) - phi/a)
      end if
   end subroutine penetration

   pure logical function seabed_has_skew(self)
      class(seabed_load), intent(in) :: self
      seabed_has_skew = .true.
   end function seabed_has_skew

   !> The contact's consistent shares: node a (the cell's first end) takes ds int_0^1 (1 - xi)
   !> k max(d, 0) n dxi, node b ds int xi k max(d, 0) n dxi, the gradient of the cell's contact
   !> energy ds k int max(d, 0)^2 / 2. So g = k Q n / 2, Q = int_0^1 (1 - 2 xi) max(d(xi), 0) dxi
   !> (delta / 3 with the whole cell in contact). Without it nodes moving alternately up and down
   !> would leave every cell's mean penetration, and so the contact, unchanged.
   pure subroutine seabed_cell_skew(self, x, ds, e, w, a, g, dg_dx, dg_de, dg_dw, dg_da)
      class(seabed_load), intent(in) :: self
      real(dp), intent(in) :: x(:), ds, e(:), w(:), a(:)
      real(dp), intent(out) :: g(:), dg_dx(:, :), dg_de(:, :), dg_dw(:, :), dg_da(:, :)
      real(dp) :: n(size(e)), offset, dm, delta, q, dq_dm, dq_dd, ad, u0, s
      integer :: i, j
      dg_dw = 0
      dg_da = 0
      call plane(self, size(e), n, offset, x)
      dm = offset - dot_product(n, x)
      delta = 0.5_dp*ds*dot_product(n, e)
      ad = abs(delta)
      s = sign(1.0_dp, delta)
      if (dm >= ad) then
         q = delta/3
         dq_dm = 0
         dq_dd = 1.0_dp/3
      else if (dm <= -ad) then
         q = 0
         dq_dm = 0
         dq_dd = 0
      else
         ! Q = s Q+(dm, |delta|), Q+ = [dm (1 - u0^2) / 2 + |delta| (1 - u0^3) / 3] / 2, u0 = -dm / |delta|.
         u0 = -dm/ad
         q = s*0.5_dp*(dm*(1 - u0*u0)/2 + ad*(1 - u0**3)/3)
         dq_dm = s*(1 - u0*u0)/4
         dq_dd = (1 - u0**3)/6
      end if
      g = 0.5_dp*self%stiffness*q*n
      do j = 1, size(e)
         do i = 1, size(e)
            dg_dx(i, j) = -0.5_dp*self%stiffness*dq_dm*n(i)*n(j)
            dg_de(i, j) = 0.25_dp*ds*self%stiffness*dq_dd*n(i)*n(j)
         end do
      end do
   end subroutine seabed_cell_skew

   !> Planar form (x, z).
   pure subroutine seabed_cell_force(self, x, ds, e, w, a, f, df_dx, df_de, df_dw, df_da)
      class(seabed_load), intent(in) :: self
      real(dp), intent(in) :: x(2), ds, e(2), w(2), a(2)
      real(dp), intent(out) :: f(2), df_dx(2, 2), df_de(2, 2), df_dw(2, 2), df_da(2, 2)
      call contact_force(self, x, ds, e, w, f, df_dx, df_de, df_dw)
      df_da = 0
   end subroutine seabed_cell_force

   !> 3-D form (x, y, z).
   pure subroutine seabed_cell_force3(self, x, ds, e, w, a, f, df_dx, df_de, df_dw, df_da)
      class(seabed_load), intent(in) :: self
      real(dp), intent(in) :: x(3), ds, e(3), w(3), a(3)
      real(dp), intent(out) :: f(3), df_dx(3, 3), df_de(3, 3), df_dw(3, 3), df_da(3, 3)
      call contact_force(self, x, ds, e, w, f, df_dx, df_de, df_dw)
      df_da = 0
   end subroutine seabed_cell_force3

   !> Contact, damping and friction per unstretched length, any dimension.
   pure subroutine contact_force(self, x, ds, e, w, f, df_dx, df_de, df_dw)
      class(seabed_load), intent(in) :: self
      real(dp), intent(in) :: x(:), ds, e(:), w(:)
      real(dp), intent(out) :: f(:), df_dx(:, :), df_de(:, :), df_dw(:, :)
      integer :: nd, i
      real(dp), dimension(size(e)) :: n, pe, ax, wa, wl, ga, gl, fric, dn_dx, dn_de
      real(dp), dimension(size(e), size(e)) :: pn, aa, gam, gml, dax_de, turn, eye
      real(dp) :: offset, dm, delta, p, dp_dm, dp_dd, phi, dphi_dm, dphi_dd, force, vn, lpe
      nd = size(e)
      f = 0
      df_dx = 0
      df_de = 0
      df_dw = 0
      call plane(self, nd, n, offset, x)
      dm = offset - dot_product(n, x)
      delta = 0.5_dp*ds*dot_product(n, e)
      call penetration(dm, delta, p, dp_dm, dp_dd, phi, dphi_dm, dphi_dd)
      if (p <= 0 .and. phi <= 0) return
      eye = 0
      do i = 1, nd
         eye(i, i) = 1
      end do
      ! The projector onto the bottom's plane (the friction's directions).
      pn = eye - outer(n, n)
      ! Contact N n, N = k P: dN/dx = -k dP/ddm n, dN/de = k dP/ddelta ds/2 n.
      force = self%stiffness*p
      dn_dx = -self%stiffness*dp_dm*n
      dn_de = 0.5_dp*ds*self%stiffness*dp_dd*n
      f = force*n
      df_dx = outer(n, dn_dx)
      df_de = outer(n, dn_de)
      ! Damping -c phi (n.w) n.
      vn = dot_product(n, w)
      f = f - self%damping*phi*vn*n
      df_dw = -self%damping*phi*outer(n, n)
      df_dx = df_dx + self%damping*vn*dphi_dm*outer(n, n)
      df_de = df_de - 0.5_dp*ds*self%damping*vn*dphi_dd*outer(n, n)
      ! The statics' friction s mu_a N r(eps) a (the module header).
      if (self%in_statics) then
         block
            real(dp) :: eps, r, dr, le, er2, c
            real(dp), dimension(size(e)) :: a, ehat
            real(dp), dimension(size(e), size(e)) :: da_de
            le = norm2(e)
            eps = le - 1
            a = matmul(pn, e)
            if (norm2(a) > 1.0e-12_dp*le) then
               da_de = matmul(eye - outer(a, a)/dot_product(a, a), pn)/norm2(a)
               a = a/norm2(a)
               ehat = e/le
               er2 = self%static_strain
               if (self%line_stiffness > 0) er2 = max(er2, fade_cells*ds*self%mu_axial*self%line_weight/self%line_stiffness)
               er2 = er2**2
               r = eps/sqrt(eps*eps + er2)
               dr = er2/sqrt(eps*eps + er2)**3
               c = self%static_towards*self%mu_axial*self%static_share
               f = f + c*force*r*a
               df_dx = df_dx + c*r*outer(a, dn_dx)
               df_de = df_de + c*(r*outer(a, dn_de) + force*dr*outer(a, ehat) + force*r*da_de)
            end if
         end block
      end if
      if (self%mu_axial == 0 .and. self%mu_lateral == 0) return
      ! Friction -N [mu_a g(w_a) + mu_l g(w_l)] in the plane.
      pe = matmul(pn, e)
      lpe = norm2(pe)
      if (lpe > 1.0e-12_dp*norm2(e)) then
         ax = pe/lpe
      else
         ax = 0
      end if
      aa = outer(ax, ax)
      wa = dot_product(ax, w)*ax
      wl = matmul(pn, w) - wa
      call regularised(wa, self%slip_velocity, ga, gam)
      call regularised(wl, self%slip_velocity, gl, gml)
      fric = -(self%mu_axial*ga + self%mu_lateral*gl)
      f = f + force*fric
      df_dx = df_dx + outer(fric, dn_dx)
      df_de = df_de + outer(fric, dn_de)
      df_dw = df_dw - force*(self%mu_axial*matmul(gam, aa) + self%mu_lateral*matmul(gml, pn - aa))
      if (lpe > 1.0e-12_dp*norm2(e)) then
         ! w_a = (a.w) a: dw_a/da = (a.w) I + a w^T, da/de = (I - a a^T) P_n / |P_n e|; w_l = P_n w - w_a.
         turn = dot_product(ax, w)*eye + outer(ax, w)
         dax_de = matmul(eye - aa, pn)/lpe
         df_de = df_de - force*matmul(self%mu_axial*gam - self%mu_lateral*gml, matmul(turn, dax_de))
      end if
   end subroutine contact_force

   !> g(v) = v / sqrt(|v|^2 + vs^2) and dg/dv.
   pure subroutine regularised(v, vs, g, dg)
      real(dp), intent(in) :: v(:), vs
      real(dp), intent(out) :: g(:), dg(:, :)
      real(dp) :: r
      integer :: i
      r = sqrt(dot_product(v, v) + vs*vs)
      g = v/r
      dg = -outer(v, v)/r**3
      do i = 1, size(v)
         dg(i, i) = dg(i, i) + 1/r
      end do
   end subroutine regularised

   pure function seabed_measure_name(self) result(name)
      class(seabed_load), intent(in) :: self
      character(:), allocatable :: name
      name = 'grounded_length'
   end function seabed_measure_name

   !> The unstretched length of the cell below the bottom, ds phi, m.
   pure real(dp) function seabed_cell_measure(self, r1, r2, ds)
      class(seabed_load), intent(in) :: self
      real(dp), intent(in) :: r1(:), r2(:), ds
      real(dp) :: n(size(r1)), offset, p, d1, d2, phi, d3, d4
      call plane(self, size(r1), n, offset, 0.5_dp*(r1 + r2))
      call penetration(offset - 0.5_dp*dot_product(n, r1 + r2), 0.5_dp*dot_product(n, r2 - r1), p, d1, d2, phi, d3, d4)
      seabed_cell_measure = ds*phi
   end function seabed_cell_measure

   !> Says how much of the line lies on the bottom at the start.
   function seabed_measure_note(self, value, length) result(text)
      class(seabed_load), intent(in) :: self
      real(dp), intent(in) :: value, length
      character(:), allocatable :: text
      text = ''
      if (value > 0) text = 'the line lies on the seabed at the start: grounded length '//quantity(value, 'm')// &
                            ' of '//quantity(length, 'm')
   end function seabed_measure_note
end module xcable_loads_seabed
