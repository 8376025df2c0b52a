MODULE propagation_through_routines
  ! Tests: an error in a routine without ERROR handler propagates up the call
  ! chain to the nearest handler; intermediate routines stop where they are.
  PROC level3()
    VAR num a{1};
    a{2} := 0;
    TPWrite "level3 not reached";
  ENDPROC
  PROC level2()
    level3;
    TPWrite "level2 not reached";
  ENDPROC
  PROC level1()
    level2;
    TPWrite "level1 not reached";
  ERROR
    IF ERRNO = ERR_OUTOFBND TPWrite "level1 caught";
    RETURN;
  ENDPROC
  PROC main()
    level1;
    TPWrite "main continues";
  ENDPROC
ENDMODULE
