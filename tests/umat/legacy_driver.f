C     A legacy (FIXED-FORM, F77-style) driver that calls the interlock UMAT the way an FE code
C     does: PROPS and STATEV arrays, one call per increment, STRAN at the start of the
C     increment and DSTRAN the increment. It links against the single-file bundle alone.
C     Scene: pure mode I on a flat interface (theta_0 = 0), opening monotonically to past the
C     critical separation. Closed forms (SPEC section 8): peak sigma0_n at s_0n = (1-eta) s_cn,
C     zero traction from s_cn = 2 Gc / sigma0_n on, work = Gc, initial stiffness
C     K = sigma0 / s_0.
C     Then a 3D cohesive point (NTENS = 3, NSTATV = 28): pure shear along
C     t2 on the same interface, the mode-II closed forms (peak sigma0_t
C     at s_0t, zero traction from s_ct on, work = Gc), no traction
C     along the normal or t1.
      PROGRAM LEGDRV
      IMPLICIT DOUBLE PRECISION (A-H, O-Z)
      INTEGER NTENS, NSTATV, NPROPS, NDI, NSHR, NOEL, NPT, LAYER, KSPT
      INTEGER KINC, JSTEP(4), I, J, NSTEP, NFAIL
      PARAMETER (NTENS = 2, NSTATV = 22, NPROPS = 9)
      DOUBLE PRECISION STRESS(NTENS), STATEV(NSTATV)
      DOUBLE PRECISION DDSDDE(NTENS, NTENS), DDSDDT(NTENS)
      DOUBLE PRECISION DRPLDE(NTENS), STRAN(NTENS), DSTRAN(NTENS)
      DOUBLE PRECISION TIME(2), PREDEF(1), DPRED(1), PROPS(NPROPS)
      DOUBLE PRECISION COORDS(3), DROT(3, 3), DFGRD0(3, 3), DFGRD1(3, 3)
      DOUBLE PRECISION SSE, SPD, SCD, RPL, DRPLDT, DTIME, TEMP, DTEMP
      DOUBLE PRECISION PNEWDT, CELENT, SIG0, GC, ETA, SC, S0, DS
      DOUBLE PRECISION PEAK, SPEAK, SEND, XK
      CHARACTER*80 CMNAME
      EXTERNAL UMAT
C     sigma0_n, sigma0_t, Gc, eta, mu, H_N (1e30: infinite), theta_0, theta_f, zeta_0
      DATA PROPS /3.0D0, 3.0D0, 0.3D0, 0.9D0, 0.5D0, 1.0D30, 0.0D0,
     &            0.0D0, 1.0D30/
      SIG0 = PROPS(1)
      GC = PROPS(3)
      ETA = PROPS(4)
      SC = 2.0D0 * GC / SIG0
      S0 = (1.0D0 - ETA) * SC
      XK = SIG0 / S0
      NSTEP = 60
      DS = 1.5D0 * SC / DBLE(NSTEP)
      CMNAME = 'INTERLOCK'
      NDI = 1
      NSHR = 1
      NOEL = 1
      NPT = 1
      LAYER = 1
      KSPT = 1
      JSTEP(1) = 1
      JSTEP(2) = 1
      JSTEP(3) = 0
      JSTEP(4) = 0
      TEMP = 0.0D0
      DTEMP = 0.0D0
      PREDEF(1) = 0.0D0
      DPRED(1) = 0.0D0
      CELENT = 1.0D0
      DO 20 I = 1, 3
        COORDS(I) = 0.0D0
        DO 10 J = 1, 3
          DROT(I, J) = 0.0D0
          DFGRD0(I, J) = 0.0D0
          DFGRD1(I, J) = 0.0D0
   10   CONTINUE
        DROT(I, I) = 1.0D0
        DFGRD0(I, I) = 1.0D0
        DFGRD1(I, I) = 1.0D0
   20 CONTINUE
      DO 30 I = 1, NSTATV
        STATEV(I) = 0.0D0
   30 CONTINUE
      STRESS(1) = 0.0D0
      STRESS(2) = 0.0D0
      SSE = 0.0D0
      SPD = 0.0D0
      SCD = 0.0D0
      PEAK = 0.0D0
      SPEAK = 0.0D0
      NFAIL = 0
      DTIME = 1.0D0 / DBLE(NSTEP)
      DO 40 KINC = 1, NSTEP
        STRAN(1) = DBLE(KINC - 1) * DS
        STRAN(2) = 0.0D0
        DSTRAN(1) = DBLE(KINC) * DS - STRAN(1)
        DSTRAN(2) = 0.0D0
        TIME(1) = DBLE(KINC - 1) * DTIME
        TIME(2) = TIME(1)
        PNEWDT = 1.0D36
        CALL UMAT(STRESS, STATEV, DDSDDE, SSE, SPD, SCD, RPL, DDSDDT,
     &    DRPLDE, DRPLDT, STRAN, DSTRAN, TIME, DTIME, TEMP, DTEMP,
     &    PREDEF, DPRED, CMNAME, NDI, NSHR, NTENS, NSTATV, PROPS,
     &    NPROPS, COORDS, DROT, PNEWDT, CELENT, DFGRD0, DFGRD1, NOEL,
     &    NPT, LAYER, KSPT, JSTEP, KINC)
