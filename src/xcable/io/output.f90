!> HDF5 result file (and, when asked, gnuplot-ready text beside it).
!>
!> Layout (h5py reads 2-D datasets as [time, node]):
!>   /  attributes status ('running', 'complete', 'failed' or 'interrupted'),
!>      failure_reason, failure_time, warnings, namelist, input_file,
!>      code_version, compiler_version, compiler_options, scheme, terms,
!>      run_id (the run's identifier, also in its checkpoints), resumes (how
!>      often it was resumed from a checkpoint), model ('2d' or '3d')
!>   /s, /time, and one 2-D dataset per field asked for in &output fields;
!>      a 3-D run also /y, /vy, /curvature_z, /twist, /binormal_shear,
!>      /curvature_n (field3_names; driver/rod3d_fields.f90)
!>   /static/{s,x,z,tension,shear,strain,u,v,curvature} (+ beta0, beta3 of the
!>      box scheme; + the 3-D fields of a 3-D run), attributes span, sag,
!>      end_angle, tension_a, tension_b, newton_iterations
!>   /history/{time,dt,newton_iterations,rejected}
!>   /history/<end>/{x,z,vx,vz,tension,force_x,force_z} for each end (+ y, vy,
!>      force_y of a 3-D run)
!>   /history/energy/{strain,kinetic,bending,gravity,work,dissipation,ledger} with the ledger
!>   /summary attributes
!> Every dataset, group and attribute is one of the output registry
!> (io/output_registry.f90), which gives each dataset its `units` and
!> `description` attributes and each group its `description`; a path it does
!> not list is not written (the write fails, naming it). /time and /s are
!> dimension scales ('time', 'node') attached to every [time, node] dataset,
!> /static/s to the static fields, /history/time to the history. Texts are
!> variable-length UTF-8 strings.
!> The status is 'running' from creation, so a run that is killed never looks
!> complete; 'interrupted' (with /summary, without /history) when it stopped
!> at SIGTERM with a checkpoint. Only the fields asked for are written.
!>
!> A resumed run reopens its file (reopen): the snapshots up to its
!> checkpoint stay, those written after it (by a process killed later) are
!> cut, as is the gnuplot text; /summary, /history and the failure and
!> warning attributes of an earlier stop are removed; status 'running'.
module xcable_io_output
   use xcable_core_kinds, only: dp
   use xcable_core_error, only: error_type, fatal_error, stat_io, stat_input
   use xcable_core_strings, only: str
   use xcable_driver_records, only: run_history, run_summary, static_info, run_observer, n_energy, energy_names, &
                                 field_names, n_fields, n_end_quantities, end_quantity_names, n_end_quantities_y, &
                                 end_quantity_names_y, n_fields3, field3_names
   use xcable_io_hdf5_put, only: put_real_vector, put_int_vector, put_real_attr, put_int_attr, put_text_attr, &
                             get_text_attr, get_int_attr, get_real_attr, open_scale, attach, append
   use xcable_io_output_registry, only: output_item, find_output, output_items
   use xcable_system_posix, only: replace_file
   use xcable_core_version, only: code_version
   use xcable_io_number_text, only: put_es, put_int
   use hdf5
   use, intrinsic :: iso_fortran_env, only: compiler_version, compiler_options
   implicit none
   private
   public :: result_file
   ! The helpers the submodules call. gfortran (12) compiles a module's private procedures as local
   ! symbols, which its submodules (io/output/) then cannot link to; so they are public here, for
   ! the submodules only.
   public :: check_attributes, close_kept, describe_dataset, describe_group, has_word, lay_out, put_ints, &
             put_reals, put_text, text_stem_of, why

   !> Fields of the gnuplot snapshot columns 2-9 (x z tension strain u v shear curvature).
   integer, parameter :: text_columns(8) = [6, 7, 1, 3, 4, 5, 2, 8]
   !> Energies of the history columns 5-11 (strain kinetic bending gravity work ledger dissipation).
   integer, parameter :: ledger_columns(7) = [1, 2, 3, 4, 5, 7, 6]

   !> An open result file; receives the static state and the snapshots of a run.
   type, extends(run_observer) :: result_file
      !> Path of the HDF5 file.
      character(:), allocatable :: path
      !> HDF5 identifier of the file.
      integer(hid_t) :: file = -1
      !> The snapshot datasets kept open between snapshots (0: /time, then
      !> field_names; -1: not open): opening and closing them for every snapshot
      !> took half of the HDF5 work of a snapshot (10 million instructions on
      !> fast_180kN). Closed before the file is (close_kept).
      integer(hid_t) :: kept(0:n_fields) = -1
      !> Output node arc lengths.
      real(dp), allocatable :: s(:)
      !> Which of field_names are written.
      logical :: want(n_fields) = .false.
      !> Snapshots written so far.
      integer :: snapshots = 0
      !> Whether gnuplot text is written, and the unit of its snapshot file.
      logical :: gnuplot_text = .false.
      integer :: text_unit = -1
      !> Stem of the gnuplot text files.
      character(:), allocatable :: text_stem
      !> Output columns where a new piece starts (a blank line in the gnuplot text).
      integer, allocatable :: piece_starts(:)
      !> A 3-D run: its snapshots come with the fields of field3_names (snapshot_extra),
      !> which the gnuplot text appends as columns 10-15; the planar fields wait in
      !> pending until they arrive.
      logical :: three_d = .false.
      !> Which snapshot fields (field_names, field3_names, beta0, beta3) this process has given
      !> their dimension scales: /time and /s on the top-level datasets, /static/s on the static
      !> ones (lay_out attaches each once: asking HDF5 whether a scale is attached costs more than
      !> the run's output).
      logical :: scaled(n_fields + n_fields3 + 2) = .false., static_scaled(n_fields + n_fields3 + 2) = .false.
      real(dp), allocatable :: pending(:, :)
      !> The first path a write found missing from the output registry (for the error message).
      character(:), allocatable :: unregistered
   contains
      procedure :: create => result_create
      procedure :: reopen => result_reopen
      procedure :: static => result_static
      procedure :: snapshot => result_snapshot
      procedure :: write_history => result_write_history
      procedure :: write_summary => result_write_summary
      procedure :: finish => result_finish
      !> The 3-D run's extra fields of a snapshot (y, w, ...): one 2-D dataset each.
      procedure :: snapshot_extra => result_snapshot_extra
      !> A text attribute of the file (the model that ran).
      procedure :: mark => result_mark
   end type result_file

   ! The result file's procedures in the submodules io/output/reopen.f90 and io/output/records.f90.
   interface
      !> Reopen the result file of a run that continues from a checkpoint. It
      !> must be the file of that run (run_id), not finished ('running' or
      !> 'interrupted'), with at least the snapshots the checkpoint counts and
      !> the same output nodes; with gnuplot text, its snapshot file must hold
      !> them too. All of this is checked before anything is changed. Then the
      !> part of the file the checkpoint counts is copied into a new file that
      !> replaces it (the snapshots after the checkpoint, /summary, /history and
      !> the failure and warning attributes of an earlier stop left behind), the
      !> text cut alike, the provenance updated (namelist, input_file; resumes
      !> counted) and the status set to 'running'.
      module subroutine result_reopen(self, path, s, fields, namelist_text, input_file, gnuplot, piece_starts, &
                                      snapshots, run_id, error, three_d)
         !> Result file.
         class(result_file), intent(inout) :: self
         !> Path of the HDF5 file.
         character(*), intent(in) :: path
         !> Output node arc lengths, m.
         real(dp), intent(in) :: s(:)
         !> Snapshot fields, separated by blanks or commas.
         character(*), intent(in) :: fields
         !> The resolved namelist (as the resumed run reads it).
         character(*), intent(in) :: namelist_text
         !> Namelist file of the case.
         character(*), intent(in) :: input_file
         !> Whether gnuplot text is written.
         logical, intent(in) :: gnuplot
         !> Output columns where a new piece starts (empty: one piece).
         integer, intent(in) :: piece_starts(:)
         !> Snapshots the checkpoint counts (the one at t = 0 included).
         integer, intent(in) :: snapshots
         !> Identifier of the run of the checkpoint.
         character(*), intent(in) :: run_id
         !> Error (stat_input) naming what does not fit; the file is then unchanged.
         type(error_type), allocatable, intent(out) :: error
         !> A 3-D run: its snapshots have the fields of field3_names too (default .false.).
         logical, intent(in), optional :: three_d
      end subroutine result_reopen

      !> Write the history of the run (and its gnuplot text).
      module subroutine result_write_history(self, history, error)
         !> Result file.
         class(result_file), intent(inout) :: self
         !> One record per accepted step.
         type(run_history), intent(in) :: history
         !> Error when writing fails.
         type(error_type), allocatable, intent(out) :: error
      end subroutine result_write_history

      !> Write the summary figures as attributes of /summary.
      module subroutine result_write_summary(self, summary, end_labels, error, info)
         !> Result file.
         class(result_file), intent(inout) :: self
         !> Figures of the run.
         type(run_summary), intent(in) :: summary
         !> Names of the ends.
         character(len=*), intent(in) :: end_labels(:)
         !> Error when writing fails.
         type(error_type), allocatable, intent(out) :: error
         !> The static state (its figures go first: static_*).
         type(static_info), intent(in), optional :: info
      end subroutine result_write_summary
   end interface

contains

   !> Create the file (status 'running') and write the provenance.
   subroutine result_create(self, path, s, fields, namelist_text, input_file, gnuplot, scheme, terms, piece_starts, error, &
                            run_id, three_d)
      !> Result file.
      class(result_file), intent(inout) :: self
      !> Path of the HDF5 file.
      character(*), intent(in) :: path
      !> Output node arc lengths, m.
      real(dp), intent(in) :: s(:)
      !> Snapshot fields, separated by blanks or commas.
      character(*), intent(in) :: fields
      !> The resolved namelist.
      character(*), intent(in) :: namelist_text
      !> Namelist file of the case.
      character(*), intent(in) :: input_file
      !> Write gnuplot-ready text too.
      logical, intent(in) :: gnuplot
      !> Discretisation and the terms of the model that were computed.
      character(*), intent(in) :: scheme, terms
      !> Output columns where a new piece starts (empty: one piece).
      integer, intent(in) :: piece_starts(:)
      !> Error when the file cannot be created.
      type(error_type), allocatable, intent(out) :: error
      !> Identifier of the run (written as the attribute run_id; its checkpoints carry it too).
      character(*), intent(in), optional :: run_id
      !> A 3-D run (its snapshots come with the fields of field3_names; default: no).
      logical, intent(in), optional :: three_d
      integer :: hdferr, i, ios, status
      integer(hid_t) :: access
      character(len=256) :: msg
      logical :: ok
      self%path = path
      self%s = s
      self%piece_starts = piece_starts
      self%three_d = .false.
      if (present(three_d)) self%three_d = three_d
      do i = 1, n_fields
         self%want(i) = has_word(fields, trim(field_names(i)))
      end do
      call h5open_f(hdferr)
      call h5eset_auto_f(0, hdferr)
      ! The file format of HDF5 1.8 and later stores attributes above 64 KB (the
      ! echo of a case with 1000-row tables) in dense storage.
      call h5pcreate_f(H5P_FILE_ACCESS_F, access, hdferr)
      call h5pset_libver_bounds_f(access, H5F_LIBVER_V18_F, H5F_LIBVER_LATEST_F, hdferr)
      call h5fcreate_f(path, H5F_ACC_TRUNC_F, self%file, hdferr, access_prp=access)
      call h5pclose_f(access, status)
      if (hdferr /= 0) then
         call fatal_error(error, "cannot create the output file '"//path// &
                          "' (&output file): does its directory exist and is it writable?", stat_io)
         self%file = -1
         return
      end if
      ok = .true.
      call put_text(self%file, 'status', 'running', ok)
      call put_text(self%file, 'namelist', namelist_text, ok)
      call put_text(self%file, 'input_file', input_file, ok)
      call put_text(self%file, 'code_version', code_version, ok)
      call put_text(self%file, 'compiler_version', compiler_version(), ok)
      call put_text(self%file, 'compiler_options', compiler_options(), ok)
      call put_text(self%file, 'scheme', scheme, ok)
      call put_text(self%file, 'terms', terms, ok)
      if (present(run_id)) call put_text(self%file, 'run_id', run_id, ok)
      call describe_group(self, self%file, '/', ok)
      call put_reals(self, self%file, '', 's', s, ok)
      if (.not. ok) then
         call fatal_error(error, "writing the provenance to '"//path//"' failed"//why(self), stat_io)
         return
      end if
      if (gnuplot) then
         self%text_stem = text_stem_of(path)
         open (newunit=self%text_unit, file=self%text_stem//'.snapshots.dat', status='replace', action='write', &
               iostat=ios, iomsg=msg)
         if (ios /= 0) then
            call fatal_error(error, 'cannot create '//self%text_stem//'.snapshots.dat (&output gnuplot): '// &
                             trim(msg), stat_io)
            ! No result file may be left by a run refused before it started.
            call close_kept(self)
            call h5fclose_f(self%file, hdferr)
            self%file = -1
            open (newunit=self%text_unit, file=path, status='old', iostat=ios)
            if (ios == 0) close (self%text_unit, status='delete')
            self%text_unit = -1
            return
         end if
         self%gnuplot_text = .true.
         write (self%text_unit, '(a)') '# xcable snapshots: one block per time (gnuplot index), blocks separated by '// &
            'two blank lines; a single blank line separates the pieces of a broken cable'
         if (self%three_d) then
            write (self%text_unit, '(a)') '# columns: s[m] x[m] z[m] tension[N] strain[-] u[m/s] v[m/s] shear[N] '// &
               'curvature[1/m]'//extra_header()
         else
            write (self%text_unit, '(a)') '# columns: s[m] x[m] z[m] tension[N] strain[-] u[m/s] v[m/s] shear[N] '// &
               'curvature[1/m]'
         end if
      end if

   contains

      !> The 3-D columns of the header: ' y[m] vy[m/s] ...'.
      function extra_header() result(text)
         character(:), allocatable :: text
         integer :: q
         type(output_item) :: item
         logical :: found
         text = ''
         do q = 1, n_fields3
            call find_output('/'//trim(field3_names(q)), item, found)
            text = text//' '//trim(field3_names(q))//'['//trim(item%units)//']'
         end do
      end function extra_header
   end subroutine result_create

   !> Stem of the gnuplot text files of a result path (without its extension).
   pure function text_stem_of(path) result(stem)
      character(*), intent(in) :: path
      character(:), allocatable :: stem
      integer :: dot
      dot = index(path, '.', back=.true.)
      if (dot <= index(path, '/', back=.true.)) dot = len(path) + 1
      stem = path(1:dot - 1)
   end function text_stem_of

   !> Write the static state (run_observer).
   subroutine result_static(self, info, error)
      !> Result file.
      class(result_file), intent(inout) :: self
      !> Static state.
      type(static_info), intent(in) :: info
      !> Error when writing fails.
      type(error_type), allocatable, intent(out) :: error
      integer(hid_t) :: group
      integer :: hdferr, i
      logical :: ok
      call h5gcreate_f(self%file, 'static', group, hdferr)
      ok = hdferr == 0
      if (ok) then
         call describe_group(self, group, '/static', ok)
         call put_reals(self, group, '/static', 's', info%s, ok)
         do i = 1, n_fields
            call put_reals(self, group, '/static', trim(field_names(i)), info%fields(:, i), ok)
         end do
         if (allocated(info%beta0)) then
            call put_reals(self, group, '/static', 'beta0', info%beta0, ok)
            call put_reals(self, group, '/static', 'beta3', info%beta3, ok)
         end if
         if (allocated(info%extra)) then
            do i = 1, n_fields3
               call put_reals(self, group, '/static', trim(field3_names(i)), info%extra(:, i), ok)
            end do
         end if
         ! The figures of one line between two ends (not of a network: its lines' ends are in /history).
         if (info%one_line) then
            call put_real_attr(group, 'span', info%span, ok)
            call put_real_attr(group, 'sag', info%sag, ok)
            call put_real_attr(group, 'end_angle', info%end_angle, ok)
            call put_real_attr(group, 'tension_a', info%tension_a, ok)
            call put_real_attr(group, 'tension_b', info%tension_b, ok)
            call put_real_attr(group, 'end_angle_b', info%end_angle_b, ok)
            call put_real_attr(group, 'lowest_z', info%lowest_z, ok)
            call put_real_attr(group, 'lowest_s', info%lowest_s, ok)
         end if
         call put_real_attr(group, 'max_tension', info%max_tension, ok)
         call put_int_attr(group, 'newton_iterations', info%newton_iterations, ok)
         call check_attributes(self, group, '/static', ok)
         call h5gclose_f(group, hdferr)
      end if
      call lay_out(self, ok)
      call h5fflush_f(self%file, H5F_SCOPE_GLOBAL_F, hdferr)
      if (.not. ok .or. hdferr /= 0) call fatal_error(error, "writing /static to '"//self%path//"' failed"//why(self), &
                                                      stat_io)
   end subroutine result_static

   !> Append one snapshot (run_observer).
   subroutine result_snapshot(self, t, fields, error)
      !> Result file.
      class(result_file), intent(inout) :: self
      !> Time, s.
      real(dp), intent(in) :: t
      !> Fields (nodes, n_fields).
      real(dp), intent(in) :: fields(:, :)
      !> Error when writing fails.
      type(error_type), allocatable, intent(out) :: error
      integer :: i, hdferr
      logical :: ok
      ok = .true.
      self%snapshots = self%snapshots + 1
      call append(self%file, 'time', [t], 1, ok, self%kept(0))
      do i = 1, n_fields
         if (self%want(i)) call append(self%file, trim(field_names(i)), fields(:, i), 2, ok, self%kept(i))
      end do
      if (self%snapshots == 1) call lay_out(self, ok)
      call h5fflush_f(self%file, H5F_SCOPE_GLOBAL_F, hdferr)
      if (.not. ok .or. hdferr /= 0) then
         call fatal_error(error, "writing snapshot at t = "//str(t)//" s to '"//self%path//"' failed"//why(self), stat_io)
         return
      end if
      if (self%gnuplot_text) then
         if (self%three_d) then
            ! The text waits for the 3-D fields (result_snapshot_extra).
            self%pending = fields
         else
            call write_text_block(self, t, fields)
         end if
      end if
   end subroutine result_snapshot

   !> One snapshot block of the gnuplot text: columns s x z tension strain u
   !> v shear curvature, and with extra (a 3-D run) the fields of
   !> field3_names, as '(9es16.8[,6es16.8])' (put_es).
   subroutine write_text_block(self, t, fields, extra)
      type(result_file), intent(inout) :: self
      real(dp), intent(in) :: t, fields(:, :)
      real(dp), intent(in), optional :: extra(:, :)
      character(len=(9 + n_fields3)*16) :: line
      integer :: k, q, pos
      if (self%snapshots > 1) write (self%text_unit, '(/)')
      write (self%text_unit, '(a,es14.6)') '# t = ', t
      do k = 1, size(self%s)
         if (any(self%piece_starts == k)) write (self%text_unit, '(a)') ''
         pos = 1
         call put_es(line, pos, self%s(k), 16, 8)
         do q = 1, 8
            call put_es(line, pos, fields(k, text_columns(q)), 16, 8)
         end do
         if (present(extra)) then
            do q = 1, size(extra, 2)
               call put_es(line, pos, extra(k, q), 16, 8)
            end do
         end if
         write (self%text_unit, '(a)') line(1:pos - 1)
      end do
      flush (self%text_unit)
   end subroutine write_text_block

   !> Extra fields of the snapshot just written, one 2-D dataset per name
   !> (a 3-D run's y, w, curvature_z, twist).
   subroutine result_snapshot_extra(self, t, names, fields, error)
      !> Result file.
      class(result_file), intent(inout) :: self
      !> Time, s.
      real(dp), intent(in) :: t
      !> Dataset names.
      character(*), intent(in) :: names(:)
      !> Fields (nodes, size(names)).
      real(dp), intent(in) :: fields(:, :)
      !> Error when writing fails (a name the output registry lacks is not written).
      type(error_type), allocatable, intent(out) :: error
      integer :: i, hdferr
      logical :: ok
      character(:), allocatable :: units, description
      ok = .true.
      do i = 1, size(names)
         call lookup(self, '/'//trim(names(i)), units, description, ok)
         if (len(description) > 0) call append(self%file, trim(names(i)), fields(:, i), 2, ok)
      end do
      if (self%snapshots == 1) call lay_out(self, ok)
      ! On disk before a checkpoint can count this snapshot (as result_snapshot's fields).
      call h5fflush_f(self%file, H5F_SCOPE_GLOBAL_F, hdferr)
      ok = ok .and. hdferr == 0
      if (.not. ok) then
         call fatal_error(error, 'writing the 3-D fields at t = '//str(t)//" s to '"//self%path//"' failed"// &
                          why(self), stat_io)
         return
      end if
      if (self%gnuplot_text .and. self%three_d .and. allocated(self%pending)) then
         call write_text_block(self, t, self%pending, fields)
         deallocate (self%pending)
      end if
   end subroutine result_snapshot_extra

   !> Write a text attribute of the file's root.
   subroutine result_mark(self, name, text, error)
      !> Result file.
      class(result_file), intent(inout) :: self
      !> Attribute name and value.
      character(*), intent(in) :: name, text
      !> Error when writing fails.
      type(error_type), allocatable, intent(out) :: error
      logical :: ok
      ok = .true.
      call put_text(self%file, name, text, ok)
      call check_attributes(self, self%file, '/', ok)
      if (.not. ok) call fatal_error(error, "writing the attribute '"//name//"' to '"//self%path//"' failed"// &
                                     why(self), stat_io)
   end subroutine result_mark

   !> Close the snapshot datasets kept open by result_snapshot (before the file).
   subroutine close_kept(self, ok)
      !> Result file.
      class(result_file), intent(inout) :: self
      !> Set to .false. when a close fails.
      logical, intent(inout), optional :: ok
      integer :: i, hdferr
      do i = 0, n_fields
         if (self%kept(i) < 0) cycle
         call h5dclose_f(self%kept(i), hdferr)
         if (present(ok)) ok = ok .and. hdferr == 0
         self%kept(i) = -1
      end do
   end subroutine close_kept

   !> Set the final status ('complete' or 'failed' with reason and time), the
   !> warnings, and close.
   subroutine result_finish(self, status, reason, time, warnings, error)
      !> Result file.
      class(result_file), intent(inout) :: self
      !> 'complete' or 'failed'.
      character(*), intent(in) :: status
      !> Why it failed.
      character(*), intent(in), optional :: reason
      !> Simulated time at the failure, s.
      real(dp), intent(in), optional :: time
      !> Warnings of the run, one per line ('' : none).
      character(*), intent(in), optional :: warnings
      !> Error when the status cannot be written or the file not closed (the
      !> file then still reads 'running').
      type(error_type), allocatable, intent(out), optional :: error
      integer :: hdferr
      logical :: ok
      if (self%file < 0) return
      ok = .true.
      if (present(reason)) call put_text(self%file, 'failure_reason', reason, ok)
      if (present(time)) call put_real_attr(self%file, 'failure_time', time, ok)
      if (present(warnings)) call put_text(self%file, 'warnings', warnings, ok)
      call put_text(self%file, 'status', status, ok)
      call check_attributes(self, self%file, '/', ok)
      call close_kept(self, ok)
      call h5fclose_f(self%file, hdferr)
      if ((.not. ok .or. hdferr /= 0) .and. present(error)) &
         call fatal_error(error, "writing the status '"//status//"' to '"//self%path//"' failed"//why(self), stat_io)
      self%file = -1
      call h5close_f(hdferr)
      if (self%gnuplot_text) close (self%text_unit)
      self%gnuplot_text = .false.
   end subroutine result_finish

   !> A text attribute of the result file: a variable-length UTF-8 string.
   subroutine put_text(loc, name, text, ok)
      integer(hid_t), intent(in) :: loc
      character(*), intent(in) :: name, text
      logical, intent(inout) :: ok
      call put_text_attr(loc, name, text, ok, utf8=.true.)
   end subroutine put_text

   !> The registry's units and description of a path ('/group/name' or '/group@name'); when the
   !> registry does not list it, ok is cleared and the path kept for the error message.
   subroutine lookup(self, path, units, description, ok)
      class(result_file), intent(inout) :: self
      character(*), intent(in) :: path
      character(:), allocatable, intent(out) :: units, description
      logical, intent(inout) :: ok
      type(output_item) :: item
      logical :: found
      call find_output(path, item, found)
      units = trim(item%units)
      description = trim(item%description)
      if (.not. found) then
         ok = .false.
         description = ''
         if (.not. allocated(self%unregistered)) self%unregistered = path
      end if
   end subroutine lookup

   !> ' (the path is not in the output registry)' after a failed write that found one, else ''.
   function why(self) result(text)
      class(result_file), intent(in) :: self
      character(:), allocatable :: text
      text = ''
      if (allocated(self%unregistered)) text = " ('"//self%unregistered// &
                                               "' is not in the output registry, io/output_registry.f90)"
   end function why

   !> A real dataset name of the group at path group ('' : the root) with the registry's units
   !> and description; not written when the registry does not list it (ok cleared).
   subroutine put_reals(self, loc, group, name, values, ok)
      class(result_file), intent(inout) :: self
      integer(hid_t), intent(in) :: loc
      character(*), intent(in) :: group, name
      real(dp), intent(in) :: values(:)
      logical, intent(inout) :: ok
      character(:), allocatable :: units, description
      call lookup(self, group//'/'//name, units, description, ok)
      if (len(description) > 0) call put_real_vector(loc, name, values, ok, units, description)
   end subroutine put_reals

   !> An integer dataset as put_reals.
   subroutine put_ints(self, loc, group, name, values, ok)
      class(result_file), intent(inout) :: self
      integer(hid_t), intent(in) :: loc
      character(*), intent(in) :: group, name
      integer, intent(in) :: values(:)
      logical, intent(inout) :: ok
      character(:), allocatable :: units, description
      call lookup(self, group//'/'//name, units, description, ok)
      if (len(description) > 0) call put_int_vector(loc, name, values, ok, units, description)
   end subroutine put_ints

   !> The registry's description of a group (or the root, path '/') as its attribute.
   subroutine describe_group(self, loc, path, ok)
      class(result_file), intent(inout) :: self
      integer(hid_t), intent(in) :: loc
      character(*), intent(in) :: path
      logical, intent(inout) :: ok
      character(:), allocatable :: units, description
      call lookup(self, path, units, description, ok)
      if (len(description) > 0) call put_text(loc, 'description', description, ok)
   end subroutine describe_group

   !> The registry's units and description on the dataset name of the group at path group
   !> ('' : the root), when it exists and lacks them (the snapshot datasets, made row by row).
   subroutine describe_dataset(self, loc, group, name, ok)
      class(result_file), intent(inout) :: self
      integer(hid_t), intent(in) :: loc
      character(*), intent(in) :: group, name
      logical, intent(inout) :: ok
      character(:), allocatable :: units, description
      integer(hid_t) :: dset
      integer :: hdferr
      logical :: exists
      call h5lexists_f(loc, name, exists, hdferr)
      if (.not. exists) return
      call h5dopen_f(loc, name, dset, hdferr)
      if (hdferr /= 0) then
         ok = .false.
         return
      end if
      call h5aexists_f(dset, 'description', exists, hdferr)
      if (.not. exists) then
         call lookup(self, group//'/'//name, units, description, ok)
         if (len(description) > 0) then
            call put_text(dset, 'units', units, ok)
            call put_text(dset, 'description', description, ok)
         end if
      end if
      call h5dclose_f(dset, hdferr)
   end subroutine describe_dataset

   !> Every attribute of loc (the group at path, '/' for the root) must be in the registry
   !> (those of HDF5's dimension scales and `description` aside); ok cleared if one is not.
   subroutine check_attributes(self, loc, path, ok)
      class(result_file), intent(inout) :: self
      integer(hid_t), intent(in) :: loc
      character(*), intent(in) :: path
      logical, intent(inout) :: ok
      integer :: count, k, hdferr
      character(len=64) :: name
      character(:), allocatable :: units, description
      call h5aget_num_attrs_f(loc, count, hdferr)
      if (hdferr /= 0) then
         ok = .false.
         return
      end if
      do k = 0, count - 1
         call h5aget_name_by_idx_f(loc, '.', H5_INDEX_NAME_F, H5_ITER_NATIVE_F, int(k, hsize_t), name, hdferr)
         if (hdferr /= 0) then
            ok = .false.
            cycle
         end if
         if (trim(name) == 'description') cycle
         if (path == '/') then
            call lookup(self, '/@'//trim(name), units, description, ok)
         else
            call lookup(self, path//'@'//trim(name), units, description, ok)
         end if
      end do
   end subroutine check_attributes

   !> The snapshot and static datasets described (describe_dataset) and given their dimension
   !> scales: /time ('time') and /s ('node') made scales and attached to every [time, node]
   !> dataset, /static/s to the static fields. Each step is skipped when done already, so this
   !> runs after the static state, the first snapshot, its 3-D fields and a reopen alike.
   subroutine lay_out(self, ok)
      class(result_file), intent(inout) :: self
      logical, intent(inout) :: ok
      character(len=*), parameter :: names(n_fields + n_fields3 + 2) = [character(len=14) :: field_names, &
                                                                          field3_names, 'beta0', 'beta3']
      integer(hid_t) :: time_scale, node_scale, group
      integer :: q, hdferr
      logical :: exists
      call describe_dataset(self, self%file, '', 'time', ok)
      call describe_dataset(self, self%file, '', 's', ok)
      do q = 1, n_fields + n_fields3
         call describe_dataset(self, self%file, '', trim(names(q)), ok)
      end do
      call open_scale(self%file, 'time', 'time', time_scale, ok)
      call open_scale(self%file, 's', 'node', node_scale, ok)
      if (time_scale >= 0 .and. node_scale >= 0) then
         do q = 1, n_fields + n_fields3
            if (self%scaled(q)) cycle
            call h5lexists_f(self%file, trim(names(q)), exists, hdferr)
            if (.not. exists) cycle
            call attach(time_scale, self%file, trim(names(q)), 0, 'time', ok, fresh=.true.)
            call attach(node_scale, self%file, trim(names(q)), 1, 'node', ok, fresh=.true.)
            self%scaled(q) = .true.
         end do
      end if
      if (time_scale >= 0) call h5dclose_f(time_scale, hdferr)
      if (node_scale >= 0) call h5dclose_f(node_scale, hdferr)
      call h5lexists_f(self%file, 'static', exists, hdferr)
      if (.not. exists) return
      call h5gopen_f(self%file, 'static', group, hdferr)
      if (hdferr /= 0) then
         ok = .false.
         return
      end if
      call open_scale(group, 's', 'node', node_scale, ok)
      if (node_scale >= 0) then
         do q = 1, size(names)
            if (self%static_scaled(q)) cycle
            call h5lexists_f(group, trim(names(q)), exists, hdferr)
            if (.not. exists) cycle
            call attach(node_scale, group, trim(names(q)), 0, 'node', ok, fresh=.true.)
            self%static_scaled(q) = .true.
         end do
         call h5dclose_f(node_scale, hdferr)
      end if
      call h5gclose_f(group, hdferr)
   end subroutine lay_out



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
