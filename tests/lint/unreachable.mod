MODULE Unreachable
  PROC main()
    VAR num n := 0;
    TPWrite "start";
    IF n > 0 THEN
      RETURN;
      n := 1;  ! expect: RMC808
      n := 2;
    ENDIF
    GOTO later;
    n := 3;  ! expect: RMC808
  later:
    n := 4;
    Stop;
    n := 5;
    Leave;
  ENDPROC

  PROC Leave()
    VAR num k := 0;
    IF k = 0 THEN
      RAISE ERR_DIVZERO;
    ELSE
      EXIT;
    ENDIF
    k := 1;  ! expect: RMC808
  ERROR
    TRYNEXT;
    k := 2;  ! expect: RMC808
  ENDPROC
ENDMODULE
