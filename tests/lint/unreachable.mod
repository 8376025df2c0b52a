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
    Skip;
    n := Ratio(n);
    Serve;
    Poll;
  ENDPROC

  PROC Leave()
    VAR num k := 0;
    IF k = 0 THEN
      RAISE ERR_DIVZERO;
    ELSE
      EXIT;
    ENDIF
    k := 1;  ! TRYNEXT below goes on after the RAISE, so this runs
  ERROR
    TRYNEXT;
    k := 2;  ! expect: RMC808
  ENDPROC

  PROC Skip()
    VAR num k := 0;
    RAISE ERR_DIVZERO;
    k := 1;  ! expect: RMC808
  ERROR
    k := 3;
    RAISE;
    k := 4;  ! expect: RMC808
  ENDPROC

  PROC Serve()
    VAR num k := 0;
    WHILE TRUE DO
      WaitTime 1;
      k := k + 1;
      IF k > 3 EXIT;  ! (EXIT ends the program: it does not leave the loop)
    ENDWHILE
    k := 0;  ! expect: RMC808
  ENDPROC

  PROC Poll()
    VAR num k := 0;
    WHILE TRUE DO
      WaitTime 1;
      k := k + 1;
      IF k > 3 GOTO done;
    ENDWHILE
    k := 5;  ! a GOTO inside may leave the loop: not reported
  done:
    k := 0;
  ENDPROC

  FUNC num Ratio(num d)
    RETURN 10 / d;
    TPWrite "after a division that may raise";
    RETURN 1;
    TPWrite "after a plain RETURN";  ! expect: RMC808
  ERROR
    TRYNEXT;
  ENDFUNC
ENDMODULE
