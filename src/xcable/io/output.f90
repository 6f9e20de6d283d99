!> HDF5 result file (and, when asked, gnuplot-ready text beside it).
!>
!> Layout (h5py reads 2-D datasets as [time, node]):
!>   /  attributes status ('running', 'complete' or 'failed'), failure_reason,
!>      failure_time, namelist, input_file, code_version, compiler_version,
!>      compiler_options
!>   /static/{s,x,z,tension,shear,strain,curvature,beta0,beta3}, attributes span, sag, end_angle
!>   /time, /s, and one 2-D dataset per field asked for in &output fields
!>   /history/{time,step,end_velocity,fixed_end_tension,newton_iterations,rejected}
!>   /history/energy/{strain,kinetic,bending,gravity,work,ledger} when the ledger is kept
!>   /summary attributes (peak_end_speed, min_fixed_end_tension, ...)
!> The status is 'running' from creation, so a run that is killed never looks complete.
module xcable_io_output
   use xcable_kinds, only: dp
   use xcable_error, only: error_type, fatal_error, stat_io
   use xcable_strings, only: str
   use xcable_model_equations, only: cable_model, n_eq, i_eps, i_sn, i_u, i_v, i_b0, i_b3, i_om
   use xcable_model_geometry, only: positions
   use xcable_io_input, only: known_fields
   use xcable_statics, only: static_state
   use xcable_dynamics, only: run_observer, run_history, run_summary, n_energy, energy_names
   use xcable_io_hdf5, only: put_real_vector, put_int_vector, put_real_attr, put_int_attr, put_text_attr
   use hdf5
   use, intrinsic :: iso_fortran_env, only: compiler_version, compiler_options
   implicit none
   private
   public :: result_file, code_version

   !> Version of the code written into every result.
   character(len=*), parameter :: code_version = '0.1.0'

   !> An open result file; receives the snapshots of a run.
   type, extends(run_observer) :: result_file
      !> Path of the HDF5 file.
      character(:), allocatable :: path
      !> HDF5 identifier of the file.
      integer(hid_t) :: file = -1
      !> Cable data (for the tension) and grid.
      type(cable_model) :: model
      real(dp), allocatable :: s(:)
      !> Which of known_fields are written.
      logical :: want(size(known_fields)) = .false.
      !> Snapshots written so far.
      integer :: snapshots = 0
      !> Whether gnuplot text is written, and the unit of its snapshot file.
      logical :: gnuplot_text = .false.
      integer :: text_unit = -1
      !> Stem of the gnuplot text files.
      character(:), allocatable :: text_stem
   contains
      procedure :: create => result_create
      procedure :: write_static => result_write_static
      procedure :: snapshot => result_snapshot
      procedure :: write_history => result_write_history
      procedure :: write_summary => result_write_summary
      procedure :: finish => result_finish
   end type result_file

