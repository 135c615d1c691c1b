! SPDX-License-Identifier: LGPL-2.1-or-later
! Okada's (1992) displacement and displacement gradient of a rectangular
! dislocation in an elastic half-space (z <= 0) at many points, through his
! subroutine DC3D (DC3D.f, not in this repository: run.sh compiles it from
! the pinned okada_wrapper clone next to this file).
!
! Reads from standard input one line with
!   alpha depth dip al1 al2 aw1 aw2 disl1 disl2 disl3
! (DC3D's arguments: alpha = (lambda + mu) / (lambda + 2 mu); lengths in m,
! dip in degrees), then one point x y z per line to the end; writes per
! point
!   x y z ux uy uz uxx uyx uzx uxy uyy uzy uxz uyz uzz iret
! (uij = d u_i / d x_j) to standard output. DC3D takes REAL*4 arguments.
program dc3d_points
  implicit none
  real(4) :: alpha, depth, dip, al1, al2, aw1, aw2, d1, d2, d3
  real(4) :: x, y, z, ux, uy, uz, uxx, uyx, uzx, uxy, uyy, uzy, uxz, uyz, uzz
  integer :: iret, ios
  read (*, *) alpha, depth, dip, al1, al2, aw1, aw2, d1, d2, d3
  do
    read (*, *, iostat=ios) x, y, z
    if (ios /= 0) exit
    call DC3D(alpha, x, y, z, depth, dip, al1, al2, aw1, aw2, d1, d2, d3, &
              ux, uy, uz, uxx, uyx, uzx, uxy, uyy, uzy, uxz, uyz, uzz, iret)
    write (*, '(15es16.8,i3)') x, y, z, ux, uy, uz, uxx, uyx, uzx, &
      uxy, uyy, uzy, uxz, uyz, uzz, iret
  end do
end program dc3d_points
