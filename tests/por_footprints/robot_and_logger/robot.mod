MODULE Robot
  ! Each instruction line ends with its footprint for partial-order reduction:
  ! LOCAL (independent of the logger, no atom), VISIBLE (independent, an atom names
  ! what it writes), SHARED (the logger may depend on it, or it on the logger).
  PERS num handshake := 0;
  PERS num robot_only := 0;
  PERS num status := 0;
  PERS num limit := 2;
  VAR num count := 0;
  VAR num reported := 0;
  VAR bool done := FALSE;
  VAR bool taught{3} := [TRUE, FALSE, TRUE];
  PERS bool ready{2} := [FALSE, FALSE];
  PROC main()
    FOR i FROM 1 TO 3 DO                 ! LOCAL
      count := count + 1;                ! LOCAL
      robot_only := robot_only + count;  ! LOCAL
      reported := count;                 ! VISIBLE
      Bookkeeping;                       ! LOCAL
      ! an indexed condition (not a fused step): what it reads, from its syntax
      IF taught{i} = TRUE done := FALSE; ! LOCAL
      IF ready{count MOD 2 + 1} THEN     ! SHARED
        done := FALSE;                   ! LOCAL
      ENDIF
      IF count > limit THEN              ! SHARED
        done := TRUE;                    ! LOCAL
      ENDIF
      count := count + status;           ! SHARED
      handshake := count;                ! SHARED
      IF handshake > 1 THEN              ! SHARED
        count := 0;                      ! LOCAL
      ENDIF
      WaitUntil handshake = 0;           ! SHARED
      TPWrite "cycle";                   ! LOCAL
      TPWrite "status ", \Num:=status;   ! SHARED
      IF DInput(diReady) = 1 THEN        ! LOCAL
        done := FALSE;                   ! LOCAL
      ENDIF
    ENDFOR
  ENDPROC                                ! LOCAL
  PROC Bookkeeping()
    count := count MOD 5;                ! LOCAL
    RETURN;                              ! LOCAL
  ENDPROC
ENDMODULE