contains

   !> Create the file (status 'running') and write the provenance.
   subroutine result_create(self, path, model, s, fields, namelist_text, input_file, gnuplot, error)
      !> Result file.
      class(result_file), intent(inout) :: self
      !> Path of the HDF5 file.
      character(*), intent(in) :: path
      !> Cable data.
      type(cable_model), intent(in) :: model
      !> Node arc lengths, m.
      real(dp), intent(in) :: s(:)
      !> Snapshot fields, separated by blanks or commas.
      character(*), intent(in) :: fields
      !> The resolved namelist.
      character(*), intent(in) :: namelist_text
      !> Namelist file of the case.
      character(*), intent(in) :: input_file
      !> Write gnuplot-ready text too.
      logical, intent(in) :: gnuplot
      !> Error when the file cannot be created.
      type(error_type), allocatable, intent(out) :: error
      integer :: hdferr, i, dot, ios
      character(len=256) :: msg
      logical :: ok
      self%path = path
      self%model = model
      self%s = s
      do i = 1, size(known_fields)
         self%want(i) = has_word(fields, trim(known_fields(i)))
      end do
      call h5open_f(hdferr)
      call h5eset_auto_f(0, hdferr)
      call h5fcreate_f(path, H5F_ACC_TRUNC_F, self%file, hdferr)
      if (hdferr /= 0) then
         call fatal_error(error, "cannot create the output file '"//path// &
                          "' (&output file): does its directory exist and is it writable?", stat_io)
         self%file = -1
         return
      end if
      ok = .true.
      call put_text_attr(self%file, 'status', 'running', ok)
      call put_text_attr(self%file, 'namelist', namelist_text, ok)
      call put_text_attr(self%file, 'input_file', input_file, ok)
      call put_text_attr(self%file, 'code_version', code_version, ok)
      call put_text_attr(self%file, 'compiler_version', compiler_version(), ok)
      call put_text_attr(self%file, 'compiler_options', compiler_options(), ok)
      call put_real_vector(self%file, 's', s, ok)
      if (.not. ok) then
         call fatal_error(error, "writing the provenance to '"//path//"' failed", stat_io)
         return
      end if
      if (gnuplot) then
         dot = index(path, '.', back=.true.)
         if (dot <= index(path, '/', back=.true.)) dot = len(path) + 1
         self%text_stem = path(1:dot - 1)
         open (newunit=self%text_unit, file=self%text_stem//'.snapshots.dat', status='replace', action='write', &
               iostat=ios, iomsg=msg)
         if (ios /= 0) then
            call fatal_error(error, 'cannot create '//self%text_stem//'.snapshots.dat (&output gnuplot): '// &
                             trim(msg), stat_io)
            ! No result file may be left by a run refused before it started.
            call h5fclose_f(self%file, hdferr)
            self%file = -1
            open (newunit=self%text_unit, file=path, status='old', iostat=ios)
            if (ios == 0) close (self%text_unit, status='delete')
            self%text_unit = -1
            return
         end if
         self%gnuplot_text = .true.
         write (self%text_unit, '(a)') '# xcable snapshots: one block per time (gnuplot index), blocks separated by '// &
            'two blank lines'
         write (self%text_unit, '(a)') '# columns: s[m] x[m] z[m] tension[N] strain[-] u[m/s] v[m/s] shear[N] '// &
            'curvature[1/m]'
      end if
   end subroutine result_create

   !> Write the static state.
   subroutine result_write_static(self, state, error)
      !> Result file.
      class(result_file), intent(inout) :: self
      !> Static solution.
      type(static_state), intent(in) :: state
      !> Error when writing fails.
      type(error_type), allocatable, intent(out) :: error
      integer(hid_t) :: group
      integer :: hdferr
      logical :: ok
      call h5gcreate_f(self%file, 'static', group, hdferr)
      ok = hdferr == 0
      if (ok) then
         call put_real_vector(group, 's', self%s, ok)
         call put_real_vector(group, 'x', state%x, ok)
         call put_real_vector(group, 'z', state%z, ok)
         call put_real_vector(group, 'tension', self%model%law%tension(state%y(i_eps, :)), ok)
         call put_real_vector(group, 'shear', state%y(i_sn, :), ok)
         call put_real_vector(group, 'strain', state%y(i_eps, :), ok)
         call put_real_vector(group, 'curvature', state%y(i_om, :), ok)
         call put_real_vector(group, 'beta0', state%y(i_b0, :), ok)
         call put_real_vector(group, 'beta3', state%y(i_b3, :), ok)
         call put_real_attr(group, 'span', state%span, ok)
         call put_real_attr(group, 'sag', state%sag, ok)
         call put_real_attr(group, 'end_angle', state%end_angle, ok)
         call put_int_attr(group, 'newton_iterations', state%newton%iterations, ok)
         call h5gclose_f(group, hdferr)
      end if
      call h5fflush_f(self%file, H5F_SCOPE_GLOBAL_F, hdferr)
      if (.not. ok .or. hdferr /= 0) call fatal_error(error, "writing /static to '"//self%path//"' failed", stat_io)
   end subroutine result_write_static

   !> Append one snapshot (run_observer).
   subroutine result_snapshot(self, t, y, error)
      !> Result file.
      class(result_file), intent(inout) :: self
      !> Time, s.
      real(dp), intent(in) :: t
      !> Unknowns (7, nodes).
      real(dp), intent(in) :: y(:, :)
      !> Error when writing fails.
      type(error_type), allocatable, intent(out) :: error
      real(dp) :: x(size(self%s)), z(size(self%s)), tension(size(self%s)), field(size(self%s))
      integer :: i, k, hdferr
      logical :: ok
      ok = .true.
      self%snapshots = self%snapshots + 1
      call append(self%file, 'time', [t], 1, ok)
      if (self%want(6) .or. self%want(7) .or. self%gnuplot_text) call positions(y, self%s, x, z)
      if (self%want(1) .or. self%gnuplot_text) tension = self%model%law%tension(y(i_eps, :))
      do i = 1, size(known_fields)
         if (.not. self%want(i)) cycle
         select case (trim(known_fields(i)))
         case ('tension'); field = tension
         case ('shear'); field = y(i_sn, :)
         case ('strain'); field = y(i_eps, :)
         case ('u'); field = y(i_u, :)
         case ('v'); field = y(i_v, :)
         case ('x'); field = x
         case ('z'); field = z
         case ('curvature'); field = y(i_om, :)
         end select
         call append(self%file, trim(known_fields(i)), field, 2, ok)
      end do
      call h5fflush_f(self%file, H5F_SCOPE_GLOBAL_F, hdferr)
      if (.not. ok .or. hdferr /= 0) call fatal_error(error, "writing snapshot at t = "//str(t)//" s to '"//self%path//"' failed", &
                                        stat_io)
      if (self%gnuplot_text) then
         if (self%snapshots > 1) write (self%text_unit, '(/)')
         write (self%text_unit, '(a,es14.6)') '# t = ', t
         do k = 1, size(self%s)
            write (self%text_unit, '(9es16.8)') self%s(k), x(k), z(k), tension(k), y(i_eps, k), y(i_u, k), &
               y(i_v, k), y(i_sn, k), y(i_om, k)
         end do
         flush (self%text_unit)
      end if
   end subroutine result_snapshot

   !> Write the history of the run.
   subroutine result_write_history(self, history, error)
      !> Result file.
      class(result_file), intent(inout) :: self
      !> One record per accepted step.
      type(run_history), intent(in) :: history
      !> Error when writing fails.
      type(error_type), allocatable, intent(out) :: error
      integer(hid_t) :: group, egroup
      integer :: hdferr, n, i, unit, ios
      logical :: ok
      n = history%n
      call h5gcreate_f(self%file, 'history', group, hdferr)
      ok = hdferr == 0
      if (ok) then
         call put_real_vector(group, 'time', history%time(0:n), ok)
         call put_real_vector(group, 'step', history%step(0:n), ok)
         call put_real_vector(group, 'end_velocity', history%end_velocity(0:n), ok)
         call put_real_vector(group, 'fixed_end_tension', history%fixed_end_tension(0:n), ok)
         call put_int_vector(group, 'newton_iterations', history%newton_iterations(0:n), ok)
         call put_int_vector(group, 'rejected', history%rejected(0:n), ok)
         if (allocated(history%energy)) then
            call h5gcreate_f(group, 'energy', egroup, hdferr)
            ok = ok .and. hdferr == 0
            if (hdferr == 0) then
               do i = 1, n_energy
                  call put_real_vector(egroup, trim(energy_names(i)), history%energy(i, 0:n), ok)
               end do
               call h5gclose_f(egroup, hdferr)
            end if
         end if
         call h5gclose_f(group, hdferr)
      end if
      if (.not. ok) then
         call fatal_error(error, "writing /history to '"//self%path//"' failed", stat_io)
         return
      end if
      if (allocated(self%text_stem)) then
         open (newunit=unit, file=self%text_stem//'.history.dat', status='replace', action='write', iostat=ios)
         if (ios /= 0) then
            call fatal_error(error, 'cannot create '//self%text_stem//'.history.dat (&output gnuplot)', stat_io)
            return
         end if
         if (allocated(history%energy)) then
            write (unit, '(a)') '# columns: t[s] end_velocity[m/s] fixed_end_tension[N] newton_iterations '// &
               'E_strain[J] E_kinetic[J] E_bending[J] E_gravity[J] W_end[J] ledger[J]'
         else
            write (unit, '(a)') '# columns: t[s] end_velocity[m/s] fixed_end_tension[N] newton_iterations'
         end if
         do i = 0, n
            if (allocated(history%energy)) then
               write (unit, '(3es16.8,i4,6es17.9)') history%time(i), history%end_velocity(i), &
                  history%fixed_end_tension(i), history%newton_iterations(i), history%energy(:, i)
            else
               write (unit, '(3es16.8,i4)') history%time(i), history%end_velocity(i), &
                  history%fixed_end_tension(i), history%newton_iterations(i)
            end if
         end do
         close (unit)
      end if
   end subroutine result_write_history

   !> Write the summary figures as attributes of /summary.
   subroutine result_write_summary(self, summary, error)
      !> Result file.
      class(result_file), intent(inout) :: self
      !> Figures of the run.
      type(run_summary), intent(in) :: summary
      !> Error when writing fails.
      type(error_type), allocatable, intent(out) :: error
      integer(hid_t) :: group
      integer :: hdferr
      logical :: ok
      call h5gcreate_f(self%file, 'summary', group, hdferr)
      ok = hdferr == 0
      if (ok) then
         call put_real_attr(group, 'peak_end_speed', summary%peak_end_speed, ok)
         call put_real_attr(group, 'peak_end_speed_time', summary%peak_end_speed_time, ok)
         call put_real_attr(group, 'min_fixed_end_tension', summary%min_fixed_end_tension, ok)
         call put_real_attr(group, 'min_fixed_end_tension_time', summary%min_fixed_end_tension_time, ok)
         call put_real_attr(group, 'front_arrival_time', summary%front_arrival_time, ok)
         call put_real_attr(group, 'energy_drift', summary%energy_drift, ok)
         call put_real_attr(group, 'time_reached', summary%time_reached, ok)
         call put_real_attr(group, 'wall_time', summary%wall_time, ok)
         call put_real_attr(group, 'max_unit_norm_error', summary%max_unit_norm_error, ok)
         call put_int_attr(group, 'steps', summary%steps, ok)
         call put_int_attr(group, 'rejected_steps', summary%rejected_steps, ok)
         call put_int_attr(group, 'newton_iterations', summary%newton_iterations, ok)
         call put_int_attr(group, 'max_newton_iterations', summary%max_newton_iterations, ok)
         call put_int_attr(group, 'factorisations', summary%factorisations, ok)
         call h5gclose_f(group, hdferr)
      end if
      if (.not. ok) call fatal_error(error, "writing /summary to '"//self%path//"' failed", stat_io)
   end subroutine result_write_summary

   !> Set the final status ('complete' or 'failed' with reason and time) and close.
   subroutine result_finish(self, status, reason, time, error)
      !> Result file.
      class(result_file), intent(inout) :: self
      !> 'complete' or 'failed'.
      character(*), intent(in) :: status
      !> Why it failed.
      character(*), intent(in), optional :: reason
      !> Simulated time at the failure, s.
      real(dp), intent(in), optional :: time
      !> Error when the status cannot be written or the file not closed (the
      !> file then still reads 'running').
      type(error_type), allocatable, intent(out), optional :: error
      integer :: hdferr
      logical :: ok
      if (self%file < 0) return
      ok = .true.
      if (present(reason)) call put_text_attr(self%file, 'failure_reason', reason, ok)
      if (present(time)) call put_real_attr(self%file, 'failure_time', time, ok)
      call put_text_attr(self%file, 'status', status, ok)
      call h5fclose_f(self%file, hdferr)
      if ((.not. ok .or. hdferr /= 0) .and. present(error)) &
         call fatal_error(error, "writing the status '"//status//"' to '"//self%path//"' failed", stat_io)
      self%file = -1
      call h5close_f(hdferr)
      if (self%gnuplot_text) close (self%text_unit)
      self%gnuplot_text = .false.
   end subroutine result_finish

   !> Append a value (rank 1) or a row of node values (rank 2) to the
   !> extendible dataset name, created on first use.
   !> ok is cleared when the dataset cannot be created or opened, extended or
   !> written.
   subroutine append(loc, name, values, rank, ok)
      integer(hid_t), intent(in) :: loc
      character(*), intent(in) :: name
      real(dp), intent(in) :: values(:)
      integer, intent(in) :: rank
      logical, intent(inout) :: ok
      integer :: hdferr, err
      integer(hid_t) :: dset, space, memspace, plist
      integer(hsize_t) :: dims(2), maxdims(2), offset(2), count(2)
      logical :: exists
      call h5lexists_f(loc, name, exists, hdferr)
      count = [int(size(values), hsize_t), 1_hsize_t]
      if (.not. exists) then
         call h5pcreate_f(H5P_DATASET_CREATE_F, plist, hdferr)
         if (rank == 1) then
            dims(1) = 0
            maxdims(1) = H5S_UNLIMITED_F
            call h5pset_chunk_f(plist, 1, [64_hsize_t], hdferr)
         else
            dims = [count(1), 0_hsize_t]
            maxdims = [count(1), H5S_UNLIMITED_F]
            call h5pset_chunk_f(plist, 2, count, hdferr)
         end if
         call h5screate_simple_f(rank, dims(1:rank), space, hdferr, maxdims(1:rank))
         call h5dcreate_f(loc, name, H5T_NATIVE_DOUBLE, space, dset, err, plist)
         call h5sclose_f(space, hdferr)
         call h5pclose_f(plist, hdferr)
      else
         call h5dopen_f(loc, name, dset, err)
      end if
      if (err /= 0) then
         ok = .false.
         return
      end if
      call h5dget_space_f(dset, space, hdferr)
      call h5sget_simple_extent_dims_f(space, dims(1:rank), maxdims(1:rank), hdferr)
      call h5sclose_f(space, hdferr)
      if (rank == 1) then
         offset(1) = dims(1)
         dims(1) = dims(1) + 1
         count(1) = 1
      else
         offset = [0_hsize_t, dims(2)]
         dims(2) = dims(2) + 1
      end if
      call h5dset_extent_f(dset, dims(1:rank), hdferr)
      ok = ok .and. hdferr == 0
      call h5dget_space_f(dset, space, hdferr)
      call h5sselect_hyperslab_f(space, H5S_SELECT_SET_F, offset(1:rank), count(1:rank), hdferr)
      call h5screate_simple_f(rank, count(1:rank), memspace, hdferr)
      call h5dwrite_f(dset, H5T_NATIVE_DOUBLE, values, count(1:rank), hdferr, memspace, space)
      ok = ok .and. hdferr == 0
      call h5sclose_f(memspace, hdferr)
      call h5sclose_f(space, hdferr)
      call h5dclose_f(dset, hdferr)
   end subroutine append

   !> Whether a blank- or comma-separated list contains a word.
   pure logical function has_word(list, word)
      character(*), intent(in) :: list, word
      integer :: i, start
      character :: ch
      has_word = .false.
      start = 0
      do i = 1, len(list) + 1
         if (i <= len(list)) then
            ch = list(i:i)
         else
            ch = ' '
         end if
         if (ch == ' ' .or. ch == ',') then
            if (start > 0) then
               if (list(start:i - 1) == word) has_word = .true.
            end if
            start = 0
         else if (start == 0) then
            start = i
         end if
      end do
   end function has_word
end module xcable_io_output