C       one full-damage jump per step is well above the default bound of 0.25
        IF (PNEWDT .LT. 0.0D0) THEN
          WRITE (*, *) 'FAIL: the UMAT rejected the input'
          NFAIL = NFAIL + 1
        END IF
        IF (KINC .EQ. 1) THEN
          CALL CHECK('initial normal stiffness', XK, DDSDDE(1, 1),
     &               1.0D-12 * XK, NFAIL)
          CALL CHECK('initial shear stiffness', XK, DDSDDE(2, 2),
     &               1.0D-12 * XK, NFAIL)
        END IF
        IF (STRESS(1) .GT. PEAK) THEN
          PEAK = STRESS(1)
          SPEAK = STRAN(1) + DSTRAN(1)
        END IF
        SEND = STRAN(1) + DSTRAN(1)
   40 CONTINUE
      CALL CHECK('mode-I peak traction', SIG0, PEAK, 1.0D-12, NFAIL)
      CALL CHECK('separation at the peak', S0, SPEAK, 1.0D-14, NFAIL)
      CALL CHECK('traction past s_c', 0.0D0, STRESS(1), 1.0D-14, NFAIL)
      CALL CHECK('damage past s_c', 1.0D0, STATEV(1), 1.0D-14, NFAIL)
      CALL CHECK('work = Gc (STATEV 19)', GC, STATEV(19), 1.0D-12,
     &           NFAIL)
      CALL CHECK('stored energy past s_c', 0.0D0, SSE, 1.0D-14, NFAIL)
      CALL CHECK('final separation', 1.5D0 * SC, SEND, 1.0D-14, NFAIL)
      WRITE (*, '(A, F10.6, A, F10.6, A, F10.6)') ' peak ', PEAK,
     &  ' at s = ', SPEAK, '   dissipation SCD ', SCD
      CALL SHEAR3(PROPS, NPROPS, NFAIL)
      IF (NFAIL .NE. 0) THEN
        WRITE (*, *) 'legacy driver: ', NFAIL, ' checks FAILED'
        STOP 1
      END IF
      WRITE (*, *) 'legacy driver: all checks passed'
      END

      SUBROUTINE CHECK(WHAT, EXPECT, ACTUAL, TOL, NFAIL)
      IMPLICIT DOUBLE PRECISION (A-H, O-Z)
      CHARACTER*(*) WHAT
      DOUBLE PRECISION EXPECT, ACTUAL, TOL
      INTEGER NFAIL
      IF (ABS(ACTUAL - EXPECT) .LE. TOL) THEN
        WRITE (*, '(A, A)') ' ok   ', WHAT
      ELSE
        WRITE (*, '(A, A, 3ES24.16)') ' FAIL ', WHAT, EXPECT, ACTUAL,
     &    ABS(ACTUAL - EXPECT)
        NFAIL = NFAIL + 1
      END IF
      END

