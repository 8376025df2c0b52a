MODULE long_jump_recovery_point
  ! Tests: ERROR (LONG_JMP_ALL_ERR) in main is an error recovery point: an
  ! error raised three calls deeper, in routines without handlers, reaches
  ! it with its ERRNO; the unwound routines' UNDO handlers run; TRYNEXT in
  ! the recovery point continues after main's call statement. (The handler
  ! prints nothing, so the output does not depend on whether UNDO runs
  ! before or after it.)
  VAR bool recovered := FALSE;
  PROC deep()
    VAR num z := 0;
    z := 1 / z;
  ENDPROC
  PROC middle()
    deep;
    TPWrite "middle not reached";
  UNDO
    TPWrite "undo middle";
  ENDPROC
  PROC main()
    middle;
    TPWrite "recovered divzero " \Bool:=recovered;
  ERROR (LONG_JMP_ALL_ERR)
    recovered := ERRNO = ERR_DIVZERO;
    TRYNEXT;
  ENDPROC
ENDMODULE