C     Shear along t2 of a 3D cohesive point (NTENS = 3, COH3D8's
C     convention), from 0 to 1.5 s_ct in 60 increments.
      SUBROUTINE SHEAR3(PROPS, NPROPS, NFAIL)
      IMPLICIT DOUBLE PRECISION (A-H, O-Z)
      INTEGER NPROPS, NFAIL, NTENS, NSTATV, KINC, JSTEP(4), I, J
      PARAMETER (NTENS = 3, NSTATV = 28)
      DOUBLE PRECISION PROPS(NPROPS), STRESS(NTENS), STATEV(NSTATV)
      DOUBLE PRECISION DDSDDE(NTENS, NTENS), DDSDDT(NTENS)
      DOUBLE PRECISION DRPLDE(NTENS), STRAN(NTENS), DSTRAN(NTENS)
      DOUBLE PRECISION TIME(2), PREDEF(1), DPRED(1), COORDS(3)
      DOUBLE PRECISION DROT(3, 3), DFGRD(3, 3)
      DOUBLE PRECISION SSE, SPD, SCD, RPL, DRPLDT, PNEWDT, SC, S0, DS
      DOUBLE PRECISION PEAK, SPEAK, OTHER
      CHARACTER*80 CMNAME
      EXTERNAL UMAT
      SC = 2.0D0 * PROPS(3) / PROPS(2)
      S0 = (1.0D0 - PROPS(4)) * SC
      DS = 1.5D0 * SC / 60.0D0
      CMNAME = 'INTERLOCK3D'
      JSTEP(1) = 1
      JSTEP(2) = 1
      JSTEP(3) = 0
      JSTEP(4) = 0
      PREDEF(1) = 0.0D0
      DPRED(1) = 0.0D0
      DO 20 I = 1, 3
        COORDS(I) = 0.0D0
        STRESS(I) = 0.0D0
        DO 10 J = 1, 3
          DROT(I, J) = 0.0D0
   10   CONTINUE
        DROT(I, I) = 1.0D0
   20 CONTINUE
      DO 25 I = 1, 3
        DO 24 J = 1, 3
          DFGRD(I, J) = DROT(I, J)
   24   CONTINUE
   25 CONTINUE
      DO 30 I = 1, NSTATV
        STATEV(I) = 0.0D0
   30 CONTINUE
      SSE = 0.0D0
      SPD = 0.0D0
      SCD = 0.0D0
      PEAK = 0.0D0
      SPEAK = 0.0D0
      OTHER = 0.0D0
      DO 40 KINC = 1, 60
        STRAN(1) = 0.0D0
        STRAN(2) = 0.0D0
        STRAN(3) = DBLE(KINC - 1) * DS
        DSTRAN(1) = 0.0D0
        DSTRAN(2) = 0.0D0
        DSTRAN(3) = DBLE(KINC) * DS - STRAN(3)
        TIME(1) = 0.0D0
        TIME(2) = 0.0D0
        PNEWDT = 1.0D36
        CALL UMAT(STRESS, STATEV, DDSDDE, SSE, SPD, SCD, RPL, DDSDDT,
     &    DRPLDE, DRPLDT, STRAN, DSTRAN, TIME, 1.0D0, 0.0D0, 0.0D0,
     &    PREDEF, DPRED, CMNAME, 1, 2, NTENS, NSTATV, PROPS,
     &    NPROPS, COORDS, DROT, PNEWDT, 1.0D0, DFGRD, DFGRD, 1,
     &    1, 1, 1, JSTEP, KINC)
        IF (PNEWDT .LT. 0.0D0) THEN
          WRITE (*, *) 'FAIL: the 3D UMAT rejected the input'
          NFAIL = NFAIL + 1
        END IF
        IF (STRESS(3) .GT. PEAK) THEN
          PEAK = STRESS(3)
          SPEAK = STRAN(3) + DSTRAN(3)
        END IF
        OTHER = MAX(OTHER, ABS(STRESS(1)), ABS(STRESS(2)))
   40 CONTINUE
      CALL CHECK('3D: mode-II peak along t2', PROPS(2), PEAK, 1.0D-12,
     &           NFAIL)
      CALL CHECK('3D: separation at the peak', S0, SPEAK, 1.0D-14,
     &           NFAIL)
      CALL CHECK('3D: traction past s_c', 0.0D0, STRESS(3), 1.0D-14,
     &           NFAIL)
      CALL CHECK('3D: no normal or t1 traction', 0.0D0, OTHER, 1.0D-14,
     &           NFAIL)
      CALL CHECK('3D: work = Gc (STATEV 19)', PROPS(3), STATEV(19),
     &           1.0D-12, NFAIL)
      END
